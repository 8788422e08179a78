"""Features and observation models against `echoplan features`, `echoplan train` and `echoplan
classify` on the same data."""
import csv
import json
from pathlib import Path

import numpy as np
import pytest
import soundfile

import echoplan
from conftest import FEATURE_SET, echoplan_command


@pytest.fixture(scope="module")
def strike(tmp_path_factory):
    path = tmp_path_factory.mktemp("clip") / "mug.wav"
    echoplan_command("synth", "--object", "coffee_mug", "--action", "strike", "--seed", 7, "-o", path)
    return path


@pytest.mark.parametrize("preset", ["psf", "librosa"])
@pytest.mark.parametrize("feature", ["mfcc", "logmel", "centroid", "zcr"])
def test_features_of_a_numpy_clip_are_the_commands(strike, preset, feature):
    samples, rate = soundfile.read(str(strike), dtype="float32", always_2d=True)
    mine = echoplan.features(samples, sample_rate=rate, preset=preset)[feature]
    text = echoplan_command("features", "--preset", preset, "--feature", feature, strike).stdout
    command = np.array([[float(x) for x in line.split(",")] for line in text.splitlines()],
                       dtype=np.float32)
    assert mine.dtype == np.float32 and mine.shape == command.shape
    np.testing.assert_array_equal(mine, command)


def read_feature_set(root):
    """The shipped feature set read with Python's csv module into numpy arrays."""
    arrays = {}
    for action_dir in sorted(Path(root).iterdir()):
        if not action_dir.is_dir():
            continue
        action = {"modalities": {}, "feature_names": {}}
        for file in sorted(action_dir.glob("*.csv")):
            rows = list(csv.reader(open(file)))
            action["objects"] = [r[0] for r in rows[1:]]
            action["sessions"] = [r[1] for r in rows[1:]]
            action["modalities"][file.stem] = np.array([[float(x) for x in r[2:]] for r in rows[1:]])
            action["feature_names"][file.stem] = rows[0][2:]
        arrays[action_dir.name] = action
    return arrays


def test_a_model_fitted_on_numpy_arrays_is_the_commands(tmp_path):
    command_model = tmp_path / "command.json"
    echoplan_command("train", "--data", FEATURE_SET, "--out", command_model)
    feature_set = echoplan.FeatureSet.from_arrays(read_feature_set(FEATURE_SET))
    assert feature_set.actions == ["press", "shake", "squeeze", "tap"]
    model = echoplan.fit_observation_model(feature_set)
    model.save(str(tmp_path / "mine.json"))
    assert json.load(open(tmp_path / "mine.json")) == json.load(open(command_model))
    # The same model classifies a feature row as the loaded one does.
    loaded = echoplan.load_observation_model(str(command_model))
    rows = {m: feature_set.rows("tap", m)[5] for m in feature_set.modalities("tap")}
    assert model.classify_rows("tap", rows).label == loaded.classify_rows("tap", rows).label
    np.testing.assert_array_equal(model.classify_rows("tap", rows).probabilities,
                                  loaded.classify_rows("tap", rows).probabilities)


def test_a_graded_model_hears_a_class_and_its_grade():
    model = echoplan.fit_observation_model(echoplan.load_feature_set(FEATURE_SET))
    assert model.graded
    grades = ["low", "mid", "high"]
    assert model.graded_symbols == [f"{c}@{g}" for c in model.classes for g in grades]
    for action in model.actions:
        graded = model.table(action, graded=True)
        assert graded.shape == (len(model.classes), 3 * len(model.classes))
        np.testing.assert_allclose(graded.sum(axis=1), 1.0, atol=1e-9)
    feature_set = echoplan.load_feature_set(FEATURE_SET)
    rows = {m: feature_set.rows("tap", m)[5] for m in feature_set.modalities("tap")}
    heard = model.classify_rows("tap", rows)
    assert heard.grade in (0, 1, 2)


def test_the_problem_of_a_feature_set_is_the_commands(tmp_path):
    groups = str(Path(FEATURE_SET) / "groups.csv")
    echoplan_command("train", "--data", FEATURE_SET, "--groups", groups, "--problem-out",
                     tmp_path / "command.yaml")
    feature_set = echoplan.load_feature_set(FEATURE_SET)
    model = echoplan.fit_observation_model(feature_set, groups=groups)
    problem = echoplan.dataset_problem(feature_set, model, groups=groups)
    command = echoplan.load_problem(str(tmp_path / "command.yaml"))
    for key, value in command.model.tables().items():
        np.testing.assert_array_equal(problem.model.tables()[key], value)


