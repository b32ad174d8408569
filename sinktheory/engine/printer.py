"""Print the compiled engine of one :class:`~sinktheory.engine.systems.SeparableSystem`.

The module it writes has four system kernels, each working on a block of B runs laid out
structure-of-arrays (q[i, b]: coordinate i of run b, runs contiguous), so the loops over
runs vectorise:

``accelerations(q, a, P)``
    a = -M^-1 grad U(q).
``hessian(q, h, P)``
    the local Hessian entries of every term (what the tangent map needs).
``tangent_kick(h, dq, dv, c, P)``
    dv += -c M^-1 Hess U(q) dq for every deviation vector: the exact derivative of the kick
    v += c a(q), so the tangent map of a splitting step is the step's Jacobian and is
    symplectic.
``energies(q, v, P, total, shared, members)``
    H per run, the shared part (container) and each member's part (particle).

The first three have a twin for a block of a single run (``accelerations_one(q, a, P, pull)``,
``hessian_one``, ``tangent_kick_one(h, dq, dv, c, P, pull)``) that loops over the members
innermost, so it vectorises across them; the members' pull on a shared coordinate goes to
the work rows ``pull`` and is summed after that loop in the order of the block kernel's
sums, so the numbers are bitwise the same.

followed by the system-independent stepper of :mod:`sinktheory.engine._stepper`.  The
printer is the project's one kernel printer (:class:`sinktheory.codegen.KernelPrinter`):
integer powers are products by repeated squaring with the exponent fixed in the text, so
the compiler sees straight-line code; divisions by the same denominator become one
reciprocal (SymPy's CSE of x/D and x D^-k).  Build time only: needs SymPy.
"""

from __future__ import annotations

import re
from pathlib import Path

import sympy as sp

from ..codegen import KernelPrinter, integer_powers, ipow
from .systems import SeparableSystem, Term

__all__ = ["POWER_CLASSES", "RESERVED", "STEPPER"]

STEPPER = Path(__file__).with_name("_stepper.py")

#: Bit counts of run-time exponents the kernels are printed for.  A kernel with run-time
#: powers has one body per class, for blocks whose runs share their exponents (the common
#: case), which raise to a scalar exponent, plus one body for blocks that mix exponents,
#: which raises each run to its own (per-lane selects, about 10 % slower at n = 4).  A block
#: takes the first class that holds its exponents, so a new exponent never compiles
#: anything.  For the paper's wells the exponents are 2n - 2 .. 2n: the classes hold
#: n <= 3, 15, 127 and 1023 (the last: every n the model allows).
POWER_CLASSES = (3, 5, 8, 11)


class upow__(sp.Function):  # noqa: N801 - printed as the helper of that name
    """A run-time power b^e whose exponent is never negative (``ipow`` sorted before CSE,
    which would hide the exponent's sign in a temporary)."""


class spow__(sp.Function):  # noqa: N801 - printed as the helper of that name
    """A run-time power b^e whose exponent may be negative."""


def _signed(expr: sp.Expr) -> sp.Expr:
    """Each ``ipow`` of ``expr`` as :class:`upow__` or :class:`spow__`, its exponent
    replaced by the symbol ``e<i>_`` of its row in the table (:data:`_EXPONENTS`)."""

    def power(f):
        helper = upow__ if f.args[1].is_nonnegative is True else spow__
        _EXPONENTS.setdefault(f.args[1], None)
        _PENDING.setdefault(f.args[1], None)
        return helper(f.args[0], sp.Symbol(f"e{list(_EXPONENTS).index(f.args[1])}_"))

    return expr.replace(lambda f: isinstance(f, ipow), power)


class _EnginePrinter(KernelPrinter):
    """The kernel printer with run-time powers printed as calls of the branch-free
    square-and-multiply helpers (:func:`_power_helpers`): ``upow__`` when the exponent
    is never negative, ``spow__`` when it may be; ``__`` becomes the bit class of the
    body (:func:`_dispatch`)."""

    def _power(self, name: str, expr) -> str:
        return f"{name}({self._print(expr.args[0])}, {self._print(expr.args[1])})"

    def _print_upow__(self, expr):  # noqa: D102 - printer protocol
        return self._power("upow__", expr)

    def _print_spow__(self, expr):  # noqa: D102 - printer protocol
        return self._power("spow__", expr)


