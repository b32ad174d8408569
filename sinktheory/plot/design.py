"""Charts of a design sweep: heat maps over pairs of parameters and the Pareto chart.

matplotlib is imported inside the functions only (the rest of the design package does
not need it).  Every function returns a :class:`matplotlib.figure.Figure` (no pyplot
state), saved by the caller or by :func:`sinktheory.design.report.write_report`.

Heat maps show, for each pair of swept parameters, the best value over the other swept
parameters of three measures: the long-time depth of absorption (largest), the
first-passage time t50 to 50 % absorbed (smallest; blank where never reached) and the
run-to-run spread relative to E0 (smallest), and when the contact damping is swept the
equivalent damping ratio zeta_eq of the container (largest).  Every parameter is drawn as
a category (its values in order), so shape and numbers mix freely.

Examples
--------
>>> import numpy as np, xarray as xr
>>> ds = xr.Dataset(
...     {"depth": (("beta", "n"), np.array([[0.5, 0.6], [0.7, 0.4]])),
...      "passage": (("beta", "n", "level"), np.full((2, 2, 2), 10.0)),
...      "spread": (("beta", "n"), np.full((2, 2), 0.01)),
...      "done": (("beta", "n"), np.ones((2, 2), bool))},
...     coords={"beta": [0.1, 0.3], "n": [4, 6], "level": [0.5, 0.8]},
...     attrs={"container_energy": 0.5})
>>> {name: f.axes[0].get_title() for name, f in heatmaps(ds).items()}
{'heatmap_beta_n.png': 'depth (max)'}
"""

from __future__ import annotations

from itertools import combinations

import numpy as np

__all__ = ["HEAT", "label", "ZETA"]


def swept(ds) -> list[str]:
    """Swept parameters of a design dataset (the dimensions of ``done``)."""
    return list(ds.done.dims)


def label(value) -> str:
    """A parameter value as a person would type it (floats without round-off).

    Examples
    --------
    >>> label(-0.5 + 0.09), label(np.float64(0.4)), label("flat"), label(5)
    ('-0.41', '0.4', 'flat', '5')
    """
    if isinstance(value, float | np.floating):
        return f"{float(value):g}"
    return str(value)


#: (title, how to make the measure from the dataset, reduce with "max" or "min", colormap)
HEAT = (
    ("depth (max)", lambda ds: ds.depth, "max", "viridis"),
    ("$t_{50}$ / T (min)", lambda ds: ds.passage.sel(level=0.5), "min", "viridis_r"),
    ("spread / $E_0$ (min)", lambda ds: ds.spread / _e0(ds), "min", "magma_r"),
)
#: The fourth panel when the contact damping is swept: the equivalent damping ratio.
ZETA = ("$\\zeta_{eq}$ (max)", lambda ds: ds.zeta_eq, "max", "cividis")


def panels(ds) -> tuple:
    """The measures drawn: :data:`HEAT`, and :data:`ZETA` when ``damping`` is swept."""
    return HEAT + (ZETA,) if "damping" in swept(ds) and "zeta_eq" in ds else HEAT


def _e0(ds):
    if "container_energy" in ds.coords:
        return ds.container_energy
    return float(ds.attrs["container_energy"])


def heatmap(ds, x: str, y: str | None = None):
    """Heat maps of the measures (:func:`panels`) over ``x`` (columns) and ``y`` (rows,
    optional).

    Other swept parameters are reduced to their best value; points not done are blank.
    """
    from matplotlib import patheffects
    from matplotlib.figure import Figure

    outline = [patheffects.withStroke(linewidth=2, foreground="w")]
    mask = ds.done
    others = [d for d in swept(ds) if d not in (x, y)]
    drawn = panels(ds)
    fig = Figure(figsize=(4.2 * len(drawn), 3.6), layout="constrained")
    axes = fig.subplots(1, len(drawn))
    for ax, (title, make, how, cmap) in zip(axes, drawn, strict=True):
        da = make(ds).where(mask)
        if others:
            da = getattr(da, how)(dim=others, skipna=True)
        da = da.transpose(*([y] if y else []), x) if y else da
        values = np.asarray(da.values, dtype=float)
        if values.ndim == 1:
            values = values[None, :]
        im = ax.imshow(np.ma.masked_invalid(values), origin="lower", aspect="auto", cmap=cmap)
        fig.colorbar(im, ax=ax, shrink=0.85)
        ax.set_xticks(range(ds[x].size), [label(v) for v in ds[x].values])
        ax.set_xlabel(x)
        if y:
            ax.set_yticks(range(ds[y].size), [label(v) for v in ds[y].values])
            ax.set_ylabel(y)
        else:
            ax.set_yticks([])
        for (i, j), val in np.ndenumerate(values):
            if np.isfinite(val) and values.size <= 64:
                ax.text(
                    j, i, f"{val:.3g}", ha="center", va="center", fontsize=7, path_effects=outline
                )
        if not np.isfinite(values).any():
            ax.text(0.5, 0.5, "never reached", transform=ax.transAxes, ha="center")
        ax.set_title(title)
    rest = f"; best over {', '.join(others)}" if others else ""
    fig.suptitle(f"Design measures over {x}" + (f" and {y}" if y else "") + rest)
    return fig


