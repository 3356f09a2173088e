"""Packaging: the version everywhere it is stated, the license, the citation, and (slow, only
when ``LINKREPRO_CHECK_PACKAGING=1``, as ``make packaging`` and CI set it) an sdist and a wheel
built with ``python -m build`` that install into fresh virtualenvs and run a scene from a
folder outside the repository.

The slow check builds what git has committed: meson-python's sdist is ``meson dist``, an
archive of HEAD, and ``build`` makes the wheel from that sdist, so uncommitted changes in a
working tree are not in them.  The wheel is repaired with ``auditwheel`` (gfortran's runtime
libraries copied into it, a manylinux tag for this glibc) and run where this system's
libgfortran, libquadmath and gfortran are hidden (``_hidden``).  It needs ``python -m venv``,
gfortran, ``unshare`` (util-linux) and the package index (pyproject's ``packaging`` extra, the
build requirements and the dependencies are installed from it), and takes minutes.
"""
from __future__ import annotations

import contextlib
import csv
import io
import os
import platform
import re
import shlex
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
TOOLS = PYPROJECT["optional-dependencies"]["packaging"]     # build, auditwheel, patchelf
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
#: what a manylinux wheel may take from the system (auditwheel's policy): everything else is in the wheel
SYSTEM_LIBS = {"linux-vdso.so.1", "libc.so.6", "libm.so.6", "libgcc_s.so.1", "libpthread.so.0", "libdl.so.2",
               "librt.so.1", "libstdc++.so.6"}
FORTRAN_RUNTIME = re.compile(r"lib(gfortran|quadmath)\b")


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
    """The sdist and the wheel ``python -m build`` makes of this repository (once per session):
    ``linux wheel`` as built, ``wheel`` repaired by ``auditwheel`` for the manylinux tag its
    ``show`` names (the oldest glibc the wheel's symbols allow)."""
    top = tmp_path_factory.mktemp("packaging")
    tools = _venv(top / "tools", *TOOLS)
    _run([tools / "python", "-m", "build", "--outdir", top / "dist", ROOT], cwd=top)
    found = {"sdist": sorted((top / "dist").glob("linkrepro-*.tar.gz")),
             "linux wheel": sorted((top / "dist").glob("linkrepro-*.whl"))}
    shown = _run([tools / "auditwheel", "show", found["linux wheel"][0]], cwd=top).stdout
    plat = re.findall(r'"(manylinux_\d+_\d+_\w+)"', shown)[0]
    _run([tools / "auditwheel", "repair", "--plat", plat, "--wheel-dir", top / "repaired", found["linux wheel"][0]],
         cwd=top, extra_env={"PATH": f"{tools}{os.pathsep}{os.environ['PATH']}"})     # its patchelf
    found["wheel"] = sorted((top / "repaired").glob("linkrepro-*.whl"))
    assert all(len(v) == 1 for v in found.values()), found
    return {kind: paths[0] for kind, paths in found.items()}


def _hidden() -> list[str]:
    """A command prefix: what follows runs in a user and mount namespace of its own (``unshare``)
    in which every libgfortran and libquadmath the system's loader knows (``ldconfig -p``) and
    every gfortran on PATH is ``/dev/null`` (bind mounts that only that process tree sees): to
    the loader and to ``shutil.which``, a machine without gfortran.  Skips where unprivileged
    namespaces are not allowed."""
    tried = subprocess.run(["unshare", "--user", "--map-root-user", "--mount", "true"], capture_output=True, text=True)
    if tried.returncode != 0:
        pytest.skip(f"cannot hide the system's libgfortran: unshare failed ({tried.stderr.strip()})")
    ldconfig = shutil.which("ldconfig", path=os.pathsep.join([os.environ.get("PATH", ""), "/sbin", "/usr/sbin"]))
    known = subprocess.run([ldconfig, "-p"], capture_output=True, text=True, check=True).stdout
    libs = [line.split(" => ")[-1] for line in known.splitlines() if FORTRAN_RUNTIME.search(line)]
    compilers = [str(p) for d in os.environ.get("PATH", "").split(os.pathsep) if d for p in Path(d).glob("*gfortran*")]
    hide = sorted({os.path.realpath(p) for p in libs + compilers})
    assert any(FORTRAN_RUNTIME.search(Path(p).name) for p in hide), f"no system libgfortran to hide: {known}"
    script = "".join(f"mount --bind /dev/null {shlex.quote(p)} && " for p in hide) + 'exec "$@"'
    return ["unshare", "--user", "--map-root-user", "--mount", "sh", "-c", script, "sh"]


