// Observation latency of the closed loop: from the end of a recording (the clip in hand) to the
// belief updated with what was heard. Target: <= 5 ms. Results: docs/BENCHMARKS.md.
//
// The clip is a 3 s stereo 44.1 kHz simulated strike (what SimulatedMicrophone hands back); the
// model is trained on 5 simulated recordings per object and action of the report's four objects;
// the belief is the problem's particle filter (1000 particles) on the calibrated problem. The parts
// are timed alone too, so the sum can be checked against the whole.
#include <benchmark/benchmark.h>

#include <atomic>
#include <filesystem>
#include <memory>

#include "../tests/common/source_dir.h"
#include "common/rng.h"
#include "loop/calibrated_problem.h"
#include "loop/object_problem.h"
#include "loop/prepare_observation.h"
#include "perception/clip_analysis.h"
#include "pomdp/particle_belief.h"
#include "pomdp/problem.h"
#include "robot/classifier_service.h"
#include "sim/recording.h"
#include "sim/simulated_robot.h"

namespace {

using namespace echoplan;

struct Fixture {
  sim::Catalogue catalogue =
      sim::load_catalogue(echoplan::testing::source_dir() + "/objects/catalogue.yaml");
  pomdp::Problem base =
      pomdp::load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml");
  std::shared_ptr<const perception::ObservationModel> model;
  pomdp::ModelPtr problem;
  audio::AudioClip clip;

  Fixture() {
    loop::SimulatedTraining training;
    training.catalogue = std::make_shared<const sim::Catalogue>(catalogue);
    training.config = std::make_shared<const sim::SimConfig>();
    training.objects = loop::object_problem(*base.model).data().objects;
    training.actions = {"slide", "strike"};
    training.per_pair = 5;
    training.seed = 1;
    training.directory = std::filesystem::temp_directory_path() / "echoplan_loop_bench";
    const std::atomic<bool> never{false};
    const loop::PreparedObservation prepared =
        loop::prepare_observation(training, &base, "", {}, never);
    std::filesystem::remove_all(training.directory);
    model = prepared.model;
    problem = prepared.problem->model;
    sim::SimulatedRobot robot(catalogue, "coffee_mug", sim::SimConfig{});
    sim::SoundRenderer recorder(robot.object(), robot.table(), sim::SimConfig{});
    Rng rng(12345);
    clip = sim::simulate_recording(robot, recorder, sim::SoundAction::strike, rng).clip;
  }
  int strike() const { return 1; }
  pomdp::Observation symbol(const robot::HeardObservation& heard) const {
    const auto& names = problem->spec().observation.names;
    pomdp::Observation o;
    o.index = static_cast<int>(
        std::find(names.begin(), names.end(), heard.unknown ? "unknown" : heard.label) -
        names.begin());
    return o;
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

// The analysis alone: mono mix, features, onset.
void BM_AnalyseClip(benchmark::State& state) {
  Fixture& f = fixture();
  perception::ClipAnalyzer analyzer(f.model->analysis());
  perception::ClipAnalysis analysis;
  for (auto _ : state) {
    analyzer.analyse(f.clip, "clip", analysis);
    benchmark::DoNotOptimize(analysis.onset_frame);
  }
}
BENCHMARK(BM_AnalyseClip)->Unit(benchmark::kMillisecond);

// The observation service: analysis, classification, calibrated probabilities, the log summary.
void BM_ObserveClip(benchmark::State& state) {
  Fixture& f = fixture();
  robot::ClassifierService service(f.model);
  for (auto _ : state) benchmark::DoNotOptimize(service.observe(f.clip, "strike"));
}
BENCHMARK(BM_ObserveClip)->Unit(benchmark::kMillisecond);

// The belief update with the heard symbol (1000 particles, the problem's filter).
void BM_BeliefUpdate(benchmark::State& state) {
  Fixture& f = fixture();
  robot::ClassifierService service(f.model);
  const pomdp::Observation heard = f.symbol(service.observe(f.clip, "strike"));
  Rng rng(7);
  const pomdp::ParticleBelief prior(f.problem, 1000, rng);
  for (auto _ : state) {
    state.PauseTiming();
    pomdp::ParticleBelief belief = prior;
    state.ResumeTiming();
    benchmark::DoNotOptimize(belief.update(f.strike(), heard, rng));
  }
}
BENCHMARK(BM_BeliefUpdate)->Unit(benchmark::kMillisecond);

// End of recording -> belief updated: observe, map the label to the problem's symbol, update.
void BM_EndOfRecordingToBelief(benchmark::State& state) {
  Fixture& f = fixture();
  robot::ClassifierService service(f.model);
  Rng rng(7);
  const pomdp::ParticleBelief prior(f.problem, 1000, rng);
  for (auto _ : state) {
    state.PauseTiming();
    pomdp::ParticleBelief belief = prior;
    state.ResumeTiming();
    const pomdp::Observation heard = f.symbol(service.observe(f.clip, "strike"));
    benchmark::DoNotOptimize(belief.update(f.strike(), heard, rng));
  }
}
BENCHMARK(BM_EndOfRecordingToBelief)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
