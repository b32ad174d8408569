"""The triangle-wave series against the exact power-law oscillator (paper Sec. 3).

Examples
--------
>>> fig = plot_series(3, 2, points=51)
>>> [ax.get_ylabel() for ax in fig.axes]
['$x$', '$|U_i - x| / A_0$']
"""

from __future__ import annotations

import numpy as np

from .. import validation as v
from ..oscillator import exact_shape, period, triangle_wave
from ..series import triangle_series

__all__ = ["plot_series"]


def plot_series(n: int, order: int, *, points: int = 801):
    """Exact x(t) and the approximations U_1 ... U_order over one period, with errors.

    Amplitude A0 = 1, phase convention ``start="zero"`` (the paper's tau(0) = 0).  Every
    approximation is drawn on the exact period T_n (its own period error is listed by
    :func:`sinktheory.series.error_table`), so the lower panel shows the shape error |U_i - x|.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    series = triangle_series(n, order)
    points = v.positive_int("points", points, minimum=3, maximum=10**6)
    t_n = float(period(series.n, amplitude=1, dps=20))
    t = np.linspace(0.0, t_n, points)
    tau = triangle_wave(t / t_n)
    exact = exact_shape(tau, series.n)
    fig = Figure(figsize=(8, 7), layout="constrained")
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(t, exact, color="black", lw=2.5, label="exact")
    for i in range(1, series.order + 1):
        u = series.shape(tau, i)
        top.plot(t, u, lw=1, label=f"$U_{{{i}}}$")
        with np.errstate(divide="ignore"):
            bottom.semilogy(t, np.abs(u - exact), lw=1, label=f"$i = {i}$")
    top.set_ylabel("$x$")
    top.set_title(f"$\\ddot x + x^{{{2 * series.n - 1}}} = 0$, $A_0 = 1$, $T_n = {t_n:.6g}$")
    top.legend(ncol=2, fontsize="small")
    bottom.set_xlabel("$t$")
    bottom.set_ylabel("$|U_i - x| / A_0$")
    bottom.set_ylim(bottom=1e-12)
    bottom.legend(ncol=2, fontsize="small")
    return fig
