// The exact identification solver (solvers/identification_solver.h) and the regret certificate
// of logged steps (experiment/regret_certificate.h) from Python: the numbers `echoplan solve` and
// `echoplan certify` print, for a problem and a run held in Python or on disk.
#include <pybind11/stl.h>

#include "bindings.h"
#include "common/error.h"
#include "experiment/regret_certificate.h"
#include "experiment/trial_log.h"
#include "interrupt.h"
#include "loop/trial_runner.h"
#include "solvers/identification_solver.h"
#include "solvers/use_limits.h"

namespace echoplan::python {

namespace {

// The solver with the problem's use limits, as `echoplan solve` and `certify` build it; InputError
// naming the problem when it is not an identification problem.
struct ExactSolver {
  ProblemPtr problem;
  std::unique_ptr<solvers::IdentificationSolver> solver;

  explicit ExactSolver(ProblemPtr p) : problem(std::move(p)) {
    const pomdp::TabularModel* tables = problem->model->tabular();
    if (!tables)
      throw InputError(problem->source_path, 0, "the exact solver needs a problem with tables");
    if (auto why = solvers::identification_shape_problem(*tables))
      throw InputError(problem->source_path, 0,
                       "the exact solver needs an identification problem (the state stays fixed "
                       "until an action ends the episode), and this one is not: " +
                           *why);
    solver = std::make_unique<solvers::IdentificationSolver>(
        solvers::read_identification_tables(*tables, solvers::UseLimits(*problem->model)));
  }
};

py::tuple bounds(const solvers::Bounds& b) { return py::make_tuple(b.lower, b.upper); }

solvers::RefineLimits limits(double gap, double seconds, long expansions) {
  solvers::RefineLimits l;
  l.target_gap = gap;
  l.seconds = seconds;
  l.expansions = expansions;
  return l;
}

void bind_exact_solver(py::module_& m) {
  using Node = solvers::IdentificationSolver::NodeId;
  py::class_<ExactSolver>(
      m, "ExactSolver",
      "Sound bounds on V* and Q* of an identification problem (the exact solver of `echoplan "
      "solve`). Nodes are beliefs reached by counts of (sensing action, observation): root is "
      "b0, child(node, action, observation) the belief after one more.")
      .def(py::init<ProblemPtr>(), py::arg("problem"))
      .def_property_readonly("root", [](const ExactSolver& s) { return s.solver->root(); })
      .def(
          "child",
          [](ExactSolver& s, Node node, py::handle a, py::handle o) {
            const pomdp::Model& model = *s.problem->model;
            return s.solver->child(node, action_index(model, a), to_observation(model, o).index);
          },
          py::arg("node"), py::arg("action"), py::arg("observation"),
          "The node after sensing `action` heard `observation` (-1: the episode ended).")
      .def(
          "value", [](const ExactSolver& s, Node node) { return bounds(s.solver->value(node)); },
          py::arg("node"), "(lower, upper) bounds on V* at the node.")
      .def(
          "action_value",
          [](const ExactSolver& s, Node node, py::handle a) {
            return bounds(s.solver->action_value(node, action_index(*s.problem->model, a)));
          },
          py::arg("node"), py::arg("action"), "(lower, upper) bounds on Q*(node, action).")
      .def(
          "belief",
          [](const ExactSolver& s, Node node) { return to_array(s.solver->belief(node)); },
          py::arg("node"))
      .def(
          "refine",
          [](ExactSolver& s, Node node, double gap, double seconds, long expansions) {
            py::gil_scoped_release release;
            return s.solver->refine(node, limits(gap, seconds, expansions));
          },
          py::arg("node"), py::kw_only(), py::arg("target_gap") = 1e-4, py::arg("seconds") = 0.0,
          py::arg("expansions") = 0,
          "Tightens V* at the node to `target_gap` or until a limit (seconds, node expansions; "
          "0: none). True when the target was reached; the bounds are valid either way.")
      .def(
          "refine_action",
          [](ExactSolver& s, Node node, py::handle a, double gap, double seconds, long expansions) {
            const int action = action_index(*s.problem->model, a);
            py::gil_scoped_release release;
            return s.solver->refine_action(node, action, limits(gap, seconds, expansions));
          },
          py::arg("node"), py::arg("action"), py::kw_only(), py::arg("target_gap") = 1e-4,
          py::arg("seconds") = 0.0, py::arg("expansions") = 0)
      .def_property_readonly("expansions",
                             [](const ExactSolver& s) { return s.solver->expansions(); })
      .def_property_readonly("num_nodes",
                             [](const ExactSolver& s) { return s.solver->num_nodes(); });
}

// Trials held in Python (from run_trials or a loop) as the logged history certify reads.
std::vector<experiment::LoggedTrial> logged(const std::vector<loop::Trial>& trials) {
  std::vector<experiment::LoggedTrial> out;
  for (const loop::Trial& t : trials) {
    experiment::LoggedTrial& l = out.emplace_back();
    l.trial = t.record.trial;
    for (const loop::Step& s : t.steps)
      l.steps.push_back(
          {s.record.step, s.record.action, s.record.observation.index, s.record.reward, 0});
  }
  return out;
}

py::dict certificate_dict(const experiment::Certificate& c) {
  py::dict d;
  d["vstar_lower"] = c.vstar.lower;
  d["vstar_upper"] = c.vstar.upper;
  d["regret_mean"] = c.regret.mean;
  d["regret_ci95"] = c.regret.half_width;
  d["trials"] = c.regret.n;
  d["regret_lower_mean"] = c.regret_lower_mean;
  d["bound_gap_mean"] = c.bound_gap_mean;
  d["share_of_vstar"] = c.share_of_vstar();
  d["decisions"] = c.decisions;
  d["unconverged_beliefs"] = c.unconverged_beliefs;
  py::list per_trial;
  for (const auto& t : c.trials) per_trial.append(t.regret);
  d["trial_regrets"] = per_trial;
  py::list worst;
  for (const auto& w : c.worst) {
    py::dict x;
    x["trial"] = w.trial;
    x["step"] = w.step;
    x["action"] = w.action;
    x["best_action"] = w.best_action;
    x["loss"] = w.loss;
    x["belief"] = to_array(w.belief);
    worst.append(x);
  }
  d["worst"] = worst;
  return d;
}

// The certificate of `steps`: a steps.csv path, or trials held in Python.
py::dict certify(const ProblemPtr& problem, py::handle steps, double gap, long expansions,
                 long root_expansions, int worst) {
  if (!(gap > 0.0)) throw InputError("gap must be > 0");
  if (expansions < 1) throw InputError("expansions must be >= 1");
  ExactSolver exact(problem);
  std::string file = "<trials>";
  std::vector<experiment::LoggedTrial> trials;
  if (py::isinstance<py::str>(steps) || py::hasattr(steps, "__fspath__")) {
    file = py::str(py::module_::import("os").attr("fspath")(steps)).cast<std::string>();
    trials = experiment::read_steps_csv(file, problem->model->spec());
  } else {
    trials = logged(steps.cast<std::vector<loop::Trial>>());
  }
  if (trials.empty()) throw InputError(file, 0, "no trials to certify");
  experiment::CertifyOptions options;
  options.decision_gap = gap;
  options.expansions_per_belief = expansions;
  options.root_expansions = root_expansions;
  options.worst = worst;
  experiment::Certificate c;
  {
    py::gil_scoped_release release;
    c = experiment::certify_trials(*exact.solver, trials, options, file);
  }
  return certificate_dict(c);
}

}  // namespace

void bind_exact(py::module_& m) {
  bind_exact_solver(m);
  const experiment::CertifyOptions defaults;
  m.def("certify", &certify, py::arg("problem"), py::arg("steps"), py::kw_only(),
        py::arg("gap") = defaults.decision_gap,
        py::arg("expansions") = defaults.expansions_per_belief,
        py::arg("root_expansions") = defaults.root_expansions, py::arg("worst") = 5,
        "The regret certificate of logged decisions, as `echoplan certify --json` computes it: "
        "`steps` is a steps.csv path or a list of Trial (run_trials, Loop.run). Returns a dict "
        "with vstar_lower, vstar_upper, regret_mean, regret_ci95, trials, share_of_vstar, "
        "bound_gap_mean, decisions, trial_regrets, worst, ...");
}

}  // namespace echoplan::python
