"""Rahman (1996): optimum mass balancing of the spatial slider crank (CSSP), Appendix B.

:mod:`.balance` runs the example (``balance(CsspInputs(), quirks=CSSP_PRINTED)``: every
table of section 5.2); :mod:`.data` holds its inputs and constants, :mod:`.listing` the
listing's kinematics and unit loads, :mod:`.objective` the objective's quantities,
:mod:`.qprog` the quadratic program, :mod:`.mechanics` the corrected closed-loop
Newton-Euler model, :mod:`.quirks` the listing's bugs (``CSSP_PRINTED``, ``CSSP_CORRECTED``).
"""
