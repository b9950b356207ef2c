#!/usr/bin/env python3
"""Unit tests of scripts/indentfit (the inverse fit's decisions) on small closed-form cases."""
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "scripts"))
from indentfit import dao, misfit, params, runs, stats  # noqa: E402


class Params(unittest.TestCase):
    def test_parse_and_scale(self):
        p = params.parse("yield=film_yield,substrate_yield:0.05:2:log")
        self.assertEqual(p.options, ["film_yield", "substrate_yield"])
        for x in (0.05, 0.3, 2.0):
            self.assertAlmostEqual(p.value(p.scaled(x)), x, places=12)
        self.assertAlmostEqual(p.value(0.5), np.sqrt(0.05 * 2), places=12)
        self.assertEqual(p.indent_options(0.3), ["-film_yield", "0.3", "-substrate_yield", "0.3"])
        q = params.parse("E=film_young:40:120")
        self.assertAlmostEqual(q.value(0.25), 60.0)
        self.assertAlmostEqual(q.dvalue_du(0.7), 80.0)
        u, h = 0.3, 1e-6
        self.assertAlmostEqual(p.dvalue_du(u), (p.value(u + h) - p.value(u - h)) / (2 * h), places=5)

    def test_bad(self):
        for text in ("E", "E=film_young:40", "E=film_young:120:40", "E=film_young:a:b", "E=:1:2",
                     "s=film_yield:0:1:log", "s=film_yield:0.1:1:lin"):
            with self.assertRaises(params.ParamError, msg=text):
                params.parse(text)
        with self.assertRaises(params.ParamError):
            params.check_unique([params.parse("a=x:0:1"), params.parse("b=y,x:0:1")])


def kick(c, h):
    return c * h * h


class Misfit(unittest.TestCase):
    def setUp(self):
        h = np.linspace(0, 60, 13)
        uh = np.array([60, 59, 58, 57, 56, 55])
        up = 100 * ((uh - 55) / 5.0) ** 1.5
        self.sim = misfit.Branches(h, kick(0.04, h), uh, up)

    def test_interpolation_exact_on_power_laws(self):
        # sqrt(P) is interpolated on the loading and P^(2/3) on the unloading: exact for P = C h^2 and
        # P ~ (h - h_f)^1.5 between the simulated steps
        h = np.array([2.5, 17.3, 59.9])
        np.testing.assert_allclose(misfit.simulated_load(self.sim, h, "loading"), kick(0.04, h), rtol=1e-12)
        uh = np.array([59.5, 57.25, 55.5, 54.0])
        want = 100 * (np.maximum(uh - 55, 0) / 5.0) ** 1.5
        np.testing.assert_allclose(misfit.simulated_load(self.sim, uh, "unloading"), want, rtol=1e-12, atol=1e-12)

    def test_residuals(self):
        lh = np.linspace(5, 60, 12)
        meas = misfit.Branches(lh, kick(0.04, lh), [60, 58, 56], 100 * ((np.array([60, 58, 56]) - 55) / 5.0) ** 1.5)
        r = misfit.residuals(meas, self.sim)
        self.assertLess(np.abs(r).max(), 1e-12)
        # a simulated curve 2% stiffer everywhere: RMS 2% of the load over P_max on each branch
        sim = misfit.Branches(self.sim.load_h, 1.02 * self.sim.load_p, self.sim.unload_h, 1.02 * self.sim.unload_p)
        r = misfit.residuals(meas, sim, 1.0, 0.0)
        want = 0.02 * np.sqrt(np.mean(meas.load_p ** 2)) / meas.p_max
        self.assertAlmostEqual(misfit.rms(r, 1.0), want, places=12)
        # a failed run: the residuals of a zero load
        r = misfit.residuals(meas, None, 1.0, 0.0)
        self.assertAlmostEqual(misfit.rms(r, 1.0), np.sqrt(np.mean(meas.load_p ** 2)) / meas.p_max, places=12)


