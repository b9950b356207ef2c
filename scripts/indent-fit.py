#!/usr/bin/env python3
"""Which material made this measured curve? Fits indent's curves to measured ones (doc/inverse.md).

  scripts/indent-fit.py --out fits/al --model inputs/fit-cone.opts --curve berkovich.csv \\
      --model inputs/fit-sphere.opts --curve sphere.csv \\
      --param E=film_young,substrate_young:40:120 --param yield=film_yield,substrate_yield:0.05:2:log \\
      --param n=film_hardening_exponent,substrate_hardening_exponent:0:0.5 [--jobs 2 --np 1] [-- OPTIONS]

--model OPTS: indent's options file for the curves that follow it (the indenter, the mesh, the fixed material
options). --curve FILE: a measured curve (CSV, Hysitron .txt, Agilent .xls/.xlsx, as scripts/measured-curve.py
reads them; --test, --format, --compliance and --drift given before it apply to it). Each curve is simulated to
its own largest depth (-load_depth) with the model given before it; options after -- go to every run. A 3D
model whose indenter is of revolution (sphere, cone, flat, table) on inputs/' parametric meshes runs on the
axisymmetric section of the same parameters (scripts/sectionmodel.py; OUT/models holds it); --3d keeps it 3D.
--param NAME=OPTION[,OPTION...]:LOW:HIGH[:log]: a parameter, the options it sets (several for one material in
two regions) and its bounds (':log': scaled by its logarithm). --imprint MAP: the residual imprint of the last
--curve (an AFM height map, Gwyddion .gsf or x y z lines), a second term of the misfit: the model's top surface
after unloading against the map, leveled on a ring around the indenter's axis (--imprint-center, -rotation,
-radius, -weight, -unit, -points, -noise given before it apply to it).

The fit: SciPy's trust-region reflective least squares on the loads at the measured depths (loading and
unloading, weights --weights L,U), its Jacobian by forward differences whose runs go concurrently (--jobs K
runs of --np R ranks; --launcher "srun -n {np} --exclusive" inside a Slurm allocation), started from the best
point of a small Latin-hypercube sweep (--start sweep) or from given values (--start V1,V2,...). One line per
evaluation on the standard output. Every forward run is kept in OUT/runs, keyed by its model file and options:
run the same command again, after an interruption (SIGTERM, SIGINT: status 75) or with other settings, and
nothing finished is run again.

Output in OUT: report.txt (the parameters with 95% confidence intervals, their correlations, the verdict on
what the curves can tell apart, the forward runs and their time), result.json, history.csv, curve-K.csv
(measured and fitted loads), imprint-K.csv (measured and fitted heights), fit.png, imprint-K.png and misfit.png.
Exit status: 0 fitted; 1 bad input (one line); 3 the forward runs failed at the start; 75 stopped.
"""
import argparse
import csv
import json
import os
import re
import signal
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import indentcurves  # noqa: E402
import sectionmodel  # noqa: E402
import runfiles  # noqa: E402
from indentfit import dao, imprint, misfit, params as fparams, runs, stats  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EX_STOPPED = 75


class FitError(Exception):
    pass


class Curve:
    def __init__(self, path, model, read_opts):
        self.path, self.model, self.read_opts = path, model, dict(read_opts)
        self.imprint_opts, self.imprint = None, None


class CurveAction(argparse.Action):
    """--curve takes the --model and reading options given before it."""

    def __call__(self, parser, ns, value, option_string=None):
        if not ns.model:
            parser.error(f"--curve {value}: give --model OPTIONS_FILE before it")
        ns.curves.append(Curve(value, ns.model, {"fmt": ns.format, "test": ns.test, "compliance": ns.compliance,
                                                 "drift": ns.drift}))


class ImprintAction(argparse.Action):
    """--imprint attaches a height map, with the --imprint-* options given before it, to the last --curve."""

    def __call__(self, parser, ns, value, option_string=None):
        if not ns.curves:
            parser.error(f"--imprint {value}: give the --curve whose indenter made it before it")
        if ns.curves[-1].imprint_opts is not None:
            parser.error(f"--imprint {value}: curve {ns.curves[-1].path} has an imprint already")
        ns.curves[-1].imprint_opts = {"path": value, "unit": ns.imprint_unit, "center": ns.imprint_center,
                                      "rotation": ns.imprint_rotation, "radius": ns.imprint_radius,
                                      "points": ns.imprint_points, "weight": ns.imprint_weight,
                                      "noise": ns.imprint_noise}


