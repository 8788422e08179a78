#!/usr/bin/python3
"""Each table of the catalogue held out in turn: the main job's objects sorted on a table no
training set heard, by a classifier trained on the other tables (docs/BENCHMARKS.md, "Other
tables").

    held_out_tables.py BUILD/echoplan [--episodes N] [--trials-per-object N] [--seed S]
                       [--random-tables N] [--out DIR]

For every table T, one campaign (`echoplan experiment`, config written to DIR/T/by_performance/
campaign.yaml): all trials on T; the arm `by_performance` hears with the classifier trained on the
other tables (`trained_on_surfaces`), calibrated as a campaign calibrates (leave-one-out by
performance), graded. Then the same trials (same seed, so the same world draws trial for trial)
heard by that classifier calibrated with each training table held out in turn instead (`echoplan
train --cross-validation surface` on the same recordings, given as `training_set.model`): the arm
`by_table`. And the same trials heard by a classifier trained on N tables drawn at random
(`training_set.surfaces: [random:N]`, N recordings per pair, one on each; sim/random_tables.h),
none of them a catalogue table: the arm `random_tables`. Prints per table each arm's share sorted
right, its mean belief in its choice at the
sort and the sorts made (trials stopped by max_steps make none), the recordings heard per trial,
and by_table and random_tables minus by_performance in discounted reward per trial, paired by trial
(mean and 95% CI, Student's t). About 4 minutes on 2 cores at the defaults.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

from scipy import stats

TABLES = ["lab_laminate", "oak_top", "glass_top", "rubber_mat", "steel_bench"]
OBJECTS = ["pringles_can", "coffee_mug", "plastic_cup", "paper_base"]
HERE = os.path.dirname(os.path.abspath(__file__))
PROBLEM = os.path.join(HERE, "..", "problems", "audio_objects.yaml")


def config(table, arm, trials, episodes, seed, model=None, random_tables=0):
    """A campaign's YAML: `arm` on `table`, trained on the other tables (or `random_tables` drawn
    at random, or hearing `model`)."""
    others = [t for t in TABLES if t != table]
    arm_line = (f"  - {{name: {arm}, problem: {PROBLEM}, calibrate: true, observations: graded"
                + ("" if model else ", trained_on_surfaces: true") + "}")
    training = (f"  model: {model}" if model else
                f"  recordings_per_pair: {random_tables}\n  surfaces: [random:{random_tables}]"
                if random_tables else
                f"  recordings_per_pair: 10\n  surfaces: [{', '.join(others)}]")
    groups = "\n".join(f"  - {{object: {o}, trials: {trials}}}" for o in OBJECTS)
    return (f"seed: {seed}\narms:\n{arm_line}\nworld:\n  type: simulated\n"
            f"  problem: {PROBLEM}\n  surface: {table}\ntraining_set:\n{training}\n"
            f"trials:\n{groups}\nplanner:\n  solver: abt\n  episodes: {episodes}\n"
            f"  max_steps: 30\n")


def run(echoplan, out, text):
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "campaign.yaml")
    with open(path, "w") as f:
        f.write(text)
    subprocess.run([echoplan, "experiment", "--config", path, "--out", os.path.join(out, "run")],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return os.path.join(out, "run")


def arm_figures(campaign, arm):
    """(its `by_surface` entry on the one table, {trial: reward}) of `arm` in `campaign`."""
    with open(os.path.join(campaign, "summary.json")) as f:
        summary = json.load(f)
    (table,) = next(e["surfaces"] for e in summary["by_surface"] if e["arm"] == arm)
    rewards = {}
    with open(os.path.join(campaign, "trials.csv"), newline="") as f:
        for row in csv.DictReader(f):
            if row["arm"] == arm:
                rewards[row["trial"]] = float(row["discounted_reward"])
    return table, rewards


def paired(a, b):
    d = [a[k] - b[k] for k in a if k in b]
    mean = sum(d) / len(d)
    sd = math.sqrt(sum((x - mean) ** 2 for x in d) / (len(d) - 1)) if len(d) > 1 else 0.0
    return mean, stats.t.ppf(0.975, len(d) - 1) * sd / math.sqrt(len(d)), len(d)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("echoplan")
    p.add_argument("--episodes", type=int, default=5000)
    p.add_argument("--trials-per-object", type=int, default=10)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--random-tables", type=int, default=40)
    p.add_argument("--out", default="/tmp/held_out_tables")
    a = p.parse_args()
    if not os.access(a.echoplan, os.X_OK):
        print(f"held_out_tables.py: {a.echoplan}: not an executable", file=sys.stderr)
        sys.exit(2)
    print("| held-out table | by_performance: right, belief (sorts), heard | by_table | "
          "random_tables | by_table minus by_performance, paired (95% CI) | random_tables minus "
          "by_performance |")
    print("|---|---|---|---|---|---|")
    for table in TABLES:
        out = os.path.join(a.out, table)
        by_perf = run(a.echoplan, os.path.join(out, "by_performance"),
                      config(table, "by_performance", a.trials_per_object, a.episodes, a.seed))
        recordings = os.path.join(by_perf, "training", "recordings_on_surfaces")
        model = os.path.join(out, "by_table.json")
        subprocess.run([a.echoplan, "train", "--data", recordings, "--cross-validation", "surface",
                        "--no-reject", "--out", model], check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)
        by_table = run(a.echoplan, os.path.join(out, "by_table"),
                       config(table, "by_table", a.trials_per_object, a.episodes, a.seed, model))
        random_arm = run(a.echoplan, os.path.join(out, "random_tables"),
                         config(table, "random_tables", a.trials_per_object, a.episodes, a.seed,
                                random_tables=a.random_tables))
        cells = []
        for campaign, arm in ((by_perf, "by_performance"), (by_table, "by_table"),
                              (random_arm, "random_tables")):
            t, rewards = arm_figures(campaign, arm)
            cells.append((f"{t['share_right']:.3f}, {t['mean_belief']:.3f} ({t['sorts']}), "
                          f"{t['mean_recordings_heard']:.2f}", rewards))
        differences = []
        for cell in cells[1:]:
            mean, half, n = paired(cell[1], cells[0][1])
            differences.append(f"{mean:+.2f} ± {half:.2f} ({n})")
        print(f"| `{table}` | {' | '.join(c[0] for c in cells)} | {' | '.join(differences)} |",
              flush=True)


if __name__ == "__main__":
    main()
