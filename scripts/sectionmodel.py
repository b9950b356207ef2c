"""The axisymmetric section of a 3D model, wherever its indenter allows it (doc/axisymmetric.md).

A model whose indenter is of revolution (sphere, cone, flat punch or table) pressed on the axis, without a scratch,
into one of the parametric 3D meshes of inputs/ runs the same on the section with the same physical names and
parameters (film, width, depth, h_tip, h_far, r_fine, grow; the layers' t1, t2, ...), in hundreds of times fewer
unknowns: inputs/berkovich_{half,full}.geo becomes axisymmetric_film.geo and multilayer_{half,full}.geo
axisymmetric_multilayer.geo. The 3D model's symmetry planes and load factor (-bc_symmetry,
-contact_symmetry_factor) have no meaning on a section and go. Used by scripts/indent-fit.py and scripts/sweep.py.
"""
import os
import re
import shlex

SECTIONS = {"berkovich_half.geo": "axisymmetric_film.geo", "berkovich_full.geo": "axisymmetric_film.geo",
            "multilayer_half.geo": "axisymmetric_multilayer.geo",
            "multilayer_full.geo": "axisymmetric_multilayer.geo"}
REVOLUTION = ("sphere", "cone", "flat", "table")
DROPPED = ("bc_symmetry", "contact_symmetry_factor")
OPTION = re.compile(r"^-[A-Za-z_]")


class ModelError(Exception):
    pass


def file_tokens(path, cwd="."):
    """The tokens of an options file (a relative path taken from cwd): '#' starts a comment; a value with blanks
    may be quoted."""
    try:
        with open(os.path.join(cwd, path)) as f:
            text = f.read()
    except OSError as e:
        raise ModelError(f"-options_file {path}: {e.strerror}")
    return [t for line in text.splitlines() for t in shlex.split(line, comments=True)]


def pairs(tokens, cwd="."):
    """(name, value or None) of each option in order, the options files expanded where they stand."""
    out, i = [], 0
    while i < len(tokens):
        tok = tokens[i]
        if not OPTION.match(tok):
            raise ModelError(f"'{tok}' is not an option (options start with '-')")
        value = tokens[i + 1] if i + 1 < len(tokens) and not OPTION.match(tokens[i + 1]) else None
        i += 2 if value is not None else 1
        if tok == "-options_file" and value is not None:
            out += pairs(file_tokens(value, cwd), cwd)
        else:
            out.append((tok[1:], value))
    return out


def section_of(tokens, cwd="."):
    """(the section's options as tokens, why) where the indenter allows the section, else (None, why not). Relative
    paths are taken from cwd, as indent run there takes them."""
    opts = pairs(tokens, cwd)
    last = {name: value for name, value in opts}
    mesh, kind = last.get("mesh_file"), last.get("indenter_type")
    if not mesh or os.path.basename(mesh) not in SECTIONS:
        return None, f"the mesh {mesh or '(none)'} is not one of inputs/' 3D meshes with a section"
    if kind not in REVOLUTION:
        return None, f"-indenter_type {kind or '(none)'} is not of revolution"
    if float(last.get("scratch_length") or 0) > 0:
        return None, "a scratch slides the indenter off the axis"
    if any(float(x) != 0 for x in (last.get("indenter_axis") or "0").split(",")):
        return None, "the indenter is off the axis (-indenter_axis)"
    section = os.path.join(os.path.dirname(mesh), SECTIONS[os.path.basename(mesh)])
    out = []
    for name, value in opts:
        if name in DROPPED:
            continue
        out += [f"-{name}"] + ([section if name == "mesh_file" else value] if value is not None else [])
    return out, f"the {kind} on the axisymmetric section {section} instead of the 3D mesh {mesh}"


def write_options(path, tokens):
    """tokens as an options file, one option a line."""
    lines, i = [], 0
    while i < len(tokens):
        if i + 1 < len(tokens) and not OPTION.match(tokens[i + 1]):
            lines.append(f"{tokens[i]} {shlex.quote(tokens[i + 1])}")
            i += 2
        else:
            lines.append(tokens[i])
            i += 1
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("# written by scripts/sectionmodel.py: the axisymmetric section of a 3D model\n")
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, path)
