"""The model's equations, derived once with SymPy from the Lagrangian.

Everything numerical in the package descends from the expressions built here: the
kernels in :mod:`sinktheory._generated` are printed from them by
:mod:`sinktheory.codegen`, and the scripts in ``derivations/`` check them against the
paper's printed forms (Pilipchuk, arXiv:1610.02939).

Units are the paper's dimensionless ones: container mass M = 1, spring stiffness 1,
so the container's own period is T = 2*pi.

The ladder of derivations
-------------------------
1. :func:`potential` -- the soft-wall well V(x, y), ``"flat"`` (paper eq. V definition)
   or ``"symmetric"`` (eq. V definition2), written through the *wall ratios*
   s1 = x / D(y) and s2 (= y, or y / D(x)) with D(s) = alpha + beta (s^2 - 1).
2. :func:`lagrangian` -- eq. (Lagr) for k particles in coordinates relative to the
   container.
3. :func:`hamiltonian` -- the Legendre transform, eq. (Hamiltonian).
4. :func:`equations_of_motion` -- Euler-Lagrange equations solved for accelerations.
5. :func:`separable_hamiltonian` -- the canonical change u_j = X + x_j after which
   H = T(momenta) + U(coordinates) with a diagonal mass matrix.
6. :func:`rescaled_equations` -- the single-particle system in the rescaled variables
   (eq. rescale), giving (x-oscill) and the linearised (y-oscill) with
   lambda = -2 beta (alpha - beta); the n = 1 case gets its extra linear term.
7. :func:`rigid_wall_curvature` -- eq. (kappa), the curvature of the wall as n -> oo.
8. :func:`period_integral` / :func:`period_closed_form` -- eq. (T).

Examples
--------
>>> from sinktheory import symbolic as S
>>> S.lambda_coefficient()
-2*beta*(alpha - beta)
>>> S.period_closed_form().subs({S.n: 1, S.A0: 1})
2*pi
"""

from __future__ import annotations

import functools
import numbers
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import sympy as sp

from .errors import ParameterError
from .limits import MAX_N

__all__ = [
    "A0",
    "alpha",
    "amplitude_of_energy",
    "atom_values",
    "AtomForm",
    "axis_reach_factor",
    "beta",
    "c",
    "denominator",
    "E",
    "energy_of_amplitude",
    "equations_of_motion",
    "flat_level_half_width",
    "gamma",
    "gradient_in_ratios",
    "hamiltonian",
    "hessian_in_ratios",
    "hill_shape",
    "iL",
    "kernel_form",
    "ladder",
    "lagrangian",
    "lambda_coefficient",
    "mass_matrix",
    "Maximum",
    "Mechanics",
    "mechanics",
    "mu",
    "n",
    "normal_mode",
    "normal_mode_refusal",
    "NormalMode",
    "oscillator_acceleration",
    "oscillator_energy",
    "period_closed_form",
    "period_integral",
    "potential",
    "potential_of_ratios",
    "rescaled_equations",
    "RescaledSystem",
    "rigid_wall_contour",
    "rigid_wall_curvature",
    "separable_hamiltonian",
    "SeparableHamiltonian",
    "Shape",
    "shape_definition",
    "SHAPES",
    "substitute_ratios",
    "symmetric_corner_bound",
    "symmetric_corner_saddle",
    "w",
    "wall_distance",
    "wall_ratios",
    "WellDefinition",
    "WellLadder",
]

# --- symbols shared by the whole package -------------------------------------------
alpha = sp.Symbol("alpha", positive=True)
beta = sp.Symbol("beta", real=True)
gamma = sp.Symbol("gamma", positive=True)
n = sp.Symbol("n", integer=True, positive=True)
mu = sp.Symbol("mu", positive=True)
X, x, y = sp.symbols("X x y", real=True)
P, p_x, p_y = sp.symbols("P p_x p_y", real=True)
E = sp.Symbol("E", positive=True)
A0 = sp.Symbol("A0", positive=True)
xdd, ydd = sp.symbols("xdd ydd", real=True)
#: alpha - beta, the distance from the centre to the wall on the x axis (rigid limit).
#: Used as a positive symbol inside derivations, then replaced by alpha - beta.
wall_distance = sp.Symbol("L", positive=True)
#: Atoms of the kernels: the wall ratios s1, s2 (V = gamma/(2n) (s1^(2n) + s2^(2n))) and
#: the denominators Dx = D(x), Dy = D(y).  Derivatives are taken in these atoms so that a
#: kernel raises numbers of order one to the power 2n (never x^(2n) and D^(-2n) apart,
#: which overflow or underflow for large n).
s1, s2 = sp.symbols("s1 s2", real=True)
Dx, Dy = sp.symbols("Dx Dy", real=True)
#: Atoms of the circular well: iL = 1 / (alpha - beta) and the squared radial wall ratio
#: w = (x^2 + y^2) iL^2.
iL = sp.Symbol("iL", positive=True)
w = sp.Symbol("w", nonnegative=True)
#: c = (2 n E / gamma)^(1/(2n)) (:func:`axis_reach_factor`): the reach of a particle of
#: energy E in units of the wall; the shapes declare their basin bounds in it.
c = sp.Symbol("c", positive=True)


def denominator(s: sp.Expr) -> sp.Expr:
    """D(s) = alpha + beta (s^2 - 1): the wall's half-width across at coordinate s (a
    SymPy expression or a finite real number).

    Examples
    --------
    >>> denominator(y)
    alpha + beta*(y**2 - 1)
    """
    return alpha + beta * (_expression("s", s) ** 2 - 1)


class Maximum(sp.Function):
    """``Maximum(expr, var, lo, hi)``: the largest value of ``expr`` over var in [lo, hi].

    Left unevaluated; :mod:`sinktheory.codegen` prints it as a call of the numerical
    maximiser of the generated kernels (grid, then golden section).
    """

    def _latex(self, printer):
        f, var, lo, hi = self.args
        return (
            rf"\max_{{{printer._print(var)} \in [{printer._print(lo)}, {printer._print(hi)}]}}"
            rf" {printer._print(f)}"
        )


