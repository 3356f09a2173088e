"""How a register entry knows and how it explains (``harness/register.py``): ``basis`` and
``settles`` parsed and validated, ``tolerance`` (an entry that explains only by closeness) and
``whole`` claims checked; what every reader's view shows of them (report.md's entries, the
HTML report's entry, ``linkrepro explain``); the scenes' floors name an entry stating them.
"""
from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import pytest

from linkrepro.harness import register as register_mod
from linkrepro.harness.diff import CLASSES, check_floor, words
from linkrepro.harness.register import BASES, load

ROOT = Path(__file__).resolve().parents[2]
ENTRY = '''
[[deviation]]
id = "D900"
kind = "{kind}"
{more}
title = "t"
where = "w"
printed = "p"
meant = "m"
evidence = "e"
effect = "f"
'''


def _register(tmp_path: Path, more: str = "", kind: str = "original-bug", after: str = "") -> dict:
    path = tmp_path / "deviations.toml"
    path.write_text(ENTRY.format(kind=kind, more=more) + after)
    return load(path)


@pytest.mark.parametrize("basis", list(BASES))
def test_each_basis_is_read(tmp_path, basis):
    settles = '\nsettles = "the lost page found"' if basis == "inferred" else ""
    entry = _register(tmp_path, f'basis = "{basis}"{settles}')["D900"]
    assert entry.basis == basis and entry.settles == ("the lost page found" if settles else None)
    shown = dict(entry.how_known())
    assert shown["basis"] == f"{basis}: {BASES[basis]}"
    assert ("settles" in shown) == (basis == "inferred")


def test_an_entry_without_basis_says_so(tmp_path):
    entry = _register(tmp_path)["D900"]
    assert entry.basis is None and entry.how_known() == [("basis", "not stated")]


@pytest.mark.parametrize("more, words_", [
    ('basis = "guessed"', "basis 'guessed' not in"),
    ('basis = "inferred"', "needs 'settles'"),
    ('basis = "inferred"\nsettles = " "', "settles must say"),
    ('basis = "measured"\nsettles = 3', "settles must say"),
    ("tolerance = 0", "not a relative tolerance"),
    ("tolerance = 1.5", "not a relative tolerance"),
    ("tolerance = true", "not a relative tolerance"),
    ('tolerance = "1e-6"', "not a relative tolerance"),
])
def test_bad_basis_settles_or_tolerance_is_a_clear_error(tmp_path, more, words_):
    with pytest.raises(ValueError, match=f"D900.*{words_}"):
        _register(tmp_path, more)


def test_an_unresolved_entry_states_no_tolerance(tmp_path):
    with pytest.raises(ValueError, match="D900: an unresolved entry explains nothing"):
        _register(tmp_path, "tolerance = 1e-6", kind="unresolved")


WHOLE = '''  [[deviation.cells]]
  scene = "s"
  rows = [10]
  columns = ["after"]
  engines = ["legacy"]
  whole = {whole}
'''
CHECK = '''  [[deviation.check]]
  command = "true"
'''


def test_a_whole_claim_is_read(tmp_path):
    entry = _register(tmp_path, after=WHOLE.format(whole="true") + CHECK)["D900"]
    assert [c.whole for c in entry.cells] == [True] and entry.cells[0].covers("s", 10, "after", "legacy")


@pytest.mark.parametrize("kind, more, after, words_", [
    ("unresolved", "", WHOLE.format(whole="true") + CHECK, "not an unresolved one"),
    ("portability", "tolerance = 1e-6", WHOLE.format(whole="true") + CHECK, "not a tolerance"),
    ("original-bug", "", WHOLE.format(whole="true"), "need a \\[\\[deviation.check\\]\\]"),
    ("original-bug", "", WHOLE.format(whole='"yes"') + CHECK, "not true or false"),
])
def test_a_whole_claim_needs_a_cause_and_a_check(tmp_path, kind, more, after, words_):
    with pytest.raises(ValueError, match=f"D900.*{words_}"):
        _register(tmp_path, more, kind=kind, after=after)


def test_every_view_of_an_entry_shows_its_basis_and_tolerance(tmp_path):
    """report.md's entry, the HTML report's entry and ``linkrepro explain``'s text."""
    from linkrepro.harness import html_report, trail
    from linkrepro.harness.report import render_entry
    entry = _register(tmp_path, 'basis = "inferred"\nsettles = "the lost page found"\ntolerance = 1e-6',
                      kind="portability")["D900"]
    md = render_entry(entry)
    assert f"- basis: inferred: {BASES['inferred']}" in md and "- settles: the lost page found" in md
    assert "- tolerance: explains a cell only by closeness: within 1e-06 relative" in md
    fields = dict(html_report._entry(entry)["fields"])
    assert fields["basis"].startswith("inferred: ") and fields["settles"] == "the lost page found"
    assert "within 1e-06 relative" in fields["tolerance"]
    shown = SimpleNamespace(scene=SimpleNamespace(name="s", key_name="k", title="T"), row="1", column="c",
                            published_text="1.0", half_unit=0.05, source="seed", engines=(), statements=(),
                            entries=(entry,), notes=(), assumptions="")
    text = " ".join(trail.as_text(shown).split())
    assert "basis: inferred: from the published table's fit" in text and "settles: the lost page found" in text


