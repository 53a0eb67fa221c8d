#!/bin/bash
# Slurm for real: starts a one-node Slurm cluster from Debian's packages (munged, slurmctld, slurmd)
# on 127.0.0.1 in a temporary folder, writes a sweep plan with `polyroll sweep --plan-only
# --slurm-tasks 3` (which submits the job array and its merge job), cancels one task while it is
# pending, lets the merge job find its runs missing, runs that task again with `sbatch --array=K`,
# merges with the written merge.sbatch, and checks the merged results.csv equals the table of the same
# plan run in one process, the wall_time_s column aside. Prints the array's measured wall time. Then
# `polyroll validate --slurm-tasks 2` (its job array and its score job) on one cheap observation, whose
# scorecard and results must equal the same validation's in one process.
# A trap stops every daemon it started, and checks none is left, even when a step fails.
# Usage: slurm_cluster_test.sh POLYROLL_EXE   (exit 77: skipped, no Slurm or not root)
# KEEP_SLURM_TEST=1 keeps the temporary folder (logs, tables) for a look afterwards.
set -euo pipefail

polyroll=$(readlink -f "${1:?usage: slurm_cluster_test.sh POLYROLL_EXE}")
export PATH="$PATH:/usr/sbin:/sbin"
for program in munged slurmctld slurmd sbatch squeue scancel scontrol sinfo; do
    if ! command -v "$program" >/dev/null; then
        echo "slurm test: skipped: no $program (Debian packages slurm-wlm and munge, third_party/debian-packages.txt)"
        exit 77
    fi
done
if [ "$(id -u)" -ne 0 ]; then
    echo "slurm test: skipped: slurmd must run as root to start jobs"
    exit 77
fi

tmp=$(mktemp -d /tmp/polyroll-slurm-XXXXXX)
chmod 711 "$tmp"  # munged's socket must be reachable by path
mkdir -p "$tmp/state" "$tmp/spool" "$tmp/log" "$tmp/pids"
started=()  # names of the daemons started, their pids in $tmp/pids/NAME.pid

log() { echo "slurm test: $*"; }