_printer = _EnginePrinter({"fully_qualified_modules": True, "standard": "python3"})

#: The run-time exponents :func:`cse_lines` has met since :func:`render` started the
#: current system (exponent i is row POWERS + i of the table and ``e<i>_`` in a kernel),
#: and those met since the last kernel was written (the ones its dispatch looks at).
_EXPONENTS: dict[sp.Expr, None] = {}
_PENDING: dict[sp.Expr, None] = {}


def _p(e) -> str:
    return _printer.doprint(sp.sympify(e))


def cse_lines(outputs: list[sp.Expr], prefix: str) -> tuple[list[str], list[str]]:
    """(assignment lines of the common subexpressions, the outputs' texts) of ``outputs``
    in the kernel printer: straight-line code for any compiled kernel.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> cse_lines([(x + y) ** 3, 1 / (x + y)], "t")
    (['t0 = x + y'], ['((t0*t0)*t0)', '(1.0/t0)'])
    """
    outputs = [_signed(e) for e in integer_powers([sp.sympify(e) for e in outputs])]
    reps, reduced = sp.cse(outputs, symbols=sp.numbered_symbols(prefix), optimizations="basic")
    return [f"{s.name} = {_p(e)}" for s, e in reps], [_p(e) for e in reduced]


def _power_helpers() -> str:
    """``upow<k>(b, e)``: b^e for a whole e in [0, 2^k) by square-and-multiply with
    selects, k bits always (no branch, so the loop over runs that calls it vectorises;
    with a scalar e the selects are the same for every run); ``spow<k>``: the same for
    |e|, inverted when e < 0."""
    out = ""
    for bits in POWER_CLASSES:
        body = ["k = int(e)", "r = b if k & 1 else 1.0", "p = b"]
        for i in range(1, bits):
            body += ["p = p * p", f"r = r * p if k & {1 << i} else r"]
        out += _function(
            f"upow{bits}", "b, e", f"b^e for a whole e in [0, {1 << bits}).", body + ["return r"]
        )
        out += _function(
            f"spow{bits}",
            "b, e",
            f"b^e for a whole |e| < {1 << bits}.",
            [f"r = upow{bits}(b, abs(e))", "return 1.0 / r if e < 0 else r"],
        )
    return out


def _dispatch(body: list[str], powers: str = "block") -> list[str]:
    """``body`` as the kernel's text when it raises no run-time power; else, for
    ``powers`` = "block", the branch of :data:`POWER_CLASSES`: the exponents (those
    :func:`cse_lines` met since the last kernel) are scanned over the block's runs, and a
    block whose runs share them takes the body of the smallest class that holds them, with
    scalar exponents ``e<i>_``; a block that mixes them takes the last class, each run
    loading its own.  "one" (a kernel of a single run): the classes only.  "lanes" (a
    kernel called once a segment, where compile time counts more than speed): the last
    class only, each run loading its own exponents."""
    rows = [list(_EXPONENTS).index(e) for e in _PENDING]
    _PENDING.clear()
    if not any("pow__(" in line for line in body):
        return body
    last = POWER_CLASSES[-1]
    if powers == "lanes":
        return [line.replace("pow__(", f"pow{last}(") for line in body]
    out = [f"e{i}_ = P[POWERS + {i}, 0]" for i in rows]
    if powers == "block":
        out += ["mixed_ = False", "for b in range(P.shape[1]):"]
        out += [f"    mixed_ = mixed_ or P[POWERS + {i}, b] != e{i}_" for i in rows]
    out += ["top_ = max(" + ", ".join(f"abs(e{i}_)" for i in rows) + ", 0.0)"]
    scalar = [line for line in body if not re.match(r"\s*e\d+_ = P\[", line)]
    classes = POWER_CLASSES if powers == "block" else POWER_CLASSES[:-1]
    for k, bits in enumerate(classes):
        test = f"not mixed_ and top_ < {1 << bits}" if powers == "block" else f"top_ < {1 << bits}"
        out.append(f"{'if' if k == 0 else 'elif'} {test}:")
        out += ["    " + line.replace("pow__(", f"pow{bits}(") for line in scalar]
    out.append("else:")
    last_body = body if powers == "block" else scalar
    return out + ["    " + line.replace("pow__(", f"pow{last}(") for line in last_body]


