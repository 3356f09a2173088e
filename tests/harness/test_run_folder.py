"""A run folder never lies (harness/run_folder.py, harness/run.py): runs stopped by SIGINT and
SIGKILL at points a seeded random draw picks among the changes they make to the folder, and at
the last ones (the reports); two runs into one folder that finish together.

After every stop, the folder and what verify and the report say of it agree: every scene folder
there holds every CSV of its scene, byte for byte those of a whole run, and its outcome.json;
every scene the report (report.md and report.html) calls done is such a folder; verify passes
it and says so where a killed run left its partial files; after a Ctrl-C the report and the
manifest are rewritten for what finished and nothing partial is left.  The runs are forked from
one process that has computed the scenes once (tests/harness/kill_trials.py), so a trial costs
its writing, not its computing.
"""
from __future__ import annotations

import json
import os
import random
import re
import shutil
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from linkrepro.harness import manifest, report_folder, run_folder, verify as verify_mod
from linkrepro.harness.run import record, reproduce
from linkrepro.harness.scene import Outcome
from tests.patience import CHILD_SECONDS

FIRST, SECOND, OTHER_GROUP = "rahman1996-table5_1", "rahman1996-table5_2", "ali1977-table1"
TRIALS = Path(__file__).with_name("kill_trials.py")


@pytest.fixture(scope="module")
def two_scenes(tmp_path_factory) -> Path:
    """A folder holding a run of FIRST and SECOND."""
    out = tmp_path_factory.mktemp("two") / "out"
    reproduce([FIRST, SECOND], out, measure_readings=False)
    return out


