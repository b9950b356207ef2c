#!/usr/bin/env python3
"""Near the Newton target, the linear solves stop at a fraction of it (-newton_linear_safeguard, src/solvers/forcing.c)
instead of reducing their residual by the full -ksp_rtol:

  check_forcing.py --mpiexec M --indent BIN --workdir D [--np N] --max-ratio R -- <indent options>

runs the case with the default and with -newton_linear_safeguard 0 and reads both load_displacement.csv: every step
must take as many Newton iterations, load the same to 1e-8 of the largest load, and the default run must need at
most R times the linear iterations of the other. Prints ok or FAIL per check; exit 1 on a failure.
"""
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402

check = indentrun.Checks()


def curve(path):
    with open(os.path.join(path, "load_displacement.csv")) as f:
        return list(csv.DictReader(f))


def main():
    ap, mine, options = indentrun.parser_and_options("check_forcing.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--max-ratio", type=float, required=True)
    args = ap.parse_args(mine)
    os.makedirs(args.workdir, exist_ok=True)
    runs = {}
    for name, extra in (("safeguarded", []), ("full", ["-newton_linear_safeguard", "0"])):
        out = os.path.join(args.workdir, name)
        if not indentrun.run(args, args.np, options + extra, out, f"the {name} run"):
            return 1
        runs[name] = curve(out)
    a, b = runs["safeguarded"], runs["full"]
    if not check(len(a) == len(b) and len(a) > 0, f"both runs took the same steps ({len(a)} and {len(b)})"):
        return check.status()
    pmax = max(abs(float(r["load_uN"])) for r in b)
    dp = max(abs(float(x["load_uN"]) - float(y["load_uN"])) for x, y in zip(a, b))
    newton = [(int(x["newton"]), int(y["newton"])) for x, y in zip(a, b)]
    lin = sum(int(r["linear"]) for r in a), sum(int(r["linear"]) for r in b)
    print(f"Newton iterations per step {[n for n, _ in newton]} and {[n for _, n in newton]}; linear iterations "
          f"{lin[0]} and {lin[1]} (ratio {lin[0] / lin[1]:.3f}); largest load difference {dp:.3g} uN of {pmax:.6g}")
    check(all(x == y for x, y in newton), "every step took as many Newton iterations")
    check(dp <= 1e-8 * pmax, f"the loads agree to 1e-8 of P_max ({dp / pmax:.2g})")
    check(lin[0] <= args.max_ratio * lin[1], f"the safeguarded run took at most {args.max_ratio} times the linear "
          f"iterations ({lin[0] / lin[1]:.3f})")
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
