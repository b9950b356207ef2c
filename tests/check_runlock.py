#!/usr/bin/env python3
"""A run directory has one owner (src/io/runlock.c):

  check_runlock.py --mpiexec M --indent BIN --workdir D [--np N] [--live-steps S] -- <indent options>

 1. while a run writes into a directory (its ranks held by SIGSTOP, so that it outlives what follows), a
    second fresh run, an -output_overwrite run and a -restart run
    into it are each refused with one line 'indent: error: ... is in use by a run started ... (pid P)'
    naming the owner's pid, and the first run's files stay; the first run then finishes (exit 0) and its
    lock is gone;
 2. a lock left by a process that no longer runs (same host) is taken over with one warning, and the
    run finishes; a lock of another host and a lock naming no run are refused, naming the lock file;
 3. mpiexec killed by SIGKILL: its ranks (in process groups of their own) end within 3 s, and the
    next run takes over their lock;
 4. two -restart runs of one checkpoint started together: one continues and finishes, the other is
    refused.
Prints ok or FAIL per check; exit 1 on a failed check.
"""
import os
import shutil
import socket
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402

LOCK = "indent.lock"
check = indentrun.Checks()


def command(args, options):
    return [args.mpiexec, "-n", str(args.np), args.indent, *options]


def run(args, options):
    return indentrun.run_quiet(args.mpiexec, args.np, args.indent, options)


def refused(status, lines, label, *words):
    check(status != 0, f"{label}: refused (exit {status})")
    check(len(lines) == 1 and lines[0].startswith("indent: error: "), f"{label}: one error line, got {lines[:3]}")
    for w in words:
        check(bool(lines) and w in lines[0], f"{label}: the line names '{w}'")


