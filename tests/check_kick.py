#!/usr/bin/env python3
"""Kick's law: a sharp cone in an elastic-perfectly-plastic block gives P = C h^2.

  check_kick.py --indent BIN --mesh MESH --workdir DIR [--np 2] [--mpiexec M] [--section]
                [--mpiexec-args "--oversubscribe"] [--depth 36] [--steps 12]
                [--min-elements 5] [--tol 0.02] [--young 100] [--yield 1] [--friction 0]
                [--options "-formulation finite ..."] [--expect-C GPa --C-tol 0.1] [--unload-steps N]

A rigid sharp cone (70.3 deg half-angle, -indenter_radius 0) is pressed, frictionless and without
unloading, into the quarter block of tests/meshes/kick_block.geo (region `domain`, E = 100 GPa,
nu = 0.3, von Mises yield 1 GPa without hardening, symmetry planes left and front, bottom fixed).
Neither the cone nor the material has a length scale, so P / h^2 is the same at every depth; the
mesh brings one in (the elements), and the check applies once the contact radius spans at least
--min-elements elements: a = sqrt(A / pi) from the contact area A of load_displacement.csv (whole
indent, symmetry included) reaches the --min-elements-th node from the tip along the mesh edge
y = z = 0 (the element boundaries along the radius, read from the mesh). Over those steps every
P / h^2 must lie within --tol of their mean.

With --section the mesh is the axisymmetric section of tests/meshes/kick_section.geo (x = r, y the axis in
the file; its top edge y = z = 0 is the radius) and the run has no symmetry planes: its loads and areas are
the whole indent's already.

The contact grows by whole nodes, so the mesh under the contact must be uniform for P / h^2 to be:
on blocks graded right from the tip (tests/meshes/hertz_block.geo) the rings of nodes widen as they
enter, and P / h^2 rose and fell by 3 to 6% with each. kick_block.geo keeps a core of equal cubes;
the contact must stay inside it (P / h^2 rose by 2% once the contact reached the core's edge).

With --expect-C the mean of the counted P / h^2 (in GPa) must lie within --C-tol of it: 25.8 GPa is
the large-deformation value of Dao et al. (Acta Mater. 49 (2001) 3899) for a 70.3 deg cone with
friction 0.15 in a block with E = 70 GPa, nu = 0.3 and yield 0.3 GPa.

With --unload-steps the run unloads and summary.json gives the pile-up figures; the check is Bolshakov
& Pharr's trend (J. Mater. Res. 13 (1998) 1049) for a non-hardening solid: h_f / h_max > 0.7 (h_f the
residual depth) and a true contact area larger than the Oliver-Pharr area A(h_c) (pile-up).

Exit status: 0 pass, 1 a check or the run failed, 2 bad arguments.
"""
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import meshcheck  # noqa: E402

NU = 0.3



def indent_options(args):
    return [
        "-domain_young", f"{args.young:g}", "-domain_poisson", str(NU),
        "-domain_model", "plastic", "-domain_yield", f"{args.yield_stress:g}", "-domain_hardening", "linear",
        "-domain_hardening_slope", "0", *([] if args.section else ["-bc_symmetry", "left,front"]),
        "-bc_fixed", "bottom",
        "-indenter_type", "cone", "-indenter_radius", "0", "-contact_friction", f"{args.friction:g}",
        *(["-load_unload_steps", str(args.unload_steps)] if args.unload_steps else ["-load_unload", "0"]),
        "-output_fields", "0", "-quiet", *args.options.split(),
    ]

PROG = "check_kick.py"


def bad_input(msg):
    meshcheck.bad_input(PROG, msg)


def parse():
    ap = meshcheck.parser(PROG, __doc__, "quarter block made from tests/meshes/kick_block.geo (ASCII msh 2.2 or 4.1)")
    ap.add_argument("--depth", type=float, default=36.0, help="largest depth, nm (36)")
    ap.add_argument("--steps", type=int, default=12, help="load steps (12)")
    ap.add_argument("--min-elements", type=int, default=5, help="elements the contact radius must span for a step to count (5)")
    ap.add_argument("--tol", type=float, default=0.02, help="largest relative deviation of P/h^2 from the mean of the counted steps (0.02)")
    ap.add_argument("--young", type=float, default=100.0, help="Young's modulus, GPa (100)")
    ap.add_argument("--yield", dest="yield_stress", type=float, default=1.0, help="yield stress, GPa (1)")
    ap.add_argument("--friction", type=float, default=0.0, help="Coulomb friction coefficient (0)")
    ap.add_argument("--options", default="", help="more indent options, e.g. \"-formulation finite\"")
    ap.add_argument("--expect-C", type=float, default=None, help="expected P/h^2, GPa (none: not checked)")
    ap.add_argument("--C-tol", type=float, default=0.1, help="relative tolerance on --expect-C (0.1)")
    ap.add_argument("--unload-steps", type=int, default=0, help="unload in this many steps and check the pile-up trend (0)")
    ap.add_argument("--section", action="store_true",
                    help="the mesh is an axisymmetric section (tests/meshes/kick_section.geo, x = r, y the axis): "
                         "no symmetry planes")
    args = ap.parse_args()
    meshcheck.check_common(PROG, args)
    if args.steps < 1 or args.min_elements < 1:
        bad_input("--steps and --min-elements must be >= 1")
    if not args.depth > 0 or not args.tol > 0:
        bad_input("--depth and --tol must be > 0")
    return args


