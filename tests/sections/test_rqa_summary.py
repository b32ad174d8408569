"""RQA.as_dict() is a summary: the line-length histograms stay out of it (issue 25)."""

import json

import numpy as np

from sinktheory.recurrence import rqa


def test_as_dict_is_a_summary_and_the_histograms_stay_available():
    series = np.sin(0.3 * np.arange(2000))
    r = rqa(series, eps=0.05)
    d = r.as_dict()
    assert set(d) == {
        "eps", "theiler", "l_min", "v_min", "recurrence_rate", "determinism",
        "laminarity", "trapping_time", "mean_recurrence_time",
    }  # fmt: skip
    assert len(json.dumps(d)) < 400  # a 2000-sample series: two histograms of 2001 entries
    h = r.histograms()
    assert h["diagonal_lines"] == r.diagonal_lines.tolist()
    assert h["vertical_lines"] == r.vertical_lines.tolist()
    ds = r.to_dataset()
    np.testing.assert_array_equal(ds.diagonal_lines.values, r.diagonal_lines)
    assert ds.attrs["determinism"] == d["determinism"]
