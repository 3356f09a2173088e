"""Ali (1977)'s part of ``linkrepro bench`` (the machine: ``harness/bench.py``): the cost of
K.E.D. Cases I-III, source and cognate, at the tables' 19 angles and 3,601 angles against the
listings' flop counts (``KED_*``); the knobs K.E.D. angle step and REAL*4 storage; the sweep of
Case III's sub-elements and mass rule (``case3_convergence.case3_data``); Exudyn's mesh (quasi-static) and step (elastodynamics),
where Exudyn is installed."""
from __future__ import annotations

from typing import Callable

import numpy as np

from ....legacy import ali1977
from ....port.ali1977 import CORRECTED, PRINTED, case2, case3, cognate_case1, source_case1
from ...bench import TRANSCENDENTAL, Computation, Knob, Sweep, crank_grid, step_label, relative_error, with_pareto_front, mprd
from ...bench import series_of_setting
from ... import multibody as exudyn_gate
from .case3_convergence import case3_data

#: four-bar position (half-angle), velocity, acceleration, beta by Cramer's rule (statements
#: 14-106): sin, cos of t2, t3, t4, t3+alp, t4-t3, t2-t3, two sqrt, two atan; ~190 + - * /
KED_KINEMATICS = 16 * TRANSCENDENTAL + 190
#: Case I, one mechanism: delta = beta' F beta P (3x8, 8x8, 8x3, 3x1) as the listing's MPRDs
KED_CASE1 = KED_KINEMATICS + mprd(3, 8, 8) + mprd(3, 8, 3) + mprd(3, 3, 1)
#: Case II, one mechanism: 40 flops of joint loads; beta' F beta2 P (3x8, 8x8, 8x8, 8x1)
KED_CASE2 = KED_KINEMATICS + 40 + mprd(3, 8, 8) + mprd(3, 8, 8) + mprd(3, 8, 1)
#: Case III source: five node blocks (~15 flops each) into the dense beta* (40x15) and F*
#: (40x40); the listing multiplies beta*' F* (15x40x40), then beta* (15x40x15) twice (its
#: second MPRD with the loads keeps N=15, M=40, L=15), then the loads (15x15x1)
KED_CASE3_SOURCE = KED_KINEMATICS + 5 * 15 + mprd(15, 40, 40) + 2 * mprd(15, 40, 15) + mprd(15, 15, 1)


# ------------------------------------------------------------------ cost per position

def _ked_pair(out: tuple) -> np.ndarray:
    """dx, dy of source and cognate, stacked."""
    return np.stack([part[k] for part in out for k in ("dx", "dy")])


#: per K.E.D. case: legacy (source, cognate), port (source, cognate), the listings' quirks,
#: the flops per angle (source + cognate)
KED = {
    "I": ((ali1977.case1_source, ali1977.case1_cognate), (source_case1, cognate_case1), (PRINTED, PRINTED),
          2 * KED_CASE1),
    "II": ((ali1977.case2_source, ali1977.case2_cognate), (case2.case2_source, case2.case2_cognate),
           (case2.LISTING, case2.COGNATE_LISTING), 2 * KED_CASE2),
    "III": ((ali1977.case3_source, ali1977.case3_cognate), (case3.case3_source, case3.case3_cognate),
            (case3.LISTING, case3.COGNATE_LISTING), KED_CASE3_SOURCE + KED_CASE1),
}


def ked_computation(case: str, step: float) -> Computation:
    """K.E.D. Case I, II or III, source and cognate, at the listings' angle step (deg); the port
    is given the listings' own angles (their REAL*4 P2=P2+DSTEP drifts), read once untimed."""
    (leg_src, leg_cog), (src, cog), listing, flops = KED[case]
    deg = ali1977.case1_source(step_deg=step)["deg"]

    def port(quirks):
        return lambda: (src(deg, quirks=quirks & listing[0]), cog(deg, quirks=quirks & listing[1]))
    engines = {"legacy": lambda: (leg_src(step_deg=step), leg_cog(step_deg=step)),
               "port_printed": port(PRINTED), "port_corrected": port(CORRECTED)}
    note = ("port corrected: the coupled model with n = 5 (another algorithm); limit: the listing's dense "
            "40 x 40 products" if case == "III" else "")
    return Computation(f"K.E.D. Case {case}, source + cognate, {len(deg)} angles", len(deg), engines,
                       lambda _: flops, lambda leg, prt: relative_error(_ked_pair(prt), _ked_pair(leg)), note=note)


