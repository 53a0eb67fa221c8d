#!/bin/sh
# Hardening checks, run by CI after the README's test command. One build serves them all: the
# hardening preset (clang, build-hardening/) compiles everything and the tests with AddressSanitizer +
# UndefinedBehaviorSanitizer, the libFuzzer coverage and -Werror, in unity batches (clang-tidy gets
# each file's own command from a configure-only twin: tests/lint_checks.sh). In order:
#   1. the build (its -Werror is the clang warnings check), then the default test suite under the
#      sanitizers, halting on the first report;
#   2. LeakSanitizer over a run, a render and a short sweep with those binaries;
#   3. the libFuzzer targets run 30 s each on the seed corpus, both at once (each fuzzer uses one core);
#   4. clang-tidy (tests/lint_checks.sh, on the same build);
#   5. beside step 4: the web page: the README's web command (the block after its "web-command"
#      marker, so that the README's promise and CI cannot drift apart) builds build-web/, and
#      tests/web_checks.sh plays it in headless Chromium.
# Any failure stops the script with a non-zero exit. Scratch files go to a temporary folder.
set -eu
cd "$(dirname "$0")/.."
root=$(pwd)
scratch=$(mktemp -d "${TMPDIR:-/tmp}/polyroll-ci-checks.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
t0=$(date +%s)
# Ninja for a new build-hardening/ (a folder configured before keeps its generator): it compiles a
# target's files while the targets it links are still being built, where make waits for them.
export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"
step() { echo "== ci_checks [$(( $(date +%s) - t0 )) s]: $*"; }

# halt_on_error: the first report fails the test that caused it (UBSan is also built with
# -fno-sanitize-recover=all). Leaks in Mesa/X are suppressed by tests/lsan.supp (third-party only).
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:strict_init_order=1:check_initialization_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=0"

step "1/5 the hardening build (clang: ASan + UBSan, libFuzzer coverage, -Werror)"
cmake --preset hardening >/dev/null
cmake --build --preset hardening
step "1/5 default tests under ASan + UBSan"
# The whole default suite, the Xvfb sandbox test included (see tests/test_sandbox_smoke.cpp for its leak check),
# but the Slurm cluster's: what it checks is Slurm's scheduling of plain runs, which the Release build's
# suite has checked already (the instrumented runs would only take longer).
ctest --test-dir build-hardening -L default -LE slurm --output-on-failure -j2

step "2/5 LeakSanitizer: a run, a render, a short sweep"
build-hardening/polyroll run --fill 0.25 --fidelity draft --time-limit 2 --out "$scratch/run" >/dev/null
build-hardening/polyroll render --fill 0.25 --fidelity draft --time-limit 1 --size 320x180 --fps 10 --hold 0 \
    --out "$scratch/render" >/dev/null
if build-hardening/polyroll sweep --help >/dev/null 2>&1; then
    build-hardening/polyroll sweep --sides 6 --fill 0,0.125 --angle 10,25 --fidelity draft --time-limit 0.5 -q \
        --jobs 2 --out "$scratch/sweep" >/dev/null
fi

step "3/5 fuzz targets (libFuzzer + ASan + UBSan), 30 s each, both at once"
# Seeds: tests/fuzz/corpus_<target>/, and for the scene parser the bundled asset files themselves.
fuzz() {
    target=$1
    mkdir -p "$scratch/corpus_$target" "$scratch/artifacts"
    seeds="tests/fuzz/corpus_$target"
    [ "$target" = scene ] && seeds="$seeds assets"
    # shellcheck disable=SC2086
    build-hardening/fuzz_$target -max_total_time=30 -print_final_stats=1 -timeout=5 -rss_limit_mb=2048 -max_len=4096 \
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

# Steps 4 and 5 run side by side: the page's checks leave a core idle much of the time (one browser
# or one native run at a time), which clang-tidy fills; the page's build does not, so the time saved
# is small (docs/testing.md has the measured run). Nothing they share is written: clang-tidy reads build-hardening/, the web command writes build-web*/, and
# the page's checks read build/ and build-web/. Chromium runs in virtual time, so a slower machine
# changes no outcome. The web log is printed whole once it ends.
step "4/5 and 5/5 at once: clang-tidy, and the web page (the README's web command, then headless Chromium)"
web_command=$(awk '/<!-- web-command -->/{found=1; next} found && /^```/{if (inblock) exit; inblock=1; next} found && inblock {print}' README.md)
[ -n "$web_command" ] || { echo "ci_checks: no web command found in README.md" >&2; exit 1; }
web_log="$scratch/web.log"
(
    echo "ci_checks: $web_command"
    sh -c "$web_command" && tests/web_checks.sh
) >"$web_log" 2>&1 &
web_pid=$!
tidy_status=0
tests/lint_checks.sh || tidy_status=$?
step "4/5 clang-tidy ended (status $tidy_status); waiting for the web page"
web_status=0
wait "$web_pid" || web_status=$?
step "5/5 the web page ended (status $web_status); its log:"
cat "$web_log"
[ "$tidy_status" -eq 0 ] || { echo "ci_checks: clang-tidy failed (above)" >&2; exit 1; }
[ "$web_status" -eq 0 ] || { echo "ci_checks: the web page's build or checks failed (its log above)" >&2; exit 1; }

step "all hardening checks passed"
# CPU time of this script's children (user and system), for docs/testing.md's measured times.
times