# --- the well shapes ----------------------------------------------------------------
@runtime_checkable
class WellDefinition(Protocol):
    """What the derivation ladder needs of a well: a registered :class:`Shape` and a
    user's :class:`sinktheory.userwell.UserWell` both have it, so every function below
    that takes ``shape`` takes either a registered name or such an object.

    Attributes
    ----------
    name : str
    atoms : tuple of (Symbol, Expr)
        Intermediate quantities (numerator / denominator) in the order a kernel computes
        them; empty for a user's well, whose derivatives SymPy takes directly.
    potential : Expr
        V in the atoms, x, y and the parameters.
    wall_ratios : tuple of Expr
        Ratios in x, y whose level 1 is the rigid wall (may be empty).
    parameter_symbols : tuple of Symbol
        The well's parameters, in the order kernels take them.
    """

    name: str
    atoms: tuple[tuple[sp.Symbol, sp.Expr], ...]
    potential: sp.Expr
    wall_ratios: tuple[sp.Expr, ...]

    @property
    def parameter_symbols(self) -> tuple[sp.Symbol, ...]: ...  # pragma: no cover


@dataclass(frozen=True)
class Shape:
    """One well shape: everything the package knows about it, declared once.

    The kernels of :mod:`sinktheory._generated.shapes` (potential, force, Hessian, Hill
    coefficient, geometry), the engine's system and the validation of
    :class:`sinktheory.model.Well` are all derived from these fields, so a new shape is
    one more entry of :data:`SHAPES` and a regeneration (``python
    derivations/generate_kernels.py``).

    Attributes
    ----------
    name : str
        Name used by the API and the CLI (letters only: it is part of engine names).
    summary : str
        One line: the formula and the meaning of alpha, beta, n, gamma for this shape.
    atoms : tuple of (Symbol, Expr)
        Intermediate quantities in the order a kernel computes them, each defined in x,
        y, the parameters and earlier atoms as numerator / denominator (an atom's
        derivative is (d num - atom d den) / den, which keeps powers of O(1) numbers).
    potential : Expr
        V in the atoms (and x, y); the same gamma, n for every shape.
    wall_ratios : tuple of Expr
        Ratios in x, y that are < 1 strictly inside the walls (the level V = gamma/(2n)
        of each term); a start position must have all of them below 1.
    rigid_wall : Expr
        x > 0 on the rigid wall (n -> oo) at height y, near y = 0; its curvature is
        reported by ``sinktheory well``.
    x_reach, y_reach : Expr
        Bounds of |x|, |y| over the basin V <= E around the centre, in c (:data:`c`),
        alpha, beta, gamma, n; may contain :class:`Maximum`.
    escape : Expr
        Energy above which the basin opens (a particle escapes); ``oo`` if never.
    escape_name : str
        What that energy is, for messages (e.g. "the corner saddle").
    """

    name: str
    summary: str
    atoms: tuple[tuple[sp.Symbol, sp.Expr], ...]
    potential: sp.Expr
    wall_ratios: tuple[sp.Expr, ...]
    rigid_wall: sp.Expr
    x_reach: sp.Expr
    y_reach: sp.Expr
    escape: sp.Expr = sp.oo
    escape_name: str = ""

    @property
    def parameter_symbols(self) -> tuple[sp.Symbol, ...]:
        """(alpha, beta, gamma, n): the parameters of every registered shape."""
        return (alpha, beta, gamma, n)

    @property
    def denominators(self) -> tuple[sp.Expr, ...]:
        """Atom denominators (as functions of x, y) that must stay > 0 wherever a
        particle can go; each is monotone in x^2 and in y^2."""
        values = dict(self.atoms)
        dens = []
        for _atom, definition in self.atoms:
            den = sp.fraction(definition)[1]
            if den in values:
                dens.append(values[den])
        return tuple(dens)


def _ratio_sum() -> sp.Expr:
    """gamma/(2n) (s1^(2n) + s2^(2n)): the paper's wells in their wall ratios."""
    return gamma / (2 * n) * (s1 ** (2 * n) + s2 ** (2 * n))


def _flat() -> Shape:
    width = flat_level_half_width().subs({Dy: denominator(y), E: gamma * c ** (2 * n) / (2 * n)})
    width = sp.expand_power_base(sp.factor_terms(width), force=True)  # D (c^2n - y^2n)^(1/2n)
    L = alpha - beta
    return Shape(
        name="flat",
        summary="paper eq. (V definition): gamma/(2n) [(x/D(y))^2n + y^2n]; walls "
        "x = +-D(y) bulge inward for beta > 0, outward for beta < 0; y = +-1 straight",
        atoms=((Dy, denominator(y)), (s1, x / Dy), (s2, y)),
        potential=_ratio_sum(),
        wall_ratios=(x / denominator(y), y),
        rigid_wall=denominator(y),
        x_reach=sp.Piecewise(
            (c * L, beta <= 0),
            (Maximum(width, y, 0, c), True),
        ),
        y_reach=c,
    )


def _symmetric() -> Shape:
    L = alpha - beta
    s_star, v_star = symmetric_corner_saddle()
    corner = symmetric_corner_bound()
    (radicand,) = [p.base for p in corner.atoms(sp.Pow) if p.exp == sp.S.Half]
    box = sp.Piecewise(
        (c * L, beta <= 0),
        (corner, radicand >= 0),
        # the wall lines x = c D(y), y = c D(x) do not meet: bound by the saddle
        (sp.Max(s_star, c * denominator(s_star)), True),
    )
    return Shape(
        name="symmetric",
        summary="paper eq. (V definition2): gamma/(2n) [(x/D(y))^2n + (y/D(x))^2n]; "
        "invariant under x <-> y; for beta > 0 confines only below its corner saddle",
        atoms=((Dy, denominator(y)), (Dx, denominator(x)), (s1, x / Dy), (s2, y / Dx)),
        potential=_ratio_sum(),
        wall_ratios=(x / denominator(y), y / denominator(x)),
        rigid_wall=denominator(y),
        x_reach=box,
        y_reach=box,
        escape=sp.Piecewise((v_star, beta > 0), (sp.oo, True)),
        escape_name="the corner saddle",
    )


def _circular() -> Shape:
    L = alpha - beta
    return Shape(
        name="circular",
        summary="gamma/(2n) ((x^2 + y^2)/(alpha - beta)^2)^n: a round well of radius "
        "alpha - beta (the wall distance of the other shapes); alpha and beta enter only "
        "through it, and the rigid wall always focuses (curvature -1/(alpha - beta))",
        atoms=((iL, 1 / L), (w, (x**2 + y**2) * iL**2)),
        potential=gamma / (2 * n) * w**n,
        wall_ratios=(sp.sqrt(x**2 + y**2) / L,),
        rigid_wall=sp.sqrt(L**2 - y**2),
        x_reach=c * L,
        y_reach=c * L,
    )


#: The shape definitions, in the order the registry lists them; a shape's name is its
#: function's name without the underscore.
_DEFINITIONS = (_flat, _symmetric, _circular)


