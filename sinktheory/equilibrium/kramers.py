"""Kramers-Moyal coefficients of the container energy, and the fluctuation-dissipation check.

The reduced model treats E_c as a one-dimensional Markov process on the shell H = E with
drift D1(E_c) and diffusion D2(E_c).  They are measured from short runs started at
prescribed E_c with the rest of the state drawn from the shell's conditional measure
(:mod:`sinktheory.equilibrium.microcanonical`): for a lag of tau periods,

    D1 = <Delta E> / tau,    D2 = <Delta E^2> / (2 tau),    Delta E = E_c(tau) - E_c(0),

with standard errors from the spread over the runs (independent).  :class:`KramersMoyal`
holds every lag asked for, so whether they agree can be seen.  For the Fig. 8 well they do
not at a few periods: E_c moves by ~0.1 (of E = 0.5) within the first period and the
moments then stay on that plateau up to ~8 periods, so <Delta E> / tau falls like 1 / tau
(docs/guide/equilibrium.rst).  With a base lag tau_0 the coefficients come from the
moments' growth after it (:func:`kramers_moyal`), which removes a fast part done by tau_0.
:func:`solve_fokker_planck` turns coefficients into <E_c>(t) and its spread.

The grid
--------
The starting energies are Gauss-Legendre nodes w_i of [0, 1] mapped by
s = E_c / E = 1 - w^n (n the wall exponent): the law's density times ds / dw is
w^(k (n + 1) - 1) times a smooth function of w (:mod:`sinktheory.equilibrium.law`), so
integrals against the law are Gauss-Legendre sums over the grid.

Fluctuation-dissipation
-----------------------
The stationary Fokker-Planck solution is p_s = exp(\\int D1 / D2) / D2 up to a constant,
i.e. D1 p = d(D2 p) / dE with zero flux at the ends.  Its weak form, for test functions
f: \\int p(E) [f'(E) D1(E) + f''(E) D2(E)] dE = 0 (the generator of the Fokker-Planck
equation has p as its invariant density).  :func:`check_fluctuation_dissipation` takes
f_m(E) = P_m(2 E / E_tot - 1) (Legendre, m = 1 .. M), evaluates each integral I_m as the
grid's Gauss sum with the law's density, and forms chi^2 = I^T C^-1 I with C the exact
covariance of the I_m (each is a linear combination of independent run means).  Under the
law and a diffusion, chi^2 ~ chi^2_M.  Note what this tests: stationarity of the law
under the measured increments (the law, the sampler, and jumps small enough for a
second-order expansion at this lag).  A stationary ensemble satisfies it whether or
not E_c is Markov; the Markov property is what the lag dependence of D1, D2 and the
Fokker-Planck prediction of the relaxation test.

Examples
--------
A Jacobi diffusion ds = c (a (1 - s) - b s) dt + sqrt(2 c s (1 - s)) dW has the Beta(a, b)
law as its stationary density; its coefficients come back from simulated increments:

>>> rng = np.random.default_rng(0)
>>> s0 = gauss_grid(8, 1)[0]
>>> inc = jacobi_increments(s0, (1, 2), 4000, rng, a=1.0, b=1.25, c=0.01)
>>> km = kramers_moyal(s0, 1.0, 1, (1, 2), inc)
>>> exact = 0.01 * (1 - s0 - 1.25 * s0)
>>> bool(np.all(np.abs(km.drift[:, 0] - exact) < 4 * km.drift_stderr[:, 0]))
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.polynomial import legendre as L
from scipy import stats

from .. import validation as v
from ..errors import NonFiniteStateError, NumericalError, ParameterError
from ..glossary import old_attribute, renamed
from ..limits import MAX_PERIODS
from ..model import RunSettings, Sink
from ..results import Result
from ..runstats import check_runs
from ..worklimit import check_particle_steps
from .law import EquilibriumLaw
from .microcanonical import shell_states

__all__ = [
    "check_fluctuation_dissipation",
    "FluctuationDissipation",
    "gauss_grid",
    "jacobi_increments",
    "SOLVE_CELLS",
    "kramers_moyal",
    "KramersMoyal",
    "LAGS",
    "measure_kramers_moyal",
    "MAX_CELLS",
    "MAX_POINTS",
    "MAX_SUBSTEPS",
    "TOP_GAP",
    "solve_fokker_planck",
]

#: Default lags (periods) at which the coefficients are estimated.
LAGS = (1, 2, 4, 8)
#: Smallest share of the total energy left to the particles at the top grid point (the top
#: Gauss node of s = 1 - w^n is 1 to rounding for n >= 10).
TOP_GAP = 1e-9
#: Most grid points (the Gauss-Legendre nodes cost points^2 memory; 12 are the default).
MAX_POINTS = 1000
#: Most finite-volume cells of :func:`solve_fokker_planck` (1000 are the default).
MAX_CELLS = 10**6
#: Most implicit Euler steps per period of :func:`solve_fokker_planck` (4 are the default).
MAX_SUBSTEPS = 10**4


def _lags(lags) -> np.ndarray:
    """``lags`` as a 1-d array of integers >= 1 (ParameterError naming ``lags``)."""
    allowed = "a non-empty list of integers >= 1 (periods)"
    values = v.finite_array("lags", lags, allowed)
    if values.ndim > 1 or values.size == 0:
        raise ParameterError("lags", f"an array of shape {values.shape}", allowed)
    return np.array(
        [v.positive_int("lags", x, maximum=MAX_PERIODS) for x in values.ravel()], dtype=int
    )


def gauss_grid(points: int, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(s_i, W_i): s = 1 - w^n at the Gauss-Legendre nodes w of [0, 1], and weights with
    sum_i W_i phi(s_i) ~ \\int_0^1 phi(s) ds (module docstring), s ascending.

    Examples
    --------
    >>> s, W = gauss_grid(12, 4)
    >>> round(float(W @ (1 - s) ** 0.25), 12)  # \\int (1 - s)^(1/4) ds = 0.8
    0.8
    """
    points = v.positive_int("points", points, minimum=2, maximum=MAX_POINTS)
    n = v.positive_int("n", n)
    x, w = L.leggauss(points)
    w_nodes, w_weights = 0.5 * (x + 1), 0.5 * w
    s = 1 - w_nodes**n
    weights = w_weights * n * w_nodes ** (n - 1)
    order = np.argsort(s)
    return s[order], weights[order]


