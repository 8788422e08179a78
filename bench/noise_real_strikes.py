#!/usr/bin/env python3
"""Background noise on real recorded strikes (docs/BENCHMARKS.md, "Background noise"; issue 52).

Each Hydrogen drum kit that Debian ships (package hydrogen-drumkits, read where it installs them,
never copied into the repository) with at least 3 instruments of at least MIN_LAYERS velocity
layers is a task: each instrument an object, each velocity layer a session of one strike. A dataset
campaign replays every held-out session heard through babble (Debian's asterisk prompts, the
digits, TALKERS at once) or room noise at each event-to-background ratio in turn, with paired arms:
the folds' classifier trained on the quiet strikes, and the one trained on them and their noisy
twins (babble of other words of the speaker, white noise or noise of a colour drawn per
recording, -6:24 dB), hearing labels,
observations graded by the measured level of each recording, or graded by the classifier's
confidence. Prints, per ratio, each arm's share sorted right, its belief at the sort and
the strikes per trial, and each noise-trained arm's paired difference from the quiet one.

Usage: bench/noise_real_strikes.py ECHOPLAN [--levels quiet,12,6,0] [--kits NAME,...] [--episodes N]
                                   [--talkers N] [--training-noise SOURCE,...]
Needs: apt-get install hydrogen-drumkits asterisk-core-sounds-en-wav.
"""
import argparse
import json
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from perception_accuracy import KITS_DIR, add_strikes, kit_instruments  # noqa: E402
import subprocess  # noqa: E402

SPEECH = "/usr/share/asterisk/sounds/en_US_f_Allison"
ARMS = ("quiet", "in_noise", "in_noise_levels", "in_noise_graded")
MIN_LAYERS = 5


def strike_tree(root, kit):
    """The kit as a recordings tree with one session per velocity layer; the instrument count."""
    instruments = [(n, f) for n, f in kit_instruments(os.path.join(KITS_DIR, kit)) if len(f) >= MIN_LAYERS]
    rows = ["file,object,action,session"]
    names = set()
    for name, files in instruments:
        add_strikes(root, name, files[:MIN_LAYERS], lambda n: n + 1, rows, names)
    with open(os.path.join(root, "manifest.csv"), "w") as out:
        out.write("\n".join(rows) + "\n")
    return len(instruments)


def campaign(data, level, episodes, talkers, training_noise):
    """The campaign at ratio `level` ("quiet": no noise in the trials), the noise-trained arms
    learning from `training_noise` (a list of sources)."""
    heard = f"""{{sources: [{SPEECH}/digits, room], ebr_db: "{level}", talkers: {talkers}}}"""
    noise = "" if level == "quiet" else f"""  noise: {heard}\n"""
    return f"""seed: 1
world:
  type: dataset
  data: {data}
  hold_out: session
{noise}training_set:
  noise: {{sources: [{", ".join(training_noise)}], ebr_db: "-6:24", talkers: {talkers}}}
task:
  rewards: {{right: 10, wrong: -100, sense: -1}}
arms:
  - {{name: quiet, strategy: plan}}
  - {{name: in_noise, strategy: plan, trained_in_noise: true}}
  - {{name: in_noise_levels, strategy: plan, trained_in_noise: true, observations: levels}}
  - {{name: in_noise_graded, strategy: plan, trained_in_noise: true, observations: graded}}
planner: {{solver: abt, episodes: {episodes}, max_steps: 10}}
"""


def row(kit, level, summary):
    """| kit | level | per arm: right @ belief (strikes) | each noise-trained arm minus quiet |"""
    cells = [kit, level]
    strikes = {r["arm"]: r["mean_action_counts"]["strike"] for r in summary["results"] if r["objects"] == "all"}
    for c in summary["sort_confidence"]:
        if c["arm"] in ARMS:
            cells.append("%.3f @ %.3f (%.2f)" % (c["share_right"], c["mean_belief"], strikes.get(c["arm"], 0)))
    for d in summary["paired_differences"]:
        cells.append("%+.2f ± %.2f" % (d["mean_discounted_reward_difference"], d["ci95"]))
    return "| " + " | ".join(cells) + " |"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("echoplan")
    parser.add_argument("--levels", default="quiet,12,6,0")
    parser.add_argument("--kits", default="")
    parser.add_argument("--episodes", type=int, default=2000)
    parser.add_argument("--talkers", type=int, default=8, help="babble: talkers heard at once")
    parser.add_argument("--training-noise",
                        default=f"{SPEECH}/letters,{SPEECH}/phonetic,white,coloured",
                        help="the noise-trained arms' sources, comma-separated (default: other "
                             "words of the speaker, white and coloured noise)")
    args = parser.parse_args()
    if not os.path.isdir(KITS_DIR) or not os.path.isdir(SPEECH):
        sys.exit("needs hydrogen-drumkits and asterisk-core-sounds-en-wav: apt-get install them")
    kits = args.kits.split(",") if args.kits else sorted(os.listdir(KITS_DIR))
    pooled = {}  # (level, arm) -> [sorts, sorts right, summed belief]
    with tempfile.TemporaryDirectory() as work:
        for kit in kits:
            data = os.path.join(work, kit.replace(" ", "_"))
            os.makedirs(data)
            if strike_tree(data, kit) < 3:
                continue
            for level in args.levels.split(","):
                config = os.path.join(work, "c.yaml")
                with open(config, "w") as out:
                    out.write(campaign(data, level, args.episodes, args.talkers,
                                       args.training_noise.split(",")))
                out_dir = os.path.join(work, "out_%s_%s" % (kit.replace(" ", "_"), level))
                subprocess.run([args.echoplan, "experiment", "--config", config, "--out", out_dir],
                               check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                with open(os.path.join(out_dir, "summary.json")) as f:
                    summary = json.load(f)
                print(row(kit, level, summary), flush=True)
                for c in summary["sort_confidence"]:
                    p = pooled.setdefault((level, c["arm"]), [0, 0.0, 0.0])
                    p[0] += c["sorts"]
                    p[1] += c["share_right"] * c["sorts"]
                    p[2] += c["mean_belief"] * c["sorts"]
    print("\npooled over the kits: share right @ belief at the sort (sorts)")
    for level in args.levels.split(","):
        cells = ["%.3f @ %.3f (%d)" % (p[1] / p[0], p[2] / p[0], p[0])
                 for p in (pooled.get((level, arm)) for arm in ARMS) if p and p[0]]
        print("| %s | %s |" % (level, " | ".join(cells)))


if __name__ == "__main__":
    main()
