"""Conditioning of the constructions and the bound of every graphical figure.

* The intersection angle of a plan is the angle of its two lines, computed here from the
  positions alone (hand-checkable on the press); ``error_mm`` is precision/sin(angle).
* The bound is a bound: on the examples, at every position and reading precision, every
  figure of the drafted plans (built here with the ordinary ``Reader``) is within its
  stated bound of the exact plan's (built with ``EXACT``), and the exact figures are the
  solver's. It is not vacuous either: the worst error reaches a good part of it.
* The bound of a figure whose only error is its own reading is that reading's rounding:
  ``pa`` of the press, SAFETY·(p/2)·Kv.
* The marks: a four-bar swept toward its toggle gets its plans marked below
  ``ILL_ANGLE_DEG``, with the draftsman's note, and nowhere else.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

import graphplan as g
from graphplan.files import bundled_example
from graphplan.forces import compute_loads, solve_forces
from graphplan.plans import (
    EXACT,
    ILL_ANGLE_DEG,
    SAFETY,
    Intersection,
    Reader,
    acceleration_plan,
    force_conditioning,
    force_plans,
    ill_conditioned,
    intersections,
    kinematic_conditioning,
    note,
    velocity_plan,
    zhukovsky_lever,
)
from graphplan.project import analyze, sheet_scales

EXAMPLES = ("press", "fourbar", "shaper", "offset_slider", "scotch_yoke", "shaper_prp",
            "sixbar_press")


def _setup(name):
    an = analyze(g.load(bundled_example(name)))
    sc = sheet_scales(an.mech, an.kin)
    return an, sc


def test_note_as_a_draftsman_writes_it():
    # lines at 1.3° read to 0.25 mm: 0.25/sin(1.3°) = 0.25/0.022687 = 11.02 mm
    x = Intersection("velocity", 3, "v_B = …", 1.3, 0.25 / math.sin(math.radians(1.3)))
    assert x.ill
    assert x.note("en") == "lines meet at 1.3°, reading ±11 mm"
    assert x.note("ru") == "линии пересекаются под углом 1,3°, точность ±11 мм"
    y = Intersection("velocity", 3, "", 66.4, 0.5 / math.sin(math.radians(66.4)))
    assert not y.ill and y.note() == "lines meet at 66.4°, reading ±0.55 mm"


def test_press_intersection_angle_by_hand():
    # At φ = 0 the crank is horizontal: A = (80, 0) mm, the guide is vertical through O, so
    # B = (0, −√(200² − 80²)) and the lines ⟂AB and ∥guide meet at α with
    # cos α = |A_x|/l_AB = 80/200 = 0.4: α = 66.4218°; error = 0.5/sin α = 0.5/0.916515 = 0.5455
    m = g.load(bundled_example("press"))
    kin = g.solve(m, [0.0])
    sc = sheet_scales(m, g.sweep(m, g.analyse_cycle(m)))
    vp = velocity_plan(m, kin, 0, sc.kl, sc.kv, Reader(0.5))
    (x,) = intersections(vp)
    assert x.angle_deg == pytest.approx(math.degrees(math.acos(0.4)), abs=1e-9)
    assert x.error_mm == pytest.approx(0.5 / math.sqrt(1 - 0.4**2), rel=1e-12)
    assert x.plan == "velocity" and not x.ill and note([vp]) == ""


def test_press_pa_bound_is_its_own_rounding():
    # pa = v_A/Kv depends on no other reading: it is laid off (±p/2) and read back (±p/2),
    # so its bound is SAFETY·2·(p/2)·Kv = 1.5·0.5·0.01 = 0.0075 m/s at Kv = 0.01 (m/s)/mm
    an, sc = _setup("press")
    c = kinematic_conditioning(an.mech, an.kin, 0, sc.kl, sc.kv, sc.ka, 0.5)
    assert c.figures[("velocity", "pa")].bound == pytest.approx(
        SAFETY * 2 * 0.25 * sc.kv.per_mm, rel=1e-6)
    assert c.figures[("velocity", "pa")].unit == "m/s"


@pytest.mark.parametrize("name", EXAMPLES)
def test_drafted_kinematic_figures_are_within_their_bounds(name):
    an, sc = _setup(name)
    m, kin = an.mech, an.kin
    worst = 0.0
    for k in range(kin.n):
        ev = velocity_plan(m, kin, k, sc.kl, sc.kv, EXACT)
        ea = acceleration_plan(m, kin, k, sc.kl, sc.ka, ev, EXACT)
        # the exact plans are the solver's: v_B = |pb|·Kv
        for p in kin.pos.points:
            if p.lower() in ev.points and p not in m.frame_points and p.lower() not in "pπ":
                assert np.hypot(*ev.points[p.lower()]) * sc.kv.per_mm == pytest.approx(
                    float(np.hypot(*kin.vel.points[p][k])), rel=1e-9, abs=1e-12)
        for prec in (0.25, 1.0):
            c = kinematic_conditioning(m, kin, k, sc.kl, sc.kv, sc.ka, prec)
            assert not c.flagged, c.marks
            dv = velocity_plan(m, kin, k, sc.kl, sc.kv, Reader(prec))
            da = acceleration_plan(m, kin, k, sc.kl, sc.ka, dv, Reader(prec))
            for plan, drawn, exact in (("velocity", dv, ev), ("acceleration", da, ea)):
                for seg, r in exact.readings.items():
                    got = drawn.readings[seg].value if seg in drawn.readings else 0.0
                    b = c.figures[(plan, seg)].bound
                    assert abs(got - r.value) <= b, (name, k, prec, plan, seg, got, r.value, b)
                    if b > 0:
                        worst = max(worst, abs(got - r.value) / b)
                sym = "ω" if plan == "velocity" else "ε"
                for link, w in exact.rates.items():
                    b = c.figures[(plan, sym + link)].bound
                    assert abs(drawn.rates[link] - w) <= b + 1e-12, (name, k, prec, link)
                for pt, xy in exact.points.items():
                    f = c.figures.get((plan, f"point {pt}"))
                    if f is None or pt not in drawn.points:
                        continue
                    d = (drawn.points[pt] - xy) * drawn.scale.per_mm
                    assert np.hypot(*d) <= f.bound + 1e-12, (name, k, prec, plan, pt)
    # not vacuous: the drafting reaches a good part of its bound somewhere
    assert worst > 0.1


@pytest.mark.parametrize("name", ("press", "fourbar", "shaper", "sixbar_press"))
def test_drafted_force_figures_are_within_their_bounds(name):
    an, sc = _setup(name)
    m, kin = an.mech, an.kin
    loads = compute_loads(m, kin, an.cycle)
    forces = solve_forces(m, kin, loads)
    for k in range(0, kin.n, 3):
        c = force_conditioning(m, kin, forces, loads, k, sc.kl, sc.kv, 0.5)
        assert not c.flagged
        exact = force_plans(m, kin, forces, loads, k, sc.kl)
        drawn = force_plans(m, kin, forces, loads, k, sc.kl, Reader(0.5))
        # Mур from the crank's plan, against the exact kinetostatics
        assert exact[-1].M_bal == pytest.approx(float(forces.M_bal[k]), rel=1e-9,
                                                abs=1e-9 * float(np.abs(forces.M_bal).max()))
        b = c.figures[("force", "Mур")].bound
        assert abs(drawn[-1].M_bal - exact[-1].M_bal) <= b
        for pe, pd in zip(exact, drawn, strict=True):
            for name_, r in pe.reactions.items():
                f = c.figures[("force", f"vector {name_}")]
                d = np.asarray(pd.reactions[name_].vector) - np.asarray(r.vector)
                assert np.hypot(*d) <= f.bound, (name, k, name_)
        lx = zhukovsky_lever(m, kin, loads, k, sc.kl, sc.kv)
        ld = zhukovsky_lever(m, kin, loads, k, sc.kl, sc.kv, Reader(0.5))
        assert abs(ld.M_bal - lx.M_bal) <= c.figures[("lever", "Mур")].bound


def _toggle(frame_mm: float, extra: list[float]):
    text = bundled_example("fourbar").read_text(encoding="utf-8")
    text = text.replace("C = [400, 0]", f"C = [{frame_mm}, 0]")
    ex = ", ".join(f'{{ label = "t{i}", phi = {p} }}' for i, p in enumerate(extra))
    text = re.sub(r"extra = \[.*?\n\]", f"extra = [{ex}]", text, flags=re.S)
    return analyze(g.loads(text, source=f"toggle-{frame_mm}.toml"))


def _collinear_angle(kin, k):
    """The acute angle (°) between AB and CB: the two lines of the velocity plan."""
    A, B, C = (kin.pos.points[p][k] for p in ("A", "B", "C"))
    u, v = B - A, B - C
    s = abs(u[0] * v[1] - u[1] * v[0]) / (np.hypot(*u) * np.hypot(*v))
    return math.degrees(math.asin(min(1.0, s)))


def test_near_toggle_plans_are_marked_and_nowhere_else():
    # frame 549.8 mm: d + a = 649.8 against b + c = 650, the coupler and the rocker line up
    # once a turn (near φ = 180°, the crank pointing away from C)
    an = _toggle(549.8, [150.0, 170.0, 175.0, 180.0, 185.0, 190.0])
    sc = sheet_scales(an.mech, an.kin)
    marked = 0
    for k in range(an.kin.n):
        ang = _collinear_angle(an.kin, k)
        c = kinematic_conditioning(an.mech, an.kin, k, sc.kl, sc.kv, sc.ka, 0.5)
        vel = [x for x in c.intersections if x.plan == "velocity"]
        assert vel[0].angle_deg == pytest.approx(ang, abs=1e-6)
        assert c.flagged == (ang < ILL_ANGLE_DEG)
        if c.flagged:
            marked += 1
            worst = c.marks[0]
            assert worst.angle_deg == pytest.approx(min(x.angle_deg for x in c.intersections))
            assert worst.note().startswith(f"lines meet at {worst.angle_deg:.1f}°")
            vp = velocity_plan(an.mech, an.kin, k, sc.kl, sc.kv, Reader(0.5))
            assert ill_conditioned(vp)[0].angle_deg == pytest.approx(ang, abs=1e-6)
            assert note([vp], "ru").startswith("линии пересекаются под углом")
    assert marked >= 3
