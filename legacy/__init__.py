"""The appendix FORTRAN, compiled with f2py: one Python face per thesis.

:mod:`.ali1977` (Appendix B: the K.E.D. listings, Cases I-III, and the IBM SSP routines) and
:mod:`.rahman1996` (Appendix B: the CSSP balancing program, INVERSE, our QPROG stand-in).
Rahman (1991) prints no program: its method runs in the 1996 build (see
``linkrepro.port.rahman1991``).  The compiled extensions are ``_ali1977`` and ``_rahman1996``.
"""
