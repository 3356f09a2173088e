"""An output folder is one report: ``report.md`` and ``report.html`` over everything run into it.

Every scene's run leaves ``<scene>/outcome.json`` in the folder (``scene.Outcome.save``); the
bench and each thesis's own commands leave their markdown in their folder (``bench/bench.md``,
``arithmetic/arithmetic.md``).  ``collect`` gathers what the folder holds, in the order of the
theses (each thesis's scenes as it lists them, then its commands' outputs; the bench last), and
names what is not there with the command that writes it (``linkrepro differential`` writes
``differential/differential.md``, and ``python -m linkrepro.harness.toolchains`` writes
``toolchains/matrix.md``, both shown before the bench).  ``write`` writes both reports from
that, each whole or not at all (a temporary file renamed), under the folder's lock
(``run_folder.locked``), so a run of one scene updates its section and keeps the others, and a
report that cannot be built leaves the last one in place.  A scene's folder that is not what its
run wrote (``run_folder.read_scene``: incomplete, damaged) is said in its section instead of
shown; a folder holding an unknown scene's outcome, and a run killed or still running in the
folder, are said at the top.  Both end with "How this run was made", from the folder's
manifest.json (``manifest.summary``).
"""
from __future__ import annotations

import shlex
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd

from . import manifest, register as register_mod, run_folder
from .diff import headline, total_counts
from .markdown_text import code_span, prose
from .report import COUNTS_WORDS
from .scene import Outcome
from .scenes import SCENES, THESES, commands_of

#: the report's two files in the folder
FILES = ("report.md", "report.html")


@dataclass(frozen=True)
class SceneSection:
    """A scene of the registry: its outcome where the folder holds one, else why not."""
    kind = "scene"
    name: str
    title: str
    outcome: Outcome | None
    problem: str = ""                   # '' or why the folder is not what its run wrote (run_folder.read_scene)


@dataclass(frozen=True)
class OutputSection:
    """What a command other than ``reproduce`` writes into ``<folder>/<subfolder>/``."""
    kind = "output"
    name: str                           # the section's id (its subfolder's name)
    title: str
    folder: Path                        # where the command writes
    markdown: Path                      # its report (shown where it exists)
    command: str                        # the command line that writes it there

    @property
    def present(self) -> bool:
        return self.markdown.is_file()


@dataclass(frozen=True)
class Folder:
    """What an output folder holds, in the report's order."""
    out_dir: Path
    sections: list                      # SceneSection (run or unreadable) and OutputSection
    absent: list[SceneSection] = field(default_factory=list)     # scenes not run into it
    notes: list[str] = field(default_factory=list)               # what else it holds: runs killed, ...

    @property
    def outcomes(self) -> list[Outcome]:
        return [s.outcome for s in self.sections if isinstance(s, SceneSection) and s.outcome is not None]

    @property
    def absent_command(self) -> str:
        """The command that runs a scene into the folder, as a shell takes it (NAME for the scene)."""
        return manifest.command_line(["reproduce", "NAME", "--out", str(self.out_dir)])

    def cell_totals(self) -> pd.Series:
        """Every table scene's cells over every engine (``diff.total_counts``)."""
        return total_counts([o.counts for o in self.outcomes if o.counts is not None])


def _bench(out_dir: Path) -> OutputSection:
    folder = out_dir / "bench"
    return OutputSection("bench", "Speed against error (linkrepro bench)", folder, folder / "bench.md",
                         manifest.command_line(["bench", "--out", str(folder)]))


def _toolchains(out_dir: Path) -> OutputSection:
    folder = out_dir / "toolchains"
    return OutputSection("toolchains", "The run of record across Fortran compilers (make toolchains)", folder,
                         folder / "matrix.md",
                         shlex.join(["python", "-m", "linkrepro.harness.toolchains", "--out", str(folder)]))


def _differential(out_dir: Path) -> OutputSection:
    folder = out_dir / "differential"
    return OutputSection("differential", "Legacy against the port on sampled geometries (linkrepro differential)",
                         folder, folder / "differential.md",
                         manifest.command_line(["differential", "ali1977", "rahman1996", "rahman1991", "--out", str(folder)]))


def _command(out_dir: Path, command) -> OutputSection:
    folder = out_dir / command.default_out.name
    return OutputSection(command.default_out.name, command.report_title, folder, folder / command.report_markdown,
                         manifest.command_line([command.name, "--out", str(folder)]))


def _scene_section(out_dir: Path, name: str) -> SceneSection:
    return SceneSection(name, SCENES[name].title, *run_folder.read_scene(out_dir, name))


