#!/usr/bin/python3
"""Loads the web page in headless Chromium in real time (no virtual time: the page's clock is the
wall clock) and prints what the page printed once it says its frames are done. For measuring the
page (?bench: frames/s and real-time factor, as polyroll-sandbox --bench; the time to the first
frame), which a virtual-time run (tests/web_checks.sh) cannot: there the page's clock is virtual.

Usage: web_page_run.py URL [TIMEOUT_S]
Exit 0 when the page finished its frames, 1 otherwise. See web_devtools.py for the browser.
"""
import sys

from web_devtools import Chromium


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    timeout_s = float(sys.argv[2]) if len(sys.argv) > 2 else 600.0
    with Chromium(timeout_s) as chromium:
        chromium.call("Page.navigate", url=sys.argv[1])
        text = chromium.wait_for_output("polyroll-web: frames done", timeout_s)
    sys.stdout.write(text)
    return 0 if "polyroll-web: frames done" in text else 1


if __name__ == "__main__":
    sys.exit(main())
