"""Packaging: the version everywhere it is stated, the license, the citation, and (slow, only
when ``LINKREPRO_CHECK_PACKAGING=1``, as ``make packaging`` and CI set it) an sdist and a wheel
built with ``python -m build`` that install into fresh virtualenvs and run a scene from a
folder outside the repository.

The slow check builds what git has committed: meson-python's sdist is ``meson dist``, an
archive of HEAD, and ``build`` makes the wheel from that sdist, so uncommitted changes in a
working tree are not in them.  It needs ``python -m venv``, gfortran and the package index
(``build``, the build requirements and the dependencies are installed from it), and takes
minutes.
"""
from __future__ import annotations

import contextlib
import csv
import io
import os
import re
import shutil
import subprocess
import sys
import tarfile
import tomllib
import uuid
import zipfile
from pathlib import Path

import pytest

import linkrepro
from linkrepro.harness.cli import main
from tests.patience import CHILD_SECONDS

ROOT = Path(__file__).resolve().parents[2]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
CHECK_ENV = "LINKREPRO_CHECK_PACKAGING"
SCENES = ["rahman1996-table5_1", "ali1977-table1"]   # every engine, and Ali's OCR readings, in seconds
PRINTED_PROGRAMS = ["ali1977_case1_source", "ali1977_case1_cognate", "ali1977_case2_source",
                    "ali1977_case2_cognate", "ali1977_case3_source", "rahman1996_cssp_main"]
THESES = {  # title: (family name, year, thesis type, institution)
    "Kineto-elastodynamic analysis of a four-bar and its cognate mechanism":
        ("Ali", 1977, "Master of Science thesis", "Oklahoma State University"),
    "Dynamic analysis of the generalized slider crank":
        ("Rahman", 1991, "Master of Science thesis", "New Jersey Institute of Technology"),
    "Reduction of inertia-induced forces in a general spatial mechanism":
        ("Rahman", 1996, "Doctor of Philosophy dissertation", "New Jersey Institute of Technology"),
}


def test_version_is_the_same_everywhere():
    meson = re.search(r"version:\s*'([^']+)'", (ROOT / "meson.build").read_text()).group(1)
    assert linkrepro.__version__ == PYPROJECT["version"] == meson


def test_version_option_prints_the_version_and_exits_0():
    out = io.StringIO()
    with contextlib.redirect_stdout(out), pytest.raises(SystemExit) as stop:
        main(["--version"])
    assert stop.value.code == 0
    assert out.getvalue() == f"linkrepro {linkrepro.__version__}\n"


def test_license_is_the_one_pyproject_declares():
    assert PYPROJECT["license"] == "MIT" and PYPROJECT["license-files"] == ["LICENSE"]
    text = (ROOT / "LICENSE").read_text()
    assert text.startswith("MIT License\n") and "Copyright (c) 2026 the linkrepro developers" in text


def test_citation_cites_linkrepro_and_the_three_theses():
    yaml = pytest.importorskip("yaml")       # in the test extra
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    assert cff["cff-version"] == "1.2.0" and cff["type"] == "software"
    assert str(cff["version"]) == linkrepro.__version__
    assert cff["license"] == PYPROJECT["license"]
    assert [a["name"] for a in cff["authors"]] == [a["name"] for a in PYPROJECT["authors"]]
    refs = {ref["title"]: ref for ref in cff["references"]}
    assert set(refs) == set(THESES)
    for title, (family, year, kind, institution) in THESES.items():
        ref = refs[title]
        assert ref["type"] == "thesis" and ref["thesis-type"] == kind
        assert (ref["authors"][0]["family-names"], ref["year"], ref["institution"]["name"]) == (family, year, institution)


def test_project_urls_are_the_theses_addresses_only():
    # linkrepro has no public repository address: none is invented
    assert PYPROJECT["urls"] == {"Rahman 1991 thesis": "https://digitalcommons.njit.edu/theses/1292"}


# --- the slow check: build, install, run from outside ------------------------------------------

slow = pytest.mark.skipif(os.environ.get(CHECK_ENV) != "1",
                          reason=f"builds and installs the package (minutes): set {CHECK_ENV}=1 (`make packaging`)")


