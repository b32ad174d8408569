"""The top-level API: ``import sinktheory as st`` gives the verbs, results and errors."""

import subprocess
import sys

import pytest

import sinktheory as st


def test_importing_the_package_loads_neither_numba_nor_sympy():
    code = (
        "import sys, sinktheory; print(sorted(m for m in ('numba', 'sympy') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


@pytest.mark.parametrize("name", st.__all__)
def test_every_public_name_exists(name):
    assert getattr(st, name) is not None
    assert name in dir(st)


def test_verbs_are_callable_modules_that_stay_modules():
    import sinktheory.simulate as module

    assert st.simulate is module and callable(st.simulate)
    sink = st.Sink(st.Well(0.5, 0.3, 4), particles=1, mass=0.2)
    settings = st.RunSettings(runs=2, periods=2, seed=3)
    direct = module.simulate(sink, settings)
    np_equal = (st.simulate(sink, settings).container_energy == direct.container_energy).all()
    assert np_equal  # the same seeded runs, bitwise
    assert isinstance(direct, st.SimulationResult)


def test_errors_keep_their_old_import_paths():
    from sinktheory.adaptive import StepControlError
    from sinktheory.hill import HillIntegrationError
    from sinktheory.nnm.shooting import ShootingError
    from sinktheory.oscillator import PeriodOutOfRangeError
    from sinktheory.sweep.runner import SweepPointError

    for error in (StepControlError, HillIntegrationError, ShootingError,
                  PeriodOutOfRangeError, SweepPointError):  # fmt: skip
        assert error is getattr(st, error.__name__)
        assert issubclass(error, st.NumericalError)


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'simulat'"):
        st.simulat  # noqa: B018


def _public_modules():
    import pkgutil

    for info in pkgutil.walk_packages(st.__path__, "sinktheory."):
        parts = info.name.split(".")
        if not any(p.startswith("_") for p in parts[1:]):
            yield info.name


@pytest.mark.parametrize("name", sorted(_public_modules()))
def test_every_public_module_declares_what_it_exports(name):
    import importlib

    module = importlib.import_module(name)
    assert isinstance(getattr(module, "__all__", None), list), f"{name} has no __all__"
    missing = [n for n in module.__all__ if not hasattr(module, n)]
    assert not missing, f"{name}.__all__ names what it lacks: {missing}"
