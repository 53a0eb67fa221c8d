#!/bin/sh
# Installs the Debian 12 packages polyroll needs (listed in debian-packages.txt beside this file).
# Run as root on a fresh machine; safe to run again.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
packages=$(grep -v '^\s*#' "$here/debian-packages.txt" | grep -v '^\s*$' | tr '\n' ' ')
missing=""
for p in $packages; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
    echo "polyroll setup: installing$missing"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    # shellcheck disable=SC2086
    apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
echo "polyroll setup: all packages present"
