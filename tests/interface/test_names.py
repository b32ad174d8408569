"""One meaning for each parameter name: the inventory of every name a user passes.

Walks every command's parser, the signatures of the public entry points (the top-level
``st.*`` callables and what each command calls) and the sweep kinds' parameters, and
checks them against :data:`sinktheory.glossary.GLOSSARY`: every name is defined there;
an option ``--foo-bar`` is stored as ``foo_bar`` and feeds the keyword ``foo_bar`` of
its command's entry points; the help of an option says what the glossary's mark says;
the renamed options and keywords still work, with a note naming the new one.
"""

import argparse
import importlib
import inspect
import warnings

import pytest
from _cli import run_cli

import sinktheory as st
from sinktheory.cli import build_parser
from sinktheory.glossary import (
    GLOSSARY,
    MARKS,
    RENAMED_OPTIONS,
    RENAMED_PARAMETERS,
    modern_argv,
    option_of,
)

#: command -> "module:callable" of the entry points its options feed (classes: their
#: constructor; "Class.method": a method).
ENTRY_POINTS = {
    "well": ["model:Well", "model:Well.summary", "model:user_well_summary"],
    "sink": ["model:Well", "model:Sink", "model:RunSettings"],
    "derive": ["symbolic:ladder"],
    "simulate": ["model:Well", "model:Sink", "model:RunSettings", "simulate:simulate"],
    "period": ["oscillator:oscillator"],
    "series": ["series:accuracy"],
    "reproduce": [],
    "floquet": [
        "floquet:model_hill",
        "floquet:pure_hill",
        "floquet:model_scan",
        "floquet:pure_scan",
        "floquet:well_floquet",
        "floquet:well_scan",
        "model:Well",
    ],
    "nnm": [
        "model:Well",
        "model:Sink",
        "nnm.continuation:continue_both",
        "nnm.agreement:agreement_report",
    ],  # fmt: skip
    "chaos": ["model:Well", "model:Sink", "model:RunSettings", "chaos:chaos"],
    "design": ["sweep:design", "sweep.runner:run_sweep"],
    "billiard": ["billiard:billiard", "billiard:well_billiard", "model:RunSettings"],
    "equilibrium": [
        "model:Well",
        "model:Sink",
        "equilibrium.law:equilibrium_law",
        "equilibrium.law:well_law",
        "equilibrium.law:EquilibriumLaw.summary",
    ],  # fmt: skip
    "lifetime": [
        "model:Well",
        "model:Sink",
        "model:RunSettings",
        "equilibrium.lifetime:measure_lifetimes",
    ],  # fmt: skip
    "compare": [
        "compare.efficiency:attachments_of",
        "compare.efficiency:compare",
        "compare.transfer:transfer_map",
        "compare.transfer:transfer_maps",
    ],  # fmt: skip
    "sweep": ["sweep.runner:run_sweep"],
    "relaxation": [
        "model:Well",
        "model:Sink",
        "equilibrium.prediction:predict_relaxation",
        "equilibrium.prediction:measure_settling",
    ],  # fmt: skip
}
#: Options that shape the command's output or its run and feed no keyword.
COMMAND_ONLY = {"json", "plot", "out", "quiet", "report", "latex", "fresh", "figure", "quick",
                "param", "top", "no_estimate", "digits", "max_hours",
                "well_param", "wavelet_plot"}  # fmt: skip
#: command -> options whose keyword is still named differently (each entry must still be
#: needed: the test fails when one is fixed, so the list only shrinks).
KNOWN_DISAGREEMENTS: dict[str, set[str]] = {}


def subparsers() -> dict[str, argparse.ArgumentParser]:
    parser = build_parser()
    action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return dict(action.choices)


def options(parser: argparse.ArgumentParser):
    """(option string, dest, help) of every option of ``parser``."""
    for a in parser._actions:
        if a.option_strings and a.dest != "help":
            long = [o for o in a.option_strings if o.startswith("--")]
            yield long[0], a.dest, a.help or ""


