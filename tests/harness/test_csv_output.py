"""harness/csv_output.write_csv writes what pandas' to_csv writes, byte for byte."""
import numpy as np
import pandas as pd
import pytest

from linkrepro.harness.csv_output import write_csv


def _frame() -> pd.DataFrame:
    rng = np.random.default_rng(3)
    floats = rng.normal(size=40) * 10.0 ** rng.integers(-12, 12, 40)
    floats[[1, 5]], floats[7], floats[8], floats[[9, 10]], floats[11] = np.nan, np.inf, -np.inf, -0.0, 0.0
    floats[12:20] = floats[20:28]                      # repeated values (each formatted once)
    return pd.DataFrame({"x": floats, "n": np.arange(40), "ok": rng.random(40) > 0.5,
                         "status": ["newton", "a, b", 'say "hi"', None] * 10,
                         "mixed": [1.5, "text", np.nan, None] * 10})


@pytest.mark.parametrize("quoted", [True, False])
@pytest.mark.parametrize("float_format", [None, "%.9g", "%.6g"])
def test_bytes_equal_pandas(tmp_path, float_format, quoted):
    frame = _frame() if quoted else _frame().drop(columns="mixed").assign(status=["newton", "dfp", None, ""] * 10)
    frame.to_csv(tmp_path / "pandas.csv", index=False, float_format=float_format)
    write_csv(frame, tmp_path / "ours.csv", float_format)
    assert (tmp_path / "ours.csv").read_bytes() == (tmp_path / "pandas.csv").read_bytes()
