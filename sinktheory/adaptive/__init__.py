"""An adaptive, time-reversible step for stiff walls (large n): opt-in, ``stepper="adaptive"``.

The fixed step of :func:`sinktheory.simulate.simulate` must resolve every wall contact,
whose duration shrinks like 1/n, in every step, so its steps per period grow like n.
Here each run takes steps of the same symmetric splitting (blanes-moan6 by default) with
its own step h = eps / rho, where rho follows a rate Omega(q, v) through an explicit,
time-reversible controller in the spirit of Hairer & Soederlind (2005, SIAM J. Sci.
Comput. 26, 1838)::

    rho_{n+1/2} - rho_{n-1/2} = dOmega/dt(y_n) (h_{n+1/2} + h_{n-1/2}) / 2,

solved in closed form for rho_{n+1/2}.  Omega sums, per particle, the local frequency
(grad V)^2 / (m V) of the power-law wall, the approach to each wall ratio r_i of the shape,
(v . grad phi_i)^2 / d(w_i)^2 with w_i = abs(r_i), phi_i = w_i^3 / 3 and d = 1/(2n) at the wall
or (1 - w_i) inside (a step covers a fraction of the distance still to go), and the crossing
of the well, v^2 (grad r_i)^2; plus 1 for the container's spring.  The wall ratios and V
are printed from the well's definition (:func:`sinktheory.symbolic.wall_ratios`), so
every registered shape and every user's well works (a user's well measures its layer d,
:meth:`sinktheory.wellat.WellAt.wall_layer`; without wall ratios only the local frequency
and the spring remain); dOmega/dt takes the Hessian the engine prints for the tangent map.

The controller runs on through period ends: a step that a period end falls in is taken in
two parts, the state between them is the period's, and the controller is updated once,
after the second part, so the full steps are those of the reversible sequence
(:func:`controller_steps`).  The final state carries each run's rho and the part of a
step still to take (``SimulationState.controller``), so a run continued from it takes
the steps it would have taken; a run's numbers do not depend on the other runs or on the
thread count (both bitwise; tested).  A run's first rate also counts each particle's
acceleration relative to the container (``start_rate`` of the generated module): started
at rest in a container at its amplitude, the particles' velocities alone give a rate of 1
and a first step of eps, which the wall reached before it ended.  The energy is audited
at every period end as in ``simulate``.

Until issue 34 each period restarted the controller at rho = Omega and cut its last step
to end on the period.  Neither is reversible, and together they made the energy drift by
the same sign in every run, about 6e-10 per period at k = 1, n = 4, eps 0.25: the
command's default failed its 1e-6 audit at period 1579.  The irreversible events left
are the controller's resets (rho below Omega / 2, when Omega changes by a large factor
within a step): about 1e-3 per run-period at n = 4, hundreds at n = 100, where they give
a slow drift.

Accuracy is set by eps directly (no tolerance rule).  Measured largest abs(dH)/H0 on
Fig. 8's ensemble (flat well, alpha 0.5, beta 0.3, 5 particles, m 0.2), n = 4, 8 runs x
4 periods, seeds 0 and 1: eps 0.25: 1.0e-11; 0.2: 2.6e-12; 0.15: 4.7e-13; 0.1: 5.4e-14
(and, before the range was cut, 0.3: 3.2e-11; 0.4: 1.9e-10; 0.5: 8.1e-10).  Halving eps
divides it by about 65, as the scheme's order 6 says.  Over long runs the error grows,
and the range of eps accepted, (0, MAX_EPS], is where 10^4 periods held the default
bound 1e-6 with a margin at n = 4, 10 and 100 (docs/guide/billiard.rst, "Long runs", from
benchmarks/bench_adaptive_drift.py).  These are measurements, not bounds; the audit
checks every run.  Cost: docs/guide/billiard.rst ("Cost against the wall stiffness"):
fewer steps than the fixed step from n ~ 10 on, but a step costs more, and the steps
still grow with n (a particle pressed against a stiff wall vibrates at a frequency
~ sqrt(n), which any soft-wall integrator has to follow) and with the particles' energy
as the sink fills.

Examples
--------
>>> from sinktheory import RunSettings, Sink, Well
>>> sink = Sink(Well(alpha=0.5, beta=0.3, n=4), particles=2, mass=0.2)
>>> res = simulate_adaptive(sink, RunSettings(runs=2, periods=2, seed=1), eps=0.2)
>>> res.container_energy.shape, res.stepper, res.scheme
((2, 3), 'adaptive', 'blanes-moan6')
>>> bool(res.max_relative_energy_error < 1e-8)
True
"""