@renamed(energy="total_energy")
@dataclass(frozen=True)
class KramersMoyal(Result):
    """Kramers-Moyal coefficients of E_c on a grid of starting energies (module docstring).

    Attributes
    ----------
    total_energy : the total energy E
    n : the wall exponent the grid was built with (s = 1 - w^n)
    container_energies : starting E_c on the grid (ascending)
    weights : W_i, quadrature weights in s = E_c / E
    lags : lags tau (periods)
    base_lag : tau_0 > 0 when the coefficients are the moments' growth after tau_0
        (:func:`kramers_moyal`), else 0
    runs : runs per grid point
    drift, drift_stderr : D1 = <Delta E> / tau and its standard error, (point, lag)
    diffusion, diffusion_stderr : D2 = <Delta E^2> / (2 tau) and its standard error
    covariance : covariance of the run means of the first and second moments behind D1
        and D2 (before the division by tau - tau_0), (point, lag, 2, 2)
    increments, increment_lags : the runs' Delta E (point, lag, run) at every lag measured
        (tau_0 included), for the exact form of the check
    message : one line on how they were measured
    """

    total_energy: float
    n: int
    container_energies: np.ndarray
    weights: np.ndarray
    lags: np.ndarray
    base_lag: int
    runs: int
    drift: np.ndarray
    drift_stderr: np.ndarray
    diffusion: np.ndarray
    diffusion_stderr: np.ndarray
    covariance: np.ndarray
    increments: np.ndarray
    increment_lags: np.ndarray
    message: str = ""

    DIMS = {
        "container_energies": ("point",),
        "weights": ("point",),
        "lags": ("lag",),
        "drift": ("point", "lag"),
        "drift_stderr": ("point", "lag"),
        "diffusion": ("point", "lag"),
        "diffusion_stderr": ("point", "lag"),
        "covariance": ("point", "lag", "moment", "moment2"),
        "increments": ("point", "increment_lag", "run"),
        "increment_lags": ("increment_lag",),
    }
    COORDS = {"lags": "lag"}

    energy = old_attribute("total_energy")

    def lag_index(self, lag: int | None) -> int:
        """Index of ``lag`` in :attr:`lags` (None: the middle one)."""
        if lag is None:
            return len(self.lags) // 2
        hits = np.flatnonzero(self.lags == v.positive_int("lag", lag))
        if not hits.size:
            raise ParameterError("lag", lag, f"one of the measured lags {self.lags.tolist()}")
        return int(hits[0])

    @property
    def spans(self) -> np.ndarray:
        """tau - tau_0, the time over which each lag's moments grew."""
        return self.lags - self.base_lag


