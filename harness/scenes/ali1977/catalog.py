"""The scenes of the thesis (``SCENES``) and their columns in words (``QUANTITIES``);
imported when first asked for (``__init__.py``): they import the engines."""
from .appendix import SCENE as APPENDIX
from .case3_convergence import SCENE as CASE3_CONVERGENCE
from .conditioning import SCENE as CONDITIONING
from .elastodynamics import SCENE as ELASTODYNAMICS
from .quantities import QUANTITIES
from .quasi_static import SCENE as QUASI_STATIC
from .tables import TABLES

SCENES = [*TABLES, APPENDIX, CASE3_CONVERGENCE, CONDITIONING, QUASI_STATIC, ELASTODYNAMICS]
