#include "signal/series_features.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <kiss_fftr.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <set>

#include "common/error.h"

namespace echoplan::signal {

const std::vector<SeriesFeaturePreset>& series_feature_presets() {
  static const std::vector<SeriesFeaturePreset> presets = {
      {"cy101-haptic", "bins(10,sum,time-major)",
       "CY101's haptics: 10 bins per joint torque, each the sum of its samples, bin by bin"},
      {"ur5-effort", "bins(10,mean,time-major)",
       "the UR5 containers' joint efforts: 10 bins per joint, bin by bin"},
      {"ur5-force", "bins(10,mean,time-major)[force_x,force_y,force_z]",
       "the UR5 containers' wrist forces: 10 bins per force axis, bin by bin"},
  };
  return presets;
}

namespace {

constexpr int kMaxBins = 1000;

std::string trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return std::string(text.substr(first, last - first + 1));
}

std::vector<std::string> split_commas(std::string_view text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto comma = text.find(',', start);
    parts.push_back(trimmed(text.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return parts;
}

[[noreturn]] void bad(std::string_view spec, const std::string& problem) {
  std::vector<std::string> presets;
  for (const auto& p : series_feature_presets()) presets.emplace_back(p.name);
  throw InputError(
      fmt::format("series features '{}': {} (expected bins(N,sum|mean[,time-major]), stats or "
                  "bands(E0,E1,...), "
                  "optionally "
                  "followed by [channel,...], or a preset: {})",
                  spec, problem, fmt::join(presets, ", ")));
}

double parse_number(const std::string& text, std::string_view spec) {
  double value = 0.0;
  const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || stop != text.data() + text.size() ||
      !std::isfinite(value))
    bad(spec, fmt::format("'{}' is not a number", text));
  return value;
}

void parse_arguments(SeriesFeatures& f, const std::vector<std::string>& args,
                     std::string_view spec) {
  switch (f.kind) {
    case SeriesFeatures::Kind::bins: {
      if (args.size() != 2 && args.size() != 3)
        bad(spec, "bins takes how many, sum or mean, and optionally time-major");
      const double n = parse_number(args[0], spec);
      if (n != std::floor(n) || n < 1 || n > kMaxBins)
        bad(spec, fmt::format("the number of bins must be a whole number from 1 to {}", kMaxBins));
      f.bins = static_cast<int>(n);
      if (args[1] == "sum")
        f.reduce = SeriesFeatures::Reduce::sum;
      else if (args[1] == "mean")
        f.reduce = SeriesFeatures::Reduce::mean;
      else
        bad(spec, fmt::format("a bin is the sum or the mean of its samples, not '{}'", args[1]));
      if (args.size() == 3 && args[2] != "time-major")
        bad(spec, fmt::format("the third argument of bins is time-major, not '{}'", args[2]));
      f.time_major = args.size() == 3;
      break;
    }
    case SeriesFeatures::Kind::stats:
      if (!args.empty()) bad(spec, "stats takes no arguments");
      break;
    case SeriesFeatures::Kind::bands:
      if (args.size() < 2) bad(spec, "bands takes at least two edges in Hz");
      for (const std::string& a : args) {
        const double edge = parse_number(a, spec);
        if (edge < 0) bad(spec, "band edges must not be negative");
        if (!f.band_edges.empty() && edge <= f.band_edges.back())
          bad(spec, "band edges must increase");
        f.band_edges.push_back(edge);
      }
      break;
  }
}

void parse_channels(SeriesFeatures& f, std::string_view list, std::string_view spec) {
  std::set<std::string> seen;
  for (std::string& channel : split_commas(list)) {
    if (channel.empty()) bad(spec, "a channel name in [...] is empty");
    if (!seen.insert(channel).second)
      bad(spec, fmt::format("channel '{}' is listed twice", channel));
    f.channels.push_back(std::move(channel));
  }
}

std::string number_text(double x) { return fmt::format("{}", x); }

// A row laid out channel by channel (`bins` entries each) laid out bin by bin instead.
template <typename T>
std::vector<T> bin_by_bin(const std::vector<T>& by_channel, int bins) {
  const std::size_t b = static_cast<std::size_t>(bins), channels = by_channel.size() / b;
  std::vector<T> out;
  out.reserve(by_channel.size());
  for (std::size_t k = 0; k < b; ++k)
    for (std::size_t c = 0; c < channels; ++c) out.push_back(by_channel[c * b + k]);
  return out;
}

const char* stat_names[] = {"mean", "std", "min", "max", "rms"};

// np.array_split's bins: the first n % bins bins hold one sample more.
std::vector<double> binned(const std::vector<double>& v, int bins, SeriesFeatures::Reduce reduce) {
  const std::size_t n = v.size(), b = static_cast<std::size_t>(bins);
  std::vector<double> out;
  std::size_t start = 0;
  for (std::size_t k = 0; k < b; ++k) {
    const std::size_t size = n / b + (k < n % b ? 1 : 0);
    double sum = 0.0;
    for (std::size_t i = start; i < start + size; ++i) sum += v[i];
    out.push_back(reduce == SeriesFeatures::Reduce::sum ? sum : sum / static_cast<double>(size));
    start += size;
  }
  return out;
}

std::vector<double> statistics(const std::vector<double>& v) {
  const double n = static_cast<double>(v.size());
  double sum = 0.0, squares = 0.0;
  for (double x : v) sum += x, squares += x * x;
  const double mean = sum / n;
  double deviations = 0.0;
  for (double x : v) deviations += (x - mean) * (x - mean);
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return {mean, std::sqrt(deviations / n), *lo, *hi, std::sqrt(squares / n)};
}

// The median spacing of the samples' times, in seconds (0 when every sample has one time).
double median_spacing(const std::vector<double>& t) {
  std::vector<double> gaps;
  for (std::size_t i = 1; i < t.size(); ++i) gaps.push_back(t[i] - t[i - 1]);
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<long>(gaps.size() / 2), gaps.end());
  return gaps[gaps.size() / 2];
}

// `v` at times t0, t0 + dt, ... (an even count), linearly interpolated between samples.
std::vector<float> resampled(const std::vector<double>& t, const std::vector<double>& v, double dt,
                             std::size_t count) {
  std::vector<float> out(count);
  std::size_t j = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const double at = t.front() + dt * static_cast<double>(i);
    while (j + 2 < t.size() && t[j + 1] <= at) ++j;
    const double span = t[j + 1] - t[j];
    const double w = span > 0 ? std::clamp((at - t[j]) / span, 0.0, 1.0) : 0.0;
    out[i] = static_cast<float>(v[j] + w * (v[j + 1] - v[j]));
  }
  return out;
}