@renamed(energy="total_energy")
def kramers_moyal(s, total_energy: float, n: int, lags, increments, weights=None,
                  base_lag: int = 0, message: str = "") -> KramersMoyal:  # fmt: skip
    """:class:`KramersMoyal` from increments Delta E of shape (point, lag, run) started
    at s = E_c / E (grid of :func:`gauss_grid` with this n, unless ``weights`` given).

    With ``base_lag`` tau_0 (one of ``lags``) the coefficients come from the growth of the
    moments after it, D1 = <Delta E(tau) - Delta E(tau_0)> / (tau - tau_0) and
    D2 = <Delta E(tau)^2 - Delta E(tau_0)^2> / (2 (tau - tau_0)), for the lags tau > tau_0:
    a fast part of the increments that is done by tau_0 (and acts like measurement noise
    on the slow process) cancels.

    Examples
    --------
    >>> inc = np.ones((2, 1, 3))  # every run gains 1 in one period
    >>> km = kramers_moyal([0.2, 0.7], 1.0, 1, [1], inc, weights=[0.5, 0.5])
    >>> km.drift.ravel().tolist(), km.diffusion.ravel().tolist()
    ([1.0, 1.0], [0.5, 0.5])
    >>> inc = np.stack([np.ones((2, 3)), 1 + 0.5 * np.ones((2, 3))], axis=1)  # 1, then 0.5 per lag
    >>> kramers_moyal([0.2, 0.7], 1.0, 1, [1, 2], inc, [0.5, 0.5], base_lag=1).drift.ravel()
    array([0.5, 0.5])
    """
    s = v.finite_array("s", s, "grid energies s = E_c / E: a 1-d array of finite numbers", 1)
    total_energy = v.positive("total_energy", total_energy)
    n = v.positive_int("n", n)
    lags = _lags(lags)
    base_lag = v.positive_int("base_lag", base_lag, minimum=0, maximum=MAX_PERIODS)
    inc = v.real_array("increments", increments)
    if inc.ndim != 3 or inc.shape[:2] != (s.size, lags.size) or inc.shape[2] < 2:
        raise ParameterError(
            "increments", f"an array of shape {inc.shape}",
            f"shape ({s.size}, {lags.size}, runs >= 2): grid point, lag, run",
        )  # fmt: skip
    if not np.all(np.isfinite(inc)):
        raise ParameterError("increments", "non-finite values", "finite numbers")
    if weights is not None:
        weights = v.finite_array("weights", weights, f"{s.size} finite quadrature weights")
        if weights.shape != s.shape:
            raise ParameterError("weights", f"{weights.size} weight(s)", f"{s.size} weights")
    else:
        grid, weights = gauss_grid(s.size, n)
        if not np.allclose(grid, s, rtol=0, atol=1e-12):
            raise ParameterError("s", s.tolist(), f"the Gauss grid of {s.size} points, n = {n}")
    lags_all = lags
    first, second = inc, inc**2
    span = lags
    if base_lag:
        hits = np.flatnonzero(lags == base_lag)
        if not hits.size or base_lag >= lags.max():
            raise ParameterError("base_lag", base_lag, f"one of {lags.tolist()} below the last")
        b, later = hits[0], lags > base_lag
        first = inc[:, later] - inc[:, [b]]
        second = inc[:, later] ** 2 - inc[:, [b]] ** 2
        lags, span = lags[later], lags[later] - base_lag
    runs = inc.shape[2]
    tau = span[None, :]
    pair = np.stack([first, second], axis=-2)  # (point, lag, 2, run)
    m = pair.mean(axis=-1)
    centred = pair - m[..., None]
    cov = np.einsum("...ir,...jr->...ij", centred, centred) / (runs - 1) / runs
    return KramersMoyal(
        total_energy=float(total_energy),
        n=int(n),
        container_energies=total_energy * s,
        weights=np.asarray(weights, dtype=float),
        lags=lags,
        base_lag=int(base_lag),
        runs=runs,
        drift=m[..., 0] / tau,
        drift_stderr=np.sqrt(cov[..., 0, 0]) / tau,
        diffusion=m[..., 1] / (2 * tau),
        diffusion_stderr=np.sqrt(cov[..., 1, 1]) / (2 * tau),
        covariance=cov,
        increments=inc,
        increment_lags=lags_all,
        message=message,
    )