def heatmaps(ds) -> dict:
    """One :func:`heatmap` per pair of swept parameters (one strip if only one is swept),
    as file name ``heatmap_<y>_<x>.png`` -> figure."""
    dims = swept(ds)
    if len(dims) == 1:
        return {f"heatmap_{dims[0]}.png": heatmap(ds, dims[0])}
    return {f"heatmap_{y}_{x}.png": heatmap(ds, x, y) for y, x in combinations(dims, 2)}


def pareto_chart(ranked: list, energy_label: str = "$E_0$"):
    """Speed (t50) against depth, coloured by reliability (spread / E0); the Pareto front
    circled and joined, error bars the standard errors.

    ``ranked`` is :func:`sinktheory.design.ranking.rank` of the sweep.  Designs that never
    reach 50 % absorbed are drawn at the right edge with an open marker; they rank after
    every design that does, so they are on the front only if no design reaches 50 %.
    """
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.5, 5), layout="constrained")
    ax = fig.subplots()
    if not ranked:
        ax.set_title("no design computed")
        return fig
    t = np.array([r[("passage", 0.5)] for r in ranked])
    t_se = np.array([r[("passage_se", 0.5)] for r in ranked])
    d = np.array([r["depth"] for r in ranked])
    d_se = np.array([r["depth_se"] for r in ranked])
    s = np.array([r["rel_spread"] for r in ranked])
    front = np.array([r["layer"] == 1 for r in ranked])
    reached = np.isfinite(t)
    edge = (np.nanmax(t) * 1.15 if reached.any() else 1.0) or 1.0
    tx = np.where(reached, t, edge)
    ax.errorbar(
        tx,
        d,
        xerr=np.where(reached & np.isfinite(t_se), t_se, 0),
        yerr=d_se,
        fmt="none",
        ecolor="0.6",
        lw=0.8,
        zorder=1,
    )
    sc = ax.scatter(tx[reached], d[reached], c=s[reached], cmap="magma_r", zorder=2, s=30)
    if (~reached).any():
        ax.scatter(
            tx[~reached],
            d[~reached],
            facecolors="none",
            edgecolors="0.3",
            s=30,
            zorder=2,
            label="never 50 % absorbed (ranked last)",
        )
    if reached.any():
        fig.colorbar(sc, ax=ax, label=f"run-to-run spread / {energy_label}")
    order = np.argsort(tx[front])
    ax.plot(tx[front][order], d[front][order], "-", color="C0", lw=0.8, zorder=1)
    ax.scatter(
        tx[front],
        d[front],
        facecolors="none",
        edgecolors="C0",
        s=110,
        lw=1.2,
        zorder=3,
        label="Pareto front (speed, depth, reliability)",
    )
    for r, x, y in zip(ranked[:5], tx[:5], d[:5], strict=False):
        ax.annotate(f"#{r['rank']}", (x, y), textcoords="offset points", xytext=(5, 4), fontsize=8)
    ax.set_xlabel("$t_{50}$ / T: first period with $\\langle E\\rangle < E_0/2$ (faster: left)")
    ax.set_ylabel("depth: long-time fraction of $E_0$ absorbed")
    ax.legend(loc="lower right", fontsize=8)
    ax.set_title("Speed against depth of absorption against reliability")
    return fig


def energy_curves(ds, ranked: list, top: int = 5):
    """<E>(jT) +- standard error of the ``top`` ranked designs."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.5, 4.5), layout="constrained")
    ax = fig.subplots()
    for r in ranked[:top]:
        where = {d: r[d] for d in swept(ds)}
        p = ds.sel(where)
        m, se = p.mean_energy.values, p.stderr.values
        t = p.period.values
        line = ax.plot(t, m, lw=0.8, label=f"#{r['rank']}: " + _describe(r, swept(ds)))[0]
        ax.fill_between(t, m - se, m + se, color=line.get_color(), alpha=0.2, lw=0)
    ax.set_xlabel("$t/T$")
    ax.set_ylabel("$\\langle E\\rangle$")
    ax.set_title("Container energy of the recommended designs (band: $\\pm$ s.e.)")
    ax.legend(fontsize=7)
    return fig


def _describe(row: dict, dims: list[str]) -> str:
    return ", ".join(f"{d} = {label(row[d])}" for d in dims) or "the design"
