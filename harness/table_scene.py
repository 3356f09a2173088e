"""A table scene: one published table, the inputs the engines run with, how each engine
produces the table in the published table's columns; its ``write`` runs every engine, diffs
each cell against the published table and the register, and writes the scene's report."""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

import pandas as pd

from . import readings, register as register_mod
from .csv_output import FULL_PRECISION, write_csv
from .diff import count_cells, diff_scene
from .engines import ENGINES, PrintedProgramError
from .listing_lines import Statement
from .published_tables import PublishedTable
from .quantities import DIFF, Quantity
from .report import counts_table, plot_scene, scene_report
from .scene import Outcome, RunOptions


@dataclass(frozen=True)
class TableScene:
    """A published table: the engines that produce it in its columns, the diff, the report."""
    name: str
    title: str
    group: str                                   # see harness/scene.py
    start: int
    table: str                                   # harness/published/<table>.csv
    columns: list[str]
    key: str | tuple[str, ...]                   # the column(s) naming a row
    inputs: str                                  # what the engines are run with, in words
    printed: Callable[[], pd.DataFrame]
    legacy: Callable[[], pd.DataFrame]
    port: Callable[[Any], pd.DataFrame]          # quirks restricted to each listing's own (&)
    quirks: tuple                                # the port's (printed, corrected) switch sets
    notes: list[str] = field(default_factory=list)
    rel_floor: float = 0.0                       # below it a non-matching cell is machine arithmetic ...
    floor_id: str | None = None                  # ... as this register entry shows (measured)
    #: more report sections: each writes its CSVs into the scene's folder, returns markdown
    sections: tuple[Callable[["TableScene", PublishedTable, pd.DataFrame, Path], str], ...] = ()
    #: where the listings compute or write a cell: (row key as printed, column) -> Statements
    statements: Callable[[str, str], tuple[Statement, ...]] = lambda row, column: ()
    #: what each column of the scene's CSVs means, and its unit (its thesis's QUANTITIES[name])
    quantities: dict[str, Quantity] = field(default_factory=dict)
    #: the thesis's reading driver (``harness/readings.py``): rebuilds its listings with the
    #: scan's literal text; None: no reading of the register is counted on this table
    readings: Any = None
    #: register ids that a run shows to explain a cell missing the printed digit: (row key as the
    #: diff holds it, column, engine) -> ids (e.g. another arithmetic of the time reaches the digit);
    #: the cell is then explained by them, not by ``floor_id``'s tolerance
    explained_by_run: Callable[[Any, str, str], tuple[str, ...]] = lambda row, column, engine: ()
    #: what a cell's trail says beside the engines: (row key, column) -> sentences (e.g. which
    #: arithmetics reach the printed digit); ``linkrepro explain`` and report.html show them
    trail_notes: Callable[[Any, str], tuple[str, ...]] = lambda row, column: ()

    @property
    def keys(self) -> tuple[str, ...]:
        return (self.key,) if isinstance(self.key, str) else tuple(self.key)

    @property
    def key_name(self) -> str:
        return "/".join(self.keys)

    def describe(self, column: str) -> Quantity:
        """What ``column`` of this table's CSVs (or of its diff.csv) means, and its unit."""
        try:
            return {**DIFF, **self.quantities}[column]
        except KeyError:
            raise KeyError(f"scene {self.name!r} describes no column {column!r}") from None

    @property
    def values(self) -> list[str]:
        """The numeric columns (every column but the key)."""
        return [c for c in self.columns if c not in self.keys]

    def run(self, engine: str) -> pd.DataFrame:
        if engine == "printed":
            return self.printed()
        if engine == "legacy":
            return self.legacy()
        if engine == "port_printed":          # each program with its own listing's quirks
            return self.port(self.quirks[0])
        if engine == "port_corrected":
            return self.port(self.quirks[1])
        raise ValueError(f"unknown engine {engine!r}")

    def compute(self) -> Computed:
        """Every engine's table and the diff against the published table.  An engine that cannot
        run (``PrintedProgramError``) is listed in ``failures``; the other engines still run."""
        register = register_mod.load()
        published = PublishedTable.load(self.table)
        results, timings, failures = {}, {}, []
        for engine in ENGINES:
            start = time.perf_counter()
            try:
                frame = self.run(engine)
            except PrintedProgramError as exc:
                failures.append(f"engine {engine} failed: {exc}")
                continue
            timings[engine] = time.perf_counter() - start
            results[engine] = frame
        return Computed(published, results, timings, failures, diff_scene(self, published, results, register))

    def write(self, out_dir: Path, options: RunOptions) -> Outcome:
        """Every engine's table, the diff, the plots, the sections, the readings, the report,
        into ``out_dir/<name>/``; a failed engine is in ``failures`` and in the report."""
        begin = time.perf_counter()
        register = register_mod.load()
        target = out_dir / self.name
        target.mkdir(parents=True, exist_ok=True)
        PublishedTable.load(self.table).text.to_csv(target / "published.csv", index=False)  # unwritable: fail first
        done = self.compute()
        published, diff, timings, failures = done.published, done.diff, done.timings, done.failures
        for engine, frame in done.results.items():
            write_csv(frame, target / f"{engine}.csv", FULL_PRECISION)
        write_csv(diff, target / "diff.csv", FULL_PRECISION)
        plots = plot_scene(self, published, done.results, target)
        extra = "\n".join(f"**{f}**" for f in failures)
        for section in self.sections:
            text = section(self, published, diff, target)
            extra += "\n\n" + text if text else ""
        if readings.has_readings(self.table, self.readings):      # an empty measurement says why it is empty
            extra += "\n\n" + (readings.as_markdown(readings.measure(self.table, self.readings), self.readings)
                                if options.measure_readings else
                                "## Reading alternatives\n\nNot measured (skipped on request: --skip-readings).")
        (target / "report.md").write_text(scene_report(self, diff, timings, register, plots, extra))
        counts = count_cells(diff, register)
        return Outcome(self.name, self.title, counts_overview(counts, timings), time.perf_counter() - begin,
                       counts=counts, failures=failures)


@dataclass(frozen=True)
class Computed:
    """What ``TableScene.compute`` gives: the published table, each engine's table (the engines
    that ran), their wall times (s), what failed, the long diff (``diff.diff_scene``)."""
    published: PublishedTable
    results: dict[str, pd.DataFrame]
    timings: dict[str, float]
    failures: list[str]
    diff: pd.DataFrame


def counts_overview(counts: pd.DataFrame, timings: dict[str, float]) -> list[str]:
    """The run report's table: cells per engine (``diff.count_cells``, headed as in the scene's
    report), and each engine's seconds."""
    shown = counts_table(counts)
    lines = ["| engine | " + " | ".join(shown.columns) + " | seconds |",
             "|---|" + "---|" * (len(shown.columns) + 1)]
    for engine, row in shown.iterrows():
        lines.append(f"| {engine} | " + " | ".join(str(v) for v in row) + f" | {timings.get(engine, float('nan')):.4f} |")
    return lines
