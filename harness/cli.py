"""The ``linkrepro`` command (``python -m linkrepro`` is the same).

Exit status: 0 done; 1 a run failed (an engine could not run, gfortran missing or broken, an
output file could not be written); 2 a usage error, as argparse (a bad argument, an unknown
scene, an ``--out`` that cannot be written); 130 interrupted (Ctrl-C: a run records the scenes
it finished first, ``harness/run_folder.py``).

A user's mistake or a missing tool is one line on stderr, ``linkrepro: error: ...``, raised as
a typed error where it is found and caught here, in ``main``.  Anything else is a bug in
linkrepro: it keeps its traceback, after one line that says so.
"""
from __future__ import annotations

import argparse
import difflib
import math
import os
import sys
from pathlib import Path

from .. import __version__
from . import blas_threads

PROG = "linkrepro"
#: the bench's timing repetitions (best of): by default, and with --quick (a smoke test: one call
#: a setting took it from 44 s to 8 s, measured 2026-11-28)
BENCH_REPEAT, QUICK_REPEAT = 10, 1


class _Parser(argparse.ArgumentParser):
    """argparse with every error on one line: ``linkrepro: error: ... (see `... --help`)``."""

    def error(self, message: str):
        self.exit(2, f"{PROG}: error: {message} (see `{self.prog} --help`)\n")


class _ReaderGone(Exception):
    """Whoever reads our standard output has gone (``linkrepro scenes | head -1``)."""


def _error(message: str) -> None:
    print(f"{PROG}: error: {message}", file=sys.stderr)


def _out(text: str) -> None:
    try:
        print(text)
        sys.stdout.flush()
    except BrokenPipeError as exc:
        raise _ReaderGone from exc


def _out_folder(text: str) -> Path:
    if not text.strip():
        raise argparse.ArgumentTypeError("the output folder must not be empty")
    return Path(text)


