"""Python face of Ali (1977), Appendix B: the K.E.D. listings of Cases I-III and the IBM SSP
routines they call (Rahman 1996 is :mod:`.rahman1996`).

The functions call the cleaned listings in ``legacy/src`` through f2py and return
numpy arrays, one value per input angle.  Defaults are the values the printed
programs hold.  Where the listing assigns a single-precision constant (for example
``CA=0.1963495408``) to a DOUBLE PRECISION variable, the default is that constant
as REAL*4 holds it, so that the defaults reproduce the printed run bit for bit.

Units: inch, pound-force, second; angles in radians for ``alp`` and degrees for the
input-angle grid; speed in rpm; ``mass_lbf`` is a weight in lbf (mass = W/g with
g = 32.178*12 in/s^2, as the listing divides).

Errors: ``TypeError`` for an argument that is not a real number (str, bool, complex,
None, arrays), ``ValueError`` for bad parameters (checked here, before FORTRAN sees them:
lengths from 1e-6 to 1e6 in, section values and step positive and finite, |alp| <= 1e6 rad,
|rpm| <= 2**31-1, a weight or density >= 0; and every value the listings hold in REAL*4
(the weight, the step) or assign from REAL*4 literals (section values, density)
representable there: finite, and positive where it must be), ``AssemblyError`` when the four-bar (or its cognate) cannot
close at some input angle, ``SingularPositionError`` when a position gives a non-finite
result, or lies at a toggle or at a zero of the listing's own Cramer determinant (its bugs
D014, D015, D026, named) to working precision (with the input angle; the port raises the
same, see ``linkrepro.port``).  Every program returns ``condition`` and ``error_bound`` (the
bound on the relative error of the deflection vector dx, dy, extender * rot against the
listing's equations, Case III's at its path point) per input angle, warns
``linkrepro.ListingBugWarning`` (naming the bugs and the angle) near a zero of the listing's
determinant and ``linkrepro.PrecisionWarning`` where fewer than half its REAL*4 digits are left
(``linkrepro.port.ali1977.conditioning``, the listing's algebra taken from the port, which
computes it bit for bit).
The cognate programs warn (``linkrepro.ListingBugWarning``, register D141) where the
listing's BETA turns the cognate into the wrong place: ``alp`` below 0 or above 180 deg, or
a coupler triangle obtuse at the follower pin (l2 cos(alp) > l3, or within the rounding of
the listing's CBTA of it, D165).

Threads: every call into the compiled FORTRAN (static storage) holds ``FORTRAN_LOCK``;
calls from several threads are serialized and each returns what it would alone.
"""
from __future__ import annotations

import math
import threading

import numpy as np

from ..checks import INTEGER_MAX, as_real4, integer, link_length, parameter, real4_array, speed_rpm, weight_lbf
from ..errors import AssemblyError
from ..port.ali1977 import case1, case2, case3
from ..port.ali1977.fourbar import Lengths, warn_listing_beta
from ..port.ali1977.quirks import PRINTED
from ..port.ali1977.structure import Section
from . import _ali1977 as _f

#: held around every call into the compiled Ali (1977) FORTRAN (static storage)
FORTRAN_LOCK = threading.Lock()

#: Constants as the printed REAL*4 literals hold them (IEEE single here; see D030).
PI_PRINTED = float(np.float32(3.142857143))
ALP_SOURCE_PRINTED = float(np.float32(1.762782545))   # source listing: 101 deg (D012)
ALP_COGNATE_PRINTED = PI_PRINTED / 3.0                # cognate listing: ALP=PI/3.0
CA_PRINTED = float(np.float32(0.1963495408))          # in^2
ME_PRINTED = float(np.float32(10000000.0))            # psi
MI_PRINTED = float(np.float32(0.0030679615))          # in^4

__all__ = ["case1_source", "case1_cognate", "case2_source", "case2_cognate", "case3_source", "case3_cognate", "gmtra", "mprd", "loc",
           "angle_grid"]

