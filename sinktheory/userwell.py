"""A well a user writes: an expression or a TOML well file, parsed without running code.

This module is the *definition* of a user's well (issue 36, items 1 and 6): what is
accepted, what is refused, and the checks a potential must pass before anything is
derived or compiled from it.  Nothing here compiles or runs a simulation.

Parsing (:func:`parse_potential`)
---------------------------------
The text is parsed with :func:`ast.parse` (``mode="eval"``), which builds a syntax tree
and runs nothing; the tree is then walked node by node and each node becomes a SymPy
object.  Neither :func:`eval`, :func:`sympy.sympify` nor ``parse_expr`` ever sees the
text (they evaluate Python).  Only these nodes pass:

* numbers (int and float literals; bool, complex, ``inf`` refused), converted exactly
  (``0.3`` is 3/10);
* the names ``x``, ``y``, the declared parameters and the constant ``pi``;
* ``+ - * / **``, parentheses, unary ``-`` and ``+``;
* calls with one positional argument of :data:`FUNCTIONS`: exp, log, sqrt, sin, cos,
  tan, sinh, cosh, tanh, Abs -- the elementary functions that wells are written with
  (exponential and logarithmic walls, radii, periodic corrugations, soft steps, |x|).
  Each is a SymPy function whose derivatives SymPy knows in closed form, which the
  Hamiltonian, forces and Hessians derived later need; anything else (special
  functions, ``Piecewise``, ``Max``) would need a printer and a derivative rule of its own.

Everything else is refused with a :class:`~sinktheory.errors.WellDefinitionError` naming
the offending token: attribute access, subscripts, calls of any other name, keyword or
starred arguments, lambdas, comprehensions, strings, f-strings, comparisons, undeclared
names, texts longer than :data:`MAX_TEXT_LENGTH` characters, nesting deeper than
:data:`MAX_DEPTH` and powers whose exponent exceeds :data:`MAX_EXPONENT` in size or
whose value would have more than :data:`MAX_DIGITS` digits (``2**10**10``).

Checks (:func:`check_well`), at given parameter values
------------------------------------------------------
* **real and finite near the centre** (numerical): V and every guard -- denominators
  (non-zero, one sign), arguments of log (> 0) and bases of non-integer powers (>= 0) --
  on the polar grid :func:`disc_grid` of the disc r <= ``radius``;
* **minimum at the centre**: symbolically when it can be decided (gradient at (0, 0)
  exactly zero; Hessian positive definite: a strict minimum; a negative eigenvalue or a
  non-zero gradient: refused); otherwise (singular Hessian, as for every n >= 2 wall, or
  derivatives undefined at the centre) numerically: V(0, 0) <= V on the rings of
  :func:`ring_grid`;
* **confinement** (numerical): the basin around the centre -- the component of
  {V <= e} holding it -- must be bounded and regular for some e above V(0, 0).  Its
  escape energy e* (a saddle, a singular point of V such as a pole, or the edge of the
  largest search box) is found with a certificate by :func:`sinktheory.basin.escape`,
  and energies at or above it are refused later; a well whose basin is open at every
  energy (a valley where V stays at V(0, 0)) is refused here.
* **wall ratios**, if given: below 1 in size at the centre (numerical);
* **y = 0 invariant** (symbolic, reported, not required): dV/dy(x, 0) == 0 identically,
  decided with :func:`sympy.simplify` after substituting the values.

The numerical checks run in float64 (a value past its range is +-inf and counts as
large; NaN means complex or undefined) with the parameters passed at call time, so a
power is computed as written.

Examples
--------
>>> well = UserWell("ellipse", "gamma/(2*n) * ((x/a)**2 + (y/b)**2)**n",
...                 {"a": (0.3, (0.01, 10)), "b": 0.2, "gamma": 1, "n": (2, (1, 20))})
>>> well.potential
gamma*((x/a)**2 + (y/b)**2)**n/(2*n)
>>> report = check_well(well)
>>> report.minimum, report.y_invariant
('V(0, 0) <= V on the rings (Hessian singular)', True)
>>> parse_potential("__import__('os').system('echo hi')", ())
Traceback (most recent call last):
...
sinktheory.errors.WellDefinitionError: potential: "__import__('os').system" is refused: \
attribute access ('.system')
"""

from __future__ import annotations

import ast
import json
import keyword
import math
import re
import tomllib
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy as sp
from sympy.printing.str import StrPrinter

from .basin import RADIUS_RANGE, Basin, guards, numeric
from .errors import ParameterError, WellDefinitionError
from .limits import MAX_N
from .symbolic import SHAPES, x, y, y_invariance

__all__ = [
    "check_well",
    "DIRECTIONS",
    "disc_grid",
    "expression_text",
    "FUNCTIONS",
    "load_well",
    "MAX_DEPTH",
    "MAX_DIGITS",
    "MAX_EXPONENT",
    "MAX_FILE_BYTES",
    "MAX_TEXT_LENGTH",
    "parameter_values",
    "parse_potential",
    "read_well",
    "Parameter",
    "ring_grid",
    "UserWell",
    "WellCheck",
    "well_report",
    "well_text",
    "y_invariant",
]