def computations(quick: bool) -> list[Computation]:
    """K.E.D. Cases I-III at the tables' 19 angles and (not ``quick``) at 3,601 angles."""
    steps = (20.0,) if quick else (20.0, 0.1)
    return [ked_computation(case, step) for step in steps for case in KED]


# ------------------------------------------------------------------ knobs

def _peak_deflection(out: tuple) -> np.ndarray:
    """Largest |deflection| (in) over the cycle, source and cognate."""
    return np.array([np.max(np.hypot(part["dx"], part["dy"])) for part in out])


def _case1(deg: np.ndarray, quirks) -> Callable:
    return lambda: (deg, source_case1(deg, quirks=quirks), cognate_case1(deg, quirks=quirks))


def ked_step_knob(steps: tuple) -> Knob:
    """K.E.D. Case I (corrected), source and cognate: the angle step against the peak deflection."""
    return Knob("K.E.D. angle step", "port_corrected", "in",
                "Case I corrected, source and cognate: largest |deflection| over the cycle, against the finest step",
                {step_label(s): _case1(crank_grid(s), CORRECTED) for s in steps}, step_label(steps[-1]),
                lambda r, ref: (float(np.max(np.abs(_peak_deflection(r[1:]) - _peak_deflection(ref[1:])))), ""),
                lambda r: len(r[0]))


def ked_precision_knob() -> Knob:
    """K.E.D. Case I (corrected), 3,601 angles: REAL*4 storage against double."""
    deg = crank_grid(0.1)
    return Knob("K.E.D. precision", "port_corrected", "in",
                f"Case I corrected, {len(deg)} angles: largest |deflection - double's| (source and cognate)",
                {"double": _case1(deg, CORRECTED),
                 "REAL*4 storage": _case1(deg, CORRECTED.only("real4_storage", True))},
                "double", lambda r, ref: (float(np.max(np.abs(_ked_pair(r[1:]) - _ked_pair(ref[1:])))), ""),
                lambda r: len(r[0]))


#: the crank speed of the Exudyn step knob (rpm): the sweep's lower half, runs of a second
EXUDYN_STEP_RPM = 100.0


def _largest_deflection_error(result, port) -> tuple[float, str]:
    """Largest |dx, dy - port's| (in) over the angles."""
    return float(max(np.abs(result[k] - port[k]).max() for k in ("dx", "dy"))), ""