from __future__ import annotations

import functools
import hashlib
import math
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path

import numpy as np

from .. import validation as v
from ..ensemble import (
    SimulationResult,
    SimulationState,
    engine_name,
    engine_params,
    join_values,
    prepare,
    run_parameters,
    split_values,
)
from ..errors import ParameterError, StepControlError
from ..glossary import renamed
from ..integrators import DEFAULT_SCHEME, get_scheme
from ..limits import DEFAULT_EPS, MAX_EPS
from ..model import RunSettings, Sink, Well
from ..progress import ProgressBar, chunks
from ..stepsize import DEFAULT_TOL, PERIOD, choose
from ..worklimit import check_particle_steps, check_work, ensemble_steps

__all__ = [
    "BLOCK",
    "check_eps",
    "check_work",
    "choose",
    "controller_steps",
    "DEFAULT_EPS",
    "DEFAULT_SCHEME",
    "DEFAULT_TOL",
    "engine_params",
    "estimated_steps",
    "get_scheme",
    "join_values",
    "MAX_EPS",
    "MAX_STEPS",
    "ParameterError",
    "PERIOD",
    "prepare",
    "ProgressBar",
    "RECORDS",
    "run_parameters",
    "RunSettings",
    "simulate_adaptive",
    "SimulationResult",
    "SimulationState",
    "Sink",
    "split_values",
    "StepControlError",
    "v",
]

#: What the adaptive method records (no trajectory: its steps are not on a grid).
RECORDS = ("container", "particles", "final")
#: Steps a run may take in one period before it is stopped (StepControlError).
MAX_STEPS = 1_000_000
#: Runs advanced together (lockstep, each with its own step) in one block.
BLOCK = 16
#: The controller's constants: the inner distance factor b of d = b (1 - w) and the
#: crossing factor c0 (the prototype's choices; phi = w^3 / 3 is written into the kernel).
_B, _C0 = 1.0, 1.0


_TEMPLATE = Path(__file__).with_name("_template.py")
_MARK = "# --- template starts\n"


def check_eps(eps: object, sink: Sink | None = None, total_energy: float | None = None) -> float:
    """eps as a float in (0, MAX_EPS], else ParameterError naming ``eps``; with ``sink``
    and ``total_energy``, also no smaller than the well and energy allow: the estimated
    steps a period (:func:`estimated_steps`, growing like 1 / eps) within
    :data:`MAX_STEPS`, where a run would be stopped anyway (eps = 1e-320 overflowed the
    estimate, 1e-300 was refused naming ``runs``).  The bound is rounded up to three
    digits, so the range quoted is the set allowed.

    Examples
    --------
    >>> check_eps(0.2)
    0.2
    >>> check_eps(2)
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: eps = 2 is not allowed: must be a number in (0, 0.25]
    >>> from sinktheory import Sink, Well
    >>> check_eps(1e-5, Sink(Well(0.5, 0.3, 4)), 0.5)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    sinktheory.errors.ParameterError: eps = 1e-05 is not allowed: must be a number in \
[0.000453, 0.25] for this well and energy (...)
    """
    value = v.finite("eps", eps) if not isinstance(eps, bool) else None
    if value is None or not 0.0 < value <= MAX_EPS:
        raise ParameterError("eps", eps, f"a number in (0, {MAX_EPS:g}]")
    if sink is None:
        return value
    estimate = MAX_EPS * estimated_steps(sink, total_energy, MAX_EPS) / MAX_STEPS
    unit = 10.0 ** (math.floor(math.log10(estimate)) - 2)
    smallest = float(f"{math.ceil(estimate / unit) * unit:.3g}")
    if value < smallest:
        raise ParameterError("eps", eps, f"a number in [{smallest:g}, {MAX_EPS:g}] for this well "
                             f"and energy", why=f"the adaptive step would take over {MAX_STEPS} "
                             "steps a period (estimated)")  # fmt: skip
    return value


