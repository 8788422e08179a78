// Objects unlike their class. Different behaviours on one object do not err independently given
// its class: an object unlike its class (a weighted can, a foam-filled bottle) fools several
// behaviours at once, and the product of their tables, each calibrated on its own, is then surer
// than the object's sorts are right (measured: docs/BENCHMARKS.md, "Honest confidence").
//
// The model: a share rho of the objects are atypical, and an atypical object's performances say
// nothing about its class: each is heard with the action's class-blind marginal
// m_a(o) = mean over classes of P_a(o | class). So
//   P(heard sequence | class k) = (1 - rho) prod_i P_ai(o_i | k) + rho prod_i m_ai(o_i),
// which is a POMDP with one more hidden bit (loop/dataset_problem.h adds an atypical copy of every
// class). One observation moves the belief a little less than its table says; agreeing
// behaviours soon make the typical term dominate; contradicting ones keep the belief open.
//
// Rho is fitted on inner-held-out sessions (held-out objects when the task sorts novel objects,
// held-out sessions when it sorts known ones): it minimises the negative log-likelihood of the
// true class after sequences that combine behaviours as a planner does: per session, its
// performances in rounds, the first of each of its behaviours in an order rotated by the session's
// index (session s starts at behaviour s mod n), then the second of each behaviour performed twice,
// and so on; and every prefix of them, as a planner stops after one, two or all. Each performance
// is scored with its action's table of the other inner folds, as tempered for repeats. Repeats
// belong in the sequences: an object unlike its class repeats its error when a behaviour is
// performed again, and a planner repeats behaviours exactly when readings disagree. On the
// recorded-data stand-in with novel objects (docs/BENCHMARKS.md, "Novel objects on the
// recorded-data stand-in"), where the planner's belief was above its share right, the shares fitted
// on first performances alone were far smaller than with repeats. (The lookalikes' share below is
// fitted on each session's whole sequence alone.)
#pragma once

#include <span>
#include <vector>

#include "perception/observation_table.h"

namespace echoplan::perception {

// One action's inner-held-out performances, in any order.
struct HeldOutPerformances {
  std::vector<int> session;  // the session each performance belongs to
  std::vector<int> fold;     // its inner fold (the same for all of a session's performances)
  std::vector<int> label;    // its true class
  std::vector<int> symbol;   // what it was heard as
  // [fold]: the action's table fitted without that fold, as the model tempers it.
  std::vector<Table> cross_fitted;
};

// The sequences described above; sequence.tables[i] indexes the actions' cross-fitted tables
// concatenated (action * folds + fold; every action has the same number of folds).
std::vector<Sequence> cross_behaviour_sequences(std::span<const HeldOutPerformances> actions);

// m(o) = the mean over the table's rows (classes) of P(o | class).
std::vector<double> class_blind_row(const Table& table);

// Sum over sequences of -log P(true class | symbols) under the mixture above, uniform prior over
// classes; tables as cross_behaviour_sequences indexes them.
double typicality_nll(std::span<const Table> tables, double rho,
                      std::span<const Sequence> sequences);

// The largest share a fit may give: beyond it an atypical object is the rule, not the exception.
inline constexpr double kMostAtypical = 0.5;

// Rho in [0, kMostAtypical] minimising typicality_nll over the actions' sequences; 0 when no
// share lowers it (or there are no sequences).
double fit_atypical_share(std::span<const HeldOutPerformances> actions);

// Objects that sound like another class. The class-blind model above says an atypical object's
// performances carry no class; a lookalike's carry the wrong one: an object of class k that sounds
// like class j in every behaviour (a weighted can heard as the mug, a novel bottle that behaves as
// the jars do). With a share rho of lookalikes, the other class uniform among the K - 1,
//   P(heard | k) = (1 - rho) L(k) + rho / (K - 1) sum_{j != k} L(j),   L(j) = prod_i P_ai(o_i | j).
// Agreeing behaviours cannot then make the belief surer than about 1 - rho: however clearly an
// object sounds like j, it is j only if it is not a lookalike. As a POMDP: every class j gets a
// copy "sounds like j, is another class", heard through j's rows, whose sorting reward is the mean
// over the other classes (loop/dataset_problem.h).
//
// Sum over sequences of -log P(true class | symbols) under that mixture; tables as
// cross_behaviour_sequences indexes them.
double lookalike_nll(std::span<const Table> tables, double rho,
                     std::span<const Sequence> sequences);
// Rho in [0, kMostAtypical] minimising lookalike_nll over each session's whole sequence
// (whole_session_sequences: every performance, not every prefix); 0 when no share lowers it, there
// are no sequences or only one class. Why whole sequences: rho caps the belief where the evidence
// is strongest, which is where a planner that keeps sensing sorts the objects it finds hard; a
// session's short prefixes, where rho changes little, outnumber its whole sequence and pulled the
// fit towards the typical objects (on the recorded-data stand-in with novel objects the prefixes
// fitted smaller shares and left the planner surer than right, the whole sequences leave it honest;
// measured: docs/BENCHMARKS.md, "Against the greedy rule on independent stand-ins" and "Tried, not
// kept").
double fit_lookalike_share(std::span<const HeldOutPerformances> actions);

// Each session's last sequence of cross_behaviour_sequences: all its performances.
std::vector<Sequence> whole_session_sequences(std::span<const HeldOutPerformances> actions);

}  // namespace echoplan::perception
