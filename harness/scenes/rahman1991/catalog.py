"""The scenes of the thesis (``SCENES``) and their columns in words (``QUANTITIES``);
imported when first asked for (``__init__.py``): they import the engines."""
from .example import SCENE as EXAMPLE
from .quantities import QUANTITIES

SCENES = [EXAMPLE]
