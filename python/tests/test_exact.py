"""The exact solver and certify against `echoplan solve --json` and `echoplan certify --json`."""
import json

import pytest

import echoplan
from conftest import REPORT_PROBLEM, echoplan_command


def test_exact_bounds_are_the_commands(report_problem):
    """`echoplan solve` (run_exact in solve.cpp): refine b0 to epsilon x max(1, |V|) within the
    expansion cap, then every action's Q at b0 to the same target."""
    expansions = 3000
    command = json.loads(echoplan_command("solve", "--problem", REPORT_PROBLEM, "--method", "exact",
                                          "--max-expansions", expansions, "--json").stdout)
    solver = echoplan.ExactSolver(report_problem)
    root = solver.root
    target = lambda b: 1e-4 * max(1.0, abs(b[0]), abs(b[1]))  # noqa: E731
    solver.refine(root, target_gap=target(solver.value(root)), seconds=1.0, expansions=expansions)
    lower, upper = solver.value(root)
    assert (lower, upper) == (command["lower"], command["upper"])
    assert solver.expansions == command["root_expansions"]


@pytest.fixture(scope="module")
def logged_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("certify")
    echoplan_command("trials", "--problem", REPORT_PROBLEM, "--trials", 6, "--episodes", 400,
                     "--seed", 11, "--out", out)
    return out / "steps.csv"


def test_certify_on_logged_steps_is_the_commands(report_problem, logged_run):
    flags = ["--root-expansions", 20000, "--expansions", 2000]
    command = json.loads(echoplan_command("certify", "--problem", REPORT_PROBLEM, "--steps",
                                          logged_run, *flags, "--json").stdout)
    mine = echoplan.certify(report_problem, str(logged_run), root_expansions=20000, expansions=2000)
    for key, value in command.items():
        assert mine[key] == value, key
    # The same trials held in Python, not read from a file, get the same certificate.
    trials = echoplan.run_trials(report_problem, trials=6, episodes=400, seed=11)
    held = echoplan.certify(report_problem, trials, root_expansions=20000, expansions=2000)
    for key, value in command.items():
        assert held[key] == value, key


def test_the_exact_solver_refuses_a_problem_of_another_shape():
    tiger = echoplan.load_problem(echoplan.shipped_file("problems/tiger.pomdp"))
    with pytest.raises(echoplan.InputError, match="identification problem"):
        echoplan.ExactSolver(tiger)
