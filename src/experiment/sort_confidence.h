// How sure each arm was when it sorted, beside how often it sorted right: the planner's belief at
// the final decision means what it says when the two agree (a reliability measure). A trial's
// confidence is the belief, at the decision that sorted, in what the decision stood for:
//   - with `right_share` (a dataset world sorts classes into bins; right_share[s][a] is the chance
//     that action a sorts an object in state s right), the belief's expectation of that chance
//     for the chosen action: the mass of the classes in the chosen bin, plus the share of each
//     lookalike copy whose other classes are in it; the trial is right when the chosen action
//     sorts the truth right;
//   - otherwise (the report's problems, right when the final belief's mode is the truth), the
//     belief in that mode.
// Trials stopped by max_steps never sorted and are left out.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "experiment/trial_journal.h"

namespace echoplan::experiment {

struct SortConfidence {
  double belief = 0.0;  // in [0, 1]
  bool right = false;
};

using RightShares = std::vector<std::vector<double>>;  // [state][action], in [0, 1]

// The trial's confidence at its sort; nothing for a capped trial or one without steps.
std::optional<SortConfidence> sort_confidence(const TrialResult& trial,
                                              const RightShares& right_share);

// Sorts whose confidence fell in [low, high) (the last bin includes 1).
struct ReliabilityBin {
  double low = 0.0;
  double high = 0.0;
  int sorts = 0;
  double mean_belief = 0.0;  // 0 when empty
  double share_right = 0.0;  // 0 when empty
};

// One arm's sorts: how sure, how right, and both per confidence bin.
struct ArmConfidence {
  std::string arm;
  int sorts = 0;
  double mean_belief = 0.0;
  double share_right = 0.0;
  std::vector<ReliabilityBin> bins;  // the fixed edges of kReliabilityEdges
};

// The bins' edges: confidence concentrates near 1, where the bins are narrow.
inline const std::vector<double> kReliabilityEdges{0.0, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 0.99, 1.0};

// Per arm of the campaign, in the configuration's order, over every journal entry of that arm.
std::vector<ArmConfidence> arm_confidence(const std::vector<std::string>& arms,
                                          const std::vector<JournalEntry>& entries,
                                          const RightShares& right_share);

}  // namespace echoplan::experiment
