// Recorded data as the world: a trial replays one held-out session of a feature set (or of a
// recordings tree's features). Each sensing action takes the session's next recorded performance
// of that behaviour, and the observation model (fitted on the other folds, or a frozen model
// file) hears it; a sorting action earns
// the problem's reward for the trial's true class. Nothing is drawn at random: the same session
// gives the same observations to every arm, so arms are compared on exactly the same data.
#pragma once

#include <memory>
#include <vector>

#include "loop/world.h"
#include "perception/feature_set.h"
#include "perception/observation_model.h"
#include "perception/performance_reader.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::loop {

// What a dataset world replays. The problem's sensing actions are the set's actions, by name.
struct DatasetWorldSpec {
  std::shared_ptr<const perception::FeatureSet> data;
  // Fitted on folds without `session`, or trained on other data (its modalities matched by name).
  std::shared_ptr<const perception::ObservationModel> model;
  int session = 0;  // index into data->sessions
};

class DatasetWorld final : public World {
 public:
  // Throws InputError when a sensing action of `problem` is not an action of the data or the
  // model, the data lacks a modality the model needs, or the model's symbols are not the
  // problem's observations.
  DatasetWorld(const pomdp::ObjectIdentificationModel& problem, DatasetWorldSpec spec);

  void reset(const pomdp::State& true_state, Rng& rng) override;
  // A sensing action used more often than the session recorded it is an InputError: the problem's
  // use limits, when they are the session's counts (as a campaign's are), stop a planner before
  // that; a replay planning with other limits (`run --data --uses problem`) may not.
  WorldStep execute(int action, Rng& rng) override;

 private:
  const pomdp::ObjectIdentificationModel& problem_;
  DatasetWorldSpec spec_;
  perception::ObservationKind kind_ = perception::ObservationKind::labels;  // the problem's
  std::vector<perception::PerformanceReader> readers_;                      // [sensing action]
  std::vector<std::vector<int>> rows_;  // [sensing action] -> the session's rows, file order
  std::vector<std::size_t> next_;       // [sensing action] -> rows used so far this trial
  int true_class_ = 0;
};

// How often the session recorded each of `problem`'s sensing actions: its use limits in a trial.
// InputError for a session without a recording of some action (a limit of 0 means none).
std::vector<int> session_uses(const pomdp::ObjectProblemData& problem,
                              const perception::FeatureSet& data, int session);

}  // namespace echoplan::loop