@functools.cache
def _registry() -> dict[str, Shape]:
    shapes = {}
    for define in _DEFINITIONS:
        shape = define()
        if shape.name != define.__name__.lstrip("_") or not shape.name.isalpha():
            raise AssertionError(f"shape {shape.name!r} must be letters named as {define}")
        shapes[shape.name] = shape
    return shapes


class _Shapes(Mapping):
    """Read-only name -> :class:`Shape` mapping, built on first use (SymPy work)."""

    def __getitem__(self, name: str) -> Shape:
        return _registry()[name]

    def __iter__(self):
        return (define.__name__.lstrip("_") for define in _DEFINITIONS)

    def __len__(self) -> int:
        return len(_DEFINITIONS)

    def __contains__(self, name: object) -> bool:
        return name in tuple(self)

    def __repr__(self) -> str:
        return f"SHAPES{tuple(self)}"


#: The registry of well shapes: iterating gives the names, ``SHAPES[name]`` the
#: :class:`Shape`.  To add a shape, write its ``_<name>()`` definition above and append
#: it to ``_DEFINITIONS``.
SHAPES = _Shapes()


def shape_definition(shape: str | WellDefinition, name: str = "shape") -> Shape | WellDefinition:
    """The :class:`Shape` called ``shape`` (ParameterError naming the allowed ones and the
    parameter ``name``), or ``shape`` itself when it is a :class:`WellDefinition` (a
    user's well)."""
    if not isinstance(shape, str) and isinstance(shape, WellDefinition):
        return shape
    if not isinstance(shape, str) or shape not in SHAPES:
        raise ParameterError(name, shape, f"one of {tuple(SHAPES)} or a user's well")
    return SHAPES[shape]


def wall_ratios(shape: str | WellDefinition) -> tuple[sp.Expr, ...]:
    """The shape's wall ratios in x, y (all < 1 strictly inside the walls).

    ``"flat"``: (x / D(y), y); ``"symmetric"``: (x / D(y), y / D(x)); ``"circular"``:
    (r / (alpha - beta),).
    """
    return shape_definition(shape).wall_ratios


def atom_values(shape: str | WellDefinition) -> dict[sp.Symbol, sp.Expr]:
    """Definitions of the atoms in x, y, in the order a kernel computes them."""
    return dict(shape_definition(shape).atoms)


def potential_of_ratios(shape: str | WellDefinition) -> sp.Expr:
    """V in the shape's atoms (gamma/(2n) (s1^(2n) + s2^(2n)) for the paper's wells)."""
    return shape_definition(shape).potential


def potential(shape: str | WellDefinition, xs: sp.Expr = x, ys: sp.Expr = y) -> sp.Expr:
    """The well V(x, y): paper eqs. (V definition), (V definition2), or another shape."""
    V = substitute_ratios(potential_of_ratios(shape), shape)
    return V.subs({x: _expression("xs", xs), y: _expression("ys", ys)}, simultaneous=True)


def _expression(name: str, value: object) -> sp.Expr:
    """``value`` as a SymPy expression (a number must be real and finite), else
    ParameterError naming ``name``."""
    allowed = "a SymPy expression or a finite real number"
    try:
        expr = sp.sympify(value, strict=True)
    except (sp.SympifyError, TypeError, ValueError):
        raise ParameterError(name, value, allowed) from None
    if not isinstance(expr, sp.Expr) or expr.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
        raise ParameterError(name, value, allowed)
    if expr.is_number and not expr.is_extended_real:
        raise ParameterError(name, value, allowed)
    return expr


# --- derivatives in atom form ------------------------------------------------------
def _atom_derivative(atom: sp.Symbol, var: sp.Symbol, shape: str | WellDefinition) -> sp.Expr:
    """d(atom)/d(var), written in atoms: d(num/den) = (d num - atom d den) / den."""
    num, den = sp.fraction(atom_values(shape)[atom])
    dnum = ratio_derivative(num, var, shape, expand=False)
    if den == 1:
        return dnum
    return (dnum - atom * ratio_derivative(den, var, shape, expand=False)) / den


def ratio_derivative(
    expr: sp.Expr, var: sp.Symbol, shape: str | WellDefinition, *, expand: bool = True
) -> sp.Expr:
    """d(expr)/d(var) for an expression in x, y and the shape's atoms (chain rule)."""
    total = sp.diff(expr, var)
    for atom in atom_values(shape):
        if expr.has(atom):
            total += sp.diff(expr, atom) * _atom_derivative(atom, var, shape)
    if not expand or not atom_values(shape):  # a user's well as written: SymPy's form
        return total
    if isinstance(shape_definition(shape), Shape):
        return sp.powsimp(sp.expand(total), force=True)
    # a user's well in atoms (kernel_form): only powers of one base are merged
    # (w^(2n) / w -> w^(2n - 1), finite at w = 0), nothing expanded or split
    return sp.powsimp(total, combine="exp", force=True)


@dataclass(frozen=True)
class AtomForm:
    """A well with the compound bases of its powers lifted into atoms (see
    :func:`kernel_form`, :func:`lift_powers`); a :class:`WellDefinition`."""

    name: str
    atoms: tuple[tuple[sp.Symbol, sp.Expr], ...]
    potential: sp.Expr
    wall_ratios: tuple[sp.Expr, ...]
    parameter_symbols: tuple[sp.Symbol, ...]


def _lift(expr: sp.Expr, atoms: dict[sp.Expr, sp.Symbol]) -> sp.Expr:
    """expr with the base of every power that depends on x or y (and is not x or y)
    replaced by an atom, innermost first; ``atoms`` maps each base to its symbol."""
    if expr.is_Atom:
        return expr
    args = [_lift(a, atoms) for a in expr.args]
    if expr.is_Pow:
        base, exp = args
        if base.free_symbols & {x, y, *atoms.values()} and not base.is_Symbol:
            if base not in atoms:
                atoms[base] = sp.Symbol(f"_w{len(atoms) + 1}", real=True)
            base = atoms[base]
        return sp.Pow(base, exp)
    return expr.func(*args)


def lift_powers(V: sp.Expr) -> tuple[tuple[tuple[sp.Symbol, sp.Expr], ...], sp.Expr]:
    """(atoms, V in the atoms): the base of every power of x, y in ``V`` (innermost first)
    becomes an atom ``_w1``, ``_w2``, ... (see :func:`kernel_form`).

    Examples
    --------
    >>> from sinktheory.userwell import parse_potential  # keeps the power as written
    >>> lift_powers(parse_potential("(x/(1 + y**2))**8", ()))
    (((_w1, y**2 + 1), (_w2, x/_w1)), _w2**8)
    """
    atoms: dict[sp.Expr, sp.Symbol] = {}
    lifted = _lift(V, atoms)
    return tuple((symbol, base) for base, symbol in atoms.items()), lifted


