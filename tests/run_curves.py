#!/usr/bin/env python3
"""Runs an indentation several ways and compares the load-displacement curves (load at each depth).

  run_curves.py --mpiexec M --indent BIN --workdir D --rtol R [--atol A] [--np 1,2]
                [--variant "NAME:OPTIONS" ...] -- <common options>

With several --np values the same run is repeated on each rank count and compared with the first.
With --variant, each variant's options are added to the common ones (run on the first rank count)
and every variant is compared with the first. Exit 0 when all curves agree.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import compare_curves  # noqa: E402
import indentrun  # noqa: E402


def main():
    ap, argv, common = indentrun.parser_and_options("run_curves.py")
    ap.add_argument("--np", default="1")
    ap.add_argument("--rtol", type=float, required=True)
    ap.add_argument("--atol", type=float, default=0.0)
    ap.add_argument("--variant", action="append", default=[])
    args = ap.parse_args(argv)
    nps = [int(n) for n in args.np.split(",")]
    if args.variant:
        runs = [(v.split(":", 1)[0], nps[0], v.split(":", 1)[1].split()) for v in args.variant]
    else:
        runs = [(f"np{n}", n, []) for n in nps]
    csvs = []
    for name, n, opts in runs:
        out = os.path.join(args.workdir, name)
        if not indentrun.run(args, n, [*common, *opts], out, f"run {name}"):
            return 1
        csvs.append((name, os.path.join(out, "load_displacement.csv")))
    failed = 0
    for name, path in csvs[1:]:
        print(f"compare {name} against {csvs[0][0]}:", flush=True)
        sys.argv = ["compare_curves.py", path, csvs[0][1], "--rtol", str(args.rtol), "--atol", str(args.atol)]
        failed += compare_curves.main() != 0
    print("all curves agree" if not failed else f"FAIL: {failed} curve(s) differ")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
