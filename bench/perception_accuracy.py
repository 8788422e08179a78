#!/usr/bin/python3
"""Few-shot accuracy of every observation classifier, side by side with report-template (docs/BENCHMARKS.md).

Two sources:
  real  Hydrogen drum kits (Debian package hydrogen-drumkits; ~220 MB, so not in CI): every instrument with
        enough velocity layers is a class; train on its n loudest layers, test on its quietest one (a force
        the training set never had). Each kit is one task; accuracy is pooled over the kits' test clips.
  sim   `echoplan synth-recordings` recordings: train on the first n recordings per (object, action) of one
        dataset seed, test on every recording of another seed.

Usage: bench/perception_accuracy.py BUILD_DIR [--shots 3,5,7] [--sim-per-pair 20] [--out results.json]
Needs: apt-get install hydrogen-drumkits (for the real source). Prints a Markdown table.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

KITS_DIR = "/usr/share/hydrogen/data/drumkits"
CLASSIFIERS = ["summary-lda", "summary-nearest-mean", "report-template", "report-gaussian"]


def kit_instruments(kit_dir):
    """(instrument name, [files loudest first]) for every instrument of a Hydrogen kit."""
    root = ET.parse(os.path.join(kit_dir, "drumkit.xml")).getroot()
    ns = root.tag.split("}")[0] + "}" if root.tag.startswith("{") else ""
    out = []
    for ins in root.iter(ns + "instrument"):
        layers = []
        for layer in ins.iter(ns + "layer"):
            f = layer.findtext(ns + "filename")
            if f and os.path.exists(os.path.join(kit_dir, f)):
                layers.append((float(layer.findtext(ns + "max") or 1.0), os.path.join(kit_dir, f)))
        files = [f for _, f in sorted(layers, reverse=True)]
        if len(set(files)) == len(files):
            out.append((ins.findtext(ns + "name"), files))
    return out


def add_strikes(root, name, files, session, rows, names):
    """Copies `files` into a recordings tree as ROOT/<object>/strike/<n>.<ext>, the object named
    after `name` (its other characters made "_", unique among `names`, which it joins), appending one manifest
    row (file,object,action,session) per file to `rows`, session(n) naming the n-th file's session.
    Returns the object's name."""
    obj = "".join(c if c.isalnum() else "_" for c in name)
    while obj in names:
        obj += "_"
    names.add(obj)
    os.makedirs(os.path.join(root, obj, "strike"))
    for n, source in enumerate(files):
        file = "%s/strike/%d%s" % (obj, n, os.path.splitext(source)[1])
        shutil.copy(source, os.path.join(root, file))
        rows.append("%s,%s,strike,%s" % (file, obj, session(n)))
    return obj


def link_set(root, classes):
    """classes: {name: [files]} -> DIR/<name>/strike/NN.<ext> (symlinks)."""
    for name, files in classes.items():
        folder = os.path.join(root, name.replace("/", "_").replace(" ", "_"), "strike")
        os.makedirs(folder, exist_ok=True)
        for i, f in enumerate(files):
            os.symlink(f, os.path.join(folder, "%02d%s" % (i, os.path.splitext(f)[1])))


