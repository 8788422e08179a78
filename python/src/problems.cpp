// Problems, models and beliefs from Python: the random engine every call draws from, a problem
// loaded from a file or text (echoplan/__init__.py builds one from dicts through the text), its
// checks, the model's generative step and likelihood, its tables as arrays, and the two beliefs.
#include <pybind11/stl.h>

#include <sstream>
#include <stdexcept>

#include "bindings.h"
#include "pomdp/exact_belief.h"
#include "pomdp/make_belief.h"
#include "pomdp/particle_belief.h"
#include "pomdp/problem_check.h"

namespace echoplan::python {

namespace {

// derive_seed takes its streams as an initializer list (a fixed number at each call site); the
// few lengths Python callers need are spelled out here so the one implementation is used.
std::uint64_t derive_seed_of(std::uint64_t seed, const std::vector<std::uint64_t>& s) {
  switch (s.size()) {
    case 0:
      return derive_seed(seed, {});
    case 1:
      return derive_seed(seed, {s[0]});
    case 2:
      return derive_seed(seed, {s[0], s[1]});
    case 3:
      return derive_seed(seed, {s[0], s[1], s[2]});
    case 4:
      return derive_seed(seed, {s[0], s[1], s[2], s[3]});
    default:
      throw py::value_error("derive_seed takes at most 4 stream numbers");
  }
}

void bind_rng(py::module_& m) {
  py::class_<Rng>(m, "Rng",
                  "echoplan's random engine (64-bit Mersenne Twister). Every random choice of a "
                  "call comes from the Rng passed in, so the same seed replays it.")
      .def(py::init<std::uint64_t>(), py::arg("seed") = 1)
      .def(
          "random", [](Rng& rng) { return uniform01(rng); },
          "A uniform number in [0, 1), the same on every platform.")
      .def(
          "next", [](Rng& rng) { return rng(); }, "The engine's next 64-bit output.")
      .def(
          "copy", [](const Rng& rng) { return rng; }, "An independent copy in the same state.")
      .def("__eq__", [](const Rng& a, const Rng& b) { return a == b; });
  m.def("derive_seed", &derive_seed_of, py::arg("seed"), py::arg("streams"),
        "The seed of an independent stream: derive_seed(seed, [t, 4]) is the planner's stream of "
        "trial t (common/rng.h). At most 4 stream numbers.");
}

void bind_state(py::module_& m) {
  py::class_<pomdp::State>(m, "State",
                           "A model state: `continuous` variables (joint angles, object offset) "
                           "and `discrete` ones (discrete[0]: the object, or the tabular state).")
      .def(py::init<>())
      .def(py::init([](std::vector<int> discrete, std::vector<double> continuous) {
             return pomdp::State{std::move(continuous), std::move(discrete)};
           }),
           py::arg("discrete"), py::arg("continuous") = std::vector<double>{})
      .def_readwrite("continuous", &pomdp::State::continuous)
      .def_readwrite("discrete", &pomdp::State::discrete)
      .def("__eq__", [](const pomdp::State& a, const pomdp::State& b) { return a == b; })
      .def("__repr__", [](const pomdp::State& s) {
        return "State(discrete=" + py::repr(py::cast(s.discrete)).cast<std::string>() +
               ", continuous=" + py::repr(py::cast(s.continuous)).cast<std::string>() + ")";
      });
  py::class_<pomdp::Observation>(m, "Observation",
                                 "An observation: a discrete symbol `index`, or a continuous "
                                 "vector `values` (index -1). Calls also take a symbol's index or "
                                 "name.")
      .def(py::init([](int index) {
             return pomdp::Observation{index, {}};
           }),
           py::arg("index"))
      .def(py::init([](std::vector<double> values) {
             return pomdp::Observation{-1, values};
           }),
           py::arg("values"))
      .def_readonly("index", &pomdp::Observation::index)
      .def_readonly("values", &pomdp::Observation::values)
      .def("__eq__",
           [](const pomdp::Observation& a, const pomdp::Observation& b) { return a == b; })
      .def("__repr__", [](const pomdp::Observation& o) {
        return o.index >= 0
                   ? "Observation(" + std::to_string(o.index) + ")"
                   : "Observation(" + py::repr(py::cast(o.values)).cast<std::string>() + ")";
      });
  py::class_<pomdp::StepResult>(m, "StepResult", "What one step of the model produced.")
      .def_readonly("next", &pomdp::StepResult::next)
      .def_readonly("observation", &pomdp::StepResult::observation)
      .def_readonly("reward", &pomdp::StepResult::reward)
      .def_readonly("terminal", &pomdp::StepResult::terminal)
      .def_readonly("collision", &pomdp::StepResult::collision);
}

// The model's tables as arrays: transition[s, a, s'], observation[a, s', o], reward[s, a].
py::dict tables_of(const pomdp::TabularModel& t) {
  const py::ssize_t S = t.num_states(), A = t.num_actions(), O = t.num_observations();
  py::array_t<double> transition({S, A, S}), observation({A, S, O}), reward({S, A});
  py::array_t<bool> terminal(S);
  auto tr = transition.mutable_unchecked<3>();
  auto ob = observation.mutable_unchecked<3>();
  auto rw = reward.mutable_unchecked<2>();
  auto te = terminal.mutable_unchecked<1>();
  for (py::ssize_t s = 0; s < S; ++s) {
    te(s) = t.terminal(int(s));
    for (py::ssize_t a = 0; a < A; ++a) {
      rw(s, a) = t.reward(int(s), int(a));
      for (py::ssize_t n = 0; n < S; ++n) tr(s, a, n) = t.transition(int(s), int(a), int(n));
      for (py::ssize_t o = 0; o < O; ++o) ob(a, s, o) = t.observation(int(a), int(s), int(o));
    }
  }
  py::dict d;
  d["transition"] = transition;
  d["observation"] = observation;
  d["reward"] = reward;
  d["terminal"] = terminal;
  d["initial_belief"] = to_array(t.initial_belief());
  d["discount"] = t.discount();
  return d;
}

void bind_model(py::module_& m) {
  using pomdp::Model;
  py::class_<Model, std::shared_ptr<Model>>(
      m, "Model",
      "The planning model of a problem: names, the generative step and the observation "
      "likelihood (pomdp/model.h). Actions and observations may be given by index or by name.")
      .def_property_readonly("name", [](const Model& x) { return x.spec().name; })
      .def_property_readonly("action_names", [](const Model& x) { return x.spec().action_names; })
      .def_property_readonly("observation_names",
                             [](const Model& x) { return x.spec().observation.names; })
      .def_property_readonly("discrete_observations",
                             [](const Model& x) { return x.spec().observation.discrete; })
      .def_property_readonly(
          "objects",
          [](const Model& x) {
            const auto& v = x.spec().state.discrete_value_names;
            return v.empty() ? std::vector<std::string>{} : v[0];
          },
          "The values of discrete state variable 0 (the objects).")
      .def_property_readonly("discount", [](const Model& x) { return x.spec().discount; })
      .def_property_readonly("num_actions", &Model::num_actions)
      .def(
          "action_index", [](const Model& x, py::handle a) { return action_index(x, a); },
          py::arg("action"))
      .def("sample_initial_state", &Model::sample_initial_state, py::arg("rng"))
      .def(
          "step",
          [](const Model& x, const pomdp::State& s, py::handle a, Rng& rng) {
            return x.step(s, action_index(x, a), rng);
          },
          py::arg("state"), py::arg("action"), py::arg("rng"),
          "Next state, observation, reward and termination of `action` in `state`.")
      .def(
          "observation_likelihood",
          [](const Model& x, const pomdp::State& next, py::handle a, py::handle o) {
            return x.observation_likelihood(next, action_index(x, a), to_observation(x, o));
          },
          py::arg("next_state"), py::arg("action"), py::arg("observation"),
          "P(observation | next_state, action) (a density for continuous observations).")
      .def("heuristic_value", &Model::heuristic_value, py::arg("state"))
      .def(
          "max_uses", [](const Model& x, py::handle a) { return x.max_uses(action_index(x, a)); },
          py::arg("action"), "How often `action` may be taken in one episode (0: no limit).")
      .def(
          "prerequisites",
          [](const Model& x, py::handle a) {
            std::vector<std::string> names;
            for (int r : x.prerequisites(action_index(x, a)))
              names.push_back(x.spec().action_names[r]);
            return names;
          },
          py::arg("action"),
          "The actions that must each have been taken before `action` is available (names).")
      .def(
          "tables",
          [](const Model& x) -> py::object {
            return x.tabular() ? py::object(tables_of(*x.tabular())) : py::object(py::none());
          },
          "The model as tables (dict of arrays: transition[s, a, s'], observation[a, s', o], "
          "reward[s, a], terminal[s], initial_belief[s], discount), or None when it has none.");
}

const pomdp::ParticleBelief& particles_of(const BeliefHandle& b) {
  const auto* p = dynamic_cast<const pomdp::ParticleBelief*>(b.belief.get());
  if (!p) throw py::type_error("an exact belief has no particles");
  return *p;
}

std::string belief_type(const pomdp::Problem& p) {
  return p.belief.type == pomdp::BeliefSettings::Type::particle ? "particle" : "exact";
}

void bind_problem(py::module_& m) {
  using pomdp::Problem;
  py::class_<Problem, ProblemPtr>(
      m, "Problem",
      "A problem as its file says: the model, how to track the belief and the planner's defaults. "
      "load_problem(path), parse_problem(text, name) or Problem.from_dict(d).")
      .def_property_readonly(
          "model", [](const Problem& p) { return std::const_pointer_cast<pomdp::Model>(p.model); })
      .def_property_readonly("source_path", [](const Problem& p) { return p.source_path; })
      .def_property_readonly("belief_type", &belief_type, "'particle' or 'exact'")
      .def_property_readonly("particles", [](const Problem& p) { return p.belief.particles; })
      .def_property_readonly("planner_defaults",
                             [](const Problem& p) {
                               py::dict d;
                               d["solver"] = p.planner.solver;
                               d["episodes"] = p.planner.episodes;
                               d["step_ms"] = p.planner.step_ms;
                               d["depth"] = p.planner.depth;
                               d["exploration"] = p.planner.exploration;
                               return d;
                             })
      .def(
          "check", [](const Problem& p) { return pomdp::check_problem(p); },
          "What looks like a mistake in the problem, one sentence each (`echoplan check`); "
          "empty when nothing was found.")
      .def(
          "make_belief",
          [](const Problem& p, Rng& rng) {
            return BeliefHandle{pomdp::make_belief(p, rng), p.model};
          },
          py::arg("rng"), "The belief the problem asks for: particles or exact.")
      .def(
          "to_yaml",
          [](const Problem& p) {
            const auto* object = p.model->object_identification();
            if (!object)
              throw py::value_error("only object-identification problems are written as YAML");
            std::ostringstream out;
            pomdp::write_problem_yaml(out, object->data(), p.belief, p.planner);
            return out.str();
          },
          "The problem as YAML text that parse_problem reads back to the same problem.");
  m.def(
      "load_problem",
      [](const std::string& path) { return std::make_shared<Problem>(pomdp::load_problem(path)); },
      py::arg("path"),
      "Reads a problem file: *.pomdp as Cassandra's format, anything else as YAML. Raises "
      "InputError naming the file and line of a mistake.");
  m.def(
      "parse_problem",
      [](const std::string& text, const std::string& name) {
        return std::make_shared<Problem>(pomdp::parse_problem(text, name));
      },
      py::arg("text"), py::arg("name") = "<text>.yaml",
      "A problem from its text; `name` names it in errors and chooses the format (*.pomdp: "
      "Cassandra's, else YAML).");
}

// Particle states as arrays: discrete (N x variables) and continuous (N x variables).
py::tuple particle_arrays(const pomdp::ParticleBelief& b) {
  const auto& ps = b.particles();
  const py::ssize_t n = ps.size();
  const py::ssize_t nd = n ? ps[0].discrete.size() : 0, nc = n ? ps[0].continuous.size() : 0;
  py::array_t<int> discrete({n, nd});
  py::array_t<double> continuous({n, nc});
  auto d = discrete.mutable_unchecked<2>();
  auto c = continuous.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    for (py::ssize_t j = 0; j < nd; ++j) d(i, j) = ps[i].discrete[j];
    for (py::ssize_t j = 0; j < nc; ++j) c(i, j) = ps[i].continuous[j];
  }
  return py::make_tuple(discrete, continuous);
}

void bind_beliefs(py::module_& m) {
  py::class_<BeliefHandle>(
      m, "Belief",
      "What the agent thinks the hidden state is (pomdp/belief.h): exact (Bayes filter over the "
      "problem's tables) or particles. Made by ExactBelief(problem), ParticleBelief(problem, ...) "
      "or problem.make_belief(rng).")
      .def_property_readonly("kind",
                             [](const BeliefHandle& b) {
                               return b.belief->exact_probabilities() ? "exact" : "particle";
                             })
      .def(
          "sample", [](const BeliefHandle& b, Rng& rng) { return b.belief->sample(rng); },
          py::arg("rng"))
      .def(
          "update",
          [](BeliefHandle& b, py::handle a, py::handle o, Rng& rng) {
            return b.belief->update(action_index(*b.model, a), to_observation(*b.model, o), rng);
          },
          py::arg("action"), py::arg("observation"), py::arg("rng"),
          "Conditions the belief on having taken `action` and heard `observation`. False when "
          "nothing explained the observation and the belief had to recover.")
      .def(
          "marginal",
          [](const BeliefHandle& b, int variable) {
            return to_array(b.belief->discrete_marginal(variable));
          },
          py::arg("variable") = 0,
          "P(each value of discrete state variable `variable`) (variable 0: the objects).")
      .def_property_readonly(
          "probabilities",
          [](py::object self) -> py::object {
            const auto* p = self.cast<const BeliefHandle&>().belief->exact_probabilities();
            return p ? py::object(view_of(*p, self)) : py::object(py::none());
          },
          "Exact beliefs: P(each tabular state), a read-only array over the belief's own data "
          "(it follows updates); None for particles.")
      .def(
          "particle_counts",
          [](const BeliefHandle& b, int variable) {
            return particles_of(b).particle_counts(variable);
          },
          py::arg("variable") = 0, "Particles: how many hold each value of `variable`.")
      .def_property_readonly(
          "particles", [](const BeliefHandle& b) { return particle_arrays(particles_of(b)); },
          "Particles: (discrete, continuous), arrays of N x variables.")
      .def("copy", [](const BeliefHandle& b) {
        return BeliefHandle{b.belief->clone(), b.model};
      });
  m.def(
      "ExactBelief",
      [](const ProblemPtr& p) {
        return BeliefHandle{std::make_unique<pomdp::ExactBelief>(p->model), p->model};
      },
      py::arg("problem"), "The exact belief at the problem's start (needs tables).");
  m.def(
      "ParticleBelief",
      [](const ProblemPtr& p, std::optional<int> particles, Rng& rng, double fresh_share) {
        return BeliefHandle{
            std::make_unique<pomdp::ParticleBelief>(
                p->model, particles.value_or(p->belief.particles), rng, fresh_share),
            p->model};
      },
      py::arg("problem"), py::arg("particles") = py::none(), py::arg("rng"),
      py::arg("fresh_share") = pomdp::ParticleBelief::kDefaultFreshShare,
      "A particle filter at the problem's start (default size: the problem's).");
}

}  // namespace

void bind_problems(py::module_& m) {
  bind_rng(m);
  bind_state(m);
  bind_model(m);
  bind_problem(m);
  bind_beliefs(m);
}

}  // namespace echoplan::python