def _trials(tmp_path: Path, base_scenes: list[str], trials: list[dict]) -> list[dict]:
    plan = tmp_path / "plan.json"
    for k, trial in enumerate(trials):
        trial.setdefault("folder", str(tmp_path / f"trial{k}"))
        trial.setdefault("events", str(tmp_path / f"events{k}.json"))
    plan.write_text(json.dumps({"base": str(tmp_path / "base"), "base_scenes": base_scenes, "trials": trials}))
    done = subprocess.run([sys.executable, str(TRIALS), str(plan)], capture_output=True, text=True,
                          timeout=CHILD_SECONDS, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stderr[-3000:]
    return [json.loads(line) for line in done.stdout.splitlines()]


def _csvs(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in folder.glob("*.csv")}


def _done_in_reports(folder: Path) -> tuple[set[str], set[str]]:
    """The scenes report.md and report.html show as run (a section with its outcome)."""
    md = (folder / "report.md").read_text()
    page = (folder / "report.html").read_text()
    return (set(re.findall(r"^## \[([^\]]+)\]\(\1/report\.md\)$", md, re.M)),
            set(re.findall(r'<section id="([^"]+)">\n<h2>[^\n]*\n(?:<p class="files">[^\n]*\n)?<p class="when">', page)))


def _agree(folder: Path, whole: dict[str, dict[str, bytes]], reference: Path) -> set[str]:
    """Check that the folder, verify and the reports agree; the scenes in the folder."""
    scenes = {p.name for p in folder.iterdir() if p.is_dir() and not p.name.startswith(".")}
    for name in scenes:                           # each whole: every CSV as a whole run writes it
        assert _csvs(folder / name) == whole[name], name
        assert Outcome.load(folder, name).scene == name
    md, page = _done_in_reports(folder)
    assert md <= scenes and page <= scenes, (md, page, scenes)
    verdict = verify_mod.verify(folder, reference)
    assert not verdict.failed, verify_mod.describe(verdict)
    killed, running = run_folder.unfinished(folder)
    assert running == [] and bool(killed) == any("killed before it finished" in n for n in verdict.notes)
    return scenes


@pytest.fixture
def stopped(tmp_path):
    """A folder holding FIRST; runs of FIRST and SECOND into copies of it, stopped at 12 points."""
    draw = random.Random(31)
    points = [draw.random() for _ in range(4)] + [-1, -2]
    trials = [{"scenes": [FIRST, SECOND]}]                                    # a whole run: counts the events
    trials += [{"scenes": [FIRST, SECOND], "signal": s, "at": at} for s in ("SIGINT", "SIGKILL") for at in points]
    trials.append({"scenes": [FIRST, SECOND], "signal": "SIGKILL", "at": 0.5})
    trials.append({"scenes": [FIRST, SECOND], "folder": trials[-1].get("folder") or str(tmp_path / "again"),
                   "again": True})
    trials[-2]["folder"] = trials[-1]["folder"]
    return _trials(tmp_path, [FIRST], trials), tmp_path


def test_a_run_stopped_anywhere_leaves_a_folder_that_does_not_lie(stopped):
    results, tmp_path = stopped
    whole_run = Path(results[0]["folder"])
    assert results[0]["exit"] == 0 and len(results[0]["events"]) > 40
    whole = {name: _csvs(whole_run / name) for name in (FIRST, SECOND)}
    assert whole[FIRST] == _csvs(tmp_path / "base" / FIRST) and len(whole[SECOND]) >= 5
    reference = tmp_path / "reference"
    verify_mod.refresh(whole_run, reference)
    stops = {"SIGINT": 0, "SIGKILL": 0}
    for trial in results[1:-1]:
        folder = Path(trial["folder"])
        assert any(e.endswith("(stopped before)") for e in trial["events"]), trial
        scenes = _agree(folder, whole, reference)
        if trial["signal"] == "SIGKILL":
            assert trial.get("killed_by") == "SIGKILL", trial
        else:                                       # Ctrl-C: exit 130, the record rewritten for what finished
            assert trial.get("exit") == 130, trial
            assert not list(folder.glob(".linkrepro-partial-*"))
            assert _done_in_reports(folder) == (scenes, scenes)
            assert scenes <= set(manifest.load(folder)["sections"])
        stops[trial["signal"]] += 1
    assert stops == {"SIGINT": 6, "SIGKILL": 7}
    # the killed run's partial files were left (hidden); the next run removes them and finishes
    again = results[-1]
    assert again["exit"] == 0 and _agree(Path(again["folder"]), whole, reference) == {FIRST, SECOND}
    assert not list(Path(again["folder"]).glob(".linkrepro-partial-*"))
    assert _done_in_reports(Path(again["folder"]))[0] == {FIRST, SECOND}


def _gone(pids: list[int]) -> bool:
    for pid in pids:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            continue
        try:                                       # a zombie has ended too
            if Path(f"/proc/{pid}/stat").read_text().split(") ")[1].startswith("Z"):
                continue
        except OSError:
            continue
        return False
    return True


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="workers die with the run on Linux (PDEATHSIG)")
def test_a_run_in_workers_stopped_by_its_worker_leaves_no_writer_and_no_lie(tmp_path):
    """Two groups in two workers; the first to put its scene in place stops the run (SIGINT, then
    in another trial SIGKILL) at once: the folder agrees with what verify and the reports say,
    and after a SIGKILL no worker is left writing into the folder."""
    scenes = [FIRST, OTHER_GROUP]
    trials = [{"scenes": scenes, "pool": True}]
    trials += [{"scenes": scenes, "pool": True, "signal": s, "from_worker": True, "pids": str(tmp_path / f"pids-{s}")}
               for s in ("SIGINT", "SIGKILL")]
    results = _trials(tmp_path, scenes, trials)
    whole_run = Path(results[0]["folder"])
    whole = {name: _csvs(whole_run / name) for name in scenes}
    reference = tmp_path / "reference"
    verify_mod.refresh(whole_run, reference)
    interrupted, killed = results[1:]
    assert interrupted.get("exit") == 130, interrupted
    assert _done_in_reports(Path(interrupted["folder"]))[0] == _agree(Path(interrupted["folder"]), whole, reference)
    assert killed.get("killed_by") == "SIGKILL", killed
    workers = [int(p.name) for p in (tmp_path / "pids-SIGKILL").iterdir()]
    assert len(workers) == 2
    deadline = threading.Event()
    for _ in range(300):                           # their parent is gone: PDEATHSIG ends them at once
        if _gone(workers):
            break
        deadline.wait(0.1)
    assert _gone(workers)
    _agree(Path(killed["folder"]), whole, reference)


