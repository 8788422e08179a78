// Search speed of the online solvers: episodes per second of ABT and POMCP growing a fresh tree
// from the initial belief of a problem file (the cost of a planning step's first episodes).
//
//   build/bench/planner_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "../tests/common/source_dir.h"
#include "pomdp/make_belief.h"
#include "pomdp/problem.h"
#include "solvers/make_solver.h"

namespace {

using namespace echoplan;

void search_from_b0(benchmark::State& state, const char* problem_file, const char* solver_name,
                    bool keep_episodes = false) {
  const pomdp::Problem problem =
      pomdp::load_problem(echoplan::testing::source_dir() + "/" + problem_file);
  solvers::SearchOptions options;
  options.max_depth = problem.planner.depth;
  options.keep_episodes = keep_episodes;
  auto solver = solvers::make_solver(solver_name, problem.model, options);
  Rng rng(1);
  const pomdp::BeliefPtr belief = pomdp::make_belief(problem, rng);
  const std::int64_t episodes = state.range(0);
  for (auto _ : state) {
    // Each iteration plans one step from scratch: reset (root particles) plus the episodes.
    solver->reset(*belief, rng);
    solver->improve(solvers::Budget::episodes(episodes), rng);
    benchmark::DoNotOptimize(solver->best_action());
  }
  state.SetItemsProcessed(state.iterations() * episodes);  // items/s = episodes per second
}

void abt_audio_objects(benchmark::State& s) {
  search_from_b0(s, "problems/audio_objects.yaml", "abt");
}
// ABT as published: every episode's steps kept for revision after a model change.
void abt_audio_objects_keeping_episodes(benchmark::State& s) {
  search_from_b0(s, "problems/audio_objects.yaml", "abt", true);
}
void pomcp_audio_objects(benchmark::State& s) {
  search_from_b0(s, "problems/audio_objects.yaml", "pomcp");
}
void abt_tiger(benchmark::State& s) { search_from_b0(s, "problems/tiger.pomdp", "abt"); }
void pomcp_tiger(benchmark::State& s) { search_from_b0(s, "problems/tiger.pomdp", "pomcp"); }

BENCHMARK(abt_audio_objects)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(abt_audio_objects_keeping_episodes)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(pomcp_audio_objects)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(abt_tiger)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(pomcp_tiger)->Arg(10000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
