"""The command line: a user's mistake or a missing tool gives one line ``linkrepro: error:
...`` naming the problem, no traceback, and a non-zero exit status (2 for usage errors, 1 for
a failed run, 130 for Ctrl-C).

Most cases call ``main`` in this process, as the script does (anything escaping ``main``
other than its exit would be a traceback); a few run it as a user does, in a child process,
as ``python -m linkrepro`` and as the ``linkrepro`` script next to the interpreter (each
child that runs or lists scenes pays the 2-3 s import of every scene; ``--help`` does not).  No
test runs a long reproduction: the one run through every engine is rahman1996-table5_1 (about
3 s; `linkrepro scenes` lists the scenes).
"""
from __future__ import annotations

import contextlib
import errno
import io
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from linkrepro.harness.cli import main
from tests.patience import CHILD_SECONDS

SCRIPT = Path(sys.executable).with_name("linkrepro")
COMMANDS = {"module": [sys.executable, "-m", "linkrepro"], "script": [str(SCRIPT)]}
VIAS = ["module", pytest.param("script", marks=pytest.mark.skipif(
    not SCRIPT.exists(), reason=f"no linkrepro script next to {sys.executable}"))]
FAST_SCENE = "rahman1996-table5_1"          # every engine in about 3 s
BIN_ENV = "LINKREPRO_PRINTED_BIN"


def _env(**changes: str | None) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k != BIN_ENV}
    for key, value in changes.items():
        if value is None:
            env.pop(key, None)
        else:
            env[key] = value
    return env


def run(*args: str, via: str = "in-process", cwd: Path, env: dict | None = None,
        timeout: float = CHILD_SECONDS) -> subprocess.CompletedProcess:
    """The command with these arguments: ``main`` here (``via="in-process"``), or a child process."""
    if via != "in-process":
        return subprocess.run([*COMMANDS[via], *args], capture_output=True, text=True, cwd=cwd,
                              env=env or _env(), timeout=timeout, stdin=subprocess.DEVNULL)
    saved_env, saved_cwd = dict(os.environ), os.getcwd()
    out, err = io.StringIO(), io.StringIO()
    try:
        os.environ.clear()
        os.environ.update(env or _env())
        os.chdir(cwd)
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                status = main(list(args))
            except SystemExit as exc:                  # argparse's exit, as the script would see it
                status = exc.code if isinstance(exc.code, int) else 1
    finally:
        os.chdir(saved_cwd)
        os.environ.clear()
        os.environ.update(saved_env)
    return subprocess.CompletedProcess(list(args), status, out.getvalue(), err.getvalue())


def error_line(done: subprocess.CompletedProcess, status: int, *words: str) -> str:
    """The one error line of a failed command, after checking status and that there is no traceback."""
    assert "Traceback" not in done.stderr, done.stderr
    assert done.returncode == status, (done.returncode, done.stderr)
    lines = [line for line in done.stderr.splitlines() if line.startswith("linkrepro:")]
    assert len(lines) == 1, done.stderr
    assert lines[0].startswith("linkrepro: error: "), lines
    for word in words:
        assert word in lines[0], (word, lines[0])
    return lines[0]


# ------------------------------------------------------------------ what works

@pytest.mark.parametrize("via", ["in-process", *VIAS[1:]])
def test_help(via, tmp_path):
    done = run("--help", via=via, cwd=tmp_path)
    assert done.returncode == 0 and done.stderr == ""
    assert done.stdout.startswith("usage: linkrepro") and "reproduce" in done.stdout
    done = run("reproduce", "--help", via=via, cwd=tmp_path)
    assert done.returncode == 0 and "--out" in done.stdout and "--skip-readings" in done.stdout


#: what ``--help`` and ``--version`` must not import: the libraries the engines are written with
#: (numpy alone adds 99 modules; --help took 2.1 s of CPU when it imported them all, 0.13 s now,
#: measured 2026-11-28), and linkrepro's engines (the port, the FORTRAN's f2py extensions in
#: legacy/) and scenes
HEAVY = ("numpy", "pandas", "numba", "llvmlite", "matplotlib", "scipy", "exudyn", "quadprog", "mpmath", "jinja2",
         "PIL", "linkrepro.port", "linkrepro.legacy", "linkrepro.harness.scene", "linkrepro.harness.table_scene")
