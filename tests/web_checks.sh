#!/bin/sh
# The web page (build-web/, README's web command) in a real browser: headless Chromium loads it from
# a local server on 127.0.0.1 and plays N frames of a scene (?frames=N: each frame 1/60 s of simulated
# time, as polyroll-sandbox --frames), printing each lane's first impact and scene. Checked:
#   1. every bundled preset (assets/sandbox-presets.json) shows on the page the outcome the native
#      program gives (tests/web_preset_check.py: the page runs each preset to its end with key G and
#      exports its lanes' summaries with key E; `polyroll run --scene` runs the same scenes): the
#      same behaviour, and a distance within 1 % of the native run's or inside the native seeds 1 to
#      20's spread; any other outcome fails;
#   2. for the default scene and `race`, every lane's first face impact is the one `polyroll run
#      --scene` gives for the same scene (its time within one tracker step, its position within 1 %:
#      the same C++ compiled to WebAssembly, only floating-point details may differ);
#   3. the page's screenshot matches the native sandbox's capture of the same scene, frame count
#      and size (polyroll-sandbox --frames N --screenshot, under Xvfb) within a tolerance on pixel
#      differences (tests/web_compare_png.py);
#   4. what a person sees, read from the laid-out page at an 800x600 and a 1920x1080 window
#      (tests/web_visible_check.py): a bad address (?sides=99, ?fill=abc, ?foo=1 and more) is refused
#      in the visible status box, styled as an error, naming the value and what is allowed, and
#      nothing is left loading; once the sandbox draws, its canvas covers exactly the window;
#   5. "Export run" (key E) downloads summary.json, trajectory.csv and impacts.csv
#      (tests/web_export_check.py, over Chromium's DevTools protocol in real time).
# Needs build/ (native) and build-web/. Exits non-zero on the first failure.
set -eu
cd "$(dirname "$0")/.."
[ -f build-web/polyroll-sandbox.wasm ] || { echo "web_checks: build-web/ is missing: run the README's web command" >&2; exit 1; }
[ -x build/polyroll ] || { echo "web_checks: build/polyroll is missing: build the native programs first" >&2; exit 1; }
scratch=$(mktemp -d "${TMPDIR:-/tmp}/polyroll-web-checks.XXXXXX")
server_pid=""
cleanup() {
    if [ -n "$server_pid" ]; then kill "$server_pid" 2>/dev/null || true; fi
    rm -rf "$scratch"
}
trap cleanup EXIT
t0=$(date +%s)
step() { echo "== web_checks [$(( $(date +%s) - t0 )) s]: $*"; }

# Frames for the first impacts (the page advances 1/60 s per frame whatever the machine's speed):
# every lane of the default scene and the race meets its first face at about 0.33 s (measured).
impact_frames=${POLYROLL_WEB_IMPACT_FRAMES:-60}
# Presets whose outcome is not compared here, for time: the large hexagon half full of BBs (1488
# grains) costs about 70 s of CPU natively and more on the page, more than all the others together
# (its page and native runs agreed: docs/sandbox.md). POLYROLL_WEB_SKIP_PRESETS= (empty) runs it too.
skip_presets=${POLYROLL_WEB_SKIP_PRESETS-hexagon-large-bb}
# The screenshots are taken after fewer frames (cheaper; the polygons are moving).
shot_frames=${POLYROLL_WEB_SHOT_FRAMES:-45}
size_w=1280
size_h=800
# Share of pixels allowed to differ between the page's picture and the native one (see the script).
max_share=${POLYROLL_WEB_MAX_PIXEL_SHARE:-0.02}

# A free port on 127.0.0.1 only (the page is never served beyond this machine).
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server --bind 127.0.0.1 --directory build-web "$port" >"$scratch/server.log" 2>&1 &
server_pid=$!
for _ in 1 2 3 4 5 6 7 8 9 10; do
    python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/index.html')" 2>/dev/null && break
    sleep 0.5
done

# Headless Chromium with WebGL 2 on the CPU (SwiftShader), a fresh profile, nothing fetched from the
# network (the machine has none beyond its mirrors). Virtual time lets the page's frames run as fast
# as the CPU draws them; the budget only bounds a page that never finishes.
chrome() {
    profile=$(mktemp -d "$scratch/profile.XXXXXX")
    chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
        --disable-background-networking --disable-component-update --disable-sync --no-first-run \
        --disable-default-apps --mute-audio --user-data-dir="$profile" --window-size=$size_w,$size_h \
        --hide-scrollbars --virtual-time-budget=600000 "$@" 2>>"$scratch/chromium.log"
}

