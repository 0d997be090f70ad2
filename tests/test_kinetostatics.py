"""Kinetostatics (graphplan.forces.loads, graphplan.forces.kinetostatics) checked by
independent routes.

* Virtual power (Zhukovsky): M_ур·ω1 + Σ F·v_point + Σ M·ω_link = 0 at every position,
  inertia included — it uses only the kinematics and the loads, never the reactions.
* Equilibrium of every link with the computed reactions (ΣF = 0, ΣM = 0), normal
  forces of the prismatic pairs ⟂ their guides (no friction).
* Random mechanisms of every dyad kind (hypothesis), built with the TOML generators of
  tests/test_kinematics_closed_forms.py and the catalogue of
  tests/test_kinematics_properties.py (PRP, guides on moving links), with random masses,
  inertias, centres, gravity and external loads.
* Hand-checkable cases: a static crank–slider with one horizontal force, and the seed's
  press at its working positions (2), (3).
* The technological resistance acts only in the working stroke and opposes the motion.

Tolerances: REL = 1e-9 of the sum of the magnitudes of the terms (round-off of the
6×6 solves is ~1e-15·κ with κ < 10 here); the seed's figures to drafting accuracy 0.2 %.
"""

from __future__ import annotations

import dataclasses
import importlib.util
import json
import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import graphplan as g
from graphplan.files import bundled_example
from graphplan.forces import (
    ForceLoad,
    MomentLoad,
    compute_loads,
    diagram_value,
    power_balance_moment,
    shift_inertia_force,
)
from graphplan.forces import kinetostatics as ks
from graphplan.kinematics import in_working_stroke

REL = 1e-9
EXAMPLES = ("press", "offset_slider", "fourbar", "shaper", "shaper_prp", "scotch_yoke",
            "sixbar_press")


def _module(name):
    """Import a sibling test module by path (pytest runs with --import-mode=importlib)."""
    spec = importlib.util.spec_from_file_location(f"_kst_{name}", Path(__file__).with_name(
        f"{name}.py"))
    mod = sys.modules[spec.name] = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


KP = _module("test_kinematics_properties")  # CASES: every kind, moving guides
CF = _module("test_kinematics_closed_forms")  # *_toml generators of RRP, RRR, RPR, RPP


def cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def dot(a, b):
    return np.sum(a * b, axis=-1)


def turned(v):
    return np.stack((-v[..., 1], v[..., 0]), axis=-1)


# --------------------------------------------------------------------------------------
# The two independent checks
# --------------------------------------------------------------------------------------

def velocity_at(m, kin, link, point, at):
    """Velocity of the point of ``link`` at ``at`` (written here, not read from graphplan)."""
    if point is not None:
        return kin.vel.points[point]
    q = m.points_of(link)[0]
    return kin.vel.points[q] + kin.vel.omega[link][:, None] * turned(at - kin.pos.points[q])


def power_residual(m, kin, loads, forces) -> float:
    """max over positions of |M_ур·ω1 + Σ F·v + Σ M·ω| / scale, the scale being the
    larger of Σ |terms| and |ω1|·(l_OA·Σ|F| + Σ|M|) (the power of the loads at the
    crank pin's speed: at a dead centre every term may vanish, not the loads)."""
    w = abs(m.crank.omega)
    terms = [dot(f.vector, velocity_at(m, kin, f.link, f.point, f.at))
             for f in loads.all_forces()]
    terms += [mm.moment * kin.vel.omega[mm.link] for mm in loads.all_moments()]
    terms.append(forces.M_bal * m.crank.omega)
    t = np.stack(terms)
    load_scale = w * (m.crank.length * sum((np.hypot(*f.vector.T) for f in loads.all_forces()),
                                           np.zeros(kin.n))
                      + sum((np.abs(x.moment) for x in loads.all_moments()), np.zeros(kin.n)))
    size = np.maximum(np.sum(np.abs(t), axis=0), load_scale)
    return float(np.max(np.abs(t.sum(axis=0)) / np.maximum(size, 1e-300)))


