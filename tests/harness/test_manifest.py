"""The run record (harness/manifest.py): manifest.json's hashes are those of the files, its flags
those meson.build declares (read here from meson.build itself), its versions importlib.metadata's;
a run into a folder keeps what the manifest says of the sections it did not write, a section
whose folder is gone is dropped, a command's folder enters its report folder's manifest, and a
write is whole or not at all.  That reproduce writes it and the report shows it: test_report_folder.py."""
from __future__ import annotations

import contextlib
import hashlib
import importlib.metadata
import io
import json
import os
import re
from pathlib import Path

import pytest

from linkrepro import _build_record
from linkrepro.harness import manifest
from linkrepro.harness.cli import main

ROOT = Path(__file__).resolve().parents[2]


def _sha(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.fixture()
def folder(tmp_path) -> Path:
    """An output folder with two scenes' CSVs (one nested) and a file that is no CSV."""
    out = tmp_path / "out"
    for name, text in {"scene-a/values.csv": "x\n1\n", "scene-a/deep/more.csv": "y\n2\n",
                       "scene-b/values.csv": "x\n3\n", "scene-b/report.md": "# b\n"}.items():
        (out / name).parent.mkdir(parents=True, exist_ok=True)
        (out / name).write_text(text)
    return out


def test_hashes_are_those_of_the_files(folder):
    data = json.loads(manifest.write(folder, "linkrepro reproduce --out out", scenes=["scene-a", "scene-b"]).read_text())
    csvs = {p.relative_to(folder).as_posix(): _sha(p) for p in folder.rglob("*.csv")}
    assert data["outputs"] == csvs and len(csvs) == 3
    inputs, package = {}, manifest.ROOT       # the package's root: the checkout, or the installed package
    for top in ("legacy/printed", "legacy/src", "harness/published"):
        for name in os.listdir(package / top):
            if (package / top / name).is_file() and not name.startswith("."):
                inputs[f"{top}/{name}"] = _sha(package / top / name)
    inputs["harness/deviations.toml"] = _sha(package / "harness" / "deviations.toml")
    inputs["legacy/fixed_form.py"] = _sha(package / "legacy" / "fixed_form.py")    # how printed/ is read (D180)
    assert data["inputs"] == dict(sorted(inputs.items()))
    assert "legacy/printed/ali1977_case1_source.f" in inputs and "legacy/src/imsl_qprog.f" in inputs
    lines = "".join(f"{h}  {p}\n" for p, h in sorted(inputs.items()))
    assert data["inputs_sha256"] == hashlib.sha256(lines.encode()).hexdigest()


def meson_legacy_args() -> dict[str, list[str]]:
    """meson.build's fortran_legacy_args per compiler family, as its branches on the compiler's id
    declare them: {"gfortran": ..., "flang": ...}."""
    text = (ROOT / "meson.build").read_text()
    blocks = re.findall(r"^(?:if|elif) fc\.get_id\(\) (==|in) ([^\n]*)\n\s*fortran_legacy_args\s*=\s*\[(.*?)\]",
                        text, re.S | re.M)
    ids = {"'gcc'": "gfortran", "['flang', 'llvm-flang']": "flang"}
    return {ids[which]: re.findall(r"'([^']*)'", block) for _, which, block in blocks}


def test_the_flags_are_those_meson_build_declares():
    text = (ROOT / "meson.build").read_text()
    family = "flang" if "flang" in _build_record.GFORTRAN.lower() else "gfortran"
    declared = meson_legacy_args()[family]
    assert "-fno-automatic" in declared and "-ffp-contract=off" in declared
    # both legacy builds (the f2py extensions, the printed programs) compile with that variable
    assert re.findall(r"fortran_args:\s*(\w+)", text) == ["fortran_legacy_args", "fortran_legacy_args"]
    fields = manifest.environment({})
    assert fields["flags_f2py_extension"] == declared and fields["flags_printed_programs"] == declared


def test_the_flags_are_on_the_build_s_compile_lines():
    """Where the build's folder is at hand (an editable install), every legacy FORTRAN file was
    compiled with the recorded flags, last on its line (after meson's own)."""
    commands = Path(_build_record.__file__).parent / "compile_commands.json"
    if not commands.is_file():
        pytest.skip("the build's compile_commands.json is not at hand (an installed package)")
    lines = [c["command"].split() for c in json.loads(commands.read_text())
             if c["file"].endswith(".f") and ("legacy/src/" in c["file"] or "legacy/printed/" in c["file"]
                                              or c["file"].endswith("_d180.f"))]     # printed/ read as D180 says
    assert len(lines) >= 10
    flags = manifest.environment({})["flags_f2py_extension"]
    for words in lines:
        own = [w for w in words if w.startswith("-") and not w.startswith(("-I", "-J", "-o", "-c"))]
        assert own[-len(flags):] == flags, " ".join(words)
        assert f"-O{_build_record.OPTIMIZATION}" in own[:-len(flags)] or _build_record.OPTIMIZATION in ("plain", "0")


def test_versions_are_importlib_metadata_s():
    fields = manifest.environment({})
    for name in ("numpy", "scipy", "numba", "pandas", "matplotlib"):
        assert fields[name] == importlib.metadata.version(name)
    try:
        meson_python = importlib.metadata.version("meson-python")
    except importlib.metadata.PackageNotFoundError:
        meson_python = "not installed"
    assert fields["meson_python"] == meson_python
    assert fields["python"].split()[0] == ".".join(map(str, __import__("sys").version_info[:3]))


def test_the_keys_are_the_documented_ones_in_order(folder):
    data = json.loads(manifest.write(folder, "linkrepro reproduce --out out", scenes=["scene-a"]).read_text())
    assert tuple(data) == manifest.KEYS and data["format"] == 1
    # the docstring's list names every key, in the manifest's order
    named = [k for line in re.findall(r"^- (.*?):", manifest.__doc__, re.M) for k in re.findall(r"``(\w+)``", line)]
    assert tuple(named) == manifest.KEYS


def _with(monkeypatch, **fields):
    real = manifest.environment
    monkeypatch.setattr(manifest, "environment", lambda inputs: {**real(inputs), **fields})


def test_a_single_scene_rerun_keeps_the_other_scenes_entries(folder, monkeypatch):
    _with(monkeypatch, numpy="1.0.0")
    manifest.write(folder, "linkrepro reproduce --out out", scenes=["scene-a", "scene-b"], started="2000-01-01T00:00:00+00:00")
    monkeypatch.undo()
    data = json.loads(manifest.write(folder, "linkrepro reproduce scene-b --out out", scenes=["scene-b"]).read_text())
    assert data["scenes"] == ["scene-b"] and data["numpy"] == importlib.metadata.version("numpy")
    a, b = data["sections"]["scene-a"], data["sections"]["scene-b"]
    assert a == {"folder": "scene-a", "started": "2000-01-01T00:00:00+00:00", "command": "linkrepro reproduce --out out",
                 "differs": {"numpy": "1.0.0"}}
    assert b["command"] == "linkrepro reproduce scene-b --out out" and b["differs"] == {} and b["started"] == data["started"]
    # a third run, under the first one's numpy again: scene-a's set-up is now the top level's
    _with(monkeypatch, numpy="1.0.0")
    data = json.loads(manifest.write(folder, "linkrepro reproduce scene-b --out out", scenes=["scene-b"]).read_text())
    assert data["sections"]["scene-a"]["differs"] == {} and data["sections"]["scene-a"]["started"].startswith("2000")
    lines = "\n".join(manifest.summary(folder))
    assert "Run earlier: scene-a, by `linkrepro reproduce --out out` started 2000-01-01T00:00:00+00:00 (the same set-up)" in lines


def test_a_section_whose_folder_is_gone_is_dropped(folder):
    manifest.write(folder, "linkrepro reproduce --out out", scenes=["scene-a", "scene-b"])
    for path in sorted((folder / "scene-a").rglob("*"), reverse=True):
        path.rmdir() if path.is_dir() else path.unlink()
    (folder / "scene-a").rmdir()
    data = json.loads(manifest.write(folder, "linkrepro reproduce scene-b --out out", scenes=["scene-b"]).read_text())
    assert list(data["sections"]) == ["scene-b"] and "scene-a/values.csv" not in data["outputs"]


def test_a_command_s_folder_enters_its_report_folder_s_manifest(folder):
    bench = folder / "bench"
    bench.mkdir()
    (bench / "bench.csv").write_text("t\n1\n")
    manifest.write(folder, "linkrepro reproduce --out out", scenes=["scene-a", "scene-b"])
    own = json.loads(manifest.write(bench, "linkrepro bench --out out/bench", outputs=["bench.csv"]).read_text())
    assert own["scenes"] == ["bench"] and own["sections"]["bench"]["folder"] == "." and list(own["outputs"]) == ["bench.csv"]
    data = json.loads(manifest.include(folder, bench).read_text())
    assert set(data["sections"]) == {"scene-a", "scene-b", "bench"} and data["sections"]["bench"]["folder"] == "bench"
    assert data["command"] == "linkrepro bench --out out/bench" and data["outputs"]["bench/bench.csv"] == _sha(bench / "bench.csv")
    assert manifest.include(folder, folder / "scene-a") is None          # no manifest there: nothing to enter


def test_a_write_is_whole_or_not_at_all(folder, monkeypatch):
    path = manifest.write(folder, "linkrepro reproduce --out out", scenes=["scene-a"])
    before = path.read_text()

    def broken(*args, **kwargs):
        raise OSError("disk full")
    monkeypatch.setattr(Path, "write_text", broken)
    with pytest.raises(OSError):
        manifest.write(folder, "linkrepro reproduce --out out", scenes=["scene-b"])
    monkeypatch.undo()
    assert path.read_text() == before and not list(folder.glob(".manifest*"))


def test_a_damaged_manifest_or_another_format_is_said_and_replaced(folder):
    (folder / "manifest.json").write_text('{"format": 99}')
    with pytest.raises(manifest.ManifestError, match="format 99"):
        manifest.load(folder)
    assert "format 99" in manifest.summary(folder)[0]
    (folder / "manifest.json").write_text("{not json")
    with pytest.raises(manifest.ManifestError, match="cannot be read"):
        manifest.load(folder)
    manifest.write(folder, "linkrepro reproduce --out out", scenes=["scene-a"])
    assert manifest.load(folder)["scenes"] == ["scene-a"]


def test_differences_name_the_fields_and_inputs_that_differ(folder):
    a = json.loads(manifest.write(folder, "linkrepro reproduce --out out", scenes=["scene-a"]).read_text())
    b = {**a, "numpy": "1.0.0", "started": "later", "inputs": {**a["inputs"], "harness/deviations.toml": "0" * 64}}
    assert manifest.differences(a, b) == {"numpy": (a["numpy"], "1.0.0"),
                                          "inputs/harness/deviations.toml": (a["inputs"]["harness/deviations.toml"], "0" * 64)}


def test_a_command_into_a_report_folder_s_subfolder_records_itself_in_both(tmp_path):
    """`linkrepro differential ... --out DIR/differential` writes its manifest there and enters its
    run into DIR's, which DIR's report shows."""
    out = tmp_path / "out" / "differential"
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        status = main(["differential", "ali1977", "--samples", "2", "--out", str(out)])
    assert status == 0
    own, parent = manifest.load(out), manifest.load(out.parent)
    line = f"linkrepro differential ali1977 --samples 2 --out {out}"
    assert own["command"] == parent["command"] == line and own["sections"]["differential"]["folder"] == "."
    assert parent["sections"]["differential"]["folder"] == "differential"
    assert parent["outputs"]["differential/differential.csv"] == _sha(out / "differential.csv")
    assert f"The latest run: `{line}`" in (out.parent / "report.md").read_text()
