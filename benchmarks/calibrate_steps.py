"""Work-precision calibration behind ``simulate(tol=...)`` (sinktheory.stepsize).

For every splitting scheme and a ladder of step x frequency products h*omega_max, run the
paper's workloads (flat alpha = 1/2 with beta in {-0.5, 0.3} and n in {4, 10}; symmetric
alpha = 1, beta = 0.1, n = 6; k in {1, 5}; m = 0.2; 2 runs x PERIODS periods) and record the
largest relative total-energy error.  The error model is err = C (h omega)^p with the
scheme's order p; h omega_max (the cliff) is the largest product at which the worst error
over the workloads is still within 10x of the order-p law through the smallest product, and
C is the largest err / (h omega)^p at or below the cliff (an envelope, not a fit).  The
script prints the table that goes into ``sinktheory/stepsize.py`` (CALIBRATION) and the raw
measurements.

    python benchmarks/calibrate_steps.py [PERIODS]

``--tail H1,H2,...`` instead measures the tail that short calibration runs miss: one
scheme (``--scheme``, default blanes-moan6) at the given products on every well with five
particles, 25 runs x 1500 periods per seed over ``--seeds`` seeds, printing the worst
error of each seed (the figures the README quotes against taking larger steps; 3 min
15 s for 0.7,0.8 and 4 seeds on 2 cores).
"""

from __future__ import annotations

import argparse
import math
import time

from sinktheory import RunSettings, Sink, Well
from sinktheory.errors import NumericalError
from sinktheory.integrators import SCHEMES
from sinktheory.simulate import simulate
from sinktheory.stepsize import aligned_step, stiffness_frequency

WELLS = [Well(0.5, b, n) for b in (-0.5, 0.3) for n in (4, 10)] + [
    Well(1.0, 0.1, 6, shape="symmetric")
]
LADDER = {
    "verlet": [0.004, 0.008, 0.016, 0.03],
    "yoshida4": [0.03, 0.06, 0.12, 0.2],
    "blanes-moan4": [0.1, 0.2, 0.3, 0.45, 0.6],
    "yoshida6": [0.1, 0.2, 0.3, 0.4],
    "blanes-moan6": [0.3, 0.45, 0.6, 0.75, 0.9],
    "suzuki-umeno8": [0.2, 0.35, 0.5, 0.65],
}


def measure(periods: int) -> dict[str, list[tuple[float, float]]]:
    """(h omega, worst error over the workloads) per scheme."""
    out: dict[str, list[tuple[float, float]]] = {}
    for name, ladder in LADDER.items():
        rows = []
        for h_omega in ladder:
            worst = 0.0
            for well in WELLS:
                for k in (1, 5):
                    sink = Sink(well, particles=k, mass=0.2)
                    omega = stiffness_frequency(sink, 0.5)
                    dt, _ = aligned_step(h_omega / omega)
                    try:
                        res = simulate(
                            sink,
                            RunSettings(runs=2, periods=periods, seed=3),
                            scheme=name,
                            dt=dt,
                            energy_bound=1e-2,
                            progress=False,
                        )
                        err = res.max_relative_energy_error
                    except NumericalError:
                        err = math.inf
                    worst = max(worst, err)
            rows.append((h_omega, worst))
            print(f"{name:14s} h*omega = {h_omega:<6g} worst error {worst:.3g}", flush=True)
        out[name] = rows
    return out


def envelope(rows, order):
    """(C, h omega_max) from the measurements (see the module docstring).

    The cliff is the largest measured product at which the error is still within 10x of
    the order-p law fitted at the smallest one; C is then the largest err / (h omega)^p
    at or below the cliff, so the model bounds every measurement it is used for.
    """
    finite = sorted((h, e) for h, e in rows if math.isfinite(e) and e > 0)
    h0, e0 = finite[0]
    cliff = max(h for h, e in finite if e <= 10 * e0 * (h / h0) ** order)
    C = max(e / h**order for h, e in finite if h <= cliff)
    return C, cliff


def tail(scheme: str, products: list[float], seeds: int) -> None:
    """Worst error per seed of ``scheme`` at each product on the five-particle workloads."""
    for well in WELLS:
        sink = Sink(well, particles=5, mass=0.2)
        omega = stiffness_frequency(sink, 0.5)
        for h_omega in products:
            dt, steps = aligned_step(h_omega / omega)
            worst = []
            for seed in range(seeds):
                res = simulate(
                    sink,
                    RunSettings(runs=25, periods=1500, seed=seed),
                    scheme=scheme,
                    dt=dt,
                    energy_bound=1.0,
                    progress=False,
                )
                worst.append(res.max_relative_energy_error)
            print(
                f"{well.shape:9s} beta={well.beta:<5g} n={well.n:<3d} h*omega={h_omega:<5g} "
                f"({steps} steps/T): worst per seed "
                + " ".join(f"{e:.2g}" for e in worst)
                + f"; max {max(worst):.2g}",
                flush=True,
            )


def main() -> None:
    from machine import describe  # benchmarks/ is on sys.path when run as a script

    print(describe())
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("periods", nargs="?", type=int, default=300)
    parser.add_argument("--tail", help="comma-separated h*omega products (tail mode)")
    parser.add_argument("--scheme", default="blanes-moan6")
    parser.add_argument("--seeds", type=int, default=4)
    args = parser.parse_args()
    if args.tail:
        tail(args.scheme, [float(h) for h in args.tail.split(",")], args.seeds)
        return
    periods = args.periods
    t = time.perf_counter()
    data = measure(periods)
    print(f"\nmeasured in {time.perf_counter() - t:.0f} s over {periods} periods\n")
    print("CALIBRATION = {")
    for name, rows in data.items():
        C, h_max = envelope(rows, SCHEMES[name].order)
        print(f'    "{name}": ({C:.3g}, {h_max:g}),')
    print("}")


if __name__ == "__main__":
    main()
