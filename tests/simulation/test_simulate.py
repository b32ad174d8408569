"""The full-dynamics simulator: accuracy against independent references, the energy audit,
reproducibility, recording and the failure paths.

Independent references used: the conserved Hamiltonian (an exact law; evaluated by the
generated energy kernel, which the integrator never uses), scipy's DOP853 on the same
equations, exact time reversal of the symmetric schemes, and numpy's own arithmetic for
ensemble statistics.
"""

import json

import numba
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from sinktheory import ParameterError, RunSettings, Sink, Well
from sinktheory.canonical import FIG8_WELL, SYMMETRIC_WELL
from sinktheory.cli import main
from sinktheory.ensemble import random_positions, total_energy
from sinktheory.errors import EnergyDriftError, NonFiniteStateError
from sinktheory.simulate import PERIOD, SimulationState, first_order_rhs, simulate
from sinktheory.stepsize import default_step

FIG8 = Sink(Well(alpha=0.5, beta=0.3, n=4), particles=5, mass=0.2)
STIFF = Sink(Well(alpha=0.5, beta=0.3, n=10), particles=5, mass=0.2)

# The paper's parameter ranges (flat: alpha = 1/2, beta in {-0.5, -0.2, 0.3}, n in {4, 10};
# symmetric: alpha = 1, beta = +-0.1, n = 6; m = 0.2), with k = 5 (lightest particles:
# stiffest) and k = 1.
PAPER_WELLS = [Well(0.5, beta, n) for beta in (-0.5, -0.2, 0.3) for n in (4, 10)] + [
    Well(1.0, beta, 6, shape="symmetric") for beta in (-0.1, 0.1)
]


# --------------------------------------------------------------------------- accuracy
@pytest.mark.parametrize("well", PAPER_WELLS, ids=lambda w: f"{w.shape}-b{w.beta}-n{w.n}")
@pytest.mark.parametrize("k", [1, 5])
def test_default_conserves_energy_over_paper_ranges(well, k):
    # 2 runs x 150 periods: long enough for the particles to take up a large share of the
    # energy (the regime that limits the step).  Bound 1e-8: the accuracy target.
    res = simulate(Sink(well, particles=k, mass=0.2), RunSettings(runs=2, periods=150, seed=5))
    assert res.max_relative_energy_error <= 1e-8
    assert res.container_energy.min() < 0.45  # energy really moved into the particles


def test_default_conserves_energy_for_1500_periods_stiffest_case():
    # The stiffest paper case (n = 10, k = 5, beta = 0.3: the largest wall frequency), one
    # run over the paper's full horizon; the audit runs at every period.
    res = simulate(STIFF, RunSettings(runs=1, periods=1500, seed=11))
    assert res.max_relative_energy_error <= 1e-8
    assert res.times[-1] == pytest.approx(1500 * PERIOD, rel=1e-15)


def test_agrees_with_dop853_on_short_horizon():
    # DOP853 at rtol 1e-12 on the same equations (RHS from the generated kernel): over three
    # periods both should agree to DOP853's own accuracy times the modest growth of
    # perturbations over that time (measured ~1e-9); 2e-8 leaves room, a wrong force or a
    # wrong coefficient gives errors of order 1e-3 or more.
    for sink in (FIG8, Sink(SYMMETRIC_WELL, particles=3, mass=0.2)):
        res = simulate(sink, RunSettings(runs=1, periods=3, seed=3), record=("trajectory",))
        z0 = res.trajectory[0, 0]
        sol = solve_ivp(
            first_order_rhs(sink),
            (0.0, res.trajectory_times[-1]),
            z0,
            method="DOP853",
            rtol=1e-12,
            atol=1e-14,
            t_eval=res.trajectory_times,
        )
        assert sol.success
        assert np.abs(sol.y.T - res.trajectory[0]).max() < 2e-8


def test_forward_then_backward_recovers_the_start():
    # Symmetric schemes are time-reversible: integrate 2 periods, flip the velocities,
    # integrate 2 more: the start comes back up to round-off amplified by the chaotic
    # dynamics.  That amplification is steep (measured max deviation 4e-13, 3e-11, 4e-10,
    # 9e-7 after 1, 2, 3, 5 periods each way), so 2 periods with the 1e-10 target.
    settings = RunSettings(runs=2, periods=2, seed=2)
    fwd = simulate(STIFF, settings, record=("final", "trajectory"), stride=10**9)
    start = fwd.trajectory[:, 0]
    k = STIFF.particles
    flipped = fwd.final_state.values.copy()
    flipped[:, 1] *= -1
    flipped[:, 2 + 2 * k :] *= -1
    back = simulate(
        STIFF,
        settings,
        initial_state=SimulationState(flipped, 0.0, fwd.initial_energy, fwd.dt, fwd.scheme),
        record=("final",),
    )
    end = back.final_state.values.copy()
    end[:, 1] *= -1
    end[:, 2 + 2 * k :] *= -1
    assert np.abs(end - start).max() < 1e-10