def _local_lines(term: Term) -> list[str]:
    """Local coordinates from the (already loaded) system coordinates, then the atoms."""
    lines = [f"{l.name} = {_p(m)}" for l, m in zip(term.local, term.maps, strict=True) if l != m]
    return lines + [f"{a.name} = {_p(e)}" for a, e in term.atoms]


def _index(system: SeparableSystem, coord: sp.Symbol) -> str:
    """Row of ``coord`` in q: a number for shared coordinates, an expression in j else."""
    if coord in system.shared:
        return str(system.shared.index(coord))
    c = system.member.index(coord)
    return f"{len(system.shared)} + {c} * K + j"


def _coords_of(system: SeparableSystem, member: bool) -> tuple[sp.Symbol, ...]:
    return system.shared + (system.member if member else ())


def _load(system: SeparableSystem, member: bool, array: str = "q", run: str = "b") -> list[str]:
    return [f"{c.name} = {array}[{_index(system, c)}, {run}]" for c in _coords_of(system, member)]


def _jacobian(term: Term, coords) -> list[list[sp.Expr]]:
    """dl_i / dq_c (constants: the maps are linear)."""
    jac = [[sp.diff(m, c) for c in coords] for m in term.maps]
    if any(not e.is_number for row in jac for e in row):
        raise ValueError("a term's local coordinates must be linear in the coordinates")
    return jac


def _masses(system: SeparableSystem) -> dict[sp.Symbol, sp.Expr]:
    masses = dict(zip(system.shared, system.shared_masses, strict=True))
    return masses | dict(zip(system.member, system.member_masses, strict=True))


def _inverse_masses(system: SeparableSystem) -> tuple[dict[sp.Symbol, sp.Symbol], list[str]]:
    """Symbols im_<coordinate> for 1/m: constant masses get a line computed once per call;
    masses that depend on the parameters are rows of the parameter table (see
    :func:`_table_rows`) and are loaded per run inside the loops."""
    masses = _masses(system)
    names = {c: sp.Symbol(f"im_{c.name}") for c in masses}
    return names, [f"{names[c].name} = {_p(1 / m)}" for c, m in masses.items() if m.is_number]


def _damping_shares(system: SeparableSystem) -> dict[str, sp.Expr]:
    """The mass ratios of the damping's pair flows, by the name a kernel loads them under:
    for a member coordinate c damped against p, the shares m_p/(m_c + m_p) and
    m_c/(m_c + m_p) of a change of their relative velocity and the reduced mass; for one
    damped on its own, its mass."""
    if system.damping is None:
        return {}
    masses, out = _masses(system), {}
    for c, partner in system.damping.pairs:
        if partner is None:
            out[f"dmass_{c.name}"] = masses[c]
            continue
        total = masses[c] + masses[partner]
        out[f"dshare_{c.name}"] = sp.simplify(masses[partner] / total)
        out[f"dshare_{partner.name}_{c.name}"] = sp.simplify(masses[c] / total)
        out[f"dreduced_{c.name}"] = sp.simplify(masses[c] * masses[partner] / total)
    return out


def _table_rows(system: SeparableSystem) -> list[tuple[str, sp.Expr]]:
    """Rows of the per-run parameter table: each parameter, then each distinct inverse mass
    that depends on the parameters (1/mu for the sink), so a kernel divides by a mass once
    per run rather than once per particle and step, then the damping's mass ratios that
    depend on the parameters (:func:`_damping_shares`)."""
    rows = [(p.name, p) for p in system.params]
    for m in dict.fromkeys(m for m in _masses(system).values() if not m.is_number):
        rows.append((f"inverse mass {m}", 1 / m))
    rows += [(name, e) for name, e in _damping_shares(system).items() if not e.is_number]
    return rows