# ------------------------------------------------------------------ generated kernels
def _walls_source(definition) -> str:
    """Source of ``walls(x, y, P, r)`` -> (V - V(0, 0), then r, r_x, r_y, r_xx, r_xy, r_yy
    of each wall ratio r of the well), the well's parameters read from column r of the
    parameter table P as the engine takes them (:func:`sinktheory.engine.systems.run_time_symbols`:
    a whole exponent as an integer, its powers through ``ipow``): straight-line code after
    common subexpression elimination in the kernel printer."""
    import sympy as sp

    from .. import symbolic as S
    from ..codegen import kernel_lines
    from ..engine.systems import run_time_symbols

    x, y = S.x, S.y
    V = S.potential(definition)
    centre = V.subs({x: 0, y: 0})
    exprs = [V if centre == 0 else V - centre]
    for r in S.wall_ratios(definition):
        rx, ry = sp.diff(r, x), sp.diff(r, y)
        exprs += [r, rx, ry, sp.diff(rx, x), sp.diff(rx, y), sp.diff(ry, y)]
    symbols = run_time_symbols(definition)
    exprs = [sp.sympify(e).subs(symbols) for e in exprs]
    params = [symbols.get(p, p) for p in definition.parameter_symbols]
    extra = set().union(*(e.free_symbols for e in exprs)) - {x, y, *params}
    if extra:
        raise ValueError(f"well {definition.name!r}: V or its wall ratios use {extra}")
    lines, reduced = kernel_lines(exprs, "c_")
    reads = [f"    {p.name} = int(P[{i}, r])" if p.is_integer else f"    {p.name} = P[{i}, r]"
             for i, p in enumerate(params)]  # fmt: skip
    body = [f"    {s}" for s in lines]
    values = ", ".join(f"float({e})" for e in reduced)
    return (
        f"#: Row of the particle mass in the parameter table.\nMU_ROW = {len(params)}\n\n\n"
        '@numba.njit(cache=True, error_model="numpy")\n'
        "def walls(x, y, P, r):\n"
        '    """V - V(0, 0) and the wall ratios with their first and second derivatives."""\n'
        + "\n".join(reads + body)
        + f"\n    return ({values},)\n"
    )


@functools.cache
def kernels(name: str):
    """The compiled adaptive module of the sink engine ``name`` (a registered shape's
    ``sink_<shape>`` or a user's well's ``well_<digest>``, any n: a run-time value):
    generated and written beside the engine modules on first use, cached by numba
    afterwards."""
    from ..engine.cache import cache_dir, import_generated, load, well_definition

    engine = load(name)
    head = (
        f'"""Adaptive stepper of {name} (generated by sinktheory.adaptive)."""\n'
        "import math\n\nimport numba\nimport numpy as np\n\n"
        "from sinktheory._generated._support import ipow\n"
        "from sinktheory.engine.cache import load\n\n"
        f"_engine = load({name!r})\n"
        "accelerations = _engine.accelerations\nhessian = _engine.hessian\n"
        "energies = _engine.energies\nmembers_of = _engine.members_of\n"
        "hessian_rows = _engine.hessian_rows\nSHARED_HESSIAN = _engine.SHARED_HESSIAN\n\n"
    )
    text = (
        head + _walls_source(well_definition(name)) + "\n\n"
        + _TEMPLATE.read_text().split(_MARK)[1]
    )  # fmt: skip
    # the engine's file name carries its own digest: a new engine makes a new module
    digest = hashlib.sha256((Path(engine.__file__).name + text).encode()).hexdigest()[:12]
    path = cache_dir() / f"adaptive_{name}_{digest}.py"
    return import_generated(path, lambda: text, f"sinktheory_{path.stem}")