@renamed(energy="total_energy")
def measure_kramers_moyal(
    sink: Sink,
    total_energy: float,
    *,
    points: int = 12,
    lags=LAGS,
    runs: int = 200,
    seed: int = 0,
    tol: float = 1e-6,
    base_lag: int = 0,
) -> KramersMoyal:
    """D1 and D2 of E_c for ``sink`` at total energy E, measured by the simulator.

    At each of ``points`` grid energies (:func:`gauss_grid`), ``runs`` states are drawn
    from the shell given E_c (:func:`~sinktheory.equilibrium.microcanonical.shell_states`,
    one child of ``SeedSequence(seed)`` per point) and integrated max(lags) periods at
    ``tol`` (one ensemble of points x runs; the energy audit applies).

    Parameters
    ----------
    sink : Sink
    total_energy : float
        Total energy E.
    points : int >= 2
    lags : sequence of int >= 1
        Lags tau in periods.
    runs : int >= 2
        Runs per grid point.
    seed : int
    tol : float
        The simulator's energy tolerance.
    base_lag : int
        tau_0 of :func:`kramers_moyal` (0: the moments themselves).

    Returns
    -------
    KramersMoyal

    Examples
    --------
    >>> from sinktheory.model import Sink, Well
    >>> sink = Sink(Well(0.5, 0.3, 4), particles=1, mass=0.2)
    >>> km = measure_kramers_moyal(sink, 0.5, points=3, lags=(1,), runs=4, seed=1)
    >>> km.drift.shape, bool(np.all(km.diffusion > 0))
    ((3, 1), True)
    """
    from ..ensemble import SimulationState
    from ..ensemble import total_energy as energies_of
    from ..simulate import simulate

    if not isinstance(sink, Sink):
        raise ParameterError("sink", sink, "a sinktheory.model.Sink")
    e = v.positive("total_energy", total_energy)
    points = v.positive_int("points", points, minimum=2)
    runs = check_runs("runs", runs)
    seed = v.positive_int("seed", seed, minimum=0)
    lags = set(_lags(lags).tolist())
    base_lag = v.positive_int("base_lag", base_lag, minimum=0, maximum=MAX_PERIODS)
    lags = np.array(sorted(lags | {base_lag} - {0}), dtype=int)
    width = 2 + 4 * sink.particles + int(lags.max()) + 1  # a state and its E_c record
    v.fits_memory("runs", runs, 16.0 * points * runs * width,
                  f"{points} point(s) x {runs} run(s) x {width} numbers", "fewer")  # fmt: skip
    s, weights = gauss_grid(points, sink.well.n)
    s = np.minimum(s, 1 - TOP_GAP)  # 1 - w^n rounds to 1 at the top node of stiff walls
    children = np.random.SeedSequence(seed).spawn(points)
    rows = np.concatenate(
        [shell_states(sink, e, e * si, runs, np.random.default_rng(c))
         for si, c in zip(s, children, strict=True)]
    )  # fmt: skip
    h0 = energies_of(sink, rows)
    state = SimulationState(rows, 0.0, h0, 0.0, "")
    res = simulate(
        sink,
        RunSettings(container_energy=e, runs=rows.shape[0], periods=int(lags.max()), seed=seed),
        tol=tol,
        initial_state=state,
        progress=False,
    )
    ec = res.container_energy.reshape(points, runs, -1)
    inc = np.stack([ec[:, :, lag] - ec[:, :, 0] for lag in lags], axis=1)
    message = (
        f"{points} points x {runs} runs, lags {lags.tolist()} periods, from the shell "
        f"(seed {seed}); {res.message}"
    )
    return kramers_moyal(s, e, sink.well.n, lags, inc, weights=weights, base_lag=base_lag,
                         message=message)  # fmt: skip