def _params(system: SeparableSystem) -> list[str]:
    """Per-run loads of the table rows, each parameter, im_<coordinate> and the damping's
    ratios (put inside a ``for b`` loop by :func:`_loop`, which keeps the ones its body
    uses)."""
    rows = _table_rows(system)
    index = {e: i for i, (_, e) in enumerate(rows)}
    where = {name: i for i, (name, _) in enumerate(rows)}
    lines = [f"{p.name} = P[{i}, b]" for i, p in enumerate(system.params)]
    lines += [f"e{i}_ = P[POWERS + {i}, b]" for i in range(len(_EXPONENTS))]
    lines += [
        f"im_{c.name} = P[{index[1 / m]}, b]" for c, m in _masses(system).items() if not m.is_number
    ]
    return lines + [
        f"{name} = {_p(e) if e.is_number else f'P[{where[name]}, b]'}"
        for name, e in _damping_shares(system).items()
    ]


def _used(loads: list[str], text: str) -> list[str]:
    """The lines ``name = ...`` of ``loads`` whose name occurs in ``text``."""
    return [s for s in loads if re.search(rf"\b{s.split(' = ')[0]}\b", text)]


def _one_params(system: SeparableSystem) -> list[str]:
    """The loads of :func:`_params` for a single run (column 0), put once at the top of a
    one-run kernel."""
    return [s.replace(", b]", ", 0]") for s in _params(system)]


def _members(body: list[str], member: bool) -> list[str]:
    """``for j`` over the members around ``body`` (a member term of a one-run kernel)."""
    return ["for j in range(K):", *("    " + s for s in body)] if member else body


def _loop(body: list[str], member: bool, runs_var: str = "B", params=()) -> list[str]:
    """``for b`` (and ``for j`` over members) around ``body``, with the run's parameter
    loads ``params`` first."""
    params = _used(params, "\n".join(body))
    inner = [f"for b in range({runs_var}):", *("    " + s for s in [*params, *body])]
    if member:
        return ["for j in range(K):", *("    " + s for s in inner)]
    return inner


def _terms(system: SeparableSystem):
    yield from ((t, False) for t in system.shared_terms)
    yield from ((t, True) for t in system.member_terms)


def _function(name: str, args: str, doc: str, body: list[str], powers: str = "block") -> str:
    """The text of a compiled kernel; ``powers``: how it raises run-time powers
    (:func:`_dispatch`)."""
    deco = '@numba.njit(cache=True, error_model="numpy")'
    text = "\n".join("    " + s for s in [f'"""{doc}"""', *_dispatch(body, powers)])
    return f"\n\n{deco}\ndef {name}({args}):\n{text}\n"


def _forces(system: SeparableSystem, term: Term, member: bool, im):
    """(coordinates, CSE lines, accelerations) of one term: -M^-1 grad W per coordinate."""
    coords = _coords_of(system, member)
    jac = _jacobian(term, coords)
    outs = []
    for c_i, c in enumerate(coords):
        force = -sum(jac[l_i][c_i] * term.gradient[l_i] for l_i in range(len(term.local)))
        outs.append(im[c] * force)
    assign, values = cse_lines(outs, "t")
    return coords, assign, values


