#!/usr/bin/python3
"""Every sandbox preset's outcome on the web page against the native program's: for each preset in
assets/sandbox-presets.json (the panel's order), headless Chromium (web_devtools.py, real time)
opens the page at ?preset=NAME, presses G ("Run to end": the rest of the run computed without
drawing, as a visitor's key does) and then E ("Export run": each lane's summary.json downloaded),
until no lane is still running. Each lane's summary holds the scene the page ran; `polyroll run
--scene` runs that scene natively.

A lane agrees when the page's behaviour is the native run's (stopped at the first impact, stopped
after rolling, rolled to the end) and its distance is within 1 % of the native one; where the
distance is further off, the native run is repeated with seeds 2 to 20 and the page's distance must
lie within their spread (widened by 1 %): the WebAssembly build rounds a few functions (sinf, cosf)
differently in the last bit, which may settle the grains into another packing, as another seed
does. A different behaviour, or a distance outside the seeds' spread, fails: the page would show a
class another outcome than the window.

Usage: web_preset_check.py URL [--presets A,B] [--skip C,D] [--seeds 1,2] [--query KEY=VALUE&...]
                           [--native-seeds N] [--polyroll build/polyroll] [--no-native]
URL is the page (http://127.0.0.1:PORT/index.html). --presets runs only those, --skip all but
those (each named as in the file, else exit 2). --seeds runs the page with ?seed=S (default: no
seed key, the page's own default, seed 1); --query adds address keys (angle=21); --no-native
prints the page's outcomes only (for measuring). Exit 0 when every lane agrees, 1 otherwise.
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

from web_devtools import Chromium

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Share of the native distance within which the page's is taken as the same run.
DISTANCE_SHARE = 0.01
# The longest a preset may take on the page (load, build, run to the end, export).
PRESET_TIMEOUT_S = float(os.environ.get("POLYROLL_WEB_PRESET_TIMEOUT_S", "240"))


def lane_number(path):
    m = re.search(r"-lane-(\d+)-summary\.json$", path)
    return int(m.group(1)) if m else 1


def page_outcome(chromium, url, downloads, lanes):
    """Each of the `lanes` lanes' exported summary once no lane is running, or None (with what was
    seen) on timeout."""
    chromium.call("Browser.setDownloadBehavior", browser=True, behavior="allow", downloadPath=downloads)
    chromium.call("Page.navigate", url=url)
    out = chromium.wait_for_output("first frame", 120)
    if "first frame" not in out:
        return None, f"the page did not draw; it printed:\n{out}"
    start, export, rounds, last = time.time(), 0, 0, "nothing exported"
    while time.time() - start < PRESET_TIMEOUT_S:
        # G again each round: a press before the lanes are built is not taken; one during the run
        # to the end changes nothing.
        chromium.press("g", "KeyG", 71)
        chromium.press("e", "KeyE", 69)
        rounds += 1
        # The newest export with all its lanes' summaries (a press the page missed exports nothing:
        # the exports are told apart by their numbers, not counted).
        summaries = None
        for _ in range(20):
            numbers = sorted({int(m.group(1)) for f in os.listdir(downloads)
                              for m in [re.match(r"run-(\d+)-.*summary\.json$", f)] if m})
            newer = [n for n in numbers if n > export]
            if newer:
                files = sorted(glob.glob(os.path.join(downloads, f"run-{newer[-1]:03d}-*summary.json")), key=lane_number)
                try:
                    summaries = [json.load(open(f)) for f in files] if len(files) == lanes else None
                except (OSError, ValueError):
                    summaries = None  # still being written
                if summaries:
                    export = newer[-1]
                    break
            time.sleep(0.25)
        if not summaries:
            last = f"round {rounds}: no new export"
            continue
        results = [s["results"] for s in summaries]
        if all(r["behaviour"] != "running" for r in results):
            return summaries, ""
        last = ", ".join(f"{r['behaviour']} at {r['sim_time_s']:.2f} s" for r in results)
        time.sleep(min(2.0, 0.5 + 0.1 * rounds))
    return None, f"not ended after {PRESET_TIMEOUT_S:.0f} s (last export: {last})"


def native_run(polyroll, scene, seed, work):
    scene = json.loads(json.dumps(scene))
    scene.setdefault("run", {})["seed"] = seed
    path, out = f"{work}-seed{seed}.json", f"{work}-seed{seed}.run"
    with open(path, "w") as f:
        json.dump(scene, f)
    p = subprocess.run([polyroll, "run", "--scene", path, "--json", "--out", out, "--force"],
                       capture_output=True, text=True)
    if p.returncode not in (0, 3):
        raise RuntimeError(f"polyroll run --scene {path} failed (exit {p.returncode}): {p.stderr.strip()}")
    return json.loads(p.stdout)["results"]


def compare(label, page, scene, polyroll, native_seeds, work):
    """The lane's comparison: (what to print, an error message or '')."""
    lines = []
    say = lines.append
    pb, pd = page["behaviour"], page["distance_m"]
    seed = int(scene["run"]["seed"])
    native = native_run(polyroll, scene, seed, work)
    nb, nd = native["behaviour"], native["distance_m"]
    said = f"  {label} (seed {seed}): page {pb}, {pd:.4f} m; polyroll run {nb}, {nd:.4f} m"
    if pb != nb:
        say(said)
        return lines, f"{label}: the page {pb} after {pd:.4f} m, polyroll run {nb} after {nd:.4f} m (the same behaviour expected)"
    if abs(pd - nd) <= DISTANCE_SHARE * abs(nd) + 1e-6:
        say(f"{said}: agree")
        return lines, ""
    others = [native_run(polyroll, scene, s, work) for s in range(1, native_seeds + 1) if s != seed]
    distances = [nd] + [o["distance_m"] for o in others]
    lo, hi = min(distances), max(distances)
    seeds = f"seeds 1 to {native_seeds}"
    behaviours = sorted({nb} | {o["behaviour"] for o in others})
    say(f"{said}; natively {seeds}: {', '.join(behaviours)}, {lo:.4f} to {hi:.4f} m")
    if lo * (1 - DISTANCE_SHARE) <= pd <= hi * (1 + DISTANCE_SHARE):
        say(f"  {label}: agree (the page's distance is inside the native {seeds}' spread)")
        return lines, ""
    return lines, (f"{label}: the page's distance {pd:.4f} m is outside the native {seeds}' spread {lo:.4f} to {hi:.4f} m "
            f"(polyroll run at seed {seed}: {nd:.4f} m)")


