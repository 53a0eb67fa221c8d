#!/usr/bin/env python3
"""Executes a notebook of docs/notebooks as a reader would (nbclient, Debian's python3-nbclient), in a
temporary folder, with POLYROLL_NOTEBOOK_QUICK=1 (the notebook's own short version); fails on the
first cell that raises. The notebook's argument, its sweep folder (`out` in its cell tagged
"parameters", read from POLYROLL_NOTEBOOK_OUT as under jupyter-execute), is a folder in the temporary
one, or DIR with --out DIR (kept). The notebook file itself is left as it is.

Usage: execute_notebook.py NOTEBOOK [--out DIR]
"""
import argparse
import os
import sys
import tempfile

import nbclient
import nbformat


def main(path, out):
    nb = nbformat.read(path, as_version=4)
    if not any("parameters" in c.metadata.get("tags", []) for c in nb.cells):
        print(f"{path}: no cell tagged 'parameters' (where the notebook's arguments are)", file=sys.stderr)
        return 1
    # ipykernel's debugger notes every start on stderr otherwise (the frozen modules of Python 3.11)
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    with tempfile.TemporaryDirectory(prefix="polyroll-notebook-") as work:
        sweep = os.path.abspath(out) if out else os.path.join(work, "sweep")
        os.environ["POLYROLL_NOTEBOOK_QUICK"] = "1"
        os.environ["POLYROLL_NOTEBOOK_OUT"] = sweep
        client = nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
                                         resources={"metadata": {"path": work}})
        client.execute()
        outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
        figures = [o for o in outputs if "image/png" in o.get("data", {})]
        if not figures:
            print(f"{path}: executed, but drew no figure", file=sys.stderr)
            return 1
        for name in ("results.csv", "distance-vs-angle.png"):
            if not os.path.exists(os.path.join(sweep, name)):
                print(f"{path}: executed, but wrote no {name} into its sweep folder {sweep}", file=sys.stderr)
                return 1
    print(f"{path}: every cell ran; {len(figures)} figure(s)" + (f", the sweep in {sweep}" if out else ""))
    return 0


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("notebook")
    parser.add_argument("--out", metavar="DIR", help="the notebook's sweep folder, kept (default: a temporary one)")
    args = parser.parse_args()
    sys.exit(main(args.notebook, args.out))
