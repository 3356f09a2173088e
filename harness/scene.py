"""The scene protocol: what the runner (``harness/run.py``) knows of a scene.

A scene is anything a thesis shows that a run reproduces: a published table, a set of
curves, figures, claims in words.  Every scene has

- ``name``: its folder under the output folder, and how ``linkrepro reproduce NAME`` selects it;
- ``title``: one line for ``linkrepro scenes`` and the run's report;
- ``group``: scenes of one group run in one process, in their listed order (they share a
  computation, cached for the process); the groups run side by side on the cores;
- ``start``: a scheduling hint, the groups start in increasing order of their smallest
  ``start`` (the longest first, and a group that loads compiled kernels after the one that
  compiles them);
- ``write(out_dir, options) -> Outcome``: write ``out_dir/<name>/`` (CSVs, figures,
  ``report.md``) and return what the run's report says of it.

Two kinds implement it: ``TableScene`` (one published table: every engine, the cell-by-cell
diff, the register; ``harness/table_scene.py``) and ``ReportScene`` (anything else: a
function that writes the scene's folder, one that summarises what it measured).  The
scenes themselves live in ``harness/scenes/<thesis>/``; the runner names none of them.
"""
from __future__ import annotations

import json
import os
import time
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Callable, Protocol

import pandas as pd

from .engines import PrintedProgramError


@dataclass(frozen=True)
class RunOptions:
    """What a run asks of every scene."""
    measure_readings: bool = True        # rebuild the listings with the scan's readings (gfortran)


class SceneSkipped(Exception):
    """A scene that cannot run on this machine (an optional dependency missing); its message
    says what is missing and how to get it.  Not a failure: the run goes on and reports it."""


@dataclass
class Outcome:
    """What a scene's run gives the run's report: markdown lines under its heading, its wall
    time (s), the cells per engine (table scenes: ``diff.count_cells``), what could not run,
    when it finished (UTC, ISO 8601), why it did not run where it was skipped (``SceneSkipped``),
    the files it wrote ({path in its folder: SHA-256}; None where not recorded, as by versions
    before it was) and the run that wrote it (its partial folder's name, ``harness/run_folder.py``).
    Kept in the scene's folder as ``outcome.json`` (``save``, ``load``), so that the folder's
    report shows every scene run into it."""
    scene: str
    title: str
    overview: list[str]
    seconds: float
    counts: pd.DataFrame | None = None
    failures: list[str] = field(default_factory=list)
    finished: str = field(default_factory=lambda: datetime.now(timezone.utc).isoformat(timespec="seconds"))
    skipped: str = ""
    files: dict[str, str] | None = None
    run: str = ""

    FILE = "outcome.json"

    def save(self, out_dir: Path) -> Path:
        """Write ``out_dir/<scene>/outcome.json`` (whole or not at all: a temporary file renamed)."""
        path = Path(out_dir) / self.scene / self.FILE
        path.parent.mkdir(parents=True, exist_ok=True)      # a skipped scene wrote nothing else
        record = {"scene": self.scene, "title": self.title, "overview": self.overview, "seconds": self.seconds,
                  "failures": self.failures, "finished": self.finished, "skipped": self.skipped,
                  "files": self.files, "run": self.run,
                  "counts": None if self.counts is None else json.loads(self.counts.to_json(orient="split"))}
        temporary = path.with_name(f".{self.FILE}.{os.getpid()}")
        temporary.write_text(json.dumps(record, indent=1))
        os.replace(temporary, path)
        return path

    @classmethod
    def load(cls, out_dir: Path, scene: str) -> "Outcome":
        """The outcome a run saved for ``scene`` in ``out_dir``; ``FileNotFoundError`` where there is
        none, ``ValueError`` where it cannot be read."""
        path = Path(out_dir) / scene / cls.FILE
        try:
            record = json.loads(path.read_text())
            counts, files = record["counts"], record.get("files")
            if files is not None and not (isinstance(files, dict) and all(isinstance(v, str) for v in files.values())):
                raise TypeError(f"its files are {files!r}, not {{path: SHA-256}}")
            return cls(str(record["scene"]), record["title"], list(record["overview"]), float(record["seconds"]),
                       None if counts is None else pd.DataFrame(counts["data"], index=counts["index"],
                                                                columns=counts["columns"]),
                       list(record["failures"]), str(record["finished"]), str(record.get("skipped", "")),
                       files, str(record.get("run", "")))
        except FileNotFoundError:
            raise
        except (OSError, ValueError, KeyError, TypeError) as exc:
            raise ValueError(f"{path} cannot be read ({type(exc).__name__}: {exc}); run the scene again") from exc


class Scene(Protocol):
    name: str
    title: str
    group: str
    start: int

    def write(self, out_dir: Path, options: RunOptions) -> Outcome: ...


@dataclass(frozen=True)
class ReportScene:
    """A scene without a published table: ``produce(out_dir)`` writes ``out_dir/<name>/`` and
    returns what it measured; ``overview(result)`` gives the run report's lines about it.  A
    ``SceneSkipped`` raised by ``produce`` makes a skipped outcome (nothing written, the reason
    kept)."""
    name: str
    title: str
    group: str
    start: int
    produce: Callable[[Path], Any]
    overview: Callable[[Any], list[str]]

    def write(self, out_dir: Path, options: RunOptions) -> Outcome:
        begin = time.perf_counter()
        try:
            result = self.produce(out_dir)
        except PrintedProgramError as exc:
            return Outcome(self.name, self.title, [], time.perf_counter() - begin,
                           failures=[f"not written, engine printed failed: {exc}"])
        except SceneSkipped as exc:
            return Outcome(self.name, self.title, [], time.perf_counter() - begin, skipped=str(exc))
        _state_assumptions(Path(out_dir) / self.name / "report.md", self.name)
        return Outcome(self.name, self.title, self.overview(result), time.perf_counter() - begin)


def _state_assumptions(report: Path, scene: str) -> None:
    """The model assumptions the register names for ``scene`` (``report.assumptions_markdown``)
    added to the report.md its ``produce`` wrote (none written: nothing added)."""
    from . import register
    from .report import assumptions_markdown
    lines = assumptions_markdown(scene, register.load())
    if lines and report.is_file():
        report.write_text(report.read_text().rstrip("\n") + "\n\n" + "\n".join(lines))
