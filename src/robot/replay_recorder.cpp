#include "robot/replay_recorder.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "audio/io.h"
#include "common/error.h"
#include "perception/recording_set.h"

namespace echoplan::robot {

namespace fs = std::filesystem;

namespace {

const std::vector<fs::path> kNoFiles;

}  // namespace

ReplayRecorder::ReplayRecorder(fs::path directory) : directory_(std::move(directory)) {
  // The one loader of recording folders, so replay accepts and rejects what training does. The
  // index is built once: trials then only shuffle and read.
  const perception::RecordingSet set = perception::load_recording_set(directory_.string());
  for (const perception::Recording& r : set.recordings)
    files_[r.object][r.action].push_back(r.path);
  for (auto& [object, actions] : files_)
    for (auto& [action, files] : actions) std::sort(files.begin(), files.end());
}

const std::vector<fs::path>& ReplayRecorder::recordings(const std::string& object,
                                                        const std::string& action) const {
  const auto o = files_.find(object);
  if (o == files_.end()) return kNoFiles;
  const auto a = o->second.find(action);
  return a == o->second.end() ? kNoFiles : a->second;
}

void ReplayRecorder::check(const std::string& object, const std::string& action) const {
  if (files_.find(object) == files_.end())
    throw InputError(
        (directory_ / object).string(), 0,
        fmt::format("no recordings of '{}' to replay (the folder is missing)", object));
  if (recordings(object, action).empty())
    throw InputError(
        (directory_ / object / action).string(), 0,
        fmt::format("no recordings of '{}' for action '{}' to replay (expected .wav, .flac or "
                    ".aiff files in this folder)",
                    object, action));
}

void ReplayRecorder::begin_trial(const TrialContext& context) {
  if (files_.find(context.object) == files_.end())
    throw InputError(
        (directory_ / context.object).string(), 0,
        fmt::format("no recordings of '{}' to replay (the folder is missing)", context.object));
  object_ = context.object;
  rng_.seed(context.seed);
  deals_.clear();
  current_.clear();
  listening_ = false;
  in_trial_ = true;
}

void ReplayRecorder::start(const std::string& action) {
  if (!in_trial_) throw std::logic_error("ReplayRecorder::start before begin_trial()");
  check(object_, action);
  const auto& files = recordings(object_, action);
  Deal& deal = deals_[action];
  if (deal.next == deal.order.size()) {
    // A fresh shuffle (Fisher-Yates on uniform01, the same on every platform).
    deal.order.resize(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) deal.order[i] = i;
    for (std::size_t i = files.size(); i > 1; --i) {
      const auto j = static_cast<std::size_t>(uniform01(rng_) * static_cast<double>(i));
      std::swap(deal.order[i - 1], deal.order[std::min(j, i - 1)]);
    }
    deal.next = 0;
  }
  current_ = files[deal.order[deal.next++]];
  listening_ = true;
}

audio::AudioClip ReplayRecorder::stop() {
  if (!listening_) throw std::logic_error("ReplayRecorder::stop without start()");
  listening_ = false;
  return audio::read_audio(current_.string());
}

ActionReport ReplayRobot::execute(const std::string& action) {
  if (std::find(actions_.begin(), actions_.end(), action) == actions_.end())
    throw InputError(fmt::format("the replay robot has no action '{}' (known: {})", action,
                                 fmt::join(actions_, ", ")));
  return ActionReport{action, ActionStatus::done, "", 0.0};
}

}  // namespace echoplan::robot