#: The functions a potential may call, each with one positional argument.
FUNCTIONS = {
    "exp": sp.exp,
    "log": sp.log,
    "sqrt": sp.sqrt,
    "sin": sp.sin,
    "cos": sp.cos,
    "tan": sp.tan,
    "sinh": sp.sinh,
    "cosh": sp.cosh,
    "tanh": sp.tanh,
    "Abs": sp.Abs,
}
_CONSTANTS = {"pi": sp.pi}
#: Names of the derivation ladder's own symbols (container X, P; mass mu; momenta,
#: velocities, accelerations, the separable coordinate u): a parameter so named would
#: print as, and be confused with, one of them.
_MECHANICS = {
    "X", "P", "mu", "u", "p_x", "p_y", "Xdot", "xdot", "ydot", "xdd", "ydd", "pi_P", "pi_p_x",
    "pi_p_y",
}  # fmt: skip
_RESERVED = {"x", "y", *FUNCTIONS, *_CONSTANTS, *_MECHANICS}
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,31}")

#: Longest text of one expression (the paper's wells take under 100 characters).
MAX_TEXT_LENGTH = 2000
#: Deepest nesting of the syntax tree: each operator or call is one level, so a sum of k
#: terms is k deep (the builder recurses once per level, far below Python's limit).
MAX_DEPTH = 100
#: Largest |exponent| of a power with a numerical exponent: 2 MAX_N, the wall power 2n
#: of the stiffest built-in well.
MAX_EXPONENT = 2 * MAX_N
#: Most decimal digits of a number computed from number ** number.
MAX_DIGITS = 1000
#: Largest well file read (a well file is a few hundred bytes).
MAX_FILE_BYTES = 65536

_FILE_KEYS = ("name", "potential", "parameters", "wall_ratios")
_PARAMETER_KEYS = ("default", "range")
_FUNCTION_LIST = ", ".join(FUNCTIONS)
_BINARY = {
    ast.Add: lambda a, b: a + b,
    ast.Sub: lambda a, b: a - b,
    ast.Mult: lambda a, b: a * b,
    ast.Div: lambda a, b: a / b,
}


# --- parsing --------------------------------------------------------------------------
def _token(text: str, node: ast.AST) -> str:
    """The source of ``node`` (at most 40 characters), for messages."""
    segment = ast.get_source_segment(text, node) or type(node).__name__
    segment = " ".join(segment.split())
    return segment if len(segment) <= 40 else segment[:37] + "..."


def _log10(number: sp.Number) -> float:
    """log10 |number| of a non-zero SymPy number, without converting it to a float
    (which overflows past 1e308)."""
    if number.is_Rational:
        return math.log10(abs(number.p)) - math.log10(number.q)
    return math.log10(abs(float(number)))


def _power(base: sp.Expr, exponent: sp.Expr, token: str, where: str) -> sp.Expr:
    """base ** exponent, refusing exponents and numbers too large to build safely (the
    numerical factor of the base counts: (1e300 x)**2000 would expand to a 600 000-digit
    coefficient)."""
    if exponent.is_Number:
        if abs(exponent) > MAX_EXPONENT:
            raise WellDefinitionError(
                where, token, f"an exponent of size > {MAX_EXPONENT} (the limit 2 MAX_N)"
            )
        factor = base.as_coeff_Mul()[0] if base.free_symbols else base
        if factor.is_Number and factor != 0:
            digits = float(abs(exponent)) * abs(_log10(factor))
            if digits > MAX_DIGITS:
                raise WellDefinitionError(
                    where, token, f"a number of more than {MAX_DIGITS} digits"
                )
    # a power of an expression stays as written ((x/a)**2, not x**2/a**2)
    return sp.Pow(base, exponent, evaluate=not base.free_symbols)


class _Builder:
    """Walks a syntax tree and builds the SymPy expression, node by node."""

    def __init__(self, text: str, root: ast.AST, symbols: Mapping[str, sp.Symbol], where: str):
        self.text = text
        self.root = root
        self.symbols = symbols
        self.where = where

    def refuse(self, node: ast.AST, reason: str) -> WellDefinitionError:
        return WellDefinitionError(self.where, _token(self.text, node), reason)

    def build(self, node: ast.AST, depth: int = 0) -> sp.Expr:
        if depth > MAX_DEPTH:  # named by the whole text: the deepest node says little
            raise self.refuse(self.root, f"nesting deeper than {MAX_DEPTH} levels")
        if isinstance(node, ast.Constant):
            value = node.value
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise self.refuse(node, f"a {type(value).__name__} constant (only numbers)")
            if isinstance(value, float):
                if not math.isfinite(value):
                    raise self.refuse(node, "a number that is not finite")
                return sp.Rational(repr(value))
            return sp.Integer(value)
        if isinstance(node, ast.Name):
            if node.id in self.symbols:
                return self.symbols[node.id]
            if node.id in _CONSTANTS:
                return _CONSTANTS[node.id]
            declared = ", ".join(self.symbols)
            raise self.refuse(node, f"a name that is not declared (declared: {declared})")
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub | ast.UAdd):
            operand = self.build(node.operand, depth + 1)
            return -operand if isinstance(node.op, ast.USub) else operand
        if isinstance(node, ast.BinOp):
            if type(node.op) in _BINARY:
                left = self.build(node.left, depth + 1)
                right = self.build(node.right, depth + 1)
                if isinstance(node.op, ast.Div) and right == 0:
                    raise self.refuse(node, "a division by zero")
                return _BINARY[type(node.op)](left, right)
            if isinstance(node.op, ast.Pow):
                base = self.build(node.left, depth + 1)
                exponent = self.build(node.right, depth + 1)
                if base == 0 and exponent.is_Number and exponent < 0:
                    raise self.refuse(node, "a division by zero")
                return _power(base, exponent, _token(self.text, node), self.where)
            raise self.refuse(node, "an operator other than + - * / **")
        if isinstance(node, ast.Call):
            func = node.func
            if not isinstance(func, ast.Name):
                self.build(func, depth + 1)  # names what is wrong inside, if anything
                raise self.refuse(node, "a call of something that is not a function name")
            if func.id not in FUNCTIONS:
                raise self.refuse(
                    node, f"a call of {func.id!r}, which is not one of {_FUNCTION_LIST}"
                )
            if node.keywords or len(node.args) != 1 or isinstance(node.args[0], ast.Starred):
                raise self.refuse(node, f"{func.id} takes exactly one positional argument")
            return FUNCTIONS[func.id](self.build(node.args[0], depth + 1))
        if isinstance(node, ast.Attribute):
            raise self.refuse(node, f"attribute access ('.{node.attr}')")
        kind = {
            ast.Subscript: "a subscript",
            ast.Lambda: "a lambda",
            ast.JoinedStr: "an f-string",
            ast.Compare: "a comparison",
            ast.BoolOp: "a boolean operator",
            ast.IfExp: "a conditional expression",
        }.get(type(node), f"Python syntax ({type(node).__name__}) outside arithmetic")
        raise self.refuse(node, kind)