def main():
    ap = argparse.ArgumentParser(add_help=False)
    ap.add_argument("url")
    ap.add_argument("--presets", default="")
    ap.add_argument("--skip", default="")
    ap.add_argument("--seeds", default="")
    ap.add_argument("--query", default="")
    # 20 seeds: a stop after rolling comes at one face impact or another, and five seeds can span
    # few of them (stops-abruptly with near contacts: 1.150-1.259 m at seeds 1-5, 1.040-1.397 m at
    # seeds 1-20, where the page's seed 1 stops after 1.397 m as the native seed 12 does). Only lanes
    # whose distance is more than 1% off are rerun.
    ap.add_argument("--native-seeds", type=int, default=20)
    ap.add_argument("--polyroll", default=os.path.join(ROOT, "build", "polyroll"))
    ap.add_argument("--no-native", action="store_true")
    ap.add_argument("-h", "--help", action="store_true")
    a = ap.parse_args()
    if a.help:
        print(__doc__)
        return 0
    with open(os.path.join(ROOT, "assets", "sandbox-presets.json")) as f:
        lane_counts = {name: len(p["lanes"]) for name, p in json.load(f)["presets"].items()}
    presets = list(lane_counts)
    names = a.presets.split(",") if a.presets else presets
    unknown = [n for n in names + [k for k in a.skip.split(",") if k] if n not in presets]
    if unknown:
        print(f"web_preset_check: no such preset: {', '.join(unknown)} (allowed: {', '.join(presets)})")
        return 2
    skipped = [n for n in names if n in a.skip.split(",")]
    names = [n for n in names if n not in skipped]
    if skipped:
        print(f"web_preset_check: not run here (--skip): {', '.join(skipped)}")
    seeds = [s for s in a.seeds.split(",") if s] or [None]
    failures, pending = [], []
    t0 = time.time()
    # The native runs go on beside the browser's next preset (one at a time: the browser has the rest).
    with tempfile.TemporaryDirectory(prefix="polyroll-web-presets-") as scratch, ThreadPoolExecutor(1) as native, \
            Chromium(PRESET_TIMEOUT_S + 60) as chromium:
        for name in names:
            for seed in seeds:
                keys = [f"preset={name}"] + ([a.query] if a.query else []) + ([f"seed={seed}"] if seed else [])
                tag = f"{name}{'-seed' + seed if seed else ''}"
                downloads = os.path.join(scratch, tag)
                os.makedirs(downloads)
                t1 = time.time()
                summaries, why = page_outcome(chromium, f"{a.url}?{'&'.join(keys)}", downloads, lane_counts[name])
                if summaries is None:
                    print(f"  {tag}: {why}", flush=True)
                    failures.append(f"{tag}: {why}")
                    continue
                print(f"  {tag}: the page ran it to the end in {time.time() - t1:.1f} s", flush=True)
                for i, summary in enumerate(summaries):
                    label = f"{tag}{f' lane {i + 1}' if len(summaries) > 1 else ''}"
                    r = summary["results"]
                    if a.no_native:
                        print(f"  {label}: page {r['behaviour']}, {r['distance_m']:.4f} m at {r['sim_time_s']:.2f} s "
                              f"({r['impacts']} impacts)", flush=True)
                        continue
                    pending.append((label, native.submit(compare, label, r, summary["scene"], a.polyroll,
                                                         a.native_seeds, os.path.join(scratch, f"{tag}-lane{i + 1}"))))
        for label, future in pending:
            try:
                lines, error = future.result()
            except (RuntimeError, OSError, ValueError, KeyError) as e:
                lines, error = [], f"{label}: {e}"
            for line in lines:
                print(line)
            if error:
                print(f"  {error}")
                failures.append(error)
    print(f"web_preset_check: {len(names)} presets in {time.time() - t0:.0f} s")
    if failures:
        print("web_preset_check: the page and polyroll run disagree:\n  " + "\n  ".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