def equilibrium_residual(m, kin, loads, forces) -> float:
    """Worst |ΣF| and |ΣM| (about the crank pivot) of any link, relative to the size of
    the forces of the whole mechanism at that position, S = Σ|F| + Σ|M|/l_OA over every
    load and reaction (S·l_OA for moments); and checks of the prismatic reactions: ⟂
    guide, line of action through ``at`` carrying the couple."""
    pivot = kin.pos.points[m.crank.pivot]
    r_oa = m.crank.length
    size = sum((np.hypot(*f.vector.T) for f in loads.all_forces()), np.zeros(kin.n))
    size = size + sum((np.hypot(*r.vector.T) + np.abs(r.couple) / r_oa
                       for r in forces.reactions.values()), np.zeros(kin.n))
    size = size + (sum((np.abs(x.moment) for x in loads.all_moments()), np.zeros(kin.n))
                   + np.abs(forces.M_bal)) / r_oa
    size = np.maximum(size, 1e-300)
    worst = 0.0
    for ln in m.moving_links:
        fs = [(f.vector, f.at, 0.0) for f in loads.forces[ln]]
        ms = [mm.moment for mm in loads.moments[ln]]
        for r in forces.reactions.values():
            s = 1.0 if r.on == ln else -1.0 if r.by == ln else 0.0
            if s:
                fs.append((s * r.vector, r.ref, s * r.couple))
        if ln == m.crank.link:
            ms.append(forces.M_bal)
        F = sum(v for v, _, _ in fs)
        mom = [cross(at - pivot, v) + c for v, at, c in fs] + ms
        m_size = np.maximum(sum(np.abs(x) for x in mom), size * r_oa)
        worst = max(worst, float(np.max(np.hypot(*F.T) / size)),
                    float(np.max(np.abs(sum(mom)) / m_size)))
    for r in forces.reactions.values():
        if r.pair == "P":
            u = kin.pos.guides[r.guide][1]
            mag = np.maximum(np.hypot(*r.vector.T), 1e-300)
            assert np.all(np.abs(dot(r.vector, u)) <= 1e-12 * mag), f"{r.name} not ⟂ guide"
            ok = r.defined
            lever = cross(r.at - r.ref, r.vector)
            assert np.allclose(lever[ok], r.couple[ok], rtol=1e-9,
                               atol=1e-9 * float(np.max(np.abs(r.couple), initial=1.0)))
    return worst


def check(m, kin, loads):
    forces = ks.solve_forces(m, kin, loads)
    p = power_residual(m, kin, loads, forces)
    e = equilibrium_residual(m, kin, loads, forces)
    assert p <= REL, f"power balance residual {p:.2e}"
    assert e <= REL, f"equilibrium residual {e:.2e}"
    assert np.all(forces.error_bound < 1e-10)
    return forces, p, e


# --------------------------------------------------------------------------------------
# The example variants
# --------------------------------------------------------------------------------------

@pytest.fixture(scope="module", params=EXAMPLES)
def example(request):
    m = g.load(bundled_example(request.param))
    cycle = g.analyse_cycle(m)
    return m, cycle, g.sweep(m, cycle)


@pytest.mark.parametrize("options", [{}, {"neglect_below": 0.0, "shift_inertia": True},
                                     {"inertia": False}])
def test_examples_balance(example, options):
    """Every example, every position: power balance and equilibrium of every link."""
    m, cycle, kin = example
    loads = compute_loads(m, kin, cycle, **options)
    forces, _, _ = check(m, kin, loads)
    # the library's own virtual-power moment agrees with the reactions' M_ур
    mp = power_balance_moment(m, kin, loads)
    assert np.allclose(forces.M_bal, mp, rtol=0, atol=REL * max(np.abs(mp).max(), 1.0))
    for k in range(kin.n):  # JSON: finite numbers only
        json.dumps(forces.as_json(k), allow_nan=False)


def test_example_reaction_names():
    """R_ij named as the method does (force of i on j), frame reaction on the crank last."""
    names = {}
    for ex in ("press", "shaper", "shaper_prp", "scotch_yoke", "sixbar_press"):
        m = g.load(bundled_example(ex))
        kin = g.solve(m, [0.3])
        names[ex] = list(ks.solve_forces(m, kin, compute_loads(m, kin)).reactions)
    assert names["press"] == ["R12", "R23", "R43", "R41"]
    assert names["shaper"] == ["R34", "R45", "R65", "R12", "R23", "R63", "R61"]
    assert names["shaper_prp"] == ["R34", "R45", "R65", "R12", "R23", "R63", "R61"]
    assert names["scotch_yoke"] == ["R12", "R23", "R43", "R41"]
    assert names["sixbar_press"] == ["R24", "R45", "R65", "R12", "R23", "R63", "R61"]


