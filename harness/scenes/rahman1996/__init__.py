"""Rahman (1996), optimum mass balancing of the spatial slider crank: Tables 5.1-5.7 and
Figures 5.1-5.6 with section 5.3's percentages; the corrected engine against Exudyn."""
from .figures import SCENE as FIGURES
from .multibody import SCENE as MULTIBODY
from .tables import TABLES
from .quantities import QUANTITIES

SCENES = [*TABLES, FIGURES, MULTIBODY]
__all__ = ["SCENES", "TABLES", "FIGURES", "QUANTITIES"]
