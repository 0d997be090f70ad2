"""Exact integrals are exact: the work over the cycle of a step and a ramp load (issue 17).

A central crank–slider, r = 0.1 m, l = 0.4 m, H = 2r = 0.2 m, no masses: the only load is
the technological force Q(s) over the working stroke, so the work of the resistance over
the cycle is, in closed form, Aс = −Q_max·H·∫₀¹ f(s) ds (the area under the diagram).

* step at s = 0.3 (the issue's synthetic press): Aс = −10 000·0.2·0.7 = −1400 J exactly
  (the trapezoid on the 0.5° grid gave −1396.74 J here, the jump falling between two
  nodes; −1406.75 J on the issue's press);
* ramp 0 → 1 over 0.2 … 0.8, then constant: ∫f = 0.6/2 + 0.2 = 0.5, Aс = −1000 J;
* step inside the idle stroke as well (a load on both strokes): ∫ = 0.7 + 0.5 = 1.2,
  Aс = −2400 J.

Mд = −Aс/2π then follows to the same relative precision, and the flywheel's ΔT closes.
"""

import math

import numpy as np
import pytest

from graphplan import dynamics as dyn
from graphplan.model import loads
from graphplan.project import analyze

PRESS = """
[frame]
link = "4"
points = {{ O = [0, 0] }}
[crank]
link = "1"
joints = ["O", "A"]
length = 0.1
rpm = 60
[[dyads]]
kind = "RRP"
links = ["2", "3"]
joints = ["A", "B"]
length = 0.4
guide = {{ link = "4", through = "O", angle = -90 }}
[[points]]
name = "S3"
link = "3"
from = "B"
[links.3]
mass = 0
centre = "S3"
[output]
working = "+"
[[loads]]
kind = "force"
link = "3"
point = "B"
max = 10000
{load}
[positions]
count = 12
[dynamics]
delta = 0.1
"""

CASES = [
    ("step", 'diagram = [[0, 0], [0.3, 0], [0.3, 1], [1, 1]]', -1400.0),
    ("ramp", 'diagram = [[0, 0], [0.2, 0], [0.8, 1], [1, 1]]', -1000.0),
    ("both-strokes", 'diagram = [[0, 0], [0.3, 0], [0.3, 1], [1, 1]]\n'
                     'stroke = "working"\n'
                     '[[loads]]\nkind = "force"\nlink = "3"\npoint = "B"\nmax = 10000\n'
                     'diagram = [[0, 1], [0.5, 1], [0.5, 0], [1, 0]]\nstroke = "idle"',
     -2400.0),
]


@pytest.mark.parametrize(("name", "load", "exact"), CASES, ids=[c[0] for c in CASES])
def test_work_of_a_step_and_a_ramp_load_is_exact(name, load, exact):
    a = analyze(loads(PRESS.format(load=load), source=f"{name}.toml"))
    m = dyn.dynamic_model(a)
    wd = dyn.work_diagrams(m)
    assert wd.A_c[-1] == pytest.approx(exact, rel=1e-9)
    assert wd.M_d == pytest.approx(-exact / (2 * math.pi), rel=1e-9)
    assert abs(wd.dT[-1]) <= 1e-9 * abs(exact)
    # the trapezoid of the same grid is what was used before: off by far more
    trap = float(np.trapezoid(m.moment.M, m.tau))
    if name == "step":
        assert abs(trap / exact - 1) > 1e-3


def test_work_inside_the_cycle_is_exact_too():
    # at the end of the working stroke (crank travel π for the central slider, the first
    # position being the start dead centre) the step load has done all its work: −1400 J
    a = analyze(loads(PRESS.format(load=CASES[0][1]), source="step.toml"))
    m = dyn.dynamic_model(a)
    k = int(np.argmin(np.abs(m.tau - math.pi)))
    assert m.tau[k] == pytest.approx(math.pi, abs=1e-12)
    assert m.moment.A[k] == pytest.approx(-1400.0, rel=1e-9)
    # and half-way through the load (s = 0.65 of the stroke), −10 000·0.2·0.35 = −700 J
    from graphplan.kinematics import stroke_angle

    phi = stroke_angle(a.mech, a.cycle, 0.65)
    tau = (phi - a.cycle.dead_centres[0]) % (2 * math.pi)
    at = dyn.exact_work(m.moment.at, np.array([0.0, tau]),
                        dyn.resistance_breaks(a, ends=True))
    assert at[-1] == pytest.approx(-700.0, rel=1e-9)


def test_graphical_integration_has_a_node_at_the_jump():
    a = analyze(loads(PRESS.format(load=CASES[0][1]), source="step.toml"))
    m = dyn.dynamic_model(a)
    assert len(m.moment.breaks) == 1
    wd = dyn.work_diagrams(m, 24)
    assert np.min(np.abs(wd.node_tau - m.moment.breaks[0])) < 1e-12
