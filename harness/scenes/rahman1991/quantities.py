"""Rahman (1991): what each column of the rahman1991-example CSVs means, and its unit
(``harness/quantities.py``).

Units as the thesis: inch, lbf, second; angles in degrees.  Each joint load is the load the
link nearer the crank exerts at that joint, its components i, j, k along its own frame's
axes (port/rahman1991/forces.py): 1F1, 1T1 in {1} (the torque about {1}'s origin), 2F2 in
{2}, 3F3 in {3}, 4F4, 4T4 in {4} (the torque about the slider's ball).
"""
from __future__ import annotations

from ....port.rahman1991.position import CLOSURE_RTOL
from ...quantities import Quantity as Q

#: a configuration of the example's grid (section 3.1)
CONFIGURATION = {
    "a4": Q("offset a4 of the slider axis", "in"),
    "alpha4_deg": Q("twist alpha4 of the slider axis", "deg"),
    "s1": Q("axial offset S1 of the crank", "in"),
}
#: port.csv, port_corrected.csv (analysis.COLUMNS): positions and the joint loads
JOINT_LOADS = {"F1": ("force 1F1, crank on frame", "lbf"),
               "T1": ("torque 1T1, crank on frame", "lbf in"),
               "F2": ("force 2F2, crank on rod", "lbf"),
               "F3": ("force 3F3, rod on slider", "lbf"),
               "F4": ("force 4F4, slider on frame", "lbf"),
               "T4": ("torque 4T4, slider on frame", "lbf in")}
POSITIONS = {
    "crank_deg": Q("crank angle theta1", "deg"),
    "converged": Q(f"the loop closes (closure within {CLOSURE_RTOL:g} of its size) on the asked branch", ""),
    "s4": Q("slider displacement S4", "in"),
    "theta2": Q("rod angle theta2 at the crank pin", "deg"),
    "eta2": Q("rod angle eta2 at the crank pin", "deg"),
    "theta3": Q("rod angle theta3 at the slider's ball", "deg"),
    "eta3": Q("rod angle eta3 at the slider's ball", "deg"),
    **{f"{load}{axis}": Q(f"{words}, {axis}", unit)
       for load, (words, unit) in JOINT_LOADS.items() for axis in "ijk"},
}
#: diagnostics.csv, convergence.csv, legacy.csv
RUNS = {
    "status": Q("how the position solver reached its answer, or why there is none", ""),
    "closure": Q("loop-closure error ||M1 L2 L3 M4 - I|| at the answer", ""),
    "engine": Q("engine or solver", ""),
    "assembles": Q("the mechanism assembles at every crank angle", ""),
    "converges": Q("the solver converges over a full turn (its Newton stops at every angle)", ""),
    "legacy": Q("the 1996 legacy build on the point: converged, or the error it raised", ""),
    "legacy_fail_deg": Q("crank angle where the 1996 build failed", "deg"),
    "replica": Q("the port's replica of the build's first pass: converged, or the error", ""),
    "replica_fail_deg": Q("crank angle where the replica failed", "deg"),
    "max_ds4_in": Q("largest |S4 difference| between the replica and the 1991 port", "in"),
    "max_dtheta2_deg": Q("largest |theta2 difference| between the replica and the 1991 port", "deg"),
}
#: claims.csv: each claim of section 3.2 (harness/published/rahman1991_claims.csv), measured
CLAIMS = {
    "claim": Q("the claim (harness/published/rahman1991_claims.csv)", ""),
    "measured": Q("what the claim constrains, measured", "", per_row="claim"),
    "tolerance": Q("the largest measured value that reproduces the claim", "", per_row="claim"),
    "verdict": Q("reproduced or contradicted", ""),
    "what": Q("what is measured, in words", ""),
    # the claims, as the rows of claims.csv name them
    "t4_zero": Q("largest |4T4|", "lbf in"),
    "f2k_zero": Q("largest |2F2k|", "lbf"),
    "f2j_constant": Q("largest |2F2j - printed constant|", "lbf"),
    "f2j_ratio": Q("largest |2F2j + T1k / a1|", "lbf"),
    "t1_moments": Q("largest |1T1i + 1F1j S1|, |1T1j - 1F1i S1|", "lbf in"),
    "t1_zero_without_s1": Q("largest |1T1i|, |1T1j| at S1 = 0", "lbf in"),
    "planar_complex": Q("largest gap to the complex-number analysis, relative", ""),
    "spikes": Q("distance of the largest |2F2i| to the nearest dead centre", "deg"),
    "iterations": Q("distance of the planar median of Newton steps from the printed range", ""),
    "converge_a4_0": Q("largest S1 up to which every S1 converges, a4 = 0", "in"),
    "converge_a4_10": Q("largest S1 up to which every S1 converges, a4 = 10 in", "in"),
    "converge_a4_30": Q("largest S1 up to which every S1 converges, a4 = 30 in", "in"),
    "converge_alpha4": Q("share of the printed alpha4 range that converges", ""),
}
#: near_singular.csv: the joint rates near theta2 = 0, evaluated five ways (near_singular.py)
RATES = {
    "theta2_d": Q("rate of theta2", "rad/s"),
    "eta2_d": Q("rate of eta2", "rad/s"),
    "s4_d": Q("slider velocity S4'", "in/s"),
    "theta2_dd": Q("angular acceleration theta2''", "rad/s^2"),
    "eta2_dd": Q("angular acceleration eta2''", "rad/s^2"),
    "s4_dd": Q("slider acceleration S4''", "in/s^2"),
}
NEAR_SINGULAR = RATES | {
    "offset_deg": Q("step off crank_deg, the crank angle where theta2 crosses 0", "deg"),
    "theta2_deg": Q("theta2 at the evaluated position", "deg"),
    "quantity": Q("the joint rate evaluated", ""),
    "printed": Q("the printed formulas at the printed Newton's position", "", per_row="quantity"),
    "printed_mp": Q("the same in 40-digit arithmetic", "", per_row="quantity"),
    "printed_exact": Q("the printed formulas at the exact loop's position", "", per_row="quantity"),
    "corrected": Q("the corrected path (exact closed loop, float64)", "", per_row="quantity"),
    "truth": Q("the exact closed loop in 40-digit arithmetic", "", per_row="quantity"),
    "digits_printed_roundoff": Q("correct digits of printed against printed_mp (its round-off)", ""),
    "digits_printed_vs_truth": Q("correct digits of printed against truth", ""),
    "digits_printed_exact_vs_truth": Q("correct digits of printed_exact against truth", ""),
    "digits_corrected_vs_truth": Q("correct digits of corrected against truth", ""),
    "flag": Q("printed loses more than half its digits", ""),
}

QUANTITIES = {"rahman1991-example": CONFIGURATION | POSITIONS | RUNS | CLAIMS | NEAR_SINGULAR}