def kernel_form(shape: str | WellDefinition) -> WellDefinition:
    """The definition a kernel printer differentiates: a registered :class:`Shape` as it
    is; a user's well with the base of each power of x, y lifted into an atom (``_w1``,
    ``_w2``, ... defined in x, y, the parameters and earlier atoms), as the registered
    shapes are written in their wall ratios.  :func:`gradient_in_ratios` and
    :func:`hessian_in_ratios` then differentiate by the chain rule through the atoms:
    d(w^n) = n w^(n - 1) dw keeps the numbers of order one and is finite where w = 0,
    where SymPy's d((y/b)^2) = 2 (y/b)^2 / y is 0/0 (NaN at the centre).

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> form = kernel_form(UserWell("e", "((x/a)**2 + (y/b)**2)**n", {"a": 1, "b": 2, "n": 3}))
    >>> form.atoms, form.potential
    (((_w1, x/a), (_w2, y/b), (_w3, _w1**2 + _w2**2)), _w3**n)
    >>> gradient_in_ratios(form)[1]
    2*_w2*_w3**(n - 1)*n/b
    """
    definition = shape_definition(shape)
    if isinstance(definition, Shape):
        return definition
    atoms, lifted = lift_powers(definition.potential)
    return AtomForm(
        definition.name,
        atoms,
        lifted,
        tuple(definition.wall_ratios),
        tuple(definition.parameter_symbols),
    )


def gradient_in_ratios(shape: str | WellDefinition) -> tuple[sp.Expr, sp.Expr]:
    """(dV/dx, dV/dy) in the atoms and x, y."""
    V = potential_of_ratios(shape)
    return ratio_derivative(V, x, shape), ratio_derivative(V, y, shape)


def hessian_in_ratios(shape: str | WellDefinition) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """(V_xx, V_xy, V_yy) in the atoms (for variational equations)."""
    Vx, Vy = gradient_in_ratios(shape)
    return (
        ratio_derivative(Vx, x, shape),
        ratio_derivative(Vx, y, shape),
        ratio_derivative(Vy, y, shape),
    )


def substitute_ratios(expr: sp.Expr, shape: str | WellDefinition) -> sp.Expr:
    """Replace the atoms by their definitions in x, y.

    Examples
    --------
    >>> substitute_ratios(s1**2 + s2, "flat")
    x**2/(alpha + beta*(y**2 - 1))**2 + y
    """
    expr = _expression("expr", expr)
    values = atom_values(shape)
    for atom in reversed(list(values)):
        expr = expr.subs(atom, values[atom])
    return expr.subs(values)


def normal_mode_refusal(shape: str) -> str:
    """Why Hill's analysis of the normal mode y = 0 does not apply to ``shape`` ("" if it
    does).

    It applies when y = 0 is invariant (V even in y) and the motion on it is the paper's
    power-law oscillator, V(x, 0) = gamma/(2n) (x / (alpha - beta))^(2n).  Checked at exact
    rational points for n = 1, 2, 5.
    """
    axis = gamma / (2 * n) * (x / (alpha - beta)) ** (2 * n)
    for k in (1, 2, 5):
        V = potential(shape).subs(n, k)
        for xv, b in (
            (sp.Rational(1, 3), sp.Rational(-3, 10)),
            (sp.Rational(-2, 5), sp.Rational(1, 4)),
        ):
            at = {alpha: sp.Rational(1, 2), beta: b, gamma: sp.Rational(7, 5), x: xv}
            if sp.simplify(sp.diff(V, y).subs(y, 0).subs(at)) != 0:
                return "y = 0 is not invariant (V is not even in y)"
            if sp.simplify((V.subs(y, 0) - axis.subs(n, k)).subs(at)) != 0:
                return (
                    "the motion on y = 0 is not the power-law oscillator "
                    "(V(x, 0) differs from gamma/(2n) (x/(alpha - beta))^(2n))"
                )
    return ""


# --- mechanics --------------------------------------------------------------------
@dataclass(frozen=True)
class Mechanics:
    """Coordinates, velocities and momenta of the container and k particles.

    For k = 1 the particle symbols are the plain ``x, y, p_x, p_y``; for k > 1 they carry
    the index j = 1..k (``x_1``, ``p_y_3``, ...).
    """

    k: int
    coordinates: tuple[sp.Symbol, ...]
    velocities: tuple[sp.Symbol, ...]
    momenta: tuple[sp.Symbol, ...]

    @property
    def xs(self) -> tuple[sp.Symbol, ...]:
        return self.coordinates[1 : 1 + self.k]

    @property
    def ys(self) -> tuple[sp.Symbol, ...]:
        return self.coordinates[1 + self.k :]


#: The largest particle count of the symbolic derivations (the engine derives k = 1 and
#: replicates it): separable_hamiltonian takes about 1.5 s at k = 2 and 10 s at k = 4.
MAX_K = 4


def _integer_in(value: object, top: int) -> bool:
    """Whether ``value`` is an integer (not a bool) in [1, top]."""
    return not isinstance(value, bool) and isinstance(value, numbers.Integral) and 1 <= value <= top


def mechanics(k: int) -> Mechanics:
    """Symbols for the container (X, P) and k particles."""
    if not _integer_in(k, MAX_K):
        raise ParameterError("k", k, f"an integer in [1, {MAX_K}]")
    if k == 1:
        xs, ys, pxs, pys = (x,), (y,), (p_x,), (p_y,)
    else:
        idx = range(1, k + 1)
        xs = tuple(sp.Symbol(f"x_{j}", real=True) for j in idx)
        ys = tuple(sp.Symbol(f"y_{j}", real=True) for j in idx)
        pxs = tuple(sp.Symbol(f"p_x_{j}", real=True) for j in idx)
        pys = tuple(sp.Symbol(f"p_y_{j}", real=True) for j in idx)
    q = (X, *xs, *ys)
    qd = tuple(sp.Symbol(f"{s.name}dot", real=True) for s in q)
    return Mechanics(k, q, qd, (P, *pxs, *pys))


def lagrangian(k: int = 1, shape: str | WellDefinition = "flat") -> tuple[sp.Expr, Mechanics]:
    """Paper eq. (Lagr): L = X'^2/2 - X^2/2 + sum_j [mu/2((X' + x_j')^2 + y_j'^2) - V_j]."""
    m = mechanics(k)
    Xd = m.velocities[0]
    xds, yds = m.velocities[1 : 1 + k], m.velocities[1 + k :]
    L = Xd**2 / 2 - X**2 / 2
    for xj, yj, xdj, ydj in zip(m.xs, m.ys, xds, yds, strict=True):
        L += mu / 2 * ((Xd + xdj) ** 2 + ydj**2) - potential(shape, xj, yj)
    return L, m