# --------------------------------------------------------------------------------------
# Random mechanisms of every kind (hypothesis)
# --------------------------------------------------------------------------------------

FULL = np.radians(np.linspace(0.0, 360.0, 12, endpoint=False) + 7.3)


@st.composite
def loaded_mechanisms(draw):
    """(mechanism, crank angles, random external loads) of every dyad kind."""
    kind = draw(st.sampled_from(["RRP", "RRR", "RPR", "RPP", "catalogue"]))
    direction = draw(st.sampled_from(["ccw", "cw"]))
    rpm = draw(st.floats(10.0, 600.0))
    branch = draw(st.sampled_from("+-"))
    phi = FULL
    if kind == "RRP":
        r, lam = draw(st.floats(0.02, 0.2)), draw(st.floats(0.1, 0.45))
        e = draw(st.floats(-0.6, 0.6)) * (r / lam - r)
        text = CF.slider_crank_toml(r, r / lam, e=e, alpha_deg=draw(st.floats(-180, 180)),
                                    branch=branch, direction=direction, rpm=rpm)
    elif kind == "RRR":
        b, c, d = (draw(st.floats(0.5, 1.5)) for _ in range(3))
        slack = b + c + d - 2 * max(b, c, d)
        assume(slack > 0.1)
        text = CF.fourbar_toml(draw(st.floats(0.05, 0.8)) * slack, b, c, d,
                               gamma_deg=draw(st.floats(-180, 180)), branch=branch,
                               direction=direction, rpm=rpm)
    elif kind == "RPR":
        r, dist, beta = draw(st.floats(0.02, 0.2)), draw(st.floats(0.2, 3.0)), draw(
            st.floats(-math.pi, math.pi))
        assume(abs(dist - 1.0) > 0.15)
        e = draw(st.floats(-0.8, 0.8)) * abs(dist - 1.0) * r
        text = CF.slotted_toml(r, dist * r * math.cos(beta), dist * r * math.sin(beta),
                               offset=e, branch=branch, direction=direction, rpm=rpm)
    elif kind == "RPP":
        text = CF.yoke_toml(draw(st.floats(0.02, 0.2)), slot_angle=draw(st.floats(30, 150)),
                            direction=direction, rpm=rpm)
    else:
        case = draw(st.sampled_from(KP.CASES))
        text, phi = case.toml, KP.sweep_phi(case, 12)
    m0 = g.loads(text)
    size = m0.crank.length
    for ln in m0.moving_links:  # masses, inertias and centres of mass at random
        if draw(st.booleans()):
            along, across = (draw(st.floats(-2.0, 2.0)) * size for _ in range(2))
            text += (f'\n[[points]]\nname = "Z{ln}"\nlink = "{ln}"\n'
                     f'from = "{m0.points_of(ln)[0]}"\nalong = {along!r}\nacross = {across!r}\n'
                     f'[links.{ln}]\nmass = {draw(st.floats(0.0, 100.0))!r}\n'
                     f'inertia = {draw(st.floats(0.0, 5.0))!r}\ncentre = "Z{ln}"\n')
    text += f"\n[gravity]\nangle = {draw(st.floats(-180.0, 180.0))!r}\n"
    m = g.loads(text, source=f"random-{kind}.toml")
    extra = []
    for n in range(draw(st.integers(0, 3))):
        ln = draw(st.sampled_from(m.moving_links))
        p = draw(st.sampled_from(m.points_of(ln)))
        vec = [draw(st.floats(-1e4, 1e4)), draw(st.floats(-1e4, 1e4))]
        extra.append((ForceLoad, f"F{n}", ln, p, vec))
    for n in range(draw(st.integers(0, 2))):
        extra.append((MomentLoad, f"M{n}", draw(st.sampled_from(m.moving_links)), None,
                      draw(st.floats(-1e3, 1e3))))
    return m, phi, extra


