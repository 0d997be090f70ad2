"""Velocity and acceleration plans built as constructions and read back at their scales."""

import glob
import math

import pytest

import graphplan as g
from graphplan.geometry import norm
from graphplan.plans import EXACT, Reader, acceleration_plan, velocity_plan
from graphplan.units import fit_scale, nice_ceil

EXAMPLES = sorted(glob.glob(str(__import__("pathlib").Path(__file__).parents[1] / "examples"
                              / "*.toml")))


def scales(m, k):
    kl = fit_scale("Kl", "m/mm", m.crank.length, 80, quantity="lOA", defining=m.crank.length,
                   segment="OA")
    vmax = max(float(norm(v).max()) for v in k.vel.points.values())
    amax = max(float(norm(v).max()) for v in k.acc.points.values())
    return kl, fit_scale("Kv", "(m/s)/mm", vmax, 100), fit_scale("Ka", "(m/s²)/mm", amax, 100)


@pytest.mark.parametrize("x", [0.0123, 0.02, 0.021, 0.0251, 0.9, 1.0, 3.0, 4.5, 700])
def test_nice_scale_is_the_next_of_the_series(x):
    s = nice_ceil(x)
    mant = s / 10 ** math.floor(math.log10(s))
    assert s >= x and round(mant, 9) in (1, 2, 2.5, 4, 5)
    # nothing of the series lies between x and s
    below = [m * 10**e for e in range(-4, 4) for m in (1, 2, 2.5, 4, 5)
             if x <= m * 10**e < s * (1 - 1e-12)]
    assert below == []


def test_scale_basis_as_students_write_it():
    kl = fit_scale("Kl", "m/mm", 0.08, 80, quantity="lOA", defining=0.08, segment="OA")
    assert kl.basis == "Kl = lOA/OA = 0.08/80 = 0.001 m/mm"


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.rsplit("/", 1)[-1])
def test_exact_readback_equals_kinematics(path):
    m = g.load(path)
    k = g.sweep(m, g.analyse_cycle(m))
    kl, kv, ka = scales(m, k)
    vmax = max(float(norm(v).max()) for v in k.vel.points.values())
    amax = max(float(norm(v).max()) for v in k.acc.points.values())
    for i in range(k.n):
        vp = velocity_plan(m, k, i, kl, kv, EXACT)
        ap = acceleration_plan(m, k, i, kl, ka, vp, EXACT)
        for name in k.vel.points:
            key = "p" + name.lower()
            if key in vp.readings:
                exact = float(norm(k.vel.points[name][i]))
                assert vp.readings[key].value == pytest.approx(exact, rel=1e-6, abs=1e-9 * vmax)
            key = "π" + name.lower()
            if key in ap.readings:
                exact = float(norm(k.acc.points[name][i]))
                assert ap.readings[key].value == pytest.approx(exact, rel=1e-6, abs=1e-9 * amax)
        for ln, w in vp.rates.items():
            if ln in k.vel.omega:
                assert w == pytest.approx(k.vel.omega[ln][i], rel=1e-6, abs=1e-9)
                assert ap.rates[ln] == pytest.approx(k.acc.epsilon[ln][i], rel=1e-6, abs=1e-8)
        for key, v in vp.sliding.items():
            assert v == pytest.approx(k.vel.sliding[key][i], rel=1e-6, abs=1e-9 * vmax)
            assert ap.sliding[key] == pytest.approx(k.acc.sliding[key][i], rel=1e-6,
                                                    abs=1e-9 * amax)
        # every intersection step records its angle and the error bound it implies
        for st in vp.steps + ap.steps:
            if st.angle_deg is not None:
                assert 0 < st.angle_deg <= 90
                assert st.error_mm == pytest.approx(0.5 / math.sin(math.radians(st.angle_deg)))


def test_drafting_mode_errs_like_a_hand_drawing():
    m = g.load(EXAMPLES[[p.endswith("press.toml") for p in EXAMPLES].index(True)])
    k = g.sweep(m, g.analyse_cycle(m))
    kl, kv, _ka = scales(m, k)
    errs = []
    for i in range(k.n):
        vp = velocity_plan(m, k, i, kl, kv, Reader(0.5))
        for r in vp.readings.values():
            assert r.mm / 0.5 == pytest.approx(round(r.mm / 0.5), abs=1e-9)  # read to 0.5 mm
            assert abs(r.mm - r.exact_mm) <= 0.25 + 1e-9 or r.name.startswith("p")
        errs.append(abs(vp.value("pb") - float(norm(k.vel.points["B"][i]))))
    assert 0 < max(errs) <= 0.5 * kv.per_mm * 3  # a few reading steps at most


def test_press_velocity_plan_by_hand():
    m = g.load(EXAMPLES[[p.endswith("press.toml") for p in EXAMPLES].index(True)])
    k = g.sweep(m, g.analyse_cycle(m))
    kl = fit_scale("Kl", "m/mm", 0.08, 80, fixed=0.001)
    kv = fit_scale("Kv", "(m/s)/mm", 0.5, 100, fixed=0.005)
    i = k.labels.index("3")  # crank horizontal (φ = 0°): A = (80, 0) mm, B = (0, −183.30) mm
    vp = velocity_plan(m, k, i, kl, kv)
    # v_A = ω1·l_OA = 5.75959·0.08 = 0.460767 m/s → pa = 0.460767/0.005 = 92.153 mm, ⟂ OA (up)
    assert vp.readings["pa"].mm == pytest.approx(92.153, abs=1e-3)
    assert vp.points["a"] == pytest.approx([0.0, 92.153], abs=1e-3)
    # the line ⟂ AB through a meets the vertical through p at b: with the crank horizontal the
    # rod's angular velocity is zero, so b = a: pb = pa, ab = 0 (ω2 = 0)
    assert vp.readings["pb"].mm == pytest.approx(92.153, abs=1e-3)
    assert vp.readings["ab"].mm == pytest.approx(0.0, abs=1e-9)
    assert vp.rates["2"] == pytest.approx(0.0, abs=1e-12)
    # steps in drawing order: pole, pa, the two lines and their intersection, the readings, s2, s3
    assert [s.number for s in vp.steps] == list(range(1, len(vp.steps) + 1))
    assert vp.steps[0].text.startswith("Pole p")
    assert "⟂ OA" in vp.steps[1].text
