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


BLOCKS = {"structure dynamics": structure_dynamics}