@renamed(energy="total_energy")
def estimated_steps(sink: Sink, total_energy: float, eps: float) -> int:
    """Steps per period for the work limit at total energy E = ``total_energy``, counted in
    fixed steps: the fixed step's count for tol 1e-8 (:func:`sinktheory.stepsize.choose`)
    times 1.05 (0.25 / eps), above the largest share of it the adaptive step took on average
    over 10^4 periods of Fig. 8's ensemble (1.02 at n = 4, 0.75 at n = 10, less at n = 100:
    its steps grow as the sink fills; the count falls with eps no faster than 1/eps), times
    3 for a step's extra cost (the rate: 2.6-2.8x a fixed step's time, measured).  An upper
    estimate where it was measured, several times too high at n = 100 and over short runs.

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> estimated_steps(Sink(Well(0.5, 0.3, 4), particles=5, mass=0.2), 0.5, 0.25)
    3771
    """
    eps = check_eps(eps)
    fixed = choose(sink, total_energy, DEFAULT_TOL, DEFAULT_SCHEME).steps_per_period
    return max(1, math.ceil(fixed * 3 * 1.05 * 0.25 / eps))


def _scheme_arrays(scheme: str) -> tuple[np.ndarray, np.ndarray]:
    A, Bk = get_scheme(scheme).arrays()
    return np.ascontiguousarray(A, dtype=float), np.ascontiguousarray(Bk, dtype=float)


def _control(eps: float, sink: Sink) -> tuple[float, float, float, float]:
    """The controller's constants (eps, wall layer, b, c0) as the kernels take them: the
    layer is 1/(2n) for a registered shape, the measured one of a user's well
    (:meth:`sinktheory.wellat.WellAt.wall_layer`)."""
    w = sink.well
    return (eps, 1.0 / (2 * w.n) if isinstance(w, Well) else w.wall_layer(), _B, _C0)


def _engine_state(sink: Sink, values: np.ndarray):
    """(module, q, v, parameter table) of state rows (R, 2 + 4k)."""
    module = kernels(engine_name(sink))
    q, vel = (np.ascontiguousarray(a) for a in split_values(np.asarray(values, dtype=float)))
    return module, q, vel, module._engine.table_of(engine_params(sink), q.shape[1])