@settings(deadline=None, max_examples=60)
@given(case=loaded_mechanisms())
def test_random_mechanisms_balance(case):
    m, phi, extra = case
    kin = g.solve(m, phi)
    loads = compute_loads(m, kin, neglect_below=0.0)
    n = kin.n
    more = [ForceLoad(name, ln, "external", p, kin.pos.points[p], np.tile(v, (n, 1)))
            if cls is ForceLoad else MomentLoad(name, ln, "external", np.full(n, v))
            for cls, name, ln, p, v in extra]
    check(m, kin, loads.with_loads(*more))


@pytest.mark.parametrize("case_id", KP.IDS)
def test_catalogue_balance(case_id):
    """Every mechanism of the kinematics catalogue (all kinds, both branches, ccw/cw,
    guides on moving links), a unit mass with inertia on every link at its last point."""
    case = KP.CASES[KP.IDS.index(case_id)]
    m0 = g.loads(case.toml)
    text = case.toml + "".join(
        f'\n[links.{ln}]\nmass = {1.0 + int(ln)}\ninertia = 0.01\n'
        f'centre = "{m0.points_of(ln)[-1]}"\n' for ln in m0.moving_links)
    m = g.loads(text)
    kin = g.solve(m, KP.sweep_phi(case, 24))
    check(m, kin, compute_loads(m, kin))


# --------------------------------------------------------------------------------------
# Hand-checkable cases
# --------------------------------------------------------------------------------------

def test_static_crank_slider_by_hand():
    """r = 0.1, l = 0.4, horizontal guide through O, φ = 90°, only Q = 1000 N along +x on B.

    A = (0, 0.1), B = (√(0.16 − 0.01), 0) = (0.387298, 0); cos β = 0.387298/0.4 = 0.968246,
    tan β = 0.1/0.387298 = 0.258199. v_B = −r·ω1 (φ = 90°, λ-term sin 2φ = 0), so by
    power M_ур = −Q·v_B/ω1 = 1000·0.1 = 100 N·m. The rod is a two-force member: it
    pulls the slider back, R23 = Q/cos β along B→A = (−1000, 258.199) = R12;
    R43 = (0, −258.199); h21 = |OA × e_AB| = 0.1·0.387298/0.4 = 0.0968246 m,
    M_ур = R21·h21 = 1032.796·0.0968246 = 100.0 N·m; R41 = −R21 = R12.
    """
    m = g.loads(CF.slider_crank_toml(0.1, 0.4, rpm=60.0))
    kin = g.solve(m, [math.pi / 2])
    loads = compute_loads(m, kin, kinds=()).with_loads(
        ForceLoad("Q", "3", "resistance", "B", kin.pos.points["B"], np.array([[1000.0, 0.0]])))
    f, _, _ = check(m, kin, loads)
    assert f.M_bal[0] == pytest.approx(100.0, rel=1e-12)
    assert f.vector("R12")[0] == pytest.approx([-1000.0, 258.19889], rel=1e-7)
    assert f.vector("R43")[0] == pytest.approx([0.0, -258.19889], abs=1e-4)
    assert f.vector("R23")[0] == pytest.approx(f.vector("R12")[0], rel=1e-12)
    assert f.vector("R41")[0] == pytest.approx(f.vector("R12")[0], rel=1e-12)
    assert f.vector("R21")[0] == pytest.approx(-f.vector("R12")[0], rel=1e-12)
    assert f.crank_arms()["R21"][0] == pytest.approx(0.0968246, rel=1e-6)
    r43 = f.reactions["R43"]
    assert r43.offset[0] == pytest.approx(0.0, abs=1e-12)  # every slider force acts at B


@pytest.fixture(scope="module")
def press():
    m = g.load(bundled_example("press"))
    cycle = g.analyse_cycle(m)
    return m, cycle, g.sweep(m, cycle)