#: DNTY=0.098 (lb/in^3, aluminium) as the REAL*4 literal holds it (Cases II, III).
DENSITY_PRINTED = float(np.float32(0.098))


def angle_grid(step_deg: float) -> int:
    """Number of input angles 0, step, ..., 360 (360 included when step divides it)."""
    step_deg = parameter("step_deg", step_deg, positive=True, largest=None)
    as_real4("step_deg", step_deg, positive=True)
    n = int(math.floor(360.0 / step_deg + 1e-9)) + 1
    if n > 200_000:
        raise ValueError(f"step_deg={step_deg} gives {n} angles; at most 200000 are allowed")
    return n


def _check_inputs(lengths, alp, rpm, mass_lbf, area, modulus, inertia, step_deg):
    """The port's rules (linkrepro.checks): lengths from 1e-6 to 1e6 in, |alp| <= 1e6, the
    listing's speed, weight and REAL*4 section values; returns the number of input angles."""
    for name, value in zip(("l1", "l2", "l3", "l4", "l5"), lengths):
        link_length(f"link length {name}", value)
    parameter("alp", alp)
    speed_rpm(rpm)
    weight_lbf("mass (or density)", mass_lbf)
    for name, value in (("area", area), ("modulus", modulus), ("inertia", inertia)):
        as_real4(f"section {name}", parameter(f"section {name}", value, positive=True, largest=None), positive=True)
    return angle_grid(step_deg)


def _raise_on_status(istat: int, deg: np.ndarray, program: str) -> None:
    if istat:
        raise AssemblyError(f"{program}: the four-bar cannot close (negative discriminant "
                            "in the closed-form position equations)", float(deg[istat - 1]))


def _finish(out: dict, run, program: str, finite: dict | None = None) -> dict:
    """The port's checks on a listing's results (``Linkage.finish``), the listing's own algebra
    taken from the port with the listing's bugs (``run``: its ``run_*``, which computes what the
    FORTRAN does, bit for bit): a SingularPositionError at the first input angle where a result
    (``finite``, default every array of ``out`` but ``deg``) is not finite, or at a toggle or a
    zero of the listing's Cramer determinant to working precision (naming the bug), a
    ListingBugWarning near such a zero, a PrecisionWarning where fewer than half the REAL*4
    digits are left; ``condition`` and ``error_bound`` added, per input angle."""
    _, finish = run(out["deg"])
    return finish(out, program, stacklevel=5, finite=finite)


def case1_source(l1=10.0, l2=10.0, l3=30.0, l4=25.0, l5=30.0, alp=ALP_SOURCE_PRINTED,
                 rpm=400.0, mass_lbf=2.0, area=CA_PRINTED, modulus=ME_PRINTED,
                 inertia=MI_PRINTED, step_deg=20.0) -> dict[str, np.ndarray]:
    """Run the Case I source four-bar program (Appendix B, first listing).

    Returns ``deg`` (input angle, deg), ``xp, yp`` (coupler point with the listing's
    ALP, in), ``dx, dy`` (elastic deflection of the coupler point, in) and ``rot``
    (its elastic rotation, rad).  Defaults are the listing's: 400 rpm, ALP=101 deg.
    Note that the listing truncates ``rpm`` to an INTEGER (``N=SPEED``).
    """
    n = _check_inputs((l1, l2, l3, l4, l5), alp, rpm, mass_lbf, area, modulus, inertia, step_deg)
    with FORTRAN_LOCK:
        deg, xp, yp, dx, dy, rot, istat = _f.ked1s(l1, l2, l3, l4, l5, alp, rpm, mass_lbf,
                                                   area, modulus, inertia, step_deg, n)
    out = {"deg": deg, "xp": xp, "yp": yp, "dx": dx, "dy": dy, "rot": rot}
    _raise_on_status(istat, deg, "KED1S")
    return _finish(out, lambda d: case1.run_source_case1(d, Lengths(l1, l2, l3, l4, l5), alp, rpm, mass_lbf,
                                                         Section(area, modulus, inertia), PRINTED), "KED1S")


