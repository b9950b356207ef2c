#!/usr/bin/env python3
"""Plots Kick's constant C = P / h^2 (GPa) against the depth for one or more load-displacement curves.

  scripts/plot-kick-constant.py --out C.png [--reference 25.8 --reference-label "Dao et al."] \
      [--min-depth 4] run1/load_displacement.csv:"finite strain" run2/load_displacement.csv:"small strain"

Only the loading branch (up to the largest depth) is drawn. The figure shows how a sharp indenter's
constant (which has no length scale) settles once the contact spans a few elements, and how two
formulations or meshes compare on the same case (doc/finite-strain.md).
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def loading(path):
    try:
        with open(path) as f:
            rows = [(float(r["depth_nm"]), float(r["load_uN"])) for r in csv.DictReader(f)]
    except (OSError, KeyError, ValueError) as e:
        sys.exit(f"plot-kick-constant.py: cannot read '{path}' as indent's load_displacement.csv: {e}")
    top = max(range(len(rows)), key=lambda i: rows[i][0]) if rows else -1
    return [(h, 1e3 * P / h**2) for h, P in rows[:top + 1] if h > 0]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("curves", nargs="+", help="CSV[:label]")
    ap.add_argument("--out", required=True, help="PNG file to write")
    ap.add_argument("--reference", type=float, help="a reference constant to draw, GPa")
    ap.add_argument("--reference-label", default="reference")
    ap.add_argument("--min-depth", type=float, default=0.0, help="leave out shallower points, nm (a node or two in contact)")
    args = ap.parse_args()
    fig, ax = plt.subplots(figsize=(6, 4))
    for spec in args.curves:
        path, _, label = spec.partition(":")
        pts = [(h, c) for h, c in loading(path) if h >= args.min_depth]
        ax.plot([h for h, _ in pts], [c for _, c in pts], "o-", ms=3, label=label or path)
    if args.reference is not None:
        ax.axhline(args.reference, color="k", ls="--", lw=1, label=f"{args.reference_label} ({args.reference:g} GPa)")
    ax.set_xlabel("depth h (nm)")
    ax.set_ylabel("C = P / h$^2$ (GPa)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
