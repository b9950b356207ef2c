#!/usr/bin/env bash
# check_slurm_real.sh REPO WORKDIR INDENT PYTHON MPIEXEC OPTIONS...: scripts/jobs/slurm-paper-case.sh
# under a real Slurm (Debian's slurm-wlm and munge, started here as root on this one node, in a
# temporary directory, with their own slurm.conf and munge key), on the case OPTIONS (they go in
# INDENT_EXTRA_OPTIONS) on 2 tasks:
#   1. starts munged, slurmctld and slurmd (skips, status 77, when not root, not installed, or the
#      daemons do not start);
#   2. runs the case without Slurm (mpiexec -n 2): the uninterrupted reference, and its wall time;
#   3. submits the job script with sbatch --time=1 --signal=B:USR1@30, timed so that the scheduler's
#      warning reaches the run after about a third of its steps (slurmctld sends it at its first
#      30-s time-limit check within 30 + 30 s of the limit: here the first check after the start);
#   4. checks that the job checkpointed on SIGUSR1, requeued itself (scontrol requeue, Restarts >= 1),
#      continued with -restart and finished (COMPLETED, exit 0), with the reference's P_max and H to
#      1e-8, and prints the timings from slurmctld's log.
# The daemons and anything left of the job are stopped on every exit (a watchdog does it if this
# shell is killed). doc/cluster.md, "Tested with a real Slurm".
set -u
skip_status=77