#: the modules they may import beyond the standard library: 15
#: today (linkrepro, its errors, the harness, cli, blas_threads, command, lazy, the registry, the
#: three theses' packages, and the two theses' commands modules with their settings); room for a
#: thesis more with a command (three) and a light module or two, while any engine library
#: brings a hundred
LIGHT_MODULES = 20
#: a fresh interpreter: the modules ``main(arguments)`` imports, and those of them beyond the
#: standard library (``sys.stdlib_module_names``: which of its modules load depends on the install,
#: e.g. an editable one's import hook loads shutil at start-up, a wheel's argparse later)
_IMPORTS = """
import contextlib, io, json, sys
before = set(sys.modules)
from linkrepro.harness.cli import main
with contextlib.redirect_stdout(io.StringIO()):
    try:
        status = main(sys.argv[1:])
    except SystemExit as exc:
        status = exc.code
new = sorted(set(sys.modules) - before)
print(json.dumps({"status": status, "new": new,
                  "beyond": [name for name in new if name.partition(".")[0] not in sys.stdlib_module_names]}))
"""


def _imported(cwd: Path, *arguments: str) -> dict:
    """What ``main(arguments)`` imports in a fresh interpreter (``_IMPORTS``), and its status."""
    done = subprocess.run([sys.executable, "-c", _IMPORTS, *arguments], capture_output=True, text=True, cwd=cwd,
                          env=_env(), timeout=CHILD_SECONDS, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.mark.parametrize("argument", ["--help", "--version"])
def test_help_and_version_import_no_engine(argument, tmp_path):
    imported = _imported(tmp_path, argument)
    assert imported["status"] == 0
    heavy = [name for name in imported["new"] if any(name == root or name.startswith(f"{root}.") for root in HEAVY)]
    assert heavy == []
    scenes = [name for name in imported["new"]
              if name.startswith("linkrepro.harness.scenes") and name.endswith(".catalog")]
    assert scenes == []                         # the registry's or a thesis's scenes (harness/lazy.py)
    assert "linkrepro.harness.cli" in imported["beyond"]
    assert len(imported["beyond"]) <= LIGHT_MODULES, imported["beyond"]


def test_the_import_check_sees_an_engine(tmp_path):
    """The check above can fail: ``verify`` imports numpy and pandas before it reads its
    arguments (a bad ``--units``: status 2)."""
    imported = _imported(tmp_path, "verify", "--units", "-1")
    assert imported["status"] == 2
    assert {"numpy", "pandas"} <= set(imported["new"])
    assert len(imported["beyond"]) > LIGHT_MODULES


def test_module_and_script_list_the_same_scenes(tmp_path):
    if not SCRIPT.exists():
        pytest.skip(f"no linkrepro script next to {sys.executable}")
    module, script = (run("scenes", via=via, cwd=tmp_path) for via in ("module", "script"))
    assert module.returncode == script.returncode == 0
    assert module.stderr == script.stderr == ""
    assert module.stdout == script.stdout
    names = [line.split()[0] for line in module.stdout.splitlines()]
    assert {"ali1977-table1", FAST_SCENE, "rahman1991-example"} <= set(names)


# ------------------------------------------------------------------ usage errors: status 2

@pytest.mark.parametrize("via", ["in-process", "module"])
def test_unknown_scene(via, tmp_path):
    done = run("reproduce", "no-such-scene", "ali1977-tabel1", "--out", str(tmp_path / "o"), via=via, cwd=tmp_path)
    line = error_line(done, 2, "unknown scene", "'no-such-scene'", "did you mean 'ali1977-table1'", "linkrepro scenes")
    assert "ali1977-table1" in line
    assert not (tmp_path / "o").exists()


@pytest.mark.parametrize("value", ["0", "-3", "x", ""])
def test_bad_repeat(value, tmp_path):
    error_line(run("bench", "--repeat", value, cwd=tmp_path), 2, "--repeat", ">= 1")


@pytest.mark.parametrize("args", [[], ["frobnicate"], ["scenes", "extra"]])
def test_bad_command_line(args, tmp_path):
    error_line(run(*args, cwd=tmp_path), 2, "--help")


@pytest.mark.parametrize("value", ["", "   "])
def test_empty_out_is_refused_not_taken_as_the_current_folder(value, tmp_path):
    error_line(run("reproduce", FAST_SCENE, "--out", value, cwd=tmp_path), 2, "--out", "empty")
    assert list(tmp_path.iterdir()) == []


def test_out_is_a_file(tmp_path):
    (tmp_path / "file").write_text("x")
    error_line(run("reproduce", FAST_SCENE, "--out", str(tmp_path / "file"), cwd=tmp_path), 2,
               str(tmp_path / "file"), "is a file", "--out")


def test_out_below_a_file(tmp_path):
    (tmp_path / "file").write_text("x")
    target = tmp_path / "file" / "out"
    error_line(run("reproduce", FAST_SCENE, "--out", str(target), cwd=tmp_path), 2, str(target), "is a file")


def _unwritable_folders() -> list:
    """Folders no one may write in, root included (chmod does not stop root)."""
    cases = [pytest.param("/proc/linkrepro-no-such-folder", "cannot create", id="proc")]
    if Path("/sys/kernel").is_dir():
        cases.append(pytest.param("/sys/kernel", "cannot write", id="sysfs"))
    return cases


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="needs Linux's /proc and /sys")
@pytest.mark.parametrize("folder, words", _unwritable_folders())
def test_out_cannot_be_written(folder, words, tmp_path):
    error_line(run("reproduce", FAST_SCENE, "--out", folder, cwd=tmp_path), 2, folder, words)


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes through file permissions")
def test_out_without_write_permission(tmp_path):
    folder = tmp_path / "locked"
    folder.mkdir(mode=0o500)
    try:
        error_line(run("reproduce", FAST_SCENE, "--out", str(folder), cwd=tmp_path), 2, "cannot write", str(folder))
    finally:
        folder.chmod(0o700)


