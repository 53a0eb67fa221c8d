"""The window's presets by name in Python: run(preset=NAME, lane=K) gives the numbers of
`polyroll run --preset NAME --lane K`; keywords change the lane; window_presets() lists them with
their lanes; a bad name or lane raises ValueError naming the argument and what is allowed, a wrong
type TypeError."""
import pytest

import polyroll
from conftest import read_summary, without_wall_time


def test_a_race_lane_gives_the_numbers_of_the_command(cli, tmp_path):
    cli("run", "--preset", "race", "--lane", "2", "--time-limit", "0.3", "--out", tmp_path / "cli")
    r = polyroll.run(preset="race", lane=2, time_limit=0.3)
    assert without_wall_time(r.summary) == without_wall_time(read_summary(tmp_path / "cli"))


def test_a_preset_lane_is_its_scene_with_the_keywords_over_it():
    presets = polyroll.window_presets()
    race = next(p for p in presets if p["name"] == "race")
    assert len(race["lanes"]) == 3
    assert polyroll.scene(preset="race", lane=3) == race["lanes"][2]
    one = next(p for p in presets if p["name"] == "hexagon-large-rice")
    assert polyroll.scene(preset="hexagon-large-rice") == one["lanes"][0]
    assert polyroll.scene(preset="hexagon-large-rice", lane=1) == one["lanes"][0]
    changed = polyroll.scene(preset="race", lane=1, angle=12, fields={"ramp.length_m": 1.5})
    assert changed["ramp"]["angle_deg"] == 12 and changed["ramp"]["length_m"] == 1.5
    assert changed["shell"] == race["lanes"][0]["shell"]
    sim = polyroll.Simulation(preset="race", lane=2, time_limit=0.1)
    assert sim.scene == polyroll.scene(preset="race", lane=2, time_limit=0.1)


@pytest.mark.parametrize("call", [polyroll.run, polyroll.scene, polyroll.Simulation])
def test_bad_names_and_lanes_raise_value_error_naming_the_argument(call):
    with pytest.raises(ValueError, match=r"^preset='rcae': unknown window preset \(allowed: default, .*race"):
        call(preset="rcae")
    with pytest.raises(ValueError, match=r"^lane=4: the preset race has 3 lanes \(allowed: 1 to 3\)"):
        call(preset="race", lane=4)
    with pytest.raises(ValueError, match=r"^lane=0: "):
        call(preset="race", lane=0)
    with pytest.raises(ValueError, match=r"^lane=10000000000000000000000: "):
        call(preset="race", lane=10**22)
    with pytest.raises(ValueError, match=r"^preset='race': a race of 3 lanes.*lane=1 to 3"):
        call(preset="race")


@pytest.mark.parametrize("kwargs, words", [
    (dict(preset=3), "preset=3: an int where a window preset's name"),
    (dict(preset="race", lane="2"), "lane='2': a str where a whole number"),
    (dict(preset="race", lane=2.0), "lane=2.0: a float where a whole number"),
    (dict(preset="race", lane=True), "lane=True: a bool"),
    (dict(lane=2), "lane=2 without preset="),
])
def test_wrong_types_raise_type_error(kwargs, words):
    with pytest.raises(TypeError, match=words.replace("(", r"\(").replace(")", r"\)")):
        polyroll.run(**kwargs)


def test_a_preset_and_a_scene_source_together_raise_type_error(tmp_path):
    with pytest.raises(TypeError, match="both a scene source"):
        polyroll.run({"ramp": {"angle_deg": 10}}, preset="race", lane=1)


def test_run_documents_the_preset_keywords():
    assert "preset=" in polyroll.run.__doc__ and "lane=" in polyroll.run.__doc__
    assert "window_presets" in polyroll.__all__
