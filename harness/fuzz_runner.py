"""The fuzz's runner: calls in worker processes, each classified.

The calls run in persistent worker processes ('spawn'), one call at a time per worker, with a
timeout the parent measures; a worker that dies or times out is replaced.  A worker's names,
scrubs and checks come from a ``context`` function the fuzz command names
(``"module:function"``, returning a ``Context``): this module knows no thesis.

Outcomes of a call:

- ``ok``: it returned, and the result holds no NaN or infinity (documented NaN aside, a
  ``scrub`` removes it);
- ``typed``: ValueError, TypeError, a LinkageError (with its input angle) or QPError;
- findings: ``untyped`` (any other exception, numpy's LinAlgError and numba's errors
  included), ``nan`` (a non-finite value in a result from finite inputs), ``angle`` (a
  LinkageError without its input angle from a function that has input angles),
  ``accepted`` (a NaN or infinite argument, or an angle array that is not 1-D, returned a
  result instead of a ValueError), ``violated`` (a result that breaks what the function
  promises: its entry's ``check``), ``crash`` (the worker died: a signal, a FORTRAN STOP) and
  ``hang`` (the timeout).
"""
from __future__ import annotations

import collections
import dataclasses
import importlib
import json
import math
import multiprocessing
import multiprocessing.connection
import os
import re
import shlex
import shutil
import signal
import sys
import tempfile
import time
import traceback
import warnings
from dataclasses import dataclass, field
from typing import Callable

from .fuzz_calls import Job

FINDINGS = ("untyped", "nan", "angle", "accepted", "violated", "crash", "hang")
OUTCOMES = ("ok", "typed") + FINDINGS
STARTUP_SECONDS = 900          # importing linkrepro may rebuild the FORTRAN first
MEMORY_BYTES = 4 << 30         # address space of a worker: a runaway allocation is a MemoryError



@dataclass
class Context:
    """What a worker evaluates calls with: the names a call text may use, the scrubs that
    remove a result's documented NaN, the checks a result must pass (each ``(arguments,
    result) -> what is broken, or None``), and the calls that compile the kernels first."""
    namespace: dict
    scrubs: dict[str, Callable] = field(default_factory=dict)
    checks: dict[str, Callable] = field(default_factory=dict)
    warm_up: tuple[str, ...] = ()


def load_context(reference: str) -> Context:
    """The ``Context`` a ``"module:function"`` reference builds."""
    module, function = reference.split(":")
    return getattr(importlib.import_module(module), function)()


def warm_up(context: Context) -> None:
    """Run the context's warm-up calls in a new worker, so that a call's time is its own."""
    for text in context.warm_up:
        eval(text, dict(context.namespace))          # noqa: S307 - fixed text


def execute(text: str, context: Context, angles: bool = False, scrub: str | None = None, refused=(),
            check: str | None = None) -> dict:
    """Evaluate one call text and classify what happened (everything but crash and hang)."""
    ns = context.namespace
    start = time.perf_counter()
    try:
        result = eval(text, dict(ns))          # noqa: S307 - the fuzz's own generated text
    except (Exception, SystemExit) as exc:     # noqa: BLE001 - classifying is the point
        out = describe_error(exc, angles)
    else:
        where = nonfinite(context.scrubs[scrub](result) if scrub else result)
        broken = None if (where or refused or check is None) else context.checks[check](arguments_of(text, ns), result)
        outcome = "accepted" if refused else ("nan" if where else ("violated" if broken else "ok"))
        out = {"outcome": outcome, "detail": where or broken or ""}
    out["seconds"] = round(time.perf_counter() - start, 4)
    return out


def describe_error(exc: BaseException, angles: bool) -> dict:
    """typed / untyped / angle, with the traceback's last line and innermost frames."""
    from linkrepro.errors import LinkageError
    frames = traceback.extract_tb(exc.__traceback__)
    ours = [f for f in frames if "site-packages" not in f.filename and "/lib/python" not in f.filename
            and f.filename != "<string>"]
    out = {"exception": type(exc).__name__, "message": (str(exc).splitlines() or [""])[0][:300],
           "where": _frame(frames[-1]) if frames else "", "library_where": _frame(ours[-1]) if ours else ""}
    if isinstance(exc, LinkageError):
        named = exc.angle_deg is not None and math.isfinite(float(exc.angle_deg))
        out["outcome"] = "typed" if named or not angles else "angle"
    else:
        out["outcome"] = "typed" if is_typed(exc) else "untyped"
    return out


