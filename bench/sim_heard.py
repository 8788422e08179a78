#!/usr/bin/python3
"""Behavioural realism: what a classifier hears in the simulator, beside what the lab's classifier heard.

The lab's counts are the final experiments' logs (../shared/reference/original-robot-runs.md: 81 sensing
actions with the four objects, 36 with the weighted can and mug). For each seed the simulator
synthesises --per-pair recordings of every (object, action) pair (`echoplan synth-recordings`); each classifier is
then measured as the report did:

  - the four objects: leave-one-out over that seed's recordings of the four originals
    (`echoplan train --folds 0 --no-reject`), its confusion per action;
  - the weighted can and mug: the classifier trained on all of the originals' recordings (as the lab's
    templates were made from the originals only) hears the variants' recordings (`echoplan evaluate`).

Each row pools the seeds and prints the share with its Wilson 95% interval, the lab's count and interval,
and whether the simulator's pooled share lies inside the lab's interval. Results: docs/BENCHMARKS.md.

Usage: bench/sim_heard.py [--echoplan build/echoplan] [--seeds 1,2,3] [--per-pair 10]
                          [--classifiers report-template,summary-lda] [--sim-config FILE] [--catalogue FILE]
                          [--confusion]
Needs only python3 (no numpy). Runs every simulation under `nice`.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

ORIGINALS = ["pringles_can", "coffee_mug", "plastic_cup", "paper_base"]
WEIGHTED = ["pringles_can_weighted", "coffee_mug_weighted"]

# (label, action, true objects, heard as, lab right, lab total). "heard as" None: the true object itself.
ROWS = [
    ("strikes heard right", "strike", ORIGINALS, None, 43, 46),
    ("slides heard right", "slide", ORIGINALS, None, 23, 35),
    ("paper base's slides heard right", "slide", ["paper_base"], None, 5, 15),
    ("paper base's slides heard as the mug", "slide", ["paper_base"], "coffee_mug", 6, 15),
    ("weighted can's slides heard as the can", "slide", ["pringles_can_weighted"], "pringles_can", 1, 8),
    ("weighted can's strikes heard as the can", "strike", ["pringles_can_weighted"], "pringles_can", 7, 9),
    ("weighted mug's strikes heard as the mug", "strike", ["coffee_mug_weighted"], "coffee_mug", 9, 11),
    ("weighted mug's slides heard as the mug", "slide", ["coffee_mug_weighted"], "coffee_mug", 5, 8),
]
# The rows the simulator must hold inside the lab's intervals (the others are printed for context).
REQUIRED = {"strikes heard right", "slides heard right", "paper base's slides heard right",
            "weighted can's slides heard as the can", "weighted can's strikes heard as the can",
            "weighted mug's strikes heard as the mug"}


def wilson(k, n, z=1.959964):
    """Wilson score 95% interval of k successes in n."""
    if n == 0:
        return (0.0, 1.0)
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return (max(0.0, centre - half), min(1.0, centre + half))


def run(command, **kw):
    return subprocess.run(["nice"] + command, check=True, capture_output=True, text=True, **kw).stdout


def link_objects(source, target, objects):
    os.makedirs(target, exist_ok=True)
    for o in objects:
        os.symlink(os.path.join(source, o), os.path.join(target, o))


def parse_loo(text):
    """{action: {true: {heard: count}}} from `echoplan train`'s leave-one-out confusion tables."""
    out, action, columns = {}, None, None
    for line in text.splitlines():
        m = re.match(r"(\w+) \(cross-validated", line)
        if m:
            action, columns = m.group(1), None
            out[action] = {}
            continue
        if action and line.strip().startswith("true \\ heard"):
            columns = line.split()[3:]
            continue
        fields = line.split()
        if action and columns and len(fields) == len(columns) + 1 and fields[0] in ORIGINALS + WEIGHTED:
            out[action][fields[0]] = dict(zip(columns, map(int, fields[1:])))
    return out


def parse_evaluation(text):
    result = {}
    for action, m in json.loads(text)["actions"].items():
        result[action] = {o: dict(zip(m["symbols"], row)) for o, row in zip(m["objects"], m["confusion"])}
    return result


