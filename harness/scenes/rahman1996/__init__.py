"""Rahman (1996), optimum mass balancing of the spatial slider crank: Tables 5.1-5.7 and
Figures 5.1-5.6 with section 5.3's percentages."""
from .figures import SCENE as FIGURES
from .tables import TABLES
from .quantities import QUANTITIES

SCENES = [*TABLES, FIGURES]
__all__ = ["SCENES", "TABLES", "FIGURES", "QUANTITIES"]
