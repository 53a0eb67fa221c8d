#!/usr/bin/env python3
"""Runs every command of the README's Quick start as written, from a folder that holds the build as
`build/` (as the project folder does after the main command), with the heavy ones cut short by flags
this test adds (a shorter simulated time); checks each exits 0 and writes what the README says.

Usage: check_readme_quick_start.py SOURCE_DIR BUILD_DIR [--no-python]
(--no-python: a build without the Python module, the sanitizer builds; its lines are then not run)
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

# Flags added to cut a command's cost, by its program and subcommand; what the README promises
# (the files) does not depend on how long the scene runs.
CUTS = [
    ("polyroll-sandbox", ["--frames", "3"]),
    ("polyroll render", ["--time-limit", "0.2", "--hold", "0"]),
    ("polyroll run --model dem3d", ["--time-limit", "0.05"]),
    ("polyroll run", ["--time-limit", "0.3"]),
    ("polyroll sweep", ["--time-limit", "0.2", "-q"]),
    ("polyroll validate", ["--time-limit", "0.3", "--fidelity", "draft", "-q"]),
    ("polyroll figures", []),
]

# What each command writes, by its output folder (the README's own paths).
EXPECTED = {
    "frames/default": ["frame_000001.png", "summary.json"],
    "frames/oct": ["frame_000001.png", "summary.json"],
    "runs/oct": ["summary.json", "trajectory.csv", "impacts.csv"],
    "runs/3d": ["summary.json", "trajectory.csv"],
    "sweeps/first": ["results.csv", "plan.json"],
    "figures/first": [],
    "runs/validate": ["scorecard.csv", "scorecard.json"],
}


def quick_start_commands(readme):
    """The commands of the Quick start section: code-block lines and `inline` commands that start
    with build/, each without its trailing comment."""
    section = readme.split("## Quick start", 1)[1].split("\n## ", 1)[0]
    commands = []
    in_block = False
    for line in section.splitlines():
        if line.startswith("```"):
            in_block = not in_block
            continue
        if in_block and line.startswith(("build/", INSTALL) + PYTHON_LINES):
            commands.append(re.split(r"\s+#", line, 1)[0].strip())
        elif not in_block:
            commands += [c.strip() for c in re.findall(r"`(build/[^`]+)`", line)]
    return commands


# The Python lines: run with this test's Python (Debian's, which has numpy: the README says so), the
# module the README's `cmake --install build` installed, into a DESTDIR of this test's own (never the
# machine's /usr/local), or the build folder's for a line that sets PYTHONPATH itself. The notebook's
# line is executed by its own test (tests/python/execute_notebook.py), with the notebook's short version.
PYTHON_PREFIX = "PYTHONPATH="
INSTALL = "cmake --install build"
# How the README's Python lines start; the notebook's sets the variable that quiets the kernel's debugger.
PYTHON_LINES = (PYTHON_PREFIX, "python3 ", "jupyter-execute ", "PYDEVD_DISABLE_FILE_VALIDATION=1 jupyter-execute ")


def install(work):
    """Runs the README's install into work/installed (DESTDIR); the folder it put the package in."""
    destdir = os.path.join(work, "installed")
    cmake = shutil.which("cmake") or "cmake"
    r = subprocess.run([cmake, "--install", os.path.join(work, "build")], cwd=work,
                       env=dict(os.environ, DESTDIR=destdir), stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, timeout=600)
    print(f"$ DESTDIR={destdir} {INSTALL}\n  exit {r.returncode}")
    if r.returncode != 0:
        raise SystemExit(f"{INSTALL}: exit {r.returncode}\n{r.stdout[-2000:]}")
    for folder, _, files in os.walk(destdir):
        if os.path.basename(folder) == "polyroll" and "__init__.py" in files:
            return os.path.dirname(folder)
    raise SystemExit(f"{INSTALL} installed no polyroll package under {destdir}")


