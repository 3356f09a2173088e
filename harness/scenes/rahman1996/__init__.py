"""Rahman (1996), optimum mass balancing of the spatial slider crank: Tables 5.1-5.7 and
Figures 5.1-5.6 with section 5.3's percentages; the corrected engine against Exudyn.

Its scenes come from ``catalog.py`` when first asked for (``harness/lazy.py``)."""
from ...lazy import deferred

__all__ = ["SCENES", "TABLES", "FIGURES", "QUANTITIES"]
__getattr__ = deferred(__name__, "catalog", __all__)
