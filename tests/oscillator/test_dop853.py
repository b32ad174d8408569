"""The DOP853 tableau of :mod:`sinktheory.dop853` satisfies its order conditions.

Independent of where the numbers came from: Butcher's conditions sum_i b_i Phi_i(t) =
1/gamma(t) over every rooted tree t with up to 8 nodes (200 trees) for the weights B, and
sum_i e_i Phi_i(t) = 0 for the error estimators (E5 up to order 5, E3 up to order 3),
evaluated at 40 digits from the 30-digit literals of the module's source.  The literals
carry 30 digits, so the sums vanish to about 1e-28; a wrong digit anywhere in the first 20
shows up as > 1e-20.
"""

import ast
import functools
from pathlib import Path

import mpmath
import pytest

from sinktheory import dop853

SOURCE = Path(dop853.__file__).read_text()
STAGES = dop853.N_STAGES + 1  # with the FSAL stage


def _literals():
    """A, C, E3, E5 from the source text at full precision (not via float64)."""
    A = [[mpmath.mpf(0)] * STAGES for _ in range(STAGES)]
    e5 = [mpmath.mpf(0)] * STAGES
    bhh = {}
    c = []
    for node in ast.parse(SOURCE).body:
        if isinstance(node, ast.Assign) and isinstance(node.targets[0], ast.Subscript):
            target = ast.unparse(node.targets[0])
            value = ast.get_source_segment(SOURCE, node.value)
            if target.startswith("A["):
                i, j = (int(k) for k in target[2:-1].split(","))
                A[i][j] = mpmath.mpf(value.replace(" ", ""))
            elif target.startswith("E5["):
                e5[int(target[3:-1])] = mpmath.mpf(value)
        elif isinstance(node, ast.AugAssign):
            bhh[int(ast.unparse(node.target)[3:-1])] = mpmath.mpf(
                ast.get_source_segment(SOURCE, node.value)
            )
        elif isinstance(node, ast.Assign) and ast.unparse(node.targets[0]) == "C":
            (elements,) = node.value.args
            c = [mpmath.mpf(ast.get_source_segment(SOURCE, e)) for e in elements.elts]
    b = A[STAGES - 1][: STAGES - 1] + [mpmath.mpf(0)]
    e3 = [b[i] - bhh.get(i, 0) for i in range(STAGES)]
    return A, c, b, e3, e5


# 40 digits here and in every test of this module (see the fixture), never globally: a
# module-level mp.dps would leak into every later test of the session
with mpmath.workdps(40):
    A, C, B, E3, E5 = _literals()


@pytest.fixture(autouse=True)
def _forty_digits():
    with mpmath.workdps(40):
        yield


@functools.cache
def _trees(order):
    """Rooted trees with ``order`` nodes, each a sorted tuple of its subtrees."""
    if order == 1:
        return ((),)
    return tuple(sorted({tuple(sorted(f)) for f in _forests(order - 1)}))


@functools.cache
def _forests(nodes):
    """Every sequence of trees with ``nodes`` nodes in all (duplicates removed by sorting)."""
    if nodes == 0:
        return ((),)
    return tuple(
        (tree, *rest)
        for size in range(1, nodes + 1)
        for tree in _trees(size)
        for rest in _forests(nodes - size)
    )


def _order(tree):
    return 1 + sum(_order(t) for t in tree)


def _density(tree):
    out = _order(tree)
    for t in tree:
        out *= _density(t)
    return out


def _phi(tree):
    """Elementary weights Phi_i(t) = prod over subtrees u of sum_j a_ij Phi_j(u)."""
    out = [mpmath.mpf(1)] * STAGES
    for u in tree:
        pu = _phi(u)
        out = [out[i] * mpmath.fsum(A[i][j] * pu[j] for j in range(STAGES)) for i in range(STAGES)]
    return out


def test_tree_count_is_butchers():
    """1, 1, 2, 4, 9, 20, 48, 115 rooted trees of orders 1..8 (OEIS A000081)."""
    assert [len(_trees(k)) for k in range(1, 9)] == [1, 1, 2, 4, 9, 20, 48, 115]


def test_nodes_are_row_sums():
    for i in range(STAGES):
        assert abs(mpmath.fsum(A[i]) - C[i]) < 1e-28


@pytest.mark.parametrize("order", range(1, 9))
def test_eighth_order_conditions(order):
    for tree in _trees(order):
        total = mpmath.fsum(b * p for b, p in zip(B, _phi(tree), strict=True))
        assert abs(total - mpmath.mpf(1) / _density(tree)) < 1e-25, tree


@pytest.mark.parametrize("weights, up_to", [(E5, 5), (E3, 3)], ids=["E5", "E3"])
def test_error_estimators_vanish_on_low_order_trees(weights, up_to):
    for order in range(1, up_to + 1):
        for tree in _trees(order):
            total = mpmath.fsum(e * p for e, p in zip(weights, _phi(tree), strict=True))
            assert abs(total) < 1e-25, (order, tree)
    # and they do not vanish beyond (else they would estimate nothing)
    worst = max(
        abs(mpmath.fsum(e * p for e, p in zip(weights, _phi(t), strict=True)))
        for t in _trees(up_to + 1)
    )
    assert worst > 1e-6


def test_float_arrays_match_the_literals():
    for i in range(STAGES):
        for j in range(STAGES - 1):
            assert dop853.A[i, j] == float(A[i][j])
    assert [float(e) for e in E5] == dop853.E5.tolist()
    assert [float(e) for e in E3] == pytest.approx(dop853.E3.tolist(), rel=1e-15, abs=1e-17)
