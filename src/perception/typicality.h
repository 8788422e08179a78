// Objects that sound like another class. Different behaviours on one object do not err
// independently given its class: an object unlike its class (a weighted can, a foam-filled bottle)
// fools several behaviours at once, and the product of their tables, each calibrated on its own,
// is then surer than the object's sorts are right (docs/BENCHMARKS.md, "Honest confidence").
//
// The model: a share rho of the objects are lookalikes, an object of class k that sounds like
// class j in every behaviour (a weighted can heard as the mug, a novel bottle that behaves as the
// jars do), the other class uniform among the K - 1:
//   P(heard | k) = (1 - rho) L(k) + rho / (K - 1) sum_{j != k} L(j),   L(j) = prod_i P_ai(o_i | j).
// Agreeing behaviours cannot then make the belief surer than about 1 - rho: however clearly an
// object sounds like j, it is j only if it is not a lookalike. As a POMDP: every class j gets a
// copy "sounds like j, is another class", heard through j's rows, whose sorting reward is the mean
// over the other classes (loop/dataset_problem.h).
//
// Rho is fitted on inner-held-out sessions (held-out objects when the task sorts novel objects,
// held-out sessions when it sorts known ones): it minimises the negative log-likelihood of the true
// class after each session's whole sequence of performances, the first of each of its behaviours in
// an order rotated by the session's index (session s starts at behaviour s mod n), then the second
// of each behaviour performed twice, and so on. Each performance is scored with its action's table
// of the other inner folds, untempered or tempered for repeats: the mixture models how repeats err
// together too, so fit_lookalikes (below) tries both and a problem with lookalikes plans with the
// tables it kept (loop/dataset_problem.h). Repeats belong in the sequences: an object unlike its
// class repeats its error when a behaviour is performed again, and a planner repeats behaviours
// exactly when readings disagree. Why whole sequences, not every prefix: rho caps the belief where
// the evidence is strongest, which is where a planner that keeps sensing sorts the objects it finds
// hard; a session's short prefixes, where rho changes little, outnumber its whole sequence and
// pulled the fit towards the typical objects (git history). A class-blind model (an unlike object's
// performances carry no class) was tried too and lost to lookalikes on every stand-in (git
// history).
#pragma once

#include <span>
#include <vector>

#include "perception/observation_table.h"

namespace echoplan::perception {

// One action's inner-held-out performances, in any order.
struct HeldOutPerformances {
  std::vector<int> session;  // the sequence of repeats each performance is one of (its session)
  std::vector<int> fold;     // its inner fold (the same for all of a session's performances)
  std::vector<int> label;    // its true class
  std::vector<int> symbol;   // what it was heard as
  // [fold]: the action's table fitted without that fold, untempered.
  std::vector<Table> cross_fitted;
  double temper = 1.0;  // the action's power for repeats (observation_table.h)
};

// Every prefix of the sequences described above, each session's in turn; sequence.tables[i]
// indexes the actions' cross-fitted tables concatenated (action * folds + fold; every action has
// the same number of folds).
std::vector<Sequence> cross_behaviour_sequences(std::span<const HeldOutPerformances> actions);

// The largest share a fit may give: beyond it a lookalike is the rule, not the exception.
inline constexpr double kLargestShare = 0.5;

// Sum over sequences of -log P(true class | symbols) under the mixture above; tables as
// cross_behaviour_sequences indexes them.
double lookalike_nll(std::span<const Table> tables, double rho,
                     std::span<const Sequence> sequences);
// Rho in [0, kLargestShare] minimising lookalike_nll over whole_session_sequences; 0 when no share
// lowers it, there are no sequences or only one class.
double fit_lookalike_share(std::span<const HeldOutPerformances> actions);

// The share and the tables it mixes: untempered, or tempered with each action's power.
struct LookalikeFit {
  double share = 0.0;
  bool untempered = false;
};
// A share fitted on the untempered tables and one on the tempered, and of the two the one whose
// mixture gives the lower lookalike_nll over every prefix of cross_behaviour_sequences (every
// point where a planner may sort). Untempered, the mixture models how repeats err together
// instead of a power, which would also flatten each first reading; where the mixture cannot
// explain the correlation (the share at its largest and still too sure) the tempered fit wins.
// An untempered fit needs a share above 0.
LookalikeFit fit_lookalikes(std::span<const HeldOutPerformances> actions);

// Each session's last sequence of cross_behaviour_sequences: all its performances.
std::vector<Sequence> whole_session_sequences(std::span<const HeldOutPerformances> actions);

}  // namespace echoplan::perception
