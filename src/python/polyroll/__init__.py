"""polyroll: hollow regular polygons, partly filled with grains, rolling down an incline.

The same simulation core as the ``polyroll`` command, in Python::

    import polyroll
    r = polyroll.run(sides=8, fill=0.375, material="bb", angle=14)
    r.summary["results"]["distance_m"]      # summary.json, as a dict
    r.trajectory["speed_m_s"]               # numpy arrays, trajectory.csv's columns
    r.to_pandas()                           # a DataFrame, where pandas is installed

Scenes take the command line's words: a scene file's path or a scene dict first, then keywords
named as its scene flags (``sides=8`` for ``--sides 8``, ``vertex_radius=`` for
``--vertex-radius``; ``scene_keywords()`` lists them), then ``fields={"FIELD": VALUE}`` for any
field, as ``--set FIELD=VALUE``. (``fields=`` was called ``set=``, which still works with a
DeprecationWarning.)

A preset of the window (``polyroll-sandbox --preset NAME``) runs by name: ``run(preset="race",
lane=2)`` runs lane 2 of the race; ``window_presets()`` lists them with their lanes.

Errors are Python's: an unknown keyword or a value of the wrong type (``angle="x"``) raises
TypeError, a value out of range (``sides=2``) raises ValueError with the command line's message;
both name the keyword as written. None is a scene's null, the value of an optional field
(``channel_width=None``: the 3D box held in its plane) and refused by the others: leave a keyword
out to keep the scene's value.

``version`` is the version line, as ``polyroll --version`` prints it.
"""

import csv
import difflib
import functools
import numbers
import os
import warnings
from collections.abc import Mapping

import numpy as np

from . import _polyroll

__all__ = ["scene", "run", "sweep", "Simulation", "Result", "SweepResult", "scene_keywords", "window_presets",
           "version"]

version = _polyroll.version


def scene_keywords():
    """Every scene keyword: a list of dicts with its keyword, scene field, command-line flag, type
    ("integer", "number", "optional_number", "seed", "preset" or "choice"), whether sweep() sweeps
    it ("swept") and help."""
    return _polyroll.scene_keywords()


@functools.lru_cache(maxsize=None)
def _keyword_rows():
    return {row["keyword"]: row for row in _polyroll.scene_keywords()}


@functools.lru_cache(maxsize=None)
def _field_types():
    return _polyroll.field_types()


# What each type of field takes, for TypeError's message.
_TAKES = {"integer": "a whole number", "number": "a number", "optional_number": "a number or None",
          "seed": "a whole number", "preset": "a preset name (str)", "choice": "a name (str)"}


def _a_type_name(value):
    """"an int", "a str": the value's type with its article, for messages."""
    name = type(value).__name__
    return ("an " if name[:1].lower() in "aeiou" else "a ") + name


def _check_type(written, value, kind):
    """TypeError unless `value` is of the Python type a field of type `kind` takes; `written` is the
    argument as the caller wrote it ("angle='x'"). Its range is the core's (ValueError)."""
    if value is None:
        if kind != "optional_number":
            raise TypeError(f"{written}: None where {_TAKES[kind]} is expected (None is only for optional fields; "
                            "leave the argument out to keep the scene's value)")
        return
    if kind in ("preset", "choice"):
        ok = isinstance(value, str)
    else:  # numbers, numpy's scalars included (they register as numbers.Real); bool is not one here
        ok = isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_))
    if not ok:
        raise TypeError(f"{written}: {_a_type_name(value)} where {_TAKES[kind]} is expected")


def _unexpected(caller, name, allowed, what):
    """Python's own TypeError for an unknown keyword, with the nearest allowed one."""
    close = difflib.get_close_matches(name, allowed, n=1)
    hint = f"; did you mean '{close[0]}'?" if close else ""
    return TypeError(f"{caller}() got an unexpected keyword argument '{name}'{hint} ({what}; any scene field: "
                     "fields={'FIELD': VALUE})")


