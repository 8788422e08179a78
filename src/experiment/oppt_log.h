// Another planner's runs as echoplan's records: the run logs OPPT (the ABT planner of the original
// robot) writes, parsed, and turned into the trial and step records that steps.csv and trials.csv
// hold, so that `echoplan certify` certifies an OPPT run (`echoplan import oppt`).
//
// The format (docs/planning.md, "Certifying another planner's run"; the reference on the original
// robot's runs describes it): a file holds several runs, each "Run #N", then its steps, each
// "t = N" with
//   S: <state numbers> <object> w: ... END ...   the true state; its last number is the object
//   A: <code> END                                the action taken
//   O: <code> END                                what was heard after it
//   IMMEDIATE_REWARD: r, DISCOUNT_FACTOR: g (the accumulated discount, not the problem's),
//   DISCOUNTED_REWARD: g r
//   PARTICLES BEGIN / p: <state numbers> <object> w: ... / PARTICLES END
//       the belief after this step's observation, i.e. the one the next decision saw (may be
//       empty: none was saved)
//   SOLVER_DATA_BEGIN / NUM HISTORIES: n / ... / SOLVER_DATA_END
// and ends with "Total discounted reward: x", "Run successful: ..." (OPPT's own flag, which says
// nothing about the sort), "Num steps: n". Other lines (the file's header, timings, the final
// state) are skipped. Codes are OPPT's numbers; OpptCodes maps them to a problem's names.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "experiment/trial_records.h"
#include "pomdp/problem.h"

namespace echoplan::experiment {

// One logged step, with OPPT's codes.
struct OpptStep {
  int t = 0;
  int line = 0;  // 1-based line of its "t = " in the log
  int action = 0;
  int observation = 0;
  int true_object = 0;  // the last number of "S:"
  double immediate_reward = 0.0;
  std::optional<double> discount_factor;    // accumulated: the problem's discount to the power t
  std::optional<double> discounted_reward;  // as logged
  long long histories = 0;                  // NUM HISTORIES: the search tree's episodes
  // Particles logged after this step, counted per object code; none when no block followed.
  std::optional<std::map<int, int>> particles_after;
  int particles_line = 0;  // line of its "PARTICLES BEGIN", for messages
};

// One logged run: its steps in order, the duplicated last step dropped.
struct OpptRun {
  int number = 0;  // N of "Run #N"
  int line = 0;    // line of "Run #N"
  std::vector<OpptStep> steps;
  double total_discounted_reward = 0.0;  // as logged
  std::optional<int> num_steps;          // "Num steps:", checked against steps.size()
};

// Parses one log's text; `file` names it in errors. Throws InputError(file, line, problem) for a
// step before any "Run #", a non-number, a field missing from a step, a block or field without its
// END, a step out of order, a run with no steps or cut off before "Total discounted reward", a
// "Num steps" that disagrees, or a file with no run.
std::vector<OpptRun> parse_oppt_log(const std::string& text, const std::string& file);

// OPPT's codes as indices into a problem: actions, observations and objects (values of discrete
// state variable 0).
struct OpptCodes {
  std::map<int, int> actions, observations, objects;
};

// Reads "CODE=NAME,CODE=NAME,..." (one flag's value) against `names`; `flag` ("--actions") names it
// in the InputError for a malformed pair, a repeated code or a name not in `names`.
std::map<int, int> parse_code_mapping(const std::string& text,
                                      const std::vector<std::string>& names,
                                      const std::string& flag);

// Where each imported step's belief came from (see oppt_run_records).
struct BeliefSources {
  int initial = 0;    // step 0: the problem's initial belief
  int particles = 0;  // the particles logged after the previous step
  int exact = 0;      // an empty block: the problem's exact belief after the logged history
};

// One run as echoplan's records, numbered `trial`. Each step's belief (particle counts out of the
// problem's `belief.particles`, as TrialLog writes them) is the one that decision saw: at step 0
// the problem's initial belief (the log has no particles before the first decision); after that the
// particles logged after the previous step, counted per object; when that block is empty the
// problem's exact Bayes belief after the logged actions and observations (OPPT's own update is not
// in the log), counted in `sources`. Rewards are the logged immediate rewards; the trial's
// discounted reward is recomputed with the problem's discount. Throws InputError naming `file`, the
// line and the flag for a code without a mapping.
TrialResult oppt_run_records(const OpptRun& run, const OpptCodes& codes,
                             const pomdp::Problem& problem, int trial, const std::string& file,
                             BeliefSources& sources);

}  // namespace echoplan::experiment
