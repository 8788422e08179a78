"""Problems, models and beliefs, against `echoplan check` and `echoplan trials` on the same files."""
import numpy as np
import pytest
import yaml

import echoplan
from conftest import REPORT_PROBLEM, echoplan_command


def test_version_is_the_commands():
    assert f"echoplan {echoplan.__version__}" == echoplan_command("version").stdout.strip()


def test_the_report_problem_loads_with_its_names(report_problem):
    model = report_problem.model
    assert model.objects == ["pringles_can", "coffee_mug", "plastic_cup", "paper_base"]
    assert model.action_names == ["slide", "strike", "move_to_A", "move_to_B"]
    assert report_problem.belief_type == "particle" and report_problem.particles == 1000
    # The command's own summary line names the same sizes.
    out = echoplan_command("check", "--problem", REPORT_PROBLEM).stdout
    assert f"{len(model.action_names)} actions, {len(model.observation_names)} observation symbols" in out


def test_check_finds_what_the_command_finds(tmp_path):
    # A problem whose two objects sound the same yet go to different bins: `check` warns.
    problem = yaml.safe_load(open(REPORT_PROBLEM))
    table = problem["observation"]["table"]
    for action in table:
        table[action]["coffee_mug"] = table[action]["pringles_can"]
    path = tmp_path / "confusable.yaml"
    path.write_text(yaml.safe_dump(problem))
    findings = echoplan.load_problem(str(path)).check()
    assert findings, "expected a finding"
    warnings = [line[len("warning: "):] for line in
                echoplan_command("check", "--problem", path).stdout.splitlines()
                if line.startswith("warning: ")]
    assert findings == warnings


def test_a_problem_from_a_dict_is_the_files(report_problem):
    from_dict = echoplan.Problem.from_dict(yaml.safe_load(open(REPORT_PROBLEM)), "report")
    a, b = report_problem.model.tables(), from_dict.model.tables()
    for key in ("transition", "observation", "reward", "initial_belief"):
        np.testing.assert_array_equal(a[key], b[key])
    # ... and plans to the same decisions.
    one = echoplan.run_trials(report_problem, trials=3, episodes=300, seed=5)
    two = echoplan.run_trials(from_dict, trials=3, episodes=300, seed=5)
    assert [[s.action for s in t.steps] for t in one] == [[s.action for s in t.steps] for t in two]


def test_a_bad_file_raises_input_error_with_the_commands_file_and_line(tmp_path):
    text = open(REPORT_PROBLEM).read().replace("pringles_can: [0.5, 0.3, 0.15, 0.05]",
                                               "pringles_can: [0.5, 0.3, 0.15]")
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    with pytest.raises(echoplan.InputError) as raised:
        echoplan.load_problem(str(path))
    error = raised.value
    assert error.file == str(path) and error.line > 0
    assert text.splitlines()[error.line - 1].strip().startswith("pringles_can: [0.5, 0.3, 0.15]")
    done = echoplan_command("check", "--problem", path, check=False)
    assert done.returncode == 2
    assert str(error) in done.stderr
    assert isinstance(error, ValueError)


def test_a_bad_dict_names_the_line_of_its_yaml():
    problem = yaml.safe_load(open(REPORT_PROBLEM))
    problem["discount"] = 1.5
    with pytest.raises(echoplan.InputError) as raised:
        echoplan.Problem.from_dict(problem, "mine")
    assert raised.value.file == "mine.yaml" and raised.value.line > 0
    assert "discount" in str(raised.value)


def test_step_and_likelihood_follow_the_tables(report_problem):
    model = report_problem.model
    tables = model.tables()
    rng = echoplan.Rng(3)
    state = model.sample_initial_state(rng)
    k = state.discrete[0]
    for action in ("slide", "strike"):
        for o, name in enumerate(model.observation_names):
            assert model.observation_likelihood(state, action, name) == pytest.approx(
                tables["observation"][model.action_index(action), k, o])
    result = model.step(state, "move_to_A", rng)
    assert result.terminal and result.reward == tables["reward"][k, 2]


def test_exact_and_particle_beliefs_as_arrays(report_problem):
    exact = echoplan.ExactBelief(report_problem)
    assert exact.kind == "exact"
    np.testing.assert_allclose(exact.marginal(), [0.25] * 4)
    probabilities = exact.probabilities  # a view: it follows the updates
    exact.update("strike", "coffee_mug", echoplan.Rng(1))
    tables = report_problem.model.tables()
    expected = tables["observation"][1, :4, 1] / tables["observation"][1, :4, 1].sum()
    np.testing.assert_allclose(probabilities[:4], expected)
    particles = report_problem.make_belief(echoplan.Rng(1))
    assert particles.kind == "particle"
    assert sum(particles.particle_counts()) == 1000
    discrete, continuous = particles.particles
    assert discrete.shape == (1000, 1) and continuous.shape == (1000, 10)
    with pytest.raises(ValueError, match="no action 'hop'"):
        particles.update("hop", 0, echoplan.Rng(1))
