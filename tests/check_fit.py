#!/usr/bin/env python3
"""scripts/indent-fit.py on curves indent made itself (doc/inverse.md), on a coarse mesh:

roundtrip: material B's cone and sphere curves with 1% noise, fitted together for E, sigma_y and n from the
  Latin-hypercube start; the fit is stopped by SIGTERM once some runs have finished (status 75), continued by
  the same command without rerunning any finished run, and must recover B and call it determined.
mystical: materials A and B (MATERIAL_A, MATERIAL_B) have nearly the same cone curve and different sphere
  curves; fitted to B's cone curve alone, the fit must say the curve cannot tell sigma_y and n apart, and to
  B's cone and sphere curves together that they determine both (and find B's n).
"""
import argparse
import glob
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "scripts"))
import heightmap  # noqa: E402
import indentcurves  # noqa: E402
import runfiles  # noqa: E402
from indentfit import dao, imprint, misfit  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
FIT = os.path.join(REPO, "scripts", "indent-fit.py")
# 8 uniform steps, as the test's figures were made (the files' -load_edge_steps 4 would double the runs)
MESH = ["-mesh_geo_parameters", "h_tip=40,h_far=500,r_fine=160", "-load_steps", "8", "-load_edge_steps", "0",
        "-load_unload_growth", "1.25"]
BOTH = ["film", "substrate"]
# A mystical pair on the test's mesh of the 3D half model (MYSTICAL_3D): B's yield is the one-parameter fit of B
# (E 70, n 0.2) to A's noise-free cone curve (scripts/indent-fit.py, doc/inverse.md); the test checks the pair's
# property again. The models in inputs/ are axisymmetric sections, on which the same construction did not give a
# mystical pair: B's cone curve stayed 1.25% from A's (n 0.2), or the cone alone determined both (n 0.15, yield
# 0.263212: spread 3.6%, limit 5%); the finer section tells these materials apart (doc/inverse.md).
MYSTICAL_3D = ["-mesh_file", "inputs/berkovich_half.geo", "-bc_symmetry", "symmetry"]
MATERIAL_A = (70.0, 0.3, 0.1)
MATERIAL_B = (70.0, 0.226451, 0.2)


def material(E, sy, n):
    out = []
    for r in BOTH:
        out += [f"-{r}_young", f"{E:g}", f"-{r}_yield", f"{sy:.12g}", f"-{r}_hardening_exponent", f"{n:g}"]
    return out


def param(name, opt, lo, hi, log=False):
    return ["--param", f"{name}={','.join(f'{r}_{opt}' for r in BOTH)}:{lo}:{hi}" + (":log" if log else "")]


def forward(args, model, opts, out, mesh=(), fields=False):
    """A run's curve; with fields, its fields at the segments' ends and the last step (its imprint)."""
    written = ["-output_fields", "1", "-output_fields_every", "1000000"] if fields else ["-output_fields", "0"]
    subprocess.run(args.launch + [args.indent, "-options_file", f"inputs/fit-{model}.opts"] + MESH + list(mesh) + opts +
                   ["-output_dir", out, "-output_overwrite", "-quiet"] + written, cwd=REPO, check=True)
    c = runfiles.read_curve(os.path.join(out, "load_displacement.csv"))
    return c["depth_nm"], c["load_uN"]


def write_curve(path, h, p, noise, seed):
    """The curve with Gaussian noise of relative size `noise` on each load."""
    indentcurves.write_csv(path, h, p * (1 + noise * np.random.default_rng(seed).standard_normal(len(p))))


def write_imprint(run_dir, path, noise, seed, half=450.0, pixels=129, center=(23.0, -17.0), tilt=(0.004, -0.003)):
    """A run's residual imprint as an AFM gives one: a square map (.gsf) whose axis is off its centre, tilted and
    raised by 6 nm, with Gaussian noise of `noise` times the imprint's depth on each pixel. Returns that depth."""
    surface = imprint.run_surface(run_dir)
    g = heightmap.grid_axis(half, pixels)
    X, Y = np.meshgrid(g, g)
    Z = surface(X - center[0], Y - center[1])
    depth = -np.nanmin(Z)
    Z = Z + tilt[0] * X + tilt[1] * Y + 6.0 + noise * depth * np.random.default_rng(seed).standard_normal(Z.shape)
    heightmap.write_gsf(path, Z, half, "synthetic AFM map")
    return depth