def _check_keywords(caller, keywords, swept=False):
    """TypeError for a keyword that is no scene keyword (sweep: no swept one) or a value of the wrong type."""
    rows = _keyword_rows()
    allowed = [k for k, row in rows.items() if row["swept"] or not swept]
    for name, value in keywords.items():
        if name not in allowed:
            raise _unexpected(caller, name, allowed,
                              "the swept keywords: " + ", ".join(allowed) if swept
                              else "the scene keywords: polyroll.scene_keywords()")
        if not swept:
            _check_type(f"{name}={value!r}", value, rows[name]["type"])


def _fields_argument(caller, fields, keywords, stacklevel=3):
    """fields= as a dict, or the deprecated set= (taken out of `keywords`), and the name the caller used."""
    name = "fields"
    if "set" in keywords:
        warnings.warn(f"{caller}(set=...) is deprecated (set shadows the builtin): use fields=", DeprecationWarning,
                      stacklevel=stacklevel)
        if fields is not None:
            raise TypeError(f"{caller}() got both fields= and set= (set= is the old name of fields=)")
        fields, name = keywords.pop("set"), "set"
    if fields is None:
        return {}, name
    if not isinstance(fields, Mapping):
        raise TypeError(f"{caller}(): {name}= takes a dict of scene fields to values, not {_a_type_name(fields)}")
    return dict(fields), name


def _check_preset(caller, source, preset, lane):
    """TypeError for a preset= or lane= of the wrong type, for lane= without preset=, or for both a
    preset and a scene source; the names and the lane's range are the core's (ValueError)."""
    if preset is None:
        if lane is not None:
            raise TypeError(f"{caller}(): lane={lane!r} without preset= (lane= picks a lane of a window preset)")
        return
    if not isinstance(preset, str):
        raise TypeError(f"{caller}(): preset={preset!r}: {_a_type_name(preset)} where a window preset's name (str) is "
                        "expected (polyroll.window_presets() lists them)")
    if lane is not None and (not isinstance(lane, numbers.Integral) or isinstance(lane, (bool, np.bool_))):
        raise TypeError(f"{caller}(): lane={lane!r}: {_a_type_name(lane)} where a whole number (the lane, from 1) "
                        "is expected")
    if source is not None:
        raise TypeError(f"{caller}() got both a scene source ({source!r}) and preset={preset!r} (allowed: one of "
                        "them; keywords and fields= change the preset's lane)")


def _resolve(caller, source, fields_and_name, keywords, preset=None, lane=None):
    """The resolved scene document of a public call's scene arguments (fields from _fields_argument)."""
    fields, name = fields_and_name
    _check_preset(caller, source, preset, lane)
    _check_keywords(caller, keywords)
    types = _field_types()
    for path, value in fields.items():
        if isinstance(path, str) and path in types:  # an unknown path is the core's ValueError
            _check_type(f'{name}["{path}"] = {value!r}', value, types[path])
    return _polyroll.resolve(source, keywords, fields, name, preset,
                             None if lane is None else int(lane))


def window_presets():
    """The window's presets (``polyroll-sandbox --preset NAME``; ``polyroll presets`` lists them too):
    a list of dicts with "name", "description" and "lanes" (each lane's resolved scene document, as
    scene() gives it). A preset of several lanes is a race: run(preset=NAME, lane=K) runs one lane,
    ``polyroll render --preset NAME`` draws them all side by side."""
    return _polyroll.window_presets()


def scene(source=None, *, fields=None, preset=None, lane=None, **keywords):
    """The resolved scene document (a dict, as summary.json's "scene"): the defaults, then `source`
    (a scene file's path or a scene dict) or a window preset's lane (``preset="race", lane=2``), then
    the scene keywords (``angle=14``), then `fields` (``{"ramp.length_m": 1.5}``, any field)."""
    return _resolve("scene", source, _fields_argument("scene", fields, keywords), keywords, preset, lane)


def _records(columns):
    """Columns of equal length as a numpy record array (r["speed_m_s"], r.speed_m_s)."""
    names = list(columns)
    return np.rec.fromarrays([np.asarray(columns[n]) for n in names], names=names)


