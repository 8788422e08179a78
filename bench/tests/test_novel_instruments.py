"""bench/novel_instruments.py's parts on hand-made inputs: the family read off an instrument's name
and the campaign it writes (read back as YAML)."""
import yaml

from bench_script import load

novel_instruments = load("novel_instruments")


def test_families_from_the_kits_instrument_names():
    cases = {
        "Kick (Tama Superstar 22\")": "kick", "BassDrum": "kick", "Pearl Kick": "kick",
        "Snare Rimshot (Pearl Free Floating Maple 14x3.5)": "snare", "Pearl Side Stick": "snare",
        "Tom Low (Tama Superstar 16\")": "tom", "Floor Tom": "tom",
        "Hi-Hat Pedal (Paiste Alpha Metal edge 14\")": "hihat", "Closed HH": "hihat",
        "Ride Bell": "cymbal", "Crash/Ride (Paiste Rude Crash/Ride 18\")": "cymbal",
        "China (Paiste Alpha 18\")": "cymbal", "Zildjian Splash Choke": "cymbal",
        "Cajon Slap": "hand", "WaterglassHi": "hand", "Agogo Low (Pearl ECB-23)": "hand",
    }
    for name, family in cases.items():
        assert novel_instruments.family(name) == family, name
    # A name no family claims is left out: "Stick" alone, "Bottom" (no "tom" word).
    assert novel_instruments.family("Stick") is None
    assert novel_instruments.family("Bottom") is None


def test_the_campaign_holds_out_whole_instruments_sorted_by_family():
    c = yaml.safe_load(novel_instruments.campaign("/d", 300, 4))
    assert c["seed"] == 4
    assert c["world"] == {"type": "dataset", "data": "/d", "hold_out": "object",
                          "groups": "/d/groups.csv"}
    assert [a["name"] for a in c["arms"]] == ["plan", "plan_plain", "information_gain",
                                              "decision_region"]
    assert c["arms"][1]["lookalike"] is False and c["arms"][1]["unheard"] == "share"
    assert c["planner"]["episodes"] == 300
