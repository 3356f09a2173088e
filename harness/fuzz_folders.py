"""The fuzz's damaged run folders: a small real run folder, damaged, then verified and reported.

``damaged_run_folder(damage, kind, index, seed)`` copies a run folder made once per fuzz worker,
at its first such call (a run of two small scenes, and a reference made of it by ``verify
--refresh``; not a warm-up: workers that never damage a folder never make it), damages one
thing in it, then runs ``linkrepro verify`` on it (the command, as a user does) and writes its
report.  ``kind`` is what is damaged: a scene's CSV, another of a scene's files, a scene's
outcome.json, the manifest, a report, a scene's folder (the ``index``-th of them, modulo their
number); ``damage`` how: ``truncate`` (to fewer bytes), ``empty``, ``delete``, ``rename``,
``garble`` (one to three bytes changed), ``folder`` (a file replaced by a folder, a folder by a
file), ``extra`` (a CSV added to the scene), ``none``; ``seed`` draws the bytes and lengths.

The check (``CHECKS["run_folder"]``) says what is broken: verify or the report writer ended in
a traceback (an exception escaping the command, an untyped one from the writer; the writer may
refuse a report file replaced by a folder with an OSError), verify passed a folder whose damage
it must see (decided from the damage alone: a scene's file changed, missing or added, its
outcome.json unreadable or no longer saying what it said of the scene, a scene's folder
renamed, a manifest no longer a JSON object with its fields), or failed an undamaged one, or
the report calls a scene it must see damaged run.  This module knows no thesis: the scenes are
the first two of the registry's that share a group and have a published table, found by the
run's own machinery.
"""
from __future__ import annotations

import contextlib
import io
import json
import random
import re
import shutil
import tempfile
import traceback
from functools import lru_cache
from pathlib import Path

from .fuzz_calls import Arg, Call, Entry, Pool

DAMAGES = ("none", "truncate", "empty", "delete", "rename", "garble", "folder", "extra")
KINDS = ("csv", "scene_file", "outcome", "manifest", "report", "scene")
#: "hostile" values are other valid choices: every call damages a folder
_DAMAGE = Pool("other", tuple(map(repr, DAMAGES)))
_KIND = Pool("other", tuple(map(repr, KINDS)))
_NUMBER = Pool("other", tuple(map(str, (0, 1, 2, 3, 5, 8, 13, 999))))


@lru_cache(maxsize=1)
def _made() -> tuple[Path, Path]:
    """(a run folder of two small scenes, a reference made of it), made once per process."""
    from . import run, verify
    from .scenes import TABLES
    root = Path(tempfile.mkdtemp(prefix="linkrepro-fuzz-folder-"))
    by_group: dict[str, list[str]] = {}
    for name, scene in TABLES.items():
        by_group.setdefault(scene.group, []).append(name)
    scenes = next(names[:2] for names in sorted(by_group.values(), key=len, reverse=True) if len(names) >= 2)
    with contextlib.redirect_stdout(io.StringIO()):
        run.reproduce(scenes, root / "run", measure_readings=False)
    verify.refresh(root / "run", root / "reference")
    return root / "run", root / "reference"


def _targets(folder: Path, kind: str) -> list[Path]:
    scenes = sorted(p for p in folder.iterdir() if p.is_dir() and not p.name.startswith("."))
    files = sorted(f for s in scenes for f in s.iterdir() if f.is_file())
    return {"csv": [f for f in files if f.suffix == ".csv"],
            "scene_file": [f for f in files if f.suffix != ".csv" and f.name != "outcome.json"],
            "outcome": [f for f in files if f.name == "outcome.json"],
            "manifest": [folder / "manifest.json"], "report": [folder / "report.md", folder / "report.html"],
            "scene": scenes}[kind]


def _still_says(original: bytes, damaged: bytes, keys: tuple[str, ...]) -> bool:
    """Whether a damaged JSON object still parses to one with ``keys`` as the original has them
    (all its keys where ``keys`` is empty)."""
    try:
        before, after = json.loads(original), json.loads(damaged)
    except ValueError:
        return False
    if not isinstance(after, dict):
        return False
    return all(after.get(k) == before.get(k) for k in keys) if keys else set(after) == set(before)


def _damage(target: Path, damage: str, rng: random.Random) -> bytes | None:
    """Damage ``target`` (a file or a scene's folder); a file's bytes after it where they changed
    (b"" where it is gone), else None."""
    if target.is_dir():
        if damage == "delete":
            shutil.rmtree(target)
        elif damage == "rename":
            target.rename(target.with_name(target.name + "-renamed"))
            return b""
        elif damage == "folder":                      # a folder replaced by a file
            shutil.rmtree(target)
            target.write_text("a file\n")
        elif damage != "none":                        # truncate, empty, garble: its files gone
            for path in target.iterdir():
                path.unlink()
        return None
    data = target.read_bytes()
    if damage in ("truncate", "empty") and data:
        after = data[:rng.randrange(len(data)) if damage == "truncate" else 0]
        target.write_bytes(after)
        return after
    if damage == "garble" and data:
        garbled = bytearray(data)
        for at in rng.sample(range(len(data)), min(len(data), rng.randint(1, 3))):
            garbled[at] ^= rng.randrange(1, 256)
        target.write_bytes(bytes(garbled))
        return bytes(garbled)
    if damage == "delete":
        target.unlink()
    elif damage == "rename":
        target.rename(target.with_name("renamed-" + target.name))
    elif damage == "folder":
        target.unlink()
        target.mkdir()
    else:
        return None
    return b""


