#!/usr/bin/env python3
"""A failed write ends the run with status 74, one line, and a checkpoint when there is room for it.

With a file-size limit (ulimit -f, set for the ranks only: Open MPI's launcher and shared memory need files
of their own, so the ranks talk over TCP), the
field file, the curve, the checkpoint and gmsh's mesh each fail; every such run ends with exit status 74
and one line naming the file, the step and the cause, a checkpoint of the last accepted step when there is
room for it, no temporary checkpoint and no lock left behind; a run that failed writing its fields,
continued with -restart once the limit is gone, ends on the uninterrupted run's curve.

  check_write_faults.py --mpiexec M --indent BIN --workdir D --geo "<options of a .geo case>"
                        -- <indent options of a small indentation on a box mesh, about 12 steps>

The limits are in sh's units of 512 bytes.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402

IO_STATUS = 74


def limited(args, nranks, kib, options):
    """indent on nranks with the file-size limit kib KiB for the ranks; (status, non-empty output lines)."""
    cmd = [args.mpiexec, "-n", str(nranks), "sh", "-c", f'ulimit -f {kib} && exec "$0" "$@"', args.indent, *options]
    print("+ (ulimit -f %d for the ranks)" % kib, " ".join(cmd[4:]), flush=True)
    # one host: over the loopback, which Open MPI leaves out by default (a machine may have no other)
    env = dict(os.environ, OMPI_MCA_orte_execute_quiet="1", OMPI_MCA_btl="self,tcp",
               OMPI_MCA_btl_tcp_if_include="lo")
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    indentrun.pass_on_unfreed(proc.stdout)
    return proc.returncode, [line for line in proc.stdout.splitlines() if line.strip()]


def curve(d):
    return np.genfromtxt(os.path.join(d, "load_displacement.csv"), delimiter=",", names=True)


def main():
    ap, argv, options = indentrun.parser_and_options("check_write_faults.py")
    ap.add_argument("--geo", required=True)
    args = ap.parse_args(argv)
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    check = indentrun.Checks()

    def fault(label, nranks, kib, opts, out, file, step_pattern, continued):
        status, lines = limited(args, nranks, kib, opts + ["-output_dir", out])
        errors = [line for line in lines if line.startswith("indent: error:")]
        print("\n".join(lines[-3:]))
        check(status == IO_STATUS, f"{label}: exit status {status} (want {IO_STATUS})")
        check(len(errors) == 1 and len(lines) == len([x for x in lines if x.startswith("indent: ")]),
              f"{label}: one error line and nothing else but indent's lines")
        where = re.escape(os.path.join(out, file))
        pattern = rf"writing '{where}' after step {step_pattern} failed: File too large; " + continued
        check(bool(errors) and re.search(pattern, errors[0]) is not None, f"{label}: the line matches '{pattern}'")
        left = [f for f in ("indent.lock", "checkpoint.h5.tmp") if os.path.exists(os.path.join(out, f))]
        check(not left, f"{label}: nothing left behind ({left})")
        return errors[0] if errors else ""

    ref = os.path.join(args.workdir, "uninterrupted")
    if not indentrun.run(args, 2, options + ["-checkpoint_every", "2"], ref, "the uninterrupted run"):
        return 1

    # fields (of every step): the limit stops indent.h5 after a few steps; the checkpoint of that step is written
    every = ["-output_fields_every", "1"]
    for nranks in (1, 2):
        out = os.path.join(args.workdir, f"fields_np{nranks}")
        fault(f"fields, {nranks} rank(s)", nranks, 1000, options + every + ["-checkpoint_every", "2"], out, "indent.h5",
              r"\d+", r"the checkpoint of step \d+ is written: make room and continue with the same options and "
              + re.escape(f"-restart {out}"))
    out = os.path.join(args.workdir, "fields_np2")
    status, lines = indentrun.run_quiet(args.mpiexec, 2, args.indent, options + every +
                                        ["-checkpoint_every", "2", "-output_dir", out, "-restart", out])
    check(status == 0, f"restart without the limit: exit status {status}")
    if status == 0:
        a, b = curve(out), curve(ref)
        same = len(a) == len(b)
        dp = float(np.max(np.abs(a["load_uN"] - b["load_uN"])) / np.max(b["load_uN"])) if same else np.inf
        check(same and dp < 1e-8, f"restarted curve = uninterrupted curve ({len(a)} and {len(b)} steps, "
              f"max |dP| / P_max = {dp:.2e})")

    # the curve: no fields, 1 KiB for the CSV; the checkpoint cannot be written either
    fault("curve", 2, 2, options + ["-output_fields", "0"], os.path.join(args.workdir, "curve"),
          "load_displacement.csv", r"\d+", "no checkpoint to continue from: make room and run again")
    # the checkpoint: no fields, a limit below the checkpoint's size; the earlier one is named
    fault("checkpoint", 2, 400, options + ["-output_fields", "0", "-checkpoint_every", "2"],
          os.path.join(args.workdir, "checkpoint"), "checkpoint.h5", "2",
          "no checkpoint to continue from: make room and run again")

    # gmsh's mesh: larger than the limit
    out = os.path.join(args.workdir, "mesh")
    status, lines = limited(args, 2, 128, shlex.split(args.geo) + ["-output_dir", out])
    print("\n".join(lines[-2:]))
    check(status == IO_STATUS, f"gmsh's mesh: exit status {status} (want {IO_STATUS})")
    check(len(lines) == 1 and re.search(r"gmsh could not write the mesh of .* to '.*mesh\.msh': File too large",
                                        lines[0]) is not None, "gmsh's mesh: one line naming the mesh and the cause")
    check(not os.path.exists(os.path.join(out, "indent.lock")), "gmsh's mesh: no lock left")
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
