// `echoplan heatmap`: a PNG or SVG heat map of one feature matrix, or of the mean over several
// recordings (like the report's Figures 3.1 and 3.2), drawn by gnuplot.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include "audio/features.h"
#include "audio/onsets.h"
#include "commands/commands.h"
#include "commands/feature_options.h"
#include "common/error.h"
#include "experiment/gnuplot.h"

namespace echoplan::cli {
namespace {

namespace fs = std::filesystem;

struct HeatmapOptions {
  FeatureOptions features;
  std::vector<std::size_t>
      onset_window;  // {frames before, frames after} the first onset; empty = from the start
  std::string output;
  std::string title;
};

// The matrix each file contributes: its whole feature matrix, or a fixed window around its first
// onset.
audio::FeatureMatrix file_matrix(const HeatmapOptions& options, const std::string& path,
                                 double& hop_seconds) {
  const audio::AudioClip clip = read_for_features(options.features, path);
  const auto config = audio::preset_by_name(options.features.preset, clip.sample_rate);
  hop_seconds = static_cast<double>(config.stft.framing.hop) / clip.sample_rate;
  audio::FeatureExtractor extractor(config);
  audio::Features f;
  extractor.compute(clip.samples, f);
  const auto& matrix = audio::select_feature(f, audio::feature_from_name(options.features.feature));
  if (options.onset_window.empty()) return matrix;
  const std::size_t anchor = audio::alignment_frame(f.flux, audio::OnsetChoice::first);
  return audio::onset_window(matrix, anchor, options.onset_window[0], options.onset_window[1]);
}

void draw(const HeatmapOptions& options) {
  // Check the output and the plotting tool before any (possibly long) feature computation.
  const fs::path output(options.output);
  std::string ext = output.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".png" && ext != ".svg")
    throw InputError(options.output, 0, "the output must end in .png or .svg");
  experiment::find_gnuplot();

  // Mean over files, over the frames every file has (the shortest file's length when not
  // onset-aligned).
  audio::FeatureMatrix mean;
  double hop_seconds = 0.0;
  for (std::size_t i = 0; i < options.features.files.size(); ++i) {
    const std::string& path = options.features.files[i];
    double hop = 0.0;
    const audio::FeatureMatrix m = file_matrix(options, path, hop);
    if (i == 0) {
      mean = m;
      hop_seconds = hop;
      continue;
    }
    if (m.cols != mean.cols)
      throw InputError(path, 0,
                       fmt::format("has {} feature columns, the first file {}: use files at one "
                                   "sample rate or --resample",
                                   m.cols, mean.cols));
    if (m.rows < mean.rows) {
      spdlog::info("{}: {} frames; averaging over the first {} frames of every file", path, m.rows,
                   m.rows);
      mean.values.resize(m.rows * mean.cols);
      mean.rows = m.rows;
    }
    for (std::size_t v = 0; v < mean.values.size(); ++v) mean.values[v] += m.values[v];
  }
  const auto n = static_cast<float>(options.features.files.size());
  for (float& v : mean.values) v /= n;

  // gnuplot reads a temporary "x y value" file; the folder is removed whatever happens.
  const experiment::TemporaryFolder work("echoplan-heatmap");
  const fs::path dir = work.path();
  {
    std::ofstream data(dir / "matrix.dat");
    for (std::size_t r = 0; r < mean.rows; ++r) {
      for (std::size_t c = 0; c < mean.cols; ++c)
        data << fmt::format("{:.6g} {} {:.9g}\n", static_cast<double>(r) * hop_seconds, c,
                            mean.at(r, c));
      data << "\n";
    }
  }
  const std::string feature = options.features.feature;
  const std::string title =
      !options.title.empty() ? options.title
      : options.features.files.size() == 1
          ? fmt::format("{} ({}) of {}", feature, options.features.preset,
                        fs::path(options.features.files[0]).filename().string())
          : fmt::format("mean {} ({}) of {} recordings", feature, options.features.preset,
                        options.features.files.size());
  const std::string x_label =
      options.onset_window.empty() ? "time (s)" : "time from the window start (s)";
  const std::string y_label = feature == "mfcc"     ? "coefficient"
                              : feature == "logmel" ? "mel band"
                                                    : feature;
  auto script = [&](const std::string& terminal) {
    return fmt::format(
        "set terminal {} size 900,500\nset output '{}'\nset title \"{}\" noenhanced\n"
        "set xlabel '{}'\nset ylabel '{}'\n"
        "set palette rgbformulae 33,13,10\nset autoscale xfix\nset autoscale yfix\n"
        "plot 'matrix.dat' using 1:2:3 with image notitle\n",
        terminal, fs::absolute(output).string(), title, x_label, y_label);
  };
  // pngcairo draws better; gnuplot builds without cairo only have the libgd "png" terminal.
  std::string error;
  bool ok = experiment::run_gnuplot(script(ext == ".svg" ? "svg" : "pngcairo"), dir, error);
  if (!ok && ext == ".png") ok = experiment::run_gnuplot(script("png"), dir, error);
  if (!ok) throw InputError(options.output, 0, fmt::format("gnuplot failed: {}", error));
  fmt::print("wrote {} ({} frames x {} columns{})\n", options.output, mean.rows, mean.cols,
             options.features.files.size() > 1
                 ? fmt::format(", mean of {} files", options.features.files.size())
                 : "");
}

}  // namespace

void add_heatmap_command(CLI::App& app) {
  auto options = std::make_shared<HeatmapOptions>();
  options->features.feature = "logmel";
  auto* cmd = app.add_subcommand(
      "heatmap",
      "Draw a heat map (PNG or SVG, with gnuplot) of a feature matrix over time, or of its mean\n"
      "over several recordings (frames every file has, or a window around each file's first "
      "onset).");
  add_feature_options(*cmd, options->features);
  cmd->add_option("-o,--output", options->output, "Output image: .png or .svg")->required();
  cmd->add_option("--onset-window", options->onset_window,
                  "Align each file on its first onset: frames BEFORE and AFTER it (e.g. "
                  "--onset-window 5 40)")
      ->expected(2);
  cmd->add_option("--title", options->title, "Plot title (default: feature, preset and files)");
  cmd->add_option("FILE", options->features.files, "Audio files (WAV, FLAC, ...)")->required();
  cmd->callback([options] { draw(*options); });
}

}  // namespace echoplan::cli
