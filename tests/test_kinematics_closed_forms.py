"""graphplan's exact kinematics against closed forms derived by hand in this file.

Nothing here calls graphplan's solver internals: every mechanism is written as a
variant (TOML text, inline), solved through the public API (``g.loads`` +
``g.solve`` / ``g.analyse_cycle``), and compared with formulas written out below
(crank–slider, four-bar / Freudenstein, slotted link, Scotch yoke).

Conventions used by the formulas (those of ``graphplan.model.mechanism``): angles in rad,
CCW positive from +x; φ is the absolute angle of O→A and dφ/dt = ω1 (constant,
negative for a clockwise crank); a link's angle θ is the angle of its reference
axis (rod: A→B; four-bar rocker: C→B; slotted link: the slot), ω = dθ/dt, ε = dω/dt.

Tolerances: both sides are exact, so they differ only by floating-point round-off;
we compare to ``REL = 1e-9`` of the quantity's natural scale (r·|ω1|ⁿ for a point,
|ω1|ⁿ for a link). The round-off is ~1e-15 of that scale, so the margin covers the
loss of digits in the 2×2 solves near (but not at) badly conditioned poses while
still catching any real error (a wrong term is O(1) of the scale).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import graphplan as g

REL = 1e-9
DIRECTIONS = ("ccw", "cw")


def omega1(rpm: float, direction: str) -> float:
    """ω1 = ±π·n/30 rad/s, CCW positive."""
    return math.pi * rpm / 30.0 * (1.0 if direction == "ccw" else -1.0)


def close(actual, expected, scale, what, rel=REL):
    """Assert |actual − expected| ≤ rel·scale everywhere."""
    actual = np.asarray(actual, float)
    expected = np.asarray(expected, float)
    err = float(np.max(np.abs(actual - expected)))
    assert err <= rel * scale, f"{what}: max |error| = {err:.3e} > {rel:.0e} × {scale:.4g}"


def wrap(angle):
    """Wrap an angle (difference) to (−π, π]."""
    return np.angle(np.exp(1j * np.asarray(angle, float)))


def unit(t):
    t = np.asarray(t, float)
    return np.stack((np.cos(t), np.sin(t)), axis=-1)


def turned(v):
    """k×v: v turned +90°."""
    v = np.asarray(v, float)
    return np.stack((-v[..., 1], v[..., 0]), axis=-1)


def dot(a, b):
    return np.sum(np.asarray(a) * np.asarray(b), axis=-1)


PHI = np.radians(np.arange(0.0, 360.0, 5.0) + 0.37)  # 72 angles, none exactly special


# --------------------------------------------------------------------------------------
# Crank–slider (RRP on a frame guide)
# --------------------------------------------------------------------------------------

def slider_crank_toml(r, l, *, e=0.0, alpha_deg=0.0, branch="+", direction="ccw", rpm=60.0):
    """Crank O–A (O at the origin), rod A–B, slider B on a frame guide.

    The guide has direction angle α and passes at signed distance e to the LEFT of
    O (i.e. through e·n with n = u turned +90°, u = (cos α, sin α)).
    """
    a = math.radians(alpha_deg)
    px, py = -e * math.sin(a), e * math.cos(a)
    return f"""