def is_typed(exc: BaseException) -> bool:
    """ValueError, TypeError or QPError, but not numpy's LinAlgError nor numba's errors
    (those should have been turned into a typed error before reaching the kernel)."""
    import numpy as np
    from linkrepro.errors import QPError
    if isinstance(exc, np.linalg.LinAlgError) or type(exc).__module__.startswith("numba"):
        return False
    return isinstance(exc, (ValueError, TypeError, QPError))


def _frame(f) -> str:
    path = f.filename
    for marker in ("/linkrepro/", "/work/main/"):
        if marker in path:
            path = path.split(marker, 1)[1]
    return f"{path}:{f.lineno} in {f.name}"


def nonfinite(value, path: str = "result", depth: int = 0) -> str | None:
    """Where the first NaN or infinity in a returned value is (dicts, sequences, arrays,
    DataFrames, dataclasses), or None."""
    import numpy as np
    pd = sys.modules.get("pandas")
    if depth > 6:
        return None
    if pd is not None and isinstance(value, (pd.DataFrame, pd.Series)):
        frame = value.to_frame() if isinstance(value, pd.Series) else value
        items = ((f"[{c!r}]", frame[c].to_numpy()) for c in frame.columns)
    elif isinstance(value, dict):
        items = ((f"[{k!r}]", v) for k, v in value.items())
    elif isinstance(value, (list, tuple)):
        items = ((f"[{i}]", v) for i, v in enumerate(value))
    elif dataclasses.is_dataclass(value) and not isinstance(value, type):
        items = ((f".{f.name}", getattr(value, f.name)) for f in dataclasses.fields(value))
    elif isinstance(value, np.ndarray) and value.dtype == object:
        items = ((f"[{i}]", v) for i, v in enumerate(value.ravel()[:1000]))
    elif isinstance(value, (float, complex, np.ndarray, np.floating, np.complexfloating)):
        arr = np.asarray(value)
        if arr.dtype.kind in "fc" and not np.all(np.isfinite(arr)):
            at = tuple(int(i) for i in np.argwhere(~np.isfinite(arr))[0])
            return f"{path}{list(at) if at else ''} = {arr[at]}"
        return None
    else:
        return None
    for key, item in items:
        where = nonfinite(item, path + key, depth + 1)
        if where:
            return where
    return None


def arguments_of(text: str, ns: dict) -> tuple[list, dict]:
    """The positional and keyword arguments a call text passes, each evaluated as the call
    evaluates it."""
    import ast
    call = ast.parse(text, mode="eval").body

    def value(node):
        return eval(compile(ast.Expression(node), "<argument>", "eval"), dict(ns))   # noqa: S307 - our own text
    return [value(a) for a in call.args], {k.arg: value(k.value) for k in call.keywords}


# --- a worker: one call at a time ---------------------------------------------------------

def _serve(conn, log_path: str, context_reference: str) -> None:
    """Worker main: output to a log (FORTRAN writes to fd 1), limited memory, one call at a
    time until told to stop (None)."""
    fd = os.open(log_path, os.O_WRONLY | os.O_CREAT | os.O_APPEND)
    os.dup2(fd, 1)
    os.dup2(fd, 2)
    try:
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_BYTES, MEMORY_BYTES))
    except (ImportError, ValueError, OSError):
        pass
    warnings.simplefilter("ignore")
    context = load_context(context_reference)
    warm_up(context)
    conn.send("ready")
    while (message := conn.recv()) is not None:
        os.ftruncate(1, 0)                   # the log holds this call's output only
        text, angles, scrub, refused, check = message
        conn.send(execute(text, context, angles, scrub, refused, check))


# --- the parent: workers, timeouts, replacements -----------------------------------------

