#!/bin/sh
# Prepares the WebAssembly build of the sandbox (README's web command): installs emscripten and
# chromium (Debian 12 packages) and Ninja, and fetches the C sources the page needs compiled for WebAssembly:
# Box2D 2.4.1, Dear ImGui 1.86 and FreeType from Debian's own source packages (the binary packages
# are for this machine's CPU only). Nothing is downloaded from anywhere but the Debian mirror the
# machine already uses, and nothing fetched is committed: the sources land in build-web-src/.
# Run as root (apt); safe to run again: what is present is kept.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
src="$root/build-web-src"

export DEBIAN_FRONTEND=noninteractive
missing=""
for p in emscripten chromium dpkg-dev fonts-dejavu-core ninja-build python3 python3-websocket xvfb; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    echo "polyroll web setup: installing$missing"
    apt-get update -qq
    # shellcheck disable=SC2086
    apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi

mkdir -p "$src"
need_source=""
[ -d "$src/box2d" ] || need_source="$need_source box2d"
[ -d "$src/imgui" ] || need_source="$need_source imgui"
[ -d "$src/freetype" ] || need_source="$need_source freetype"
if [ -n "$need_source" ]; then
    # Source packages come from the same mirror and suites as the binary ones: a deb-src twin of the
    # machine's own sources file, kept apart so the original is untouched.
    list=/etc/apt/sources.list.d/polyroll-deb-src.sources
    if [ ! -f "$list" ]; then
        base=/etc/apt/sources.list.d/debian.sources
        [ -f "$base" ] || { echo "polyroll web setup: $base not found (needed to add its deb-src twin)" >&2; exit 1; }
        sed 's/^Types: deb$/Types: deb-src/' "$base" >"$list"
    fi
    apt-get update -qq
    cd "$src"
    for p in $need_source; do
        echo "polyroll web setup: fetching the Debian source package $p"
        apt-get source -qq "$p" >/dev/null 2>&1 || apt-get source "$p"
        # apt-get source unpacks into NAME-VERSION/: a fixed name for the web build.
        d=$(find . -maxdepth 1 -type d -name "$p-[0-9]*" | head -n 1)
        [ -n "$d" ] || { echo "polyroll web setup: the source of $p did not unpack" >&2; exit 1; }
        mv "$d" "$p"
        rm -f ./"$p"_*.dsc ./"$p"_*.tar.* ./"$p"_*.debian.tar.* ./"$p"_*.diff.gz
    done
fi
# sed reads emcc's whole output (head would close the pipe early and emcc, a Python program, would
# print a BrokenPipeError traceback).
echo "polyroll web setup: emscripten $(emcc --version | sed -n '1s/.* \([0-9][0-9.]*\) .*/\1/p'), sources in $src"
