// Each arm's trials by the conditions they were heard in: per table they stood on, and by how
// noisy they sounded: the ratio measured from the trial's own recordings
// (the median of its steps' heard_ebr_db, audio/levels.h), in fixed bands, and per band the share
// sorted right beside the belief at the sort (sort_confidence.h) and the recordings heard per
// trial. What a campaign heard through background noise reports per noise level; the bands come
// from the recordings, not from the configured ratio, so a range of ratios is split as heard.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "experiment/condition_shares.h"

namespace echoplan::experiment {

// The bands' inner edges in dB: below 0, 0 to 6, 6 to 12, 12 to 24, 24 and above.
inline const std::vector<double> kNoiseBandEdges{0.0, 6.0, 12.0, 24.0};

struct NoiseBand : ConditionShares {
  std::optional<double> low, high;  // dB; none: unbounded
  std::string label() const;        // "< 0 dB", "0 to 6 dB", ">= 24 dB"
};

struct ArmNoiseBands {
  std::string arm;
  std::vector<NoiseBand> bands;  // one per band of kNoiseBandEdges, low to high
};

// The trial's heard level: the median of its steps' heard_ebr_db; none when it heard no recording.
std::optional<double> trial_heard_level(const TrialResult& trial);

// Per arm, in the given order, over every journal entry of that arm that heard a recording.
// `action_costs` as ConditionShares::add takes them.
std::vector<ArmNoiseBands> arm_noise_bands(const std::vector<std::string>& arms,
                                           const std::vector<JournalEntry>& entries,
                                           const RightShares& right_share,
                                           const std::vector<double>& action_costs);

// One arm's trials on one table (TrialRecord::surface).
struct SurfaceShares : ConditionShares {
  std::string surface;
};
struct ArmSurfaces {
  std::string arm;
  std::vector<SurfaceShares> surfaces;  // in order of first appearance in the journal
};

// Per arm, in the given order, over every journal entry of that arm whose world chose a table;
// empty when none did (the lab's table).
std::vector<ArmSurfaces> arm_surfaces(const std::vector<std::string>& arms,
                                      const std::vector<JournalEntry>& entries,
                                      const RightShares& right_share,
                                      const std::vector<double>& action_costs);

}  // namespace echoplan::experiment