def _repeat(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be a whole number >= 1, not {text!r}")
    return value


def _parser() -> tuple[_Parser, dict[str, _Parser], dict]:
    """The parser, its subparsers by command, and the theses' own commands by name (found
    through the scene registry, ``harness/command.py``)."""
    from .scenes import commands
    theirs = {command.name: command for command in commands()}
    parser = _Parser(prog=PROG, description=(
        "Rebuild, port and diff the FORTRAN of three mechanism-dynamics theses."),
        epilog="Exit status: 0 done, 1 a run failed, 2 a usage error, 130 interrupted.")
    parser.add_argument("--version", action="version", version=f"{PROG} {__version__}")
    names = ["reproduce", "scenes", "explain", "bench", "verify", "differential", *theirs]
    sub = parser.add_subparsers(dest="command", required=True, metavar="{" + ",".join(names) + "}")
    rep = sub.add_parser("reproduce", help="run every engine of the scenes and write the report")
    rep.add_argument("scenes", nargs="*", help="scene names (default: all; see `linkrepro scenes`)")
    rep.add_argument("--out", default=Path("out"), type=_out_folder,
                     help="output folder (default: out/); checked writable before the run starts")
    rep.add_argument("--skip-readings", action="store_true",
                     help="do not measure the OCR readings (they rebuild the listings with gfortran)")
    rep.add_argument("--without", action="append", default=[], metavar="SCENE",
                     help="leave this scene out (repeatable; `make test` leaves out the long dynamic study)")
    scenes = sub.add_parser("scenes", help="list the scenes")
    explain = sub.add_parser("explain", help="one published cell's trail: the published value, every engine's "
                             "value and status, the register entries, the listing lines behind it")
    explain.add_argument("scene", help="a table scene (see `linkrepro scenes`), e.g. ali1977-table1")
    explain.add_argument("row", help="the row as printed in the table's first column(s), e.g. 160 or crank/i_xx")
    explain.add_argument("column", help="the column, e.g. src_dx (the scene's report lists them)")
    explain.add_argument("--out", default=Path("out"), type=_out_folder,
                         help="a run's output folder to read the scene's diff from (default: out/)")
    explain.add_argument("--run", action="store_true",
                         help="where --out holds no run of the scene, run its engines now (as `reproduce SCENE` "
                              "does) instead of stopping with an error")
    bench = sub.add_parser("bench", help="time each engine against its error: cost per position against "
                           "legacy and a flop-count limit, and speed against error for each knob")
    bench.add_argument("--repeat", type=_repeat, default=None,
                       help=f"timing repetitions, >= 1 (best of; default {BENCH_REPEAT}, {QUICK_REPEAT} with --quick; "
                            "bench.md says how long its run took)")
    bench.add_argument("--out", default=Path("out/bench"), type=_out_folder,
                       help="output folder for bench.md, bench.png, bench.csv (default: out/bench/)")
    bench.add_argument("--quick", action="store_true",
                       help="a reduced configuration (the tables' 19 angles, three settings a knob, no Case III "
                            "sweep, one call a setting unless --repeat): a smoke test; bench.md says how long it took")
    verify = sub.add_parser("verify", help="compare a run's scene CSVs with the stored run of record, cell by "
                            "cell (identical, within the policy, moved, status changed)")
    verify.add_argument("scenes", nargs="*", help="scenes to compare (default: every scene run into --out)")
    verify.add_argument("--out", default=Path("out"), type=_out_folder, help="the run's output folder (default: out/)")
    verify.add_argument("--reference", type=Path, default=None,
                        help="the run of record (default: the reference/ the package carries)")
    verify.add_argument("--units", type=float, default=None,
                        help="across toolchains, units in the last place a number may move: ulps where it is "
                             "written in full, else units of its last written digit (default: as far as the "
                             "reference's measured matrix saw another compiler move each engine, where it measured "
                             "the run's compiler; else 4)")
    verify.add_argument("--refresh", action="store_true",
                        help="print the comparison, then make --out's scenes the reference")
    subparsers = {"reproduce": rep, "scenes": scenes, "explain": explain, "bench": bench, "verify": verify,
                  "differential": _differential_parser(sub)}
    for command in theirs.values():
        own = sub.add_parser(command.name, help=command.help)
        own.add_argument("--out", default=command.default_out, type=_out_folder, help=command.out_help)
        command.add_arguments(own)
        subparsers[command.name] = own
    return parser, subparsers, theirs


def _scene_titles() -> dict[str, str]:
    """Every scene `reproduce` knows, with its title."""
    from .scenes import SCENES
    return {scene.name: scene.title for scene in SCENES.values()}


def _unknown_scenes(unknown: list[str], known: list[str]) -> str:
    hints = [f"{name!r} (did you mean {close[0]!r}?)" if (close := difflib.get_close_matches(name, known, 1))
             else repr(name) for name in unknown]
    return (f"unknown scene{'s' if len(unknown) > 1 else ''} {', '.join(hints)}; "
            f"`linkrepro scenes` lists them: {', '.join(known)}")


def _under(exc: OSError, folder: Path) -> bool:
    """Whether an OSError is about a file in the output folder (a write that failed)."""
    try:
        root = folder.resolve()
        return any(name is not None and Path(name).resolve().is_relative_to(root)
                   for name in (exc.filename, exc.filename2))
    except (OSError, ValueError, TypeError):
        return False


def _summary(done: list, out_dir: Path) -> None:
    """Each table's cells per engine of this run (``diff.count_cells``), then the last line: the
    report and the cells of every table and engine it shows (``diff.headline``: matched, explained,
    within tolerance, unresolved, unexplained, not produced), this run's scenes and those run into
    the folder before."""
    from .diff import headline
    for item in done:
        if item.skipped:
            _out(f"{item.scene}: skipped, {item.skipped}")
        if item.counts is not None:
            _out(f"{item.scene}:")
            for engine, row in item.counts.iterrows():
                _out(f"  {engine}: {headline(row, by_kind=True)}")
    _report_line(out_dir, lambda folder: f"; {headline(folder.cell_totals())}")


def _report_line(out_dir: Path, more=lambda folder: "") -> None:
    """The last line of a run: the folder's report.html (and report.md), the scenes it shows
    (those skipped, where Exudyn is missing, counted apart)."""
    from .report_folder import collect
    folder = collect(out_dir)
    skipped = sum(1 for outcome in folder.outcomes if outcome.skipped)
    scenes = len(folder.outcomes) - skipped
    _out(f"report: {out_dir / 'report.html'} and report.md  ({scenes} scene{'s' * (scenes != 1)}"
         f"{f', {skipped} skipped' if skipped else ''}{more(folder)})")


def _reproduce(args: argparse.Namespace, parser: _Parser) -> int:
    known = list(_scene_titles())
    unknown = [name for name in dict.fromkeys(args.scenes + args.without) if name not in known]
    if unknown:
        parser.error(_unknown_scenes(unknown, known))
    if args.without:
        args.scenes = [name for name in args.scenes or known if name not in args.without]
        if not args.scenes:
            parser.error("--without leaves no scene to run")
    from .engines import PrintedProgramError
    from .readings import CompilerError
    from .run import OutputFolderError, RunFailedError, WorkerDiedError, reproduce
    try:
        done = reproduce(args.scenes, args.out, measure_readings=not args.skip_readings, command=args.line)
    except OutputFolderError as exc:          # found before the run: the --out argument is wrong
        _error(f"{exc} (--out)")
        return 2
    except RunFailedError as exc:             # the run finished, but an engine could not run
        _summary(exc.done, args.out)
        _error(str(exc))
        return 1
    except (CompilerError, PrintedProgramError, WorkerDiedError) as exc:
        _error(str(exc))
        return 1
    except OSError as exc:
        if not _under(exc, args.out):
            raise
        _error(f"could not write {exc.filename}: {exc.strerror or exc}")
        return 1
    _summary(done, args.out)
    return 0


def _explain(args: argparse.Namespace, parser: _Parser) -> int:
    """``linkrepro explain SCENE ROW COLUMN``: the cell's trail printed; an unknown scene, row or
    column, or an --out without a run of the scene (unless --run), is a usage error (status 2);
    an engine that cannot run, status 1."""
    from .scenes import TABLES
    if args.scene not in TABLES:
        known = list(TABLES)
        if args.scene in _scene_titles():
            parser.error(f"scene {args.scene!r} has no published table to explain; table scenes: {', '.join(known)}")
        parser.error(_unknown_scenes([args.scene], known))
    from .engines import PrintedProgramError
    from .manifest import command_line
    from .trail import CellNotFound, as_text, cell_trail, read_diff
    scene = TABLES[args.scene]
    ran = args.out / scene.name / "diff.csv"
    if not args.run and not ran.is_file():
        why = ("does not exist" if not args.out.exists() else "is not a folder" if not args.out.is_dir()
               else f"holds no run of {scene.name} (no {ran.relative_to(args.out)})")
        parser.error(f"--out {args.out} {why}: `{command_line(['reproduce', scene.name, '--out', str(args.out)])}` "
                     "runs it, or add --run to run its engines now")
    try:
        diff = read_diff(scene, args.out if ran.is_file() else None)
        text = as_text(cell_trail(scene, args.row, args.column, diff))
    except CellNotFound as exc:
        parser.error(str(exc))
    except PrintedProgramError as exc:
        _error(str(exc))
        return 1
    _out(text)
    return 0


def _write_outputs(out: Path, outputs, writer: str, job, failures: tuple = (), line: str = "") -> int:
    """A command that writes ``outputs`` into ``out``: the folder checked writable before the
    work (status 2); a failure in ``failures`` or a failed write after it, status 1; the
    markdown ``job()`` returns printed; ``line``: its command line, for out/manifest.json."""
    from . import manifest
    from .run import OutputFolderError, check_output_folder
    try:
        check_output_folder(out, [])
        for name in outputs:
            if (out / name).is_dir():
                raise OutputFolderError(f"{out / name} is a folder; {writer} writes a file there")
    except OutputFolderError as exc:
        _error(f"{exc} (--out)")
        return 2
    try:
        started = manifest.now()
        text = job()
        if line:
            manifest.write(out, line, outputs=outputs, started=started)
    except failures as exc:
        _error(str(exc))
        return 1
    except OSError as exc:
        if not _under(exc, out):
            raise
        _error(f"could not write {exc.filename}: {exc.strerror or exc}")
        return 1
    _out(text)
    return 0


def _bench(args: argparse.Namespace) -> int:
    """``linkrepro bench``: --out checked writable before the run (status 2), a failed write
    after it status 1; the markdown printed."""
    from .bench_run import OUTPUTS, run_bench
    repeat = args.repeat or (QUICK_REPEAT if args.quick else BENCH_REPEAT)
    status = _write_outputs(args.out, OUTPUTS, "the bench", lambda: run_bench(repeat, args.out, quick=args.quick),
                            line=args.line)
    return status or _report_of_parent(args.out, "bench")


def _verify(args: argparse.Namespace) -> int:
    """``linkrepro verify``: 0 every cell keeps the policy, 1 one does not, 2 a usage error
    (no or a damaged reference, no scene run in --out); ``--refresh`` prints the comparison
    first, then replaces the reference."""
    from .verify import REFERENCE_DIR, VerifyError, describe, refresh, verify
    reference = args.reference or REFERENCE_DIR
    if args.units is not None and (not math.isfinite(args.units) or args.units < 0):
        _error("--units must be a number >= 0")
        return 2
    try:
        if args.refresh and not reference.exists():
            verdict = None
        else:
            verdict = verify(args.out, reference, args.units, args.scenes or None)
            _out(describe(verdict))
        if args.refresh:
            size = refresh(args.out, reference)
            _out(f"reference: {reference} now holds the scenes of {args.out} ({size / 1e6:.1f} MB)")
            return 0
    except VerifyError as exc:
        _error(str(exc))
        return 2
    return 1 if verdict.failed else 0


def _differential_parser(sub) -> _Parser:
    from .scenes import thesis_names
    own = sub.add_parser("differential", help="legacy against the port with the listing's bugs on a random sample "
                         "of a thesis's geometries (or on given ones): where they differ (status 1 if anywhere)")
    own.add_argument("theses", nargs="+", metavar="THESIS",
                     help=f"one or more of {', '.join(thesis_names())}")
    own.add_argument("--samples", type=_repeat, default=None, help="geometries per program, >= 1 (default 100)")
    own.add_argument("--seed", type=_seed, default=1, help="the sampler's seed, >= 0 (numpy default_rng; default 1)")
    own.add_argument("--out", default=Path("out/differential"), type=_out_folder,
                     help="output folder for differential.md and differential.csv (default: out/differential/, "
                          "which reproduce's report shows)")
    own.add_argument("--program", action="append", metavar="NAME", help="only this program (repeatable; one thesis)")
    own.add_argument("--domain", metavar="NAME", help="the thesis's sampler (default: its first; differential.md names it)")
    own.add_argument("--bounds", nargs="+", action="extend", default=[], metavar="NAME=LO:HI",
                     help="draw NAME uniformly in LO..HI (log-uniformly for lengths and section values) instead "
                          "of from the domain; NAME=VALUE holds it constant")
    own.add_argument("--geometry", nargs="+", action="extend", default=[], metavar="NAME=VALUE",
                     help="run one given geometry (one thesis); parameters not given are the published example's")
    own.add_argument("--geometry-file", type=Path, metavar="FILE",
                     help="run the geometries of a JSON or TOML file: a table NAME = VALUE, or a list of them")
    return own


def _seed(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError(f"must be a whole number >= 0, not {text!r}")
    return value


def _differential(args: argparse.Namespace, parser: _Parser) -> int:
    """``linkrepro differential``: 0 legacy and port agree on every sample, 1 they differ on one
    (or a write failed), 2 a usage error."""
    import time
    from . import differential as machine
    from .scenes import differentials
    known, theses = differentials(), list(dict.fromkeys(args.theses))
    unknown = [t for t in theses if t not in known]
    if unknown:
        parser.error(f"unknown thesis {', '.join(map(repr, unknown))}; known: {', '.join(known)}")
    given = bool(args.geometry or args.geometry_file)
    if given and (len(theses) > 1 or args.samples is not None or (args.geometry and args.geometry_file)):
        parser.error("a given geometry (--geometry or --geometry-file, one of them) is for one thesis and takes no --samples")
    if args.program and len(theses) > 1:
        parser.error("--program names the programs of one thesis")
    try:
        plan = []
        for key in theses:
            geometries = None
            if args.geometry:
                geometries = [machine.parse_geometry(known[key], args.geometry)]
            elif args.geometry_file:
                geometries = machine.read_geometries(known[key], args.geometry_file)
            plan.append(machine.plan_of(key, known[key], args.program, args.samples or 100, args.seed, args.domain,
                                        args.bounds, geometries))
    except machine.DifferentialUsageError as exc:
        parser.error(str(exc))
    done = []

    def job() -> str:
        start = time.perf_counter()
        done.append(machine.run(args.line, plan, args.seed))
        return machine.write(done[0], args.out, time.perf_counter() - start)
    status = _write_outputs(args.out, machine.OUTPUTS, "linkrepro differential", job, line=args.line)
    status = status or _report_of_parent(args.out, "differential")
    if status == 0 and done[0].differ:
        _error(f"legacy and the port differ on {done[0].differ} of {len(done[0].rows)} samples "
               f"({args.out / 'differential.md'} lists them)")
        return 1
    return status


def _report_of_parent(out: Path, folder: str) -> int:
    """After a command that wrote ``out``: where ``out`` is a report folder's ``folder`` (its
    default, e.g. out/bench), rebuild that folder's report (which shows it) and name it;
    else say where the output is.  A failed write, status 1."""
    from .manifest import include
    from .report_folder import write
    from .run_folder import locked
    if out.name != folder:
        _out(f"written: {out} (a report shows it when it is a report folder's {folder}/)")
        return 0
    try:
        with locked(out.parent):
            include(out.parent, out)
            write(out.parent)
    except OSError as exc:
        _error(f"could not write {exc.filename}: {exc.strerror or exc}")
        return 1
    _report_line(out.parent)
    return 0


def _main(argv: list[str] | None) -> int:
    parser, commands, theirs = _parser()
    args = parser.parse_args(argv)
    from .manifest import command_line     # after --help and a bad command line: it imports pandas
    args.line = command_line(sys.argv[1:] if argv is None else argv)       # for the run's manifest.json
    if args.command == "scenes":
        titles = _scene_titles()
        width = max(map(len, titles))
        _out("\n".join(f"{name:{width}s}  {title}" for name, title in titles.items()))
        return 0
    if args.command == "reproduce":
        return _reproduce(args, commands["reproduce"])
    if args.command == "explain":
        return _explain(args, commands["explain"])
    if args.command == "bench":
        return _bench(args)
    if args.command == "differential":
        return _differential(args, commands["differential"])
    if args.command == "verify":
        return _verify(args)
    if args.command in theirs:          # a thesis's own command (harness/command.py)
        command = theirs[args.command]
        status = _write_outputs(args.out, command.outputs, f"linkrepro {command.name}", lambda: command.run(args),
                                command.failures, line=args.line)
        return status or (_report_of_parent(args.out, command.default_out.name) if command.report_markdown else 0)
    raise AssertionError(f"command {args.command!r} has no branch")


def main(argv: list[str] | None = None) -> int:
    """Run the command; return its exit status (argparse's ``SystemExit`` for --help and
    usage errors passes through, as argparse does)."""
    blas_threads.use_one()
    try:
        return _main(argv)
    except KeyboardInterrupt:
        print(f"{PROG}: interrupted", file=sys.stderr)
        return 130
    except _ReaderGone:
        try:                                  # stop Python's final flush complaining too
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        except OSError:
            pass
        return 1
    except Exception as exc:
        first = (str(exc).strip().splitlines() or [""])[0]
        print(f"{PROG}: internal error, a bug in linkrepro (please report it with the traceback below): "
              f"{type(exc).__name__}: {first}", file=sys.stderr)
        raise


if __name__ == "__main__":
    sys.exit(main())
