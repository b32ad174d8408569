"""A well text or file from someone else never runs code: every hostile input is refused
with its reason, and nothing is executed (no marker file appears, and neither eval, exec
nor compile-to-code is called while parsing or loading)."""

import ast
import builtins
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sinktheory.errors import ParameterError, WellDefinitionError
from sinktheory.userwell import (
    MAX_DEPTH,
    MAX_FILE_BYTES,
    MAX_TEXT_LENGTH,
    UserWell,
    load_well,
    parse_potential,
)

# (text, a fragment of the reason); MARKER is replaced by a path the code would create
HOSTILE_TEXTS = [
    ("__import__('os').system('touch MARKER')", "attribute access ('.system')"),
    ("__import__('os')", "a call of '__import__'"),
    ("open('MARKER', 'w')", "a call of 'open'"),
    ("exec(\"open('MARKER', 'w')\")", "a call of 'exec'"),
    ("eval('1')", "a call of 'eval'"),
    ("x.__class__", "attribute access ('.__class__')"),
    ("().__class__.__bases__[0].__subclasses__()", "attribute access ('.__subclasses__')"),
    ("(lambda: __import__('os').system('touch MARKER'))()", "a lambda"),
    ("lambda: 0", "a lambda"),
    ("[c for c in 'ab']", "ListComp"),
    ("{c: 1 for c in 'ab'}", "DictComp"),
    ("'abc'", "a str constant"),
    ("f'{x}'", "an f-string"),
    ("x[0]", "a subscript"),
    ("exp(x, y)", "exp takes exactly one positional argument"),
    ("exp(x=1)", "exp takes exactly one positional argument"),
    ("exp(*x)", "exp takes exactly one positional argument"),
    ("os", "a name that is not declared"),
    ("z + x", "a name that is not declared"),
    ("__builtins__", "a name that is not declared"),
    ("x if y else 0", "a conditional expression"),
    ("x < y", "a comparison"),
    ("x and y", "a boolean operator"),
    ("x // y", "an operator other than + - * / **"),
    ("x % y", "an operator other than + - * / **"),
    ("x @ y", "an operator other than + - * / **"),
    ("~x", "UnaryOp"),
    ("not x", "UnaryOp"),
    ("True * x", "a bool constant"),
    ("1j * x", "a complex constant"),
    ("1e999 * x", "a number that is not finite"),
    ("2**10**10", "an exponent of size > 2000"),
    ("x**100000", "an exponent of size > 2000"),
    ("9**2000", "a number of more than 1000 digits"),
    ("(9**900)**2", "a number of more than 1000 digits"),
    ("(1e300*x)**2000", "a number of more than 1000 digits"),
    ("(x/1e300)**2000", "a number of more than 1000 digits"),
    ("(9**900)**0.5 * x", None),  # 429 digits: accepted
    ("+".join(["x**2"] * 99), None),  # a sum of 99 terms is 99 deep: accepted
    ("1/0", "a division by zero"),
    ("0**-1", "a division by zero"),
    ("x; import os", "not an expression"),
    ("import os", "not an expression"),
    ("x\x00", "not an expression"),
    ("x+" * (MAX_TEXT_LENGTH // 2) + "x", f"longer than {MAX_TEXT_LENGTH} characters"),
    ("-" * (MAX_DEPTH + 5) + "x", f"nesting deeper than {MAX_DEPTH} levels"),
    ("exp(" * (MAX_DEPTH + 1) + "x" + ")" * (MAX_DEPTH + 1), "nesting deeper"),
    ("(" * 500 + "x" + ")" * 500, "not an expression"),  # the parser's own nesting limit
    ("", "not an expression"),
]


def _module_file(filename: object) -> bool:
    """A module imported from a file (sympy imports some modules lazily) may be compiled
    and executed; nothing else may."""
    return isinstance(filename, str) and filename.endswith(".py") and Path(filename).is_file()


@pytest.fixture
def nothing_runs(monkeypatch, tmp_path):
    """Fails the test if eval or exec runs anything but a module file's code, or compile
    is asked for anything but an AST or a module file; yields the marker path the hostile
    texts would create."""
    calls = []
    real = {name: getattr(builtins, name) for name in ("eval", "exec", "compile")}

    def guarded(name):
        def run(source, *args, **kwargs):
            if not _module_file(getattr(source, "co_filename", None)):
                calls.append((name, source))
                raise AssertionError(f"{name} was called on {source!r:.60}")
            return real[name](source, *args, **kwargs)

        return run

    def ast_only(source, filename, mode, flags=0, *args, **kwargs):
        if not flags & ast.PyCF_ONLY_AST and not _module_file(filename):
            calls.append(("compile", source))
            raise AssertionError("compile to code was called")
        return real["compile"](source, filename, mode, flags, *args, **kwargs)

    monkeypatch.setattr(builtins, "eval", guarded("eval"))
    monkeypatch.setattr(builtins, "exec", guarded("exec"))
    monkeypatch.setattr(builtins, "compile", ast_only)
    marker = tmp_path / "MARKER"
    yield marker, calls
    assert calls == []
    assert not marker.exists()


@pytest.mark.parametrize("text,reason", HOSTILE_TEXTS)
def test_hostile_text_is_refused_with_its_reason(text, reason, nothing_runs):
    text = text.replace("MARKER", str(nothing_runs[0]))
    if reason is None:
        assert parse_potential(text, ("a",)).free_symbols == {parse_potential("x", ())}
        return
    with pytest.raises(WellDefinitionError) as info:
        parse_potential(text, ("a",))
    message = str(info.value)
    assert reason in message
    assert "\n" not in message and message.startswith("potential: ")
    assert isinstance(info.value, ParameterError)  # the CLI's exit status 2


def test_the_guard_would_see_eval(nothing_runs):
    # the fixture is not vacuous: a parser that used eval, exec or compile would be caught
    _, calls = nothing_runs
    with pytest.raises(AssertionError, match="eval was called"):
        builtins.eval("1")
    with pytest.raises(AssertionError, match="exec was called"):
        builtins.exec("import os")
    with pytest.raises(AssertionError, match="compile to code"):
        builtins.compile("1", "<s>", "eval")
    import sympy

    with pytest.raises(AssertionError, match="was called"):
        sympy.sympify("x + 1")
    assert [name for name, _ in calls][:3] == ["eval", "exec", "compile"]
    assert len(calls) > 3  # sympify ran code (exec of "from sympy import *", then eval)
    calls.clear()  # let the teardown pass


def _file(tmp_path: Path, text: str | bytes) -> Path:
    path = tmp_path / "hostile.toml"
    path.write_bytes(text.encode() if isinstance(text, str) else text)
    return path


GOOD = """name = "ok"
potential = "gamma*(x**2 + y**2)"
[parameters]
gamma = { default = 1.0, range = [0.1, 10.0] }
"""

HOSTILE_FILES = [
    (GOOD.replace('"gamma*(x**2 + y**2)"', "\"__import__('os').system('touch MARKER')\""),
     "hostile.toml: potential: \"__import__('os').system\" is refused: attribute access"),
    (GOOD.replace('"gamma*(x**2 + y**2)"', '"x.__class__.__bases__"'), "attribute access"),
    (GOOD.replace('"gamma*(x**2 + y**2)"', '"(lambda: 1)()"'), "a lambda"),
    (GOOD.replace('"gamma*(x**2 + y**2)"', '"gamma*(x**2 + y**2) + os"'), "'os' is refused"),
    ('wall_ratios = ["x.__class__"]\n' + GOOD, "wall_ratios[0]: 'x.__class__' is refused"),
    (GOOD.replace('"gamma*(x**2 + y**2)"', '"' + "x+" * 5000 + 'x"'), "longer than 2000"),
    (GOOD.replace('"gamma*(x**2 + y**2)"', '"' + "exp(" * 110 + "x" + ")" * 110 + '"'),
     "nesting deeper"),
    ('exec = "import os"\n' + GOOD, "hostile.toml: key: 'exec' is refused: unknown"),
    (GOOD.replace("range", "code = 'x', range"), "parameters.gamma: 'code' is refused: unknown"),
    (GOOD.replace('potential = "gamma*(x**2 + y**2)"\n', ""),
     "key: 'potential' is refused: missing"),
    (GOOD.replace('name = "ok"\n', ""), "key: 'name' is refused: missing"),
    (GOOD.replace('"gamma*(x**2 + y**2)"', '["x"]'),
     "potential: ['x'] is refused: must be a string"),
    (GOOD.replace('"ok"', "3"), "name: 3 is refused: must be a string"),
    (GOOD.replace('"ok"', '"flat"'), "name: 'flat' is refused: the name of a built-in shape"),
    (GOOD.replace('"ok"', '"../../etc"'), "name: '../../etc' is refused"),
    (GOOD.replace("default = 1.0", "default = 20.0"),
     "parameters.gamma.default: 20.0 is refused: outside the range [0.1, 10.0]"),
    (GOOD.replace("default = 1.0", 'default = "1"'), "parameters.gamma.default: '1' is refused"),
    (GOOD.replace("default = 1.0", "default = true"), "parameters.gamma.default: True is refused"),
    (GOOD.replace("default = 1.0, ", ""), "parameters.gamma: 'default' is refused: missing"),
    (GOOD.replace("[0.1, 10.0]", "[10.0, 0.1]"), "parameters.gamma.range"),
    (GOOD.replace("[0.1, 10.0]", '"0..10"'), "parameters.gamma.range: '0..10' is refused"),
    (GOOD.replace("[0.1, 10.0]", "[0.1, nan]"), "parameters.gamma.range"),
    (GOOD.replace("gamma = {", "x = {"), "parameters: 'x' is refused: a reserved name"),
    (GOOD.replace("gamma = {", "__class__ = {"), "'__class__' is refused: a parameter name"),
    (GOOD.replace("[parameters]\n", "").replace("gamma = {", "parameters = {gamma = {")
     .replace("] }", "] }}"), None),  # the same table written inline: accepted
    (GOOD.split("[parameters]")[0] + "parameters = 3\n",
     "parameters: 3 is refused: must be a table"),
    (GOOD.split("[parameters]")[0] + "parameters = [1, 2]\n", "must be a table"),
    (GOOD.replace("gamma = { default = 1.0, range = [0.1, 10.0] }", "gamma = 1.0"),
     "parameters.gamma: 1.0 is refused: must be a table"),
    (GOOD + 'exec = "import os"\n', "parameters.exec: 'import os' is refused: must be a table"),
    ('wall_ratios = "x"\n' + GOOD, "wall_ratios: 'x' is refused: must be a list of strings"),
    ("this is not TOML at all", "not TOML"),
    ('name = "a"\nname = "b"\n', "not TOML"),  # a key given twice
    ('name = "a"\n[[potential]]\nx = 1\n', "potential: [{'x': 1}] is refused: must be a string"),
    ("", "key: 'name' is refused: missing"),  # an empty file
    ('name = "\xff"\n'.encode("latin-1"), "not UTF-8 text"),
    (b"\xff\xfe" + GOOD.encode("utf-16-le"), "not UTF-8 text"),
]  # fmt: skip


@pytest.mark.parametrize("text,reason", HOSTILE_FILES)
def test_hostile_well_file_is_refused_with_its_reason(text, reason, tmp_path, nothing_runs):
    if isinstance(text, str):
        text = text.replace("MARKER", str(nothing_runs[0]))
    path = _file(tmp_path, text)
    if reason is None:
        assert load_well(path).parameter_names == ("gamma",)
        return
    with pytest.raises(WellDefinitionError) as info:
        load_well(path)
    message = str(info.value)
    assert reason in message, message
    assert "\n" not in message and message.startswith("hostile.toml")


def test_a_ten_megabyte_file_is_refused_before_it_is_parsed(tmp_path, nothing_runs):
    path = _file(tmp_path, GOOD + "# " + "x" * (10 * 2**20) + "\n")
    with pytest.raises(WellDefinitionError, match=f"larger than {MAX_FILE_BYTES} bytes"):
        load_well(path)


def test_a_missing_file_and_a_directory_are_refused(tmp_path):
    with pytest.raises(WellDefinitionError, match="cannot be read"):
        load_well(tmp_path / "nowhere.toml")
    with pytest.raises(WellDefinitionError, match="cannot be read"):
        load_well(tmp_path)


def test_the_good_file_loads(tmp_path, nothing_runs):
    well = load_well(_file(tmp_path, GOOD))
    assert well.name == "ok" and well.parameters[0].range == (0.1, 10.0)


def test_a_hostile_sympy_expression_is_refused_too():
    import sympy as sp

    x = sp.Symbol("x")
    for expr, reason in [
        (sp.Function("f")(x), "'f' is refused"),
        (sp.besselj(0, x), "not arithmetic"),
        (sp.Integral(x, x), "not arithmetic"),
        (x + sp.I, "not arithmetic"),
        (x + sp.oo, "not finite"),
        (x + sp.Symbol("os"), "'os' is refused: a symbol that is not declared"),
        (x ** (10**10), "an exponent of size > 2000"),
    ]:
        with pytest.raises(WellDefinitionError, match=reason):
            UserWell("u", expr, {})
    with pytest.raises(WellDefinitionError, match="must be a string or SymPy expression"):
        UserWell("u", lambda: 0, {})

    class Evil(sp.exp):  # would print itself as code when kernels are printed
        def _numpycode(self, printer):
            return "__import__('os').getpid()"

    with pytest.raises(WellDefinitionError, match="'Evil' is refused: a class defined outside"):
        UserWell("u", Evil(x) + x**2, {})
    assert UserWell("u", sp.exp(1) * x**2 + sp.pi * sp.Symbol("y") ** 2, {}).potential.has(sp.E)


# --- fuzzing: any text either parses or is refused with a WellDefinitionError ------------
_PIECES = ["x", "y", "a", "2", "0.5", "1e3", "+", "-", "*", "/", "**", "(", ")", "exp(", "log(",
           "sqrt(", "Abs(", ",", ".", "[", "]", "'", "lambda", ":", "__import__", " ", "os",
           "_", "=", "1j", "9**9**9", "\\", "\n", "\x00", "é", "{", "}", "@"]  # fmt: skip


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(_PIECES), max_size=30).map("".join) | st.text(max_size=60))
def test_any_text_parses_or_is_refused_with_one_line(text):
    try:
        expr = parse_potential(text, ("a",))
    except WellDefinitionError as error:
        assert "\n" not in str(error) and str(error).startswith("potential: ")
    else:
        assert expr.free_symbols <= set(parse_potential("a + x + y", ("a",)).free_symbols)