[variant]
name = "slider-crank"
length_unit = "m"
[frame]
link = "4"
points = {{ O = [0.0, 0.0] }}
[crank]
link = "1"
joints = ["O", "A"]
length = {r!r}
rpm = {rpm!r}
direction = "{direction}"
[[dyads]]
kind = "RRP"
links = ["2", "3"]
joints = ["A", "B"]
length = {l!r}
guide = {{ link = "4", through = [{px!r}, {py!r}], angle = {alpha_deg!r} }}
branch = "{branch}"
"""


def offset_slider_crank(r, l, e, s, w, psi):
    """Exact offset crank–slider in the guide's own frame (x along the guide, y = n).

    ψ is the crank angle measured from the guide direction; the guide is the line
    y = e; s = ±1 is the branch (B ahead of / behind the foot of A along the guide).

    Position:   x_B = r cos ψ + s·√(l² − (e − r sin ψ)²),   rod angle θ (A→B):
                sin θ = (e − r sin ψ)/l,  cos θ = s·√(l² − (e − r sin ψ)²)/l.
    Velocity:   the y-loop  r sin ψ + l sin θ = e  gives  r ω cos ψ + l cos θ·ω2 = 0:
                ω2 = −r ω cos ψ /(l cos θ);
                the x-loop  x_B = r cos ψ + l cos θ  gives
                v_B = −r ω sin ψ − l sin θ·ω2 = −r ω sin(ψ − θ)/cos θ.
    Accel.:     differentiate the y-loop again:
                −r ω² sin ψ − l sin θ·ω2² + l cos θ·ε2 = 0
                ε2 = (r ω² sin ψ + l ω2² sin θ)/(l cos θ);
                a_B = −r ω² cos ψ − l cos θ·ω2² − l sin θ·ε2.
    """
    root = s * np.sqrt(l**2 - (e - r * np.sin(psi)) ** 2)
    xb = r * np.cos(psi) + root
    sin_t = (e - r * np.sin(psi)) / l
    cos_t = root / l
    theta = np.arctan2(sin_t, cos_t)
    w2 = -r * w * np.cos(psi) / (l * cos_t)
    vb = -r * w * np.sin(psi - theta) / cos_t
    e2 = (r * w**2 * np.sin(psi) + l * w2**2 * sin_t) / (l * cos_t)
    ab = -r * w**2 * np.cos(psi) - l * cos_t * w2**2 - l * sin_t * e2
    return xb, theta, vb, w2, ab, e2


@pytest.mark.parametrize("direction", DIRECTIONS)
def test_central_slider_crank_textbook_formulas(direction):
    """Central crank–slider, guide along +x through O, φ from the outer dead position.

    Textbook (λ = r/l, sin β = λ sin φ, β measured the other way from θ2, i.e. β = −θ2):
      x_B = r cos φ + l cos β
      v_B = −ω r sin(φ+β)/cos β
      dβ/dt = ω λ cos φ / cos β                        → ω2 = −dβ/dt
      a_B = −ω² r [cos(φ+β)/cos β + λ cos²φ/cos³β]
      d²β/dt² = −ω² λ sin φ (1−λ²)/cos³β               → ε2 = −d²β/dt²
    valid for either sign of ω (ω enters as dφ/dt and ω² for a constant ω).
    """
    r, l, rpm = 0.1, 0.35, 90.0
    w = omega1(rpm, direction)
    m = g.loads(slider_crank_toml(r, l, direction=direction, rpm=rpm), source="central.toml")
    k = g.solve(m, PHI)
    lam = r / l
    phi = PHI
    beta = np.arcsin(lam * np.sin(phi))
    xb = r * np.cos(phi) + l * np.cos(beta)
    vb = -w * r * np.sin(phi + beta) / np.cos(beta)
    dbeta = w * lam * np.cos(phi) / np.cos(beta)
    cb = np.cos(beta)
    ab = -(w**2) * r * (np.cos(phi + beta) / cb + lam * np.cos(phi) ** 2 / cb**3)
    ddbeta = -(w**2) * lam * np.sin(phi) * (1 - lam**2) / np.cos(beta) ** 3

    P, V, A = k.pos.points["B"], k.vel.points["B"], k.acc.points["B"]
    close(P[:, 0], xb, r, "x_B")
    close(P[:, 1], 0.0, r, "y_B (on the guide)")
    close(V[:, 0], vb, r * abs(w), "v_B")
    close(V[:, 1], 0.0, r * abs(w), "v_B ⟂ guide")
    close(A[:, 0], ab, r * w**2, "a_B")
    close(A[:, 1], 0.0, r * w**2, "a_B ⟂ guide")
    close(wrap(k.pos.theta["2"] - (-beta)), 0.0, 1.0, "θ2 = −β")
    close(k.vel.omega["2"], -dbeta, abs(w), "ω2")
    close(k.acc.epsilon["2"], -ddbeta, w**2, "ε2")
    # the crank, the slider and the sliding pair
    close(k.vel.omega["1"], w, abs(w), "ω1 = ±π·n/30")
    close(k.acc.epsilon["1"], 0.0, w**2, "ε1 = 0")
    close(k.vel.omega["3"], 0.0, abs(w), "ω3 (slider translates)")
    close(k.vel.sliding["3/4"], vb, r * abs(w), "sliding speed of 3 on 4")
    close(k.acc.sliding["3/4"], ab, r * w**2, "sliding acceleration of 3 on 4")


@pytest.mark.parametrize("branch", ["+", "-"])
@pytest.mark.parametrize("direction", DIRECTIONS)
@pytest.mark.parametrize(("e", "alpha_deg"), [(0.03, 0.0), (-0.045, 0.0), (0.025, 35.0),
                                               (-0.02, -120.0)])
def test_offset_slider_crank_exact(e, alpha_deg, direction, branch):
    """Offset crank–slider, guide at angle α: the exact formulas of offset_slider_crank."""
    r, l, rpm = 0.06, 0.21, 120.0
    w = omega1(rpm, direction)
    s = 1.0 if branch == "+" else -1.0
    m = g.loads(slider_crank_toml(r, l, e=e, alpha_deg=alpha_deg, branch=branch,
                                  direction=direction, rpm=rpm), source="offset.toml")
    k = g.solve(m, PHI)
    _check_offset_slider(k, r, l, e, math.radians(alpha_deg), s, w)


def _check_offset_slider(k, r, l, e, alpha, s, w):
    psi = k.phi - alpha  # crank angle measured from the guide direction
    xb, theta, vb, w2, ab, e2 = offset_slider_crank(r, l, e, s, w, psi)
    u = np.array([math.cos(alpha), math.sin(alpha)])
    n = np.array([-math.sin(alpha), math.cos(alpha)])
    P, V, A = k.pos.points["B"], k.vel.points["B"], k.acc.points["B"]
    close(P @ u, xb, r, "x_B along the guide")
    close(P @ n, e, r, "B on the guide line")
    close(V @ u, vb, r * abs(w), "v_B")
    close(V @ n, 0.0, r * abs(w), "v_B ⟂ guide")
    close(A @ u, ab, r * w**2, "a_B")
    close(A @ n, 0.0, r * w**2, "a_B ⟂ guide")
    close(wrap(k.pos.theta["2"] - (theta + alpha)), 0.0, 1.0, "rod angle θ2")
    close(wrap(k.pos.theta["3"] - alpha), 0.0, 1.0, "slider axis = guide direction")
    close(k.vel.omega["2"], w2, abs(w), "ω2")
    close(k.acc.epsilon["2"], e2, w**2, "ε2")
    close(k.vel.sliding["3/4"], vb, r * abs(w), "sliding speed")
    close(k.acc.sliding["3/4"], ab, r * w**2, "sliding acceleration")


@settings(deadline=None, max_examples=40)
@given(
    r=st.floats(0.01, 0.2),
    lam=st.floats(0.08, 0.5),
    e_frac=st.floats(-0.6, 0.6),
    alpha_deg=st.floats(-180.0, 180.0),
    branch=st.sampled_from(["+", "-"]),
    direction=st.sampled_from(DIRECTIONS),
    rpm=st.floats(10.0, 1500.0),
)
def test_random_offset_slider_crank_exact(r, lam, e_frac, alpha_deg, branch, direction, rpm):
    """Random valid crank–sliders: |e| ≤ 0.6(l − r) keeps |e − r sin ψ| < l (no lock-up
    for either branch)."""
    l = r / lam
    e = e_frac * (l - r)
    w = omega1(rpm, direction)
    m = g.loads(slider_crank_toml(r, l, e=e, alpha_deg=alpha_deg, branch=branch,
                                  direction=direction, rpm=rpm), source="random.toml")
    k = g.solve(m, PHI)
    _check_offset_slider(k, r, l, e, math.radians(alpha_deg), 1.0 if branch == "+" else -1.0, w)


# --------------------------------------------------------------------------------------
# The press of examples/press.toml: one position checked by hand
# --------------------------------------------------------------------------------------

PRESS = """
[variant]
name = "press"
length_unit = "mm"
[frame]
link = "4"
points = { O = [0, 0] }
[crank]
link = "1"
joints = ["O", "A"]
length = 80
rpm = 55
direction = "ccw"
[[dyads]]
kind = "RRP"
links = ["2", "3"]
joints = ["A", "B"]
length = 200
guide = { link = "4", through = [0, 0], angle = -90 }
branch = "+"
[output]
link = "3"
working = "+"
[positions]
count = 8
first = "end"
extra = [ { label = "(2)", from = "end", turn = -20 } ]
"""


def test_press_position_2_by_hand():
    """Press, position (2): 20° of crank before the bottom dead centre.

    r = 80 mm, l = 200 mm, λ = 0.4, guide vertical pointing down, O on it.
    Bottom dead centre: A straight below O, φ = 270°; position (2): φ = 250°.
    Measured from the BDC (the outer dead position), ψ = −20° (the crank is 20°
    short of it, turning CCW).
      |OB| = r cos 20° + √(l² − r² sin² 20°)
           = 80·0.939693 + √(40000 − 27.3616²) = 75.1754 + √39251.34
           = 75.1754 + 198.1195 = 273.2949 mm
      rod angle from the vertical: β = asin(80·sin 20°/200) = asin(0.136808) = 7.8632°;
      A is left of the guide (x_A = 80 cos 250° = −27.36 mm), so A→B points down and
      to the right: θ2 = −90° + 7.8632° = −82.1368°.
      ω1 = π·55/30 = 5.759587 rad/s, ω1² = 33.17284 s⁻².
      v_B = −ω r sin(ψ+β)/cos β with sin β = λ sin ψ (β = −7.8632°):
          = −5.759587·0.08·sin(−27.8632°)/cos(7.8632°)
          = −0.460767·(−0.467362)/0.990598 = +0.217389 m/s (down: toward the BDC)
      a_B = −ω² r [cos(ψ+β)/cos β + λ cos²ψ/cos³β]
          = −33.17284·0.08·[0.884066/0.990598 + 0.4·0.883022/0.972066]
          = −2.653827·[0.892457 + 0.363362] = −3.332728 m/s² along the guide
            (i.e. 3.3327 m/s² upward: the ram is braking before the BDC)
      dβ/dt = ω λ cos ψ/cos β = 5.759587·0.4·0.939693/0.990598 = 2.185445 rad/s;
          in the guide's frame the rod angle is θ2 − (−90°) = −β, so ω2 = −dβ/dt
          = −2.185445 rad/s (clockwise);
      d²β/dt² = −ω² λ sin ψ (1−λ²)/cos³β
              = −33.17284·0.4·(−0.342020)·0.84/0.972066
          = +3.921767 rad/s²  → ε2 = −3.921767 rad/s².
    """
    m = g.loads(PRESS, source="press.toml")
    c = g.analyse_cycle(m)
    # dead centres: start of the working (downward) stroke at the TDC φ = 90°, end at the BDC
    assert np.degrees(c.dead_centres) == pytest.approx([90.0, 270.0], abs=1e-6)
    assert c.stroke == pytest.approx(0.160, rel=1e-9)  # 2r
    i = c.labels.index("(2)")
    assert math.degrees(c.phi[i]) == pytest.approx(250.0, abs=1e-6)
    k = g.sweep(m, c)
    B = k.pos.points["B"][i]
    assert B[0] == pytest.approx(0.0, abs=1e-12)
    assert -B[1] * 1000 == pytest.approx(273.2949, abs=5e-4)  # |OB| in mm
    rod_from_vertical = math.degrees(k.pos.theta["2"][i]) + 90.0
    assert rod_from_vertical == pytest.approx(7.8632, abs=5e-5)
    v = k.vel.points["B"][i]
    a = k.acc.points["B"][i]
    assert v[0] == pytest.approx(0.0, abs=1e-12)
    assert -v[1] == pytest.approx(0.217389, abs=2e-6)
    assert k.vel.sliding["3/4"][i] == pytest.approx(0.217389, abs=2e-6)
    assert a[1] == pytest.approx(3.332728, abs=2e-6)  # upward
    assert k.acc.sliding["3/4"][i] == pytest.approx(-3.332728, abs=2e-6)
    assert k.vel.omega["2"][i] == pytest.approx(-2.185445, abs=2e-6)
    assert k.acc.epsilon["2"][i] == pytest.approx(-3.921767, abs=2e-6)
    # the crank pin: v_A = ω·r = 0.460767 m/s, a_A = ω²·r = 2.653827 m/s² toward O
    assert np.hypot(*k.vel.points["A"][i]) == pytest.approx(0.460767, abs=1e-6)
    assert np.hypot(*k.acc.points["A"][i]) == pytest.approx(2.653827, abs=1e-6)


# --------------------------------------------------------------------------------------
# Four-bar (RRR): Freudenstein, and the loop equations differentiated by hand
# --------------------------------------------------------------------------------------

def fourbar_toml(a, b, c, d, *, gamma_deg=0.0, branch="+", direction="ccw", rpm=60.0):
    """Crank O–A = a, coupler A–B = b, rocker C–B = c, frame O–C = d at angle γ."""
    gm = math.radians(gamma_deg)
    cx, cy = d * math.cos(gm), d * math.sin(gm)
    return f"""
