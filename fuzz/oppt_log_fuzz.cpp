// libFuzzer target: arbitrary bytes as an OPPT run log (`echoplan import oppt`), parsed and turned
// into records against the seed problem with the report's code mappings. Bad input must end in
// echoplan::InputError; anything else (a crash, a sanitizer report, another exception, a hang) is a
// bug. Seeds: any OPPT-layout log, e.g. the ones tests/apps/import_cli_test.sh writes.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "experiment/oppt_log.h"
#include "pomdp/problem.h"

namespace {

// The seed problem, written inline so the target needs no files.
const echoplan::pomdp::Problem& seed_problem() {
  static const echoplan::pomdp::Problem problem = echoplan::pomdp::parse_problem_yaml(R"(
name: audio_objects
discount: 0.99
objects: [pringles_can, coffee_mug, plastic_cup, paper_base]
actions:
  sensing: [slide, strike]
  sorting: [move_to_A, move_to_B]
initial_belief:
  type: fixed_configuration
  joints: [-2.89527, 1.45058, -0.18396, 2.07696, -0.310356, 0.630897, -1.54233]
  offset: [0.1, 0, 0]
  objects: uniform
transition:
  type: kinematic
  offset_change:
    slide: [0.05, 0, 0]
    strike: [0, 0, 0]
  collision_probability:
    slide: 0
    strike: 0
observation:
  type: table
  symbols: [pringles_can, coffee_mug, plastic_cup, paper_base]
  table:
    slide:
      pringles_can: [0.5, 0.3, 0.15, 0.05]
      coffee_mug: [0.11, 0.67, 0.11, 0.11]
      plastic_cup: [0.11, 0.11, 0.67, 0.11]
      paper_base: [0.01, 0.01, 0.48, 0.5]
    strike:
      pringles_can: [0.6, 0.05, 0.3, 0.05]
      coffee_mug: [0.05, 0.6, 0.3, 0.05]
      plastic_cup: [0.11, 0.11, 0.67, 0.11]
      paper_base: [0.11, 0.11, 0.11, 0.67]
reward:
  sensing: {slide: -1, strike: -1}
  sorting:
    move_to_A: {pringles_can: 10, coffee_mug: -100, plastic_cup: 10, paper_base: -100}
    move_to_B: {pringles_can: -100, coffee_mug: 10, plastic_cup: -100, paper_base: 10}
  collision: -100
terminal:
  type: sorting_or_collision
heuristic:
  type: known_object
)",
                                                                                      "fuzz.yaml");
  return problem;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace echoplan;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const pomdp::Problem& problem = seed_problem();
  const pomdp::ModelSpec& spec = problem.model->spec();
  experiment::OpptCodes codes;
  codes.actions = experiment::parse_code_mapping("4=slide,5=strike,6=move_to_A,7=move_to_B",
                                                 spec.action_names, "--actions");
  codes.observations = experiment::parse_code_mapping(
      "0=pringles_can,1=coffee_mug,2=plastic_cup,3=paper_base,5=none", spec.observation.names,
      "--observations");
  codes.objects =
      experiment::parse_code_mapping("0=pringles_can,1=coffee_mug,2=plastic_cup,3=paper_base",
                                     spec.state.discrete_value_names[0], "--objects");
  try {
    experiment::BeliefSources sources;
    int trial = 0;
    for (const experiment::OpptRun& run : experiment::parse_oppt_log(text, "fuzz.log")) {
      if (run.steps.empty()) __builtin_trap();
      const experiment::TrialResult t =
          experiment::oppt_run_records(run, codes, problem, trial++, "fuzz.log", sources);
      if (t.steps.size() != run.steps.size() || t.record.true_state < 0 || t.record.true_state >= 4)
        __builtin_trap();
    }
  } catch (const InputError&) {
  }
  return 0;
}
