#!/usr/bin/env python3
"""A run killed with SIGKILL at any moment leaves every completed step readable: the curve's lines
parse, the XDMF index parses and every step it lists is readable in indent.h5, and the checkpoint, if
one was written, opens and names its format. Kills the whole process group (mpiexec and its ranks)
after a different delay in each trial, some in the middle of a step's output.

  check_sigkill.py --mpiexec M --indent BIN --workdir D [--np 2] [--trials 6] [--seed 1] -- <indent options>
"""
import os
import random
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402


def readable(d):
    """Problems found in the run directory d (empty: every completed step is readable)."""
    problems, steps = [], 0
    csv = os.path.join(d, "load_displacement.csv")
    if os.path.exists(csv):
        lines = open(csv).read().splitlines()
        for l in lines[1:]:
            fields = l.split(",")
            try:
                [float(x) for x in fields]
            except ValueError:
                problems.append(f"curve line does not parse: {l!r}")
            if len(fields) != len(lines[0].split(",")):
                problems.append(f"curve line has {len(fields)} fields: {l!r}")
    xdmf = os.path.join(d, "indent.xdmf")
    if os.path.exists(xdmf):
        try:
            root = ET.parse(xdmf).getroot()
            steps = len([g for g in root.iter("Grid") if g.get("GridType") == "Uniform"])
        except ET.ParseError as e:
            problems.append(f"indent.xdmf does not parse: {e}")
    h5 = os.path.join(d, "indent.h5")
    if steps:
        try:
            with h5py.File(h5, "r") as f:
                for name, ds in f["fields"].items():
                    if ds.shape[0] < steps:
                        problems.append(f"indent.h5 /fields/{name} holds {ds.shape[0]} steps, the index lists {steps}")
                    else:
                        ds[steps - 1]
        except (OSError, KeyError) as e:
            problems.append(f"indent.h5 unreadable: {e}")
    ck = os.path.join(d, "checkpoint.h5")
    if os.path.exists(ck):
        try:
            with h5py.File(ck, "r") as f:
                fmt = f.attrs["format"]
                if not (fmt.decode() if isinstance(fmt, bytes) else str(fmt)).startswith("indent checkpoint"):
                    problems.append("checkpoint.h5 has no format")
        except (OSError, KeyError) as e:
            problems.append(f"checkpoint.h5 unreadable: {e}")
    return problems, steps


def ranks_end(d, limit=5.0):
    """Waits for the killed run's ranks: Open MPI puts them in process groups of their own, and they end
    within a second of mpiexec (their parent watch); rank 0's pid is in the run's lock."""
    try:
        with open(os.path.join(d, "indent.lock")) as f:
            pid = int(f.read().split()[1])
    except (OSError, IndexError, ValueError):
        return
    t0 = time.time()
    while time.time() - t0 < limit:
        try:
            with open(f"/proc/{pid}/stat") as f:
                if f.read().rsplit(")", 1)[-1].split()[0] == "Z":
                    return
        except OSError:
            return
        time.sleep(0.05)


def main():
    ap, argv, options = indentrun.parser_and_options("check_sigkill.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--trials", type=int, default=6)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args(argv)
    rng = random.Random(args.seed)
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    # How long a whole run takes, to spread the kills over it.
    d = os.path.join(args.workdir, "whole")
    t0 = time.time()
    if not indentrun.run(args, args.np, options + ["-checkpoint_every", "1"], d, "the whole run"):
        return 1
    whole = time.time() - t0
    failed = 0
    for k in range(args.trials):
        d = os.path.join(args.workdir, f"kill{k}")
        delay = rng.uniform(0.3, 0.95) * whole
        cmd = [args.mpiexec, "-n", str(args.np), args.indent, *options, "-checkpoint_every", "1", "-output_dir", d]
        proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        time.sleep(delay)
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
        ranks_end(d)
        problems, steps = readable(d)
        print(f"kill {k} after {delay:6.2f} s: {steps} steps in the index, "
              f"{'checkpoint present' if os.path.exists(os.path.join(d, 'checkpoint.h5')) else 'no checkpoint'}"
              f"{': ' + '; '.join(problems) if problems else ', all readable'}")
        failed += bool(problems)
    # The last trial that left a checkpoint is continued: the curve then equals the whole run's.
    resumable = [k for k in range(args.trials) if os.path.exists(os.path.join(args.workdir, f"kill{k}", "checkpoint.h5"))]
    if resumable:
        d = os.path.join(args.workdir, f"kill{resumable[-1]}")
        cmd = [args.mpiexec, "-n", str(args.np), args.indent, *options, "-output_dir", d, "-restart", d]
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        indentrun.pass_on_unfreed(proc.stdout)
        a = np.genfromtxt(os.path.join(args.workdir, "whole", "load_displacement.csv"), delimiter=",", names=True)
        b = np.genfromtxt(os.path.join(d, "load_displacement.csv"), delimiter=",", names=True)
        same = proc.returncode == 0 and len(a) == len(b)
        dp = np.max(np.abs(a["load_uN"] - b["load_uN"])) / np.max(np.abs(a["load_uN"])) if same else float("inf")
        print(f"kill {resumable[-1]} continued with -restart: exit {proc.returncode}, {len(b)} curve points "
              f"({len(a)} whole), max |dP| / P_max = {dp:.3e}")
        if not same or dp > 1e-8:
            print(proc.stdout)
            failed += 1
    print("every killed run left its completed steps readable" if not failed else f"FAIL: {failed} trial(s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