def resolve(spec: str):
    if spec.startswith("sweep:"):
        return spec
    module, _, name = spec.partition(":")
    obj = importlib.import_module(f"sinktheory.{module}")
    for part in name.split("."):
        obj = getattr(obj, part)
    return obj


def keywords(obj) -> set[str]:
    if isinstance(obj, str):  # "sweep:KIND": the parameters of a sweep kind
        from sinktheory.sweep.kinds import KINDS

        return set(KINDS[obj.partition(":")[2]].params)
    if isinstance(obj, type(st)):  # a verb module: the function it calls
        obj = obj.__call__
    fn = obj.__init__ if isinstance(obj, type) else obj
    skip = (inspect.Parameter.VAR_POSITIONAL, inspect.Parameter.VAR_KEYWORD)
    return {
        name
        for name, p in inspect.signature(fn).parameters.items()
        if p.kind not in skip and name not in ("self", "cls")
    }


def top_level_callables():
    for name in st.__all__:
        obj = getattr(st, name)
        if isinstance(obj, type) and (issubclass(obj, BaseException) or name not in
                                      ("Well", "Sink", "RunSettings")):  # fmt: skip
            continue  # errors and result types are not called by users
        yield name, obj


PARSERS = subparsers()


def test_every_command_is_inventoried():
    assert set(ENTRY_POINTS) == set(PARSERS)


@pytest.mark.parametrize("command", sorted(PARSERS))
def test_options_are_stored_under_their_own_name(command):
    for option, dest, _ in options(PARSERS[command]):
        assert option == option_of(dest), f"{command} {option} is stored as {dest!r}"


@pytest.mark.parametrize("command", sorted(PARSERS))
def test_every_option_is_in_the_glossary_and_its_help_says_so(command):
    for option, dest, text in options(PARSERS[command]):
        assert dest in GLOSSARY, f"{command} {option}: add its one meaning to the glossary"
        mark = MARKS.get(dest)
        assert mark is None or mark in text, f"{command} {option}: help must say {mark!r}"


@pytest.mark.parametrize("command", sorted(PARSERS))
def test_options_feed_keywords_of_the_same_name(command):
    fed = set().union(*(keywords(resolve(s)) for s in ENTRY_POINTS[command]))
    known = KNOWN_DISAGREEMENTS.get(command, set())
    names = {dest for _, dest, _ in options(PARSERS[command])} - COMMAND_ONLY
    differ = names - fed
    assert differ <= known, f"{command}: {sorted(differ - known)} feed no keyword of that name"
    assert known <= differ, f"{command}: {sorted(known - differ)} agree now; drop them"


def test_every_keyword_of_the_entry_points_is_in_the_glossary():
    specs = {s for specs in ENTRY_POINTS.values() for s in specs}
    objs = [(s, resolve(s)) for s in sorted(specs)] + list(top_level_callables())
    missing = {f"{where}({name})" for where, obj in objs for name in keywords(obj)
               if name not in GLOSSARY}  # fmt: skip
    assert not missing, f"keywords with no meaning in the glossary: {sorted(missing)}"


def test_every_sweep_parameter_is_in_the_glossary():
    from sinktheory.sweep.kinds import KINDS

    names = {p for kind in KINDS.values() for p in kind.params}
    missing = sorted(p for p in names if p not in GLOSSARY)
    assert not missing, f"sweep parameters with no meaning in the glossary: {missing}"
    assert not names & set(RENAMED_PARAMETERS), "an old sweep parameter name is back"
    assert set(RENAMED_PARAMETERS.values()) <= names