def _accelerations(system: SeparableSystem, im, one: bool = False) -> list[str]:
    """Body of ``accelerations`` (or, ``one``, of ``accelerations_one``: a single run,
    members in the innermost loop so that it vectorises across them).

    A coordinate's first contribution is written as 0.0 + value, the bits of adding it to
    a zero (signed zeros included) without zeroing the array first: LLVM turned that loop
    into a call to memset at every evaluation (8-10 % of a block's time, half a single
    run's).  Only coordinates that no term acts on, and shared ones first reached inside a
    loop over members, are zeroed.  In the one-run kernel a shared coordinate sums in a
    local from 0.0, and each member's pull on it goes to the work row pull[i, :] inside
    the member loop and is added after it, member by member: the block kernel's order, so
    both kernels give the same bits."""
    run = "0" if one else "b"
    forces = [(term, member, *_forces(system, term, member, im)) for term, member in _terms(system)]
    first = {}  # coordinate -> its first contribution comes from a member term
    for _, member, coords, _, values in forces:
        for c, val in zip(coords, values, strict=True):
            if val != "0":
                first.setdefault(c, member)
    acc = {c: f"acc_{c.name}" for c in system.shared} if one else {}
    zero = [c for c in system.shared if not one and first.get(c, True)]
    zero += [c for c in system.member if c not in first]
    body = ["D = q.shape[0]", "K = members_of(D)"] + ([] if one else ["B = q.shape[1]"])
    body += [f"{a} = 0.0" for a in acc.values()]
    for c in zero:
        line = f"a[{_index(system, c)}, {run}] = 0.0"
        body += _members([line], c in system.member) if one else _loop([line], c in system.member)
    written = set(zero)
    for term, member, coords, assign, values in forces:
        inner = _load(system, member, run=run) + _local_lines(term) + assign
        sums = []
        for c, val in zip(coords, values, strict=True):
            if val == "0":
                continue
            if c in acc and member:
                i = system.shared.index(c)
                inner.append(f"pull[{i}, j] = {val}")
                sums += ["for j in range(K):", f"    {acc[c]} += pull[{i}, j]"]
            elif c in acc:
                inner.append(f"{acc[c]} += {val}")
            else:
                op = "+=" if c in written else "= 0.0 +"
                inner.append(f"a[{_index(system, c)}, {run}] {op} {val}")
                written.add(c)
        if one:
            body += _members(inner, member) + sums
        else:
            body += _loop(inner, member, params=_params(system))
    body += [f"a[{system.shared.index(c)}, 0] = {a}" for c, a in acc.items()]
    return _used(_one_params(system), "\n".join(body)) + body if one else body


def _hessian_rows(system: SeparableSystem):
    """(term, member, first row in h) for every term, rows per shared part, rows per member.

    Member term entries sit at first + e K + j (first counted in units of K rows)."""
    row, rows = 0, []
    for term in system.shared_terms:
        rows.append((term, False, row))
        row += len(term.hessian)
    shared_rows, per_member = row, 0
    for term in system.member_terms:
        rows.append((term, True, per_member))
        per_member += len(term.hessian)
    return rows, shared_rows, per_member


def _h_index(system, member, first, e) -> str:
    if member:
        return f"SHARED_HESSIAN + {first + e} * K + j"
    return str(first + e)


def _hessian(system: SeparableSystem, one: bool = False) -> list[str]:
    """Body of ``hessian`` (or, ``one``, of ``hessian_one``: a single run, members in the
    innermost loop)."""
    run = "0" if one else "b"
    body = (
        ["K = members_of(q.shape[0])"] if one else ["B = q.shape[1]", "K = members_of(q.shape[0])"]
    )
    for term, member, first in _hessian_rows(system)[0]:
        assign, values = cse_lines(list(term.hessian), "t")
        inner = _load(system, member, run=run) + _local_lines(term) + assign
        inner += [
            f"h[{_h_index(system, member, first, e)}, {run}] = {val}"
            for e, val in enumerate(values)
        ]
        body += _members(inner, member) if one else _loop(inner, member, params=_params(system))
    return _used(_one_params(system), "\n".join(body)) + body if one else body


