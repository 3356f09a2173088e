"""Ali (1977): what each column of the scenes' CSVs means, and its unit (``harness/quantities.py``).

Deflections and positions of the path point P in inches, angles in degrees, rotations in
radians, as the K.E.D. tables and the Appendix A curves give them; the Exudyn scenes' speeds in
rev/min, frequencies in Hz, times in seconds.
"""
from __future__ import annotations

from ...quantities import DIFF, Quantity as Q
from .elastodynamics import FREQUENCY_ELEMENTS, LINK_MASS, QUASI_STATIC_RPM
from .multibody import SHEAR_FACTOR
from .quasi_static import EB_ELEMENTS, PAIR
from .structure_dynamics import DAMPING_HZ, ERROR_LEVEL, RPM, ZETA, ZETA_LOW, ZETA_LOWEST

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

#: ali1977-conditioning: conditioning.csv (a point and engine a row) and summary.csv (conditioning.py)
CONDITIONING = {
    "l1": Q("link length l1, the input link (crank)", "in"),
    "l2": Q("link length l2, the extender (coupler point to path point)", "in"),
    "l3": Q("link length l3, the coupler", "in"),
    "l4": Q("link length l4, the follower", "in"),
    "l5": Q("link length l5, the ground link", "in"),
    "alp_deg": Q("angle alpha from the coupler to the extender (the listings' ALP)", "deg"),
    "input_deg": KED["input_deg"],
    "sin_mu": Q("sine of the transmission angle (coupler to follower), from the 60-digit evaluation", ""),
    "spread": Q("the links' spread: longest link length / shortest", ""),
    "condition": Q("the condition the engines compute: the links' spread / sin^2(transmission angle)", ""),
    "engine": Q("engine (float64: the corrected port; real4: the same with the listings' REAL*4 storage)", ""),
    "bound": Q("the bound on the relative error the engine returns with the point (error_bound; where it refused, "
               "the bound of a deflection whose terms do not cancel)", ""),
    "error": Q("relative error of the Case I source deflection (dx, dy, l2 rot) against the same equations in "
               "60 digits (empty where the engine refused)", ""),
    "verdict": Q("what the engine did (returned, PrecisionWarning, SingularPositionError or AssemblyError)", ""),
    "points": Q("points (four-bar and input angle) evaluated", ""),
    "refused": Q("points the engine refused (no deflection returned)", ""),
    "warned": Q("points the engine answered with a PrecisionWarning", ""),
    "worst_error_over_bound": Q("largest relative error / its bound over the answered points", ""),
    "silent_failures": Q("points returned without a warning whose relative error passes half the storage's digits "
                         "(sqrt of its unit roundoff)", ""),
}

