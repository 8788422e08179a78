"""A campaign run from Python against `echoplan experiment` on the same file: the same trials,
steps and summary, read back as Python objects."""
import json
import re

import echoplan
from conftest import SOURCE, echoplan_command


def small_lab_campaign(folder):
    """experiments/chapter5_lab.yaml made small (1 trial per object, 300 episodes), its relative
    paths made absolute."""
    text = (SOURCE / "experiments" / "chapter5_lab.yaml").read_text()
    text = text.replace("../problems/", f"{SOURCE}/problems/")
    text = re.sub(r"^reference: .*$", "", text, flags=re.M)
    text = text.replace("trials: 10}", "trials: 1}").replace("episodes: 20000", "episodes: 300")
    path = folder / "lab.yaml"
    path.write_text(text)
    return path


def test_a_campaign_from_python_is_the_commands(tmp_path):
    config = small_lab_campaign(tmp_path)
    echoplan_command("experiment", "--config", config, "--out", tmp_path / "command", "--workers", 1)
    campaign = echoplan.run_campaign(config, tmp_path / "mine", workers=2, figures=False)
    for name in ("trials.csv", "steps.csv", "arms/lab/steps.csv"):
        assert (tmp_path / "mine" / name).read_bytes() == (tmp_path / "command" / name).read_bytes(), name
    assert campaign.summary == json.load(open(tmp_path / "command" / "summary.json"))
    assert campaign.arms == ["hand_tuned", "lab"]
    assert len(campaign.trials) == 8 and len(campaign.trials_of("lab")) == 4
    first = campaign.trials[0]
    assert isinstance(first["steps"], int) and isinstance(first["discounted_reward"], float)
    # Running it again continues the finished campaign: nothing changes.
    again = echoplan.run_campaign(config, tmp_path / "mine", figures=False)
    assert again.trials == campaign.trials


def test_a_bad_campaign_file_raises_the_commands_error(tmp_path):
    config = small_lab_campaign(tmp_path)
    text = config.read_text().replace("episodes: 300", "episodez: 300")
    config.write_text(text)
    line = next(n for n, l in enumerate(text.splitlines(), 1) if "episodez" in l)
    try:
        echoplan.run_campaign(config, tmp_path / "out")
        raise AssertionError("expected an InputError")
    except echoplan.InputError as error:
        assert error.file == str(config) and error.line == line and "episodez" in str(error)
        done = echoplan_command("experiment", "--config", config, "--out", tmp_path / "out2", check=False)
        assert done.returncode == 2 and str(error) in done.stderr