@settings(max_examples=8, deadline=None)
@given(
    positions=st.lists(
        st.tuples(st.floats(-0.05, 0.05), st.floats(-0.05, 0.05)), min_size=2, max_size=2
    ),
    symmetric=st.booleans(),
)
def test_mirror_symmetry_y_to_minus_y(positions, symmetric):
    # Both wells are even in y and the container moves along x only, so starting from the
    # mirror image (y -> -y) must give the mirror-image motion.  The kernels use only odd
    # integer powers of y for forces, so the mirror holds bit for bit.
    well = SYMMETRIC_WELL if symmetric else Well(0.5, -0.2, 4)
    sink = Sink(well, particles=2, mass=0.2)
    start = np.array(positions)
    mirror = start * [1.0, -1.0]
    record = ("container", "final")
    a = simulate(sink, RunSettings(runs=1, periods=2), initial=start, record=record)
    b = simulate(sink, RunSettings(runs=1, periods=2), initial=mirror, record=record)
    k = 2
    flip = np.ones(2 + 4 * k)
    flip[2 + k : 2 + 2 * k] = -1  # y
    flip[2 + 3 * k :] = -1  # ydot
    assert np.array_equal(a.container_energy, b.container_energy)
    assert np.array_equal(a.final_state.values * flip, b.final_state.values)


def test_particle_and_container_energies_add_up_to_the_total():
    res = simulate(FIG8, RunSettings(runs=3, periods=20), record=("container", "particles"))
    total = res.container_energy + res.particle_energy.sum(axis=2)
    # container + particles = H exactly by definition; H drifts by <= the audited error,
    # and the split costs a few round-offs
    drift = res.max_relative_energy_error + 1e-14
    assert np.abs(total / res.initial_energy[:, None] - 1).max() <= drift
    assert np.all(res.particle_energy >= 0)


def test_default_step_is_aligned_and_resolves_the_wall():
    dt, steps = default_step(FIG8, 0.5)
    assert steps * dt == pytest.approx(PERIOD, rel=1e-15)
    # a step 4 times larger than the default breaks the 1e-8 target: the default is not
    # wastefully small by orders of magnitude, nor is the audit toothless
    res = simulate(FIG8, RunSettings(runs=2, periods=150, seed=5), dt=4 * dt, energy_bound=1)
    assert res.max_relative_energy_error > 1e-8


# --------------------------------------------------------------------------- reproducibility
def test_same_seed_same_bits_whatever_the_threads():
    settings = RunSettings(runs=4, periods=3, seed=9)
    record = ("container", "particles", "final")
    before = numba.get_num_threads()
    try:
        numba.set_num_threads(1)
        one = simulate(FIG8, settings, record=record)
        numba.set_num_threads(min(2, numba.config.NUMBA_NUM_THREADS))
        two = simulate(FIG8, settings, record=record)
    finally:
        numba.set_num_threads(before)
    assert np.array_equal(one.container_energy, two.container_energy)
    assert np.array_equal(one.particle_energy, two.particle_energy)
    assert np.array_equal(one.final_state.values, two.final_state.values)


def test_continuing_equals_running_through():
    settings = RunSettings(runs=2, periods=4, seed=4)
    whole = simulate(FIG8, settings, record=("container", "final"))
    half = simulate(FIG8, RunSettings(runs=2, periods=2, seed=4), record=("container", "final"))
    rest = simulate(FIG8, RunSettings(runs=2, periods=2), initial_state=half.final_state)
    assert np.array_equal(whole.container_energy[:, 2:], rest.container_energy)
    assert rest.times[0] == pytest.approx(2 * PERIOD)
    assert rest.dt == whole.dt


def test_random_positions_depend_only_on_seed_and_run():
    a = random_positions(RunSettings(runs=3, seed=1), 5)
    b = random_positions(RunSettings(runs=5, seed=1), 5)
    assert np.array_equal(a, b[:3])  # run r's start does not depend on the ensemble size
    assert np.all(np.abs(a) < 0.01)
    assert not np.array_equal(a, random_positions(RunSettings(runs=3, seed=2), 5))


