"""``linkrepro reproduce``: run every engine of each scene, diff, write the report."""
from __future__ import annotations

import ctypes
import gc
import multiprocessing
import os
import signal
import tempfile
import threading
import time
from contextlib import contextmanager
from pathlib import Path
from queue import Empty

import pandas as pd

from . import manifest, progress, readings, report_folder, run_folder
from .diff import total_counts
from .scene import Outcome, RunOptions
from .scenes import SCENES, TABLES, get


class OutputFolderError(OSError):
    """The output folder cannot be created or written to (found before the run starts)."""


class WorkerDiedError(RuntimeError):
    """A worker process died (killed by a signal: the system out of memory, a kill); the scenes
    that finished before are in place, the others as they were."""


class RunFailedError(RuntimeError):
    """The run finished, but an engine could not run (a printed program missing, ...).
    Everything else was written; ``failures`` lists what failed, ``done`` the scenes' summaries."""

    def __init__(self, failures: list[str], done: list[dict], out_dir: Path):
        self.failures, self.done = failures, done
        more = f"; {len(failures)} failures in all" if len(failures) > 1 else ""
        super().__init__(f"{failures[0]} (the other results are written{more}: see {out_dir / 'report.html'})")


def check_output_folder(out_dir: Path, names: list[str]) -> None:
    """Create ``out_dir`` and prove it writable (a probe file written and removed), and check
    that nothing the run writes at its top level is in the way: before any work is done, so
    that a bad ``--out`` fails at once and not after minutes.  ``OutputFolderError`` if not."""
    out_dir = Path(out_dir)
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except FileExistsError as exc:
        raise OutputFolderError(f"output folder {out_dir} is a file, not a folder") from exc
    except NotADirectoryError as exc:
        raise OutputFolderError(f"cannot create output folder {out_dir}: a part of that path is a file, "
                                "not a folder") from exc
    except OSError as exc:
        raise OutputFolderError(f"cannot create output folder {out_dir}: {exc.strerror or exc}") from exc
    try:
        with tempfile.NamedTemporaryFile(dir=out_dir, prefix=".linkrepro-write-check-"):
            pass
    except OSError as exc:
        raise OutputFolderError(f"cannot write to output folder {out_dir}: {exc.strerror or exc}") from exc
    for name in names:
        if (out_dir / name).exists() and not (out_dir / name).is_dir():
            raise OutputFolderError(f"{out_dir / name} is a file; the run writes the scene's folder there")
    for written in ("report.md", "report.html", manifest.FILE):
        if (out_dir / written).is_dir():
            raise OutputFolderError(f"{out_dir / written} is a folder; the run writes a file there")


IN_POOL_ENV = "LINKREPRO_IN_POOL"


def _groups(names: list[str]) -> list[list[str]]:
    """The named scenes by group (each group's scenes in the order named), the groups in the
    order they start (smallest ``start`` first)."""
    groups: dict[str, list[str]] = {}
    for name in names:
        groups.setdefault(get(name).group, []).append(name)
    return sorted(groups.values(), key=lambda group: min(get(n).start for n in group))


def _run_item(name: str, out_dir: Path, options: RunOptions, partial: Path) -> Outcome:
    """Run one scene into the run's partial folder, record the files it wrote in its outcome
    (``outcome.json``, written last, for the folder's report and verify), and put its folder in
    place whole (``harness/run_folder.py``)."""
    outcome = get(name).write(partial, options)
    outcome.files, outcome.run = run_folder.file_hashes(partial / name), partial.name
    outcome.save(partial)
    run_folder.place(partial / name, out_dir / name)
    return outcome


def _run_group(names: list[str], out_dir: Path, options: RunOptions, partial: Path) -> dict:
    results = {}
    for name in names:
        progress.note(name, "")
        results[name] = _run_item(name, out_dir, options, partial)
        progress.done(name)
    return results


