#!/usr/bin/python3
"""The page's "Export run" (key E) hands the run's files to the browser as downloads: loads the page
(default scene, playing in real time), lets it run for 20 s, presses E, and checks that
summary.json, trajectory.csv and impacts.csv arrive in the download folder, the summary readable
JSON with the run's behaviour. For tests/web_checks.sh.

Usage: web_export_check.py URL
"""
import json
import os
import sys
import tempfile
import time

from web_devtools import Chromium

EXPECTED = ["run-001-summary.json", "run-001-trajectory.csv", "run-001-impacts.csv"]


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    with tempfile.TemporaryDirectory() as downloads, Chromium(300) as chromium:
        chromium.call("Browser.setDownloadBehavior", browser=True, behavior="allow", downloadPath=downloads)
        chromium.call("Page.navigate", url=sys.argv[1])
        if "first frame" not in chromium.wait_for_output("first frame", 120):
            print(f"web_export_check: the page did not draw; it printed:\n{chromium.output()}")
            return 1
        # Let the run go on for a while (the default scene ends 3.6 s into the page's run, which
        # plays at 0.3x to 1x real time on this machine); an export mid-run is as valid, its
        # behaviour then "running".
        time.sleep(20)
        chromium.press("e", "KeyE", 69)
        end = time.time() + 30
        while time.time() < end and sorted(os.listdir(downloads)) != sorted(EXPECTED):
            time.sleep(0.5)
        got = sorted(os.listdir(downloads))
        if got != sorted(EXPECTED):
            print(f"web_export_check: downloads {got}, expected {sorted(EXPECTED)}")
            return 1
        summary = json.load(open(os.path.join(downloads, "run-001-summary.json")))
        behaviour = summary["results"]["behaviour"]
        rows = open(os.path.join(downloads, "run-001-trajectory.csv")).read().count("\n")
        print(f"web_export_check: downloaded {', '.join(got)}; behaviour {behaviour}, {rows} trajectory lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