class Worker:
    """One persistent child process."""

    def __init__(self, ctx, log_path: str, context: str):
        self.log_path = log_path
        self.conn, child = ctx.Pipe()
        self.proc = ctx.Process(target=_serve, args=(child, log_path, context), daemon=True)
        self.proc.start()
        child.close()
        self.job, self.deadline = None, math.inf

    def wait_ready(self) -> "Worker":
        if not self.conn.poll(STARTUP_SECONDS):
            raise RuntimeError(f"a fuzz worker did not start in {STARTUP_SECONDS} s:\n{self.log_tail()}")
        try:
            self.conn.recv()
        except EOFError:
            raise RuntimeError(f"a fuzz worker died while starting:\n{self.log_tail()}") from None
        return self

    def submit(self, job: Job, timeout: float) -> None:
        self.conn.send((job.text, job.angles, job.scrub, job.refused, job.check))
        self.job, self.deadline = job, time.monotonic() + (timeout if job.timeout is None else job.timeout)

    def log_tail(self, chars: int = 600) -> str:
        try:
            with open(self.log_path, errors="replace") as f:
                return f.read()[-chars:].strip()
        except OSError:
            return ""

    def death(self) -> str:
        self.proc.join(5)
        code = self.proc.exitcode
        if code is None:
            return "the worker closed its pipe"
        how = f"killed by {signal.Signals(-code).name}" if code < 0 else f"exit code {code}"
        return how + (" (a FORTRAN STOP exits 0)" if code == 0 else "")

    def stop(self, kill: bool = False) -> None:
        if not kill:
            try:
                self.conn.send(None)
            except OSError:
                pass
            self.proc.join(5)
        if self.proc.is_alive():
            self.proc.kill()
            self.proc.join()
        self.conn.close()


def run(jobs: list, context: str, timeout: float = 20.0, workers: int = 2, progress=None) -> list:
    """Run the jobs on ``workers`` persistent processes, each with the ``Context`` the
    ``"module:function"`` reference ``context`` builds; one result dict per job, in order.
    ``progress(done, total)``: called after each call."""
    for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS"):
        os.environ.setdefault(var, "1")
    ctx = multiprocessing.get_context("spawn")
    logs = tempfile.mkdtemp(prefix="linkrepro-fuzz-")
    pool = [Worker(ctx, os.path.join(logs, f"worker{k}.log"), context) for k in range(max(1, workers))]
    pool = [w.wait_ready() for w in pool]
    todo, results, done = collections.deque(jobs), {}, 0
    try:
        while todo or any(w.job for w in pool):
            for w in pool:
                if w.job is None and todo:
                    w.submit(todo.popleft(), timeout)
            busy = [w for w in pool if w.job]
            wait = max(0.0, min(w.deadline for w in busy) - time.monotonic())
            ready = multiprocessing.connection.wait([w.conn for w in busy], timeout=wait)
            for k, w in enumerate(pool):
                if w.job is None or (w.conn not in ready and time.monotonic() < w.deadline):
                    continue
                result, replace = _collect(w, w.conn in ready, timeout if w.job.timeout is None else w.job.timeout)
                results[w.job.index] = result
                done += 1
                w.job = None
                if replace:
                    w.stop(kill=True)
                    pool[k] = Worker(ctx, os.path.join(logs, f"worker{k}-{done}.log"), context).wait_ready()
                if progress:
                    progress(done, len(jobs))
    finally:
        for w in pool:
            w.stop()
        shutil.rmtree(logs, ignore_errors=True)
    return [results[job.index] for job in jobs]


def _collect(w: Worker, ready: bool, timeout: float) -> tuple[dict, bool]:
    """The result of a worker's call, or a crash or hang record; and whether to replace it."""
    if ready:
        try:
            return w.conn.recv(), False
        except (EOFError, OSError):
            return {"outcome": "crash", "detail": w.death(), "log": w.log_tail()}, True
    return {"outcome": "hang", "detail": f"no answer in {timeout:g} s", "log": w.log_tail()}, True


# --- the report --------------------------------------------------------------------------

@dataclass
class Report:
    jobs: list
    results: list
    seconds: float
    seed: int
    timeout: float
    workers: int
    counts: dict = field(default_factory=dict)
    findings: list = field(default_factory=list)

    def __post_init__(self):
        self.counts = collections.defaultdict(collections.Counter)
        for job, res in zip(self.jobs, self.results):
            self.counts[job.entry][res["outcome"]] += 1
            if res["outcome"] in FINDINGS:
                self.findings.append({"index": job.index, "entry": job.entry, "call": job.text,
                                      "hostile": list(job.hostile), "group": group_key(job, res), **res})