def _tangent_kick(system: SeparableSystem, im, one: bool = False) -> list[str]:
    """Body of ``tangent_kick`` (or, ``one``, of ``tangent_kick_one``: a single run, members
    in the innermost loop, their pull on the shared coordinates stored in ``pull`` and summed
    after that loop in the order of the block kernel's sums)."""
    run = "0" if one else "b"
    body = ["M = dq.shape[1]", "K = members_of(dq.shape[0])"]
    body += [] if one else ["B = dq.shape[2]"]
    body += ["for m in range(M):"]
    for term, member, first in _hessian_rows(system)[0]:
        coords = _coords_of(system, member)
        jac = _jacobian(term, coords)
        L = len(term.local)
        hsym = {}
        e = 0
        for i in range(L):
            for k in range(i, L):
                hsym[(i, k)] = hsym[(k, i)] = sp.Symbol(f"h{e}")
                e += 1
        d = [sp.Symbol(f"d_{c.name}") for c in coords]
        dl = [sum(jac[i][c] * d[c] for c in range(len(coords))) for i in range(L)]
        df = [sum(hsym[(i, k)] * dl[k] for k in range(L)) for i in range(L)]
        outs = [
            -im[c] * sp.Symbol("c") * sum(jac[i][ci] * df[i] for i in range(L))
            for ci, c in enumerate(coords)
        ]
        assign, values = cse_lines(outs, "t")
        inner = [f"h{x} = h[{_h_index(system, member, first, x)}, {run}]" for x in range(e)]
        inner += [f"d_{c.name} = dq[{_index(system, c)}, m, {run}]" for c in coords]
        inner += assign
        sums = []
        for c, val in zip(coords, values, strict=True):
            if val == "0":
                continue
            if one and member and c in system.shared:
                i = system.shared.index(c)
                inner.append(f"pull[{i}, j] = {val}")
                sums += ["for j in range(K):", f"    dv[{i}, m, 0] += pull[{i}, j]"]
            else:
                inner.append(f"dv[{_index(system, c)}, m, {run}] += {val}")
        if one:
            lines = _members(inner, member) + sums
        else:
            lines = _loop(inner, member, params=_params(system))
        body += ["    " + s for s in lines]
    return _used(_one_params(system), "\n".join(body)) + body if one else body


def _energies(system: SeparableSystem) -> list[str]:
    masses = _masses(system)
    body = ["B = q.shape[1]", "K = members_of(q.shape[0])"]
    shared_kin = " + ".join(
        f"0.5*({_p(m)})*v[{i}, b]*v[{i}, b]" for i, m in enumerate(system.shared_masses)
    )
    body += _loop([f"shared[b] = {shared_kin}"], False, params=_params(system))
    if system.member:
        kin = " + ".join(
            f"0.5*({_p(masses[c])})*v[{_index(system, c)}, b]*v[{_index(system, c)}, b]"
            for c in system.member
        )
        body += _loop([f"members[j, b] = {kin}"], True, params=_params(system))
    for term, member in _terms(system):
        assign, (value,) = cse_lines([term.value], "t")
        inner = _load(system, member) + _local_lines(term) + assign
        inner.append(f"{'members[j, b]' if member else 'shared[b]'} += {value}")
        body += _loop(inner, member, params=_params(system))
    body += ["for b in range(B):", "    total[b] = shared[b]"]
    if system.member:
        body += _loop(["total[b] += members[j, b]"], True)
    return body


def _shared_energy(system: SeparableSystem) -> list[str]:
    """Body of ``shared_energy``: the shared coordinates' energy (the container's), kinetic
    plus shared terms, in the order of the ``energies`` kernel (the same bits)."""
    body = ["B = q.shape[1]"]
    kin = " + ".join(
        f"0.5*({_p(m)})*v[{i}, b]*v[{i}, b]" for i, m in enumerate(system.shared_masses)
    )
    body += _loop([f"shared[b] = {kin}"], False, params=_params(system))
    for term in system.shared_terms:
        assign, (value,) = cse_lines([term.value], "t")
        inner = _load(system, False) + _local_lines(term) + assign + [f"shared[b] += {value}"]
        body += _loop(inner, False, params=_params(system))
    return body


def _damping_factors(system: SeparableSystem, im) -> list[str]:
    """Body of ``damping_factors``: the decay factors of the exact pair flows over ``tau``
    at the positions q (see :class:`~sinktheory.engine.systems.Damping`)."""
    damping = system.damping
    if damping is None:
        return ["return"]
    if len(system.member_terms) != 1:
        raise ValueError("damping weights are printed for one member term")
    (term,) = system.member_terms
    weight = sp.Symbol("wgt_")
    outs = [damping.weight * term.value]
    for c, partner in damping.pairs:
        rate = im[c] + (im[partner] if partner is not None else 0)
        outs.append(rate)
    assign, (scaled, *rates) = cse_lines(outs, "t")
    inner = _load(system, True) + _local_lines(term) + assign
    inner.append(f"{weight} = c0 * ({scaled}) if weighted else c0")
    for (c, partner), rate in zip(damping.pairs, rates, strict=True):
        row = f"{system.member.index(c)} * K + j"
        if partner is None:  # the velocity decays: its factor exp(-c t / m) - 1
            inner.append(f"decay[{row}, b] = math.expm1(-{weight} * ({rate}) * tau)")
        else:  # the relative velocity decays: 1 - exp(-c (1/m + 1/M) t)
            inner.append(f"decay[{row}, b] = -math.expm1(-{weight} * ({rate}) * tau)")
    return ["B = q.shape[1]", "K = members_of(q.shape[0])"] + _loop(
        inner, True, params=_params(system)
    )


