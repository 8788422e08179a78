#!/usr/bin/python3
"""The main job with the calibrated table from hard counts against soft counts, paired by seed.

For each seed, runs `echoplan experiment` twice on experiments/chapter5.yaml, once with
`training_set.table: counts` and once with `table: soft` (a copy of the file written next to it, so
its relative paths hold), and prints per seed: correct trials per object and overall, mean
discounted reward (95% CI) of each calibrated arm and of the hand-tuned arm, the paired differences
(same seed: same trials, same world noise), steps, slides, strikes and collisions per arm, and the
soft model's tables. Then the paired difference pooled over all seeds.

The hand-tuned arm does not depend on the table (the classifier that hears is the same), so the
script checks it is identical in both runs: the pairing holds.

Usage: bench/table_estimate.py [--binary build/echoplan] [--seeds 1,2,3] [--out /tmp/table_estimate]
       [--workers 2]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
from statistics import mean, stdev

ORIGINALS = ("pringles_can", "coffee_mug", "plastic_cup", "paper_base")
HERE = os.path.dirname(os.path.abspath(__file__))


def arm_rows(folder, arm):
    with open(os.path.join(folder, "trials.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["arm"] == arm]
    return sorted(rows, key=lambda r: int(r["trial"]))


def right(row):
    return row["believed_state"] == row["object"].replace("_weighted", "")


def mean_ci(values):
    """Mean and 95% half-width (Student t quantile, Cornish-Fisher: exact to 1e-3 for 30+ values)."""
    if len(values) < 2:
        return mean(values), 0.0
    df = len(values) - 1
    t = 1.96 + (1.96**3 + 1.96) / (4 * df)
    return mean(values), t * stdev(values) / math.sqrt(len(values))


def rewards(rows):
    return [float(r["discounted_reward"]) for r in rows]


def describe(name, rows):
    objects = list(dict.fromkeys(r["object"] for r in rows))
    per = " ".join(f"{o} {sum(right(r) for r in rows if r['object'] == o)}" for o in objects)
    four = sum(right(r) for r in rows if r["object"] in ORIGINALS)
    m, w = mean_ci(rewards(rows))
    print(f"  {name:10s} four {four}/40, all {sum(map(right, rows))}/{len(rows)} ({per}); "
          f"reward {m:.2f} ± {w:.2f}; steps {mean(float(r['steps']) for r in rows):.2f}, "
          f"slides {mean(float(r['n_slide']) for r in rows):.2f}, "
          f"strikes {mean(float(r['n_strike']) for r in rows):.2f}, "
          f"collisions {sum(int(r['collision']) for r in rows)}")


def paired(a, b):
    if [r["object"] for r in a] != [r["object"] for r in b]:
        sys.exit("the arms' trials are not the same objects in the same order: not paired")
    return [x - y for x, y in zip(rewards(a), rewards(b))]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--binary", default="build/echoplan")
    p.add_argument("--seeds", default="1,2,3")
    p.add_argument("--out", default="/tmp/table_estimate")
    p.add_argument("--workers", default="2")
    args = p.parse_args()
    base = os.path.join(HERE, "..", "experiments", "chapter5.yaml")
    configs = {}
    for table in ("counts", "soft"):
        configs[table] = os.path.join(HERE, "..", "experiments", f".table_{table}.yaml")
        with open(base) as f:
            text = f.read()
        marker = "  recordings_per_pair: 10\n"
        if marker not in text:
            sys.exit(f"{base}: no '{marker.strip()}' line to add the table to")
        with open(configs[table], "w") as f:
            f.write(text.replace(marker, marker + f"  table: {table}\n"))
    pooled, only = [], {"soft": 0, "counts": 0}
    try:
        for seed in args.seeds.split(","):
            folders = {}
            for table in ("counts", "soft"):
                folders[table] = os.path.join(args.out, f"{table}{seed}")
                print(f"seed {seed}, {table}: {folders[table]}", file=sys.stderr, flush=True)
                subprocess.run([args.binary, "experiment", "--config", configs[table], "--seed", seed,
                                "--out", folders[table], "--workers", args.workers],
                               check=True, stdout=subprocess.DEVNULL)
            soft = arm_rows(folders["soft"], "calibrated")
            counts = arm_rows(folders["counts"], "calibrated")
            hand = arm_rows(folders["counts"], "hand_tuned")
            if rewards(hand) != rewards(arm_rows(folders["soft"], "hand_tuned")):
                sys.exit(f"seed {seed}: the hand-tuned arm differs between the runs: not paired")
            print(f"seed {seed}")
            describe("soft", soft)
            describe("counts", counts)
            describe("hand_tuned", hand)
            for name, other in (("counts", counts), ("hand_tuned", hand)):
                m, w = mean_ci(paired(soft, other))
                print(f"  soft - {name}: {m:+.2f} ± {w:.2f} (paired, {len(soft)} trials)")
            pooled += paired(soft, counts)
            only["soft"] += sum(right(x) and not right(y) for x, y in zip(soft, counts))
            only["counts"] += sum(right(y) and not right(x) for x, y in zip(soft, counts))
            with open(os.path.join(folders["soft"], "training", "model.json")) as f:
                model = json.load(f)
            for action, entry in model["per_action"].items():
                print(f"  soft table, {action} (T {entry['temperature']:.4g}):")
                for name, row in zip(model["classes"], entry["table"]):
                    print(f"    {name:14s}" + " ".join(f"{x:.3f}" for x in row))
    finally:
        for path in configs.values():
            os.remove(path)
    m, w = mean_ci(pooled)
    print(f"pooled over seeds {args.seeds}: soft - counts {m:+.2f} ± {w:.2f} ({len(pooled)} pairs); "
          f"right only with soft {only['soft']}, only with counts {only['counts']}")


if __name__ == "__main__":
    main()
