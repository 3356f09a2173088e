"""The clean Python port: numpy (and numba kernels), vectorised over input angles.

One subpackage per thesis: :mod:`.ali1977` (K.E.D. four-bar, Cases I-III), :mod:`.rahman1996`
(CSSP balancing), :mod:`.rahman1991` (the generalized slider crank).  Shared by them:
:mod:`.quirks` (the quirk-switch base), :mod:`.dual` (dual numbers), :mod:`.real4` (REAL*4
storage), :mod:`.libm` (the C library's single-precision functions) and :mod:`.slider_crank`
(the spatial slider-crank loop both Rahman theses solve: its inputs, first estimate, Newton
kernel and exact kinematics).

Each thesis's quirk set turns its listings' bugs on (``PRINTED``: the port reproduces the
legacy FORTRAN) or off (``CORRECTED``: what the thesis meant), one named switch per bug.

Importing it sets numba's cache folder (``_numba_cache``: a folder named by the port's source, so
that an edit to any kernel compiles every kernel anew) before any of its modules imports numba.
"""
from . import _numba_cache

_numba_cache.configure()
