"""Forward runs of indent for a fit, each kept in a directory named by a hash of everything that decides its
curve (the model file's text and the options). A fit run again, or continued after an interruption, reruns
nothing that finished, and a run stopped with a checkpoint continues from it. K runs go at once, each on R
ranks, through a launcher (mpiexec here, srun inside a Slurm allocation).
"""
import concurrent.futures
import hashlib
import json
import os
import shlex
import signal
import subprocess
import threading
import time

DONE = "fit-run.json"      # written last, atomically: a run with it is finished (or failed for good)
LOG = "fit-run.log"
INTERRUPTED = (75, 130, 143, -2, -9, -15)   # stopped by a signal: run again, never cached as a failure


def child_env():
    """The runs' environment. Open MPI binds a job of one or two ranks to cores counted from core 0, every mpiexec
    alike: runs at once would share core 0 (two 1-rank runs took twice as long each). Unbound, the scheduler
    spreads them; a launcher that places ranks itself (srun) ignores this, and a user's own setting is kept."""
    env = dict(os.environ)
    env.setdefault("OMPI_MCA_hwloc_base_binding_policy", "none")
    return env


class Stopped(Exception):
    """The fit was told to stop (SIGTERM, SIGINT): runs in progress were ended."""


def run_key(model_text, options):
    """The cache key of a run: its model file's text and its options, in order."""
    h = hashlib.sha256()
    h.update(model_text.encode())
    h.update(b"\0")
    h.update(json.dumps(options).encode())
    return h.hexdigest()[:20]


class Runner:
    """Runs indent in OUT/runs/<key>: submit() returns a future of the run's record (a dict: key, dir,
    returncode, seconds, cached)."""

    def __init__(self, root, indent, launcher, np_, jobs, log=print):
        self.root, self.indent, self.launcher, self.np, self.log = root, indent, launcher, np_, log
        os.makedirs(root, exist_ok=True)
        self.pool = concurrent.futures.ThreadPoolExecutor(max_workers=jobs)
        self.futures = {}
        self.procs = set()
        self.lock = threading.Lock()
        self.stopping = False
        self.counts = {"run": 0, "cached": 0, "failed": 0, "seconds": 0.0}

    def command(self, model, options, outdir, resume):
        launch = [a.replace("{np}", str(self.np)) for a in shlex.split(self.launcher)]
        # no fields unless the options ask for them (the imprint's runs): those come after, and the last wins
        return launch + [self.indent, "-options_file", model, "-output_fields", "0"] + options + [
            "-output_dir", outdir, "-quiet"] + (["-restart", outdir] if resume else ["-output_overwrite"])

    def _launch(self, cmd, d):
        with open(os.path.join(d, LOG), "a") as log:
            log.write(" ".join(shlex.quote(c) for c in cmd) + "\n")
            log.flush()
            proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, start_new_session=True, env=child_env())
            with self.lock:
                self.procs.add(proc)
            rc = proc.wait()
            with self.lock:
                self.procs.discard(proc)
        return rc

    def submit(self, model, model_text, options):
        key = run_key(model_text, options)
        with self.lock:
            fut = self.futures.get(key)
            if fut is None or (fut.done() and not fut.cancelled() and fut.exception() is not None):
                fut = self.pool.submit(self._run, key, model, options)
                self.futures[key] = fut
        return fut

    def pending(self):
        with self.lock:
            running = sum(1 for f in self.futures.values() if f.running())
            queued = sum(1 for f in self.futures.values() if not f.done() and not f.running())
        return running, queued

    def _run(self, key, model, options):
        d = os.path.join(self.root, key)
        done = os.path.join(d, DONE)
        if os.path.isfile(done):
            with open(done) as f:
                rec = json.load(f)
            rec.update(cached=True, dir=d)
            with self.lock:
                self.counts["cached"] += 1
            return rec
        if self.stopping:
            raise Stopped()
        os.makedirs(d, exist_ok=True)
        t0 = time.time()
        # a run the fit's interruption stopped with a checkpoint continues from it; should that fail (a checkpoint
        # of another indent, say), the run starts afresh
        resume = os.path.isfile(os.path.join(d, "checkpoint.h5"))
        rc = self._launch(self.command(model, options, d, resume), d)
        if resume and rc and rc not in INTERRUPTED and not self.stopping:
            rc = self._launch(self.command(model, options, d, False), d)
        seconds = time.time() - t0
        if self.stopping or rc in INTERRUPTED:
            raise Stopped()
        rec = {"key": key, "model": model, "options": options, "returncode": rc, "seconds": seconds}
        tmp = done + ".tmp"
        with open(tmp, "w") as f:
            json.dump(rec, f, indent=1)
        os.replace(tmp, done)
        with self.lock:
            self.counts["run"] += 1
            self.counts["seconds"] += seconds
            if rc:
                self.counts["failed"] += 1
        if rc:
            self.log(f"fit: a forward run failed (status {rc}); its log: {os.path.join(d, LOG)}")
        rec.update(cached=False, dir=d)
        return rec

    def stop(self, sig=signal.SIGTERM):
        """Ends the runs in progress (indent checkpoints and exits on SIGTERM) and drops the queued ones."""
        with self.lock:
            self.stopping = True
            procs = list(self.procs)
            futs = list(self.futures.values())
        for f in futs:
            f.cancel()
        for p in procs:
            try:
                os.killpg(p.pid, sig)
            except ProcessLookupError:
                pass

    def shutdown(self):
        self.stop()
        self.pool.shutdown(wait=True, cancel_futures=True)
