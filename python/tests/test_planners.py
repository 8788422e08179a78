"""Planners and trials against `echoplan trials` on the report's problem, same seed and budget."""
import numpy as np
import pytest

import echoplan
from conftest import REPORT_PROBLEM, echoplan_command, read_csv


@pytest.fixture(scope="module")
def command_trials(tmp_path_factory):
    """`echoplan trials` on the report's problem: 2 trials per object, 500 episodes, seed 7."""
    out = tmp_path_factory.mktemp("trials")
    echoplan_command("trials", "--problem", REPORT_PROBLEM, "--per-object", 2, "--episodes", 500,
                     "--seed", 7, "--out", out)
    return read_csv(out / "trials.csv"), read_csv(out / "steps.csv")


def steps_of(trials, model):
    """Trials as the command's steps.csv rows hold them: (trial, step, action, observation,
    reward, particles per object)."""
    return [(str(s.record.trial), str(s.record.step), model.action_names[s.action],
             model.observation_names[s.observation.index], s.reward,
             [round(p * 1000) for p in s.record.belief])
            for t in trials for s in t.steps]


def command_steps(rows, model):
    return [(r["trial"], r["step"], r["action"], r["observation"], float(r["reward"]),
             [int(r["particles_" + o]) for o in model.objects]) for r in rows]


def test_run_trials_makes_the_commands_decisions(report_problem, command_trials):
    trials_rows, step_rows = command_trials
    trials = echoplan.run_trials(report_problem, per_object=2, episodes=500, seed=7)
    model = report_problem.model
    assert steps_of(trials, model) == command_steps(step_rows, model)
    assert [t.record.discounted_reward for t in trials] == pytest.approx(
        [float(r["discounted_reward"]) for r in trials_rows], abs=1e-12)
    assert [model.objects[t.record.true_state] for t in trials] == [r["true_state"] for r in trials_rows]


def test_the_planner_step_by_step_makes_the_commands_decisions(report_problem, command_trials):
    """The trial runner's loop written out in Python with Planner, Belief and Model: trial t's
    streams are derive_seed(seed, [t, stream]) (loop/trial_runner.cpp), the world is the model."""
    _, step_rows = command_trials
    model = report_problem.model
    planner = echoplan.Planner(report_problem, episodes=500)
    logged = []
    for t in range(8):
        truth, world, belief_rng, planner_rng = (
            echoplan.Rng(echoplan.derive_seed(7, [t, s])) for s in (1, 2, 3, 4))
        state = model.sample_initial_state(truth)
        while state.discrete[0] != t // 2:  # --per-object 2: trial t holds object t // 2
            state = model.sample_initial_state(truth)
        belief = report_problem.make_belief(belief_rng)
        planner.reset(belief, rng=planner_rng)
        for step in range(100):
            counts = belief.particle_counts()
            planner.improve(episodes=500, rng=planner_rng)
            assert planner.stats()["episodes_last"] == 500
            values = planner.action_values()
            action = planner.best_action()
            assert values[action] == np.nanmax(values)
            result = model.step(state, action, world)
            state = result.next
            logged.append((str(t), str(step), model.action_names[action],
                           model.observation_names[result.observation.index], result.reward, counts))
            if result.terminal or result.collision:
                break
            belief.update(action, result.observation, belief_rng)
            planner.update(action, result.observation, belief, rng=planner_rng)
    assert logged == command_steps(step_rows, model)


@pytest.mark.parametrize("solver", ["information_gain", "decision_region", "pomcp"])
def test_any_solver_by_name_makes_the_commands_decisions(report_problem, tmp_path, solver):
    echoplan_command("trials", "--problem", REPORT_PROBLEM, "--solver", solver, "--trials", 6,
                     "--episodes", 300, "--seed", 3, "--out", tmp_path)
    trials = echoplan.run_trials(report_problem, solver=solver, trials=6, episodes=300, seed=3)
    model = report_problem.model
    assert steps_of(trials, model) == command_steps(read_csv(tmp_path / "steps.csv"), model)


def test_unheard_outcomes_at_commit_makes_the_commands_decisions(report_problem, tmp_path):
    echoplan_command("trials", "--problem", REPORT_PROBLEM, "--unheard", "commit", "--trials", 6,
                     "--episodes", 300, "--seed", 3, "--out", tmp_path)
    trials = echoplan.run_trials(report_problem, unheard="commit", trials=6, episodes=300, seed=3)
    model = report_problem.model
    assert steps_of(trials, model) == command_steps(read_csv(tmp_path / "steps.csv"), model)
    assert echoplan.Planner(report_problem, unheard="commit").settings["search"]["unheard"] == "commit"
    with pytest.raises(echoplan.InputError, match="lookahead"):
        echoplan.Planner(report_problem, unheard="commit", leaf="lookahead")


def test_planner_settings_are_checked_as_the_commands_flags(report_problem):
    planner = echoplan.Planner(report_problem, solver="abt", episodes=100, exploration=5.0)
    assert planner.settings["solver"] == "abt"
    with pytest.raises(echoplan.InputError, match="foo"):
        echoplan.Planner(report_problem, solver="foo")
    with pytest.raises(TypeError, match="planner settings"):
        echoplan.Planner(report_problem, episdoes=100)


def test_expected_reward_is_the_commands(tmp_path):
    """expected_reward() of each trial is the value `echoplan trials` writes to
    expected_rewards.csv for the same problem (with an exact belief), seed and strategy."""
    text = open(REPORT_PROBLEM).read().replace(
        "belief: {type: particle, particles: 1000}", "belief: {type: exact}")
    assert "belief: {type: exact}" in text
    path = tmp_path / "exact.yaml"
    path.write_text(text)
    echoplan_command("trials", "--problem", path, "--solver", "information_gain", "--trials", 30,
                     "--seed", 4, "--out", tmp_path / "out")
    rows = read_csv(tmp_path / "out" / "expected_rewards.csv")
    problem = echoplan.load_problem(str(path))
    trials = echoplan.run_trials(problem, solver="information_gain", trials=30, seed=4)
    assert [echoplan.expected_reward(problem, t) for t in trials] == pytest.approx(
        [float(r["expected_reward"]) for r in rows], abs=1e-12)
