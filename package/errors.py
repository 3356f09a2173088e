"""Typed errors shared by every engine.

Each carries the input angle (degrees) at which the mechanism failed, so that a
caller can tell where in the cycle it happened.
"""


class LinkageError(ArithmeticError):
    """Base class: a mechanism position that cannot be computed."""

    def __init__(self, message: str, angle_deg: float | None = None, **values: float):
        self.angle_deg = angle_deg
        self.values = values
        detail = ", ".join(f"{k}={v:g}" for k, v in values.items())
        where = f" at input angle {angle_deg:g} deg" if angle_deg is not None else ""
        super().__init__(f"{message}{where}" + (f" ({detail})" if detail else ""))


class AssemblyError(LinkageError):
    """The loop cannot close: no real position exists for this input angle."""


class SingularPositionError(LinkageError):
    """The position exists but a matrix of the analysis is singular there
    (a dead-centre or toggle position: division by zero in the printed formulas)."""


class ConvergenceError(LinkageError):
    """An iterative solver did not converge."""


class QPError(ArithmeticError):
    """A quadratic program has no solution: inconsistent constraints, the iteration limit,
    or a Hessian that is not finite.  Raised alike by the legacy QPROG and the port's QP."""
