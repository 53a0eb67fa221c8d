#!/usr/bin/env python3
"""The figures of polyroll figures, drawn from a small checked-in sweep (tests/sweep_figures/: a
results table edited by hand to hold every case, the context the C++ side passes, and one short run
folder): no text leaves the canvas or overlaps other text, and each figure's CSV holds the numbers it
plots.

The fixture's results.csv is a real draft sweep of octagon-small (r = 0.125 and 0.375, 10 to 16 deg,
3 seeds) with three edits: two seeds at r = 0.125, 12 deg and one at 14 deg stop after rolling (1.9,
2.1 and 2.3 m), so the third behaviour spans three angles and has a fit (two angles would not: a line
through two always fits); one seed at r = 0.125, 16 deg runs away (1.2 m/s).

Run by ctest ("sweep figures: ..."); exit 77 (skipped) when this Python has no matplotlib.
  check_sweep_figures.py SOURCE_DIR
"""
import importlib.util
import json
import math
import os
import subprocess
import sys
import tempfile

SKIP = 77
FIGURES = ("distance_vs_angle", "terminal_velocity_vs_fill", "behaviour_map", "speed_vs_time")


def load(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def points(line):
    return list(zip(map(float, line.get_xdata()), map(float, line.get_ydata())))


def close(a, b):
    return math.isclose(float(a), float(b), rel_tol=1e-9, abs_tol=1e-9)


def same_points(a, b):
    a, b = sorted(a), sorted(b)
    return len(a) == len(b) and all(close(x, u) and close(y, v) for (x, y), (u, v) in zip(a, b))


def check_d(module, fig, rows, table, csv_rows, check):
    """Every run drawn where its outcome says, the fit over the third behaviour only, the experiment's
    line only in the panel that matches it, the panels sharing their axes; the CSV is the figure."""
    axes = [ax for ax in fig.axes if ax.get_visible() and ax.axison]
    check(len(axes) == 2, f"D: {len(axes)} panels, expected 2 (r = 0.125 and 0.375)")
    check(all(ax.get_ylim() == axes[0].get_ylim() and ax.get_xlim() == axes[0].get_xlim() for ax in axes),
          "D: the panels do not share their axes")
    by_panel = {}
    for ax in axes:
        lines = {ln.get_gid(): ln for ln in ax.get_lines() if ln.get_gid()}
        panel = ax.get_title(loc="left").split("\n")[0]
        by_panel[panel] = lines
        runs = [p for gid, ln in lines.items() if gid.startswith("run:") for p in points(ln)]
        mine = [r for r in csv_rows if r["panel"] == panel and r["element"] == "run"]
        check(same_points(runs, [(r["angle_deg"], r["distance_m"]) for r in mine]),
              f"D {panel}: the CSV's runs are not the plotted markers")
        check(len(mine) == 12, f"D {panel}: {len(mine)} runs in the CSV, expected 12")
    table_by_id = {r["run_id"]: r for r in rows}
    for r in (r for r in csv_rows if r["element"] == "run"):
        t = table_by_id[r["run_id"]]
        want = 2.539 if t["behaviour"] == "rolled_to_end" else float(t["distance_m"])
        check(close(r["distance_m"], want), f"D: run {r['run_id']} drawn at {r['distance_m']}, expected {want}")
    low = by_panel.get("r = 0.125", {})
    stopped = [(float(t["angle_deg"]), float(t["distance_m"])) for t in rows
               if t["fill_ratio"] == "0.125" and t["behaviour"] == "stopped"]
    import numpy as np
    slope, intercept = np.polyfit([a for a, _ in stopped], [d for _, d in stopped], 1)
    fit = points(low["simulation_fit"]) if "simulation_fit" in low else []
    check(same_points(fit, [(10, slope * 10 + intercept), (14, slope * 14 + intercept)]),
          f"D: the fit at r = 0.125 {fit} is not the least squares over its 6 stops after rolling")
    # Stops at two angles only (the runs at 14 deg left out) draw no fit: R^2 1.00 through two points.
    runs = module.sweep_runs([t for t in rows if t["fill_ratio"] == "0.125" and t["angle_deg"] != "14"],
                             {t["run_id"]: 2.539 for t in rows})
    check(module.third_behaviour_fit(runs) is None, "D: a fit is drawn from stops at only two angles")
    check("paper_fit" not in low and "paper_fit" in by_panel.get("r = 0.375", {}),
          "D: the experiment's line is not drawn in exactly the panel matching fig2a (r = 0.375)")
    if "paper_fit" in by_panel.get("r = 0.375", {}):
        check(same_points(points(by_panel["r = 0.375"]["paper_fit"]), [(11.0, 0.6 * 11 - 6.61), (15.2, 0.6 * 15.2 - 6.61)]),
              "D: the experiment's line is not 0.60 m/deg x theta - 6.61 m over 11 to 15.2 deg")
    paper_rows = [(r["angle_deg"], r["distance_m"]) for r in csv_rows if r["element"] == "paper_fit"]
    check(same_points(paper_rows, [(11.0, 0.6 * 11 - 6.61), (15.2, 0.6 * 15.2 - 6.61)]), "D: the CSV's paper_fit rows")
    check(close(axes[0].get_ylim()[1], 1.06 * 2.539), "D: the y axis does not reach the ramp's end (2.539 m)")


def overlapping_texts(fig):
    """Pairs of drawn texts whose boxes overlap (a panel's title running into the next one's), by text.
    Tick labels are left out: matplotlib places those, and a legend's texts are its own layout."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    undrawn = canvas_check.undrawn_tick_labels(fig)
    # Only axes that draw their axis: asking a hidden one (the legend row's) for its tick labels makes them.
    ticks = {id(t) for ax in fig.axes if ax.axison for t in ax.get_xticklabels() + ax.get_yticklabels()}
    in_legends = {id(t) for leg in fig.findobj(lambda a: isinstance(a, matplotlib.legend.Legend))
                  for t in leg.get_texts() + [leg.get_title()]}
    texts = [t for t in fig.findobj(matplotlib.text.Text)
             if t.get_visible() and t.get_text().strip() and id(t) not in undrawn | ticks | in_legends]
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in texts]
    return [(a, b) for i, (a, box_a) in enumerate(boxes) for b, box_b in boxes[i + 1:]
            if box_a.x0 < box_b.x1 - 0.5 and box_b.x0 < box_a.x1 - 0.5 and box_a.y0 < box_b.y1 - 0.5
            and box_b.y0 < box_a.y1 - 0.5]


def check_vt(fig, csv_rows, check):
    """Medians over seeds with the range, the runaway seed marked on the top edge and out of the scale."""
    ax = [a for a in fig.axes if a.get_visible() and a.axison][0]
    top = ax.get_ylim()[1]
    runaway = [r for r in csv_rows if r["element"] == "runaway"]
    check(len(runaway) == 1 and close(runaway[0]["terminal_velocity_m_s"], 1.2) and close(runaway[0]["angle_deg"], 16)
          and close(runaway[0]["fill_ratio"], 0.125), f"Vt: the runaway rows {runaway}")
    check(top < 1.2, f"Vt: the runaway seed (1.2 m/s) sets the y scale (top {top})")
    medians = [r for r in csv_rows if r["element"] == "median"]
    point = [r for r in medians if close(r["angle_deg"], 16) and close(r["fill_ratio"], 0.125)]
    check(len(point) == 1 and float(point[0]["high_m_s"]) < 0.5 and point[0]["seeds"] == "3",
          f"Vt: the runaway seed is in the median's range: {point}")
    drawn = [p for ln in ax.get_lines() if (ln.get_gid() or "").startswith("median:") for p in points(ln)]
    check(same_points(drawn, [(r["fill_ratio"], r["terminal_velocity_m_s"]) for r in medians]),
          "Vt: the CSV's medians are not the plotted points")
    marks = [p for ln in ax.get_lines() if ln.get_gid() == "runaway" for p in points(ln)]
    check(same_points(marks, [(0.125, top)]), f"Vt: the runaway mark {marks} is not on the top edge at r = 0.125")


def check_map(fig, csv_rows, check):
    """Cells centred on the swept values; the legend in its own row under the panels."""
    for r in csv_rows:
        f, a = float(r["fill_ratio"]), float(r["angle_deg"])
        check(close((float(r["fill_from"]) + float(r["fill_to"])) / 2, f)
              and close((float(r["angle_from_deg"]) + float(r["angle_to_deg"])) / 2, a),
              f"map: the cell at r = {f}, {a} deg is not centred on them")
    check(len(csv_rows) == 8, f"map: {len(csv_rows)} cells, expected 2 fills x 4 angles")
    legends = [a.get_legend() for a in fig.axes if a.get_legend()]
    panel = [a for a in fig.axes if a.axison][0]
    renderer = fig.canvas.get_renderer()
    check(len(legends) == 1 and legends[0].get_window_extent(renderer).y1 <= panel.get_window_extent(renderer).y0,
          "map: the legend is not below the panels")


def main():
    source_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    if not all(importlib.util.find_spec(m) for m in ("matplotlib", "numpy")):
        print("skipped: this Python has no matplotlib/numpy")
        return SKIP
    script = os.path.join(source_dir, "src", "figures", "polyroll_figures.py")
    module = load(script, "polyroll_figures")
    # The canvas check and the report are polyroll validate's own (one check for every figure the script draws).
    canvas = load(os.path.join(source_dir, "tests", "check_validate_figures.py"), "check_validate_figures")
    global canvas_check, matplotlib
    canvas_check = canvas
    import matplotlib
    import matplotlib.legend
    import matplotlib.text
    fixture = os.path.join(source_dir, "tests", "sweep_figures")
    results, context_path, run_dir = (os.path.join(fixture, n) for n in ("results.csv", "context.json", "run"))
    rows = module.read_rows(results)
    with open(context_path) as f:
        context = json.load(f)
    failures = []

    def check(ok, what):
        if not ok:
            failures.append(what)

    import matplotlib.pyplot as plt
    figures = {
        "distance_vs_angle": module.d_vs_angle_sweep(rows, context["ramp_length_m"], context["observations"]),
        "terminal_velocity_vs_fill": module.terminal_velocity_sweep(module.read_rows(results)),
        "behaviour_map": module.behaviour_map_sweep(module.read_rows(results)),
        "speed_vs_time": module.speed_vs_time_figure([run_dir]),
        "energy_vs_time": module.energy_vs_time_figure([run_dir, run_dir]),
    }
    for name, (fig, _) in figures.items():
        outside, tight_inside = canvas.texts_outside(fig)
        check(not outside, f"{name}: text outside the canvas: {outside}")
        check(tight_inside, f"{name}: the tight bounding box leaves the canvas")
        overlaps = overlapping_texts(fig)
        check(not overlaps, f"{name}: texts overlap: {overlaps}")
    # The overlap check must catch two panels' long titles running into each other, or it proves nothing.
    fig, (left, right) = plt.subplots(1, 2, figsize=(4, 2))
    left.set_title("a title long enough to run into the next panel's", loc="left")
    right.set_title("the next panel's title", loc="left")
    check(overlapping_texts(fig), "overlapping titles are not caught by the check")
    plt.close(fig)
    # A small sweep (2 seeds, 12 and 14 deg) whose three panels differ in every facet, as a user drew
    # one: long panel titles side by side, none running into the next.
    base = [t for t in rows if t["fill_ratio"] == "0.125" and t["angle_deg"] in ("12", "14") and t["seed"] in ("1", "2")]
    small = []
    for k, (model, fidelity, polygon, sides, release, material) in enumerate(
            (("grains", "standard", "octagon-small", "8", "vertex", "bb"),
             ("segments", "draft", "hexagon-small", "6", "face", "rice"),
             ("rigid", "fine", "hexagon-large", "6", "vertex", "peas"))):
        small += [dict(t, run_id=f"{t['run_id']}{k}", model=model, fidelity=fidelity, polygon=polygon, sides=sides,
                       release=release, material=material) for t in base]
    lengths = {t["run_id"]: 2.539 for t in small}
    for name, fig in (("D", module.d_vs_angle_sweep([dict(t) for t in small], lengths, [])[0]),
                      ("Vt", module.terminal_velocity_sweep([dict(t) for t in small])[0]),
                      ("map", module.behaviour_map_sweep([dict(t) for t in small])[0])):
        check(not overlapping_texts(fig), f"small sweep {name}: texts overlap: {overlapping_texts(fig)}")
        outside, _ = canvas.texts_outside(fig)
        check(not outside, f"small sweep {name}: text outside the canvas: {outside}")
        plt.close(fig)
    with tempfile.TemporaryDirectory() as out:
        done = subprocess.run([sys.executable, script, "sweep", results, out, "--context", context_path,
                               "--trajectory", run_dir, "--format", "png,svg"], capture_output=True, text=True)
        check(done.returncode == 0, f"the script failed: {done.stderr}")
        names = sorted(os.listdir(out))
        want = sorted(f"{stem}.{ext}" for stem in FIGURES for ext in ("png", "svg", "csv"))
        check(names == want, f"files written: {names}, expected {want}")
        if names == want:
            csvs = {stem: module.read_rows(os.path.join(out, f"{stem}.csv")) for stem in FIGURES}
            check_d(module, figures["distance_vs_angle"][0], rows, None, csvs["distance_vs_angle"], check)
            check_vt(figures["terminal_velocity_vs_fill"][0], csvs["terminal_velocity_vs_fill"], check)
            check_map(figures["behaviour_map"][0], csvs["behaviour_map"], check)
            speed = csvs["speed_vs_time"]
            trajectory = module.read_rows(os.path.join(run_dir, "trajectory.csv"))
            check(len([r for r in speed if r["element"] == "speed"]) == len(trajectory),
                  "speed_vs_time: the CSV does not hold every trajectory row")
    for fig, _ in figures.values():
        plt.close(fig)
    return canvas_check.report(failures)


if __name__ == "__main__":
    sys.exit(main())
