"""Ctrl-C stops a long call cleanly: the call raises KeyboardInterrupt soon after the signal,
and Python goes on (the same as `echoplan trials` stopping between steps)."""
import os
import signal
import subprocess
import sys
import time

from conftest import REPORT_PROBLEM

PROGRAM = f"""
import echoplan, sys, time
problem = echoplan.load_problem({REPORT_PROBLEM!r})
print("ready", flush=True)
start = time.monotonic()
try:
    echoplan.run_trials(problem, trials=100000, episodes=2000, seed=1)
    print("finished")
except KeyboardInterrupt:
    print(f"interrupted after {{time.monotonic() - start:.1f}} s", flush=True)
print("still running", flush=True)
"""


def test_ctrl_c_stops_a_long_call_with_keyboard_interrupt():
    child = subprocess.Popen([sys.executable, "-c", PROGRAM], stdout=subprocess.PIPE, text=True,
                             env=os.environ)
    assert child.stdout.readline().strip() == "ready"
    time.sleep(1.0)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=60)
    assert "interrupted after" in out and "still running" in out
    assert time.monotonic() - sent < 20
    assert child.returncode == 0
