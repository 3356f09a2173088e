"""Rahman (1991), the generalized slider crank: section 3.1's example and the claims of
section 3.2.

Its scenes come from ``catalog.py`` when first asked for (``harness/lazy.py``)."""
from ...lazy import deferred

__all__ = ["SCENES", "QUANTITIES"]
__getattr__ = deferred(__name__, "catalog", __all__)
