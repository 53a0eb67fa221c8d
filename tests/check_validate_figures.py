#!/usr/bin/env python3
"""The figures of polyroll validate, drawn from a small hand-made scorecard and results table
(tests/validate_figures/): no text leaves the canvas, and each figure's CSV holds the numbers it plots.

Run by ctest ("validate figures: ..."); exit 77 (skipped) when this Python has no matplotlib.
  check_validate_figures.py SOURCE_DIR
"""
import csv
import importlib.util
import json
import math
import os
import subprocess
import sys
import tempfile

SKIP = 77


def load_script(source_dir):
    path = os.path.join(source_dir, "src", "figures", "polyroll_figures.py")
    spec = importlib.util.spec_from_file_location("polyroll_figures", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module, path


def undrawn_tick_labels(fig):
    """Tick labels matplotlib keeps but does not draw: their ticks lie outside the axis' view."""
    skip = set()
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            lo, hi = sorted(axis.get_view_interval())
            tiny = 1e-9 * max(1.0, abs(hi - lo))
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                if not (lo - tiny <= tick.get_loc() <= hi + tiny):
                    skip.update({id(tick.label1), id(tick.label2)})
    return skip


def texts_outside(fig):
    """The text artists (titles, labels, ticks, legends) reaching beyond the figure, and whether the
    figure's tight bounding box (everything drawn) lies within its extent."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    canvas = fig.bbox  # pixels
    eps = 0.5
    outside = []
    undrawn = undrawn_tick_labels(fig)
    for t in fig.findobj(lambda a: hasattr(a, "get_text") and hasattr(a, "get_window_extent")):
        if not t.get_visible() or not t.get_text().strip() or id(t) in undrawn:
            continue
        box = t.get_window_extent(renderer)
        if box.x0 < canvas.x0 - eps or box.y0 < canvas.y0 - eps or box.x1 > canvas.x1 + eps or box.y1 > canvas.y1 + eps:
            outside.append(t.get_text())
    tight = fig.get_tightbbox(renderer)  # inches
    width, height = fig.get_size_inches()
    eps_in = eps / fig.dpi
    tight_inside = (tight.x0 >= -eps_in and tight.y0 >= -eps_in and tight.x1 <= width + eps_in
                    and tight.y1 <= height + eps_in)
    return outside, tight_inside


def check(condition, what, failures):
    if not condition:
        failures.append(what)


def report(failures):
    """Prints each failure and the verdict; the exit status (also check_sweep_figures.py's)."""
    for f in failures:
        print("FAILED:", f)
    print("ok" if not failures else f"{len(failures)} check(s) failed")
    return 1 if failures else 0


def close(a, b):
    return math.isclose(float(a), float(b), rel_tol=1e-9, abs_tol=1e-9)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def check_canvas(module, scorecard, runs_by_id, failures):
    import matplotlib.pyplot as plt
    band = scorecard["observations"][0]
    figures = {"D against theta": module.d_vs_angle_figure(band, runs_by_id[band["id"]])[0],
               "behaviour map": module.behaviour_map_figure(scorecard, runs_by_id)[0]}
    for name, fig in figures.items():
        outside, tight_inside = texts_outside(fig)
        check(not outside, f"{name}: text outside the canvas: {outside}", failures)
        check(tight_inside, f"{name}: the tight bounding box leaves the canvas", failures)
    # The check itself must catch a clipped title, or it proves nothing.
    fig, ax = plt.subplots(figsize=(3, 2))
    ax.set_title("a title far too long to fit on a canvas three inches wide, clipped at both ends")
    outside, tight_inside = texts_outside(fig)
    check(outside and not tight_inside, "a clipped title is not caught by the check", failures)
    for fig in list(figures.values()) + [fig]:
        plt.close(fig)
    return figures


def plotted_lines(module, scorecard, runs_by_id):
    """The (x, y) points of every line of the D-against-theta figure, by its gid."""
    import matplotlib.pyplot as plt
    band = scorecard["observations"][0]
    fig, _ = module.d_vs_angle_figure(band, runs_by_id[band["id"]])
    lines = {}
    for line in fig.axes[0].get_lines():  # a gid drawn as several lines (the median, cut by behaviour): all its points
        if line.get_gid():
            lines[line.get_gid()] = sorted(lines.get(line.get_gid(), []) +
                                           list(zip(map(float, line.get_xdata()), map(float, line.get_ydata()))))
    plt.close(fig)
    return lines


def check_d_csv(rows, lines, fixture_rows, failures):
    """The CSV's rows are the figure's points, and the runs' points are the table's, drawn where the
    figure promises (rolled to the end: the ramp's length; failed: 0)."""
    by_element = {}
    for r in rows:
        by_element.setdefault(r["element"], []).append(r)
    runs = by_element.get("run", [])
    check(len(runs) == 14, f"D csv: {len(runs)} run rows, expected 14", failures)
    table = {r["run_id"]: r for r in fixture_rows}
    for r in runs:
        t = table[r["run_id"]]
        want = 2.539 if t["behaviour"] == "rolled_to_end" else (0.0 if t["status"] != "ok" else float(t["distance_m"]))
        check(close(r["distance_m"], want) and close(r["angle_deg"], t["angle_deg"]),
              f"D csv: run {r['run_id']} at ({r['angle_deg']}, {r['distance_m']}), table says ({t['angle_deg']}, {want})",
              failures)
        behaviour = "failed" if t["status"] != "ok" else t["behaviour"]
        check(r["behaviour"] == behaviour, f"D csv: run {r['run_id']} is {r['behaviour']}, table {behaviour}", failures)
    for gid, element in (("seed_median", "seed_median"), ("paper_fit", "paper_fit"),
                         ("simulation_fit", "simulation_fit")):
        want = sorted((float(r["angle_deg"]), float(r["distance_m"])) for r in by_element.get(element, []))
        got = lines.get(gid, [])
        check(len(want) == len(got) and all(close(a, c) and close(b, d) for (a, b), (c, d) in zip(want, got)),
              f"D csv: {element} rows {want} differ from the plotted line {got}", failures)
    run_points = sorted((float(r["angle_deg"]), float(r["distance_m"])) for r in runs)
    plotted = sorted(p for gid, pts in lines.items() if gid.startswith("run:") for p in pts)
    check(run_points == plotted, "D csv: the run rows differ from the plotted run markers", failures)
    median_12 = [r for r in by_element.get("seed_median", []) if close(r["angle_deg"], 12)]
    check(len(median_12) == 1 and close(median_12[0]["distance_m"], 0.535) and close(median_12[0]["low_m"], 0.45)
          and close(median_12[0]["high_m"], 0.62), f"D csv: median at 12 deg: {median_12}", failures)
    paper = sorted((float(r["angle_deg"]), float(r["distance_m"])) for r in by_element.get("paper_fit", []))
    check(len(paper) == 2 and close(paper[0][0], 11.0) and close(paper[0][1], 0.60 * 11.0 - 6.61)
          and close(paper[1][0], 15.2) and close(paper[1][1], 0.60 * 15.2 - 6.61),
          f"D csv: the paper's line {paper}", failures)


def check_map_csv(rows, failures):
    cells = [r for r in rows if r["row"] != "experiment"]
    check(len(cells) == 7 + 1 + 4, f"map csv: {len(cells)} simulation cells, expected 12", failures)
    mixed = [r for r in cells if r["observation"] == "never" and r["row"] == "shell.preset=octagon-small"
             and close(r["angle_deg"], 12)]
    check(len(mixed) == 1 and mixed[0]["shown"] == "stopped" and mixed[0]["mixed"] == "yes"
          and mixed[0]["agreeing"] == "1" and close(mixed[0]["cell_from_deg"], 10) and close(mixed[0]["cell_to_deg"], 14),
          f"map csv: the mixed octagon cell at 12 deg: {mixed}", failures)
    band = [r for r in rows if r["observation"] == "band" and r["row"] == "experiment" and r["shown"] == "stopped"]
    check(len(band) == 1 and close(band[0]["cell_from_deg"], 11.0) and close(band[0]["cell_to_deg"], 15.2),
          f"map csv: the experiment's band: {band}", failures)


def check_measured_only(module, script, scorecard, results_path, failures):
    """An observation holding only a lab's measured numbers (terminal_velocity_m_s; no behaviour, as
    assets/experiment.json's format allows) is drawn in the behaviour map with what was measured: the
    script raised KeyError: 'behaviour' and drew nothing."""
    measured = dict(scorecard["observations"][1], id="my-lab-vt", source="my lab: Vt only",
                    experiment={"behaviour_share": 1.0},
                    checks=[{"check": "terminal velocity", "experiment": "0.3 m/s (+/- 0.05)", "simulation": "",
                             "agree": True, "difference": 0.01, "unit": "m/s", "by": "+0.01 m/s"}])
    doc = dict(scorecard, observations=[measured])
    with tempfile.TemporaryDirectory() as out:
        path = os.path.join(out, "scorecard.json")
        with open(path, "w") as f:
            json.dump(doc, f)
        done = subprocess.run([sys.executable, script, "validate", path, results_path, out], capture_output=True,
                              text=True)
        check(done.returncode == 0, f"measured only: the script failed: {done.stderr}", failures)
        check(os.path.exists(os.path.join(out, "behaviour_map.png")), "measured only: no behaviour map drawn", failures)
        if os.path.exists(os.path.join(out, "behaviour_map.csv")):
            rows = read_csv(os.path.join(out, "behaviour_map.csv"))
            experiment = [r for r in rows if r["row"] == "experiment"]
            check(experiment and all(r["shown"] == "measured only" for r in experiment),
                  f"measured only: the experiment row {experiment}", failures)
            check(all(r["agreeing"] == "" for r in rows if r["row"] != "experiment"),
                  "measured only: cells count seeds agreeing with a behaviour nobody observed", failures)


def main():
    source_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    if not all(importlib.util.find_spec(m) for m in ("matplotlib", "numpy")):
        print("skipped: this Python has no matplotlib/numpy")
        return SKIP
    module, script = load_script(source_dir)
    fixture = os.path.join(source_dir, "tests", "validate_figures")
    scorecard_path, results_path = os.path.join(fixture, "scorecard.json"), os.path.join(fixture, "results.csv")
    with open(scorecard_path) as f:
        scorecard = json.load(f)
    fixture_rows = read_csv(results_path)
    table_by_id = {r["run_id"]: r for r in fixture_rows}
    runs_by_id = {o["id"]: module.observation_runs(o, table_by_id) for o in scorecard["observations"]}
    failures = []
    check_canvas(module, scorecard, runs_by_id, failures)
    lines = plotted_lines(module, scorecard, runs_by_id)
    with tempfile.TemporaryDirectory() as out:
        # As polyroll validate runs it: the script's own command line.
        done = subprocess.run([sys.executable, script, "validate", scorecard_path, results_path, out],
                              capture_output=True, text=True)
        check(done.returncode == 0, f"the script failed: {done.stderr}", failures)
        names = sorted(os.listdir(out))
        want = sorted(f"{stem}.{ext}" for stem in ("d_vs_angle-band", "behaviour_map") for ext in ("png", "svg", "csv"))
        check(names == want, f"files written: {names}, expected {want} (no temporary left)", failures)
        for name in want:
            check(f"  figure     {os.path.join(out, name)}" in done.stdout, f"{name} not listed: {done.stdout}",
                  failures)
        if names == want:
            check_d_csv(read_csv(os.path.join(out, "d_vs_angle-band.csv")), lines, fixture_rows, failures)
            check_map_csv(read_csv(os.path.join(out, "behaviour_map.csv")), failures)
    check_measured_only(module, script, scorecard, results_path, failures)
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
