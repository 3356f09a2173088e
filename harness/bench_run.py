"""``linkrepro bench``: the run.  Every thesis's computations, knobs and sweeps, found through
the scene registry (each ``harness/scenes/<thesis>/bench.py``), timed by the machine of
``harness/bench.py``, written to ``--out`` (bench.md, bench.png, bench.csv)."""
from __future__ import annotations

import time
import warnings
from collections import Counter
from pathlib import Path

import pandas as pd

from . import progress
from .bench import COLUMNS, OUTPUTS, cost_rows, knob_rows, markdown, plot, step
from .scenes import bench_computations as computations, bench_knobs as knobs, bench_sweeps as sweeps

__all__ = ["OUTPUTS", "computations", "knobs", "sweeps", "warm_up", "run_bench"]


def warm_up() -> None:
    """Call every engine once on the quick configuration, untimed: numba compiles (or loads) its
    kernels at their first call, which a timing must not see."""
    for comp in computations(quick=True):
        for func in comp.engines.values():
            func()


def run_bench(repeat: int = 10, out: Path | str = Path("out/bench"), quick: bool = False) -> str:
    """Run the bench; write OUT/bench.md, bench.png, bench.csv; return the markdown.

    ``repeat``: calls per timing (best of; a sweep takes repeat // 10, at least 1); ``quick``:
    the reduced configuration (each thesis's smallest: few positions, three settings a knob, no
    sweep): a smoke test (bench.md says how long its run took)."""
    if repeat < 1:
        raise ValueError("repeat must be >= 1")
    start, out = time.perf_counter(), Path(out)
    with warnings.catch_warnings(record=True) as caught:       # said in bench.md, not on stderr
        warnings.simplefilter("always")
        comps, knob_list, sweep_list = computations(quick), knobs(quick), sweeps(quick)
        descriptions = {k.name: f"{k.what} ({k.engine})" for k in knob_list} | {s.name: s.what for s in sweep_list}
        with progress.Bar(1 + len(comps) + len(knob_list) + len(sweep_list)):
            step("warming up (the first run compiles the numba kernels)", warm_up)
            rows = []
            for comp in comps:
                rows += step(comp.name, lambda: cost_rows(comp, repeat))
            for knob in knob_list:
                rows += step(f"knob: {knob.name}", lambda: knob_rows(knob, repeat))
            for sweep in sweep_list:
                rows += step(f"knob: {sweep.name}", lambda: sweep.rows(max(1, repeat // 10)))
    warned = Counter((w.category.__name__, str(w.message)) for w in caught)
    frame = pd.DataFrame(rows).reindex(columns=COLUMNS)
    out.mkdir(parents=True, exist_ok=True)
    md, png, csv = (out / name for name in OUTPUTS)
    frame.to_csv(csv, index=False)
    plot(frame, png, {sweep.name: sweep.series for sweep in sweep_list if sweep.series})
    text = markdown(frame, descriptions, repeat, time.perf_counter() - start, png.name, warned)
    md.write_text(text)
    return text
