#!/usr/bin/python3
"""What a person sees on the web page, read from the page as laid out in headless Chromium (over its
DevTools protocol, web_devtools.py), at a small window (800x600) and a large one (1920x1080):

  1. a bad address (a value out of range, not a number, an unknown key, ...) is refused in the
     visible status box, styled as an error: its visible text (innerText, which leaves out what
     CSS hides) holds the program's refusal (the bad value and what is allowed), the box lies
     inside the window and on top at its message, the loading note is gone and the empty canvas is
     hidden (the page does not look half-loaded);
  2. the status box's words each stay on one line (no word broken letter by letter) and the box
     fits the window;
  3. once the sandbox draws, the status box is gone and the canvas covers exactly the window (a
     window smaller than the sandbox's 640x480 minimum gets a scaled drawing, not a cut-off one).

The sandbox's own panel (Dear ImGui, drawn inside the canvas) is not part of the page's DOM and is
not measured here.

Usage: web_visible_check.py URL [SCREENSHOT_DIR]
URL is the page (http://127.0.0.1:PORT/index.html). With SCREENSHOT_DIR, a PNG of each state is
saved there to look at. Exit 0 when every check holds, 1 otherwise.
"""
import json
import os
import sys
import time

from web_devtools import Chromium

WINDOWS = [(800, 600), (1920, 1080)]

# Address -> a text the visible status box must hold (the program's refusal, without its name;
# the program's own line from its error stream must be there too, whatever it says).
ALWAYS_CHECKED = [
    ("sides=99", "shell.sides = 99 (from sides=99) is out of range (allowed: 3 to 64)"),
    ("fill=abc", "fill=abc: not a number (allowed: "),
    ("foo=1", "foo: unknown setting in the address (allowed: preset, polygon, sides, fill, material, ramp, angle, "),
]
# More of the mistakes a hand-typed or truncated link holds, at the small window only.
SMALL_WINDOW_ONLY = [
    ("sides=2.5", "sides=2.5: "),
    ("fill=1.5", "fill.ratio = 1.5 (from fill=1.5) is out of range (allowed: "),
    ("angle=", "angle="),
    ("material=sand", "material=sand: unknown material preset 'sand' (allowed: "),
    ("preset=nonagon", "preset=nonagon: unknown (allowed: default, "),
    ("sides=8&sides=9", "sides=9: sides is given twice in the address"),
    ("Sides=8", "Sides: unknown setting in the address"),
    ("=5", "=5: no setting name before the '=' (allowed: preset, "),
    ("paused=yes", "paused=yes: unknown (allowed: 1, 0, or no value)"),
    ("sides=99&fill=abc", "shell.sides = 99 (from sides=99) is out of range (allowed: 3 to 64); fill=abc: not a number (allowed: "),
]

# The visible state of the status box and the canvas, as a JSON string.
STATE_JS = r"""
(() => {
  const box = document.getElementById("status");
  const message = document.getElementById("message");
  const canvas = document.getElementById("canvas");
  const style = getComputedStyle(box);
  const r = box.getBoundingClientRect();
  const m = message.getBoundingClientRect();
  const W = window.innerWidth, H = window.innerHeight;
  const inside = (a, b) => a.left >= b.left - 0.5 && a.top >= b.top - 0.5 && a.right <= b.right + 0.5 &&
                           a.bottom <= b.bottom + 0.5;
  const viewport = { left: 0, top: 0, right: W, bottom: H };
  // Is the message what a person sees at its centre (not covered by anything else)?
  const atCentre = document.elementFromPoint((m.left + m.right) / 2, (m.top + m.bottom) / 2);
  // Words broken across lines: a word laid out in more than one box, unless each of its pieces
  // between break opportunities (after '-' or '/') stays on one line.
  const broken = [];
  const walker = document.createTreeWalker(box, NodeFilter.SHOW_TEXT);
  const range = document.createRange();
  const lines = (node, start, end) => {
    range.setStart(node, start);
    range.setEnd(node, end);
    const tops = new Set();
    for (const rect of range.getClientRects()) if (rect.width > 0) tops.add(Math.round(rect.top));
    return tops.size;
  };
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    if (!node.parentElement.offsetParent && node.parentElement !== box) continue;  // not displayed
    for (const word of node.data.matchAll(/\S+/g)) {
      if (lines(node, word.index, word.index + word[0].length) <= 1) continue;
      let at = word.index;
      for (const piece of word[0].split(/(?<=[-\/])/)) {
        if (lines(node, at, at + piece.length) > 1) broken.push(word[0]);
        at += piece.length;
      }
    }
  }
  const c = canvas.getBoundingClientRect();
  return JSON.stringify({
    window: W + "x" + H,
    shown: style.display !== "none" && style.visibility === "visible" && Number(style.opacity) > 0 &&
           r.width > 0 && r.height > 0,
    error: box.classList.contains("error"),
    border: style.borderTopColor,
    text: box.innerText,
    boxInWindow: inside(r, viewport),
    messageInBox: inside(m, r),
    messageOnTop: !!atCentre && (atCentre === message || message.contains(atCentre)),
    broken: [...new Set(broken)],
    canvasVisible: getComputedStyle(canvas).visibility === "visible" && getComputedStyle(canvas).display !== "none",
    canvasRect: [c.left, c.top, c.right, c.bottom],
    canvasPixels: [canvas.width, canvas.height],
    output: document.getElementById("output").textContent,
  });
})()
"""