def _die_with(parent: int) -> None:
    """Linux: this process is killed when ``parent`` dies (a run killed leaves no worker
    writing into its folder); elsewhere nothing."""
    try:
        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)      # PR_SET_PDEATHSIG
    except (AttributeError, OSError):
        return
    if os.getppid() != parent:          # it died before this line
        os._exit(1)


def _group_process(index: int, names: list[str], out_dir: Path, options: RunOptions, partial: Path,
                   parent: int, queue) -> None:
    """A worker process: run one group; send ("result" or "error", index, value) home.
    A Ctrl-C is the main process's to handle (it terminates the workers)."""
    _die_with(parent)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    gc.freeze()              # what it inherits (modules, compiled kernels) is never collected: full
                             # collections skip those ~250 000 objects (0.15-0.3 s a scene)
    os.environ[IN_POOL_ENV] = "1"                 # no pools of its own (figures drawn here)
    progress.attach(queue)
    try:
        queue.put(("result", index, _run_group(names, out_dir, options, partial)))
    except BaseException as exc:                  # noqa: BLE001 - raised again in the main process
        queue.put(("error", index, exc))


@contextmanager
def _interrupt_deferred():
    """A Ctrl-C inside the block is raised (as KeyboardInterrupt) when the block ends (in the
    main thread, which alone receives signals; elsewhere nothing).  Where Ctrl-C is ignored (a
    run started with SIGINT ignored, as a shell's background job is), it stays ignored."""
    if threading.current_thread() is not threading.main_thread() \
            or signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
        yield
        return
    caught = []
    previous = signal.signal(signal.SIGINT, lambda *_: caught.append(True))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if caught:
        raise KeyboardInterrupt


def _run_groups(groups: list[list[str]], out_dir: Path, options: RunOptions, partial: Path) -> dict:
    """Every group's results: one process per group, as many at once as there are cores
    (forked where the system can: this process has imported everything and compiled nothing,
    so a worker starts at once; else spawned); else here, in turn.  Each scene is written into
    ``partial`` (the run's partial folder) and put in place in ``out_dir`` whole.
    On a Ctrl-C (or any error) every worker is terminated and joined before it goes on; a
    worker killed by a signal is a ``WorkerDiedError``."""
    workers = min(len(groups), os.cpu_count() or 1)
    if workers < 2 or os.environ.get(IN_POOL_ENV):
        return {k: v for names in groups for k, v in _run_group(names, out_dir, options, partial).items()}
    forks = "fork" in multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("fork" if forks else "spawn")
    queue, waiting, running, results = context.Queue(), list(enumerate(groups)), {}, {}
    prepared = False
    try:
        while waiting or running:
            while waiting and len(running) < workers:
                index, names = waiting.pop(0)
                worker = context.Process(target=_group_process,
                                         args=(index, names, out_dir, options, partial, os.getpid(), queue))
                with _interrupt_deferred():           # never half-started
                    worker.start()
                    running[index] = worker
            if not prepared:         # what the reports need, loaded while the workers run (no scene needs it)
                report_folder.prepare()
                prepared = True
            try:
                kind, key, value = queue.get(timeout=0.2)
            except Empty:
                dead = [(i, w.exitcode) for i, w in running.items() if w.exitcode not in (None, 0)]
                if dead:
                    index, code = dead[0]
                    how = f"killed by {signal.Signals(-code).name}" if code < 0 else f"exit code {code}"
                    raise WorkerDiedError(f"a reproduce worker died ({how}) while running {', '.join(groups[index])}; "
                                          "the scenes finished before are in place, the others as they were") from None
                continue
            if kind == "error":
                raise value
            if kind == "result":
                results.update(value)
                running.pop(key).join()
            else:
                progress.handle((kind, key, value))
    finally:
        for worker in running.values():
            worker.terminate()
        for worker in running.values():
            worker.join()
    return results


