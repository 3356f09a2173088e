"""linkrepro: rebuild, port and diff the FORTRAN of three mechanism-dynamics theses.

Subpackages
-----------
linkrepro.legacy   the appendix FORTRAN, compiled with f2py (plain functions, numpy out)
linkrepro.port     the clean Python port (PRINTED quirks reproduce legacy, CORRECTED fix them)
linkrepro.harness  scenes, engines, cell-by-cell diff against the published tables, report
"""
from .errors import (AssemblyError, ConvergenceError, LinkageError, LinkreproWarning, ListingBugWarning,
                     PrecisionWarning, QPError, SingularPositionError)

__version__ = "0.1.0"
__all__ = ["AssemblyError", "ConvergenceError", "LinkageError", "LinkreproWarning", "ListingBugWarning",
           "PrecisionWarning", "QPError", "SingularPositionError"]
