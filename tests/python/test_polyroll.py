"""import polyroll: the same scene gives the same numbers as the command line; bad input raises
Python's errors (TypeError for an unknown keyword or a wrong type, ValueError with the command line's
line for a value out of range) naming the keyword as written; Ctrl-C stops a run, a 3D run and a
sweep; Simulation is deterministic as run(); sweep() resumes and gives the command's table."""
import csv
import inspect
import os
import pydoc
import signal
import threading
import time
import warnings

import numpy as np
import pytest

import polyroll
from conftest import read_summary, without_wall_time

# A short octagon run that rolls, hits faces and has grains: cheap (a second or two) but not trivial.
OCTAGON = dict(polygon="octagon-small", fill=0.375, material="bb", angle=14, time_limit=1.5)
OCTAGON_FLAGS = ["--polygon", "octagon-small", "--fill", "0.375", "--material", "bb", "--angle", "14",
                 "--time-limit", "1.5"]


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def assert_columns_match_csv(records, path):
    """The arrays hold the file's numbers (rounded there: angles to 4 decimals, others to 6 or to 9 digits)."""
    header, rows = read_csv(path)
    assert list(records.dtype.names) == header
    assert len(records) == len(rows)
    for k, name in enumerate(header):
        from_file = np.array([float(r[k]) if r[k] != "" else np.nan for r in rows])
        np.testing.assert_allclose(records[name], from_file, rtol=1e-8, atol=5e-5, equal_nan=True, err_msg=name)


