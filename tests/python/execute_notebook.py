#!/usr/bin/env python3
"""Executes a notebook of docs/notebooks as a reader would (nbclient, Debian's python3-nbclient), in a
temporary folder, with POLYROLL_NOTEBOOK_QUICK=1 (the notebook's own short version) and its sweep
folder there; fails on the first cell that raises. The notebook file itself is left as it is.

Usage: execute_notebook.py NOTEBOOK
"""
import os
import sys
import tempfile

import nbclient
import nbformat


def main(path):
    nb = nbformat.read(path, as_version=4)
    # ipykernel's debugger notes every start on stderr otherwise (a file-validation notice)
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    with tempfile.TemporaryDirectory(prefix="polyroll-notebook-") as work:
        os.environ["POLYROLL_NOTEBOOK_QUICK"] = "1"
        os.environ["POLYROLL_NOTEBOOK_OUT"] = os.path.join(work, "sweep")
        client = nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
                                         resources={"metadata": {"path": work}})
        client.execute()
        outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
        figures = [o for o in outputs if "image/png" in o.get("data", {})]
        if not figures:
            print(f"{path}: executed, but drew no figure", file=sys.stderr)
            return 1
        for name in ("results.csv", "distance-vs-angle.png"):
            if not os.path.exists(os.path.join(work, "sweep", name)):
                print(f"{path}: executed, but wrote no {name} into its sweep folder", file=sys.stderr)
                return 1
    print(f"{path}: every cell ran; {len(figures)} figure(s)")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