def mass_matrix(k: int = 1, shape: str | WellDefinition = "flat") -> sp.Matrix:
    """The (constant) mass matrix d^2 L / dq' dq' in relative coordinates."""
    L, m = lagrangian(k, shape)
    M = sp.hessian(L, m.velocities)
    if any(M.has(q) for q in m.coordinates):
        raise AssertionError("mass matrix depends on coordinates")
    return M


def hamiltonian(k: int = 1, shape: str | WellDefinition = "flat") -> sp.Expr:
    """Legendre transform H = sum p q' - L, paper eq. (Hamiltonian), in (q, p).

    The paper's sum lists only p_j x_j'; the y-momenta enter the transform too.
    """
    L, m = lagrangian(k, shape)
    momenta_of_velocities = [sp.diff(L, v) for v in m.velocities]
    sol = sp.solve(
        [sp.Eq(p, e) for p, e in zip(m.momenta, momenta_of_velocities, strict=True)],
        m.velocities,
        dict=True,
    )[0]
    H = sum(p * v for p, v in zip(m.momenta, m.velocities, strict=True)) - L
    H = sp.expand(H.subs(sol))
    potential_part = H.subs({p: 0 for p in m.momenta})
    return sp.expand(sp.simplify(H - potential_part)) + potential_part


def equations_of_motion(
    k: int = 1, shape: str | WellDefinition = "flat"
) -> dict[sp.Symbol, sp.Expr]:
    """Euler-Lagrange equations solved for the accelerations, in relative coordinates.

    L = q'^T M q'/2 - U(q) with a constant mass matrix M, so M q'' = -grad U.  Returns
    ``{coordinate: acceleration}``.  For k = 1 the result is written in the kernel atoms
    (s1, s2, Dx, Dy; see :func:`substitute_ratios`), for k > 1 explicitly in x_j, y_j.
    """
    L, m = lagrangian(k, shape)
    M = mass_matrix(k, shape)
    if k == 1:
        Vx, Vy = gradient_in_ratios(shape)
        grad_U = sp.Matrix([X, Vx, Vy])
    else:
        U = -L.subs({v: 0 for v in m.velocities})
        grad_U = sp.Matrix([sp.diff(U, q) for q in m.coordinates])
    acc = M.inv().applyfunc(sp.factor) * (-grad_U)
    return {q: sp.expand(a) for q, a in zip(m.coordinates, acc, strict=True)}


@dataclass(frozen=True)
class SeparableHamiltonian:
    """H = kinetic(momenta) + potential(coordinates) in absolute particle coordinates.

    Attributes
    ----------
    coordinates : (X, u_1..u_k, y_1..y_k) with u_j = X + x_j
    momenta : (Pi, pi_1..pi_k, pi_y_1..pi_y_k)
    kinetic, potential : the two parts of H
    masses : diagonal of the mass matrix, (1, mu, ..., mu)
    """

    coordinates: tuple[sp.Symbol, ...]
    momenta: tuple[sp.Symbol, ...]
    kinetic: sp.Expr
    potential: sp.Expr
    masses: tuple[sp.Expr, ...]


def separable_hamiltonian(k: int = 1, shape: str | WellDefinition = "flat") -> SeparableHamiltonian:
    """Canonical change u_j = X + x_j (type-2 generating function) separating H.

    F2 = X Pi + sum_j [(X + x_j) pi_j + y_j pi_y_j] gives P = Pi + sum pi_j, p_j = pi_j,
    so the kinetic energy loses its cross terms and the mass matrix becomes diagonal.
    """
    m = mechanics(k)
    H = hamiltonian(k, shape)
    us = tuple(sp.Symbol(f"u_{j}" if k > 1 else "u", real=True) for j in range(1, k + 1))
    new_p = tuple(sp.Symbol(f"pi_{s.name}", real=True) for s in m.momenta)
    F2 = X * new_p[0]
    for xj, yj, pij, piyj in zip(m.xs, m.ys, new_p[1 : 1 + k], new_p[1 + k :], strict=True):
        F2 += (X + xj) * pij + yj * piyj
    old_p = {p: sp.diff(F2, q) for p, q in zip(m.momenta, m.coordinates, strict=True)}
    new_q = [sp.diff(F2, pn) for pn in new_p]
    to_abs = {xj: uj - X for xj, uj in zip(m.xs, us, strict=True)}
    H_new = sp.expand(H.subs(old_p, simultaneous=True).subs(to_abs, simultaneous=True))
    coords = (X, *us, *m.ys)
    # the new coordinates are what F2 says they are
    for qn, c in zip(new_q, coords, strict=True):
        if sp.simplify(qn.subs(to_abs) - c) != 0:
            raise AssertionError("generating function does not give the new coordinates")
    pot = sp.simplify(H_new.subs({p: 0 for p in new_p}))
    kinetic = sp.expand(sp.simplify(H_new - pot))
    if any(kinetic.has(q) for q in coords):
        raise AssertionError("kinetic part still depends on coordinates: H does not separate")
    masses = tuple(sp.simplify(1 / sp.diff(kinetic, p, 2)) for p in new_p)
    return SeparableHamiltonian(coords, new_p, kinetic, pot, masses)


# --- the normal mode y = 0 and the whole ladder -------------------------------------
def y_invariance(V: sp.Expr) -> tuple[bool, str]:
    """Whether y = 0 is invariant for the well ``V``: dV/dy(x, 0) == 0 identically,
    decided symbolically (:func:`sympy.simplify` after :func:`sympy.expand`).

    Examples
    --------
    >>> y_invariance(x**4 + x**2 * y**2)
    (True, 'dV/dy(x, 0) = 0')
    >>> y_invariance(x**2 + y**2 + x**2 * y)
    (False, 'dV/dy(x, 0) = x**2, not identically 0')
    """
    d = _on_axis(sp.diff(V, y))
    if d is sp.nan:
        return False, "dV/dy(x, 0) could not be decided" + _UNDECIDED
    if d == 0 or sp.simplify(sp.expand(d)) == 0:
        return True, "dV/dy(x, 0) = 0"
    return False, f"dV/dy(x, 0) = {sp.simplify(d)}, not identically 0"


_UNDECIDED = " (NaN at y = 0 for general parameters)"


