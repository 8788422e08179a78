#include "experiment/sort_confidence.h"

#include <algorithm>

namespace echoplan::experiment {

std::optional<SortConfidence> sort_confidence(const TrialResult& trial,
                                              const RightShares& right_share) {
  if (trial.record.capped || trial.steps.empty()) return std::nullopt;
  const StepRecord& last = trial.steps.back();
  const std::vector<double>& belief = last.belief;
  if (right_share.empty()) {
    const int mode = trial.record.believed_state;
    if (mode < 0 || mode >= static_cast<int>(belief.size())) return std::nullopt;
    return SortConfidence{belief[mode], mode == trial.record.true_state};
  }
  const auto share = [&](std::size_t state) {
    const std::vector<double>& row = right_share.at(state);
    return last.action >= 0 && static_cast<std::size_t>(last.action) < row.size()
               ? row[static_cast<std::size_t>(last.action)]
               : 0.0;
  };
  double mass = 0.0;
  for (std::size_t s = 0; s < belief.size() && s < right_share.size(); ++s)
    mass += belief[s] * share(s);
  const auto truth = static_cast<std::size_t>(trial.record.true_state);
  return SortConfidence{std::clamp(mass, 0.0, 1.0), share(truth) > 0.5};
}

std::vector<ArmConfidence> arm_confidence(const std::vector<std::string>& arms,
                                          const std::vector<JournalEntry>& entries,
                                          const RightShares& right_share) {
  std::vector<ArmConfidence> all;
  const std::size_t bins = kReliabilityEdges.size() - 1;
  for (const std::string& arm : arms) {
    ArmConfidence c;
    c.arm = arm;
    for (std::size_t b = 0; b < bins; ++b)
      c.bins.push_back({kReliabilityEdges[b], kReliabilityEdges[b + 1]});
    for (const JournalEntry& e : entries) {
      if (e.arm != arm) continue;
      const std::optional<SortConfidence> sort = sort_confidence(e.result, right_share);
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