SIDE = Q("four-bar (source, or its crossed cognate)", "")
ELEMENTS_PER_LINK = Q("beam elements per link (Exudyn)", "")
_EXUDYN = f"Exudyn: shear stiffness 12 EI / h^2 per element, {EB_ELEMENTS} elements per link"
_STIFF = f"Exudyn with stiff shear ({SHEAR_FACTOR:g} EA), extrapolated from {PAIR[0]} and {PAIR[1]} elements per link"
#: the path point's deflection, the corrected port's (both Exudyn scenes)
PORT_DEFLECTION = {
    "port_dx": Q("path-point deflection along x (source frame), the corrected port", "in"),
    "port_dy": Q("path-point deflection along y (source frame), the corrected port", "in"),
}
#: ali1977-multibody (quasi_static.py): deflections.csv, convergence.csv, shear.csv, linearity.csv
MULTIBODY = PORT_DEFLECTION | {
    "case": Q("loading case (1, 2, 3: Case I mass at the path point, II at each joint, III distributed)", ""),
    "side": SIDE,
    "input_deg": KED["input_deg"],
    "port_rot": Q("path-point rotation about z, the corrected port", "rad"),
    "exudyn_dx": Q(f"path-point deflection along x (source frame), {_EXUDYN}", "in"),
    "exudyn_dy": Q(f"path-point deflection along y (source frame), {_EXUDYN}", "in"),
    "exudyn_rot": Q(f"path-point rotation about z, {_EXUDYN}", "rad"),
    "stiff_dx": Q(f"path-point deflection along x (source frame), {_STIFF}", "in"),
    "stiff_dy": Q(f"path-point deflection along y (source frame), {_STIFF}", "in"),
    "stiff_rot": Q(f"path-point rotation about z, {_STIFF}", "rad"),
    "reference": Q("what Exudyn is held against (port: the corrected port)", ""),
    "shear": Q("the beams' shear stiffness model (factor x EA, or kappa x 12 EI / h^2 per element)", ""),
    "value": Q("the shear stiffness's factor (of EA) or kappa (of 12 EI / h^2)", ""),
    "elements": ELEMENTS_PER_LINK,
    "scheme": Q("raw (one mesh), or extrapolated (h^2 error removed from n/2 and n elements)", ""),
    "peak_in": Q("peak path-point deflection |(dx, dy)| of the corrected port over the angles", "in"),
    "max_error_in": Q("largest |(dx, dy)| difference from the corrected port over the angles", "in"),
    "relative_to_peak": Q("largest |(dx, dy)| difference / the port's peak deflection", ""),
    "max_rot_error_rad": Q("largest path-point rotation difference from the corrected port over the angles", "rad"),
    # linearity.csv: Case I source at its largest deflection, the loads scaled and the answer scaled back
    "solve": Q("Exudyn's static solve (linear, or geometrically nonlinear)", ""),
    "load_scale": Q("load factor (the answer divided by it)", ""),
    "dx": Q("path-point deflection along x / the load factor", "in"),
    "dy": Q("path-point deflection along y / the load factor", "in"),
    "rot": Q("path-point rotation about z / the load factor", "rad"),
    "relative_difference": Q("|(dx, dy) - the linear answer at load factor 1| / |that answer|", ""),
}

