#include "solvers/leaf_value.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "common/error.h"
#include "solvers/belief_leaf_values.h"
#include "solvers/identification_solver.h"
#include "solvers/state_leaf_values.h"

namespace echoplan::solvers {

namespace {
constexpr std::array kLeafModes{LeafMode::policy,    LeafMode::exact,     LeafMode::exact_offline,
                                LeafMode::lookahead, LeafMode::heuristic, LeafMode::rollout};
}  // namespace

LeafMode parse_leaf_mode(const std::string& text) {
  for (LeafMode mode : kLeafModes)
    if (text == leaf_mode_name(mode)) return mode;
  throw InputError("leaf value '" + text + "' is not one of " +
                   fmt::format("{}", fmt::join(leaf_mode_names(), ", ")));
}

std::vector<std::string> leaf_mode_names() {
  std::vector<std::string> names;
  for (LeafMode mode : kLeafModes) names.emplace_back(leaf_mode_name(mode));
  return names;
}

const char* leaf_mode_name(LeafMode mode) {
  switch (mode) {
    case LeafMode::policy:
      return "policy";
    case LeafMode::exact:
      return "exact";
    case LeafMode::exact_offline:
      return "exact-offline";
    case LeafMode::lookahead:
      return "lookahead";
    case LeafMode::heuristic:
      return "heuristic";
    case LeafMode::rollout:
      return "rollout";
  }
  return "?";
}

LeafMode default_leaf_mode(const std::string& solver, const pomdp::Model& model) {
  const pomdp::TabularModel* tables = model.tabular();
  if (solver == "abt" && tables != nullptr && !identification_shape_problem(*tables))
    return LeafMode::policy;
  return LeafMode::lookahead;
}

bool follows_exact_belief(LeafMode mode) {
  return mode == LeafMode::policy || mode == LeafMode::exact || mode == LeafMode::exact_offline;
}

std::unique_ptr<LeafValue> make_leaf_value(const LeafOptions& options, const pomdp::ModelPtr& model,
                                           LeafUse use) {
  const LeafMode mode = options.mode;
  switch (mode) {
    case LeafMode::lookahead:
      return std::make_unique<LookaheadLeafValue>();
    case LeafMode::heuristic:
      return std::make_unique<HeuristicLeafValue>();
    case LeafMode::rollout:
      return std::make_unique<RolloutLeafValue>();
    case LeafMode::policy:
    case LeafMode::exact:
    case LeafMode::exact_offline:
      break;
  }
  // POMCP stays the textbook algorithm: its leaves see states, not beliefs.
  if (use == LeafUse::state_tree)
    throw InputError(std::string("the ") + leaf_mode_name(mode) +
                     " leaf value is ABT's; POMCP takes lookahead, heuristic or rollout");
  if (model->tabular() == nullptr)
    throw InputError(std::string("the ") + leaf_mode_name(mode) +
                     " leaf value needs a discrete problem with tables; use --leaf "
                     "lookahead for this one");
  if (mode == LeafMode::policy) return std::make_unique<PolicyLeafValue>(model);
  return std::make_unique<ExactLeafValue>(
      model, options.exact_share, mode == LeafMode::exact_offline ? options.offline_expansions : 0);
}

double* LeafEstimate::accumulate(std::size_t accumulators, int samples) {
  sums_.resize(accumulators, 0.0);
  count_ += samples;
  return sums_.data();
}

double LeafEstimate::value() const {
  if (count_ == 0) return 0.0;
  // One accumulator is a plain mean; several are per-action (or per-threshold) means, of which the
  // best counts.
  return *std::max_element(sums_.begin(), sums_.end()) / count_;
}

void LeafEstimate::remove(const std::vector<double>& contribution) {
  if (count_ == 0 || contribution.size() != sums_.size())
    throw std::logic_error("LeafEstimate::remove(): not a contribution of this estimate");
  // An action used up at the node holds -inf from every particle (a contribution measured across
  // add() is then NaN or infinite): it stays -inf.
  for (std::size_t i = 0; i < sums_.size(); ++i)
    if (std::isfinite(contribution[i])) sums_[i] -= contribution[i];
  --count_;
}

void LeafEstimate::set(double value) {
  sums_.assign(1, value);
  count_ = 1;
}

void LeafEstimate::release() {
  sums_.clear();
  sums_.shrink_to_fit();
}

}  // namespace echoplan::solvers
