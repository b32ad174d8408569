"""Write the notebooks (cells without outputs) from the cell texts below:
notebooks/tour.ipynb (the guided tour) and notebooks/your_own_well.ipynb (a well of your
own, end to end).

    python notebooks/make_notebooks.py

The notebooks are committed without outputs (tests/interface/test_notebooks.py checks
them, and that they match this file).  The documentation build executes them with myst-nb
and renders each as a page with its outputs; tests/interface/test_docs.py checks those
pages for the printed results and the figures as images.  Each first code cell selects
matplotlib's inline backend: without it a kernel started with ``MPLBACKEND=Agg`` (CI, the
test suite, some servers) shows a returned figure as the text ``<Figure size 800x450 with
1 Axes>``.
"""

from pathlib import Path

import nbformat

TOUR = [
    ("md", """# A guided tour of sinktheory

The stochastic energy sink of Pilipchuk (arXiv:1610.02939): a container of mass 1 on a
spring of stiffness 1 (period $T = 2\\pi$) holds $k$ light particles in a soft-walled
well. Nothing is damped, yet the container's energy drains into the particles.

The tour follows the paper's ladder with small parameters so it runs in about a minute:
derivation → period and series → Floquet chart → energy sink → recurrence."""),
    ("code", """%matplotlib inline
import numpy as np
import sinktheory as st
from sinktheory import symbolic as S"""),
    ("md", """## 1. Derivation
Everything numerical starts from the Lagrangian. The rescaled single-particle equations
come out of it, with $\\lambda = -2\\beta(\\alpha - \\beta)$ in Hill's equation:"""),
    ("code", """flat = S.rescaled_equations("flat")
print("x-equation:", flat.x_equation, "= 0")
print("y-equation:", flat.y_equation, "= 0")
print("lambda =", S.lambda_coefficient())
print("n = 1 adds a term:", S.rescaled_equations("flat", 1).hill_coefficient)"""),
    ("md", """## 2. The power-law oscillator
Along the normal mode the particle obeys $\\ddot x + x^{2n-1} = 0$. Its period has a
closed Gamma-function form, evaluated here to 40 digits; the triangle-wave series
approaches the exact solution order by order."""),
    ("code", """import mpmath
from sinktheory.oscillator import period
from sinktheory.series import error_table
print(mpmath.nstr(period(7, amplitude=1, dps=40), 40))
for row in error_table(5, 4, samples=801):
    print(row)"""),
    ("md", """## 3. Floquet stability of the normal mode $y = 0$
$\\phi_{T/2}$ against $\\beta$ for the flat well of Fig. 7; the stable interval's ends are
found by root finding, not read off the grid."""),
    ("code", """from sinktheory.floquet import model_problem, scan
from sinktheory.plot.floquet import plot_scan
result = scan(model_problem(0.5, 2), -1.0, 0.49, 200)
print("stable intervals:", result.stable_intervals)
plot_scan(result)"""),
    ("md", """## 4. The energy sink
Five particles in a scattering flat well (Fig. 8, here 6 runs over 150 periods). The
integrator is symplectic and every run's total energy is audited."""),
    ("code", """from sinktheory.simulate import simulate
sink = st.Sink(st.Well(alpha=0.5, beta=0.3, n=4), particles=5, mass=0.2)
res = simulate(sink, st.RunSettings(runs=6, periods=150, seed=1), progress=False)
mean, stderr = res.ensemble_energy()
print(res.message)
print("<E> at t = 0, 50T, 100T, 150T:", mean[::50].round(4))"""),
    ("md", """## 5. Recurrence
The recurrence plot of $\\langle E\\rangle$ (eq. Rij) and its quantification."""),
    ("code", """from sinktheory.plot.recurrence import plot_recurrence
from sinktheory.recurrence import rqa
print(rqa(mean, 0.005).as_dict())
plot_recurrence(mean, 0.005)"""),
    ("md", "Every figure of the paper, with each claim checked: "
           "`sinktheory reproduce --out out/`."),
]