def _on_axis(expr: sp.Expr) -> sp.Expr:
    """expr at y = 0.  Where plain substitution meets 0^k / 0 (y^(2n) / y from the chain
    rule, NaN to SymPy) the powers of y are split off and merged first: a symbolic n
    leaves terms 0^(2n - 2), which are 1 at n = 1 and 0 above (the n = 1 well's extra
    linear term).  NaN is returned if that does not settle it."""
    value = expr.subs(y, 0)
    if value.has(sp.nan, sp.zoo):
        merged = sp.powsimp(sp.expand(sp.expand_power_base(expr, force=True)), force=True)
        value = merged.subs(y, 0)
    return sp.nan if value.has(sp.nan, sp.zoo) else value


@dataclass(frozen=True)
class NormalMode:
    """The motion on y = 0 of one particle (k = 1) and its transverse linearisation, in
    the well's own variables (no rescaling).

    Attributes
    ----------
    invariant : bool
        y = 0 is invariant (dV/dy(x, 0) == 0, decided symbolically).
    reason : str
        How that was decided, or why the line is not invariant: Floquet multipliers,
        nonlinear normal modes and transverse exponents refuse a well with this reason.
    x_acceleration, X_acceleration : Expr or None
        xdd and Xdd on y = 0 (the container and the particle along the line).
    hill_coefficient : Expr or None
        q(x) of y'' + q(x) y = 0, the y-equation linearised about y = 0:
        -d(ydd)/dy at y = 0, which is V_yy(x, 0) / mu.
    """

    invariant: bool
    reason: str
    x_acceleration: sp.Expr | None = None
    X_acceleration: sp.Expr | None = None
    hill_coefficient: sp.Expr | None = None


def normal_mode(
    shape: str | WellDefinition, values: Mapping[sp.Symbol, sp.Expr] | None = None
) -> NormalMode:
    """The normal mode y = 0 of ``shape`` (a name or a :class:`WellDefinition`), from the
    equations of motion: invariant when ydd vanishes on y = 0 for every x (symbolically),
    then the accelerations there and Hill's coefficient (see :class:`NormalMode`).

    Where SymPy cannot decide it for general parameters (y^(2n - 1) at y = 0 when nothing
    says n >= 1, as for a user's parameter n), it is decided at ``values`` (parameter
    symbol -> number), and the reason says so; without values it is refused.

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> mode = normal_mode(UserWell("quartic", "x**4/4 + y**2/2 + x**2*y**2", {}))
    >>> mode.invariant, mode.hill_coefficient
    (True, (2*x**2 + 1)/mu)
    >>> normal_mode(UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {})).reason
    'dV/dy(x, 0) = x**2, not identically 0'
    >>> power = UserWell("power", "x**2 + y**(2*n)", {"n": 2})
    >>> normal_mode(power, power.values()).reason
    'dV/dy(x, 0) = 0 at n = 2'
    """
    values = _parameter_values(shape_definition(shape), values)
    V = potential(shape)
    invariant, reason = y_invariance(V)
    at = {}
    if not invariant and reason.endswith(_UNDECIDED) and values:
        at = dict(values)
        V = V.subs(at)
        invariant, reason = y_invariance(V)
        reason += " at " + ", ".join(f"{k} = {v}" for k, v in at.items())
    if not invariant:
        return NormalMode(False, reason)
    acc = {q: substitute_ratios(a, shape) for q, a in equations_of_motion(1, shape).items()}
    # the equations of motion give mu ydd = -dV/dy, so -d(ydd)/dy = V_yy / mu, taken from
    # V (whose powers of y merge where those of the expanded accelerations do not)
    if sp.simplify(mu * acc[y] + sp.diff(potential(shape), y)) != 0:
        raise AssertionError("the y equation of motion is not mu ydd = -dV/dy")
    q = sp.factor(sp.simplify(_on_axis(sp.diff(V, y, 2)) / mu))
    on_line = {c: sp.simplify(_on_axis(acc[c].subs(at))) for c in (x, X)}
    return NormalMode(True, reason, on_line[x], on_line[X], q)


def _parameter_values(
    definition: WellDefinition, values: object
) -> dict[sp.Symbol, sp.Expr] | None:
    """``values`` (None, or a mapping of some of the well's parameter symbols to finite
    real numbers) as a dict, else ParameterError naming ``values``."""
    if values is None:
        return None
    symbols = tuple(definition.parameter_symbols)
    allowed = f"None or a mapping of the well's parameters {symbols} to finite real numbers"
    if not isinstance(values, Mapping):
        raise ParameterError("values", values, allowed)
    out = {}
    for key, value in values.items():
        if key not in symbols:
            raise ParameterError("values", values, allowed, why=f"{key!r} is not one of them")
        try:
            number = _expression("values", value)
        except ParameterError:
            number = None
        if number is None or not number.is_number:
            raise ParameterError("values", values, allowed, why=f"{key} = {value!r}") from None
        out[key] = number
    return out


@dataclass(frozen=True)
class WellLadder:
    """The derivation ladder of one well, k = 1 particle (every entry derived here from
    the Lagrangian, nothing retyped): what ``sinktheory derive --well FILE`` prints and
    what a printer of kernels consumes.

    Attributes
    ----------
    name : str
    parameters : the well's parameter symbols
    potential : V(x, y)
    lagrangian, hamiltonian : L(q, q'), H(q, p) in coordinates relative to the container
    equations_of_motion : {X: Xdd, x: xdd, y: ydd}
    separable : the canonical form H = T(momenta) + U(coordinates)
    force : (-dV/dx, -dV/dy)
    hessian : (V_xx, V_xy, V_yy)
    normal_mode : the line y = 0 (:class:`NormalMode`)
    """

    name: str
    parameters: tuple[sp.Symbol, ...]
    potential: sp.Expr
    lagrangian: sp.Expr
    hamiltonian: sp.Expr
    equations_of_motion: dict[sp.Symbol, sp.Expr]
    separable: SeparableHamiltonian
    force: tuple[sp.Expr, sp.Expr]
    hessian: tuple[sp.Expr, sp.Expr, sp.Expr]
    normal_mode: NormalMode

    def items(self) -> dict[str, sp.Expr]:
        """The ladder as named expressions, in order (for printing)."""
        out = {
            "potential": self.potential,
            "lagrangian": self.lagrangian,
            "hamiltonian": self.hamiltonian,
            **{f"{q.name}dd": a for q, a in self.equations_of_motion.items()},
            "separable_kinetic": self.separable.kinetic,
            "separable_potential": self.separable.potential,
            "force_x": self.force[0],
            "force_y": self.force[1],
            "hessian_xx": self.hessian[0],
            "hessian_xy": self.hessian[1],
            "hessian_yy": self.hessian[2],
        }
        mode = self.normal_mode
        if mode.invariant:
            out["hill_coefficient"] = mode.hill_coefficient
        return out


