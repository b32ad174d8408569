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

from importlib.metadata import PackageNotFoundError, version

from .errors import NumericalError, ParameterError
from .model import RunSettings, Sink, Well

try:
    __version__ = version("sinktheory")
except PackageNotFoundError:  # running from a source tree that is not installed
    __version__ = "0.1.0"

__all__ = ["NumericalError", "ParameterError", "RunSettings", "Sink", "Well", "__version__"]
