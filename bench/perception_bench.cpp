// Observation-model speed (docs/BENCHMARKS.md): latency from a finished 3 s recording to its
// observation (analysis + classification, one core), and training time for 80 clips, for each
// classifier.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "../tests/perception/synthetic_sounds.h"
#include "perception/classifier.h"
#include "perception/clip_analysis.h"
#include "perception/observation_model.h"

namespace {

namespace fs = std::filesystem;
using echoplan::perception::test_sounds::strike;
using echoplan::perception::test_sounds::three_objects;

// 4 objects x 2 actions x `per_pair` synthetic 3 s recordings (leading zeros, noise, random force).
fs::path write_set(int per_pair) {
  const fs::path dir =
      echoplan::perception::test_sounds::fresh_dir("bench" + std::to_string(per_pair));
  auto objects = three_objects();
  objects.push_back({{600.0, 0.4, 0.5}, {1500.0, 0.2, 0.3}});
  for (std::size_t k = 0; k < objects.size(); ++k)
    for (const std::string action : {"strike", "slide"})
      for (int i = 0; i < per_pair; ++i) {
        const unsigned seed = static_cast<unsigned>(1000 * k + 10 * i + (action == "slide"));
        const auto clip = strike(objects[k], {.duration_s = 3.0,
                                              .leading_zeros_s = 0.35,
                                              .onset_s = 0.8,
                                              .gain = 0.2 + 0.06 * i,
                                              .noise_rms = 0.001,
                                              .detune = 0.02,
                                              .seed = seed});
        const fs::path path =
            dir / ("object" + std::to_string(k)) / action / (std::to_string(i) + ".wav");
        fs::create_directories(path.parent_path());
        echoplan::audio::write_audio(path.string(), clip);
      }
  return dir;
}

const std::vector<std::string>& names() {
  static const auto n = echoplan::perception::classifier_names();
  return n;
}

void BM_RecordingToObservation(benchmark::State& state) {
  static const fs::path dir = write_set(3);
  echoplan::perception::FitOptions options;
  options.classifier = names()[static_cast<std::size_t>(state.range(0))];
  const auto model = echoplan::perception::train_observation_model(
      echoplan::perception::load_recording_set(dir.string()), options);
  const auto clip = strike(three_objects()[1], {.duration_s = 3.0,
                                                .leading_zeros_s = 0.35,
                                                .onset_s = 0.9,
                                                .gain = 0.4,
                                                .noise_rms = 0.001,
                                                .seed = 99});
  // What the observation service does per clip: analyse, then classify.
  echoplan::perception::ClipAnalyzer analyzer(model.analysis());
  echoplan::perception::ClipAnalysis analysis;
  for (auto _ : state) {
    analyzer.analyse(clip, "clip", analysis);
    benchmark::DoNotOptimize(model.classify(analysis, "strike"));
  }
  state.SetLabel(options.classifier);
}
BENCHMARK(BM_RecordingToObservation)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

void BM_Train80Clips(benchmark::State& state) {
  static const fs::path dir = write_set(10);  // 4 objects x 2 actions x 10 = 80 clips
  echoplan::perception::FitOptions options;
  options.classifier = names()[static_cast<std::size_t>(state.range(0))];
  const auto set = echoplan::perception::load_recording_set(dir.string());
  for (auto _ : state)
    benchmark::DoNotOptimize(echoplan::perception::train_observation_model(set, options));
  state.SetLabel(options.classifier);
}
BENCHMARK(BM_Train80Clips)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
