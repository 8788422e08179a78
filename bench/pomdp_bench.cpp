// Speed of what solvers and the execution loop call most: the model's step and observation
// likelihood, and belief updates. Results: docs/BENCHMARKS.md, section "pomdp".
#include <benchmark/benchmark.h>

#include <memory>

#include "../tests/common/source_dir.h"
#include "pomdp/exact_belief.h"
#include "pomdp/particle_belief.h"
#include "pomdp/problem.h"
#include "pomdp/random_problem.h"

namespace {

using namespace echoplan;
using namespace echoplan::pomdp;

// range(0) = number of objects: 4 is the report's problem, larger ones are random problems.
ModelPtr object_model(int objects) {
  if (objects == 4)
    return load_problem(echoplan::testing::source_dir() + "/problems/audio_objects.yaml").model;
  Rng rng(1);
  return std::make_shared<const ObjectIdentificationModel>(
      make_random_object_problem(RandomProblemSettings{objects, 4, 1.5, 1}, rng));
}

void BM_ObjectModelStep(benchmark::State& st) {
  const ModelPtr model = object_model(static_cast<int>(st.range(0)));
  Rng rng(2);
  State s = model->sample_initial_state(rng);
  int action = 0;
  for (auto _ : st) {
    StepResult r = model->step(s, action, rng);
    benchmark::DoNotOptimize(r);
    action ^= 1;  // alternate the first two sensing actions
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_ObjectModelStep)->Arg(4)->Arg(16)->Arg(64);

void BM_ObjectModelLikelihood(benchmark::State& st) {
  const ModelPtr model = object_model(static_cast<int>(st.range(0)));
  Rng rng(3);
  const State s = model->sample_initial_state(rng);
  const Observation o{1, {}};
  double sum = 0.0;
  for (auto _ : st) {
    sum += model->observation_likelihood(s, 1, o);
    benchmark::DoNotOptimize(sum);
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_ObjectModelLikelihood)->Arg(4)->Arg(16)->Arg(64);

// One SIR update of the report's 1000-particle belief (propagate, weight, resample, and the fresh
// particles replayed through the history against depletion), averaged over trials of 10 updates:
// the fresh particles' cost grows with the history, so the belief starts over every 10 updates
// (outside the timing). `fresh_share` 0 is plain SIR, the baseline.
void particle_belief_update(benchmark::State& st, double fresh_share) {
  const ModelPtr model = object_model(static_cast<int>(st.range(0)));
  Rng rng(4);
  auto belief = std::make_unique<ParticleBelief>(model, 1000, rng, fresh_share);
  int step = 0;
  for (auto _ : st) {
    if (step % 10 == 0) {
      st.PauseTiming();
      belief = std::make_unique<ParticleBelief>(model, 1000, rng, fresh_share);
      st.ResumeTiming();
    }
    belief->update(step % 2, Observation{step % 3, {}}, rng);
    ++step;
  }
  st.SetItemsProcessed(st.iterations() * 1000);
}
void BM_ParticleBeliefUpdate(benchmark::State& st) {
  particle_belief_update(st, ParticleBelief::kDefaultFreshShare);
}
void BM_ParticleBeliefUpdatePlainSir(benchmark::State& st) { particle_belief_update(st, 0.0); }
BENCHMARK(BM_ParticleBeliefUpdate)->Arg(4)->Arg(16)->Arg(64);
BENCHMARK(BM_ParticleBeliefUpdatePlainSir)->Arg(4)->Arg(16)->Arg(64);

void BM_ExactBeliefUpdate(benchmark::State& st) {
  const ModelPtr model = object_model(static_cast<int>(st.range(0)));
  Rng rng(5);
  ExactBelief belief(model);
  int step = 0;
  for (auto _ : st) {
    belief.update(step % 2, Observation{step % 3, {}}, rng);
    ++step;
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_ExactBeliefUpdate)->Arg(4)->Arg(16)->Arg(64);

}  // namespace

BENCHMARK_MAIN();
