#!/usr/bin/env python3
"""Novel instruments sorted by family from repeated real strikes (docs/BENCHMARKS.md, "Under its own
model"; issue 54's repeats that err together).

Every instrument of the Hydrogen drum kits Debian ships (package hydrogen-drumkits, read where it
installs them, never copied into the repository) with at least LAYERS velocity layers is an object,
its layers one session of LAYERS strikes (loudest first), its family (kick, snare, tom, hi-hat,
cymbal, hand percussion) read off its name; instruments no family names are left out. A dataset
campaign holds out whole instruments (`hold_out: object`): each trial strikes an instrument the
classifiers never heard, up to LAYERS times, and sorts it by family. Repeated strikes of one
instrument err together: an instrument unlike its family sounds unlike it at every velocity. Arms:
the planner as a campaign sorting novel objects plans by default (lookalikes, unheard outcomes at
commit), the plain planner, and the two greedy rules. Prints each arm's share sorted right, its
belief at the sort, its strikes, its reward, and its paired difference from the planner.

Usage: bench/novel_instruments.py ECHOPLAN [--episodes N] [--layers L] [--seed S] [--out DIR]
Needs: apt-get install hydrogen-drumkits.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from perception_accuracy import KITS_DIR, add_strikes, kit_instruments  # noqa: E402

# First match wins: "Ride Bell" is a cymbal, "Snare Rimshot" a snare, "Hi-Hat Pedal" a hi-hat.
FAMILIES = [
    ("hihat", r"hat|\bhh\b"),
    ("cymbal", r"ride|crash|china|splash|bell|cymbal"),
    ("kick", r"kick|bass ?drum"),
    ("snare", r"snare|rim|side stick"),
    ("tom", r"\btom"),
    ("hand", r"cajon|maraca|clap|snap|bongo|tambourine|cowbell|clave|woodblock|waterglass|agogo"),
]
ARMS = """  - {name: plan, strategy: plan}
  - {name: plan_plain, strategy: plan, unheard: share, lookalike: false}
  - {name: information_gain, strategy: information_gain}
  - {name: decision_region, strategy: decision_region}
"""


def family(name):
    for fam, pattern in FAMILIES:
        if re.search(pattern, name, re.IGNORECASE):
            return fam
    return None


def instrument_tree(root, layers):
    """Every kit's instruments with a family and >= `layers` layers as a recordings tree, one
    session of `layers` strikes each, and its groups file; {family: instruments}."""
    rows, groups, names, counts = ["file,object,action,session"], ["object,group"], set(), {}
    for kit in sorted(os.listdir(KITS_DIR)):
        for name, files in kit_instruments(os.path.join(KITS_DIR, kit)):
            fam = family(name)
            if fam is None or len(files) < layers:
                continue
            obj = add_strikes(root, kit + "_" + name, files[:layers], lambda n: 1, rows, names)
            groups.append("%s,%s" % (obj, fam))
            counts[fam] = counts.get(fam, 0) + 1
    with open(os.path.join(root, "manifest.csv"), "w") as out:
        out.write("\n".join(rows) + "\n")
    with open(os.path.join(root, "groups.csv"), "w") as out:
        out.write("\n".join(groups) + "\n")
    return counts


def campaign(data, episodes, seed):
    return f"""seed: {seed}
world:
  type: dataset
  data: {data}
  hold_out: object
  groups: {data}/groups.csv
task:
  rewards: {{right: 10, wrong: -100, sense: -1}}
arms:
{ARMS}planner: {{solver: abt, episodes: {episodes}, max_steps: 20}}
"""


def report(summary):
    strikes = {r["arm"]: r["mean_action_counts"]["strike"] for r in summary["results"] if r["objects"] == "all"}
    reward = {r["arm"]: (r["mean_discounted_reward"], r["ci95"]) for r in summary["results"] if r["objects"] == "all"}
    diff = {d["arm"]: (d["mean_discounted_reward_difference"], d["ci95"]) for d in summary["paired_differences"]}
    print("| arm | sorted right | belief at the sort | strikes | reward (95% CI) | minus plan, paired (95% CI) |")
    print("|---|---|---|---|---|---|")
    for c in summary["sort_confidence"]:
        arm = c["arm"]
        d = "%+.2f ± %.2f" % diff[arm] if arm in diff else ""
        print("| %s | %.3f | %.3f | %.2f | %.2f ± %.2f | %s |" % (
            arm, c["share_right"], c["mean_belief"], strikes[arm], reward[arm][0], reward[arm][1], d))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("echoplan")
    parser.add_argument("--episodes", type=int, default=2000)
    parser.add_argument("--layers", type=int, default=4, help="strikes per instrument (velocity layers)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", default="", help="keep the campaign's folder here")
    args = parser.parse_args()
    if not os.path.isdir(KITS_DIR):
        sys.exit("needs hydrogen-drumkits: apt-get install it")
    with tempfile.TemporaryDirectory() as work:
        data = os.path.join(work, "instruments")
        os.makedirs(data)
        counts = instrument_tree(data, args.layers)
        print("instruments per family: " + ", ".join("%s %d" % kv for kv in sorted(counts.items())))
        config = os.path.join(work, "c.yaml")
        with open(config, "w") as out:
            out.write(campaign(data, args.episodes, args.seed))
        out_dir = args.out or os.path.join(work, "out")
        subprocess.run([args.echoplan, "experiment", "--config", config, "--out", out_dir, "--workers", "2"],
                       check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(out_dir, "summary.json")) as f:
            report(json.load(f))


if __name__ == "__main__":
    main()
