"""harness/compare_runs.py: which CSVs of two reproduce folders differ, and by how much."""
import pandas as pd

from linkrepro.harness.compare_runs import compare


def _write(folder, name, frame):
    (folder / name).parent.mkdir(parents=True, exist_ok=True)
    frame.to_csv(folder / name, index=False)


def test_equal_folders_agree_and_each_kind_of_change_is_named(tmp_path):
    before, after = tmp_path / "before", tmp_path / "after"
    base = pd.DataFrame({"x": [1.0, 2.0, float("nan")], "ids": ["D001", None, "D002 D003"],
                         "seconds": [0.1, 0.2, 0.3]})
    for folder in (before, after):
        _write(folder, "a/same.csv", base)
    _write(before, "a/moved.csv", base)
    _write(after, "a/moved.csv", base.assign(x=[1.0, 2.0 + 1e-9, float("nan")], ids=["D001", None, "D002"],
                                              seconds=[9.0, 9.0, 9.0]))
    _write(after, "a/new.csv", base)
    worst, found = compare(before, after, 1e-12)
    assert "a/same.csv" not in found
    assert abs(worst - 1e-9 / 2.0) < 1e-15                   # the gap over the largest |x|
    assert any("x: relative difference" in p for p in found["a/moved.csv"])
    assert any("ids: text differs in 1 rows" in p for p in found["a/moved.csv"])
    assert not any("seconds" in p for p in found["a/moved.csv"])            # timings are not compared
    assert found["a/new.csv"] == ["new in AFTER"]
