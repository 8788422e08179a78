#include "loop/loop_log.h"

#include <fmt/format.h>

#include "audio/io.h"
#include "common/error.h"
#include "common/file_io.h"

namespace echoplan::loop {

namespace fs = std::filesystem;

namespace {

std::ofstream open_for_writing(const fs::path& path) {
  std::ofstream out(path, std::ios::trunc);
  if (!out) throw InputError(path.string(), 0, "cannot write this file (is the folder writable?)");
  return out;
}

// What the recording lost on its way in; `dropout` marks a clip with a gap in it.
nlohmann::json capture_json(const robot::CaptureReport& c) {
  return {{"overflow_callbacks", c.overflow_callbacks},
          {"dropped_frames", c.dropped_frames},
          {"stream_error", c.stream_error},
          {"dropout", c.dropout()}};
}

// A trial's losses, summed over its recordings, and its faults in the order they happened.
void add_capture_and_faults(nlohmann::json& settings, const Trial& trial) {
  int overflows = 0, dropouts = 0;
  std::size_t dropped = 0;
  nlohmann::json faults = nlohmann::json::array();
  for (const Step& s : trial.steps) {
    if (!s.robot) continue;
    overflows += s.robot->capture.overflow_callbacks;
    dropped += s.robot->capture.dropped_frames;
    if (s.robot->capture.dropout()) ++dropouts;
    if (s.robot->fault) faults.push_back({{"step", s.record.step}, {"kind", s.robot->fault->kind}});
  }
  settings["capture"] = {{"overflow_callbacks", overflows},
                         {"dropped_frames", dropped},
                         {"recordings_with_dropout", dropouts}};
  settings["faults"] = faults;
}

nlohmann::json named_values(const std::vector<std::string>& names,
                            const std::vector<double>& values) {
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t i = 0; i < names.size() && i < values.size(); ++i) j[names[i]] = values[i];
  return j;
}

}  // namespace

LoopLog::LoopLog(const fs::path& directory, const pomdp::ObjectIdentificationModel& model)
    : directory_(directory), model_(model), objects_(model.data().objects) {
  std::error_code ec;
  fs::create_directories(directory_ / "clips", ec);
  if (ec)
    throw InputError(directory_.string(), 0, "cannot create the output folder: " + ec.message());
  csv_ = open_for_writing(directory_ / "loop_steps.csv");
  jsonl_ = open_for_writing(directory_ / "loop_steps.jsonl");
  csv_ << "trial,step,action,status,heard,probability,observation";
  for (const auto& o : objects_) csv_ << ",p_" << o;
  csv_ << ",reward,heard_ebr_db,clip\n" << std::flush;
}

nlohmann::json LoopLog::write_step(const Step& s) {
  // A world without a robot (recorded data replayed, a table world) leaves the robot's fields
  // empty: no status, clip or classifier answer beyond the observation itself.
  const RobotStep step = s.robot ? *s.robot : RobotStep{};
  const StepRecord& r = s.record;
  const std::string& action = model_.spec().action_names[r.action];
  const std::string& observation = model_.spec().observation.names[r.observation.index];
  const std::vector<double>* belief_after = s.belief_after ? &*s.belief_after : nullptr;
  std::string clip;
  if (step.recorded) {
    clip = fmt::format("clips/{:03d}_{:02d}_{}.wav", r.trial, r.step, action);
    try {
      audio::write_audio((directory_ / clip).string(), step.clip);
    } catch (const InputError& e) {
      std::error_code ignored;
      fs::remove(directory_ / clip, ignored);  // no part-written clip is left behind
      throw InputError(e.file(), 0,
                       fmt::format("trial {}, step {}: the clip could not be saved "
                                   "({}); is the disk full? {} step(s) are logged",
                                   r.trial, r.step + 1, e.problem(), steps_written_));
    }
  }
  const std::string heard =
      step.classified ? (step.heard.unknown ? "unknown" : step.heard.label) : "";
  const std::string status = s.robot ? robot::to_string(step.report.status) : "";
  csv_ << r.trial << ',' << r.step << ',' << action << ',' << status << ',' << heard << ','
       << (step.classified ? fmt::format("{:.4f}", step.heard.probability) : "") << ','
       << observation;
  for (std::size_t k = 0; k < objects_.size(); ++k)
    csv_ << ',' << (belief_after ? fmt::format("{:.4f}", (*belief_after)[k]) : "");
  csv_ << ',' << fmt::format("{:g}", r.reward) << ','
       << (r.heard_ebr_db ? fmt::format("{:.1f}", *r.heard_ebr_db) : "") << ',' << clip << '\n'
       << std::flush;

  nlohmann::json j = {
      {"trial", r.trial},
      {"step", r.step},
      {"action", action},
      {"report", s.robot ? nlohmann::json{{"status", status},
                                          {"reason", step.report.reason},
                                          {"duration_s", step.report.duration_s}}
                         : nlohmann::json(nullptr)},
      {"observation", observation},
      {"reward", r.reward},
      {"terminal", s.terminal},
      {"belief_before", named_values(objects_, r.belief)},
      {"belief_after",
       belief_after ? named_values(objects_, *belief_after) : nlohmann::json(nullptr)},
      {"clip", clip.empty() ? nlohmann::json(nullptr) : nlohmann::json(clip)},
      {"heard_ebr_db", r.heard_ebr_db ? nlohmann::json(*r.heard_ebr_db) : nlohmann::json(nullptr)},
  };
  if (s.robot) {
    j["report"]["attempts"] = step.attempts;
    if (step.recorded) j["capture"] = capture_json(step.capture);
    j["fault"] = step.fault ? nlohmann::json{{"kind", step.fault->kind},
                                             {"detail", step.fault->detail},
                                             {"observation_skipped", step.observation_skipped()}}
                            : nlohmann::json(nullptr);
  }
  if (step.classified) {
    nlohmann::json probabilities = nlohmann::json::object(), features = nlohmann::json::object();
    for (const auto& [name, p] : step.heard.probabilities) probabilities[name] = p;
    for (const auto& [name, v] : step.heard.features) features[name] = v;
    j["heard"] = {{"label", step.heard.label},
                  {"unknown", step.heard.unknown},
                  {"probability", step.heard.probability},
                  {"probabilities", probabilities},
                  {"distance", step.heard.distance},
                  {"observe_ms", step.observe_ms}};
    j["features"] = features;
  }
  jsonl_ << j.dump() << '\n' << std::flush;
  // A stream that failed (a full disk) would drop every later row without a word.
  if (!csv_ || !jsonl_)
    throw InputError(directory_.string(), 0,
                     fmt::format("trial {}, step {}: loop_steps.csv or loop_steps.jsonl could not "
                                 "be written; is the disk full? {} step(s) were logged before",
                                 r.trial, r.step + 1, steps_written_));
  ++steps_written_;
  return j;
}

void LoopLog::write_trial(nlohmann::json settings, const std::optional<Trial>& trial) const {
  settings["interrupted"] = !trial.has_value();
  if (trial) {
    const TrialRecord& r = trial->record;
    settings.update(
        {{"believed_state", objects_[r.believed_state]},
         {"steps", r.steps},
         {"discounted_reward", r.discounted_reward},
         {"collision", r.collision},
         {"capped", r.capped},
         {"final_action", model_.spec().action_names[trial->steps.back().record.action]}});
    if (!r.surface.empty()) settings["surface"] = r.surface;
    add_capture_and_faults(settings, *trial);
  }
  write_file_atomically(directory_ / "trial.json", settings.dump(2) + "\n");
}

}  // namespace echoplan::loop
