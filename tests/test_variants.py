"""Variants nobody wrote the code for (tests/data/variants/), and the warnings of a machine
that is probably not the one meant.

* The output against its working direction: a resistance given with its own sign (a force
  along a fixed ``angle``) on the working stroke must do negative work there. Each variant
  is flipped each way — the other assembly branch, the other ``output.working``, the other
  sense of rotation — and the warning must fire exactly when the force does positive work,
  name the changes that remove it, and those changes must remove it.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from graphplan.kinematics import analyse_cycle, link_coordinate, solve_positions
from graphplan.model import load, loads
from graphplan.project import analyze
from graphplan.project.plausibility import load_work

ROOT = Path(__file__).resolve().parent.parent
VARIANTS = ROOT / "tests" / "data" / "variants"


def _text(name: str, **edits: str) -> str:
    text = (VARIANTS / f"{name}.toml").read_text(encoding="utf-8")
    for old, new in edits.items():
        assert old in text, old
        text = text.replace(old, new)
    return text


def _warnings(text: str, source: str) -> tuple[str, ...]:
    return analyze(loads(text, source=source)).warnings


# --- the output against its working direction ----------------------------------------------

BRANCH = {'branch = "+"           # B to the left': 'branch = "-"           # B to the left'}
WORKING = {'working = "+"          # the working swing': 'working = "-"          # the working '
           'swing'}
CW = {'direction = "ccw"': 'direction = "cw"'}


def test_no_warning_as_written():
    for path in sorted(VARIANTS.glob("*.toml")):
        assert analyze(load(path)).warnings == (), path.name


def test_the_other_branch_makes_the_resistance_drive():
    # B below the frame line: the rocker swings over −141°…−101°, and its CCW working swing
    # moves B to the right, with the force Fс along +x
    (w,) = _warnings(_text("fourbar_force", **BRANCH), "fb-branch.toml")
    assert w.startswith("fb-branch.toml: loads[0] (Fс): given on the working stroke, it does "
                        "positive work over it (+")
    assert "\n" not in w
    assert w.endswith('likely fix: output.working = "-" / dyads[0].branch = "+"'), w
    # each fix it names removes the warning
    assert _warnings(_text("fourbar_force", **BRANCH, **WORKING), "fixed.toml") == ()
    assert _warnings(_text("fourbar_force"), "fixed.toml") == ()


def test_the_other_working_sense_makes_the_resistance_drive():
    (w,) = _warnings(_text("fourbar_force", **WORKING), "fb-working.toml")
    assert w.endswith('likely fix: output.working = "+" / dyads[0].branch = "-"'), w


def test_the_other_sense_of_rotation_keeps_the_working_swing():
    # turning the crank the other way swaps the strokes' crank angles, not the rocker's
    # working sense: the force still resists, no warning about it
    assert not any("positive work" in w for w in _warnings(_text("fourbar_force", **CW),
                                                             "fb-cw.toml"))


def test_a_crusher_force_on_the_jaw_flipped():
    text = _text("crusher_force", **{'working = "-"': 'working = "+"'})
    (w,) = _warnings(text, "crusher-plus.toml")
    assert "loads[0] (Fс)" in w and w.endswith('likely fix: output.working = "-"'), w


@pytest.mark.parametrize("flip", [{}, BRANCH], ids=["as written", "other branch"])
def test_load_work_is_the_line_integral_of_the_force(flip):
    """The warning's work against an independent sum over the positions alone: the force
    is ``f(x)·600 N`` along +x at B, so ``W = Σ F_x·Δx_B`` (midpoint F, Δx from the plan
    of positions, no velocities), 20 000 steps."""
    mech = loads(_text("fourbar_force", **flip), source="fb.toml")
    cycle = analyse_cycle(mech)
    work, scale = load_work(mech, cycle, 0)
    from graphplan.forces import resistance_loads
    from graphplan.kinematics import solve

    tau = np.linspace(0.0, 2 * math.pi, 20001)
    phi = cycle.origin + mech.crank.sense * tau
    xB = solve_positions(mech, phi).points["B"][:, 0]
    mid = cycle.origin + mech.crank.sense * 0.5 * (tau[1:] + tau[:-1])
    Fx = resistance_loads(mech, solve(mech, mid), cycle)[0].vector[:, 0]
    by_positions = float(np.sum(Fx * np.diff(xB)))
    assert work == pytest.approx(by_positions, rel=1e-4)
    assert scale >= abs(work) > 0
    assert (work < 0) == (not flip)
    # the rocker's travel over the working swing has the stated sign (CCW: θ3 grows)
    lt = cycle.travels[("3", 1)]
    pos = solve_positions(mech, np.asarray(lt.dead_centres))
    q = link_coordinate(mech, "3", pos)[1]
    assert (q[1] - q[0]) % (2 * math.pi) < math.pi