YOUR_OWN_WELL = [
    ("md", """# A well of your own

The paper's container has soft walls of two or three shapes, but nothing in the toolkit
is tied to them: a well is a potential V(x, y) typed as text, with named parameters.
From it the toolkit derives the equations of motion, decides whether the normal mode
y = 0 exists, certifies the basin's escape energy, charts Floquet stability, compiles an
engine for the container with particles in it, and computes the exact equilibrium law.

Two wells here: an **elliptic container**, V = γ/(2n) ((x/a)² + (y/b)²)ⁿ, and a
**Hénon–Heiles-type well** turned so that y = 0 is invariant,
V = (x² + y²)/2 + x y² − x³/3."""),
    ("code", """%matplotlib inline
import numpy as np
import matplotlib.pyplot as plt
import sinktheory as st
from sinktheory import symbolic as S
from sinktheory.userwell import UserWell
from sinktheory.wellat import WellAt

elliptic = UserWell(
    "elliptic", "gamma/(2*n) * ((x/a)**2 + (y/b)**2)**n",
    {"a": 0.5, "b": 0.3, "gamma": 1.0, "n": (4, (1, 100))},  # default, or (default, range)
    wall_ratios=["sqrt((x/a)**2 + (y/b)**2)"],               # level 1: the rigid wall
)
henon = UserWell("henon_heiles_x", "(x**2 + y**2)/2 + x*y**2 - x**3/3", {})"""),
    ("md", """## 1. Derivation
The same ladder as the built-in wells, derived from the Lagrangian of the container
(mass 1, spring 1) with one particle of mass μ; the particle's coordinates are relative to
the container. The normal mode y = 0 exists when ∂V/∂y(x, 0) ≡ 0, decided symbolically."""),
    ("code", """steps = S.ladder(elliptic)
print("V =", steps.potential)
print("y'' =", steps.equations_of_motion[S.y])
print("y = 0 invariant:", steps.normal_mode.invariant, "-", steps.normal_mode.reason)
print("Hill coefficient along y = 0:", steps.normal_mode.hill_coefficient)"""),
    ("md", """The Hénon–Heiles-type well is open: its basin ends at three saddles. The toolkit finds
the escape energy numerically, with a bracketing certificate; the closed form is 1/6."""),
    ("code", """escape = WellAt(henon).report.basin.escape
print(escape)
print("escape energy - 1/6 =", escape.escape_potential - 1 / 6)"""),
    ("md", """## 2. Floquet stability of the normal mode
Along y = 0 the transverse motion obeys Hill's equation. For the elliptic well the chart
does not depend on the amplitude (V is homogeneous), so it is drawn against the semi-axis
b. At n = 1 the motion along y = 0 is harmonic and the half-period trace is
cos(π a / b) exactly, a check of the numerics."""),
    ("code", """from sinktheory.floquet import well_floquet

bs = np.linspace(0.3, 1.5, 13)
phi = {n: np.array([well_floquet(elliptic, 0.2, {"b": b, "n": n}).phi_half for b in bs])
       for n in (1, 2)}
print("n = 1, largest |phi - cos(pi a/b)|:", np.abs(phi[1] - np.cos(np.pi * 0.5 / bs)).max())
fig, ax = plt.subplots(figsize=(7, 3.5))
fine = np.linspace(0.3, 1.5, 400)
ax.plot(fine, np.cos(np.pi * 0.5 / fine), color="0.7", label="cos(π a / b), n = 1")
for n, marker in ((1, "o"), (2, "s")):
    ax.plot(bs, phi[n], marker, label=f"Floquet, n = {n}")
ax.axhspan(-1, 1, color="tab:green", alpha=0.08)
ax.set(xlabel="semi-axis b (a = 0.5)", ylabel="half-period trace φ", title="elliptic well")
ax.legend(); fig.tight_layout()"""),
    ("md", """The Hénon–Heiles-type well is not homogeneous, so its chart runs over the amplitude
(the turning point on y = 0; the saddle on the axis is at x = 1). Stability boundaries are
located by root finding. The original Hénon–Heiles well, with the cubic terms in y, has no
invariant line y = 0, and the toolkit says so instead of charting it."""),
    ("code", """from sinktheory.errors import ParameterError
from sinktheory.floquet import well_hill, well_scan

chart = well_scan(well_hill(henon), (0.05, 0.95, 40))
print("stable amplitude intervals:", [(round(lo, 4), round(hi, 4)) for lo, hi in chart.stable_intervals])
original = UserWell("henon_heiles", "(x**2 + y**2)/2 + x**2*y - y**3/3", {})
try:
    well_hill(original)
except ParameterError as error:
    print("refused:", error)
fig, ax = plt.subplots(figsize=(7, 3.5))
ax.plot(chart.amplitude, chart.trace, ".-")
ax.axhline(1, color="0.5", lw=0.8); ax.axhline(-1, color="0.5", lw=0.8)
ax.set(xlabel="amplitude", ylabel="half-period trace φ", title="Hénon–Heiles-type well")
fig.tight_layout()"""),
    ("md", """## 3. The sink, and the equilibrium law
Each well gets its own compiled engine on first use (about half a minute, then cached
on disk; any parameter values, n included, reuse it). One particle, the container started
at its amplitude, the particle at rest near the centre. The exact equilibrium law of the
container's energy follows from the well's area function A(e); it holds if the particle's
motion fills its energy shell."""),
    ("code", """from sinktheory.equilibrium.law import well_law

cases = {"elliptic (m = 0.2, E0 = 0.5)": (elliptic, 0.2, 0.5, 32, 1000),
         "Hénon–Heiles-type (m = 1, E0 = 0.15)": (henon, 1.0, 0.15, 64, 2000)}
fig, ax = plt.subplots(figsize=(7, 3.5))
for label, (well, mass, E0, runs, periods) in cases.items():
    sink = st.Sink(WellAt(well), particles=1, mass=mass)
    res = st.simulate(sink, st.RunSettings(container_energy=E0, runs=runs, periods=periods,
                                           seed=1), progress=False)
    law = well_law(well, 1, float(res.initial_energy.mean()))
    late = res.container_energy[:, periods // 2:].mean(axis=1)  # each run's late mean
    print(f"{label}: late <E_c> = {late.mean():.4f} +- {late.std(ddof=1) / np.sqrt(runs):.4f} "
          f"({runs} runs), law {law.mean:.4f}; {res.message}")
    line, = ax.plot(res.times / (2 * np.pi), res.container_energy.mean(axis=0), label=label)
    ax.axhline(law.mean, color=line.get_color(), ls="--", lw=1)
ax.set(xlabel="t / T", ylabel="<E_c>", title="container energy (dashed: the law)")
ax.legend(); fig.tight_layout()"""),
    ("md", """The Hénon–Heiles-type well at resonance (particle and container both of frequency 1)
drains to the law; so it did over other seeds and with twice the runs, within one to two
standard errors. The elliptic container keeps far more than its law says: its particle
does not fill the energy shell on this time scale. A rigid elliptic billiard is
integrable, and the soft elliptic wall inherits much of that regularity, whereas the
paper's walls scatter. The law is a statement about ergodic motion, and a well of your
own is where that assumption gets tested.

The same wells from the command line, written as a TOML file
(`docs/guide/elliptic.toml` is an elliptic well of this form): `sinktheory derive --well FILE`,
`sinktheory well --well FILE --plot`, `sinktheory floquet --well FILE --amplitude-range
0.05 0.95 40`, `sinktheory simulate --well FILE --well-param n=10 --stepper adaptive`,
`sinktheory equilibrium --well FILE`. More in the guide's page on users' wells."""),
]

NOTEBOOKS = {"tour": TOUR, "your_own_well": YOUR_OWN_WELL}


def build(name: str = "tour") -> nbformat.NotebookNode:
    """The notebook ``name`` (a key of :data:`NOTEBOOKS`), without outputs."""
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}  # fmt: skip
    for kind, text in NOTEBOOKS[name]:
        make = nbformat.v4.new_markdown_cell if kind == "md" else nbformat.v4.new_code_cell
        nb.cells.append(make(text))
    return nb


if __name__ == "__main__":
    for name in NOTEBOOKS:
        path = Path(__file__).with_name(f"{name}.ipynb")
        nbformat.write(build(name), path)
        print(path)
