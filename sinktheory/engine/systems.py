"""Separable Hamiltonian systems the engine compiles, defined symbolically (build time).

A system is H = sum_i p_i^2 / (2 m_i) + U(q) with the potential written as a sum of
*terms*.  Each term is a function W(l) of a few local coordinates l that are linear in the
system's coordinates; the term supplies its value, gradient and Hessian in l (possibly
through intermediate atoms, such as the wall ratios of the soft-wall well, that keep the
numbers of order one for large exponents).  Coordinates are either *shared* (the
container) or belong to one of K identical *members* (the particles); a member term is
written once for a template member and repeated over the members by a loop whose length
the compiled code reads from the state (so one module serves any number of members).

Everything here needs SymPy and runs only when a kernel module is generated
(:mod:`sinktheory.engine.printer`); nothing at run time imports it.

Examples
--------
>>> s = sink_system("flat")
>>> [str(c) for c in s.shared], [str(c) for c in s.member], [str(p) for p in s.params]
(['X'], ['u', 'y'], ['alpha', 'beta', 'gamma', 'n', 'mu'])
>>> len(henon_heiles().shared), henon_heiles().member
(2, ())
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from .. import symbolic as S

__all__ = [
    "Damping",
    "henon_heiles",
    "SeparableSystem",
    "Term",
    "two_dof_duffing",
]


@dataclass(frozen=True)
class Term:
    """One potential term W(l) in local coordinates l = maps(q) (linear in q).

    Attributes
    ----------
    local : local coordinate symbols l_1..l_L
    maps : each l_i as a linear expression in the system (or template member) coordinates
    atoms : intermediate symbols and their definitions (in l and earlier atoms), in order
    value : W in l and the atoms
    gradient : dW/dl_i in l and the atoms
    hessian : d^2 W / dl_i dl_j for i <= j (row-major upper triangle)
    """

    local: tuple[sp.Symbol, ...]
    maps: tuple[sp.Expr, ...]
    atoms: tuple[tuple[sp.Symbol, sp.Expr], ...]
    value: sp.Expr
    gradient: tuple[sp.Expr, ...]
    hessian: tuple[sp.Expr, ...]

    @classmethod
    def _plain(cls, local, maps, value) -> Term:
        """A term whose derivatives SymPy takes directly (no atoms)."""
        local = tuple(local)
        grad = tuple(sp.diff(value, v) for v in local)
        hess = tuple(
            sp.diff(value, local[i], local[j])
            for i in range(len(local))
            for j in range(i, len(local))
        )
        return cls(local, tuple(maps), (), value, grad, hess)


@dataclass(frozen=True)
class Damping:
    """Linear damping of the members' velocities, which the engine may switch on.

    Each member coordinate in ``pairs`` is damped either relative to a shared coordinate
    (a dashpot between the member and, say, the container: the pair's momentum is kept) or
    on its own (``None``: the coordinate's partner does not move along it).  The force on
    member j's coordinate is -c_j (its velocity minus its partner's), with

        c_j = c0 * weight * (the member's potential terms at its position)   (contact)
        c_j = c0                                                             (viscous)

    so a contact weight vanishes where the member is far from the walls.  With the
    positions frozen this field is linear in the velocities and exactly solvable pair by
    pair, which is how the engine integrates it (:mod:`sinktheory.engine._stepper`).
    """

    pairs: tuple[tuple[sp.Symbol, sp.Symbol | None], ...]
    weight: sp.Expr


@dataclass(frozen=True)
class SeparableSystem:
    """H = kinetic + sum of terms, with shared and member coordinates (see module doc).

    The state layout of a system with S shared and C member coordinates and K members is
    [shared q, shared v, member q, member v] where member coordinate c of member j sits at
    index S + c K + j of q (so all u_j, then all y_j, for the sink).  K is not part of the
    system: the compiled code reads it from the number of coordinates.
    """

    name: str
    shared: tuple[sp.Symbol, ...]
    shared_masses: tuple[sp.Expr, ...]
    member: tuple[sp.Symbol, ...] = ()
    member_masses: tuple[sp.Expr, ...] = ()
    params: tuple[sp.Symbol, ...] = ()
    shared_terms: tuple[Term, ...] = ()
    member_terms: tuple[Term, ...] = field(default=())
    damping: Damping | None = None


def _well_term(well) -> Term:
    """V(x, y) of one particle, x = u - X, in the atoms of ``well`` (:func:`sinktheory.
    symbolic.kernel_form`: a registered shape's own, a user's well's lifted powers).

    The exponents stay symbolic (n is a run-time parameter; the printer raises each base
    to its run-time power once).  Every atom that appears with a fixed negative power (a
    denominator such as D(y)) gets one reciprocal atom iD = 1/D and every D^-k becomes
    iD^k, so a kernel divides once per denominator.
    """
    u = sp.Symbol("u", real=True)
    definition = S.kernel_form(well)
    outputs = (
        S.potential_of_ratios(definition),
        *S.gradient_in_ratios(definition),
        *S.hessian_in_ratios(definition),
    )
    names = dict(definition.atoms)

    def fixed_negative(p) -> bool:
        return p.is_Pow and p.base in names and p.exp.is_number and p.exp.is_negative

    recip = {
        p.base: sp.Symbol(f"i{p.base.name}", real=True)
        for e in outputs
        for p in e.atoms(sp.Pow)
        if fixed_negative(p)
    }

    def fix(e):
        return e.replace(fixed_negative, lambda t: recip[t.base] ** (-t.exp))

    atoms = []
    for a, e in definition.atoms:
        atoms.append((a, fix(e)))
        if a in recip:
            atoms.append((recip[a], 1 / a))
    value, *derivatives = (fix(e) for e in outputs)
    return Term(
        local=(S.x, S.y),
        maps=(u - S.X, S.y),
        atoms=tuple(atoms),
        value=value,
        gradient=tuple(derivatives[:2]),
        hessian=tuple(derivatives[2:]),
    )


def sink_system(well, name: str | None = None) -> SeparableSystem:
    """The container (mass 1, spring 1) with particles in ``well``: a name of the registry
    :data:`sinktheory.symbolic.SHAPES` or a user's well (a
    :class:`~sinktheory.symbolic.WellDefinition`); the well term is built from its
    definition (atoms, potential and its derivatives), the same way for both.

    Coordinates are those of :func:`sinktheory.symbolic.separable_hamiltonian`; the masses
    are read from it, and the potential is checked there to be X^2/2 + sum V(u_j - X, y_j).
    Run-time parameters: the well's (alpha, beta, gamma, n for a registered shape, the
    exponent n included), then the particle mass mu.  The well term is V - V(0, 0), so the
    engine's energies count from the well's centre as everything else does (a registered
    shape's V(0, 0) is 0).  ``name`` defaults to sink_<shape>.
    """
    definition = S.shape_definition(well)
    sh = S.separable_hamiltonian(1, well)
    u = sp.Symbol("u", real=True)
    X = S.X
    params = tuple(definition.parameter_symbols)
    whole = run_time_symbols(definition)
    expected = X**2 / 2 + S.potential(well, u - X, S.y)
    probe = {X: sp.Rational(1, 3), u: sp.Rational(1, 2), S.y: sp.Rational(-1, 5)}
    probe |= {p: sp.Integer(2 + i) for i, p in enumerate(params)}  # whole: n is an exponent
    got = sh.potential.subs({sh.coordinates[1]: u})
    if sp.nsimplify((got - expected).subs(probe)) != 0:
        raise AssertionError("separable potential is not X^2/2 + sum V(u - X, y)")
    term = _well_term(well)
    # energies count from the well's centre, as the basin, the law and the audit take them
    # (a user's V(0, 0) may be any number; a registered shape's is 0 and stays unprinted)
    centre = S.potential(well).subs({S.x: 0, S.y: 0})
    value = sp.sympify(term.value) - centre
    term = Term(term.local, term.maps, tuple((a, e.subs(whole)) for a, e in term.atoms),
                value.subs(whole), tuple(e.subs(whole) for e in term.gradient),
                tuple(e.subs(whole) for e in term.hessian))  # fmt: skip
    return SeparableSystem(
        name=name or f"sink_{definition.name}",
        shared=(X,),
        shared_masses=(sh.masses[0],),
        member=(u, S.y),
        member_masses=(sh.masses[1], sh.masses[2]),
        params=(*(p.subs(whole) for p in params), S.mu),
        shared_terms=(Term._plain((X,), (X,), X**2 / 2),),
        member_terms=(term,),
        # contact weight V / (its level at the wall): about 1 at the wall, (1/2)^(2n)
        # half-way to it for the paper's wells (2 n V / gamma)
        damping=Damping(pairs=((u, X), (S.y, None)), weight=_contact_weight(definition)),
    )


def run_time_symbols(definition) -> dict[sp.Symbol, sp.Symbol]:
    """The parameters of a user's well mapped to the symbols its engine takes them as:
    ``par_<name>`` (a kernel's own names, such as the loop variable b, stay free), an
    integer (non-negative or positive when the declared range says so) for each that sits
    in an exponent with a whole default value, so that its powers become run-time powers
    whose values must then be whole (checked when a parameter table is made).  Empty for
    a registered shape (its n is an integer symbol already)."""
    ranges = {p.symbol: (p.default, *p.range) for p in getattr(definition, "parameters", ())}
    out = {s: sp.Symbol(f"par_{s.name}", real=True) for s in ranges}  # no clash with kernels
    for power in definition.potential.atoms(sp.Pow):
        for symbol in power.exp.free_symbols & set(ranges):
            default, lo, _ = ranges[symbol]
            if float(default).is_integer():
                out[symbol] = sp.Symbol(
                    f"par_{symbol.name}", integer=True, nonnegative=lo >= 0 or None,
                    positive=lo > 0 or None,
                )  # fmt: skip
    return out


def _contact_weight(definition) -> sp.Expr:
    """The damping's contact weight per unit of the well term: 2n/gamma for the paper's
    wells (V = gamma/(2n) at the wall); for a user's well, 1 (the weight is V itself)."""
    if {S.gamma, S.n} <= set(definition.parameter_symbols):
        return 2 * S.n / S.gamma
    return sp.Integer(1)


def henon_heiles() -> SeparableSystem:
    """Henon & Heiles (1964): U = (x^2 + y^2)/2 + x^2 y - y^3/3, unit masses.

    A canonical reference for chaos indicators (Skokos et al., GALI, Physica D 2007).
    """
    x, y = sp.symbols("x y", real=True)
    U = (x**2 + y**2) / 2 + x**2 * y - y**3 / 3
    return SeparableSystem(
        name="henon_heiles",
        shared=(x, y),
        shared_masses=(sp.Integer(1), sp.Integer(1)),
        shared_terms=(Term._plain((x, y), (x, y), U),),
    )


def two_dof_duffing() -> SeparableSystem:
    """Kerschen et al. (MSSP 2009) benchmark: two unit masses, three unit springs, a cubic
    spring of stiffness 0.5 on the first mass; linear frequencies 1 and sqrt(3)."""
    x1, x2 = sp.symbols("x1 x2", real=True)
    U = x1**2 / 2 + (x2 - x1) ** 2 / 2 + x2**2 / 2 + sp.Rational(1, 2) * x1**4 / 4
    return SeparableSystem(
        name="duffing2",
        shared=(x1, x2),
        shared_masses=(sp.Integer(1), sp.Integer(1)),
        shared_terms=(Term._plain((x1, x2), (x1, x2), U),),
    )