def _declared(parameters: Iterable[str], where: str = "parameters") -> dict[str, sp.Symbol]:
    """x, y and the parameter symbols by name (real symbols; names checked)."""
    symbols = {"x": x, "y": y}
    if isinstance(parameters, str | bytes) or not isinstance(parameters, Iterable):
        raise WellDefinitionError(where, parameters, "must be a list of parameter names")
    for name in parameters:
        if not isinstance(name, str) or not _NAME.fullmatch(name):
            raise WellDefinitionError(
                where, name, "a parameter name must be a letter then up to 31 letters, "
                "digits or _",
            )  # fmt: skip
        if keyword.iskeyword(name):
            raise WellDefinitionError(
                where, name, "a Python keyword (it cannot be written in an expression)"
            )
        if name in _RESERVED:
            raise WellDefinitionError(
                where, name, "a reserved name (x, y, pi, a function, or a symbol of the "
                f"mechanics: {', '.join(sorted(_MECHANICS))})",
            )  # fmt: skip
        symbols[name] = sp.Symbol(name, real=True)
    return symbols


def parse_potential(text: str, parameters: Iterable[str], *, where: str = "potential") -> sp.Expr:
    """The SymPy expression of ``text``, an expression in x, y and ``parameters``.

    Parsed with :func:`ast.parse` and built node by node; no code in ``text`` runs (see
    the module docstring for what passes).  ``where`` names the text in messages.

    Parameters
    ----------
    text : str
        The expression, Python syntax (``**`` for powers).
    parameters : iterable of str
        The declared parameter names (letters, digits, ``_``; not x, y, pi or a function).

    Returns
    -------
    sympy.Expr
        In the real symbols :data:`sinktheory.symbolic.x`, ``y`` and real symbols named
        as the parameters.

    Raises
    ------
    WellDefinitionError
        One line naming the offending token and why it is refused.

    Examples
    --------
    >>> parse_potential("(x**2 + y**2)/2 + x**2*y - y**3/3", ())
    x**2*y + x**2/2 - y**3/3 + y**2/2
    >>> parse_potential("x.__class__", ())
    Traceback (most recent call last):
    ...
    sinktheory.errors.WellDefinitionError: potential: 'x.__class__' is refused: attribute \
access ('.__class__')
    >>> parse_potential("2**10**10", ())
    Traceback (most recent call last):
    ...
    sinktheory.errors.WellDefinitionError: potential: '2**10**10' is refused: an exponent \
of size > 2000 (the limit 2 MAX_N)
    """
    if not isinstance(text, str):
        raise WellDefinitionError(
            where, type(text).__name__, "must be a string or SymPy expression"
        )
    if len(text) > MAX_TEXT_LENGTH:
        raise WellDefinitionError(
            where, text[:20] + "...", f"longer than {MAX_TEXT_LENGTH} characters"
        )
    symbols = _declared(parameters)
    try:
        tree = ast.parse(text, mode="eval")
    except (SyntaxError, ValueError, RecursionError, MemoryError) as exc:
        reason = getattr(exc, "msg", None) or str(exc) or type(exc).__name__
        raise WellDefinitionError(where, text[:40], f"not an expression ({reason})") from None
    return _Builder(text, tree.body, symbols, where).build(tree.body)


#: SymPy node classes a given expression may contain (sqrt is a Pow).
_ALLOWED_HEADS = (sp.Add, sp.Mul, sp.Pow, *(f for f in FUNCTIONS.values() if isinstance(f, type)))


def _check_expression(expr: sp.Expr, symbols: Mapping[str, sp.Symbol], where: str) -> sp.Expr:
    """A SymPy expression given directly: its symbols renamed onto ours by name, and its
    nodes limited to what :func:`parse_potential` can build."""
    if not isinstance(expr, sp.Expr):
        raise WellDefinitionError(
            where, type(expr).__name__, "must be a string or SymPy expression"
        )
    for node in sp.preorder_traversal(expr):
        kind = type(node)
        if not (kind.__module__ or "").startswith("sympy."):
            # a subclass could print itself as any code when the kernels are printed
            raise WellDefinitionError(where, kind.__name__, "a class defined outside SymPy")
        if isinstance(node, sp.Symbol):
            if node.name not in symbols:
                raise WellDefinitionError(
                    where, node.name, f"a symbol that is not declared (declared: "
                    f"{', '.join(symbols)})",
                )  # fmt: skip
        elif isinstance(node, sp.Number):
            if not node.is_finite:
                raise WellDefinitionError(where, str(node), "a number that is not finite")
        elif node is sp.pi or node is sp.E:  # exp(1) evaluates to E
            continue
        elif kind not in _ALLOWED_HEADS:
            raise WellDefinitionError(
                where, str(node.func), f"not arithmetic or one of {_FUNCTION_LIST}"
            )
        elif kind is sp.Pow and node.exp.is_Number:
            _power(node.base, node.exp, str(node)[:40], where)
    return expr.xreplace({s: symbols[s.name] for s in expr.free_symbols})


