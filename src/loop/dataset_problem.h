// The planning problem of a recorded dataset: identify a trial's class (an object, or its group)
// by performing the set's behaviours, each at most as often as a session recorded it, then sort it
// into a bin (docs/feature-sets.md, "The problem of a feature set").
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "perception/dataset_task.h"
#include "perception/feature_set.h"
#include "perception/observation_model.h"
#include "pomdp/object_identification_model.h"

namespace echoplan::loop {

// The task of sorting recorded data (a campaign's `task:`), beside what the data itself decides.
// What it earns (`task: rewards`, `train --reward-*`): by default the report's +10 for the right
// bin, -100 for a wrong one, and -1 per behaviour performed. `costs` (`task: costs`,
// `train --costs`) prices behaviours one by one, since on a real robot a look takes half a second
// and a push or a shake several: a behaviour with cost C earns -C per performance; the others earn
// `sense`. `prerequisites` (`task: requires`) opens a behaviour only after others were performed in
// the trial (a shake needs a grasp first; pomdp::SensingAction::prerequisites).
struct TaskSpec {
  double right = 10.0;
  double wrong = -100.0;
  double sense = -1.0;
  std::map<std::string, double> costs = {};  // behaviour -> cost (>= 0)
  // behaviour -> the behaviours it needs performed first
  std::map<std::string, std::vector<std::string>> prerequisites = {};

  // The reward of one performance of `behaviour`: -cost when it is priced, else `sense`.
  double sensing_reward(const std::string& behaviour) const;
};

// The problem: objects = the task's classes with a uniform prior (the datasets are balanced, and a
// prior from the trials' own frequencies would leak the test split); one sensing action per model
// action (same order, reward `sense`, no motion, no collision, `uses[a]` its use limit, 0: none);
// one sorting action per bin, rewarding `right` when the class is in that bin and `wrong`
// otherwise; observation symbols = the model's of `kind` (the classes, or the graded symbols); the
// table = the model's observation tables of that kind;
// discount 0.99 (the report's problems). Each sensing action's reward is
// rewards.sensing_reward(its name), its prerequisites rewards.prerequisites[its name]. Throws
// InputError when `uses` is not one entry per action, or negative, when `rewards.costs` prices or
// `rewards.prerequisites` names a behaviour the model does not have, when the prerequisites go
// round in a circle, or when the model's classes are not the task's (or it rejects), or `kind` is
// graded and the model has no grades.
//
// With a lookalike share rho, objects that sound like another class are hidden states too
// (perception/typicality.h): after the classes comes a lookalike copy of every class j, named
// lookalike_name(j): "sounds like j, is another class". Its prior is rho times j's (j keeps 1 - rho
// of it), its observation rows are j's, and its sorting reward is the mean of the other classes'
// (the class it really is is any other, equally likely). However clearly an object sounds like j,
// the belief that it is j then stays below about 1 - rho. Usually rho is the model's
// lookalike_share(kind); 0 plans exactly as without copies; none: no copies. With rho > 0 and a
// model whose share was fitted on its untempered tables (lookalikes_untempered(kind)), every row
// is the untempered one (ObservationModel::untempered_table): the lookalikes then model how an
// object's readings err together, its repeats too; a tempered table as well would flatten every
// first reading (docs/feature-sets.md, 6).
pomdp::ObjectProblemData dataset_problem(
    const perception::DatasetTask& task, const perception::ObservationModel& model,
    const TaskSpec& rewards, std::vector<int> uses,
    perception::ObservationKind kind = perception::ObservationKind::labels,
    std::optional<double> lookalike_share = std::nullopt);

// The same problem's shape, with every observation row uniform and default_uses(set): its names
// (classes, their lookalike copies with `lookalike`, actions, bins, symbols) before any model is
// fitted, e.g. for a campaign's report.
pomdp::ObjectProblemData dataset_problem_shape(const perception::DatasetTask& task,
                                               const perception::FeatureSet& set,
                                               const TaskSpec& rewards, bool lookalike = false);

// The hidden state of an object that sounds like class `name` and is another: "<name>~lookalike".
std::string lookalike_name(const std::string& name);
// Per action of `set`: the most performances of that action in any one session (a trial can
// perform it at most that often).
std::vector<int> default_uses(const perception::FeatureSet& set);

}  // namespace echoplan::loop
