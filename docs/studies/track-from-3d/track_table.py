#!/usr/bin/env python3
"""Tables of `polyroll validate` scorecards side by side: one row per observation check, one column per
validation folder (a model on a track), each cell the check's simulated value and whether it agrees.

Usage: track_table.py LABEL=FOLDER [LABEL=FOLDER ...]
  e.g. track_table.py "3D, straight=/work/ref3d/val/straight4" "2D, straight=/work/ref3d/val2d/straight-none"

Prints a Markdown table, then each column's count of agreeing observations. A folder whose scorecard is
missing (a validation not finished) is a column of "-", said under the table. Used for
docs/studies/track-from-3d.md (issue: the experiment's track decided by the model with the least model
error)."""
import json
import os
import sys


def load(folder):
    path = os.path.join(folder, "scorecard.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def cell(check):
    mark = "yes" if check["agree"] else "**no**"
    # The least agreeing point is the scorecard's own detail; the table keeps the figure.
    return f"{mark}: {check['simulation'].split('; least agreeing point')[0]}"


def main(argv):
    columns = []
    for arg in argv:
        label, _, folder = arg.partition("=")
        if not folder:
            sys.exit(f"track_table.py: '{arg}' is not LABEL=FOLDER")
        columns.append((label, folder, load(folder)))
    rows = []  # (observation id, check name), in the first scorecard's order
    for _, _, card in columns:
        if card is None:
            continue
        for obs in card["observations"]:
            for check in obs["checks"]:
                if (obs["id"], check["check"]) not in rows:
                    rows.append((obs["id"], check["check"]))
    print("| observation | check | experiment | " + " | ".join(label for label, _, _ in columns) + " |")
    print("| --- | --- | --- | " + " | ".join("---" for _ in columns) + " |")
    for obs_id, check_name in rows:
        experiment, cells = "", []
        for _, _, card in columns:
            found = None
            if card is not None:
                for obs in card["observations"]:
                    if obs["id"] == obs_id:
                        found = next((c for c in obs["checks"] if c["check"] == check_name), None)
            if found is not None:
                experiment = found["experiment"]
            cells.append(cell(found) if found is not None else "-")
        print(f"| {obs_id} | {check_name} | {experiment} | " + " | ".join(cells) + " |")
    print()
    for label, folder, card in columns:
        if card is None:
            print(f"- {label}: no scorecard yet in {folder}")
        else:
            print(f"- {label}: {card['observations_agreeing']} of {card['observations_total']} observations agree "
                  f"({card['runs']} runs, seeds {card['seeds']})")


if __name__ == "__main__":
    main(sys.argv[1:])
