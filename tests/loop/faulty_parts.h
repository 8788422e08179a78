// Fault injection through the loop's seams: a robot, a recorder and an observation service that
// wrap the simulated ones and, on the calls a test picks, answer as a failing arm, microphone or
// classifier would. Every other call goes to the simulated part unchanged, so a trial the fault
// does not touch runs exactly as without the wrapper.
#pragma once

#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "loop/robot_world.h"
#include "mug_or_cup.h"
#include "robot/classifier_service.h"
#include "robot/simulated_world.h"
#include "robot/transient_error.h"

namespace echoplan::loop::test {

// Which call a fault hits: the trial (as the world numbers them, from 0) and the call of the part
// in that trial (from 0: the first action, the first recording, the first observation).
struct Call {
  int trial = 0;
  int call = 0;
};

// Counts a part's calls per trial.
class CallCounter {
 public:
  void begin_trial(int trial) {
    trial_ = trial;
    call_ = 0;
  }
  Call next() { return {trial_, call_++}; }

 private:
  int trial_ = 0;
  int call_ = 0;
};

// A robot whose `inject` may answer instead of the simulated arm (which is then not moved: the
// arm stopped before it changed anything, or never answered).
class FaultyArm final : public robot::Robot {
 public:
  using Inject = std::function<std::optional<robot::ActionReport>(Call, const std::string&)>;
  FaultyArm(std::shared_ptr<robot::SimulatedWorld> world, Inject inject)
      : arm_(std::move(world)), inject_(std::move(inject)) {}
  void begin_trial(const robot::TrialContext& context) override {
    calls_.begin_trial(context.trial);
    arm_.begin_trial(context);
  }
  robot::ActionReport execute(const std::string& action) override {
    if (auto report = inject_(calls_.next(), action)) return *report;
    return arm_.execute(action);
  }

 private:
  robot::SimulatedArm arm_;
  Inject inject_;
  CallCounter calls_;
};

// What a recording fault does: change the clip, say what capture lost, or throw from start() or
// stop() as robot::TransientError (a device that cannot be opened, or gave nothing).
struct RecordingFault {
  std::function<void(audio::AudioClip&)> change_clip;
  robot::CaptureReport capture;
  std::string start_error;
  std::string stop_error;
};

class FaultyMicrophone final : public robot::Recorder {
 public:
  using Inject = std::function<std::optional<RecordingFault>(Call)>;
  FaultyMicrophone(std::shared_ptr<robot::SimulatedWorld> world, Inject inject)
      : microphone_(std::move(world)), inject_(std::move(inject)) {}
  void begin_trial(const robot::TrialContext& context) override {
    calls_.begin_trial(context.trial);
  }
  void start(const std::string& action) override {
    fault_ = inject_(calls_.next());
    capture_ = {};
    if (fault_ && !fault_->start_error.empty()) throw robot::TransientError(fault_->start_error);
    microphone_.start(action);
  }
  audio::AudioClip stop() override {
    audio::AudioClip clip = microphone_.stop();
    if (!fault_) return clip;
    if (!fault_->stop_error.empty()) throw robot::TransientError(fault_->stop_error);
    if (fault_->change_clip) fault_->change_clip(clip);
    capture_ = fault_->capture;
    return clip;
  }
  robot::CaptureReport capture_report() const override { return capture_; }

 private:
  robot::SimulatedMicrophone microphone_;
  Inject inject_;
  CallCounter calls_;
  std::optional<RecordingFault> fault_;
  robot::CaptureReport capture_;
};

// A service that may fail one call (a timeout) or answer another label than the classifier heard.
class FaultyService final : public robot::ObservationService {
 public:
  struct Fault {
    std::string error;  // thrown as robot::TransientError when not empty
    std::string label;  // else: the label answered instead
  };
  using Inject = std::function<std::optional<Fault>(Call)>;
  explicit FaultyService(Inject inject)
      : service_(std::make_unique<robot::ClassifierService>(model())), inject_(std::move(inject)) {}
  // A remote service cannot tell what it may answer: the loop checks each answer as it comes.
  robot::HeardObservation observe(const audio::AudioClip& clip,
                                  const std::string& action) override {
    ++observed;
    const auto fault = inject_({trial, call++});
    if (fault && !fault->error.empty()) throw robot::TransientError(fault->error);
    robot::HeardObservation heard = service_->observe(clip, action);
    if (fault) {
      heard.label = fault->label;
      heard.unknown = false;
    }
    return heard;
  }
  int observed = 0;  // calls in all
  int trial = 0;     // set by the test: the service is not told when a trial begins
  int call = 0;

 private:
  std::unique_ptr<robot::ClassifierService> service_;
  Inject inject_;
};

// Faults to inject into each part; none by default (the simulated parts as they are).
struct Faults {
  FaultyArm::Inject arm = [](Call, const std::string&) { return std::nullopt; };
  FaultyMicrophone::Inject microphone = [](Call) { return std::nullopt; };
  FaultyService::Inject service;  // null: the classifier service itself, vocabulary and all
  RecordingChecks checks;
};

inline RobotParts faulty_parts(const pomdp::ObjectIdentificationModel& problem, Faults faults) {
  auto world = std::make_shared<robot::SimulatedWorld>(testing::shipped_catalogue(),
                                                       sim::SimConfig{}, problem.data().sorting);
  RobotParts parts;
  parts.robot = std::make_unique<FaultyArm>(world, faults.arm);
  parts.recorder = std::make_unique<FaultyMicrophone>(world, faults.microphone);
  if (faults.service)
    parts.service = std::make_unique<FaultyService>(faults.service);
  else
    parts.service = std::make_unique<robot::ClassifierService>(model());
  parts.checks = faults.checks;
  return parts;
}

// What the loop logs while it lives (spdlog's default logger, restored after).
class CapturedLog {
 public:
  CapturedLog() : previous_(spdlog::default_logger()) {
    auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(text_);
    spdlog::set_default_logger(std::make_shared<spdlog::logger>("captured", sink));
  }
  ~CapturedLog() { spdlog::set_default_logger(previous_); }
  std::string text() const { return text_.str(); }

 private:
  std::shared_ptr<spdlog::logger> previous_;
  std::ostringstream text_;
};

}  // namespace echoplan::loop::test