# --- the definition -------------------------------------------------------------------
@dataclass(frozen=True)
class Parameter:
    """A parameter of a user's well: its name, default value and allowed range [lo, hi].

    Examples
    --------
    >>> Parameter("a", 0.3, (0.01, 10)).symbol
    a
    >>> Parameter("a", 20, (0.01, 10))
    Traceback (most recent call last):
    ...
    sinktheory.errors.WellDefinitionError: parameters.a.default: 20.0 is refused: outside \
the range [0.01, 10.0]
    """

    name: str
    default: float
    range: tuple[float, float] = (-math.inf, math.inf)

    def __post_init__(self) -> None:
        _declared([self.name])
        where = f"parameters.{self.name}"
        set_ = object.__setattr__
        bounds = self.range
        if not isinstance(bounds, list | tuple) or len(bounds) != 2:
            raise WellDefinitionError(f"{where}.range", bounds, "must be [lo, hi]")
        lo, hi = (_number(f"{where}.range", b, finite=False) for b in bounds)
        if not lo <= hi or lo == math.inf or hi == -math.inf:
            raise WellDefinitionError(f"{where}.range", bounds, "must have lo <= hi")
        set_(self, "range", (lo, hi))
        set_(self, "default", self.check(self.default, f"{where}.default"))

    @property
    def symbol(self) -> sp.Symbol:
        """The real SymPy symbol of this parameter."""
        return sp.Symbol(self.name, real=True)

    def check(self, value: object, where: str | None = None) -> float:
        """``value`` as a finite float inside the range (WellDefinitionError otherwise)."""
        where = where or self.name
        value = _number(where, value)
        lo, hi = self.range
        if not lo <= value <= hi:
            raise WellDefinitionError(where, value, f"outside the range [{lo}, {hi}]")
        return value


def _number(where: str, value: object, *, finite: bool = True) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float | np.integer | np.floating):
        raise WellDefinitionError(where, value, "must be a number")
    value = float(value)
    if math.isnan(value) or (finite and not math.isfinite(value)):
        raise WellDefinitionError(where, value, "must be a finite number")
    return value


def _exact(value: float) -> sp.Rational:
    """The decimal a user wrote, exactly: 0.3 -> 3/10, 4.0 -> 4."""
    return sp.Integer(int(value)) if value.is_integer() else sp.Rational(repr(value))


@dataclass(frozen=True)
class UserWell:
    """A well V(x, y) defined by a user: a name, a potential, parameters, wall ratios.

    Parameters
    ----------
    name : str
        Letters, digits, ``_`` or ``-`` (up to 40), not a built-in shape's name.
    potential : str or sympy.Expr
        In x, y and the parameters; a string is parsed by :func:`parse_potential`, an
        expression is checked the same way (its symbols are matched by name).
    parameters : mapping or iterable of Parameter
        ``name -> default`` or ``name -> (default, (lo, hi))``, or :class:`Parameter`\\ s.
    wall_ratios : sequence of str or sympy.Expr, optional
        Expressions whose level 1 is the rigid wall (< 1 inside it).

    Examples
    --------
    >>> w = UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3 + c*(x**2 + y**2)**2",
    ...              {"c": (0.1, (0.0, 10.0))})
    >>> w.parameter_names, w.values(c=0.5)
    (('c',), {c: 1/2})
    """

    name: str
    potential: sp.Expr
    parameters: tuple[Parameter, ...] = ()
    wall_ratios: tuple[sp.Expr, ...] = ()

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        name = self.name
        if not isinstance(name, str) or not re.fullmatch(r"[A-Za-z][A-Za-z0-9_-]{0,39}", name):
            raise WellDefinitionError(
                "name", name, "must be a letter then up to 39 letters, digits, _ or -"
            )
        if name in tuple(SHAPES):
            raise WellDefinitionError("name", name, "the name of a built-in shape")
        params = self.parameters
        if isinstance(params, Mapping):
            params = tuple(_parameter(k, v) for k, v in params.items())
        if isinstance(params, str | bytes) or not isinstance(params, Iterable):
            raise WellDefinitionError("parameters", params, "must be a mapping or Parameters")
        params = tuple(params)
        if not all(isinstance(p, Parameter) for p in params):
            raise WellDefinitionError("parameters", params, "must be Parameter objects")
        names = [p.name for p in params]
        if len(set(names)) != len(names):
            raise WellDefinitionError("parameters", names, "a parameter declared twice")
        set_(self, "parameters", params)
        symbols = _declared(names)
        set_(self, "potential", _expression(self.potential, symbols, "potential"))
        ratios = self.wall_ratios
        if isinstance(ratios, str | sp.Expr) or not isinstance(ratios, Iterable):
            raise WellDefinitionError("wall_ratios", ratios, "must be a list of expressions")
        ratios = tuple(_expression(r, symbols, f"wall_ratios[{i}]") for i, r in enumerate(ratios))
        set_(self, "wall_ratios", ratios)

    @property
    def parameter_names(self) -> tuple[str, ...]:
        return tuple(p.name for p in self.parameters)

    @property
    def parameter_symbols(self) -> tuple[sp.Symbol, ...]:
        """The parameters' real SymPy symbols, in declaration order."""
        return tuple(p.symbol for p in self.parameters)

    @property
    def atoms(self) -> tuple:
        """No intermediate atoms: SymPy differentiates V directly (the
        :class:`~sinktheory.symbolic.WellDefinition` protocol)."""
        return ()

    def values(self, **given: float) -> dict[sp.Symbol, sp.Rational]:
        """Parameter symbol -> exact value: the defaults, replaced by ``given`` (each
        checked against its range; unknown names refused)."""
        by_name = {p.name: p for p in self.parameters}
        for key in given:
            if key not in by_name:
                raise WellDefinitionError(
                    "parameter", key, f"not a parameter of {self.name} ({', '.join(by_name)})"
                )
        return {
            p.symbol: _exact(p.check(given[p.name]) if p.name in given else p.default)
            for p in self.parameters
        }

    def potential_at(self, **given: float) -> sp.Expr:
        """V(x, y) with the parameters' values substituted (defaults unless given)."""
        return self.potential.subs(self.values(**given))

    def with_defaults(self, **given: float) -> UserWell:
        """This well with the defaults of the parameters in ``given`` replaced (each
        within its range; unknown names refused).

        Examples
        --------
        >>> UserWell("bowl", "k*(x**2 + y**2)/2", {"k": 1}).with_defaults(k=3).parameters
        (Parameter(name='k', default=3.0, range=(-inf, inf)),)
        """
        self.values(**given)  # names and ranges checked
        params = tuple(Parameter(p.name, given.get(p.name, p.default), p.range)
                       for p in self.parameters)  # fmt: skip
        return UserWell(self.name, self.potential, params, self.wall_ratios)


