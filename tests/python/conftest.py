"""Where the tests find polyroll: the module from PYTHONPATH (build/python), the command from
POLYROLL_BIN (build/polyroll); ctest sets both (tests/CMakeLists.txt)."""
import json
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def polyroll_bin():
    path = os.environ.get("POLYROLL_BIN", "")
    if not os.access(path, os.X_OK):
        pytest.fail(f"POLYROLL_BIN={path!r} is not the polyroll command (ctest sets it)")
    return path


@pytest.fixture(scope="session")
def cli(polyroll_bin):
    """Runs `polyroll ARGS`; returns the CompletedProcess (text)."""
    def run(*args, check=True):
        p = subprocess.run([polyroll_bin, *map(str, args)], capture_output=True, text=True)
        if check and p.returncode != 0:
            raise AssertionError(f"polyroll {' '.join(map(str, args))} exited {p.returncode}: {p.stderr}")
        return p
    return run


def without_wall_time(doc):
    """A summary without the one value that is not a function of the scene (and the host's)."""
    if isinstance(doc, dict):
        return {k: without_wall_time(v) for k, v in doc.items() if k not in ("wall_time_s", "cpu_time_s")}
    if isinstance(doc, list):
        return [without_wall_time(v) for v in doc]
    return doc


def read_summary(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        return json.load(f)
