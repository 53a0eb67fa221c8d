#!/bin/sh
# Hardening checks (issue 7), run by CI after the README's test command. In order:
#   1. everything built with AddressSanitizer + UndefinedBehaviorSanitizer (preset asan, build-asan/),
#      and the default test suite run under it, halting on the first report;
#   2. LeakSanitizer over a run, a render and a short sweep with those binaries;
#   3. the libFuzzer targets (preset fuzz, clang, build-fuzz/) run 60 s each on the seed corpus, both
#      at once (each fuzzer uses one core);
#   4. the warnings and static analysis of tests/lint_checks.sh (clang -Werror build, clang-tidy);
#   5. the web page: the README's web command (the block after its "web-command" marker, so that the
#      README's promise and CI cannot drift apart) builds build-web/, and tests/web_checks.sh plays it
#      in headless Chromium.
# The g++ build with -Werror is step 1 (the asan preset turns warnings into errors).
# Any failure stops the script with a non-zero exit. Scratch files go to a temporary folder.
set -eu
cd "$(dirname "$0")/.."
root=$(pwd)
scratch=$(mktemp -d "${TMPDIR:-/tmp}/polyroll-ci-checks.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
t0=$(date +%s)
step() { echo "== ci_checks [$(( $(date +%s) - t0 )) s]: $*"; }

# halt_on_error: the first report fails the test that caused it (UBSan is also built with
# -fno-sanitize-recover=all). Leaks in Mesa/X are suppressed by tests/lsan.supp (third-party only).
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:strict_init_order=1:check_initialization_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=0"

step "1/5 ASan + UBSan build"
cmake --preset asan >/dev/null
cmake --build --preset asan
step "1/5 default tests under ASan + UBSan"
# The whole default suite, the Xvfb sandbox test included (see tests/test_sandbox_smoke.cpp for its leak check).
ctest --test-dir build-asan -L default --output-on-failure -j2

step "2/5 LeakSanitizer: a run, a render, a short sweep"
build-asan/polyroll run --fill 0.25 --fidelity draft --time-limit 2 --out "$scratch/run" >/dev/null
build-asan/polyroll render --fill 0.25 --fidelity draft --time-limit 1 --size 320x180 --fps 10 --hold 0 \
    --out "$scratch/render" >/dev/null
if build-asan/polyroll sweep --help >/dev/null 2>&1; then
    build-asan/polyroll sweep --sides 6 --fill 0,0.125 --angle 10,25 --fidelity draft --time-limit 0.5 -q \
        --jobs 2 --out "$scratch/sweep" >/dev/null
fi

step "3/5 fuzz targets (clang, libFuzzer + ASan + UBSan), 60 s each, both at once"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
# Seeds: tests/fuzz/corpus_<target>/, and for the scene parser the bundled asset files themselves.
fuzz() {
    target=$1
    mkdir -p "$scratch/corpus_$target" "$scratch/artifacts"
    seeds="tests/fuzz/corpus_$target"
    [ "$target" = scene ] && seeds="$seeds assets"
    # shellcheck disable=SC2086
    build-fuzz/fuzz_$target -max_total_time=60 -print_final_stats=1 -timeout=5 -rss_limit_mb=2048 -max_len=4096 \
        -artifact_prefix="$scratch/artifacts/$target-" "$scratch/corpus_$target" $seeds \
        2>"$scratch/fuzz_$target.log"
}
fuzz scene & scene_pid=$!
fuzz cli & cli_pid=$!
fuzz_failed=""
wait "$scene_pid" || fuzz_failed="$fuzz_failed scene"
wait "$cli_pid" || fuzz_failed="$fuzz_failed cli"
for target in scene cli; do
    case " $fuzz_failed " in *" $target "*) tail -n 60 "$scratch/fuzz_$target.log" ;; esac
    grep -E '^Done [0-9]+ runs|DONE' "$scratch/fuzz_$target.log" || true
done
[ -z "$fuzz_failed" ] || { echo "ci_checks: fuzz target(s)$fuzz_failed failed (above)" >&2; exit 1; }

step "4/5 warnings (clang -Werror) and clang-tidy"
tests/lint_checks.sh

step "5/5 the web page: the README's web command, then headless Chromium"
web_command=$(awk '/<!-- web-command -->/{found=1; next} found && /^```/{if (inblock) exit; inblock=1; next} found && inblock {print}' README.md)
[ -n "$web_command" ] || { echo "ci_checks: no web command found in README.md" >&2; exit 1; }
echo "ci_checks: $web_command"
sh -c "$web_command"
tests/web_checks.sh

step "all hardening checks passed"
