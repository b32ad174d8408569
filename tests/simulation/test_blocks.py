"""The engine's block policy (sinktheory.engine.blocks): the plan against brute force over
every uniform blocking, its guarantees (padding below one block, a thread only with a block
of its own, never a predicted slow-down from threads), and the on-disk cost table."""

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sinktheory.canonical import HENON_HEILES
from sinktheory.engine import blocks

COSTS = st.dictionaries(
    st.sampled_from(blocks.SIZES), st.floats(1e-9, 1e-6), min_size=1, max_size=len(blocks.SIZES)
)


@settings(max_examples=200, deadline=None)
@given(runs=st.integers(1, 600), costs=COSTS, threads=st.integers(1, 8))
def test_plan_guarantees(runs, costs, threads):
    p = blocks.plan(runs, costs, threads)
    assert p.block in costs
    assert runs <= p.padded < runs + p.block  # inert copies fill the last block only
    assert p.padded % p.block == 0
    assert p.threads <= min(threads, p.blocks)  # every thread has a block of its own
    # never predicted slower than the best single-thread plan, by brute force over blocks
    single = min(-(-runs // b) * b * c for b, c in costs.items())
    assert p.predicted <= single * (1 + 1e-12)
    if p.threads > 1:  # a second thread must pay its way, each with an efficient block
        assert p.predicted * blocks.THREAD_GAIN <= single * (1 + 1e-12)
        cheapest = min(costs.values())
        assert costs[p.block] <= 2 * cheapest
    for q in blocks.candidates(runs, costs, threads):  # nor is one tried on a narrow block
        assert q.threads == 1 or costs[q.block] <= 2 * min(costs.values())


def test_tiny_ensembles_stay_on_one_thread():
    # blocks of 1 and 2 runs are far from the vector width (4 here): two runs as two
    # one-run blocks on two threads would be predicted 1.4x faster, but each thread would
    # hold a scalar block and wait for a second core that may be busy
    costs = {1: 5.0e-8, 2: 4.0e-8, 4: 1.9e-8, 16: 1.0e-8}
    assert blocks.efficient_width(costs) == 4
    for runs in (1, 2, 3, 4):  # less than two efficient blocks
        assert blocks.plan(runs, costs, 2).threads == 1
        assert {p.threads for p in blocks.candidates(runs, costs, 2)} == {1}
    for runs in (5, 8):  # two blocks of 4 (the last padded): one per core
        p = blocks.plan(runs, costs, 2)
        assert (p.block, p.threads) == (4, 2)


def test_plan_pads_when_the_table_says_so():
    # a machine where 16-run blocks vectorise and smaller ones do not (as measured on an
    # AVX-512 CPU with numba 0.68): 13 runs go as one padded block of 16
    costs = {1: 130e-9, 8: 53e-9, 12: 43e-9, 16: 15.6e-9, 24: 11.3e-9, 32: 10e-9}
    assert (blocks.plan(13, costs, 1).block, blocks.plan(13, costs, 1).padded) == (16, 16)
    fig8 = blocks.plan(25, costs, 2)  # Fig. 8's 25 runs: two 16-run blocks, one per core
    assert (fig8.block, fig8.padded, fig8.threads) == (16, 32, 2)
    assert blocks.plan(1, costs, 2) == blocks.BlockPlan(1, 1, 1, 1, 130e-9)


def test_fixed_block_keeps_the_callers_choice():
    p = blocks.fixed(11, 3, 8)
    assert (p.block, p.padded, p.threads, p.blocks) == (3, 11, 4, 4)


STEP_GROUPS = st.lists(st.tuples(st.integers(1, 40), st.integers(50, 2000)), min_size=1,
                       max_size=6, unique_by=lambda g: g[1])  # fmt: skip


@settings(max_examples=150, deadline=None)
@given(groups=STEP_GROUPS, costs=COSTS, threads=st.integers(1, 4), pad=st.booleans())
def test_layout_of_step_groups(groups, costs, threads, pad):
    """Runs with their own steps: every run in exactly one column of a block of its own step
    count, inert copies only in a group's last block (copies of a run of that group, record
    rows past the runs), thread parts that cover the blocks in order, and a predicted time
    that is the slowest part's work (checked against the blocks' own sums)."""
    rng = np.random.default_rng(len(groups))
    steps = rng.permutation(np.concatenate([np.full(n, s) for n, s in groups]))
    R = steps.size
    shape = blocks.groups_of(steps)
    plan = blocks.plan(shape, costs, threads) if pad else blocks.fixed(shape, 4, threads)
    columns, (parts, bounds, rows, dts, nsteps, _) = blocks.layout(plan, steps, 2 * np.pi / steps)
    real = rows < R
    assert sorted(columns[real]) == list(range(R)) and np.array_equal(columns[real], rows[real])
    assert sorted(rows[~real]) == list(range(R, columns.size)) and columns.size == plan.padded
    for i in range(bounds.size - 1):
        block = slice(bounds[i], bounds[i + 1])
        assert np.all(steps[columns[block]] == nsteps[i]) and 0 < bounds[i + 1] - bounds[i]
        assert bounds[i + 1] - bounds[i] <= plan.block and dts[i] == 2 * np.pi / nsteps[i]
        if not real[block].all():  # inert copies: padding of a group's last block only
            assert pad and (i + 1 == bounds.size - 1 or nsteps[i + 1] != nsteps[i])
    assert parts[0] == 0 and parts[-1] == bounds.size - 1 and np.all(np.diff(parts) >= 0)
    assert parts.size - 1 == plan.threads <= threads
    if pad:
        cost = plan.block * costs[plan.block] / nsteps.max()
        work = [cost * nsteps[parts[j] : parts[j + 1]].sum() for j in range(plan.threads)]
        assert plan.predicted == pytest.approx(max(work), rel=1e-12)


def test_step_groups_balance_the_threads():
    """Two step groups on two threads: the cheap blocks are not all given to one thread."""
    p = blocks.fixed(((8, 0.25), (8, 1.0)), 4, 2)  # blocks of relative work .25 .25 1 1
    assert p.parts() == [0, 3, 4]  # 1.5 against 1, not 0.5 against 2


class _Counting:
    """Stands in for measure(): counts calls, returns a fixed table."""

    def __init__(self):
        self.calls = 0

    def __call__(self, module, q, v, table):
        self.calls += 1
        return {b: 1e-8 * (1 + b % 16) for b in blocks.SIZES}


def test_cost_table_is_measured_once_then_read_from_disk(tmp_path, monkeypatch):
    fake = _Counting()
    monkeypatch.setattr(blocks, "measure", fake)
    monkeypatch.setattr(blocks, "_memory", {})
    path = tmp_path / "engine_D11.blocks.json"
    state = (np.zeros((11, 1)),) * 3
    first = blocks.block_costs(None, path, 5, state)
    monkeypatch.setattr(blocks, "_memory", {})  # a new process
    second = blocks.block_costs(None, path, 5, state)
    assert fake.calls == 1 and first == second
    # a damaged or incomplete table, or one measured by another calibration, is measured
    # again, never trusted
    version = blocks.CALIBRATION
    for damage in ["{not json", json.dumps({"costs": {"16": 1e-8}, "calibration": version}),
                   json.dumps({"costs": {str(b): -1.0 for b in blocks.SIZES},
                               "calibration": version}),
                   json.dumps({"costs": {str(b): 2.0 for b in blocks.SIZES},
                               "calibration": version - 1})]:  # fmt: skip
        path.write_text(damage)
        monkeypatch.setattr(blocks, "_memory", {})
        assert blocks.block_costs(None, path, 5, state) == first
    assert fake.calls == 5


def test_measured_table_covers_every_size_with_positive_costs():
    from sinktheory.engine.cache import load

    mod = load(HENON_HEILES)
    costs = blocks.measure(mod, np.array([[0.0], [0.1]]), np.array([[0.3], [0.0]]),
                           mod.table_of([], 1))  # fmt: skip
    assert set(costs) == set(blocks.SIZES)
    assert all(np.isfinite(c) and c > 0 for c in costs.values())
    # a block of 64 runs costs more in all than one run (a sanity check on the timing)
    assert costs[64] * 64 > costs[1]


def test_a_disturbed_timing_never_makes_a_step_look_free(monkeypatch):
    """The cold CI once timed a short call slower than the long one: the step then cost
    1e-12 s, and the block looked free.  With fake clocks (``steps`` seconds a call, the
    short calls disturbed to 3x in the first round, or in every round) the cost is the true
    one after a new round, or the long call's upper bound, never below it."""
    calls = {"n": 0, "rounds": 1}

    def fake_time(module, q, v, table, size, weights, steps):
        calls["n"] += 1
        first_rounds = calls["n"] <= 2 * blocks._REPEATS * calls["rounds"]
        disturbed = first_rounds and steps == 100
        return 1e-3 + steps * (3.0 if disturbed else 1.0)

    monkeypatch.setattr(blocks, "_time", fake_time)
    assert blocks._step_seconds(None, None, None, None, 1, None, 100) == pytest.approx(1.0)
    calls.update(n=0, rounds=blocks._ROUNDS)
    bound = (1e-3 + 200.0) / 200
    assert blocks._step_seconds(None, None, None, None, 1, None, 100) == pytest.approx(bound)


@pytest.mark.parametrize("runs", [1, 7, 40])
def test_ensemble_plan_is_the_policy_for_its_runs(runs):
    from sinktheory.engine.core import Ensemble

    q = np.tile(np.array([[0.0], [0.1]]), runs)
    v = np.tile(np.array([[0.3], [0.0]]), runs)
    ens = Ensemble(HENON_HEILES, q, v, [])
    p = ens.plan(2)
    assert p.runs == runs and p.padded >= runs and p.threads <= 2


def test_chooser_keeps_the_faster_plan_and_looks_again_now_and_then():
    from sinktheory.engine.core import _Chooser

    two = blocks.BlockPlan(32, 16, 32, 2, 1.0)
    one = blocks.BlockPlan(32, 32, 32, 1, 1.5)
    speed = {two: 3.0, one: 1.0}  # a busy second core: two threads are slower here
    seconds: dict = {}
    chooser, picked, warm = _Chooser([two, one], seconds), [], False
    for _ in range(40):
        plan = chooser.next()
        picked.append(plan.threads)
        chooser.record(plan, speed[plan], warm)
        warm = True
    # warm-up, then each plan timed twice (the least-timed first), then the faster,
    # re-timing the other every 16th chunk
    assert picked[:5] == [2, 2, 1, 2, 1]
    assert [i for i, p in enumerate(picked) if p == 2 and i >= 5] == [15, 31]
    # one slow timing (a pause of the machine) does not switch: the best of the last two
    chooser.record(one, 10.0, True)
    assert chooser.next() is one
    # a later run of the same ensemble starts from what it learnt
    assert _Chooser([two, one], seconds).next() is one


def test_chooser_does_not_try_a_plan_predicted_slower_than_what_runs():
    """Two runs on two threads at their predicted speed: the one-thread plan, predicted twice
    as slow, is never run (it cost a short ensemble 2 of its 5 periods); once the running
    plan slows down past that prediction (a busy core), it is tried and taken."""
    from sinktheory.engine.core import _Chooser

    two = blocks.BlockPlan(2, 1, 2, 2, 30e-9)
    one = blocks.BlockPlan(2, 1, 2, 1, 60e-9)
    evaluations = 1197 * 11  # force evaluations per segment (blanes-moan6, Fig. 8's step)
    speed = {two: 0.4e-3, one: 0.75e-3}  # seconds per segment, as measured
    chooser, picked = _Chooser([two, one], {}, evaluations), []
    for i in range(40):
        plan = chooser.next()
        picked.append(plan)
        chooser.record(plan, speed[plan], i > 0)
    assert all(p is two for p in picked)
    speed[two] = 3e-3  # the second core got busy
    for _ in range(6):
        plan = chooser.next()
        picked.append(plan)
        chooser.record(plan, speed[plan], True)
    assert picked[-1] is one