def _ldd(path: Path) -> dict[str, str]:
    """The shared libraries the loader resolves for ``path``: name -> file (or ``not found``)."""
    out = _run(["ldd", path], cwd=path.parent).stdout
    return {name: file or name for name, file in re.findall(r"^\s*(\S+)(?: => (.+?))?(?: \(0x[0-9a-f]+\))?$", out, re.M)}


def _loaded(folder: Path) -> dict[str, list[str]]:
    """From ``LD_DEBUG=libs`` logs (``LD_DEBUG_OUTPUT``, one file a process): each process's
    program -> the libraries the loader initialised in it."""
    out = {}
    for log in folder.glob("ld.*"):
        text = log.read_text()
        programs = re.findall(r"initialize program: (.+)", text)
        assert len(programs) == 1, (log, programs)          # one exec a process: no library misattributed
        out.setdefault(programs[0].strip(), []).extend(m.strip() for m in re.findall(r"calling init: (.+)", text))
    return out


def _check_scenes(out: Path) -> None:
    """Every engine of ``SCENES`` wrote its CSV, and printed, legacy and the printed port match."""
    assert (out / "report.md").exists() and (out / "report.html").exists()
    for scene in SCENES:
        for engine in ("printed", "legacy", "port_printed", "port_corrected"):
            assert (out / scene / f"{engine}.csv").stat().st_size > 0, (scene, engine)
        with open(out / scene / "diff.csv", newline="") as f:
            matched = {row["engine"] for row in csv.DictReader(f) if row["status"] == "match"}
        assert {"printed", "legacy", "port_printed"} <= matched, scene


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
def test_the_repaired_wheel_carries_gfortrans_runtime_for_this_glibc(dists):
    """auditwheel copied libgfortran and libquadmath into linkrepro.libs/ (the wheel as built had
    none) and tagged it manylinux_2_N with N no later than this machine's glibc."""
    glibc = tuple(map(int, platform.libc_ver()[1].split(".")))
    tag = re.search(r"-(manylinux_(\d+)_(\d+)_\w+)\.whl$", dists["wheel"].name)
    assert tag and (int(tag.group(2)), int(tag.group(3))) <= glibc, (dists["wheel"].name, glibc)
    for kind, bundled in (("linux wheel", set()), ("wheel", {"gfortran", "quadmath"})):
        with zipfile.ZipFile(dists[kind]) as wheel:
            libs = {m.group(1) for n in wheel.namelist() if n.startswith("linkrepro.libs/")
                    if (m := FORTRAN_RUNTIME.match(n.removeprefix("linkrepro.libs/")))}
        assert libs == bundled, kind


@slow
def test_sdist_installs_and_runs_scenes_from_outside_the_repository(dists, tmp_path):
    """Every engine, the printed programs (installed in linkrepro/legacy/bin) among them, and the
    OCR readings (the installed listings rebuilt with gfortran, into an empty build cache)."""
    dist = tmp_path / uuid.uuid4().hex / dists["sdist"].name   # a path never used before: pip caches
    dist.parent.mkdir()                                          # the wheel it builds by the sdist's URL
    shutil.copy(dists["sdist"], dist)
    bin_ = _venv(tmp_path / "venv", dist)
    away = tmp_path / "elsewhere"
    away.mkdir()
    assert _run([bin_ / "linkrepro", "--version"], cwd=away).stdout == f"linkrepro {linkrepro.__version__}\n"
    where = _run([bin_ / "python", "-c", "import linkrepro; print(linkrepro.__file__)"], cwd=away).stdout
    assert Path(where.strip()).is_relative_to(tmp_path / "venv")        # the installed copy, not the checkout
    _run([bin_ / "linkrepro", "reproduce", *SCENES, "--out", "out"], cwd=away,
         extra_env={"LINKREPRO_BUILD_CACHE": str(tmp_path / "build-cache")})
    _check_scenes(away / "out")
    assert "## Reading alternatives (measured" in (away / "out" / "ali1977-table1" / "report.md").read_text()


