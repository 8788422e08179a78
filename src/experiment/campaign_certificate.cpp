#include "experiment/campaign_certificate.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "common/error.h"
#include "common/file_io.h"
#include "experiment/dataset_campaign.h"
#include "solvers/identification_solver.h"

namespace echoplan::experiment {

namespace fs = std::filesystem;

Certificate certify_steps(const pomdp::Problem& problem, const std::string& problem_path,
                          const fs::path& steps, const CertifyOptions& options) {
  const pomdp::TabularModel* tables = problem.model->tabular();
  if (tables == nullptr)
    throw InputError(problem_path, 0, "certify needs a discrete problem with tables");
  if (auto why = solvers::identification_shape_problem(*tables))
    throw InputError(problem_path, 0,
                     "certify needs an identification problem (the state stays fixed until an "
                     "action ends the episode), and this one is not: " +
                         *why);
  const auto trials = read_steps_csv(steps, problem.model->spec());
  if (trials.empty()) throw InputError(steps.string(), 0, "no trials in the steps file");
  // With the problem's use limits: each decision is judged with the uses its trial had made so far
  // (the solver's node after the trial's earlier steps counts them).
  solvers::IdentificationSolver solver(
      solvers::read_identification_tables(*tables, solvers::UseLimits(*problem.model)));
  return certify_trials(solver, trials, options, steps.string());
}

namespace {

// The fold folders under `folds`, in numeric order ("2" before "10").
std::vector<std::string> fold_names(const fs::path& folds) {
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(folds))
    if (e.is_directory()) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  return names;
}

struct ArmEntry {
  std::string name;
  ArmProblemKind problem;
};

// The campaign's arms in its own order (campaign.json's configuration, resolved as the campaign
// resolved them), the planner usually first, with the kind of fold problem each planned with
// (problem.yaml, problem-graded.yaml, ...).
std::vector<ArmEntry> arm_entries(const fs::path& directory) {
  const fs::path described = directory / "campaign.json";
  const nlohmann::json j = nlohmann::json::parse(
      read_text_file(described.string(), "campaign description"), nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("config"))
    throw InputError(described.string(), 0, "is not a campaign description");
  std::vector<ArmEntry> arms;
  try {
    for (const ResolvedArm& arm :
         resolve_arms(campaign_config_from_json(j["config"], described.string())))
      arms.push_back({arm.name, arm.plans_with});
  } catch (const InputError& e) {
    throw InputError(described.string(), 0, e.problem());
  }
  return arms;
}

}  // namespace

std::vector<ArmCertificate> certify_campaign(const fs::path& directory,
                                             const CertifyOptions& options,
                                             const CertifiedProgress& progress,
                                             const std::atomic<bool>* stop) {
  const fs::path folds = directory / "folds";
  if (!fs::is_directory(folds))
    throw InputError(directory.string(), 0,
                     "has no folds/ folder: certify --campaign takes a dataset campaign's folder "
                     "(each fold's problem beside its trials)");
  const std::vector<ArmEntry> arms = arm_entries(directory);
  const std::vector<std::string> fold_list = fold_names(folds);
  const std::size_t total = fold_list.size() * arms.size();
  if (total == 0) throw InputError(folds.string(), 0, "holds no folds");
  std::vector<ArmCertificate> certificates;
  for (const std::string& fold : fold_list) {
    std::map<std::string, pomdp::Problem> problems;  // loaded once per fold
    for (const ArmEntry& arm : arms) {
      if (stop != nullptr && stop->load()) return certificates;
      const std::string name = fold_problem_name(arm.problem);
      const std::string problem_file = "folds/" + fold + "/" + name;
      const fs::path problem_path = directory / problem_file;
      if (!problems.contains(name)) {
        if (!fs::is_regular_file(problem_path))
          throw InputError(
              problem_path.string(), 0,
              "missing: the campaign writes each fold's problem once its folds are fitted");
        problems.emplace(name, pomdp::load_problem(problem_path.string()));
      }
      const fs::path steps = folds / fold / "arms" / arm.name / "steps.csv";
      if (!fs::is_regular_file(steps))
        throw InputError(steps.string(), 0,
                         "missing: the campaign has not written this fold's trials");
      certificates.push_back(
          {fold, arm.name, problem_file,
           certify_steps(problems.at(name), problem_path.string(), steps, options)});
      if (progress) progress(certificates.back(), certificates.size(), total);
    }
  }
  return certificates;
}

