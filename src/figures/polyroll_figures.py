#!/usr/bin/env python3
"""The PNG figures of a polyroll sweep and of the speed/accuracy study, drawn with matplotlib.

polyroll figures, polyroll tradeoff and polyroll validate run this script; it only reads files the
C++ side wrote:
  polyroll_figures.py sweep RESULTS_CSV OUT_DIR [--trajectory RUN_DIR ...] [--context JSON] [--format png,svg]
  polyroll_figures.py run|compare OUT_DIR RUN_DIR ... [--format png,svg]
  polyroll_figures.py tradeoff POINTS_CSV OUT_PNG
  polyroll_figures.py validate SCORECARD_JSON RESULTS_CSV OUT_DIR
Every axis says its unit; spreads over seeds are the median and the full seed range. Each figure is
written with a CSV of exactly what it plots.
"""
import argparse
import csv
import json
import math
import os
import sys
import textwrap
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
    "time_limit": "#997700",  # Tol's dark yellow: his bright #ccbb44 is too pale on white
    "diverged": "#000000",
    "failed": "#bbbbbb",
}
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


def panel_title(keys, values):
    return ", ".join(fmt_value(k, v) for k, v in zip(keys, values)) or "all runs"


def majority(behaviours):
    counts = defaultdict(int)
    for b in behaviours:
        counts[b] += 1
    best = max(counts.values())
    for b in BEHAVIOURS:  # ties go to the earlier behaviour: a stable choice
        if counts.get(b) == best:
            return b, len(counts) > 1
    return behaviours[0], len(counts) > 1


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


def cross_section_models(rows):
    """The panels, left to right: the 2D grain model, then each closure column ("grains+<closure preset>"),
    then the 3D reference; only those the csv holds (an older csv has no closure column)."""
    present = {r["model"] for r in rows}
    closures = sorted(m for m in present if m.startswith("grains+"))
    models = [("grains", "2D grain model (standard, no closure)")]
    models += [(m, f"2D grain model, closure {m.split('+', 1)[1]}") for m in closures]
    models.append(("dem3d", "3D reference (Yade)"))
    return [(m, title) for m, title in models if m in present]


def cross_section_figure(args):
    """The behaviour maps of the 2D grain model, the same with a closure and the 3D reference side by
    side: one row per scene (n, r), one cell per angle, split into a part per seed, coloured by
    behaviour and labelled with the distance rolled."""
    rows = read_rows(args.maps)
    scenes = sorted({(int(r["sides"]), float(r["fill_ratio"])) for r in rows})
    models = cross_section_models(rows)
    seeds = sorted({int(r["seed"]) for r in rows})
    angles = sorted({float(r["angle_deg"]) for r in rows})
    # About 6 inches a panel of seven angles, and room for the scene names and the legend.
    fig, axes = plt.subplots(1, len(models), figsize=(2.5 + 6.0 * len(models), 1.0 + 0.75 * len(scenes)),
                             layout="constrained", sharey=True, squeeze=False)
    axes = axes[0]
    for ax, (model, title) in zip(axes, models):
        for y, (n, fill) in enumerate(scenes):
            for r in rows:
                if r["model"] != model or int(r["sides"]) != n or float(r["fill_ratio"]) != fill:
                    continue
                a, k = float(r["angle_deg"]), seeds.index(int(r["seed"]))
                h = 0.9 / len(seeds)
                y0 = y - 0.45 + k * h
                colour = BEHAVIOUR_COLOURS.get(r["behaviour"], "#bbbbbb")
                ax.add_patch(plt.Rectangle((a - 0.45, y0), 0.9, h, color=colour))
                d = num(r["distance_m"])
                if math.isfinite(d) and r["behaviour"] != "rolled_to_end":
                    ax.text(a, y0 + h / 2, f"{d:.2f}", ha="center", va="center", fontsize=6, color="white")
        ax.set_xlim(min(angles) - 0.8, max(angles) + 0.8)
        ax.set_ylim(-0.6, len(scenes) - 0.4)
        ax.set_yticks(range(len(scenes)))
        ax.set_yticklabels([f"n = {n}, r = {f:g}" for n, f in scenes])
        ax.set_xticks(angles)
        ax.set_xticklabels([f"{a:g}" for a in angles], fontsize=7)
        ax.set_xlabel("ramp angle (degrees)")
        ax.set_title(title, fontsize=10)
    present = [b for b in BEHAVIOURS if any(r["behaviour"] == b for r in rows)]
    handles = [plt.Rectangle((0, 0), 1, 1, color=BEHAVIOUR_COLOURS[b]) for b in present]
    # Beside the right panel: constrained layout makes room for an axes' legend outside it (Debian 12's
    # matplotlib 3.6 has no "outside" figure legends).
    axes[-1].legend(handles, [BEHAVIOUR_LABELS[b] for b in present], loc="upper left", bbox_to_anchor=(1.02, 1.0),
                    fontsize=8)
    fig.suptitle("Behaviour on the 2.54 m air track, BBs: each cell one angle, its lower half seed 1 and upper "
                 "half seed 2; numbers: distance rolled (m)", fontsize=10)
    fig.savefig(args.out, dpi=110)
    plt.close(fig)
    print(args.out)


# ---------------------------------------------------------------------------------------------------
# polyroll validate: D against theta for each angle-range observation, and the behaviour map of every
# observation. scorecard.json says which runs are an observation's (and where each sits); results.csv
# says what each run showed. Each figure is written as PNG and SVG, with a CSV of exactly what it plots.

VALIDATE_DPI = 110
# How each outcome is drawn in D against theta: all on one axis, from 0 to the ramp's length.
RUN_STYLES = OrderedDict([
    ("stopped_at_first_impact", dict(marker="o", mfc="white", label="stopped at the first impact")),
    ("stopped", dict(marker="o", mfc=None, label="rolled, then stopped (third behaviour)")),
    ("rolled_to_end", dict(marker="^", mfc=None, label="rolled to the end (drawn at the ramp's end)")),
    ("time_limit", dict(marker="s", mfc="white", label="time limit reached (still moving)")),
    ("diverged", dict(marker="x", mfc=None, label="diverged (drawn at 0)")),
    ("failed", dict(marker="x", mfc=None, label="failed (drawn at 0)")),
])
D_COLUMNS = ["element", "angle_deg", "distance_m", "low_m", "high_m", "behaviour", "seed", "run_id"]
MAP_COLUMNS = ["observation", "row", "angle_deg", "cell_from_deg", "cell_to_deg", "shown", "runs", "counts", "mixed",
               "agreeing"]