@pytest.mark.parametrize("kinds", [None, ("resistance",)])
@pytest.mark.parametrize(("label", "Q", "R12", "h21_mm", "M"), [
    # (2): Q = 0.7·Q0 = 420 kN, cos β = 0.990597 (β = 7.8632°), R12 = Q/cos β = 424.0 kN
    # (the seed reads 42.4 mm · 10 kN/mm), h21 = 37.389 mm, Mур = 424·37.39·0.001 = 15.85 kN·m
    ("(2)", 420e3, 424e3, 37.389, 15.85e3),
    # (3): Q = Q0 = 600 kN, cos β = 0.997585 (β = 3.9829°), R12 = 601.5 kN (60.15 mm),
    # h21 = 19.33 mm, Mур = 601.5·19.33·0.001 = 11.627 kN·m
    ("(3)", 600e3, 601.5e3, 19.33, 11.627e3),
])
def test_press_working_positions_match_the_seed(press, kinds, label, Q, R12, h21_mm, M):
    """The seed neglects gravity and inertia at (2), (3): the variant's 10 % rule drops
    them (G3 = 12.3 kN < 42 kN), so the default loads and a Q-only load set agree."""
    m, cycle, kin = press
    loads = compute_loads(m, kin, cycle) if kinds is None else compute_loads(
        m, kin, cycle, kinds=kinds)
    f, _, _ = check(m, kin, loads)
    k = kin.labels.index(label)
    q = next(x for x in loads.all_forces() if x.name == "Q")
    assert np.hypot(*q.vector[k]) == pytest.approx(Q, rel=2e-3)
    assert f.reactions["R12"].magnitude[k] == pytest.approx(R12, rel=2e-3)
    assert f.crank_arms()["R21"][k] * 1e3 == pytest.approx(h21_mm, rel=2e-3)
    assert f.M_bal[k] == pytest.approx(M, rel=2e-3)  # positive: the motor drives CCW
    # exactly: the rod is a two-force member, R12 = Q/cos β and Mур = R21·h21
    rod = kin.pos.points["B"][k] - kin.pos.points["A"][k]
    cos_b = abs(rod[1]) / np.hypot(*rod)
    assert f.reactions["R12"].magnitude[k] == pytest.approx(np.hypot(*q.vector[k]) / cos_b,
                                                            rel=1e-12)
    assert f.M_bal[k] == pytest.approx(f.reactions["R12"].magnitude[k]
                                       * f.crank_arms()["R21"][k], rel=1e-12)
    if kinds is None:
        assert set(f.as_json(k)["loads"]["neglected"]) == {"G2", "Pи2", "G3", "Pи3"}


def test_press_neglect_rule(press):
    """10 % of the largest load of the group: Q at (2), (3); in the idle stroke G3 keeps
    G2 (1265.5 N > 1226.25 N) and drops Pи2 (≤ 129·3.1 = 400 N); 0 keeps everything."""
    m, cycle, kin = press
    loads = compute_loads(m, kin, cycle)
    assert loads.neglect_below == 0.1
    idle = [kin.labels.index(x) for x in "1234"]
    assert loads.neglected["Pи2"][idle].all()
    assert "G2" not in loads.neglected or not loads.neglected["G2"][idle].any()
    assert not compute_loads(m, kin, cycle, neglect_below=0.0).neglected


# --------------------------------------------------------------------------------------
# Technological resistance
# --------------------------------------------------------------------------------------

def test_diagram_value_linear_and_jumps():
    shaper = ((0.0, 0.0), (0.05, 0.0), (0.05, 1.0), (0.95, 1.0), (0.95, 0.0), (1.0, 0.0))
    s = np.array([0.0, 0.02, 0.05, 0.05 - 1e-12, 0.5, 0.95, 0.97, 1.0])
    assert diagram_value(shaper, s).tolist() == [0, 0, 1, 1, 1, 1, 0, 0]
    trapezoid = ((0.0, 0.0), (0.1, 1.0), (0.9, 1.0), (1.0, 0.0))
    assert diagram_value(trapezoid, [0.05, 0.5, 0.95]) == pytest.approx([0.5, 1.0, 0.5])
    assert diagram_value(((0.2, 1.0), (0.6, 0.0)), [0.1, 0.4, 0.7]) == pytest.approx(
        [0.0, 0.5, 0.0])


