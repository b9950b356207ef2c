#!/usr/bin/env python3
"""Scratch tests (-scratch_length): the forces of scratch.csv and the stick zone of the fields.

  --frictionless TOL: a frictionless sphere sliding on an elastic block at constant depth; at every
    slide step |lateral| <= TOL * normal (the pressure is symmetric about the axis) and no side force;
  --friction MU --tol TOL: with Coulomb friction MU every contact node slips once the slide passes
    --steady nm, and there lateral / normal = MU within TOL (relative);
  --load P: under load control (-load_force P) the normal load stays P within 1e-6 while sliding;
  --mindlin MU --estar E --radius R --cell H: Cattaneo-Mindlin, a sphere pressed and then moved
    sideways by less than full sliding: the stick zone's radius c, from the area of the contact nodes
    that have not slipped since the slide began (a uniform core of cells H wide), equals a (1 - Q / (MU P))^(1/3) with a = (3 P R / (4 E*))^(1/3), within one cell H;
  --ranks N: the run on N ranks gives the same scratch.csv within 1e-8 of each column's largest value.

  check_scratch.py --mpiexec M --indent BIN --workdir D [--np N] <check> -- <indent options>
"""
import os
import shutil
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402


def table(d, name):
    return np.atleast_1d(np.genfromtxt(os.path.join(d, name), delimiter=",", names=True))


def print_rows(s):
    print(f"{'step':>4} {'slid nm':>8} {'P uN':>11} {'F_lat uN':>11} {'F_side uN':>10} {'ratio':>10} "
          f"{'contact':>7} {'stick':>5}")
    for r in s:
        print(f"{int(r['step']):4d} {r['distance_nm']:8.3f} {r['normal_uN']:11.5f} {r['lateral_uN']:11.5f} "
              f"{r['side_uN']:10.3g} {r['friction']:10.3e} {int(r['contact']):7d} {int(r['stick']):5d}")


def sliding(s):
    """The rows of the slide: the indenter has moved and not yet begun to unload (the rows up to the
    slide's end: unloading rows repeat its distance)."""
    end = np.flatnonzero(s["distance_nm"] == s["distance_nm"].max())[0]
    return s[: end + 1][s["distance_nm"][: end + 1] > 0]


def check_frictionless(s, tol):
    rows = sliding(s)
    worst = np.max(np.abs(rows["lateral_uN"]) / rows["normal_uN"])
    side = np.max(np.abs(rows["side_uN"]))
    print(f"frictionless slide: largest |lateral| / normal {worst:.3e} (tolerance {tol:g}), side force {side:g} uN")
    return (worst > tol) + (side != 0)


def check_load(s, load, rtol):
    rows = sliding(s)
    dev = np.max(np.abs(rows["normal_uN"] / load - 1))
    print(f"load control: normal load on the slide within {dev:.2e} of {load:g} uN (tolerance {rtol:g})")
    return dev > rtol


def check_friction(s, mu, tol, steady):
    rows = sliding(s)
    rows = rows[rows["distance_nm"] >= steady]
    if len(rows) == 0:
        print(f"FAIL: no slide step at or past {steady:g} nm")
        return 1
    dev = np.max(np.abs(rows["friction"] / mu - 1))
    stick = int(np.max(rows["stick"]))
    print(f"slide past {steady:g} nm: lateral / normal from {rows['friction'].min():.5f} to "
          f"{rows['friction'].max():.5f}, mu {mu:g}: largest relative difference {dev:.2e} (tolerance {tol:g}); "
          f"sticking nodes at most {stick}")
    return (dev > tol) + (stick != 0)


def step_fields(run):
    """Per output step: the current positions of the vertices and the contact status."""
    import h5py  # only this check reads the fields
    with h5py.File(os.path.join(run, "indent.h5"), "r") as h5:
        x = h5["geometry/vertices"][...]
        steps = sorted(int(k) for k in h5["xdmf"].keys())
        return [(x + h5[f"xdmf/{k}/displacement"][...], h5[f"xdmf/{k}/contact_status"][...][:, 0]) for k in steps]