#: ali1977-elastodynamics (elastodynamics.py, structure_dynamics.py): Case I, the Exudyn runs at
#: ``elastodynamics.ELEMENTS`` elements per link; "the thesis's structure run dynamically" is
#: ``structure_dynamics.linear_periodic`` (the port's stiffness, the deflection's inertia kept)
_RPM, _LOW = f"{RPM:g} rpm", f"zeta {ZETA_LOW:g}"
_MASS = f"the links given {LINK_MASS:.0%} of their own mass"
ELASTODYNAMICS = PORT_DEFLECTION | {
    "side": SIDE,
    "crank_deg": Q("crank angle (input-link rotation)", "deg"),
    # frequencies.csv, frequencies_port.csv: the frozen linkage, the path-point mass on massless links
    "f1_exudyn": Q(f"first natural frequency of the frozen linkage, Exudyn ({FREQUENCY_ELEMENTS} elements per link, its "
                   "stiffness condensed onto the path point)", "Hz"),
    "f2_exudyn": Q(f"second natural frequency of the frozen linkage, Exudyn ({FREQUENCY_ELEMENTS} elements per link, its "
                   "stiffness condensed onto the path point)", "Hz"),
    "f1_port": Q("first natural frequency of the frozen linkage, the corrected port's flexibility (beta^T F beta)",
                 "Hz"),
    "f2_port": Q("second natural frequency of the frozen linkage, the corrected port's flexibility (beta^T F beta)",
                 "Hz"),
    "condensation_check_in": Q("largest |Exudyn's condensed compliance x the Case I load - its linear deflection| "
                               "(a check of the condensation)", "in"),
    # statics.csv: the 300 rpm Case I load on the frozen linkage
    "exudyn_linear_dx": Q(f"path-point deflection along x (source frame) under the {_RPM} load, Exudyn linear", "in"),
    "exudyn_linear_dy": Q(f"path-point deflection along y (source frame) under the {_RPM} load, Exudyn linear", "in"),
    "nonlinear_dx": Q(f"path-point deflection along x (source frame) under the {_RPM} load, Exudyn geometrically "
                      "nonlinear", "in"),
    "nonlinear_dy": Q(f"path-point deflection along y (source frame) under the {_RPM} load, Exudyn geometrically "
                      "nonlinear", "in"),
    # steady_300.csv: over the last revolution at 300 rpm
    "quasi_static_dx": Q(f"quasi-static path-point deflection along x (source frame) at {_RPM}, the corrected port",
                         "in"),
    "quasi_static_dy": Q(f"quasi-static path-point deflection along y (source frame) at {_RPM}, the corrected port",
                         "in"),
    "dynamic_dx": Q(f"path-point deflection along x (source frame) in the elastodynamic steady state at {_RPM}, "
                    f"Exudyn, zeta {ZETA:g}", "in"),
    "dynamic_dy": Q(f"path-point deflection along y (source frame) in the elastodynamic steady state at {_RPM}, "
                    f"Exudyn, zeta {ZETA:g}", "in"),
    "linear_dynamic_dx": Q(f"path-point deflection along x (source frame) at {_RPM}, the thesis's structure run "
                           f"dynamically, zeta {ZETA:g}", "in"),
    "linear_dynamic_dy": Q(f"path-point deflection along y (source frame) at {_RPM}, the thesis's structure run "
                           f"dynamically, zeta {ZETA:g}", "in"),
    # runs_300.csv (the 300 rpm steady states), limit_runs.csv, limits.csv, error_harmonics.csv, linear_sweep.csv
    "study": Q("the run's model: Case I (massless links) or the links' own mass; limit_runs.csv: limit search", ""),
    "model": Q("Exudyn, or the thesis's structure run dynamically (stress.csv: the model the moment comes from: the "
               "K.E.D. model's member forces, Exudyn's linear or nonlinear statics, Exudyn's steady state)", ""),
    "limit_rpm": Q(f"speed where the quasi-static answer's error passes {ERROR_LEVEL:.0%} of its peak", "rpm"),
    "harmonic": Q("harmonic of the crank (1: once per revolution)", ""),
    "frequency_hz": Q("the harmonic's frequency at the row's speed", "Hz"),
    "amplitude_in": Q("amplitude of the harmonic of |steady state - quasi-static deflection| (the two components' "
                      "Fourier amplitudes, root of the sum of their squares)", "in"),
    "share_of_largest": Q("the harmonic's amplitude / the largest harmonic's", ""),
    "rpm": Q("crank speed", "rpm"),
    "elements": ELEMENTS_PER_LINK,
    "steps_per_rev": Q("time steps per revolution", ""),
    "zeta": Q(f"modal damping ratio at {DAMPING_HZ:g} Hz (stiffness-proportional damping)", ""),
    "start_deg": Q("crank angle the run starts from (undeformed)", "deg"),
    "revolutions": Q("revolutions run", ""),
    "period": Q("the steady state's period in revolutions (1 or 2; 0: none reached)", ""),
    "periodicity_in": Q("largest difference of the path point between the last two revolutions", "in"),
    "period2_in": Q("largest difference of the path point between the last revolution and the one two before", "in"),
    "quasi_static_peak": Q("peak quasi-static path-point deflection |(dx, dy)| over a revolution at the row's speed, "
                           "the corrected port (with the links' mass: the model's own steady state at "
                           f"{QUASI_STATIC_RPM:g} rpm times the speed ratio squared; summary.csv: the source four-bar at "
                           f"{_RPM})", "in"),
    "dynamic_peak": Q("peak path-point deflection |(dx, dy)| over a revolution of the steady state, Exudyn "
                      "(linear_sweep.csv: the thesis's structure run dynamically; summary.csv: the source four-bar "
                      f"at {_RPM}, zeta {ZETA:g})", "in"),
    "max_error": Q("largest |steady state - quasi-static deflection| over a revolution, Exudyn", "in"),
    "error_over_peak": Q("largest |steady state - quasi-static deflection| / the quasi-static peak, Exudyn "
                         "(linear_sweep.csv: the thesis's structure run dynamically)", ""),
    "link_mass": Q("the beams' mass, a fraction of the links' own (0: massless links, as Case I)", ""),
    "newton_diverged_at_s": Q("time from the start where Exudyn's Newton iteration diverged (empty: it did not)", "s"),
    "seed_rpm": Q("crank speed of the converged run this run started from, its state scaled to this speed (empty: "
                  "started undeformed)", "rpm"),
    "transient_left_per_rev": Q("fraction of a start-up transient left after a revolution (the revolution map's "
                                "spectral radius)", ""),
    # stress.csv (stress.table): per side, model and speed, each link's peak bending moment and stress
    "link": Q("the link: crank, coupler (with its extender) or follower", ""),
    "member": Q("the member of the link where its moment peaks (crank, extender, coupler, follower)", ""),
    "from_joint": Q("the joint the member's distance is measured from (O2, A, B)", ""),
    "at_in": Q("distance of the peak from that joint along the member (empty: the statics, read at the joint)", "in"),
    "moment_lbf_in": Q("peak bending moment of the link over the revolution", "lbf in"),
    "stress_psi": Q("peak bending stress M c / I of the 0.5 in round section", "psi"),
    "stress_over_yield": Q("the stress / the assumed alloy's yield (stress.YIELD_PSI, 6061-T6's minimum)", ""),
    # statics.csv: per member, the bending moment of the largest size along it (Exudyn's linear and nonlinear solves)
    **{f"{kind}_moment_{member}": Q(f"the {member}'s bending moment of the largest size along it under the {_RPM} load, "
                                    f"Exudyn {words}", "lbf in")
       for kind, words in (("exudyn_linear", "linear"), ("nonlinear", "geometrically nonlinear"))
       for member in ("crank", "extender", "coupler", "follower")},
}
#: summary.csv: each four-bar's numbers, the source's under these names and the cognate's as
#: cognate_<name>; a name a file's column has too keeps that column's words (ELASTODYNAMICS)
_PER_SIDE = {
    "f1_min_hz": Q("lowest first natural frequency of the frozen linkage over the cycle (the corrected port, every "
                   "degree)", "Hz"),
    "f1_max_hz": Q("highest first natural frequency of the frozen linkage over the cycle (the corrected port, every "
                   "degree)", "Hz"),
    "f2_min_hz": Q("lowest second natural frequency of the frozen linkage over the cycle (the corrected port, every "
                   "degree)", "Hz"),
    "f2_max_hz": Q("highest second natural frequency of the frozen linkage over the cycle (the corrected port, every "
                   "degree)", "Hz"),
    "f1_exudyn_over_port_max": Q("largest |Exudyn's first natural frequency / the port's - 1|", ""),
    "quasi_static_peak": Q(f"peak quasi-static path-point deflection over a revolution at {_RPM}, the corrected port",
                           "in"),
    "nonlinear_peak": Q(f"peak geometrically nonlinear static deflection under the {_RPM} load, Exudyn", "in"),
    "nonlinear_gap_max": Q(f"largest |nonlinear static deflection - the port's| under the {_RPM} load", "in"),
    "nonlinear_gap_over_peak": Q(f"largest |nonlinear static deflection - the port's| under the {_RPM} load / the "
                                 "port's peak", ""),
    "exudyn_linear_gap_over_peak": Q(f"largest |Exudyn's linear static deflection - the port's| under the {_RPM} load "
                                     "/ the port's peak", ""),
    "dynamic_peak": Q(f"peak deflection of the elastodynamic steady state at {_RPM}, Exudyn", "in"),
    "dynamic_error": Q(f"largest |steady state - quasi-static deflection| over a revolution at {_RPM}, Exudyn", "in"),
    "dynamic_error_over_peak": Q(f"largest |steady state - quasi-static deflection| at {_RPM} / the quasi-static "
                                 "peak, Exudyn", ""),
    "dynamic_revolutions": Q(f"revolutions Exudyn ran to the steady state at {_RPM}", ""),
    "dynamic_periodicity_in": Q(f"largest difference of the path point between the last two revolutions at {_RPM}",
                                "in"),
    "linear_dynamic_peak_300": Q(f"peak deflection of the thesis's structure run dynamically at {_RPM}, "
                                 f"zeta {ZETA:g}", "in"),
    "linear_dynamic_peak_300_low": Q(f"peak deflection of the thesis's structure run dynamically at {_RPM}, {_LOW}",
                                     "in"),
    "speed_limit_rpm": Q(f"speed where the quasi-static answer's error first passes {ERROR_LEVEL:.0%} of its peak, "
                         f"Exudyn's sweep (zeta {ZETA:g})", "rpm"),
    "speed_limit_linear_rpm": Q(f"speed where the quasi-static answer's error first passes {ERROR_LEVEL:.0%} of its "
                                f"peak, the thesis's structure run dynamically (zeta {ZETA:g})", "rpm"),
    "speed_limit_linear_low_zeta_rpm": Q(f"speed where the quasi-static answer's error first passes "
                                         f"{ERROR_LEVEL:.0%} of its peak, the thesis's structure run dynamically "
                                         f"({_LOW})", "rpm"),
    "speed_limit_linear_lowest_zeta_rpm": Q(f"speed where the quasi-static answer's error first passes "
                                            f"{ERROR_LEVEL:.0%} of its peak, the thesis's structure run dynamically "
                                            f"(zeta {ZETA_LOWEST:g})", "rpm"),
}
#: summary.csv's numbers of the source four-bar alone
_SOURCE_ONLY = {
    "crank_hz": Q(f"the crank's frequency at {_RPM}", "Hz"),
    **{f"harmonic_{n}": Q(f"harmonic {n} of the source path point's rigid acceleration, its size / the first's", "")
       for n in range(2, 6)},
    "link_mass_quasi_static_peak": Q(f"peak quasi-static deflection at {_RPM} with {_MASS} (the model's own steady "
                                     f"state at {QUASI_STATIC_RPM:g} rpm times the speed ratio squared)", "in"),
    "link_mass_dynamic_peak": Q(f"peak deflection of the steady state at {_RPM}, zeta {ZETA:g}, {_MASS}, Exudyn", "in"),
    "link_mass_dynamic_error_over_peak": Q(f"largest |steady state - quasi-static| / the quasi-static peak at {_RPM}, "
                                           f"zeta {ZETA:g}, {_MASS}, Exudyn", ""),
    "link_mass_speed_limit_rpm": Q(f"speed where the quasi-static answer's error passes {ERROR_LEVEL:.0%} of its peak "
                                   f"with {_MASS}, Exudyn (zeta {ZETA:g})", "rpm"),
    "low_zeta_peak": Q(f"peak deflection of the source's steady state at {_RPM}, {_LOW}, {_MASS}, Exudyn", "in"),
    "low_zeta_error_over_peak": Q(f"largest |steady state - quasi-static| / the quasi-static peak at {_RPM}, {_LOW}, "
                                  f"{_MASS}, Exudyn", ""),
    "speed_limit_low_zeta_rpm": Q(f"speed where the quasi-static answer's error passes {ERROR_LEVEL:.0%} of its peak, "
                                  f"Exudyn, {_LOW}, massless links", "rpm"),
    "limit_error_top_harmonic": Q("the largest harmonic of the quasi-static answer's error at the limit speed (Exudyn, "
                                  f"zeta {ZETA:g})", ""),
    "massless_low_zeta_diverged_at_s": Q(f"time from the start where Exudyn's Newton iteration diverged, the source at "
                                         f"{_RPM}, {_LOW}, massless links (full Newton, 720 steps per revolution)", "s"),
    "limit_resonant_harmonic_first": Q("the lowest harmonic of the crank inside the first mode's band at the limit speed",
                                       ""),
    "limit_resonant_harmonic_last": Q("the highest harmonic of the crank inside the first mode's band at the limit speed",
                                      ""),
    "limit_resonant_share": Q("the smallest share of the largest harmonic among the quasi-static error's harmonics "
                              "inside the first mode's band, at the limit speed", ""),
    "limit_next_harmonic_share": Q("the error's harmonic above the first mode's band: its share of the largest, at "
                                   "the limit speed", ""),
    "limit_f1_min_over_crank": Q("the lowest first natural frequency / the crank frequency at the limit speed", ""),
    "limit_f1_max_over_crank": Q("the highest first natural frequency / the crank frequency at the limit speed", ""),
}
ELASTODYNAMICS_SUMMARY = (
    _SOURCE_ONLY
    | {name: Q(f"source four-bar: {q.words}", q.unit) for name, q in _PER_SIDE.items() if name not in ELASTODYNAMICS}
    | {f"cognate_{name}": Q(f"cognate four-bar: {q.words}", q.unit) for name, q in _PER_SIDE.items()})

QUANTITIES = {
    "ali1977-table1": KED | SUMS,
    "ali1977-table2": KED | SUMS | COGNATE_SEARCH,
    "ali1977-table3": KED | SUMS | COGNATE_SEARCH,
    "ali1977-appendixA": APPENDIX,
    "ali1977-case3-convergence": CASE3,
    "ali1977-conditioning": CONDITIONING,
    "ali1977-multibody": MULTIBODY,
    "ali1977-elastodynamics": ELASTODYNAMICS | ELASTODYNAMICS_SUMMARY,
}