def parse_args(argv):
    extra = []
    if "--" in argv:
        k = argv.index("--")
        argv, extra = argv[:k], argv[k + 1:]
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True, help="the fit's directory (its runs, report and plots)")
    ap.add_argument("--model", help="indent's options file for the curves after it")
    ap.add_argument("--3d", dest="three_d", action="store_true",
                    help="keep a 3D model whose indenter of revolution would run on the axisymmetric section")
    ap.add_argument("--format", default="auto", help="format of the curves after it: auto, csv, hysitron, agilent")
    ap.add_argument("--test", type=int, default=1, help="the test (sheet) of an Agilent file, for the curves after it")
    ap.add_argument("--compliance", type=float, default=0.0, help="frame compliance (nm/uN) of the curves after it")
    ap.add_argument("--drift", type=float, default=0.0, help="thermal drift (nm/s) of the curves after it")
    ap.add_argument("--curve", action=CurveAction, dest="curves", default=[], help="a measured curve")
    ap.add_argument("--imprint-unit", default="nm",
                    help="length unit of the x y z maps after it (a .gsf names its own)")
    ap.add_argument("--imprint-center", default="deepest",
                    help="the indenter's axis on the maps after it: X,Y in the map's frame (nm), or 'deepest' "
                         "(the centroid of the pixels deeper than half the imprint, then the shift that registers "
                         "the model's surface on the map at every evaluation; default)")
    ap.add_argument("--imprint-rotation", type=float, default=0.0,
                    help="the direction on the maps after it (degrees from their x axis) of the model's x axis")
    ap.add_argument("--imprint-radius", type=float,
                    help="radius (nm) of the disc fitted on the maps after it (default: 0.8 of the largest disc "
                         "around the centre inside the map; the ring between them levels the map)")
    ap.add_argument("--imprint-points", type=int, default=2000, help="most pixels fitted per map (default 2000)")
    ap.add_argument("--imprint-weight", type=float, default=1.0,
                    help="weight of the maps after it against a curve's loading or unloading (default 1)")
    ap.add_argument("--imprint-noise", type=float,
                    help="height noise (nm) of the maps after it, needed with --noise in uN")
    ap.add_argument("--imprint", action=ImprintAction,
                    help="a measured residual imprint (AFM height map: .gsf, or x y z lines) of the last --curve: "
                         "a second term of the misfit (doc/inverse.md)")
    ap.add_argument("--param", action="append", default=[], help="NAME=OPTION[,OPTION...]:LOW:HIGH[:log]")
    ap.add_argument("--weights", default="1,1", help="weights of the loading and the unloading (default 1,1)")
    ap.add_argument("--points", type=int, default=40, help="measured points per branch fitted (default 40)")
    ap.add_argument("--start", default="sweep",
                    help="'sweep', 'dao' (Dao et al.'s reverse analysis of the first curve, for parameters named E, "
                         "yield and n of a sharp tip) or the parameters' values V1,V2,...")
    ap.add_argument("--indent-op", help="indent-op, for --start dao (default: beside --indent)")
    ap.add_argument("--sweep-points", type=int, default=0, help="points of the starting sweep (default 2p+2)")
    ap.add_argument("--noise", default="residual",
                    help="the load noise for the intervals: 'residual' (the residuals' scatter) or uN")
    ap.add_argument("--fd-step", type=float, default=0.02, help="finite-difference step, as a fraction of the range")
    ap.add_argument("--method", default="dogbox", choices=("dogbox", "trf"),
                    help="SciPy's bounded least-squares method (default dogbox: trf's scaling near a bound "
                         "shortens its steps there)")
    ap.add_argument("--max-evals", type=int, default=40, help="most evaluations of the optimiser (default 40)")
    ap.add_argument("--tol", type=float, default=1e-3, help="relative tolerance on the misfit and the parameters")
    ap.add_argument("--spread-limit", type=float, default=0.05,
                    help="largest 95%% spread (fraction of the bounds' range) of a combination of parameters "
                         "still called determined (default 0.05)")
    ap.add_argument("--model-error", type=float, default=0.005,
                    help="the model's own load error (its mesh and load steps), RMS fraction of P_max: a fit whose "
                         "weakest combination of parameters it moves more than the spread limit is reported as "
                         "not robust (default 0.005; 0: not checked)")
    ap.add_argument("--jobs", type=int, default=0, help="forward runs at once (default: cores / np)")
    ap.add_argument("--np", type=int, default=1, help="ranks per forward run (default 1)")
    ap.add_argument("--indent", default=os.path.join(REPO, "build", "indent"), help="indent's executable")
    ap.add_argument("--launcher", default="mpiexec -n {np}", help="command before indent; {np} is --np")
    ap.add_argument("--no-speculate", action="store_true",
                    help="start a point's Jacobian runs only when the optimiser asks for them")
    ap.add_argument("--no-plots", action="store_true")
    args = ap.parse_args(argv)
    args.extra = extra
    if not args.curves:
        ap.error("no --curve given")
    if not args.param:
        ap.error("no --param given")
    if not args.model_error >= 0:
        ap.error(f"--model-error {args.model_error:g}: a load error, a fraction of P_max >= 0 (0.005 is 0.5%)")
    return args


