"""Per-run chaos indicators come with the warning that only ensemble means compare."""

import numpy as np

from sinktheory.chaos.result import PER_RUN_NOTE, ChaosResult


def test_per_run_lambda1_carries_the_note():
    times = np.array([0.0, 1.0, 2.0])
    logs = np.array([[0.0, 0.5, 1.2], [0.0, 0.3, 0.8]])  # lambda_1(t = 2) = 0.6 and 0.4
    d = ChaosResult(times=times, log_growth=logs).as_dict()
    assert d["lambda1"]["runs"] == [0.6, 0.4]
    assert abs(d["lambda1"]["mean"] - 0.5) < 1e-15
    assert d["note"] == PER_RUN_NOTE and "only the ensemble means" in PER_RUN_NOTE
