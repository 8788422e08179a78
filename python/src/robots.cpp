// The loop with a robot written in Python: Robot, Recorder and ObservationService (src/robot/) as
// Python base classes (pybind11 trampolines), whose subclasses plug into the same loop::Loop that
// `echoplan run` and the ROS planner node run (loop/loop.h, PartsWorldSpec), the way a real arm's
// driver would. echoplan/__init__.py wraps objects that only have the methods (no base class).
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "interrupt.h"
#include "loop/calibrated_problem.h"
#include "loop/loop.h"
#include "planner_settings.h"
#include "robot/classifier_service.h"

namespace echoplan::python {

namespace {

using robot::ActionReport;
using robot::HeardObservation;

// Trampolines: each method a Python subclass defines is called (with the GIL taken) when the loop
// calls the C++ one.
// What a Python method returned, as the C++ value, accepting Python's shorter spellings too.
ActionReport report_of(py::handle r, const std::string& action) {
  ActionReport report;
  if (py::isinstance<ActionReport>(r))
    report = r.cast<ActionReport>();
  else if (py::isinstance<py::str>(r))
    report = py::module_::import("echoplan._echoplan")
                 .attr("ActionReport")(action, r)
                 .cast<ActionReport>();
  else if (!r.is_none())
    throw py::type_error(
        "Robot.execute returned " + py::repr(r).cast<std::string>() +
        "; return an ActionReport, a status ('done', 'collision', 'failed') or None (done)");
  if (report.action.empty()) report.action = action;
  return report;
}

audio::AudioClip clip_of(py::handle r) {
  if (py::isinstance<py::tuple>(r) && py::len(r) == 2)
    return to_clip(r.cast<py::tuple>()[0], r.cast<py::tuple>()[1].cast<int>());
  if (py::isinstance<audio::AudioClip>(r) || py::isinstance<py::array>(r)) return to_clip(r, 44100);
  throw py::type_error("Recorder.stop returned " + py::repr(r).cast<std::string>() +
                       "; return an AudioClip, (samples, sample_rate) or samples at 44100 Hz");
}

HeardObservation heard_of(py::handle r) {
  if (py::isinstance<HeardObservation>(r)) return r.cast<HeardObservation>();
  if (py::isinstance<py::str>(r)) {
    HeardObservation h;
    h.label = r.cast<std::string>();
    h.unknown = h.label == "unknown";
    h.probability = 1.0;
    return h;
  }
  throw py::type_error("ObservationService.observe returned " + py::repr(r).cast<std::string>() +
                       "; return a HeardObservation or a label");
}

// The Python method `name` of a subclass, or an error saying it is missing.
template <class Base>
py::function method(const Base* self, const char* type, const char* name) {
  py::function f = py::get_override(self, name);
  if (!f)
    throw py::type_error(std::string(type) + "." + name + " is not implemented by the subclass");
  return f;
}

// Trampolines: each method a Python subclass defines is called (with the GIL taken) when the loop
// calls the C++ one; its result may use the shorter spellings above.
class PythonRobot : public robot::Robot {
 public:
  void begin_trial(const robot::TrialContext& context) override {
    py::gil_scoped_acquire gil;
    method<robot::Robot>(this, "Robot", "begin_trial")(context);
  }
  ActionReport execute(const std::string& action) override {
    py::gil_scoped_acquire gil;
    return report_of(method<robot::Robot>(this, "Robot", "execute")(action), action);
  }
};

class PythonRecorder : public robot::Recorder {
 public:
  void begin_trial(const robot::TrialContext& context) override {
    PYBIND11_OVERRIDE(void, robot::Recorder, begin_trial, context);
  }
  void start(const std::string& action) override {
    py::gil_scoped_acquire gil;
    method<robot::Recorder>(this, "Recorder", "start")(action);
  }
  audio::AudioClip stop() override {
    py::gil_scoped_acquire gil;
    return clip_of(method<robot::Recorder>(this, "Recorder", "stop")());
  }
};

class PythonService : public robot::ObservationService {
 public:
  std::optional<robot::ServiceVocabulary> vocabulary() const override {
    py::gil_scoped_acquire gil;
    py::function f =
        py::get_override(static_cast<const robot::ObservationService*>(this), "vocabulary");
    if (!f) return std::nullopt;
    py::object v = f();
    if (v.is_none()) return std::nullopt;
    if (py::isinstance<py::dict>(v))
      return robot::ServiceVocabulary{v.cast<std::map<std::string, std::vector<std::string>>>(),
                                      false, false};
    return v.cast<robot::ServiceVocabulary>();
  }
  HeardObservation observe(const audio::AudioClip& clip, const std::string& action) override {
    py::gil_scoped_acquire gil;
    return heard_of(
        method<robot::ObservationService>(this, "ObservationService", "observe")(clip, action));
  }
};

// A part the loop owns (RobotParts holds unique_ptrs) that forwards to a Python object it keeps
// alive. The calls are not wrapped in the GIL: a Python subclass's trampoline takes it, a part
// implemented in C++ (ClassifierService) runs without it.
template <class Part>
struct Held {
  py::object owner;
  Part* part = nullptr;
  explicit Held(py::object o) : owner(std::move(o)), part(owner.cast<Part*>()) {}
  ~Held() {
    py::gil_scoped_acquire gil;
    owner = py::object();
  }
};

class HeldRobot final : public robot::Robot {
 public:
  explicit HeldRobot(py::object o) : held_(std::move(o)) {}
  void begin_trial(const robot::TrialContext& c) override { held_.part->begin_trial(c); }
  ActionReport execute(const std::string& a) override { return held_.part->execute(a); }

