"""Rahman (1991), the generalized slider crank: section 3.1's example and the claims of
section 3.2."""
from .example import SCENE as EXAMPLE
from .quantities import QUANTITIES

SCENES = [EXAMPLE]
__all__ = ["SCENES", "QUANTITIES"]
