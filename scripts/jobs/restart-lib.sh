# shellcheck shell=bash
# Sourced by the batch job scripts (slurm-paper-case.sh, pbs-paper-case.sh and those scripts/sweep.py
# writes from them): decides whether a run starts, continues from its checkpoint or is already done,
# runs the MPI launcher with the batch shell forwarding its signals to it, and resubmits the job
# when indent exits with 75 (EX_TEMPFAIL: checkpoint written, run not finished). doc/cluster.md.
#
# The job script sets, before calling indent_job_main slurm|pbs:
#   RUN_DIR          directory the run starts in (relative paths in the options are relative to it)
#   INDENT_EXE       the indent executable
#   OUTPUT_DIR       indent's -output_dir, where the checkpoint is looked for
#   INDENT_OPTIONS   array: indent's options (without -output_dir and -restart); the environment's
#                    INDENT_EXTRA_OPTIONS (split at blanks) come after them, so they override them
#   LAUNCHER         array: the MPI launcher and its arguments (srun; mpiexec -n N)
#   MAX_RESUBMITS    resubmissions allowed in all (Slurm counts requeues in SLURM_RESTART_COUNT)
#   OVERWRITE_PARTIAL  1: a run directory holding an unfinished run without checkpoint is started
#                    again with -output_overwrite; 0: indent refuses it and the job stops
#   JOB_SCRIPT       the script to submit again (sbatch or qsub)
#   Slurm: RESUBMIT  requeue (scontrol requeue: the same job id) or sbatch (a new job)
#   PBS: SIGNAL_MARGIN  seconds before the wall-time limit at which indent is told to checkpoint

INDENT_EX_TEMPFAIL=75
# The files by which indent recognises a run in its -output_dir (RunFiles in src/io/rundir.c): a fresh
# run refuses a directory holding any of them unless -output_overwrite is given.
INDENT_RUN_FILES=(indent.h5 indent.xdmf indent.xdmf.tmp load_displacement.csv summary.txt summary.json
  checkpoint.h5 checkpoint.h5.tmp checkpoint.previous.h5 mesh.msh mesh.msh.log imprint.csv imprint.png
  load_displacement.png stress_slice.png indent.stopped)

indent_log() {
  printf 'indent-job %s: %s\n' "$(date '+%F %T')" "$*"
}

# finished | interrupted | partial | new: the state of the run in directory $1. A summary.json
# without a "status" key is finished (indent wrote it only at the end before it had checkpoints).
indent_run_state() {
  local dir=$1 f
  if [[ -f $dir/summary.json ]]; then
    if ! grep -q '"status"' "$dir/summary.json" ||
      grep -Eq '"status"[[:space:]]*:[[:space:]]*"finished"' "$dir/summary.json"; then
      echo finished
      return 0
    fi
  fi
  if [[ -f $dir/checkpoint.h5 ]]; then
    echo interrupted
    return 0
  fi
  for f in "${INDENT_RUN_FILES[@]}"; do
    if [[ -e $dir/$f ]]; then
      echo partial
      return 0
    fi
  done
  echo new
}

