"""The residual imprint as a second term of the misfit: a measured height map (an AFM's, as .gsf or x y z
lines) against the top surface of a forward run after unloading.

The measured map is put in the model's frame once: its centre (the indenter's axis; given, or the centroid of
the pixels deeper than half the imprint) moved to the origin, the map turned by the given angle (a pyramid's
edge on the model's x axis), and a plane fitted to the pixels of an outer ring subtracted (the AFM's tilt and
offset), so that its far surface is at height 0. The fitted disc, inside the ring, is thinned to at most
`points` pixels. The model's surface is read at those pixels (a section's profile at their radius; a 3D
model's surface, mirrored to the whole plane, by linear interpolation) and leveled the same way, by the mean
of its heights on the ring's pixels. Unless the centre was given, the model's surface is shifted first by the
least-squares offset (at most a tenth of the disc's radius) that registers it on the map: a centroid finds
the axis only to a few pixels, and a coarse mesh's imprint is not quite symmetric. A residual is the model's
height minus the measured one, as a fraction of the imprint's measured depth, times weight / sqrt(pixels):
the imprint weighs as much as a curve's branch of the same weight, whatever its pixel count.
"""
import os

import numpy as np

import heightmap
import runfiles

H5_NAME = "indent.h5"


class ImprintError(Exception):
    pass


class Frame:
    """A map seen from an axis: the points in the model's frame (the map turned by -rotation about the centre,
    so that the map's direction at +rotation is the model's x), the leveling ring and the heights with the
    ring's plane taken out."""

    def __init__(self, hmap, center, rotation_deg, ring):
        x, y, z = hmap.x, hmap.y, hmap.z
        c = self.center = np.asarray(center, float)
        inscribed = min(c[0] - x.min(), x.max() - c[0], c[1] - y.min(), y.max() - c[1])
        if inscribed <= 0:
            raise ImprintError(f"{hmap.path}: the centre ({c[0]:.6g}, {c[1]:.6g}) nm is not inside the map")
        t = np.radians(rotation_deg)
        dx, dy = x - c[0], y - c[1]
        self.x, self.y = np.cos(t) * dx + np.sin(t) * dy, -np.sin(t) * dx + np.cos(t) * dy
        self.dist = np.hypot(self.x, self.y)
        self.ring = (0.8 * inscribed, inscribed) if ring is None else tuple(ring)
        self.on_ring = (self.dist >= self.ring[0]) & (self.dist <= self.ring[1])
        if self.on_ring.sum() < 8:
            raise ImprintError(f"{hmap.path}: fewer than 8 points on the leveling ring "
                               f"({self.ring[0]:.6g} to {self.ring[1]:.6g} nm from the centre)")
        k = self.on_ring
        self.z = z - plane_fit(self.x[k], self.y[k], z[k])(self.x, self.y)