def mindlin_step(row, start, pos, status, mu, estar, radius, cell):
    P, Q = row["normal_uN"] * 1e3, row["lateral_uN"] * 1e3  # nN: with GPa and nm
    a = (3 * P * radius / (4 * estar)) ** (1 / 3)
    ratio = Q / (mu * P)
    c_theory = a * (1 - ratio) ** (1 / 3)
    # The stick zone: the contact nodes that have not slipped since the slide began (they moved with the
    # indenter, to the solver's precision), rather than the status of the last increment, which near the
    # zone's edge, where the slip vanishes, is decided by rounding.
    slip = np.hypot(pos[:, 0] - start[:, 0] - row["distance_nm"], pos[:, 1] - start[:, 1])
    stuck = (status > 0) & (slip <= 1e-6 * slip[status > 0].max())
    # Its radius from its area: on the uniform core each surface node carries a cell's area, half of it on
    # the mirror plane y = 0 (the half model's stick zone is a half disc).
    weight = np.where(np.abs(pos[:, 1]) <= 1e-6 * cell, 0.5, 1.0)
    c = cell * np.sqrt(2 * np.sum(weight[stuck]) / np.pi)
    r = np.hypot(pos[:, 0] - row["x_nm"], pos[:, 1] - row["y_nm"])
    print(f"{row['distance_nm']:8.3f} {P * 1e-3:9.4f} {Q * 1e-3:9.4f} {ratio:8.4f} {a:8.2f} {c_theory:9.2f} "
          f"{c:9.2f} {c - c_theory:+8.2f} {r[stuck].max():9.2f} {r[(status > 0) & ~stuck].min():9.2f}")
    return abs(c - c_theory) > cell


def check_mindlin(s, run, mu, estar, radius, cell):
    fields = step_fields(run)
    if len(fields) != len(s):
        print(f"FAIL: {len(fields)} output steps for {len(s)} accepted steps (the check needs -output_fields_every 1)")
        return 1
    start = fields[np.flatnonzero(s["distance_nm"] == 0)[-1]][0]
    print(f"{'slid nm':>8} {'P uN':>9} {'Q uN':>9} {'Q/(mu P)':>8} {'Hertz a':>8} {'Mindlin c':>9} {'stick c':>9} "
          f"{'c diff':>8} {'out stick':>9} {'in slip':>9}   (nm; stick c from the area of the nodes that never slipped)")
    failed, checked = 0, 0
    for row, (pos, status) in zip(s, fields):
        ratio = row["lateral_uN"] / (mu * row["normal_uN"]) if row["normal_uN"] > 0 else 0
        if row["distance_nm"] > 0 and 0.2 <= ratio <= 0.9:
            failed += mindlin_step(row, start, pos, status, mu, estar, radius, cell)
            checked += 1
    print(f"{checked} slide steps with 0.2 <= Q / (mu P) <= 0.9 checked; tolerance one cell, {cell:g} nm")
    return failed + (checked < 3)


def check_ranks(s, other):
    if s.shape != other.shape:
        print(f"FAIL: {len(s)} rows against {len(other)}")
        return 1
    worst = 0.0
    for name in s.dtype.names:
        scale = max(np.max(np.abs(s[name])), 1e-300)
        worst = max(worst, np.max(np.abs(s[name] - other[name])) / scale)
    print(f"scratch.csv on two rank counts: largest difference {worst:.2e} of a column's largest value (tolerance 1e-8)")
    return worst > 1e-8


def main():
    ap, argv, options = indentrun.parser_and_options("check_scratch.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--frictionless", type=float)
    ap.add_argument("--friction", type=float)
    ap.add_argument("--tol", type=float, default=0.02)
    ap.add_argument("--steady", type=float, default=0.0)
    ap.add_argument("--load", type=float)
    ap.add_argument("--mindlin", type=float)
    ap.add_argument("--estar", type=float)
    ap.add_argument("--radius", type=float)
    ap.add_argument("--cell", type=float)
    ap.add_argument("--ranks", type=int)
    args = ap.parse_args(argv)
    shutil.rmtree(args.workdir, ignore_errors=True)
    run = os.path.join(args.workdir, "scratch")
    if not indentrun.run(args, args.np, options, run, "indent"):
        return 1
    s = table(run, "scratch.csv")
    print_rows(s)
    failed = 0
    if args.frictionless is not None:
        failed += check_frictionless(s, args.frictionless)
    if args.friction is not None:
        failed += check_friction(s, args.friction, args.tol, args.steady)
    if args.load is not None:
        failed += check_load(s, args.load, 1e-6)
    if args.mindlin is not None:
        failed += check_mindlin(s, run, args.mindlin, args.estar, args.radius, args.cell)
    if args.ranks is not None:
        other = os.path.join(args.workdir, f"np{args.ranks}")
        if not indentrun.run(args, args.ranks, options, other, "indent"):
            return 1
        failed += check_ranks(s, table(other, "scratch.csv"))
    print("the scratch checks out" if not failed else f"FAIL: {failed} check(s)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
