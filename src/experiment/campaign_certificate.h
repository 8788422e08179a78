// A dataset campaign certified fold by fold (`echoplan certify --campaign DIR`): each fold's trials
// judged with the problem that fold planned with (DIR/folds/<fold>/problem.yaml beside
// DIR/folds/<fold>/arms/<arm>/steps.csv, written by the campaign), since the folds' calibrated
// tables differ and one problem for all would certify the wrong decisions.
#pragma once

#include <atomic>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiment/regret_certificate.h"
#include "pomdp/problem.h"

namespace echoplan::experiment {

// Certifies the trials of `steps` (an echoplan steps.csv) against `problem` (read from
// `problem_path`, named in errors). Throws InputError when the problem has no tables or is not an
// identification problem, or the steps file has no trials or a history the problem cannot produce.
Certificate certify_steps(const pomdp::Problem& problem, const std::string& problem_path,
                          const std::filesystem::path& steps, const CertifyOptions& options);

struct ArmCertificate {
  std::string fold;  // the folder name under folds/ ("1", "2", ...)
  std::string arm;
  std::string problem;  // the fold's problem the arm planned with, relative to the campaign folder
  Certificate certificate;
};

// Told after each fold and arm is certified, in order: that certificate, and how many of how many
// are done (a campaign's certificates can take many minutes, the exact bounds at every belief).
using CertifiedProgress =
    std::function<void(const ArmCertificate& certified, std::size_t done, std::size_t total)>;

// Every fold (in numeric order) and arm (in the campaign's order, from its campaign.json) of the
// campaign folder `directory`; once `stop` is set, no further one is begun, and those finished are
// returned. Throws InputError when it has no folds/ (not a dataset campaign, or written before
// folds were), a fold has no problem.yaml, or an arm's steps.csv is missing.
std::vector<ArmCertificate> certify_campaign(const std::filesystem::path& directory,
                                             const CertifyOptions& options,
                                             const CertifiedProgress& progress = {},
                                             const std::atomic<bool>* stop = nullptr);

// A certificate's share of V* is only worth stating when its bounds are this tight: V*(b0)'s gap
// and the mean per-trial looseness each within 1% of V*.
inline constexpr double kTightShare = 0.01;

// One entry per fold and arm: V*(b0)'s bounds, the regret (mean, CI), `tight`, and then either the
// certified share of V* with its 95% CI, or (not tight) `share_of_vstar` null, the share's range
// between the bounds' two ends (`share_range`) and how loose the bounds are as a share of V*
// (`looseness_share`).
nlohmann::ordered_json campaign_certificate_json(const std::vector<ArmCertificate>& certificates);

// The same as text, a line per fold and arm.
std::string campaign_certificate_text(const std::vector<ArmCertificate>& certificates);

}  // namespace echoplan::experiment
