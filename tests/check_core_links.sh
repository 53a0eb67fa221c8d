#!/bin/sh
# Checks that the GL-free core's test binary links no GL provider, GLFW or Dear ImGui: neither as a
# shared library (ldd) nor statically (libimgui.a: ImGui symbols; GL or GLFW entry points).
# Usage: check_core_links.sh BINARY
set -eu
bin=$1
[ -x "$bin" ] || { echo "check_core_links: no executable at $bin" >&2; exit 1; }
shared=$(ldd "$bin" | grep -Ei 'libGL|libEGL|libOSMesa|libglfw|libimgui|libX11' || true)
static=$(nm -C "$bin" | grep -E ' (ImGui::|glfw[A-Z]|gl[A-Z][a-zA-Z]+$|OSMesa)' | head -5 || true)
if [ -n "$shared$static" ]; then
    echo "check_core_links: $bin links graphics code it must not:" >&2
    [ -n "$shared" ] && echo "$shared" >&2
    [ -n "$static" ] && echo "$static" >&2
    exit 1
fi
echo "check_core_links: $bin links no GL, OSMesa, GLFW or ImGui"