def test_two_runs_that_finish_together_keep_both_sections(two_scenes, tmp_path, monkeypatch):
    """Two runs' records into one folder at the same moment: the first holds what it read of the
    manifest until the second has written, or is waiting for the folder's lock (an injected
    delay).  Under the lock both sections are kept, in the manifest and the reports; without it
    (the manifest alone, as it was written) the first run's write drops the second's section."""
    out = Path(shutil.copytree(two_scenes, tmp_path / "out"))

    def finish_together(job) -> dict:
        (out / manifest.FILE).unlink(missing_ok=True)
        read, second_waits = threading.Event(), threading.Event()
        real_load, real_flock = manifest.load, run_folder._flock

        def load(folder):
            found = real_load(folder)
            if threading.current_thread().name == "first" and not read.is_set():
                read.set()
                second_waits.wait(CHILD_SECONDS)     # the delay: until the second writes or waits
            return found

        def flock(path, wait=True):
            if threading.current_thread().name == "second":
                second_waits.set()                 # it is about to wait for the lock
            return real_flock(path, wait)
        monkeypatch.setattr(manifest, "load", load)
        monkeypatch.setattr(run_folder, "_flock", flock)

        def second():
            read.wait(CHILD_SECONDS)
            job(SECOND)
            second_waits.set()
        threads = [threading.Thread(target=job, name="first", args=(FIRST,)), threading.Thread(target=second, name="second")]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join(CHILD_SECONDS)
        monkeypatch.undo()
        return real_load(out)["sections"]

    def write_manifest(name):
        manifest.write(out, f"linkrepro reproduce {name}", scenes=[name])

    def record_run(name):
        record(out, f"linkrepro reproduce {name}", [name], manifest.now(), "")

    monkeypatch.setattr(run_folder, "fcntl", None)                  # no lock: the race, shown
    assert set(finish_together(write_manifest)) == {FIRST}
    assert set(finish_together(record_run)) == {FIRST, SECOND}      # the lock (monkeypatch.undo restored it)
    assert _done_in_reports(out)[0] == {FIRST, SECOND}


def test_the_reports_command_hints_are_shell_quoted(tmp_path):
    """The report's `linkrepro reproduce NAME --out <path>` (and the other commands it names)
    as a shell takes them: split by shlex, the path comes back whole; in markdown, a code span
    that holds the command whole."""
    import html
    import shlex
    out = tmp_path / """a b's "q" `t` $(x)"""
    out.mkdir()
    report_folder.write(out)
    md, page = (out / "report.md").read_text(), (out / "report.html").read_text()
    span = re.search(r"(`+) ?(linkrepro reproduce NAME --out .*?) ?\1 runs one", md).group(2)
    assert shlex.split(span) == ["linkrepro", "reproduce", "NAME", "--out", str(out)]
    shown = html.unescape(re.search(r"<code>(linkrepro reproduce NAME --out [^<]*)</code> runs one", page).group(1))
    assert shlex.split(shown) == ["linkrepro", "reproduce", "NAME", "--out", str(out)]
    bench = html.unescape(re.search(r"<code>(linkrepro bench [^<]*)</code>", page).group(1))
    assert shlex.split(bench) == ["linkrepro", "bench", "--out", str(out / "bench")]