def ladder(
    well: str | WellDefinition, values: Mapping[sp.Symbol, sp.Expr] | None = None
) -> WellLadder:
    """The :class:`WellLadder` of a registered shape or a user's well, one interface for
    both: the equations of motion, force and Hessian are written in x, y (the atoms of a
    registered shape substituted), for general parameters; ``values`` decide the normal
    mode where general parameters cannot (:func:`normal_mode`).

    Examples
    --------
    >>> from sinktheory.userwell import UserWell
    >>> steps = ladder(UserWell("round", "k*(x**2 + y**2)/2", {"k": 2}))
    >>> steps.force, steps.equations_of_motion[y]
    ((-k*x, -k*y), -k*y/mu)
    """
    definition = shape_definition(well, "well")
    values = _parameter_values(definition, values)
    L, _ = lagrangian(1, well)
    eom = equations_of_motion(1, well)
    V = potential(well)
    return WellLadder(
        name=definition.name,
        parameters=tuple(definition.parameter_symbols),
        potential=V,
        lagrangian=L,
        hamiltonian=hamiltonian(1, well),
        equations_of_motion={q: substitute_ratios(a, well) for q, a in eom.items()},
        separable=separable_hamiltonian(1, well),
        force=(-sp.diff(V, x), -sp.diff(V, y)),
        hessian=(sp.diff(V, x, 2), sp.diff(V, x, y), sp.diff(V, y, 2)),
        normal_mode=normal_mode(well, values),
    )


# --- rescaled single-particle system --------------------------------------------------
@dataclass(frozen=True)
class RescaledSystem:
    """Single particle (k = 1) in the variables of eq. (rescale).

    x_equation, y_equation : expressions equal to zero, in xdd, ydd, x, y, X
    hill_coefficient : q(x) such that the linearised y-equation reads ydd + q(x) y = 0
    """

    x_equation: sp.Expr
    y_equation: sp.Expr
    hill_coefficient: sp.Expr