def train_and_evaluate(echoplan, train_dir, test_dir, classifier, work):
    model = os.path.join(work, "model.json")
    subprocess.run([echoplan, "train", "--data", train_dir, "--out", model, "--classifier", classifier, "--no-reject"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    out = subprocess.run([echoplan, "evaluate", "--model", model, "--data", test_dir, "--json"], check=True,
                         capture_output=True, text=True).stdout
    result = {}
    for action, m in json.loads(out)["actions"].items():
        right = sum(row[m["symbols"].index(o)] for o, row in zip(m["objects"], m["confusion"]))
        total = sum(sum(row) for row in m["confusion"])
        result[action] = (right, total)
    return result


def real_tasks(shots):
    """[(kit, {instrument: [train files]}, {instrument: [test file]})] for kits with >= 3 usable instruments."""
    tasks = []
    for kit in sorted(os.listdir(KITS_DIR)):
        instruments = [(n, f) for n, f in kit_instruments(os.path.join(KITS_DIR, kit)) if len(f) >= shots + 1]
        if len(instruments) < 3:
            continue
        names = {}
        for n, f in instruments:
            names[n if n not in names else n + "_%d" % len(names)] = f
        tasks.append((kit, {n: f[:shots] for n, f in names.items()}, {n: f[-1:] for n, f in names.items()}))
    return tasks


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("build_dir")
    p.add_argument("--shots", default="3,5,7")
    p.add_argument("--sim-shots", default="3,5,10")
    p.add_argument("--sim-per-pair", type=int, default=20)
    p.add_argument("--out", default="")
    args = p.parse_args()
    echoplan = os.path.join(args.build_dir, "echoplan")
    results = []
    with tempfile.TemporaryDirectory() as work:
        # Simulated recordings: two dataset seeds, train on the first n of seed 1, test on all of seed 2.
        sim_train, sim_test = os.path.join(work, "sim1"), os.path.join(work, "sim2")
        for seed, d in ((1, sim_train), (2, sim_test)):
            subprocess.run([echoplan, "synth-recordings", "--per-pair", str(args.sim_per_pair), "--seed", str(seed), "-o", d],
                           check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        objects = sorted(o for o in os.listdir(sim_train) if os.path.isdir(os.path.join(sim_train, o)))
        for shots in [int(s) for s in args.sim_shots.split(",")]:
            subset = os.path.join(work, "sim_train_%d" % shots)
            for o in objects:
                for a in ("slide", "strike"):
                    folder = os.path.join(subset, o, a)
                    os.makedirs(folder)
                    for f in sorted(os.listdir(os.path.join(sim_train, o, a)))[:shots]:
                        os.symlink(os.path.join(sim_train, o, a, f), os.path.join(folder, f))
            for c in CLASSIFIERS:
                r = train_and_evaluate(echoplan, subset, sim_test, c, work)
                for action, (right, total) in r.items():
                    results.append({"source": "sim " + action, "shots": shots, "classifier": c, "right": right, "total": total})
                    print("sim %-6s shots %2d %-22s %d/%d" % (action, shots, c, right, total), file=sys.stderr)
        # Real recordings.
        if os.path.isdir(KITS_DIR):
            for shots in [int(s) for s in args.shots.split(",")]:
                tasks = real_tasks(shots)
                for c in CLASSIFIERS:
                    right = total = 0
                    for i, (kit, train, test) in enumerate(tasks):
                        train_dir, test_dir = os.path.join(work, "r_train_%d_%d" % (shots, i)), os.path.join(work, "r_test_%d_%d" % (shots, i))
                        if not os.path.exists(train_dir):
                            link_set(train_dir, train)
                            link_set(test_dir, test)
                        r = train_and_evaluate(echoplan, train_dir, test_dir, c, work)["strike"]
                        right += r[0]
                        total += r[1]
                    results.append({"source": "real (%d kits)" % len(tasks), "shots": shots, "classifier": c, "right": right, "total": total})
                    print("real shots %d %-22s %d/%d over %d kits" % (shots, c, right, total, len(tasks)), file=sys.stderr)
        else:
            print("hydrogen-drumkits not installed: real-recording benchmark skipped", file=sys.stderr)
    if args.out:
        with open(args.out, "w") as f:
            json.dump(results, f, indent=1)
    # Markdown: one row per (source, shots), one column per classifier.
    print("| source | shots | " + " | ".join(CLASSIFIERS) + " |")
    print("|---|---|" + "---|" * len(CLASSIFIERS))
    keys = []
    for r in results:
        if (r["source"], r["shots"]) not in keys:
            keys.append((r["source"], r["shots"]))
    for source, shots in keys:
        cells = []
        for c in CLASSIFIERS:
            r = next(x for x in results if x["source"] == source and x["shots"] == shots and x["classifier"] == c)
            cells.append("%.3f (%d/%d)" % (r["right"] / r["total"], r["right"], r["total"]))
        print("| %s | %d | %s |" % (source, shots, " | ".join(cells)))


if __name__ == "__main__":
    main()