def _parameter(name: object, spec: object) -> Parameter:
    if isinstance(spec, Parameter):
        return spec
    if isinstance(spec, Mapping):  # as in a well file: {"default": ..., "range": [lo, hi]}
        extra = [k for k in spec if k not in _PARAMETER_KEYS]
        if extra or "default" not in spec:
            raise WellDefinitionError(
                f"parameters.{name}", extra[0] if extra else "default",
                "unknown key" if extra else "missing (a default value is required)",
            )  # fmt: skip
        return Parameter(name, spec["default"], spec.get("range", (-math.inf, math.inf)))
    if isinstance(spec, tuple | list):
        if len(spec) != 2:
            raise WellDefinitionError(f"parameters.{name}", spec, "must be (default, (lo, hi))")
        return Parameter(name, spec[0], tuple(spec[1]) if isinstance(spec[1], list) else spec[1])
    return Parameter(name, spec)


def _expression(value: object, symbols: Mapping[str, sp.Symbol], where: str) -> sp.Expr:
    if isinstance(value, str):
        return parse_potential(value, [s for s in symbols if s not in ("x", "y")], where=where)
    return _check_expression(value, symbols, where)


# --- well files -----------------------------------------------------------------------
def load_well(path: str | Path) -> UserWell:
    """The :class:`UserWell` of a TOML well file; no code in the file runs.

    The file holds ``name`` and ``potential`` (strings), a ``[parameters]`` table with one
    table ``{default = ..., range = [lo, hi]}`` per parameter, and optionally
    ``wall_ratios`` (a list of strings).  Unknown keys, wrong types, a missing potential,
    defaults outside their range, files over :data:`MAX_FILE_BYTES` bytes, bytes that are
    not UTF-8 and text that is not TOML are refused, each with one line naming the key.

    Examples
    --------
    >>> from pathlib import Path
    >>> guide = Path(__file__).resolve().parents[1] / "docs" / "guide"  # in the repository
    >>> well = load_well(guide / "elliptic.toml")
    >>> well.name, well.parameter_names
    ('elliptic', ('a', 'b', 'gamma', 'n'))
    """
    path = Path(path)
    where = path.name
    try:
        with open(path, "rb") as handle:
            raw = handle.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise WellDefinitionError(where, str(path), f"cannot be read ({exc.strerror})") from None
    if len(raw) > MAX_FILE_BYTES:
        raise WellDefinitionError(where, str(path), f"larger than {MAX_FILE_BYTES} bytes")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise WellDefinitionError(where, str(path), f"not UTF-8 text (byte {exc.start})") from None
    return read_well(text, where=where, source=str(path))


