# Sourced by the run scripts: lets Open MPI run as root and oversubscribe small machines; a rank that
# exits with an error has said why in one line, so mpiexec's own banner about it is turned off.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export HWLOC_HIDE_ERRORS=2 OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 OMPI_MCA_orte_execute_quiet=1
# Open MPI binds a job of one or two ranks to cores counted from core 0, every mpiexec alike: two 1-rank runs at
# once (ctest -j, indent-fit's --jobs) shared core 0 and took twice as long. The scheduler places unbound ranks.
export OMPI_MCA_hwloc_base_binding_policy=none
# Open MPI opens its cm messaging layer at every start to probe the PSM2 and OFI fabric libraries, 0.22 of the 0.38 s
# that MPI_Init took here, though it then chooses ob1 (shared memory, TCP) on a machine without such a fabric: the
# test suite starts MPI some thousand times. A choice made already (a cluster's fabric) is kept.
export OMPI_MCA_pml=${OMPI_MCA_pml:-^cm}
