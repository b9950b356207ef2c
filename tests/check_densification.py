#!/usr/bin/env python3
"""A densifying block (-domain_model densifying) compressed equally in x, y and z, through the whole code: the
written compaction and stress of every cell at every step against the closed form. The strain is uniform and
hydrostatic, e = ln(stretch) each way (small strain: the stretch minus 1), so the trial pressure is -kappa tr(e);
past the cap p_c0 the glass compacts by c = (p_tr - p_c0) / (kappa + H_v) and holds p = p_c0 + H_v c, with no
deviatoric stress. At finite strain that p is Kirchhoff's: the Cauchy stress written is -p / J, J = stretch^3.

  check_densification.py --mpiexec M --indent BIN --np N --workdir DIR --formulation small|finite
"""
import argparse
import math
import os
import subprocess
import sys

import h5py
import numpy as np

E, NU, SY, PC, HV = 72.0, 0.17, 6.0, 10.0, 20.0
SQUEEZE, STEPS = 0.15, 5  # displacement of the far faces of the unit box at full load, nm; load steps


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--mpiexec", required=True)
    ap.add_argument("--indent", required=True)
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--formulation", choices=("small", "finite"), required=True)
    args = ap.parse_args()
    out = os.path.join(args.workdir, args.formulation)
    cmd = [args.mpiexec, "-n", str(args.np), args.indent, "-dm_plex_box_faces", "2,2,2", "-mesh_perturb", "0.2",
           "-domain_young", str(E), "-domain_poisson", str(NU), "-domain_model", "densifying",
           "-domain_yield", str(SY), "-domain_yield_pressure", str(PC), "-domain_densification_modulus", str(HV),
           "-bc_roller", "left:x,front:y,bottom:z",
           "-bc_displacement", f"right:x={-SQUEEZE},back:y={-SQUEEZE},top:z={-SQUEEZE}",
           "-load_steps", str(STEPS), "-load_unload", "0", "-load_predictor", "none", "-output_fields_every", "1",
           "-formulation", args.formulation, "-snes_rtol", "1e-12", "-snes_atol", "1e-12", "-ksp_type", "preonly",
           "-pc_type", "lu", "-pc_factor_mat_solver_type", "mumps", "-quiet", "-output_dir", out,
           "-output_overwrite"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode:
        print(r.stdout, r.stderr)
        print("FAIL: indent failed")
        return 1
    kappa = E / (3 * (1 - 2 * NU))
    worst_c = worst_p = worst_dev = 0.0
    compacted = 0
    with h5py.File(os.path.join(out, "indent.h5"), "r") as f:
        comp, stress, steps = f["fields/compaction"][:, :, 0], f["fields/stress"][:], f["fields/step"][:]
    for k, step in enumerate(np.ravel(steps)):
        stretch = 1.0 - SQUEEZE * step / STEPS
        e = math.log(stretch) if args.formulation == "finite" else stretch - 1.0
        p_tr = -kappa * 3 * e
        c = max(0.0, (p_tr - PC) / (kappa + HV))
        p = p_tr - kappa * c
        if args.formulation == "finite":
            p /= stretch ** 3
        compacted += c > 0
        worst_c = max(worst_c, np.abs(comp[k] - c).max())
        worst_p = max(worst_p, np.abs(-stress[k, :, :3].mean(axis=1) - p).max() / p)
        dev = stress[k, :, :3] - stress[k, :, :3].mean(axis=1, keepdims=True)
        worst_dev = max(worst_dev, np.abs(dev).max(), np.abs(stress[k, :, 3:]).max())
        print(f"step {int(step)}: stretch {stretch:.3f}, compaction {comp[k].mean():.10f} (closed form {c:.10f}), "
              f"pressure {-stress[k, :, :3].mean():.8f} GPa (closed form {p:.8f})")
    print(f"worst compaction error {worst_c:.2e}, pressure {worst_p:.2e} (relative), deviatoric stress "
          f"{worst_dev:.2e} GPa; {compacted} of {len(steps)} steps past the cap")
    ok = compacted >= 2 and worst_c < 1e-9 and worst_p < 1e-9 and worst_dev < 1e-8
    print("ok" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
