#!/bin/sh
# Remakes every image in screenshots/ from the current build, so they stay real captures of the
# current program. Needs a build (build/polyroll, build/polyroll-sandbox) and xvfb-run.
# Usage: screenshots/make_screenshots.sh [build-folder]
set -eu
build=$(cd "${1:-build}" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Headless frames (polyroll render): pick one frame of each sequence.
"$build/polyroll" render --fill 0.5 --angle 25 --out "$work/whole" >/dev/null 2>&1
cp "$work/whole/frame_000045.png" "$here/render-whole-ramp.png"            # t = 1.47 s
"$build/polyroll" render --sides 8 --fill 0.375 --material peas --angle 18 --follow --colour-by speed \
    --out "$work/peas" >/dev/null 2>&1
cp "$work/peas/frame_000060.png" "$here/render-follow-speed-colours.png"    # t = 1.97 s
"$build/polyroll" render --fill 0.25 --material rice --angle 30 --follow --slow 4 --out "$work/rice" >/dev/null 2>&1
cp "$work/rice/frame_000090.png" "$here/render-follow-rice.png"            # t = 0.74 s, slowed 4x

# The sandbox window under Xvfb; each frame advances 1/60 s of simulated time.
sandbox() { xvfb-run -a -s "-screen 0 1280x800x24" "$build/polyroll-sandbox" "$@" >/dev/null; }
sandbox --screenshot "$here/sandbox-default.png" --frames 30                      # t = 0.5 s
sandbox --preset race --screenshot "$here/sandbox-race.png" --frames 80           # t = 1.33 s
sandbox --preset stops-abruptly --screenshot "$here/sandbox-stopped.png" --frames 660  # t = 11 s, past its stop (8.0 s)
# A costly scene stepped as asked: the panel says it costs more than real time here and offers the
# cheaper model; the status band, a capture's, claims no rate (each frame steps 1/60 s).
printf '%s\n' '{"shell": "hexagon-large", "fill": {"ratio": 0.8, "material": "rice"}, "run": {"model": "grains"}}' \
    > "$work/rice.json"
(cd "$work" && xvfb-run -a -s "-screen 0 1280x960x24" "$build/polyroll-sandbox" --scene rice.json --colour-by speed \
    --size 1280x960 --screenshot "$here/sandbox-budget.png" --frames 60 >/dev/null)  # t = 1 s
# The race on a projector: 1920x1080 at UI scale 2.
xvfb-run -a -s "-screen 0 1920x1080x24" "$build/polyroll-sandbox" --preset race --size 1920x1080 --ui-scale 2 \
    --screenshot "$here/sandbox-race-1920-scale2.png" --frames 80 >/dev/null
# The web page in headless Chromium (needs build-web/, README's web command; SKIP_WEB=1 skips it): the race after 150
# frames, the window sized so that the page's canvas is 1280x800, the screenshot cut to the canvas.
if [ -f build-web/polyroll-sandbox.wasm ] && [ -z "${SKIP_WEB:-}" ]; then
    port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
    python3 -m http.server --bind 127.0.0.1 --directory build-web "$port" >/dev/null 2>&1 &
    server=$!
    sleep 1
    chromium --headless=new --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader \
        --disable-background-networking --disable-component-update --disable-sync --no-first-run \
        --user-data-dir="$work/profile" --window-size=1280,943 --hide-scrollbars --virtual-time-budget=600000 \
        --screenshot="$work/web.png" "http://127.0.0.1:$port/index.html?preset=race&frames=150" >/dev/null 2>&1
    kill "$server"
    python3 -c "import sys; sys.path.insert(0, '$here/../tests'); from web_compare_png import read_png, write_png
w, h, c, rows = read_png('$work/web.png'); write_png('$here/web-race-chromium.png', 1280, 800, c, rows)"
fi
echo "screenshots remade in $here"