def edge_nodes(path):
    """Sorted x > 0 of the mesh nodes on the edge y = z = 0 (ASCII gmsh 2.2 or 4.1)."""
    try:
        with open(path) as f:
            lines = f.read().split("\n")
    except (OSError, UnicodeDecodeError) as e:
        bad_input(f"cannot read the mesh '{path}' as ASCII gmsh: {e}")
    if "$MeshFormat" not in lines or "$Nodes" not in lines:
        bad_input(f"'{path}' is not a gmsh mesh file (no $MeshFormat and $Nodes sections)")
    try:
        fmt = lines[lines.index("$MeshFormat") + 1].split()
        if fmt[1] != "0":
            bad_input(f"'{path}' is a binary gmsh file; write it with ASCII")
        i = lines.index("$Nodes") + 1
        coords = []
        if fmt[0].startswith("2"):
            for line in lines[i + 1:i + 1 + int(lines[i])]:
                coords.append(tuple(map(float, line.split()[1:4])))
        elif fmt[0].startswith("4"):
            nblocks = int(lines[i].split()[0])
            i += 1
            for _ in range(nblocks):
                n = int(lines[i].split()[3])
                i += 1 + n  # the block header, then n node tags
                for line in lines[i:i + n]:
                    coords.append(tuple(map(float, line.split()[:3])))
                i += n
        else:
            bad_input(f"'{path}': gmsh format {fmt[0]} is neither 2.2 nor 4.1")
    except (ValueError, IndexError):
        bad_input(f"'{path}': cannot read the nodes of this gmsh file")
    scale = max((abs(c) for p in coords for c in p), default=1.0)
    xs = sorted({x for x, y, z in coords if abs(y) <= 1e-9 * scale and abs(z) <= 1e-9 * scale and x > 1e-9 * scale})
    if len(xs) < 2:
        bad_input(f"'{path}' has no nodes on the edge y = z = 0, x > 0: not a quarter block of kick_block.geo")
    return xs


def uniform_core(xs):
    """The radius out to which the elements along the edge are all as wide as the first."""
    width = xs[0]
    k = 1
    while k < len(xs) and abs(xs[k] - xs[k - 1] - width) <= 1e-6 * width:
        k += 1
    return xs[k - 1]


def run_indent(args, out):
    return meshcheck.run_indent(PROG, args, [*indent_options(args), "-load_depth", f"{args.depth:g}", "-load_steps", str(args.steps)], out)


