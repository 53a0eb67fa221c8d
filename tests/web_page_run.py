#!/usr/bin/python3
"""Loads the web page in headless Chromium in real time (no virtual time: the page's clock is the
wall clock) and prints what the page printed once it says its frames are done. For measuring the
page (?bench: frames/s and real-time factor, as polyroll-sandbox --bench; the time to the first
frame), which a virtual-time run (tests/web_checks.sh) cannot: there the page's clock is virtual.

Usage: web_page_run.py URL [TIMEOUT_S]
Drives Chromium over its DevTools protocol with Debian's python3-websocket (hence /usr/bin/python3);
the browser listens on 127.0.0.1 only and is ended when the script ends. Exit 0 when the page
finished, 1 otherwise.
"""
import json
import os
import subprocess
import sys
import tempfile
import time
import urllib.request

import websocket  # Debian: python3-websocket

CHROMIUM_FLAGS = [
    "--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
    "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
    "--disable-default-apps", "--mute-audio", "--window-size=1280,800", "--hide-scrollbars",
    "--remote-debugging-address=127.0.0.1", "--remote-debugging-port=0",
]


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    url = sys.argv[1]
    timeout_s = float(sys.argv[2]) if len(sys.argv) > 2 else 600.0
    with tempfile.TemporaryDirectory() as profile:
        browser = subprocess.Popen(["chromium", *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "about:blank"],
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            port_file = os.path.join(profile, "DevToolsActivePort")
            for _ in range(200):
                if os.path.exists(port_file) and open(port_file).read().count("\n") >= 1:
                    break
                time.sleep(0.1)
            port = int(open(port_file).read().split("\n")[0])
            targets = json.load(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list"))
            page = next(t for t in targets if t.get("type") == "page")
            ws = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=timeout_s)
            next_id = [0]

            def call(method, **params):
                next_id[0] += 1
                ws.send(json.dumps({"id": next_id[0], "method": method, "params": params}))
                while True:
                    reply = json.loads(ws.recv())
                    if reply.get("id") == next_id[0]:
                        return reply.get("result", {})

            call("Page.navigate", url=url)
            end = time.time() + timeout_s
            text = ""
            while time.time() < end:
                time.sleep(1.0)
                got = call("Runtime.evaluate",
                           expression="(document.getElementById('output') || {}).textContent || ''")
                text = got.get("result", {}).get("value", "") or ""
                if "polyroll-web: frames done" in text or "polyroll-web: exit" in text or "abort" in text:
                    break
            ws.close()
        finally:
            browser.terminate()
            try:
                browser.wait(timeout=10)
            except subprocess.TimeoutExpired:
                browser.kill()
    sys.stdout.write(text)
    return 0 if "polyroll-web: frames done" in text else 1


if __name__ == "__main__":
    sys.exit(main())