@dataclass(frozen=True)
class FluctuationDissipation(Result):
    """The weak-form check of D1 p = d(D2 p)/dE against a law (module docstring).

    Attributes
    ----------
    lag : the lag used (periods)
    tests : M, the number of Legendre test functions
    integrals : I_m = \\int p (f_m' D1 + f_m'' D2) dE, m = 1 .. M
    stderr : their standard errors
    chi2, dof, p_value : chi^2 = I^T C^-1 I, its degrees of freedom M and P(chi^2_M >= chi2)
    scale : \\int p |f_m'| |D1| dE, the size of the terms that must cancel (for reading
        the integrals)
    law_particles, law_beta, law_mean : which law was tested (k, beta, <E_c>)
    """

    lag: int
    tests: int
    integrals: np.ndarray
    stderr: np.ndarray
    chi2: float
    dof: int
    p_value: float
    scale: np.ndarray
    law_particles: int
    law_beta: float
    law_mean: float

    DIMS = {"integrals": ("test",), "stderr": ("test",), "scale": ("test",)}


def check_fluctuation_dissipation(
    km: KramersMoyal,
    law: EquilibriumLaw,
    *,
    lag: int | None = None,
    tests: int = 4,
    exact: bool = False,
) -> FluctuationDissipation:
    """Whether ``law`` is the stationary density of the Fokker-Planck equation with the
    measured D1, D2 at ``lag`` (default the middle lag): chi^2 of the weak form with
    ``tests`` Legendre test functions (module docstring).

    With ``exact`` the integrands are the runs' own f(E_c(tau)) - f(E_c(tau_0)) (tau_0 = 0
    without a base lag) instead of their expansion f' Delta E + f'' Delta E^2 / 2: the
    law's stationarity under the measured dynamics, with no assumption on the size of the
    jumps.  The two agree for tests <= 2 (f quadratic); where the exact form holds and the
    expansion fails, E_c is not a diffusion at this lag.

    Examples
    --------
    >>> from sinktheory.model import Sink, Well
    >>> from sinktheory.equilibrium import equilibrium_law
    >>> s, W = gauss_grid(10, 1)
    >>> inc = jacobi_increments(s, (1,), 4000, np.random.default_rng(2), a=1, b=2, c=0.005)
    >>> km = kramers_moyal(s, 1.0, 1, (1,), inc)
    >>> right = equilibrium_law(Sink(Well(0.5, 0.0, 1), particles=1), 1.0)  # Beta(1, 2)
    >>> wrong = equilibrium_law(Sink(Well(0.5, 0.0, 1), particles=2), 1.0)  # Beta(1, 4)
    >>> check_fluctuation_dissipation(km, right).p_value > 0.01
    True
    >>> check_fluctuation_dissipation(km, wrong).p_value < 1e-6
    True
    """
    if not isinstance(km, KramersMoyal):
        raise ParameterError("km", km, "a KramersMoyal result")
    if not isinstance(law, EquilibriumLaw):
        raise ParameterError("law", law, "an EquilibriumLaw")
    most = 2 * km.container_energies.size  # two moments per grid point
    tests = v.positive_int(
        "tests", tests, maximum=most, why=lambda t: f"{most // 2} grid points give at most "
        f"{most} independent test integrals",
    )  # fmt: skip
    if not math.isclose(law.total_energy, km.total_energy, rel_tol=1e-12):
        raise ParameterError("law", f"a law at E = {law.total_energy:g}",
                             f"the law at E = {km.total_energy:g}")  # fmt: skip
    j = km.lag_index(lag)
    if v.flag("exact", exact):
        return _exact_check(km, law, j, tests)
    tau = km.spans[j]
    e = km.total_energy
    s = km.container_energies / e
    density = law.pdf(s) * km.weights  # p(s) ds at the nodes
    x = 2 * s - 1
    rows, scale = [], []
    for m in range(1, tests + 1):
        c = np.zeros(m + 1)
        c[m] = 1
        d1 = L.legval(x, L.legder(c)) * 2 / e
        d2 = L.legval(x, L.legder(c, 2)) * 4 / e**2
        rows.append(np.stack([d1, 0.5 * d2], axis=-1) / tau * density[:, None])  # (point, 2)
        scale.append(float(np.sum(density * np.abs(d1 * km.drift[:, j]))))
    a = np.stack(rows)  # (test, point, 2)
    means = np.stack([km.drift[:, j] * tau, km.diffusion[:, j] * 2 * tau], axis=-1)
    integrals = np.einsum("mpi,pi->m", a, means)
    cov = np.einsum("mpi,pij,npj->mn", a, km.covariance[:, j], a)
    return _verdict(km, law, j, integrals, cov, np.array(scale))


