#!/usr/bin/env python3
"""A damaged checkpoint is refused, in one line, and the one before it is offered:

  check_checkpoint_damage.py --mpiexec M --indent BIN --workdir D [--np N] [--other=-OPT=VALUE] -- <indent options>

runs the case with a checkpoint after every step and stops it after step 4 (checkpoint.h5 of step 4,
checkpoint.previous.h5 of step 3), then, each on a copy of the run directory, restarts from:
  - checkpoint.h5 with 64 KiB zeroed inside a dataset;
  - checkpoint.h5 cut to half its size;
  - checkpoint.h5 with one value of the history flipped in a single bit (found by its checksum alone);
  - the checkpoint of another case (the same options with --other), which is refused as another model;
each must exit non-zero with exactly one line 'indent: error: ...' naming the file (and for the damaged
ones the previous checkpoint and its step), no PETSc or HDF5 error block, and the run's other files
byte for byte as before. Then the restart from checkpoint.previous.h5, as the line advises, must finish
(exit 0) with the curve's steps 1, 2, ... in order. Prints ok or FAIL per check; exit 1 on a failed check.
"""
import hashlib
import os
import shutil
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402

EXIT_CHECKPOINTED = 75
check = indentrun.Checks()


def launch(args, options):
    status, lines = indentrun.run_quiet(args.mpiexec, args.np, args.indent, options)
    return status, "\n".join(lines)


def digests(d):
    """sha256 of every file of the directory but the checkpoints, by name."""
    out = {}
    for name in sorted(os.listdir(d)):
        if not name.startswith("checkpoint"):
            with open(os.path.join(d, name), "rb") as f:
                out[name] = hashlib.sha256(f.read()).hexdigest()
    return out


def flip_history_bit(path):
    """Flips the lowest mantissa bit of one history value, in place, through HDF5 (the file stays valid)."""
    with h5py.File(path, "r+") as f:
        h = f["cells/history_committed"]
        row = h.shape[0] // 2
        v = np.array(h[row], dtype=np.float64)
        k = int(np.argmax(np.abs(v)))
        bits = v.view(np.uint64)
        bits[k] ^= np.uint64(1)
        h[row] = bits.view(np.float64)


def refused(args, options, run, label, damage, expect):
    """A copy of the run directory, its checkpoint damaged, restarted: one line, nothing else touched."""
    d = os.path.join(args.workdir, label)
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(run, d)
    damage(os.path.join(d, "checkpoint.h5"))
    before = digests(d)
    status, text = launch(args, [*options, "-output_dir", d, "-restart", d])
    lines = [l for l in text.splitlines() if l.strip()]
    errors = [l for l in lines if l.startswith("indent: error:")]
    check(status != 0, f"{label}: refused (exit {status})")
    check(len(errors) == 1 and len(lines) == 1, f"{label}: one line, got {len(lines)}: {lines[:3]}")
    check(not any("PETSC ERROR" in l or "HDF5-DIAG" in l for l in lines), f"{label}: no PETSc or HDF5 error block")
    for what in expect:
        check(bool(errors) and what in errors[0], f"{label}: the line says '{what}'")
    check(digests(d) == before, f"{label}: the run's other files untouched")


def main():
    ap, mine, options = indentrun.parser_and_options("check_checkpoint_damage.py")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--other", default="-load_depth=25", help="a model option of another case, -OPT=VALUE")
    args = ap.parse_args(mine)
    os.makedirs(args.workdir, exist_ok=True)
    run = os.path.join(args.workdir, "run")
    status, text = launch(args, [*options, "-output_dir", run, "-output_overwrite", "-checkpoint_every", "1",
                                 "-checkpoint_stop_after_step", "4"])
    if not check(status == EXIT_CHECKPOINTED, f"stopped after step 4 with a checkpoint (exit {status})"):
        print(text)
        return 1
    ckpt, prev = os.path.join(run, "checkpoint.h5"), os.path.join(run, "checkpoint.previous.h5")
    check(os.path.isfile(prev), "the checkpoint of step 3 kept as checkpoint.previous.h5")
    with h5py.File(prev, "r") as f:
        step = int(f["load_path/position"][2])
        check(step == 3, f"checkpoint.previous.h5 is of step {step}, not 3")
    advice = ["is damaged", "after step 3", "-restart " + os.path.join(args.workdir, "{}", "checkpoint.previous.h5")]

    def zero_middle(p):
        """64 KiB zeroed in the middle of the cells' keys (centroids, none zero: a change whatever the case;
        the middle of the file may hold history values that are zero already)."""
        with h5py.File(p, "r") as f:
            keys = f["cells/keys"].id
            if keys.get_create_plist().get_layout() == h5py.h5d.CHUNKED:  # written by PETSc's VecView
                info = keys.get_chunk_info(0)
                offset, size = info.byte_offset, info.size
            else:
                offset, size = keys.get_offset(), keys.get_storage_size()
        with open(p, "r+b") as f:
            f.seek(offset + max(0, size // 2 - 32768))
            f.write(bytes(min(65536, size)))

    def truncate(p):
        os.truncate(p, os.path.getsize(p) // 2)

    for label, damage in (("zeroed", zero_middle), ("truncated", truncate), ("bit", flip_history_bit)):
        refused(args, options, run, label, damage, [a.format(label) for a in advice])

    # a checkpoint of another case, in this run's directory
    other = os.path.join(args.workdir, "other")
    name, value = args.other.split("=", 1)
    status, _ = launch(args, [*options, name, value, "-output_dir", other, "-output_overwrite",
                              "-checkpoint_stop_after_step", "2"])
    check(status == EXIT_CHECKPOINTED, f"another case stopped with a checkpoint (exit {status})")
    refused(args, options, run, "another_case",
            lambda p: shutil.copyfile(os.path.join(other, "checkpoint.h5"), p), [name.lstrip("-")])

    # continuing from the previous checkpoint, as the line advises
    d = os.path.join(args.workdir, "from_previous")
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(run, d)
    zero_middle(os.path.join(d, "checkpoint.h5"))
    status, text = launch(args, [*options, "-output_dir", d, "-restart", os.path.join(d, "checkpoint.previous.h5")])
    check(status == 0, f"the restart from checkpoint.previous.h5 finished (exit {status})")
    if status == 0:
        steps = np.genfromtxt(os.path.join(d, "load_displacement.csv"), delimiter=",", names=True)["step"]
        check(len(steps) > 4 and list(steps) == list(range(1, len(steps) + 1)),
              f"its curve has steps 1 to {len(steps)} in order")
    else:
        print(text)
    return check.status()


if __name__ == "__main__":
    sys.exit(main())
