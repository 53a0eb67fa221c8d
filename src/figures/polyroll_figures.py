#!/usr/bin/env python3
"""The PNG figures of a polyroll sweep and of the speed/accuracy study, drawn with matplotlib.

polyroll figures and polyroll tradeoff run this script; it only reads tables the C++ side wrote:
  polyroll_figures.py sweep RESULTS_CSV OUT_DIR [--trajectory RUN_DIR ...]
  polyroll_figures.py tradeoff POINTS_CSV OUT_PNG
Every axis says its unit; error bars are the spread over seeds (one standard deviation).
"""
import argparse
import csv
import json
import math
import os
import sys
from collections import OrderedDict, defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

BEHAVIOURS = ["stopped_at_first_impact", "stopped", "rolled_to_end", "time_limit", "diverged", "failed"]
BEHAVIOUR_LABELS = {
    "stopped_at_first_impact": "stops at first impact",
    "stopped": "rolls, then stops",
    "rolled_to_end": "rolls to the end",
    "time_limit": "time limit reached",
    "diverged": "diverged",
    "failed": "invalid / failed",
}
BEHAVIOUR_COLOURS = {
    "stopped_at_first_impact": "#4477aa",
    "stopped": "#ee6677",
    "rolled_to_end": "#228833",
    "time_limit": "#ccbb44",
    "diverged": "#000000",
    "failed": "#bbbbbb",
}
MATERIAL_COLOURS = {"bb": "#4477aa", "rice": "#ccbb44", "peas": "#228833"}
# Columns that can split a figure into panels besides the ones a figure plots.
FACET_COLUMNS = ["model", "fidelity", "polygon", "sides", "ramp", "release", "fill_ratio", "material", "angle_deg"]
MAX_PANELS = 24


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(s):
    return float(s) if s not in ("", None) else math.nan


def fmt_value(col, v):
    units = {"fill_ratio": "r = {}", "angle_deg": "{} deg", "sides": "n = {}"}
    return units.get(col, "{}").format(v)


def sort_key(v):
    try:
        return (0, float(v), "")
    except ValueError:
        return (1, 0.0, v)


def varying(rows, columns):
    return [c for c in columns if len({r[c] for r in rows}) > 1]


def facets(rows, exclude):
    """Groups rows by every facet column that varies (except `exclude`), in a stable order."""
    keys = [c for c in varying(rows, FACET_COLUMNS) if c not in exclude]
    groups = OrderedDict()
    for r in sorted(rows, key=lambda r: [sort_key(r[c]) for c in keys]):
        groups.setdefault(tuple(r[c] for c in keys), []).append(r)
    items = list(groups.items())
    if len(items) > MAX_PANELS:
        print(f"polyroll figures: {len(items)} panels, drawing the first {MAX_PANELS}", file=sys.stderr)
        items = items[:MAX_PANELS]
    return keys, items


def panel_grid(n, width=4.2, height=3.3, max_cols=4):
    cols = min(max_cols, max(1, n))
    rows = max(1, math.ceil(n / cols))
    fig, axes = plt.subplots(rows, cols, figsize=(width * cols, height * rows + 0.8), squeeze=False,
                             layout="constrained")
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    return fig, list(axes.flat[:n])


def panel_title(keys, values):
    return ", ".join(fmt_value(k, v) for k, v in zip(keys, values)) or "all runs"


def seed_stats(rows, value):
    """mean, standard deviation over seeds and count of a column, for rows of one point."""
    v = np.array([num(r[value]) for r in rows])
    v = v[np.isfinite(v)]
    if len(v) == 0:
        return math.nan, math.nan, 0
    return float(v.mean()), float(v.std(ddof=1)) if len(v) > 1 else 0.0, len(v)


def seeds_note(rows):
    seeds = len({r["seed"] for r in rows})
    return f"error bars: spread over {seeds} seeds (1 standard deviation)" if seeds > 1 else "one seed per point"


def ok_rows(rows):
    return [r for r in rows if r["status"] == "ok"]