def exudyn_knobs(quick: bool) -> list[Knob]:
    """Case I source in Exudyn: the mesh of the quasi-static beams against the corrected port,
    and the step of the 100 rpm steady state against the finest; none without Exudyn."""
    if not exudyn_gate.available():
        return []
    from . import elastodynamics, multibody
    deg = np.arange(0.0, 361.0, 10.0)
    meshes = (2,) if quick else (2, 4, 8, 16, 32)
    mesh = {f"{n} per link, stiff shear": (lambda n=n: multibody.quasi_static("source", 1, deg, n)) for n in meshes}
    mesh["2 per link, shear 12 EI/h^2"] = lambda: multibody.quasi_static("source", 1, deg, 2, shear_per_element=1.0)
    mesh["port_corrected"] = lambda: multibody.port_deflections("source", 1, deg)
    steps = (90, 180, 360) if quick else (90, 180, 360, 720, 1440)
    step = {f"{n} per rev": (lambda n=n: elastodynamics.steady_state(EXUDYN_STEP_RPM, steps=n, cached=False))
            for n in steps}
    from .structure_dynamics import RPM
    scene = dict(elements=elastodynamics.ELEMENTS, periodicity=elastodynamics.PERIODICITY_IN,
                 modified_newton=elastodynamics.MODIFIED_NEWTON)
    def label(elements, steps, periodicity, modified_newton) -> str:
        """A setting in short: elements per link, steps per revolution, periodicity (in), Newton."""
        return f"{elements}/link, {steps}/rev, {periodicity:g} in, {'modified' if modified_newton else 'full'}"
    ours = label(elastodynamics.ELEMENTS, elastodynamics.STEPS_PER_REV, **{k: scene[k] for k in ("periodicity",
                                                                                               "modified_newton")})
    variants = {f"the scene's: {ours}": scene, "8/link": scene | dict(elements=8),
                "1e-06 in, full": scene | dict(periodicity=1e-6, modified_newton=False)}
    if not quick:
        variants |= {"2/link": scene | dict(elements=2), "720/rev": scene | dict(steps=720),
                     "0.001 in": scene | dict(periodicity=1e-3)}
    finest = (dict(elements=16, steps=1440, periodicity=1e-8, modified_newton=False) if not quick else
              dict(elements=8, steps=720, periodicity=1e-6, modified_newton=False))
    reference = label(**finest)
    variants[reference] = finest
    settings = {name: (lambda kw=kw: elastodynamics.steady_state(RPM, cached=False, **kw)) for name, kw in variants.items()}

    def peak_error(run, ref) -> tuple[float, str]:
        peak = lambda r: float(np.hypot(*r.deflection.T).max())
        return abs(peak(run) / peak(ref) - 1.0), f"orbit {elastodynamics.orbit_change(run, ref):.1e} in from the reference"
    return [
        Knob("Exudyn settings (K.E.D. dynamics)", "exudyn", "",
             f"Case I source, the {RPM:g} rpm steady state (zeta 0.05): |peak / the reference's - 1|, for the scene's "
             "elements per link, steps per revolution, periodicity tolerance and Newton variant", settings, reference,
             peak_error, lambda r: r.steps * r.revolutions),
        Knob("Exudyn mesh (K.E.D.)", "exudyn", "in",
             "Case I source, linear quasi-static deflection at 37 angles from Exudyn's beams, elements per link "
             "(stiff shear: the elements' c h^2 error; shear 12 EI/h^2 cancels it), against the corrected port "
             "(the reference)", mesh, "port_corrected", _largest_deflection_error, lambda r: len(deg)),
        Knob("Exudyn step (K.E.D. dynamics)", "exudyn", "in",
             f"Case I source, the {EXUDYN_STEP_RPM:g} rpm elastodynamic steady state, steps per revolution: the "
             f"largest distance from the {steps[-1]}-step orbit", step, f"{steps[-1]} per rev",
             lambda r, ref: (elastodynamics.orbit_change(r, ref), ""), lambda r: r.steps * r.revolutions),
    ]