def section_model(args, c):
    """The curve's model on the axisymmetric section where its indenter allows it (scripts/sectionmodel.py)."""
    try:
        tokens, why = sectionmodel.section_of(["-options_file", c.model])
    except (sectionmodel.ModelError, ValueError) as e:
        raise FitError(f"--model {c.model}: {e}") from None
    if tokens is None:
        return
    os.makedirs(os.path.join(args.out, "models"), exist_ok=True)
    path = os.path.join(args.out, "models", f"{c.index + 1}-{os.path.basename(c.model)}")
    sectionmodel.write_options(path, tokens)
    with open(path) as f:
        c.model_text = f.read()
    c.model_abs = os.path.abspath(path)
    print(f"fit: curve {c.index + 1}: model {c.model}: {why}, written to {path} (--3d keeps the 3D model)")


def load_curves(args):
    out = []
    for k, c in enumerate(args.curves):
        if not os.path.isfile(c.model):
            raise FitError(f"--model {c.model}: no such file")
        ro = c.read_opts
        raw = indentcurves.correct(indentcurves.read(c.path, ro["fmt"], ro["test"]), ro["compliance"], ro["drift"])
        try:
            b = misfit.measured_branches(raw, args.points, name=os.path.basename(c.path))
        except ValueError as e:
            raise FitError(str(e)) from None
        with open(c.model) as f:
            c.model_text = f.read()
        c.model_abs = os.path.abspath(c.model)
        c.branches, c.index = b, k
        if not args.three_d:
            section_model(args, c)
        if c.imprint_opts is not None:
            o = c.imprint_opts
            try:
                c.imprint = imprint.load(o["path"], o["unit"], o["center"], o["rotation"], o["radius"], o["points"],
                                         o["weight"], o["noise"])
            except imprint.ImprintError as e:
                raise FitError(str(e)) from None
        out.append(c)
    return out


