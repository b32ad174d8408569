"""Write notebooks/tour.ipynb (cells without outputs) from the cell texts below.

    python notebooks/make_tour.py

The notebook is committed without outputs (tests/interface/test_notebooks.py checks it, and that it
matches this file).  The documentation build executes it with myst-nb and renders it as
a page with its outputs; tests/interface/test_docs.py checks that page for the printed results and
the two figures as images.  The first cell selects matplotlib's inline backend:
without it a kernel started with ``MPLBACKEND=Agg`` (CI, the test suite, some servers)
shows a returned figure as the text ``<Figure size 800x450 with 1 Axes>``.
"""

from pathlib import Path

import nbformat

CELLS = [
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


def build() -> nbformat.NotebookNode:
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}
    for kind, text in CELLS:
        make = nbformat.v4.new_markdown_cell if kind == "md" else nbformat.v4.new_code_cell
        nb.cells.append(make(text))
    return nb


if __name__ == "__main__":
    path = Path(__file__).with_name("tour.ipynb")
    nbformat.write(build(), path)
    print(path)
