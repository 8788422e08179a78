"""bench/pooled_pairs.py on hand-made campaign folders: the pairing, the pooled interval (against
Student's t table values) and the errors that name the file."""
import os
import subprocess
import sys

import pytest

SCRIPT = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "pooled_pairs.py")
HEADER = "trial,arm,object,session,discounted_reward,seed\n"


def campaign(folder, rows, header=HEADER):
    """A campaign folder whose trials.csv holds `rows` (arm, object, session, reward)."""
    folder.mkdir()
    lines = [f"{i},{arm},{obj},{session},{reward},7\n" for i, (arm, obj, session, reward)
             in enumerate(rows)]
    (folder / "trials.csv").write_text(header + "".join(lines))
    return str(folder)


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)


def test_pairs_on_object_and_session_and_pools_campaigns(tmp_path):
    # Campaign a: plan minus rule 1, 2, 3 on three (object, session) pairs, listed in another
    # order for each arm, beside a third arm that is ignored.
    a = campaign(tmp_path / "a", [
        ("plan", "mug", "s1", 5.0), ("plan", "mug", "s2", 6.0), ("plan", "can", "s1", 3.0),
        ("other", "mug", "s1", 99.0),
        ("rule", "can", "s1", 0.0), ("rule", "mug", "s2", 4.0), ("rule", "mug", "s1", 4.0),
    ])
    # Campaign b (another seed): differences 0 and 4.
    b = campaign(tmp_path / "b", [
        ("rule", "cup", "s1", 1.0), ("plan", "cup", "s1", 1.0),
        ("rule", "cup", "s2", -2.0), ("plan", "cup", "s2", 2.0),
    ])
    result = run("plan", "rule", a, b)
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    # 1, 2, 3: mean 2, sd 1, t(0.975, 2) = 4.3027: 4.3027 / sqrt(3) = 2.48.
    assert lines[0] == f"{a}: plan minus rule: +2.00 ± 2.48 (95% CI, 3 pairs)"
    # 0 and 4: mean 2, sd 2.828, t(0.975, 1) = 12.706: 12.706 * 2.828 / sqrt(2) = 25.41.
    assert lines[1] == f"{b}: plan minus rule: +2.00 ± 25.41 (95% CI, 2 pairs)"
    # 1, 2, 3, 0, 4: mean 2, sd sqrt(10 / 4), t(0.975, 4) = 2.7764: 1.96.
    assert lines[2] == "pooled: plan minus rule: +2.00 ± 1.96 (95% CI, 5 pairs)"


@pytest.mark.parametrize("rows, header, message", [
    ([("plan", "mug", "s1", 1.0)], "trial,arm,object,discounted_reward,seed\n", "no column session"),
    ([("plan", "mug", "s1", 1.0), ("plan", "mug", "s1", 2.0), ("rule", "mug", "s1", 0.0)], HEADER,
     "arm 'plan' has object mug session s1 twice"),
    ([("plan", "mug", "s1", 1.0), ("rule", "mug", "s2", 0.0)], HEADER,
     "did not run the same trials"),
    ([("plan", "mug", "s1", 1.0)], HEADER, "no trials of arm 'rule'"),
    ([("plan", "mug", "s1", "x"), ("rule", "mug", "s1", 0.0)], HEADER,
     "discounted_reward 'x' is not a number"),
])
def test_bad_campaigns_name_the_file_and_exit_2(tmp_path, rows, header, message):
    folder = campaign(tmp_path / "c", rows, header)
    result = run("plan", "rule", folder)
    assert result.returncode == 2
    assert message in result.stderr
    assert folder in result.stderr
    assert result.stdout == ""


def test_a_missing_folder_and_too_few_arguments_exit_2(tmp_path):
    result = run("plan", "rule", str(tmp_path / "none"))
    assert result.returncode == 2
    assert os.path.join(str(tmp_path / "none"), "trials.csv") in result.stderr
    usage = run("plan", "rule")
    assert usage.returncode == 2
    assert "pooled_pairs.py ARM BASELINE CAMPAIGN" in usage.stderr
