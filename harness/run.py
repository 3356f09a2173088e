"""``linkrepro reproduce``: run every engine of each scene, diff, write the report."""
from __future__ import annotations

import multiprocessing
import os
import signal
import tempfile
import time
from contextlib import contextmanager
from pathlib import Path
from queue import Empty

import pandas as pd

from . import appendix, arithmetic, case3_convergence, cognate_search, identities, progress, rahman1991, rahman1996_figures, readings, register as register_mod
from .csv_output import write_csv
from .diff import diff_scene, summary
from .engines import ENGINES, PrintedProgramError
from .published_tables import PublishedTable
from .report import plot_scene, scene_report
from .scenes import SCENES, get

SPECIAL = (appendix.NAME, rahman1996_figures.NAME, rahman1991.NAME)


class OutputFolderError(OSError):
    """The output folder cannot be created or written to (found before the run starts)."""


class RunFailedError(RuntimeError):
    """The run finished, but an engine could not run (a printed program missing, ...).
    Everything else was written; ``failures`` lists what failed, ``done`` the scenes' summaries."""

    def __init__(self, failures: list[str], done: list[dict], out_dir: Path):
        self.failures, self.done = failures, done
        more = f"; {len(failures)} failures in all" if len(failures) > 1 else ""
        super().__init__(f"{failures[0]} (the other results are written{more}: see {out_dir / 'report.md'})")


def check_output_folder(out_dir: Path, names: list[str], convergence: bool = False) -> None:
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
    files = ["report.md"] + ([f"case3_convergence.{ext}" for ext in ("csv", "png", "md")] if convergence else [])
    for name in files:
        if (out_dir / name).is_dir():
            raise OutputFolderError(f"{out_dir / name} is a folder; the run writes a file there")


def run_scene(name: str, out_dir: Path, measure_readings: bool = True) -> dict:
    """Run one scene; write DIR/<scene>/...; return its summary counts and timings.  An
    engine that cannot run (``PrintedProgramError``) is listed in ``failures`` and in the
    scene's report; the other engines still run."""
    scene = get(name)
    register = register_mod.load()
    published = PublishedTable.load(scene.table)
    target = out_dir / scene.name
    target.mkdir(parents=True, exist_ok=True)
    published.text.to_csv(target / "published.csv", index=False)

    results, timings, failures = {}, {}, []
    for engine in ENGINES:
        start = time.perf_counter()
        try:
            frame = scene.run(engine)
        except PrintedProgramError as exc:
            failures.append(f"engine {engine} failed: {exc}")
            continue
        timings[engine] = time.perf_counter() - start
        write_csv(frame, target / f"{engine}.csv", "%.9g")
        results[engine] = frame

    diff = diff_scene(scene, published, results, register)
    write_csv(diff, target / "diff.csv", "%.9g")
    plots = plot_scene(scene, published, results, target)
    extra = "\n".join(f"**{f}**" for f in failures)
    sums = identities.sum_checks(scene.table, published)
    if len(sums):                              # the table's own arithmetic
        sums = identities.with_register(sums, diff)
        write_csv(sums, target / "identities.csv", "%.9g")
        extra += "\n\n" + identities.as_markdown(sums)
    case = cognate_search.case_of(scene.table)
    if case:                                   # the search over the reconstructed cognate loads
        found = cognate_search.search(case)
        write_csv(found, target / "cognate_search.csv", "%.9g")
        extra += "\n\n" + cognate_search.as_markdown(found)
    if readings.has_readings(scene.table):     # an empty measurement says why it is empty
        extra += "\n\n" + (readings.as_markdown(readings.measure(scene.table)) if measure_readings else
                           "## Reading alternatives\n\nNot measured (skipped on request: --skip-readings).")
    (target / "report.md").write_text(scene_report(scene, diff, timings, register, plots, extra))
    return {"scene": scene.name, "title": scene.title, "counts": summary(diff), "timings": timings,
            "failures": failures}


#: the job that writes out/case3_convergence.*, run with the ali1977 scenes
CASE3 = "case3-convergence"
#: the groups of scenes, in the order they start: each group runs in one process (its scenes
#: share one computation), the groups side by side on the cores.  The 1991 example (the
#: longest) compiles the Newton kernels first; the 1996 tables come last, when the kernels
#: they share with it can be loaded from numba's cache instead of compiled a second time.
GROUP_ORDER = ("rahman1991", "ali1977", CASE3, "rahman1996")
IN_POOL_ENV = "LINKREPRO_IN_POOL"


