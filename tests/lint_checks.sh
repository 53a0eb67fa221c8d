#!/bin/sh
# Warnings and static analysis, run by tests/ci_checks.sh (step 4) and by hand:
#   1. the hardening build (preset hardening, build-hardening/: clang with -Wall -Wextra -Wpedantic
#      -Werror; nothing to do when ci_checks.sh has just built it);
#   2. clang-tidy with the checked-in .clang-tidy over the .cpp files of src/ that changed since the
#      last tree that passed in full (tests/lint_clean_at), or include a header that did, or every one
#      (tests/lint_files.py says which and why; `tests/lint_checks.sh --all` checks every file and,
#      on a clean tree, records it), with that build's compile
#      commands file by file and without its precompiled header; any finding is an error
#      (WarningsAsErrors in .clang-tidy). A file costs 1 to 20 CPU-seconds: its checks walk every
#      header it parses (nlohmann/json adds about 9, CLI11 about 20: hence flags/command_flags.h
#      and sim/model_blocks.h), and the static analyser its own functions (docs/testing.md).
set -eu
cd "$(dirname "$0")/.."
all=""
case "${1:-}" in
    --all) all="--all" ;;
    "") ;;
    *) echo "usage: tests/lint_checks.sh [--all]" >&2; exit 2 ;;
esac
t0=$(date +%s)
# Ninja for a new build-hardening/, as tests/ci_checks.sh (which says why) when run on its own.
export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"
step() { echo "== lint_checks [$(( $(date +%s) - t0 )) s]: $*"; }

step "1/2 the hardening build (clang, -Wall -Wextra -Wpedantic -Werror)"
cmake --preset hardening >/dev/null
cmake --build --preset hardening

# src/web/ is the WebAssembly side of the platform seams: emscripten compiles it (web/CMakeLists.txt,
# -Wall -Wextra); it is not in this build's compile_commands.json, so clang-tidy cannot read it here.
# Nor is src/python/: the sanitizer build has no Python module (POLYROLL_PYTHON). Its seven files cost
# clang-tidy about 30 CPU-seconds each (pybind11's templates), more than CI's time allows for now;
# run it by hand on the Release build's commands: clang-tidy -p build src/python/*.cpp.
step "2/2 clang-tidy over src/ (without src/web/ and src/python/)"
# The files to check: tests/lint_files.py (its header says why a file unchanged since a tree that
# passed in full, with unchanged headers, flags, checks and clang-tidy, needs no second look).
files=$(python3 tests/lint_files.py $all)
# clang-tidy counts the warnings its configuration hides ("N warnings generated.") on stderr: that
# noise is dropped from the log; findings and the exit status are kept.
log=$(mktemp "${TMPDIR:-/tmp}/polyroll-clang-tidy.XXXXXX")
trap 'rm -f "$log"' EXIT
status=0
# Each file's own compile command, as the hardening build's flags give it, but file by file and
# without the precompiled header: that build compiles in batches (POLYROLL_UNITY), and its
# compile_commands.json names only the batches, so a twin of it configured with both off (nothing
# built, about 6 s) writes the commands. clang-tidy then parses each file whole and on its own, its
# includes seen as written: a file that compiles only after its batch's neighbours (an include
# missing) is an error here. What it checks does not depend on the PCH, and it gains no time from one
# (its checks walk the whole syntax tree, read from a PCH or not).
db=$(mktemp -d "${TMPDIR:-/tmp}/polyroll-tidy-db.XXXXXX")
trap 'rm -f "$log"; rm -rf "$db"' EXIT
cmake --preset hardening -B "$db" -DPOLYROLL_UNITY=OFF -DPOLYROLL_PCH=OFF >"$db/configure.log" 2>&1 ||
    { cat "$db/configure.log" >&2; echo "lint_checks: configuring the file-by-file compile commands failed" >&2; exit 1; }
if grep -q -e '-include-pch' -e 'Unity/unity_' "$db/compile_commands.json"; then
    echo "lint_checks: the compile commands still name a precompiled header or a unity batch" >&2
    exit 1
fi
# Four files per clang-tidy process: a process costs about 0.7 CPU-seconds to start, and one file
# per process was no faster in a fresh-clone CI run (docs/testing.md).
[ -z "$files" ] || printf '%s\n' "$files" | xargs -P 2 -n 4 clang-tidy -p "$db" --quiet >"$log" 2>&1 || status=$?
grep -v ' warnings\? generated\.$' "$log" || true
[ "$status" -eq 0 ] || { echo "lint_checks: clang-tidy reported findings (above)" >&2; exit 1; }

# A full pass on a committed tree is recorded, so that later runs check only what changes after it.
if [ -n "$all" ] && [ -z "$(git status --porcelain --untracked-files=no 2>/dev/null)" ] && git rev-parse HEAD >/dev/null 2>&1; then
    python3 tests/lint_files.py --record
fi
step "lint checks passed"