def _run(cmd: list, cwd: Path, extra_env: dict[str, str] | None = None) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items()
           if k not in ("LINKREPRO_PRINTED_BIN", "PYTHONPATH", "VIRTUAL_ENV", "PYTHONHOME")}
    done = subprocess.run([str(c) for c in cmd], cwd=cwd, env=env | (extra_env or {}), capture_output=True,
                          text=True, timeout=CHILD_SECONDS, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, f"{' '.join(map(str, cmd))} exited {done.returncode}:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    return done


def _venv(path: Path, *install) -> Path:
    _run([sys.executable, "-m", "venv", path], cwd=path.parent)
    if install:
        _run([path / "bin" / "python", "-m", "pip", "install", "-q", *install], cwd=path.parent)
    return path / "bin"


@pytest.fixture(scope="module")
def dists(tmp_path_factory) -> dict[str, Path]:
    """The sdist and the wheel ``python -m build`` makes of this repository (once per session)."""
    top = tmp_path_factory.mktemp("packaging")
    tools = _venv(top / "tools", "build")
    _run([tools / "python", "-m", "build", "--outdir", top / "dist", ROOT], cwd=top)
    found = {"sdist": sorted((top / "dist").glob("linkrepro-*.tar.gz")),
             "wheel": sorted((top / "dist").glob("linkrepro-*.whl"))}
    assert all(len(v) == 1 for v in found.values()), found
    return {kind: paths[0] for kind, paths in found.items()}


@slow
def test_sdist_holds_the_sources_license_and_citation(dists):
    with tarfile.open(dists["sdist"]) as sdist:
        names = {name.split("/", 1)[1] for name in sdist.getnames() if "/" in name}
    assert {"LICENSE", "CITATION.cff", "pyproject.toml", "meson.build", "README.md"} <= names
    assert {f"legacy/printed/{p}.f" for p in PRINTED_PROGRAMS} <= names


@slow
def test_wheel_holds_the_license_metadata_and_printed_programs(dists):
    with zipfile.ZipFile(dists["wheel"]) as wheel:
        names = set(wheel.namelist())
        info = next(n for n in names if n.endswith(".dist-info/METADATA")).rsplit("/", 1)[0]
        metadata = wheel.read(f"{info}/METADATA").decode()
    assert f"{info}/licenses/LICENSE" in names
    for line in ("License-Expression: MIT", "License-File: LICENSE", "Author: the linkrepro developers",
                 f"Version: {linkrepro.__version__}",
                 "Project-URL: Rahman 1991 thesis, https://digitalcommons.njit.edu/theses/1292"):
        assert line in metadata.splitlines(), line
    assert {f"linkrepro/legacy/bin/{p}" for p in PRINTED_PROGRAMS} <= names
    assert any(re.fullmatch(r"linkrepro/legacy/_rahman1996\..*\.so", n) for n in names)


@slow
@pytest.mark.parametrize("kind", ["wheel", "sdist"])
def test_installed_package_runs_scenes_from_outside_the_repository(dists, kind, tmp_path):
    """Every engine, the printed programs (installed in linkrepro/legacy/bin) among them, and the
    OCR readings (the installed listings rebuilt with gfortran, into an empty build cache)."""
    dist = dists[kind]
    if kind == "sdist":       # a path never used before: pip caches the wheel it builds by the sdist's URL
        dist = tmp_path / uuid.uuid4().hex / dist.name
        dist.parent.mkdir()
        shutil.copy(dists[kind], dist)
    bin_ = _venv(tmp_path / "venv", dist)
    away = tmp_path / "elsewhere"
    away.mkdir()
    assert _run([bin_ / "linkrepro", "--version"], cwd=away).stdout == f"linkrepro {linkrepro.__version__}\n"
    where = _run([bin_ / "python", "-c", "import linkrepro; print(linkrepro.__file__)"], cwd=away).stdout
    assert Path(where.strip()).is_relative_to(tmp_path / "venv")        # the installed copy, not the checkout
    _run([bin_ / "linkrepro", "reproduce", *SCENES, "--out", "out"], cwd=away,
         extra_env={"LINKREPRO_BUILD_CACHE": str(tmp_path / "build-cache")})
    assert (away / "out" / "report.md").exists() and (away / "out" / "report.html").exists()
    for scene in SCENES:
        for engine in ("printed", "legacy", "port_printed", "port_corrected"):
            assert (away / "out" / scene / f"{engine}.csv").stat().st_size > 0, (scene, engine)
        with open(away / "out" / scene / "diff.csv", newline="") as f:
            matched = {row["engine"] for row in csv.DictReader(f) if row["status"] == "match"}
        assert {"printed", "legacy", "port_printed"} <= matched, scene
    assert "## Reading alternatives (measured" in (away / "out" / "ali1977-table1" / "report.md").read_text()
