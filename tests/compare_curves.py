#!/usr/bin/env python3
"""Compares the load columns of two load_displacement.csv files step by step (same depths).

  compare_curves.py RUN.csv REF.csv --rtol T [--atol A]

Passes when |P_run - P_ref| <= atol + rtol |P_ref| at every common depth. Prints each step's
relative difference. Exit 0 on pass, 1 on a difference, 2 on bad input.
"""
import argparse
import csv
import sys


def read(path):
    try:
        with open(path) as f:
            return [(float(r["depth_nm"]), float(r["load_uN"])) for r in csv.DictReader(f)]
    except (OSError, KeyError, ValueError) as e:
        print(f"compare_curves.py: cannot read {path}: {e}")
        sys.exit(2)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("ref")
    ap.add_argument("--rtol", type=float, required=True)
    ap.add_argument("--atol", type=float, default=0.0)
    a = ap.parse_args()
    run, ref = read(a.run), read(a.ref)
    if len(run) != len(ref) or not run:
        print(f"FAIL: {len(run)} steps in {a.run}, {len(ref)} in {a.ref}")
        return 1
    worst = 0.0
    bad = 0
    for (h1, p1), (h2, p2) in zip(run, ref):
        if abs(h1 - h2) > 1e-9 * max(1.0, abs(h2)):
            print(f"FAIL: depths differ, {h1} vs {h2}")
            return 1
        rel = abs(p1 - p2) / abs(p2) if p2 else abs(p1 - p2)
        worst = max(worst, rel)
        ok = abs(p1 - p2) <= a.atol + a.rtol * abs(p2)
        bad += not ok
        print(f"{'ok  ' if ok else 'FAIL'} depth {h1:10.4f} nm: P {p1:.10e} vs {p2:.10e} uN, relative {rel:.3e}")
    print(f"largest relative difference {worst:.3e} (rtol {a.rtol:g}, atol {a.atol:g}): {'FAIL' if bad else 'ok'}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
