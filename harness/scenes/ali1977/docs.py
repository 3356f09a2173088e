"""Ali (1977)'s generated blocks of the docs (``harness/docs.py``)."""
from __future__ import annotations

import numpy as np

from . import structure_dynamics as sd


def structure_dynamics() -> str:
    """The thesis's own structure run dynamically (``structure_dynamics.linear_sweep``: the corrected
    port's path-point stiffness, small-deflection theory; no Exudyn needed): per mechanism, its
    frozen first natural frequency over the cycle, the speed where the quasi-static answer's
    error passes ``ERROR_LEVEL`` of its peak, and that error at the design speed."""
    sweep = sd.linear_sweep()
    deg = np.arange(0.0, 360.0, 1.0)
    lines = [f"| mechanism | first natural frequency over the cycle (Hz) | error passes {sd.ERROR_LEVEL:.0%} of the peak "
             f"at (rpm), damping {sd.ZETA:.0%} / {sd.ZETA_LOW:.0%} | error / quasi-static peak at {sd.RPM:g} rpm, "
             f"damping {sd.ZETA:.0%} |", "|---|---|---|---|"]
    for side in sd.SIDES:
        f1 = sd.frequencies_of(sd.port_stiffness(deg, side))[:, 0]
        limits = []
        for zeta in (sd.ZETA, sd.ZETA_LOW):
            rows = sweep[(sweep.side == side) & (sweep.zeta == zeta)]
            limits.append(f"{sd.crossing(rows.rpm, rows.error_over_peak):.0f}")
        at_design = sweep[(sweep.side == side) & (sweep.zeta == sd.ZETA) & (sweep.rpm == sd.RPM)].error_over_peak
        lines.append(f"| {side} | {f1.min():.1f} to {f1.max():.1f} | {' / '.join(limits)} | {float(at_design.iloc[0]):.2f} |")
    return "\n".join(lines) + "\n"


def ked_bound() -> str:
    """The K.E.D. error bound's calibration sample as ``linkrepro ked-bound --record`` last wrote
    it (``calibration.RECORD``): per engine, runs, points checked against 60 digits, refused,
    warned, the worst error over its bound, the points over it and the silent failures."""
    import pandas as pd
    from .calibration import RECORD
    table = pd.read_csv(RECORD)
    seed, draws = int(table["seed"].iloc[0]), int(table["draws"].iloc[0])
    lines = [f"`linkrepro ked-bound --draws {draws} --seed {seed}`: {int(table['runs'].sum())} runs.", "",
             "| engine | runs | points checked | refused | warned | worst error / bound | over the bound | "
             "silent failures |", "|---|---|---|---|---|---|---|---|"]
    lines += [f"| {r.engine} | {r.runs} | {r.points} | {r.refused} | {r.warned} | {r.worst_error_over_bound:.2g} | "
              f"{r.over_bound} | {r.silent_failures} |" for r in table.itertuples()]
    return "\n".join(lines) + "\n"


def ked_example() -> str:
    """The published example's rows (legacy, each program at its printed inputs): the largest
    bound on the deflection's relative error the engine states, at which angle, against the
    warning level, and what the engine said."""
    import math
    import warnings

    from ....errors import LinkreproWarning
    from ....legacy import ali1977
    from ....port.ali1977.conditioning import REAL4_UNIT
    lines = ["| program | largest error bound (at deg) | warning level | warnings |", "|---|---|---|---|"]
    for name in ("case1_source", "case1_cognate", "case2_source", "case2_cognate", "case3_source", "case3_cognate"):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", LinkreproWarning)
            out = getattr(ali1977, name)()
        i = int(np.argmax(out["error_bound"]))
        said = sorted({w.category.__name__ for w in caught if issubclass(w.category, LinkreproWarning)})
        lines.append(f"| {name} | {out['error_bound'][i]:.2g} ({out['deg'][i]:g}) | {math.sqrt(REAL4_UNIT):.2g} | "
                     f"{', '.join(said) or 'none'} |")
    return "\n".join(lines) + "\n"


BLOCKS = {"structure dynamics": structure_dynamics, "ked bound": ked_bound, "ked example": ked_example}
