"""An output folder is one report (harness/report_folder.py): two scenes run into one folder one
after the other both stay in report.md and report.html; the bench's and a thesis command's
outputs are shown where they are there and named with the command that writes them where
not; a broken outcome is said in its section; a report that cannot be built leaves the last one.
The browser's view of the same page is tests/harness/test_report_html.py's."""
from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from linkrepro.harness import html_report, report_folder
from linkrepro.harness.run import reproduce
from linkrepro.harness.scene import Outcome
from linkrepro.harness.scenes import SCENES
from tests.patience import CHILD_SECONDS

FIRST, SECOND = "rahman1996-table5_1", "ali1977-table1"


@pytest.fixture(scope="module")
def two_runs(tmp_path_factory) -> Path:
    """FIRST run into a folder, then SECOND alone into the same folder."""
    out = tmp_path_factory.mktemp("folder")
    reproduce([FIRST], out, measure_readings=False)
    reproduce([SECOND], out, measure_readings=False)
    return out


def test_a_second_run_keeps_the_first_scene_in_both_reports(two_runs):
    md, page = (two_runs / "report.md").read_text(), (two_runs / "report.html").read_text()
    for name in (FIRST, SECOND):
        assert f"## [{name}]({name}/report.md)" in md
        assert f'<section id="{name}">' in page
    first, second = (Outcome.load(two_runs, n) for n in (FIRST, SECOND))
    assert first.finished <= second.finished and f"Run {first.finished}" in md and f"Run {second.finished}" in md
    # the headline counts both tables: 12 + 190 published cells, once per engine (4 engines)
    assert f"{(12 + 190) * 4} cells" in md.splitlines()[2]


def test_the_manifest_keeps_the_first_scene_and_the_report_shows_it(two_runs):
    """reproduce writes manifest.json: the second run at its top, the first run's scene kept with
    its own start and command; both reports end with "How this run was made" from it."""
    record = json.loads((two_runs / "manifest.json").read_text())
    assert record["format"] == 1 and record["scenes"] == [SECOND]
    assert record["command"] == f"linkrepro reproduce {SECOND} --out {two_runs} --skip-readings"
    first, second = record["sections"][FIRST], record["sections"][SECOND]
    assert first["command"] == f"linkrepro reproduce {FIRST} --out {two_runs} --skip-readings"
    assert first["started"] <= second["started"] == record["started"] and first["differs"] == {} == second["differs"]
    assert {f"{FIRST}/diff.csv", f"{SECOND}/diff.csv"} <= set(record["outputs"])
    md, page = (two_runs / "report.md").read_text(), (two_runs / "report.html").read_text()
    made = md.split("## How this run was made\n")[1]
    assert f"`{record['command']}`" in made and record["flags_f2py_extension"][0] in made
    assert f"Run earlier: {FIRST}, by `{first['command']}` started {first['started']} (the same set-up)" in made
    section = page.split('<section id="how-made">')[1].split("</section>")[0]
    assert "<h2>How this run was made</h2>" in section and 'href="manifest.json"' in section
    assert f"<code>{record['command']}</code>" in section and '<a href="#how-made">' in page


def test_the_scenes_not_run_are_named_with_the_command(two_runs):
    md = (two_runs / "report.md").read_text()
    others = [n for n in SCENES if n not in (FIRST, SECOND)]
    assert f"`linkrepro reproduce NAME --out {two_runs}`" in md and all(n in md.split("## Not run")[1] for n in others)


def test_a_missing_output_is_named_with_the_command_that_writes_it(two_runs):
    md = (two_runs / "report.md").read_text()
    assert f"`linkrepro bench --out {two_runs / 'bench'}` writes it" in md
    assert f"`linkrepro arithmetic --out {two_runs / 'arithmetic'}` writes it" in md


def test_a_present_output_is_rendered_not_pasted(tmp_path):
    bench = tmp_path / "bench"
    bench.mkdir()
    (bench / "bench.md").write_text("# Bench\n\nSome **words**, a [file](bench.csv).\n\n| a | b |\n|---|---|\n| 1 | 2 |\n\n"
                                    "![error against time](bench.png)\n")
    report_folder.write(tmp_path)
    page = (tmp_path / "report.html").read_text()
    section = page.split('<section id="bench">')[1].split("</section>")[0]
    assert "<table>" in section and "<td>1</td>" in section and "<strong>words</strong>" in section
    assert "|---|" not in section and "**" not in section and "![" not in section
    assert 'href="bench/bench.csv"' in section                 # relative to the report's folder
    assert "(bench/bench.md)" in (tmp_path / "report.md").read_text()