class MeasuredImprint:
    """A measured map in the model's frame: points (x, y) of the fitted disc, their heights, the ring's points,
    the depth scale and the residuals' scale. Without a centre the axis is the pit's centroid, found on the raw
    map and again on the map leveled around it (a tilted map's deepest pixels lie downhill of the axis), then
    refined by registering the model's surface at every evaluation."""

    def __init__(self, hmap, center=None, rotation_deg=0.0, radius=None, ring=None, points=2000, weight=1.0,
                 noise=None):
        if weight <= 0 or points < 16 or (noise is not None and not noise > 0):
            raise ImprintError(f"{hmap.path}: the imprint's weight and noise must be > 0 and its points >= 16")
        self.noise = noise  # height noise (nm) for the intervals when the curves' noise is given in uN
        self.register = center is None
        if center is None:
            first = Frame(hmap, pit_centroid(hmap.x, hmap.y, hmap.z), rotation_deg, ring)
            center = pit_centroid(hmap.x, hmap.y, first.z)
        f = Frame(hmap, center, rotation_deg, ring)
        self.center, self.rotation, self.path, self.ring = f.center, rotation_deg, hmap.path, f.ring
        self.shift = np.zeros(2)
        self.radius = self.ring[0] if radius is None else float(radius)
        if not 0 < self.radius <= self.ring[0] < self.ring[1]:
            raise ImprintError(f"{hmap.path}: need 0 < radius ({self.radius:.6g} nm) <= the ring's inner radius "
                               f"({self.ring[0]:.6g}) < its outer ({self.ring[1]:.6g}), inside the map around the "
                               "centre")
        inside = np.flatnonzero(f.dist <= self.radius)
        keep = inside[thin(len(inside), points)]
        self.ring_x, self.ring_y = f.x[f.on_ring], f.y[f.on_ring]
        self.x, self.y, self.z = f.x[keep], f.y[keep], f.z[keep]
        self.depth = float(-self.z.min())
        if not self.depth > 1e-6 * self.ring[1]:
            raise ImprintError(f"{hmap.path}: no imprint: the map is nowhere below its leveled far surface")
        self.weight = weight
        self.scale = weight / (self.depth * np.sqrt(len(self.z)))

    def residuals(self, surface):
        """Model minus measured heights, scaled; surface None (a failed run, or no fields) counts as a flat
        surface, the imprint's whole depth missed."""
        return self.scale * (self.model_heights(surface) - self.z)

    def model_heights(self, surface):
        if surface is None:
            return np.zeros_like(self.z)
        if self.register:
            self.shift = self.registration(surface)
        return self._heights(surface, self.shift)

    def _heights(self, surface, shift):
        h = surface(self.x - shift[0], self.y - shift[1])
        ring = surface(self.ring_x - shift[0], self.ring_y - shift[1])
        if np.isnan(h).any() or np.isnan(ring).all():
            raise ImprintError(f"the model's top surface does not reach {self.radius:.6g} nm (the imprint's disc) "
                               f"and the ring to {self.ring[1]:.6g} nm: a larger model or a smaller --imprint-radius")
        return h - np.nanmean(ring)

    def registration(self, surface):
        """The shift of the model's surface (model frame, nm) that fits the map best, within a tenth of the disc."""
        from scipy.optimize import least_squares
        limit = 0.1 * self.radius
        sol = least_squares(lambda s: self._heights(surface, s) - self.z, np.zeros(2), bounds=(-limit, limit),
                            x_scale=limit, diff_step=1e-4, xtol=1e-10, ftol=1e-12)
        return sol.x

    def center_found(self):
        """The indenter's axis on the map (map frame, nm): the centre plus the registration's shift."""
        t = np.radians(self.rotation)
        return self.center + np.array([np.cos(t) * self.shift[0] - np.sin(t) * self.shift[1],
                                       np.sin(t) * self.shift[0] + np.cos(t) * self.shift[1]])

    def write_fitted(self, path, fit):
        """The fitted pixels' measured heights beside fit, the model's (model_heights) at the same pixels."""
        with open(path, "w") as f:
            f.write("x_nm,y_nm,r_nm,measured_height_nm,fitted_height_nm\n")
            for a, b, m, s in zip(self.x, self.y, self.z, fit):
                f.write(f"{a:.8g},{b:.8g},{np.hypot(a, b):.8g},{m:.8g},{s:.8g}\n")


def pit_centroid(x, y, z):
    """The indenter's axis on a map: the centroid of the points deeper than half the imprint (halfway between the
    deepest and the median height, the far surface), a disc for a cone or a sphere, a triangle for a Berkovich."""
    low = z <= z.min() + 0.5 * (np.median(z) - z.min())
    return np.array([x[low].mean(), y[low].mean()])


def plane_fit(x, y, z):
    """The least-squares plane z = a + b x + c y through the points, as a function."""
    A = np.column_stack([np.ones_like(x), x, y])
    coef = np.linalg.lstsq(A, z, rcond=None)[0]
    return lambda px, py: coef[0] + coef[1] * px + coef[2] * py


def thin(n, points):
    """Indices of at most `points` of n points, evenly spaced through them (a map's pixels row by row: a
    regular sub-grid when the stride and the row length are coprime or the stride divides it)."""
    if n <= points:
        return np.arange(n)
    return np.unique(np.linspace(0, n - 1, points).round().astype(int))


def run_surface(run_dir):
    """The top surface of a finished forward run at its last written step, as a function (x, y) -> height in nm
    (NaN outside the model); None when the run wrote no fields."""
    import h5py
    path = os.path.join(run_dir, H5_NAME)
    if not os.path.isfile(path):
        return None
    with h5py.File(path, "r") as h5:
        profile = runfiles.top_profile(h5, path)
        if profile is None:
            xy, height, tris, axes, tol = runfiles.top_surface(h5, path)
    if profile is not None:
        r, height = profile
        return lambda px, py: np.interp(np.hypot(px, py), r, height, right=np.nan)
    from matplotlib.tri import LinearTriInterpolator, Triangulation
    pts, tr, src, _ = runfiles.mirror(xy, tris, axes, tol)
    interp = LinearTriInterpolator(Triangulation(pts[:, 0], pts[:, 1], tr), height[src])
    return lambda px, py: np.ma.filled(interp(px, py), np.nan)


def parse_center(text):
    """'X,Y' (nm) or None for 'deepest'."""
    if text in (None, "", "deepest"):
        return None
    try:
        c = [float(v) for v in text.split(",")]
    except ValueError:
        c = []
    if len(c) != 2:
        raise ImprintError(f"--imprint-center {text}: 'deepest' or X,Y in nm")
    return c


def load(path, unit="nm", center=None, rotation=0.0, radius=None, points=2000, weight=1.0, noise=None):
    """The measured imprint of indent-fit's --imprint and its options; errors name the option."""
    c = parse_center(center)
    try:
        return MeasuredImprint(heightmap.read_map(path, unit), c, rotation, radius, None, points, weight, noise)
    except (heightmap.MapError, ImprintError) as e:
        raise ImprintError(f"--imprint {e}") from None
