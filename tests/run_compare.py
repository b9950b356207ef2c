#!/usr/bin/env python3
"""Run indent on several rank counts and compare the HDF5 outputs with scripts/h5compare.py.

  run_compare.py --mpiexec M --indent BIN --workdir D --np 1,2,3 [--reference REF.h5]
                 [--reference-options "OPTS"] [--field NAME:ATOL:RTOL ...] [--curve REF.csv --curve-rtol R]
                 -- <indent options>

Without --reference the first rank count is the reference for the others (parallel consistency);
with it, every run is compared against the committed file (regression); with --reference-options, a
run on the first rank count with these options added is the reference for every run (a variant that
must not change the answer, e.g. "-mesh_reorder 0"). With --curve, every run's
load_displacement.csv is also compared with REF.csv (load at each depth, tests/compare_curves.py).
Exit 0 when all agree.
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402

H5COMPARE = os.path.join(HERE, "..", "scripts", "h5compare.py")
COMPARE_CURVES = os.path.join(HERE, "compare_curves.py")


def main():
    ap, argv, options = indentrun.parser_and_options("run_compare.py")
    ap.add_argument("--np", default="1,2,3")
    ap.add_argument("--reference")
    ap.add_argument("--reference-options", help="options added to a reference run on the first rank count")
    ap.add_argument("--field", action="append", default=[])
    ap.add_argument("--curve")
    ap.add_argument("--curve-rtol", type=float, default=1e-6)
    ap.add_argument("--curve-atol", type=float, default=1e-6)
    args = ap.parse_args(argv)

    outputs = []
    counts = [int(n) for n in args.np.split(",")]
    if args.reference_options:
        out = os.path.join(args.workdir, "reference")
        if not indentrun.run(args, counts[0], options + args.reference_options.split(), out,
                             f"indent on {counts[0]} rank(s) with {args.reference_options}"):
            return 1
        args.reference = os.path.join(out, "indent.h5")
    for np_ in counts:
        out = os.path.join(args.workdir, f"np{np_}")
        if not indentrun.run(args, np_, options, out, f"indent on {np_} ranks"):
            return 1
        outputs.append((np_, os.path.join(out, "indent.h5")))

    failed = 0
    pairs = [(o, args.reference) for o in outputs] if args.reference else [(o, outputs[0][1]) for o in outputs[1:]]
    for (np_, path), ref in pairs:
        print(f"compare {np_} ranks against {'reference' if args.reference else f'{outputs[0][0]} rank(s)'}:", flush=True)
        cmd = [sys.executable, H5COMPARE, path, ref] + [a for f in args.field for a in ("--field", f)]
        failed += subprocess.run(cmd).returncode != 0
    if args.curve:
        for np_, path in outputs:
            print(f"compare the curve of {np_} ranks against {args.curve}:", flush=True)
            csv = os.path.join(os.path.dirname(path), "load_displacement.csv")
            cmd = [sys.executable, COMPARE_CURVES, csv, args.curve, "--rtol", str(args.curve_rtol), "--atol", str(args.curve_atol)]
            failed += subprocess.run(cmd).returncode != 0
    print("all runs agree" if not failed else f"FAIL: {failed} comparison(s) differ")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