@pytest.mark.parametrize("name", [x for x in EXAMPLES if x != "shaper_prp"])
def test_resistance_only_in_working_stroke_and_against_motion(name):
    m = g.load(bundled_example(name))
    cycle = g.analyse_cycle(m)
    phi = np.radians(np.arange(0.0, 360.0, 0.5) + 0.25)
    kin = g.solve(m, phi)
    loads = compute_loads(m, kin, cycle, kinds=("resistance",))
    working = in_working_stroke(m, cycle, phi)
    (res,) = [*loads.all_forces(), *loads.all_moments()]
    if isinstance(res, ForceLoad):
        size = np.hypot(*res.vector.T)
        v = kin.vel.points[res.point]
        power = dot(res.vector, v)
        u = kin.pos.guides[f"{res.link}/{m.frame_link}"][1]
        assert np.allclose(cross(res.vector, u), 0.0, atol=1e-9 * size.max())  # along the guide
        moving = np.hypot(*v.T) > 1e-9 * np.hypot(*v.T).max()
    else:
        size = np.abs(res.moment)
        power = res.moment * kin.vel.omega[res.link]
        moving = np.abs(kin.vel.omega[res.link]) > 1e-9 * np.abs(kin.vel.omega[res.link]).max()
    assert size.max() == pytest.approx(m.resistances[0].maximum, rel=1e-6)
    assert np.all(size[~working] == 0.0)
    on = (size > 0) & moving
    assert on.sum() > 10
    assert np.all(power[on] < 0)  # always against the motion
    assert np.all(power <= 0)


# --------------------------------------------------------------------------------------
# Shifted inertia force, conditioning
# --------------------------------------------------------------------------------------

def test_shift_inertia_force_is_equivalent():
    m = g.load(bundled_example("fourbar"))
    cycle = g.analyse_cycle(m)
    kin = g.sweep(m, cycle)
    plain = compute_loads(m, kin, cycle, neglect_below=0.0, shift_inertia=False)
    moved = compute_loads(m, kin, cycle, neglect_below=0.0, shift_inertia=True)
    f0, f1 = ks.solve_forces(m, kin, plain), ks.solve_forces(m, kin, moved)
    assert np.allclose(f1.M_bal, f0.M_bal, rtol=1e-12, atol=1e-12 * np.abs(f0.M_bal).max())
    for name, r in f0.reactions.items():
        assert np.allclose(f1.reactions[name].vector, r.vector, rtol=1e-12, atol=1e-9)
    for ln in ("2", "3"):
        P = next(f for f in plain.forces[ln] if f.name == f"Pи{ln}")
        M = next(x for x in plain.moments[ln] if x.name == f"Mи{ln}").moment
        h, at, ok = shift_inertia_force(P.vector, M, P.at)
        assert ok.all()
        assert np.allclose(h, M / np.hypot(*P.vector.T), rtol=1e-12)
        assert np.allclose(cross(at - P.at, P.vector), M, rtol=1e-9)  # its moment about S = Mи
        assert np.allclose(np.hypot(*(at - P.at).T), np.abs(h), rtol=1e-12)
        assert np.allclose(moved.shift[ln], h)
        assert np.all(next(x for x in moved.moments[ln] if x.name == f"Mи{ln}").moment == 0)


def test_singular_pose_is_reported(press, monkeypatch):
    """Above COND_LIMIT the analysis raises, naming the dyad and the position."""
    m, cycle, kin = press
    loads = compute_loads(m, kin, cycle)
    kappa = ks.solve_forces(m, kin, loads).conditioning["RRP(2-3)"]
    limit = 0.5 * (kappa.min() + kappa.max())
    first = int(np.argmax(kappa > limit))
    monkeypatch.setattr(ks, "COND_LIMIT", limit)
    phi = np.degrees(kin.phi[first]) % 360
    with pytest.raises(g.SingularPoseError, match=rf"RRP\(2-3\).*position "
                       rf"{re.escape(kin.labels[first])} \(φ = {phi:.2f}°\)"):
        ks.solve_forces(m, kin, loads)


def test_loads_for_other_positions_are_refused(press):
    m, cycle, kin = press
    loads = compute_loads(m, kin, cycle)
    other = g.solve(m, kin.phi + 0.1)
    with pytest.raises(ValueError, match="other positions"):
        ks.solve_forces(m, other, loads)


def test_loads_are_frozen(press):
    m, cycle, kin = press
    loads = compute_loads(m, kin, cycle)
    with pytest.raises(dataclasses.FrozenInstanceError):
        loads.inertia = False  # type: ignore[misc]


def test_package_loads_is_the_text_loader():
    """The applied loads live in graphplan.forces.loads: graphplan.loads stays the loader."""
    import graphplan.forces.loads  # noqa: F401

    m = g.loads(CF.slider_crank_toml(0.1, 0.4), source="x.toml")
    assert m.source == "x.toml" and m.dyads[0].kind == "RRP"
