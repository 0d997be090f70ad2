# %% [markdown]
# # The crank press, from its variant file to the flywheel
#
# A walk through graphplan on the bundled press (`examples/press.toml`): structure,
# positions, the velocity and acceleration plans as constructions, the force plans of a
# working position, Zhukovsky's lever, and the flywheel — with a teaching page of each
# construction.
#
# Run it as a script, `python examples/tutorial.py [OUT_DIR]` (it prints the numbers and
# writes the pages to OUT_DIR, by default `tutorial-out/`), or open it as a notebook
# (the `# %%` cells are Jupytext's percent format; VS Code and JupyterLab with Jupytext
# run them cell by cell). In a notebook the plans, the sheets and the lessons show
# themselves inline: a plan as a coloured drawing, a sheet as its SVG, a lesson as its
# interactive page (next/previous, the keys ← →, "try it yourself").

# %%
import sys
from pathlib import Path

from graphplan.dynamics import dynamic_model, flywheel, simulate
from graphplan.files import bundled_example
from graphplan.model import load
from graphplan.plans import acceleration_plan, velocity_plan
from graphplan.project import analyze, sheet_scales
from graphplan.teaching import lesson, write_lesson

OUT = Path(sys.argv[1]) if len(sys.argv) > 1 and not sys.argv[1].startswith("-") else Path(
    "tutorial-out")


def show(obj, text: str = "") -> None:
    """In a notebook, display ``obj`` (its rich view); in a script, print ``text``."""
    try:
        from IPython import get_ipython
        from IPython.display import display

        if get_ipython() is not None:
            display(obj)
            return
    except ImportError:
        pass
    if text:
        print(text)


# %% [markdown]
# ## 1. The variant and its structure
# The variant file gives the links in mm, the crank's speed, the dyad (an RRP group:
# the rod A–B and the ram B on a vertical guide), the masses and the technological
# resistance. `analyze` checks the structure (Chebyshev's formula, Assur groups) and
# solves the positions, velocities and accelerations exactly at every position.

# %%
mech = load(bundled_example("press"))
a = analyze(mech)
print(a.structure.mobility_equation)
print("formula of structure:", a.structure.formula)
print(f"ω1 = {mech.crank.omega:.4f} rad/s, stroke H = {a.cycle.stroke * 1000:.2f} mm")
print("positions:", ", ".join(a.kin.labels))

# %% [markdown]
# ## 2. The velocity plan of position 2, line by line
# Each step of the construction is drawn in sheet millimetres at the scales of sheet 1;
# values are read back off the drawing (`v_B = pb·Kv`).

# %%
sc = sheet_scales(mech, a.kin)
k = a.kin.labels.index("2")
vp = velocity_plan(mech, a.kin, k, sc.kl, sc.kv)
print(sc.kl.basis)
print(sc.kv.basis)
for s in vp.steps:
    print(f"{s.number}. {s.text}")
show(vp)

# %% [markdown]
# The same construction as a lesson: one step at a time, the vector equation, what is
# known and unknown, the scale conversion. The page is self-contained (open it with no
# network).

# %%
les = lesson(a, "velocity", "2")
page = write_lesson(les, OUT, lang="en", frames=True)[0]
print("teaching page:", page)
show(les)

# %% [markdown]
# ## 3. The acceleration plan of position 2
# The normal components ω²·l come from the velocity plan's readings; the tangential
# and the slider's relative acceleration close the equation.

# %%
ap = acceleration_plan(mech, a.kin, k, sc.kl, sc.ka, vp)
for name, r in ap.readings.items():
    print(f"{name} = {r.mm:.2f} mm → {r.quantity} = {r.value:.4g} {r.unit}")
print(f"ε2 = {ap.rates['2']:.4g} rad/s² (CCW positive)")
print("teaching page:", write_lesson(lesson(a, "acceleration", "2"), OUT, lang="en")[0])
show(ap)

# %% [markdown]
# ## 4. Force analysis of the working position (2)
# The group 2–3 is drawn first (the moment equation about B with the arms measured on
# the scheme, then the force polygon at Kp), then the crank: Mур from ΣM_O = 0.

# %%
kw = a.kin.labels.index("(2)")
forces = a.forces  # the project solves every stage once (solve_project)
print(f"Mур at (2), exact kinetostatics: {forces.M_bal[kw]:.1f} N·m")
fl = lesson(a, "forces", "(2)")
for r in fl.results:
    print(f"  {r.segment} = {r.mm:.2f} mm → {r.quantity} = {r.value:.6g} {r.unit}")
print("teaching page:", write_lesson(fl, OUT, lang="en")[0])

# %% [markdown]
# ## 5. Zhukovsky's lever of (2)
# The velocity plan turned by 90°, every force at the image of its point: the sum of
# their moments about the pole gives the same Mур (the power balance).

# %%
lv = lesson(a, "zhukovsky", "(2)")
print(lv.steps[-1].notes[0]["en"])
print("teaching page:", write_lesson(lv, OUT, lang="en")[0])

# %% [markdown]
# ## 6. The flywheel
# The reduced moment of the resistance Mс(φ) is integrated graphically into the work
# diagrams; the energy–mass diagram and its tangents at ψmax, ψmin give the flywheel's
# moment of inertia for δ; a simulation checks it.

# %%
model = dynamic_model(a)
fw = flywheel(model)
print(f"δ = {fw.delta}, Mд = {fw.M_d:.1f} N·m, ΔTmax = {fw.dT_max:.0f} J")
print(f"kl = {fw.segment_mm:.2f} mm → J_I = {fw.J_I:.1f} kg·m², Iм = {fw.I_m:.1f} kg·m²")
print(f"rim: D = {fw.size.D:.3f} m, mass {fw.size.mass:.0f} kg")
sim = simulate(model, fw.I_m, cycles=3)
print(f"simulated δ with this flywheel: {sim.delta_actual:.4f} (target {fw.delta})")
print("teaching page:", write_lesson(lesson(a, "flywheel"), OUT, lang="en")[0])

# %% [markdown]
# ## 7. The sheet
# Sheet 1 (kinematic analysis) shows itself in a notebook; in a script it is written.

# %%
from graphplan.drawing import kinematics_sheet  # noqa: E402
from graphplan.render.svg import write_svg  # noqa: E402

sheet = kinematics_sheet(a, lang="en", diagrams=False)
print("sheet 1:", write_svg(sheet, OUT / "sheet1.svg"))
show(sheet)