namespace {

// How loose the certificate is, as a share of V*: V*(b0)'s own gap or the mean per-trial gap its
// bounds add to the regret, whichever is larger.
double looseness_share(const Certificate& c) {
  const double vstar = 0.5 * (c.vstar.lower + c.vstar.upper);
  const double loose = std::max(c.vstar.upper - c.vstar.lower, c.bound_gap_mean);
  return vstar != 0.0 ? loose / std::abs(vstar) : std::numeric_limits<double>::infinity();
}

bool tight(const Certificate& c) { return looseness_share(c) <= kTightShare; }

double share(const Certificate& c, double regret) { return share_of_vstar(c.vstar, regret); }

}  // namespace

nlohmann::ordered_json campaign_certificate_json(const std::vector<ArmCertificate>& certificates) {
  nlohmann::ordered_json folds = nlohmann::ordered_json::array();
  for (const ArmCertificate& a : certificates) {
    const Certificate& c = a.certificate;
    nlohmann::ordered_json j = {{"fold", a.fold}, {"arm", a.arm}, {"problem", a.problem}};
    j.update(to_json(c));  // share_of_vstar is replaced below: stated only where tight
    j["looseness_share"] = looseness_share(c);
    j["tight"] = tight(c);
    if (tight(c)) {
      j["share_of_vstar"] = share(c, c.regret.mean);
      j["share_ci95"] = {share(c, c.regret.mean + c.regret.half_width),
                         share(c, c.regret.mean - c.regret.half_width)};
    } else {
      j["share_of_vstar"] = nullptr;
      j["share_range"] = {share(c, c.regret.mean), share(c, c.regret_lower_mean)};
    }
    folds.push_back(std::move(j));
  }
  nlohmann::ordered_json out;
  out["tight_within"] = kTightShare;
  out["folds"] = std::move(folds);
  return out;
}

std::string campaign_certificate_text(const std::vector<ArmCertificate>& certificates) {
  std::size_t width = 20;  // the arm column fits the longest name
  for (const ArmCertificate& a : certificates) width = std::max(width, a.arm.size() + 2);
  std::string out = fmt::format("{:>6}  {:<{}}{:>8}{:>22}{:>24}  {}\n", "fold", "arm", width,
                                "trials", "V*(b0)", "regret (95% CI)", "certified share of V*");
  for (const ArmCertificate& a : certificates) {
    const Certificate& c = a.certificate;
    out += fmt::format("{:>6}  {:<{}}{:>8}{:>22}{:>24}  ", a.fold, a.arm, width, c.regret.n,
                       fmt::format("[{:.4f}, {:.4f}]", c.vstar.lower, c.vstar.upper),
                       fmt::format("{:.4f} ± {:.4f}", c.regret.mean, c.regret.half_width));
    out += tight(c) ? fmt::format("{:.2f}% ({:.2f}% to {:.2f}%)\n", 100.0 * share(c, c.regret.mean),
                                  100.0 * share(c, c.regret.mean + c.regret.half_width),
                                  100.0 * share(c, c.regret.mean - c.regret.half_width))
                    : fmt::format("bounds too loose to say ({:.2f}% of V*): {:.2f}% to {:.2f}%\n",
                                  100.0 * looseness_share(c), 100.0 * share(c, c.regret.mean),
                                  100.0 * share(c, c.regret_lower_mean));
  }
  return out;
}

}  // namespace echoplan::experiment
