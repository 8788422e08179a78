#!/usr/bin/python3
"""How sure a dataset campaign's arm would have been at each sort, counting repeats or not.

    belief_by_repeats.py CAMPAIGN ARM

For every trial of ARM in CAMPAIGN (an `echoplan experiment` folder of a dataset world), recomputes
the belief in the bin it chose from its logged performances, under the fold's own problem
(folds/<fold>/problem.yaml, the classes' tables, uniform prior), two ways: every performance
counted, as the planner counts them, and only the first performance of each behaviour. Prints, for
trials that sensed fewer than 8 and at least 8 times and for all, the mean belief, the share sorted
right and the gap in points. A gap that shrinks when repeats are left out says the repeats of one
behaviour are worth less than the table says; one that stays says the behaviours together are.
Beliefs are of the classes alone (a lookalike arm's copies are left out).
"""
import collections
import csv
import glob
import math
import os
import sys

import yaml


def belief_in(problem, performances, chosen):
    objects = [o for o in problem["objects"] if "~" not in o]
    symbols = problem["observation"]["symbols"]
    table = problem["observation"]["table"]
    log = [0.0] * len(objects)
    for action, heard in performances:
        o = symbols.index(heard)
        for k, name in enumerate(objects):
            log[k] += math.log(table[action][name][o])
    top = max(log)
    weights = [math.exp(x - top) for x in log]
    return weights[objects.index(chosen)] / sum(weights)


def fail(problem):
    print(f"belief_by_repeats.py: {problem}", file=sys.stderr)
    sys.exit(2)


def first_of_each(performances):
    first, seen = [], set()
    for action, heard in performances:
        if action not in seen:
            first.append((action, heard))
            seen.add(action)
    return first


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    campaign, arm = sys.argv[1], sys.argv[2]
    folds = sorted(glob.glob(os.path.join(campaign, "folds", "*")))
    if not folds:
        fail(f"{campaign} has no folds/ (not a dataset campaign)")
    missing = [f for f in folds if not os.path.isfile(os.path.join(f, "arms", arm, "steps.csv"))]
    if missing:
        fail(f"{missing[0]}/arms/{arm}/steps.csv: no such file (is '{arm}' an arm of the campaign?)")
    sums = collections.defaultdict(lambda: [0.0, 0, 0])  # (counting, length) -> belief, right, n
    for fold in folds:
        problem = yaml.safe_load(open(os.path.join(fold, "problem.yaml")))
        sensing = problem["observation"]["table"]
        trials = {r["trial"]: r for r in csv.DictReader(open(os.path.join(fold, "arms", arm, "trials.csv")))}
        steps = collections.defaultdict(list)
        for row in csv.DictReader(open(os.path.join(fold, "arms", arm, "steps.csv"))):
            steps[row["trial"]].append(row)
        for trial, rows in steps.items():
            chosen = trials[trial]["believed_state"].split("~")[0]
            right = trials[trial]["true_state"].split("~")[0] == chosen
            every = [(r["action"], r["observation"]) for r in sorted(rows, key=lambda r: int(r["step"]))
                     if r["action"] in sensing]
            first = first_of_each(every)
            length = "fewer than 8" if len(every) < 8 else "8 or more"
            for counting, performances in (("every performance", every), ("first of each", first)):
                b = belief_in(problem, performances, chosen)
                for key in ((counting, length), (counting, "all")):
                    s = sums[key]
                    s[0] += b
                    s[1] += right
                    s[2] += 1
    print(f"{'counting':<18} {'performances':<13} {'trials':>6} {'belief':>7} {'right':>6} {'gap':>6}")
    for (counting, length), (belief, right, n) in sorted(sums.items()):
        print(f"{counting:<18} {length:<13} {n:>6} {belief / n:>7.3f} {right / n:>6.3f} "
              f"{100 * (belief - right) / n:>+6.1f}")


if __name__ == "__main__":
    main()
