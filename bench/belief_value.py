#!/usr/bin/python3
"""Rao-Blackwellised value of a logged run of an object-identification YAML problem.

    belief_value.py PROBLEM.yaml DIR/steps.csv

Sums, per trial, gamma^t * E_b[R(s, a_t)] with b the exact belief recomputed from the logged actions
and observations (sorting rewards replaced by their expectation under b). Its mean over trials is
an unbiased estimate of the planner's value V(b0), with a standard deviation about a third of the
raw returns' (no +10/-100 coin flip at the end). Needs no bounds, so it complements
`echoplan certify` when the certificate is loose; it has far more variance than certify's regret.
Prints n, the mean and the half-width of its 95% CI (normal approximation).
"""
import collections
import csv
import math
import sys

import yaml


def main():
    problem = yaml.safe_load(open(sys.argv[1]))
    gamma = problem["discount"]
    objects = problem["objects"]
    symbols = problem["observation"]["symbols"]
    table = problem["observation"]["table"]
    reward = problem["reward"]
    trials = collections.defaultdict(list)
    for row in csv.DictReader(open(sys.argv[2])):
        trials[int(row["trial"])].append(row)
    values = []
    for rows in trials.values():
        belief = [1.0 / len(objects)] * len(objects)  # the file's uniform initial belief
        weight, value = 1.0, 0.0
        for row in sorted(rows, key=lambda r: int(r["step"])):
            action = row["action"]
            if action in reward["sensing"]:
                value += weight * reward["sensing"][action]
                o = symbols.index(row["observation"])
                belief = [belief[k] * table[action][objects[k]][o] for k in range(len(objects))]
                total = sum(belief)
                belief = [p / total for p in belief]
            else:
                value += weight * sum(belief[k] * reward["sorting"][action][objects[k]]
                                      for k in range(len(objects)))
            weight *= gamma
        values.append(value)
    n = len(values)
    mean = sum(values) / n
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1))
    print(f"n={n} value={mean:.4f} ± {1.96 * sd / math.sqrt(n):.4f} sd={sd:.3f}")


if __name__ == "__main__":
    main()