def write_whole(path, write):
    """Writes through `write(temporary_path)`, then renames into place: never a half-written file."""
    tmp = f"{path}.tmp{os.getpid()}"
    try:
        write(tmp)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def write_csv(path, columns, rows):
    def write(tmp):
        with open(tmp, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=columns, lineterminator="\n")
            w.writeheader()
            for r in rows:
                w.writerow({c: csv_cell(r.get(c)) for c in columns})
    write_whole(path, write)


def csv_cell(v):
    if v is None:
        return ""
    if isinstance(v, float):
        return f"{v:.12g}"
    return v


def save_validate_figure(fig, table, columns, out, stem, formats=("png", "svg")):
    """The figure in each format (PNG, SVG) and the numbers it plots as CSV, side by side; returns the paths."""
    paths = []
    for ext in formats:
        path = os.path.join(out, f"{stem}.{ext}")
        write_whole(path, lambda tmp, ext=ext: fig.savefig(tmp, dpi=VALIDATE_DPI, format=ext))
        paths.append(path)
    plt.close(fig)
    path = os.path.join(out, f"{stem}.csv")
    write_csv(path, columns, table)
    paths.append(path)
    return paths


def outcome(run):
    """The behaviour a run showed, with failed runs (invalid point, error, missing) as 'failed'."""
    if run["status"] == "ok" or run["behaviour"] == "diverged":
        return run["behaviour"] if run["behaviour"] in RUN_STYLES else "failed"
    return "failed"


def observation_runs(observation, table_by_id):
    """The observation's runs from scorecard.json, each with what results.csv says it showed."""
    runs = []
    for r in observation["runs"]:
        row = table_by_id.get(r["run_id"], {})
        run = dict(r, status=row.get("status", "missing"), behaviour=row.get("behaviour", ""),
                   distance_m=num(row.get("distance_m")))
        run["outcome"] = outcome(run)
        runs.append(run)
    return runs


def drawn_distance_m(run):
    """Where a run sits on the one D axis: at the ramp's end when it rolled off, at 0 when it failed."""
    if run["outcome"] == "rolled_to_end":
        return run["ramp_length_m"]
    if run["outcome"] in ("failed", "diverged") or not math.isfinite(run["distance_m"]):
        return 0.0
    return run["distance_m"]


def check_of(observation, name):
    return next((c for c in observation["checks"] if c["check"] == name), None)


def wrapped(text, width):
    return "\n".join(textwrap.wrap(text, width))


def line_text(slope, intercept):
    sign = "\u2212" if intercept < 0 else "+"
    return f"D = {slope:.2f} m/deg \u00d7 \u03b8 {sign} {abs(intercept):.2f} m"


def seed_medians(runs):
    """Per simulated angle: the median, least and greatest drawn D over the runs that did not fail, and
    the behaviour most of them showed."""
    by_angle = defaultdict(list)
    for r in runs:
        if r["outcome"] not in ("failed", "diverged"):
            by_angle[r["angle_deg"]].append(r)
    angles = sorted(by_angle)
    out = []
    for a in angles:
        ds = [drawn_distance_m(r) for r in by_angle[a]]
        out.append((a, float(np.median(ds)), min(ds), max(ds), majority([r["outcome"] for r in by_angle[a]])[0]))
    return out


def same_behaviour_runs(medians):
    """The medians cut where the behaviour most seeds show changes: a line joins neighbouring angles
    only within one behaviour (a stop at the first impact at 15 deg and a whole ramp at 20 deg are not
    a linear rise between them)."""
    segments = []
    for m in medians:
        if segments and segments[-1][-1][4] == m[4]:
            segments[-1].append(m)
        else:
            segments.append([m])
    return segments


def two_point(element, x0, x1, y0=None, y1=None):
    return [dict(element=element, angle_deg=x0, distance_m=y0), dict(element=element, angle_deg=x1, distance_m=y1)]


def d_vs_angle_figure(observation, runs):
    """D against theta for one angle-range observation: (figure, table of what it plots)."""
    e = observation["experiment"]
    lo, hi = e["angle_range_deg"]
    tol = e.get("angle_tolerance_deg", 0.0)
    length_m = max((r["ramp_length_m"] for r in runs), default=1.0)
    fig, ax = plt.subplots(figsize=(8.2, 6.6), layout="constrained")
    sim_fit, band = observation["details"].get("fit"), observation["details"].get("band_deg")
    table = draw_d_vs_angle(ax, runs, length_m, (lo, hi, tol), e.get("linear_fit"),
                            (sim_fit, band) if sim_fit and band else None)
    angles = sorted({r["angle_deg"] for r in runs}) or [lo, hi]
    half_step = (angles[1] - angles[0]) / 2 if len(angles) > 1 else 0.5
    ax.set_xlim(min(angles[0], lo - tol) - half_step, max(angles[-1], hi + tol) + half_step)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.11), ncol=2, fontsize=7.5, frameon=False)
    ax.set_title(d_vs_angle_title(observation, runs), fontsize=9, loc="left")
    return fig, table


