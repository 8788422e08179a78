#include "solvers/leaf_value.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/error.h"
#include "solvers/belief_leaf_values.h"
#include "solvers/identification_solver.h"
#include "solvers/state_leaf_values.h"

namespace echoplan::solvers {

LeafMode parse_leaf_mode(const std::string& text) {
  if (text == "policy") return LeafMode::policy;
  if (text == "exact") return LeafMode::exact;
  if (text == "exact-offline") return LeafMode::exact_offline;
  if (text == "lookahead") return LeafMode::lookahead;
  if (text == "heuristic") return LeafMode::heuristic;
  if (text == "rollout") return LeafMode::rollout;
  throw InputError("leaf value '" + text +
                   "' is not one of policy, exact, exact-offline, lookahead, heuristic, rollout");
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
