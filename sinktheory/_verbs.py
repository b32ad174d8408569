"""Modules that are also verbs: ``st.simulate(...)`` calls the function of the same name.

A package attribute named like one of its submodules is replaced by the submodule as soon
as that submodule is imported (Python binds every loaded submodule on its parent), so the
top-level verbs ``simulate``, ``chaos``, ``bifurcation`` and ``billiard`` cannot be plain
functions there.  Instead each of these modules becomes callable: calling the module calls
its main function, and everything else in it (``st.simulate.SimulationResult``, ``import
sinktheory.simulate as m``, ``mock.patch("sinktheory.simulate.x")``) works as for any module.

Examples
--------
>>> import sinktheory as st
>>> callable(st.simulate), st.simulate.__call__.__doc__.splitlines()[0]
(True, 'Integrate an ensemble of the full container + particles system.')
"""

from __future__ import annotations

import sys
import types


def make_callable(module_name: str, function_name: str) -> None:
    """Let ``module_name`` be called as its function ``function_name`` (module docstring)."""
    module = sys.modules[module_name]

    class VerbModule(types.ModuleType):
        def __call__(self, *args, **kwargs):
            return getattr(self, function_name)(*args, **kwargs)

    VerbModule.__call__.__doc__ = getattr(module, function_name).__doc__
    VerbModule.__name__ = f"VerbModule[{function_name}]"
    module.__class__ = VerbModule
