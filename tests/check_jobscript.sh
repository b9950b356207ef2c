#!/usr/bin/env bash
# check_jobscript.sh REPO WORKDIR: runs scripts/jobs/slurm-paper-case.sh and pbs-paper-case.sh with
# stub srun, mpiexec, scontrol, sbatch, qsub and qstat first on PATH (written here into WORKDIR). The
# stub launcher records its arguments and exits 0 or 75 or waits for SIGUSR1 (then exits 75, as
# indent does after its checkpoint). Checks: -restart is added exactly when a checkpoint exists; a
# finished run is not started again; exit 75 requeues (scontrol requeue, else sbatch; PBS: qsub)
# and exit 0 or a failure does not; the resubmission cap; SIGUSR1 to the batch shell reaches the
# launcher; a cancelled job (SIGTERM) checkpoints without requeueing; under PBS, timeout signals
# the launcher before the wall time read from qstat.
# check_jobscript.sh REPO WORKDIR --real INDENT MPIEXEC OPTIONS...: the Slurm script around the real
# indent (srun is MPIEXEC -n 2; OPTIONS, a tiny case, go in INDENT_EXTRA_OPTIONS).
set -u
repo=$1
work=$2
rm -rf "$work"
mkdir -p "$work/stubs"
stubs=$work/stubs
out=$work/out
slurm_script=$repo/scripts/jobs/slurm-paper-case.sh
pbs_script=$repo/scripts/jobs/pbs-paper-case.sh
for f in "$slurm_script" "$pbs_script" "$repo/scripts/jobs/restart-lib.sh"; do
  bash -n "$f" || { echo "FAIL: bash -n $f"; exit 1; }
done

cat > "$stubs/launcher" << 'EOF'
#!/bin/bash
# Stub MPI launcher: one argument per line in launch_args, then as STUB_MODE says. Exit 75 comes
# with a new checkpoint in the -output_dir, as indent writes it; error75 is an error with code 75.
printf '%s\n' "$@" > "$STUB_DIR/launch_args"
echo launched >> "$STUB_DIR/calls"
out=$(grep -A1 -x -- -output_dir "$STUB_DIR/launch_args" | tail -n 1)
case $STUB_MODE in
  exit75) echo new > "$out/checkpoint.h5"; exit 75 ;;
  error75) exit 75 ;;
  stopped1) echo new > "$out/checkpoint.h5"; echo "stopped by SIGTERM after step 3" > "$out/indent.stopped"; exit 1 ;;
  exit*) exit "${STUB_MODE#exit}" ;;
  wait)
    trap 'echo USR1 >> "$STUB_DIR/signals"; echo new > "$out/checkpoint.h5"; exit 75' USR1
    touch "$STUB_DIR/ready"
    for _ in $(seq 300); do sleep 0.1; done
    echo "stub launcher: no SIGUSR1 within 30 s" >&2
    exit 9 ;;
esac
EOF
for name in srun mpiexec; do cp "$stubs/launcher" "$stubs/$name"; done
for name in scontrol sbatch qsub; do
  cat > "$stubs/$name" << EOF
