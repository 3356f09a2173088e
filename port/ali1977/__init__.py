"""Ali (1977): the K.E.D. analysis of a four-bar and its crossed cognate, Cases I-III.

``quirks=PRINTED`` reproduces the legacy FORTRAN; ``quirks=CORRECTED`` removes
every registered bug of the original.  See ``quirks.Quirks`` for the switches.
"""
from .fourbar import Cognate, Lengths
from .case1 import cognate_case1, source_case1
from .data import EXAMPLE
from .quirks import CORRECTED, PRINTED, Quirks
from .structure import Section

__all__ = ["CORRECTED", "PRINTED", "Quirks", "Lengths", "Section", "Cognate", "EXAMPLE",
           "source_case1", "cognate_case1"]
