#!/usr/bin/env python3
"""Checkpoint and restart: a run stopped after a step (by -checkpoint_stop_after_step, or by a real
signal sent to mpiexec) and continued with -restart, on the same or another rank count, gives the
uninterrupted run's curve, contact-node counts, summary (its warnings too) and final fields; a restart with other model
options or another mesh is refused with one line naming the difference, leaving the files untouched.

  check_restart.py --mpiexec M --indent BIN --workdir D [--np A,B] [--stop K] [--signal USR1]
                   [--rtol R] [--changed-option=-OPT=VALUE] [--mesh-change=-OPT=VALUE] -- <indent options>
"""
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import indentrun  # noqa: E402

EXIT_CHECKPOINTED = 75


def launch(args, nranks, options, out, extra=(), wait=True):
    cmd = [args.mpiexec, "-n", str(nranks), args.indent, *options, "-output_dir", out, *extra]
    print("+", " ".join(cmd), flush=True)
    if not wait:
        return subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    indentrun.pass_on_unfreed(proc.stdout)
    return proc.returncode, proc.stdout


def curve(d):
    return np.genfromtxt(os.path.join(d, "load_displacement.csv"), delimiter=",", names=True)


def last_fields(d):
    """Every field's last step, rows ordered by vertex coordinates or cell centroid (rank-independent)."""
    with h5py.File(os.path.join(d, "indent.h5"), "r") as f:
        order = {1: np.arange(1),  # /fields/step: one value per step
                 f["geometry/vertices"].shape[0]: np.lexsort(f["geometry/vertices"][()].T[::-1]),
                 f["topology/cell_centroids"].shape[0]: np.lexsort(f["topology/cell_centroids"][()].T[::-1])}
        return {k: f["fields"][k][-1][order[f["fields"][k].shape[1]]] for k in f["fields"]}, \
            {k: f["fields"][k].shape[0] for k in f["fields"]}


def digest(d):
    h = hashlib.sha256()
    for name in sorted(os.listdir(d)):
        with open(os.path.join(d, name), "rb") as fp:
            h.update(name.encode() + fp.read())
    return h.hexdigest()


def compare(ref, got, rtol, label):
    a, b = curve(ref), curve(got)
    bad = []
    if len(a) != len(b):
        bad.append(f"{len(b)} curve points, {len(a)} uninterrupted")
    else:
        dp = np.max(np.abs(a["load_uN"] - b["load_uN"])) / np.max(np.abs(a["load_uN"]))
        dh = np.max(np.abs(a["depth_nm"] - b["depth_nm"]))
        print(f"  {label}: curve max |dP| / P_max = {dp:.3e}, max |dh| = {dh:.3e} nm, "
              f"contact nodes identical: {bool(np.all(a['contact_nodes'] == b['contact_nodes']))}")
        if dp > rtol or dh > rtol * np.max(a["depth_nm"]):
            bad.append("curve differs")
        if not np.all(a["contact_nodes"] == b["contact_nodes"]):
            bad.append("contact-node counts differ")
    if os.path.exists(os.path.join(ref, "scratch.csv")):  # a scratch: its forces at every step
        sa, sb = (np.genfromtxt(os.path.join(d, "scratch.csv"), delimiter=",", names=True) for d in (ref, got))
        if sa.shape != sb.shape:
            bad.append(f"{len(sb)} scratch.csv rows, {len(sa)} uninterrupted")
        else:
            ds = max(np.max(np.abs(sa[k] - sb[k])) / max(np.max(np.abs(sa[k])), 1e-300) for k in sa.dtype.names)
            print(f"  {label}: scratch.csv max diff / column max = {ds:.3e}")
            if ds > rtol:
                bad.append("scratch.csv differs")
    fa, na = last_fields(ref)
    fb, nb = last_fields(got)
    if na != nb:
        bad.append(f"output steps {nb} vs {na}")
    for k in fa:
        if k == "contact_status":  # stick/slip of a node on the Coulomb cone's edge is round-off's choice
            continue
        scale = max(np.max(np.abs(fa[k])), 1e-300)
        d = np.max(np.abs(fa[k] - fb[k])) / scale
        print(f"  {label}: last step {k:<17} max diff / max = {d:.3e}")
        if d > 100 * rtol:
            bad.append(f"field {k} differs by {d:.2e}")
    sa = json.load(open(os.path.join(ref, "summary.json")))
    sb = json.load(open(os.path.join(got, "summary.json")))
    for k in ("H_GPa", "E_r_GPa", "P_max_uN"):
        # withheld (null) or absent in both runs alike
        if (sa.get(k) is None) != (sb.get(k) is None):
            bad.append(f"summary {k} in one run only")
        elif sa.get(k) is not None and abs(sa[k] - sb[k]) > rtol * abs(sa[k]):
            bad.append(f"summary {k} {sb[k]} vs {sa[k]}")
    if not sb.get("restarted"):
        bad.append("summary.json does not record the restart")
    if sa.get("warnings") != sb.get("warnings"):  # those of the steps before the restart kept by the checkpoint
        bad.append(f"summary warnings {sb.get('warnings')} vs {sa.get('warnings')}")
    for name in ("checkpoint.h5", "checkpoint.previous.h5"):
        if os.path.exists(os.path.join(got, name)):
            bad.append(f"the finished run left {name}")
    for b_ in bad:
        print(f"FAIL ({label}): {b_}")
    return not bad


