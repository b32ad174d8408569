"""Exception types of sinktheory.

Two families, kept apart on purpose:

* :class:`ParameterError` (a :class:`ValueError`) -- the caller asked for something
  outside the model's domain.  The message is one line naming the parameter, the value
  given and what is allowed.  The CLI turns it into exit status 2.
* :class:`NumericalError` -- a computation went wrong although the input was valid
  (energy drift over its bound, a non-finite state, a root that cannot be bracketed).
  Each subclass says where and when it happened; nothing returns silently wrong numbers.
"""

from __future__ import annotations

__all__ = [
    "BracketError",
    "EnergyDriftError",
    "HillIntegrationError",
    "NonFiniteStateError",
    "NumericalError",
    "ParameterError",
    "PeriodOutOfRangeError",
    "ShootingError",
    "StepControlError",
    "SweepPointError",
    "WellDefinitionError",
]


class ParameterError(ValueError):
    """An input outside the allowed range.

    Examples
    --------
    >>> raise ParameterError("n", 0, "an integer >= 1")
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: n = 0 is not allowed: must be an integer >= 1
    """

    def __init__(self, name: str, value: object, allowed: str, *, why: str | None = None):
        self.name = name
        self.value = value
        self.allowed = allowed
        text = f"{name} = {value!r} is not allowed: must be {allowed}"
        if why:
            text += f" ({why})"
        super().__init__(text)


class WellDefinitionError(ParameterError):
    """A user's well (an expression, a well file or a parameter value of it) is refused.

    A :class:`ParameterError`, so the CLI exits with status 2.  The message is one line:
    where (``potential``, a file's key, a check), the offending token or value, and why.

    Examples
    --------
    >>> raise WellDefinitionError("potential", "os", "a name that is not declared")
    Traceback (most recent call last):
    ...
    sinktheory.errors.WellDefinitionError: potential: 'os' is refused: a name that is not declared
    """

    def __init__(self, where: str, token: object, reason: str):
        self.name = where
        self.value = token
        self.allowed = reason
        text = f"{where}: {token!r} is refused: {reason}"
        ValueError.__init__(self, " ".join(text.split()))


class NumericalError(RuntimeError):
    """Base class of failures of a computation on valid input."""


class NonFiniteStateError(NumericalError):
    """A state variable became NaN or infinite."""


class EnergyDriftError(NumericalError):
    """The relative error of a conserved energy exceeded its bound."""


class BracketError(NumericalError):
    """A root finder could not bracket or converge to a root."""


class StepControlError(NumericalError):
    """A run of the adaptive step needed more than its step limit in one period
    (:data:`sinktheory.adaptive.MAX_STEPS`)."""


class ShootingError(NumericalError):
    """Newton's method on the periodicity conditions of a periodic orbit did not converge."""


class SweepPointError(NumericalError):
    """A point of a sweep failed numerically; the message names the point."""


class HillIntegrationError(NumericalError):
    """The quarter-period integration of Hill's equation did not finish within its step
    budget."""


class PeriodOutOfRangeError(NumericalError):
    """The period (or A0^(n-1)) is outside float64 range, so the float path cannot run."""
