// Simulator speed: one 3 s stereo recording (physics + synthesis), and each half alone.
// Results and the command: docs/BENCHMARKS.md, section "Simulator".
#include <benchmark/benchmark.h>

#include <string>

#include "../tests/common/source_dir.h"
#include "sim/recording.h"

namespace {

using echoplan::sim::SimConfig;

const echoplan::sim::Catalogue& catalogue() {
  static const auto c =
      echoplan::sim::load_catalogue(echoplan::testing::source_dir() + "/objects/catalogue.yaml");
  return c;
}

const char* kObjects[] = {"coffee_mug", "pringles_can", "plastic_cup", "paper_base"};
const echoplan::sim::SoundAction kActions[] = {echoplan::sim::SoundAction::slide,
                                               echoplan::sim::SoundAction::strike};

// Whole recording: execute the action in MuJoCo and synthesize 3 s of stereo audio. The robot (its
// compiled scene) is built once, as a running robot would be.
void BM_Recording(benchmark::State& state) {
  const char* object = kObjects[state.range(0)];
  const echoplan::sim::SoundAction action = kActions[state.range(1)];
  const SimConfig config;
  echoplan::sim::SimulatedRobot robot(catalogue(), object, config);
  echoplan::sim::SoundRenderer recorder(robot.object(), robot.table(), config);
  std::uint64_t seed = 0;
  double audio_seconds = 0;
  for (auto _ : state) {
    echoplan::Rng rng(++seed);
    auto r = echoplan::sim::simulate_recording(robot, recorder, action, rng);
    audio_seconds = r.clip.duration_seconds();
    benchmark::DoNotOptimize(r.clip.samples.data());
  }
  state.SetLabel(std::string(object) + "/" + to_string(action));
  state.counters["audio_s_per_s"] =
      benchmark::Counter(audio_seconds * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Recording)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMillisecond);

void BM_PhysicsOnly(benchmark::State& state) {
  const SimConfig config;
  echoplan::sim::SimulatedRobot robot(catalogue(), kObjects[0], config);
  std::uint64_t seed = 0;
  for (auto _ : state) {
    echoplan::Rng rng(++seed);
    // A new trial each time, as a recording's: repeated slides without one push the object out of
    // reach after a few, and an action out of reach returns at once.
    robot.reset_trial(rng);
    benchmark::DoNotOptimize(robot.execute(kActions[state.range(0)], rng));
  }
  state.SetLabel(std::string("coffee_mug/") + to_string(kActions[state.range(0)]));
}
BENCHMARK(BM_PhysicsOnly)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_SynthesisOnly(benchmark::State& state) {
  const SimConfig config;
  echoplan::sim::SimulatedRobot robot(catalogue(), kObjects[0], config);
  echoplan::sim::SoundRenderer recorder(robot.object(), robot.table(), config);
  echoplan::Rng rng(1);
  const auto outcome = robot.execute(kActions[state.range(0)], rng);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        recorder.render(outcome.trace, outcome.duration_s, rng).samples.data());
  state.SetLabel(std::string("coffee_mug/") + to_string(kActions[state.range(0)]));
}
BENCHMARK(BM_SynthesisOnly)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// Baseline for the ratio: compiling the scene once (paid per object, not per recording).
void BM_SceneCompile(benchmark::State& state) {
  const SimConfig config;
  for (auto _ : state)
    benchmark::DoNotOptimize(echoplan::sim::SimulatedRobot(catalogue(), kObjects[0], config));
}
BENCHMARK(BM_SceneCompile)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
