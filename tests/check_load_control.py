#!/usr/bin/env python3
"""Load control (-load_force): each loading step's load equals its share of the largest load, the largest
load is reached, and the curve is the depth-controlled one: with --depth-reference D, a depth-controlled
run to D sets the largest load and the load-controlled run must reach it at depth D; with --hertz E*,R
every point lies on Hertz's curve; with --restart-after K, a run stopped after step K and continued
with -restart gives the same curve; with --unload-to-zero, the unloading ends at zero force; with
--newton-ratio R, a depth-controlled run to the depth where the load-controlled one reached F takes at
least 1/R of its Newton iterations per step.

  check_load_control.py --mpiexec M --indent BIN --workdir D [--np 2] (--depth-reference D | --force F --limit L)
                        [--rtol 1e-6] [--hertz ESTAR,R,TOL] [--restart-after K] -- <indent options>
"""
import os
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402


def curve(d):
    return np.genfromtxt(os.path.join(d, "load_displacement.csv"), delimiter=",", names=True)


def main():
    ap, argv, options = indentrun.parser_and_options("check_load_control.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--depth-reference", type=float)
    ap.add_argument("--force", type=float)
    ap.add_argument("--limit", type=float)
    ap.add_argument("--rtol", type=float, default=1e-6)
    ap.add_argument("--hertz")
    ap.add_argument("--restart-after", type=int)
    ap.add_argument("--unload-to-zero", action="store_true")
    ap.add_argument("--newton-ratio", type=float)
    args = ap.parse_args(argv)
    shutil.rmtree(args.workdir, ignore_errors=True)
    failed = 0
    if args.depth_reference:
        ref = os.path.join(args.workdir, "depth")
        if not indentrun.run(args, args.np, options + ["-load_depth", repr(args.depth_reference)], ref, "depth control"):
            return 1
        c = curve(ref)
        force, limit = float(np.max(c["load_uN"])), 1.5 * args.depth_reference
        print(f"depth control to {args.depth_reference:g} nm: P_max = {force:.12g} uN")
    else:
        force, limit = args.force, args.limit
    lc = os.path.join(args.workdir, "force")
    lc_opts = options + ["-load_force", repr(force), "-load_depth", repr(limit)]
    if not indentrun.run(args, args.np, lc_opts, lc, "load control"):
        return 1
    c = curve(lc)
    loading = c["t"] <= 1 + 1e-12
    err = np.max(np.abs(c["load_uN"][loading] - c["t"][loading] * force)) / force
    top = np.argmax(c["load_uN"])
    print(f"load control: {len(c)} steps; loading loads vs t * F: max error / F = {err:.3e}; "
          f"P_max = {c['load_uN'][top]:.12g} uN at {c['depth_nm'][top]:.10g} nm")
    failed += err > args.rtol
    failed += abs(c["load_uN"][top] - force) > args.rtol * force
    if args.depth_reference:
        dd = abs(c["depth_nm"][top] - args.depth_reference) / args.depth_reference
        print(f"  depth at P_max vs the depth-controlled run's {args.depth_reference:g} nm: relative {dd:.3e}")
        failed += dd > args.rtol
    if args.hertz:
        estar, radius, tol = (float(x) for x in args.hertz.split(","))
        h, p = c["depth_nm"][loading], c["load_uN"][loading]
        hertz = 4.0 / 3.0 * estar * np.sqrt(radius) * h ** 1.5 * 1e-3
        rel = np.max(np.abs(p / hertz - 1))
        print(f"  loading points vs Hertz: max relative difference {rel:.3e} (tolerance {tol:g})")
        failed += rel > tol
    if args.unload_to_zero:
        end = c["load_uN"][-1]
        print(f"  unloading ends at {end:.3e} uN at depth {c['depth_nm'][-1]:.6g} nm, t = {c['t'][-1]:.6g}")
        failed += abs(end) > args.rtol * force or c["t"][-1] < 2 - 1e-9
    if args.newton_ratio:
        ref = os.path.join(args.workdir, "depth_same")
        dc_opts = options + ["-load_depth", repr(float(c["depth_nm"][top]))]
        if not indentrun.run(args, args.np, dc_opts, ref, "depth control to the same depth"):
            return 1
        d = curve(ref)
        per_load, per_depth = np.mean(c["newton"]), np.mean(d["newton"])
        print(f"  Newton iterations per step: load control {per_load:.2f} ({len(c)} steps), depth control "
              f"{per_depth:.2f} ({len(d)} steps); ratio {per_load / per_depth:.2f} (at most {args.newton_ratio:g})")
        failed += per_load > args.newton_ratio * per_depth
    if args.restart_after:
        part = os.path.join(args.workdir, "restarted")
        stop = ["-checkpoint_stop_after_step", str(args.restart_after), "-output_dir", part, "-output_overwrite"]
        if not indentrun.run_expecting(args, args.np, lc_opts + stop, 75, "the stopped run"):
            return 1
        again = ["-output_dir", part, "-restart", part]
        if not indentrun.run_expecting(args, args.np, lc_opts + again, 0, "the restarted run"):
            return 1
        r = curve(part)
        same = len(r) == len(c)
        dp = np.max(np.abs(r["load_uN"] - c["load_uN"])) / force if same else np.inf
        dh = np.max(np.abs(r["depth_nm"] - c["depth_nm"])) / limit if same else np.inf
        print(f"  stopped after step {args.restart_after} and restarted: max |dP| / F = {dp:.3e}, max |dh| / limit = {dh:.3e}")
        failed += not same or dp > 1e-8 or dh > 1e-8
    print("load control reproduces the prescribed loads" if not failed else f"FAIL: {failed} check(s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
