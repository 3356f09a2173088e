"""Ali (1977), the K.E.D. analysis of a four-bar and its crossed cognate: Tables I-III, the
Appendix A curves, the Case III convergence study, the conditioning near a toggle."""
from .appendix import SCENE as APPENDIX
from .case3_convergence import SCENE as CASE3_CONVERGENCE
from .conditioning import SCENE as CONDITIONING
from .elastodynamics import SCENE as ELASTODYNAMICS
from .quantities import QUANTITIES
from .quasi_static import SCENE as QUASI_STATIC
from .tables import TABLES

SCENES = [*TABLES, APPENDIX, CASE3_CONVERGENCE, CONDITIONING, QUASI_STATIC, ELASTODYNAMICS]
__all__ = ["SCENES", "TABLES", "QUANTITIES"]