def _must_fail(kind: str, damage: str, before: bytes, after: bytes | None) -> bool:
    """Whether verify must see a damage, from the damage alone: a scene's file changed, gone or
    added; its outcome.json no longer saying what it said of the scene; a scene's folder renamed;
    the manifest there but no longer a JSON object with its fields."""
    if after is None or kind == "report":
        return False
    if kind == "outcome" and damage == "garble":
        return not _still_says(before, after, ("scene", "files", "skipped"))
    if kind == "manifest":
        return damage not in ("delete", "rename") and not _still_says(before, after, ())
    return True


def _scene_of(folder: Path, target: Path) -> str:
    """The scene a damaged path lies in ('' for the folder's own files)."""
    return target.relative_to(folder).parts[0] if len(target.relative_to(folder).parts) > 1 else ""


def _raised(exc: BaseException) -> str:
    frames = traceback.extract_tb(exc.__traceback__)
    where = f" at {Path(frames[-1].filename).name}:{frames[-1].lineno}" if frames else ""
    return f"{type(exc).__name__}: {(str(exc).splitlines() or [''])[0][:200]}{where}"


def damaged_run_folder(damage: str, kind: str, index: int, seed: int) -> dict:
    """Damage a copy of the worker's run folder (see the module's docstring); what verify and the
    report writer did."""
    from . import report_folder
    from .cli import main
    if damage not in DAMAGES or kind not in KINDS or not isinstance(index, int) or not isinstance(seed, int):
        raise ValueError(f"damaged_run_folder({damage!r}, {kind!r}, {index!r}, {seed!r}): not a damage of {DAMAGES}, "
                         f"a kind of {KINDS} and two whole numbers")
    base, reference = _made()
    with tempfile.TemporaryDirectory(prefix="linkrepro-fuzz-damaged-") as tmp:
        folder = Path(shutil.copytree(base, Path(tmp) / "run"))
        candidates = _targets(folder, kind)
        target = candidates[index % len(candidates)]
        scene = _scene_of(folder, target)
        if damage == "extra":
            into = folder / (scene or next(p.name for p in _targets(folder, "scene")))
            (into / "extra.csv").write_text("a,b\n1,2\n")
            scene, must_fail = into.name, True
        else:
            before = target.read_bytes() if target.is_file() else b""
            must_fail = _must_fail(kind, damage, before, _damage(target, damage, random.Random(seed)))
        result = {"damage": damage, "target": target.relative_to(folder).as_posix(), "must_fail": must_fail,
                  "scene": scene if must_fail else "", "raised": ""}
        out, err = io.StringIO(), io.StringIO()
        try:
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                result["verify"] = main(["verify", "--out", str(folder), "--reference", str(reference)])
        except BaseException as exc:              # noqa: BLE001 - a traceback is what is looked for
            result["verify"], result["raised"] = None, f"verify: {_raised(exc)}"
        said = (err.getvalue() or out.getvalue()).strip().splitlines()
        result["verify_said"] = said[-1][:300] if said else ""
        try:
            report_folder.write(folder)
            md = (folder / "report.md").read_text()
            result["report_shows"] = sorted(set(re.findall(r"^## \[([^\]]+)\]\(\1/report\.md\)$", md, re.M)))
        except OSError as exc:                    # a report file replaced by a folder: refused
            refused = exc.filename and Path(str(exc.filename)).name.lstrip(".").startswith(report_folder.FILES)
            result["report_shows"] = []
            if not refused:
                result["raised"] = result["raised"] or f"report: {_raised(exc)}"
        except Exception as exc:                  # noqa: BLE001
            result["report_shows"], result["raised"] = [], result["raised"] or f"report: {_raised(exc)}"
    return result


def _broken(arguments, result) -> str | None:
    """What a damaged folder's verify and report got wrong, or None."""
    if result["raised"]:
        return f"{result['damage']} {result['target']}: {result['raised']}"
    if result["verify"] == 0 and result["must_fail"]:
        return f"verify passed a folder with {result['target']} damaged ({result['damage']}): {result['verify_said']}"
    if result["damage"] == "none" and result["verify"] != 0:
        return f"verify failed an undamaged folder: {result['verify_said']}"
    if result["scene"] and result["scene"] in result["report_shows"]:
        return f"the report shows {result['scene']} as run with {result['target']} damaged ({result['damage']})"
    return None


def _spec(rng: random.Random) -> Call:
    return Call("damaged_run_folder", [Arg(None, repr(rng.choice(DAMAGES[1:])), _DAMAGE),
                                       Arg(None, repr(rng.choice(KINDS)), _KIND),
                                       Arg(None, str(rng.randrange(20)), _NUMBER),
                                       Arg(None, str(rng.randrange(10**6)), _NUMBER)])


ENTRIES = [Entry("run_folder.damaged_run_folder", _spec, check="run_folder")]
CHECKS = {"run_folder": _broken}


def namespace() -> dict:
    return {"damaged_run_folder": damaged_run_folder}