def draw_d_vs_angle(ax, runs, length_m, band=None, paper_fit=None, sim_fit=None, counted=True):
    """D against theta on one axis from 0 to the ramp's length: every run by its outcome, the median and
    range over seeds (joined only within one behaviour), the experiment's band (lo, hi, tolerance) and fit, and the simulation's fit
    ((fit, (from, to)) over the third behaviour). Returns the table of what it plots (polyroll validate
    and polyroll figures draw it alike)."""
    table = []
    if band:
        lo, hi, tol = band
        # Light greys: the band is the background the runs and lines are read against, not a datum.
        ax.axvspan(lo - tol, hi + tol, color="#f2f2f2", lw=0, gid="paper_band_tolerance",
                   label=f"paper's band \u00b1 {tol:g} deg (tolerance)")
        ax.axvspan(lo, hi, color="#dcdcdc", lw=0, gid="paper_band", label=f"paper's band, {lo:.1f} to {hi:.1f} deg")
        table += two_point("paper_band_tolerance", lo - tol, hi + tol) + two_point("paper_band", lo, hi)

    ax.axhline(length_m, ls=":", color="#555555", lw=1, gid="ramp_end", label=f"end of the ramp ({length_m:g} m)")

    medians = seed_medians(runs)
    for k, seg in enumerate(same_behaviour_runs(medians)):
        xs = [m[0] for m in seg]
        ax.fill_between(xs, [m[2] for m in seg], [m[3] for m in seg], color="#66ccee", alpha=0.45, lw=0,
                        gid="seed_range", label="seed range (least to greatest)" if k == 0 else None)
        # A short tick marks a median alone in its behaviour, which no line joins.
        ax.plot(xs, [m[1] for m in seg], "-", marker="_", ms=9, color="#4477aa", lw=1.3, gid="seed_median",
                label="median over seeds" if k == 0 else None)
    table += [dict(element="seed_median", angle_deg=a, distance_m=med, low_m=low, high_m=high, behaviour=b)
              for a, med, low, high, b in medians]

    for b, style in RUN_STYLES.items():
        mine = [r for r in runs if r["outcome"] == b]
        if not mine:
            continue
        colour = BEHAVIOUR_COLOURS[b]
        ax.plot([r["angle_deg"] for r in mine], [drawn_distance_m(r) for r in mine], ls="none", ms=6, mew=1.2,
                marker=style["marker"], color=colour, mfc=style["mfc"] or colour, alpha=0.85, gid=f"run:{b}",
                label=f"{style['label']}: {len(mine)}" if counted else style["label"], clip_on=False, zorder=3)
        table += [dict(element="run", angle_deg=r["angle_deg"], distance_m=drawn_distance_m(r), behaviour=b,
                       seed=r["seed"], run_id=r["run_id"]) for r in mine]

    if paper_fit and band:
        lo, hi = band[0], band[1]
        ys = [paper_fit["slope_m_per_deg"] * x + paper_fit["intercept_m"] for x in (lo, hi)]
        ax.plot([lo, hi], ys, "-", color="black", lw=2, gid="paper_fit",
                label=f"paper: {line_text(paper_fit['slope_m_per_deg'], paper_fit['intercept_m'])}, over its band")
        table += two_point("paper_fit", lo, hi, *ys)
    if sim_fit:
        fit, (x0, x1) = sim_fit
        ys = [fit["slope_m_per_deg"] * x + fit["intercept_m"] for x in (x0, x1)]
        ax.plot([x0, x1], ys, "--", color=BEHAVIOUR_COLOURS["stopped"], lw=2, gid="simulation_fit",
                label=f"simulation, third behaviour: {line_text(fit['slope_m_per_deg'], fit['intercept_m'])}"
                      + (f" (R\u00b2 {fit['r_squared']:.2f})" if fit.get("r_squared") is not None else "")
                      + f", over {x0:g} to {x1:g} deg")
        table += two_point("simulation_fit", x0, x1, *ys)
    table.append(dict(element="ramp_end", distance_m=length_m))
    ax.set_ylim(-0.04 * length_m, 1.06 * length_m)
    ax.set_xlabel("ramp angle \u03b8 (deg)")
    ax.set_ylabel("distance before stopping D (m)")
    ax.grid(alpha=0.3)
    return table


def d_vs_angle_title(observation, runs):
    """The observation and its source, then what the simulation showed against it (the scorecard's verdict)."""
    seeds = len({r["seed"] for r in runs})
    rows = len({r["row"] for r in runs})
    pooled = f", {rows} grid points pooled as scored" if rows > 1 else ""
    verdict = "agrees" if observation["agree"] else "disagrees"
    lines = [f"D against \u03b8: {observation['id']} ({seeds} seed{'s' if seeds != 1 else ''}{pooled})",
             wrapped("Source: " + observation["source"], 110)]
    checks = [c for c in (check_of(observation, n) for n in ("band start", "band end", "D slope")) if c]
    if checks:
        lines.append(wrapped(f"Simulation {verdict}: " + "; ".join(f"{c['check']} {c['by']}" for c in checks), 110))
    return "\n".join(lines)


def cell_edges(values, lone_width):
    """Cell edges centred on the values (midpoints between neighbours); a lone value gets `lone_width`."""
    v = np.array(values, dtype=float)
    if len(v) == 1:
        return np.array([v[0] - lone_width / 2, v[0] + lone_width / 2])
    mid = (v[1:] + v[:-1]) / 2
    return np.concatenate([[v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]])


ROW_NAMES = {"shell.preset": "{}", "fill.ratio": "r = {}", "fill.material": "{}", "ramp.preset": "{}"}


def row_name(row):
    """'shell.preset=octagon-small fill.ratio=0.5' as 'octagon-small, r = 0.5'."""
    if not row:
        return "simulation"
    parts = []
    for item in row.split(" "):
        key, _, value = item.partition("=")
        parts.append(ROW_NAMES.get(key, key.rsplit(".", 1)[-1] + " = {}").format(value))
    return ", ".join(parts)


def observed_behaviour(experiment):
    """Whether the experiment names a behaviour (seen, or never seen); a lab's observation may hold only
    measured numbers (distance_m, terminal_velocity_m_s), scored as checks, with no behaviour to colour."""
    return "behaviour" in experiment or "not_behaviour" in experiment


def agreeing_count(experiment, outcomes):
    """Seeds agreeing with the experiment's behaviour; None when it names none (measured numbers only)."""
    if "not_behaviour" in experiment:
        return sum(o != experiment["not_behaviour"] for o in outcomes)
    if "behaviour" not in experiment:
        return None
    return sum(o == experiment["behaviour"] for o in outcomes)


def map_panel(ax, observation, runs, table):
    """One observation's behaviour against angle (a row per grid point), under a row of what the
    experiment saw. Returns the behaviours drawn."""
    e = observation["experiment"]
    rows = list(OrderedDict.fromkeys(r["row"] for r in runs))
    angles = sorted({r["angle_deg"] for r in runs})
    edges = cell_edges(angles, 1.0)
    cells = defaultdict(list)
    for r in runs:
        cells[(r["row"], r["angle_deg"])].append(r["outcome"])
    present = {e["behaviour"]} if "angle_range_deg" in e else set()  # the band's colour needs its legend entry
    label_counts = len(angles) <= 12  # narrower cells have no room for a number
    for (row, angle), outcomes in cells.items():
        shown, mixed = majority(outcomes)
        present.add(shown)
        j, y = angles.index(angle), rows.index(row) + 1
        ax.add_patch(matplotlib.patches.Rectangle((edges[j], y - 0.5), edges[j + 1] - edges[j], 1.0,
                                                  facecolor=BEHAVIOUR_COLOURS[shown], edgecolor="white", lw=0.5,
                                                  hatch="////" if mixed else None))
        agreeing = agreeing_count(e, outcomes)
        if label_counts and agreeing is not None:
            # On a white chip: readable on every colour and through the hatching of mixed cells.
            ax.text(angle, y, f"{agreeing}/{len(outcomes)}", ha="center", va="center", fontsize=6.5,
                    bbox=dict(boxstyle="round,pad=0.15", facecolor="white", edgecolor="none", alpha=0.85))
        counts = "; ".join(f"{b} {outcomes.count(b)}" for b in BEHAVIOURS if b in outcomes)
        table.append(dict(observation=observation["id"], row=row or "simulation", angle_deg=angle,
                          cell_from_deg=float(edges[j]), cell_to_deg=float(edges[j + 1]), shown=shown,
                          runs=len(outcomes), counts=counts, mixed="yes" if mixed else "no",
                          agreeing="" if agreeing is None else agreeing))
    x_from, x_to = float(edges[0]), float(edges[-1])
    if "angle_range_deg" in e:
        x_from, x_to = experiment_band_row(ax, observation, len(rows), x_from, x_to, table)
    else:
        experiment_cells_row(ax, observation, angles, edges, table)
    ax.axhline(0.5, color="black", lw=0.8)
    ax.set_xlim(x_from, x_to)
    ax.set_ylim(len(rows) + 0.5, -0.5)
    ax.set_yticks(range(len(rows) + 1))
    ax.set_yticklabels(["experiment"] + [row_name(r) for r in rows], fontsize=7.5)
    if len(angles) <= 12:  # a tick under every cell; more cells keep matplotlib's ticks
        ax.set_xticks(angles)
        ax.set_xlim(x_from, x_to)
    ax.tick_params(axis="x", labelsize=7.5)
    ax.set_xlabel("ramp angle \u03b8 (deg)", fontsize=8)
    short_source = observation["source"].split(":")[0]
    verdict = "agrees" if observation["agree"] else "disagrees"
    ax.set_title(f"{observation['id']} [{short_source}]: {expected_text(e, observation.get('checks', []))}; "
                 f"simulation {verdict}", fontsize=8.5, loc="left")
    return present


