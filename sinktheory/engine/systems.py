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
>>> s = sink_system("flat", n=4)
>>> [str(c) for c in s.shared], [str(c) for c in s.member], [str(p) for p in s.params]
(['X'], ['u', 'y'], ['alpha', 'beta', 'gamma', 'mu'])
>>> len(henon_heiles().shared), henon_heiles().member
(2, ())
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from .. import symbolic as S

__all__ = ["Damping", "henon_heiles", "SeparableSystem", "sink_system", "Term", "two_dof_duffing"]


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
    def plain(cls, local, maps, value) -> Term:
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


def _well_term(shape: str, n: int) -> Term:
    """V(x, y) of one particle, x = u - X, in the shape's atoms, exponent fixed to n.

    Every atom that appears with a negative power (a denominator such as D(y)) gets one
    reciprocal atom iD = 1/D and every D^-k becomes iD^k, so a kernel divides once per
    denominator.
    """
    u = sp.Symbol("u", real=True)
    definition = S.shape_definition(shape)
    outputs = (
        definition.potential,
        *S.gradient_in_ratios(shape),
        *S.hessian_in_ratios(shape),
    )
    outputs = [e.subs(S.n, n) for e in outputs]  # terms with a factor n - 1 cancel here
    names = dict(definition.atoms)
    recip = {
        p.base: sp.Symbol(f"i{p.base.name}", real=True)
        for e in outputs
        for p in e.atoms(sp.Pow)
        if p.base in names and p.exp.is_negative
    }

    def fix(e):
        e = e.subs(S.n, n)
        return e.replace(
            lambda t: t.is_Pow and t.base in recip and t.exp.is_negative,
            lambda t: recip[t.base] ** (-t.exp),
        )

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


def sink_system(shape: str, n: int) -> SeparableSystem:
    """The container (mass 1, spring 1) with particles in the ``shape`` well, exponent 2n.

    ``shape`` is any name of the registry :data:`sinktheory.symbolic.SHAPES`: the well
    term is built from that shape's definition (atoms, potential and its derivatives).

    Coordinates are those of :func:`sinktheory.symbolic.separable_hamiltonian`; the masses
    are read from it, and the potential is checked there to be X^2/2 + sum V(u_j - X, y_j).
    Runtime parameters: alpha, beta, gamma, mu.
    """
    sh = S.separable_hamiltonian(1, shape)
    u = sp.Symbol("u", real=True)
    X = S.X
    expected = X**2 / 2 + S.potential(shape, u - X, S.y)
    probe = {X: sp.Rational(1, 3), u: sp.Rational(1, 2), S.y: sp.Rational(-1, 5)}
    probe |= {S.alpha: sp.Rational(1, 2), S.beta: sp.Rational(3, 10), S.gamma: 2, S.n: n}
    got = sh.potential.subs({sh.coordinates[1]: u})
    if sp.nsimplify((got - expected).subs(probe)) != 0:
        raise AssertionError("separable potential is not X^2/2 + sum V(u - X, y)")
    return SeparableSystem(
        name=f"sink_{shape}_n{n}",
        shared=(X,),
        shared_masses=(sh.masses[0],),
        member=(u, S.y),
        member_masses=(sh.masses[1], sh.masses[2]),
        params=(S.alpha, S.beta, S.gamma, S.mu),
        shared_terms=(Term.plain((X,), (X,), X**2 / 2),),
        member_terms=(_well_term(shape, n),),
        # the wall term 2 n V / gamma: about 1 at the wall, (1/2)^(2n) half-way to it
        damping=Damping(pairs=((u, X), (S.y, None)), weight=2 * sp.Integer(n) / S.gamma),
    )


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
        shared_terms=(Term.plain((x, y), (x, y), U),),
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
        shared_terms=(Term.plain((x1, x2), (x1, x2), U),),
    )