@pytest.mark.parametrize("name", ["report.md", "manifest.json"])
def test_out_checked_before_the_run(tmp_path, name):
    """What the run would write at the top level is checked first: no scene ran."""
    out = tmp_path / "out"
    (out / name).mkdir(parents=True)
    error_line(run("reproduce", FAST_SCENE, "--out", str(out), cwd=tmp_path), 2, name, "is a folder")
    assert sorted(p.name for p in out.iterdir()) == [name]


# ------------------------------------------------------------------ failed runs: status 1

def test_output_file_that_cannot_be_written_during_the_run(tmp_path, monkeypatch):
    """A write that fails during the run (here the disk full, as a CSV is written) is one line,
    exit 1; the scene's folder is as it was (a scene is put in place whole or not at all)."""
    from linkrepro.harness import table_scene
    earlier = tmp_path / "out" / FAST_SCENE / "published.csv"
    earlier.parent.mkdir(parents=True)
    earlier.write_text("an earlier run's\n")

    def full(frame, path, *args, **kwargs):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))
    monkeypatch.setattr(table_scene, "write_csv", full)
    error_line(run("reproduce", FAST_SCENE, "--out", str(tmp_path / "out"), cwd=tmp_path), 1,
               "could not write", FAST_SCENE, os.strerror(errno.ENOSPC))
    assert [p.name for p in earlier.parent.iterdir()] == ["published.csv"] and earlier.read_text() == "an earlier run's\n"
    assert not list((tmp_path / "out").glob(".linkrepro-partial-*"))


def test_without_leaves_scenes_out(tmp_path):
    """``--without`` runs the named (or all) scenes but those; a name it does not know, or one
    that leaves nothing to run, is a usage error."""
    out = tmp_path / "out"
    done = run("reproduce", FAST_SCENE, "rahman1996-table5_3", "--without", "rahman1996-table5_3", "--out", str(out),
               "--skip-readings", cwd=tmp_path, via="module")
    # (in a child process: a run in this one would fix the printed programs' folder, which later tests change)
    assert done.returncode == 0, done.stderr
    assert sorted(p.parent.name for p in out.glob("*/outcome.json")) == [FAST_SCENE]
    error_line(run("reproduce", "--without", "no-such-scene", "--out", str(out), cwd=tmp_path), 2, "no-such-scene")
    error_line(run("reproduce", FAST_SCENE, "--without", FAST_SCENE, "--out", str(out), cwd=tmp_path), 2,
               "--without", "no scene")