def _dissipate(system: SeparableSystem) -> list[str]:
    """Body of ``dissipate``: the damping flow with the positions frozen, the exact pair
    flows of members 1..K then K..1 (each over half the time of the factors ``decay``), the
    work each run loses into ``work`` (set, not added).  The mass ratios are rows of the
    parameter table (:func:`_damping_shares`), so nothing is divided here."""
    damping = system.damping
    body = ["B = v.shape[1]", "K = members_of(v.shape[0])", "for b in range(B):",
            "    work[b] = 0.0"]  # fmt: skip
    if damping is None:
        return body
    inner = []
    for c, partner in damping.pairs:
        row = f"{system.member.index(c)} * K + j"
        mine = f"v[{_index(system, c)}, b]"
        if partner is None:
            inner += [
                f"vd_ = {mine}",
                f"dv_ = decay[{row}, b] * vd_",
                f"{mine} = vd_ + dv_",
                f"work[b] += 0.5 * dmass_{c.name} * (vd_ * vd_ - (vd_ + dv_) * (vd_ + dv_))",
            ]
        else:
            theirs = f"v[{_index(system, partner)}, b]"
            inner += [
                f"w_ = {mine} - {theirs}",
                f"dw_ = -decay[{row}, b] * w_",
                f"{mine} += dw_ * dshare_{c.name}",
                f"{theirs} -= dw_ * dshare_{partner.name}_{c.name}",
                "wn_ = w_ + dw_",
                f"work[b] += 0.5 * dreduced_{c.name} * (w_ * w_ - wn_ * wn_)",
            ]
    loop = _loop(inner, False, params=_params(system))
    return body + [
        "for jj in range(2 * K):",
        "    j = jj if jj < K else 2 * K - 1 - jj",
        *("    " + s for s in loop),
    ]


#: Names the kernels use for their arguments and loop variables: no coordinate, parameter
#: or atom of a system may take one (the circular well's atom w met the work array w once).
RESERVED = frozenset(
    "q v a h P c dq dv pull total shared members D B K M i j b m "
    "decay c0 weighted tau work jj wgt_ vd_ dv_ w_ dw_ wn_ mixed_ top_ e k r p".split()
)


def _check_names(system: SeparableSystem) -> None:
    names = {s.name for s in (*system.shared, *system.member, *system.params)}
    for term, _ in _terms(system):
        names |= {s.name for s in term.local} | {a.name for a, _ in term.atoms}
    clash = sorted(names & RESERVED)
    if clash:
        raise ValueError(f"system {system.name!r}: symbol names {clash} are the kernels' own")