@slow
def test_repaired_wheel_runs_where_gfortran_is_not(dists, tmp_path):
    """The repaired wheel in a fresh venv: ``ldd`` resolves every library of its native files
    (the f2py extensions, the printed programs) to the wheel's own copies or to what manylinux
    lets a wheel take from the system, with the system's libgfortran present; then, where the
    system's libgfortran, libquadmath and gfortran are hidden (``_hidden``, where a printed
    program of the wheel as built cannot start), every engine runs, and the loader's log shows
    each printed program loading the wheel's libgfortran and libquadmath."""
    hide = _hidden()
    bin_ = _venv(tmp_path / "venv", dists["wheel"])
    away = tmp_path / "elsewhere"
    away.mkdir()
    package = Path(_run([bin_ / "python", "-c", "import linkrepro; print(linkrepro.__file__)"], cwd=away)
                   .stdout.strip()).parent
    assert package.is_relative_to(tmp_path / "venv")
    bundled = package.parent / "linkrepro.libs"
    native = [p for p in package.rglob("*") if p.is_file() and p.read_bytes()[:4] == b"\x7fELF"]
    assert {p.name for p in native} >= set(PRINTED_PROGRAMS) and any(p.suffix == ".so" for p in native)
    for path in native:
        resolved = _ldd(path)
        for name, file in resolved.items():
            assert file != "not found" and (name in SYSTEM_LIBS or Path(file).name.startswith("ld-linux")
                                            or Path(file).resolve().parent == bundled), (path, name, file)
        runtime = {m.group(1) for name in resolved if (m := FORTRAN_RUNTIME.search(name))}
        # the extensions' sources write nothing (register D041, D052): they need no Fortran runtime
        assert runtime == (set() if path.suffix == ".so" else {"gfortran", "quadmath"}), (path, resolved)

    control = tmp_path / "as-built" / PRINTED_PROGRAMS[-1]
    control.parent.mkdir()
    with zipfile.ZipFile(dists["linux wheel"]) as wheel:
        control.write_bytes(wheel.read(f"linkrepro/legacy/bin/{control.name}"))
    control.chmod(0o755)
    failed = subprocess.run(hide + [str(control)], capture_output=True, text=True, stdin=subprocess.DEVNULL,
                            timeout=CHILD_SECONDS)
    assert failed.returncode == 127 and "libgfortran" in failed.stderr, failed.stderr

    assert _run(hide + [bin_ / "linkrepro", "--version"], cwd=away).stdout == f"linkrepro {linkrepro.__version__}\n"
    refused = subprocess.run(hide + [str(bin_ / "linkrepro"), "reproduce", "ali1977-table1", "--out", "out"], cwd=away,
                             capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=CHILD_SECONDS)
    assert refused.returncode == 1 and "gfortran is not on PATH" in refused.stderr, refused.stderr
    logs = tmp_path / "ld"
    logs.mkdir()
    _run(hide + ["env", "LD_DEBUG=libs", f"LD_DEBUG_OUTPUT={logs / 'ld'}",       # not unshare's and sh's
                 bin_ / "linkrepro", "reproduce", *SCENES, "--skip-readings", "--out", "out"], cwd=away)
    _check_scenes(away / "out")
    assert "## Reading alternatives\n\nNot measured" in (away / "out" / "ali1977-table1" / "report.md").read_text()
    loaded = _loaded(logs)
    programs = {Path(p).name: libs for p, libs in loaded.items() if Path(p).parent == package / "legacy" / "bin"}
    assert {"ali1977_case1_source", "ali1977_case1_cognate", "rahman1996_cssp_main"} <= set(programs), loaded.keys()
    for name, libs in programs.items():
        runtime = {FORTRAN_RUNTIME.search(Path(lib).name).group(1): Path(lib).resolve().parent
                   for lib in libs if FORTRAN_RUNTIME.search(Path(lib).name)}
        assert runtime == {"gfortran": bundled, "quadmath": bundled}, (name, libs)
    for program, libs in loaded.items():      # numpy and scipy load their wheels' own copies
        assert all(Path(lib).is_relative_to(tmp_path / "venv") for lib in libs if FORTRAN_RUNTIME.search(lib)), program
    python = next(libs for p, libs in loaded.items() if Path(p).name.startswith("python"))
    assert {Path(lib).name.split(".")[0] for lib in python} >= {"_ali1977", "_rahman1996"}   # the legacy engines