def heard_for_seed(args, seed, classifier, work):
    """{action: {true object: {heard: count}}} for one seed and classifier (originals and variants)."""
    data = os.path.join(work, "seed%d" % seed)
    if not os.path.isdir(data):
        command = [args.echoplan, "synth-recordings", "--per-pair", str(args.per_pair), "--seed", str(seed), "-o", data,
                   "--threads", "1", "--objects", ",".join(ORIGINALS + WEIGHTED)]
        command += ["--sim-config", args.sim_config] if args.sim_config else []
        command += ["--catalogue", args.catalogue] if args.catalogue else []
        run(command)
        link_objects(data, data + "_originals", ORIGINALS)
        link_objects(data, data + "_weighted", WEIGHTED)
    model = os.path.join(work, "model_%d_%s.json" % (seed, classifier))
    heard = parse_loo(run([args.echoplan, "train", "--data", data + "_originals", "--classifier", classifier,
                           "--folds", "0", "--no-reject", "-o", model]))
    variants = parse_evaluation(run([args.echoplan, "evaluate", "--model", model, "--data", data + "_weighted",
                                     "--json"]))
    for action, rows in variants.items():
        heard.setdefault(action, {}).update(rows)
    return heard


def count(heard, action, objects, heard_as):
    k = n = 0
    for o in objects:
        row = heard.get(action, {}).get(o, {})
        k += row.get(heard_as or o, 0)
        n += sum(row.values())
    return k, n


def print_table(classifier, per_seed, seeds):
    print("\n%s (%s recordings per pair; seeds %s)" % (classifier, ARGS.per_pair, ",".join(map(str, seeds))))
    print("| | lab | lab 95%% CI | %s | pooled | pooled 95%% CI | inside |" %
          " | ".join("seed %d" % s for s in seeds))
    print("|---|---|---|%s---|---|---|" % ("---|" * len(seeds)))
    inside_required = 0
    for label, action, objects, heard_as, k_lab, n_lab in ROWS:
        lo, hi = wilson(k_lab, n_lab)
        cells, k_all, n_all = [], 0, 0
        for s in seeds:
            k, n = count(per_seed[s], action, objects, heard_as)
            cells.append("%.2f" % (k / n) if n else "-")
            k_all, n_all = k_all + k, n_all + n
        p = k_all / n_all if n_all else float("nan")
        plo, phi = wilson(k_all, n_all)
        inside = lo <= p <= hi
        inside_required += inside and label in REQUIRED
        mark = ("yes" if inside else "NO") + ("" if label in REQUIRED else " (context)")
        print("| %s | %d/%d = %.2f | %.2f-%.2f | %s | %d/%d = %.2f | %.2f-%.2f | %s |" %
              (label, k_lab, n_lab, k_lab / n_lab, lo, hi, " | ".join(cells), k_all, n_all, p, plo, phi, mark))
    print("%s: %d of %d required rows inside the lab's 95%% interval" % (classifier, inside_required, len(REQUIRED)))


def print_confusion(classifier, per_seed, seeds):
    for action in ("strike", "slide"):
        print("\n%s %s, pooled over seeds (true \\ heard: %s)" % (classifier, action, " ".join(ORIGINALS)))
        for o in ORIGINALS + WEIGHTED:
            row = [sum(per_seed[s].get(action, {}).get(o, {}).get(h, 0) for s in seeds) for h in ORIGINALS]
            print("  %-22s %s" % (o, " ".join("%3d" % c for c in row)))


def main():
    global ARGS
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--echoplan", default="build/echoplan")
    parser.add_argument("--seeds", default="1,2,3")
    parser.add_argument("--per-pair", type=int, default=10)
    parser.add_argument("--classifiers", default="report-template,summary-lda")
    parser.add_argument("--sim-config")
    parser.add_argument("--catalogue")
    parser.add_argument("--confusion", action="store_true", help="also print the pooled confusion tables")
    ARGS = parser.parse_args()
    seeds = [int(s) for s in ARGS.seeds.split(",")]
    with tempfile.TemporaryDirectory() as work:
        for classifier in ARGS.classifiers.split(","):
            per_seed = {s: heard_for_seed(ARGS, s, classifier, work) for s in seeds}
            print_table(classifier, per_seed, seeds)
            if ARGS.confusion:
                print_confusion(classifier, per_seed, seeds)
    return 0


ARGS = None
if __name__ == "__main__":
    sys.exit(main())