def controller_steps(
    sink: Sink,
    values: np.ndarray,
    count: int,
    *,
    eps: float = DEFAULT_EPS,
    rho: np.ndarray | None = None,
    scheme: str = DEFAULT_SCHEME,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``count`` steps of the controller and the splitting from state rows ``values``
    (R, 2 + 4k), without the period cut: (values, the rates rho the last step used, the
    rates for the next step, each run's controller resets).  ``rho`` None starts from
    Omega (as a period does).

    The sequence is time-reversible: flipping the velocities of the result and taking
    ``count`` steps from the rates the last step used returns to the start (up to
    round-off amplified by the dynamics), unless the controller was reset on the way
    (rho fell below Omega / 2, when Omega changes by a large factor within a step: about
    once in 300 periods of a run of Fig. 8's ensemble at n = 4, eps 0.25, 130 times a
    period at n = 100; ``simulate_adaptive`` reports the count in its message).

    Examples
    --------
    >>> from sinktheory import Sink, Well
    >>> from sinktheory.layout import StateLayout
    >>> from sinktheory.ensemble import start_state
    >>> sink = Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2)
    >>> y0 = start_state(sink, 0.5, np.array([[[0.003, -0.004]]]))
    >>> flip = StateLayout(1).v
    >>> y1, used, _, resets = controller_steps(sink, y0, 200, eps=0.2, rho=[20.0])
    >>> y1[:, flip] *= -1
    >>> back, _, _, resets_back = controller_steps(sink, y1, 200, eps=0.2, rho=used)
    >>> back[:, flip] *= -1
    >>> bool(np.abs(back - y0).max() < 1e-12), resets, resets_back
    (True, array([0]), array([0]))
    """
    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    eps = check_eps(eps)
    count = v.positive_int("count", count)
    width = 2 + 4 * sink.particles
    allowed = f"finite state rows of shape (R, {width}), R >= 1"
    rows = v.real_array("values", values, allowed)
    if rows.ndim != 2 or rows.shape[1] != width or not len(rows):
        raise ParameterError("values", f"an array of shape {rows.shape}", allowed)
    if not np.isfinite(rows).all():
        raise ParameterError("values", "non-finite values", allowed)
    runs = len(rows)
    check_particle_steps("count", count, ensemble_steps(runs, 2.0 * count, sink.particles,
                                                        scheme=get_scheme(scheme).name),
                         f"{count} step(s) x {runs} run(s) x {sink.particles} particle(s) at "
                         "2 particle steps each (estimated_steps)")  # fmt: skip
    module, q, vel, table = _engine_state(sink, rows)
    A, Bk = _scheme_arrays(scheme)
    ctl = _control(eps, sink)
    if rho is None:
        rho = module.rate_of(q, vel, table, ctl)
    allowed = f"{runs} finite rates > 0, one per run"
    rho = np.array(v.real_array("rho", rho, allowed), dtype=float)
    if rho.shape != (runs,):
        raise ParameterError("rho", f"an array of shape {rho.shape}", allowed)
    if not (np.isfinite(rho) & (rho > 0)).all():
        raise ParameterError(
            "rho", rho.tolist() if runs <= 4 else "some not finite or <= 0", allowed
        )
    resets = np.zeros(q.shape[1], dtype=np.int64)
    used = module.steps(q, vel, table, A, Bk, ctl, rho, count, resets)
    return join_values(q, vel), used, rho, resets


def simulate_adaptive(
    sink: Sink,
    settings: RunSettings | None = None,
    *,
    eps: float = DEFAULT_EPS,
    scheme: str = DEFAULT_SCHEME,
    record: Sequence[str] = ("container",),
    initial: np.ndarray | None = None,
    initial_state=None,
    energy_bound: float | None = None,
    progress: bool | None = None,
):
    """:func:`sinktheory.simulate.simulate` with the adaptive step (``stepper="adaptive"``
    there calls this).

    Parameters as in ``simulate``, and:

    eps : float in (0, MAX_EPS] = (0, 0.25]
        Step factor, h = eps / rho (default :data:`DEFAULT_EPS` = 0.25; the energy error
        it gives is measured in the module docstring), no smaller than the well and energy
        allow (:func:`check_eps`).
    scheme : str
        Splitting scheme of each step (default blanes-moan6).
    record : subset of {"container", "particles", "final"}
        No trajectory (the steps are not on a grid).

    Returns a :class:`~sinktheory.simulate.SimulationResult` with method "adaptive",
    steps_per_period the mean over runs and periods, dt = T / that mean.

    Raises ParameterError for bad input, EnergyDriftError / NonFiniteStateError naming
    the run and the time as ``simulate`` does, and StepControlError when a run needs more
    than :data:`MAX_STEPS` steps in a period.

    Examples
    --------
    >>> from sinktheory import RunSettings, Sink, Well
    >>> sink = Sink(Well(alpha=0.5, beta=0.3, n=4), particles=1, mass=0.2)
    >>> res = simulate_adaptive(sink, RunSettings(runs=1, periods=1), initial=[(0.0, 0.01)],
    ...                         record=("container", "final"), eps=0.15)
    >>> res.final_state.stepper, res.message.split(":")[0]
    ('adaptive', '1 run(s) x 1 period(s), adaptive blanes-moan6, eps = 0.15')
    """
    eps = check_eps(eps)
    scheme = get_scheme(scheme).name
    begun = prepare(sink, settings, record, initial=initial, initial_state=initial_state,
                    energy_bound=energy_bound, allowed=RECORDS)  # fmt: skip
    settings, record, bound, values = begun.settings, begun.record, begun.bound, begun.values
    t0, h0, runs, periods = begun.time, begun.reference_energy, begun.runs, settings.periods
    energy = float(np.max(h0))
    check_eps(eps, sink, energy)
    check_work(replace(settings, runs=runs), sink, estimated_steps(sink, energy, eps), scheme)
    module, q, vel, table = _engine_state(sink, values)
    ctl = _control(eps, sink)
    rho, rem = _carried(initial_state, runs)
    if rho is None:  # a fresh start: the controller begins at the rate, with a whole step
        rho, rem = module.start_rate(q, vel, table, ctl), np.zeros(runs)
    K = sink.particles
    shared = np.zeros((runs, periods + 1 if "container" in record else 0))
    members = np.zeros((runs, periods + 1 if "particles" in record else 0, K))
    total0, shared0, members0 = module._engine.block_energies(q, vel, table)
    if shared.size:
        shared[:, 0] = shared0
    if members.size:
        members[:, 0] = members0.T
    taken = np.zeros(runs, dtype=np.int64)
    resets = np.zeros(runs, dtype=np.int64)
    status = np.zeros(runs, dtype=np.int64)
    fail_period, fail_energy, worst = np.zeros(runs, dtype=np.int64), np.zeros(runs), np.zeros(runs)
    audit = (np.ascontiguousarray(h0, dtype=float), bound, status, fail_period, fail_energy, worst)
    fixed = (*_scheme_arrays(scheme), ctl, PERIOD, MAX_STEPS)
    chunk = max(1, math.ceil(periods / 100))
    bar = ProgressBar(periods, enabled=progress is not False, label="adaptive ", unit="period")
    try:
        for start, stop in chunks(periods, most=chunk):  # interrupts between chunks
            module.advance(q, vel, table, fixed, start, stop, BLOCK, audit,
                           (shared, members, taken, resets, rho, rem))  # fmt: skip
            _raise_on_failure(status, fail_period, fail_energy, h0, t0, bound)
            bar.update(stop - start)
    finally:
        bar.close()
    values = join_values(q, vel)
    mean_steps = taken.sum() / (runs * periods) if periods else 0.0
    dt = PERIOD / mean_steps if mean_steps else PERIOD
    worst_all = float(worst.max()) if runs else 0.0
    return SimulationResult(
        times=t0 + PERIOD * np.arange(periods + 1),
        container_energy=shared if "container" in record else None,
        particle_energy=members if "particles" in record else None,
        trajectory=None,
        trajectory_times=None,
        final_state=SimulationState(
            values, t0 + periods * PERIOD, h0, dt, scheme, np.column_stack([rho, rem]), "adaptive"
        )  # fmt: skip
        if "final" in record
        else None,
        initial_energy=h0,
        run_errors=worst,
        max_relative_energy_error=worst_all,
        stepper="adaptive",
        scheme=scheme,
        dt=dt,
        steps_per_period=round(mean_steps),
        message=f"{runs} run(s) x {periods} period(s), adaptive {scheme}, eps = {eps:.3g}"
        + f": {mean_steps:.0f} steps per period on average "
        f"({resets.sum() / runs / max(periods, 1):.3g} controller resets), max relative "
        "energy error "
        f"{worst_all:.3g} <= {bound:.3g}",
        parameters=run_parameters(sink, settings, runs),
    )


def _carried(initial_state, runs: int) -> tuple[np.ndarray | None, np.ndarray | None]:
    """(rho, remainder) of each run from an adaptive ``initial_state`` that carries them,
    else (None, None); ParameterError if they are not rates > 0 and remainders >= 0."""
    c = getattr(initial_state, "controller", None)
    if c is None or initial_state.stepper != "adaptive":
        return None, None
    c = np.array(c, dtype=float)
    if (
        c.shape != (runs, 2)
        or not np.all(np.isfinite(c))
        or np.any(c[:, 0] <= 0)
        or np.any(c[:, 1] < 0)
    ):
        raise ParameterError(
            "initial_state",
            "a state whose controller values are not (rho > 0, remainder >= 0) per run",
            "the final_state of an adaptive run, unchanged",
        )
    return np.ascontiguousarray(c[:, 0]), np.ascontiguousarray(c[:, 1])


def _raise_on_failure(status, fail_period, fail_energy, h0, t0, bound) -> None:
    """Raise for the earliest failure (period, then run), whatever the threads."""
    from ..engine.core import audit_error, earliest_failure

    r = earliest_failure(status, fail_period)
    if r is None:
        return
    p = int(fail_period[r])
    where = f"run {r} at t = {t0 + p * PERIOD:.6g} (period {p}, adaptive step)"
    H, H0 = float(fail_energy[r]), float(h0[r])
    if status[r] == 3:  # STALLED
        raise StepControlError(
            f"{where}: more than {MAX_STEPS} steps in one period (H = {H!r}, H0 = {H0!r}); "
            "the rate Omega grew without bound"
        )
    raise audit_error(where, status[r] == 2, H, H0, bound,  # 2: NONFINITE
                      ("use a smaller eps", "use a smaller eps or tolerance"))  # fmt: skip
