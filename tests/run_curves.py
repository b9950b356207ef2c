#!/usr/bin/env python3
"""Runs an indentation several ways and compares the load-displacement curves (load at each depth).

  run_curves.py --mpiexec M --indent BIN --workdir D --rtol R [--atol A] [--np 1,2]
                [--variant "NAME:OPTIONS" ...] -- <common options>

With several --np values the same run is repeated on each rank count and compared with the first.
With --variant, each variant's options are added to the common ones (run on the first rank count)
and every variant is compared with the first. Exit 0 when all curves agree.
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import compare_curves  # noqa: E402


def main():
    argv = sys.argv[1:]
    if "--" not in argv:
        sys.exit("run_curves.py: indent options must follow --")
    split = argv.index("--")
    ap = argparse.ArgumentParser()
    ap.add_argument("--mpiexec", required=True)
    ap.add_argument("--indent", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--np", default="1")
    ap.add_argument("--rtol", type=float, required=True)
    ap.add_argument("--atol", type=float, default=0.0)
    ap.add_argument("--variant", action="append", default=[])
    args = ap.parse_args(argv[:split])
    common = argv[split + 1:]
    nps = [int(n) for n in args.np.split(",")]
    runs = []
    if args.variant:
        for v in args.variant:
            name, opts = v.split(":", 1)
            runs.append((name, nps[0], opts.split()))
    else:
        runs = [(f"np{n}", n, []) for n in nps]
    csvs = []
    for name, n, opts in runs:
        out = os.path.join(args.workdir, name)
        cmd = [args.mpiexec, "-n", str(n), args.indent, *common, *opts, "-output_dir", out, "-options_left"]
        print("+", " ".join(cmd), flush=True)
        run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        print(run.stdout, end="")
        if run.returncode != 0 or "WARNING! There are" in run.stdout:
            print(f"FAIL: run {name} exited with {run.returncode}")
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