def _exact_check(km: KramersMoyal, law: EquilibriumLaw, j: int, tests: int):
    e, runs = km.total_energy, km.increments.shape[2]
    s = km.container_energies / e
    density = law.pdf(s) * km.weights
    col = int(np.flatnonzero(km.increment_lags == km.lags[j])[0])
    end = km.container_energies[:, None] + km.increments[:, col]
    if km.base_lag:
        base = int(np.flatnonzero(km.increment_lags == km.base_lag)[0])
        start = km.container_energies[:, None] + km.increments[:, base]
    else:
        start = np.repeat(km.container_energies[:, None], runs, axis=1)
    q = []
    for m in range(1, tests + 1):
        c = np.zeros(m + 1)
        c[m] = 1
        q.append((L.legval(2 * end / e - 1, c) - L.legval(2 * start / e - 1, c)) / km.spans[j])
    q = np.stack(q)  # (test, point, run)
    means = q.mean(axis=2)
    centred = q - means[..., None]
    cov_points = np.einsum("mpr,npr->pmn", centred, centred) / (runs - 1) / runs
    integrals = means @ density
    cov = np.einsum("p,pmn->mn", density**2, cov_points)
    return _verdict(km, law, j, integrals, cov, np.sum(np.abs(means) * density, axis=1))


def _verdict(km: KramersMoyal, law: EquilibriumLaw, j: int, integrals, cov, scale):
    """The chi-square of the test integrals (zero if the law is stationary) against their
    covariance, as a :class:`FluctuationDissipation` at lag ``km.lags[j]``."""
    tests = integrals.size
    try:
        chi2 = float(integrals @ np.linalg.solve(cov, integrals))
    except np.linalg.LinAlgError:
        raise NumericalError(
            f"fluctuation-dissipation check at lag {km.lags[j]}: the covariance of the "
            f"{tests} test integrals is singular (fewer tests, or more runs)"
        ) from None
    return FluctuationDissipation(
        lag=int(km.lags[j]),
        tests=tests,
        integrals=integrals,
        stderr=np.sqrt(np.diag(cov)),
        chi2=chi2,
        dof=tests,
        p_value=float(stats.chi2.sf(chi2, tests)),
        scale=scale,
        law_particles=law.particles,
        law_beta=law.beta,
        law_mean=law.mean,
    )


