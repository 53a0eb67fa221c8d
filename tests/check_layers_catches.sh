#!/bin/sh
# check_layers.sh itself, on made-up trees: it passes a wing that includes the core and itself and
# the registry that includes every wing, and fails a wing that includes another wing and a core file
# that includes a wing. So the layer test cannot pass by checking nothing.
# Usage: check_layers_catches.sh TESTS_DIR
set -eu
check=$1/check_layers.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0
# tree NAME FILE INCLUDE...: a source tree whose one file FILE (under src/) includes each INCLUDE.
tree() {
    root=$tmp/$1
    file=$2
    shift 2
    for folder in process flags sim sweep render figures app web cli python; do mkdir -p "$root/src/$folder"; done
    mkdir -p "$(dirname "$root/src/$file")"
    for include in "$@"; do echo "#include \"$include\"" >>"$root/src/$file"; done
    echo "$root"
}
# expect RESULT TREE: check_layers.sh passes ("passes") or fails ("fails") on TREE.
expect() {
    if "$check" "$2" >/dev/null 2>&1; then got=passes; else got=fails; fi
    if [ "$got" != "$1" ]; then
        echo "check_layers_catches: check_layers.sh $got on ${2#"$tmp"/}, expected it $1" >&2
        failed=1
    fi
}
expect passes "$(tree wing_on_core sim/grains/a.cpp sim/grains/b.h sim/geometry/c.h sim/scene/d.h sim/e.h)"
expect passes "$(tree registry_on_wings sim/registry/a.cpp sim/grains/b.h sim/reduced/c.h sim/dem3d/d.h)"
expect fails "$(tree wing_on_wing sim/reduced/a.cpp sim/grains/fill_plan.h)"
expect fails "$(tree new_wing_on_wing sim/newmodel/a.h sim/reduced/reveal.h)"
expect fails "$(tree core_on_wing sim/scene/a.cpp sim/grains/disc_size.h)"
expect fails "$(tree core_top_on_wing sim/run_result.h sim/grains/engine_units.h)"
expect fails "$(tree core_on_registry sim/a.cpp sim/registry/auto_run.h)"
[ "$failed" -eq 0 ] || exit 1
echo "check_layers_catches: check_layers.sh fails each wrong include and passes the right ones"
