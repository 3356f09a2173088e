"""Ali (1977)'s generated blocks of the docs (``harness/docs.py``)."""
from __future__ import annotations

import numpy as np

from . import structure_dynamics as sd


def structure_dynamics() -> str:
    """The thesis's own structure run dynamically (``structure_dynamics.linear_sweep``: the corrected
    port's path-point stiffness, small-deflection theory; no Exudyn needed): per mechanism, its
    frozen first natural frequency over the cycle, the speed where the quasi-static answer's
    error passes ``ERROR_LEVEL`` of its peak at each damping ratio (``linear_limit``), and that
    error at the design speed (the linear model's, invalid there: geometric nonlinearity)."""
    sweep = sd.linear_sweep()
    deg = np.arange(0.0, 360.0, 1.0)
    zetas = (sd.ZETA, sd.ZETA_LOW, sd.ZETA_LOWEST)
    lines = [f"| mechanism | first natural frequency over the cycle (Hz) | error passes {sd.ERROR_LEVEL:.0%} of the peak "
             f"at (rpm), damping {' / '.join(f'{z:.1%}' for z in zetas)} | linear model's error / quasi-static peak at "
             f"{sd.RPM:g} rpm, damping {sd.ZETA:.0%} (invalid there) |", "|---|---|---|---|"]
    for side in sd.SIDES:
        f1 = sd.frequencies_of(sd.port_stiffness(deg, side))[:, 0]
        limits = [f"{sd.linear_limit(sweep, side, zeta):.1f}" for zeta in zetas]
        at_design = sweep[(sweep.side == side) & (sweep.zeta == sd.ZETA) & (sweep.rpm == sd.RPM)].error_over_peak
        lines.append(f"| {side} | {f1.min():.1f} to {f1.max():.1f} | {' / '.join(limits)} | {float(at_design.iloc[0]):.2f} |")
    return "\n".join(lines) + "\n"


def stresses() -> str:
    """The links' peak bending stress under the thesis's own quasi-static loads at the design speed
    (``stress.ked_moments``: the corrected port's member forces, every degree; no Exudyn needed),
    against the assumed alloy's yield."""
    from . import stress
    deg = np.arange(0.0, 360.0, 1.0)
    rows = stress.peaks(stress.ked_moments(deg), deg, dict.fromkeys(stress.FROM, 0.0))
    lines = [f"| link | peak moment at {sd.RPM:g} rpm (lbf in) | where | stress (ksi) | over {stress.ALLOY}'s "
             f"{stress.YIELD_PSI[0] / 1e3:g} ksi yield |", "|---|---|---|---|---|"]
    for r in rows:
        psi = r["moment_lbf_in"] / stress.section_modulus()
        where = f"{r['member']} at {r['from_joint']}, crank angle {r['crank_deg']:g} deg" if psi else "no bending"
        lines.append(f"| {r['link']} | {r['moment_lbf_in']:.0f} | {where} | {psi / 1e3:.1f} | {psi / stress.YIELD_PSI[0]:.2f} |")
    return "\n".join(lines) + "\n"


def ked_bound() -> str:
    """The K.E.D. error bound's calibration sample as ``linkrepro ked-bound --record`` last wrote
    it (``calibration.RECORD``): per engine, runs, points checked against 60 digits, refused,
    warned, the worst error over its bound, the points over it and the silent failures."""
    import pandas as pd
    from .calibration import RECORD
    table = pd.read_csv(RECORD)
    seed, draws = int(table["seed"].iloc[0]), int(table["draws"].iloc[0])
    lines = [ked_formula(), f"`linkrepro ked-bound --draws {draws} --seed {seed}`: {int(table['runs'].sum())} runs.", "",
             "| engine | runs | points checked | refused | warned | worst error / bound | over the bound | "
             "silent failures |", "|---|---|---|---|---|---|---|---|"]
    lines += [f"| {r.engine} | {r.runs} | {r.points} | {r.refused} | {r.warned} | {r.worst_error_over_bound:.2g} | "
              f"{r.over_bound} | {r.silent_failures} |" for r in table.itertuples()]
    return "\n".join(lines) + "\n"


def ked_formula() -> str:
    """The bound and the pole rule as ``port.ali1977.conditioning`` holds them, in words."""
    from ....port.ali1977 import conditioning as c
    return (f"The bound is ({c.STORAGE_FACTOR:g} u_s + {c.CONDITION_FACTOR:g} u kappa K + {c.POLE_FACTOR:g} u K / rho) "
            "times the deflection's cancellation (the size of its terms before they cancel, over its length): u_s "
            "the storage's unit roundoff (REAL*4 or double), u the double's, kappa the condition near a toggle, K the "
            "rounding the crossed cognate carries from its construction (1 for the source), rho the listing's Cramer "
            "determinant R1 over the sum of its six terms' magnitudes (with the listing's bugs only). A "
            f"ListingBugWarning where rho < {c.POLE_NEAR:g}, a SingularPositionError where the bound without the "
            "cancellation reaches 1, a PrecisionWarning where the bound passes half the stored digits.\n")


def ked_bound_summary() -> str:
    """The rule (``ked_formula``) and one sentence of the record (``ked_bound``): runs, points
    checked, over the bound, silent."""
    import pandas as pd
    from .calibration import RECORD
    t = pd.read_csv(RECORD)
    return ked_formula() + (f"Measured: {int(t['runs'].sum())} runs (`linkrepro ked-bound`: random geometries, sections, toggles and listing "
            f"poles, Cases I-III, source and cognate, legacy and the port, REAL*4 and double), "
            f"{int(t['points'].sum())} points checked against 60 digits: {int(t['over_bound'].sum())} over their "
            f"bound, {int(t['silent_failures'].sum())} silent (largest error / bound "
            f"{t['worst_error_over_bound'].max():.2g}).\n")


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


def exudyn_headline() -> str:
    """The elastodynamic study's Exudyn figures (the scene ali1977-elastodynamics' summary.csv as
    reference/ holds it: the verified run, which ``linkrepro verify`` holds equal to a fresh one)."""
    import pandas as pd
    from ...verify import REFERENCE_DIR
    s = pd.read_csv(REFERENCE_DIR / "ali1977-elastodynamics" / "summary.csv.xz").iloc[0]
    lines = [f"| mechanism | links | quasi-static peak at {sd.RPM:g} rpm (in) | dynamic peak (in) | error / quasi-static "
             f"peak | error passes {sd.ERROR_LEVEL:.0%} of the peak at (rpm), damping {sd.ZETA:.0%} |", "|---|---|---|---|---|---|"]
    for name, prefix, links in (("source", "", "massless (Case I)"), ("source", "link_mass_", "their own mass"),
                                ("cognate", "cognate_", "massless (Case I)")):
        lines.append(f"| {name} | {links} | {s[f'{prefix}quasi_static_peak']:.2f} | {s[f'{prefix}dynamic_peak']:.2f} | "
                     f"{s[f'{prefix}dynamic_error_over_peak']:.2f} | {s[f'{prefix}speed_limit_rpm']:.1f} |")
    return "\n".join(lines) + "\n"


BLOCKS = {"exudyn headline": exudyn_headline, "structure dynamics": structure_dynamics, "stresses": stresses, "ked bound": ked_bound, "ked bound summary": ked_bound_summary,
          "ked example": ked_example}