def case1_cognate(l1=10.0, l2=10.0, l3=30.0, l4=25.0, l5=30.0, alp=ALP_COGNATE_PRINTED,
                  rpm=300.0, mass_lbf=2.0, area=CA_PRINTED, modulus=ME_PRINTED,
                  inertia=MI_PRINTED, step_deg=20.0) -> dict[str, np.ndarray]:
    """Run the Case I crossed-cognate program (Appendix B, second listing).

    The lengths and ``alp`` are the *source* four-bar's; the program derives the
    cognate from them.  Returns ``deg``, ``xp, yp`` (source coupler point with this
    listing's ALP=PI/3, in: the rigid-mode columns of Table I), ``cxp, cyp`` (the
    cognate's own coupler point after the listing's rotation into place, in),
    ``dx, dy`` (cognate deflections, in) and ``rot`` (rad).  Default speed 300 rpm.
    """
    n = _check_inputs((l1, l2, l3, l4, l5), alp, rpm, mass_lbf, area, modulus, inertia, step_deg)
    warn_listing_beta("case1_cognate", l2, l3, alp)
    with FORTRAN_LOCK:
        deg, xp, yp, cxp, cyp, dx, dy, rot, istat = _f.ked1c(
            l1, l2, l3, l4, l5, alp, rpm, mass_lbf, area, modulus, inertia, step_deg, n)
    out = {"deg": deg, "xp": xp, "yp": yp, "cxp": cxp, "cyp": cyp, "dx": dx, "dy": dy, "rot": rot}
    _raise_on_status(istat, deg, "KED1C")
    return _finish(out, lambda d: case1.run_cognate_case1(d, Lengths(l1, l2, l3, l4, l5), alp, rpm, mass_lbf,
                                                          Section(area, modulus, inertia), PRINTED, warn_beta=False),
                   "KED1C")


def case2_source(l1=10.0, l2=10.0, l3=30.0, l4=25.0, l5=30.0, alp=ALP_COGNATE_PRINTED,
                 rpm=300.0, density=DENSITY_PRINTED, area=CA_PRINTED, modulus=ME_PRINTED,
                 inertia=MI_PRINTED, step_deg=20.0) -> dict[str, np.ndarray]:
    """Run the Case II source program (Appendix C): each link's mass lumped at its joints.

    ``density`` in lb/in^3 (weight); link masses are density * area * length.  Returns
    ``deg``, ``xp, yp`` (coupler point, in), ``dx, dy`` (in) and ``rot`` (rad).
    """
    n = _check_inputs((l1, l2, l3, l4, l5), alp, rpm, density, area, modulus, inertia, step_deg)
    with FORTRAN_LOCK:
        deg, xp, yp, dx, dy, rot, istat = _f.ked2s(l1, l2, l3, l4, l5, alp, rpm, density, area,
                                                   modulus, inertia, step_deg, n)
    out = {"deg": deg, "xp": xp, "yp": yp, "dx": dx, "dy": dy, "rot": rot}
    _raise_on_status(istat, deg, "KED2S")
    return _finish(out, lambda d: case2.run_case2_source(d, Lengths(l1, l2, l3, l4, l5), alp, rpm, density,
                                                         Section(area, modulus, inertia), case2.LISTING), "KED2S")


