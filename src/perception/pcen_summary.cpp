#include "perception/pcen_summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "audio/pcen.h"
#include "common/error.h"
#include "perception/summary_features.h"

namespace echoplan::perception {
namespace {

// psf's energies are of samples in [-1, 1]; in 16-bit units they are 2^30 times larger.
const double kSixteenBitPower = std::ldexp(1.0, 30);

// The average starts at the first sound, as the mean energy of the frames between it and the
// onset: the background heard before the contact, rather than one frame that may straddle the end
// of the recorder's digital silence. With no frame before the onset, the onset's own energy.
audio::PcenStart background_start(const audio::FeatureMatrix& energies, std::size_t first,
                                  std::size_t onset) {
  audio::PcenStart start{first, {}};
  if (onset == first) return start;
  start.average.assign(energies.cols, 0.0);
  for (std::size_t t = first; t < onset; ++t)
    for (std::size_t b = 0; b < energies.cols; ++b) start.average[b] += energies.at(t, b);
  for (double& v : start.average) v /= static_cast<double>(onset - first);
  return start;
}

}  // namespace

std::vector<double> pcen_summary(const ClipAnalysis& clip) {
  const audio::FeatureMatrix& log_mel = clip.features.log_mel;
  if (log_mel.cols != kSummaryBands)
    throw InputError(fmt::format(
        "PCEN summary features need 26 log-mel bands (the psf preset), got {}", log_mel.cols));
  if (log_mel.rows == 0) throw InputError("PCEN summary features need at least one frame");
  audio::FeatureMatrix energies = log_mel;
  for (float& v : energies.values) v = static_cast<float>(std::exp(v) * kSixteenBitPower);
  const std::size_t last = log_mel.rows - 1;
  const std::size_t onset = std::min(clip.onset_frame, last);
  const audio::FeatureMatrix normalised =
      audio::pcen(energies, clip.hop_seconds, audio::PcenConfig{},
                  background_start(energies, std::min(clip.first_sound_frame, onset), onset));

  std::vector<double> out;
  out.reserve(kPcenSummarySize);
  for (const auto& [from, to] : kSummarySegments)
    for (std::size_t b = 0; b < kSummaryBands; ++b) {
      double sum = 0.0;
      for (std::size_t f = from; f < to; ++f) sum += normalised.at(std::min(onset + f, last), b);
      out.push_back(sum / static_cast<double>(to - from));
    }
  return out;
}

std::vector<std::string> pcen_summary_names() { return segment_band_names("pcen"); }

}  // namespace echoplan::perception