class Fit:
    def __init__(self, args, curves, params):
        self.args, self.curves, self.params = args, curves, params
        w = [float(x) for x in args.weights.split(",")]
        if len(w) != 2 or min(w) < 0 or max(w) == 0:
            raise FitError(f"--weights {args.weights}: give two non-negative numbers, not both zero")
        self.w = w
        self.w2 = len(curves) * (w[0] ** 2 + w[1] ** 2) + sum(c.imprint.weight ** 2 for c in curves if c.imprint)
        jobs = args.jobs or max(1, (os.cpu_count() or 1) // args.np)
        self.runner = runs.Runner(os.path.join(args.out, "runs"), args.indent, args.launcher, args.np, jobs,
                                  log=self.say)
        self.evals = {}
        self.history = []
        self.best = None
        self.t0 = time.time()

    def say(self, text):
        print(text, flush=True)

    def options(self, curve, u):
        opts = []
        for p, uu in zip(self.params, u):
            opts += p.indent_options(p.value(uu))
        # a run whose imprint is fitted writes the fields of its segments' ends and of its last step only
        fields = ["-output_fields", "1", "-output_fields_every", "1000000"] if curve.imprint else []
        return opts + ["-load_depth", f"{curve.branches.h_max:.10g}"] + fields + self.args.extra

    def submit(self, u):
        return [self.runner.submit(c.model_abs, c.model_text, self.options(c, u)) for c in self.curves]

    def fd_points(self, u):
        h = self.args.fd_step
        pts = []
        for i in range(len(u)):
            v = np.array(u, float)
            step = h if v[i] + h <= 1.0 else -h
            v[i] += step
            pts.append((v, step))
        return pts

    def residual(self, u, kind="eval"):
        key = tuple(np.round(u, 12))
        if key in self.evals:
            return self.evals[key][0]
        recs = [f.result() for f in self.submit(u)]
        parts, sims = [], []
        for c, rec in zip(self.curves, recs):
            sim = None
            path = os.path.join(rec["dir"], "load_displacement.csv")
            if rec["returncode"] == 0 and os.path.isfile(path):
                sim = misfit.read_indent_curve(path)
            sims.append(sim)
            parts.append(misfit.residuals(c.branches, sim, *self.w))
            if c.imprint:
                try:
                    parts.append(c.imprint.residuals(self.surface(rec)))
                except imprint.ImprintError as e:
                    raise FitError(f"--imprint {c.imprint.path}: {e}") from None
        r = np.concatenate(parts)
        self.evals[key] = (r, recs, sims)
        if kind != "fd":
            self.record(u, r, kind, failed=sum(rec["returncode"] != 0 for rec in recs))
        return r

    def groups(self):
        """Index arrays of each curve's residuals and each imprint's: each has a noise of its own."""
        out, k = [], 0
        for c in self.curves:
            sizes = [sum(len(h) for _, h, _, _ in misfit.fitted_branches(c.branches, *self.w))]
            sizes += [len(c.imprint.z)] if c.imprint else []
            for n in sizes:
                out.append(np.arange(k, k + n))
                k += n
        return out

    def surface(self, rec):
        """The top surface of a run whose imprint is fitted (None for a failed run)."""
        if rec["returncode"] != 0:
            return None
        try:
            return imprint.run_surface(rec["dir"])
        except (OSError, ValueError, RuntimeError, runfiles.InputError) as e:
            # RuntimeError: matplotlib's search of a top surface whose deformed triangles overlap
            raise FitError(f"the top surface of {rec['dir']} cannot be read: {e}") from None

    def record(self, u, r, kind, failed=0):
        m = misfit.rms(r, self.w2)
        if self.best is None or m < self.best[0]:
            self.best = (m, np.array(u, float))
        x = [p.value(uu) for p, uu in zip(self.params, u)]
        self.history.append((len(self.history) + 1, kind, m, *x))
        running, queued = self.runner.pending()
        cnt = self.runner.counts
        vals = " ".join(f"{p.name}={v:.5g}" for p, v in zip(self.params, x))
        # a failed run's curve counts as zero load: say so rather than show that misfit as the model's
        what = f"{failed} forward run(s) failed, counted as zero load" if failed else f"misfit {100 * m:.4g}%"
        self.say(f"fit: {kind} {len(self.history):3d}  {what} (best {100 * self.best[0]:.4g}%)  "
                 f"{vals}  runs: {cnt['run']} run, {cnt['cached']} cached, {running} running, {queued} queued  "
                 f"[{time.time() - self.t0:.0f} s]")

    def fun(self, u):
        self.submit(u)
        if not self.args.no_speculate:
            # the optimiser asks for the Jacobian at every point it accepts: queue its runs behind the point's own
            for v, _ in self.fd_points(u):
                self.submit(v)
        return self.residual(u, "eval")

    def jac(self, u):
        r0 = self.residual(u, "eval")
        cols = []
        pts = self.fd_points(u)
        for v, _ in pts:
            self.submit(v)
        for v, step in pts:
            cols.append((self.residual(v, "fd") - r0) / step)
        return np.column_stack(cols)

    def start(self):
        """The optimiser's first point, evaluated: a start whose every forward run failed is an error, whatever
        chose it (the optimiser would read the zero loads' flat misfit as converged)."""
        u0 = self.first_point()
        self.fun(u0)
        if all(rec["returncode"] for rec in self.evals[tuple(np.round(u0, 12))][1]):
            raise FitError(self.failed_line(u0))
        return u0

    def first_point(self):
        p = len(self.params)
        if self.args.start == "dao":
            return self.dao_start()
        if self.args.start != "sweep":
            try:
                x = [float(v) for v in self.args.start.split(",")]
            except ValueError:
                raise FitError(f"--start {self.args.start}: 'sweep' or {p} numbers") from None
            if len(x) != p:
                raise FitError(f"--start {self.args.start}: {len(x)} values for {p} parameters")
            for pp, v in zip(self.params, x):
                if not pp.low <= v <= pp.high:
                    raise FitError(f"--start: {pp.name} = {v:g} is outside its bounds [{pp.low:g}, {pp.high:g}]")
            return np.array([pp.scaled(v) for pp, v in zip(self.params, x)])
        from scipy.stats import qmc
        n = self.args.sweep_points or 2 * p + 2
        pts = [np.full(p, 0.5)] + list(qmc.LatinHypercube(d=p, seed=20070516).random(n))
        for u in pts:
            self.submit(u)
        res = [(misfit.rms(self.residual(u, "sweep"), self.w2), k) for k, u in enumerate(pts)]
        return pts[min(res)[1]]

    def dao_start(self):
        """E from the first curve's Oliver-Pharr modulus, yield from Dao's Pi_1 and the middle of n's bounds."""
        byname = {p.name.lower(): p for p in self.params}
        if "e" not in byname or "yield" not in byname or set(byname) - {"e", "yield", "n"}:
            raise FitError("--start dao needs parameters named E and yield (and n), and no others")
        c = self.curves[0]
        opt = byname["e"].options[0].rsplit("_", 1)[0]
        model = c.model_text + " " + " ".join(self.args.extra)
        nu = re.findall(rf"-{opt}_poisson\s+([0-9.eE+-]+)", model)
        kind = re.findall(r"-indenter_type\s+(\w+)", model)
        if not nu or not kind or kind[-1] not in ("cone", "berkovich"):
            raise FitError(f"--start dao: the first curve's model must give -{opt}_poisson and a cone or berkovich "
                           "-indenter_type")
        nu = float(nu[-1])
        b = c.branches
        csv_path = os.path.join(self.args.out, "dao-curve.csv")
        indentcurves.write_csv(csv_path, np.r_[b.load_h, b.unload_h], np.r_[b.load_p, b.unload_p])
        op = self.args.indent_op or os.path.join(os.path.dirname(self.args.indent), "indent-op")
        run = subprocess.run([op, "-op_file", csv_path, "-indenter_type", kind[-1], "-op_poisson", f"{nu}"],
                             capture_output=True, text=True)
        m = re.search(r"E_r ([0-9.eE+-]+) GPa", run.stdout)
        if run.returncode or not m:
            raise FitError(f"--start dao: indent-op could not analyse the first curve: {run.stderr.strip()}")
        e_star = float(m.group(1))
        C = dao.kick_constant(b.load_h, b.load_p, b.h_max) * 1e3  # uN/nm^2 = GPa / 1000
        sr = dao.sigma_r(C, e_star)
        if sr is None:
            raise FitError(f"--start dao: no sigma_0.033 gives C = {C:.4g} GPa with E* = {e_star:.4g} GPa in Dao's "
                           "Pi_1: use --start sweep")
        E = e_star * (1 - nu * nu)
        n = 0.5 * (byname["n"].low + byname["n"].high) if "n" in byname else 0.0
        values = {"e": E, "yield": dao.yield_from(sr, E, n), "n": n}
        self.say(f"fit: Dao's start from curve 1: E* {e_star:.4g} GPa (Oliver-Pharr), C {C:.4g} GPa, sigma_0.033 "
                 f"{sr:.4g} GPa; E {E:.4g} GPa, yield {values['yield']:.4g} GPa"
                 + (f" at n {n:.3g} (the middle of its bounds)" if "n" in byname else ""))
        return np.array([min(max(p.scaled(min(max(values[p.name.lower()], p.low), p.high)), 0.0), 1.0)
                         for p in self.params])

    def failed_line(self, u):
        rec = self.evals[tuple(np.round(u, 12))][1][0]
        last = ""
        try:
            with open(os.path.join(rec["dir"], runs.LOG)) as f:
                lines = [ln.strip() for ln in f if ln.strip()]
            last = lines[-1] if lines else ""
        except OSError:
            pass
        return f"every forward run of the start failed; the first said: {last} ({rec['dir']})"


def noise_sigma(args, fit):
    if args.noise == "residual":
        return None
    try:
        s = float(args.noise)
    except ValueError:
        raise FitError(f"--noise {args.noise}: 'residual' or a load in uN") from None
    if s <= 0:
        raise FitError(f"--noise {args.noise}: must be positive")
    parts = []
    for c in fit.curves:
        parts += [np.full(len(h), s * scale) for _, h, _, scale in misfit.fitted_branches(c.branches, *fit.w)]
        if c.imprint:
            if c.imprint.noise is None:
                raise FitError(f"--noise {args.noise} uN: give the height noise of {c.imprint.path} as well "
                               "(--imprint-noise NM before --imprint)")
            parts.append(np.full(len(c.imprint.z), c.imprint.noise * c.imprint.scale))
    return np.concatenate(parts)


def strict_json(value):
    """value with every non-finite float as None: JSON has no NaN or Infinity (an interval of a parameter the
    curves cannot determine, a singular Jacobian's condition), and strict readers (jq, JavaScript) refuse them."""
    if isinstance(value, dict):
        return {k: strict_json(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [strict_json(v) for v in value]
    if isinstance(value, (float, np.floating)):
        return float(value) if np.isfinite(value) else None
    return value


def write_outputs(args, fit, sol, res):
    out = args.out
    u = sol.x
    r, recs, sims = fit.evals[tuple(np.round(u, 12))]
    names = [p.name for p in fit.params]
    cnt = fit.runner.counts
    result = {
        "parameters": {p.name: {"value": float(v), "ci95": float(ci), "sd": float(sd), "options": p.options,
                                "bounds": [p.low, p.high], "log": p.log}
                       for p, v, ci, sd in zip(fit.params, res["values"], res["ci95"], res["sd"])},
        "correlation": {"names": names, "matrix": res["corr"].tolist()},
        "misfit_rms": misfit.rms(r, fit.w2), "evaluations": len(fit.history), "optimizer": sol.message,
        "condition": res["condition"], "weak_direction": res["weak_direction"].tolist(),
        "weak_spread": res["weak_spread"], "distinguishable": res["distinguishable"], "noise": res["noise"],
        "model_error": res["model_error"], "model_spread": res["model_spread"], "robust": res["robust"],
        "forward_runs": {"run": cnt["run"], "cached": cnt["cached"], "failed": cnt["failed"],
                         "seconds": cnt["seconds"]},
        "wall_seconds": time.time() - fit.t0,
        "curves": [{"file": c.path, "model": c.model, "h_max": c.branches.h_max, "p_max": c.branches.p_max,
                    "run": rec["dir"]} for c, rec in zip(fit.curves, recs)],
        "imprints": [],
    }
    imprint_lines, fitted = [], {}
    for c, rec in zip(fit.curves, recs):
        if not c.imprint:
            continue
        m = c.imprint
        fitted[c.index] = m.model_heights(fit.surface(rec))  # registered at the optimum: center_found() below
        path = os.path.join(out, f"imprint-{c.index + 1}.csv")
        m.write_fitted(path, fitted[c.index])
        rms_nm = float(np.sqrt(np.mean((fitted[c.index] - m.z) ** 2)))
        result["imprints"].append({"file": m.path, "curve": c.index + 1, "center_nm": m.center_found().tolist(),
                                   "registered": m.register,
                                   "rotation_deg": m.rotation, "radius_nm": m.radius, "ring_nm": list(m.ring),
                                   "pixels": len(m.z), "depth_nm": m.depth, "weight": m.weight, "rms_nm": rms_nm,
                                   "fitted": path})
        axis = m.center_found()
        imprint_lines.append(f"imprint of curve {c.index + 1}: {m.path}: {len(m.z)} pixels within {m.radius:.4g} nm of "
                             f"({m.center[0]:.4g}, {m.center[1]:.4g}) nm, leveled on the ring to {m.ring[1]:.4g} nm; "
                             f"the model's axis {'registered' if m.register else 'given'} at ({axis[0]:.4g}, "
                             f"{axis[1]:.4g}) nm; "
                             f"measured depth {m.depth:.4g} nm, RMS height difference {rms_nm:.3g} nm "
                             f"({100 * rms_nm / m.depth:.3g}% of it); measured and fitted in {path}")
    with open(os.path.join(out, "result.json"), "w") as f:
        json.dump(strict_json(result), f, indent=1, allow_nan=False)
    what = "load error / P_max" + (" and height error / imprint depth" if result["imprints"] else "")
    lines = [f"indent-fit: {len(fit.curves)} curve(s), {len(result['imprints'])} imprint(s), {len(fit.params)} "
             f"parameter(s); {sol.message}", f"misfit (weighted RMS {what}): {100 * result['misfit_rms']:.4g}%", "",
             f"{'parameter':12s} {'value':>12s} {'95% interval':>14s}   bounds"]
    for p, v, ci in zip(fit.params, res["values"], res["ci95"]):
        lines.append(f"{p.name:12s} {v:12.6g} {'+/- ' + format(ci, '.3g'):>14s}   [{p.low:g}, {p.high:g}]"
                     f"{' log' if p.log else ''}  (-{', -'.join(p.options)})")
    lines += ["", f"intervals from the Jacobian at the optimum and {res['noise']} (t = {res['t']:.3f}, "
                  f"{res['dof']} degrees of freedom)", "correlation:"]
    for i, n in enumerate(names):
        lines.append(f"  {n:10s} " + " ".join(f"{res['corr'][i, j]:+7.3f}" for j in range(len(names))))
    lines += [""] + stats.verdict_lines(res, fit.params, bool(result["imprints"])) + [""]
    lines.append(f"forward runs: {cnt['run']} run in {cnt['seconds']:.0f} s of run time ({cnt['failed']} failed), "
                 f"{cnt['cached']} taken from {os.path.join(out, 'runs')}; {len(fit.history)} evaluations; "
                 f"wall {result['wall_seconds']:.0f} s")
    for c, rec, sim in zip(fit.curves, recs, sims):
        path = os.path.join(out, f"curve-{c.index + 1}.csv")
        if sim is not None:
            misfit.write_fitted(path, c.branches, sim)
            lines.append(f"curve {c.index + 1}: {c.path} (model {c.model}): measured and fitted in {path}")
    lines += imprint_lines
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "report.txt"), "w") as f:
        f.write(text)
    with open(os.path.join(out, "history.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["evaluation", "kind", "misfit"] + names)
        w.writerows(fit.history)
    print(text, end="")
    if not args.no_plots:
        plots(args, fit, sims, fitted)


def plots(args, fit, sims, fitted):
    """fit.png, misfit.png, and imprint-K.png for each curve K whose imprint's model heights are in fitted."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    for k, (c, sim) in enumerate(zip(fit.curves, sims)):
        b, color = c.branches, f"C{k}"
        label = f"{os.path.basename(c.path)} ({os.path.basename(c.model)})"
        ax.plot(np.r_[b.load_h, b.unload_h], np.r_[b.load_p, b.unload_p], ".", ms=4, color=color,
                label=f"measured: {label}")
        if sim is not None:
            # drawn as the fit reads it: interpolated between the load steps as the residuals are
            lh = np.linspace(0.0, sim.h_max, 200)
            uh = np.linspace(sim.h_max, sim.unload_h.min(), 100)
            ax.plot(np.r_[lh, uh], np.r_[misfit.simulated_load(sim, lh, "loading"),
                                         misfit.simulated_load(sim, uh, "unloading")], "-", color=color,
                    label="fitted")
    ax.set_xlabel("depth (nm)")
    ax.set_ylabel("load (uN)")
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "fit.png"), dpi=120)
    plt.close(fig)
    for c in fit.curves:
        if c.index not in fitted:
            continue
        m = c.imprint
        fig, ax = plt.subplots(figsize=(6.4, 4.0))
        r = np.hypot(m.x, m.y)
        ax.plot(r, m.z, ".", ms=2, color="C0", label=f"measured: {os.path.basename(m.path)}")
        ax.plot(r, fitted[c.index], ".", ms=2, color="C1", label="fitted")
        ax.set_xlabel("distance from the axis (nm)")
        ax.set_ylabel("height (nm)")
        ax.legend(fontsize="small", markerscale=4)
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, f"imprint-{c.index + 1}.png"), dpi=120)
        plt.close(fig)
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    h = fit.history
    ax.semilogy([e[0] for e in h], [100 * e[2] for e in h], "o-", ms=3)
    ax.set_xlabel("evaluation")
    ax.set_ylabel("misfit (% of P_max)")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "misfit.png"), dpi=120)
    plt.close(fig)


def main(argv):
    from scipy.optimize import least_squares
    args = parse_args(argv)
    try:
        prm = [fparams.parse(t) for t in args.param]
        fparams.check_unique(prm)
        if not (os.path.isfile(args.indent) and os.access(args.indent, os.X_OK)):
            raise FitError(f"--indent {args.indent}: not an executable file")
        if args.jobs < 0 or args.np < 1 or not 0 < args.fd_step < 0.5 or args.points < 3:
            raise FitError("--jobs >= 0, --np >= 1, 0 < --fd-step < 0.5 and --points >= 3 are needed")
        curves = load_curves(args)
        os.makedirs(args.out, exist_ok=True)
        fit = Fit(args, curves, prm)
        sigma = noise_sigma(args, fit)
    except (FitError, fparams.ParamError, indentcurves.CurveError, OSError) as e:
        print(f"indent-fit: error: {e}", file=sys.stderr)
        return 1
    with open(os.path.join(args.out, "fit.json"), "w") as f:
        json.dump({"argv": argv, "cwd": os.getcwd()}, f, indent=1)
    stopped = []

    def handle(sig, frame):
        stopped.append(signal.Signals(sig).name)
        fit.runner.stop()
    for s in (signal.SIGTERM, signal.SIGINT):
        signal.signal(s, handle)
    fit.say(f"fit: {len(curves)} curve(s), {len(prm)} parameter(s), forward runs in {os.path.join(args.out, 'runs')}"
            f" ({fit.runner.pool._max_workers} at once, {args.np} rank(s) each)")
    try:
        u0 = fit.start()
        sol = least_squares(fit.fun, u0, jac=fit.jac, bounds=(0.0, 1.0), method=args.method, x_scale=1.0,
                            ftol=args.tol, xtol=args.tol, gtol=1e-10, max_nfev=args.max_evals)
        J = fit.jac(sol.x)
        res = stats.analyse(J, fit.residual(sol.x), prm, sol.x, sigma, args.spread_limit, args.model_error,
                            fit.w2, fit.groups())
    except FitError as e:
        fit.runner.shutdown()
        print(f"indent-fit: error: {e}", file=sys.stderr)
        return 3
    except (runs.Stopped, Exception) as e:
        if not stopped:
            fit.runner.shutdown()
            raise
        fit.runner.shutdown()
        cnt = fit.runner.counts
        print(f"indent-fit: stopped by {stopped[0]}: {cnt['run']} forward runs finished in this call are kept "
              f"in {os.path.join(args.out, 'runs')}; run the same command to continue", file=sys.stderr)
        return EX_STOPPED
    fit.runner.shutdown()
    write_outputs(args, fit, sol, res)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
