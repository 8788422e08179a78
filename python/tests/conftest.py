"""What every test of the Python module shares: the `echoplan` command built beside it (the
independent reference: each test compares a call with the command's own output on the same
inputs), the source tree's shipped files, and a helper that runs the command."""
import csv
import os
import subprocess
from pathlib import Path

import pytest

SOURCE = Path(os.environ.get("ECHOPLAN_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("ECHOPLAN_BINARY", str(SOURCE / "build" / "echoplan"))
REPORT_PROBLEM = str(SOURCE / "problems" / "audio_objects.yaml")
FEATURE_SET = str(SOURCE / "experiments" / "data" / "synthetic_objects")


def echoplan_command(*args, check=True):
    """Runs the `echoplan` command; returns the finished process (stdout and stderr as text)."""
    done = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"echoplan {' '.join(map(str, args))} failed "
                             f"({done.returncode}):\n{done.stderr}")
    return done


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture(scope="session")
def report_problem():
    import echoplan
    return echoplan.load_problem(REPORT_PROBLEM)