 private:
  Held<robot::Robot> held_;
};

class HeldRecorder final : public robot::Recorder {
 public:
  explicit HeldRecorder(py::object o) : held_(std::move(o)) {}
  void begin_trial(const robot::TrialContext& c) override { held_.part->begin_trial(c); }
  void start(const std::string& a) override { held_.part->start(a); }
  audio::AudioClip stop() override { return held_.part->stop(); }

 private:
  Held<robot::Recorder> held_;
};

class HeldService final : public robot::ObservationService {
 public:
  explicit HeldService(py::object o) : held_(std::move(o)) {}
  std::optional<robot::ServiceVocabulary> vocabulary() const override {
    return held_.part->vocabulary();
  }
  HeardObservation observe(const audio::AudioClip& c, const std::string& a) override {
    return held_.part->observe(c, a);
  }

 private:
  Held<robot::ObservationService> held_;
};

void bind_values(py::module_& m) {
  py::class_<robot::TrialContext>(m, "TrialContext", "What a robot is told when a trial begins.")
      .def_readonly("trial", &robot::TrialContext::trial)
      .def_readonly("object", &robot::TrialContext::object,
                    "The true object's name (a real robot ignores it: an operator placed it).")
      .def_readonly("seed", &robot::TrialContext::seed);
  py::class_<ActionReport>(m, "ActionReport",
                           "How an action went: status 'done', 'collision' or 'failed', the "
                           "reason in words, its duration in seconds.")
      .def(py::init([](const std::string& action, const std::string& status,
                       const std::string& reason, double duration) {
             ActionReport r{action, sim::ActionStatus::done, reason, duration};
             if (status == "collision")
               r.status = sim::ActionStatus::collision;
             else if (status == "failed")
               r.status = sim::ActionStatus::failed;
             else if (status != "done")
               throw py::value_error("status '" + status +
                                     "' is not one of done, collision, failed");
             return r;
           }),
           py::arg("action") = "", py::arg("status") = "done", py::arg("reason") = "",
           py::arg("duration_s") = 0.0)
      .def_readonly("action", &ActionReport::action)
      .def_property_readonly(
          "status", [](const ActionReport& r) { return std::string(sim::to_string(r.status)); })
      .def_readonly("reason", &ActionReport::reason)
      .def_readonly("duration_s", &ActionReport::duration_s);
  py::class_<HeardObservation>(m, "HeardObservation",
                               "What a service heard: a class label (or 'unknown'), its "
                               "calibrated probability, the probability of every class.")
      .def(py::init([](const std::string& label, double p,
                       std::vector<std::pair<std::string, double>> probabilities, bool unknown,
                       int grade) {
             HeardObservation h;
             h.label = label;
             h.probability = p;
             h.probabilities = std::move(probabilities);
             h.unknown = unknown;
             h.grade = grade;
             return h;
           }),
           py::arg("label"), py::arg("probability") = 1.0,
           py::arg("probabilities") = std::vector<std::pair<std::string, double>>{},
           py::arg("unknown") = false, py::arg("grade") = -1)
      .def_readonly("label", &HeardObservation::label)
      .def_readonly("unknown", &HeardObservation::unknown)
      .def_readonly("probability", &HeardObservation::probability)
      .def_readonly("grade", &HeardObservation::grade)
      .def_readonly("level_grade", &HeardObservation::level_grade)
      .def_readonly("probabilities", &HeardObservation::probabilities)
      .def_readonly("distance", &HeardObservation::distance)
      .def_readonly("features", &HeardObservation::features);
  py::class_<robot::ServiceVocabulary>(m, "ServiceVocabulary",
                                       "What a service can report: per action its labels.")
      .def(py::init([](std::map<std::string, std::vector<std::string>> labels, bool unknown,
                       bool grades) {
             return robot::ServiceVocabulary{std::move(labels), unknown, grades};
           }),
           py::arg("labels"), py::arg("may_report_unknown") = false, py::arg("grades") = false)
      .def_readonly("labels", &robot::ServiceVocabulary::labels)
      .def_readonly("may_report_unknown", &robot::ServiceVocabulary::may_report_unknown)
      .def_readonly("grades", &robot::ServiceVocabulary::grades);
  py::class_<loop::RobotStep>(m, "RobotStep", "A robot's part of a step.")
      .def_readonly("report", &loop::RobotStep::report)
      .def_readonly("recorded", &loop::RobotStep::recorded)
      .def_readonly("clip", &loop::RobotStep::clip)
      .def_readonly("classified", &loop::RobotStep::classified)
      .def_readonly("heard", &loop::RobotStep::heard)
      .def_readonly("observe_ms", &loop::RobotStep::observe_ms);
}

void bind_parts(py::module_& m) {
  py::class_<robot::Robot, PythonRobot>(
      m, "Robot",
      "Subclass it for your arm: begin_trial(context) prepares a trial; execute(action) runs a "
      "sensing or sorting action by name, blocking, and returns an ActionReport (physical "
      "outcomes are reported, not raised).")
      .def(py::init<>())
      .def("begin_trial", &robot::Robot::begin_trial, py::arg("context"))
      .def("execute", &robot::Robot::execute, py::arg("action"));
  py::class_<robot::Recorder, PythonRecorder>(
      m, "Recorder",
      "Subclass it for your microphone: start(action) starts listening before the action, "
      "stop() returns the AudioClip heard since; begin_trial(context) is optional.")
      .def(py::init<>())
      .def("begin_trial", &robot::Recorder::begin_trial, py::arg("context"))
      .def("start", &robot::Recorder::start, py::arg("action"))
      .def("stop", &robot::Recorder::stop);
  py::class_<robot::ObservationService, PythonService>(
      m, "ObservationService",
      "Subclass it for your classifier: observe(clip, action) returns a HeardObservation; "
      "vocabulary() may say in advance which labels it reports per action (a ServiceVocabulary, "
      "or None: checked as they come).")
      .def(py::init<>())
      .def("vocabulary", &robot::ObservationService::vocabulary)
      .def("observe", &robot::ObservationService::observe, py::arg("clip"), py::arg("action"));
  py::class_<robot::ClassifierService, robot::ObservationService>(
      m, "ClassifierService", "The observation service of a trained ObservationModel (C++).")
      .def(py::init([](std::shared_ptr<perception::ObservationModel> model) {
             return std::make_unique<robot::ClassifierService>(std::move(model));
           }),
           py::arg("model"));
}

}  // namespace

void bind_loop(py::module_& m);  // loop_binding.cpp

void bind_robots(py::module_& m) {
  bind_values(m);
  bind_parts(m);
  bind_loop(m);
  m.def(
      "calibrate_problem",
      [](const ProblemPtr& base, const perception::ObservationModel& model) {
        return std::const_pointer_cast<pomdp::Problem>(loop::calibrate_problem(*base, model));
      },
      py::arg("problem"), py::arg("model"),
      "The problem with its observation table replaced by the model's calibrated one (what "
      "`echoplan run` plans on without --problem).");
}

// Parts for PartsWorldSpec, each kept alive by the loop that owns it.
loop::RobotParts held_parts(py::object robot, py::object recorder, py::object service) {
  return {std::make_unique<HeldRobot>(std::move(robot)),
          std::make_unique<HeldRecorder>(std::move(recorder)),
          std::make_unique<HeldService>(std::move(service)), loop::RecordingChecks{}};
}

}  // namespace echoplan::python