def expected_text(e, checks=()):
    if not observed_behaviour(e):  # a lab's measured numbers only: what was measured, as scored
        measured = [f"{c['check']} {c['experiment']}" for c in checks if c.get("experiment")]
        return "measured " + ("; ".join(measured) if measured else "numbers only")
    if "not_behaviour" in e:
        share = e.get("behaviour_share", 1.0)
        return (f"never {BEHAVIOUR_LABELS[e['not_behaviour']]}" if share >= 1.0 else
                f"{BEHAVIOUR_LABELS[e['not_behaviour']]} in at most {100 * (1 - share):g}% of runs")
    if "angle_range_deg" in e:
        lo, hi = e["angle_range_deg"]
        return f"{BEHAVIOUR_LABELS[e['behaviour']]} from {lo:g} to {hi:g} deg (\u00b1 {e['angle_tolerance_deg']:g})"
    return f"{BEHAVIOUR_LABELS[e['behaviour']]} in at least {100 * e['behaviour_share']:g}% of runs"


def experiment_band_row(ax, observation, n_rows, x_from, x_to, table):
    """The paper's band in the experiment row, its tolerance lighter, and its ends across every row."""
    e = observation["experiment"]
    lo, hi = e["angle_range_deg"]
    tol = e.get("angle_tolerance_deg", 0.0)
    colour = BEHAVIOUR_COLOURS[e["behaviour"]]
    for a, b, alpha, what in ((lo - tol, lo, 0.35, "tolerance"), (lo, hi, 1.0, e["behaviour"]),
                              (hi, hi + tol, 0.35, "tolerance")):
        if b > a:
            ax.add_patch(matplotlib.patches.Rectangle((a, -0.5), b - a, 1.0, facecolor=colour, alpha=alpha, lw=0))
            table.append(dict(observation=observation["id"], row="experiment", cell_from_deg=a, cell_to_deg=b,
                              shown=what))
    for x in (lo, hi):
        ax.plot([x, x], [-0.5, n_rows + 0.5], "--", color="black", lw=1)
    return min(x_from, lo - tol), max(x_to, hi + tol)


def experiment_cells_row(ax, observation, angles, edges, table):
    """What the experiment saw at each simulated angle: the behaviour's colour, or crossed when it says
    a behaviour never shows."""
    e = observation["experiment"]
    if not observed_behaviour(e):
        # Nothing to colour: the row says so, and the title says what was measured.
        ax.add_patch(matplotlib.patches.Rectangle((edges[0], -0.5), edges[-1] - edges[0], 1.0, facecolor="white",
                                                  edgecolor="grey", lw=0.5))
        ax.text((edges[0] + edges[-1]) / 2, 0, "no behaviour observed (measured numbers only)", ha="center",
                va="center", fontsize=6.5, color="#555555")
        for j, angle in enumerate(angles):
            table.append(dict(observation=observation["id"], row="experiment", angle_deg=angle,
                              cell_from_deg=float(edges[j]), cell_to_deg=float(edges[j + 1]), shown="measured only"))
        return
    never = "not_behaviour" in e
    b = e["not_behaviour"] if never else e["behaviour"]
    for j, angle in enumerate(angles):
        ax.add_patch(matplotlib.patches.Rectangle(
            (edges[j], -0.5), edges[j + 1] - edges[j], 1.0, lw=0.5,
            facecolor="white" if never else BEHAVIOUR_COLOURS[b],
            edgecolor=BEHAVIOUR_COLOURS[b] if never else "white", hatch="xxx" if never else None))
        table.append(dict(observation=observation["id"], row="experiment", angle_deg=angle,
                          cell_from_deg=float(edges[j]), cell_to_deg=float(edges[j + 1]),
                          shown=f"not {b}" if never else b))


def behaviour_map_figure(scorecard, runs_by_id):
    """Every observation's behaviour against angle, one panel each: (figure, table of what it plots)."""
    observations = scorecard["observations"]
    heights = [0.9 + 0.24 * (1 + len({r["row"] for r in runs_by_id[o["id"]]})) for o in observations]
    legend_height = 0.9
    fig = plt.figure(figsize=(8.6, sum(heights) + legend_height + 0.4), layout="constrained")
    grid = fig.add_gridspec(len(observations) + 1, 1, height_ratios=heights + [legend_height])
    table, present = [], set()
    for k, o in enumerate(observations):
        ax = fig.add_subplot(grid[k])
        present |= map_panel(ax, o, runs_by_id[o["id"]], table)
    legend_ax = fig.add_subplot(grid[len(observations)])
    legend_ax.axis("off")
    bands = [o["experiment"]["behaviour"] for o in observations if "angle_range_deg" in o["experiment"]]
    legend_ax.legend(handles=map_legend_handles(present, bands), loc="center", ncol=3, fontsize=7.5, frameon=False)
    fig.suptitle(f"Behaviour against ramp angle, per observation ({scorecard.get('seeds', '?')} seeds per scene; "
                 "cells centred on the simulated angles)", fontsize=10)
    return fig, table


def map_legend_handles(present, band_behaviours):
    Patch = matplotlib.patches.Patch
    handles = [Patch(color=BEHAVIOUR_COLOURS[b], label=BEHAVIOUR_LABELS[b]) for b in BEHAVIOURS if b in present]
    handles += [Patch(facecolor="white", edgecolor="grey", hatch="////", label="seeds disagree (majority shown)"),
                Patch(facecolor="white", edgecolor="grey", hatch="xxx", label="experiment: never this behaviour")]
    if band_behaviours:
        handles += [Patch(facecolor=BEHAVIOUR_COLOURS[band_behaviours[0]], alpha=0.35,
                          label="experiment: band's tolerance"),
                    matplotlib.lines.Line2D([], [], ls="--", color="black", lw=1, label="experiment: band's ends")]
    handles.append(Patch(facecolor="white", edgecolor="white", label="k/n: seeds agreeing with the experiment"))
    return handles