def _group(name: str) -> int:
    return next(k for k, prefix in enumerate(GROUP_ORDER) if name.startswith(prefix))


def _run_item(name: str, out_dir: Path, measure_readings: bool):
    """One scene's summary, a special scene's result, or a failure message (str)."""
    if name == CASE3:
        return write_case3(out_dir)
    module = {m.NAME: m for m in (appendix, rahman1996_figures, rahman1991)}.get(name)
    if module is None:
        return run_scene(name, out_dir, measure_readings)
    try:
        return module.run(out_dir)
    except PrintedProgramError as exc:
        return f"{name}: not written, engine printed failed: {exc}"


def _run_group(names: list[str], out_dir: Path, measure_readings: bool) -> dict:
    results = {}
    for name in names:
        progress.note(name, "")
        results[name] = _run_item(name, out_dir, measure_readings)
        progress.done(name)
    return results


def _group_process(index: int, names: list[str], out_dir: Path, measure_readings: bool, queue) -> None:
    """A worker process: run one group; send ("result" or "error", index, value) home.
    A Ctrl-C is the main process's to handle (it terminates the workers)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    os.environ[IN_POOL_ENV] = "1"                 # no pools of its own (figures drawn here)
    progress.attach(queue)
    try:
        queue.put(("result", index, _run_group(names, out_dir, measure_readings)))
    except BaseException as exc:                  # noqa: BLE001 - raised again in the main process
        queue.put(("error", index, exc))


@contextmanager
def _interrupt_deferred():
    """A Ctrl-C inside the block is raised (as KeyboardInterrupt) when the block ends."""
    caught = []
    previous = signal.signal(signal.SIGINT, lambda *_: caught.append(True))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if caught:
        raise KeyboardInterrupt


def _run_groups(groups: list[list[str]], out_dir: Path, measure_readings: bool) -> dict:
    """Every group's results: one process per group, as many at once as there are cores
    (forked where the system can: this process has imported everything and compiled nothing,
    so a worker starts at once; else spawned); else here, in turn.
    On a Ctrl-C (or any error) every worker is terminated and joined before it goes on."""
    workers = min(len(groups), os.cpu_count() or 1)
    if workers < 2 or os.environ.get(IN_POOL_ENV):
        return {k: v for names in groups for k, v in _run_group(names, out_dir, measure_readings).items()}
    context = multiprocessing.get_context("fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn")
    queue, waiting, running, results = context.Queue(), list(enumerate(groups)), {}, {}
    try:
        while waiting or running:
            while waiting and len(running) < workers:
                index, names = waiting.pop(0)
                worker = context.Process(target=_group_process, args=(index, names, out_dir, measure_readings, queue))
                with _interrupt_deferred():           # never half-started
                    worker.start()
                    running[index] = worker
            try:
                kind, key, value = queue.get(timeout=0.2)
            except Empty:
                dead = [w.exitcode for w in running.values() if w.exitcode not in (None, 0)]
                if dead:
                    raise RuntimeError(f"a reproduce worker died (exit code {dead[0]})") from None
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


def write_case3(out_dir: Path) -> None:
    """out/case3_convergence.{csv,png,md}: the Case III speed-against-error sweep."""
    data = case3_convergence.case3_data(repeat=1)
    write_csv(data, out_dir / "case3_convergence.csv", "%.6g")
    case3_convergence.plot_case3(data, out_dir / "case3_convergence.png")
    (out_dir / "case3_convergence.md").write_text(
        "# Case III: speed against error\n" + "\n".join(case3_convergence.case3_sweep(1, data))
        + "\n\n![case3 convergence](case3_convergence.png)\n")


def reproduce(names: list[str] | None, out_dir: Path, measure_readings: bool = True) -> list[dict]:
    """Run the named scenes (all by default) and write DIR/report.md over them; with all
    scenes (or ali1977-table3) also the Case III speed-against-error sweep.  The scenes
    of each thesis run in one process, the theses side by side on the cores; a progress
    line on standard error when it is a terminal.

    Before any work: ``OutputFolderError`` if DIR cannot be written, ``readings.CompilerError``
    if the OCR readings need gfortran and it is missing (``measure_readings=False`` skips
    them).  After the run, if an engine could not run: ``RunFailedError`` (everything else
    is written, the failures are in the reports)."""
    measure_convergence = not names or "ali1977-table3" in names
    names = list(dict.fromkeys(names or list(SCENES) + list(SPECIAL)))
    out_dir = Path(out_dir)
    check_output_folder(out_dir, names, measure_convergence)
    if measure_readings:
        readings.require_compiler({name: get(name).table for name in names if name not in SPECIAL})
    start = time.perf_counter()
    items = names + ([CASE3] if measure_convergence else [])
    groups = [[n for n in items if _group(n) == k] for k in range(len(GROUP_ORDER))]
    groups = sorted((g for g in groups if g), key=lambda g: _group(g[0]))
    with progress.Bar(len(items)):
        results = _run_groups(groups, out_dir, measure_readings)
    done = [results[name] for name in names if name not in SPECIAL]
    failures = [f"{item['scene']}: {failure}" for item in done for failure in item["failures"]]
    failures += [r for r in results.values() if isinstance(r, str)]

    def special(module):
        result = results.get(module.NAME)
        return None if result is None or isinstance(result, str) else result

    curves, figures, example = special(appendix), special(rahman1996_figures), special(rahman1991)
    total = time.perf_counter() - start
    lines = ["# linkrepro: reproduction report", "",
             "Each published cell, for each engine: `match` (within half a unit of the printed last "
             "digit), `registered` (explained in harness/deviations.toml), `unexplained`, or "
             "`not-produced` (the engine does not give it).", ""]
    for item in done:
        lines += [f"## [{item['scene']}]({item['scene']}/report.md)", "", item["title"], "",
                  "| engine | " + " | ".join(item["counts"].columns) + " | seconds |",
                  "|---|" + "---|" * (len(item["counts"].columns) + 1)]
        for engine, row in item["counts"].iterrows():
            secs = item["timings"].get(engine, float("nan"))
            lines.append(f"| {engine} | " + " | ".join(str(v) for v in row) + f" | {secs:.4f} |")
        lines += [f"\n**{f}**" for f in item["failures"]] + [""]
    if measure_convergence:
        lines += ["## [Case III: speed against error](case3_convergence.md)", "",
                  "Sub-elements n and angle step against the converged distributed-mass answer, and which "
                  "mass model each table needs (timings from this one run).", ""]
    if curves is not None:
        lines += [f"## [{curves['scene']}]({curves['scene']}/report.md)", "", curves["title"], "",
                  f"{curves['curves']} of 36 curves, engine against engine (no published numbers); largest "
                  f"|port - legacy| {curves['max_engine_gap']:.3g}; {', '.join(curves['missing']) or 'every curve from both engines'}.", ""]
    if figures is not None:
        lines += [f"## [{figures['scene']}]({figures['scene']}/report.md)", "", figures["title"],
                  "(recomputed from every engine beside the printed text).", ""]
    if example is not None:
        verdicts = example["claims"].groupby(["engine", "verdict"]).size().unstack(fill_value=0)
        lines += [f"## [{example['scene']}]({example['scene']}/report.md)", "", example["title"], "",
                  "No numeric table is printed; each claim of section 3.2, per engine "
                  "(see the scene report and register D085-D094):", "",
                  "| engine | " + " | ".join(verdicts.columns) + " |", "|---|" + "---|" * len(verdicts.columns)]
        lines += [f"| {engine} | " + " | ".join(str(v) for v in row) + " |" for engine, row in verdicts.iterrows()]
        lines.append("")
    lines += arithmetic.report_link(out_dir)          # written by `linkrepro arithmetic`, when there
    if failures:
        lines += ["## Failures", "", *[f"- **{failure}**" for failure in failures], ""]
    lines.append(f"Total wall time of this reproduce run: {total:.2f} s.")
    (out_dir / "report.md").write_text("\n".join(lines) + "\n")
    if failures:
        raise RunFailedError(failures, done, out_dir)
    return done


def unexplained_count(done: list[dict]) -> int:
    return int(sum(item["counts"].get("unexplained", pd.Series(dtype=int)).sum() for item in done))
