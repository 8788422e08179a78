#!/usr/bin/python3
"""Two arms' paired reward difference, campaign by campaign and pooled over campaigns.

    pooled_pairs.py ARM BASELINE CAMPAIGN [CAMPAIGN ...]

Each CAMPAIGN is an `echoplan experiment` folder holding both arms (for example
`SEED=N bench/dataset_campaign.sh`'s fifth argument, one per seed). Within a campaign ARM's and
BASELINE's trials are paired on (object, session) as the campaign pairs them; campaigns drawn from
different seeds are independent, so their pairs pool into one sample. Prints, for each campaign and
pooled, the number of pairs and ARM minus BASELINE in discounted reward per trial, mean and 95% CI
(Student's t), as summary.txt writes it.
"""
import csv
import math
import os
import sys

from scipy import stats


def fail(message):
    print(f"pooled_pairs.py: {message}", file=sys.stderr)
    sys.exit(2)


COLUMNS = ("arm", "object", "session", "discounted_reward")


def rewards_by_arm(campaign, arms):
    """{arm: {(object, session): discounted reward}} for `arms`, from one read of trials.csv."""
    path = os.path.join(campaign, "trials.csv")
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            missing = [c for c in COLUMNS if c not in (reader.fieldnames or [])]
            if missing:
                fail(f"{path}: no column {', '.join(missing)}")
            rows = [row for row in reader if row["arm"] in arms]
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    rewards = {arm: {} for arm in arms}
    for row in rows:
        arm, key = row["arm"], (row["object"], row["session"])
        if key in rewards[arm]:
            fail(f"{path}: arm '{arm}' has object {key[0]} session {key[1]} twice; "
                 "only a campaign with one trial per recorded session pairs this way")
        try:
            rewards[arm][key] = float(row["discounted_reward"])
        except ValueError:
            fail(f"{path}: arm '{arm}': discounted_reward '{row['discounted_reward']}' "
                 "is not a number")
    for arm in arms:
        if not rewards[arm]:
            fail(f"{path}: no trials of arm '{arm}'")
    return rewards


def differences(campaign, arm, baseline):
    rewards = rewards_by_arm(campaign, (arm, baseline))
    a, b = rewards[arm], rewards[baseline]
    if a.keys() != b.keys():
        fail(f"{campaign}: arms '{arm}' and '{baseline}' did not run the same trials")
    return [a[key] - b[key] for key in sorted(a)]


def interval(values):
    n = len(values)
    mean = sum(values) / n
    if n < 2:
        return n, mean, 0.0
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1))
    return n, mean, stats.t.ppf(0.975, n - 1) * sd / math.sqrt(n)


def main():
    if len(sys.argv) < 4:
        print(__doc__.strip(), file=sys.stderr)
        sys.exit(2)
    arm, baseline, campaigns = sys.argv[1], sys.argv[2], sys.argv[3:]
    pooled = []
    for campaign in campaigns:
        d = differences(campaign, arm, baseline)
        pooled += d
        n, mean, half = interval(d)
        print(f"{campaign}: {arm} minus {baseline}: {mean:+.2f} ± {half:.2f} (95% CI, {n} pairs)")
    n, mean, half = interval(pooled)
    print(f"pooled: {arm} minus {baseline}: {mean:+.2f} ± {half:.2f} (95% CI, {n} pairs)")


if __name__ == "__main__":
    main()
