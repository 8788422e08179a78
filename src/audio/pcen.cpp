#include "audio/pcen.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/error.h"

namespace echoplan::audio {
namespace {

void check_config(const PcenConfig& c) {
  auto in_unit = [](double v) { return v > 0.0 && v <= 1.0; };
  if (!in_unit(c.gain)) throw InputError(fmt::format("PCEN gain = {} is outside (0, 1]", c.gain));
  if (!in_unit(c.power))
    throw InputError(fmt::format("PCEN power = {} is outside (0, 1]", c.power));
  if (!(c.bias > 0.0)) throw InputError(fmt::format("PCEN bias = {} must be positive", c.bias));
  if (!(c.eps > 0.0)) throw InputError(fmt::format("PCEN eps = {} must be positive", c.eps));
}

}  // namespace

double pcen_smoothing(double time_constant_s, double hop_s) {
  if (!(time_constant_s > 0.0) || !(hop_s > 0.0))
    throw InputError(
        fmt::format("PCEN time constant ({} s) and frame hop ({} s) must both be positive",
                    time_constant_s, hop_s));
  const double t = time_constant_s / hop_s;
  return (std::sqrt(1.0 + 4.0 * t * t) - 1.0) / (2.0 * t * t);
}

FeatureMatrix pcen(const FeatureMatrix& energies, double hop_s, const PcenConfig& config,
                   const PcenStart& start) {
  check_config(config);
  const double s = pcen_smoothing(config.time_constant_s, hop_s);
  FeatureMatrix out;
  out.resize(energies.rows, energies.cols);
  std::fill(out.values.begin(), out.values.end(), 0.0f);
  if (energies.rows == 0) return out;
  if (start.frame >= energies.rows)
    throw InputError(
        fmt::format("PCEN cannot start at frame {} of {}", start.frame, energies.rows));
  if (!start.average.empty() && start.average.size() != energies.cols)
    throw InputError(fmt::format("PCEN's start average has {} bands, the energies {}",
                                 start.average.size(), energies.cols));
  const double floor = std::pow(config.bias, config.power);
  std::vector<double> average = start.average;
  if (average.empty())
    average.assign(energies.row(start.frame).begin(), energies.row(start.frame).end());
  for (std::size_t t = start.frame; t < energies.rows; ++t) {
    for (std::size_t b = 0; b < energies.cols; ++b) {
      const double e = energies.at(t, b);
      average[b] = (1.0 - s) * average[b] + s * e;
      const double ratio = e / std::pow(config.eps + average[b], config.gain);
      out.at(t, b) = static_cast<float>(std::pow(ratio + config.bias, config.power) - floor);
    }
  }
  return out;
}

}  // namespace echoplan::audio