def file_stem(observation_id):
    return "".join(c if c.isalnum() or c in "-_" else "_" for c in observation_id)


def validate_figures(args):
    with open(args.scorecard) as f:
        scorecard = json.load(f)
    table_by_id = {r["run_id"]: r for r in read_rows(args.results)}
    runs_by_id = {o["id"]: observation_runs(o, table_by_id) for o in scorecard["observations"]}
    written = []
    for o in scorecard["observations"]:
        if "angle_range_deg" in o["experiment"]:
            fig, table = d_vs_angle_figure(o, runs_by_id[o["id"]])
            written += save_validate_figure(fig, table, D_COLUMNS, args.out, f"d_vs_angle-{file_stem(o['id'])}")
    if scorecard["observations"]:
        fig, table = behaviour_map_figure(scorecard, runs_by_id)
        written += save_validate_figure(fig, table, MAP_COLUMNS, args.out, "behaviour_map")
    for path in written:
        print(f"  figure     {path}")


# ---------------------------------------------------------------------------------------------------
# polyroll figures on a sweep folder: D against theta, terminal velocity against fill, the behaviour
# map and speed against time, each as PNG (and SVG with --format) with a CSV of what it plots. The
# C++ side passes a context file: each run's ramp length (rolls to the end are drawn there) and the
# experiment's angle-range observations with a linear fit (drawn where a panel matches one's scene).

# Observation scene fields and the results.csv column each is matched against.
OBSERVATION_COLUMNS = {"shell.preset": "polygon", "shell.sides": "sides", "fill.ratio": "fill_ratio",
                       "fill.material.preset": "material", "fill.material": "material", "ramp.preset": "ramp",
                       "release.pose": "release"}
# A seed's terminal velocity this many times its point's median is a runaway (bounding) run.
RUNAWAY_FACTOR = 1.5
SWEEP_D_COLUMNS = ["panel"] + D_COLUMNS
VT_COLUMNS = ["panel", "element", "fill_ratio", "angle_deg", "terminal_velocity_m_s", "low_m_s", "high_m_s", "seeds",
              "seed", "run_id"]
SWEEP_MAP_COLUMNS = ["panel", "fill_ratio", "angle_deg", "fill_from", "fill_to", "angle_from_deg", "angle_to_deg",
                     "shown", "runs", "counts", "mixed"]
SPEED_COLUMNS = ["run", "element", "time_s", "speed_m_s"]


def sweep_runs(rows, lengths):
    """results.csv rows as the runs draw_d_vs_angle draws (outcome, drawn where). Without the ramp's
    length from the C++ side (the script run by hand), the farthest run that rolled to the end stands
    for it."""
    reached = [num(r["distance_m"]) for r in rows if r["behaviour"] == "rolled_to_end"]
    fallback = max([d for d in reached if math.isfinite(d)], default=1.0)
    runs = []
    for r in rows:
        run = dict(r, angle_deg=num(r["angle_deg"]), distance_m=num(r["distance_m"]),
                   ramp_length_m=float(lengths.get(r["run_id"], fallback)))
        run["outcome"] = outcome(run)
        runs.append(run)
    return runs


def panel_label(keys, values):
    return panel_title(keys, values)


def matching_observation(observations, grows):
    """The first observation whose scene every row of the panel shows (only fields results.csv holds)."""
    for o in observations:
        scene = o.get("scene", {})
        if not scene or any(k not in OBSERVATION_COLUMNS for k in scene):
            continue
        if all(all(same_value(r[OBSERVATION_COLUMNS[k]], v) for r in grows) for k, v in scene.items()):
            return o
    return None


def same_value(cell, value):
    try:
        return math.isclose(float(cell), float(value), rel_tol=1e-9, abs_tol=1e-12)
    except (TypeError, ValueError):
        return str(cell) == str(value)


# The fewest distinct angles a fit of D against theta is drawn from: a line through two angles always
# fits them (R^2 1.00 through two points says nothing), a third is the first that can disagree.
MIN_FIT_ANGLES = 3


def third_behaviour_fit(runs):
    """Least squares over every run that rolled, then stopped, when they span MIN_FIT_ANGLES angles or more."""
    pts = [(r["angle_deg"], r["distance_m"]) for r in runs if r["outcome"] == "stopped"]
    if len({a for a, _ in pts}) < MIN_FIT_ANGLES:
        return None
    x, y = np.array([p[0] for p in pts]), np.array([p[1] for p in pts])
    slope, intercept = np.polyfit(x, y, 1)
    residual = float(((y - (slope * x + intercept)) ** 2).sum())
    total = float(((y - y.mean()) ** 2).sum())
    r2 = 1.0 - residual / total if total > 0 else None
    return dict(slope_m_per_deg=float(slope), intercept_m=float(intercept), r_squared=r2), (float(x.min()),
                                                                                             float(x.max()))


def shared_handles(axes):
    """The legend entries of every panel, once each: one legend in its own row under the panels."""
    seen = OrderedDict()
    for ax in axes:
        for h, label in zip(*ax.get_legend_handles_labels()):
            seen.setdefault(label, h)
    return seen


def shared_legend(legend_ax, axes, ncol):
    """Every panel's entries, once each, as one legend in the legend row."""
    handles = shared_handles(axes)
    legend_ax.legend(list(handles.values()), list(handles.keys()), loc="center", ncol=ncol, fontsize=7, frameon=False)


# A printed page's width: the figures are drawn at the size a paper prints them, fonts 7 to 9 pt.
PAGE_WIDTH_IN = 7.2


