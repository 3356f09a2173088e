"""The scenes of the thesis (``SCENES``) and their columns in words (``QUANTITIES``);
imported when first asked for (``__init__.py``): they import the engines."""
from .figures import SCENE as FIGURES
from .multibody import SCENE as MULTIBODY
from .tables import TABLES
from .quantities import QUANTITIES

SCENES = [*TABLES, FIGURES, MULTIBODY]