[variant]
name = "four-bar"
[frame]
link = "4"
points = {{ O = [0.0, 0.0], C = [{cx!r}, {cy!r}] }}
[crank]
link = "1"
joints = ["O", "A"]
length = {a!r}
rpm = {rpm!r}
direction = "{direction}"
[[dyads]]
kind = "RRR"
links = ["2", "3"]
joints = ["A", "B", "C"]
lengths = [{b!r}, {c!r}]
branch = "{branch}"
"""


def fourbar_closed_form(a, b, c, d, s, w, phi):
    """Four-bar in the frame's own axes (O at the origin, C at (d, 0)).

    Loop: a e^{iφ} + b e^{iθ2} = d + c e^{iθ3}  (θ2 coupler A→B, θ3 rocker C→B).
    Eliminating θ2 (|B − A| = b with B = C + c e^{iθ3}):
        (d + c cos θ3 − a cos φ)² + (c sin θ3 − a sin φ)² = b²
      ⇔ P cos θ3 + Q sin θ3 = R,  P = 2c(d − a cos φ), Q = −2ac sin φ,
                                   R = b² − a² − c² − d² + 2ad cos φ,
    i.e. Freudenstein's  K1 cos θ3 − K2 cos φ + K3 = cos(φ − θ3),
         K1 = d/a, K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac).
    (P, Q) ∝ (d − a cos φ, −a sin φ) = C − A, so with γ = atan2(Q, P) (direction A→C)
        θ3 = γ + s·acos(R/√(P² + Q²)),
    s = +1 puts B to the left of A→C, s = −1 to the right (the two assemblies).
    θ2 = atan2(B − A).

    Velocities (d/dt of the x and y loop equations, ω = dφ/dt):
        −b sin θ2·ω2 + c sin θ3·ω3 =  a ω sin φ
         b cos θ2·ω2 − c cos θ3·ω3 = −a ω cos φ
    Accelerations (d/dt again, ω constant):
        −b sin θ2·ε2 + c sin θ3·ε3 = a ω² cos φ + b ω2² cos θ2 − c ω3² cos θ3
         b cos θ2·ε2 − c cos θ3·ε3 = a ω² sin φ + b ω2² sin θ2 − c ω3² sin θ3
    Both 2×2 systems are solved by Cramer's rule below.
    """
    P = 2 * c * (d - a * np.cos(phi))
    Q = -2 * a * c * np.sin(phi)
    R = b**2 - a**2 - c**2 - d**2 + 2 * a * d * np.cos(phi)
    th3 = np.arctan2(Q, P) + s * np.arccos(R / np.hypot(P, Q))
    Bx, By = d + c * np.cos(th3), c * np.sin(th3)
    th2 = np.arctan2(By - a * np.sin(phi), Bx - a * np.cos(phi))

    # matrix [[m11, m12], [m21, m22]] is the same for both systems
    m11, m12 = -b * np.sin(th2), c * np.sin(th3)
    m21, m22 = b * np.cos(th2), -c * np.cos(th3)
    det = m11 * m22 - m12 * m21

    def cramer(r1, r2):
        return (r1 * m22 - m12 * r2) / det, (m11 * r2 - r1 * m21) / det

    w2, w3 = cramer(a * w * np.sin(phi), -a * w * np.cos(phi))
    e2, e3 = cramer(
        a * w**2 * np.cos(phi) + b * w2**2 * np.cos(th2) - c * w3**2 * np.cos(th3),
        a * w**2 * np.sin(phi) + b * w2**2 * np.sin(th2) - c * w3**2 * np.sin(th3),
    )
    vB = c * w3[:, None] * np.stack((-np.sin(th3), np.cos(th3)), axis=-1)
    aB = (c * e3[:, None] * np.stack((-np.sin(th3), np.cos(th3)), axis=-1)
          - c * (w3**2)[:, None] * np.stack((np.cos(th3), np.sin(th3)), axis=-1))
    B = np.stack((Bx, By), axis=-1)
    return th2, th3, w2, w3, e2, e3, B, vB, aB


def _rot(v, g_):
    cg, sg = math.cos(g_), math.sin(g_)
    return np.stack((cg * v[..., 0] - sg * v[..., 1], sg * v[..., 0] + cg * v[..., 1]), axis=-1)


def _check_fourbar(a, b, c, d, gamma_deg, branch, direction, rpm):
    w = omega1(rpm, direction)
    s = 1.0 if branch == "+" else -1.0
    gm = math.radians(gamma_deg)
    m = g.loads(fourbar_toml(a, b, c, d, gamma_deg=gamma_deg, branch=branch,
                             direction=direction, rpm=rpm), source="fourbar.toml")
    k = g.solve(m, PHI)
    phi_local = PHI - gm  # crank angle from the frame line O→C
    th2, th3, w2, w3, e2, e3, B, vB, aB = fourbar_closed_form(a, b, c, d, s, w, phi_local)
    # Freudenstein's equation itself holds for graphplan's rocker angle
    t3 = k.pos.theta["3"] - gm
    K1, K2, K3 = d / a, d / c, (a**2 - b**2 + c**2 + d**2) / (2 * a * c)
    close(K1 * np.cos(t3) - K2 * np.cos(phi_local) + K3 - np.cos(phi_local - t3), 0.0,
          max(1.0, K1, K2, abs(K3)), "Freudenstein residual")
    close(wrap(k.pos.theta["3"] - (th3 + gm)), 0.0, 1.0, "rocker angle θ3")
    close(wrap(k.pos.theta["2"] - (th2 + gm)), 0.0, 1.0, "coupler angle θ2")
    close(k.pos.points["B"], _rot(B, gm), a, "B")
    close(k.vel.omega["2"], w2, abs(w), "ω2")
    close(k.vel.omega["3"], w3, abs(w), "ω3")
    close(k.acc.epsilon["2"], e2, w**2, "ε2")
    close(k.acc.epsilon["3"], e3, w**2, "ε3")
    close(k.vel.points["B"], _rot(vB, gm), a * abs(w), "v_B")
    close(k.acc.points["B"], _rot(aB, gm), a * w**2, "a_B")
    return k


@pytest.mark.parametrize("branch", ["+", "-"])
@pytest.mark.parametrize("direction", DIRECTIONS)
def test_fourbar_crank_rocker_both_branches(branch, direction):
    """Grashof crank–rocker a + d < b + c (0.08 + 0.30 < 0.25 + 0.20), frame tilted 10°."""
    k = _check_fourbar(0.08, 0.25, 0.20, 0.30, 10.0, branch, direction, 75.0)
    # the two branches are really different assemblies (mirror images in A–C)
    other = "-" if branch == "+" else "+"
    m2 = g.loads(fourbar_toml(0.08, 0.25, 0.20, 0.30, gamma_deg=10.0, branch=other,
                              direction=direction, rpm=75.0))
    k2 = g.solve(m2, PHI)
    assert np.min(np.hypot(*(k.pos.points["B"] - k2.pos.points["B"]).T)) > 0.05


@pytest.mark.parametrize("branch", ["+", "-"])
def test_fourbar_double_crank(branch):
    """Drag link (double crank): the frame is the shortest link and s + L < p + q
    (0.07 + 0.28 < 0.20 + 0.24), so the "rocker" turns fully too; clockwise crank."""
    _check_fourbar(0.20, 0.28, 0.24, 0.07, -30.0, branch, "cw", 40.0)


@settings(deadline=None, max_examples=40)
@given(
    b=st.floats(0.5, 1.5),
    c=st.floats(0.5, 1.5),
    d=st.floats(0.5, 1.5),
    frac=st.floats(0.05, 0.85),
    scale=st.floats(0.05, 2.0),
    gamma_deg=st.floats(-180.0, 180.0),
    branch=st.sampled_from(["+", "-"]),
    direction=st.sampled_from(DIRECTIONS),
    rpm=st.floats(10.0, 1000.0),
)
def test_random_grashof_crank_rocker(b, c, d, frac, scale, gamma_deg, branch, direction, rpm):
    """Random Grashof crank–rockers: a = frac·(p + q − L) < p + q − L for the other three
    links (L the longest of b, c, d), so a + L < p + q and a is the shortest: the crank
    turns fully and the transmission angle never reaches 0 or π."""
    longest = max(b, c, d)
    slack = b + c + d - 2 * longest  # p + q − L
    assume(slack > 0.1)
    a = frac * slack
    _check_fourbar(a * scale, b * scale, c * scale, d * scale, gamma_deg, branch, direction, rpm)


# --------------------------------------------------------------------------------------
# Slotted link (RPR, oscillating кулиса)
# --------------------------------------------------------------------------------------

def slotted_toml(r, cx, cy, *, offset=0.0, branch="+", direction="ccw", rpm=60.0):
    """Crank O–A; block 2 pinned at A slides in the slot of link 3 pivoted at O3 = (cx, cy)."""
    return f"""
