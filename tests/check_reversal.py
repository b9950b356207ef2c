#!/usr/bin/env python3
"""The first step after the indenter turns back starts from the elastic unloading with every node in contact
rising with it (IndSolverPredictUnloading), so Newton does not spend its iterations finding which nodes stick:

  check_reversal.py --mpiexec M --indent BIN --workdir D [--np N] --max-newton K -- <indent options>

runs the case and reads load_displacement.csv: the first step whose depth is below the last one's must have
converged in at most K Newton iterations, with no cut-back. Prints ok or FAIL per check; exit 1 on a failure.
"""
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402

check = indentrun.Checks()


def main():
    ap, mine, options = indentrun.parser_and_options("check_reversal.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--max-newton", type=int, required=True)
    args = ap.parse_args(mine)
    out = os.path.join(args.workdir, f"np{args.np}")
    os.makedirs(args.workdir, exist_ok=True)
    if not indentrun.run(args, args.np, options, out, "the run"):
        return 1
    with open(os.path.join(out, "load_displacement.csv")) as f:
        rows = list(csv.DictReader(f))
    turn = next((k for k in range(1, len(rows)) if float(rows[k]["depth_nm"]) < float(rows[k - 1]["depth_nm"])), None)
    if not check(turn is not None, "the indenter turns back"):
        return check.status()
    r = rows[turn]
    print(f"step {r['step']}: {rows[turn - 1]['depth_nm']} -> {r['depth_nm']} nm, {r['newton']} Newton iterations, "
          f"{r['cutbacks']} cut-backs")
    check(int(r["newton"]) <= args.max_newton, f"the first unloading step took {r['newton']} Newton iterations "
          f"(at most {args.max_newton})")
    check(int(r["cutbacks"]) == 0, "and was not cut back")
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