def test_the_report_says_what_is_not_whole(two_scenes, tmp_path):
    """A scene's files without outcome.json, a changed file, a folder holding an unknown scene's
    outcome, a killed run's partial files: each said in the report, none shown as run."""
    out = Path(shutil.copytree(two_scenes, tmp_path / "out"))
    (out / SECOND / Outcome.FILE).unlink()
    with open(out / FIRST / "legacy.csv", "a") as handle:
        handle.write("1,2\n")
    (out / "renamed").mkdir()
    (out / "renamed" / Outcome.FILE).write_text((out / FIRST / Outcome.FILE).read_text())
    (out / f"{run_folder.PARTIAL}1-x" / "rahman1996-table5_7").mkdir(parents=True)
    report_folder.write(out)
    md = (out / "report.md").read_text()
    assert _done_in_reports(out) == (set(), set())
    assert f"## {SECOND}\n\n" in md and "incomplete: rahman1996-table5_2/ holds files but no outcome.json" in md
    assert f"## {FIRST}\n\n" in md and "changed since the run wrote it: legacy.csv" in md
    assert "Not shown: renamed (a folder holding outcome.json but no scene" in md
    assert "killed before it finished rahman1996-table5_7" in md
    page = (out / "report.html").read_text()
    assert "incomplete: rahman1996-table5_2/" in page and "killed before it finished rahman1996-table5_7" in page


def test_a_command_s_damaged_output_is_said_not_a_traceback(tmp_path):
    """The bench's markdown not UTF-8, or a figure beside it that is no image: the report is
    written and says it cannot be read."""
    out = tmp_path / "out"
    (out / "bench").mkdir(parents=True)
    (out / "bench" / "bench.md").write_bytes(b"# Bench\n\xff\xfe\n")
    report_folder.write(out)
    assert "bench/bench.md or a figure beside it cannot be read (UnicodeDecodeError)" in (out / "report.html").read_text()
    (out / "bench" / "bench.md").write_text("# Bench\n\nfine\n")
    (out / "bench" / "bench.png").write_bytes(b"\x89PNG\r\n\x1a\n cut short")
    report_folder.write(out)
    assert "cannot be read (UnidentifiedImageError)" in (out / "report.html").read_text()


@pytest.mark.parametrize("swap", [True, False], ids=["exchange", "moved aside"])
def test_a_scene_is_put_in_place_whole_with_or_without_an_exchange(tmp_path, monkeypatch, swap):
    """``place``: into an empty place by a rename; over an old folder by an exchange (Linux), or
    where the system has none, by moving the old one aside first; the old one is removed."""
    if not swap:
        monkeypatch.setattr(run_folder, "_exchange", lambda a, b: False)
    out = tmp_path / "out"
    out.mkdir()
    for k in range(2):
        new = tmp_path / "partial" / "scene"
        new.mkdir(parents=True)
        (new / "a.csv").write_text(f"x\n{k}\n")
        run_folder.place(new, out / "scene")
        assert [p.name for p in (out / "scene").iterdir()] == ["a.csv"] and (out / "scene" / "a.csv").read_text() == f"x\n{k}\n"
        assert list((tmp_path / "partial").iterdir()) == []


@pytest.mark.parametrize("ignored", [False, True])
def test_a_ctrl_c_inside_a_deferred_block_is_raised_after_it_unless_ctrl_c_is_ignored(ignored):
    """Ctrl-C during a folder write is raised when the write is done; a run started with SIGINT
    ignored (a shell's background job) is not made interruptible by it."""
    import signal as signals

    from linkrepro.harness.run import _interrupt_deferred
    previous = signals.signal(signals.SIGINT, signals.SIG_IGN if ignored else signals.default_int_handler)
    try:
        finished = []
        try:
            with _interrupt_deferred():
                os.kill(os.getpid(), signals.SIGINT)
                finished.append(True)              # the block runs to its end
            raised = False
        except KeyboardInterrupt:
            raised = True
        assert finished == [True] and raised is not ignored
        assert signals.getsignal(signals.SIGINT) is (signals.SIG_IGN if ignored else signals.default_int_handler)
    finally:
        signals.signal(signals.SIGINT, previous)