def case2_cognate(l1=10.0, l2=10.0, l3=30.0, l4=25.0, l5=30.0, alp=ALP_COGNATE_PRINTED,
                  rpm=300.0, density=DENSITY_PRINTED, area=CA_PRINTED, modulus=ME_PRINTED,
                  inertia=MI_PRINTED, step_deg=20.0) -> dict[str, np.ndarray]:
    """Run the Case II cognate program (Appendix C), its missing page (statements 241-281:
    the loads and the last product) RECONSTRUCTED from the Case II source listing (D037).

    Returns ``deg``, ``xp, yp`` (source coupler point, in), ``cxp, cyp`` (cognate's, in),
    ``dx, dy`` (in) and ``rot`` (rad).
    """
    n = _check_inputs((l1, l2, l3, l4, l5), alp, rpm, density, area, modulus, inertia, step_deg)
    warn_listing_beta("case2_cognate", l2, l3, alp)
    with FORTRAN_LOCK:
        deg, xp, yp, cxp, cyp, dx, dy, rot, istat = _f.ked2c(l1, l2, l3, l4, l5, alp, rpm, density, area,
                                                             modulus, inertia, step_deg, n)
    out = {"deg": deg, "xp": xp, "yp": yp, "cxp": cxp, "cyp": cyp, "dx": dx, "dy": dy, "rot": rot}
    _raise_on_status(istat, deg, "KED2C")
    return _finish(out, lambda d: case2.run_case2_cognate(d, Lengths(l1, l2, l3, l4, l5), alp, rpm, density,
                                                          Section(area, modulus, inertia), case2.COGNATE_LISTING,
                                                          warn_beta=False), "KED2C")


def case3_source(l1=10.0, l2=10.0, l3=30.0, l4=25.0, l5=30.0, alp=ALP_COGNATE_PRINTED,
                 rpm=300.0, density=DENSITY_PRINTED, area=CA_PRINTED, modulus=ME_PRINTED,
                 inertia=MI_PRINTED, step_deg=20.0) -> dict[str, np.ndarray]:
    """Run the Case III source program (Appendix D): the extender's mass at 5 nodes.

    Returns ``deg``, ``xp, yp`` (in), ``dx, dy, rot`` at the path point (node 1), and
    ``nodes`` (N, 5, 3): dx, dy (in), rot (rad) of nodes 1..5 (10, 8, 6, 4, 2 in from the
    crank pin) as the listing prints them.
    """
    n = _check_inputs((l1, l2, l3, l4, l5), alp, rpm, density, area, modulus, inertia, step_deg)
    if l2 <= 8.0:
        raise ValueError(f"l2={l2}: the listing's nodes L2-2 ... L2-8 need l2 > 8 in")
    with FORTRAN_LOCK:
        deg, xp, yp, deflections, istat = _f.ked3s(l1, l2, l3, l4, l5, alp, rpm, density, area,
                                                   modulus, inertia, step_deg, n)
    nodes = np.ascontiguousarray(deflections.T.reshape(n, 5, 3))
    out = {"deg": deg, "xp": xp, "yp": yp, "dx": nodes[:, 0, 0], "dy": nodes[:, 0, 1],
           "rot": nodes[:, 0, 2], "nodes": nodes}
    _raise_on_status(istat, deg, "KED3S")
    return _finish(out, lambda d: case3.run_case3_source(d, 5, Lengths(l1, l2, l3, l4, l5), alp, rpm, density,
                                                         Section(area, modulus, inertia), case3.LISTING), "KED3S",
                   finite={"xp": xp, "yp": yp, "nodes": nodes})


def case3_cognate(l1=10.0, l2=10.0, l3=30.0, l4=25.0, l5=30.0, alp=ALP_COGNATE_PRINTED,
                  rpm=300.0, density=DENSITY_PRINTED, area=CA_PRINTED, modulus=ME_PRINTED,
                  inertia=MI_PRINTED, step_deg=20.0) -> dict[str, np.ndarray]:
    """A RECONSTRUCTION (D037): Appendix D prints no Case III cognate program.  The Case I
    cognate listing with the Case III source listing's changes (the tip node's weight
    density*area*CL2, double-precision loads, E*I bending).  Returns as case1_cognate."""
    n = _check_inputs((l1, l2, l3, l4, l5), alp, rpm, density, area, modulus, inertia, step_deg)
    warn_listing_beta("case3_cognate", l2, l3, alp)
    with FORTRAN_LOCK:
        deg, xp, yp, cxp, cyp, dx, dy, rot, istat = _f.ked3c(l1, l2, l3, l4, l5, alp, rpm, density, area,
                                                             modulus, inertia, step_deg, n)
    out = {"deg": deg, "xp": xp, "yp": yp, "cxp": cxp, "cyp": cyp, "dx": dx, "dy": dy, "rot": rot}
    _raise_on_status(istat, deg, "KED3C")
    return _finish(out, lambda d: case3.run_case3_cognate(d, 5, Lengths(l1, l2, l3, l4, l5), alp, rpm, density,
                                                          Section(area, modulus, inertia), case3.COGNATE_LISTING,
                                                          warn_beta=False), "KED3C")


