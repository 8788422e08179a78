// Cross-validation folds over a feature set's sessions, by the task's kind of hold-out.
//
// Folds are deterministic (no seed): the same set and task always give the same folds, so the
// lead's campaign can cache a fitted model per fold and every arm sees the same split.
#pragma once

#include <span>
#include <vector>

#include "perception/dataset_task.h"
#include "perception/feature_set.h"

namespace echoplan::perception {

// Sessions held out together (FeatureSet session indices, ascending).
struct Fold {
  std::vector<int> test_sessions;
};

// Folds over `sessions` (FeatureSet session indices; empty: every session of the set). Every
// listed session is in exactly one fold.
//  - hold_out session: fold f holds the f-th listed session of every object (sessions in set
//    order), so there are as many folds as the most sessions any object has, and every object has
//    training sessions in every fold. InputError when an object has fewer than 2 sessions (its
//    class would have no training data in the fold that holds its only session).
//  - hold_out object: the objects are dealt into k = min(10, fewest objects of any class) folds,
//    stratified by class: each class's objects in set order go round-robin into the folds,
//    continuing where the previous class stopped (balanced fold sizes); an object's sessions stay
//    together. Every class keeps training objects in every fold. InputError when a class has fewer
//    than 2 objects.
std::vector<Fold> make_folds(const FeatureSet& set, const DatasetTask& task,
                             std::span<const int> sessions = {});

// The sessions of `sessions` (empty: all of the set) not in `fold`, ascending.
std::vector<int> training_sessions(const FeatureSet& set, const Fold& fold,
                                   std::span<const int> sessions = {});

}  // namespace echoplan::perception