def test_every_entry_of_the_register_says_how_it_knows():
    entries = register_mod.load().values()
    assert all(e.basis in BASES for e in entries)
    assert all(e.settles for e in entries if e.basis == "inferred")


def test_every_floor_names_an_entry_that_states_it():
    from linkrepro.harness.scenes import TABLES
    register = register_mod.load()
    floors = [scene for scene in TABLES.values() if scene.floor_id]
    assert floors, "no scene has a floor: this test checks nothing"
    for scene in floors:
        check_floor(scene, register)
        assert register[scene.floor_id].tolerance == scene.rel_floor


def test_a_floor_its_entry_does_not_state_is_an_error(tmp_path):
    register = _register(tmp_path)
    scene = SimpleNamespace(name="s", floor_id="D900", rel_floor=1e-6)
    with pytest.raises(ValueError, match="scene s: floor_id D900 states tolerance None, not the scene's rel_floor"):
        check_floor(scene, register)
    with pytest.raises(ValueError, match="floor_id D999 states no entry"):
        check_floor(SimpleNamespace(name="s", floor_id="D999", rel_floor=1e-6), register)
    check_floor(SimpleNamespace(name="s", floor_id=None, rel_floor=0.0), register)      # no floor: nothing to check


def test_the_register_page_says_every_basis_and_class():
    page = (ROOT / "docs" / "register.md").read_text()
    for basis in BASES:
        assert f"`{basis}`" in page, basis
    for name in CLASSES:
        assert f"*{words(name)}*" in page, name


@pytest.mark.parametrize("kind, more, after, words_", [
    ("model-assumption", "", "", "needs `scenes`"),
    ("model-assumption", "scenes = []", "", "needs `scenes`"),
    ("model-assumption", 'scenes = "ali1977-table1"', "", "needs `scenes`"),
    ("model-assumption", 'scenes = ["s", ""]', "", "needs `scenes`"),
    ("model-assumption", 'scenes = ["s"]\nquirk = "q"', "", "switches no quirk, but gives quirk"),
    ("model-assumption", 'scenes = ["s"]\ntolerance = 1e-6', "", "but gives tolerance"),
    ("model-assumption", 'scenes = ["s"]', WHOLE.format(whole="false"), "but gives cells"),
    ("original-bug", 'scenes = ["s"]', "", "`scenes` is for a model-assumption only"),
])
def test_a_malformed_model_assumption_is_a_clear_error(tmp_path, kind, more, after, words_):
    with pytest.raises(ValueError, match=f"D900.*{words_}"):
        _register(tmp_path, more, kind=kind, after=after)


def test_a_model_assumption_is_said_for_its_scenes_only(tmp_path):
    register = _register(tmp_path, 'basis = "measured"\nscenes = ["s", "t"]', kind="model-assumption")
    assert register["D900"].scenes == ("s", "t")
    assert [e.id for e in register_mod.assumed_by("t", register)] == ["D900"]
    assert register_mod.assumed_by("u", register) == [] and register_mod.assumptions_said("u", register) == ""
    assert "model-assumption" in register_mod.assumptions_said("s", register)
    assert "D900 t." in register_mod.assumptions_said("s", register)          # its id and title


def test_the_register_s_model_assumptions_name_scenes_and_measure_their_effect():
    """Case II's axial lumping, Case I's massless links, the CSSP's crank pin, K.E.D.'s quasi-static
    linear method: each names scenes that exist, claims no cell and has a check of its effect."""
    from linkrepro.harness.scenes import SCENES
    found = [e for e in register_mod.load().values() if e.kind == register_mod.MODEL_ASSUMPTION]
    assert {"D185", "D186", "D187", "D188"} <= {e.id for e in found}
    for entry in found:
        assert entry.scenes and set(entry.scenes) <= set(SCENES), entry.id
        assert entry.basis == "measured" and entry.checks and not entry.cells and entry.quirk is None, entry.id


def test_a_report_scene_s_report_states_its_model_assumptions(tmp_path, monkeypatch):
    """A scene without a published table: the section is added to the report.md it wrote, where
    the register names it; nothing is added for a scene no model assumption names."""
    from linkrepro.harness.scene import ReportScene
    register = _register(tmp_path, 'basis = "measured"\nscenes = ["s"]', kind="model-assumption")
    monkeypatch.setattr(register_mod, "load", lambda *args: register)

    def produce(name):
        def write(out: Path):
            (out / name).mkdir(parents=True)
            (out / name / "report.md").write_text(f"# {name}\n")
        return write
    for name in ("s", "u"):
        ReportScene(name, name.upper(), "g", 0, produce(name), lambda result: []).write(tmp_path / "out", None)
    said = (tmp_path / "out" / "s" / "report.md").read_text()
    assert said.startswith("# s\n\n## What the corrected engine still assumes") and "- **D900** t. f" in said
    assert (tmp_path / "out" / "u" / "report.md").read_text() == "# u\n"