[variant]
name = "slotted"
[frame]
link = "4"
points = {{ O = [0.0, 0.0], O3 = [{cx!r}, {cy!r}] }}
[crank]
link = "1"
joints = ["O", "A"]
length = {r!r}
rpm = {rpm!r}
direction = "{direction}"
[[dyads]]
kind = "RPR"
links = ["2", "3"]
joints = ["A", "O3"]
offset = {offset!r}
branch = "{branch}"
"""


@pytest.mark.parametrize("direction", DIRECTIONS)
@pytest.mark.parametrize(("r", "cx", "cy"), [(0.1, 0.0, -0.3), (0.08, 0.05, 0.2),
                                              (0.1, 0.0, -0.04)])  # last: rotating slot
def test_slotted_link_central(r, cx, cy, direction):
    """Slot through the pivot (offset 0), branch "+": the slot points O3→A.

    u = (A − O3)/l, l = |O3A|, n = k×u. From A − O3 = l·u, u̇ = ω3 n:
      v_A = l̇ u + l ω3 n           → ω3 = v_A·n / l,  v_r = l̇ = v_A·u
      a_A = (l̈ − l ω3²) u + (l ε3 + 2 l̇ ω3) n
                                   → ε3 = (a_A·n − 2 ω3 v_r)/l,  a_r = a_A·u + ω3² l
    with v_A = r ω (−sin φ, cos φ), a_A = −r ω² (cos φ, sin φ) (crank at constant ω).
    """
    rpm = 100.0
    w = omega1(rpm, direction)
    m = g.loads(slotted_toml(r, cx, cy, direction=direction, rpm=rpm), source="slotted.toml")
    k = g.solve(m, PHI)
    A = r * unit(PHI)
    vA = r * w * turned(unit(PHI))
    aA = -r * w**2 * unit(PHI)
    d = A - np.array([cx, cy])
    ln = np.hypot(d[:, 0], d[:, 1])
    u = d / ln[:, None]
    n = turned(u)
    th3 = np.arctan2(d[:, 1], d[:, 0])
    w3 = dot(vA, n) / ln
    vr = dot(vA, u)
    e3 = (dot(aA, n) - 2 * w3 * vr) / ln
    ar = dot(aA, u) + w3**2 * ln

    close(wrap(k.pos.theta["3"] - th3), 0.0, 1.0, "θ3")
    close(wrap(k.pos.theta["2"] - th3), 0.0, 1.0, "θ2 = θ3 (block turns with the slot)")
    close(k.vel.omega["3"], w3, abs(w), "ω3")
    close(k.vel.omega["2"], w3, abs(w), "ω2 = ω3")
    close(k.vel.sliding["2/3"], vr, r * abs(w), "v_r")
    close(k.acc.epsilon["3"], e3, w**2, "ε3")
    close(k.acc.epsilon["2"], e3, w**2, "ε2 = ε3")
    close(k.acc.sliding["2/3"], ar, r * w**2, "a_r")
    # Coriolis acceleration of the block in the turning slot: 2 ω3 k×(v_r u)
    close(k.acc.coriolis["2/3"], 2 * (w3 * vr)[:, None] * n, r * w**2, "Coriolis")


@pytest.mark.parametrize("branch", ["+", "-"])
@pytest.mark.parametrize("direction", DIRECTIONS)
@pytest.mark.parametrize("offset", [0.025, -0.04])
def test_slotted_link_with_offset(offset, branch, direction):
    """Slot axis at signed distance e to the left of the slot direction from the pivot C.

    A − C = s u + e n  (s the block's coordinate along the slot, u = (cos θ, sin θ),
    n = k×u; s > 0 for branch "+", s < 0 for "−"; |s| = √(l² − e²), l = |CA|), so
        θ = atan2(A − C) − atan2(e, s).
    d/dt (u̇ = ω n, ṅ = −ω u):
        v_A = (ṡ − e ω) u + s ω n
        a_A = (s̈ − e ε − s ω²) u + (2 ṡ ω + s ε − e ω²) n
    hence  ω = v_A·n / s,  ṡ = v_A·u + e ω,
           ε = (a_A·n − 2 ṡ ω + e ω²)/s,  s̈ = a_A·u + e ε + s ω².
    """
    r, cx, cy, rpm = 0.09, 0.02, -0.26, 80.0
    w = omega1(rpm, direction)
    sg = 1.0 if branch == "+" else -1.0
    m = g.loads(slotted_toml(r, cx, cy, offset=offset, branch=branch, direction=direction,
                             rpm=rpm), source="slotted-offset.toml")
    k = g.solve(m, PHI)
    e = offset
    A = r * unit(PHI)
    vA = r * w * turned(unit(PHI))
    aA = -r * w**2 * unit(PHI)
    dv = A - np.array([cx, cy])
    ln = np.hypot(dv[:, 0], dv[:, 1])
    s = sg * np.sqrt(ln**2 - e**2)
    th = np.arctan2(dv[:, 1], dv[:, 0]) - np.arctan2(e, s)
    u, n = unit(th), turned(unit(th))
    close(A - np.array([cx, cy]), s[:, None] * u + e * n, r, "loop A − C = s u + e n")
    om = dot(vA, n) / s
    sd = dot(vA, u) + e * om
    ep = (dot(aA, n) - 2 * sd * om + e * om**2) / s
    sdd = dot(aA, u) + e * ep + s * om**2
    close(wrap(k.pos.theta["3"] - th), 0.0, 1.0, "θ3")
    close(k.vel.omega["3"], om, abs(w), "ω3")
    close(k.vel.sliding["2/3"], sd, r * abs(w), "v_r")
    close(k.acc.epsilon["3"], ep, w**2, "ε3")
    close(k.acc.sliding["2/3"], sdd, r * w**2, "a_r")


# --------------------------------------------------------------------------------------
# Scotch yoke (RPP: block 2 at A in the slot of yoke 3, yoke on a frame guide)
# --------------------------------------------------------------------------------------

def yoke_toml(r, *, slot_angle=90.0, direction="ccw", rpm=60.0):
    return f"""
