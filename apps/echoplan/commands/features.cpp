// `echoplan features`: the feature matrix of one recording (CSV or JSON), or a readable summary of
// all features. `echoplan heatmap` (heatmap.cpp) plots the same matrices.
#include "audio/features.h"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numeric>

#include "audio/io.h"
#include "audio/onsets.h"
#include "commands/commands.h"
#include "commands/feature_options.h"
#include "common/error.h"

namespace echoplan::cli {
namespace {

// CSV as the references write it: one row per frame, %.9g, no header.
void write_csv(std::FILE* out, const audio::FeatureMatrix& m) {
  for (std::size_t r = 0; r < m.rows; ++r) {
    for (std::size_t c = 0; c < m.cols; ++c)
      fmt::print(out, "{}{:.9g}", c == 0 ? "" : ",", static_cast<double>(m.at(r, c)));
    fmt::print(out, "\n");
  }
}

void write_json(std::FILE* out, const audio::FeatureMatrix& m, const FeatureOptions& options,
                const audio::AudioClip& clip) {
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t r = 0; r < m.rows; ++r) {
    const auto row = m.row(r);
    rows.push_back(std::vector<double>(row.begin(), row.end()));
  }
  const auto config = audio::preset_by_name(options.preset, clip.sample_rate);
  const nlohmann::json doc{
      {"file", options.files.front()},
      {"preset", options.preset},
      {"feature", options.feature},
      {"sample_rate", clip.sample_rate},
      {"hop_seconds", static_cast<double>(config.stft.framing.hop) / clip.sample_rate},
      {"frames", m.rows},
      {"columns", m.cols},
      {"values", rows}};
  fmt::print(out, "{}\n", doc.dump());
}

struct Stats {
  double mean = 0, min = 0, max = 0;
};

Stats stats(const audio::FeatureMatrix& m) {
  Stats s;
  if (m.values.empty()) return s;
  const auto [lo, hi] = std::minmax_element(m.values.begin(), m.values.end());
  s.min = *lo;
  s.max = *hi;
  s.mean =
      std::accumulate(m.values.begin(), m.values.end(), 0.0) / static_cast<double>(m.values.size());
  return s;
}

void print_summary(const FeatureOptions& options, const audio::AudioClip& clip,
                   const audio::FeatureConfig& config, const audio::Features& f) {
  const auto g = audio::global_features(clip.samples, clip.sample_rate);
  const double hop = static_cast<double>(config.stft.framing.hop) / clip.sample_rate;
  fmt::print("{}: {} Hz, {:.3f} s ({} frames; channels averaged), preset {}\n",
             options.files.front(), clip.sample_rate, clip.duration_seconds(), clip.frames(),
             options.preset);
  fmt::print("whole signal: rms {:.6g}, zero crossings {}, spectral centroid {:.1f} Hz\n", g.rms,
             g.zero_crossings, g.centroid_hz);
  fmt::print("per frame ({} frames, hop {:.1f} ms):\n", f.rms.rows, 1000 * hop);
  fmt::print("  {:<10} {:>12} {:>12} {:>12}  {}\n", "feature", "mean", "min", "max", "unit");
  const std::pair<audio::FeatureKind, const char*> scalars[] = {
      {audio::FeatureKind::rms, "full scale"}, {audio::FeatureKind::zcr, "per sample"},
      {audio::FeatureKind::centroid, "Hz"},    {audio::FeatureKind::bandwidth, "Hz"},
      {audio::FeatureKind::rolloff, "Hz"},     {audio::FeatureKind::flatness, "0..1"},
      {audio::FeatureKind::flux, "magnitude"}};
  for (const auto& [kind, unit] : scalars) {
    const Stats s = stats(audio::select_feature(f, kind));
    fmt::print("  {:<10} {:>12.6g} {:>12.6g} {:>12.6g}  {}\n", audio::feature_name(kind), s.mean,
               s.min, s.max, unit);
  }
  const char* log_unit = config.log_scale == audio::LogScale::decibel ? "dB" : "ln";
  const Stats lm = stats(f.log_mel);
  fmt::print("  {:<10} {} x {} bands, mean {:.4g} {}, range {:.4g}..{:.4g}\n", "logmel",
             f.log_mel.rows, f.log_mel.cols, lm.mean, log_unit, lm.min, lm.max);
  fmt::print("  {:<10} {} x {} coefficients\n", "mfcc", f.mfcc.rows, f.mfcc.cols);
  const auto onsets = audio::detect_onsets(f.flux);
  std::string times;
  for (std::size_t t : onsets)
    times += fmt::format("{}{:.3f}", times.empty() ? "" : ", ", static_cast<double>(t) * hop);
  fmt::print("onsets (s): {}\n", onsets.empty() ? "none" : times);
  fmt::print("preset parameters:\n");
  for (const auto& p : audio::describe_parameters(config))
    fmt::print("  {:<17} {:>12.6g} {:<8} ({})\n", p.name, p.value, p.unit, p.description);
}

}  // namespace

void add_features_command(CLI::App& app) {
  auto options = std::make_shared<FeatureOptions>();
  auto* cmd = app.add_subcommand(
      "features",
      "Compute audio features of a recording: the frames x coefficients matrix of one feature\n"
      "(CSV or JSON), or, without --feature, a readable summary of every feature.");
  add_feature_options(*cmd, *options);
  cmd->add_option("FILE", options->files, "Audio file (WAV, FLAC, ...)")->required()->expected(1);
  cmd->add_option("--format", options->format,
                  "Output format of --feature: csv (one row per frame, no header) or json")
      ->check(CLI::IsMember({"csv", "json"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", options->output,
                  "Write the matrix to this file instead of the terminal");
  cmd->callback([options] {
    const audio::AudioClip clip = read_for_features(*options, options->files.front());
    const auto config = audio::preset_by_name(options->preset, clip.sample_rate);
    audio::FeatureExtractor extractor(config);
    audio::Features f;
    extractor.compute(clip.samples, f);
    if (options->feature.empty()) {
      print_summary(*options, clip, config, f);
      return;
    }
    const auto& matrix = audio::select_feature(f, audio::feature_from_name(options->feature));
    std::FILE* out = stdout;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(nullptr, &std::fclose);
    if (!options->output.empty()) {
      file.reset(std::fopen(options->output.c_str(), "w"));
      if (!file) throw InputError(options->output, 0, "cannot open for writing");
      out = file.get();
    }
    if (options->format == "json")
      write_json(out, matrix, *options, clip);
    else
      write_csv(out, matrix);
  });
}

}  // namespace echoplan::cli
