"""The build cache (harness/build_cache.py): a hit is the cold build's executable and answer, a
damaged entry is built again, builds side by side in several processes leave a whole entry, and
the readings measured from the cache equal those of cold builds."""
from __future__ import annotations

import shutil
import subprocess
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import pytest
from pandas.testing import assert_frame_equal

from linkrepro.harness import build_cache

needs_gfortran = pytest.mark.skipif(shutil.which("gfortran") is None, reason="needs gfortran")

PROGRAM = """\
      PROGRAM HELLO
      DOUBLE PRECISION X
      X = 1.0D0 / 3.0D0
      WRITE(*,'(ES26.17E3)') X
      END
"""
FLAGS = ["-O1", "-ffp-contract=off"]


@pytest.fixture
def cache(tmp_path, monkeypatch) -> Path:
    folder = tmp_path / "cache"
    monkeypatch.setenv(build_cache.ENV, str(folder))
    return folder


def _build(workdir: Path, text: str = PROGRAM) -> tuple[bool, bytes, str]:
    """Build PROGRAM through the cache in ``workdir``: (a hit, the executable, what it prints)."""
    workdir.mkdir(parents=True, exist_ok=True)
    (workdir / "hello.f").write_text(text)
    exe = workdir / "hello"

    def build() -> None:
        subprocess.run(["gfortran", *FLAGS, "-o", str(exe), "hello.f"], cwd=workdir, check=True, capture_output=True)
    hit = build_cache.executable(build_cache.key("gfortran", FLAGS, [("hello.f", text)]), exe, build)
    return hit, exe.read_bytes(), build_cache.run([str(exe)], capture_output=True, text=True, check=True).stdout


