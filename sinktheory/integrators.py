"""Symplectic splitting schemes for separable Hamiltonians H = T(p) + U(q).

A scheme advances one step h as the sequence

    kick b[0] h, drift a[0] h, kick b[1] h, drift a[1] h, ..., drift a[s-1] h, kick b[s] h

where a *drift* is ``q += c h p / m`` (the exact flow of the kinetic energy) and a *kick*
is ``p += c h F(q)`` (the exact flow of the potential energy).  Every scheme here is
symmetric (palindromic), hence time-reversible, and costs ``s = len(a)`` force
evaluations per step (the force after the last drift is reused by the next step's first
kick).  Schemes are looked up by name in :data:`SCHEMES`.

Where they stop being trustworthy: all are explicit, so the step must resolve the
fastest oscillation, h omega_max well below ~1 (for the high-order compositions with
negative weights, below ~0.5); past that the energy error does not shrink with the
order and eventually the run blows up.  High order pays only when the forces are smooth
on the scale of the step; with stiff walls (n = 10) the gain over order 4 is modest.

Examples
--------
>>> s = get_scheme("verlet")
>>> s.order, s.stages, s.a, s.b
(2, 1, (1.0,), (0.5, 0.5))
>>> sorted(SCHEMES)  # doctest: +NORMALIZE_WHITESPACE
['blanes-moan4', 'blanes-moan6', 'suzuki-umeno8', 'verlet', 'yoshida4', 'yoshida6']
>>> abs(sum(get_scheme("blanes-moan6").a) - 1) < 1e-15
True
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import validation as v
from .errors import ParameterError
from .limits import DEFAULT_SCHEME

__all__ = ["DEFAULT_SCHEME", "get_scheme", "SCHEMES", "SplittingScheme"]


@dataclass(frozen=True)
class SplittingScheme:
    """Coefficients of one symmetric kick-drift splitting method.

    Parameters
    ----------
    name : str
        Registry name.
    order : int
        Classical order p: the error after a fixed time scales like h^p.
    a : tuple of float
        Drift weights (s of them, summing to 1).
    b : tuple of float
        Kick weights (s + 1 of them, summing to 1).
    reference : str
        Where the coefficients come from.

    The fields are checked (a ParameterError names the first one refused), since a scheme
    built by hand goes straight to the compiled engine (:meth:`sinktheory.engine.core.
    Ensemble.run`), whose loops take the lengths of ``a`` and ``b`` as given.

    Examples
    --------
    >>> SplittingScheme("leapfrog", 2, [1.0], [0.5, 0.5], "by hand").b
    (0.5, 0.5)
    >>> SplittingScheme("leapfrog", 2, [1.0], [0.5, 0.4], "by hand")
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: b = (0.5, 0.4) is not allowed: must be 2 finite kick \
weights summing to 1 (to 1e-12), one more than a
    """

    name: str
    order: int
    a: tuple[float, ...]
    b: tuple[float, ...]
    reference: str

    def __post_init__(self):
        for field in ("name", "reference"):
            if not isinstance(getattr(self, field), str) or not getattr(self, field):
                raise ParameterError(field, getattr(self, field), "a non-empty string")
        object.__setattr__(self, "order", v.positive_int("order", self.order))
        a = _weights("a", self.a, None, "one or more finite drift weights summing to 1 (to 1e-12)")
        b = _weights("b", self.b, len(a) + 1, f"{len(a) + 1} finite kick weights summing "
                     "to 1 (to 1e-12), one more than a")  # fmt: skip
        object.__setattr__(self, "a", a)
        object.__setattr__(self, "b", b)

    @property
    def stages(self) -> int:
        """Force evaluations per step."""
        return len(self.a)

    @property
    def relative_cost(self) -> float:
        """The cost of a step relative to a step of
        :data:`~sinktheory.limits.DEFAULT_SCHEME`: (stages + 1) / (its stages + 1), the
        work estimates' scheme factor (measured in :func:`sinktheory.worklimit.scheme_factor`).

        >>> get_scheme("verlet").relative_cost, get_scheme(DEFAULT_SCHEME).relative_cost
        (0.16666666666666666, 1.0)
        """
        return (self.stages + 1) / (get_scheme(DEFAULT_SCHEME).stages + 1)

    def arrays(self) -> tuple[np.ndarray, np.ndarray]:
        """(a, b) as float64 arrays for the compiled stepping loop."""
        return np.array(self.a, dtype=np.float64), np.array(self.b, dtype=np.float64)


def _weights(name: str, value: object, size: int | None, allowed: str) -> tuple[float, ...]:
    """``value`` as a tuple of finite floats summing to 1 (to 1e-12), of ``size`` entries
    (at least one if None), else ParameterError naming ``name``."""
    shown = tuple(value) if isinstance(value, list | tuple) else value
    try:
        w = v.finite_array(name, value, ndim=1)
    except ParameterError:
        raise ParameterError(name, shown, allowed) from None
    if (w.size != size if size else w.size == 0) or not abs(w.sum() - 1.0) <= 1e-12:
        raise ParameterError(name, shown, allowed)
    return tuple(float(x) for x in w)


def _composition(weights: tuple[float, ...]) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """Drift/kick weights of the composition of Stoermer-Verlet steps of sizes w_i h.

    Verlet (kick h/2, drift h, kick h/2) composed with itself merges the touching
    half-kicks: a_i = w_i, b_0 = w_1/2, b_i = (w_i + w_{i+1})/2, b_s = w_s/2.
    """
    a = tuple(weights)
    b = (weights[0] / 2,)
    b += tuple((weights[i] + weights[i + 1]) / 2 for i in range(len(weights) - 1))
    b += (weights[-1] / 2,)
    return a, b


def _symmetric(half: tuple[float, ...]) -> tuple[float, ...]:
    """Complete a palindrome whose middle entry makes the sum 1: (w1..wm, w0, wm..w1)."""
    middle = 1.0 - 2.0 * sum(half)
    return half + (middle,) + half[::-1]


def _symmetric_even(half: tuple[float, ...]) -> tuple[float, ...]:
    """Palindrome of even length whose two middle entries make the sum 1."""
    middle = 0.5 - sum(half)
    return half + (middle, middle) + half[::-1]


# The "triple jump" of Yoshida (1990), Phys. Lett. A 150, 262 (also Forest & Ruth 1990), as
# in Hairer, Lubich & Wanner, GNI (2006), eq. (II.4.4): w1 = w3 = 1/(2 - 2^(1/3)),
# w2 = -2^(1/3) w1.
_W1 = 1.0 / (2.0 - 2.0 ** (1.0 / 3.0))
_YOSHIDA4 = (_W1, 1.0 - 2.0 * _W1, _W1)

# Yoshida (1990), Table 1, solution A (order 6, 7 Verlet stages): w1, w2, w3; w0 = 1 - 2 sum.
_YOSHIDA6 = _symmetric(
    (0.78451361047755726381949763, 0.23557321335935813368479318, -1.17767998417887100694641568)
)

# Suzuki & Umeno (1993) and McLachlan (1995), SIAM J. Sci. Comput. 16, 151, order 8 with 15
# Verlet stages; the coefficients as listed in Hairer, Lubich & Wanner, Geometric Numerical
# Integration (2006), Sect. V.3.2 (order 8, s = 15).
_SUZUKI_UMENO8 = _symmetric(
    (
        0.74167036435061295344822780,
        -0.40910082580003159399730010,
        0.19075471029623837995387626,
        -0.57386247111608226665638773,
        0.29906418130365592384446354,
        0.33462491824529818378495798,
        0.31529309239676659663205666,
    )
)

# Blanes & Moan (2002), J. Comput. Appl. Math. 142, 313, Table 3, SRKN_6^b (order 4,
# 6 force evaluations), optimised for q'' = f(q).  Kicks b1..b4 (b4 = 1 - 2(b1+b2+b3)),
# drifts a1..a3 (a3 = 1/2 - a1 - a2).
_BM4_A = _symmetric_even((0.245298957184271, 0.604872665711080))
_BM4_B = _symmetric((0.0829844064174052, 0.396309801498368, -0.0390563049223486))

# Blanes & Moan (2002), Table 3, SRKN_11^b (order 6, 11 force evaluations).
_BM6_A = _symmetric(
    (
        0.123229775946271,
        0.290553797799558,
        -0.127049212625417,
        -0.246331761062075,
        0.357208872795928,
    )
)
_BM6_B = _symmetric_even(
    (
        0.0414649985182624,
        0.198128671918067,
        -0.0400061921041533,
        0.0752539843015807,
        -0.0115113874206879,
    )
)


def _scheme(name, order, ab, reference) -> SplittingScheme:
    a, b = ab
    return SplittingScheme(name, order, tuple(a), tuple(b), reference)


#: Every scheme by name.  The step each needs for a given energy error is calibrated in
#: :mod:`sinktheory.stepsize`.
SCHEMES: dict[str, SplittingScheme] = {
    s.name: s
    for s in (
        _scheme("verlet", 2, ((1.0,), (0.5, 0.5)), "Stoermer-Verlet (leapfrog), kick-drift-kick"),
        _scheme(
            "yoshida4",
            4,
            _composition(_YOSHIDA4),
            "Yoshida, Phys. Lett. A 150 (1990) 262: triple jump (Hairer-Lubich-Wanner eq. II.4.4)",
        ),
        _scheme(
            "blanes-moan4",
            4,
            (_BM4_A, _BM4_B),
            "Blanes & Moan, J. Comput. Appl. Math. 142 (2002) 313, Table 3, SRKN_6^b",
        ),
        _scheme(
            "yoshida6",
            6,
            _composition(_YOSHIDA6),
            "Yoshida, Phys. Lett. A 150 (1990) 262, Table 1, solution A",
        ),
        _scheme(
            "blanes-moan6",
            6,
            (_BM6_A, _BM6_B),
            "Blanes & Moan, J. Comput. Appl. Math. 142 (2002) 313, Table 3, SRKN_11^b",
        ),
        _scheme(
            "suzuki-umeno8",
            8,
            _composition(_SUZUKI_UMENO8),
            "McLachlan, SIAM J. Sci. Comput. 16 (1995) 151 / Suzuki & Umeno (1993), order 8, "
            "15 stages; Hairer-Lubich-Wanner GNI Sect. V.3.2",
        ),
    )
}


def get_scheme(name: str) -> SplittingScheme:
    """The scheme registered under ``name`` (ParameterError naming ``scheme`` otherwise)."""
    return SCHEMES[v.choice("scheme", name, tuple(SCHEMES))]
