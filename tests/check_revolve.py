#!/usr/bin/env python3
"""scripts/revolve.py on an axisymmetric run: the revolved solid's volume is N sin(d) times the section's
integral of r dA (d = angle / N, straight edges; every cell positively oriented as VTK counts it); each
vertex copy carries the section's displacement turned to its angle (no hoop component); each cell's stress
and strain are the section's turned to its segment's middle angle (turned back they are equal, their von
Mises stress is the section's); a quarter turn has N + 1 copies of the vertices; meshio reads the XDMF; a
3D run is refused in one line with status 2.

  check_revolve.py RUN_DIR WORKDIR
"""
import math
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPT = os.path.join(HERE, "..", "scripts", "revolve.py")
sys.path.insert(0, os.path.join(HERE, "..", "scripts"))
from revolve import rotate_voigt  # noqa: E402


def ring_integral(x, cells):
    """sum over cells of int r dA, quadrilaterals as the triangles (0, 1, 2) and (0, 2, 3)."""
    tris = [cells[:, [0, 1, 2]]] + ([cells[:, [0, 2, 3]]] if cells.shape[1] == 4 else [])
    total = 0.0
    for t in tris:
        p = x[t][:, :, [0, 2]]
        area = 0.5 * np.abs((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
                            - (p[:, 2, 0] - p[:, 0, 0]) * (p[:, 1, 1] - p[:, 0, 1]))
        total += float(np.sum(area * p[:, :, 0].mean(axis=1)))
    return total


def tet_volumes(p, tets):
    a, b, c, d = (p[:, k] for k in tets)
    return np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a) / 6.0


def cell_volumes(pts, cells):
    p = pts[cells]
    if cells.shape[1] == 6:
        # VTK's wedge: (0, 1, 2) faces away from (3, 4, 5), so these tetrahedra are negative when it is valid
        return -(tet_volumes(p, (0, 1, 2, 3)) + tet_volumes(p, (1, 2, 3, 4)) + tet_volumes(p, (2, 3, 4, 5)))
    # VTK's hexahedron: (0, 1, 2, 3) faces towards (4, 5, 6, 7)
    return sum(tet_volumes(p, t) for t in [(0, 1, 3, 4), (1, 2, 3, 6), (1, 3, 4, 6), (1, 4, 5, 6), (3, 4, 6, 7)])


def von_mises(s):
    return np.sqrt(0.5 * ((s[:, 0] - s[:, 1]) ** 2 + (s[:, 1] - s[:, 2]) ** 2 + (s[:, 2] - s[:, 0]) ** 2)
                   + 3 * (s[:, 3] ** 2 + s[:, 4] ** 2 + s[:, 5] ** 2))


def check(run_dir, out, segments, angle):
    cmd = [sys.executable, SCRIPT, run_dir, "--segments", str(segments), "--angle", str(angle), "--out", out]
    print("+", " ".join(cmd), flush=True)
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(proc.stdout, end="")
    if proc.returncode != 0:
        print(f"FAIL: revolve.py exited with {proc.returncode}")
        return False
    ok = True
    with h5py.File(os.path.join(run_dir, "indent.h5"), "r") as s, h5py.File(os.path.join(out, "revolved.h5"), "r") as r:
        x, cells = s["geometry/vertices"][:], s["topology/cells"][:].astype(np.int64)
        pts, rc = r["geometry/vertices"][:], r["topology/cells"][:]
        full = angle >= 360
        ncopy = segments if full else segments + 1
        d = math.radians(angle) / segments
        if len(pts) != ncopy * len(x) or len(rc) != segments * len(cells):
            print(f"FAIL: {len(pts)} vertices and {len(rc)} cells, not {ncopy} x {len(x)} and "
                  f"{segments} x {len(cells)}")
            return False
        if not np.array_equal(r["fields/step"][:].reshape(-1), s["fields/step"][:].reshape(-1)):
            print("FAIL: the revolved steps are not the run's")
            ok = False
        vol = cell_volumes(pts, rc)
        expect = segments * math.sin(d) * ring_integral(x, cells)
        err = abs(vol.sum() / expect - 1)
        smallest = vol.min() / vol.max()
        print(f"volume {vol.sum():.12g} nm^3 against N sin(d) int r dA = {expect:.12g}: {err:.2e}; smallest cell "
              f"volume / largest {smallest:.3g}")
        if err > 1e-10 or smallest < -1e-12:
            print("FAIL: the revolved volume is not the section's, or a cell is inverted")
            ok = False
        worst_u = worst_s = worst_vm = 0.0
        for i in range(s["fields/displacement"].shape[0]):
            u = s["fields/displacement"][i]
            ru = r[f"xdmf/{i}/displacement"][:]
            scale = max(float(np.abs(u).max()), 1e-300)
            for k in range(ncopy):
                t = k * d
                part = ru[k * len(x):(k + 1) * len(x)]
                want = np.column_stack([u[:, 0] * math.cos(t), u[:, 0] * math.sin(t), u[:, 2]])
                worst_u = max(worst_u, float(np.abs(part - want).max()) / scale)
            sig, rs = s["fields/stress"][i], r[f"xdmf/{i}/stress"][:]
            sscale = max(float(np.abs(sig).max()), 1e-300)
            for k in range(segments):
                part = rs[k * len(cells):(k + 1) * len(cells)]
                back = rotate_voigt(part, -(k + 0.5) * d, False)
                worst_s = max(worst_s, float(np.abs(back - sig).max()) / sscale)
                worst_vm = max(worst_vm, float(np.abs(von_mises(part) - von_mises(sig)).max()) / sscale)
        print(f"displacement turned to each copy: {worst_u:.2e}; stress turned back: {worst_s:.2e}; von Mises: "
              f"{worst_vm:.2e} (relative to the largest values)")
        if max(worst_u, worst_s, worst_vm) > 1e-12:
            print("FAIL: the revolved fields are not the section's turned")
            ok = False
    try:
        import meshio
    except ImportError:
        print("meshio not installed: its reading of the XDMF not checked")
        return ok
    with meshio.xdmf.TimeSeriesReader(os.path.join(out, "revolved.xdmf")) as reader:
        points, blocks = reader.read_points_cells()
        t, point_data, cell_data = reader.read_data(0)
    ncells = sum(len(b.data) for b in blocks)
    print(f"meshio: {len(points)} points, {ncells} cells ({blocks[0].type}), fields {sorted(point_data)} and "
          f"{sorted(cell_data)} at t = {t:g}")
    if len(points) != len(pts) or ncells != len(rc) or "displacement" not in point_data or "stress" not in cell_data:
        print("FAIL: meshio's reading differs")
        ok = False
    return ok


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    run_dir, work = sys.argv[1], sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    ok = check(run_dir, os.path.join(work, "full"), 8, 360) and check(run_dir, os.path.join(work, "quarter"), 3, 90)
    # a 3D run: the revolved file itself, as a run's indent.h5
    fake = os.path.join(work, "solid")
    os.makedirs(fake)
    shutil.copy(os.path.join(work, "full", "revolved.h5"), os.path.join(fake, "indent.h5"))
    proc = subprocess.run([sys.executable, SCRIPT, fake], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(proc.stdout, end="")
    lines = proc.stdout.strip().splitlines()
    if proc.returncode != 2 or len(lines) != 1 or "not an axisymmetric section" not in lines[0]:
        print("FAIL: a 3D run must be refused in one line with status 2")
        ok = False
    print("ok" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
