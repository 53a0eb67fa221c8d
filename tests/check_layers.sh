#!/bin/sh
# Checks that every #include of the project's own headers follows the layers docs/design.md draws:
# a folder includes only itself and the folders below it. The window (src/app/) never includes the
# command line (src/cli/); the simulation (src/sim/) includes nothing above it. Inside src/sim/, the
# core (its own files, scene/, files/, geometry/) includes no model; each model's wing (every other
# folder but registry/) includes the core and itself, never another wing; registry/ (the model table
# and auto's run) is the one folder that includes the wings.
# Usage: check_layers.sh SOURCE_DIR
set -eu
src=$1/src
[ -d "$src" ] || { echo "check_layers: no src/ under $1" >&2; exit 1; }
failed=0
# folder: the top-level folders under src/ its files may include
check() {
    folder=$1
    allowed=$2
    for file in $(find "$src/$folder" -name '*.cpp' -o -name '*.h'); do
        for target in $(sed -n 's/^#include "\([a-z0-9_]*\)\/.*/\1/p' "$file" | sort -u); do
            case " $allowed " in
                *" $target "*) ;;
                *) echo "check_layers: ${file#"$1"/} includes $target/, above its layer (allowed: $allowed)" >&2
                   failed=1 ;;
            esac
        done
    done
}
check process "process"
check flags "flags sim"
check sim "sim process"
check sweep "sweep sim process"
check render "render sim"
check figures "figures sim process"
check app "app render sim flags process"
check web "web app render sim flags process"
check cli "cli sweep render figures sim flags process"
check python "python sweep sim process"

# Inside src/sim/: which part a path under it belongs to, "core" or the name of its folder.
core_folders="scene files geometry"
sim_part() {
    case $1 in
        */*) folder=${1%%/*}
             case " $core_folders " in
                 *" $folder "*) echo core ;;
                 *) echo "$folder" ;;
             esac ;;
        *) echo core ;;
    esac
}
for file in $(find "$src/sim" -name '*.cpp' -o -name '*.h'); do
    part=$(sim_part "${file#"$src/sim/"}")
    [ "$part" = registry ] && continue
    for target in $(sed -n 's/^#include "sim\/\([^"]*\)".*/\1/p' "$file" | sort -u); do
        target_part=$(sim_part "$target")
        [ "$target_part" = core ] || [ "$target_part" = "$part" ] && continue
        if [ "$part" = core ]; then
            echo "check_layers: ${file#"$1"/} includes sim/$target: the simulation's core includes no model's wing" >&2
        else
            echo "check_layers: ${file#"$1"/} includes sim/$target: the $part wing includes only the core and itself" >&2
        fi
        failed=1
    done
done
[ "$failed" -eq 0 ] || exit 1
echo "check_layers: every include of src/ follows the layers"