def test_the_folder_follows_xdg_and_can_be_turned_off(monkeypatch, tmp_path):
    monkeypatch.delenv(build_cache.ENV, raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert build_cache.folder() == tmp_path / "linkrepro" / "builds"
    monkeypatch.setenv("XDG_CACHE_HOME", "relative/path")           # not absolute: ignored, as the spec says
    assert build_cache.folder() == Path.home() / ".cache" / "linkrepro" / "builds"
    monkeypatch.setenv(build_cache.ENV, "off")
    assert build_cache.folder() is None and build_cache.key("gfortran", FLAGS, [("a.f", "x")]) is None


def test_the_key_names_everything_that_makes_the_build(cache, monkeypatch):
    monkeypatch.setattr(build_cache, "compiler_identity", lambda compiler: f"{compiler} 1.0")
    base = build_cache.key("gfortran", FLAGS, [("a.f", "X"), ("b.f", "Y")])
    assert base == build_cache.key("gfortran", list(FLAGS), [("a.f", "X"), ("b.f", "Y")])
    others = [build_cache.key("gfortran", FLAGS[:1], [("a.f", "X"), ("b.f", "Y")]),             # a flag
              build_cache.key("gfortran", FLAGS, [("a.f", "X "), ("b.f", "Y")]),               # a text
              build_cache.key("gfortran", FLAGS, [("c.f", "X"), ("b.f", "Y")]),                # a name
              build_cache.key("gfortran", FLAGS, [("b.f", "Y"), ("a.f", "X")]),                # the order
              build_cache.key("gfortran", FLAGS, [("a.f (object)", "X"), ("b.f", "Y")]),       # how it enters
              build_cache.key("gfortran", FLAGS, [("a.fX", ""), ("b.f", "Y")]),                # no run-together
              build_cache.key("gfortran-13", FLAGS, [("a.f", "X"), ("b.f", "Y")])]             # the compiler
    assert len({base, *others}) == len(others) + 1
    monkeypatch.setattr(build_cache, "compiler_identity", lambda compiler: None)
    assert build_cache.key("gfortran", FLAGS, [("a.f", "X")]) is None                       # unknown: no cache


@needs_gfortran
def test_the_compiler_identity_is_its_version_and_file():
    identity = build_cache.compiler_identity("gfortran")
    assert "GNU Fortran" in identity and build_cache.compiler_identity("gfortran") == identity
    assert build_cache.compiler_identity("gfortran-that-is-not-there") is None


@needs_gfortran
def test_a_hit_is_the_cold_build(cache, tmp_path):
    cold_hit, cold_exe, cold_out = _build(tmp_path / "cold")
    warm_hit, warm_exe, warm_out = _build(tmp_path / "warm")
    assert (cold_hit, warm_hit) == (False, True)
    assert warm_exe == cold_exe and warm_out == cold_out and "3.3333333333333331" in cold_out
    assert [p.name for p in cache.iterdir()] == [build_cache.key("gfortran", FLAGS, [("hello.f", PROGRAM)])]
    changed_hit, _, changed_out = _build(tmp_path / "changed", PROGRAM.replace("3.0D0", "7.0D0"))
    assert not changed_hit and changed_out != cold_out                    # another text: another entry


@needs_gfortran
@pytest.mark.parametrize("damage", ["flip a byte", "cut short", "empty", "no digest"])
def test_a_damaged_entry_is_built_again(cache, tmp_path, damage):
    _, exe, out = _build(tmp_path / "cold")
    entry = next(cache.iterdir())
    data = entry.read_bytes()
    entry.write_bytes({"flip a byte": data[:-100] + bytes([data[-100] ^ 1]) + data[-99:],
                       "cut short": data[:len(data) // 2], "empty": b"", "no digest": data[65:]}[damage])
    hit, again, again_out = _build(tmp_path / "again")
    assert not hit and again == exe and again_out == out
    assert entry.read_bytes() == data                                     # and the entry is whole again
    assert _build(tmp_path / "third")[0]


@needs_gfortran
def test_an_unwritable_cache_is_no_cache(tmp_path, monkeypatch):
    blocker = tmp_path / "a file"
    blocker.write_text("not a folder")
    monkeypatch.setenv(build_cache.ENV, str(blocker / "builds"))
    first, second = _build(tmp_path / "one"), _build(tmp_path / "two")
    assert (first[0], second[0]) == (False, False) and first[2] == second[2]


def _build_in_process(args: tuple[str, str]) -> tuple[bool, bytes, str]:
    folder, workdir = args
    import os
    os.environ[build_cache.ENV] = folder
    return _build(Path(workdir))


@needs_gfortran
def test_builds_side_by_side_leave_one_whole_entry(tmp_path):
    """Six processes build the same program into an empty cache at once, three times over (each
    writes the entry); then a seventh takes it from the cache: every one the same executable."""
    folder = tmp_path / "cache"
    for round_ in range(3):
        with ProcessPoolExecutor(6) as pool:
            done = list(pool.map(_build_in_process, [(str(folder), str(tmp_path / f"w{round_}-{k}")) for k in range(6)]))
        assert len({out for _, _, out in done}) == 1
    entries = [p for p in folder.iterdir()]
    assert len(entries) == 1 and not entries[0].name.startswith(".")    # no temporary file left behind
    hit, exe, out = _build_in_process((str(folder), str(tmp_path / "last")))
    assert hit and out == done[0][2]


@needs_gfortran
def test_readings_from_the_cache_equal_cold_builds(cache, monkeypatch):
    """The OCR readings of Ali's Table III and of Rahman's Table 5.2 (both drivers: the printed
    listings with the SSP routines, legacy/src through the arithmetic study's shared objects),
    measured with an empty cache and again from it: the same frames, and no build the second time."""
    from linkrepro.harness import readings
    from linkrepro.harness.scenes import TABLES
    from linkrepro.harness.scenes.rahman1996 import readings as rahman_readings
    hits = []
    executable = build_cache.executable
    monkeypatch.setattr(build_cache, "executable", lambda *args: hits.append(executable(*args)) or hits[-1])
    measured = []
    for warm in (False, True):
        hits.clear()
        rahman_readings.cssp_counts.cache_clear()                          # its in-process cache
        measured.append([readings.measure(TABLES[name].table, TABLES[name].readings)
                         for name in ("ali1977-table3", "rahman1996-table5_2")])
        assert hits and set(hits) == {warm}
    rahman_readings.cssp_counts.cache_clear()
    for cold, from_cache in zip(*measured):
        assert not cold.empty
        assert_frame_equal(cold, from_cache)


def test_the_pages_webp_figures_are_cached_pixel_for_pixel(cache, monkeypatch):
    """report.html's figures (lossless WebP) come from the cache on a second write, the same
    pixels as the PNG; a damaged entry is encoded again."""
    import io

    import numpy as np
    from PIL import Image, features

    from linkrepro.harness import html_report
    if not features.check("webp"):
        pytest.skip("Pillow without WebP: the page embeds the PNG itself")
    pixels = np.random.default_rng(7).integers(0, 256, (40, 60, 3), dtype=np.uint8)
    buffer = io.BytesIO()
    Image.fromarray(pixels).save(buffer, format="png")
    png = buffer.getvalue()
    first = html_report.webp(png)
    assert np.array_equal(np.asarray(Image.open(io.BytesIO(first)).convert("RGB")), pixels)
    entry, = cache.iterdir()

    def no_encoding(*args, **kwargs):
        raise AssertionError("encoded again: the cache was not read")
    with monkeypatch.context() as patched:
        patched.setattr(Image.Image, "save", no_encoding)
        assert html_report.webp(png) == first
    entry.write_bytes(entry.read_bytes()[:-10])                           # cut short: encoded again, stored whole
    assert html_report.webp(png) == first and build_cache.fetch(entry.name) == first


def test_the_least_recently_used_entries_go_beyond_the_limit(cache):
    """An entry stored or fetched is used; beyond the limit the ones used longest ago are removed."""
    import hashlib
    import os
    names = [hashlib.sha256(bytes([k])).hexdigest() for k in range(5)]
    for age, name in enumerate(names):
        build_cache.store(name, bytes(100))
        os.utime(cache / name, (1e9 + age, 1e9 + age))                  # stored in this order
    assert build_cache.fetch(names[0]) == bytes(100)                    # the oldest used again: kept
    entry_bytes = (cache / names[0]).stat().st_size
    removed = build_cache.prune(cache, limit=3 * entry_bytes)
    assert removed == names[1:3] and sorted(p.name for p in cache.iterdir()) == sorted([names[0], *names[3:]])