def main():
    ap, mine, options = indentrun.parser_and_options("check_runlock.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--live-steps", default="250", help="-load_steps of the runs that must outlive another")
    args = ap.parse_args(mine)
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)

    # 1. a live run's directory
    live = os.path.join(args.workdir, "live")
    cmd = command(args, [*options, "-load_steps", args.live_steps, "-checkpoint_every", "1", "-output_dir", live])
    print("+", " ".join(cmd), flush=True)
    first = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    lock = os.path.join(live, LOCK)
    deadline = time.time() + 60
    while not os.path.exists(os.path.join(live, "checkpoint.h5")) and time.time() < deadline \
            and first.poll() is None:
        time.sleep(0.05)
    if check(first.poll() is None and os.path.exists(lock), "the first run holds the lock while it runs"):
        with open(lock) as f:
            owner = f.read().split()
        pid = owner[1] if len(owner) > 1 else "?"
        kept = ("load_displacement.csv", "mesh.msh")
        sizes = {n: os.path.getsize(os.path.join(live, n)) for n in kept}
        # The ranks are held (SIGSTOP) while the three try, so that the run outlives them however fast it is.
        ranks = indentrun.ranks_below(first.pid)
        check(len(ranks) == args.np, f"the first run's {args.np} ranks found ({ranks})")
        with indentrun.held(ranks):
            status, lines = run(args, [*options, "-output_dir", live])
            refused(status, lines, "a fresh run into it", "-output_dir", "is in use by a run started", f"pid {pid}")
            status, lines = run(args, [*options, "-output_dir", live, "-output_overwrite"])
            refused(status, lines, "-output_overwrite on it", "-output_overwrite", f"pid {pid}")
            status, lines = run(args, [*options, "-output_dir", live, "-restart", live])
            refused(status, lines, "-restart on it", "-restart", "is in use by a run started", f"pid {pid}")
            check(all(os.path.exists(os.path.join(live, n)) and os.path.getsize(os.path.join(live, n)) >= sizes[n]
                      for n in kept), "the first run's curve and mesh are there, whole")
            check(first.poll() is None and all(os.path.exists(f"/proc/{r}") for r in ranks),
                  "the first run was still running through all three (else the test proves nothing)")
    out, _ = first.communicate()
    check(first.returncode == 0, f"the first run finished (exit {first.returncode})")
    if first.returncode:
        print(out)
    check(not os.path.exists(lock), "its lock is gone")

    # 2. stale, foreign and unreadable locks
    stale = os.path.join(args.workdir, "stale")
    os.makedirs(stale)
    dead = subprocess.Popen(["true"])
    dead.wait()
    with open(os.path.join(stale, LOCK), "w") as f:
        f.write(f"pid {dead.pid} host {socket.gethostname()} job - started 2026-01-01T00:00:00Z\n")
    status, lines = run(args, [*options, "-output_dir", stale])
    warn = [l for l in lines if l.startswith("indent: warning: took over the lock")]
    check(status == 0 and len(warn) == 1 and f"pid {dead.pid}" in warn[0],
          f"a dead process's lock taken over with one warning, and the run finished (exit {status}, {warn})")
    for label, text, word in (("another host's lock", "pid 1 host no-such-host.example job - started x\n",
                               "no-such-host.example"),
                              ("a lock naming no run", "garbage\n", "names no run")):
        d = os.path.join(args.workdir, label.replace(" ", "_").replace("'", ""))
        os.makedirs(d)
        with open(os.path.join(d, LOCK), "w") as f:
            f.write(text)
        status, lines = run(args, [*options, "-output_dir", d])
        refused(status, lines, label, word, LOCK)
        check(os.path.exists(os.path.join(d, LOCK)), f"{label}: left in place")

    # 2b. the launcher killed: its ranks end within seconds (a parent watch), leaving a stale lock
    orphan = os.path.join(args.workdir, "orphan")
    launcher = subprocess.Popen(command(args, [*options, "-load_steps", args.live_steps, "-output_dir", orphan]),
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    lock = os.path.join(orphan, LOCK)
    deadline = time.time() + 60
    while not os.path.exists(os.path.join(orphan, "load_displacement.csv")) and time.time() < deadline:
        time.sleep(0.05)
    if check(os.path.exists(lock), "a second long run holds its lock"):
        with open(lock) as f:
            rank0 = int(f.read().split()[1])
        launcher.kill()  # SIGKILL to mpiexec alone: Open MPI's ranks are in process groups of their own
        launcher.wait()
        t0 = time.time()
        while time.time() - t0 < 10 and os.path.exists(f"/proc/{rank0}") and \
                not open(f"/proc/{rank0}/stat").read().split(")")[-1].split()[0] == "Z":
            time.sleep(0.1)
        gone = time.time() - t0
        check(gone < 3, f"mpiexec SIGKILLed: its rank 0 (pid {rank0}) ended {gone:.1f} s later (at most 3 s)")
        status, lines = run(args, [*options, "-output_dir", orphan, "-output_overwrite"])
        check(status == 0 and any("took over the lock" in l for l in lines),
              f"the next run into its directory takes the lock over (exit {status})")

    # 3. two restarts of one checkpoint at once
    ck = os.path.join(args.workdir, "restarts")
    # Of S steps, so that the restart that wins is still running when the other one looks at the lock.
    long_run = [*options, "-load_steps", args.live_steps, "-output_dir", ck]
    status, _ = run(args, [*long_run, "-checkpoint_stop_after_step", "2"])
    if check(status == 75, f"a run stopped after step 2 with a checkpoint (exit {status})"):
        env = dict(os.environ, OMPI_MCA_orte_execute_quiet="1")
        procs = [subprocess.Popen(command(args, [*long_run, "-restart", ck]), stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, text=True, env=env) for _ in range(2)]
        results = [(p.wait(), p.communicate()[0]) for p in procs]
        codes = sorted(r[0] for r in results)
        check(codes[0] == 0 and codes[1] != 0, f"one restart finished and one was refused (exits {codes})")
        loser = [r[1] for r in results if r[0] != 0]
        check(bool(loser) and "is in use by a run started" in loser[0],
              "the refused one says the directory is in use" + ("" if not loser or "is in use by a run started" in
                                                                 loser[0] else f" (it said: {loser[0].strip()!r})"))
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
