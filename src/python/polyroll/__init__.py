"""polyroll: hollow regular polygons, partly filled with grains, rolling down an incline.

The same simulation core as the ``polyroll`` command, in Python::

    import polyroll
    r = polyroll.run(sides=8, fill=0.375, material="bb", angle=14)
    r.summary["results"]["distance_m"]      # summary.json, as a dict
    r.trajectory["speed_m_s"]               # numpy arrays, trajectory.csv's columns
    r.to_pandas()                           # a DataFrame, where pandas is installed

Scenes take the command line's words: keywords named as its scene flags (``sides=8`` for ``--sides
8``, ``vertex_radius=`` for ``--vertex-radius``), ``set={"FIELD": VALUE}`` for ``--set
FIELD=VALUE``, and a scene file's path or a scene dict first. A bad value raises ValueError with the
command line's message. ``scene_keywords()`` lists the keywords.
"""

import csv
import os

import numpy as np

from . import _polyroll

__all__ = ["scene", "run", "sweep", "Simulation", "Result", "SweepResult", "scene_keywords", "version"]

version = _polyroll.version


def scene_keywords():
    """Every scene keyword: a list of dicts with its keyword, scene field, command-line flag and help."""
    return _polyroll.scene_keywords()


def scene(source=None, *, set=None, **fields):
    """The resolved scene document (a dict, as summary.json's "scene"): the defaults, then `source`
    (a scene file's path or a scene dict), then the keywords, then `set` ({"field.path": value})."""
    return _polyroll.resolve(source, fields, dict(set or {}))


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
        self.trajectory = _records(native.trajectory_columns())
        self.impacts = _records(native.impact_columns())

    @property
    def behaviour(self):
        return self.summary["results"]["behaviour"]

    @property
    def distance_m(self):
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


def run(source=None, *, set=None, **fields):
    """Runs a scene to its end, as `polyroll run` (the same numbers), and returns a Result. Any model,
    `model="auto"` and `model="dem3d"` included. Releases the GIL; Ctrl-C raises KeyboardInterrupt."""
    return Result(_polyroll.run(scene(source, set=set, **fields)))


class Simulation:
    """A run to step and read, for notebooks and control loops; deterministic as `run`.

        sim = polyroll.Simulation(sides=6, fill=0.25, angle=21)
        while sim.step(100):
            print(sim.time_s, sim.shell()["speed_m_s"])
        result = sim.result()
    """

    def __init__(self, source=None, *, set=None, **fields):
        self.scene = scene(source, set=set, **fields)
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

    time_s = property(lambda self: self._native.time_s, doc="simulated time since release")
    steps = property(lambda self: self._native.steps, doc="tracker steps since release")
    finished = property(lambda self: self._native.finished)
    behaviour = property(lambda self: self._native.behaviour, doc="'running' until the run has ended")
    grain_count = property(lambda self: self._native.grain_count)

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
    if isinstance(values, (bool, np.bool_)) or values is None:
        raise ValueError(f"{name}={values!r}: not a grid value (allowed: a number, a name, a list or 'start:stop:step')")
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
        import pandas  # noqa: PLC0415
        return pandas.read_csv(self.report["table"])

    def __repr__(self):
        r = self.report
        return f"<polyroll.SweepResult {len(self.table)} rows in {r['table']}, {r['failed']} failed this session>"


def sweep(out, source=None, *, set=None, seed=None, seeds=0, jobs=None, trajectories=False, retry_failed=False,
          large=False, quiet=True, **axes):
    """Runs a grid of scenes in parallel into the folder `out`, as `polyroll sweep --out`, and returns
    the results table. Axes in the command line's grid vocabulary: ``angle="5:20:1"``, ``sides=[6, 8]``,
    ``material="bb,rice"``; ``set={"shell.depth_m": [0.05, 0.062]}`` for any field; ``seeds=3`` or
    ``seed=[1, 5, 9]``. `source` is the base scene (a path or a dict). The same call resumes an
    interrupted sweep and extends one with more values; Ctrl-C stops after the runs in flight."""
    jobs = os.cpu_count() if jobs is None else jobs
    if not 1 <= jobs <= 1024:
        raise ValueError(f"jobs={jobs}: allowed: 1 to 1024")
    if not 0 <= seeds <= 100000:
        raise ValueError(f"seeds={seeds}: allowed: 0 to 100000")
    axis_text = {name: _grid_text(name, v) for name, v in axes.items()}
    set_text = {field: _grid_text(field, v) for field, v in (set or {}).items()}
    seed_text = "" if seed is None else _grid_text("seed", seed)
    report = _polyroll.sweep(os.fspath(out), source, axis_text, set_text, seed_text, int(seeds), int(jobs),
                             trajectories, retry_failed, large, quiet)
    return SweepResult(report)
