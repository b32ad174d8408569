"""One result object for every chaos indicator of an ensemble run.

All exponents are per unit time (the paper's units: container period T = 2 pi); ``times``
are the segment ends (for the sink, the container periods t_j = j T) at which the engine
renormalised the deviation vectors and recorded the indicators.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from .. import validation as v
from ..errors import ParameterError
from ..results import Result, plain
from ..runstats import ensemble_mean
from .verdicts import Split, box_starts, split

__all__ = ["ChaosResult", "PER_RUN_NOTE", "sali_from_gali2"]

#: What ``as_dict`` says next to the per-run values (``--json`` of ``sinktheory chaos``).
PER_RUN_NOTE = (
    "per-run values: a chaotic run changes with any change of round-off (threads, compiler, "
    "machine, version), so compare only the ensemble means with their standard errors"
)


def sali_from_gali2(g: np.ndarray) -> np.ndarray:
    """SALI of two unit vectors from their GALI_2 = sin(theta).

    SALI = min(|w1 + w2|, |w1 - w2|) = 2 sin(phi/2), phi = min(theta, pi - theta), and
    sin(phi) = GALI_2; written as GALI_2 / cos(phi/2) so tiny values keep their digits.

    Examples
    --------
    >>> th = np.array([1e-13, 0.3, np.pi / 2, np.pi - 0.3])
    >>> w1, w2 = np.array([1.0, 0.0]), np.stack([np.cos(th), np.sin(th)], 1)
    >>> direct = np.minimum(np.linalg.norm(w1 + w2, axis=1), np.linalg.norm(w1 - w2, axis=1))
    >>> bool(np.allclose(sali_from_gali2(np.sin(th)), direct, rtol=1e-12, atol=0))
    True
    """
    from ..validation import finite_array

    g = np.clip(finite_array("g", g, "GALI_2 values (finite numbers in [0, 1])"), 0.0, 1.0)
    return g / np.cos(0.5 * np.arcsin(g))


def time_average(times: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Running time average (1/t) int_0^t y ds by the trapezoid rule over the samples
    (last axis); the first sample (t = 0) is returned as is."""
    y = np.asarray(y, float)
    dt = np.diff(times)
    integral = np.concatenate(
        [np.zeros(y.shape[:-1] + (1,)), np.cumsum(0.5 * dt * (y[..., 1:] + y[..., :-1]), -1)], -1
    )
    out = y.copy()
    out[..., 1:] = integral[..., 1:] / (times[1:] - times[0])
    return out


