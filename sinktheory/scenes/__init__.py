"""One scene per figure of the paper; :data:`SCENES` maps figure numbers to scenes.

Each scene declares the least model it needs and computes only that (see
:class:`~sinktheory.scenes.base.Scene`).

The catalogue below (figure number -> module, and the measured run time of each figure)
is plain data, so ``sinktheory reproduce --help`` and its refusals read it without
importing a scene module (they pull in numpy, numba and matplotlib); :data:`SCENES` and
:func:`scene` import the modules on first use.

Examples
--------
>>> FIGURES
(2, 3, 4, 5, 7, 8, 9, 10, 11, 12)
>>> scene(7).title
'Floquet stability of the normal mode'
"""

from importlib import import_module

from ..errors import ParameterError

#: The module of each figure's scene (its object is ``FIG<number>`` there).
MODULES = {
    2: "wells",
    3: "orbits",
    4: "trajectories",
    5: "ensembles",
    7: "stability",
    8: "ensembles",
    9: "ensembles",
    10: "wells",
    11: "orbits",
    12: "ensembles",
}
#: The paper's figures that have a scene, in order.
FIGURES = tuple(sorted(MODULES))

#: Seconds of each figure as (quick, paper) fidelity: the CPU seconds (all threads and
#: finished worker processes) printed by ``python benchmarks/bench_reproduce.py --cold``
#: on the project's 2-core machine (AVX-512, warm compilation cache, 2026-11-26), which
#: was never idle that day: paper fidelity 145.4 s of CPU in 222.8 s wall at a load
#: average of 6, quick 10.6 s of CPU in 57.9 s wall at 14.  On 2 idle cores a figure's
#: wall time is at most about its CPU time (less where the kernels' two threads or the
#: sweeps' two workers share the work: Fig. 9, unchanged since its idle measurement of
#: 1.6 s, shows 2.4 CPU seconds).  ``reproduce`` announces them before each figure as its
#: estimate.  Figs. 5, 8 and 12 re-measured after their horizons changed (the settling
#: times of :mod:`sinktheory.scenes.horizons` measured with several seeds): the CPU seconds
#: ``reproduce --figure 5`` and ``--figure 8 12`` wrote into report.md (load 10-13).
#: Fig. 3 re-measured after its phi = -1 row gained the coupled mode's fine grid: 54.4 CPU
#: seconds from ``reproduce --figure 3`` at load 5-9 (the code of the 37.8 took 45.6 s at
#: load 8 the same hour, so about half of the rise is the load, the rest the code).
SECONDS = {
    2: (0.5, 0.5),
    3: (4.8, 54.4),
    4: (0.2, 0.4),
    5: (0.1, 8.0),
    7: (0.1, 0.1),
    8: (0.4, 65.2),
    9: (0.2, 2.4),
    10: (0.1, 0.1),  # 0.0 s printed; 0.1 s, the resolution, as the estimate
    11: (4.1, 31.9),
    12: (0.2, 4.6),
}


#: The compiled engines each figure runs (:func:`sinktheory.engine.cache.load` names), so
#: that ``reproduce`` can add their compilation to its estimate on a machine that has not
#: compiled them yet (``tests/interface/test_reproduce.py`` checks the table against what each
#: figure loads).
ENGINES = {
    2: (),
    3: ("sink_flat",),
    4: ("sink_flat",),
    5: ("sink_flat",),
    7: (),
    8: ("sink_flat",),
    9: ("sink_flat",),
    10: (),
    11: ("sink_symmetric",),
    12: ("sink_symmetric", "sink_flat"),
}


def _figure(number: int) -> int:
    """``number`` if a figure of the paper has a scene (ParameterError naming it if not)."""
    from ..validation import positive_int

    allowed = "a figure with a scene: " + ", ".join(map(str, FIGURES))
    try:
        figure = positive_int("number", number)
    except ParameterError:
        raise ParameterError("number", number, allowed) from None
    if figure not in MODULES:
        raise ParameterError("number", number, allowed)
    return figure


def scene(number: int):
    """The :class:`~sinktheory.scenes.base.Scene` of figure ``number`` (imported now)."""
    number = _figure(number)
    module = import_module(f".{MODULES[number]}", __name__)
    return getattr(module, f"FIG{number}")


def estimate(number: int, quick: bool) -> float:
    """Expected wall seconds of figure ``number`` (see :data:`SECONDS`) at the fidelity
    ``quick`` (True: ``--quick``) selects."""
    from ..validation import flag

    return SECONDS[_figure(number)][0 if flag("quick", quick) else 1]


_BASE = ("Claim", "Scene", "SceneResult")


def __getattr__(name: str):
    if name == "SCENES":
        return {number: scene(number) for number in FIGURES}
    if name in _BASE:
        return getattr(import_module(".base", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["ENGINES", "FIGURES", "MODULES", "SCENES", "SECONDS", "estimate", "scene", *_BASE]
