#!/usr/bin/env python3
"""High friction on the default iterative solver: at mu = 2 a sliding node's contact row loses its diagonal, and the
multigrid's smoothers scaled by the diagonal stalled GMRES where the indenter turns back. With rows scaled by their
largest entry (the default since) the run goes through and agrees with a direct solve:

  check_friction_high.py --mpiexec M --indent BIN --workdir D [--np N] [--rtol R] -- <indent options>

runs the case twice, with the default solver and with MUMPS (-ksp_type preonly -pc_type lu), and compares P_max, H
and E_r of their summary.json. Prints ok or FAIL per check; exit 1 on a failure.
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402

check = indentrun.Checks()
DIRECT = ["-ksp_type", "preonly", "-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps"]


def main():
    ap, mine, options = indentrun.parser_and_options("check_friction_high.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--rtol", type=float, default=1e-6)
    args = ap.parse_args(mine)
    os.makedirs(args.workdir, exist_ok=True)
    runs = {}
    for name, extra in (("iterative", []), ("direct", DIRECT)):
        out = os.path.join(args.workdir, name)
        if not check(indentrun.run(args, args.np, options + extra, out, f"the {name} run"),
                     f"the run with the {name} solver finishes"):
            return check.status()
        with open(os.path.join(out, "summary.json")) as f:
            runs[name] = json.load(f)
    for key in ("P_max_uN", "H_GPa", "E_r_GPa"):
        a, b = runs["iterative"][key], runs["direct"][key]
        check(a is not None and b is not None and abs(a - b) <= args.rtol * abs(b),
              f"{key}: {a} (iterative) against {b} (direct), within {args.rtol:g}")
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