def elastodynamic_knobs(quick: bool) -> list[Knob]:
    """The elastodynamic study's other settings, each against a converged reference (relative
    errors): the frozen frequencies' mesh (against the port), the nonlinear statics' mesh and load
    steps (the largest gap from the linear answer over the peak), and (not ``quick``) the limit
    speed's mesh, step, periodicity and Newton variant; none without Exudyn."""
    if not exudyn_gate.available():
        return []
    from . import elastodynamics as ed
    from . import structure_dynamics as sd
    deg = np.arange(0.0, 360.0, 30.0 if quick else 10.0)
    port = sd.frequencies_of(sd.port_stiffness(deg))[:, 0]
    meshes = (2, 4) if quick else (2, 4, 8, 16)
    freq = {f"{n} per link": (lambda n=n: np.array([sd.frequencies_of(ed.exudyn_stiffness(d, n)[0])[0] for d in deg]))
            for n in meshes}
    freq["port_corrected"] = lambda: port
    qs_peak = float(np.hypot(*sd.quasi_static(deg, sd.RPM).T).max())
    static_settings = [(ed.STATIC_ELEMENTS, ed.LOAD_STEPS), (8, 4)] + ([] if quick else [(4, 1), (16, 8)])
    gap = {f"{n} per link, {k} load step(s)": (
        lambda n=n, k=k: max(float(np.hypot(*(ed.exudyn_static(d, n, k)[1] - ed.exudyn_static(d, n, k)[0])))
                             for d in deg) / qs_peak) for n, k in static_settings}
    out = [
        Knob("Exudyn mesh (frozen frequencies)", "exudyn", "",
             f"Case I source, the first natural frequency at {len(deg)} angles from Exudyn's condensed stiffness, "
             "elements per link: largest |f1 / the port's - 1|", freq, "port_corrected",
             lambda r, ref: (float(np.abs(r / ref - 1.0).max()), ""), lambda r: len(deg)),
        Knob("Exudyn mesh and load steps (nonlinear statics)", "exudyn", "",
             f"Case I source, the {sd.RPM:g} rpm load at {len(deg)} angles: the nonlinear answer's largest gap from "
             "the linear one over the quasi-static peak, against the finest setting's", gap,
             f"{static_settings[-1][0]} per link, {static_settings[-1][1]} load step(s)",
             lambda r, ref: (abs(r / ref - 1.0), ""), lambda r: len(deg))]
    if not quick:
        guess = sd.linear_limit(sd.linear_sweep(), "source", sd.ZETA)
        variants = {"the scene's": {}, "reference: 16 per link, 1440 per rev, periodicity 1e-8, full Newton": dict(
            elements=16, steps=1440, periodicity=1e-8, modified_newton=False)}

        def limit(kw):
            return lambda: sd.speed_limit(lambda rpm: ed._row("bench", ed.steady_state(rpm, cached=False, **kw))[
                "error_over_peak"], guess)
        out.append(Knob("Exudyn settings (limit speed)", "exudyn", "",
                        "Case I source, zeta 0.05: the speed where the quasi-static error passes 10 % of its peak, "
                        "|limit / the reference's - 1|", {name: limit(kw) for name, kw in variants.items()},
                        next(iter(reversed(variants))), lambda r, ref: (abs(r / ref - 1.0), f"{r:.2f} rpm"),
                        lambda r: 1))
    return out


def knobs(quick: bool) -> list[Knob]:
    """The angle step (``quick``: three settings), REAL*4 storage, Exudyn's mesh and step."""
    steps = (20.0, 5.0, 1.0) if quick else (20.0, 10.0, 5.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01)
    return [ked_step_knob(steps), ked_precision_knob(), *exudyn_knobs(quick), *elastodynamic_knobs(quick)]


CASE3 = "Case III sub-elements n and mass rule"
CASE3_WHAT = ("tip deflection, max |dx, dy - converged| over the turn at 20, 10 and 1 deg, the converged answer "
              "the coupled model Richardson-extrapolated from n = 1600, 3200 (harness/case3_convergence); "
              "coupled: port corrected; listing: the listing's mass rule, uncoupled")


def case3_rows(repeat: int) -> list[dict]:
    """Case III's sweep (harness/case3_convergence.case3_data): n and the mass rule at three
    angle steps, against the converged coupled model."""
    rows = [dict(kind="knob", subject=CASE3, setting=f"n = {r.n}, {r.model}, {r.step_deg:g} deg",
                 engine="port_corrected" if r.model == "coupled" else "port_listing_model",
                 positions=len(crank_grid(r.step_deg)), seconds=r.seconds,
                 us_per_position=1e6 * r.seconds / len(crank_grid(r.step_deg)), error=r.error_in, error_unit="in",
                 reference=False, note="")
            for r in case3_data(repeat).itertuples()]
    return with_pareto_front(rows)


def sweeps(quick: bool) -> list[Sweep]:
    """Case III's sweep (48 settings; none when ``quick``)."""
    return [] if quick else [Sweep(CASE3, CASE3_WHAT, case3_rows, series_of_setting)]
