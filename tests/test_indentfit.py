#!/usr/bin/env python3
"""Unit tests of scripts/indentfit (the inverse fit's decisions) on small closed-form cases."""
import os
import shutil
import sys
import tempfile
import unittest
import unittest.mock

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "scripts"))
import heightmap  # noqa: E402
from indentfit import dao, imprint, misfit, params, runs, stats  # noqa: E402


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

    def test_groups_of_other_noise(self):
        # a straight line measured twice: 20 points on [0, 1] with noise 1 and 2000 on [0, 0.01] with noise 0.01 (a
        # curve, and an imprint that tells the intercept only, in residual units). The spread of the least-squares
        # estimates over 400 draws is what the intervals must give (measured: within 7%); one pooled scatter
        # (groups=None) puts the slope's 10 times too small.
        rng = np.random.default_rng(5)
        x = np.r_[np.linspace(0, 1, 20), np.linspace(0, 0.01, 2000)]
        sig = np.r_[np.full(20, 1.0), np.full(2000, 0.01)]
        X = np.column_stack([np.ones_like(x), x])
        groups = [np.arange(20), np.arange(20, 2020)]
        pa, pb = params.parse("a=oa:-10:10"), params.parse("b=ob:-10:10")
        est, sd_grouped, sd_pooled = [], [], []
        for k in range(400):
            y = 1 + 2 * x + sig * rng.standard_normal(len(x))
            beta = np.linalg.lstsq(X, y, rcond=None)[0]
            est.append(beta)
            if k < 20:
                u = [pa.scaled(beta[0]), pb.scaled(beta[1])]
                J = X * np.array([pa.dvalue_du(u[0]), pb.dvalue_du(u[1])])
                sd_grouped.append(stats.analyse(J, X @ beta - y, [pa, pb], u, groups=groups)["sd"])
                sd_pooled.append(stats.analyse(J, X @ beta - y, [pa, pb], u)["sd"])
        spread = np.std(est, axis=0)
        np.testing.assert_allclose(np.median(sd_grouped, axis=0), spread, rtol=0.15)
        self.assertLess(np.median(sd_pooled, axis=0)[1], 0.2 * spread[1])  # the slope, which the 20 points tell

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


    def test_runs_at_once_not_bound_to_one_core(self):
        """Two 1-rank runs at once through mpiexec: each may use every core this test may (Open MPI bound both to
        core 0, and each took twice as long)."""
        cores = len(os.sched_getaffinity(0))
        mpiexec = shutil.which("mpiexec")
        if cores < 2 or not mpiexec:
            self.skipTest("needs mpiexec and two cores")
        with tempfile.TemporaryDirectory() as d:
            fake = os.path.join(d, "indent")   # writes the cores it may run on into its -output_dir
            with open(fake, "w") as f:
                f.write(f"#!{sys.executable}\nimport os, sys\nout = sys.argv[sys.argv.index('-output_dir') + 1]\n"
                        "open(os.path.join(out, 'cores'), 'w').write(str(len(os.sched_getaffinity(0))))\n")
            os.chmod(fake, 0o755)
            model = os.path.join(d, "model.opts")
            with open(model, "w") as f:
                f.write("-x 1\n")
            runner = runs.Runner(os.path.join(d, "runs"), fake, f"{mpiexec} -n {{np}}", 1, 2, log=lambda s: None)
            env = {k: v for k, v in os.environ.items() if k != "OMPI_MCA_hwloc_base_binding_policy"}
            with unittest.mock.patch.dict(os.environ, env, clear=True):   # as if mpi-env.sh had not set it
                recs = [f.result() for f in [runner.submit(model, "-x 1\n", ["-y", str(k)]) for k in range(2)]]
            runner.shutdown()
            for rec in recs:
                self.assertEqual(rec["returncode"], 0)
                with open(os.path.join(rec["dir"], "cores")) as f:
                    self.assertEqual(int(f.read()), cores)


def bowl(x, y, depth=20.0, radius=100.0):
    """A residual imprint: a parabolic pit of the given depth and radius, a rim of 2 nm at 1.3 radii."""
    r = np.hypot(x, y)
    return np.where(r < radius, -depth * (1 - (r / radius) ** 2), 0.0) + 2.0 * np.exp(-((r - 1.3 * radius) / 20) ** 2)


