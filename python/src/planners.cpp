// Planners from Python: any solver or baseline strategy by name with its settings, driven step by
// step (reset, improve, best_action, update, the root's action values), and whole trials on a
// problem's own table run by the same loop as `echoplan trials` (loop/loop.h), so the same seed and
// budget give the same decisions.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include "bindings.h"
#include "experiment/expected_reward.h"
#include "interrupt.h"
#include "loop/loop.h"
#include "loop/planner.h"
#include "loop/streams.h"
#include "planner_settings.h"

namespace echoplan::python {

namespace {

// A planner with the problem it plans on and a random stream of its own (used when a call is
// given no `rng`).
struct PythonPlanner {
  ProblemPtr problem;
  loop::Planner planner;
  Rng rng;
};

Rng& rng_or_own(PythonPlanner& p, Rng* rng) { return rng ? *rng : p.rng; }

solvers::Budget budget_of(const PythonPlanner& p, std::optional<std::int64_t> episodes,
                          std::optional<std::int64_t> ms) {
  if (episodes && ms) throw py::value_error("give episodes or ms, not both");
  const solvers::Budget budget = episodes ? solvers::Budget::episodes(*episodes)
                                 : ms     ? solvers::Budget::milliseconds(*ms)
                                          : p.planner.budget;
  if (budget.amount < 1) throw py::value_error("the budget must be at least 1 (episode or ms)");
  return budget;
}

py::dict stats_of(const solvers::SolverStats& s) {
  py::dict d;
  d["episodes_total"] = s.episodes_total;
  d["episodes_last"] = s.episodes_last;
  d["belief_nodes"] = s.belief_nodes;
  d["action_nodes"] = s.action_nodes;
  d["max_depth"] = s.max_depth;
  d["root_particles"] = s.root_particles;
  return d;
}

void bind_planner(py::module_& m) {
  py::class_<PythonPlanner>(
      m, "Planner",
      "A solver or baseline strategy by name, with the problem file's settings unless keyword "
      "arguments override them (the flags of `echoplan trials`): Planner(problem, solver='abt', "
      "episodes=2000, seed=1). Drive it with reset(belief), improve(), best_action() and "
      "update(action, observation, belief).")
      .def(py::init([](ProblemPtr problem, std::uint64_t seed, const py::kwargs& settings) {
             const solvers::PlannerOverrides overrides = planner_overrides(settings);
             loop::Planner planner = loop::make_planner(overrides, *problem, problem->source_path);
             return PythonPlanner{std::move(problem), std::move(planner), Rng(seed)};
           }),
           py::arg("problem"), py::kw_only(), py::arg("seed") = 1, planner_settings_doc())
      .def_property_readonly("name", [](const PythonPlanner& p) { return p.planner.name; })
      .def_property_readonly(
          "rng", [](PythonPlanner& p) -> Rng& { return p.rng; },
          py::return_value_policy::reference_internal,
          "The planner's own random stream (used when a call gets no rng).")
      .def("describe", [](const PythonPlanner& p) { return p.planner.describe(); })
      .def_property_readonly(
          "settings", [](const PythonPlanner& p) { return to_python(p.planner.to_json()); },
          "Solver, budget per step and search options, as summary.json says.")
      .def(
          "reset",
          [](PythonPlanner& p, const BeliefHandle& belief, Rng* rng) {
            p.planner.solver->reset(*belief.belief, rng_or_own(p, rng));
          },
          py::arg("belief"), py::arg("rng") = py::none(),
          "Discards any tree and roots a new one at `belief`.")
      .def(
          "improve",
          [](PythonPlanner& p, std::optional<std::int64_t> episodes, std::optional<std::int64_t> ms,
             Rng* rng) {
            const solvers::Budget budget = budget_of(p, episodes, ms);
            Rng& r = rng_or_own(p, rng);
            py::gil_scoped_release release;  // bounded by its budget: no stop flag needed
            p.planner.solver->improve(budget, r);
          },
          py::kw_only(), py::arg("episodes") = py::none(), py::arg("ms") = py::none(),
          py::arg("rng") = py::none(),
          "Searches from the root: `episodes` episodes (the same every run) or `ms` milliseconds "
          "of wall time; neither: the planner's budget per step.")
      .def(
          "best_action", [](const PythonPlanner& p) { return p.planner.solver->best_action(); },
          "The root action with the highest estimated value (after at least one improve()).")
      .def(
          "action_values",
          [](const PythonPlanner& p) { return to_array(p.planner.solver->root_action_values()); },
          "The root's estimated value of each action (NaN for actions never tried).")
      .def(
          "update",
          [](PythonPlanner& p, py::handle action, py::handle observation,
             const BeliefHandle& belief_after, Rng* rng) {
            const pomdp::Model& model = *p.problem->model;
            p.planner.solver->update(action_index(model, action),
                                     to_observation(model, observation), *belief_after.belief,
                                     rng_or_own(p, rng));
          },
          py::arg("action"), py::arg("observation"), py::arg("belief_after"),
          py::arg("rng") = py::none(),
          "After acting and hearing: the child for (action, observation) becomes the root; "
          "`belief_after` (already updated) tops it up when it holds too few particles.")
      .def("stats", [](const PythonPlanner& p) { return stats_of(p.planner.solver->stats()); });
}

void bind_records(py::module_& m) {
  py::class_<loop::StepRecord>(m, "StepRecord", "One decision as steps.csv logs it.")
      .def_readonly("trial", &loop::StepRecord::trial)
      .def_readonly("step", &loop::StepRecord::step)
      .def_readonly("action", &loop::StepRecord::action)
      .def_readonly("observation", &loop::StepRecord::observation)
      .def_property_readonly(
          "belief", [](const loop::StepRecord& r) { return to_array(r.belief); },
          "The belief the action was chosen from (over the objects).")
      .def_readonly("reward", &loop::StepRecord::reward)
      .def_readonly("episodes", &loop::StepRecord::episodes)
      .def_readonly("heard_probability", &loop::StepRecord::heard_probability);
  py::class_<loop::TrialRecord>(m, "TrialRecord", "One trial as trials.csv logs it.")
      .def_readonly("trial", &loop::TrialRecord::trial)
      .def_readonly("true_state", &loop::TrialRecord::true_state)
      .def_readonly("believed_state", &loop::TrialRecord::believed_state)
      .def_readonly("steps", &loop::TrialRecord::steps)
      .def_readonly("action_counts", &loop::TrialRecord::action_counts)
      .def_readonly("discounted_reward", &loop::TrialRecord::discounted_reward)
      .def_readonly("collision", &loop::TrialRecord::collision)
      .def_readonly("capped", &loop::TrialRecord::capped);
  py::class_<loop::Step>(m, "Step",
                         "One real step: the decision, the belief after, the robot's part.")
      .def_readonly("record", &loop::Step::record)
      .def_property_readonly("action", [](const loop::Step& s) { return s.record.action; })
      .def_property_readonly("observation",
                             [](const loop::Step& s) { return s.record.observation; })
      .def_property_readonly("reward", [](const loop::Step& s) { return s.record.reward; })
      .def_property_readonly("belief_after",
                             [](const loop::Step& s) -> py::object {
                               if (!s.belief_after) return py::none();
                               return to_array(*s.belief_after);
                             })
      .def_readonly("robot", &loop::Step::robot,
                    "In a world with a robot: its report, clip, heard.")
      .def_readonly("terminal", &loop::Step::terminal);
  py::class_<loop::Trial>(m, "Trial", "A finished trial: its record and its steps.")
      .def_readonly("record", &loop::Trial::record)
      .def_readonly("steps", &loop::Trial::steps);
}

// Trials on the problem's own table, as `echoplan trials` runs them (apps/echoplan/commands/
// trials.cpp): trial t's true object is drawn (or the t / per_object-th object), every stream comes
// from (seed, t).
std::vector<loop::Trial> run_trials(const ProblemPtr& problem, int trials, int per_object,
                                    std::uint64_t seed, int max_steps, const py::kwargs& settings) {
  loop::LoopSettings s;
  s.problem = problem;
  s.planner = planner_overrides(settings);
  s.max_steps = max_steps;
  auto loop = std::make_shared<loop::Loop>(std::make_shared<const loop::LoopSpec>(std::move(s)));
  loop::TrialOptions options;
  options.trials = trials;
  options.per_object = per_object;
  options.budget = loop->planner().budget;
  options.max_steps = max_steps;
  options.validate();
  const int total = options.total_trials(problem->model->spec());
  return run_interruptibly([&](const std::atomic<bool>& stop) {
    std::vector<loop::Trial> done;
    for (int t = 0; t < total; ++t) {
      auto trial = loop->run({t, options.object_of_trial(t), seed}, {}, &stop);
      if (!trial) break;
      done.push_back(std::move(*trial));
    }
    return done;
  });
}

}  // namespace

void bind_planners(py::module_& m) {
  bind_planner(m);
  bind_records(m);
  m.def("run_trials", &run_trials, py::arg("problem"), py::kw_only(), py::arg("trials") = 40,
        py::arg("per_object") = 0, py::arg("seed") = 1, py::arg("max_steps") = 100,
        (std::string("Planning trials on the problem's own table, exactly as `echoplan trials` "
                     "runs them: the same seed and episode budget give the same decisions. "
                     "per_object=K runs K trials per object instead of `trials` drawn ones. "
                     "Returns a list of Trial. Ctrl-C stops after the step in progress.\n") +
         planner_settings_doc())
            .c_str());
  m.def(
      "expected_reward",
      [](const ProblemPtr& problem, const loop::Trial& trial) -> py::object {
        const pomdp::TabularModel* tables = problem->model->tabular();
        if (tables == nullptr)
          throw py::value_error("expected_reward needs a discrete problem with tables");
        std::vector<loop::StepRecord> steps;
        for (const loop::Step& s : trial.steps) steps.push_back(s.record);
        const auto value = experiment::expected_discounted_reward(steps, *tables);
        if (!value) return py::none();
        return py::float_(*value);
      },
      py::arg("problem"), py::arg("trial"),
      "The trial's rewards in expectation under the beliefs its actions were chosen from, "
      "discounted (experiment/expected_reward.h): with an exact belief (the problem's `belief: "
      "{type: exact}`) and the model as the world, the same mean over trials as "
      "record.discounted_reward with less variance, as `echoplan trials` reports it. None when a "
      "step's belief does not fit the problem's states.");
  m.def(
      "stream_seed",
      [](std::uint64_t seed, const std::string& stream) {
        if (stream == "run_trial") return loop::stream_seed(seed, loop::Stream::run_trial);
        if (stream == "run_training") return loop::stream_seed(seed, loop::Stream::run_training);
        throw py::value_error("stream '" + stream + "' is not one of run_trial, run_training");
      },
      py::arg("seed"), py::arg("stream"),
      "The seed `echoplan run --seed S` gives a stream (loop/streams.h): stream_seed(S, "
      "'run_trial') is its trial's seed.");
}

}  // namespace echoplan::python
