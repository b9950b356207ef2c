#!/bin/bash
# The paper's case (inputs/berkovich.opts on the README's h_tip 4 mesh, 160k dofs) as a PBS job
# that checkpoints before its wall-time limit and submits itself again until the run is finished.
# Submit it from the top of the indent checkout (edit the #PBS lines and the settings first):
#   qsub scripts/jobs/pbs-paper-case.sh
# PBS gives no warning before the limit, so the launcher runs under `timeout`, which sends it
# SIGUSR1 SIGNAL_MARGIN seconds before the wall time (read from qstat, or this script's
# walltime line); indent finishes or abandons its step, writes OUTPUT_DIR/checkpoint.h5 and exits
# with 75, and the job submits this script again (qsub), whose run adds -restart OUTPUT_DIR. A
# finished run (summary.json) makes the job do nothing. By hand: `qsig -s USR1 <job>` checkpoints
# and resubmits now, `qsig -s TERM <job>` checkpoints and ends the job (qdel signals every process:
# do not count on its checkpoint). doc/cluster.md explains it all; scripts/sweep.py --pbs writes one
# such script per run of a sweep.
#PBS -N indent-paper
# PBS Pro syntax; Torque: #PBS -l nodes=1:ppn=8
#PBS -l select=1:ncpus=8:mpiprocs=8
#PBS -l walltime=01:00:00
#PBS -j oe

# ---- run settings (begin)
# The checkout holding build/indent and scripts/jobs: by default the directory qsub was run in.
INDENT_REPO=${INDENT_REPO:-${PBS_O_WORKDIR:-$PWD}}
RUN_DIR=$INDENT_REPO
INDENT_EXE=${INDENT_EXE:-$INDENT_REPO/build/indent}
# Relative to RUN_DIR; a scratch file system is better for the fields (223 MB at h_tip 4,
# 1.56 GB with -output_fields_every 1).
OUTPUT_DIR=${INDENT_OUTPUT_DIR:-output/berkovich_h4}
# indent writes a checkpoint every 10 accepted steps by default (-checkpoint_every N to change it).
INDENT_OPTIONS=(-options_file inputs/berkovich.opts -mesh_geo_parameters "h_tip=4,h_far=250")
# Ranks: one per line of the node file (the mpiprocs above).
NP=${INDENT_NP:-$(wc -l < "${PBS_NODEFILE:?not in a PBS job: set INDENT_NP}")}
LAUNCHER=(mpiexec -n "$NP")
MAX_RESUBMITS=${INDENT_MAX_RESUBMITS:-10}
SIGNAL_MARGIN=${INDENT_SIGNAL_MARGIN:-300}
OVERWRITE_PARTIAL=0
# PBS Pro runs a copy of the submitted script as $0; Torque may feed it on stdin instead.
JOB_SCRIPT=${INDENT_JOB_SCRIPT:-$0}
[[ -f $JOB_SCRIPT ]] || JOB_SCRIPT=$INDENT_REPO/scripts/jobs/pbs-paper-case.sh
# ---- run settings (end)

set -uo pipefail
# shellcheck source=restart-lib.sh
. "$INDENT_REPO/scripts/jobs/restart-lib.sh" || exit 1
indent_job_main pbs
exit $?
