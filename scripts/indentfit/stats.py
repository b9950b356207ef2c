"""What a fit's optimum can say: the parameters' 95% confidence intervals and correlations from the Jacobian
at the optimum and the noise, and whether the curves can tell the parameters apart at all.

The residuals are r(u) in scaled coordinates u (params.py). Near the optimum r(u + du) ~ r + J du; the fit
minimises r.r, so with independent residual noise of standard deviation s_i the covariance of u is the
sandwich A J^T S J A, A = (J^T J)^-1 and S = diag(s_i^2) (Gauss-Newton; s^2 A when every s_i is s), and that
of the parameters D cov_u D with D = diag(dx/du). s_i is the measured noise carried into residual units when
it is given, and otherwise the residuals' own scatter, sqrt(r.r / (m - p)), taken group by group: each
curve's residuals and each imprint's have a scatter of their own (a map's thousands of pixels and a curve's
dozens of points are scaled so that each term weighs as its weight, not as its count), and the scatter also
holds what the model cannot fit.

The data cannot tell the parameters apart when some combination of them can move far within the bounds
and change the curves by less than the noise: the eigenvector of cov_u's largest eigenvalue lambda is that
combination (with one s, the right singular vector of J's smallest singular value sigma_min, lambda =
s^2 / sigma_min^2), and t sqrt(lambda) is how far (in u, fractions of the bounds' ranges) it may move inside
the 95% interval. Chen et al. (J. Mech. Phys. Solids 55 (2007) 1618) built such
"mystical" materials, whose Berkovich curves coincide.

The noise is not the only error: the model's own (its mesh, its load steps) is a load error of its own,
smooth along the curve, which no count of points averages away. A load error of e (RMS fraction of P_max)
is a residual vector of norm e sqrt(w2), w2 the sum of the branches' squared weights, and it can move the
weakest combination by e sqrt(w2) / sigma_min(J): when that is more than the spread limit, the values owe as
much to the model's error as to the material.
"""
import numpy as np
from scipy import stats as spstats


def scatter(r, groups, p):
    """The residuals' own noise per residual: each group's sqrt(sum r^2 / (its share of the m - p degrees of
    freedom))."""
    m = len(r)
    sigma = np.empty(m)
    for g in groups:
        share = len(g) * max(m - p, 1) / m
        sigma[g] = np.sqrt(np.dot(r[g], r[g]) / share)
    return sigma


def analyse(J, r, params, u, noise_sigma=None, spread_limit=0.05, model_error=0.0, w2=1.0, groups=None):
    """J: m x p Jacobian in u; r: residuals at the optimum; noise_sigma: residual-unit noise per residual
    (array of m) or None for the residuals' own scatter in each of groups (index arrays; default one group);
    model_error: the model's own load error (RMS fraction of P_max) and w2 the sum of the fitted branches'
    squared weights. Returns a dict (see the keys at the end)."""
    m, p = J.shape
    dof = max(m - p, 1)
    if noise_sigma is None:
        groups = [np.arange(m)] if groups is None else groups
        sigma = scatter(r, groups, p)
        noise = "the residuals' scatter" + (" (each curve's and each imprint's)" if len(groups) > 1 else "")
    else:
        sigma = np.asarray(noise_sigma, float)
        noise = "the measured noise"
    t = float(spstats.t.ppf(0.975, dof))
    _, sv, Vt = np.linalg.svd(J, full_matrices=False)
    tiny = sv.max() * 1e-12 if sv.max() > 0 else 1.0
    inv = np.where(sv > tiny, 1.0 / np.maximum(sv, tiny), np.inf)
    with np.errstate(invalid="ignore"):
        A = (Vt.T * inv**2) @ Vt            # (J^T J)^-1
        B = (J * sigma[:, None]).T @ (J * sigma[:, None])
        cov_u = A @ B @ A
    if not np.all(np.isfinite(cov_u)):
        lam, weak = np.inf, Vt[-1]
    else:
        w, V = np.linalg.eigh(0.5 * (cov_u + cov_u.T))
        lam, weak = max(float(w[-1]), 0.0), V[:, -1]
    D = np.array([pp.dvalue_du(uu) for pp, uu in zip(params, u)])
    cov = cov_u * np.outer(D, D)
    sd = np.sqrt(np.abs(np.diag(cov)))
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(sd, sd)
    x = np.array([pp.value(uu) for pp, uu in zip(params, u)])
    weak = weak * np.sign(weak[np.argmax(np.abs(weak))])
    spread = float(t * np.sqrt(lam))
    at_bound = [pp.name for pp, uu in zip(params, u) if uu <= 1e-6 or uu >= 1 - 1e-6]
    smin, Vm = sv[-1], Vt[-1]
    model_weak = Vm * np.sign(Vm[np.argmax(np.abs(Vm))])
    model_spread = float(model_error * np.sqrt(w2) / smin) if smin > 0 else float("inf")
    return {
        "values": x, "sd": sd, "ci95": t * sd, "corr": corr, "cov": cov, "t": t, "dof": dof, "noise": noise,
        "singular_values": sv, "condition": float(sv[0] / sv[-1]) if sv[-1] > 0 else float("inf"),
        "weak_direction": weak, "weak_spread": spread,
        "distinguishable": bool(spread <= spread_limit), "spread_limit": spread_limit, "at_bound": at_bound,
        "model_error": model_error, "model_spread": model_spread, "model_weak_direction": model_weak,
        "robust": bool(model_spread <= spread_limit),
    }