@dataclass(frozen=True)
class ChaosResult(Result):
    """Chaos indicators of R runs, recorded at the segment ends.

    Attributes
    ----------
    times : ndarray (S + 1,)
        Segment ends t_0 = 0, ..., t_S (for the sink, multiples of the period T = 2 pi).
    log_growth : ndarray (R, S + 1)
        ln |delta_1(t)| of the first deviation vector (its growth with every
        renormalisation accumulated); lambda_1(t) = log_growth / t.
    spectrum_logs : ndarray (R, S + 1, 2D), (R, S + 1, D) or None
        Accumulated ln R_ii of the QR (modified Gram-Schmidt) renormalisations of 2D
        vectors (or of D, when ``spectrum_paired``); lambda_i(t) = spectrum_logs[..., i] / t,
        in decreasing order.
    spectrum_paired : bool
        Only the D largest exponents were computed; :attr:`spectrum` completes them by
        the symplectic pairing lambda_{2D+1-i} = -lambda_i, and :attr:`pair_sums` is None
        (nothing measured to check).
    gali : ndarray (R, S + 1) or None
        GALI_k(t) of the first ``gali_order`` unit deviation vectors.
    gali_order : int
        k of ``gali`` (0: not computed).
    megno : ndarray (R, S + 1) or None
        MEGNO Y(t) of the first deviation vector (Cincotta & Simo 2000).
    transverse_logs : ndarray (R, S + 1) or None
        ln |delta_y(t)| of a deviation vector in the y-directions, for runs started on the
        invariant subspace y = 0 (their own orbits, not those of ``log_growth``).
    run_errors : ndarray (R,)
        Largest relative total-energy error of each run (of every ensemble that ran).
    parameters : dict
        What was run (system, parameters, scheme, dt, steps, renorm, seed, ...).
    transient : int
        Segments left out of :attr:`lambda1` and :attr:`transverse`: with t_0 =
        times[transient] they are the growth rates from t_0, (ln|delta(t)| -
        ln|delta(t_0)|) / (t - t_0), so the approach to the attractor does not weigh in.
    """

    times: np.ndarray
    log_growth: np.ndarray
    spectrum_logs: np.ndarray | None = None
    spectrum_paired: bool = False
    gali: np.ndarray | None = None
    gali_order: int = 0
    megno: np.ndarray | None = None
    transverse_logs: np.ndarray | None = None
    run_errors: np.ndarray = field(default_factory=lambda: np.zeros(0))
    parameters: dict = field(default_factory=dict)
    transient: int = 0

    # ----------------------------------------------------------------- per run
    def _runs_of(self, runs: slice, parameters: dict) -> ChaosResult:
        """The result of the runs ``runs`` alone, described by ``parameters``."""

        def part(a):
            return None if a is None else a[runs]

        return replace(
            self,
            log_growth=self.log_growth[runs],
            spectrum_logs=part(self.spectrum_logs),
            gali=part(self.gali),
            megno=part(self.megno),
            transverse_logs=part(self.transverse_logs),
            run_errors=self.run_errors[runs],
            parameters=parameters,
        )

    @property
    def runs(self) -> int:
        return self.log_growth.shape[0]

    @property
    def duration(self) -> float:
        return float(self.times[-1] - self.times[0])

    def _rate(self, logs: np.ndarray) -> np.ndarray:
        """Growth rate of ``logs`` (R, S + 1) over the run, after the transient."""
        if self.transient == 0:
            return logs[:, -1] / self.duration
        tr = self.transient
        return (logs[:, -1] - logs[:, tr]) / (self.times[-1] - self.times[tr])

    @property
    def lambda1(self) -> np.ndarray:
        """Maximal Lyapunov exponent of each run at the last time (after the transient),
        (R,)."""
        return self._rate(self.log_growth)

    @property
    def starts(self) -> str:
        """The start distribution, in words (the sink's runs: from their parameters)."""
        p = self.parameters
        return box_starts(p["box"]) if "box" in p else "start states given to indicators"

    def split(self) -> Split:
        """:attr:`lambda1` split into regular and chaotic runs
        (:func:`sinktheory.chaos.verdicts.split`, over the time after the transient)."""
        span = self.times[-1] - self.times[self.transient]
        return split(self.lambda1, span / (2.0 * np.pi), self.starts)

    @property
    def finite_time_lambda1(self) -> np.ndarray:
        """lambda_1(t_j) = ln|delta_1(t_j)| / t_j for j >= 1, (R, S)."""
        return self.log_growth[:, 1:] / (self.times[1:] - self.times[0])

    @property
    def spectrum(self) -> np.ndarray | None:
        """Lyapunov spectrum lambda_1 >= ... >= lambda_2D of each run, (R, 2D)."""
        if self.spectrum_logs is None:
            return None
        top = self.spectrum_logs[:, -1] / self.duration
        if self.spectrum_paired:
            return np.concatenate([top, -top[:, ::-1]], axis=1)
        return top

    @property
    def pair_sums(self) -> np.ndarray | None:
        """lambda_i + lambda_{2D+1-i}, i = 1..D, of each run (0 for a symplectic flow), (R, D)."""
        s = self.spectrum
        if s is None or self.spectrum_paired:
            return None
        D = s.shape[1] // 2
        return s[:, :D] + s[:, ::-1][:, :D]

    @property
    def sali(self) -> np.ndarray | None:
        """SALI(t) of the first two vectors (only when ``gali_order`` is 2), (R, S + 1)."""
        if self.gali is None or self.gali_order != 2:
            return None
        return sali_from_gali2(self.gali)

    @property
    def mean_megno(self) -> np.ndarray | None:
        """Time-averaged MEGNO <Y>(t) (trapezoid over the segment ends), (R, S + 1).

        Tends to 2 on quasi-periodic orbits, 0 on stable periodic ones and grows like
        lambda_1 t / 2 on chaotic ones.
        """
        if self.megno is None:
            return None
        return time_average(self.times, self.megno)

    @property
    def transverse(self) -> np.ndarray | None:
        """Transverse exponent of the invariant subspace y = 0 of each run (after the
        transient), (R,)."""
        if self.transverse_logs is None:
            return None
        return self._rate(self.transverse_logs)

    def window_exponents(self, window: int, logs: np.ndarray | None = None):
        """Finite-time exponents over consecutive windows of ``window`` segments.

        Returns (ends, exponents): window end times (W,) and, per run, (L(t_end) -
        L(t_start)) / (t_end - t_start), shape (R, W), of ``logs`` (default
        ``log_growth``; any (R, S + 1, ...) array of accumulated logs).
        """
        window = v.positive_int("window", window, maximum=max(1, len(self.times) - 1))
        if logs is not None:
            logs = v.real_array("logs", logs)
            if logs.ndim < 2 or logs.shape[:2] != self.log_growth.shape[:2]:
                allowed = f"shape (R, S + 1, ...) = {self.log_growth.shape[:2]} + ..."
                raise ParameterError("logs", f"an array of shape {logs.shape}", allowed)
        logs = self.log_growth if logs is None else logs
        idx = np.arange(0, len(self.times), window)
        t = self.times[idx]
        return t[1:], np.diff(logs[:, idx], axis=1) / np.diff(t).reshape(
            (1, -1) + (1,) * (logs.ndim - 2)
        )

    # ----------------------------------------------------------------- ensemble
    def mean(self, name: str) -> tuple[np.ndarray, np.ndarray]:
        """Ensemble mean and standard error of a per-run quantity (see
        :func:`sinktheory.runstats.ensemble_mean`): ``name`` is an attribute or property
        of shape (R, ...), e.g. "lambda1", "spectrum", "finite_time_lambda1", "gali"."""
        allowed = "a per-run quantity of this run (lambda1, spectrum, finite_time_lambda1, gali...)"
        a = getattr(self, name, None) if isinstance(name, str) and name[:1].isalpha() else None
        try:
            a = np.asarray(a, float)
        except (TypeError, ValueError):
            a = None
        if a is None or a.ndim == 0 or a.shape[0] != self.log_growth.shape[0]:
            raise ParameterError("name", name, allowed)
        shape = a.shape[1:]
        m, se = ensemble_mean(a.reshape(a.shape[0], -1))
        return m.reshape(shape), se.reshape(shape)

    def as_dict(self, *, series: bool = False) -> dict:
        """JSON-ready summary: per-run final values, ensemble mean and standard error, and
        ``note`` (:data:`PER_RUN_NOTE`: only the ensemble means are comparable).

        ``series=True`` adds the ensemble mean (and standard error) of the time series
        (finite-time lambda_1, GALI, MEGNO) at ``times``.
        """

        def clean(x):  # floats, flattened
            return plain(np.asarray(x, float).ravel() if np.ndim(x) else float(x))

        def summary(runs, m, se) -> dict:
            return {"runs": plain(np.asarray(runs, float)), "mean": clean(m), "stderr": clean(se)}

        out: dict = {"parameters": plain(self.parameters), "runs": self.runs}
        out["note"] = PER_RUN_NOTE
        out["time"] = self.duration
        out["transient_time"] = float(self.times[self.transient] - self.times[0])
        out["max_relative_energy_error"] = float(np.max(self.run_errors, initial=0.0))
        out["spectrum_paired"] = self.spectrum_paired
        names = ["lambda1"]
        if self.spectrum_logs is not None:
            names += ["spectrum"] if self.spectrum_paired else ["spectrum", "pair_sums"]
        if self.transverse_logs is not None:
            names.append("transverse")
        for name in names:
            per_run = getattr(self, name)
            m, se = self.mean(name)
            out[name] = summary(per_run, m, se)
        out["split_lambda1"] = self.split().as_dict()
        finals = {}
        if self.gali is not None:
            finals[f"gali{self.gali_order}"] = self.gali[:, -1]
        if self.sali is not None:
            finals["sali"] = self.sali[:, -1]
        if self.megno is not None:
            finals["megno"] = self.megno[:, -1]
            finals["mean_megno"] = self.mean_megno[:, -1]
        for name, per_run in finals.items():
            m, se = ensemble_mean(per_run[:, None])
            out[name] = summary(per_run, m[0], se[0])
        if series:
            s = {"times": self.times.tolist()}
            m, se = self.mean("finite_time_lambda1")
            s["lambda1"] = {"mean": [None] + clean(m), "stderr": [None] + clean(se)}
            for name in ("gali", "megno"):
                a = getattr(self, name)
                if a is not None:
                    m, se = ensemble_mean(a)
                    s[name] = {"mean": clean(m), "stderr": clean(se)}
            out["series"] = s
        return out

    def to_dataset(self):
        """The result as an :class:`xarray.Dataset` (dims run, time, exponent).

        Examples
        --------
        >>> r = ChaosResult(np.arange(3.0), np.array([[0.0, 1.0, 2.0]]))
        >>> ds = r.to_dataset()
        >>> float(ds.lambda1[0]), ds.log_growth.dims
        (1.0, ('run', 'time'))
        """
        import xarray as xr

        rt = ("run", "time")
        data = {
            "log_growth": (rt, self.log_growth),
            "lambda1": (("run",), self.lambda1),
            "run_errors": (("run",), np.asarray(self.run_errors, float))
            if np.size(self.run_errors) == self.runs
            else (("run",), np.zeros(self.runs)),
        }
        if self.spectrum_logs is not None:
            computed = "computed_exponent" if self.spectrum_paired else "exponent"
            data["spectrum_logs"] = (rt + (computed,), self.spectrum_logs)
            data["spectrum"] = (("run", "exponent"), self.spectrum)
        if self.gali is not None:
            data["gali"] = (rt, self.gali)
        if self.sali is not None:
            data["sali"] = (rt, self.sali)
        if self.megno is not None:
            data["megno"] = (rt, self.megno)
            data["mean_megno"] = (rt, self.mean_megno)
        if self.transverse_logs is not None:
            data["transverse_logs"] = (rt, self.transverse_logs)
            data["transverse"] = (("run",), self.transverse)
        attrs = {
            k: (v if isinstance(v, int | float | str) else str(v))
            for k, v in self.parameters.items()
        }
        attrs["gali_order"] = self.gali_order
        attrs["spectrum_paired"] = int(self.spectrum_paired)
        return xr.Dataset(
            data, coords={"time": self.times, "run": np.arange(self.runs)}, attrs=attrs
        )
