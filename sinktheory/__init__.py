"""sinktheory: the stochastic energy sink of Pilipchuk (arXiv:1610.02939).

A massive container on a spring drains its energy into a few light particles bouncing in
a soft-wall potential well, with no damping at all.  The package derives the model
symbolically (:mod:`sinktheory.symbolic`), prints numerical kernels from it
(:mod:`sinktheory._generated`) and builds analyses on top of validated parameters
(:mod:`sinktheory.model`).

Examples
--------
>>> import sinktheory as st
>>> st.Well(alpha=0.5, beta=0.3, n=10).curvature_at_centre
0.6
"""

from importlib import import_module

from .errors import NumericalError, ParameterError

#: Loaded on first use, so ``import sinktheory`` (and ``sinktheory --version``) stays light.
_LAZY = {"RunSettings": "model", "Sink": "model", "Well": "model"}


def __getattr__(name: str):
    if name in _LAZY:
        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    if name == "__version__":
        from importlib.metadata import PackageNotFoundError, version

        try:
            return version("sinktheory")
        except PackageNotFoundError:  # running from a source tree that is not installed
            return "0.1.0"
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted([*globals(), *_LAZY, "__version__"])


__all__ = ["NumericalError", "ParameterError", "RunSettings", "Sink", "Well", "__version__"]
