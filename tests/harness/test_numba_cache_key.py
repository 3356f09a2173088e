"""numba's cache of the port's kernels is keyed to the port's source (``port/_numba_cache.py``).

numba reuses a cached kernel while its own file is unchanged: an edit to a kernel it calls from
another module leaves the caller's old machine code in use (numba issue 1833).  These tests edit
a callee in a copy of the package and see the caller's result change, and check where the keyed
folder goes (the user's cache, a ``NUMBA_CACHE_DIR`` of the user's, a fallback) and its pruning,
without numba.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import linkrepro
import linkrepro.port
from linkrepro.port import _numba_cache as nc

from ..patience import CHILD_SECONDS

PORT, TOP = Path(linkrepro.port.__file__).parent, Path(linkrepro.__file__).parent

#: the Case I source kernel (``source._source_motion``) at one input angle: it calls
#: ``fourbar.half_angle_roots`` (another module) for T3; prints T3 (rad) and numba's cache folder
CALLER = r"""
import math, os, sys
import numpy as np
sys.path.insert(0, sys.argv[1])
from copied.port.ali1977.fourbar import freudenstein_constants
from copied.port.ali1977.source import _source_motion
l1, l3, l4, l5 = 1.0, 3.0, 3.5, 4.0
out = _source_motion(np.array([60.0]), math.pi, *freudenstein_constants(l1, l3, l4, l5), l1, l3, l4, 0.0,
                     10.0, True, 1.0)
print(repr(float(out[1, 0])), os.environ["NUMBA_CACHE_DIR"])
"""
CALLEE_RETURN = "    return t3, t4, disc3, disc4\n"
EDITED_RETURN = "    return t3 + 1.0, t4, disc3, disc4\n"


def _copy_package(dest: Path) -> Path:
    """The package's top modules and its port, without their caches, as the package ``copied``."""
    package = dest / "copied"
    shutil.copytree(PORT, package / "port", ignore=shutil.ignore_patterns("__pycache__"))
    for path in TOP.glob("*.py"):
        shutil.copy(path, package / path.name)
    return package


def _caller(copy_root: Path, cache_home: Path) -> tuple[float, Path]:
    env = {k: v for k, v in os.environ.items() if k not in (nc.ENV, nc.OURS)}
    env["XDG_CACHE_HOME"] = str(cache_home)
    done = subprocess.run([sys.executable, "-c", CALLER, str(copy_root)], capture_output=True, text=True, env=env,
                          timeout=CHILD_SECONDS, stdin=subprocess.DEVNULL)
    assert done.returncode == 0, done.stderr[-2000:]
    t3, folder = done.stdout.split()
    return float(t3), Path(folder)


def test_an_edit_to_a_callee_recompiles_its_caller(tmp_path):
    """The caller's T3 before and after ``half_angle_roots`` (in fourbar.py) is edited to return
    T3 + 1: each in a fresh process on the same cache home; the caller's own file is unchanged,
    its kernel was cached by the first run, and the second returns the edited value (numba alone
    would load the first run's machine code: source.py did not change)."""
    package, cache_home = _copy_package(tmp_path / "copy"), tmp_path / "cache"
    before, first = _caller(tmp_path / "copy", cache_home)
    assert first.parent == cache_home / "linkrepro" / "numba"
    assert list(first.rglob("source._source_motion-*.nbi")), "the first run cached no caller"
    fourbar = package / "port" / "ali1977" / "fourbar.py"
    text = fourbar.read_text()
    assert text.count(CALLEE_RETURN) == 1
    fourbar.write_text(text.replace(CALLEE_RETURN, EDITED_RETURN))
    after, second = _caller(tmp_path / "copy", cache_home)
    assert second != first and second.parent == first.parent
    assert after == before + 1.0
    assert not list(package.rglob("*.nb[ic]")), "a kernel cached beside its module (a read-only install cannot)"


def test_the_folder_is_keyed_and_placed(tmp_path, monkeypatch):
    """Without numba: the key follows every byte of the sources; the folder goes under
    XDG_CACHE_HOME, under a NUMBA_CACHE_DIR of the user's, the same in a child process that
    inherits linkrepro's, and to the temporary folder where the root cannot be made."""
    monkeypatch.delitem(sys.modules, "numba", raising=False)      # no numba config reloaded here
    for name in (nc.ENV, nc.OURS):
        monkeypatch.delenv(name, raising=False)
    port, top = tmp_path / "pkg" / "port", tmp_path / "pkg"
    (port / "sub").mkdir(parents=True)
    (port / "sub" / "callee.py").write_text("X = 1\n")
    (top / "errors.py").write_text("")
    key = nc.source_key(port, top)
    (port / "sub" / "callee.py").write_text("X = 2\n")
    after_callee = nc.source_key(port, top)
    assert after_callee != key
    (top / "errors.py").write_text("#")
    assert nc.source_key(port, top) not in {key, after_callee}

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    folder = nc.configure(port, top)
    assert folder == tmp_path / "xdg" / "linkrepro" / "numba" / (nc.PREFIX + nc.source_key(port, top))
    assert os.environ[nc.ENV] == os.environ[nc.OURS] == str(folder) and folder.is_dir()
    assert nc.configure(port, top) == folder                         # a child process: the same

    monkeypatch.setenv(nc.ENV, str(tmp_path / "mine"))              # the user's own
    mine = nc.configure(port, top)
    assert mine.parent == tmp_path / "mine" and nc.configure(port, top) == mine

    monkeypatch.delenv(nc.ENV)
    (tmp_path / "file").write_text("")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "file"))    # no folder can be made there
    monkeypatch.setattr("tempfile.tempdir", str(tmp_path / "tmp"))
    assert nc.configure(port, top).parent.parent == tmp_path / "tmp"


def test_prune_keeps_the_recently_used(tmp_path):
    """Of seven keyed folders (and a folder of another name), the four most recently used stay,
    and one more used within the hour; the two unused for two and three hours go."""
    now = time.time()
    ages = [0, 10, 20, 30, 600, 2 * 3600, 3 * 3600]               # seconds since last use
    folders = [tmp_path / f"{nc.PREFIX}{i:016x}" for i in range(len(ages))]
    for folder, age in zip(folders, ages):
        folder.mkdir()
        (folder / "x.nbi").write_text("")
        os.utime(folder, (now - age, now - age))
    (tmp_path / "other").mkdir()
    os.utime(tmp_path / "other", (now - 10 ** 6, now - 10 ** 6))
    assert sorted(nc.prune(tmp_path)) == folders[5:]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([f.name for f in folders[:5]] + ["other"])