def read_well(text: str, *, where: str = "well", source: str | None = None) -> UserWell:
    """The :class:`UserWell` of the TOML text of a well file (what :func:`load_well` reads
    from a file, and what :func:`well_text` writes); ``where`` names it in a refusal
    (``source``, the text's origin, is quoted when it is not TOML).  No code in it runs.

    Examples
    --------
    >>> read_well('name = "bowl"\\npotential = "k*(x**2 + y**2)/2"\\n'
    ...           '[parameters]\\nk = { default = 1.0 }\\n').parameter_names
    ('k',)
    """
    if not isinstance(text, str):
        raise WellDefinitionError(where, type(text).__name__, "must be the text of a well file")
    if len(text.encode()) > MAX_FILE_BYTES:
        raise WellDefinitionError(where, f"{len(text.encode())} bytes",
                                  f"larger than {MAX_FILE_BYTES} bytes")  # fmt: skip
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        shown = source if source is not None else "the text"
        raise WellDefinitionError(where, shown, f"not TOML ({exc})") from None
    unknown = [k for k in data if k not in _FILE_KEYS]
    if unknown:
        raise WellDefinitionError(
            f"{where}: key", unknown[0], f"unknown (allowed: {', '.join(_FILE_KEYS)})"
        )
    for key in ("name", "potential"):
        if key not in data:
            raise WellDefinitionError(f"{where}: key", key, "missing")
        if not isinstance(data[key], str):
            raise WellDefinitionError(f"{where}: {key}", data[key], "must be a string")
    table = data.get("parameters", {})
    if not isinstance(table, dict):
        raise WellDefinitionError(f"{where}: parameters", table, "must be a table")
    params = []
    for name, spec in table.items():
        key = f"{where}: parameters.{name}"
        if not isinstance(spec, dict):
            raise WellDefinitionError(
                key, spec, "must be a table {default = ..., range = [lo, hi]}"
            )
        extra = [k for k in spec if k not in _PARAMETER_KEYS]
        if extra or "default" not in spec:
            raise WellDefinitionError(
                key, extra[0] if extra else "default",
                "unknown key" if extra else "missing (a default value is required)",
            )  # fmt: skip
        bounds = spec.get("range", [-math.inf, math.inf])
        try:
            params.append(Parameter(name, spec["default"], bounds))
        except WellDefinitionError as exc:
            raise WellDefinitionError(f"{where}: {exc.name}", exc.value, exc.allowed) from None
    ratios = data.get("wall_ratios", [])
    if not isinstance(ratios, list) or not all(isinstance(r, str) for r in ratios):
        raise WellDefinitionError(f"{where}: wall_ratios", ratios, "must be a list of strings")
    try:
        return UserWell(data["name"], data["potential"], tuple(params), tuple(ratios))
    except WellDefinitionError as exc:
        raise WellDefinitionError(f"{where}: {exc.name}", exc.value, exc.allowed) from None


class _WellPrinter(StrPrinter):
    """SymPy's str printer, with Euler's number as ``exp(1)`` (the parser knows no ``E``)."""

    def _print_Exp1(self, expr) -> str:
        return "exp(1)"


def expression_text(expr: sp.Expr) -> str:
    """``expr`` in the syntax of a well file: every symbol by its plain name (a parameter
    named ``gamma``, ``beta`` or ``E`` prints as that name, not as a SymPy function or
    constant), Euler's number as ``exp(1)``, powers as ``**``.  :func:`parse_potential`
    reads a potential so printed back (:func:`well_text` checks it does); the derived
    equations of ``sinktheory derive --well`` are printed so too.

    Examples
    --------
    >>> E, gamma = sp.Symbol("E", real=True), sp.Symbol("gamma", real=True)
    >>> expression_text(gamma * x**2 / 2 + E * sp.exp(1) * y**4)
    'exp(1)*E*y**4 + gamma*x**2/2'
    """
    if not isinstance(expr, sp.Basic):
        raise WellDefinitionError("expression", type(expr).__name__, "must be a SymPy expression")
    return _WellPrinter().doprint(expr)


def well_text(well: UserWell) -> str:
    """The TOML text of a well file that :func:`read_well` reads back as ``well`` (same
    name, potential, parameters, defaults, ranges and wall ratios, checked here): how a
    well travels with the work that uses it -- a sweep stores it in its store and sends
    it to its workers, which rebuild the well without the original file.  Comments and
    spelling of the original file are not kept (the text is SymPy's canonical form).

    Examples
    --------
    >>> well = UserWell("bowl", "k*(y**2 + x**2)/2 + exp(1)*x**4", {"k": (1, (0.5, 2))})
    >>> print(well_text(well))
    name = "bowl"
    potential = "k*(x**2 + y**2)/2 + exp(1)*x**4"
    [parameters]
    k = { default = 1.0, range = [0.5, 2.0] }
    >>> read_well(well_text(well)) == well
    True
    """
    if not isinstance(well, UserWell):
        raise WellDefinitionError("well", type(well).__name__, "must be a UserWell")
    lines = [f"name = {json.dumps(well.name)}",
             f"potential = {json.dumps(expression_text(well.potential))}"]  # fmt: skip
    if well.wall_ratios:
        ratios = ", ".join(json.dumps(expression_text(r)) for r in well.wall_ratios)
        lines.append(f"wall_ratios = [{ratios}]")
    lines.append("[parameters]")
    for p in well.parameters:
        lo, hi = (_toml_float(b) for b in p.range)
        lines.append(f"{p.name} = {{ default = {_toml_float(p.default)}, range = [{lo}, {hi}] }}")
    text = "\n".join(lines)
    if read_well(text, where=f"well {well.name}") != well:
        raise WellDefinitionError(
            f"well {well.name}", "its potential", "does not print as a text that reads back as "
            "the same expression",
        )  # fmt: skip
    return text


def _toml_float(value: float) -> str:
    """A float as TOML writes it: repr's digits (exact round trip), inf as ``inf``."""
    return repr(float(value)) if math.isfinite(value) else ("inf" if value > 0 else "-inf")


# --- checks ---------------------------------------------------------------------------
#: Number of directions of the polar grids (angles 2 pi j / DIRECTIONS, a multiple of 8:
#: the axes and the diagonals are among them, exactly).
DIRECTIONS = 64


