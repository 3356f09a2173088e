"""What ``solution`` means, in legacy and the port alike (issue 22, item 4; register D151).

The listing solves the QP twice: the first answer (after pass 1) is the masses its 'after'
columns of Tables 5.2-5.7 are computed with in pass 2, the second (after pass 2, with OF
summed over both passes) the masses of Table 5.1.  ``solution`` is the first, the masses
behind the 'after' columns; ``solution_table51`` the second.  ``solution=`` given replaces
both answers (D055), so feeding a run's ``solution`` back must give the same 'after' columns
bit for bit, and feeding ``solution_table51`` back the same Table 5.1.
"""
import numpy as np
import pytest

from linkrepro.legacy import rahman1996
from linkrepro.port.rahman1996.balance import CSSP_CORRECTED, CSSP_PRINTED, CsspInputs, balance
from linkrepro.port.rahman1996.data import QP_BOUNDS, QP_EQUALITIES, QP_ROWS

#: the issue's geometry (a1, a2, a4, alpha4_deg, s1, rpm), where feeding legacy's former
#: ``solution`` (the second QP's answer) back moved its 'after' columns by 1.3e-4 relative
ISSUE = dict(a1=2.0, a2=6.9946, a4=-2.71788, alpha4_deg=90.0, s1=-0.20045, rpm=2.04846)
GEOMETRIES = pytest.mark.parametrize("geometry", [{}, ISSUE], ids=["published", "issue"])
ENGINES = {"legacy": lambda g, **kw: rahman1996.cssp(**g, **kw),
           "port_printed": lambda g, **kw: balance(CsspInputs(**g), CSSP_PRINTED, **kw),
           "port_corrected": lambda g, **kw: balance(CsspInputs(**g), CSSP_CORRECTED, **kw)}


@GEOMETRIES
@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("masses, output", [("solution", "table"), ("solution_table51", "inertia")])
def test_feeding_the_masses_back_reproduces_what_they_mean(engine, geometry, masses, output):
    """``solution`` fed back: the same 'after' columns (and 'before'); ``solution_table51``:
    the same Table 5.1."""
    run = ENGINES[engine](geometry)
    again = ENGINES[engine](geometry, solution=run[masses])
    np.testing.assert_array_equal(again[output], run[output])


@GEOMETRIES
def test_legacy_and_the_port_mean_the_same_masses(geometry):
    """The port with the listing's bugs runs the same QPs as the build: the same REAL*4 masses."""
    ours, theirs = ENGINES["port_printed"](geometry), ENGINES["legacy"](geometry)
    for key in ("solution", "solution_table51"):
        np.testing.assert_array_equal(np.float32(ours[key]), np.float32(theirs[key]))


def test_solution_is_the_first_qps_answer():
    """Independently of the runs' own bookkeeping: the first QP's Hessian (``hessian``) solved
    by QPROG gives ``solution``; on the issue's geometry the two QPs differ, so Table 5.1's
    masses are not the 'after' columns' (their difference is what moved the columns)."""
    run = rahman1996.cssp(**ISSUE)
    bounds = np.float32(QP_BOUNDS).astype(float)                  # DATA b, as QPROG gets it
    first = rahman1996.qprog(run["hessian"], np.zeros(9), QP_ROWS, bounds, QP_EQUALITIES)["sol"]
    np.testing.assert_array_equal(np.float32(first), np.float32(run["solution"]))
    assert not np.array_equal(run["solution"], run["solution_table51"])