def distance_vs_angle(rows, out):
    rows = ok_rows(rows)
    stopping = [r for r in rows if r["behaviour"] in ("stopped", "stopped_at_first_impact")]
    if not stopping:
        return None
    keys, groups = facets(stopping, exclude={"material", "angle_deg"})
    fig, axes = panel_grid(len(groups))
    for ax, (values, grows) in zip(axes, groups):
        by_material = defaultdict(list)
        for r in grows:
            by_material[r["material"]].append(r)
        for material, mrows in sorted(by_material.items()):
            colour = MATERIAL_COLOURS.get(material)
            by_angle = defaultdict(list)
            for r in mrows:
                by_angle[float(r["angle_deg"])].append(r)
            angles = sorted(by_angle)
            stats = [seed_stats(by_angle[a], "distance_m") for a in angles]
            mean = np.array([s[0] for s in stats])
            sd = np.array([s[1] for s in stats])
            # The fit is over the angles where the polygon rolled before stopping (the third
            # behaviour), when there are two or more: a first-impact stop has no distance to speak of.
            rolled = [a for a in angles if sum(r["behaviour"] == "stopped" for r in by_angle[a]) * 2 >= len(by_angle[a])]
            fit_angles = rolled if len(rolled) >= 2 else angles
            label = material or "(no material)"
            if len(fit_angles) >= 2:
                x = np.array(fit_angles)
                y = np.array([mean[angles.index(a)] for a in fit_angles])
                slope, intercept = np.polyfit(x, y, 1)
                xs = np.linspace(x.min(), x.max(), 50)
                ax.plot(xs, slope * xs + intercept, "--", color=colour, lw=1)
                label += f": slope {slope:.3g} m/deg"
            ax.errorbar(angles, mean, yerr=sd, fmt="none", capsize=2, color=colour)
            # Filled: the polygon rolled, then stopped (the third behaviour); hollow: it stopped at its
            # first impact.
            filled = [a in rolled for a in angles]
            for want, face in ((True, colour), (False, "white")):
                xs = [a for a, f in zip(angles, filled) if f == want]
                if xs:
                    ys = [m for m, f in zip(mean, filled) if f == want]
                    first = want or not any(filled)
                    ax.plot(xs, ys, "o", ms=5, color=colour, mfc=face, label=label if first else None)
        ax.set_title(panel_title(keys, values), fontsize=9)
        ax.set_xlabel("ramp angle theta (deg)")
        ax.set_ylabel("distance before stopping D (m)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Distance before stopping against ramp angle, per material (dashed: linear fit)\n"
                 f"filled: rolled, then stopped; hollow: stopped at the first impact; runs that rolled to the end are not "
                 f"shown; {seeds_note(rows)}", fontsize=10)
    path = os.path.join(out, "distance_vs_angle.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def terminal_velocity_vs_fill(rows, out):
    rows = [r for r in ok_rows(rows) if r["behaviour"] == "rolled_to_end" and r["terminal_velocity_m_s"]]
    if not rows:
        return None
    keys, groups = facets(rows, exclude={"fill_ratio", "angle_deg"})
    all_angles = sorted({float(r["angle_deg"]) for r in rows})
    cmap = plt.get_cmap("viridis")
    norm = matplotlib.colors.Normalize(min(all_angles), max(all_angles) if len(all_angles) > 1 else min(all_angles) + 1)
    fig, axes = panel_grid(len(groups))
    for ax, (values, grows) in zip(axes, groups):
        by_angle = defaultdict(list)
        for r in grows:
            by_angle[float(r["angle_deg"])].append(r)
        for angle in sorted(by_angle):
            by_fill = defaultdict(list)
            for r in by_angle[angle]:
                by_fill[float(r["fill_ratio"])].append(r)
            fills = sorted(by_fill)
            stats = [seed_stats(by_fill[f], "terminal_velocity_m_s") for f in fills]
            ax.errorbar(fills, [s[0] for s in stats], yerr=[s[1] for s in stats], fmt="o-", ms=3, lw=1, capsize=2,
                        color=cmap(norm(angle)), label=f"{angle:g} deg")
        ax.set_title(panel_title(keys, values), fontsize=9)
        ax.set_xlabel("fill ratio r")
        ax.set_ylabel("terminal velocity Vt (m/s)")
        ax.set_xlim(-0.05, 1.05)
        ax.grid(alpha=0.3)
        if len(all_angles) <= 8:
            ax.legend(fontsize=7, title="ramp angle", title_fontsize=7)
    if len(all_angles) > 8:
        sm = matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap)
        fig.colorbar(sm, ax=axes, label="ramp angle theta (deg)", shrink=0.8)
    fig.suptitle("Terminal velocity against fill ratio (runs that rolled to the end)\n" + seeds_note(rows), fontsize=10)
    path = os.path.join(out, "terminal_velocity_vs_fill.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def majority(behaviours):
    counts = defaultdict(int)
    for b in behaviours:
        counts[b] += 1
    best = max(counts.values())
    for b in BEHAVIOURS:  # ties go to the earlier behaviour: a stable choice
        if counts.get(b) == best:
            return b, len(counts) > 1
    return behaviours[0], len(counts) > 1


def behaviour_map(rows, out):
    for r in rows:
        r["_b"] = r["behaviour"] if r["status"] == "ok" or r["behaviour"] == "diverged" else "failed"
    keys, groups = facets(rows, exclude={"fill_ratio", "angle_deg"})
    fig, axes = panel_grid(len(groups), width=4.4, height=3.8)
    present = set()
    for ax, (values, grows) in zip(axes, groups):
        fills = sorted({float(r["fill_ratio"]) for r in grows if r["fill_ratio"]})
        angles = sorted({float(r["angle_deg"]) for r in grows if r["angle_deg"]})
        if not fills or not angles:
            ax.set_visible(False)
            continue
        cells = defaultdict(list)
        for r in grows:
            if r["fill_ratio"] and r["angle_deg"]:
                cells[(float(r["fill_ratio"]), float(r["angle_deg"]))].append(r["_b"])

        def edges(v):
            v = np.array(v)
            if len(v) == 1:
                return np.array([v[0] - 0.5, v[0] + 0.5])
            mid = (v[1:] + v[:-1]) / 2
            return np.concatenate([[v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]])

        fx, ay = edges(fills), edges(angles)
        for (f, a), bs in cells.items():
            b, mixed = majority(bs)
            present.add(b)
            i, j = fills.index(f), angles.index(a)
            ax.add_patch(matplotlib.patches.Rectangle((fx[i], ay[j]), fx[i + 1] - fx[i], ay[j + 1] - ay[j],
                                                      facecolor=BEHAVIOUR_COLOURS[b], edgecolor="white", lw=0.3,
                                                      hatch="////" if mixed else None))
        ax.set_xlim(fx[0], fx[-1])
        ax.set_ylim(ay[0], ay[-1])
        ax.set_title(panel_title(keys, values), fontsize=9)
        ax.set_xlabel("fill ratio r")
        ax.set_ylabel("ramp angle theta (deg)")
    handles = [matplotlib.patches.Patch(color=BEHAVIOUR_COLOURS[b], label=BEHAVIOUR_LABELS[b]) for b in BEHAVIOURS
               if b in present]
    handles.append(matplotlib.patches.Patch(facecolor="white", edgecolor="grey", hatch="////",
                                            label="seeds disagree (majority shown)"))
    visible = [ax for ax in axes if ax.get_visible()]
    if visible:
        visible[-1].legend(handles=handles, loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8)
    fig.suptitle("Which behaviour occurs where, over fill ratio and ramp angle", fontsize=10)
    path = os.path.join(out, "behaviour_map.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def speed_vs_time(run_dirs, out):
    if not run_dirs:
        return None
    fig, ax = plt.subplots(figsize=(9, 4.8))
    colours = plt.get_cmap("tab10")
    for k, d in enumerate(run_dirs):
        traj = read_rows(os.path.join(d, "trajectory.csv"))
        impacts = read_rows(os.path.join(d, "impacts.csv"))
        with open(os.path.join(d, "summary.json")) as f:
            summary = json.load(f)
        s, res = summary["scene"], summary["results"]
        t = np.array([float(r["time_s"]) for r in traj])
        v = np.array([float(r["speed_m_s"]) for r in traj])
        label = (f"n = {s['shell']['sides']}, {s['fill']['material'].get('preset', 'custom')}, "
                 f"r = {s['fill']['ratio']:g}, {s['ramp']['angle_deg']:g} deg, {s['run']['model']}: "
                 f"{BEHAVIOUR_LABELS.get(res['behaviour'], res['behaviour'])}")
        c = colours(k % 10)
        ax.plot(t, v, color=c, lw=1.2, label=label)
        if impacts:
            ti = np.array([float(r["time_s"]) for r in impacts])
            ax.plot(ti, np.interp(ti, t, v), "o", ms=3, color=c, mfc="white")
    ax.plot([], [], "o", ms=3, color="grey", mfc="white", label="face impacts")
    ax.set_xlabel("time since release (s)")
    ax.set_ylabel("lid centre speed along the ramp (m/s)")
    ax.set_title("Speed against time (sampled at the run's sample rate; circles: face impacts)", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    path = os.path.join(out, "speed_vs_time.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def sweep_figures(args):
    rows = read_rows(args.results)
    if not rows:
        sys.exit(f"polyroll figures: {args.results} has no rows")
    made = [distance_vs_angle(rows, args.out), terminal_velocity_vs_fill(rows, args.out), behaviour_map(rows, args.out),
            speed_vs_time(args.trajectory or [], args.out)]
    for m in made:
        if m:
            print(m)
    skipped = {"distance_vs_angle.png": made[0], "terminal_velocity_vs_fill.png": made[1],
               "speed_vs_time.png": made[3]}
    for name, m in skipped.items():
        if not m:
            print(f"polyroll figures: no {name}: no run in the table shows it", file=sys.stderr)


def pareto(points):
    """Indices of the points no other point beats in both cost and error."""
    front = []
    for i, (c, e) in enumerate(points):
        if not any((c2 <= c and e2 <= e) and (c2 < c or e2 < e) for j, (c2, e2) in enumerate(points) if j != i):
            front.append(i)
    return sorted(front, key=lambda i: points[i][0])


def tradeoff_figure(args):
    rows = read_rows(args.points)
    metrics = [("distance_error", "mean relative error in distance D"),
               ("velocity_error", "mean relative error in terminal velocity Vt"),
               ("behaviour_error", "share of scenes with the wrong behaviour")]
    fig, axes = plt.subplots(1, 3, figsize=(16, 5.2), layout="constrained")
    markers = {"grains": "o", "segments": "s", "rigid": "^"}
    # The yardsticks are lines, not choices: the second seed (the spread a different packing gives)
    # and the reference with its step halved (the reference's own error).
    yardsticks = {"seed 2": ("seed-to-seed spread (standard)", ":"), "halved": ("reference vs its step halved", "--")}
    for ax, (col, label) in zip(axes, metrics):
        pts, keep = [], []
        for r in rows:
            c, e = num(r["wall_time_s"]), num(r[col])
            if not (math.isfinite(c) and math.isfinite(e)) or r["variant"] == "reference":
                continue
            if r["variant"] in yardsticks:
                text, style = yardsticks[r["variant"]]
                ax.axhline(e, ls=style, color="grey", lw=1, label=f"{text}: {e:.3g}")
                continue
            pts.append((max(c, 1e-5), e))
            keep.append(r)
        for (c, e), r in zip(pts, keep):
            ax.plot(c, e, markers.get(r["model"], "o"), ms=7, color="#4477aa" if r["model"] == "grains" else "#ee6677",
                    mfc="white" if r["variant"] == "coarse" else None)
            short = r["label"].replace("standard, coarse ", "coarse ")
            ax.annotate(short, (c, e), fontsize=7, xytext=(5, 4), textcoords="offset points")
        front = pareto(pts)
        if front:
            ax.plot([pts[i][0] for i in front], [pts[i][1] for i in front], "-", color="grey", lw=1, zorder=0)
            ax.plot([pts[i][0] for i in front], [pts[i][1] for i in front], "o", ms=14, mfc="none", color="grey",
                    label="Pareto front")
        ax.set_xscale("log")
        ax.set_xlabel("mean wall time per run (s, one core)")
        ax.set_ylabel(label)
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7, loc="best")
    fig.suptitle("Error against cost, one point per model and preset, against the reference (grains, reference "
                 "preset, seed 1). Circles: grains (hollow: coarser grains, same fill mass); square: segments; "
                 "triangle: rigid", fontsize=10)
    fig.savefig(args.out, dpi=110)
    plt.close(fig)
    print(args.out)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="what", required=True)
    s = sub.add_parser("sweep")
    s.add_argument("results")
    s.add_argument("out")
    s.add_argument("--trajectory", action="append", help="a run folder with trajectory.csv, impacts.csv, summary.json")
    t = sub.add_parser("tradeoff")
    t.add_argument("points")
    t.add_argument("out")
    args = p.parse_args()
    if args.what == "sweep":
        sweep_figures(args)
    else:
        tradeoff_figure(args)


if __name__ == "__main__":
    main()
