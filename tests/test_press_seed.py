"""The seed's press (examples/press.toml) at its working positions, checked by hand arithmetic."""

import math

import numpy as np
import pytest

import graphplan as g
from graphplan.files import bundled_example


@pytest.fixture(scope="module")
def press():
    m = g.load(bundled_example("press"))
    cycle = g.analyse_cycle(m)
    return m, cycle, g.sweep(m, cycle)


def test_positions_are_the_seeds(press):
    _, cycle, kin = press
    # 8 positions every 45°, position 1 at the bottom dead centre (crank pointing down,
    # φ = 270°, ccw), then the working positions (2), (3) 20° and 10° before it.
    assert kin.labels == ("1", "2", "3", "4", "5", "6", "7", "8", "(2)", "(3)")
    expected = [270, 315, 0, 45, 90, 135, 180, 225, 250, 260]
    assert np.degrees(kin.phi) == pytest.approx(expected, abs=1e-9)
    # dead centres: top (start of the down stroke) at φ = 90°, bottom (end) at 270°
    assert np.degrees(cycle.dead_centres) == pytest.approx([90, 270], abs=1e-7)
    # central crank-slider: H = 2·r = 160 mm
    assert cycle.stroke == pytest.approx(0.160, rel=1e-12)


@pytest.mark.parametrize(
    ("label", "ob_mm", "beta_deg", "h21_mm"),
    [
        # (2): ψ = 20° before BDC. r sinψ = 80·0.342020 = 27.3616 mm,
        # r cosψ = 80·0.939693 = 75.1754 mm, sqrt(200² − 27.3616²) = sqrt(39251.34) = 198.1195,
        # |OB| = 75.1754 + 198.1195 = 273.2949 mm; β = asin(27.3616/200) = asin(0.136808) = 7.8632°;
        # h21 (arm of the rod force about O) = r sinψ·|OB|/l = 27.3616·273.2949/200 = 37.389 mm
        # (the seed measured 37.39 mm).
        ("(2)", 273.2949, 7.8632, 37.389),
        # (3): ψ = 10°. r sinψ = 13.8919, r cosψ = 78.7846, sqrt(200² − 13.8919²) = 199.5169,
        # |OB| = 278.3016 mm; β = asin(13.8919/200) = asin(0.069459) = 3.9829°;
        # h21 = 13.8919·278.3015/200
        # = 19.331 mm (the seed measured 19.33 mm).
        ("(3)", 278.3016, 3.9829, 19.331),
    ],
)
def test_working_positions_by_hand(press, label, ob_mm, beta_deg, h21_mm):
    _, _, kin = press
    k = kin.labels.index(label)
    O, A, B = (kin.pos.points[p][k] for p in ("O", "A", "B"))
    assert np.linalg.norm(B - O) * 1e3 == pytest.approx(ob_mm, abs=1e-3)
    assert B[0] == pytest.approx(0.0, abs=1e-12)  # on the central vertical guide
    rod = B - A
    beta = math.degrees(math.atan2(abs(rod[0]), abs(rod[1])))  # rod angle from the vertical
    assert beta == pytest.approx(beta_deg, abs=1e-4)
    # perpendicular from O to the line AB (the rod is a two-force member when only the
    # press force acts): |OA × AB| / |AB|
    arm = abs(A[0] * rod[1] - A[1] * rod[0]) / np.linalg.norm(rod) * 1e3
    assert arm == pytest.approx(h21_mm, abs=2e-3)


def test_acceleration_scale_of_the_seed(press):
    _m, _, kin = press
    # Ka = ω1²·l_OA / 100 mm: (π·55/30)² · 0.08 / 100 = 5.75959² · 0.0008 = 0.026539
    a_A = np.linalg.norm(kin.acc.points["A"], axis=1)
    assert a_A / 100 == pytest.approx(np.full(kin.n, 0.026539), abs=1e-6)


def test_idle_position_2_slider_acceleration(press):
    _, _, kin = press
    # position 2: 45° past the bottom dead centre. Exact slider acceleration
    # a_B = ω²r[cosψ + λ cos2ψ/cosβ + λ³ sin²2ψ/(4cos³β)] with λ = 0.4, ψ = 45°:
    # cos2ψ = 0 and sin2ψ = 1, sinβ = 0.4·0.707107 = 0.282843, cosβ = sqrt(0.92) = 0.959166,
    # cos³β = 0.882433, ω²r = 5.759587²·0.08 = 33.172837·0.08 = 2.653827,
    # a_B = 2.653827·[0.707107 + 0 + 0.064/(4·0.882433)] = 2.653827·0.725239 = 1.924657 m/s²
    # (the seed read πb = 74.08 mm → 1.966 m/s², 2 % high: a drafting reading).
    k = kin.labels.index("2")
    assert np.linalg.norm(kin.acc.points["B"][k]) == pytest.approx(1.924657, rel=1e-6)
