#pragma once
/* A rank outlives its job when the launcher is killed (SIGKILL to mpiexec: Open MPI's ranks are not in
   its process group) and goes on writing into the run's directory, beside the run that continues it.
   Started on each rank of a launched job, a thread ends the rank within a second of its parent's death,
   as SIGKILL would have, unless stop_requested (may be NULL) says a stop signal came: the rank then
   finishes its checkpoint and exits. Returns 0, or the error of pthread_create. */
int IndParentWatchStart(int (*stop_requested)(void));