# --------------------------------------------------------------------------- recording
def test_records_only_what_is_asked_and_trajectory_matches_final_state():
    res = simulate(FIG8, RunSettings(runs=2, periods=2), record=("trajectory", "final"), stride=1)
    assert res.container_energy is None and res.particle_energy is None
    assert res.trajectory.shape == (2, 2 * res.steps_per_period + 1, 22)
    assert res.trajectory_times[-1] == pytest.approx(2 * PERIOD)
    assert np.array_equal(res.trajectory[:, -1], res.final_state.values)
    only_e = simulate(FIG8, RunSettings(runs=2, periods=2))
    assert only_e.trajectory is None and only_e.final_state is None
    assert only_e.container_energy.shape == (2, 3)


def test_single_run_from_given_positions():
    sink = Sink(Well(0.5, 0.3, 10), particles=1, mass=0.2)
    res = simulate(sink, RunSettings(runs=1, periods=2), initial=[(0.0, 0.01)], record=("final",))
    # total energy: E0 = 1/2 plus V(0, 0.01) = gamma/(2n) 0.01^(2n) with n = 10 (paper eq. V)
    assert res.initial_energy[0] == pytest.approx(0.5 + 0.01**20 / 20, rel=1e-15)
    end = total_energy(sink, res.final_state.values)[0]
    assert abs(end / res.initial_energy[0] - 1) <= res.max_relative_energy_error + 1e-16


def test_energy_the_well_cannot_hold_is_refused():
    # beta = -0.5: D(y) = 1 - y^2/2 vanishes at |y| = sqrt 2; with E0 = 2 a particle can
    # take enough energy (sqrt(2)^8/8 = 2) to get there, where V is singular
    sink = Sink(Well(0.5, -0.5, 4), particles=1, mass=0.2)
    with pytest.raises(ParameterError) as info:
        simulate(sink, RunSettings(container_energy=2.0, runs=1, periods=1), initial=[(0.0, 0.5)])
    assert info.value.name == "beta"


def test_step_too_large_raises_energy_drift_naming_run_and_time():
    sink = Sink(Well(0.5, 0.3, 10), particles=1, mass=0.2)
    with pytest.raises(EnergyDriftError, match=r"run \d+ at t = 6\.28319 \(period 1\).*H0 ="):
        simulate(sink, RunSettings(runs=2, periods=20), dt=0.1)


def test_blow_up_raises_non_finite_state():
    sink = Sink(Well(0.5, 0.3, 10), particles=1, mass=0.2)
    with pytest.raises(NonFiniteStateError, match=r"run 0 at t = 6\.28319.*non-finite"):
        simulate(sink, RunSettings(runs=2, periods=20), dt=1.0)


def test_non_finite_continuation_state_is_refused():
    res = simulate(FIG8, RunSettings(runs=1, periods=1), record=("final",))
    bad = res.final_state.values.copy()
    bad[0, 3] = np.nan
    state = SimulationState(bad, 0.0, res.initial_energy, res.dt, res.scheme)
    with pytest.raises(ParameterError) as info:
        simulate(FIG8, RunSettings(runs=1, periods=1), initial_state=state)
    assert info.value.name == "initial_state"


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({"dt": 0.0}, "dt"),
        ({"dt": -1e-3}, "dt"),
        ({"scheme": "euler"}, "scheme"),
        ({"stepper": "rk45"}, "stepper"),
        ({"stepper": "adaptive", "scheme": "verlet"}, "scheme"),
        ({"record": ("energy",)}, "record"),
        ({"energy_bound": 0}, "energy_bound"),
        ({"initial": np.zeros((4, 2))}, "initial"),
        ({"initial": np.zeros((5, 2))}, "initial"),  # (k, 2) needs runs = 1
        ({"record": ("trajectory",), "stride": 0}, "stride"),
    ],
)
def test_bad_input_raises_parameter_error(kwargs, name):
    kwargs = dict(kwargs)
    runs = kwargs.pop("runs", 2)
    with pytest.raises(ParameterError) as info:
        simulate(FIG8, RunSettings(runs=runs, periods=1), **kwargs)
    assert info.value.name == name