class HeightMaps(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_gsf_round_trip(self):
        # the grid export-curves.py writes, read back at Gwyddion's pixel centres, in nm
        half, n = 300.0, 65
        g = heightmap.grid_axis(half, n)
        X, Y = np.meshgrid(g, g)
        Z = bowl(X - 10, Y + 5) + 0.01 * X
        path = os.path.join(self.dir, "m.gsf")
        heightmap.write_gsf(path, Z, half, "test")
        m = heightmap.read_gsf(path)
        self.assertEqual(len(m.z), n * n)
        np.testing.assert_allclose(m.x, X.ravel(), rtol=0, atol=1e-9 * half)
        np.testing.assert_allclose(m.y, Y.ravel(), rtol=0, atol=1e-9 * half)
        np.testing.assert_allclose(m.z, Z.ravel(), rtol=1e-6, atol=1e-5)  # float32

    def test_gsf_units_and_damage(self):
        half, n = 1.0, 8
        path = os.path.join(self.dir, "u.gsf")
        heightmap.write_gsf(path, np.ones((n, n)), half, "t")
        with open(path, "rb") as f:
            data = f.read()
        head = data[:data.find(b"\0")].replace(b"XYUnits = m\n", b"XYUnits = um\n")
        with open(path, "wb") as f:
            f.write(head + b"\0" * (4 - len(head) % 4) + data[-4 * n * n:])
        m = heightmap.read_gsf(path)
        self.assertAlmostEqual(m.x.max(), (half - half / n) * 1e-9 * 1e3, places=12)
        self.assertAlmostEqual(m.z[0], 1.0, places=5)
        for bad, why in ((data[:-4], "bytes of data"), (b"hello" + data, "not a Gwyddion"),
                         (data.replace(b"ZUnits = m", b"ZUnits = s"), "not a length"),
                         (data.replace(b"XRes = 8", b"XRes = x"), "not a number")):
            with open(path, "wb") as f:
                f.write(bad)
            with self.assertRaisesRegex(heightmap.MapError, why):
                heightmap.read_gsf(path)

    def test_xyz(self):
        path = os.path.join(self.dir, "m.xyz")
        g = np.linspace(-1, 1, 5)
        X, Y = np.meshgrid(g, g)
        np.savetxt(path, np.column_stack([X.ravel(), Y.ravel(), (X + Y).ravel()]), header="x y z", comments="")
        m = heightmap.read_map(path, "um")
        self.assertAlmostEqual(m.z.max(), 2000.0)
        with open(path, "a") as f:
            f.write("1 2\n")
        with self.assertRaisesRegex(heightmap.MapError, "2 numbers, not 3"):
            heightmap.read_map(path)
        with self.assertRaisesRegex(heightmap.MapError, "not a length"):
            heightmap.read_map(path, "furlong")
        # as a spreadsheet saves it: semicolons and decimal commas with a byte-order mark, or tab-separated UTF-16
        rows = np.column_stack([X.ravel(), Y.ravel(), (X + Y).ravel() + 0.25])
        for name, sep, comma, enc in (("eu.xyz", ";", True, "utf-8-sig"), ("u16.xyz", "\t", True, "utf-16")):
            other = os.path.join(self.dir, name)
            with open(other, "w", encoding=enc) as f:
                f.write(sep.join(("x", "y", "z")) + "\n")
                for r in rows:
                    cells = [repr(float(v)) for v in r]
                    f.write(sep.join(c.replace(".", ",") if comma else c for c in cells) + "\n")
            m = heightmap.read_map(other)
            np.testing.assert_array_equal(np.column_stack([m.x, m.y, m.z]), rows)


class Imprint(unittest.TestCase):
    def grid_map(self, center=(0.0, 0.0), tilt=(0.0, 0.0), offset=0.0, angle=0.0, shape=bowl):
        g = np.linspace(-400, 400, 121)
        X, Y = np.meshgrid(g, g)
        t = np.radians(angle)
        dx, dy = X - center[0], Y - center[1]
        # the surface seen in the model's frame: the map's point turned by -angle
        xm, ym = np.cos(t) * dx + np.sin(t) * dy, -np.sin(t) * dx + np.cos(t) * dy
        Z = shape(xm, ym) + tilt[0] * X + tilt[1] * Y + offset
        return heightmap.HeightMap(X, Y, Z, "synthetic")

    def test_leveled_centred_and_zero_against_itself(self):
        # a tilted, offset map of the pit 37 nm and -21 nm off the map's centre: the centre is found, the plane
        # removed, and the model that made it has zero residuals
        m = imprint.MeasuredImprint(self.grid_map((37.0, -21.0), (0.02, -0.01), 5.0), points=3000)
        np.testing.assert_allclose(m.center, (37.0, -21.0), atol=4.0)  # the centroid: to the 6.7 nm pixels
        r = m.residuals(bowl)  # registered: the model's surface shifted onto the map
        np.testing.assert_allclose(m.center_found(), (37.0, -21.0), atol=1e-3)
        self.assertLess(np.abs(r).max(), 1e-5)
        exact = imprint.MeasuredImprint(self.grid_map((37.0, -21.0), (0.02, -0.01), 5.0), center=(37.0, -21.0))
        surface = lambda x, y: bowl(x, y) + 3.0  # noqa: E731  (the model's far surface at another level)
        np.testing.assert_allclose(exact.residuals(surface), 0.0, atol=1e-9)
        self.assertLessEqual(len(exact.z), 2000)
        self.assertAlmostEqual(exact.depth, 20.0, delta=0.2)
        # a model 10% deeper: the residual is the difference over the depth, times 1 / sqrt(pixels)
        r = exact.residuals(lambda x, y: 1.1 * bowl(x, y))
        self.assertAlmostEqual(np.sqrt(np.dot(r, r)), np.sqrt(np.mean((0.1 * exact.z) ** 2)) / exact.depth, places=3)
        # a failed run: a flat surface, the whole imprint missed
        flat = exact.residuals(None)
        np.testing.assert_allclose(flat, -exact.z * exact.scale)

    def test_rotation(self):
        # a three-fold pit (a pyramid's imprint) drawn turned by 40 degrees: with --imprint-rotation 40 the model's
        # unturned shape matches it, without it does not
        def tri(x, y):
            th = np.arctan2(y, x)
            return bowl(x, y) * (1 + 0.3 * np.cos(3 * th))
        hm = self.grid_map(angle=40.0, shape=tri)
        good = imprint.MeasuredImprint(hm, center=(0, 0), rotation_deg=40.0)
        bad = imprint.MeasuredImprint(hm, center=(0, 0), rotation_deg=0.0)
        self.assertLess(np.abs(good.residuals(tri)).max(), 1e-9)
        self.assertGreater(np.abs(bad.residuals(tri)).max(), 1e-3)
        # off the map's centre, found and registered in the turned frame: the axis comes back in the map's frame
        moved = imprint.MeasuredImprint(self.grid_map((30.0, 12.0), angle=40.0, shape=tri), rotation_deg=40.0)
        self.assertLess(np.abs(moved.residuals(tri)).max(), 1e-5)
        np.testing.assert_allclose(moved.center_found(), (30.0, 12.0), atol=1e-3)

    def test_bad(self):
        hm = self.grid_map()
        with self.assertRaisesRegex(imprint.ImprintError, "not inside the map"):
            imprint.MeasuredImprint(hm, center=(500.0, 0.0))
        with self.assertRaisesRegex(imprint.ImprintError, "radius"):
            imprint.MeasuredImprint(hm, center=(0.0, 0.0), radius=390.0)
        with self.assertRaisesRegex(imprint.ImprintError, "no imprint"):
            imprint.MeasuredImprint(heightmap.HeightMap(hm.x, hm.y, 0 * hm.z + 1.0), center=(0.0, 0.0))
        with self.assertRaisesRegex(imprint.ImprintError, "X,Y"):
            imprint.parse_center("1;2")
        small = imprint.MeasuredImprint(hm, center=(0.0, 0.0))
        with self.assertRaisesRegex(imprint.ImprintError, "does not reach"):
            small.residuals(lambda x, y: np.where(np.hypot(x, y) < 100, bowl(x, y), np.nan))


def write_run(path, x, cells, u):
    """indent.h5 as indent lays it out, with one displacement step: what run_surface reads."""
    import h5py
    with h5py.File(path, "w") as h5:
        h5["geometry/vertices"] = x
        h5["topology/cells"] = cells
        h5["fields/displacement"] = u[None]


class RunSurface(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.h5 = os.path.join(self.dir, imprint.H5_NAME)

    def tearDown(self):
        self.tmp.cleanup()

    def test_section(self):
        # a section of triangles (x = r, y = 0, z up): its top surface moves out by 10% and down by 10 (1 - r / 100)
        r, z = np.meshgrid(np.linspace(0, 100, 5), np.linspace(-50, 0, 3))
        x = np.column_stack([r.ravel(), np.zeros(r.size), z.ravel()])
        k = np.arange(15).reshape(3, 5)
        cells = np.concatenate([np.column_stack([k[:-1, :-1].ravel(), k[:-1, 1:].ravel(), k[1:, 1:].ravel()]),
                                np.column_stack([k[:-1, :-1].ravel(), k[1:, 1:].ravel(), k[1:, :-1].ravel()])])
        u = np.column_stack([0.1 * x[:, 0], np.zeros(15), np.where(x[:, 2] == 0, -10 * (1 - x[:, 0] / 100), 0)])
        write_run(self.h5, x, cells, u)
        surface = imprint.run_surface(self.dir)
        px, py = np.array([0.0, 30.0, -40.0, 60.0]), np.array([0.0, 40.0, 30.0, -80.0])  # radii 0, 50, 50, 100
        rho = np.hypot(px, py)
        np.testing.assert_allclose(surface(px, py), -10 * (1 - rho / 1.1 / 100), atol=1e-12)
        self.assertTrue(np.isnan(surface(np.array([111.0]), np.array([0.0])))[0])  # past the model's edge

    def test_quarter_model_mirrored(self):
        # a quarter block of hexahedra (symmetry planes x = 0 and y = 0): a linear height is read back exactly
        # anywhere in the plane, mirrored
        g = np.linspace(0, 100, 5)
        X, Y, Z = np.meshgrid(g, g, [-50.0, 0.0], indexing="ij")
        x = np.column_stack([X.ravel(), Y.ravel(), Z.ravel()])
        n = np.arange(x.shape[0]).reshape(5, 5, 2)
        cells = [[n[i, j, 0], n[i + 1, j, 0], n[i + 1, j + 1, 0], n[i, j + 1, 0],
                  n[i, j, 1], n[i + 1, j, 1], n[i + 1, j + 1, 1], n[i, j + 1, 1]] for i in range(4) for j in range(4)]
        u = np.zeros_like(x)
        u[:, 2] = np.where(x[:, 2] == 0, -5 + 0.02 * x[:, 0] + 0.03 * x[:, 1], 0)
        write_run(self.h5, x, np.array(cells), u)
        surface = imprint.run_surface(self.dir)
        px, py = np.array([-30.0, 20.0, -70.0, 99.0]), np.array([20.0, -45.0, -10.0, 99.0])
        np.testing.assert_allclose(surface(px, py), -5 + 0.02 * np.abs(px) + 0.03 * np.abs(py), atol=1e-12)
        self.assertIsNone(imprint.run_surface(os.path.join(self.dir, "none")))  # a run without fields


class ImprintOptions(unittest.TestCase):
    """indent-fit.py's --imprint on bad input: one line naming the option or file, exit 1 (2: argparse's)."""

    def run_fit(self, *argv):
        import subprocess
        fit = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "scripts", "indent-fit.py")
        return subprocess.run([sys.executable, fit, "--out", os.path.join(self.dir, "out"), "--indent", "/bin/true",
                               "--param", "E=film_young:40:120", *argv], capture_output=True, text=True)

    def setUp(self):
        import indentcurves
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        h = np.r_[np.linspace(1, 60, 30), np.linspace(60, 50, 20)]
        self.curve = os.path.join(self.dir, "c.csv")
        indentcurves.write_csv(self.curve, h, np.r_[0.04 * np.linspace(1, 60, 30) ** 2, np.linspace(144, 1, 20)])
        self.model = os.path.join(self.dir, "m.opts")
        with open(self.model, "w") as f:
            f.write("-indenter_type cone\n")

    def tearDown(self):
        self.tmp.cleanup()

    def test_bad(self):
        r = self.run_fit("--imprint", "a.gsf")
        self.assertEqual(r.returncode, 2)
        self.assertIn("give the --curve whose indenter made it before it", r.stderr)
        missing = os.path.join(self.dir, "missing.gsf")
        r = self.run_fit("--model", self.model, "--curve", self.curve, "--imprint", missing)
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr.strip(), f"indent-fit: error: --imprint {missing}: No such file or directory")
        bad = os.path.join(self.dir, "bad.xyz")
        with open(bad, "w") as f:
            f.write("0 0 0\n1 1\n")
        r = self.run_fit("--model", self.model, "--curve", self.curve, "--imprint", bad)
        self.assertEqual((r.returncode, r.stderr.count("\n")), (1, 1))
        self.assertIn(f"{bad}:2: 2 numbers, not 3", r.stderr)
        r = self.run_fit("--model", self.model, "--curve", self.curve, "--imprint-center", "3", "--imprint", bad)
        self.assertIn("--imprint-center 3: 'deepest' or X,Y in nm", r.stderr)
        g = np.linspace(-100, 100, 21)
        X, Y = np.meshgrid(g, g)
        pit = os.path.join(self.dir, "pit.xyz")
        np.savetxt(pit, np.column_stack([X.ravel(), Y.ravel(), bowl(X, Y, 10.0, 40.0).ravel()]))
        r = self.run_fit("--model", self.model, "--curve", self.curve, "--imprint-noise", "-1", "--imprint", pit)
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr.strip(), f"indent-fit: error: --imprint {pit}: the imprint's weight and noise must "
                         "be > 0 and its points >= 16")


if __name__ == "__main__":
    unittest.main(verbosity=1)