# Seconds from [[HH:]MM:]SS or a plain number of seconds; nothing for anything else.
indent_hms_seconds() {
  local t=$1 h=0 m=0 s
  if [[ $t =~ ^([0-9]+):([0-9]+):([0-9]+)$ ]]; then
    h=${BASH_REMATCH[1]} m=${BASH_REMATCH[2]} s=${BASH_REMATCH[3]}
  elif [[ $t =~ ^([0-9]+):([0-9]+)$ ]]; then
    m=${BASH_REMATCH[1]} s=${BASH_REMATCH[2]}
  elif [[ $t =~ ^([0-9]+)$ ]]; then
    s=${BASH_REMATCH[1]}
  else
    return 1
  fi
  echo $((10#$h * 3600 + 10#$m * 60 + 10#$s))
}

# The PBS job's wall time in seconds: $INDENT_WALLTIME, Torque's $PBS_WALLTIME, qstat -f, or the
# "#PBS -l walltime=" line of $JOB_SCRIPT, in that order.
indent_pbs_walltime() {
  local w=""
  if [[ -n ${INDENT_WALLTIME:-} ]]; then
    w=$INDENT_WALLTIME
  elif [[ -n ${PBS_WALLTIME:-} ]]; then
    w=$PBS_WALLTIME
  elif [[ -n ${PBS_JOBID:-} ]] && command -v qstat > /dev/null 2>&1; then
    w=$(qstat -f "$PBS_JOBID" 2> /dev/null |
      sed -n 's/^[[:space:]]*Resource_List\.walltime[[:space:]]*=[[:space:]]*//p' | head -n 1)
  fi
  if [[ -z $w && -r ${JOB_SCRIPT:-} ]]; then
    w=$(sed -n 's/^#PBS[[:space:]].*walltime=\([0-9:]*\).*/\1/p' "$JOB_SCRIPT" | head -n 1)
  fi
  [[ -n $w ]] && indent_hms_seconds "$w"
}

# The batch shell's signals go to the launcher as SIGUSR1, which indent (through srun or mpiexec)
# answers by checkpointing and exiting with 75. USR1 is the scheduler's warning before the time
# limit; TERM and INT mean the job is being cancelled: the run still checkpoints, but the job is
# not resubmitted.
_indent_on_signal() {
  if [[ $1 == USR1 ]]; then
    INDENT_GOT_WARNING=1
  else
    INDENT_CANCELLED=1
  fi
  indent_log "got SIG$1: asking indent to checkpoint and stop (SIGUSR1 to the launcher)"
  if [[ -n ${_INDENT_CHILD:-} ]]; then
    kill -USR1 "$_INDENT_CHILD" 2> /dev/null || true
  else
    _INDENT_PENDING=1
  fi
}

# Runs "$@" in the background and waits for it, forwarding signals; returns its exit status.
indent_run_forwarding() {
  local rc
  INDENT_GOT_WARNING=0 INDENT_CANCELLED=0 _INDENT_PENDING=0 _INDENT_CHILD=""
  trap '_indent_on_signal USR1' USR1
  trap '_indent_on_signal TERM' TERM
  trap '_indent_on_signal INT' INT
  "$@" &
  _INDENT_CHILD=$!
  if ((_INDENT_PENDING)); then
    kill -USR1 "$_INDENT_CHILD" 2> /dev/null || true
  fi
  # A trapped signal ends `wait` early (status > 128) while the launcher still runs: wait again.
  while kill -0 "$_INDENT_CHILD" 2> /dev/null; do
    wait "$_INDENT_CHILD"
  done
  wait "$_INDENT_CHILD"
  rc=$?
  trap - USR1 TERM INT
  _INDENT_CHILD=""
  return "$rc"
}

_indent_resubmit_slurm() {
  local count=$1
  if [[ ${RESUBMIT:-requeue} == requeue && -n ${SLURM_JOB_ID:-} ]]; then
    indent_log "requeueing job $SLURM_JOB_ID (resubmission $((count + 1)) of at most $MAX_RESUBMITS)"
    if scontrol requeue "$SLURM_JOB_ID"; then
      return 0
    fi
    indent_log "scontrol requeue failed (is the job requeueable? #SBATCH --requeue); submitting it again instead"
  fi
  indent_log "sbatch $JOB_SCRIPT (resubmission $((count + 1)) of at most $MAX_RESUBMITS)"
  sbatch --export="ALL,INDENT_RESUBMIT_COUNT=$((count + 1))" "$JOB_SCRIPT"
}

_indent_resubmit_pbs() {
  local count=$1 vars name
  # qsub passes no environment by default: the count and the INDENT_* settings exported at
  # submission (a value holding commas goes in single quotes, as qsub -v wants).
  vars="INDENT_RESUBMIT_COUNT=$((count + 1))"
  while read -r name; do
    if [[ $name == INDENT_RESUBMIT_COUNT ]]; then
      continue
    elif [[ ${!name} == *,* ]]; then
      vars+=",$name='${!name}'"
    else
      vars+=",$name=${!name}"
    fi
  done < <(compgen -e | grep '^INDENT_')
  indent_log "qsub $JOB_SCRIPT (resubmission $((count + 1)) of at most $MAX_RESUBMITS)"
  qsub -v "$vars" "$JOB_SCRIPT"
}

# indent_job_main slurm|pbs: the whole job. Its status is indent's, except 0 after a resubmission.
indent_job_main() {
  local flavor=$1 state rc count limit walltime start
  local -a extra=() cmd=() more=()
  cd "$RUN_DIR" || return 1
  state=$(indent_run_state "$OUTPUT_DIR")
  case $state in
    finished)
      indent_log "$OUTPUT_DIR holds a finished run (summary.json): nothing to do"
      return 0
      ;;
    interrupted)
      extra=(-restart "$OUTPUT_DIR")
      indent_log "continuing from $OUTPUT_DIR/checkpoint.h5"
      ;;
    partial)
      if [[ ${OVERWRITE_PARTIAL:-0} == 1 ]]; then
        extra=(-output_overwrite)
        indent_log "$OUTPUT_DIR holds an unfinished run without checkpoint: starting it again"
      else
        indent_log "$OUTPUT_DIR holds an unfinished run without checkpoint: indent will refuse it" \
          "(set OVERWRITE_PARTIAL=1 to start it again, or choose another OUTPUT_DIR)"
      fi
      ;;
    new) indent_log "starting a new run in $OUTPUT_DIR" ;;
  esac
  read -r -a more <<< "${INDENT_EXTRA_OPTIONS:-}"
  cmd=("${LAUNCHER[@]}" "$INDENT_EXE" "${INDENT_OPTIONS[@]}" "${more[@]}" -output_dir "$OUTPUT_DIR" "${extra[@]}")
  if [[ $flavor == pbs ]]; then
    # PBS sends no warning before the limit: timeout sends SIGUSR1 to the launcher SIGNAL_MARGIN
    # seconds before it (--foreground: to the launcher only, which passes it on to every rank
    # once; --preserve-status: indent's 75 comes back, not timeout's 124).
    if walltime=$(indent_pbs_walltime); then
      limit=$((walltime - ${SIGNAL_MARGIN:-300} - SECONDS))
      if ((limit < 1)); then
        indent_log "wall time ${walltime} s leaves no time before the margin of ${SIGNAL_MARGIN:-300} s"
        return 1
      fi
      indent_log "wall time ${walltime} s: checkpoint signal in ${limit} s"
      cmd=(timeout --foreground --preserve-status --signal=USR1 "${limit}s" "${cmd[@]}")
    else
      indent_log "wall time unknown (set INDENT_WALLTIME): no checkpoint before the limit"
    fi
  fi
  indent_log "running: ${cmd[*]}"
  start=$(date +%s)
  indent_run_forwarding "${cmd[@]}"
  rc=$?
  if ((rc == 0)); then
    indent_log "indent finished: $OUTPUT_DIR/summary.json"
    return 0
  fi
  # Open MPI's mpiexec reports a status of its own (1) after forwarding SIGTERM, though every rank wrote the
  # checkpoint and exited with 75: the marker indent leaves beside the checkpoint says it stopped.
  if ((rc != INDENT_EX_TEMPFAIL)) && [[ -f $OUTPUT_DIR/indent.stopped ]] &&
    (($(stat -c %Y "$OUTPUT_DIR/indent.stopped") >= start)); then
    indent_log "the launcher exited with $rc, but indent stopped with a checkpoint ($(cat "$OUTPUT_DIR/indent.stopped")):" \
      "as exit status 75"
    rc=$INDENT_EX_TEMPFAIL
  fi
  if ((rc != INDENT_EX_TEMPFAIL)); then
    indent_log "indent failed with exit status $rc: not resubmitting"
    return "$rc"
  fi
  # PETSc's error code 75 (PETSC_ERR_ARG_INCOMP) is also an exit status of 75: only a checkpoint
  # written by this run means that the run stopped to be continued.
  if ! [[ -f $OUTPUT_DIR/checkpoint.h5 ]] || (($(stat -c %Y "$OUTPUT_DIR/checkpoint.h5") < start)); then
    indent_log "exit status 75 but no new checkpoint: an error (PETSc's code 75: incompatible arguments)," \
      "not resubmitting"
    return "$rc"
  fi
  if ((INDENT_CANCELLED && !INDENT_GOT_WARNING)); then
    indent_log "job cancelled; checkpoint in $OUTPUT_DIR. Submit this script again to continue"
    return "$rc"
  fi
  count=$((${SLURM_RESTART_COUNT:-0} + ${INDENT_RESUBMIT_COUNT:-0}))
  if ((count >= MAX_RESUBMITS)); then
    indent_log "checkpoint written, but $count resubmissions reached MAX_RESUBMITS=$MAX_RESUBMITS:" \
      "submit this script again to continue"
    return "$rc"
  fi
  if ! "_indent_resubmit_$flavor" "$count"; then
    indent_log "resubmission failed; checkpoint in $OUTPUT_DIR: submit this script again to continue"
    return "$rc"
  fi
  return 0
}