#: Cell steps one banded solve costs beyond its cells' (scipy's call overhead):
#: ``python benchmarks/bench_estimates.py --only solve_fokker_planck`` (2-core AVX-512 Xeon,
#: load 2, 2026-11-26) took 2.8e-5 s a solve at 10 cells and 5.2e-5 s at 1000, i.e. about
#: 230 + cells particle steps at SECONDS_PER_PARTICLE_STEP; priced per cell alone it was
#: 1.3x optimistic at 200 cells and 23x at 10.  With 250 the work took 0.37-0.88 of it (load 1).
SOLVE_CELLS = 250


@renamed(energy="total_energy")
def solve_fokker_planck(
    total_energy: float,
    points,
    drift,
    diffusion,
    start: float,
    periods: int,
    *,
    cells: int = 1000,
    substeps: int = 4,
) -> tuple[np.ndarray, np.ndarray]:
    """Mean and standard deviation of E_c at t = 0, 1, ..., ``periods`` (periods) from the
    Fokker-Planck equation dp/dt = -dJ/dE, J = D1 p - d(D2 p)/dE, on [0, E] with zero
    flux at both ends, started as a delta at ``start``.

    D1 and D2 are interpolated linearly between ``points`` (constant beyond them; D2
    clipped at 0).  Finite volumes (``cells``), the drift upwinded, the diffusion flux
    centred; implicit Euler with ``substeps`` steps per period (first order in both:
    errors ~1e-3 of E with the defaults, measured on the Jacobi diffusion, whose mean
    relaxes exactly as exp(-c (a + b) t)).

    Examples
    --------
    >>> s = np.linspace(0, 1, 101)
    >>> mean, sd = solve_fokker_planck(1.0, s, 0.01 * (1 - s - 1.25 * s), 0.01 * s * (1 - s),
    ...                                1.0, 200)
    >>> exact = 1 / 2.25 + (1 - 1 / 2.25) * np.exp(-0.0225 * 200)
    >>> bool(abs(mean[-1] - exact) < 2e-3)
    True
    """
    e = v.positive("total_energy", total_energy)
    cells = v.positive_int("cells", cells, minimum=10, maximum=MAX_CELLS)
    substeps = v.positive_int("substeps", substeps, maximum=MAX_SUBSTEPS)
    periods = v.positive_int("periods", periods, minimum=0)
    x0 = v.finite("start", start)
    if not 0 <= x0 <= e:
        raise ParameterError("start", x0, f"an energy in [0, {e:g}]")
    points = v.finite_array("points", points, "an increasing 1-d array of energies", 1)
    if points.size < 2 or not np.all(np.diff(points) > 0):
        raise ParameterError("points", f"{points.size} value(s)", "an increasing 1-d array")
    coefficients = []
    for name, values in (("drift", drift), ("diffusion", diffusion)):
        values = v.finite_array(name, values, f"{points.size} finite values, one per point")
        if values.shape != points.shape:
            raise ParameterError(name, f"{values.size} value(s)", f"{points.size}, one per point")
        coefficients.append(values)
    v.fits_memory("periods", periods, 16.0 * (periods + 1), f"{periods + 1} periods", "fewer")
    check_particle_steps("periods", periods, (cells + SOLVE_CELLS) * float(substeps) * periods,
                         f"{periods} period(s) x {substeps} step(s) x ({cells} + {SOLVE_CELLS}) "
                         "cells, a cell step priced as a particle step")  # fmt: skip
    h = e / cells
    centres = (np.arange(cells) + 0.5) * h
    faces = np.arange(1, cells) * h
    d1 = np.interp(faces, points, coefficients[0])
    d2 = np.clip(np.interp(centres, points, coefficients[1]), 0.0, None)
    # J_{i+1/2} = max(d1, 0) p_i + min(d1, 0) p_{i+1} - (d2_{i+1} p_{i+1} - d2_i p_i) / h
    left = np.maximum(d1, 0) + d2[:-1] / h  # coefficient of p_i in J_{i+1/2}
    right = np.minimum(d1, 0) - d2[1:] / h  # coefficient of p_{i+1}
    # dp_i/dt = (J_{i-1/2} - J_{i+1/2}) / h
    diag = np.zeros(cells)
    diag[:-1] -= left / h
    diag[1:] += right / h
    upper = -right / h  # d(dp_i)/d p_{i+1}
    lower = left / h  # d(dp_{i+1})/d p_i
    dt = 1.0 / substeps
    banded = np.zeros((3, cells))
    banded[0, 1:] = -dt * upper
    banded[1] = 1 - dt * diag
    banded[2, :-1] = -dt * lower
    p = np.zeros(cells)
    p[min(int(x0 / h), cells - 1)] = 1.0
    means, sds = np.empty(periods + 1), np.empty(periods + 1)
    from scipy.linalg import solve_banded

    for t in range(periods + 1):
        if t:
            for _ in range(substeps):
                p = solve_banded((1, 1), banded, p)
        with np.errstate(over="ignore", invalid="ignore"):  # refused just below
            m = p @ centres / p.sum()
            means[t], sds[t] = m, math.sqrt(max(p @ (centres - m) ** 2 / p.sum(), 0.0))
        if not (math.isfinite(means[t]) and math.isfinite(sds[t])):
            raise NonFiniteStateError(
                f"Fokker-Planck solution on [0, {e:g}]: mean or spread not finite at period {t}"
            )
    return means, sds