# --watchdog PID DIR: wait for PID (the test) to end; if DIR still exists, its cleanup did not run
# (the test was killed): end the processes recorded in DIR/pids and those started under its
# slurm.conf, and remove DIR.
if [[ ${1:-} == --watchdog ]]; then
  test_pid=$2 tmp=$3
  while kill -0 "$test_pid" 2> /dev/null; do sleep 2; done
  [[ -d $tmp ]] || exit 0
  while read -r pid; do kill -TERM "$pid" 2> /dev/null; done < "$tmp/pids"
  for f in /proc/[0-9]*/environ; do
    pid=${f#/proc/}
    pid=${pid%/environ}
    [[ $pid == "$$" ]] && continue
    grep -qz "^SLURM_CONF=$tmp/slurm.conf$" "$f" 2> /dev/null && kill -KILL "$pid" 2> /dev/null
  done
  sleep 2
  while read -r pid; do kill -KILL "$pid" 2> /dev/null; done < "$tmp/pids"
  rm -rf "$tmp"
  exit 0
fi

repo=$1
work=$2
indent=$3
python=$4
mpiexec=$5
shift 5
case_options=("$@")
job_script=$repo/scripts/jobs/slurm-paper-case.sh
t_start=$(date +%s)
deadline=$((t_start + 240)) # the ctest TIMEOUT is 300 s

skip() {
  echo "SKIP: $*"
  exit "$skip_status"
}

# Prerequisites: root, and the Debian packages slurm-wlm and munge (scripts/install-deps.sh).
[[ $(id -u) == 0 ]] || skip "not root: a private munged, slurmctld and slurmd need root (no real-Slurm test)"
PATH=$PATH:/usr/sbin:/sbin
for cmd in munged munge unmunge slurmctld slurmd sbatch scontrol scancel sinfo srun; do
  command -v "$cmd" > /dev/null || skip "$cmd not installed (apt-get install slurm-wlm munge; scripts/install-deps.sh)"
done
[[ -x $indent ]] || { echo "FAIL: no indent at $indent"; exit 1; }

rm -rf "$work"
mkdir -p "$work"
# The daemons' files in a short path under /tmp (a Unix socket path has at most 107 characters):
# munged wants its socket's directory searchable by all.
tmp=$(mktemp -d /tmp/indent-slurm.XXXXXX) || { echo "FAIL: mktemp"; exit 1; }
chmod 755 "$tmp"
mkdir -p "$tmp/state" "$tmp/spool"
: > "$tmp/pids"
export SLURM_CONF=$tmp/slurm.conf
job_id=""
# A job's states on its way to the end: scontrol prints a state flag in place of RUNNING while it is
# set (SIGNALING while --signal's warning is delivered, REQUEUED, STAGE_OUT ...).
unfinished='PENDING|RUNNING|COMPLETING|CONFIGURING|REQUEUED|REQUEUE_FED|RESIZING|SUSPENDED|SIGNALING|STAGE_OUT'
daemons=() # slurmd, slurmctld, munged: stopped in this order
watchdog_pid=""

# save_logs: the daemons' logs into WORKDIR, kept after the test; show_logs: the job's output and the
# ends of the logs.
save_logs() {
  local f
  for f in munged.log slurmctld.log slurmd.log slurmctld.out slurmd.out; do
    [[ -f $tmp/$f ]] && cp "$tmp/$f" "$work/$f"
  done
}
show_logs() {
  local f
  for f in "$work"/job-*.out "$tmp/slurmctld.log" "$tmp/slurmd.log" "$tmp/munged.log"; do
    [[ -f $f ]] || continue
    echo "---- $(basename "$f") (last 40 lines)"
    tail -n 40 "$f"
  done
}

# The processes started under this test's slurm.conf but this shell (a zombie's environment is
# unreadable: not listed).
# shellcheck disable=SC2317 # (called by cleanup)
job_processes() {
  local f pid
  for f in /proc/[0-9]*/environ; do
    pid=${f#/proc/}
    pid=${pid%/environ}
    [[ $pid == "$$" || $pid == "$BASHPID" ]] && continue
    grep -qz "^SLURM_CONF=$tmp/slurm.conf$" "$f" 2> /dev/null && echo "$pid"
  done
}

# The EXIT trap: cancel the job, stop slurmd, slurmctld and munged (TERM, then KILL after 10 s), end
# any process still running under this slurm.conf (slurmstepd, the batch shell, srun, indent), and
# remove the temporary directory.
# shellcheck disable=SC2317 # (called by the trap)
cleanup() {
  local pid f alive
  trap - EXIT INT TERM
  if [[ -n $job_id ]] && scontrol -o show job "$job_id" 2> /dev/null | grep -Eq "JobState=($unfinished)"; then
    scancel "$job_id" 2> /dev/null
    for _ in $(seq 20); do
      scontrol -o show job "$job_id" 2> /dev/null | grep -Eq "JobState=($unfinished)" || break
      sleep 0.5
    done
  fi
  save_logs
  for pid in "${daemons[@]}"; do kill -TERM "$pid" 2> /dev/null; done
  for _ in $(seq 40); do
    alive=0
    for pid in "${daemons[@]}"; do kill -0 "$pid" 2> /dev/null && alive=1; done
    ((alive)) || break
    sleep 0.25
  done
  for pid in "${daemons[@]}"; do
    if kill -0 "$pid" 2> /dev/null; then
      echo "note: daemon $pid did not stop on SIGTERM: SIGKILL"
      kill -KILL "$pid" 2> /dev/null
    fi
  done
  ((${#daemons[@]})) && wait "${daemons[@]}" 2> /dev/null
  # slurmstepd and the job's processes (their environment holds this SLURM_CONF) end by themselves
  # once the job has ended: give them 5 s.
  for _ in $(seq 10); do
    [[ -z $(job_processes) ]] && break
    sleep 0.5
  done
  for pid in $(job_processes); do
    echo "note: process $pid of the job still running: SIGKILL ($(tr '\0' ' ' < "/proc/$pid/cmdline" 2> /dev/null))"
    kill -KILL "$pid" 2> /dev/null
  done
  rm -rf "$tmp"
  [[ -n $watchdog_pid ]] && kill "$watchdog_pid" 2> /dev/null
}
trap cleanup EXIT
trap 'exit 143' TERM
trap 'exit 130' INT

fail() {
  echo "FAIL: $*"
  [[ -n $job_id ]] && scontrol show job "$job_id" 2> /dev/null
  save_logs
  show_logs
  echo "(logs in $work)"
  exit 1
}

# The watchdog, in a session of its own: cleans up if this shell is killed (SIGKILL, no trap).
env -u SLURM_CONF setsid bash "$0" --watchdog $$ "$tmp" < /dev/null > /dev/null 2>&1 &
watchdog_pid=$!

# A free TCP port on this host (for slurmctld and slurmd: not Slurm's 6817/6818, which a Slurm
# installed on the machine may use).
free_port() {
  "$python" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# ---- 1. the daemons
node=$(hostname -s)
dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 status=none
chmod 600 "$tmp/munge.key"
munged --foreground --key-file="$tmp/munge.key" --socket="$tmp/munge.sock" --pid-file="$tmp/munged.pid" \
  --log-file="$tmp/munged.log" --seed-file="$tmp/munged.seed" > "$tmp/munged.out" 2>&1 &
munged_pid=$!
daemons=("$munged_pid")
echo "$munged_pid" >> "$tmp/pids"
for _ in $(seq 50); do
  [[ -S $tmp/munge.sock ]] && break
  kill -0 "$munged_pid" 2> /dev/null || break
  sleep 0.1
done
if ! munge -n -S "$tmp/munge.sock" 2> /dev/null | unmunge -S "$tmp/munge.sock" > /dev/null 2>&1; then
  skip "munged did not start: $(tail -n 1 "$tmp/munged.out" "$tmp/munged.log" 2> /dev/null | grep -v '^==>' | grep . | tail -n 1)"
fi

ctld_port=$(free_port)
slurmd_port=$(free_port)
while [[ $slurmd_port == "$ctld_port" ]]; do slurmd_port=$(free_port); done
# No cgroups: processes tracked by their parentage (proctrack/linuxproc), no task binding or
# accounting; cgroup/v1 because slurmd 22.05 initialises a cgroup plugin even when nothing uses
# it, and v1's does not touch /sys/fs/cgroup (v2's needs systemd or a writable hierarchy).
# cred_expire=5: a requeued job may start again 6 s after the requeue (Slurm's default: 121 s).
# sched_interval=1: a pending job is looked at every second (default 60 s). MpiDefault=pmix: srun
# starts Open MPI's ranks through PMIx (with "none" MPI_Init fails).
cat > "$tmp/slurm.conf" << EOF
ClusterName=indenttest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.sock,cred_expire=5
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
SlurmctldDebug=debug2
SlurmdDebug=info
MailProg=/bin/true
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
SchedulerParameters=sched_interval=1
MpiDefault=pmix
ReturnToService=2
MinJobAge=600
KillWait=5
InactiveLimit=0
SlurmdParameters=config_overrides
NodeName=$node NodeAddr=127.0.0.1 CPUs=2 Sockets=1 CoresPerSocket=2 ThreadsPerCore=1 State=UNKNOWN
PartitionName=indent Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
cat > "$tmp/cgroup.conf" << EOF
CgroupPlugin=cgroup/v1
CgroupAutomount=no
EOF
# srun's PMIx keeps its clients' files here, not in /tmp.
echo "PMIxCliTmpDirBase=$tmp" > "$tmp/mpi.conf"

# slurmctld checks the running jobs' time limits (and sends --signal's warning) every 30 s from
# its start: t_ctld + 30, + 60, ... (t_ctld refined from its log below)
t_ctld=$(date +%s.%N)
slurmctld -D -i -f "$tmp/slurm.conf" > "$tmp/slurmctld.out" 2>&1 &
ctld_pid=$!
daemons=("$ctld_pid" "${daemons[@]}")
echo "$ctld_pid" >> "$tmp/pids"
slurmd -D -N "$node" -f "$tmp/slurm.conf" > "$tmp/slurmd.out" 2>&1 &
slurmd_pid=$!
daemons=("$slurmd_pid" "${daemons[@]}")
echo "$slurmd_pid" >> "$tmp/pids"
state=""
for _ in $(seq 100); do
  kill -0 "$ctld_pid" 2> /dev/null || skip "slurmctld did not start: $(grep -E 'error|fatal' "$tmp/slurmctld.out" | tail -n 1)"
  kill -0 "$slurmd_pid" 2> /dev/null || skip "slurmd did not start: $(grep -E 'error|fatal' "$tmp/slurmd.out" | tail -n 1)"
  state=$(sinfo -h -n "$node" -o %t 2> /dev/null)
  [[ $state == idle ]] && break
  sleep 0.2
done
[[ $state == idle ]] || skip "the Slurm node did not come up (state '$state'): $(grep -E 'error|fatal' "$tmp/slurmd.out" | tail -n 1)"
# The checks' clock starts at the whole second (time(), truncated) at which slurmctld's background thread
# begins, just after it logs its start; under load that comes a second or more after its launch (t_ctld), and
# a job timed from t_ctld then missed the first check (it ended first). Time them from the logged second.
started=$(grep -m 1 -E '^\[[^]]*\] slurmctld version .* started' "$tmp/slurmctld.log" | sed 's/^\[\([^]]*\)\].*/\1/')
if [[ -n $started ]] && logged=$(date -d "$started" +%s 2> /dev/null); then
  t_ctld=$logged
fi
echo "ok: munged, slurmctld and slurmd running (node $node, ports $ctld_port and $slurmd_port), $(slurmctld -V)"

# ---- 2. the uninterrupted run, without Slurm, with the job's options
cd "$repo" || fail "cd $repo"
t0=$(date +%s.%N)
timeout 120 "$mpiexec" -n 2 "$indent" -options_file inputs/berkovich.opts "${case_options[@]}" \
  -output_dir "$work/reference" > "$work/reference.log" 2>&1 || {
  tail -n 30 "$work/reference.log"
  fail "the reference run failed"
}
t1=$(date +%s.%N)
ref_seconds=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')
ref_steps=$(($(wc -l < "$work/reference/load_displacement.csv") - 1))
echo "ok: the uninterrupted run: $ref_steps steps in $ref_seconds s"

# ---- 3. the job, submitted so that it starts a third of the reference's wall time (plus sbatch's
# 0.4 s) before a time-limit check of slurmctld: the warning then reaches indent after about a third
# of its steps, and still within them if this run is up to 3 times faster or slower than the
# reference (the set-up before step 1 takes a few percent of it). --time=1 (minute) and
# --signal=B:USR1@30: the warning is due at the first check after the start (a check sends it when
# the limit is at most 30 + 30 s away); the limit, 60 s after the start, is checked at the first
# check at or after it.
now=$(date +%s.%N)
read -r submit_at check_at < <(awk -v c0="$t_ctld" -v now="$now" -v ref="$ref_seconds" 'BEGIN {
  lead = ref / 3 + 0.4
  for (k = 1; ; k++) {
    c = c0 + 30.1 + 30.05 * (k - 1)
    if (c - lead >= now + 0.2) { printf "%.2f %.2f\n", c - lead, c; exit }
  }
}')
sleep "$(awk -v a="$submit_at" -v b="$(date +%s.%N)" 'BEGIN { d = a - b; printf "%.2f", (d > 0 ? d : 0) }')"
out=$work/run
sbatch_args=(--parsable --job-name=indent-slurm-real --ntasks=2 --time=1 --signal=B:USR1@30
  --output="$work/job-%j.out")
t_submit=$(date +%s.%N)
job_id=$(INDENT_EXE=$indent INDENT_OUTPUT_DIR=$out INDENT_EXTRA_OPTIONS="${case_options[*]}" \
  INDENT_MAX_RESUBMITS=3 sbatch "${sbatch_args[@]}" "$job_script" 2> "$work/sbatch.err") ||
  fail "sbatch failed: $(cat "$work/sbatch.err")"
job_id=${job_id%%;*}
echo "ok: submitted job $job_id ($(awk -v a="$check_at" -v b="$t_submit" 'BEGIN { printf "%.1f", a - b }') s before a check of slurmctld):"
echo "  (cd $repo; INDENT_EXE=... INDENT_OUTPUT_DIR=... INDENT_EXTRA_OPTIONS=\"...\" INDENT_MAX_RESUBMITS=3 sbatch ${sbatch_args[*]} scripts/jobs/slurm-paper-case.sh)"

# ---- 4. wait for it (at most 150 s, and the test's deadline), then check.
job_deadline=$(($(date +%s) + 150))
((job_deadline > deadline)) && job_deadline=$deadline
state=""
seen_count=""
seen_restarts=""
batch_script=$tmp/spool/job$(printf %05d "$job_id")/slurm_script
while (($(date +%s) < job_deadline)); do
  info=$(scontrol -o show job "$job_id" 2> /dev/null)
  state=$(sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' <<< "$info")
  # The requeued part's batch shell: SLURM_RESTART_COUNT in its environment (the job script's count
  # of resubmissions for MAX_RESUBMITS).
  running_restarts=$(sed -n 's/.*[[:space:]]Restarts=\([0-9]*\).*/\1/p' <<< "$info")
  if [[ -z $seen_count && $state == RUNNING && ${running_restarts:-0} -ge 1 ]]; then
    for f in /proc/[0-9]*/cmdline; do
      if grep -qaF -- "$batch_script" "$f" 2> /dev/null; then
        seen_count=$(tr '\0' '\n' < "${f%/cmdline}/environ" 2> /dev/null | sed -n 's/^SLURM_RESTART_COUNT=//p')
        seen_restarts=$running_restarts
        [[ -n $seen_count ]] && break
      fi
    done
  fi
  [[ -z $state ]] || grep -Eqx "$unfinished" <<< "$state" || break
  sleep 0.5
done
job_out=$work/job-$job_id.out
if [[ $state != COMPLETED ]]; then
  [[ -z $state ]] || grep -Eqx "$unfinished" <<< "$state" &&
    fail "job $job_id not finished after $(($(date +%s) - ${t_submit%.*})) s (state ${state:-unknown})"
  fail "job $job_id ended in state $state"
fi
exit_code=$(sed -n 's/.*[[:space:]]ExitCode=\([0-9:]*\).*/\1/p' <<< "$info")
restarts=$(sed -n 's/.*[[:space:]]Restarts=\([0-9]*\).*/\1/p' <<< "$info")
[[ $exit_code == 0:0 ]] || fail "job $job_id: ExitCode=$exit_code"
((restarts >= 1)) || fail "job $job_id was not requeued (Restarts=$restarts): the warning did not come in time"
grep -q "got SIGUSR1" "$job_out" || fail "the batch shell did not get SIGUSR1"
grep -q "indent: stopped by SIGUSR1 after step" "$job_out" || fail "indent did not report the signal"
grep -q "requeueing job $job_id (resubmission 1 of" "$job_out" || fail "the job did not requeue itself"
grep -q "continuing from $out/checkpoint.h5" "$job_out" || fail "the requeued job did not continue from the checkpoint"
grep -q "indent finished: $out/summary.json" "$job_out" || fail "the job did not finish the run"
if grep -q "indent failed" "$job_out"; then fail "indent failed in a part of the job"; fi
[[ ! -e $out/checkpoint.h5 ]] || fail "the finished run kept its checkpoint"
steps=$(($(wc -l < "$out/load_displacement.csv") - 1))
((steps == ref_steps)) || fail "the job's curve has $steps steps, the uninterrupted run's $ref_steps"
[[ -n $seen_count && $seen_count == "$seen_restarts" ]] ||
  fail "a requeued part's batch shell had SLURM_RESTART_COUNT='$seen_count', expected its Restarts ($seen_restarts)"
stop_step=$(sed -n 's/.*indent: stopped by SIGUSR1 after step \([0-9]*\).*/\1/p' "$job_out" | head -n 1)

"$python" - "$work/reference/summary.json" "$out/summary.json" << 'EOF' || fail "summary.json differs from the uninterrupted run's"
import json, sys
ref, job = (json.load(open(p)) for p in sys.argv[1:3])
bad = []
if job.get("status") != "finished" or job.get("restarted") is not True:
    bad.append(f"status {job.get('status')!r}, restarted {job.get('restarted')!r}: expected a finished, restarted run")
for key in ("P_max_uN", "H_GPa"):
    a, b = ref.get(key), job.get(key)
    if not isinstance(a, (int, float)) or not isinstance(b, (int, float)):
        bad.append(f"{key}: reference {a!r}, job {b!r} (not numbers)")
    elif abs(a - b) > 1e-8 * abs(a):
        bad.append(f"{key}: reference {a!r}, job {b!r}, relative difference {abs(a - b) / abs(a):.2e} > 1e-8")
    else:
        print(f"ok: {key} {b!r} (uninterrupted {a!r}, relative difference {abs(a - b) / abs(a):.1e})")
for line in bad:
    print(line)
sys.exit(1 if bad else 0)
EOF

# Timings from slurmctld's log (its clock, ms): the starts, the warning, the requeue, the end.
stamp() {
  grep -E "$1" "$tmp/slurmctld.log" | sed -n "${2:-1}s/^\[\([^]]*\)\].*/\1/p"
}
since() {
  local t
  [[ -n $1 ]] || { echo "?"; return; }
  t=$(date -d "$1" +%s.%N)
  awk -v a="$t_submit" -v b="$t" 'BEGIN { printf "%.1f", b - a }'
}
start1=$(stamp "sched: Allocate JobId=$job_id " 1)
warn=$(stamp "warning signal 10 to JobId=$job_id\$" 1)
requeue=$(stamp "Requeuing JobId=$job_id\$" 1)
start2=$(stamp "sched: Allocate JobId=$job_id " 2)
done_at=$(stamp "_job_complete: JobId=$job_id done" "\$")
echo "ok: job $job_id COMPLETED, Restarts=$restarts (SLURM_RESTART_COUNT=$seen_count in the requeued part); seconds after sbatch: started $(since "$start1"), SIGUSR1 $(since "$warn")" \
  "(after step $stop_step of $ref_steps), requeued $(since "$requeue"), started again $(since "$start2"), finished $(since "$done_at");" \
  "test $(($(date +%s) - t_start)) s"
echo "all real-Slurm checks passed"
exit 0