class Result:
    """One run's results: `summary` (summary.json as a dict), `trajectory` and `impacts` (numpy record
    arrays with trajectory.csv's and impacts.csv's columns; NaN where those files have a blank)."""

    def __init__(self, native):
        self._native = native
        self.summary = native.summary()
        # Built once in C++ as record arrays from the columns' one declaration; the view adds
        # attribute access (r.speed_m_s) without a copy.
        self.trajectory = native.trajectory_records().view(np.recarray)
        self.impacts = native.impact_records().view(np.recarray)

    @property
    def behaviour(self):
        """What the run did: summary["results"]["behaviour"] ("stopped", "rolled_off", ...)."""
        return self.summary["results"]["behaviour"]

    @property
    def distance_m(self):
        """The distance rolled, in metres: summary["results"]["distance_m"]."""
        return self.summary["results"]["distance_m"]

    def to_pandas(self, what="trajectory"):
        """The trajectory (or "impacts") as a pandas DataFrame; pandas is not one of polyroll's packages."""
        import pandas  # noqa: PLC0415 (optional: only this call needs it)
        if what not in ("trajectory", "impacts"):
            raise ValueError(f"to_pandas({what!r}): allowed: 'trajectory' or 'impacts'")
        return pandas.DataFrame(getattr(self, what))

    def save(self, folder, force=False):
        """Writes summary.json, trajectory.csv and impacts.csv into `folder`, as `polyroll run --out`."""
        self._native.save(os.fspath(folder), force)

    def __repr__(self):
        s = self.summary
        return (f"<polyroll.Result {s['results']['behaviour']}, {s['results']['distance_m']:.3f} m, "
                f"{len(self.trajectory)} samples, {len(self.impacts)} impacts>")


def run(source=None, *, fields=None, preset=None, lane=None, **keywords):
    """Runs a scene to its end, as `polyroll run` (the same numbers), and returns a Result. The scene
    as scene() takes it: `source`, the scene keywords, `fields`. Any model, `model="auto"` and
    `model="dem3d"` included. Releases the GIL; Ctrl-C raises KeyboardInterrupt.

    A preset of the window by name instead of `source`, as ``polyroll run --preset NAME --lane K``::

        polyroll.run(preset="hexagon-large-rice")           # a preset of one lane
        polyroll.run(preset="race", lane=2)                 # one lane of a race (lanes count from 1)
        polyroll.run(preset="race", lane=2, time_limit=3)   # keywords and fields= change the lane

    window_presets() lists the presets with their lanes. A name that is no preset, a lane out of range
    or a race without lane= raises ValueError naming the argument and what is allowed; a preset or
    lane of the wrong type raises TypeError."""
    return Result(_polyroll.run(_resolve("run", source, _fields_argument("run", fields, keywords), keywords,
                                         preset, lane)))


class Simulation:
    """A run to step and read, for notebooks and control loops; deterministic as `run`.

        sim = polyroll.Simulation(sides=6, fill=0.25, angle=21)
        while sim.step(100):
            print(sim.time_s, sim.shell()["speed_m_s"])
        result = sim.result()
    """

    def __init__(self, source=None, *, fields=None, preset=None, lane=None, **keywords):
        """Builds the run of a scene as scene() takes it (pouring and settling its grains, if any);
        ``preset="race", lane=2`` for a window preset's lane, as run() takes it."""
        self.scene = _resolve("Simulation", source, _fields_argument("Simulation", fields, keywords), keywords,
                              preset, lane)
        self._native = _polyroll.Simulation(self.scene)

    def step(self, n=1):
        """Up to n tracker steps (1 / fidelity.step_hz each); whether the run goes on."""
        if n < 1:
            raise ValueError(f"step(n={n}): allowed: n of 1 or more")
        return self._native.step(int(n))

    def run_to_end(self):
        """Steps to the end and returns the Result."""
        return Result(self._native.run_to_end())

    def result(self):
        """The Result as far as the run has gone (its behaviour "running" until it ends)."""
        return Result(self._native.result())

    def measured(self):
        """The summary so far (summary.json's document as a dict; its behaviour "running" until the end)."""
        return self._native.measured()

    time_s = property(lambda self: self._native.time_s, doc="Simulated time since release, in seconds.")
    steps = property(lambda self: self._native.steps, doc="Tracker steps since release.")
    step_s = property(lambda self: self._native.step_s, doc="One tracker step, in seconds (1 / fidelity.step_hz).")
    finished = property(lambda self: self._native.finished, doc="Whether the run has ended.")
    behaviour = property(lambda self: self._native.behaviour, doc="'running' until the run has ended, then its behaviour.")
    grain_count = property(lambda self: self._native.grain_count, doc="The number of grains (0 for a model without).")

    def shell(self):
        """The shell's pose (ramp frame: x down the slope, y along its normal) and the tracker's reading."""
        return self._native.shell()

    def grains(self):
        """Every grain's position, radius and speed as a numpy record array (empty without grains)."""
        return _records(self._native.grains())

    def energies(self):
        """Kinetic, potential (from release) and dissipated energy now, in joules."""
        return self._native.energies()


