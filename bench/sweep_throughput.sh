#!/bin/sh
# Sweep throughput: a fixed 100-run grid at the standard preset (n = 6, 8; r = 0 to 1 in quarters;
# 10 to 28 degrees in steps of 2; BBs; one seed), swept with 1 job and with 2, in runs per minute.
# Prints the figures; asserts nothing (docs/sweeps.md has the measured values and the targets).
# Usage: bench/sweep_throughput.sh [path/to/polyroll]
set -eu
exe=${1:-build/polyroll}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
grid="--sides 6,8 --fill 0:1:0.25 --angle 10:28:2 --material bb --fidelity standard --seed 1 -q"
printf '%-6s %6s %10s %10s\n' jobs runs wall_s runs_min
for jobs in 1 2; do
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    "$exe" sweep $grid --jobs "$jobs" --out "$work/j$jobs" >/dev/null
    end=$(date +%s.%N)
    runs=$(($(wc -l <"$work/j$jobs/results.csv") - 1))
    awk -v j="$jobs" -v n="$runs" -v s="$start" -v e="$end" \
        'BEGIN { w = e - s; printf "%-6s %6d %10.1f %10.1f\n", j, n, w, 60 * n / w }'
    eval "wall_$jobs=\$(awk -v s=\"\$start\" -v e=\"\$end\" 'BEGIN { print e - s }')"
done
awk -v a="$wall_1" -v b="$wall_2" 'BEGIN { printf "speed-up with 2 jobs: %.2fx (target 1.8x; 100 runs in under 60 s)\n", a / b }'
