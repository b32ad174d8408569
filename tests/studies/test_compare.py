"""The attachment comparison (issue 23): efficiency, 90 % times, wavelet ridge, CLI."""

import json
import math

import numpy as np
import pytest
from _cli import probe, run_cli

from sinktheory.attachments import Attachment, impulse_response
from sinktheory.compare.efficiency import attachments_of, compare
from sinktheory.compare.wavelet import wavelet_map
from sinktheory.errors import ParameterError

TINY = ["--energies", "0.01", "0.1", "2", "--runs", "2", "--periods", "6", "--quiet"]


def test_efficiency_is_the_mean_of_direct_impulse_responses():
    """A tiny grid against impulse_response called directly with the same seed: the
    efficiency is the runs' mean fraction (s.e. with ddof = 1), the 90 % time their mean
    crossing in periods, to round-off."""
    atts = [Attachment("nes", n=2), Attachment("impact")]
    energies = [0.02, 0.2]
    c = compare(atts, energies, damping=0.05, periods=12, runs=3, seed=7, progress=False)
    for i, att in enumerate(atts):
        for j, e in enumerate(energies):
            r = impulse_response(att, e, damping=0.05, periods=12, runs=3, seed=7)
            f = r.fraction_dissipated()
            assert c.efficiency[i, j] == pytest.approx(f.mean(), rel=1e-14)
            assert c.efficiency_se[i, j] == pytest.approx(f.std(ddof=1) / math.sqrt(3), rel=1e-12)
            t = r.time_to_fraction(0.9) / (2 * math.pi)
            assert c.reached[i, j] == np.isfinite(t).sum()
            if np.isfinite(t).any():
                assert c.t90[i, j] == pytest.approx(t[np.isfinite(t)].mean(), rel=1e-14)
            else:
                assert math.isnan(c.t90[i, j])
    # the vibro-impact absorber at c = 0.05 reaches 90 % within 12 periods at E0 = 0.02
    assert c.reached[1, 0] == 3


def test_without_a_dashpot_nothing_is_dissipated():
    """An independent anchor for the efficiency: with no damper the model is conservative
    (the energy that leaves the container goes into the attachment, it is not dissipated),
    so the fraction dissipated is 0 to the audit's tolerance, whatever the attachment moved
    -- an efficiency counted from the container's loss instead would be far from 0."""
    atts = [Attachment("nes", n=2), Attachment("impact"), Attachment("well", n=4)]
    c = compare(atts, [0.05, 0.5], damping=0.0, periods=12, runs=2, seed=3, progress=False)
    assert np.all(np.abs(c.efficiency) < 1e-8), c.efficiency
    for att in atts:  # while the container did lend energy to the attachment (to 0.28-0.55)
        r = impulse_response(att, 0.5, damping=0.0, periods=12, runs=2, seed=3)
        assert r.container_energy.min(axis=1).max() < 0.9 * 0.5


@pytest.mark.parametrize("omega0", [0.45, 0.9, 1.3, 2.6])
def test_wavelet_ridge_recovers_a_pure_tone(omega0):
    """The ridge of cos(omega0 t + 0.4), 16 samples per period T = 2 pi, 40 periods, equals
    omega0 (the oracle: the tone's own frequency) at every time inside the cone of
    influence, to 1e-3 relative with 8 or more samples per cycle (omega0 <= 2) and 2e-3 at
    omega0 = 2.6 (6 samples per cycle: the sampled wavelet's wobble, 1.05e-3 measured).
    The map's grid spacing is 1.5 %, so the parabolic refinement and the scale
    correction are what is tested."""
    t = np.arange(0, 40 * 2 * np.pi, 2 * np.pi / 16)
    w = wavelet_map(t, 3.0 * np.cos(omega0 * t + 0.4), omega=(0.3, 4.0, 180))
    ridge = w.ridge[np.isfinite(w.ridge)]
    assert ridge.size > t.size // 3
    assert np.max(np.abs(ridge / omega0 - 1)) < (1e-3 if omega0 <= 2 else 2e-3)


