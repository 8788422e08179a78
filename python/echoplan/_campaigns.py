"""Campaigns: a campaign file run into a folder, and its results read back from the folder."""
import csv
import json
import os
from dataclasses import dataclass, field

from . import _echoplan


def _value(text):
    """A CSV cell as the number it spells, else the text (an empty cell stays '')."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _rows(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return [{k: _value(v) for k, v in row.items()} for row in csv.DictReader(f)]


@dataclass
class Campaign:
    """A campaign's output folder as Python objects: `summary` (summary.json), `config`
    (campaign.json), `trials` and `steps` (trials.csv and steps.csv, one dict per row with
    numbers as numbers), `summary_text` (summary.txt)."""

    directory: str
    summary: dict = field(repr=False)
    config: dict = field(repr=False)
    trials: list = field(repr=False)
    steps: list = field(repr=False)
    summary_text: str = field(repr=False)

    @property
    def arms(self):
        """The arms' names, in the campaign's order."""
        return [arm["name"] for arm in self.config.get("config", self.config).get("arms", [])]

    def trials_of(self, arm):
        """The trials of one arm."""
        return [t for t in self.trials if t.get("arm") == arm]


def read_campaign(directory):
    """Reads a campaign's output folder (what `echoplan experiment --out DIR` wrote)."""
    directory = os.fspath(directory)

    def text(name):
        path = os.path.join(directory, name)
        if not os.path.exists(path):
            return ""
        with open(path) as f:
            return f.read()

    summary = text("summary.json")
    config = text("campaign.json")
    return Campaign(directory=directory,
                    summary=json.loads(summary) if summary else {},
                    config=json.loads(config) if config else {},
                    trials=_rows(os.path.join(directory, "trials.csv")),
                    steps=_rows(os.path.join(directory, "steps.csv")),
                    summary_text=text("summary.txt"))


def run_campaign(config, out, *, workers=None, seed=None, shard="1/1", figures=True):
    """Runs a campaign file into folder `out`, as `echoplan experiment --config CONFIG --out OUT`
    (the same files, byte for byte), and returns its results (read_campaign). Running it again
    continues an interrupted campaign. workers: threads (default: all cores; results do not
    depend on it); seed: overrides the file's; shard: 'I/N'; figures: False skips figures and the
    page. Ctrl-C stops after each worker's step in progress and rebuilds the report first."""
    _echoplan._run_campaign(os.fspath(config), os.fspath(out), workers=workers, seed=seed,
                            shard=shard, figures=figures)
    return read_campaign(out)
