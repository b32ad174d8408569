"""Every public method with user input is fuzzed (issue 34, item 5).

The property-based test of test_api_fuzz.py for the methods of the public classes
(``_fuzz.public_methods``): on a small valid instance (tests/_fuzz_methods.py), one
argument at a time is replaced by a hostile value; the call must succeed with finite
numbers or raise a ParameterError naming the parameter (one line), or a NumericalError.
The guard fails on a public method that is neither fuzzed (here, or as a bound method in
the hand-written tables) nor pending with its reason.
"""

import inspect

import _fuzz_methods as tables
import numpy as np
import pytest
from _cli import FUZZ_SCALE, HOSTILE, call_hostile, fuzz_one, non_finite
from _fuzz import _arguments, hand_entries, key_of, public_methods, resolved
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

PENDING = {key: why for why, keys in tables.PENDING_BY_REASON.items() for key in keys}
#: Methods the hand-written tables fuzz as bound methods (``law.pdf``).
HAND = {
    f"{key_of(f)}.{f.__name__}"
    for _, f, _ in hand_entries()
    if inspect.ismethod(f) and not inspect.isclass(f.__self__)
}


def _entries() -> list:
    """(method key, class key, method name, valid keyword arguments) of each method fuzzed
    here; its instance is built when first fuzzed."""
    given_arguments, out = tables.arguments(), []
    for key, (cls, name) in sorted(public_methods().items()):
        if key in PENDING or key in HAND or key in tables.KEYWORD_CALLS:
            continue
        function = inspect.getattr_static(cls, name)
        function = getattr(function, "__func__", function)
        valid = _arguments(function, given_arguments.get(key, {}))
        out.append((key, key.rsplit(".", 1)[0], name, valid))
    return out


ENTRIES = _entries()
_INSTANCES = tables.instances()
_BASELINE: dict = {}


def _method(owner, name):
    if owner in tables.FRESH:
        return getattr(tables.FRESH[owner](), name)
    return getattr(resolved({"x": _INSTANCES[owner]})["x"], name)


def _no_nan(value, depth: int = 0) -> str | None:
    """Where ``value`` holds a NaN or a complex number (+-inf allowed), or None."""
    if depth > 4 or isinstance(value, str | bytes):
        return None
    if isinstance(value, list | tuple):
        return next(filter(None, (_no_nan(x, depth + 1) for x in value)), None)
    a = np.asarray(value)
    if a.dtype.kind == "c":
        return f"complex {value!r}"
    if a.dtype.kind == "f" and np.isnan(a).any():
        return f"NaN in {value!r}"
    return None


def _fuzz(key, owner, name, valid, data):
    valid = resolved(valid)
    if key in tables.INFINITE_ANSWER:  # +-inf is the documented answer; NaN never is
        assert _no_nan(_method(owner, name)(**valid)) is None
        argument = data.draw(st.sampled_from(sorted(valid)), label="argument")
        value = data.draw(st.sampled_from(HOSTILE), label="value")
        result = call_hostile(_method(owner, name), valid, argument, value)
        where = _no_nan(result)
        assert where is None, f"{argument} = {value!r} returned {where} silently"
        return
    if key not in _BASELINE:
        _BASELINE[key] = non_finite(_method(owner, name)(**valid))
    fuzz_one(_method(owner, name), valid, data, baseline=_BASELINE[key])


@pytest.mark.parametrize(("key", "owner", "name", "valid"), ENTRIES, ids=[e[0] for e in ENTRIES])
@settings(max_examples=12 * FUZZ_SCALE, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])  # fmt: skip
@given(data=st.data())
def test_every_public_method_raises_only_documented_errors(key, owner, name, valid, data):
    _fuzz(key, owner, name, valid, data)


@pytest.mark.parametrize("key", sorted(tables.KEYWORD_CALLS))
@settings(max_examples=12 * FUZZ_SCALE, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])  # fmt: skip
@given(data=st.data())
def test_keyword_only_methods_raise_only_documented_errors(key, data):
    """Methods taking only ``**given`` (a well's parameters by name): one keyword's value
    replaced by a hostile one, or an unknown keyword added (refused unless the method keeps
    any keyword as metadata)."""
    cls, name = public_methods()[key]
    method = _method(key.rsplit(".", 1)[0], name)
    valid = tables.KEYWORD_CALLS[key]
    baseline = non_finite(method(**valid))
    argument = data.draw(st.sampled_from([*sorted(valid), "not_a_parameter"]), label="argument")
    value = data.draw(st.sampled_from(HOSTILE), label="value")
    result = call_hostile(method, valid, argument, value)
    if argument == "not_a_parameter" and key not in tables.OPEN_KEYWORDS:
        assert result is None, f"the unknown keyword {argument} = {value!r} was accepted"
    where = None if result is None or baseline else non_finite(result)
    assert where is None, f"{argument} = {value!r} returned {where} silently"


def test_every_public_method_is_fuzzed_or_pending():
    """Each public method with user input is fuzzed (here or by hand) or pending with its
    reason; the lists name only public methods, once."""
    public = set(public_methods())
    fuzzed = HAND | {e[0] for e in ENTRIES} | set(tables.KEYWORD_CALLS)
    assert not sorted(public - fuzzed - set(PENDING)), sorted(public - fuzzed - set(PENDING))
    listed = set(PENDING) | set(tables.INFINITE_ANSWER)
    stale = sorted((listed | set(tables.KEYWORD_CALLS)) - public)
    assert not stale, f"listed but not public methods: {stale}"
    assert not sorted(HAND & set(PENDING)), "fuzzed by hand and also pending"


def test_no_method_is_pending():
    assert not PENDING, sorted(PENDING)


def test_named_leaks_of_the_methods():
    """The leaks this fuzz found in methods, each refused naming its parameter."""
    from sinktheory.errors import ParameterError

    for make, name in tables.fixed_leaks():
        with pytest.raises(ParameterError) as info:
            make()
        assert info.value.name == name, (name, str(info.value))