def verdict_lines(res, params, with_imprint=False):
    """Plain sentences on what the data can and cannot tell (with_imprint: an imprint is fitted already)."""
    lines = []
    if res["at_bound"]:
        lines.append("at a bound: " + ", ".join(res["at_bound"]) + " (widen the bounds: the interval there means "
                     "little)")
    if res["distinguishable"]:
        lines.append(f"the curves determine every parameter: no combination moves more than "
                     f"{100 * res['weak_spread']:.2g}% of the bounds' ranges within the 95% interval "
                     f"(limit {100 * res['spread_limit']:.2g}%)")
        if res["robust"]:
            if res["model_error"] > 0:
                lines.append(f"  and a load error of {100 * res['model_error']:.2g}% of P_max from the model itself "
                             f"moves none more than {100 * res['model_spread']:.2g}% of them")
            return lines
        parts = [f"{'+' if c >= 0 else '-'}{abs(c):.2f} {p.name}" for p, c in zip(params, res["model_weak_direction"])
                 if abs(c) >= 0.05]
        far = "without limit" if not np.isfinite(res["model_spread"]) else \
            f"{100 * res['model_spread']:.3g}% of the bounds' ranges"
        lines.append(f"WARNING: but not against the model's own error: a load error of {100 * res['model_error']:.2g}% "
                     f"of P_max (a mesh or load-step error of that size; --model-error) would move the combination "
                     f"({' '.join(parts)}) {far}, more than the limit of {100 * res['spread_limit']:.2g}%. Trust "
                     f"these values only as far as the model's mesh and load steps are converged "
                     f"(doc/load-steps.md), or make the curves tell them apart better.")
        lines += _resolve(res, params, with_imprint)
        return lines
    parts = [f"{'+' if c >= 0 else '-'}{abs(c):.2f} {p.name}" for p, c in zip(params, res["weak_direction"])
             if abs(c) >= 0.05]
    far = "without limit" if not np.isfinite(res["weak_spread"]) else f"{100 * res['weak_spread']:.3g}% of their " \
        "bounds' ranges"
    lines.append("WARNING: the curves cannot tell the parameters apart. Along the combination "
                 f"({' '.join(parts)}) of scaled parameters they may move {far} "
                 "and stay within the noise: different materials give these same curves "
                 "(the 'mystical materials' of Chen et al., J. Mech. Phys. Solids 55 (2007) 1618).")
    return lines + _resolve(res, params, with_imprint)


def _resolve(res, params, with_imprint):
    """The correlated pairs, and what would tell them apart."""
    lines = []
    pairs = [(params[i].name, params[j].name, res["corr"][i, j]) for i in range(len(params))
             for j in range(i + 1, len(params)) if abs(res["corr"][i, j]) >= 0.9]
    if pairs:
        lines.append("  correlated: " + ", ".join(f"{a} and {b} ({c:+.3f})" for a, b, c in pairs))
    imprint = "" if with_imprint else "the imprint's pile-up (--imprint), "
    lines.append("  What would resolve it: a curve from a second indenter of another shape (a sphere, or a cone "
                 f"of another angle) fitted together with this one, {imprint}or a parameter "
                 "fixed from another test (e.g. E from an unloading slope or a tensile test).")
    return lines
