"""Pure-Python twins of the generated numba kernels, for light single-point work.

The first call of a compiled kernel in a process costs about half a second (numba loads
its compiler and target); a light command such as ``sinktheory well`` or a one-point
``sinktheory floquet`` should not pay it.  :func:`python_kernel` runs the very same
generated code by Python instead: no formula is retyped.
"""

from __future__ import annotations

import types as pytypes

__all__: list[str] = []  # python_kernel is the package's own (model, equilibrium)


def python_kernel(kernel):
    """The pure-Python twin of a compiled kernel (or of a plain function calling them).

    The kernel's ``py_func`` (or the function itself) with every compiled kernel it
    calls by a global name (``ipow``, ``oscillator_acceleration``) replaced by that
    kernel's twin, so calling it never dispatches to numba: same code, run by Python.

    Examples
    --------
    >>> from sinktheory._generated.shapes import flat
    >>> q = python_kernel(flat.hill_coefficient)
    >>> hasattr(q, "py_func"), q(0.5, 0.5, 0.1, 4) == -2 * 0.1 * 0.4 * 0.5**8
    (False, True)
    """
    func = getattr(kernel, "py_func", kernel)
    if not isinstance(func, pytypes.FunctionType):
        return kernel
    scope = func.__globals__
    twins = {
        name: python_kernel(scope[name])
        for name in func.__code__.co_names
        if hasattr(scope.get(name), "py_func")
    }
    if not twins:
        return func
    return pytypes.FunctionType(
        func.__code__, {**scope, **twins}, func.__name__, func.__defaults__, func.__closure__
    )
