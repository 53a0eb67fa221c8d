#!/usr/bin/env python3
"""`cmake --install` puts `import polyroll` where Python imports it: installs the build's python
component into a temporary DESTDIR, then imports the installed package from a folder outside the
tree with PYTHONPATH set to the installed folder only, runs the default scene and checks that the
module came from there. Where the build's install folder is on this Python's own path (the default
prefix, /usr/local, on Debian), it also says that a real `cmake --install` needs no PYTHONPATH.

Usage: check_installed_module.py CMAKE BUILD_DIR INSTALL_PATH
  INSTALL_PATH: the folder the build installs the package into (CMAKE_INSTALL_PREFIX and
  POLYROLL_PYTHON_INSTALL_DIR, as src/python/CMakeLists.txt computes it).
"""
import os
import site
import subprocess
import sys
import tempfile

# The check, with the module's location printed too.
PROGRAM = "import polyroll; print(polyroll.__file__); print(polyroll.run().behaviour)"


def main(cmake, build_dir, install_path):
    with tempfile.TemporaryDirectory(prefix="polyroll-install-") as work:
        destdir = os.path.join(work, "root")
        env = dict(os.environ, DESTDIR=destdir)
        subprocess.run([cmake, "--install", build_dir, "--component", "python"], env=env, check=True,
                       stdout=subprocess.DEVNULL)
        installed = destdir + install_path
        package = os.path.join(installed, "polyroll")
        found = sorted(os.listdir(package))
        if "__init__.py" not in found or not any(f.startswith("_polyroll.") and f.endswith(".so") for f in found):
            print(f"{package} holds {found}: not the package (__init__.py and _polyroll*.so)", file=sys.stderr)
            return 1
        # Only the installed folder: nothing of the build or the source tree, from a folder elsewhere.
        env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "POLYROLL"))}
        env["PYTHONPATH"] = installed
        elsewhere = os.path.join(work, "elsewhere")
        os.mkdir(elsewhere)
        p = subprocess.run([sys.executable, "-c", PROGRAM], cwd=elsewhere, env=env, capture_output=True, text=True)
        if p.returncode != 0:
            print(f"the installed module failed (exit {p.returncode}):\n{p.stderr}", file=sys.stderr)
            return 1
        module_file, behaviour = p.stdout.split()
        if not module_file.startswith(package + os.sep):
            print(f"imported {module_file}, not the installed package in {package}", file=sys.stderr)
            return 1
        if behaviour != "rolled_to_end":  # the default scene's, as `polyroll run` gives it
            print(f"the installed module's default run: {behaviour}", file=sys.stderr)
            return 1
    on_path = os.path.realpath(install_path) in map(os.path.realpath, site.getsitepackages())
    print(f"installed into {install_path} (under DESTDIR), imported from a folder outside the tree: the default "
          f"run {behaviour}; {install_path} is {'' if on_path else 'not '}on {sys.executable}'s own path")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    sys.exit(main(*sys.argv[1:]))
