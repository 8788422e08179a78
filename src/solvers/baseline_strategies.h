// The five baseline strategies a campaign compares the planner with, as Solvers the loop can run
// (`--solver <name>`, built by make_solver.h like "abt" and "pomcp"). Each decides by a fixed rule
// from the belief over the objects and the actions taken so far (fixed_strategy.h), with no search,
// and ends by sorting to the bin most likely right (most_likely_right_sort()):
//   all_actions       every sensing action once, in the problem's order, skipping any whose uses
//                     have run out and taking one that waits for a prerequisite once it is open
//                     (Model::prerequisites); then sort.
//   best_single       the sensing action of the best value, cost included (single_action_value():
//                     one performance, then sorting right as often as its held-out accuracy says;
//                     with equal costs, the most accurate; the first on ties), repeated while its
//                     uses last; then sort. An action with no
//                     use limit is repeated while one more performance is worth its cost by
//                     information_gain's rule (sense_then_commit_value() above commit_value()),
//                     since repeating it forever never sorts. An action that waits for others
//                     counts their costs in its value and is performed after them.
//   decision_region   greedy on the sort decision rather than the identity (equivalence-class edge
//                     cutting: EC2, Golovin, Krause & Ray 2010; decision-region determination,
//                     Javdani et al. 2014): the commit rule of information_gain below, else the
//                     available sensing action with the greatest expected edge mass removed per
//                     unit cost (the same cost and ties). Each object's region is its best bin
//                     (decision_regions(): the first on ties); an edge joins two objects of
//                     different regions, weighted b(k) b(k'). The tests are noisy (the table is a
//                     classifier's confusion, no symbol rules an object out), so nothing is ever
//                     cut outright: the mass removed is ECED's discount (Chen, Hassani & Krause
//                     2017; EdgeCut::expected_cut() says exactly what it sums), which is EC2's cut
//                     on noise-free rows and 0 for an action that cannot tell any objects apart.
//                     Guarantees: with noise-free tests each performed once, EC2's objective is
//                     adaptive submodular and its greedy, run until every edge is cut, costs within
//                     2 ln(1/p_min) + 1 of the cheapest policy that finds the region (p_min the
//                     smallest prior); with noisy tests conditionally independent given the object,
//                     ECED's greedy keeps a bicriteria bound (the cost of reaching a decision error
//                     within a polylogarithmic factor of the optimal cost of reaching a smaller
//                     one), for its own stopping rule. Neither carries over here: this rule stops
//                     by the one-step commit rule and is judged by discounted reward, so it is a
//                     heuristic with no bound. What it changes: a performance is worth only the
//                     edges it cuts between bins, so telling apart two objects of one bin counts
//                     only as far as it rules one of them out against the other bins' objects
//                     (information_gain counts it in full).
//   information_gain  greedy: while some sensing action is available, commit when committing now is
//                     worth at least the best one-step lookahead (sense once, then commit), else
//                     take the available sensing action with the greatest expected entropy
//                     reduction per unit cost (cost |r_a|, the action's reward per use; a zero cost
//                     counts as 1, i.e. the gain itself; the first on ties). Both greedy rules
//                     weigh only the actions open now: a prerequisite that tells nothing by itself
//                     (a grasp before a shake) has no gain and is never chosen, so what it opens
//                     is never reached. That is where looking ahead pays (docs/planning.md).
//   random            each step, uniformly among the available sensing actions and "sort now" (so
//                     with M available actions, sorting has chance 1/(M+1)); sorts when none is
//                     available. Draws from the Rng improve() is given.
// root_action_values(): information_gain's and decision_region's lookahead values (sensing) and
// expected rewards (sorting); NaN for the other strategies and for actions a strategy did not
// weigh.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "pomdp/model.h"
#include "solvers/solver.h"

namespace echoplan::solvers {

// all_actions, best_single, decision_region, information_gain, random.
std::vector<std::string> strategy_names();
bool is_strategy(const std::string& name);

// Throws InputError for an unknown name, or a model that is not an object-identification problem
// (naming the strategy and why).
std::unique_ptr<Solver> make_strategy(const std::string& name, pomdp::ModelPtr model);

}  // namespace echoplan::solvers