def test_an_old_sweep_parameter_still_works_with_a_note():
    """``--param energy=...`` is rewritten as modern_argv rewrites an old option; in Python
    the old name works with a DeprecationWarning, as an old keyword does."""
    from sinktheory.sweep.kinds import get_kind

    argv, notes = modern_argv(["sweep", "ensemble", "--param", "energy=0.3,0.4",
                               "--param=method=verlet", "--param", "beta=0.1"])  # fmt: skip
    assert argv[2:] == ["--param", "container_energy=0.3,0.4", "--param=scheme=verlet",
                        "--param", "beta=0.1"]  # fmt: skip
    assert notes == ["--param energy is now --param container_energy",
                     "--param method is now --param scheme"]  # fmt: skip
    kind = get_kind("ensemble")
    given = {"alpha": 0.5, "beta": 0.1, "n": 4}
    with pytest.warns(DeprecationWarning) as caught:
        old = kind.complete({**given, "energy": 0.3, "method": "verlet"})
    assert [str(w.message).split(" (")[0] for w in caught] == [
        "sweep: the parameter 'energy' is now 'container_energy'",
        "sweep: the parameter 'method' is now 'scheme'",
    ]
    assert old == kind.complete({**given, "container_energy": 0.3, "scheme": "verlet"})


def test_a_second_meaning_fails():
    """The checks above see a name used for something else: an option whose help does not
    say the glossary's mark."""
    marked = [(dest, text) for p in PARSERS.values() for _, dest, text in options(p)
              if dest in MARKS]  # fmt: skip
    assert {dest for dest, _ in marked} >= {"container_energy", "total_energy", "energy"}
    assert MARKS["container_energy"] not in "total energy E > 0"


@pytest.mark.parametrize(
    "command, old", [(c, o) for c, table in sorted(RENAMED_OPTIONS.items()) for o in table]
)
def test_renamed_options_are_gone_from_the_parser(command, old):
    assert old not in {o for o, _, _ in options(PARSERS[command])}
    new = RENAMED_OPTIONS[command][old]
    new = new("") if callable(new) else new
    assert new in {o for o, _, _ in options(PARSERS[command])}


def test_an_old_option_still_works_with_a_note(capsys):
    new = run_cli(["sink", "--alpha", "0.5", "--beta", "0.3", "--n", "4",
                   "--container-energy", "0.7", "--json"], capsys)  # fmt: skip
    old = run_cli(["sink", "--alpha", "0.5", "--beta", "0.3", "--n", "4",
                   "--energy=0.7", "--json"], capsys)  # fmt: skip
    assert new[0] == old[0] == 0 and new[1] == old[1] and new[2] == ""
    assert old[2].strip() == (
        "sinktheory sink: note: --energy is now --container-energy (the old name goes in "
        "the next release)"
    )


def test_an_old_keyword_still_works_with_a_warning():
    with pytest.warns(DeprecationWarning, match="'energy' is now 'container_energy'"):
        old = st.RunSettings(energy=0.7)
    assert old == st.RunSettings(container_energy=0.7)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        st.RunSettings(container_energy=0.7)