def _notes(out_dir: Path) -> list[str]:
    """What the report says of the folder besides its sections: folders holding the outcome of
    a scene this linkrepro does not know, runs killed before they finished, runs going on."""
    notes = []
    unknown = sorted(p.parent.name for p in out_dir.glob(f"*/{Outcome.FILE}")
                     if p.parent.name not in SCENES and not p.parent.name.startswith("."))
    if unknown:
        notes.append(f"Not shown: {', '.join(map(prose, unknown))} (a folder holding {Outcome.FILE} but no scene of this "
                     "linkrepro: renamed?).")
    killed, running = run_folder.unfinished(out_dir)
    if killed:
        notes.append(f"A run into this folder was killed before it finished {', '.join(killed)}: their sections are as "
                     "the runs before it left them (its partial files are hidden in the folder; the next run removes "
                     "them).")
    if running:
        notes.append(f"A run is writing {', '.join(running)} into this folder now: this report shows them as they were "
                     "before it.")
    return notes


def prepare() -> None:
    """Load now what writing the reports will need (the listings' alignment with the scan, the
    register, the page's template, the theses' commands): ``reproduce`` calls it while its
    workers run, so that its reports after them take less time.  Each is kept for the process."""
    from . import html_report, listing_lines
    listing_lines.align_every_listing()
    register_mod.parsed()
    html_report.template()
    for thesis in THESES:
        commands_of(thesis)


def collect(out_dir: Path) -> Folder:
    """What ``out_dir`` holds: scenes run into it (or unreadable), the commands' outputs (present
    or not), in the report's order; the scenes not run into it apart."""
    out_dir = Path(out_dir)
    sections, absent = [], []
    for thesis in THESES:
        for scene in thesis.SCENES:
            section = _scene_section(out_dir, scene.name)
            (sections if section.outcome is not None or section.problem else absent).append(section)
        sections += [_command(out_dir, command) for command in commands_of(thesis) if command.report_markdown]
    return Folder(out_dir, sections + [_differential(out_dir), _toolchains(out_dir), _bench(out_dir)], absent, _notes(out_dir))


def _scene_lines(section: SceneSection, register: dict) -> list[str]:
    if section.outcome is None:
        return [f"## {section.name}", "", section.title, "", f"**{prose(section.problem)}**", ""]
    o = section.outcome
    said = register_mod.assumptions_said(o.scene, register)
    lines = [f"## [{o.scene}]({o.scene}/report.md)", "", o.title, "", *o.overview, "",
             *([said, ""] if said else []), f"Run {o.finished}, wall time {o.seconds:.2f} s.", ""]
    skipped = [f"**Skipped: {o.skipped}**", ""] if o.skipped else []
    return lines + skipped + [f"**{prose(failure)}**\n" for failure in o.failures]


def _output_lines(section: OutputSection, out_dir: Path) -> list[str]:
    if section.present:
        return [f"## [{section.title}]({section.markdown.relative_to(out_dir).as_posix()})", ""]
    return [f"## {section.title}", "", f"Not in this folder: {code_span(section.command)} writes it.", ""]


def markdown(folder: Folder, latest: str = "") -> str:
    """report.md: the headline over the folder's tables, each section, the scenes not run."""
    lines = ["# linkrepro: reproduction report", "",
             f"The published cells of every table below, once per engine: "
             f"{headline(folder.cell_totals(), by_kind=True)}.", "",
             "Each published cell is counted once per engine. " + COUNTS_WORDS + " The register is "
             "harness/deviations.toml.", ""]
    if latest:
        lines += [latest, ""]
    lines += [f"**{note}**\n" for note in folder.notes]
    register = register_mod.load()
    for section in folder.sections:
        lines += (_scene_lines(section, register) if isinstance(section, SceneSection)
                  else _output_lines(section, folder.out_dir))
    failures = [f"{o.scene}: {prose(f)}" for o in folder.outcomes for f in o.failures]
    if failures:
        lines += ["## Failures", "", *[f"- **{failure}**" for failure in failures], ""]
    if folder.absent:
        lines += ["## Not run into this folder", "",
                  f"{code_span(folder.absent_command)} runs one: "
                  + ", ".join(s.name for s in folder.absent) + ".", ""]
    lines += [f"## {manifest.TITLE}", "", *manifest.summary(folder.out_dir)]
    return "\n".join(lines) + "\n"


def write(out_dir: Path, latest: str = "") -> Path:
    """Write ``out_dir/report.md`` and ``report.html`` over what the folder holds (``latest``: a
    line on the run that just ended), under the folder's lock; returns report.html's path."""
    from . import html_report
    out_dir = Path(out_dir)
    with run_folder.locked(out_dir):
        folder = collect(out_dir)
        page = html_report.render(folder, latest)
        run_folder.replace_text(out_dir / "report.md", markdown(folder, latest))
        run_folder.replace_text(out_dir / "report.html", page)
    size = len(page.encode())
    if size > html_report.PAGE_BUDGET:
        warnings.warn(f"{out_dir / 'report.html'} is {size / 1e6:.2f} MB, over the page's budget of "
                      f"{html_report.PAGE_BUDGET / 1e6:g} MB (html_report.PAGE_BUDGET): it is written; "
                      "make its figures or data smaller", html_report.PageSizeWarning, stacklevel=2)
    return out_dir / "report.html"