// The number of points of the even grid the bands are computed on: at least one per median
// spacing across the series, rounded up to a length whose factors are 2, 3 and 5 (kissfft's other
// factors cost a pass per factor: a length twice a large prime would take hours). Samples with
// gaps far wider than their median spacing are refused: most of the grid would be interpolation.
std::size_t band_grid(const Series& series, double dt, const std::string& source,
                      const std::string& spec) {
  const double natural = series.duration() / dt + 1.0;
  const double limit = 4.0 * static_cast<double>(series.samples()) + 64.0;
  if (natural > limit)
    throw InputError(
        source, 0,
        fmt::format("'{}': the samples have gaps (spanning {} s at a median spacing of "
                    "{} s would take {:.0f} points from {} samples)",
                    spec, series.duration(), dt, natural, series.samples()));
  return static_cast<std::size_t>(
      kiss_fftr_next_fast_size_real(static_cast<int>(std::ceil(natural - 1e-9))));
}

struct FftDeleter {
  void operator()(kiss_fftr_state* s) const { kiss_fftr_free(s); }
};

// The mean power of `x` (sampled every dt s) in each band: |X_k|^2 / n^2 averaged over the FFT
// bins whose frequency lies in [edge_i, edge_i+1); a band narrower than the bins' spacing takes the
// bin nearest its centre.
std::vector<double> band_powers(const std::vector<float>& x, double dt,
                                const std::vector<double>& edges) {
  const int n = static_cast<int>(x.size());
  std::unique_ptr<kiss_fftr_state, FftDeleter> cfg(kiss_fftr_alloc(n, 0, nullptr, nullptr));
  std::vector<kiss_fft_cpx> spectrum(static_cast<std::size_t>(n / 2 + 1));
  kiss_fftr(cfg.get(), x.data(), spectrum.data());
  const double resolution = 1.0 / (dt * n);
  std::vector<double> power(spectrum.size());
  for (std::size_t k = 0; k < spectrum.size(); ++k)
    power[k] = (double(spectrum[k].r) * spectrum[k].r + double(spectrum[k].i) * spectrum[k].i) /
               (double(n) * n);
  std::vector<double> out;
  for (std::size_t b = 0; b + 1 < edges.size(); ++b) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < power.size(); ++k) {
      const double f = resolution * static_cast<double>(k);
      if (f >= edges[b] && f < edges[b + 1]) sum += power[k], ++count;
    }
    if (count == 0) {
      const double centre = 0.5 * (edges[b] + edges[b + 1]);
      const auto k =
          std::min(power.size() - 1, static_cast<std::size_t>(std::lround(centre / resolution)));
      sum = power[k], count = 1;
    }
    out.push_back(sum / count);
  }
  return out;
}

}  // namespace