def test_old_attributes_still_read_with_a_warning():
    """Result fields renamed to the glossary's names keep their old names readable (with a
    DeprecationWarning naming the new ones); a state made under the old field name, by
    keyword or with "adaptive" where the scheme now stands, still constructs."""
    import numpy as np

    from sinktheory.bifurcation import BifurcationDiagram
    from sinktheory.ensemble import SimulationResult, SimulationState
    from sinktheory.stepsize import StepChoice

    row, one = np.zeros((1, 6)), np.ones(1)
    fixed = SimulationState(row, 0.0, one, 0.1, "verlet")
    with pytest.warns(DeprecationWarning, match="'method' is now 'stepper' and 'scheme'"):
        assert fixed.method == "verlet"
    with pytest.warns(DeprecationWarning, match="'method' is now 'scheme'"):
        keyword = SimulationState(row, 0.0, one, 0.1, method="verlet")
    assert (keyword.stepper, keyword.scheme) == (fixed.stepper, fixed.scheme) == ("fixed", "verlet")
    old = SimulationState(row, 0.0, one, 0.1, "adaptive", np.ones((1, 2)))
    assert (old.stepper, old.scheme) == ("adaptive", None)
    with pytest.warns(DeprecationWarning):
        assert old.method == "adaptive"
    result = SimulationResult(
        times=np.zeros(1), container_energy=None, particle_energy=None, trajectory=None,
        trajectory_times=None, final_state=None, initial_energy=one, run_errors=one,
        max_relative_energy_error=1.0, stepper="adaptive", scheme="blanes-moan6", dt=0.1,
        steps_per_period=63, message="",
    )  # fmt: skip
    assert "method" not in result.as_dict() and result.as_dict()["stepper"] == "adaptive"
    with pytest.warns(DeprecationWarning):
        assert result.method == "adaptive"
    diagram = BifurcationDiagram(np.zeros(1), np.zeros((1, 1)), "y", 0.5, 4, 1.0, "flat", 0.2,
                                 0.7, 0, 1)  # fmt: skip
    with pytest.warns(DeprecationWarning, match="'energy' is now 'container_energy'"):
        assert diagram.energy == diagram.container_energy == 0.7
    choice = StepChoice("verlet", 0.1, 63, 0.1, 1e-3, 63)
    with pytest.warns(DeprecationWarning, match="'method' is now 'scheme'"):
        assert choice.method == "verlet"
    law = st.equilibrium_law(st.Sink(st.Well(0.5, 0.0, 4), particles=2), total_energy=0.5)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        assert law.energy == law.total_energy == 0.5
    from dataclasses import fields

    from sinktheory.equilibrium.prediction import RelaxationPrediction

    given = {f.name: 0.0 for f in fields(RelaxationPrediction) if f.name != "container_energy"}
    with pytest.warns(DeprecationWarning, match="'energy' is now 'container_energy'"):
        old = RelaxationPrediction(**given, energy=0.7)
    assert old.container_energy == 0.7
    with pytest.warns(DeprecationWarning, match="'energy' is now 'container_energy'"):
        assert old.energy == 0.7


def test_old_equilibrium_keywords_still_work_with_a_warning():
    """The total energy E and a particle's energy e of the equilibrium functions took the
    keyword ``energy``; it still works, with a warning naming the new one, and gives the
    same numbers; the Kramers-Moyal result's old field still reads."""
    import numpy as np

    from sinktheory.canonical import FIG8_WELL
    from sinktheory.equilibrium.area import basin_area, scaled_energy
    from sinktheory.equilibrium.kramers import kramers_moyal

    with pytest.warns(DeprecationWarning, match="'energy' is now 'particle_energy'"):
        assert basin_area(FIG8_WELL, energy=0.1) == basin_area(FIG8_WELL, particle_energy=0.1)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'particle_energy'"):
        assert scaled_energy(FIG8_WELL, energy=0.125) == scaled_energy(FIG8_WELL, 0.125)
    inc = np.ones((2, 1, 3))
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        km = kramers_moyal([0.2, 0.7], energy=2.0, n=1, lags=[1], increments=inc, weights=[1, 1])
    assert km.total_energy == 2.0 and km.container_energies.tolist() == [0.4, 1.4]
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        assert km.energy == 2.0


def test_old_step_keyword_still_works_with_a_warning():
    """The step choice's ``energy`` is the total energy E (not the total-energy error
    bound ``energy_bound``); the old keyword still works, with a warning."""
    from sinktheory.canonical import FIG8_SINK
    from sinktheory.stepsize import choose, step_of

    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        old = choose(FIG8_SINK, energy=0.5, tol=1e-6)
    assert old == choose(FIG8_SINK, total_energy=0.5, tol=1e-6)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        assert step_of(FIG8_SINK, energy=0.5) == step_of(FIG8_SINK, 0.5)


