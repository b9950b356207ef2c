"""Shared by the test drivers that run indent: the `-- <indent options>` split and one checked run."""
import argparse
import contextlib
import os
import re
import signal
import subprocess
import sys
import time

# PETSc's -malloc_dump report of an unfreed block (the tests run with it): ctest fails on these lines.
UNFREED = re.compile(r"^\[ *\d+\] ?\d+ bytes \S+\(\) (at|line) ")


def pass_on_unfreed(text):
    """Prints the -malloc_dump lines of output a driver otherwise keeps to itself."""
    for line in text.splitlines():
        if UNFREED.match(line):
            print(line, flush=True)


def parser_and_options(script):
    """The driver's own arguments come before `--`, indent's after. Returns (ArgumentParser with
    --mpiexec, --indent, --workdir already added, driver argv, indent options)."""
    argv = sys.argv[1:]
    if "--" not in argv:
        sys.exit(f"{script}: indent options must follow --")
    split = argv.index("--")
    ap = argparse.ArgumentParser(prog=script)
    ap.add_argument("--mpiexec", required=True)
    ap.add_argument("--indent", required=True)
    ap.add_argument("--workdir", required=True)
    return ap, argv[:split], argv[split + 1:]


def run(args, nranks, options, out, label):
    """Runs indent into out; False (with a message) if it failed or left an option unused."""
    # the test's directory holds the previous ctest run's files: replacing them is intended
    cmd = [args.mpiexec, "-n", str(nranks), args.indent, *options, "-output_dir", out, "-output_overwrite", "-options_left"]
    print("+", " ".join(cmd), flush=True)
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(proc.stdout, end="")
    if proc.returncode != 0 or "WARNING! There are" in proc.stdout:
        print(f"FAIL: {label} exited with {proc.returncode}")
        return False
    return True


def run_expecting(args, nranks, options, status, label):
    """Runs indent with options as given (output directory included); False, with its output, unless it
    exits with status."""
    cmd = [args.mpiexec, "-n", str(nranks), args.indent, *options]
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    pass_on_unfreed(proc.stdout)
    if proc.returncode != status:
        print(proc.stdout)
        print(f"FAIL: {label} exited with {proc.returncode}, not {status}")
        return False
    return True


class Checks:
    """A driver's checks: prints "ok   what" or "FAIL what" for each, keeps the failures, and gives the
    exit status (0, or 1 after a line counting the failures)."""

    def __init__(self):
        self.failures = []

    def __call__(self, ok, what):
        print(("ok   " if ok else "FAIL ") + what, flush=True)
        if not ok:
            self.failures.append(what)
        return ok

    def status(self):
        if self.failures:
            print(f"{len(self.failures)} check(s) failed")
            return 1
        return 0


def run_quiet(mpiexec, nranks, indent, options):
    """Runs indent on nranks with mpiexec's own banner about a non-zero exit off (it is not indent's
    output, as in expect_error.sh); returns (exit status, non-empty lines of output)."""
    cmd = [mpiexec, "-n", str(nranks), indent, *options]
    print("+", " ".join(cmd), flush=True)
    env = dict(os.environ, OMPI_MCA_orte_execute_quiet="1")
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    pass_on_unfreed(proc.stdout)
    return proc.returncode, [line for line in proc.stdout.splitlines() if line.strip()]


def ranks_below(pid, name="indent"):
    """The processes called name among pid's descendants: the ranks an mpiexec (or a script over one) started
    on this host."""
    parent, called = {}, {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    head, tail = f.read().rsplit(")", 1)
                parent[int(entry)], called[int(entry)] = int(tail.split()[1]), head.split("(", 1)[1]
            except (OSError, ValueError, IndexError):
                pass  # ended while listed
    found, below = [], [pid]
    while below:
        p = below.pop()
        for child in (c for c, pp in parent.items() if pp == p):
            below.append(child)
            if called[child] == name:
                found.append(child)
    return sorted(found)


@contextlib.contextmanager
def held(pids):
    """The processes stopped (SIGSTOP) inside the block and continued after it, so that a run cannot end,
    however fast it is, while a test does something to it."""
    for p in pids:
        with contextlib.suppress(ProcessLookupError):  # ended just before: nothing to hold
            os.kill(p, signal.SIGSTOP)
    try:
        yield
    finally:
        for p in pids:
            with contextlib.suppress(ProcessLookupError):
                os.kill(p, signal.SIGCONT)


def pending(pid, sig):
    """Whether signal sig waits to be delivered to process pid (stopped, it cannot take it yet); a process that
    has ended counts as having it (nothing is left to wait for)."""
    try:
        with open(f"/proc/{pid}/status") as f:
            masks = [int(line.split()[1], 16) for line in f if line.startswith(("SigPnd:", "ShdPnd:"))]
    except OSError:
        return True
    return any(m >> (sig - 1) & 1 for m in masks)


def signal_mid_run(proc, sig, timeout=30):
    """Sends sig to proc (mpiexec, or a script that passes it on) with the ranks below it held until each has
    it pending, so that the run sees the signal before it can finish: a stop signal sent to a fast run lands
    mid-run on any machine. Returns the ranks' pids (empty: the run had ended)."""
    ranks = ranks_below(proc.pid)
    with held(ranks):
        proc.send_signal(sig)
        deadline = time.time() + timeout
        while time.time() < deadline and not all(pending(r, sig) for r in ranks):
            time.sleep(0.02)
    return ranks
