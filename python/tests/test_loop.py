"""The loop with robot parts written in Python, against the trial `echoplan run` drove with its
own replayed recordings: the same clips heard through a Python robot and recorder give the same
decisions, observations and beliefs."""
import json

import numpy as np
import pytest
import soundfile

import echoplan
from conftest import REPORT_PROBLEM, echoplan_command


@pytest.fixture(scope="module")
def command_run(tmp_path_factory):
    """`echoplan run` replaying recordings of the mug with a model trained on other recordings."""
    root = tmp_path_factory.mktemp("loop")
    echoplan_command("synth-recordings", "--per-pair", 3, "--seed", 2, "-o", root / "train")
    echoplan_command("synth-recordings", "--per-pair", 4, "--seed", 9, "-o", root / "replay")
    echoplan_command("train", "--data", root / "train", "--out", root / "model.json")
    echoplan_command("run", "--object", "coffee_mug", "--model", root / "model.json", "--recordings",
                     root / "replay", "--episodes", 300, "--seed", 3, "--out", root / "run")
    steps = [json.loads(line) for line in open(root / "run" / "loop_steps.jsonl")]
    return root, steps


class ArmStandIn(echoplan.Robot):
    """A robot class as a driver would write one: it is told each action and reports it done."""

    def __init__(self):
        super().__init__()
        self.trials, self.actions = [], []

    def begin_trial(self, context):
        self.trials.append(context.object)

    def execute(self, action):
        self.actions.append(action)
        return echoplan.ActionReport(action, "done", duration_s=1.5)


class LoggedClips:
    """A recorder with only the methods (no base class): it hands over the clips `echoplan run`
    saved, in order, as numpy arrays."""

    def __init__(self, folder, steps):
        self.clips = [folder / s["clip"] for s in steps if s["clip"]]
        self.started = []

    def start(self, action):
        self.started.append(action)

    def stop(self):
        samples, rate = soundfile.read(str(self.clips[len(self.started) - 1]), dtype="float32",
                                       always_2d=True)
        return samples, rate


def test_a_python_robot_drives_the_trial_echoplan_run_drove(command_run):
    root, steps = command_run
    model = echoplan.load_observation_model(str(root / "model.json"))
    problem = echoplan.calibrate_problem(echoplan.load_problem(REPORT_PROBLEM), model)
    arm, recorder = ArmStandIn(), LoggedClips(root / "run", steps)
    loop = echoplan.Loop(problem, robot=arm, recorder=recorder,
                         service=echoplan.ClassifierService(model), episodes=300)
    seen = []
    trial = loop.run("coffee_mug", seed=echoplan.stream_seed(3, "run_trial"), on_step=seen.append)
    names = problem.model.action_names
    assert [names[s.action] for s in trial.steps] == [s["action"] for s in steps]
    assert arm.actions == [s["action"] for s in steps] and arm.trials == ["coffee_mug"]
    assert len(seen) == len(trial.steps)
    for mine, logged in zip(trial.steps, steps):
        assert problem.model.observation_names[mine.observation.index] == logged["observation"]
        assert mine.reward == logged["reward"]
        before = [logged["belief_before"][o] for o in problem.model.objects]
        np.testing.assert_array_equal(mine.record.belief, before)
        if "heard" in logged:  # a sensing step: the same clip heard the same way
            assert mine.robot.heard.label == logged["heard"]["label"]
            assert mine.robot.heard.probability == logged["heard"]["probability"]
            assert dict(mine.robot.heard.probabilities) == logged["heard"]["probabilities"]
            assert mine.robot.report.duration_s == 1.5
    assert trial.steps[-1].terminal


class TableService(echoplan.ObservationService):
    """A service that hears whatever the problem's table says (no sound at all)."""

    def __init__(self, problem, rng):
        super().__init__()
        self.problem, self.rng, self.object = problem, rng, None

    def vocabulary(self):
        sensing = [a for a in self.problem.model.action_names if not a.startswith("move_to")]
        return {a: list(self.problem.model.objects) for a in sensing}

    def observe(self, clip, action):
        assert clip.samples.shape == (441, 1)
        return self.problem.model.objects[self.object]


class SilentRecorder(echoplan.Recorder):
    def start(self, action):
        pass

    def stop(self):
        return np.zeros(441, dtype=np.float32)


class NamedRobot:
    """Only the methods (no base class), and a strike that hits the table."""

    def __init__(self, service):
        self.service = service

    def begin_trial(self, context):
        self.service.object = ["pringles_can", "coffee_mug", "plastic_cup", "paper_base"].index(
            context.object)

    def execute(self, action):
        return "collision" if action == "strike" else None


def test_a_collision_reported_by_a_python_robot_ends_the_trial(report_problem):
    service = TableService(report_problem, None)
    loop = echoplan.Loop(report_problem, robot=NamedRobot(service), recorder=SilentRecorder(),
                         service=service, solver="all_actions")
    trial = loop.run("plastic_cup")
    names = report_problem.model.action_names
    assert [names[s.action] for s in trial.steps] == ["slide", "strike"]
    assert trial.record.collision and trial.steps[-1].reward == -100
    assert trial.steps[-1].robot.report.status == "collision"


class FaultyArm(echoplan.Robot):
    def begin_trial(self, context):
        pass

    def execute(self, action):
        raise RuntimeError("arm fault: joint 3 over current")


def test_an_exception_in_a_python_robot_reaches_the_caller(report_problem):
    service = TableService(report_problem, None)
    loop = echoplan.Loop(report_problem, robot=FaultyArm(), recorder=SilentRecorder(),
                         service=service, episodes=50)
    with pytest.raises(RuntimeError, match="joint 3"):
        loop.run("coffee_mug")


def test_a_service_that_cannot_hear_the_problems_symbols_is_refused_before_any_trial(report_problem):
    class Deaf(TableService):
        def vocabulary(self):
            return {"slide": ["a", "b"], "strike": ["a", "b"]}

    with pytest.raises(echoplan.InputError):
        echoplan.Loop(report_problem, robot=ArmStandIn(), recorder=SilentRecorder(),
                      service=Deaf(report_problem, None), episodes=50)
    with pytest.raises(TypeError, match="execute"):
        echoplan.Loop(report_problem, robot=object(), recorder=SilentRecorder(),
                      service=Deaf(report_problem, None))