def jacobi_increments(s0, lags, runs: int, rng: np.random.Generator, *, a: float, b: float,
                      c: float, substeps: int = 50) -> np.ndarray:  # fmt: skip
    """Increments (point, lag, run) of the Jacobi diffusion
    ds = c (a (1 - s) - b s) dt + sqrt(2 c s (1 - s)) dW started at each s0, observed at
    integer ``lags`` (Euler-Maruyama with ``substeps`` per unit time, s kept in [0, 1]):
    the synthetic process with known D1 = c (a (1 - s) - b s), D2 = c s (1 - s) and
    stationary law Beta(a, b) that the estimator and the check are tested on.

    Examples
    --------
    >>> jacobi_increments([0.5], (1, 2), 3, np.random.default_rng(0), a=1, b=1, c=0.1).shape
    (1, 2, 3)
    """
    s0 = v.finite_array("s0", s0, "a 1-d array of start values in [0, 1]", 1)
    if not np.all((s0 >= 0) & (s0 <= 1)):
        raise ParameterError("s0", s0.tolist(), "a 1-d array of start values in [0, 1]")
    lags = _lags(lags)
    runs = v.positive_int("runs", runs)
    if not isinstance(rng, np.random.Generator):
        raise ParameterError("rng", type(rng).__name__, "a numpy.random.Generator")
    a, b, c = v.nonnegative("a", a), v.nonnegative("b", b), v.positive("c", c)
    substeps = v.positive_int("substeps", substeps)
    v.fits_memory("runs", runs, 8.0 * s0.size * runs * (lags.size + 4),
                  f"{s0.size} point(s) x {runs} run(s)", "fewer")  # fmt: skip
    steps = float(lags.max()) * substeps * s0.size * runs
    what = f"{lags.max()} x {substeps} step(s) x {s0.size} x {runs} run(s)"
    check_particle_steps("lags", int(lags.max()), steps, what)
    dt = 1.0 / substeps
    s = np.repeat(s0[:, None], runs, axis=1)
    out = np.empty((s0.size, lags.size, runs))
    with np.errstate(over="ignore", invalid="ignore"):  # a non-finite state is refused below
        for step in range(1, lags.max() * substeps + 1):
            drift = c * (a * (1 - s) - b * s)
            noise = np.sqrt(2 * c * np.clip(s * (1 - s), 0, None) * dt)
            s = np.clip(s + drift * dt + noise * rng.standard_normal(s.shape), 0.0, 1.0)
            if step % substeps == 0:
                hit = lags == step // substeps
                if hit.any():
                    out[:, np.flatnonzero(hit)[0]] = s - s0[:, None]
    if not np.all(np.isfinite(out)):
        raise NonFiniteStateError(
            f"Jacobi diffusion (a = {a:g}, b = {b:g}, c = {c:g}): a non-finite state within "
            f"{lags.max()} time unit(s); c / substeps is too large"
        )
    return out
