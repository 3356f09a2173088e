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
    a Hessian that is not finite, or an answer that would miss a constraint by more than the
    solver's rounding.  Raised alike by the legacy QPROG and the port's QP."""


class LinkreproWarning(UserWarning):
    """Base class of linkrepro's warnings: a result is returned, but part of it cannot be
    trusted as far as its digits suggest."""


class ListingBugWarning(LinkreproWarning):
    """The inputs fall where a known bug of the original listing changes the result: the
    engine keeps the listing's behaviour (it is what the author ran) and says so.
    ``entry`` is the deviation register's id (``harness/deviations.toml``; ids joined by ", "
    where several bugs act together); ``angle_deg`` the first input angle concerned and
    ``relative_error`` the expected error there, where the warning is about one position."""

    def __init__(self, message: str, entry: str, angle_deg: float | None = None,
                 relative_error: float | None = None):
        self.entry, self.angle_deg, self.relative_error = entry, angle_deg, relative_error
        super().__init__(f"{message} (the listing's bug {entry}, see the deviation register; "
                         "quirks=CORRECTED computes what the thesis meant)")


class PrecisionWarning(LinkreproWarning):
    """The expected rounding error of a result passes what its digits claim: the position is
    close to a singular one (a toggle, a dead centre) and the analysis is ill-conditioned
    there.  ``angle_deg`` is the first input angle concerned; ``condition`` the estimate."""

    def __init__(self, message: str, angle_deg: float | None = None, condition: float | None = None,
                 relative_error: float | None = None):
        self.angle_deg, self.condition, self.relative_error = angle_deg, condition, relative_error
        where = f" at input angle {angle_deg:g} deg" if angle_deg is not None else ""
        detail = [f"condition {condition:.3g}" if condition is not None else "",
                  f"expected relative error {relative_error:.2g}" if relative_error is not None else ""]
        detail = ", ".join(d for d in detail if d)
        super().__init__(f"{message}{where}" + (f" ({detail})" if detail else ""))
