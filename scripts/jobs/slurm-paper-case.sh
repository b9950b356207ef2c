#!/bin/bash
# The paper's case (inputs/berkovich.opts on the README's h_tip 4 mesh, 160k dofs) as a Slurm job
# that checkpoints before its time limit and requeues itself until the run is finished.
# Submit it from the top of the indent checkout (edit the #SBATCH lines and the settings first):
#   sbatch scripts/jobs/slurm-paper-case.sh
# Slurm sends SIGUSR1 to this shell 300 s before the limit (--signal=B:USR1@300); the shell passes it
# on to srun, srun to every rank, and indent finishes or abandons its step, writes
# OUTPUT_DIR/checkpoint.h5 and exits with 75; the job then requeues itself and the next run adds
# -restart OUTPUT_DIR. A finished run (summary.json) makes the job do nothing. By hand:
# `scancel -b -s USR1 <job>` checkpoints and requeues now, `scancel -b -s TERM <job>` checkpoints and
# ends the job (a plain scancel may signal the ranks twice: do not count on its checkpoint).
# doc/cluster.md explains it all; scripts/sweep.py --slurm writes one such script per run of a sweep.
#SBATCH --job-name=indent-paper
#SBATCH --ntasks=8
#SBATCH --cpus-per-task=1
#SBATCH --time=01:00:00
#SBATCH --signal=B:USR1@300
#SBATCH --requeue
#SBATCH --open-mode=append
#SBATCH --output=indent-paper-%j.out

# ---- run settings (begin)
# The checkout holding build/indent and scripts/jobs: by default the directory sbatch was run in.
INDENT_REPO=${INDENT_REPO:-${SLURM_SUBMIT_DIR:-$PWD}}
RUN_DIR=$INDENT_REPO
INDENT_EXE=${INDENT_EXE:-$INDENT_REPO/build/indent}
# Relative to RUN_DIR; a scratch file system is better for the fields (223 MB at h_tip 4,
# 1.56 GB with -output_fields_every 1).
OUTPUT_DIR=${INDENT_OUTPUT_DIR:-output/berkovich_h4}
# indent writes a checkpoint every 10 accepted steps by default (-checkpoint_every N to change it).
INDENT_OPTIONS=(-options_file inputs/berkovich.opts -mesh_geo_parameters "h_tip=4,h_far=250")
LAUNCHER=(srun)
MAX_RESUBMITS=${INDENT_MAX_RESUBMITS:-10}
RESUBMIT=requeue
OVERWRITE_PARTIAL=0
JOB_SCRIPT=${INDENT_JOB_SCRIPT:-$0}
# ---- run settings (end)

set -uo pipefail
# shellcheck source=restart-lib.sh
. "$INDENT_REPO/scripts/jobs/restart-lib.sh" || exit 1
indent_job_main slurm
exit $?