def test_wavelet_ridge_follows_a_frequency_step():
    """Two tones one after the other (0.8 then 1.6): the ridge is each tone's frequency
    away from the switch (4 envelope widths of the lower tone on either side)."""
    t = np.arange(0, 120 * 2 * np.pi, 2 * np.pi / 16)
    half = t[t.size // 2]
    x = np.where(t < half, np.cos(0.8 * t), np.cos(1.6 * t))
    w = wavelet_map(t, x, omega=(0.4, 3.0, 160))
    width = 4 * (2 * np.pi / 0.8) * math.sqrt(1.5 / 2)
    early = np.isfinite(w.ridge) & (t < half - width)
    late = np.isfinite(w.ridge) & (t > half + width)
    assert early.sum() > 100 and late.sum() > 100
    assert np.max(np.abs(w.ridge[early] / 0.8 - 1)) < 2e-3
    assert np.max(np.abs(w.ridge[late] / 1.6 - 1)) < 2e-3


@pytest.mark.parametrize(
    "kw, name",
    [
        ({"wavelet": "morl"}, "wavelet"),
        ({"omega": (0.5, 20.0, 50)}, "omega"),  # above the Nyquist frequency 8
        ({"omega": (1.0, 0.5, 50)}, "omega"),
    ],
)
def test_wavelet_map_refuses_bad_input(kw, name):
    t = np.arange(0, 100.0, 2 * np.pi / 16)
    with pytest.raises(ParameterError, match=f"^{name} ="):
        wavelet_map(t, np.cos(t), **kw)


def test_attachments_of_refuses_bad_lists():
    with pytest.raises(ParameterError, match="^attachments ="):
        attachments_of(["nes", "spring"])
    with pytest.raises(ParameterError, match="^particles ="):
        attachments_of(["well"], particles=[1, 1])


REFUSALS = [
    (["--damping", "-1"], "damping"),
    (["--damping", "0.01", "--energies", "1", "0.1", "3"], "energies"),
    (["--damping", "0.01", "--energies", "0", "0.1", "3"], "energies"),
    (["--damping", "0.01", "--attachments", "nes,spring"], "attachments"),
    (["--damping", "0.01", "--runs", "1"], "runs"),
    (["--damping", "0.01", "--periods", "0"], "periods"),
    (["--damping", "0.01", "--particles", "0"], "particles"),
    (["--damping", "0.01", "--mass", "0"], "mass"),
    (["--damping", "0.01", "--periods", "1e15"], "periods"),
    (["--damping", "0.01", "--plot", "out.txt"], "plot"),
    (["--damping", "0.01", "--wavelet-energy", "0.1"], "wavelet_energy"),
    (
        ["--damping", "0.01", "--wavelet-plot", "w.png", "--samples-per-period", "4"],
        "samples_per_period",
    ),  # fmt: skip
]


@pytest.mark.parametrize("argv, name", REFUSALS)
def test_cli_refuses_in_one_line(argv, name, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, err = run_cli(["compare", *argv], capsys)
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and f"error: {name} =" in err, err
    assert not any(tmp_path.iterdir())


def test_cli_json_and_plot(capsys, tmp_path):
    plot = tmp_path / "c.png"
    argv = ["compare", "--attachments", "nes,well", "--particles", "1,2", "--damping", "0.05"]
    code, out, err = run_cli([*argv, *TINY, "--plot", str(plot), "--json"], capsys)
    assert code == 0, err
    d = json.loads(out)
    assert d["attachment"] == ["NES n = 2", "well flat k = 1", "well flat k = 2"]
    assert d["container_energy"] == pytest.approx([0.01, 0.1])
    for key in ("efficiency", "efficiency_se", "t90", "t90_se", "reached", "max_audit_error"):
        assert np.array(d[key], dtype=float).shape == (3, 2), key
    assert set(d["half_dissipated"]) == set(d["attachment"])
    assert [a["kind"] for a in d["attachments"]] == ["nes", "well", "well"]
    assert d["damping"] == 0.05 and d["runs"] == 2 and d["periods"] == 6
    assert max(d["max_audit_error"][0] + d["max_audit_error"][1]) < 1e-6
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_compare_help_imports_nothing_heavy(tmp_path):
    status, heavy, proc = probe(["compare", "--help"], tmp_path)
    assert status == 0 and heavy == [], proc.stderr
    status, heavy, proc = probe(["compare", "--damping", "0.1", "--plot", "x.txt"], tmp_path)
    assert status == 2 and heavy == [], proc.stderr


def test_cli_wavelet_figure_and_notes(capsys, tmp_path):
    """--wavelet-plot writes the maps over the backbones and names in the JSON what could not
    be drawn: the vibro-impact NES has no smooth normal modes."""
    png = tmp_path / "w.png"
    argv = ["compare", "--attachments", "nes,impact", "--damping", "0.01", *TINY]
    code, out, err = run_cli([*argv, "--wavelet-plot", str(png), "--json"], capsys)
    assert code == 0, err
    notes = json.loads(out)["wavelet_notes"]
    assert any(n.startswith("vibro-impact: ") and "no smooth normal modes" in n for n in notes)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_top_level_help_lists_compare(tmp_path):
    """The command's summary (with its '%') goes through argparse's help formatting."""
    status, heavy, proc = probe(["--help"], tmp_path)
    assert status == 0 and heavy == [], proc.stderr
    assert "90 % times" in " ".join(proc.stdout.split())  # however the help wraps
