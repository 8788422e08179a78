#include "experiment/sort_confidence.h"

#include <algorithm>

namespace echoplan::experiment {

std::optional<SortConfidence> sort_confidence(const TrialResult& trial,
                                              const std::vector<int>& right_action) {
  if (trial.record.capped || trial.steps.empty()) return std::nullopt;
  const StepRecord& last = trial.steps.back();
  const std::vector<double>& belief = last.belief;
  if (right_action.empty()) {
    const int mode = trial.record.believed_state;
    if (mode < 0 || mode >= static_cast<int>(belief.size())) return std::nullopt;
    return SortConfidence{belief[mode], mode == trial.record.true_state};
  }
  double mass = 0.0;
  for (std::size_t s = 0; s < belief.size() && s < right_action.size(); ++s)
    if (right_action[s] == last.action) mass += belief[s];
  return SortConfidence{std::clamp(mass, 0.0, 1.0),
                        right_action.at(trial.record.true_state) == last.action};
}

std::vector<ArmConfidence> arm_confidence(const std::vector<std::string>& arms,
                                          const std::vector<JournalEntry>& entries,
                                          const std::vector<int>& right_action) {
  std::vector<ArmConfidence> all;
  const std::size_t bins = kReliabilityEdges.size() - 1;
  for (const std::string& arm : arms) {
    ArmConfidence c;
    c.arm = arm;
    for (std::size_t b = 0; b < bins; ++b)
      c.bins.push_back({kReliabilityEdges[b], kReliabilityEdges[b + 1]});
    for (const JournalEntry& e : entries) {
      if (e.arm != arm) continue;
      const std::optional<SortConfidence> sort = sort_confidence(e.result, right_action);
      if (!sort) continue;
      ++c.sorts;
      c.mean_belief += sort->belief;
      c.share_right += sort->right;
      const auto upper = std::upper_bound(kReliabilityEdges.begin() + 1,
                                          kReliabilityEdges.end() - 1, sort->belief);
      ReliabilityBin& bin = c.bins[upper - kReliabilityEdges.begin() - 1];
      ++bin.sorts;
      bin.mean_belief += sort->belief;
      bin.share_right += sort->right;
    }
    const auto mean = [](double& sum, int n) { sum = n ? sum / n : 0.0; };
    mean(c.mean_belief, c.sorts);
    mean(c.share_right, c.sorts);
    for (ReliabilityBin& bin : c.bins) {
      mean(bin.mean_belief, bin.sorts);
      mean(bin.share_right, bin.sorts);
    }
    all.push_back(std::move(c));
  }
  return all;
}

}  // namespace echoplan::experiment