# Every daemon started is stopped, jobs first; then none may be left (each checked with pgrep by its
# pid file, copied at start: the daemons remove their own on exit).
cleanup() {
    local rc=$? left=0
    set +e
    trap - EXIT INT TERM
    if [ "$rc" -ne 0 ]; then
        log "FAILED (exit $rc); the logs' last lines:"
        for f in "$tmp"/log/*.log "$tmp"/sweep/slurm/*.out; do
            [ -f "$f" ] && { echo "--- $f"; tail -n 15 "$f"; }
        done
    fi
    if [[ " ${started[*]} " == *" slurmctld "* ]]; then
        local jobs
        jobs=$(squeue -h -o %A 2>/dev/null | sort -u | tr '\n' ' ')
        if [ -n "$jobs" ]; then
            # shellcheck disable=SC2086
            scancel $jobs 2>/dev/null
            for _ in $(seq 1 20); do [ -z "$(squeue -h -o %A 2>/dev/null)" ] && break; sleep 0.5; done
        fi
    fi
    for ((i = ${#started[@]} - 1; i >= 0; i--)); do
        local name=${started[i]} pid
        pid=$(cat "$tmp/pids/$name.pid")
        kill "$pid" 2>/dev/null
        for _ in $(seq 1 40); do kill -0 "$pid" 2>/dev/null || break; sleep 0.25; done
        if pgrep -F "$tmp/pids/$name.pid" >/dev/null; then
            log "$name (pid $pid) did not stop on SIGTERM: killed"
            kill -9 "$pid" 2>/dev/null
            left=1
        fi
    done
    # A job step's processes carry this cluster's SLURM_CONF in their environment.
    for env in /proc/[0-9]*/environ; do
        local pid=${env#/proc/} vars
        pid=${pid%/environ}
        vars=$(tr '\0' '\n' 2>/dev/null <"$env") || continue
        if grep -qx "SLURM_CONF=$tmp/slurm.conf" <<<"$vars" && grep -q '^SLURM_JOB_ID=' <<<"$vars"; then
            log "a job's process is left (pid $pid: $(tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null)): killed"
            kill -9 "$pid" 2>/dev/null
            left=1
        fi
    done
    for name in "${started[@]}"; do
        if pgrep -F "$tmp/pids/$name.pid" >/dev/null; then
            log "$name is still running"
            left=1
        fi
    done
    if [ "$left" -eq 0 ]; then
        log "every daemon started (${started[*]:-none}) is stopped"
    elif [ "$rc" -eq 0 ]; then
        rc=1
    fi
    if [ -n "${KEEP_SLURM_TEST:-}" ]; then log "kept $tmp"; else rm -rf "$tmp"; fi
    exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

fail() {
    log "FAIL: $*"
    exit 1
}

# Waits until `condition` (a command) succeeds, at most `seconds`.
wait_for() {
    local seconds=$1 what=$2
    shift 2
    local deadline=$((SECONDS + seconds))
    until "$@"; do
        [ "$SECONDS" -lt "$deadline" ] || fail "waited $seconds s for $what"
        sleep 0.5
    done
}

# A daemon started: its pid file copied, so the trap finds it after the daemon removed its own.
record_daemon() {
    local name=$1 pidfile=$2
    wait_for 20 "$name's pid file" test -s "$pidfile"
    cp "$pidfile" "$tmp/pids/$name.pid"
    started+=("$name")
}

free_port() {
    local port=$1
    while (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; do port=$((port + 1)); done
    echo "$port"
}

# --- munge, with its own key, socket, pid and log ---
dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge.key"
munged --force --socket="$tmp/munge.socket" --key-file="$tmp/munge.key" --pid-file="$tmp/munged.pid" \
    --log-file="$tmp/log/munged.log" --seed-file="$tmp/munged.seed"
record_daemon munged "$tmp/munged.pid"
wait_for 20 "munged's socket" test -S "$tmp/munge.socket"

# --- slurmctld and slurmd on 127.0.0.1 ---
ctld_port=$(free_port $((16817 + $$ % 500 * 2)))
slurmd_port=$(free_port $((ctld_port + 1)))
cpus=$(nproc)
cat >"$tmp/slurm.conf" <<EOF
ClusterName=polyroll-test
SlurmctldHost=localhost
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
MailProg=/bin/true
PlugStackConfig=$tmp/plugstack.conf
ReturnToService=2
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=polyroll Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
: >"$tmp/plugstack.conf"
export SLURM_CONF="$tmp/slurm.conf"
slurmctld -f "$SLURM_CONF"
record_daemon slurmctld "$tmp/slurmctld.pid"
slurmd -f "$SLURM_CONF" -N localhost
record_daemon slurmd "$tmp/slurmd.pid"
node_idle() { [ "$(sinfo -h -n localhost -o %t 2>/dev/null)" = idle ]; }
wait_for 60 "the node to be idle" node_idle
log "one-node Slurm up: slurmctld on 127.0.0.1:$ctld_port, slurmd on :$slurmd_port, $cpus CPUs"

# --- the plan: cheap 2D runs and one 3D run (Yade), a short simulated time ---
sweep="$tmp/sweep"
grid=(--sides 6 --fill 0.25 --angle "12,24" --set "run.model=auto,rigid,segments,dem3d" --fidelity draft --time-limit 0.3)
tasks=3
cancelled=2
# Nothing starts before a task is cancelled: the partition is down while the plan is submitted.
scontrol update PartitionName=polyroll State=DOWN
plan_rc=0
out=$("$polyroll" sweep "${grid[@]}" --out "$sweep" --plan-only --slurm-tasks "$tasks" 2>&1) || plan_rc=$?
echo "$out"
[ "$plan_rc" -eq 0 ] || fail "polyroll sweep --plan-only --slurm-tasks exited $plan_rc"
array=$(sed -n 's/.*submitted job array \([0-9]*\) .*/\1/p' <<<"$out")
merge=$(sed -n 's/.* merge job \([0-9]*\) .*/\1/p' <<<"$out")
if [ -z "$array" ] || [ -z "$merge" ]; then fail "no job ids in polyroll's output"; fi
runs=$(sed -n 's/.*plan of \([0-9]*\) runs* written.*/\1/p' <<<"$out")
grep -q "^#SBATCH --array=1-$tasks\$" "$sweep/slurm/array.sbatch" || fail "array.sbatch has no --array=1-$tasks"
mkdir "$tmp/one"
cp "$sweep/plan.json" "$tmp/one/plan.json"

scancel "${array}_$cancelled"
pending=$(squeue -h -r -j "$array" -o %K | sort -n | tr '\n' ' ')
[ "$pending" = "1 3 " ] || fail "after scancel ${array}_$cancelled the array's pending tasks are '$pending', not '1 3 '"
log "cancelled task $cancelled of job array $array while pending"

queue_empty() { [ -z "$(squeue -h -o %A)" ]; }
job_field() { scontrol show job "$1" | tr ' ' '\n' | sed -n "s/^$2=//p" | head -n 1; }
start=$(date +%s.%N)
scontrol update PartitionName=polyroll State=UP
wait_for 150 "tasks 1 and 3 and the merge job" queue_empty
[ "$(job_field "$merge" JobState)" = FAILED ] || fail "the first merge job is $(job_field "$merge" JobState), not FAILED"
grep -q "runs are in no table yet" "$sweep"/slurm/merge-"$merge".out ||
    fail "the first merge job does not name the missing runs"
log "the merge job $merge found task $cancelled's runs missing: $(grep -o 'plan indices [0-9, .]*' "$sweep"/slurm/merge-"$merge".out)"

rerun=$(sbatch --parsable --array="$cancelled" "$sweep/slurm/array.sbatch")
wait_for 150 "task $cancelled run again (job $rerun)" queue_empty
end=$(date +%s.%N)
[ "$(job_field "$rerun" JobState)" = COMPLETED ] || fail "the rerun of task $cancelled is $(job_field "$rerun" JobState)"
log "$(printf 'job array of %d runs in %d tasks, task %d run again: %.1f s wall time' "$runs" "$tasks" "$cancelled" \
    "$(awk "BEGIN { print $end - $start }")")"

merge2=$(sbatch --parsable "$sweep/slurm/merge.sbatch")
wait_for 60 "the merge job $merge2" queue_empty
[ "$(job_field "$merge2" JobState)" = COMPLETED ] || fail "the second merge job is $(job_field "$merge2" JobState)"
cat "$sweep/slurm/merge-$merge2.out"

# --- the same plan in one process ---
one_start=$(date +%s.%N)
"$polyroll" sweep --from "$tmp/one" --jobs "$cpus" --quiet >"$tmp/one.log" 2>&1 ||
    { cat "$tmp/one.log"; fail "polyroll sweep --from (one process) failed"; }
log "$(printf 'the same plan in one process (--jobs %d): %.1f s' "$cpus" "$(awk "BEGIN { print $(date +%s.%N) - $one_start }")")"

# --- the tables: equal but for the last column, wall_time_s ---
[ "$(tail -n 1 "$sweep/results.csv" | wc -l)" -eq 1 ] || fail "results.csv does not end with a newline"
[ "$(head -n 1 "$sweep/results.csv" | sed 's/.*,//')" = wall_time_s ] || fail "results.csv's last column is not wall_time_s"
sed 's/,[^,]*$//' "$sweep/results.csv" >"$tmp/slurm.csv"
sed 's/,[^,]*$//' "$tmp/one/results.csv" >"$tmp/one.csv"
rows=$(($(wc -l <"$tmp/slurm.csv") - 1))
[ "$rows" -eq "$runs" ] || fail "the merged table has $rows rows, the plan $runs runs"
if ! diff "$tmp/one.csv" "$tmp/slurm.csv"; then fail "the merged table differs from the one-process table"; fi
status=$(head -n 1 "$tmp/slurm.csv" | tr ',' '\n' | grep -nx status | cut -d: -f1)
model_used=$(head -n 1 "$tmp/slurm.csv" | tr ',' '\n' | grep -nx model_used | cut -d: -f1)
[ "$(tail -n +2 "$tmp/slurm.csv" | cut -d, -f"$status" | sort -u)" = ok ] || fail "not every run is ok"
tail -n +2 "$tmp/slurm.csv" | cut -d, -f"$model_used" | grep -qx dem3d || fail "no run used dem3d"
log "the merged table of $rows runs equals the one-process table (wall_time_s aside)"

# --- validate through Slurm: its job array, then its score job, against the same in one process ---
validate=(--only text-empty-and-full-two-behaviours --seeds 2)
val_rc=0
out=$("$polyroll" validate "${validate[@]}" --out "$tmp/validate" --slurm-tasks 2 2>&1) || val_rc=$?
echo "$out"
[ "$val_rc" -eq 0 ] || fail "polyroll validate --slurm-tasks exited $val_rc"
score=$(sed -n 's/.* score job \([0-9]*\) .*/\1/p' <<<"$out")
[ -n "$score" ] || fail "no score job id in polyroll validate's output"
wait_for 150 "validate's job array and its score job $score" queue_empty
[ "$(job_field "$score" JobState)" = COMPLETED ] || fail "validate's score job is $(job_field "$score" JobState)"
"$polyroll" validate "${validate[@]}" --out "$tmp/validate-one" --jobs "$cpus" --quiet >"$tmp/validate-one.log" 2>&1 ||
    { cat "$tmp/validate-one.log"; fail "polyroll validate (one process) failed"; }
if ! diff "$tmp/validate-one/scorecard.csv" "$tmp/validate/scorecard.csv"; then
    fail "validate's scorecard through Slurm differs from the one-process scorecard"
fi
sed 's/,[^,]*$//' "$tmp/validate/results.csv" >"$tmp/validate-slurm.csv"
sed 's/,[^,]*$//' "$tmp/validate-one/results.csv" >"$tmp/validate-one.csv"
if ! diff "$tmp/validate-one.csv" "$tmp/validate-slurm.csv"; then fail "validate's results through Slurm differ"; fi
log "validate through Slurm: $(head -n 2 "$tmp/validate/scorecard.csv" | tail -n 1 | cut -d, -f1,4,5), as in one process"
log "PASS: sweep and validate through Slurm equal one process (wall_time_s aside)"