def test_markdown_is_rendered_with_raw_html_escaped():
    html = html_report.markdown_html("<script>x</script> and `code`\n\n- one\n- two")
    assert "<script>" not in html and "&lt;script&gt;" in html and "<li>one</li>" in html


def test_an_unreadable_outcome_is_said_in_its_section(two_runs, tmp_path):
    out = tmp_path / "copy"
    (out / FIRST).mkdir(parents=True)
    (out / FIRST / Outcome.FILE).write_text(json.dumps({"scene": FIRST}))   # no title, no counts
    report_folder.write(out)
    md = (out / "report.md").read_text()
    assert f"## {FIRST}" in md and "cannot be read" in md and "run the scene again" in md


def test_a_scene_report_that_cannot_be_read_is_said_in_its_section(two_runs, tmp_path):
    """A report.md its run kept no record of (an outcome written before outcomes recorded their
    files), not UTF-8: the page says so in the scene's section and is written."""
    out = tmp_path / "copy"
    (out / FIRST).mkdir(parents=True)
    outcome = Outcome.load(two_runs, FIRST)
    outcome.files = None
    outcome.save(out)
    (out / FIRST / "report.md").write_bytes(b"# T\n\xff\xfe not UTF-8\n")
    report_folder.write(out)
    section = (out / "report.html").read_text().split(f'<section id="{FIRST}">')[1].split("</section>")[0]
    assert f"{FIRST}/report.md cannot be read (UnicodeDecodeError); run the scene again" in section


def test_a_report_that_cannot_be_built_leaves_the_last_one(two_runs, monkeypatch):
    before = {name: (two_runs / name).read_text() for name in report_folder.FILES}

    def broken(folder, latest):
        raise RuntimeError("the page cannot be rendered")
    monkeypatch.setattr(html_report, "render", broken)
    with pytest.raises(RuntimeError):
        report_folder.write(two_runs)
    assert {name: (two_runs / name).read_text() for name in report_folder.FILES} == before
    assert not list(two_runs.glob(".report*"))                  # no temporary file left


def test_a_page_over_its_budget_is_written_with_a_warning(two_runs, monkeypatch):
    """Within the budget nothing is said; over it, a PageSizeWarning naming the size, the page still
    written whole."""
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error", html_report.PageSizeWarning)
        page = report_folder.write(two_runs)
    size = page.stat().st_size
    monkeypatch.setattr(html_report, "PAGE_BUDGET", size - 1)
    with pytest.warns(html_report.PageSizeWarning, match=rf"{size / 1e6:.2f} MB, over the page's budget"):
        report_folder.write(two_runs)
    assert page.stat().st_size == size


def _linkrepro(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "linkrepro", *args], capture_output=True, text=True, cwd=cwd,
                          timeout=CHILD_SECONDS)


def test_a_run_ends_by_naming_report_html(tmp_path):
    done = _linkrepro("reproduce", FIRST, "--skip-readings", "--out", str(tmp_path / "o"), cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    last = done.stdout.strip().splitlines()[-1]
    assert last.startswith(f"report: {tmp_path / 'o' / 'report.html'} and report.md  (1 scene; 48 cells:")


@pytest.mark.parametrize("where", ["missing", "a-file", "empty"])
def test_explain_with_an_out_that_holds_no_run_says_so(tmp_path, where):
    out = tmp_path / where
    if where == "a-file":
        out.write_text("not a folder")
    elif where == "empty":
        out.mkdir()
    done = _linkrepro("explain", FIRST, "crank/i_xx", "before", "--out", str(out), cwd=tmp_path)
    why = {"missing": "does not exist", "a-file": "is not a folder", "empty": f"holds no run of {FIRST}"}[where]
    assert done.returncode == 2 and why in done.stderr and "--run" in done.stderr, done.stderr
    assert done.stdout == "" and "Traceback" not in done.stderr


def test_explain_runs_the_engines_only_when_asked(tmp_path):
    done = _linkrepro("explain", FIRST, "crank/i_xx", "before", "--out", str(tmp_path), "--run", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert re.search(r"^\s+legacy\s", done.stdout, re.M)
