#!/usr/bin/env python3
"""A 3D model run on the axisymmetric section where its indenter allows it (scripts/sectionmodel.py), by default in
the inverse fit and the sweep helper:

  check_section_model.py --indent BIN --workdir D

1. The conversion: inputs/berkovich.opts with a cone (and with a sphere on the multilayer) becomes the section of
   the same parameters, every other option kept in its order, -bc_symmetry dropped; a Berkovich, a scratch, an
   indenter off the axis, a mesh file of its own and a model already on a section stay as they are, each with its
   reason; a stray word is an error.
2. The converted model runs (2 loading steps on the coarse section, 1 rank) and loads the cone.
3. scripts/indent-fit.py writes the section's model in OUT/models and says so (its runs are not needed here: the
   indent given is /bin/false, so it stops at its first runs); with --3d it keeps the 3D model.
4. scripts/sweep.py --dry-run: the cone's runs on the section, the Berkovich's on the 3D mesh; --3d keeps both 3D.
Prints ok or FAIL per check; exit 1 on any failure.
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(REPO, "scripts"))
import sectionmodel  # noqa: E402
from checklist import check, status  # noqa: E402  (this folder)

BERKOVICH = os.path.join("inputs", "berkovich.opts")


def conversion():
    tokens, why = sectionmodel.section_of(["-options_file", BERKOVICH, "-indenter_type", "cone", "-load_depth", "7"],
                                          REPO)
    given = sectionmodel.pairs(["-options_file", BERKOVICH], REPO)
    kept = [p for p in given if p[0] not in ("bc_symmetry", "mesh_file")] + [("indenter_type", "cone"),
                                                                               ("load_depth", "7")]
    out = sectionmodel.pairs(tokens or [])
    check(tokens is not None and ("mesh_file", "inputs/axisymmetric_film.geo") in out
          and [p for p in out if p[0] != "mesh_file"] == kept and "section" in why,
          f"berkovich.opts with a cone: {why}")
    tokens, why = sectionmodel.section_of(["-options_file", BERKOVICH, "-mesh_file", "inputs/multilayer_half.geo",
                                           "-indenter_type", "sphere"], REPO)
    check(tokens is not None and sectionmodel.pairs(tokens)[-2] == ("mesh_file", "inputs/axisymmetric_multilayer.geo"),
          f"the multilayer with a sphere: {why}")
    for more, say in (([], "not of revolution"), (["-indenter_type", "cone", "-scratch_length", "100"], "scratch"),
                      (["-indenter_type", "cone", "-indenter_axis", "5,0"], "off the axis"),
                      (["-indenter_type", "cone", "-mesh_file", "my.msh"], "not one of"),
                      (["-indenter_type", "cone", "-mesh_file", "inputs/axisymmetric_film.geo"], "not one of")):
        tokens, why = sectionmodel.section_of(["-options_file", BERKOVICH] + more, REPO)
        check(tokens is None and say in why, f"{' '.join(more) or 'the Berkovich'}: kept 3D ({why})")
    try:
        sectionmodel.section_of(["-load_depth", "7", "oops"])
        check(False, "a stray word: an error")
    except sectionmodel.ModelError as e:
        check("oops" in str(e), f"a stray word: {e}")


def runs(args):
    tokens, _ = sectionmodel.section_of(["-options_file", BERKOVICH, "-indenter_type", "cone", "-indenter_radius",
                                         "20", "-mesh_geo_parameters", "h_tip=20,h_far=400"], REPO)
    model = os.path.join(args.workdir, "cone-section.opts")
    sectionmodel.write_options(model, tokens)
    out = os.path.join(args.workdir, "run")
    run = subprocess.run([args.indent, "-options_file", model, "-load_depth", "10", "-load_steps", "2",
                          "-load_unload", "0", "-output_fields", "0", "-quiet", "-output_dir", out,
                          "-output_overwrite"], cwd=REPO, capture_output=True, text=True)
    load = 0.0
    if run.returncode == 0:
        with open(os.path.join(out, "load_displacement.csv")) as f:
            load = float(f.read().splitlines()[-1].split(",")[3])
    check(run.returncode == 0 and load > 0, f"the converted model runs: {load:.4g} uN at 10 nm "
          f"({run.stderr.strip().splitlines()[-1] if run.returncode else 'exit 0'})")

    curve = os.path.join(args.workdir, "curve.csv")
    with open(curve, "w") as f:
        f.write("depth_nm,load_uN\n" + "".join(f"{h},{h * h / 10}\n" for h in range(1, 31)) +
                "".join(f"{30 - h},{(30 - h) ** 2 / 20}\n" for h in range(1, 11)))
    model3d = os.path.join(args.workdir, "cone3d.opts")
    with open(model3d, "w") as f:
        f.write(f"-options_file {BERKOVICH}\n-indenter_type cone\n")
    for three_d in (False, True):
        fit_out = os.path.join(args.workdir, "fit3d" if three_d else "fit")
        cmd = [sys.executable, os.path.join(REPO, "scripts", "indent-fit.py"), "--out", fit_out, "--indent",
               "/bin/false", "--model", model3d, "--curve", curve, "--param", "yield=film_yield:0.1:1"]
        run = subprocess.run(cmd + (["--3d"] if three_d else []), cwd=REPO, capture_output=True, text=True)
        written = os.path.join(fit_out, "models", "1-cone3d.opts")
        text = open(written).read() if os.path.exists(written) else ""
        if three_d:
            check(not os.path.exists(written) and "axisymmetric section" not in run.stdout,
                  "indent-fit --3d: the 3D model kept")
        else:
            check("inputs/axisymmetric_film.geo" in text and "bc_symmetry" not in text
                  and "axisymmetric section" in run.stdout, f"indent-fit: the section's model in {written}")


def sweep(args):
    for three_d in (False, True):
        cmd = [sys.executable, os.path.join(REPO, "scripts", "sweep.py"), "--base", f"-options_file {BERKOVICH}",
               "--vary", "indenter_type=cone,berkovich", "--out", os.path.join(args.workdir, "sweep"), "--dry-run"]
        run = subprocess.run(cmd + (["--3d"] if three_d else []), cwd=REPO, capture_output=True, text=True)
        lines = [ln for ln in run.stdout.splitlines() if "/indent " in ln]
        cone = [ln for ln in lines if "indenter_type=cone" in ln]
        berk = [ln for ln in lines if "indenter_type=berkovich" in ln]
        if three_d:
            check(run.returncode == 0 and len(lines) == 2 and all("axisymmetric" not in ln for ln in lines),
                  "sweep --3d: both runs on the 3D model")
        else:
            check(run.returncode == 0 and len(cone) == 1 and "-mesh_file inputs/axisymmetric_film.geo" in cone[0]
                  and "-bc_symmetry" not in cone[0] and len(berk) == 1 and "axisymmetric" not in berk[0],
                  "sweep: the cone on the section, the Berkovich on the 3D mesh")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--indent", required=True)
    ap.add_argument("--workdir", required=True)
    args = ap.parse_args()
    args.workdir = os.path.abspath(args.workdir)
    os.makedirs(args.workdir, exist_ok=True)
    conversion()
    runs(args)
    sweep(args)
    return status()


if __name__ == "__main__":
    sys.exit(main())