def gmtra(a: np.ndarray) -> np.ndarray:
    """SSP GMTRA: transpose an N x M general matrix (REAL*4, column-major storage)."""
    a = real4_array("a", a)
    if a.ndim != 2 or a.size == 0:
        raise ValueError("gmtra needs a non-empty 2-D matrix")
    n, m = a.shape
    with FORTRAN_LOCK:
        r = _f.gmtra(a.ravel(order="F"), n, m)
    return r.reshape((m, n), order="F")


#: the most elements mprd's result may hold
MAX_ELEMENTS = 10**8


def _storage_length(n: int, mode: int) -> int:
    return {0: n * n, 1: n * (n + 1) // 2, 2: n}[mode]


def mprd(a: np.ndarray, b: np.ndarray, n: int, m: int, l: int, msa: int = 0, msb: int = 0) -> np.ndarray:
    """SSP MPRD: R (N x L) = A (N x M) times B (M x L), each in SSP storage.

    ``a`` and ``b`` are the *storage vectors* as SSP keeps them: general (mode 0,
    column-major N*M), symmetric (mode 1, upper triangle by columns, N*(N+1)/2) or
    diagonal (mode 2, N elements).  Symmetric and diagonal matrices are square.
    Returns R as a general N x L matrix, or its N diagonal elements when both
    inputs are diagonal (the SSP table in the listing's header).
    """
    n, m, l = (integer(name, v) for name, v in (("n", n), ("m", m), ("l", l)))
    msa, msb = (integer(name, v, 0, 2) for name, v in (("msa", msa), ("msb", msb)))
    if msa and n != m:
        raise ValueError("a symmetric or diagonal A must be square (n == m)")
    if msb and m != l:
        raise ValueError("a symmetric or diagonal B must be square (m == l)")
    if n * l > MAX_ELEMENTS:
        raise ValueError(f"R would hold {n * l} elements; at most {MAX_ELEMENTS} are allowed")
    a, b = real4_array("a", a).ravel(), real4_array("b", b).ravel()
    need_a = n * m if msa == 0 else _storage_length(n, msa)
    need_b = m * l if msb == 0 else _storage_length(m, msb)
    if a.size != need_a or b.size != need_b:
        raise ValueError(f"storage vectors must hold {need_a} (A) and {need_b} (B) elements, "
                         f"got {a.size} and {b.size}")
    with FORTRAN_LOCK:
        r = _f.mprd(a, b, n, m, msa, msb, l)
    if not np.all(np.isfinite(r)):
        raise ValueError("the product overflows REAL*4 (|R| > 3.4e38)")
    return r if (msa == 2 and msb == 2) else r.reshape((n, l), order="F")


def loc(i: int, j: int, n: int, m: int, ms: int) -> int:
    """SSP LOC: 1-based storage subscript of element (i, j); 0 when not stored.  Every
    argument an INTEGER; n*m (the storage length) within the INTEGER range."""
    i, j, n, m = (integer(name, v) for name, v in (("i", i), ("j", j), ("n", n), ("m", m)))
    ms = integer("ms", ms, 0, 2)
    if n * m > INTEGER_MAX or i * n > INTEGER_MAX or j * n > INTEGER_MAX:
        raise ValueError(f"LOC's subscripts overflow the FORTRAN INTEGER for n={n}, m={m}")
    with FORTRAN_LOCK:
        return int(_f.loc(i, j, n, m, ms))
