"""Headless Chromium driven over its DevTools protocol, for the web page's scripts in tests/ that a
plain `chromium --dump-dom` cannot do: real (not virtual) time, keys, downloads, resizing. Uses
Debian's python3-websocket (hence /usr/bin/python3); the browser listens on 127.0.0.1 only, on a
port it picks, with a fresh profile, and is ended when the `with` block ends."""
import base64
import json
import os
import shutil
import subprocess
import tempfile
import time
import urllib.request

import websocket  # Debian: python3-websocket

CHROMIUM_FLAGS = [
    "--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
    "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
    "--disable-default-apps", "--mute-audio", "--hide-scrollbars",
    "--remote-debugging-address=127.0.0.1", "--remote-debugging-port=0",
]


class Chromium:
    def __init__(self, timeout_s=600.0, window_size=(1280, 800)):
        """window_size: the browser window's, as --window-size (headless Chromium's page is that wide
        and about 143 px less high: 1280x800 gives a 1280x657 page)."""
        self.timeout_s = timeout_s
        self.window_size = window_size

    def __enter__(self):
        self.profile = tempfile.mkdtemp(prefix="polyroll-chromium-")
        window = f"--window-size={self.window_size[0]},{self.window_size[1]}"
        self.process = subprocess.Popen(["chromium", *CHROMIUM_FLAGS, window, f"--user-data-dir={self.profile}",
                                         "about:blank"],
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        port_file = os.path.join(self.profile, "DevToolsActivePort")
        for _ in range(300):
            if os.path.exists(port_file) and open(port_file).read().count("\n") >= 1:
                break
            time.sleep(0.1)
        port, browser_path = open(port_file).read().split("\n")[:2]
        self.browser = websocket.create_connection(f"ws://127.0.0.1:{port}{browser_path}", timeout=self.timeout_s)
        targets = json.load(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list"))
        page = next(t for t in targets if t.get("type") == "page")
        self.page = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=self.timeout_s)
        self.next_id = 0
        return self

    def __exit__(self, *exc):
        for ws in (self.page, self.browser):
            try:
                ws.close()
            except OSError:
                pass
        self.process.terminate()
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        shutil.rmtree(self.profile, ignore_errors=True)

    def call(self, method, browser=False, **params):
        ws = self.browser if browser else self.page
        self.next_id += 1
        ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            reply = json.loads(ws.recv())
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})

    def evaluate(self, expression):
        return self.call("Runtime.evaluate", expression=expression).get("result", {}).get("value")

    def output(self):
        """What the page printed (its <pre id="output">)."""
        return self.evaluate("(document.getElementById('output') || {}).textContent || ''") or ""

    def wait_for_output(self, text, timeout_s):
        end = time.time() + timeout_s
        while time.time() < end:
            out = self.output()
            if text in out or "polyroll-web: exit" in out or "polyroll-web: abort" in out:
                return out
            time.sleep(0.5)
        return self.output()

    def press(self, key, code, key_code):
        for kind in ("keyDown", "keyUp"):
            self.call("Input.dispatchKeyEvent", type=kind, key=key, code=code, windowsVirtualKeyCode=key_code,
                      nativeVirtualKeyCode=key_code)
            time.sleep(0.3)  # a few of the page's frames, so the sandbox sees the key down, then up

    def screenshot(self, path):
        """Saves what the page shows now (its viewport) as a PNG."""
        data = self.call("Page.captureScreenshot", format="png")["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))
