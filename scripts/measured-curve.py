#!/usr/bin/env python3
"""A measured load-depth curve into indent's CSV (depth_nm, load_uN), and its Oliver-Pharr analysis:

  measured-curve.py FILE [--format auto|agilent|hysitron|niget|csv] [--test N] [--compliance C] [--drift R]
                    [--out CURVE.csv] [--op --indent-op BIN (--area C0,C1,... | --indenter-type T) [-- OPTIONS]]
                    [--tip-table TIP.csv --area C0,C1,...|file [--tip-height 3000]]

FILE: an Agilent/Keysight/KLA NanoSuite export (.xls, .xlsx: --test picks the test, 1 by default), a Hysitron
TriboScan .txt export, a NIGET file (.niget: '#NIGET a b c d', then depth in nm and force in mN), or a CSV whose
header names a depth and a load column with their units. Depth is converted
to nm and load to uN; the loading, hold and unloading segments are taken from the file (NanoSuite names them) or
found from the load; a frame compliance C (nm/uN) and a thermal drift rate R (nm/s) are subtracted from the depth.
With --op, indent-op analyses the written curve with the calibrated area function A(h_c) = C0 h_c^2 + C1 h_c +
C2 h_c^(1/2) + C3 h_c^(1/4) + ... (--area; an Agilent file's own coefficients with --area file) or the indenter's
ideal one; options after -- go to indent-op (e.g. -op_indenter_modulus 1141 -op_poisson 0.18). The instrument's
own E and H of the test are printed beside it when the file holds them. --tip-table writes the tip of that area
function as an indenter of revolution for the axisymmetric model (-indenter_type table -indenter_profile TIP.csv):
r = sqrt(A(h) / pi) at 600 heights up to --tip-height nm (3000), from r = h = 0.
Exit status 1 with one line 'measured-curve.py: error: ...' on a file it cannot read.
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import indentcurves  # noqa: E402


def agilent_area(path):
    """The area coefficients in a NanoSuite file's 'Results' sheet ('Area Coefficient 1', ...)."""
    import xlrd
    sh = xlrd.open_workbook(path).sheet_by_name("Results")
    head, row = sh.row_values(0), sh.row_values(2)
    coef = [row[k] for k, h in enumerate(head) if str(h).startswith("Area Coefficient")]
    if not coef:
        raise indentcurves.CurveError(f"{path}: no 'Area Coefficient' columns in the sheet 'Results'")
    return coef


def area_of(coef, h):
    """A(h) = C0 h^2 + C1 h + C2 h^(1/2) + ...: the area function of the coefficients."""
    return sum(c * h ** (2.0 / 2 ** k) for k, c in enumerate(coef))


def write_tip_table(path, coef, height, n=600):
    """The tip whose projected area at height h is A(h): rows r, h with r = sqrt(A / pi), from 0, 0."""
    import numpy as np
    h = np.geomspace(height * 1e-5, height, n)
    area = area_of(coef, h)
    start = np.nonzero(area > 0)[0]
    if not len(start) or np.any(area[start[0]:] <= 0) or np.any(np.diff(area[start[0]:]) <= 0):
        raise indentcurves.CurveError(f"the area function {','.join(f'{c:g}' for c in coef)} does not rise from 0 "
                                      f"to {height:g} nm: no tip of revolution has it")
    h, r = h[start[0]:], np.sqrt(area[start[0]:] / np.pi)
    with open(path, "w") as f:
        f.write(f"# r_nm,height_nm: the tip of the area function {','.join(f'{c:.10g}' for c in coef)}, "
                "r = sqrt(A(h)/pi)\n0,0\n")
        for a, b in zip(r, h):
            f.write(f"{a:.12g},{b:.12g}\n")
    return len(h) + 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("--format", default="auto")
    ap.add_argument("--test", type=int, default=1)
    ap.add_argument("--compliance", type=float, default=0.0, help="frame compliance, nm/uN")
    ap.add_argument("--drift", type=float, default=0.0, help="thermal drift rate, nm/s")
    ap.add_argument("--out", help="the curve as indent's CSV (default: a temporary file with --op)")
    ap.add_argument("--op", action="store_true", help="run indent-op on it")
    ap.add_argument("--indent-op", default="indent-op")
    ap.add_argument("--area", help="C0,C1,... of the calibrated area function, or 'file' (an Agilent file's)")
    ap.add_argument("--indenter-type", help="the ideal area function of this indenter instead")
    ap.add_argument("--tip-table", help="write the tip of the --area function as an indenter table (CSV)")
    ap.add_argument("--tip-height", type=float, default=3000.0, help="the table's height, nm (3000)")
    args, rest = ap.parse_known_args()
    if rest and rest[0] == "--":
        rest = rest[1:]
    try:
        c = indentcurves.correct(indentcurves.read(args.file, args.format, args.test), args.compliance, args.drift)
        depth, load = indentcurves.loading_and_unloading(c)
        print(f"{args.file}: {len(c['depth'])} points, P_max {load.max():.6g} uN at {depth[load.argmax()]:.6g} nm")
        for kind, a, b in c["segments"]:
            print(f"  {kind:9s} points {a:5d} to {b:5d}: depth {c['depth'][a]:10.4g} to {c['depth'][b]:10.4g} nm, "
                  f"load {c['load'][a]:10.4g} to {c['load'][b]:10.4g} uN")
        out, scratch = args.out, None
        if args.op and not out:  # indent-op reads a file: a temporary one, removed when it is done
            scratch = tempfile.TemporaryDirectory(prefix="measured-curve-")
            out = os.path.join(scratch.name, "curve.csv")
            indentcurves.write_csv(out, depth, load)
        elif out:
            indentcurves.write_csv(out, depth, load)
            print(f"  written {out} ({len(depth)} points from first contact)")
        if args.tip_table:
            if not args.area:
                raise indentcurves.CurveError("--tip-table needs --area (C0,C1,... or file)")
            if not args.tip_height > 0:
                raise indentcurves.CurveError(f"--tip-height must be > 0 nm, got {args.tip_height:g}")
            coef = agilent_area(args.file) if args.area == "file" else [float(x) for x in args.area.split(",")]
            rows = write_tip_table(args.tip_table, coef, args.tip_height)
            print(f"  written {args.tip_table}: the tip of the area function, {rows} rows to {args.tip_height:g} nm")
        if args.op:
            cmd = [args.indent_op, "-op_file", out]
            if args.area:
                coef = agilent_area(args.file) if args.area == "file" else [float(x) for x in args.area.split(",")]
                cmd += ["-op_area_coefficients", ",".join(f"{x:.10g}" for x in coef)]
            elif args.indenter_type:
                cmd += ["-indenter_type", args.indenter_type]
            else:
                raise indentcurves.CurveError("--op needs --area or --indenter-type for the area function")
            run = subprocess.run(cmd + rest, capture_output=True, text=True)
            if scratch:
                scratch.cleanup()
            sys.stdout.write(run.stdout)
            if run.returncode:
                sys.stderr.write(run.stderr)
                return run.returncode
        for k, v in c.get("reported", {}).items():
            if k.startswith(("E ", "H ", "Drift")):
                print(f"  the instrument's {k}: {v:.6g}")
    except indentcurves.CurveError as e:
        print(f"measured-curve.py: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
