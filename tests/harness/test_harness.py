"""The harness: published table, register claims, the quirks' effects, the CLI."""
import numpy as np
import pandas as pd
import pytest

from linkrepro.harness import cli
from linkrepro.harness.diff import diff_scene, quirk_effects
from linkrepro.harness.published_tables import PublishedTable
from linkrepro.harness.scenes import TABLES as SCENES, get
from linkrepro.port.ali1977 import PRINTED


@pytest.fixture(scope="module", params=[name for name in SCENES if name.startswith("ali1977")])
def scene(request):
    return get(request.param)


@pytest.fixture(scope="module")
def published(scene):
    return PublishedTable.load(scene.table)


@pytest.fixture(scope="module")
def results(scene):
    return {engine: scene.run(engine) for engine in ("printed", "legacy", "port_printed", "port_corrected")}


def test_published_table_shape(published, scene):
    assert list(published.text.columns) == scene.columns
    assert len(published.text) == 19 and published.values.notna().all().all()
    assert list(published.values["input_deg"]) == list(range(0, 361, 20))


def test_no_cell_is_unexplained(scene, published, results, register):
    diff = diff_scene(scene, published, results, register)
    assert len(diff) == 4 * 190
    assert (diff["status"] == "unexplained").sum() == 0, diff[diff["status"] == "unexplained"]
    registered = diff[diff["status"] == "registered"]
    assert registered["register_ids"].str.len().gt(0).all()
    for ids in registered["register_ids"]:
        assert all(i in register for i in ids.split())


def test_register_cell_claims_are_real_deviations(scene, published, results, register):
    """A claimed cell must really differ for that engine: no stale claims."""
    pub, half = published.values, published.half_unit
    for entry in register.values():
        for claim in entry.cells:
            if claim.scene != scene.name:      # e.g. section 5.3's quoted numbers (engine 'published')
                continue
            for engine in claim.engines:
                frame = results[engine]
                for i, deg in enumerate(pub["input_deg"]):
                    for col in scene.columns[1:]:
                        if claim.covers(scene.name, deg, col, engine) and not np.isnan(frame.at[i, col]):
                            assert abs(frame.at[i, col] - pub.at[i, col]) > half.at[i, col], (entry.id, deg, col)


def test_rounding_claims_are_sums_of_printed_values(register):
    """D023: each claimed K.E.D. cell equals rigid + deflection as printed, exactly."""
    claims = register["D023"].cells
    assert {c.scene for c in claims} == {name for name in SCENES if name.startswith("ali1977")}
    for claim in claims:
        pub = PublishedTable.load(get(claim.scene).table).values
        for col in claim.columns:
            axis, prefix = col[4], col[:3]
            for deg in claim.rows:
                row = pub[pub["input_deg"] == deg].iloc[0]
                assert round(row[f"rigid_{axis}"] + row[f"{prefix}_d{axis}"], 3) == round(row[col], 3)


def test_each_quirk_moves_exactly_the_columns_its_entry_names(scene, published, register):
    effects = quirk_effects(scene, published, scene.port(PRINTED))
    for name, moved in effects.items():
        entry = next(e for e in register.values() if e.quirk == name)
        columns = sorted(c for c in scene.values if moved[c].any())
        assert columns == sorted(entry.moves[scene.name]), (entry.id, columns)


def test_cli_lists_scenes(capsys):
    assert cli.main(["scenes"]) == 0
    assert "ali1977-table1" in capsys.readouterr().out


def test_cli_reproduce_writes_every_file(tmp_path):
    assert cli.main(["reproduce", "ali1977-table1", "--out", str(tmp_path)]) == 0
    target = tmp_path / "ali1977-table1"
    for name in ("published", "printed", "legacy", "port_printed", "port_corrected", "diff"):
        frame = pd.read_csv(target / f"{name}.csv")
        if name != "diff":
            assert list(frame.columns) == SCENES["ali1977-table1"].columns
    assert (target / "report.md").read_text().count("![table](table.png)") == 1      # one figure per table
    assert (target / "table.png").exists() and not (target / "src_dx.png").exists()
    assert (tmp_path / "report.md").exists() and (tmp_path / "report.html").exists()


def test_cli_rejects_unknown_scene():
    with pytest.raises(SystemExit) as info:
        cli.main(["reproduce", "no-such-scene"])
    assert info.value.code == 2


def test_appendix_scene_curves_and_speed_claim(tmp_path):
    """Appendix A: every produced curve from both engines, port equal to legacy, and the
    speed claim against closed form: inertia loads grow as the speed squared and the
    structure is linear, so the 400/300 rpm peak ratio is (4/3)^2 for every curve."""
    from linkrepro.harness.scenes.ali1977 import appendix
    from linkrepro.harness.figures import caption_of
    summary = appendix.run(tmp_path)
    assert summary["curves"] == 36 and summary["max_engine_gap"] < 1e-12
    pngs = sorted((tmp_path / appendix.NAME).glob("*.png"))
    assert [p.name for p in pngs] == ["case1.png", "case2.png", "case3.png"]       # one figure per case
    for case, png in zip(("I", "II", "III"), pngs):
        caption = caption_of(png)
        assert caption.startswith(f"Case {case}:") and "equal at every point" in caption    # measured: gap 0
    claims = pd.read_csv(tmp_path / appendix.NAME / "claims.csv")
    np.testing.assert_allclose(claims["ratio_400_300"], 16 / 9, rtol=1e-4)
