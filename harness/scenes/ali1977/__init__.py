"""Ali (1977), the K.E.D. analysis of a four-bar and its crossed cognate: Tables I-III, the
Appendix A curves, the Case III convergence study, the conditioning near a toggle.

Its scenes come from ``catalog.py`` when first asked for (``harness/lazy.py``)."""
from ...lazy import deferred

__all__ = ["SCENES", "TABLES", "QUANTITIES"]
__getattr__ = deferred(__name__, "catalog", __all__)