class Stats(unittest.TestCase):
    def test_linear_regression_interval(self):
        # y = a + b x with noise: the interval must be the textbook one, t s sqrt((X^T X)^-1)
        rng = np.random.default_rng(3)
        x = np.linspace(0, 1, 30)
        y = 1 + 2 * x + 0.01 * rng.standard_normal(30)
        X = np.column_stack([np.ones_like(x), x])
        beta, *_ = np.linalg.lstsq(X, y, rcond=None)
        r = X @ beta - y
        pa, pb = params.parse("a=oa:0:10"), params.parse("b=ob:-5:5")
        u = [pa.scaled(beta[0]), pb.scaled(beta[1])]
        J = X * np.array([pa.dvalue_du(u[0]), pb.dvalue_du(u[1])])
        res = stats.analyse(J, r, [pa, pb], u)
        s2 = r @ r / 28
        from scipy import stats as sp
        want = sp.t.ppf(0.975, 28) * np.sqrt(np.diag(s2 * np.linalg.inv(X.T @ X)))
        np.testing.assert_allclose(res["ci95"], want, rtol=1e-10)
        np.testing.assert_allclose(res["values"], beta, rtol=1e-12)
        self.assertTrue(res["distinguishable"])

    def test_indistinguishable(self):
        # two parameters that enter only as their sum: the verdict must say so and name both
        rng = np.random.default_rng(4)
        c = rng.uniform(0.5, 1.5, 20)
        J = np.column_stack([c, c + 1e-3 * rng.standard_normal(20)])
        r = 0.01 * rng.standard_normal(20)
        p = [params.parse("a=oa:0:1"), params.parse("b=ob:0:1")]
        res = stats.analyse(J, r, p, [0.5, 0.5])
        self.assertFalse(res["distinguishable"])
        text = "\n".join(stats.verdict_lines(res, p))
        self.assertIn("cannot tell", text)
        self.assertIn("a and b", text)
        self.assertIn("second indenter", text)
        # exactly proportional columns: no finite interval, and still one plain warning
        res = stats.analyse(np.column_stack([c, 2 * c]), r, p, [0.5, 0.5])
        self.assertFalse(res["distinguishable"])
        self.assertIn("without limit", "\n".join(stats.verdict_lines(res, p)))


    def test_model_error(self):
        # Two nearly collinear columns and little noise: the noise determines both, but a load error of the
        # model's own of 0.5% moves their weak combination by model_error sqrt(w2) / sigma_min, which the
        # verdict must call out; well separated columns pass both tests.
        rng = np.random.default_rng(5)
        c = rng.uniform(0.5, 1.5, 200)
        p = [params.parse("a=oa:0:1"), params.parse("b=ob:0:1")]
        r = 1e-4 * rng.standard_normal(200)
        # columns as the fit scales them: a load difference over P_max over the root of the point count
        J = np.column_stack([c, c + 0.05 * rng.standard_normal(200)]) / np.sqrt(200)
        res = stats.analyse(J, r, p, [0.5, 0.5], model_error=0.005, w2=2.0)
        want = 0.005 * np.sqrt(2.0) / np.linalg.svd(J, compute_uv=False)[-1]
        self.assertAlmostEqual(res["model_spread"], want, delta=1e-12 * want)
        self.assertTrue(res["distinguishable"])
        self.assertFalse(res["robust"])
        text = "\n".join(stats.verdict_lines(res, p))
        self.assertIn("not against the model's own error", text)
        self.assertIn("second indenter", text)
        J = np.column_stack([c, rng.uniform(-1, 1, 200)]) / np.sqrt(200)
        res = stats.analyse(J, r, p, [0.5, 0.5], model_error=0.005, w2=2.0)
        self.assertTrue(res["distinguishable"] and res["robust"])
        self.assertIn("from the model itself moves none more", "\n".join(stats.verdict_lines(res, p)))
        # model_error 0: not checked
        self.assertTrue(stats.analyse(np.column_stack([c, c + 1e-3 * c]), r, p, [0.5, 0.5])["robust"])


class Dao(unittest.TestCase):
    def test_pi1_gives_daos_kick_constant(self):
        # Dao et al.'s own example of elastic-perfectly plastic aluminium: E 70 GPa, nu 0.3, yield 0.3 GPa,
        # C = 25.8 GPa (the value kick_cone_finite_dao_np2 checks indent against)
        e_star = 70 / (1 - 0.3 ** 2)
        self.assertAlmostEqual(0.3 * dao.pi1(e_star / 0.3), 25.8, delta=0.05)
        self.assertAlmostEqual(dao.sigma_r(0.3 * dao.pi1(e_star / 0.3), e_star), 0.3, places=9)
        self.assertIsNone(dao.sigma_r(1e-6, e_star))

    def test_yield_from_representative_stress(self):
        for sy, n in ((0.25, 0.2), (0.1, 0.45), (1.0, 0.0)):
            sr = sy * (1 + 70 * dao.EPS_R / sy) ** n
            self.assertAlmostEqual(dao.yield_from(sr, 70, n), sy, places=9)

    def test_kick_constant(self):
        h = np.linspace(1, 60, 30)
        p = 0.0258 * h ** 2
        p[h < 0.2 * 60] *= 3  # the tip's rounding: left out
        self.assertAlmostEqual(dao.kick_constant(h, p, 60.0), 0.0258, places=12)


class Cache(unittest.TestCase):
    def test_key(self):
        k = runs.run_key("-a 1\n", ["-x", "1"])
        self.assertEqual(k, runs.run_key("-a 1\n", ["-x", "1"]))
        self.assertNotEqual(k, runs.run_key("-a 2\n", ["-x", "1"]))
        self.assertNotEqual(k, runs.run_key("-a 1\n", ["-x", "1.0"]))
        self.assertNotEqual(runs.run_key("", ["-x", "1", "-y"]), runs.run_key("", ["-x", "1 -y"]))


if __name__ == "__main__":
    unittest.main(verbosity=1)