def test_old_model_and_start_keywords_still_work_with_a_warning():
    """A particle's energy of the well's checks is particle_energy, the start's E0
    container_energy, the adaptive estimate's E total_energy; the old ``energy`` still
    works, with a warning, and gives the same result."""
    import numpy as np

    from sinktheory.adaptive import estimated_steps
    from sinktheory.canonical import FIG8_SINK, FIG8_WELL
    from sinktheory.ensemble import start_state
    from sinktheory.errors import ParameterError
    from sinktheory.model import confining_betas

    at = np.array([[[0.003, -0.004]]])
    with pytest.warns(DeprecationWarning, match="'energy' is now 'container_energy'"):
        old = start_state(FIG8_SINK, energy=0.5, positions=at)
    assert np.array_equal(old, start_state(FIG8_SINK, container_energy=0.5, positions=at))
    assert old[0, 0] == 1.0  # X = sqrt(2 E0)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'particle_energy'"):
        old = confining_betas(1.0, 6, energy=0.5, shape="symmetric", points=41)
    assert old == confining_betas(1.0, 6, 0.5, shape="symmetric", points=41)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'particle_energy'"):
        with pytest.raises(ParameterError, match="particle_energy = 1e[+]308"):
            FIG8_WELL.check_energy(energy=1e308)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        assert estimated_steps(FIG8_SINK, energy=0.5, eps=0.25) == estimated_steps(
            FIG8_SINK, 0.5, 0.25
        )


def test_old_basin_keywords_and_reach_field_still_work_with_a_warning():
    """The basin's reach, area and check take a particle's energy, particle_energy; the
    reach keeps it under that name, and ``energy`` still reads, with a warning."""
    from sinktheory.basin import Basin
    from sinktheory.userwell import UserWell

    well = UserWell("ellipse", "(x/a)**2 + (y/b)**2", {"a": 0.3, "b": 0.2})
    basin = Basin.of(well.potential, well.values(), well.name)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'particle_energy'"):
        old = basin.reach(energy=1.0)
    assert old == basin.reach(particle_energy=1.0)
    assert (old.x_max, old.y_max) == pytest.approx((0.3, 0.2), rel=1e-12)  # the ellipse
    with pytest.warns(DeprecationWarning, match="'energy' is now 'particle_energy'"):
        assert old.energy == old.particle_energy == 1.0
    with pytest.warns(DeprecationWarning, match="'energy' is now 'particle_energy'"):
        assert basin.area(energy=1.0) == basin.area(1.0)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'particle_energy'"):
        assert basin.check_energy(energy=0.5) == 0.5
    escape = basin.escape  # the ellipse never opens: V on the largest box's edge
    with pytest.warns(DeprecationWarning, match="'energy' is now 'escape_potential'"):
        assert escape.energy == escape.escape_potential == basin.escape_energy + basin.well.v0


def test_old_impulse_fields_still_read_with_a_warning():
    """The impulse's E0 of ImpulseResponse and TransferMap is impulse_energy (their
    container_energy is the record E_c(t)); Comparison's E0 grid is container_energy, its
    dataset dimension too.  The old field name still constructs and reads, with a note."""
    import numpy as np

    from sinktheory.attachments import Attachment, ImpulseResponse
    from sinktheory.compare.efficiency import Comparison
    from sinktheory.compare.transfer import TransferMap

    row = np.zeros((1, 2))
    fields = dict(t=np.zeros(2), container_x=row, container_v=row, container_energy=row,
                  dissipated=row, initial_energy=np.ones(1), max_audit_error=0.0,
                  attachment=Attachment("nes", n=2), damping=0.1)  # fmt: skip
    with pytest.warns(DeprecationWarning, match="'energy' is now 'impulse_energy'"):
        old = ImpulseResponse(**fields, energy=0.3)
    assert old == ImpulseResponse(**fields, impulse_energy=0.3)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'impulse_energy'"):
        assert old.energy == 0.3
    assert old.as_dict()["impulse_energy"] == 0.3 and "energy" not in old.as_dict()
    transfer = TransferMap(None, np.zeros(2), np.zeros(2), "NES", 0.3, 0.1, 0)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'impulse_energy'"):
        assert transfer.energy == transfer.impulse_energy == 0.3
    grid = np.array([0.1, 1.0])
    c = Comparison(("a",), grid, *[np.zeros((1, 2))] * 6, [], 0.0, 2, 10, 0, 16, 0.0)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'container_energy'"):
        assert c.energy is c.container_energy is grid
    assert c.to_dataset()["efficiency"].dims == ("attachment", "container_energy")