# The page's printed lines (the <pre id="output"> of the dumped page), HTML entities decoded.
page_output() {
    chrome --dump-dom "http://127.0.0.1:$port/index.html?$1" |
        python3 -c 'import sys, html, re
m = re.search(r"<pre id=\"output\">(.*?)</pre>", sys.stdin.read(), re.S)
print(html.unescape(m.group(1)) if m else "")'
}

check_scene() {
    name=$1
    query=$2
    frames=$3
    step "$name: $frames frames in Chromium, each lane's first impact against polyroll run"
    page_output "$query&frames=$frames" >"$scratch/$name.out"
    grep -q '^polyroll-web: frames done' "$scratch/$name.out" || {
        echo "web_checks: the page did not finish its frames; it printed:" >&2
        cat "$scratch/$name.out" >&2
        tail -n 20 "$scratch/chromium.log" >&2
        exit 1
    }
    grep '^polyroll-web: \(first frame\|lane [0-9]*:\)' "$scratch/$name.out"
    lanes=$(grep -c '^polyroll-web: lane [0-9]*:' "$scratch/$name.out")
    [ "$lanes" -ge 1 ] || { echo "web_checks: $name: no lane reported" >&2; exit 1; }
    # The native run needs only the page's stretch of time (and a second more) for its impacts.
    limit=$(python3 -c "print($frames / 60 + 1)")
    i=1
    while [ "$i" -le "$lanes" ]; do
        grep "^polyroll-web: lane $i scene " "$scratch/$name.out" | sed "s/^polyroll-web: lane $i scene //" \
            >"$scratch/$name-lane$i.json"
        build/polyroll run --scene "$scratch/$name-lane$i.json" --time-limit "$limit" --json \
            --out "$scratch/$name-lane$i.run" >"$scratch/$name-lane$i.native.json" || {
            rc=$?
            [ "$rc" -eq 3 ] || { echo "web_checks: polyroll run failed (exit $rc)" >&2; exit 1; }
        }
        line=$(grep "^polyroll-web: lane $i:" "$scratch/$name.out")
        impact=$(grep "^polyroll-web: lane $i first impact:" "$scratch/$name.out" || true)
        python3 - "$line" "$scratch/$name-lane$i.native.json" "$name lane $i" "$limit" "$impact" \
            "$scratch/$name-lane$i.run/impacts.csv" "$scratch/$name-lane$i.json" "$scratch/$name-lane$i" <<'PY'
import csv, json, os, re, subprocess, sys
line, native_path, label, limit = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
impact_line, native_impacts, lane_scene, work = sys.argv[5], sys.argv[6], sys.argv[7], sys.argv[8]
m = re.match(r"polyroll-web: lane \d+: behaviour (\S+), distance (\S+) m at (\S+) s", line)
if not m:
    sys.exit(f"web_checks: {label}: unreadable line: {line}")
page_time_s = float(m.group(3))
# The first face impact must agree, strictly: up to it the page and the native run follow the same
# path (within floating-point details); only after it can a tipping point part them (each preset's
# end is compared by tests/web_preset_check.py, against the native seeds' spread).
rows = [r for r in csv.DictReader(open(native_impacts)) if float(r["time_s"]) <= page_time_s]
if not (rows or impact_line):
    sys.exit(f"web_checks: {label}: no face impact in the page's {page_time_s:.2f} s: raise POLYROLL_WEB_IMPACT_FRAMES")
if not (rows and impact_line):
    sys.exit(f"web_checks: {label}: first impact on one side only (page: {impact_line or 'none'}; native: {len(rows)} impacts)")
m = re.match(r"polyroll-web: lane \d+ first impact: time (\S+) s, position (\S+) m, kinetic before (\S+) J", impact_line)
if not m:
    sys.exit(f"web_checks: {label}: unreadable line: {impact_line}")
page = [float(g) for g in m.groups()]
native = [float(rows[0][k]) for k in ("time_s", "position_m", "kinetic_before_J")]
# An impact is seen at a tracker step (1 ms at the standard fidelity): the page may see it one step
# earlier or later, and the kinetic energy "before" it then falls on either side of part of the
# impact (a full hexagon's: 0.0184 J against 0.0256 J, one step apart), so that energy is printed,
# not compared; the time must agree within one step and the position within 1 %.
step_s = 1.0 / json.load(open(native_path))["scene"]["fidelity"]["step_hz"]
dt, dx = abs(page[0] - native[0]), abs(page[1] - native[1]) / abs(native[1])
print(f"  {label} first impact: page {page[0]:.4f} s, {page[1]:.6f} m, {page[2]:.6g} J before; polyroll run "
      f"{native[0]:.4f} s, {native[1]:.6f} m, {native[2]:.6g} J (time {1000 * dt:.1f} ms apart, position {100 * dx:.3f} %)")
if dt > step_s * 1.000001 or dx > 0.01:
    # A fine pile settles, before the release, into one of a few packings, and a change in the
    # last bits picks which: the full hexagon of 217 discs reaches its first impact at 0.328 s
    # natively at 20 and 20.0001 deg, at 0.330 s (0.4 mm further) at 19.999 deg. So a page whose
    # first impact is not the native run's must match the native run of the same scene with its
    # angle moved by at most 0.001 deg.
    def first_impact(angle_change_deg):
        scene = json.load(open(lane_scene))
        scene.setdefault("ramp", {})["angle_deg"] = float(scene["ramp"]["angle_deg"]) + angle_change_deg
        path, out = f"{work}.{angle_change_deg:+g}.json", f"{work}.{angle_change_deg:+g}.run"
        json.dump(scene, open(path, "w"))
        subprocess.run(["build/polyroll", "run", "--scene", path, "--time-limit", limit, "--out", out, "--force"],
                       capture_output=True)
        rows = list(csv.DictReader(open(os.path.join(out, "impacts.csv"))))
        return [float(rows[0][k]) for k in ("time_s", "position_m")] if rows else None
    matched = None
    for change in (1e-4, -1e-4, 1e-3, -1e-3):
        other = first_impact(change)
        if other and abs(page[0] - other[0]) <= step_s * 1.000001 and abs(page[1] - other[1]) <= 0.01 * abs(other[1]):
            matched = (change, other)
            break
    if matched is None:
        sys.exit(f"web_checks: {label}: the first impact differs (allowed: one tracker step, {1000 * step_s:g} ms, "
                 "in time and 1 % in position from the native run at the same angle or at most 0.001 deg from it)")
    print(f"  {label} first impact: matches the native run at {matched[0]:+g} deg: {matched[1][0]:.4f} s, "
          f"{matched[1][1]:.6f} m (the pile settled into another packing)")
PY
        i=$((i + 1))
    done

    step "$name: screenshots, page and native sandbox, after $shot_frames frames"
    # The canvas fills the browser's inner window (smaller than --window-size): the native sandbox
    # is captured at the canvas's size, and the page's screenshot compared over the canvas.
    canvas=$(sed -n 's/^polyroll-web: first frame .* canvas \([0-9]*x[0-9]*\) .*/\1/p' "$scratch/$name.out")
    [ -n "$canvas" ] || { echo "web_checks: the page did not print its canvas size" >&2; exit 1; }
    chrome --screenshot="$scratch/$name-web.png" "http://127.0.0.1:$port/index.html?$query&frames=$shot_frames" \
        >/dev/null
    preset=$(printf '%s' "$query" | sed -n 's/.*preset=\([^&]*\).*/\1/p')
    xvfb-run -a -s "-screen 0 ${size_w}x${size_h}x24" build/polyroll-sandbox --preset "${preset:-default}" \
        --frames "$shot_frames" --size "$canvas" --screenshot "$scratch/$name-native.png" >/dev/null
    python3 tests/web_compare_png.py "$scratch/$name-web.png" "$scratch/$name-native.png" "$max_share"
    if [ -n "${POLYROLL_WEB_KEEP:-}" ]; then
        cp "$scratch/$name-web.png" "$scratch/$name-native.png" "$POLYROLL_WEB_KEEP/"
    fi
}

check_scene race "preset=race" "$impact_frames"
check_scene default "preset=default" "$impact_frames"
step "every preset's outcome: the page runs it to the end (key G) and exports it (E); polyroll run runs the same scenes"
/usr/bin/python3 tests/web_preset_check.py "http://127.0.0.1:$port/index.html" --skip "$skip_presets"

step "what the page shows: bad addresses refused visibly, the layout at 800x600 and 1920x1080"
# The visible text of the status box (innerText, not the hidden <pre> of the program's lines), over
# Chromium's DevTools protocol in real time.
/usr/bin/python3 tests/web_visible_check.py "http://127.0.0.1:$port/index.html" ${POLYROLL_WEB_KEEP:+"$POLYROLL_WEB_KEEP"}
step "Export (key E) downloads the run's files"
/usr/bin/python3 tests/web_export_check.py "http://127.0.0.1:$port/index.html"
step "all web checks passed"
