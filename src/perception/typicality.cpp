#include "perception/typicality.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/golden_section.h"

namespace echoplan::perception {

namespace {

// One performance of an action in a session: its fold, class and symbol.
struct Performance {
  int fold = 0;
  int label = 0;
  int symbol = 0;
};

// A sequence's log-likelihoods, which do not depend on rho: per class, log prod_i P_ai(o_i | k).
struct ScoredSequence {
  std::vector<double> log_likelihood;
  int true_class = 0;
};

std::vector<ScoredSequence> score(std::span<const Table> tables,
                                  std::span<const Sequence> sequences) {
  const std::size_t classes = tables.front().size();
  std::vector<ScoredSequence> scored;
  for (const Sequence& sequence : sequences) {
    ScoredSequence s{std::vector<double>(classes, 0.0), sequence.true_class};
    for (std::size_t i = 0; i < sequence.symbols.size(); ++i) {
      const auto t = static_cast<std::size_t>(sequence.tables.at(i));
      const auto o = static_cast<std::size_t>(sequence.symbols[i]);
      for (std::size_t c = 0; c < classes; ++c) s.log_likelihood[c] += std::log(tables[t][c][o]);
    }
    scored.push_back(std::move(s));
  }
  return scored;
}

}  // namespace

std::vector<Sequence> cross_behaviour_sequences(std::span<const HeldOutPerformances> actions) {
  if (actions.empty()) return {};
  const auto folds = static_cast<int>(actions.front().cross_fitted.size());
  // [session][action] -> its performances in order; actions in index order.
  std::map<int, std::map<int, std::vector<Performance>>> sessions;
  for (std::size_t a = 0; a < actions.size(); ++a) {
    const HeldOutPerformances& held = actions[a];
    for (std::size_t i = 0; i < held.session.size(); ++i)
      sessions[held.session[i]][static_cast<int>(a)].push_back(
          Performance{held.fold[i], held.label[i], held.symbol[i]});
  }
  std::vector<Sequence> sequences;
  for (const auto& [session, performed] : sessions) {
    const std::vector<std::pair<int, std::vector<Performance>>> order(performed.begin(),
                                                                      performed.end());
    const std::size_t n = order.size();
    std::size_t rounds = 0;
    for (const auto& [action, list] : order) rounds = std::max(rounds, list.size());
    Sequence sequence;
    sequence.true_class = order.front().second.front().label;
    for (std::size_t r = 0; r < rounds; ++r)
      for (std::size_t k = 0; k < n; ++k) {
        const auto& [action, list] = order[(static_cast<std::size_t>(session) + k) % n];
        if (r >= list.size()) continue;
        sequence.symbols.push_back(list[r].symbol);
        sequence.tables.push_back(action * folds + list[r].fold);
        sequences.push_back(sequence);
      }
  }
  return sequences;
}

std::vector<Sequence> whole_session_sequences(std::span<const HeldOutPerformances> actions) {
  std::vector<Sequence> prefixes = cross_behaviour_sequences(actions);
  // A session's prefixes come one performance longer each, so a prefix that the next one does not
  // extend is its session's whole sequence.
  std::vector<Sequence> whole;
  for (std::size_t i = 0; i < prefixes.size(); ++i)
    if (i + 1 == prefixes.size() || prefixes[i + 1].symbols.size() <= prefixes[i].symbols.size())
      whole.push_back(std::move(prefixes[i]));
  return whole;
}

namespace {

// Per sequence, the posterior of its true class without lookalikes, L(true) / sum_j L(j) (uniform
// prior), and its number of classes: all the lookalike mixture needs, whatever rho.
struct TruthPosterior {
  double truth = 0.0;
  double classes = 0.0;
};

std::vector<TruthPosterior> truth_posteriors(const std::vector<ScoredSequence>& scored) {
  std::vector<TruthPosterior> posteriors;
  for (const ScoredSequence& s : scored) {
    const double top = *std::max_element(s.log_likelihood.begin(), s.log_likelihood.end());
    double evidence = 0.0;
    for (double l : s.log_likelihood) evidence += std::exp(l - top);
    posteriors.push_back(
        {std::exp(s.log_likelihood[static_cast<std::size_t>(s.true_class)] - top) / evidence,
         static_cast<double>(s.log_likelihood.size())});
  }
  return posteriors;
}

// Sum of -log P(true class | sequence) when a share rho of the objects sound like another class:
// P(heard | k) = (1 - rho) L(k) + rho / (K - 1) sum_{j != k} L(j), uniform class prior, so the
// evidence sum_k P(heard | k) is sum_j L(j) whatever rho, and the posterior of the true class is
// (1 - rho) t + rho (1 - t) / (K - 1) with t its posterior without lookalikes.
double lookalike_nll(const std::vector<TruthPosterior>& posteriors, double rho) {
  double total = 0.0;
  for (const TruthPosterior& p : posteriors)
    total -= std::log((1.0 - rho) * p.truth + rho * (1.0 - p.truth) / (p.classes - 1.0));
  return total;
}

// The share in [0, kLargestShare] minimising `nll`, or 0 when none lowers it.
template <class Nll>
double fit_share(const Nll& nll) {
  const double rho = golden_section_minimum(nll, 0.0, kLargestShare);
  // The search never evaluates the end points; keep 0 (the tables as they are) unless rho helps.
  return nll(rho) < nll(0.0) ? rho : 0.0;
}

// `sequences` of the actions (as cross_behaviour_sequences indexes them) scored with their
// cross-fitted tables.
std::vector<ScoredSequence> scored_sequences(std::span<const HeldOutPerformances> actions,
                                             const std::vector<Sequence>& sequences) {
  if (sequences.empty()) return {};
  std::vector<Table> tables;
  for (const HeldOutPerformances& held : actions)
    tables.insert(tables.end(), held.cross_fitted.begin(), held.cross_fitted.end());
  return score(tables, sequences);
}

}  // namespace

double lookalike_nll(std::span<const Table> tables, double rho,
                     std::span<const Sequence> sequences) {
  return lookalike_nll(truth_posteriors(score(tables, sequences)), rho);
}

LookalikeFit fit_lookalikes(std::span<const HeldOutPerformances> actions) {
  std::vector<HeldOutPerformances> tempered(actions.begin(), actions.end());
  for (HeldOutPerformances& held : tempered)
    for (Table& table : held.cross_fitted) table = temper(table, held.temper);
  const LookalikeFit as_is{fit_lookalike_share(actions), true},
      powered{fit_lookalike_share(tempered), false};
  const std::vector<Sequence> prefixes = cross_behaviour_sequences(actions);
  if (as_is.share <= 0.0 || prefixes.empty()) return powered;
  const auto nll = [&](std::span<const HeldOutPerformances> held, double share) {
    return lookalike_nll(truth_posteriors(scored_sequences(held, prefixes)), share);
  };
  return nll(actions, as_is.share) < nll(tempered, powered.share) ? as_is : powered;
}

double fit_lookalike_share(std::span<const HeldOutPerformances> actions) {
  const std::vector<ScoredSequence> scored =
      scored_sequences(actions, whole_session_sequences(actions));
  if (scored.empty() || scored.front().log_likelihood.size() < 2) return 0.0;
  const std::vector<TruthPosterior> posteriors = truth_posteriors(scored);
  return fit_share([&](double rho) { return lookalike_nll(posteriors, rho); });
}

}  // namespace echoplan::perception