def _scaled_accelerations(shape: str, n_value: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """Accelerations of x and y (k = 1) in the rescaled variables, with alpha = L + beta."""
    acc = equations_of_motion(1, shape)
    L = wall_distance
    # q = L qbar and t = L sqrt(mu/gamma) tbar, hence q'' = gamma/(mu L) qbar''.
    scale = {x: L * x, y: L * y, X: L * X}
    out = []
    for q in (x, y):
        a = substitute_ratios(acc[q], shape).subs(n, n_value)
        a = a.subs(alpha, L + beta).subs(scale, simultaneous=True)
        out.append(mu * L / gamma * a)
    return out[0], out[1]


def _linear_coefficient(ay: sp.Expr) -> sp.Expr:
    """q(x) in ydd = -q(x) y + O(y^2), checking that y = 0 is invariant (a normal mode)."""
    if sp.simplify(ay.subs(y, 0)) != 0:
        raise AssertionError("y = 0 is not an invariant line")
    ay = sp.powsimp(sp.expand_power_base(ay, force=True), force=True)
    slope = sp.powsimp(sp.expand(sp.diff(ay, y)), force=True)
    return sp.simplify(-slope.subs(y, 0))


def rescaled_equations(shape: str = "flat", n_value: int | None = None) -> RescaledSystem:
    """Paper eqs. (x-oscill) and (y-oscill), derived from the Lagrangian.

    Parameters
    ----------
    shape : a name in :data:`SHAPES` whose normal mode y = 0 exists
    n_value : None for general n >= 2 (where y^(2n) adds nothing linear), or a specific
        integer, e.g. 1, where the y-term of the well adds a linear restoring force.
    """
    if not isinstance(shape_definition(shape), Shape):
        why = "the paper's rescaling is for registered shapes only; a user's well has normal_mode"
        raise ParameterError("shape", "a user's well", f"one of {tuple(SHAPES)}", why=why)
    if n_value is not None and not _integer_in(n_value, MAX_N):
        raise ParameterError("n_value", n_value, f"None or an integer in [1, {MAX_N}]")
    return _rescaled_equations(shape, None if n_value is None else int(n_value))


@functools.cache
def _rescaled_equations(shape: str, n_value: int | None) -> RescaledSystem:
    """:func:`rescaled_equations` of checked arguments (cached)."""
    if n_value is None:
        m = sp.Symbol("m", integer=True, nonnegative=True)  # n = m + 2 >= 2
        nv = m + 2
    else:
        nv = sp.Integer(n_value)
    ax, ay = _scaled_accelerations(shape, nv)
    ax0 = sp.simplify(sp.powsimp(ax.subs(y, 0), force=True))
    q = _linear_coefficient(ay)
    back = {wall_distance: alpha - beta}
    if n_value is None:
        back[m] = n - 2
    x_eq = sp.expand(xdd - ax0).subs(back, simultaneous=True)
    q = sp.powsimp(sp.factor_terms(q.subs(back, simultaneous=True)), force=True)
    y_eq = ydd + q * y
    return RescaledSystem(sp.powsimp(x_eq, force=True), y_eq, q)


def oscillator_acceleration() -> sp.Expr:
    """xdd of the unloaded power-law oscillator: (x-oscill) with mu -> 0, i.e. -x^(2n-1)."""
    x_eq = rescaled_equations("flat").x_equation.subs(mu, 0)
    (acc,) = sp.solve(x_eq, xdd)
    return sp.powsimp(acc, force=True)


def hill_shape() -> sp.Expr:
    """x^(2n): Hill's coefficient over lambda for n >= 2, the pure equation's q(x) / Lam."""
    return sp.powsimp(
        sp.simplify(rescaled_equations("flat").hill_coefficient / lambda_coefficient()), force=True
    )


def lambda_coefficient() -> sp.Expr:
    """lambda = q(x) / x^(2n) for general n, i.e. -2 beta (alpha - beta).

    Derived from the flat well; the symmetric well gives the same value.
    """
    q = rescaled_equations("flat").hill_coefficient
    lam = sp.simplify(sp.powsimp(q / x ** (2 * n), force=True))
    return sp.factor(lam)


# --- rigid-wall limit ---------------------------------------------------------------------
def rigid_wall_contour() -> sp.Expr:
    """x_wall(y): the level line V = E of the flat well as n -> oo (for x > 0).

    On the level line x = D(y) (2nE/gamma)^(1/(2n)); the factor tends to 1.
    """
    factor = (2 * n * E / gamma) ** (1 / (2 * n))
    lim = sp.limit(factor, n, sp.oo)
    return denominator(y) * lim


def rigid_wall_curvature(shape: str = "flat") -> sp.Expr:
    """Curvature of the rigid wall x = x_wall(y) of ``shape``, paper eq. (kappa) for the
    flat well (positive: the wall bulges inward)."""
    xw = rigid_wall_contour() if shape == "flat" else shape_definition(shape).rigid_wall
    k = sp.diff(xw, y, 2) / (1 + sp.diff(xw, y) ** 2) ** sp.Rational(3, 2)
    L = wall_distance  # alpha = L + beta with L > 0 lets SymPy take the square roots
    k = sp.powsimp(sp.simplify(k.subs(alpha, L + beta)), force=True)
    return k.subs(L, alpha - beta)


# --- reach of a particle with energy E ----------------------------------------------
def axis_reach_factor() -> sp.Expr:
    """c = (2 n E / gamma)^(1/(2n)): V(0, y) = E at y = c for the flat well.

    A wall term of any shape, gamma/(2n) ratio^(2n), is <= E only where its ratio is
    <= c, so the shapes declare their basins in c (:data:`c`).
    """
    sol = sp.solve(sp.Eq(_ratio_sum().subs({s1: 0, s2: c}), E), c)
    return sp.simplify(sol[0])


def flat_level_half_width() -> sp.Expr:
    """x > 0 on the level line V = E of the flat well at height y, in the atom Dy.

    From s1^(2n) + y^(2n) = 2 n E / gamma: x = Dy (2 n E / gamma - y^(2n))^(1/(2n)).
    """
    t = sp.Symbol("t", positive=True)
    level = sp.Eq(_ratio_sum().subs({s1: t, s2: y}), E)
    sample = {E: sp.Rational(1, 2), n: 3, gamma: 1, y: sp.Rational(1, 2)}
    roots = [r for r in sp.solve(level, t) if sp.N(r.subs(sample)).is_positive]
    if len(roots) != 1:
        raise AssertionError(f"expected one positive root, got {roots}")
    return roots[0] * Dy


def symmetric_corner_saddle() -> tuple[sp.Expr, sp.Expr]:
    """(s*, V*) of the saddle on the diagonal x = y of the symmetric well (beta > 0).

    Beyond this pass the level set V <= E opens to infinity through the corners, so the
    well confines a particle only while its energy stays below V*.
    """
    s = sp.Symbol("s", positive=True)
    b = sp.Symbol("b", positive=True)  # beta > 0 here
    L = wall_distance  # alpha = beta + L with L > 0
    Vd = _ratio_sum().subs({s1: s / denominator(s), s2: s / denominator(s)})
    Vd = Vd.subs(beta, b).subs(alpha, L + b)
    crit = [r for r in sp.solve(sp.diff(Vd, s), s) if r.is_positive]
    if len(crit) != 1:
        raise AssertionError(f"expected one positive critical point, got {crit}")
    s_star = sp.simplify(crit[0])
    V_star = sp.simplify(Vd.subs(s, s_star))
    back = {b: beta, L: alpha - beta}
    return s_star.subs(back, simultaneous=True), V_star.subs(back, simultaneous=True)


def symmetric_corner_bound() -> sp.Expr:
    """Smallest s > 0 with s = c D(s): where the wall lines x = c D(y) and y = c D(x) meet.

    For beta > 0 the basin around the centre lies inside |x|, |y| <= this value.
    """
    s = sp.Symbol("s", positive=True)
    roots = sp.solve(sp.Eq(s, c * denominator(s)), s)
    if len(roots) != 2:
        raise AssertionError(f"expected two roots, got {roots}")
    sample = {alpha: 1, beta: sp.Rational(1, 10), c: 1}
    return min(roots, key=lambda r: float(r.subs(sample)))


# --- power-law oscillator ---------------------------------------------------------------
def period_integral() -> sp.Integral:
    """T_n = 4 sqrt(n) / A0^(n-1) * Integral(1/sqrt(1 - z^(2n)), (z, 0, 1)).

    From E_n = x'^2/2 + x^(2n)/(2n) = A0^(2n)/(2n): T = 4 int_0^A0 dx / sqrt(2(E_n - V)),
    then x = A0 z.
    """
    z = sp.Symbol("z", positive=True)
    xx = sp.Symbol("xx", positive=True)
    En = A0 ** (2 * n) / (2 * n)
    integrand = 1 / sp.sqrt(2 * (En - xx ** (2 * n) / (2 * n)))
    scaled = sp.powsimp(sp.simplify(integrand.subs(xx, A0 * z) * A0), force=True)
    return 4 * sp.Integral(scaled, (z, 0, 1))


def period_closed_form() -> sp.Expr:
    """Closed Gamma-function form of the period, paper eq. (T), evaluated from the integral."""
    z = sp.Symbol("z", positive=True)
    I = sp.integrate(1 / sp.sqrt(1 - z ** (2 * n)), (z, 0, 1), meijerg=True, conds="none")
    inner = sp.gammasimp(sp.hyperexpand(I))
    (integral,) = period_integral().atoms(sp.Integral)
    integrand = integral.function
    prefactor = sp.simplify(integrand * sp.sqrt(1 - z ** (2 * n)))
    if prefactor.has(z):
        raise AssertionError("period integrand is not prefactor / sqrt(1 - z^(2n))")
    return sp.simplify(4 * prefactor * inner)  # period_integral() = 4 * prefactor * I


def oscillator_energy() -> sp.Expr:
    """E_n = x'^2/2 + x^(2n)/(2n): the conserved energy of x'' + x^(2n-1) = 0.

    Derived as the first integral: multiply the equation by x' and integrate.
    """
    t = sp.Symbol("t", real=True)
    xf = sp.Function("x")(t)
    xd = sp.Symbol("xd", real=True)
    first_integral = sp.integrate(sp.diff(xf, t, 2) * sp.diff(xf, t), t) + sp.integrate(
        xf ** (2 * n - 1) * sp.diff(xf, t), t
    )
    return sp.powsimp(first_integral.subs(sp.diff(xf, t), xd).subs(xf, x), force=True)


def energy_of_amplitude() -> sp.Expr:
    """E_n at a turning point x = A0, x' = 0: A0^(2n) / (2n)."""
    xd = sp.Symbol("xd", real=True)
    return oscillator_energy().subs({xd: 0, x: A0})


def amplitude_of_energy() -> sp.Expr:
    """A0 = (2 n E)^(1/(2n)): the inverse of :func:`energy_of_amplitude`."""
    a = sp.Symbol("a", positive=True)
    return sp.solve(sp.Eq(energy_of_amplitude().subs(A0, a), E), a)[0]