def rejected_work(*outputs):
    """Newton and linear iterations of the attempts cut back, from the runs' printed rejections."""
    found = [m for out in outputs for m in re.findall(r"rejected after newton (\d+) linear (\d+)", out)]
    return sum(int(n) for n, _ in found), sum(int(l) for _, l in found)


def check_rejected(d, outputs, label):
    """summary.json's iterations of the attempts cut back are those the run printed (all its parts), and some."""
    s = json.load(open(os.path.join(d, "summary.json")))
    newton, linear = rejected_work(*outputs)
    got = (s.get("newton_rejected"), s.get("linear_rejected"))
    ok = newton > 0 and got == (newton, linear)
    print(f"  {label}: summary's iterations of the attempts cut back {got}, printed {(newton, linear)}")
    if not ok:
        print(f"FAIL ({label}): expected cut-back attempts, and the summary's counts equal to the printed ones")
    return ok


def refused(args, nranks, options, d, extra, expect, label):
    before = digest(d)
    code, out = launch(args, nranks, options, d, extra)
    lines = [l for l in out.splitlines() if l.strip()]
    ok = code != 0 and any(expect in l for l in lines) and digest(d) == before
    print(f"  {label}: exit {code}, {'files untouched' if digest(d) == before else 'FILES CHANGED'}: "
          f"{lines[0] if lines else '(no output)'}")
    if not ok:
        print(out)
        print(f"FAIL ({label}): expected a non-zero exit, a line with {expect!r} and untouched files")
    return ok


def main():
    ap, argv, options = indentrun.parser_and_options("check_restart.py")
    ap.add_argument("--np", default="1,2")
    ap.add_argument("--stop", type=int, default=3)
    ap.add_argument("--signal", default="")
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--changed-option", metavar="OPTION=VALUE", help="a model option to change for a refused restart")
    ap.add_argument("--mesh-change", metavar="OPTION=VALUE", help="an option that changes the mesh, for a refused restart")
    ap.add_argument("--expect-rejected", action="store_true",
                    help="the run cuts steps back (not -quiet): its summary counts their iterations, across the restart")
    args = ap.parse_args(argv)
    first, second = [int(n) for n in args.np.split(",")]
    shutil.rmtree(args.workdir, ignore_errors=True)
    os.makedirs(args.workdir)
    ref, part = os.path.join(args.workdir, "uninterrupted"), os.path.join(args.workdir, "restarted")

    code, out = launch(args, first, options, ref)
    if code != 0:
        print(out)
        print(f"FAIL: the uninterrupted run exited with {code}")
        return 1
    ref_out = out

    if args.signal:
        proc = launch(args, first, options, part, wait=False)
        csv = os.path.join(part, "load_displacement.csv")
        deadline = time.time() + 300
        while time.time() < deadline and proc.poll() is None:
            if os.path.exists(csv) and sum(1 for _ in open(csv)) > args.stop:
                break
            time.sleep(0.05)
        indentrun.signal_mid_run(proc, getattr(signal, "SIG" + args.signal))
        out, _ = proc.communicate()
        code = proc.returncode
        indentrun.pass_on_unfreed(out)
    else:
        code, out = launch(args, first, options, part, ["-checkpoint_stop_after_step", str(args.stop)])
    print(out, end="")
    stopped_out = out
    ok = code == EXIT_CHECKPOINTED and os.path.exists(os.path.join(part, "checkpoint.h5")) \
        and not os.path.exists(os.path.join(part, "summary.json")) and "-restart" in out
    print(f"  stopped run: exit {code} (expected {EXIT_CHECKPOINTED}), checkpoint "
          f"{'present' if os.path.exists(os.path.join(part, 'checkpoint.h5')) else 'MISSING'}")
    if not ok:
        print("FAIL: the stopped run did not end with its checkpoint and a message naming -restart")
        return 1

    good = True
    if args.changed_option:
        opt, val = args.changed_option.split("=", 1)
        changed = list(options)
        changed[len(changed) - 1 - changed[::-1].index(opt) + 1] = val  # the last one given wins
        good &= refused(args, second, changed, part, ["-restart", part], opt, "other model option")
    if args.mesh_change:
        opt, val = args.mesh_change.split("=", 1)
        changed = list(options)
        changed[len(changed) - 1 - changed[::-1].index(opt) + 1] = val
        good &= refused(args, second, changed, part, ["-restart", part], opt, "other mesh")
    good &= refused(args, second, options, part, [], "-output_overwrite", "fresh run into it")

    code, out = launch(args, second, options, part, ["-restart", part])
    print(out, end="")
    if code != 0:
        print(f"FAIL: the restarted run exited with {code}")
        return 1
    good &= compare(ref, part, args.rtol, f"{first} -> {second} ranks")
    if args.expect_rejected:
        good &= check_rejected(ref, [ref_out], "uninterrupted run")
        good &= check_rejected(part, [stopped_out, out], "stopped and restarted run")
    print("restart reproduces the uninterrupted run" if good else "FAIL")
    return 0 if good else 1


if __name__ == "__main__":
    sys.exit(main())