@pytest.mark.parametrize("model", ["grains", "auto", "rigid", "dem3d"])
def test_same_numbers_as_the_command(model, cli, tmp_path):
    flags = OCTAGON_FLAGS + ["--model", model]
    fields = dict(OCTAGON, model=model)
    if model == "dem3d":  # a few hundredths of a simulated second: the comparison, not the physics
        fields["time_limit"] = 0.05
        flags[flags.index("--time-limit") + 1] = "0.05"
    cli("run", *flags, "--out", tmp_path / "cli")
    r = polyroll.run(**fields)
    r.save(tmp_path / "py")
    for name in ("trajectory.csv", "impacts.csv"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    assert without_wall_time(r.summary) == without_wall_time(read_summary(tmp_path / "cli"))
    assert_columns_match_csv(r.trajectory, tmp_path / "cli" / "trajectory.csv")
    assert_columns_match_csv(r.impacts, tmp_path / "cli" / "impacts.csv")
    assert len(r.trajectory) > (2 if model == "dem3d" else 10)
    if model == "grains":
        assert r.summary["results"]["grains"] > 0 and len(r.impacts) > 0


def test_scene_sources_layer_as_the_command(cli, tmp_path):
    scene_file = tmp_path / "scene.json"
    scene_file.write_text('{"shell": "octagon-small", "fill": {"ratio": 0.375}}\n')
    from_file = polyroll.scene(scene_file, angle=12, fields={"ramp.length_m": 1.5})
    from_dict = polyroll.scene({"shell": "octagon-small", "fill": {"ratio": 0.375}}, angle=12,
                               fields={"ramp.length_m": 1.5})
    assert from_file == from_dict
    assert from_file["shell"]["sides"] == 8 and from_file["ramp"]["angle_deg"] == 12
    assert from_file["ramp"]["length_m"] == 1.5
    # The resolved document is a scene itself: feeding it back changes nothing.
    assert polyroll.scene(from_file) == from_file
    assert polyroll.scene({"shell": {"sides": np.int64(8)}}, angle=np.float64(12.5))["ramp"]["angle_deg"] == 12.5


@pytest.mark.parametrize("keywords, flags, flag_words, keyword_words", [
    (dict(sides=99), ["--sides", "99"], "--sides", "sides=99"),
    (dict(angle=95.0), ["--angle", "95"], "--angle", "angle=95.0"),
    (dict(material="gravel"), ["--material", "gravel"], "--material", "material='gravel'"),
    (dict(fields={"fill.material.wall_friction": -1}), ["--set", "fill.material.wall_friction=-1"],
     "--set fill.material.wall_friction", 'fields["fill.material.wall_friction"]'),
    (dict(fields={"shell.nonsense": 1}), ["--set", "shell.nonsense=1"], "--set shell.nonsense",
     'fields["shell.nonsense"]'),
])
def test_bad_values_raise_the_commands_message_in_python_words(keywords, flags, flag_words, keyword_words, cli):
    p = cli("run", *flags, check=False)
    assert p.returncode == 2
    line = p.stderr.strip().splitlines()[0]
    assert line.startswith("polyroll: ") and flag_words in line
    with pytest.raises(ValueError) as e:
        polyroll.run(**keywords)
    # The command's line, naming the argument as the caller wrote it instead of the flag.
    assert str(e.value) == line[len("polyroll: "):].replace(flag_words, keyword_words)


@pytest.mark.parametrize("call", [polyroll.scene, polyroll.run, polyroll.Simulation,
                                  lambda **kw: polyroll.sweep("unused", **kw)])
def test_an_unknown_keyword_is_a_type_error_naming_it(call):
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'sidez'; did you mean 'sides'\?") as e:
        call(sidez=6)
    assert "--" not in str(e.value).split("(")[0]


def test_sweep_refuses_a_keyword_it_cannot_sweep():
    with pytest.raises(TypeError, match=r"sweep\(\) got an unexpected keyword argument 'step_hz'.*swept keywords: .*angle"):
        polyroll.sweep("unused", step_hz=[500, 1000])


@pytest.mark.parametrize("keywords, written", [
    (dict(angle="x"), "angle='x': a str where a number is expected"),
    (dict(angle=True), "angle=True: a bool where a number is expected"),
    (dict(sides="6"), "sides='6': a str where a whole number is expected"),
    (dict(polygon=3), "polygon=3: an int where a preset name (str) is expected"),
    (dict(fields={"ramp.length_m": "x"}), 'fields["ramp.length_m"] = \'x\': a str where a number is expected'),
    (dict(fields=[("ramp.length_m", 1.5)]), "fields= takes a dict"),
])
def test_a_wrong_type_is_a_type_error_naming_the_keyword(keywords, written):
    for call in (polyroll.scene, polyroll.run):
        with pytest.raises(TypeError) as e:
            call(**keywords)
        assert written in str(e.value) and "--" not in str(e.value)


def test_a_value_out_of_range_is_a_value_error_naming_the_keyword():
    with pytest.raises(ValueError) as e:
        polyroll.run(sides=2)
    assert str(e.value) == "shell.sides = 2 (from sides=2) is out of range (allowed: 3 to 64)"
    with pytest.raises(ValueError, match=r"\(from sides=6\.5\) must be a whole number"):
        polyroll.run(sides=6.5)


def test_none_is_the_scenes_null_refused_where_a_field_has_none():
    # None is refused where a field takes no null: it never silently keeps the default.
    with pytest.raises(TypeError, match=r"fill=None: None where a number is expected .*leave the argument out"):
        polyroll.run(fill=None)
    with pytest.raises(TypeError, match=r'fields\["shell.sides"\] = None'):
        polyroll.scene(fields={"shell.sides": None})
    # An optional field's None is its documented null (the 3D box held in its plane).
    wide = polyroll.scene(channel_width=0.2)
    assert wide["dem3d"]["channel_width_m"] == 0.2
    assert polyroll.scene(wide, channel_width=None)["dem3d"]["channel_width_m"] is None
    assert polyroll.scene(wide, fields={"dem3d.channel_width_m": None})["dem3d"]["channel_width_m"] is None


def test_set_is_the_deprecated_name_of_fields():
    new = polyroll.scene(fields={"ramp.length_m": 1.5})
    with pytest.warns(DeprecationWarning, match=r"scene\(set=...\) is deprecated.*use fields=") as w:
        old = polyroll.scene(set={"ramp.length_m": 1.5})
    assert old == new and w[0].filename == __file__  # the warning points at the caller's line
    with pytest.warns(DeprecationWarning), pytest.raises(ValueError, match=r'from set\["ramp.length_m"\]'):
        polyroll.run(set={"ramp.length_m": -1})
    with pytest.warns(DeprecationWarning), pytest.raises(TypeError, match="both fields= and set="):
        polyroll.Simulation(fields={"ramp.length_m": 1.5}, set={"ramp.length_m": 1.5})
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # fields= itself warns of nothing
        polyroll.scene(fields={"ramp.length_m": 1.5})
    for call in (polyroll.scene, polyroll.run, polyroll.Simulation, polyroll.sweep):
        assert "set" not in inspect.signature(call).parameters  # no builtin shadowed


def public_members():
    """Every public name of the package and of its public classes, as (qualified name, object)."""
    for name in polyroll.__all__:
        obj = getattr(polyroll, name)
        yield name, obj
        if inspect.isclass(obj):
            for member, value in vars(obj).items():
                if not member.startswith("_") or member == "__init__":
                    yield f"{name}.{member}", value


def test_every_public_name_has_a_docstring_that_help_shows():
    assert polyroll.__doc__ and "TypeError" in polyroll.__doc__ and "fields=" in polyroll.__doc__
    shown = pydoc.render_doc(polyroll, renderer=pydoc.plaintext)
    for name, obj in public_members():
        if isinstance(obj, str):  # version: a value, described in the module's docstring
            assert name in polyroll.__doc__, name
            continue
        doc = inspect.getdoc(obj)
        assert doc and doc.strip(), f"{name} has no docstring"
        assert doc.splitlines()[0] in shown, f"help(polyroll) does not show {name}'s docstring"


def test_bad_python_arguments_raise():
    with pytest.raises(TypeError, match="an int is not a scene"):
        polyroll.scene(42)
    with pytest.raises(TypeError, match="an object is not a scene value"):
        polyroll.scene({"ramp": {"angle_deg": object()}})
    with pytest.raises(ValueError, match=r"step\(n=0\)"):
        polyroll.Simulation(fill=0.0, time_limit=0.1).step(0)
    with pytest.raises(ValueError, match="jobs=0"):
        polyroll.sweep("unused", jobs=0)
    with pytest.raises(TypeError, match="angle=<object.*an object where a grid value is expected"):
        polyroll.sweep("unused", angle=object())


def test_save_refuses_a_folder_with_files(tmp_path):
    r = polyroll.run(fill=0.0, time_limit=0.2)
    (tmp_path / "x").mkdir()
    (tmp_path / "x" / "keep.txt").write_text("mine\n")
    with pytest.raises(ValueError, match="force=True"):
        r.save(tmp_path / "x")
    assert os.listdir(tmp_path / "x") == ["keep.txt"]
    r.save(tmp_path / "x", force=True)
    assert (tmp_path / "x" / "summary.json").exists()


def test_simulation_is_deterministic_as_run():
    whole = polyroll.run(**OCTAGON)
    sim = polyroll.Simulation(**OCTAGON)
    assert sim.grain_count == whole.summary["results"]["grains"]
    grains = sim.grains()
    assert len(grains) == sim.grain_count and np.all(grains.radius_m > 0)
    seen_speed = []
    while sim.step(37):  # an odd chunk: stepping in chunks must not change the run
        seen_speed.append(sim.shell()["speed_m_s"])
        e = sim.energies()
        assert np.isfinite([e["kinetic_J"], e["potential_J"], e["dissipated_J"]]).all()
    assert sim.finished and sim.behaviour == whole.behaviour
    stepped = sim.result()
    assert without_wall_time(stepped.summary) == without_wall_time(whole.summary)
    np.testing.assert_array_equal(stepped.trajectory.speed_m_s, whole.trajectory.speed_m_s)
    assert max(seen_speed) > 0.05  # it rolled


def interrupted(call, after_s):
    """Calls call() with a SIGINT (a Ctrl-C) sent to this process after `after_s` from another thread;
    whether call() raised KeyboardInterrupt. The signal is called off if call() returns first."""
    timer = threading.Timer(after_s, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        call()
    except KeyboardInterrupt:
        return True
    finally:
        timer.cancel()
        timer.join()
    return False


# Minutes of work if nothing stopped it: the octagon rolling down a 100 m track.
LONG = dict(OCTAGON, angle=20, time_limit=60, fields={"ramp.length_m": 100})


def yade_children():
    """The 3D reference's processes this test process started (children running polyroll_dem3d.py)."""
    found = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open(f"/proc/{pid}/stat") as f:
                ppid = int(f.read().rsplit(")", 1)[1].split()[1])
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                cmd = f.read()
        except OSError:
            continue
        if ppid == os.getpid() and b"dem3d" in cmd:
            found.append(int(pid))
    return found


@pytest.mark.parametrize("model", ["grains", "dem3d"])
def test_ctrl_c_stops_a_run(model):
    start = time.monotonic()
    assert interrupted(lambda: polyroll.run(**dict(LONG, model=model)), 2.0)
    assert time.monotonic() - start < 15
    assert yade_children() == []


def test_ctrl_c_stops_the_grains_settling():
    # A full large hexagon (about 1,500 discs) given a minute to settle, at a rest speed it never
    # reaches: a stop not heard while it settles would let the call run for minutes.
    start = time.monotonic()
    assert interrupted(lambda: polyroll.Simulation(polygon="hexagon-large", fill=1.0, material="bb", model="grains",
                                                   fields={"run.settle_time_s": 60, "run.rest_speed_m_s": 1e-6}), 2.0)
    assert time.monotonic() - start < 15


def test_ctrl_c_stops_a_simulation_step():
    sim = polyroll.Simulation(**LONG)
    assert interrupted(lambda: sim.step(10 ** 9), 1.0)
    assert 0 < sim.time_s < 60 and not sim.finished
    sim.step(10)  # it goes on from where it stopped


GRID = dict(polygon="octagon-small", fill=0.375, angle="10,14", time_limit=0.4)
GRID_FLAGS = ["--polygon", "octagon-small", "--fill", "0.375", "--angle", "10,14", "--time-limit", "0.4"]


def table_without_wall_time(path):
    header, rows = read_csv(path)
    keep = [k for k, name in enumerate(header) if name != "wall_time_s"]
    return [header[k] for k in keep], [[r[k] for k in keep] for r in rows]


def test_sweep_gives_the_commands_table_and_resumes(cli, tmp_path):
    cli("sweep", *GRID_FLAGS, "--seeds", "2", "--out", tmp_path / "cli", "-q", "--jobs", "2")
    s = polyroll.sweep(tmp_path / "py", seeds=2, jobs=2, **GRID)
    assert s.report["ran"] == 4 and s.report["failed"] == 0
    assert table_without_wall_time(tmp_path / "py" / "results.csv") == \
        table_without_wall_time(tmp_path / "cli" / "results.csv")
    assert list(s.table.angle_deg) == [10, 10, 14, 14] and list(s.table.seed) == [1, 2, 1, 2]
    assert s.table.behaviour.dtype.kind == "U" and np.all(np.isfinite(s.table.distance_m))
    again = polyroll.sweep(tmp_path / "py", seeds=2, jobs=2, **GRID)
    assert again.report["ran"] == 0 and again.report["already"] == 4
    # More values for the same axis extend the sweep: only the new point runs.
    wider = polyroll.sweep(tmp_path / "py", seeds=2, jobs=2, **dict(GRID, angle=[10, 12, 14]))
    assert wider.report["ran"] == 2 and len(wider.table) == 6


def test_sweep_refuses_what_the_command_refuses(tmp_path):
    with pytest.raises(ValueError, match="fill"):
        polyroll.sweep(tmp_path / "bad", fill=25)
    assert not (tmp_path / "bad").exists()
    with pytest.raises(ValueError, match="--angle"):
        polyroll.sweep(tmp_path / "bad", angle="5:1:1")
    polyroll.sweep(tmp_path / "one", angle=12, time_limit=0.2, fill=0.0)
    with pytest.raises(ValueError, match="holds a different sweep"):
        polyroll.sweep(tmp_path / "one", sides=5, time_limit=0.2, fill=0.0)


def test_ctrl_c_stops_a_sweep_and_the_same_call_resumes(tmp_path):
    # Six runs two at a time, each pouring and settling its grains before it rolls: far more than
    # the half second after which the Ctrl-C comes, so it stops the sweep after the runs in flight.
    grid = dict(polygon="octagon-small", fill=0.375, angle="11:16:1", time_limit=4)
    assert interrupted(lambda: polyroll.sweep(tmp_path / "s", jobs=2, **grid), 0.5)
    done = polyroll.sweep(tmp_path / "s", jobs=2, **grid)
    assert done.report["already"] < 6 and done.report["ran"] > 0
    assert done.report["already"] + done.report["ran"] == 6 and len(done.table) == 6


def test_pandas_frames_where_pandas_is_installed(tmp_path):
    pandas = pytest.importorskip("pandas")
    r = polyroll.run(fill=0.0, time_limit=0.3, angle=20)
    frame = r.to_pandas()
    assert isinstance(frame, pandas.DataFrame) and list(frame.columns) == list(r.trajectory.dtype.names)
    np.testing.assert_array_equal(frame["speed_m_s"].to_numpy(), r.trajectory.speed_m_s)
    assert len(r.to_pandas("impacts")) == len(r.impacts)
    with pytest.raises(ValueError, match="allowed: 'trajectory' or 'impacts'"):
        r.to_pandas("grains")
    s = polyroll.sweep(tmp_path / "s", fill=0.0, angle="10,20", time_limit=0.3, jobs=1)
    table = s.to_pandas()
    assert list(table["angle_deg"]) == [10, 20] and list(table.columns) == list(s.table.dtype.names)