[variant]
name = "yoke"
[frame]
link = "4"
points = {{ O = [0.0, 0.0] }}
[crank]
link = "1"
joints = ["O", "A"]
length = {r!r}
rpm = {rpm!r}
direction = "{direction}"
[[dyads]]
kind = "RPP"
links = ["2", "3"]
joints = ["A", "D"]
guide = {{ link = "4", through = "O", angle = 0 }}
slot_angle = {slot_angle!r}
"""


@pytest.mark.parametrize("direction", DIRECTIONS)
def test_scotch_yoke_exact_harmonic(direction):
    """Slot ⟂ guide (guide = x axis through O): D = (r cos φ, 0) exactly,
    v = −r ω sin φ, a = −r ω² cos φ; the block slides in the slot (direction +y)
    by A − D = (0, r sin φ): v_r = r ω cos φ, a_r = −r ω² sin φ."""
    r, rpm = 0.12, 200.0
    w = omega1(rpm, direction)
    m = g.loads(yoke_toml(r, direction=direction, rpm=rpm), source="yoke.toml")
    k = g.solve(m, PHI)
    D, V, A = k.pos.points["D"], k.vel.points["D"], k.acc.points["D"]
    close(D[:, 0], r * np.cos(PHI), r, "x_D")
    close(D[:, 1], 0.0, r, "y_D")
    close(V[:, 0], -r * w * np.sin(PHI), r * abs(w), "v_D")
    close(V[:, 1], 0.0, r * abs(w), "v_D ⟂ guide")
    close(A[:, 0], -r * w**2 * np.cos(PHI), r * w**2, "a_D")
    close(A[:, 1], 0.0, r * w**2, "a_D ⟂ guide")
    close(k.vel.sliding["3/4"], -r * w * np.sin(PHI), r * abs(w), "yoke sliding speed")
    close(k.acc.sliding["3/4"], -r * w**2 * np.cos(PHI), r * w**2, "yoke sliding accel.")
    close(k.vel.sliding["2/3"], r * w * np.cos(PHI), r * abs(w), "block in the slot, speed")
    close(k.acc.sliding["2/3"], -r * w**2 * np.sin(PHI), r * w**2, "block in the slot, accel.")
    for link in ("2", "3"):
        close(k.vel.omega[link], 0.0, abs(w), f"ω{link}")
        close(k.acc.epsilon[link], 0.0, w**2, f"ε{link}")
    close(wrap(k.pos.theta["3"]), 0.0, 1.0, "yoke axis along the guide")
    close(wrap(k.pos.theta["2"] - math.pi / 2), 0.0, 1.0, "block axis along the slot")
    # no rotation of the guides: no Coriolis acceleration
    close(k.acc.coriolis["3/4"], 0.0, r * w**2, "Coriolis 3/4")
    close(k.acc.coriolis["2/3"], 0.0, r * w**2, "Coriolis 2/3")


@pytest.mark.parametrize("direction", DIRECTIONS)
@pytest.mark.parametrize("slot_deg", [60.0, 135.0, -75.0])
def test_scotch_yoke_inclined_slot(slot_deg, direction):
    """Slot at angle α to the guide (the x axis): D is where the line through A along
    (cos α, sin α) meets y = 0, D = A − (r sin φ / sin α)(cos α, sin α):
        x_D = r cos φ − r sin φ cot α = r sin(α − φ)/sin α
        v_D = −r ω cos(α − φ)/sin α,  a_D = −r ω² sin(α − φ)/sin α."""
    r, rpm = 0.05, 300.0
    w = omega1(rpm, direction)
    al = math.radians(slot_deg)
    m = g.loads(yoke_toml(r, slot_angle=slot_deg, direction=direction, rpm=rpm))
    k = g.solve(m, PHI)
    close(k.pos.points["D"][:, 0], r * np.sin(al - PHI) / math.sin(al), r, "x_D")
    close(k.vel.points["D"][:, 0], -r * w * np.cos(al - PHI) / math.sin(al), r * abs(w), "v_D")
    close(k.acc.points["D"][:, 0], -r * w**2 * np.sin(al - PHI) / math.sin(al), r * w**2, "a_D")
    # block: position along the slot s = (A − D)·w = r sin φ / sin α
    close(k.vel.sliding["2/3"], r * w * np.cos(PHI) / math.sin(al), r * abs(w), "v_r in slot")
    close(k.acc.sliding["2/3"], -r * w**2 * np.sin(PHI) / math.sin(al), r * w**2, "a_r in slot")
