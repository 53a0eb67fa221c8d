#!/bin/sh
# Hardening checks (issue 7), run by CI after the README's test command. In order:
#   1. everything built with AddressSanitizer + UndefinedBehaviorSanitizer (preset asan, build-asan/),
#      and the default test suite run under it, halting on the first report;
#   2. LeakSanitizer over a run, a render and a short sweep with those binaries;
#   3. the libFuzzer targets (preset fuzz, clang, build-fuzz/) run 60 s each on the seed corpus;
#   4. the warnings and static analysis of tests/lint_checks.sh (clang -Werror build, clang-tidy);
#   5. the web page in headless Chromium (tests/web_checks.sh, 2.5 to 5.5 min measured), when
#      build-web/ has been built (README's web command; building it took 15 min with other builds
#      beside it, so it is not part of the test command: see README, "The sandbox in a web browser").
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

step "3/5 fuzz targets (clang, libFuzzer + ASan + UBSan), 60 s each"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
# Seeds: tests/fuzz/corpus_<target>/, and for the scene parser the bundled asset files themselves.
for target in scene cli; do
    mkdir -p "$scratch/corpus_$target" "$scratch/artifacts"
    seeds="tests/fuzz/corpus_$target"
    [ "$target" = scene ] && seeds="$seeds assets"
    # shellcheck disable=SC2086
    build-fuzz/fuzz_$target -max_total_time=60 -print_final_stats=1 -timeout=5 -rss_limit_mb=2048 -max_len=4096 \
        -artifact_prefix="$scratch/artifacts/$target-" "$scratch/corpus_$target" $seeds \
        2>"$scratch/fuzz_$target.log" || { tail -n 60 "$scratch/fuzz_$target.log"; exit 1; }
    grep -E '^Done [0-9]+ runs|DONE' "$scratch/fuzz_$target.log" || true
done

step "4/5 warnings (clang -Werror) and clang-tidy"
tests/lint_checks.sh

step "5/5 the web page in headless Chromium"
if [ -f build-web/polyroll-sandbox.wasm ]; then
    tests/web_checks.sh
else
    echo "skipped: build-web/ has not been built (README's web command)"
fi

step "all hardening checks passed"