def fit(args, out, curves, params, extra=(), timeout=None, check=True, more=()):
    cmd = [sys.executable, FIT, "--out", out, "--indent", args.indent, "--launcher", args.launcher,
           "--jobs", str(2 // args.np), "--np", str(args.np), "--no-plots"] + list(more)
    for model, path, *imprint_map in curves:
        cmd += ["--model", f"inputs/fit-{model}.opts", "--curve", path]
        cmd += sum((["--imprint", m] for m in imprint_map), [])
    cmd += params + ["--"] + MESH + list(extra)
    proc = subprocess.Popen(cmd, cwd=REPO, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if timeout is None:
        text = proc.communicate()[0]
    else:
        runs = os.path.join(out, "runs")
        t0 = time.time()
        while len(glob.glob(os.path.join(runs, "*", "fit-run.json"))) < timeout and time.time() - t0 < 300:
            time.sleep(0.2)
        proc.send_signal(signal.SIGTERM)
        text = proc.communicate()[0]
    print(text, end="")
    if check and proc.returncode:
        raise SystemExit(f"FAIL: indent-fit exited {proc.returncode}")
    return proc.returncode, text


def branches(h, p):
    top = int(np.argmax(h))
    return misfit.Branches(np.r_[0.0, h[:top + 1]], np.r_[0.0, p[:top + 1]], h[top:], p[top:])


def dense(h, p, n_load=60, n_unload=40):
    """indent's curve sampled as densely as a measured one: 60 loading and 40 unloading points, interpolated as
    the fit interpolates a simulated curve (so that the fit's model holds the truth exactly)."""
    b = branches(h, p)
    lh = np.linspace(b.load_h[1], b.h_max, n_load)
    last = b.unload_h[np.nonzero(b.unload_p > 0)[0][-1]]
    uh = np.linspace(b.h_max, last, n_unload)
    return (np.r_[lh, uh[1:]], np.r_[misfit.simulated_load(b, lh, "loading"),
                                      misfit.simulated_load(b, uh[1:], "unloading")])


def misfit_between(a, b):
    """The RMS load difference (fraction of P_max, loading and unloading weighted alike) of two of indent's
    curves given as (depth, load) arrays."""
    meas, sim = branches(*a), branches(*b)
    meas.unload_h, meas.unload_p = meas.unload_h[meas.unload_p > 0], meas.unload_p[meas.unload_p > 0]
    return misfit.rms(misfit.residuals(meas, sim), 2.0)


def result(out):
    with open(os.path.join(out, "result.json")) as f:
        return json.load(f)


def finished(out):
    return {p: os.stat(p).st_mtime_ns for p in glob.glob(os.path.join(out, "runs", "*", "fit-run.json"))}


def roundtrip(args, work):
    truth = MATERIAL_B
    curves = []
    for k, model in enumerate(("cone", "sphere")):
        h, p = dense(*forward(args, model, material(*truth), os.path.join(work, f"B_{model}")))
        path = os.path.join(work, f"B_{model}.csv")
        write_curve(path, h, p, 0.01, 11 + k)
        curves.append((model, path))
    params = (param("E", "young", 40, 120) + param("yield", "yield", 0.05, 2, True) +
              param("n", "hardening_exponent", 0, 0.5))
    out = os.path.join(work, "fit_roundtrip")
    shutil.rmtree(out, ignore_errors=True)
    rc, text = fit(args, out, curves, params, timeout=6, check=False, more=["--sweep-points", "4"])
    if rc != 75 or "run the same command to continue" not in text:
        raise SystemExit(f"FAIL: SIGTERM gave status {rc}, not 75 with a line on how to continue")
    before = finished(out)
    if not before:
        raise SystemExit("FAIL: no forward run had finished before the stop")
    fit(args, out, curves, params, more=["--sweep-points", "4"])
    after = finished(out)
    rerun = [p for p, t in before.items() if after.get(p) != t]
    if rerun:
        raise SystemExit(f"FAIL: {len(rerun)} finished forward runs were run again: {rerun[:3]}")
    res = result(out)
    if res["forward_runs"]["cached"] < len(before):
        raise SystemExit(f"FAIL: {res['forward_runs']['cached']} runs from the cache, {len(before)} were finished")
    got = {k: v["value"] for k, v in res["parameters"].items()}
    errs = {"E": abs(got["E"] / truth[0] - 1), "yield": abs(got["yield"] / truth[1] - 1), "n": abs(got["n"] - truth[2])}
    print(f"round trip: {len(before)} runs finished before SIGTERM, none run again; E {got['E']:.4g} "
          f"(error {100 * errs['E']:.2f}%), yield {got['yield']:.4g} ({100 * errs['yield']:.2f}%), "
          f"n {got['n']:.4g} (error {errs['n']:.4f})")
    # the tolerances: E 1%, yield 3%, n 0.02
    if errs["E"] > 0.01 or errs["yield"] > 0.03 or errs["n"] > 0.02:
        raise SystemExit("FAIL: the round trip missed the material")
    if not res["distinguishable"]:
        raise SystemExit("FAIL: cone and sphere together were called indistinguishable")
    for k, v in res["parameters"].items():
        if not (v["ci95"] is not None and v["ci95"] > 0):  # null: an interval without bound
            raise SystemExit(f"FAIL: no confidence interval for {k}")
    # Dao's start from the cone curve: E from its unloading, yield on the valley of its sigma_0.033
    out = os.path.join(work, "fit_dao_start")
    shutil.rmtree(out, ignore_errors=True)
    rc, text = fit(args, out, curves, params, more=["--start", "dao", "--max-evals", "1"])
    m = re.search(r"Dao's start from curve 1: E\* ([0-9.]+) GPa \(Oliver-Pharr\), C ([0-9.]+) GPa, sigma_0.033 "
                  r"([0-9.]+) GPa; E ([0-9.]+) GPa", text)
    if not m:
        raise SystemExit("FAIL: no line on Dao's start")
    e_star, C, sr, E = (float(g) for g in m.groups())
    sr_true = truth[1] * (1 + truth[0] * 0.033 / truth[1]) ** truth[2]
    print(f"Dao's start: E* {e_star:.4g} (truth {truth[0] / 0.91:.4g}), C {C:.4g}, sigma_0.033 {sr:.4g} (truth "
          f"{sr_true:.4g}), E {E:.4g} (truth {truth[0]:g})")
    # what the start must hold: Dao's Pi_1 at the printed E* and C, and E from E* with the model's nu (0.3).
    # How near the truth it lands depends on Oliver-Pharr's E* for this model's unloading (doc/inverse.md).
    if abs(C / sr / dao.pi1(e_star / sr) - 1) > 1e-3 or abs(E / (e_star * 0.91) - 1) > 1e-3:
        raise SystemExit("FAIL: Dao's start does not satisfy Pi_1 or E = E* (1 - nu^2)")


def mystical(args, work):
    a, b = MATERIAL_A, MATERIAL_B
    ca, sa = (forward(args, m, material(*a), os.path.join(work, f"MA_{m}"), MYSTICAL_3D) for m in ("cone", "sphere"))
    bc, bs = (forward(args, m, material(*b), os.path.join(work, f"MB_{m}"), MYSTICAL_3D, fields=m == "cone")
              for m in ("cone", "sphere"))
    dc, ds = misfit_between(ca, bc), misfit_between(sa, bs)
    print(f"mystical pair: A = {a}, B = {b}; RMS load difference of the cone curves {100 * dc:.2f}% of P_max, "
          f"of the sphere curves {100 * ds:.2f}%")
    if dc > 0.01 or ds < 2 * dc:
        raise SystemExit("FAIL: A and B are not a mystical pair on this mesh")
    # sampled as indent samples it (16 points), with 1% noise: at this density B's cone curve cannot tell A's
    # sigma_y and n from B's; dense curves of this coarse model do (doc/inverse.md)
    paths = []
    for k, (model, hp) in enumerate((("cone", bc), ("sphere", bs))):
        paths.append((model, os.path.join(work, f"MB_{model}.csv")))
        write_curve(paths[-1][1], *hp, 0.01, 21 + k)
    # B's imprint under the cone, as an AFM map (1% noise on each pixel's height)
    afm = os.path.join(work, "MB_cone.gsf")
    depth = write_imprint(os.path.join(work, "MB_cone"), afm, 0.01, 31)
    params = param("yield", "yield", 0.01, 1, True) + param("n", "hardening_exponent", 0, 0.5)
    res = {}
    for name, cs in (("cone", paths[:1]), ("cone_sphere", paths), ("cone_imprint", [paths[0] + (afm,)])):
        out = os.path.join(work, f"fit_mystical_{name}")
        shutil.rmtree(out, ignore_errors=True)
        fit(args, out, cs, params, extra=MYSTICAL_3D + sum(([f"-{r}_young", "70"] for r in BOTH), []),
            more=["--start", "0.2,0.2"])
        res[name] = result(out)
    one, two = res["cone"], res["cone_sphere"]
    print(f"B's cone curve alone: determined {one['distinguishable']}, spread {100 * one['weak_spread']:.3g}% of the "
          f"bounds' ranges; with the sphere curve: {two['distinguishable']}, spread {100 * two['weak_spread']:.3g}%, "
          f"yield {two['parameters']['yield']['value']:.4g}, n {two['parameters']['n']['value']:.4g}; a 0.5% load "
          f"error of the model's own moves them {100 * one['model_spread']:.3g}% (cone) and "
          f"{100 * two['model_spread']:.3g}% (cone and sphere)")
    if one["robust"]:
        raise SystemExit("FAIL: the cone curve alone was said to be robust to the model's own error")
    if one["distinguishable"]:
        raise SystemExit("FAIL: the cone curve alone was said to determine yield and n")
    if not two["distinguishable"]:
        raise SystemExit("FAIL: cone and sphere together were said not to determine yield and n")
    if abs(two["parameters"]["n"]["value"] - b[2]) > 0.03:
        raise SystemExit("FAIL: cone and sphere together did not find B's n")
    im = res["cone_imprint"]
    got = {k: v["value"] for k, v in im["parameters"].items()}
    print(f"B's cone curve with its imprint (depth {depth:.4g} nm, {im['imprints'][0]['pixels']} pixels, RMS height "
          f"difference {im['imprints'][0]['rms_nm']:.3g} nm): determined {im['distinguishable']}, spread "
          f"{100 * im['weak_spread']:.3g}%, yield {got['yield']:.4g} (B {b[1]:.4g}), n {got['n']:.4g} (B {b[2]:g}); "
          f"the model's own error moves them {100 * im['model_spread']:.3g}%")
    if not im["distinguishable"]:
        raise SystemExit("FAIL: the cone curve and its imprint together were said not to determine yield and n")
    # B within twice the 95% intervals: the model's own error on this coarse mesh (the report's warning) moves the
    # optimum along the valley by about one interval (measured: yield 1.2, n 1.1 of theirs)
    far = {k: abs(got[k] - want) / im["parameters"][k]["ci95"] for k, want in (("yield", b[1]), ("n", b[2]))}
    print(f"B's distance from the fit, in 95% intervals: yield {far['yield']:.2f}, n {far['n']:.2f}")
    if max(far.values()) > 2:
        raise SystemExit("FAIL: the cone curve and its imprint did not find B")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case", choices=("roundtrip", "mystical"))
    ap.add_argument("--indent", required=True)
    ap.add_argument("--mpiexec", default="mpiexec")
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--np", type=int, default=1, choices=(1, 2), help="ranks of each forward run of the fits")
    args = ap.parse_args()
    args.launcher = f"{args.mpiexec} -n {{np}}"
    args.launch = [args.mpiexec, "-n", "1"]
    os.makedirs(args.workdir, exist_ok=True)
    {"roundtrip": roundtrip, "mystical": mystical}[args.case](args, args.workdir)
    print("PASS")


if __name__ == "__main__":
    main()