#!/bin/bash
echo "$name \$*" >> "\$STUB_DIR/calls"
exit \${STUB_${name^^}_RC:-0}
EOF
done
cat > "$stubs/qstat" << 'EOF'
#!/bin/bash
echo "Job Id: $2"
echo "    Resource_List.walltime = $STUB_WALLTIME"
EOF
chmod +x "$stubs"/*

fail() {
  echo "FAIL: $*"
  echo "---- job output"
  cat "$work/job.out"
  echo "---- stub calls"
  cat "$work/calls" 2> /dev/null
  exit 1
}

# Fresh output directory and stub records; $1: what the output directory holds.
reset() {
  rm -rf "$out" "$work"/{launch_args,calls,signals,ready,job.out}
  mkdir -p "$out"
  case $1 in
    checkpoint)
      echo old > "$out/checkpoint.h5"
      touch -d '1 hour ago' "$out/checkpoint.h5"
      echo "step,t" > "$out/load_displacement.csv"
      ;;
    finished) printf '{\n  "P_max_uN": 13.7,\n  "status": "finished"\n}\n' > "$out/summary.json" ;;
    partial) echo "step,t" > "$out/load_displacement.csv" ;;
    empty) ;;
  esac
}

# The job environment: stubs first on PATH, no Slurm/PBS variables but the ones given. env execs
# the job shell, so that a background job's $! is the batch shell itself.
jobenv=(env -u SLURM_RESTART_COUNT -u INDENT_RESUBMIT_COUNT -u PBS_WALLTIME -u INDENT_WALLTIME -u PBS_JOBID
  PATH="$stubs:$PATH" STUB_DIR="$work" INDENT_REPO="$repo" INDENT_EXE=/opt/fake/indent INDENT_OUTPUT_DIR="$out")
slurmenv=("${jobenv[@]}" SLURM_JOB_ID=4242 SLURM_SUBMIT_DIR="$repo")

slurm() {
  "${slurmenv[@]}" "$@" bash "$slurm_script" > "$work/job.out" 2>&1
}

# The launcher got option $1 followed by value $2.
has_arg_pair() {
  grep -qx -- "$1" "$work/launch_args" && grep -A1 -x -- "$1" "$work/launch_args" | tail -n 1 | grep -qx -- "$2"
}
called() { grep -q -- "$1" "$work/calls" 2> /dev/null; }

# --real: the Slurm script around the real indent, srun standing for mpiexec -n 2. SIGUSR1 to the batch
# shell after two steps: checkpoint, status 75, requeue; the requeued job continues with -restart
# and finishes; a third start does nothing.
if [[ ${3:-} == --real ]]; then
  indent=$4
  mpiexec=$(command -v "$5") || { echo "FAIL: no $5"; exit 1; }
  shift 5
  printf '#!/bin/bash\nexec %q -n 2 "$@"\n' "$mpiexec" > "$stubs/srun"
  real=("${slurmenv[@]}" INDENT_EXE="$indent" INDENT_EXTRA_OPTIONS="$*")
  reset empty
  "${real[@]}" bash "$slurm_script" > "$work/job.out" 2>&1 &
  job=$!
  for _ in $(seq 1200); do
    [[ -f $out/load_displacement.csv && $(wc -l < "$out/load_displacement.csv") -ge 3 ]] && break
    kill -0 "$job" 2> /dev/null || break
    sleep 0.1
  done
  kill -0 "$job" 2> /dev/null || fail "real: the job ended before its second step"
  kill -USR1 "$job"
  wait "$job"
  rc=$?
  ((rc == 0)) || fail "real: job exit status $rc after SIGUSR1, expected 0 (requeued)"
  grep -q "stopped by SIGUSR1" "$work/job.out" || fail "real: indent did not report the signal"
  [[ -f $out/checkpoint.h5 ]] || fail "real: no checkpoint.h5"
  called "scontrol requeue 4242" || fail "real: not requeued"
  steps=$(($(wc -l < "$out/load_displacement.csv") - 1))
  echo "ok: SIGUSR1 through the batch shell and srun: checkpoint after step $steps, requeued"
  rm -f "$work/calls"
  "${real[@]}" SLURM_RESTART_COUNT=1 bash "$slurm_script" > "$work/job.out" 2>&1
  rc=$?
  ((rc == 0)) || fail "real: the requeued job's exit status $rc"
  grep -q -- "-restart $out" "$work/job.out" || fail "real: the requeued job did not pass -restart"
  grep -q "continuing from" "$work/job.out" || fail "real: indent did not continue from the checkpoint"
  grep -Eq '"status": *"finished"' "$out/summary.json" 2> /dev/null || fail "real: no finished summary.json"
  [[ ! -e $out/checkpoint.h5 ]] || fail "real: the finished run kept its checkpoint"
  called scontrol && fail "real: requeued a finished run"
  echo "ok: the requeued job continued and finished ($(($(wc -l < "$out/load_displacement.csv") - 1)) steps)"
  "${real[@]}" SLURM_RESTART_COUNT=2 bash "$slurm_script" > "$work/job.out" 2>&1
  rc=$?
  if ((rc != 0)) || ! grep -q "nothing to do" "$work/job.out"; then
    fail "real: a finished run was started again"
  fi
  echo "ok: a third start does nothing"
  echo "all real job-script checks passed"
  exit 0
fi

# 1. New run, exit 0: no -restart, the options and -output_dir passed on, no requeue.
reset empty
slurm STUB_MODE=exit0
rc=$?
((rc == 0)) || fail "new run: exit status $rc"
has_arg_pair -options_file inputs/berkovich.opts || fail "new run: -options_file not passed"
has_arg_pair -output_dir "$out" || fail "new run: -output_dir not passed"
[[ $(head -n 1 "$work/launch_args") == /opt/fake/indent ]] || fail "new run: srun does not start INDENT_EXE"
grep -qx -- -restart "$work/launch_args" && fail "new run: -restart without a checkpoint"
called scontrol && fail "new run: requeued after exit 0"
called sbatch && fail "new run: resubmitted after exit 0"
echo "ok: new run, exit 0"

# 2. Checkpoint present: -restart OUTPUT_DIR, exit 0, no requeue.
reset checkpoint
slurm STUB_MODE=exit0
rc=$?
((rc == 0)) || fail "restart: exit status $rc"
has_arg_pair -restart "$out" || fail "restart: no '-restart $out' with a checkpoint present"
called scontrol && fail "restart: requeued after exit 0"
echo "ok: checkpoint present, -restart added"

# 3. Exit 75: scontrol requeue of the job, job exits 0.
reset checkpoint
slurm STUB_MODE=exit75
rc=$?
((rc == 0)) || fail "exit 75: job exit status $rc"
called "scontrol requeue 4242" || fail "exit 75: no 'scontrol requeue 4242'"
called sbatch && fail "exit 75: sbatch as well as requeue"
echo "ok: exit 75 requeues"

# 3b. The launcher's own status 1 after indent stopped with a checkpoint (its marker): requeues as on 75.
reset checkpoint
slurm STUB_MODE=stopped1
rc=$?
((rc == 0)) || fail "stopped, launcher status 1: job exit status $rc"
called "scontrol requeue 4242" || fail "stopped, launcher status 1: no 'scontrol requeue 4242'"
echo "ok: the stop marker requeues when the launcher reports 1"

# 4. Exit 75 with the cap reached (SLURM_RESTART_COUNT 10 of 10): no requeue, status 75.
reset checkpoint
slurm STUB_MODE=exit75 SLURM_RESTART_COUNT=10
rc=$?
((rc == 75)) || fail "cap: exit status $rc, expected 75"
called scontrol && fail "cap: requeued past MAX_RESUBMITS"
called sbatch && fail "cap: resubmitted past MAX_RESUBMITS"
echo "ok: resubmission cap"

# 5. A failure (exit 3): no requeue, the status passed on.
reset empty
slurm STUB_MODE=exit3
rc=$?
((rc == 3)) || fail "failure: exit status $rc, expected 3"
called scontrol && fail "failure: requeued after exit 3"
echo "ok: failure not requeued"

# 6. Requeue refused (job not requeueable): falls back to sbatch of the script with the count.
reset checkpoint
slurm STUB_MODE=exit75 STUB_SCONTROL_RC=1 SLURM_RESTART_COUNT=2
rc=$?
((rc == 0)) || fail "sbatch fallback: exit status $rc"
called "sbatch --export=ALL,INDENT_RESUBMIT_COUNT=3 $slurm_script" || fail "sbatch fallback: no sbatch with the count 3"
echo "ok: sbatch when requeue fails"

# 6b. Exit 75 without a new checkpoint (PETSc's error code 75, e.g. a restart refused): no requeue.
reset checkpoint
slurm STUB_MODE=error75
rc=$?
((rc == 75)) || fail "error 75: exit status $rc, expected 75"
called scontrol && fail "error 75: requeued without a new checkpoint"
called sbatch && fail "error 75: resubmitted without a new checkpoint"
echo "ok: status 75 without a new checkpoint not requeued"

# 7. A finished run is not started again.
reset finished
slurm STUB_MODE=exit3
rc=$?
((rc == 0)) || fail "finished: exit status $rc"
called launched && fail "finished: launcher started for a finished run"
echo "ok: finished run skipped"

# 8. SIGUSR1 to the batch shell (Slurm's warning) reaches the launcher; exit 75 then requeues.
reset empty
"${slurmenv[@]}" STUB_MODE=wait bash "$slurm_script" > "$work/job.out" 2>&1 &
job=$!
for _ in $(seq 100); do [[ -e $work/ready ]] && break; sleep 0.1; done
[[ -e $work/ready ]] || fail "signal: launcher not started"
kill -USR1 "$job"
wait "$job"
rc=$?
grep -qx USR1 "$work/signals" 2> /dev/null || fail "signal: SIGUSR1 to the batch shell did not reach the launcher"
((rc == 0)) || fail "signal: exit status $rc"
called "scontrol requeue 4242" || fail "signal: not requeued after the warning"
echo "ok: SIGUSR1 forwarded, requeued"

# 9. SIGTERM to the batch shell (scancel): the launcher is told to checkpoint, no requeue.
reset empty
"${slurmenv[@]}" STUB_MODE=wait bash "$slurm_script" > "$work/job.out" 2>&1 &
job=$!
for _ in $(seq 100); do [[ -e $work/ready ]] && break; sleep 0.1; done
kill -TERM "$job"
wait "$job"
rc=$?
grep -qx USR1 "$work/signals" 2> /dev/null ||
  fail "cancel: SIGTERM to the batch shell did not reach the launcher as SIGUSR1"
((rc == 75)) || fail "cancel: exit status $rc, expected 75"
called scontrol && fail "cancel: requeued a cancelled job"
echo "ok: cancelled job checkpoints, not requeued"

# 10. PBS: 3 ranks from the node file, walltime 3 s from qstat, margin 1 s: timeout sends SIGUSR1
# after about 2 s, indent's 75 comes back through timeout, and qsub submits the script again.
printf 'node1\nnode1\nnode1\n' > "$work/nodefile"
pbs() {
  "${jobenv[@]}" PBS_NODEFILE="$work/nodefile" PBS_O_WORKDIR="$repo" "$@" bash "$pbs_script" > "$work/job.out" 2>&1
}
reset checkpoint
start=$SECONDS
pbs PBS_JOBID=77.server STUB_WALLTIME=00:00:03 INDENT_SIGNAL_MARGIN=1 STUB_MODE=wait \
  INDENT_EXTRA_OPTIONS="-load_depth 10 -mesh_geo_parameters h_tip=60,h_far=600"
rc=$?
grep -qx USR1 "$work/signals" 2> /dev/null || fail "pbs: timeout did not send SIGUSR1 to the launcher"
((SECONDS - start <= 10)) || fail "pbs: the signal came after $((SECONDS - start)) s"
((rc == 0)) || fail "pbs: exit status $rc"
has_arg_pair -n 3 || fail "pbs: mpiexec not given -n 3"
has_arg_pair -restart "$out" || fail "pbs: no -restart with a checkpoint present"
called "qsub -v INDENT_RESUBMIT_COUNT=1" || fail "pbs: no qsub with the count 1"
called "$pbs_script" || fail "pbs: qsub of another script"
has_arg_pair -mesh_geo_parameters h_tip=60,h_far=600 || fail "pbs: INDENT_EXTRA_OPTIONS not passed to indent"
called ",INDENT_EXTRA_OPTIONS='-load_depth 10 -mesh_geo_parameters h_tip=60,h_far=600'" ||
  fail "pbs: INDENT_EXTRA_OPTIONS not passed on to the next job, quoted for its commas"
echo "ok: PBS timeout signal, qsub again"

# 11. PBS cap, and the wall time taken from the script's own #PBS line when qstat cannot tell.
reset checkpoint
pbs INDENT_RESUBMIT_COUNT=10 STUB_MODE=exit75
rc=$?
((rc == 75)) || fail "pbs cap: exit status $rc, expected 75"
called qsub && fail "pbs cap: resubmitted past MAX_RESUBMITS"
grep -q "wall time 3600 s" "$work/job.out" || fail "pbs: wall time not read from the #PBS line"
echo "ok: PBS cap, wall time from the script"
echo "all job-script checks passed"