def reproduce(names: list[str] | None, out_dir: Path, measure_readings: bool = True,
              command: str | None = None) -> list[Outcome]:
    """Run the named scenes (all by default; ``linkrepro scenes`` lists them) into DIR.  The scenes of a group run in one process, the groups side by
    side on the cores; a progress line on standard error when it is a terminal.

    Before any work: ``OutputFolderError`` if DIR cannot be written, ``readings.CompilerError``
    if the OCR readings need gfortran and it is missing (``measure_readings=False`` skips
    them).  Each scene is written whole or not at all, its outcome kept in its folder
    (``harness/run_folder.py``), and DIR/report.md and DIR/report.html show every scene run into
    DIR, this run's and earlier ones', with the outputs of the other commands found there
    (``harness/report_folder.py``), and DIR/manifest.json says how they were made
    (``harness/manifest.py``; ``command``: the command line, by default the one that runs the
    same).  After the run, if an engine could not run: ``RunFailedError`` (everything else is
    written, the failures are in the reports).  Interrupted (Ctrl-C: ``KeyboardInterrupt``, raised
    again) or a worker killed (``WorkerDiedError``), the scenes that finished are in place and the
    manifest and the reports are rewritten for them (the report says the run did not finish);
    killed outright, the folder holds every scene as before or as the run finished it."""
    started = manifest.now()
    command = command or manifest.command_line(["reproduce", *(names or []), "--out", str(out_dir),
                                                *([] if measure_readings else ["--skip-readings"])])
    names = list(dict.fromkeys(names or SCENES))
    out_dir = Path(out_dir)
    check_output_folder(out_dir, names)
    if measure_readings:
        readings.require_compiler({name: (TABLES[name].table, TABLES[name].readings) for name in names
                                   if name in TABLES})
    start, run_id = time.perf_counter(), None
    try:
        with progress.Bar(len(names)), run_folder.partial(out_dir) as partial:
            run_id = partial.name
            results = _run_groups(_groups(names), out_dir, RunOptions(measure_readings), partial)
    except BaseException:                 # a Ctrl-C, a worker killed: record what finished, if anything
        with _interrupt_deferred():
            run_folder.remove_own_partials(out_dir)
            finished = [name for name in names if run_id and _written_by(out_dir, name, run_id)]
            if finished:
                record(out_dir, command, finished, started,
                       f"The latest reproduce run was stopped after {time.perf_counter() - start:.2f} s, before its "
                       f"end: it wrote {len(finished)} of its {len(names)} scenes ({', '.join(finished)})"
                       + ("." if len(finished) == len(names) else "; the others are as they were before it."))
        raise
    done = [results[name] for name in names]
    failures = [f"{item.scene}: {failure}" for item in done for failure in item.failures]
    with _interrupt_deferred():           # a Ctrl-C now waits for the manifest and the reports
        record(out_dir, command, names, started, f"The latest reproduce run ({len(names)} of {len(SCENES)} scenes) "
                                                 f"took {time.perf_counter() - start:.2f} s.")
    if failures:
        raise RunFailedError(failures, done, out_dir)
    return done


def _written_by(out_dir: Path, name: str, run_id: str) -> bool:
    """Whether ``out_dir/name`` is the scene as the run ``run_id`` wrote it."""
    outcome, _ = run_folder.read_scene(out_dir, name)
    return outcome is not None and outcome.run == run_id


def record(out_dir: Path, command: str, scenes: list[str], started: str, latest: str) -> None:
    """Write the folder's manifest.json (``scenes``: the sections this run wrote) and its
    reports (``latest``: a line on the run), under the folder's lock: two runs into one folder
    that finish together keep each other's sections."""
    with run_folder.locked(out_dir):
        manifest.write(out_dir, command, scenes=scenes, started=started)
        report_folder.write(out_dir, latest)


def cell_totals(done: list[Outcome]) -> pd.Series:
    """Every table scene's cells over every engine, by what they count as (``diff.count_cells``
    added up by ``diff.total_counts``): the numbers of the run report's and the CLI's headline."""
    return total_counts([item.counts for item in done if item.counts is not None])
