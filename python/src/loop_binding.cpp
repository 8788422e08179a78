// echoplan.Loop: the closed loop of `echoplan run` (loop/loop.h) over the problem's own table,
// recordings replayed with a model, or robot parts written in Python (PartsWorldSpec). A trial
// returns its steps; Ctrl-C stops it after the step in progress.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "common/error.h"
#include "interrupt.h"
#include "loop/loop.h"
#include "planner_settings.h"
#include "robot/classifier_service.h"

namespace echoplan::python {

loop::RobotParts held_parts(py::object robot, py::object recorder, py::object service);

namespace {

using ObservationModelPtr = std::shared_ptr<perception::ObservationModel>;

struct PythonLoop {
  std::unique_ptr<loop::Loop> loop;
};

// The parts, made once, when the loop builds its world; the Python objects are cast to their
// C++ bases here, so an object of the wrong type fails before any trial.
loop::PartsWorldSpec parts_world(py::object robot, py::object recorder, py::object service,
                                 const std::string& description) {
  auto parts = std::make_shared<loop::RobotParts>(
      held_parts(std::move(robot), std::move(recorder), std::move(service)));
  return {[parts] { return std::move(*parts); }, description};
}

loop::WorldSpec world_of(const py::object& robot, const py::object& recorder, py::object service,
                         const ObservationModelPtr& model, const std::string& recordings,
                         const std::string& description) {
  if (!robot.is_none()) {
    if (recorder.is_none()) throw py::value_error("a robot needs a recorder too");
    if (service.is_none()) {
      if (!model)
        throw py::value_error("a robot needs an observation service (or a model to classify with)");
      service = py::module_::import("echoplan._echoplan").attr("ClassifierService")(model);
    }
    return parts_world(robot, recorder, service, description);
  }
  if (!recorder.is_none() || !service.is_none())
    throw py::value_error("a recorder or service needs a robot");
  if (!recordings.empty()) return loop::ReplayWorldSpec{recordings};
  return loop::TableWorldSpec{};
}

PythonLoop make_loop(const ProblemPtr& problem, const py::object& robot, const py::object& recorder,
                     const py::object& service, const ObservationModelPtr& model,
                     const std::string& recordings, const ProblemPtr& world_problem,
                     std::map<std::string, std::string> world_objects, int max_steps,
                     const std::string& description, const py::kwargs& settings) {
  loop::LoopSettings s;
  s.problem = problem;
  s.world_problem = world_problem;
  s.world = world_of(robot, recorder, service, model, recordings, description);
  s.observation_model = model;
  s.world_objects = std::move(world_objects);
  s.planner = planner_overrides(settings);
  s.max_steps = max_steps;
  return {std::make_unique<loop::Loop>(std::make_shared<const loop::LoopSpec>(std::move(s)))};
}

loop::Trial run(PythonLoop& self, py::handle object, int index, std::uint64_t seed,
                const py::object& on_step) {
  int truth = -1;
  if (py::isinstance<py::str>(object))
    truth = loop::object_index(self.loop->spec().problem(), object.cast<std::string>());
  else if (!object.is_none())
    truth = object.cast<int>();
  loop::StepFn each;
  if (!on_step.is_none())
    each = [&on_step](const loop::Step& s) {
      py::gil_scoped_acquire gil;
      on_step(s);
    };
  auto trial = run_interruptibly([&](const std::atomic<bool>& stop) {
    return self.loop->run({index, truth, seed}, each, &stop);
  });
  if (!trial) throw std::logic_error("the trial stopped without a stop request");
  return std::move(*trial);
}

}  // namespace

void bind_loop(py::module_& m) {
  py::class_<PythonLoop>(
      m, "Loop",
      "The closed loop `echoplan run` runs (loop/loop.h): plan, act, listen, classify, update, "
      "until the object is sorted. The world: robot parts (robot=, recorder=, service= or "
      "model=: objects of Robot, Recorder and ObservationService subclasses, or with their "
      "methods), recordings replayed (recordings=DIR with model=), or the problem's own table "
      "(neither). Every check happens here, before any trial (InputError).")
      .def(py::init(&make_loop), py::arg("problem"), py::kw_only(), py::arg("robot") = py::none(),
           py::arg("recorder") = py::none(), py::arg("service") = py::none(),
           py::arg("model") = ObservationModelPtr(), py::arg("recordings") = "",
           py::arg("world_problem") = ProblemPtr(),
           py::arg("world_objects") = std::map<std::string, std::string>{},
           py::arg("max_steps") = 100, py::arg("description") = "robot", planner_settings_doc())
      .def("run", &run, py::arg("object") = py::none(), py::kw_only(), py::arg("index") = 0,
           py::arg("seed") = 1, py::arg("on_step") = py::none(),
           "Runs one trial with the true `object` (a name or index; None: drawn) and returns "
           "the Trial. Its streams come from (seed, index): `echoplan run --seed S` is "
           "index 0 and seed stream_seed(S, 'run_trial'). on_step(step) sees each Step as it "
           "happens. Ctrl-C stops after the step in progress (KeyboardInterrupt).")
      .def("describe", [](const PythonLoop& l) { return l.loop->planner().describe(); })
      .def_property_readonly(
          "settings", [](const PythonLoop& l) { return to_python(l.loop->planner().to_json()); });
}

}  // namespace echoplan::python