def test_missing_printed_program_in_reproduce(tmp_path):
    """The other engines still run and are written; the failure is one line and exit 1."""
    empty = tmp_path / "bin"
    empty.mkdir()
    out = tmp_path / "out"
    done = run("reproduce", FAST_SCENE, "--out", str(out), cwd=tmp_path, env=_env(**{BIN_ENV: str(empty)}))
    error_line(done, 1, "rahman1996_cssp_main", "not built", str(empty), "report.html")
    assert (out / FAST_SCENE / "legacy.csv").exists() and not (out / FAST_SCENE / "printed.csv").exists()
    assert "rahman1996_cssp_main" in (out / "report.md").read_text()
    assert "legacy" in done.stdout                   # the counts are still printed


def test_printed_program_that_cannot_start(tmp_path):
    folder = tmp_path / "bin"
    folder.mkdir()
    (folder / "rahman1996_cssp_main").write_text("not a program\n")
    done = run("reproduce", FAST_SCENE, "--out", str(tmp_path / "out"), cwd=tmp_path,
               env=_env(**{BIN_ENV: str(folder)}))
    error_line(done, 1, "rahman1996_cssp_main", "could not be started")


def _path_without_gfortran(folder: Path) -> str:
    """A PATH with every program of the current PATH but gfortran (symbolic links)."""
    folder.mkdir()
    for directory in os.environ.get("PATH", "").split(os.pathsep):
        if not os.path.isdir(directory):
            continue
        for entry in os.scandir(directory):
            if "gfortran" not in entry.name and not (folder / entry.name).exists():
                (folder / entry.name).symlink_to(entry.path)
    return str(folder)


def test_missing_compiler_is_found_before_the_run(tmp_path):
    """ali1977-table1's OCR readings rebuild a printed listing with gfortran."""
    out = tmp_path / "out"
    env = _env(PATH=_path_without_gfortran(tmp_path / "path"))
    done = run("reproduce", "ali1977-table1", "--out", str(out), cwd=tmp_path, env=env)
    error_line(done, 1, "gfortran", "not on PATH", "ali1977-table1", "--skip-readings")
    assert [p.name for p in out.iterdir()] == []      # nothing ran


def test_broken_compiler(tmp_path):
    fake = tmp_path / "fake"
    fake.mkdir()
    (fake / "gfortran").write_text("#!/bin/sh\necho 'gfortran: fatal error: cannot execute f951' >&2\nexit 1\n")
    (fake / "gfortran").chmod(0o755)
    env = _env(PATH=f"{fake}{os.pathsep}{os.environ.get('PATH', '')}")
    done = run("reproduce", "ali1977-table1", "--out", str(tmp_path / "out"), cwd=tmp_path, env=env)
    error_line(done, 1, "gfortran", "could not build", "f951")


# ------------------------------------------------------------------ Ctrl-C: status 130

@pytest.mark.parametrize("via", ["module"])
def test_ctrl_c(via, tmp_path):
    """SIGINT once the run has started (its output folder exists): one line, status 130."""
    out = tmp_path / "out"
    child = subprocess.Popen([*COMMANDS[via], "reproduce", "ali1977-table3", "--out", str(out)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=tmp_path,
                             env=_env(), stdin=subprocess.DEVNULL,
                             preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        deadline = time.monotonic() + CHILD_SECONDS
        while not out.is_dir() and child.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert child.poll() is None, "the run ended before it could be interrupted"
        child.send_signal(signal.SIGINT)
        stdout, stderr = child.communicate(timeout=CHILD_SECONDS)
    finally:
        if child.poll() is None:
            child.kill()
            child.communicate()
    assert child.returncode == 130, (child.returncode, stderr)
    assert "Traceback" not in stderr
    assert stderr.strip().splitlines()[-1] == "linkrepro: interrupted"
    assert len([line for line in stderr.splitlines() if line.startswith("linkrepro:")]) == 1
