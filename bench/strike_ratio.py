#!/usr/bin/python3
"""Where the mug-vs-cup strike distance comes from: the clip, the thud, or the room.

sim_realism.py's strike ratio (between mug and cup / within cups, mean absolute difference of the
level-removed mean 64-band log-mel spectra; lab 1.5) is taken over whole clips. This script
synthesises N mug and N cup strikes per seed with `echoplan synth-recordings` and prints that ratio

  - over the whole clip (sim_realism.py's figure),
  - over parts of the clip, placed at its loudest 5 ms frame (the impact): the thud (50 ms before to
    100 ms after), the event (to 0.5 s after), everything before the thud, everything from 0.5 s
    after it;
  - over whole clips once more with the mug's recordings made in a room ROOM_DB louder (the same
    seeds, `recording.noise_dbfs` raised in a copy of objects/sim_config.yaml): the lab's one mug
    strike has a noise floor 4.6 dB above its three cup strikes' mean (real-robot-recordings.md), a
    difference of recording session rather than of object.

Usage: bench/strike_ratio.py [--per-pair 10] [--seeds 1,2] [--room-db 4.6]
                             [--echoplan build/echoplan] [--measures ../shared/tools/sound_measures.py]
Needs Debian's python3-numpy, python3-scipy, python3-soundfile (run with /usr/bin/python3).
"""
import argparse
import glob
import itertools
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import sim_realism  # noqa: E402  (its REPO, load_measures and level_removed_logmel)

PARTS = [("thud (-50..+100 ms)", -0.05, 0.10), ("event (-50..+500 ms)", -0.05, 0.50),
         ("before the thud", None, -0.05), ("from 0.5 s after", 0.50, None)]


def part_logmel(sm, path, start_s, end_s):
    """Level-removed mean log-mel (as sound_measures.logmel_mean) of the part [start, end) of the clip
    placed at its loudest 5 ms frame (None: the clip's start or end); digital-silence frames left out."""
    x, sr, n, silent_frame = sm.load_mono(path)
    energy = (x.reshape(len(silent_frame), n) ** 2).mean(axis=1)
    peak = int(np.argmax(energy)) * n
    lo = 0 if start_s is None else max(0, peak + int(start_s * sr))
    hi = len(x) if end_s is None else min(len(x), peak + int(end_s * sr))
    silent = np.repeat(silent_frame, n)[lo:hi]
    n_fft, hop = 2048, 512
    frames = np.lib.stride_tricks.sliding_window_view(x[lo:hi], n_fft)[::hop]
    live = ~np.lib.stride_tricks.sliding_window_view(silent, n_fft)[::hop].all(axis=1)
    spec = np.abs(np.fft.rfft(frames[live] * np.hanning(n_fft), axis=1)) ** 2
    mel = spec @ sm.mel_filterbank(sr, n_fft).T
    v = (10 * np.log10(mel + 1e-10)).mean(axis=0)
    return v - v.mean()


def ratio(mug, cup):
    within = np.mean([np.mean(np.abs(a - b)) for a, b in itertools.combinations(cup, 2)])
    between = np.mean([np.mean(np.abs(a - b)) for a in mug for b in cup])
    return between, within, between / within


def louder_room_config(db, path):
    """objects/sim_config.yaml with recording.noise_dbfs raised by `db`, written to `path`."""
    with open(os.path.join(sim_realism.REPO, "objects", "sim_config.yaml")) as f:
        text = f.read()
    pattern = re.compile(r"^(\s+noise_dbfs:\s*)(-?[0-9.]+)", re.MULTILINE)
    m = pattern.search(text)
    if not m:
        sys.exit("strike_ratio.py: objects/sim_config.yaml has no 'noise_dbfs:' line")
    with open(path, "w") as f:
        f.write(text[:m.start(2)] + f"{float(m.group(2)) + db:g}" + text[m.end(2):])


def dataset(echoplan, per_pair, seed, out, objects, config=None):
    cmd = [echoplan, "synth-recordings", "--per-pair", str(per_pair), "--seed", str(seed), "-o", out,
           "--objects", objects, "--actions", "strike"]
    if config:
        cmd += ["--sim-config", config]
    subprocess.run(cmd, check=True, cwd=sim_realism.REPO, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return {o: sorted(glob.glob(os.path.join(out, o, "strike", "*.wav"))) for o in objects.split(",")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--per-pair", type=int, default=10)
    ap.add_argument("--seeds", default="1,2")
    ap.add_argument("--room-db", type=float, default=4.6)
    ap.add_argument("--echoplan", default=os.path.join(sim_realism.REPO, "build", "echoplan"))
    ap.add_argument("--measures", default=os.path.join(sim_realism.REPO, "..", "..", "shared", "tools",
                                                       "sound_measures.py"))
    args = ap.parse_args()
    sm = sim_realism.load_measures(args.measures)
    with tempfile.TemporaryDirectory() as tmp:
        loud = os.path.join(tmp, "louder_room.yaml")
        louder_room_config(args.room_db, loud)
        for seed in [int(s) for s in args.seeds.split(",")]:
            print(f"seed {seed}: {args.per_pair} mug and {args.per_pair} cup strikes; mug vs cup between / within cups")
            files = dataset(args.echoplan, args.per_pair, seed, os.path.join(tmp, f"s{seed}"),
                            "coffee_mug,plastic_cup")
            mug = [sim_realism.level_removed_logmel(sm, f) for f in files["coffee_mug"]]
            cup = [sim_realism.level_removed_logmel(sm, f) for f in files["plastic_cup"]]
            print("  %-34s between %.2f, within %.2f: ratio %.2f" % (("whole clip",) + ratio(mug, cup)))
            for name, start, end in PARTS:
                r = ratio([part_logmel(sm, f, start, end) for f in files["coffee_mug"]],
                          [part_logmel(sm, f, start, end) for f in files["plastic_cup"]])
                print("  %-34s between %.2f, within %.2f: ratio %.2f" % ((name,) + r))
            loud_mug = dataset(args.echoplan, args.per_pair, seed, os.path.join(tmp, f"loud{seed}"),
                               "coffee_mug", loud)["coffee_mug"]
            r = ratio([sim_realism.level_removed_logmel(sm, f) for f in loud_mug], cup)
            print("  %-34s between %.2f, within %.2f: ratio %.2f" %
                  ((f"whole clip, mug room +{args.room_db:g} dB",) + r))


if __name__ == "__main__":
    main()