def render(system: SeparableSystem, banner: str) -> str:
    """Source text of the engine module of ``system``."""
    _check_names(system)
    _EXPONENTS.clear()
    _PENDING.clear()
    im, im_lines = _inverse_masses(system)
    _, shared_rows, member_rows = _hessian_rows(system)
    C = len(system.member)
    head = (
        f"{banner}"
        f'"""Engine of the separable system {system.name!r} (generated; see '
        'sinktheory.engine.printer)."""\n'
        "import math  # noqa: F401\n\nimport numba\nimport numpy as np\n\n"
        f"SHARED = {len(system.shared)}\nMEMBER_COORDS = {C}\nNPARAMS = {len(system.params)}\n"
        f"POWERS = {len(_table_rows(system))}\nMAX_POWER = {1 << POWER_CLASSES[-1]}\n"
        f"SHARED_HESSIAN = {shared_rows}\nMEMBER_HESSIAN = {member_rows}\n"
        f"DAMPED = {system.damping is not None}\n"
    )
    sizes = _function(
        "members_of",
        "D",
        "Number of members K of a state with D coordinates (D = SHARED + MEMBER_COORDS K).",
        [f"return (D - SHARED) // {C}" if C else "return 0"],
    ) + _function(
        "hessian_rows",
        "D",
        "Rows of the Hessian buffer for a state with D coordinates.",
        ["return SHARED_HESSIAN + MEMBER_HESSIAN * members_of(D)"],
    )
    kernels = [
        _function(
            "accelerations",
            "q, a, P",
            "a = -M^-1 grad U(q) for a block q[coordinate, run].",
            im_lines + _accelerations(system, im),
        ),
        _function(
            "accelerations_one",
            "q, a, P, pull",
            "accelerations of a single run q[coordinate, 0], bitwise those of the block "
            "kernel; pull (SHARED, K) is work space.",
            im_lines + _accelerations(system, im, one=True),
            powers="one",
        ),
        _function(
            "hessian",
            "q, h, P",
            "Local Hessian entries of every potential term, h[entry, run].",
            _hessian(system),
        ),
        _function(
            "tangent_kick",
            "h, dq, dv, c, P",
            "dv[:, m] += -c M^-1 Hess U dq[:, m]: the derivative of the kick v += c a(q).",
            im_lines + _tangent_kick(system, im),
        ),
        _function(
            "hessian_one",
            "q, h, P",
            "hessian of a single run, h[entry, 0].",
            _hessian(system, one=True),
            powers="one",
        ),
        _function(
            "tangent_kick_one",
            "h, dq, dv, c, P, pull",
            "tangent_kick of a single run, bitwise; pull (SHARED, K) is work space.",
            im_lines + _tangent_kick(system, im, one=True),
        ),
        _function(
            "shared_energy",
            "q, v, P, shared",
            "The shared coordinates' energy (kinetic and shared terms) per run.",
            _shared_energy(system),
        ),
        _function(
            "damping_factors",
            "q, P, c0, weighted, tau, decay",
            "Decay factors decay[member coordinate * K + member, run] of the damping's exact "
            "pair flows over tau at the positions q (coefficient c0, contact-weighted or "
            "not).",
            im_lines + _damping_factors(system, im),
        ),
        _function(
            "dissipate",
            "v, decay, P, work",
            "The damping flow on the velocities v in place (positions frozen), members 1..K "
            "then K..1 with the factors decay; the energy each run loses into work.",
            _dissipate(system),
        ),
        _function(
            "energies",
            "q, v, P, total, shared, members",
            "Total energy H, its shared (container) part and each member's part, per run.",
            _energies(system),
            powers="lanes",
        ),
    ]
    stepper = STEPPER.read_text()
    stepper = stepper[stepper.index("# --- template starts") :]
    parts = [head, sizes, _power_helpers(), _table(system), *kernels]
    return "".join(parts) + "\n\n" + stepper


def _table(system: SeparableSystem) -> str:
    """``NTABLE`` and ``parameter_table``: the rows of :func:`_table_rows`, then each
    run-time exponent the kernels raise a base to (row POWERS + i: :data:`_EXPONENTS`)."""
    rows = _table_rows(system)
    loads = [f"{p.name} = P[{i}, b]" for i, p in enumerate(system.params)]
    fill = [f"T[{i}, b] = {_p(e)}" for i, (_, e) in enumerate(rows)]
    fill += [f"T[POWERS + {i}, b] = {_p(e)}" for i, e in enumerate(_EXPONENTS)]
    return f"NTABLE = {len(fill)}\n" + _function(
        "parameter_table",
        "P",
        "The kernels' per-run table (NTABLE, R) from the parameters P (NPARAMS, R): the "
        "rows the kernels load, then each run-time exponent.",
        ["R = P.shape[1]", "T = np.empty((NTABLE, R))"]
        + (["for b in range(R):", *("    " + s for s in loads + fill)] if fill else [])
        + ["return T"],
    )