SeriesFeatures parse_series_features(std::string_view spec_text) {
  const std::string spec = trimmed(spec_text);
  for (const auto& preset : series_feature_presets())
    if (spec == preset.name) return parse_series_features(preset.spec);
  SeriesFeatures f;
  std::string_view rest = spec;
  std::string_view channels;
  if (const auto open = rest.find('['); open != std::string_view::npos) {
    if (rest.back() != ']') bad(spec, "the channel list must end the spec with ']'");
    channels = rest.substr(open + 1, rest.size() - open - 2);
    rest = rest.substr(0, open);
  }
  const auto paren = rest.find('(');
  const std::string kind = trimmed(rest.substr(0, paren));
  std::vector<std::string> args;
  if (paren != std::string_view::npos) {
    if (rest.back() != ')') bad(spec, "the arguments must be closed with ')'");
    args = split_commas(rest.substr(paren + 1, rest.size() - paren - 2));
  }
  if (kind == "bins")
    f.kind = SeriesFeatures::Kind::bins;
  else if (kind == "stats")
    f.kind = SeriesFeatures::Kind::stats;
  else if (kind == "bands")
    f.kind = SeriesFeatures::Kind::bands;
  else
    bad(spec, fmt::format("unknown kind '{}'", kind));
  parse_arguments(f, args, spec);
  if (!channels.empty() || spec.find('[') != std::string::npos) parse_channels(f, channels, spec);
  return f;
}

std::string SeriesFeatures::spec() const {
  std::string text;
  switch (kind) {
    case Kind::bins:
      text = fmt::format("bins({},{}{})", bins, reduce == Reduce::sum ? "sum" : "mean",
                         time_major ? ",time-major" : "");
      break;
    case Kind::stats:
      text = "stats";
      break;
    case Kind::bands: {
      std::vector<std::string> edges;
      for (double e : band_edges) edges.push_back(number_text(e));
      text = fmt::format("bands({})", fmt::join(edges, ","));
      break;
    }
  }
  if (!channels.empty()) text += fmt::format("[{}]", fmt::join(channels, ","));
  return text;
}

std::size_t SeriesFeatures::row_length(std::size_t series_channels) const {
  const std::size_t per_channel = kind == Kind::bins    ? static_cast<std::size_t>(bins)
                                  : kind == Kind::stats ? std::size(stat_names)
                                                        : band_edges.size() - 1;
  return per_channel * (channels.empty() ? series_channels : channels.size());
}

std::vector<std::string> SeriesFeatures::feature_names(
    const std::vector<std::string>& series_channels) const {
  const std::vector<std::string>& read = channels.empty() ? series_channels : channels;
  std::vector<std::string> names;
  for (const std::string& channel : read) {
    switch (kind) {
      case Kind::bins:
        for (int k = 1; k <= bins; ++k) names.push_back(fmt::format("{}_b{}", channel, k));
        break;
      case Kind::stats:
        for (const char* stat : stat_names) names.push_back(fmt::format("{}_{}", channel, stat));
        break;
      case Kind::bands:
        for (std::size_t b = 0; b + 1 < band_edges.size(); ++b)
          names.push_back(fmt::format("{}_{}_{}hz", channel, number_text(band_edges[b]),
                                      number_text(band_edges[b + 1])));
        break;
    }
  }
  return time_major ? bin_by_bin(names, bins) : names;
}

std::vector<double> SeriesFeatures::extract(const Series& series, const std::string& source) const {
  std::vector<int> read;
  if (channels.empty())
    for (std::size_t c = 0; c < series.channels.size(); ++c) read.push_back(static_cast<int>(c));
  for (const std::string& channel : channels) {
    const int c = series.channel_index(channel);
    if (c < 0)
      throw InputError(source, 0,
                       fmt::format("no channel '{}' (the series has {}), which '{}' reads", channel,
                                   fmt::join(series.channels, ", "), spec()));
    read.push_back(c);
  }
  const std::size_t n = series.samples();
  if (kind == Kind::bins && n < static_cast<std::size_t>(bins))
    throw InputError(source, 0,
                     fmt::format("{} samples, fewer than the {} bins of '{}'", n, bins, spec()));
  double dt = 0.0;
  std::size_t grid = 0;
  if (kind == Kind::bands) {
    dt = n >= 4 ? median_spacing(series.t) : 0.0;
    if (dt <= 0)
      throw InputError(source, 0,
                       fmt::format("'{}' needs at least 4 samples at distinct times", spec()));
    if (band_edges.back() > 0.5 / dt + 1e-9)
      throw InputError(source, 0,
                       fmt::format("band edge {} Hz is above half the series' rate ({} Hz)",
                                   band_edges.back(), 1.0 / dt));
    grid = band_grid(series, dt, source, spec());
    dt = series.duration() / static_cast<double>(grid - 1);
  }
  std::vector<double> row;
  for (int c : read) {
    const auto& v = series.values[static_cast<std::size_t>(c)];
    std::vector<double> part = kind == Kind::bins ? binned(v, bins, reduce)
                               : kind == Kind::stats
                                   ? statistics(v)
                                   : band_powers(resampled(series.t, v, dt, grid), dt, band_edges);
    row.insert(row.end(), part.begin(), part.end());
  }
  return time_major ? bin_by_bin(row, bins) : row;
}

}  // namespace echoplan::signal
