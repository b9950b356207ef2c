"""Curves as loading and unloading branches, and the residuals between a measured and a simulated curve.

A residual is the simulated load minus the measured one at a measured depth, as a fraction of the measured
P_max, over the square root of the branch's point count and times the branch's weight: each branch weighs
by its weight whatever its sampling, and sqrt(sum r^2 / sum w^2) is the weighted RMS load error as a
fraction of P_max.
"""
import numpy as np

import runfiles


class Branches:
    """depth (nm) and load (uN) of a curve's loading and unloading, with its P_max and h_max."""

    def __init__(self, load_h, load_p, unload_h, unload_p, name=""):
        self.load_h, self.load_p = np.asarray(load_h, float), np.asarray(load_p, float)
        self.unload_h, self.unload_p = np.asarray(unload_h, float), np.asarray(unload_p, float)
        self.name = name
        self.p_max = float(max(self.load_p.max(initial=0.0), self.unload_p.max(initial=0.0)))
        self.h_max = float(self.unload_h[0]) if len(self.unload_h) else float(self.load_h.max())


def _thin(h, p, points, keep_first=False):
    """At most `points` points of a branch, evenly spread in depth (the nearest measured point to each), and its
    first point with keep_first."""
    if len(h) <= points:
        return h, p
    idx = {int(np.argmin(np.abs(h - t))) for t in np.linspace(h.min(), h.max(), points)}
    idx = sorted(idx | ({0} if keep_first else set()))
    return h[idx], p[idx]


def measured_branches(curve, points=40, name=""):
    """The branches of a curve read by scripts/indentcurves.py: the loading segment from first contact (load and
    depth above zero) and the unloading segment, each thinned to `points` points. The hold is not fitted: the
    model has no creep; h_max is the depth at the start of the unloading, after the hold."""
    seg = {kind: (a, b) for kind, a, b in curve["segments"]}
    h, p = curve["depth"], curve["load"]
    la, lb = seg.get("loading", (0, 0))
    ua, ub = seg["unloading"]
    lk = [i for i in range(la, lb + 1) if p[i] > 0 and h[i] > 0]
    uk = [i for i in range(ua, ub + 1) if p[i] > 0]
    lh, lp = _thin(h[lk], p[lk], points)
    uh, up = _thin(h[uk], p[uk], points, keep_first=True)
    if len(lh) < 3 or len(uh) < 3:
        raise ValueError(f"{name or curve.get('path')}: fewer than 3 points on the loading or the unloading")
    return Branches(lh, lp, uh, up, name)


def read_indent_curve(path):
    """indent's load_displacement.csv -> Branches (the loading from the origin up to the deepest step, then the
    unloading)."""
    c = runfiles.read_curve(path)
    depth, load = np.r_[0.0, c["depth_nm"]], np.r_[0.0, c["load_uN"]]
    top = int(np.argmax(depth))
    return Branches(depth[:top + 1], load[:top + 1], depth[top:], load[top:])


def simulated_load(sim, h, branch):
    """The simulated load at depths h on its loading or unloading branch. Past the end of the unloading the
    load is zero when the simulated unloading ended at zero load (the indenter has left the surface), and
    the last load otherwise."""
    if branch == "loading":
        # sqrt(P) is linear in h for a sharp tip (Kick's law) and nearly so for a sphere: interpolating it
        # instead of P keeps coarse load steps from biasing the fit (linearly, P is off by (dh / h)^2 / 4)
        return np.interp(h, sim.load_h, np.sqrt(np.maximum(sim.load_p, 0.0))) ** 2
    # an unloading curve is close to P ~ (h - h_f)^1.5 (Oliver-Pharr's m = 1.2 to 1.6): P^(2/3) is nearly linear
    # in h, so interpolating it keeps the coarse unloading steps from biasing the stiffness, and with it E
    uh, up = sim.unload_h[::-1], np.maximum(sim.unload_p[::-1], 0.0) ** (2.0 / 3.0)
    below = 0.0 if up[0] <= 1e-9 * max(sim.p_max, 1e-300) else up[0]
    return np.interp(h, uh, up, left=below) ** 1.5


def fitted_branches(meas, w_load=1.0, w_unload=1.0):
    """(branch, depths, loads, scale) of each fitted branch: a load difference times scale is its residual."""
    return [(branch, h, p, w / (meas.p_max * np.sqrt(len(p))))
            for branch, h, p, w in (("loading", meas.load_h, meas.load_p, w_load),
                                    ("unloading", meas.unload_h, meas.unload_p, w_unload)) if w != 0]


def residuals(meas, sim, w_load=1.0, w_unload=1.0):
    """The residual vector of one curve (loading then unloading); sim None (a failed run) gives the
    residuals of a zero load, the largest misfit a curve can have within reason."""
    return np.concatenate([scale * ((np.zeros_like(p) if sim is None else simulated_load(sim, h, branch)) - p)
                           for branch, h, p, scale in fitted_branches(meas, w_load, w_unload)])


def rms(r, weights_squared):
    """The weighted RMS load error as a fraction of P_max, from the whole residual vector."""
    return float(np.sqrt(np.dot(r, r) / weights_squared))


def write_fitted(path, meas, sim):
    """The measured branches beside the fitted curve's load at the same depths."""
    with open(path, "w") as f:
        f.write("branch,depth_nm,measured_load_uN,fitted_load_uN\n")
        for branch, h, p in (("loading", meas.load_h, meas.load_p), ("unloading", meas.unload_h, meas.unload_p)):
            fit = simulated_load(sim, h, branch)
            for a, b, c in zip(h, p, fit):
                f.write(f"{branch},{a:.10g},{b:.10g},{c:.10g}\n")