def test_old_nnm_attributes_still_read_with_a_warning():
    """An orbit's, a branch's and a branch result's total energy H was ``energy``, and the
    flow system's Hamiltonian at a state ``energy(z)``; each still reads, with a warning,
    and the orbits' H(z0) is the shooting's target."""
    import numpy as np

    from sinktheory.nnm.continuation import continue_orbits
    from sinktheory.nnm.shooting import checked_start
    from sinktheory.nnm.system import FlowSystem

    duffing = FlowSystem("duffing2", [])
    branch = continue_orbits(duffing, np.array([0.1, 0.1, 0, 0]), 2 * np.pi, steps=64,
                             total_energy=0.01, interval=(5e-3, 0.02), max_points=3)  # fmt: skip
    orbit, result = branch.orbits[0], branch.result()
    assert orbit.total_energy == duffing.hamiltonian(orbit.z0) == result.total_energy[0]
    assert abs(orbit.total_energy - 0.01) < 1e-14
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        assert orbit.energy == orbit.total_energy
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        assert np.array_equal(branch.energy, branch.total_energy)
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        assert result.energy is result.total_energy
    assert "energy" not in result.as_dict() and len(result.as_dict()["total_energy"]) > 1
    with pytest.warns(DeprecationWarning, match="'energy' is now 'hamiltonian'"):
        assert duffing.energy(orbit.z0) == orbit.total_energy
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        old = checked_start(duffing, orbit.z0, energy=0.01)
    assert old[1] == checked_start(duffing, orbit.z0, 0.01)[1] == 0.01


def test_old_rigid_shell_keyword_still_works_with_a_warning():
    """The rigid shell's ``energy`` is the total energy E; the old keyword still works,
    with a warning, and draws the same states from the same seed."""
    import numpy as np

    from sinktheory.billiard.relaxation import rigid_shell_increments, rigid_shell_states
    from sinktheory.billiard.table import rigid_table
    from sinktheory.errors import ParameterError

    table = rigid_table("flat", 0.5, 0.3)
    new = rigid_shell_states(table, 2, 0.2, 0.5, 0.25, 3, np.random.default_rng(1))
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        old = rigid_shell_states(table, 2, 0.2, energy=0.5, s=0.25, runs=3,
                                 rng=np.random.default_rng(1))  # fmt: skip
    assert all(np.array_equal(a, b) for a, b in zip(old, new, strict=True))
    assert np.allclose(0.5 * (old[2] ** 2).sum(axis=1), 0.25 * 0.5, rtol=1e-14)  # E_c = s E
    with pytest.raises(ParameterError, match="^total_energy = "):
        rigid_shell_states(table, 2, 0.2, -0.5, 0.25, 3, np.random.default_rng(1))
    with pytest.warns(DeprecationWarning, match="'energy' is now 'total_energy'"):
        s, inc, _ = rigid_shell_increments(table, 1, 0.2, energy=0.5, points=3, runs=2,
                                           lags=[1, 2], seed=0)  # fmt: skip
    assert np.array_equal(inc, rigid_shell_increments(table, 1, 0.2, 0.5, 3, 2, [1, 2], 0)[1])


def test_the_old_wavelet_output_option_is_rewritten_with_a_note():
    """``compare --wavelet FILE.png`` was the output file (Python's ``wavelet`` is the
    wavelet's type): it is ``--wavelet-plot`` now; ``--wavelet-energy`` is left alone."""
    argv, notes = modern_argv(["compare", "--damping", "0.01", "--wavelet", "w.png",
                               "--wavelet-energy", "0.1", "--wavelet=v.png"])  # fmt: skip
    assert argv == ["compare", "--damping", "0.01", "--wavelet-plot", "w.png",
                    "--wavelet-energy", "0.1", "--wavelet-plot=v.png"]  # fmt: skip
    assert notes == ["--wavelet is now --wavelet-plot"]
