#include "experiment/noise_levels.h"

#include <fmt/format.h>

#include <algorithm>

namespace echoplan::experiment {

std::string NoiseBand::label() const {
  if (!low) return fmt::format("< {:g} dB", *high);
  if (!high) return fmt::format(">= {:g} dB", *low);
  return fmt::format("{:g} to {:g} dB", *low, *high);
}

std::optional<double> trial_heard_level(const TrialResult& trial) {
  std::vector<double> levels;
  for (const loop::StepRecord& s : trial.steps)
    if (s.heard_ebr_db) levels.push_back(*s.heard_ebr_db);
  if (levels.empty()) return std::nullopt;
  std::sort(levels.begin(), levels.end());
  const std::size_t n = levels.size();
  return n % 2 ? levels[n / 2] : (levels[n / 2 - 1] + levels[n / 2]) / 2;
}

namespace {

std::vector<NoiseBand> empty_bands() {
  std::vector<NoiseBand> bands(kNoiseBandEdges.size() + 1);
  for (std::size_t b = 0; b < bands.size(); ++b) {
    if (b > 0) bands[b].low = kNoiseBandEdges[b - 1];
    if (b < kNoiseBandEdges.size()) bands[b].high = kNoiseBandEdges[b];
  }
  return bands;
}

NoiseBand& band_of(std::vector<NoiseBand>& bands, double level) {
  const auto above = std::upper_bound(kNoiseBandEdges.begin(), kNoiseBandEdges.end(), level);
  return bands[above - kNoiseBandEdges.begin()];
}

}  // namespace

std::vector<ArmNoiseBands> arm_noise_bands(const std::vector<std::string>& arms,
                                           const std::vector<JournalEntry>& entries,
                                           const RightShares& right_share) {
  std::vector<ArmNoiseBands> all;
  for (const std::string& arm : arms) {
    ArmNoiseBands a{arm, empty_bands()};
    for (const JournalEntry& e : entries) {
      const std::optional<double> level = trial_heard_level(e.result);
      if (e.arm != arm || !level) continue;
      NoiseBand& band = band_of(a.bands, *level);
      ++band.trials;
      band.mean_heard += static_cast<double>(
          std::count_if(e.result.steps.begin(), e.result.steps.end(),
                        [](const loop::StepRecord& s) { return s.heard_ebr_db.has_value(); }));
      if (const std::optional<SortConfidence> sort = sort_confidence(e.result, right_share)) {
        ++band.sorts;
        band.mean_belief += sort->belief;
        band.share_right += sort->right;
      }
    }
    for (NoiseBand& band : a.bands) {
      if (band.trials) band.mean_heard /= band.trials;
      if (band.sorts) band.mean_belief /= band.sorts, band.share_right /= band.sorts;
    }
    all.push_back(std::move(a));
  }
  return all;
}

}  // namespace echoplan::experiment