def main():
    args = parse()
    xs = edge_nodes(args.mesh)
    if len(xs) < args.min_elements:
        bad_input(f"the mesh has only {len(xs)} elements along its edge, fewer than --min-elements {args.min_elements}")
    a_min = xs[args.min_elements - 1]
    core = uniform_core(xs)
    out = os.path.join(os.path.abspath(args.workdir), "kick")
    os.makedirs(out, exist_ok=True)
    curve = os.path.join(out, "load_displacement.csv")
    if os.path.exists(curve):
        os.remove(curve)
    wall = run_indent(args, out)
    if wall is None:
        return 1
    try:
        with open(curve) as f:
            rows = list(csv.DictReader(f))
        steps = [(int(r["step"]), float(r["depth_nm"]), float(r["load_uN"]), float(r["contact_area_nm2"]), int(r["contact_nodes"]),
                  int(r["newton"]), int(r["cutbacks"])) for r in rows]
    except (OSError, KeyError, ValueError) as e:
        print(f"FAIL: cannot read {curve}: {e}")
        return 1

    steps = [s for s in steps if s[0] <= steps_loading(steps)]
    print(f"cone 70.3 deg, E/Y = {args.young / args.yield_stress:g}, friction {args.friction:g} {args.options}, depth {args.depth:g} nm in {args.steps} steps: {len(steps)} steps, "
          f"{steps[-1][6] if steps else 0} cutbacks, {sum(s[5] for s in steps)} Newton iterations, {wall:.1f} s")
    print(f"a step counts when its contact radius a = sqrt(A/pi) spans >= {args.min_elements} elements (a >= {a_min:.4g} nm; "
          f"element edges along the radius at {', '.join(f'{x:.4g}' for x in xs[:args.min_elements + 3])}, ... nm)")
    print(f"  {'step':>4} {'h (nm)':>8} {'P (uN)':>11} {'P/h^2 (uN/nm^2)':>16} {'a (nm)':>8} {'a/h':>5} {'elements':>8} {'nodes':>5}  counted")
    counted = []
    for step, h, P, A, nodes, _, _ in steps:
        if h <= 0:
            continue
        a = math.sqrt(A / math.pi)
        k = sum(1 for x in xs if x <= a * (1 + 1e-12))
        use = k >= args.min_elements
        if use:
            counted.append((step, h, P / h**2))
        print(f"  {step:4d} {h:8.3f} {P:11.5g} {P / h**2:16.6g} {a:8.4g} {a / h:5.2f} {k:8d} {nodes:5d}  {'yes' if use else 'no'}")
    a_last = math.sqrt(steps[-1][3] / math.pi) if steps else 0.0
    # a node's tributary area reaches half an element beyond it, and so does a
    print(f"the mesh's uniform core reaches {core:.4g} nm along the edge (elements {xs[0]:.4g} nm); "
          f"the contact radius at the last step is {a_last:.4g} nm")
    if a_last > core + 0.5 * xs[0]:
        print("FAIL: the contact grew past the uniform core, where the rings of nodes widen: lower --depth or use a larger core")
        return 1
    if len(counted) < 3:
        print(f"FAIL: only {len(counted)} step(s) with the contact over >= {args.min_elements} elements (need 3): raise --depth or --steps")
        return 1
    c = [v for _, _, v in counted]
    mean = sum(c) / len(c)
    dev = [v / mean - 1 for v in c]
    worst = max(range(len(c)), key=lambda i: abs(dev[i]))
    half = len(c) // 2
    trend = (sum(c[len(c) - half:]) / half) / (sum(c[:half]) / half) - 1
    print(f"P/h^2 over the {len(c)} counted steps (h = {counted[0][1]:g} to {counted[-1][1]:g} nm): mean {mean:.6g} uN/nm^2, "
          f"min {min(c):.6g} ({100 * (min(c) / mean - 1):+.2f}%), max {max(c):.6g} ({100 * (max(c) / mean - 1):+.2f}%), "
          f"spread (max - min)/mean {100 * (max(c) - min(c)) / mean:.2f}%; last {half} against first {half}: {100 * trend:+.2f}%")
    if abs(dev[worst]) > args.tol:
        print(f"FAIL: P/h^2 at step {counted[worst][0]} (h = {counted[worst][1]:g} nm) is {100 * dev[worst]:+.2f}% off the mean "
              f"(tolerance {100 * args.tol:g}%)")
        return 1
    print(f"every counted P/h^2 within {100 * args.tol:g}% of the mean (largest {100 * abs(dev[worst]):.2f}%)")
    if args.expect_C is not None:
        C = 1e3 * mean  # uN/nm^2 -> GPa
        off = C / args.expect_C - 1
        print(f"Kick's constant C = {C:.4g} GPa against {args.expect_C:g} GPa: {100 * off:+.2f}% (tolerance {100 * args.C_tol:g}%)")
        if abs(off) > args.C_tol:
            print("FAIL: Kick's constant off the expected value")
            return 1
    if args.unload_steps:
        try:
            with open(os.path.join(out, "summary.json")) as f:
                summary = json.load(f)
            values = {k: v["value"] if isinstance(v, dict) else v for k, v in summary.items()}
            hf, hmax, ratio = values["residual_depth_nm"], values["h_max_nm"], values["area_ratio"]
            pile = values["pileup_at_P_max_nm"]
        except (OSError, KeyError, ValueError, TypeError) as e:
            print(f"FAIL: cannot read the pile-up figures of {out}/summary.json: {e}")
            return 1
        print(f"unloaded: h_f/h_max = {hf / hmax:.3f}, true area / A(h_c) = {ratio:.3f}, pile-up at P_max {pile:.3g} nm "
              f"({100 * pile / hmax:.1f}% of h_max); Bolshakov & Pharr: h_f/h_max > 0.7 with pile-up (ratio > 1)")
        if not (hf / hmax > 0.7 and ratio > 1):
            print("FAIL: not the pile-up trend of a non-hardening solid")
            return 1
    print("PASS")
    return 0


def steps_loading(steps):
    """The last step of the loading (the step of the largest depth)."""
    return max(steps, key=lambda s: s[1])[0] if steps else 0


if __name__ == "__main__":
    sys.exit(main())
