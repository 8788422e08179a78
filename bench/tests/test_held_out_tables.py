"""bench/held_out_tables.py's parts on hand-made inputs: the campaign it writes for a held-out table
(read back as YAML) and the paired interval (against Student's t table values)."""
import yaml

from bench_script import load

held_out_tables = load("held_out_tables")


def test_a_campaign_trains_on_every_table_but_the_one_its_trials_stand_on():
    c = yaml.safe_load(held_out_tables.config("glass_top", "by_performance", 3, 100, 7))
    assert c["seed"] == 7
    assert c["world"]["surface"] == "glass_top"
    assert c["training_set"]["surfaces"] == ["lab_laminate", "oak_top", "rubber_mat", "steel_bench"]
    (arm,) = c["arms"]
    assert arm["name"] == "by_performance" and arm["trained_on_surfaces"] is True
    assert arm["observations"] == "graded" and arm["calibrate"] is True
    assert [g["trials"] for g in c["trials"]] == [3, 3, 3, 3]
    assert c["planner"]["episodes"] == 100
    given = yaml.safe_load(held_out_tables.config("steel_bench", "by_table", 1, 100, 7, "m.json"))
    assert given["training_set"] == {"model": "m.json"}
    assert "trained_on_surfaces" not in given["arms"][0]


def test_the_random_tables_arm_trains_on_as_many_drawn_tables_as_recordings_per_pair():
    c = yaml.safe_load(held_out_tables.config("rubber_mat", "random_tables", 2, 100, 7,
                                              random_tables=40))
    assert c["world"]["surface"] == "rubber_mat"
    assert c["training_set"] == {"recordings_per_pair": 40, "surfaces": ["random:40"]}
    assert c["arms"][0]["trained_on_surfaces"] is True


def test_pairs_by_trial_and_gives_students_interval():
    # Differences 1, 2, 3 (trial "9" has no partner): mean 2, sd 1, t(0.975, 2) = 4.303.
    a = {"0": 5.0, "1": 6.0, "2": 7.0, "9": 100.0}
    b = {"0": 4.0, "1": 4.0, "2": 4.0}
    mean, half, n = held_out_tables.paired(a, b)
    assert n == 3
    assert abs(mean - 2.0) < 1e-12
    assert abs(half - 4.303 / 3 ** 0.5) < 1e-3
