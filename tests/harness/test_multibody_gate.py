"""Exudyn is optional: without it the multibody scenes are skipped (saying how to get it), the
run goes on and succeeds, the reports show why, and ``linkrepro verify`` refuses a skipped
scene the reference holds.  A child process sees an ``exudyn`` that cannot be imported (a
package on PYTHONPATH that raises ImportError), as on a machine without the extra."""
from __future__ import annotations

import importlib.metadata
import lzma
import os
import subprocess
import sys

import pytest

from linkrepro.harness import multibody
from linkrepro.harness.scene import Outcome, ReportScene, RunOptions, SceneSkipped
from linkrepro.harness.verify import verify
from tests.patience import CHILD_SECONDS

SCENE = "rahman1996-multibody"


@pytest.fixture
def hidden(tmp_path):
    """An environment whose ``import exudyn`` fails."""
    package = tmp_path / "hide" / "exudyn"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text('raise ImportError("hidden for the test")\n')
    return {**os.environ, "PYTHONPATH": str(tmp_path / "hide")}


def test_require_says_how_to_install_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "exudyn", None)      # import exudyn raises ImportError
    with pytest.raises(multibody.ExudynMissing, match=r"pip install 'linkrepro\[multibody\]'"):
        multibody.require()


def test_the_pin_is_the_package_s_extra():
    """PINNED (the version the tolerances were measured with) is what the extra installs."""
    wanted = [r for r in importlib.metadata.requires("linkrepro") or [] if r.startswith(multibody.DISTRIBUTION)]
    assert wanted == [f'{multibody.DISTRIBUTION}=={multibody.PINNED}; extra == "multibody"']


def test_a_skipped_scene_keeps_its_reason(tmp_path):
    def produce(out_dir):
        raise SceneSkipped("needs a thing; `pip install thing` installs it")

    scene = ReportScene("a-scene", "A scene", "group", 0, produce, lambda result: [])
    outcome = scene.write(tmp_path, RunOptions())
    assert outcome.skipped.startswith("needs a thing") and not outcome.failures
    outcome.save(tmp_path)
    assert Outcome.load(tmp_path, "a-scene").skipped == outcome.skipped


def test_without_exudyn_a_run_skips_the_scene_and_says_why(tmp_path, hidden):
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "linkrepro", "reproduce", SCENE, "--out", str(out), "--skip-readings"],
                          capture_output=True, text=True, env=hidden, timeout=CHILD_SECONDS, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stderr
    assert f"{SCENE}: skipped, needs Exudyn {multibody.PINNED}" in done.stdout
    assert multibody.INSTALL in done.stdout
    assert "(0 scenes, 1 skipped" in done.stdout.splitlines()[-1]          # the last line counts it apart
    assert f"**Skipped: needs Exudyn {multibody.PINNED}" in (out / "report.md").read_text()
    assert "Skipped: needs Exudyn" in (out / "report.html").read_text()
    assert sorted(p.name for p in (out / SCENE).iterdir()) == ["outcome.json"]
    reference = tmp_path / "reference" / SCENE            # a reference that holds the scene
    reference.mkdir(parents=True)
    (reference / "curves.csv.xz").write_bytes(lzma.compress(b"crank_deg\n0\n"))
    verdict = verify(out, reference.parent, scenes=[SCENE])
    assert [f.problem.split(":")[0] for f in verdict.failed] == ["skipped in the run", "nothing was compared"]


def test_without_exudyn_the_bench_leaves_its_knobs_out(monkeypatch):
    from linkrepro.harness import bench_run
    monkeypatch.setitem(sys.modules, "exudyn", None)
    assert not multibody.available()
    assert not [knob.name for knob in bench_run.knobs(quick=True) if "Exudyn" in knob.name]