# --------------------------------------------------------------------------- command line
def test_cli_json_npz_and_plot(tmp_path, capsys):
    npz, png = tmp_path / "e.npz", tmp_path / "e.png"
    argv = ["simulate", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--particles", "5"]
    argv += ["--runs", "3", "--periods", "4", "--json", "--out", str(npz), "--plot", str(png)]
    assert main(argv) == 0
    data = json.loads(capsys.readouterr().out)
    direct = simulate(FIG8, RunSettings(runs=3, periods=4), record=("container", "final"))
    assert data == direct.as_dict()  # the JSON is the API result's as_dict()
    mean, err = direct.ensemble_energy()
    assert data["mean_energy"] == mean.tolist() and data["stderr"] == err.tolist()
    assert len(data["mean_energy"]) == 5
    assert (data["parameters"]["runs"], data["parameters"]["periods"]) == (3, 4)
    assert (data["stepper"], data["scheme"]) == ("fixed", direct.scheme)
    assert data["dt"] == direct.dt
    assert data["max_relative_energy_error"] < 1e-8
    saved = np.load(npz)
    assert np.array_equal(saved["container_energy"], direct.container_energy)
    assert json.loads(str(saved["parameters"]))["seed"] == 0 and "version" in saved
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_cli_single_run_from_initial_positions(capsys):
    argv = ["simulate", "--alpha", "0.5", "--beta", "0.3", "--n", "10", "--initial", "0", "0.01"]
    assert main(argv + ["--periods", "2", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    # one run has no standard error: NaN in Python, null in JSON, said in the text
    assert data["parameters"]["runs"] == 1 and data["stderr"] == [None, None, None]
    assert main(argv + ["--periods", "2"]) == 0
    assert "(no standard error from one run)" in capsys.readouterr().out


@pytest.mark.parametrize(
    "extra",
    [
        ["--initial", "0", "0.01", "0.0"],  # odd count
        ["--particles", "2", "--initial", "0", "0.01"],  # count != 2 k
        ["--dt", "0"],
        ["--scheme", "rk45"],
        ["--stepper", "rk45"],
        ["--out", "x.csv"],
    ],
)
def test_cli_bad_input_exits_2(extra, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    argv = ["simulate", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--periods", "1"]
    assert main(argv + extra) == 2
    assert capsys.readouterr().err.count("\n") == 1
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(initial="x"), "initial"),
        (dict(initial=[[0.0, 0.0, 0.0]]), "initial"),  # not (k, 2)
        (dict(dt=1e-300), "dt"),
        (dict(dt=0.0), "dt"),
    ],
)
def test_api_refuses_bad_starts_and_steps_naming_the_parameter(kwargs, name):
    sink = Sink(FIG8_WELL, particles=1, mass=0.2)
    with pytest.raises(ParameterError, match=rf"^{name} = "):
        simulate(sink, RunSettings(runs=1, periods=1), progress=False, **kwargs)


def test_the_steppers_registry_is_what_simulate_dispatches_on():
    """Every stepper of STEPPERS runs under its own name, its options are keywords of
    simulate, and an option of another stepper is refused naming the keyword."""
    import inspect

    from sinktheory.simulate import STEPPERS

    keywords = set(inspect.signature(simulate).parameters)
    sink, settings = Sink(FIG8_WELL, particles=1, mass=0.2), RunSettings(runs=1, periods=1)
    assert set(STEPPERS) == {"fixed", "adaptive"}
    for name, stepper in STEPPERS.items():
        assert stepper.name == name and set(stepper.options) <= keywords
        res = simulate(sink, settings, stepper=name, progress=False)
        assert res.stepper == name
        foreign = {o for other in STEPPERS.values() for o in other.options} - set(stepper.options)
        for option in sorted(foreign):
            with pytest.raises(ParameterError, match=f"^{option} = .*stepper {name!r}"):
                simulate(sink, settings, stepper=name, **{option: 0.2 if option != "stride"
                                                          else 2})  # fmt: skip


def test_tiny_step_is_estimated_and_refused_over_the_hour(capsys, tmp_path, monkeypatch):
    """Issue 34: --dt 1e-7 ran past a minute unannounced.  A step of 2 runs of 1 particle
    counts 2 + 8 particle steps (the block's overhead): 3 periods are 1.9e9 particle steps
    (226 s at 1.2e-7 s: allowed); 300 periods are 10 x 300 x ceil(2 pi / 1e-7) = 1.9e11,
    over the hour's 3e10: refused."""
    import math

    from _cli import refused

    steps = (2 + 8) * 300 * math.ceil(2 * math.pi / 1e-7)
    argv = ["simulate", "--alpha", "0.5", "--beta", "0.3", "--n", "4", "--dt", "1e-7",
            "--runs", "2", "--periods", "300", "--quiet"]  # fmt: skip
    line = refused(argv, capsys, tmp_path, monkeypatch, "periods")
    assert f"is {steps:.3g} particle steps" in line and "--max-hours" in line, line