# The error colour of index.html's #status.error border.
ERROR_BORDER = "rgb(176, 0, 32)"


def page_state(chromium):
    return json.loads(chromium.evaluate(STATE_JS))


def wait_until(chromium, condition_js, timeout_s):
    end = time.time() + timeout_s
    while time.time() < end:
        if chromium.evaluate(condition_js):
            return True
        time.sleep(0.25)
    return False


def check_refusal(chromium, url, query, expected, shots, size):
    chromium.call("Page.navigate", url=f"{url}?{query}")
    # The program's refusal on its error stream, or the page's own line (an exit, an abort, a frame).
    done = wait_until(chromium, "/polyroll-(web|sandbox): /.test(document.getElementById('output').textContent)", 60)
    time.sleep(0.3)  # the status box is filled in the same task as the line: let it be laid out
    s = page_state(chromium)
    label = f"?{query} at {s['window']}"
    problems = []
    if not done:
        problems.append("the program neither refused the address nor stopped within 60 s")
    refusals = [line.removeprefix("polyroll-sandbox: ") for line in s["output"].splitlines()
                if line.startswith("polyroll-sandbox: ")]
    if not refusals:
        problems.append("the program printed no refusal")
    if not s["shown"]:
        problems.append("the status box is not displayed")
    if not s["error"] or s["border"] != ERROR_BORDER:
        problems.append(f"the status box is not styled as an error (border {s['border']})")
    for text in dict.fromkeys([expected, *refusals]):
        if text not in s["text"]:
            problems.append(f"the visible text lacks {text!r}")
    if "Loading" in s["text"]:
        problems.append("the loading note is still shown")
    if s["canvasVisible"]:
        problems.append("the empty canvas is still shown")
    if not s["boxInWindow"]:
        problems.append("the status box reaches outside the window")
    if not s["messageInBox"] or not s["messageOnTop"]:
        problems.append("the message is covered or scrolled out of its box")
    if s["broken"]:
        problems.append(f"words broken across lines: {s['broken']}")
    if shots:
        name = query.replace("&", "+").replace("=", "-") or "empty"
        chromium.screenshot(os.path.join(shots, f"refused-{name}-{size[0]}x{size[1]}.png"))
    shown = s["text"].replace("\n\n", "\n").replace("\n", " | ")
    print(f"  {label}: {'ok' if not problems else 'FAILED'}: shows: {shown}")
    for p in problems:
        print(f"    web_visible_check: {label}: {p}")
    return not problems


def check_running(chromium, url, query, shots, size):
    chromium.call("Page.navigate", url=f"{url}?{query}" if query else url)
    drew = wait_until(chromium, "document.getElementById('output').textContent.includes('first frame')", 120)
    time.sleep(1.0)  # a few frames after the first
    s = page_state(chromium)
    label = f"{'?' + query if query else 'no address settings'} at {s['window']}"
    problems = []
    if not drew:
        problems.append(f"the page did not draw within 120 s; it printed: {s['output']!r}")
    if s["shown"]:
        problems.append("the status box still covers the canvas after the first frame")
    w, h = (int(v) for v in s["window"].split("x"))
    left, top, right, bottom = s["canvasRect"]
    if abs(left) > 0.5 or abs(top) > 0.5 or abs(right - w) > 0.5 or abs(bottom - h) > 0.5:
        problems.append(f"the canvas covers {s['canvasRect']}, not the window's 0 0 {w} {h}: part of it is cut off "
                        "or the window is not filled")
    pw, ph = s["canvasPixels"]
    if pw < 640 or ph < 480:
        problems.append(f"the canvas draws {pw}x{ph}, below the sandbox's 640x480")
    elif abs(pw / ph - w / h) > 0.01 * (w / h):
        problems.append(f"the canvas draws {pw}x{ph}, stretched to the window's {w}x{h}")
    if shots:
        chromium.screenshot(os.path.join(shots, f"running-{query or 'default'}-{size[0]}x{size[1]}.png"))
    print(f"  {label}: {'ok' if not problems else 'FAILED'}: canvas {pw}x{ph} drawn over {right - left:g}x"
          f"{bottom - top:g} px of the window")
    for p in problems:
        print(f"    web_visible_check: {label}: {p}")
    return not problems


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__)
        return 2
    url = sys.argv[1]
    shots = sys.argv[2] if len(sys.argv) == 3 else None
    if shots:
        os.makedirs(shots, exist_ok=True)
    ok = True
    for size in WINDOWS:
        print(f"web_visible_check: window {size[0]}x{size[1]}")
        with Chromium(180, window_size=size) as chromium:
            cases = ALWAYS_CHECKED + (SMALL_WINDOW_ONLY if size == WINDOWS[0] else [])
            for query, expected in cases:
                ok = check_refusal(chromium, url, query, expected, shots, size) and ok
            for query in ("", "preset=race"):
                ok = check_running(chromium, url, query, shots, size) and ok
    print("web_visible_check: " + ("all checks passed" if ok else "FAILED (above)"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
