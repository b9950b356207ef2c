"""A start for a sharp-tip fit from Dao et al.'s reverse analysis (Acta Mater. 49 (2001) 3899), the parts of it
that hold for indent's model:

  E* from the unloading (Oliver-Pharr, indent-op: E* = E_r, the indenter rigid in the model);
  Kick's constant C from the loading, P = C h^2 (least squares over h >= 20% of h_max, above the tip's rounding);
  sigma_0.033 from Dao's Pi_1, C / sigma_0.033 = -1.131 L^3 + 13.635 L^2 - 30.594 L + 29.267 with
      L = ln(E* / sigma_0.033), for a 70.3 deg cone (or a Berkovich) with friction 0.15. It gives Dao's
      C = 25.8 GPa for E 70 GPa, nu 0.3, yield 0.3 GPa, the case indent's kick_cone_finite_dao_np2 checks
      (25.36 GPa);
  sigma_y from sigma_0.033 = sigma_y (1 + E 0.033 / sigma_y)^n, Dao's power law, for a guessed n.

Dao's Pi_2 (n from the unloading slope) is not used: its coefficients could not be checked here, and the
curves rarely fix n well (doc/inverse.md). So n starts in the middle of its bounds, on the valley of
materials whose sigma_0.033 is the measured one, which the fit then follows.
"""
import math

import numpy as np

EPS_R = 0.033
PI1 = (-1.131, 13.635, -30.594, 29.267)


def pi1(ratio):
    """Dao's Pi_1(E* / sigma_0.033) = C / sigma_0.033."""
    L = math.log(ratio)
    a, b, c, d = PI1
    return ((a * L + b) * L + c) * L + d


def kick_constant(h, p, h_max):
    """C of P = C h^2, least squares over the loading points deeper than 20% of h_max."""
    keep = h >= 0.2 * h_max
    if keep.sum() < 2:
        raise ValueError("fewer than 2 loading points deeper than 20% of h_max for Kick's constant")
    x = h[keep] ** 2
    return float(np.dot(x, p[keep]) / np.dot(x, x))


def sigma_r(C, E_star):
    """sigma_0.033 with C / sigma = Pi_1(E* / sigma): the root in Dao's range of E* / sigma_0.033 (about 3 to
    1300), by bisection on a log grid. None when there is none (a curve Dao's function cannot have made)."""
    ratios = np.exp(np.linspace(math.log(3.0), math.log(1300.0), 400))
    f = np.array([C / (E_star / r) - pi1(r) for r in ratios])
    sign = np.nonzero(np.sign(f[:-1]) != np.sign(f[1:]))[0]
    if not len(sign):
        return None
    lo, hi = ratios[sign[0]], ratios[sign[0] + 1]
    g = lambda r: C / (E_star / r) - pi1(r)  # noqa: E731
    for _ in range(100):
        mid = math.sqrt(lo * hi)
        if np.sign(g(mid)) == np.sign(g(lo)):
            lo = mid
        else:
            hi = mid
    return E_star / math.sqrt(lo * hi)


def yield_from(sig_r, E, n):
    """sigma_y with sigma_y (1 + E eps_r / sigma_y)^n = sigma_r (bisection: the left side rises with sigma_y)."""
    if n == 0:
        return sig_r
    lo, hi = 1e-9 * sig_r, sig_r
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        if mid * (1 + E * EPS_R / mid) ** n < sig_r:
            lo = mid
        else:
            hi = mid
    return math.sqrt(lo * hi)
