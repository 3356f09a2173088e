"""Ali (1977): what each column of the scenes' CSVs means, and its unit (``harness/quantities.py``).

Deflections and positions of the path point P in inches, angles in degrees, rotations in
radians, as the K.E.D. tables and the Appendix A curves give them.
"""
from __future__ import annotations

from ...quantities import DIFF, Quantity as Q

#: the K.E.D. tables' columns (Tables I-III): published.csv, each engine's CSV
KED = {
    "input_deg": Q("input-link rotation", "deg"),
    "rigid_x": Q("rigid-link path point, x", "in"),
    "rigid_y": Q("rigid-link path point, y", "in"),
    "src_dx": Q("source four-bar, path-point deflection along x", "in"),
    "src_dy": Q("source four-bar, path-point deflection along y", "in"),
    "src_xnew": Q("source four-bar, deflected path point x (rigid + deflection)", "in"),
    "src_ynew": Q("source four-bar, deflected path point y (rigid + deflection)", "in"),
    "cog_dx": Q("cognate four-bar, path-point deflection along x", "in"),
    "cog_dy": Q("cognate four-bar, path-point deflection along y", "in"),
    "cog_xnew": Q("cognate four-bar, deflected path point x (rigid + deflection)", "in"),
    "cog_ynew": Q("cognate four-bar, deflected path point y (rigid + deflection)", "in"),
}
#: identities.csv: the tables' printed sums X_new = X + dX against their printed terms (sums.py)
SUMS = {
    "table": Q("published table (harness/published/<table>.csv)", ""),
    "sum_column": Q("the printed sum's column", ""),
    "printed_sum": Q("printed deflected coordinate", "in"),
    "sum_of_printed_terms": Q("printed rigid coordinate + printed deflection", "in"),
    "gap": Q("|printed sum - sum of printed terms|", "in"),
    "rounding_bound": Q("largest gap rounding allows (the three cells' half-units added)", "in"),
    "verdict": Q("consistent, or misprint (gap beyond the bound)", ""),
}
CASE = Q("loading case (I: mass at the path point, II: at each joint, III: distributed)", "")
#: cognate_search.csv (Tables II, III): the sign and frame search over the reconstructed cognate loads
COGNATE_SEARCH = {
    "case": CASE,
    "variant": Q("the reconstruction's terms or frames changed", ""),
    "changes": Q("terms or frames changed", ""),
    "cells_matched": Q("cognate cells within half a unit of the printed digit", ""),
    "cells": Q("cognate cells compared", ""),
    "max_err_in": Q("largest |variant - published| over the cells", "in"),
}
#: the Appendix A curves' quantities (curves.csv's ``quantity``)
CURVES = {
    "dx": Q("path-point deflection along x", "in"),
    "dy": Q("path-point deflection along y", "in"),
    "rot": Q("path-point rotation about z", "rad"),
}
APPENDIX = CURVES | {
    "case": CASE,
    "mechanism": Q("four-bar (source or cognate)", ""),
    "rpm": Q("input-link speed", "rpm"),
    "engine": DIFF["engine"],
    "quantity": Q("the curve's quantity (dx, dy or rot)", ""),
    "input_deg": KED["input_deg"],
    "value": Q("the curve's value", "", per_row="quantity"),
    # claims.csv: chapter V's two claims, per curve pair (legacy)
    "ratio_400_300": Q("peak |value| at 400 rpm / peak |value| at 300 rpm", ""),
    "peak_deg_300": Q("input-link rotation at the peak, 300 rpm", "deg"),
    "peak_deg_400": Q("input-link rotation at the peak, 400 rpm", "deg"),
    "peak_in_second_half": Q("both peaks beyond 180 deg", ""),
}
#: case3_convergence.csv: the Case III sweep (case3_convergence.py)
CASE3 = {
    "step_deg": Q("input-angle step", "deg"),
    "n": Q("sub-elements of the extender", ""),
    "model": Q("mass model (coupled, or the listing's)", ""),
    "seconds": Q("port wall time", "s"),
    "error_in": Q("largest |tip deflection - converged|", "in"),
    "legacy_seconds_n5": Q("legacy wall time (n = 5)", "s"),
}

QUANTITIES = {
    "ali1977-table1": KED | SUMS,
    "ali1977-table2": KED | SUMS | COGNATE_SEARCH,
    "ali1977-table3": KED | SUMS | COGNATE_SEARCH,
    "ali1977-appendixA": APPENDIX,
    "ali1977-case3-convergence": CASE3,
}