def test_lookalikes_are_a_copy_of_each_class_heard_through_its_rows():
    groups = str(Path(FEATURE_SET) / "groups.csv")
    feature_set = echoplan.load_feature_set(FEATURE_SET)
    model = echoplan.fit_observation_model(feature_set, groups=groups, hold_out="object")
    share = model.lookalike_share()
    assert 0.0 <= share <= 0.5 and 0.0 <= model.lookalike_share(graded=True) <= 0.5
    plain = echoplan.dataset_problem(feature_set, model, groups=groups, hold_out="object")
    problem = echoplan.dataset_problem(feature_set, model, groups=groups, hold_out="object",
                                       lookalike=True)
    classes = plain.model.objects
    k = len(classes)
    assert problem.model.objects == classes + [f"{c}~lookalike" for c in classes]
    tables = problem.model.tables()
    np.testing.assert_allclose(tables["initial_belief"][k:2 * k], share / k)
    np.testing.assert_allclose(tables["initial_belief"][:k], (1.0 - share) / k)
    np.testing.assert_array_equal(tables["observation"][:, k:2 * k, :],
                                  tables["observation"][:, :k, :])
    # The classes' rows are the plain problem's unless the share was fitted on untempered tables.
    untempered = model.lookalikes_untempered()
    assert isinstance(untempered, bool)
    if not untempered or share == 0.0:
        np.testing.assert_array_equal(tables["observation"][:, :k, :],
                                      plain.model.tables()["observation"][:, :k, :])


def test_bad_arrays_raise_input_error_naming_action_modality_and_row():
    arrays = read_feature_set(FEATURE_SET)
    arrays["tap"]["modalities"]["haptic"][4, 1] = np.nan
    with pytest.raises(echoplan.InputError) as raised:
        echoplan.FeatureSet.from_arrays(arrays)
    assert raised.value.file == "arrays[tap][haptic]" and raised.value.line == 5


def test_a_bad_feature_file_raises_the_commands_error(tmp_path):
    bad = tmp_path / "set" / "tap"
    bad.mkdir(parents=True)
    (bad / "audio.csv").write_text("object,session,f0\nmug,s1,1.0\nmug,s2,oops\n")
    with pytest.raises(echoplan.InputError) as raised:
        echoplan.load_feature_set(str(tmp_path / "set"))
    assert raised.value.file == str(bad / "audio.csv") and raised.value.line == 3
    done = echoplan_command("train", "--data", tmp_path / "set", "--problem-out",
                            tmp_path / "p.yaml", check=False)
    assert done.returncode == 2 and str(raised.value) in done.stderr


def test_classify_a_clip_as_the_command_does(tmp_path, strike):
    recordings = tmp_path / "recordings"
    echoplan_command("synth-recordings", "--per-pair", 3, "--seed", 2, "-o", recordings)
    echoplan_command("train", "--data", recordings, "--out", tmp_path / "model.json")
    mine = echoplan.fit_observation_model(str(recordings))
    mine.save(str(tmp_path / "mine.json"))
    assert json.load(open(tmp_path / "mine.json")) == json.load(open(tmp_path / "model.json"))
    command = json.loads(echoplan_command("classify", "--model", tmp_path / "model.json",
                                          "--action", "strike", "--json", strike).stdout)
    samples, rate = soundfile.read(str(strike), dtype="float32", always_2d=True)
    heard = mine.classify(samples, "strike", sample_rate=rate)
    assert heard.label == command["class"]
    assert heard.distance == command["distance"]
    assert dict(zip(mine.classes, heard.probabilities)) == command["probabilities"]


def test_a_feature_set_model_has_no_level_grades():
    # A feature set's rows carry no measured level: the model says so instead of inventing one.
    model = echoplan.fit_observation_model(echoplan.load_feature_set(FEATURE_SET))
    assert not model.levelled
    with pytest.raises(echoplan.InputError, match="no observations graded by level"):
        model.level_symbols
    feature_set = echoplan.load_feature_set(FEATURE_SET)
    rows = {m: feature_set.rows("tap", m)[5] for m in feature_set.modalities("tap")}
    assert model.classify_rows("tap", rows).level_grade == -1