def panels_with_legend_row(n, height=2.5, max_cols=3, legend_rows=3):
    """Panels sharing their axes, up to three a row across a page, and a row under them for the legend."""
    cols = min(max_cols, max(1, n))
    rows = max(1, math.ceil(n / cols))
    legend_in = 0.17 * legend_rows + 0.2
    fig = plt.figure(figsize=(PAGE_WIDTH_IN, height * rows + legend_in + 0.6), layout="constrained")
    grid = fig.add_gridspec(rows + 1, cols, height_ratios=[height] * rows + [legend_in])
    axes, first = [], None
    for k in range(n):
        ax = fig.add_subplot(grid[k // cols, k % cols], sharex=first, sharey=first)
        first = first or ax
        if k % cols:  # shared y axis: its numbers and name once, on the left panel of each row
            ax.tick_params(labelleft=False)
        axes.append(ax)
    legend_ax = fig.add_subplot(grid[rows, :])
    legend_ax.axis("off")
    return fig, axes, legend_ax


def fit_titles(fig, titles):
    """Wraps each panel's title (a Text that set_title returned, drawn from its panel's left edge) to
    the panel's width: a long one ran into the next panel's. Measured after a layout pass,
    so it holds for any font, figure size and number of panels."""
    for _ in range(3):  # wrapping changes the layout a little: measure again, a few times at most
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        changed = False
        for t in titles:
            room, width = t.axes.get_window_extent(renderer).width, t.get_window_extent(renderer).width
            if width <= room or not t.get_text().strip():
                continue
            lines = t.get_text().split("\n")
            # Characters per pixel of the widest line: how many characters the panel's width holds.
            chars = max(8, int(0.95 * room * max(len(line) for line in lines) / width))
            t.set_text("\n".join(w for line in lines for w in (textwrap.wrap(line, chars) or [""])))
            changed = True
        if not changed:
            return


def left_panel(ax, axes, cols=3):
    return axes.index(ax) % min(cols, len(axes)) == 0


def page_title(fig, text):
    fig.suptitle("\n".join(textwrap.wrap(text, 110)), fontsize=8.5)


def d_vs_angle_sweep(rows, lengths, observations):
    runs = sweep_runs(rows, lengths)
    keys, groups = facets(runs, exclude={"angle_deg"})
    fig, axes, legend_ax = panels_with_legend_row(len(groups), legend_rows=4)
    length_m = max((r["ramp_length_m"] for r in runs if math.isfinite(r["ramp_length_m"])), default=1.0)
    table, matched, titles = [], [], []
    fitted = False
    for ax, (values, grows) in zip(axes, groups):
        name = panel_label(keys, values)
        o = matching_observation(observations, grows)
        band = paper_fit = None
        if o:
            matched.append(o["id"])
            band = (o["angle_range_deg"][0], o["angle_range_deg"][1], o.get("angle_tolerance_deg", 0.0))
            paper_fit = o["linear_fit"]
        fit = third_behaviour_fit(grows)
        fitted = fitted or fit is not None
        part = draw_d_vs_angle(ax, grows, length_m, band, paper_fit, fit, counted=False)
        table += [dict(t, panel=name) for t in part]
        titles.append(ax.set_title(name + (f"\nexp. {o['id']}" if o else ""), fontsize=7.5, loc="left"))
        ax.tick_params(labelsize=7.5)
        ax.xaxis.label.set_size(8)
        ax.yaxis.label.set_size(8)
        if not left_panel(ax, axes):
            ax.set_ylabel("")
    shared_legend(legend_ax, axes, ncol=2)
    # The dashed fit is promised only where a panel draws one.
    fit_text = (f"dashed: linear fit over the runs that rolled, then stopped (from {MIN_FIT_ANGLES} angles or more)"
                if fitted else f"no fit drawn: no panel has runs that rolled, then stopped at {MIN_FIT_ANGLES} angles")
    page_title(fig, "Distance before stopping D against ramp angle \u03b8, every run "
               f"({seeds_count(rows)} seed{'s' if seeds_count(rows) != 1 else ''} per point); " + fit_text)
    fit_titles(fig, titles)
    return fig, table


def seeds_count(rows):
    return len({r["seed"] for r in rows})


def vt_points(grows):
    """Per (angle, fill): the median terminal velocity over the seeds that rolled to the end, its range
    without runaway seeds, and the runaway seeds (RUNAWAY_FACTOR times the median or more)."""
    by_point = defaultdict(list)
    for r in grows:
        v = num(r["terminal_velocity_m_s"])
        if r["status"] == "ok" and r["behaviour"] == "rolled_to_end" and math.isfinite(v):
            by_point[(float(r["angle_deg"]), float(r["fill_ratio"]))].append((v, r))
    points = []
    for (angle, fill), vs in sorted(by_point.items()):
        median = float(np.median([v for v, _ in vs]))
        runaway = [(v, r) for v, r in vs if len(vs) > 1 and v >= RUNAWAY_FACTOR * median]
        kept = [v for v, _ in vs if all(v != w for w, _ in runaway)]
        median = float(np.median(kept))
        points.append(dict(angle=angle, fill=fill, median=median, low=min(kept), high=max(kept), seeds=len(vs),
                           runaway=runaway))
    return points


def terminal_velocity_sweep(rows):
    keys, groups = facets(rows, exclude={"fill_ratio", "angle_deg"})
    per_panel = [(values, vt_points(grows)) for values, grows in groups]
    if not any(points for _, points in per_panel):
        return None
    all_angles = sorted({p["angle"] for _, points in per_panel for p in points})
    cmap = plt.get_cmap("viridis")
    norm = matplotlib.colors.Normalize(all_angles[0], all_angles[-1] if len(all_angles) > 1 else all_angles[0] + 1)
    fig, axes, legend_ax = panels_with_legend_row(len(per_panel), legend_rows=2 + len(all_angles) // 6)
    # The y scale is set by the medians and ranges, never by a runaway seed: those sit on the top edge.
    top = 1.15 * max((p["high"] for _, points in per_panel for p in points), default=1.0)
    table, titles = [], []
    for ax, (values, points) in zip(axes, per_panel):
        name = panel_label(keys, values)
        for angle in sorted({p["angle"] for p in points}):
            mine = [p for p in points if p["angle"] == angle]
            colour = cmap(norm(angle)) if len(all_angles) > 1 else "#4477aa"
            xs, med = [p["fill"] for p in mine], [p["median"] for p in mine]
            yerr = [[m - p["low"] for m, p in zip(med, mine)], [p["high"] - m for m, p in zip(med, mine)]]
            bars = ax.errorbar(xs, med, yerr=yerr, fmt="o-", ms=3.5, lw=1, capsize=2, color=colour,
                               label=f"\u03b8 = {angle:g} deg")
            bars.lines[0].set_gid(f"median:{angle:g}")
            for p in mine:
                table.append(dict(panel=name, element="median", fill_ratio=p["fill"], angle_deg=angle,
                                  terminal_velocity_m_s=p["median"], low_m_s=p["low"], high_m_s=p["high"],
                                  seeds=p["seeds"]))
                for v, r in p["runaway"]:
                    ax.plot([p["fill"]], [top], marker="^", ms=7, ls="none", color=colour, mec="black", clip_on=False,
                            zorder=4, gid="runaway", label="runaway seed (bounding), off scale: value in the CSV")
                    table.append(dict(panel=name, element="runaway", fill_ratio=p["fill"], angle_deg=angle,
                                      terminal_velocity_m_s=v, seed=r["seed"], run_id=r["run_id"]))
        titles.append(ax.set_title(name, fontsize=8, loc="left"))
        ax.set_xlabel("fill ratio r", fontsize=8)
        ax.set_ylabel("terminal velocity Vt (m/s)", fontsize=8)
        ax.tick_params(labelsize=7.5)
        ax.set_xlim(-0.05, 1.05)
        ax.set_ylim(0, top)
        ax.grid(alpha=0.3)
        if not left_panel(ax, axes):
            ax.set_ylabel("")
    shared_legend(legend_ax, axes, ncol=4)
    page_title(fig, "Terminal velocity against fill ratio, runs that rolled to the end: median over seeds, bars the "
               f"least to greatest seed (a seed at {RUNAWAY_FACTOR:g}x its point's median or more is a runaway, "
               "marked on the top edge and left out of the median and range)")
    fit_titles(fig, titles)
    return fig, table


def behaviour_map_sweep(rows):
    for r in rows:
        r["_b"] = r["behaviour"] if r["status"] == "ok" or r["behaviour"] == "diverged" else "failed"
    keys, groups = facets(rows, exclude={"fill_ratio", "angle_deg"})
    fig, axes, legend_ax = panels_with_legend_row(len(groups), legend_rows=2)
    present, table, titles = set(), [], []
    for ax, (values, grows) in zip(axes, groups):
        name = panel_label(keys, values)
        fills = sorted({float(r["fill_ratio"]) for r in grows})
        angles = sorted({float(r["angle_deg"]) for r in grows})
        cells = defaultdict(list)
        for r in grows:
            cells[(float(r["fill_ratio"]), float(r["angle_deg"]))].append(r["_b"])
        # Cells centred on the swept values: each reaches half way to its neighbours.
        fx, ay = cell_edges(fills, 0.1), cell_edges(angles, 1.0)
        for (f, a), bs in sorted(cells.items()):
            b, mixed = majority(bs)
            present.add(b)
            i, j = fills.index(f), angles.index(a)
            ax.add_patch(matplotlib.patches.Rectangle((fx[i], ay[j]), fx[i + 1] - fx[i], ay[j + 1] - ay[j],
                                                      facecolor=BEHAVIOUR_COLOURS[b], edgecolor="white", lw=0.5,
                                                      hatch="////" if mixed else None))
            table.append(dict(panel=name, fill_ratio=f, angle_deg=a, fill_from=float(fx[i]), fill_to=float(fx[i + 1]),
                              angle_from_deg=float(ay[j]), angle_to_deg=float(ay[j + 1]), shown=b, runs=len(bs),
                              counts="; ".join(f"{k} {bs.count(k)}" for k in BEHAVIOURS if k in bs),
                              mixed="yes" if mixed else "no"))
        ax.set_xlim(fx[0], fx[-1])
        ax.set_ylim(ay[0], ay[-1])
        if len(fills) <= 9:
            ax.set_xticks(fills)
        if len(angles) <= 12:
            ax.set_yticks(angles)
        ax.tick_params(labelsize=7.5)
        titles.append(ax.set_title(name, fontsize=8, loc="left"))
        ax.set_xlabel("fill ratio r", fontsize=8)
        ax.set_ylabel("ramp angle \u03b8 (deg)" if left_panel(ax, axes) else "", fontsize=8)
    handles = [matplotlib.patches.Patch(color=BEHAVIOUR_COLOURS[b], label=BEHAVIOUR_LABELS[b]) for b in BEHAVIOURS
               if b in present]
    handles.append(matplotlib.patches.Patch(facecolor="white", edgecolor="grey", hatch="////",
                                            label="seeds disagree (majority shown)"))
    legend_ax.legend(handles=handles, loc="center", ncol=3, fontsize=7.5, frameon=False)
    page_title(fig, f"Behaviour over fill ratio and ramp angle ({seeds_count(rows)} seeds per cell; cells centred on "
               "the swept values)")
    fit_titles(fig, titles)
    return fig, table


def speed_vs_time_figure(run_dirs):
    """Speed against time of each run folder, face impacts marked: (figure, table of what it plots)."""
    fig, ax = plt.subplots(figsize=(7.5, 4.6), layout="constrained")
    colours = plt.get_cmap("tab10")
    table = []
    for k, d in enumerate(run_dirs):
        traj = read_rows(os.path.join(d, "trajectory.csv"))
        impacts = read_rows(os.path.join(d, "impacts.csv"))
        with open(os.path.join(d, "summary.json")) as f:
            summary = json.load(f)
        s, res = summary["scene"], summary["results"]
        t = np.array([float(r["time_s"]) for r in traj])
        v = np.array([float(r["speed_m_s"]) for r in traj])
        label = (f"n = {s['shell']['sides']}, {s['fill']['material'].get('preset', 'custom')}, "
                 f"r = {s['fill']['ratio']:g}, {s['ramp']['angle_deg']:g} deg, {model_label(summary)}: "
                 f"{BEHAVIOUR_LABELS.get(res['behaviour'], res['behaviour'])}")
        c = colours(k % 10)
        name = os.path.basename(os.path.normpath(d))
        ax.plot(t, v, color=c, lw=1.2, label=label, gid=f"speed:{name}")
        table += [dict(run=name, element="speed", time_s=a, speed_m_s=b) for a, b in zip(t, v)]
        if impacts:
            ti = np.array([float(r["time_s"]) for r in impacts])
            vi = np.interp(ti, t, v)
            ax.plot(ti, vi, "o", ms=3, color=c, mfc="white", gid=f"impacts:{name}")
            table += [dict(run=name, element="impact", time_s=a, speed_m_s=b) for a, b in zip(ti, vi)]
    ax.plot([], [], "o", ms=3, color="grey", mfc="white", label="face impacts")
    ax.set_xlabel("time since release (s)")
    ax.set_ylabel("lid centre speed along the ramp (m/s)")
    ax.set_title("Speed against time (circles: face impacts)", fontsize=9, loc="left")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.14), frameon=False)
    return fig, table


def sweep_figures(args):
    rows = read_rows(args.results)
    if not rows:
        sys.exit(f"polyroll figures: {args.results} has no rows")
    context = {}
    if args.context:
        with open(args.context) as f:
            context = json.load(f)
    lengths, observations = context.get("ramp_length_m", {}), context.get("observations", [])
    formats = args.format.split(",")
    made = [("distance_vs_angle", d_vs_angle_sweep(rows, lengths, observations), SWEEP_D_COLUMNS),
            ("terminal_velocity_vs_fill", terminal_velocity_sweep(rows), VT_COLUMNS),
            ("behaviour_map", behaviour_map_sweep(rows), SWEEP_MAP_COLUMNS),
            ("speed_vs_time", speed_vs_time_figure(args.trajectory) if args.trajectory else None, SPEED_COLUMNS)]
    for stem, drawn, columns in made:
        if drawn is None:
            print(f"polyroll figures: no {stem}: no run in the table shows it", file=sys.stderr)
            continue
        for path in save_validate_figure(drawn[0], drawn[1], columns, args.out, stem, formats):
            print(f"  figure     {path}")


# ---------------------------------------------------------------------------------------------------
# polyroll figures on a run folder (polyroll run --out) or a compare folder (polyroll compare --out):
# speed against time with the face impacts, and the energy against time, one panel per run.

ENERGY_COLUMNS = ["run", "time_s", "kinetic_J", "potential_J", "dissipated_J"]
ENERGY_STYLES = [("kinetic_J", "kinetic", "#4477aa", "-"), ("potential_J", "potential (from release)", "#228833", "--"),
                 ("dissipated_J", "dissipated", "#ee6677", ":")]


def model_label(summary):
    """The model a run names, and for auto the model(s) it ran: "auto (grains)", "auto (rigid then grains from 0.465 s)"."""
    model = summary["scene"]["run"]["model"]
    choice = summary["results"].get("model_choice")
    if model != "auto" or not choice:
        return model
    ran = choice["model"]
    if choice.get("then") and choice.get("hand_over_time_s") is not None:
        ran += f" then {choice['then']} from {choice['hand_over_time_s']:.3f} s"  # no comma: a CSV cell
    return f"auto ({ran})"


def run_name(summary, d):
    return model_label(summary) if summary else os.path.basename(os.path.normpath(d))


def energy_vs_time_figure(run_dirs):
    """Kinetic, potential and dissipated energy against time, one panel per run, axes shared."""
    fig, axes, legend_ax = panels_with_legend_row(len(run_dirs), height=2.4, legend_rows=1)
    table, titles = [], []
    for ax, d in zip(axes, run_dirs):
        traj = read_rows(os.path.join(d, "trajectory.csv"))
        with open(os.path.join(d, "summary.json")) as f:
            summary = json.load(f)
        name = run_name(summary, d)
        t = [float(r["time_s"]) for r in traj]
        for col, label, colour, style in ENERGY_STYLES:
            ax.plot(t, [num(r[col]) for r in traj], style, color=colour, lw=1.2, label=label, gid=f"{col}:{name}")
        table += [dict(run=name, time_s=float(r["time_s"]), kinetic_J=num(r["kinetic_J"]),
                       potential_J=num(r["potential_J"]), dissipated_J=num(r["dissipated_J"])) for r in traj]
        res = summary["results"]
        titles.append(ax.set_title(f"{name}: {BEHAVIOUR_LABELS.get(res['behaviour'], res['behaviour'])}", fontsize=8,
                                   loc="left"))
        ax.set_xlabel("time since release (s)", fontsize=8)
        ax.set_ylabel("energy (J)" if left_panel(ax, axes) else "", fontsize=8)
        ax.tick_params(labelsize=7.5)
        ax.grid(alpha=0.3)
    shared_legend(legend_ax, axes, ncol=3)
    page_title(fig, "Energy against time: kinetic, potential (relative to the release) and dissipated")
    fit_titles(fig, titles)
    return fig, table


def report_text(run_dirs):
    """A short report of one run or one compare: the scene, then a row per run of what it showed."""
    lines, scene_line = [], None
    for d in run_dirs:
        with open(os.path.join(d, "summary.json")) as f:
            summary = json.load(f)
        s, res = summary["scene"], summary["results"]
        scene_line = scene_line or (f"{s['shell'].get('preset') or 'custom shell'} (n = {s['shell']['sides']}), "
                                    f"{s['fill']['material'].get('preset', 'custom material')}, r = {s['fill']['ratio']:g}, "
                                    f"{s['ramp'].get('preset') or 'custom ramp'} at {s['ramp']['angle_deg']:g} deg, "
                                    f"{s['fidelity'].get('preset') or 'custom'} fidelity")
        vt = res.get("terminal_velocity_m_s")
        lines.append(f"| {run_name(summary, d)} | {BEHAVIOUR_LABELS.get(res['behaviour'], res['behaviour'])} | "
                     f"{res['distance_m']:.3f} | {'-' if vt is None else f'{vt:.3f}'} | {res['impacts']} | "
                     f"{'yes' if res.get('model_valid', True) else 'no'} |")
    return "\n".join([f"# {'Run' if len(run_dirs) == 1 else 'Compare'}: {scene_line}", "",
                      "| model | behaviour | distance D (m) | terminal velocity Vt (m/s) | face impacts | model valid |",
                      "| --- | --- | ---: | ---: | ---: | --- |"] + lines +
                     ["", "Figures: speed_vs_time (face impacts marked), energy_vs_time; each with a CSV of what it "
                      "plots.", ""])


def run_figures(args):
    formats = args.format.split(",")
    report = os.path.join(args.out, "report.md")
    text = report_text(args.runs)
    def write(tmp):
        with open(tmp, "w") as f:
            f.write(text)
    write_whole(report, write)
    print(f"  report     {report}")
    made = [("speed_vs_time", speed_vs_time_figure(args.runs), SPEED_COLUMNS),
            ("energy_vs_time", energy_vs_time_figure(args.runs), ENERGY_COLUMNS)]
    for stem, (fig, table), columns in made:
        for path in save_validate_figure(fig, table, columns, args.out, stem, formats):
            print(f"  figure     {path}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="what", required=True)
    s = sub.add_parser("sweep")
    s.add_argument("results")
    s.add_argument("out")
    s.add_argument("--trajectory", action="append", help="a run folder with trajectory.csv, impacts.csv, summary.json")
    s.add_argument("--context", help="JSON: ramp_length_m by run id, the experiment's observations to draw")
    s.add_argument("--format", default="png", help="png, svg or png,svg")
    for what in ("run", "compare"):
        r = sub.add_parser(what)
        r.add_argument("out")
        r.add_argument("runs", nargs="+", help="run folders with trajectory.csv, impacts.csv, summary.json")
        r.add_argument("--format", default="png", help="png, svg or png,svg")
    t = sub.add_parser("tradeoff")
    t.add_argument("points")
    t.add_argument("out")
    c = sub.add_parser("cross-section")
    c.add_argument("maps", help="cross-section.csv of polyroll tradeoff --dem3d")
    c.add_argument("out")
    v = sub.add_parser("validate")
    v.add_argument("scorecard", help="scorecard.json of polyroll validate")
    v.add_argument("results", help="results.csv of the same folder")
    v.add_argument("out", help="folder for the figures")
    args = p.parse_args()
    if args.what == "sweep":
        sweep_figures(args)
    elif args.what in ("run", "compare"):
        run_figures(args)
    elif args.what == "validate":
        validate_figures(args)
    elif args.what == "cross-section":
        cross_section_figure(args)
    else:
        tradeoff_figure(args)


if __name__ == "__main__":
    main()