def python_argv(command, work, installed):
    """argv and environment of a README Python line, or None for the notebook's."""
    argv = shlex.split(command)
    if "jupyter-execute" in argv[:2]:
        return None
    if command.startswith(PYTHON_PREFIX):
        argv, path = argv[1:], os.path.join(work, "build", "python")  # the module is this build's
    elif installed is None:
        raise SystemExit(f"{command}: a Python line without PYTHONPATH before the README's `{INSTALL}`")
    else:
        path = installed
    if argv[0] != "python3":
        raise SystemExit(f"a Python line this test does not know how to run: {command}")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = path
    return [sys.executable] + argv[1:], env


def cut_for(command):
    program = command.split()[0].split("/")[-1]
    words = " ".join([program] + command.split()[1:])
    for prefix, flags in CUTS:
        if words.startswith(prefix):
            return flags
    raise SystemExit(f"no cut known for: {command} (add one to CUTS)")


def main():
    source_dir, build_dir = sys.argv[1], sys.argv[2]
    with_python = "--no-python" not in sys.argv[3:]
    with open(os.path.join(source_dir, "README.md"), encoding="utf-8") as f:
        commands = quick_start_commands(f.read())
    if len(commands) < 6:
        raise SystemExit(f"only {len(commands)} commands found in the README's Quick start: {commands}")
    work = tempfile.mkdtemp(prefix="polyroll-readme-")
    failures = []
    try:
        os.symlink(os.path.abspath(build_dir), os.path.join(work, "build"))
        installed = None
        for command in commands:
            if command == INSTALL:
                if not with_python:
                    print(f"$ {command}\n  not run: this build has no Python module")
                    continue
                installed = install(work)
                continue
            if command.startswith(PYTHON_LINES):
                if not with_python:
                    print(f"$ {command}\n  not run: this build has no Python module")
                    continue
                python = python_argv(command, work, installed)
                if python is None:
                    print(f"$ {command}\n  executed by the notebook's own test")
                    continue
                argv, env = python
                r = subprocess.run(argv, cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   text=True, timeout=600)
                print(f"$ {command}\n  exit {r.returncode}: {r.stdout.strip()[-300:]}")
                if r.returncode != 0:
                    failures.append(f"{command}: exit {r.returncode}\n{r.stdout[-2000:]}")
                continue
            argv = command.split() + cut_for(command)
            env = dict(os.environ)
            if argv[0].endswith("polyroll-sandbox"):
                argv = ["xvfb-run", "-a", "-s", "-screen 0 1280x800x24"] + argv
                # Under AddressSanitizer, as tests/test_sandbox_smoke.cpp runs the window: no leak check at
                # exit, where Mesa's unloaded GLX driver leaves allocations no suppression can name.
                if env.get("ASAN_OPTIONS") is not None:
                    env["ASAN_OPTIONS"] += ":detect_leaks=0"
            r = subprocess.run(argv, cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               timeout=600)
            print(f"$ {' '.join(argv)}\n  exit {r.returncode}")
            if r.returncode != 0:
                failures.append(f"{command}: exit {r.returncode}\n{r.stdout[-2000:]}")
        for folder, files in EXPECTED.items():
            path = os.path.join(work, folder)
            if not any(folder in c for c in commands) and not (folder == "runs/validate" and any(
                    "validate" in c for c in commands)):
                failures.append(f"the README no longer writes {folder}: update this test's EXPECTED")
                continue
            if not os.path.isdir(path):
                failures.append(f"{folder}: not written")
                continue
            for name in files:
                if not os.path.isfile(os.path.join(path, name)):
                    failures.append(f"{folder}/{name}: not written")
            if folder == "figures/first" and not any(n.endswith(".png") for n in os.listdir(path)):
                failures.append("figures/first: no PNG figure")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for f in failures:
        print("FAILED:", f)
    print(f"{len(commands)} Quick start commands run, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