def _grammar():
    """(text, sympy expression) pairs built from the accepted grammar."""
    import sympy as sp

    x, y = sp.symbols("x y", real=True)
    leaves = st.sampled_from(
        [("x", x), ("y", y), ("2", sp.Integer(2)), ("0.25", sp.Rational(1, 4))]
    )

    def grow(children):
        binary = st.tuples(children, st.sampled_from("+-*"), children).map(
            lambda t: (
                f"({t[0][0]}) {t[1]} ({t[2][0]})",
                {"+": t[0][1] + t[2][1], "-": t[0][1] - t[2][1], "*": t[0][1] * t[2][1]}[t[1]],
            )  # fmt: skip
        )
        calls = st.tuples(st.sampled_from(["exp", "sin", "cosh", "Abs"]), children).map(
            lambda t: (f"{t[0]}({t[1][0]})", getattr(sp, t[0])(t[1][1]))
        )
        powers = st.tuples(children, st.integers(0, 4)).map(
            lambda t: (f"({t[0][0]})**{t[1]}", t[0][1] ** t[1])
        )
        return binary | calls | powers

    return st.recursive(leaves, grow, max_leaves=8)


@settings(max_examples=100, deadline=None)
@given(_grammar())
def test_the_parser_builds_what_sympy_builds(pair):
    import sympy as sp

    text, expected = pair
    built = parse_potential(text, ())
    x, y = sp.symbols("x y", real=True)
    point = {x: sp.Rational(3, 7), y: -sp.Rational(2, 5)}
    value = sp.N(expected.subs(point), 30)
    # both exact; compared at 30 digits to 1e-25 relative (SymPy may order them apart)
    assert abs(sp.N(built.subs(point), 30) - value) <= 1e-25 * (1 + abs(value))