def _directions() -> tuple[np.ndarray, np.ndarray]:
    """cos and sin of the angles 2 pi j / DIRECTIONS, built from the first octant by the
    symmetries of the square, so that the axes are exactly (+-1, 0), (0, +-1) and the
    diagonals have |cos| == |sin| (a valley of V along x = y is then seen, not missed by
    one rounding)."""
    per = DIRECTIONS // 8
    t = 2 * np.pi * np.arange(per + 1) / DIRECTIONS
    c, s = np.cos(t), np.sin(t)
    c[0], s[0] = 1.0, 0.0
    c[per] = s[per] = np.sqrt(0.5)
    m = np.arange(per)
    octants = [
        (c[m], s[m]), (s[per - m], c[per - m]), (-s[m], c[m]), (-c[per - m], s[per - m]),
        (-c[m], -s[m]), (-s[per - m], -c[per - m]), (s[m], -c[m]), (c[per - m], -s[per - m]),
    ]  # fmt: skip
    cos = np.concatenate([o[0] for o in octants]) + 0.0  # + 0.0 turns -0.0 into 0.0
    sin = np.concatenate([o[1] for o in octants]) + 0.0
    return cos, sin


def _radius(radius: object) -> float:
    """The radius of the checks: a finite number whose grids stay finite and whose
    squares on the finest ring do not underflow."""
    radius, (lo, hi) = _number("radius", radius), RADIUS_RANGE
    if not lo <= radius <= hi:
        raise WellDefinitionError(
            "radius", radius, f"must be in [{lo:g}, {hi:g}] (below, r**2 underflows "
            "on the checks' finest ring, radius/2**20)",
        )  # fmt: skip
    return radius


def disc_grid(radius: float) -> tuple[np.ndarray, np.ndarray]:
    """Points (x, y) of the disc r <= radius: the centre and radii radius k/16,
    k = 1..16, on :data:`DIRECTIONS` directions (1025 points)."""
    r = _radius(radius) * np.arange(1, 17) / 16
    cos, sin = _directions()
    xs = np.concatenate([[0.0], np.outer(r, cos).ravel()])
    ys = np.concatenate([[0.0], np.outer(r, sin).ravel()])
    return xs, ys


def ring_grid(radius: float) -> tuple[np.ndarray, np.ndarray]:
    """Rings r = radius 2^-k, k = 1..20, on :data:`DIRECTIONS` directions."""
    r = _radius(radius) * 2.0 ** -np.arange(1, 21)
    cos, sin = _directions()
    return np.outer(r, cos), np.outer(r, sin)


@dataclass(frozen=True)
class WellCheck:
    """What :func:`check_well` found: each field says how it was decided."""

    name: str
    values: dict
    radius: float
    minimum: str
    confinement: str
    y_invariant: bool
    y_invariant_reason: str
    #: the basin around the centre: escape energy (with its certificate), reach, area
    basin: Basin


def _where(xs, ys, i) -> str:
    return f"(x, y) = ({float(np.ravel(xs)[i]):.6g}, {float(np.ravel(ys)[i]):.6g})"


def _check_centre(V: sp.Expr, f, where: str, radius: float) -> None:
    """Real and finite on :func:`disc_grid` (NaN or -inf refused; +inf is float64
    overflow, since a zero denominator or log argument is caught by the guards); guards
    keep their sign there."""
    xs, ys = disc_grid(radius)
    values = f(xs, ys)
    bad = np.isnan(values) | (values == -np.inf)
    if bad.any():
        i = int(np.argmax(bad))
        raise WellDefinitionError(
            where, f"V = {values[i]:.6g}", f"not real and finite at {_where(xs, ys, i)} "
            f"(the disc r <= {radius:g} around the centre; NaN: complex or undefined)",
        )  # fmt: skip
    for guard, rule in guards(V):
        g = numeric(guard)(xs, ys)
        if "log" in rule:
            bad = ~(g > 0)
        elif "non-integer" in rule:
            bad = ~(g >= 0)
        else:
            bad = ~(np.sign(g) == np.sign(g[0])) | (g == 0)
        if bad.any():
            i = int(np.argmax(bad))
            raise WellDefinitionError(
                where, str(guard), f"{rule}, fails at {_where(xs, ys, i)} (the disc r <= "
                f"{radius:g}): V is singular or complex near the centre",
            )  # fmt: skip


def _is_real_number(value: sp.Expr) -> bool:
    """True for a finite real number SymPy can compare (not nan, zoo, DiracDelta(0))."""
    return bool(value.is_comparable) and bool(value.is_finite)


def _at_centre(expr: sp.Expr) -> sp.Expr:
    """expr at (0, 0), simplified only when substitution leaves more than a number."""
    value = expr.subs({x: 0, y: 0})
    return value if value.is_Number else sp.simplify(value)