def _grid_text(name, values):
    """A grid axis in the command line's vocabulary: "5:20:1", "6,8", or a list/number made into it."""
    if isinstance(values, str):
        return values
    if isinstance(values, (list, tuple, np.ndarray)):
        if len(values) == 0:
            raise ValueError(f"{name}=[]: no values (allowed: a value, a list, or a text such as '5:20:1')")
        return ",".join(_grid_text(name, v) for v in values)
    if isinstance(values, (bool, np.bool_)) or not isinstance(values, numbers.Real):
        raise TypeError(f"{name}={values!r}: {_a_type_name(values)} where a grid value is expected (allowed: a "
                        "number, a name, a list or 'start:stop:step')")
    return repr(values.item() if isinstance(values, np.generic) else values)


def _read_table(path):
    """A results table as a numpy record array: numeric columns as floats (NaN for blanks), the others as text."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    columns = {}
    for k, name in enumerate(header):
        cells = [r[k] if k < len(r) else "" for r in body]
        try:
            columns[name] = np.array([float(c) if c != "" else np.nan for c in cells], dtype=float)
        except ValueError:
            columns[name] = np.array(cells, dtype=str)
    return _records(columns) if header else np.rec.array([])


class SweepResult:
    """A sweep's results table (`table`: a record array of results.csv), its folder and its report."""

    def __init__(self, report):
        self.report = report
        self.folder = os.path.dirname(report["table"])
        self.table = _read_table(report["table"])

    def to_pandas(self):
        """The results table as a pandas DataFrame; pandas is not one of polyroll's packages."""
        import pandas  # noqa: PLC0415 (optional: only this call needs it)
        return pandas.read_csv(self.report["table"])

    def __repr__(self):
        r = self.report
        return f"<polyroll.SweepResult {len(self.table)} rows in {r['table']}, {r['failed']} failed this session>"


def sweep(out, source=None, *, fields=None, seed=None, seeds=0, jobs=None, trajectories=False, retry_failed=False,
          large=False, quiet=True, **axes):
    """Runs a grid of scenes in parallel into the folder `out`, as `polyroll sweep --out`, and returns
    the results table (a SweepResult). Axes in the command line's grid vocabulary: ``angle="5:20:1"``,
    ``sides=[6, 8]``, ``material="bb,rice"``; ``fields={"shell.depth_m": [0.05, 0.062]}`` for any
    field; ``seeds=3`` or ``seed=[1, 5, 9]``. `source` is the base scene (a path or a dict); `jobs`
    runs at a time (all cores by default). The same call resumes an interrupted sweep and extends
    one with more values; Ctrl-C stops after the runs in flight."""
    fields, _ = _fields_argument("sweep", fields, axes)
    _check_keywords("sweep", axes, swept=True)
    jobs = os.cpu_count() if jobs is None else jobs
    if not 1 <= jobs <= 1024:
        raise ValueError(f"jobs={jobs}: allowed: 1 to 1024")
    if not 0 <= seeds <= 100000:
        raise ValueError(f"seeds={seeds}: allowed: 0 to 100000")
    axis_text = {name: _grid_text(name, v) for name, v in axes.items()}
    set_text = {field: _grid_text(field, v) for field, v in fields.items()}
    seed_text = "" if seed is None else _grid_text("seed", seed)
    report = _polyroll.sweep(os.fspath(out), source, axis_text, set_text, seed_text, int(seeds), int(jobs),
                             trajectories, retry_failed, large, quiet)
    return SweepResult(report)
