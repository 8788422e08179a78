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
                                           const RightShares& right_share,
                                           const std::vector<double>& action_costs) {
  std::vector<ArmNoiseBands> all;
  for (const std::string& arm : arms) {
    ArmNoiseBands a{arm, empty_bands()};
    for (const JournalEntry& e : entries) {
      const std::optional<double> level = trial_heard_level(e.result);
      if (e.arm == arm && level) band_of(a.bands, *level).add(e.result, right_share, action_costs);
    }
    for (NoiseBand& band : a.bands) band.finish();
    all.push_back(std::move(a));
  }
  return all;
}

std::vector<ArmSurfaces> arm_surfaces(const std::vector<std::string>& arms,
                                      const std::vector<JournalEntry>& entries,
                                      const RightShares& right_share,
                                      const std::vector<double>& action_costs) {
  std::vector<std::string> surfaces;
  for (const JournalEntry& e : entries)
    if (!e.result.record.surface.empty() &&
        std::find(surfaces.begin(), surfaces.end(), e.result.record.surface) == surfaces.end())
      surfaces.push_back(e.result.record.surface);
  if (surfaces.empty()) return {};
  std::vector<ArmSurfaces> all;
  for (const std::string& arm : arms) {
    ArmSurfaces a{arm, {}};
    for (const std::string& surface : surfaces) {
      SurfaceShares shares;
      shares.surface = surface;
      for (const JournalEntry& e : entries)
        if (e.arm == arm && e.result.record.surface == surface)
          shares.add(e.result, right_share, action_costs);
      shares.finish();
      a.surfaces.push_back(std::move(shares));
    }
    all.push_back(std::move(a));
  }
  return all;
}

}  // namespace echoplan::experiment