def group_key(job: Job, res: dict) -> str:
    """The cause of a finding, with numbers and indices left out."""
    outcome = res["outcome"]
    if outcome == "accepted":
        cause = "refusable argument returned a result: " + ", ".join(sorted(set(job.refused)))
    elif outcome == "nan":
        cause = "non-finite value in " + re.sub(r"\[[\d, ]*\]| = .*", "", res["detail"])
    elif outcome == "violated":
        cause = _normalise(res["detail"])
    elif outcome in ("crash", "hang"):
        cause = res["detail"]
    else:
        cause = f"{res['exception']}: {_normalise(res['message'])} [{res.get('library_where', '')}]"
    return f"{outcome} | {job.entry} | {cause}"


def _normalise(message: str) -> str:
    message = re.sub(r"'[^']*'|\"[^\"]*\"", "'…'", message)
    return re.sub(r"(?<![\w.])[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(?!\w)", "#", message)[:160]


def replay_command(text: str) -> str:
    return f"python -m linkrepro.harness.fuzz --replay {shlex.quote(text)}"


def format_report(report: Report, every: bool = False) -> str:
    """Counts per entry point and outcome, then the findings grouped by cause."""
    name_width = max(map(len, report.counts)) if report.counts else 10
    lines = [f"linkrepro fuzz: {len(report.jobs)} calls, seed {report.seed}, timeout {report.timeout:g} s, "
             f"{report.workers} workers, {report.seconds:.1f} s", "",
             f"{'entry point':{name_width}} " + " ".join(f"{o:>8}" for o in OUTCOMES)]
    total = collections.Counter()
    for name, counter in report.counts.items():
        total.update(counter)
        lines.append(f"{name:{name_width}} " + " ".join(f"{counter[o]:8d}" for o in OUTCOMES))
    lines.append(f"{'total':{name_width}} " + " ".join(f"{total[o]:8d}" for o in OUTCOMES))
    timed = [(r.get("seconds", 0.0), j) for j, r in zip(report.jobs, report.results)]
    if timed:
        seconds, job = max(timed, key=lambda t: t[0])
        lines.append(f"slowest call that answered: {seconds:.2f} s, {job.text}")
    lines += ["", format_findings(report, every)]
    return "\n".join(lines)


def format_findings(report: Report, every: bool = False) -> str:
    """Each group of findings: its cause, count, last traceback line and one reproducer (the
    shortest), or every reproducer with ``every``."""
    groups = collections.defaultdict(list)
    for f in report.findings:
        groups[f["group"]].append(f)
    lines = [f"findings: {len(report.findings)} calls in {len(groups)} groups"]
    for key, items in sorted(groups.items(), key=lambda kv: kv[0]):
        lines.append(f"\n[{len(items)}] {key}")
        shown = items if every else [min(items, key=lambda f: len(f["call"]))]
        for f in shown:
            if "exception" in f:
                lines.append(f"    {f['exception']}: {f['message']}")
            if f.get("detail"):
                lines.append(f"    {f['detail']}")
            if f["hostile"]:
                lines.append(f"    hostile: {', '.join(f['hostile'])}")
            if f.get("where") and f.get("where") != f.get("library_where"):
                lines.append(f"    innermost frame: {f['where']}")
            if f.get("log"):
                lines.append("    worker output: " + f["log"].replace("\n", " | ")[-300:])
            lines.append(f"    {replay_command(f['call'])}")
    return "\n".join(lines)


def write_report(report: Report, path: str) -> None:
    """JSON (everything) or CSV (one row per finding), by the file's extension."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    if path.endswith(".csv"):
        import csv
        columns = ["index", "entry", "outcome", "group", "exception", "message", "library_where", "where",
                   "detail", "call"]
        with open(path, "w", newline="") as f:
            writer = csv.DictWriter(f, columns, extrasaction="ignore")
            writer.writeheader()
            writer.writerows(report.findings)
        return
    with open(path, "w") as f:
        json.dump({"seed": report.seed, "calls": len(report.jobs), "timeout": report.timeout,
                   "workers": report.workers, "seconds": round(report.seconds, 1),
                   "counts": {k: dict(v) for k, v in report.counts.items()},
                   "findings": report.findings}, f, indent=1)