def _check_minimum(V: sp.Expr, f, where: str, radius: float) -> str:
    """Symbolic second-derivative test at (0, 0), else V(0, 0) <= V on the rings."""
    grad = [_at_centre(sp.diff(V, v)) for v in (x, y)]
    decided = all(_is_real_number(g) for g in grad)
    if decided and any(g != 0 for g in grad):
        raise WellDefinitionError(
            where, f"grad V(0, 0) = ({grad[0]}, {grad[1]})", "no minimum at the centre: the "
            "gradient there is not zero",
        )  # fmt: skip
    if decided:
        h = [_at_centre(sp.diff(V, a, b)) for a, b in ((x, x), (x, y), (y, y))]
        if all(_is_real_number(v) for v in h):
            hxx, hxy, hyy = h
            det = sp.simplify(hxx * hyy - hxy**2)
            if hxx < 0 or hyy < 0 or det < 0:
                raise WellDefinitionError(
                    where, f"Hessian at (0, 0) = [[{hxx}, {hxy}], [{hxy}, {hyy}]]",
                    "no minimum at the centre: the Hessian has a negative eigenvalue",
                )  # fmt: skip
            if hxx > 0 and det > 0:
                return "strict: gradient 0, Hessian positive definite at (0, 0) (symbolic)"
    xs, ys = ring_grid(radius)
    v0 = f(0.0, 0.0)
    values = f(xs, ys)
    slack = 4 * np.finfo(float).eps * abs(float(v0))
    bad = ~(values >= v0 - slack)
    if bad.any():
        i = int(np.argmax(bad))
        raise WellDefinitionError(
            where, f"V = {float(np.ravel(values)[i]):.6g} < V(0, 0) = {float(v0):.6g}",
            f"no minimum at the centre: lower at {_where(xs, ys, i)}",
        )  # fmt: skip
    why = "Hessian singular" if decided else "derivatives undefined at the centre"
    return f"V(0, 0) <= V on the rings ({why})"


def y_invariant(V: sp.Expr) -> tuple[bool, str]:
    """Whether y = 0 is invariant: dV/dy(x, 0) == 0 identically (symbolic).

    Examples
    --------
    >>> y_invariant(parse_potential("x**4 + x**2*y**2 + y**4", ()))
    (True, 'dV/dy(x, 0) = 0')
    >>> y_invariant(parse_potential("x**2 + y**2 + x**2*y", ()))
    (False, 'dV/dy(x, 0) = x**2, not identically 0')
    """
    if not isinstance(V, sp.Expr):  # sympify would evaluate a string as Python
        raise WellDefinitionError("V", type(V).__name__, "must be a SymPy expression")
    return y_invariance(V)


def check_well(well: UserWell, radius: float = 1.0, **given: float) -> WellCheck:
    """Check ``well`` at its parameter values (defaults unless ``given``).

    Real and finite on the disc r <= ``radius``, a minimum at the centre, a bounded basin
    above V(0, 0) (each raises :class:`~sinktheory.errors.WellDefinitionError` with one
    line saying what is wrong), and whether y = 0 is invariant (reported).  How each is
    decided, and its certificate, is in the module docstring.

    Examples
    --------
    >>> hh = UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {})
    >>> round(check_well(hh).basin.escape.escape_potential * 6, 15)  # the saddles' height 1/6
    1.0
    >>> check_well(UserWell("valley", "x**2", {}))  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.WellDefinitionError: well valley: 'V(0, 0) = 0' is refused: not \
confining: at every energy above V(0, 0) the basin reaches (0, -1.04858e+06) on the edge of \
the box |x|, |y| <= 1.04858e+06
    """
    if not isinstance(well, UserWell):
        raise WellDefinitionError("well", type(well).__name__, "must be a UserWell")
    radius = _radius(radius)
    values = well.values(**given)
    V = well.potential.subs(values)
    where = f"well {well.name}"
    f = numeric(well.potential, values)
    _check_centre(V, f, where, radius)
    for i, ratio in enumerate(well.wall_ratios):
        level = float(numeric(ratio, values)(0.0, 0.0))
        if not abs(level) < 1:
            raise WellDefinitionError(
                f"{where}: wall_ratios[{i}]", f"{level:.6g} at (0, 0)",
                "a wall ratio must be below 1 at the centre (its level 1 is the rigid wall)",
            )  # fmt: skip
    minimum = _check_minimum(V, f, where, radius)
    basin = Basin.of(well.potential, values, well.name, radius)
    invariant, reason = y_invariant(V)
    return WellCheck(
        well.name,
        {s.name: v for s, v in values.items()},
        radius,
        minimum,
        basin.escape.describe(basin.well.v0),
        invariant,
        reason,
        basin,
    )


def parameter_values(values: object) -> dict:
    """A user's well's parameter ``values`` by name: a mapping with text keys, or None for
    none (each value is checked by the well).

    Examples
    --------
    >>> parameter_values({"a": 0.3}), parameter_values(None)
    ({'a': 0.3}, {})
    >>> parameter_values([0.3])
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: values = [0.3] is not allowed: must be a mapping of \
parameter names to numbers, or None
    """
    if values is None:
        return {}
    if not isinstance(values, Mapping) or not all(isinstance(k, str) for k in values):
        raise ParameterError("values", values, "a mapping of parameter names to numbers, or None")
    return dict(values)


def well_report(well: UserWell, values=None, well_check=None) -> tuple[dict, WellCheck]:
    """(``values`` by name, the well's :func:`check_well` at them): ``well_check`` when the
    caller has run that check at those values already, else the check run now.  The entry
    points that take a user's well at its values start here.

    Examples
    --------
    >>> well = UserWell("hh", "(x**2 + y**2)/2 + x**2*y - y**3/3", {})
    >>> given, report = well_report(well)
    >>> given, report.y_invariant
    ({}, False)
    >>> well_report(well, well_check="yes")
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: well_check = 'yes' is not allowed: must be None or the \
well's check at those values, a sinktheory.userwell.WellCheck
    """
    given = parameter_values(values)
    if well_check is None:
        return given, check_well(well, **given)
    if not isinstance(well_check, WellCheck):
        raise ParameterError("well_check", well_check,
                             "None or the well's check at those values, a "
                             "sinktheory.userwell.WellCheck")  # fmt: skip
    return given, well_check
