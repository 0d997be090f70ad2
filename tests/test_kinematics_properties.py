"""Properties every exact kinematic solution must have, for every kind of dyad.

Catalogue (variants written inline below): every dyad kind — RRR, RRP, RPR, PRP,
RPP — both assembly branches where there are two, counter-clockwise and clockwise
cranks, and guides carried by MOVING links (an RRP slider on a guide carried by a
rocker, a PRP whose first guide is on a rocker or on a coupler, an RPP whose yoke
slides on a rocker, an RPR whose slotted link is pivoted on a rocker, a six-bar whose
second RRR hangs on a coupler point of the first).

For each mechanism, over a sweep of crank angles (time t with dφ/dt = ω1):

* velocities are central differences of positions in time, accelerations central
  differences of velocities: every point, every link angle (θ → ω → ε) and every
  sliding coordinate along its guide (s → v_r → a_r);
* distances between any two points of the same link stay constant;
* rigid-body relations hold for every pair of points P, Q of a link:
  v_P − v_Q = ω k×(P − Q),  a_P − a_Q = ε k×(P − Q) − ω²(P − Q);
* the chosen assembly branch holds over the whole sweep, and the motion on a
  fine grid is continuous (no jump to the other branch);
* sliding pairs: the composition of velocities and accelerations in the moving
  guide (v_X = v_Xk + v_r u, a_X = a_Xk + a_c + a_r u), Coriolis a_c = 2 ω_k k×(v_r u),
  the guide turns with its carrier, the slider stays on its guide; for a frame
  guide the sliding speed is the slider point's velocity along the guide.

Tolerances (see ``FD_REL`` and ``EXACT_REL``).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import graphplan as g

# Central differences with a crank step of H_PHI rad (dt = H_PHI/|ω1|): the truncation
# error h²/6·f''' is ~1e-9 of the derivative's scale for the catalogue (measured: worst
# 1.1e-9 over all cases, scaling as h², i.e. truncation-dominated; round-off ≈ 1e-16/h
# ≈ 1e-11). FD_REL = 1e-6 leaves a ~1000× margin while any wrong term (sign, missing
# Coriolis, wrong ω of a guide) shows up as an O(1) relative error.
H_PHI = 1e-5
FD_REL = 1e-6
# Relations that must hold exactly (up to round-off) between solved quantities.
EXACT_REL = 1e-9


def omega1(rpm: float, direction: str) -> float:
    """ω1 = ±π·n/30 rad/s, CCW positive (written here, not read from graphplan)."""
    return math.pi * rpm / 30.0 * (1.0 if direction == "ccw" else -1.0)


def turned(v):
    """k×v: each vector turned +90°."""
    v = np.asarray(v, float)
    return np.stack((-v[..., 1], v[..., 0]), axis=-1)


def dot(a, b):
    return np.sum(np.asarray(a, float) * np.asarray(b, float), axis=-1)


def cross(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def wrap(angle):
    """Wrap to (−π, π]."""
    return np.angle(np.exp(1j * np.asarray(angle, float)))


def close(actual, expected, floor, what, rel):
    """|actual − expected| ≤ rel·max(max|expected|, floor) over the whole sweep."""
    actual = np.asarray(actual, float)
    expected = np.asarray(expected, float)
    scale = max(float(np.max(np.abs(expected))) if expected.size else 0.0, floor)
    err = float(np.max(np.abs(actual - expected)))
    assert err <= rel * scale, f"{what}: max |error| = {err:.3e} > {rel:.0e} × {scale:.4g}"


# --------------------------------------------------------------------------------------
# The catalogue of mechanisms
# --------------------------------------------------------------------------------------

CRANK = """
[crank]
link = "1"
joints = ["O", "A"]
length = {r}
rpm = {rpm}
direction = "{dir}"
"""

SLIDER = """
[frame]
link = "0"
points = { O = [-0.05, 0.03] }   # the crank pivot off the origin
""" + CRANK + """
[[dyads]]                # offset crank–slider on an inclined frame guide
kind = "RRP"
links = ["2", "3"]
joints = ["A", "B"]
length = 0.2
guide = { link = "0", through = [0.02, 0.015], angle = 20 }
branch = "{b1}"
[[points]]
name = "S2"
link = "2"
from = "A"
toward = "B"
fraction = 0.3
across = 0.01
[[points]]
name = "S3"
link = "3"
from = "B"
along = 0.03
across = 0.02
"""

SLOTTED = """
[frame]
link = "0"
points = { O = [0.0, 0.0], O3 = [0.02, -0.15] }
""" + CRANK + """
[[dyads]]                # oscillating slotted link, slot offset from the pivot
kind = "RPR"
links = ["2", "3"]
joints = ["A", "O3"]
offset = 0.02
branch = "{b1}"
[[points]]
name = "P2"
link = "2"
from = "A"
along = 0.01
across = 0.005
[[points]]
name = "K3"
link = "3"
from = "O3"
along = 0.25
across = 0.01
"""

WHITWORTH = """
[frame]
link = "0"
points = { O = [0.0, 0.0], O3 = [0.0, -0.03] }
""" + CRANK + """
[[dyads]]                # rotating slotted link (pivot inside the crank circle)
kind = "RPR"
links = ["2", "3"]
joints = ["A", "O3"]
offset = -0.01
branch = "{b1}"
[[points]]
name = "P2"
link = "2"
from = "A"
along = -0.01
across = 0.004
[[points]]
name = "K3"
link = "3"
from = "O3"
along = 0.12
across = -0.01
"""

YOKE = """
[frame]
link = "0"
points = { O = [0.0, 0.0] }
""" + CRANK + """
[[dyads]]                # Scotch yoke with an inclined slot on an inclined frame guide
kind = "RPP"
links = ["2", "3"]
joints = ["A", "D"]
guide = { link = "0", through = [0.01, -0.02], angle = 10 }
slot_angle = 70
[[points]]
name = "P2"
link = "2"
from = "A"
along = 0.02
across = 0.01
[[points]]
name = "K3"
link = "3"
from = "D"
along = 0.1
across = 0.03
"""

TANGENT = """
[frame]
link = "0"
points = { O = [0.0, 0.0] }
""" + CRANK + """
[[points]]
name = "T1"
link = "1"
from = "O"
along = 0.04
across = 0.01
[[dyads]]                # tangent mechanism: guide 1 on the turning crank, guide 2 on the frame
kind = "PRP"
links = ["2", "3"]
joints = ["P"]
guides = [
  { link = "1", through = "T1", angle = 0 },
  { link = "0", through = [0.0, 0.12], angle = 0 },
]
[[points]]
name = "M2"
link = "2"
from = "P"
along = 0.02
across = 0.01
[[points]]
name = "N3"
link = "3"
from = "P"
along = -0.03
across = 0.02
"""

FOURBAR = """
[frame]
link = "0"
points = { O = [0.0, 0.0], C = [0.30, 0.05], F = [0.10, 0.45] }
""" + CRANK + """
[[dyads]]                # Grashof crank–rocker (0.08 + 0.304 < 0.25 + 0.20)
kind = "RRR"
links = ["2", "3"]
joints = ["A", "B", "C"]
lengths = [0.25, 0.20]
branch = "{b1}"
[[points]]
name = "E"
link = "2"
from = "A"
toward = "B"
fraction = 0.4
across = 0.03
[[points]]
name = "K"
link = "3"
from = "C"
along = 0.1
across = -0.02
"""

# second dyads hung on the four-bar (guides or pivots on moving links)
TAILS = {
    "RRP slider on a guide carried by the rocker 3": """
[[dyads]]
kind = "RRP"
links = ["4", "5"]
joints = ["E", "G"]
length = 0.22
guide = { link = "3", through = "C", toward = "B" }
branch = "{b2}"
[[points]]
name = "M4"
link = "4"
from = "E"
toward = "G"
fraction = 0.5
across = 0.02
[[points]]
name = "N5"
link = "5"
from = "G"
along = 0.05
across = 0.03
""",
    "PRP, guide 1 on the rocker 3, guide 2 on the frame": """
[[dyads]]
kind = "PRP"
links = ["4", "5"]
joints = ["P"]
guides = [
  { link = "3", through = "C", toward = "B" },
  { link = "0", through = [0.0, 0.25], angle = 0 },
]
[[points]]
name = "M4"
link = "4"
from = "P"
along = 0.04
across = 0.01
[[points]]
name = "N5"
link = "5"
from = "P"
along = -0.03
across = 0.02
""",
    "PRP, guide 1 on the coupler 2 (at an angle), guide 2 on the frame": """
[[dyads]]
kind = "PRP"
links = ["4", "5"]
joints = ["P"]
guides = [ { link = "2", through = "E", angle = 100 }, { link = "0", through = "F", angle = 10 } ]
[[points]]
name = "M4"
link = "4"
from = "P"
along = 0.04
across = 0.01
[[points]]
name = "N5"
link = "5"
from = "P"
along = -0.03
across = 0.02
""",
    "six-bar: RRR hung on the coupler point E and the frame point F": """
[[dyads]]
kind = "RRR"
links = ["4", "5"]
joints = ["E", "G", "F"]
lengths = [0.32, 0.26]
branch = "{b2}"
[[points]]
name = "N5"
link = "5"
from = "F"
toward = "G"
fraction = 1.3
across = -0.01
""",
    "RPP whose yoke slides on a guide carried by the rocker 3": """
[[dyads]]
kind = "RPP"
links = ["4", "5"]
joints = ["E", "D"]
guide = { link = "3", through = "K", angle = 15 }
slot_angle = 80
[[points]]
name = "M4"
link = "4"
from = "E"
along = 0.03
across = 0.01
[[points]]
name = "N5"
link = "5"
from = "D"
along = 0.05
across = -0.02
""",
    "RPR whose slotted link is pivoted on the rocker point K": """
[[dyads]]
kind = "RPR"
links = ["4", "5"]
joints = ["E", "K"]
offset = 0.01
branch = "{b2}"
[[points]]
name = "M4"
link = "4"
from = "E"
along = 0.03
across = 0.01
[[points]]
name = "N5"
link = "5"
from = "K"
along = 0.1
across = 0.02
""",
}


@dataclass(frozen=True)
class Case:
    id: str
    toml: str
    r: float  # crank length, m
    rpm: float
    direction: str
    phi_range: tuple[float, float]  # degrees, the sweep (a full turn unless limited)

    @property
    def omega(self) -> float:
        return omega1(self.rpm, self.direction)


FULL = (0.0, 360.0)


def _cases() -> list[Case]:
    out: list[Case] = []

    def add(label, template, r, rpm, *, b1=None, b2=None, phi_range=FULL):
        for direction in ("ccw", "cw"):
            text = (template.replace("{r}", repr(r)).replace("{rpm}", repr(rpm))
                    .replace("{dir}", direction))
            tag = [label, direction]
            if b1 is not None:
                text = text.replace("{b1}", b1)
                tag.append(f"b1{b1}")
            if b2 is not None:
                text = text.replace("{b2}", b2)
                tag.append(f"b2{b2}")
            out.append(Case(" ".join(tag), text, r, rpm, direction, phi_range))

    for b in "+-":
        add("RRR four-bar", FOURBAR, 0.08, 60.0, b1=b)
        add("RRP slider, frame guide", SLIDER, 0.06, 150.0, b1=b)
        add("RPR oscillating slotted link", SLOTTED, 0.06, 90.0, b1=b)
        add("RPR rotating slotted link", WHITWORTH, 0.06, 45.0, b1=b)
    add("RPP Scotch yoke", YOKE, 0.05, 120.0)
    add("PRP tangent mechanism", TANGENT, 0.08, 30.0, phi_range=(25.0, 155.0))
    for name, tail in TAILS.items():
        has_b2 = "{b2}" in tail
        for b1, b2 in itertools.product("+-", "+-" if has_b2 else [None]):
            add(f"four-bar + {name}", FOURBAR + tail, 0.08, 60.0, b1=b1, b2=b2)
    return out


CASES = _cases()
IDS = [c.id for c in CASES]


def sweep_phi(case: Case, n: int) -> np.ndarray:
    lo, hi = case.phi_range
    if (lo, hi) == FULL:
        return np.radians(np.linspace(0.0, 360.0, n, endpoint=False) + 0.3)
    return np.radians(np.linspace(lo, hi, n))


@pytest.fixture(scope="module")
def swept():
    """``swept(case_id)`` → the mechanism, its solutions at φ and φ ± ω1·dt, and dt: each
    case solved once for this module."""
    made: dict[str, tuple] = {}

    def get(case_id: str) -> tuple:
        if case_id not in made:
            case = CASES[IDS.index(case_id)]
            m = g.loads(case.toml, source=f"{case.id}.toml")
            made[case_id] = (m, *fd_solutions(m, case.omega, sweep_phi(case, 48)))
        return made[case_id]

    return get


def fd_solutions(m, w, phi):
    """Solutions at t and t ± dt, with φ(t ± dt) = φ ± ω1·dt, dt = H_PHI/|ω1|."""
    dt = H_PHI / abs(w)
    return g.solve(m, phi), g.solve(m, phi + w * dt), g.solve(m, phi - w * dt), dt


def sliding_pairs(m):
    """(key "j/k", slider point X fixed on link j, carrier link k) of every sliding pair.

    RRP: slider j at B on the guide of k; RPR: block i at A in the slot of j;
    PRP: i and j at B on their guides; RPP: yoke j at D on the guide of k, block i at A
    in the slot of j.
    """
    out = []
    for d in m.dyads:
        i, j = d.links
        if d.kind == "RRP":
            out.append((f"{j}/{d.guides[0].link}", d.joints[1], d.guides[0].link))
        elif d.kind == "RPR":
            out.append((f"{i}/{j}", d.joints[0], j))
        elif d.kind == "PRP":
            out.append((f"{i}/{d.guides[0].link}", d.joints[0], d.guides[0].link))
            out.append((f"{j}/{d.guides[1].link}", d.joints[0], d.guides[1].link))
        elif d.kind == "RPP":
            out.append((f"{j}/{d.guides[0].link}", d.joints[1], d.guides[0].link))
            out.append((f"{i}/{j}", d.joints[0], j))
    return out


def carrier_point(m, k, carrier):
    """A point fixed on the carrier link (the origin for the frame), its v and a."""
    if carrier == m.frame_link:
        z = np.zeros_like(k.pos.points[m.crank.pin])
        return z, z, z
    q = m.points_of(carrier)[0]
    return k.pos.points[q], k.vel.points[q], k.acc.points[q]


def sliding_coordinate(m, k, key, x, carrier):
    """s = (X − Q)·u: X on the slider, Q fixed on the carrier, u the guide direction.

    Since Q and u are fixed in the carrier, ds/dt is the velocity of X relative to the
    carrier (a straight line in it) and d²s/dt² its relative acceleration.
    """
    Q = carrier_point(m, k, carrier)[0]
    u = k.pos.guides[key][1]
    return dot(k.pos.points[x] - Q, u)


# --------------------------------------------------------------------------------------
# Tests on the catalogue
# --------------------------------------------------------------------------------------

@pytest.mark.parametrize("case_id", IDS)
def test_everything_is_solved(swept, case_id):
    """Every point has a position, velocity and acceleration; every link θ, ω, ε; every
    sliding pair its speed, acceleration and Coriolis term; the crank turns at ω1."""
    case = CASES[IDS.index(case_id)]
    m, k, _, _, _ = swept(case_id)
    names = set(k.pos.points)
    for link in (m.frame_link, *m.moving_links):
        assert set(m.points_of(link)) <= names
    assert set(k.vel.points) == names
    assert set(k.acc.points) == names
    links = {m.frame_link, *m.moving_links}
    assert set(k.pos.theta) == set(k.vel.omega) == set(k.acc.epsilon) == links
    keys = {key for key, _, _ in sliding_pairs(m)}
    assert set(k.pos.guides) == set(k.vel.sliding) == set(k.acc.sliding) == keys
    assert set(k.acc.coriolis) == keys
    w = case.omega
    assert m.crank.omega == pytest.approx(w, rel=1e-15)
    assert np.all(k.vel.omega[m.crank.link] == pytest.approx(w, rel=1e-15))
    assert np.all(k.acc.epsilon[m.crank.link] == 0.0)
    for q in m.points_of(m.frame_link):
        assert np.all(k.vel.points[q] == 0.0) and np.all(k.acc.points[q] == 0.0)


@pytest.mark.parametrize("case_id", IDS)
def test_velocity_is_time_derivative_of_position(swept, case_id):
    case = CASES[IDS.index(case_id)]
    m, k, kp, km, dt = swept(case_id)
    r, w = case.r, abs(case.omega)
    for p in k.pos.points:
        fd = (kp.pos.points[p] - km.pos.points[p]) / (2 * dt)
        close(k.vel.points[p], fd, r * w, f"v_{p}", FD_REL)
    for link in k.pos.theta:
        fd = wrap(kp.pos.theta[link] - km.pos.theta[link]) / (2 * dt)
        close(k.vel.omega[link], fd, w, f"ω{link}", FD_REL)
    for key, x, carrier in sliding_pairs(m):
        fd = (sliding_coordinate(m, kp, key, x, carrier)
              - sliding_coordinate(m, km, key, x, carrier)) / (2 * dt)
        close(k.vel.sliding[key], fd, r * w, f"sliding speed {key}", FD_REL)


@pytest.mark.parametrize("case_id", IDS)
def test_acceleration_is_time_derivative_of_velocity(swept, case_id):
    case = CASES[IDS.index(case_id)]
    m, k, kp, km, dt = swept(case_id)
    r, w = case.r, abs(case.omega)
    for p in k.pos.points:
        fd = (kp.vel.points[p] - km.vel.points[p]) / (2 * dt)
        close(k.acc.points[p], fd, r * w**2, f"a_{p}", FD_REL)
    for link in k.vel.omega:
        fd = (kp.vel.omega[link] - km.vel.omega[link]) / (2 * dt)
        close(k.acc.epsilon[link], fd, w**2, f"ε{link}", FD_REL)
    for key, _, _ in sliding_pairs(m):
        fd = (kp.vel.sliding[key] - km.vel.sliding[key]) / (2 * dt)
        close(k.acc.sliding[key], fd, r * w**2, f"sliding acceleration {key}", FD_REL)


def _check_lengths(m, k, r):
    for link in (m.frame_link, *m.moving_links):
        pts = m.points_of(link)
        for p, q in itertools.combinations(pts, 2):
            dist = np.hypot(*(k.pos.points[p] - k.pos.points[q]).T)
            close(dist, dist[0], r, f"|{p}{q}| on link {link}", EXACT_REL)
    # the lengths given in the variant
    cr = m.crank
    close(np.hypot(*(k.pos.points[cr.pin] - k.pos.points[cr.pivot]).T), cr.length, r,
          "crank length", EXACT_REL)
    for d in m.dyads:
        if d.kind == "RRR":
            a, b, c = d.joints
            close(np.hypot(*(k.pos.points[b] - k.pos.points[a]).T), d.lengths[0], r,
                  f"l_{a}{b}", EXACT_REL)
            close(np.hypot(*(k.pos.points[b] - k.pos.points[c]).T), d.lengths[1], r,
                  f"l_{c}{b}", EXACT_REL)
        elif d.kind == "RRP":
            a, b = d.joints
            close(np.hypot(*(k.pos.points[b] - k.pos.points[a]).T), d.lengths[0], r,
                  f"l_{a}{b}", EXACT_REL)


@pytest.mark.parametrize("case_id", IDS)
def test_link_lengths_stay_constant(case_id):
    case = CASES[IDS.index(case_id)]
    m = g.loads(case.toml)
    k = g.solve(m, sweep_phi(case, 721))
    _check_lengths(m, k, case.r)


def _check_rigid(m, k, r, w):
    for link in m.moving_links:
        om, ep = k.vel.omega[link], k.acc.epsilon[link]
        for p, q in itertools.combinations(m.points_of(link), 2):
            d = k.pos.points[p] - k.pos.points[q]
            close(k.vel.points[p] - k.vel.points[q], om[:, None] * turned(d), r * w,
                  f"v_{p} − v_{q} = ω{link} k×{q}{p}", EXACT_REL)
            close(k.acc.points[p] - k.acc.points[q],
                  ep[:, None] * turned(d) - (om**2)[:, None] * d, r * w**2,
                  f"a_{p} − a_{q} = ε{link} k×{q}{p} − ω{link}²·{q}{p}", EXACT_REL)


@pytest.mark.parametrize("case_id", IDS)
def test_rigid_body_velocity_and_acceleration(swept, case_id):
    case = CASES[IDS.index(case_id)]
    m, k, _, _, _ = swept(case_id)
    _check_rigid(m, k, case.r, abs(case.omega))


def _branch_sign(d, k):
    """The sign that the variant's branch fixes, per dyad kind (None: no branch).

    RRR: B to the left (+) or right (−) of A→C, sign of (C − A)×(B − A);
    RRP: B ahead of (+) or behind (−) the foot of A along the guide, sign of (B − A)·u;
    RPR: A ahead of (+) or behind (−) the pivot C along the slot, sign of (A − C)·u.
    """
    P = k.pos.points
    if d.kind == "RRR":
        a, b, c = d.joints
        return np.sign(cross(P[c] - P[a], P[b] - P[a]))
    if d.kind == "RRP":
        a, b = d.joints
        return np.sign(dot(P[b] - P[a], k.pos.guides[f"{d.links[1]}/{d.guides[0].link}"][1]))
    if d.kind == "RPR":
        a, c = d.joints
        return np.sign(dot(P[a] - P[c], k.pos.guides[f"{d.links[0]}/{d.links[1]}"][1]))
    return None


@pytest.mark.parametrize("case_id", IDS)
def test_branch_holds_and_motion_is_continuous(case_id):
    """On a fine grid (0.1° steps) the branch sign never changes and no point or link
    angle jumps: a step is at most 2.5·max(|v_k|, |v_k+1|)·Δt (≥ |v|Δt + |a|Δt²/2 for a
    smooth motion, since |v_k+1 − v_k| ≈ |a|Δt), plus round-off."""
    case = CASES[IDS.index(case_id)]
    m = g.loads(case.toml)
    lo, hi = case.phi_range
    phi = np.radians(np.arange(lo, hi + 1e-9, 0.1) + (0.05 if (lo, hi) == FULL else 0.0))
    if (lo, hi) == FULL:
        phi = np.append(phi, phi[0] + 2 * math.pi)  # close the turn
    k = g.solve(m, phi)
    dt = np.radians(0.1) / abs(case.omega)
    for d in m.dyads:
        sgn = _branch_sign(d, k)
        if sgn is not None:
            assert np.all(sgn == d.branch), f"{d.name}: branch {d.branch:+d} not held"
    for p in k.pos.points:
        step = np.hypot(*np.diff(k.pos.points[p], axis=0).T)
        speed = np.hypot(*k.vel.points[p].T)
        bound = 2.5 * np.maximum(speed[:-1], speed[1:]) * dt + 1e-12
        at = np.degrees(phi[np.argmax(step - bound)])
        assert np.all(step <= bound), f"{p} jumps at φ = {at:.1f}°"
    for link in k.pos.theta:
        step = np.abs(wrap(np.diff(k.pos.theta[link])))
        rate = np.abs(k.vel.omega[link])
        bound = 2.5 * np.maximum(rate[:-1], rate[1:]) * dt + 1e-12
        assert np.all(step <= bound), f"θ{link} jumps"
    # a full turn of the crank brings every point back (the assembly does not drift)
    if (lo, hi) == FULL:
        for p in k.pos.points:
            assert np.allclose(k.pos.points[p][-1], k.pos.points[p][0], rtol=0, atol=1e-12)


@pytest.mark.parametrize("case_id", IDS)
def test_sliding_pairs(swept, case_id):
    """For each slider X of link j on a guide (unit u) of link k, with Q fixed on k:

    * v_X = v_Q + ω_k k×(X − Q) + v_r u                       (composition of velocities)
    * a_X = a_Q + ε_k k×(X − Q) − ω_k²(X − Q) + a_c + a_r u,
      a_c = 2 ω_k k×(v_r u)                                    (… of accelerations)
    * the guide turns with its carrier: angle(u) − θ_k is constant;
    * X stays on the guide line: its distance from the line through Q along u is constant
      and X lies on the line (G, u) that graphplan reports;
    * the slider turns with the carrier (ω_j = ω_k, ε_j = ε_k);
    * on a frame guide: v_r = v_X·u, a_r = a_X·u, no Coriolis term.
    """
    case = CASES[IDS.index(case_id)]
    m, k, _, _, _ = swept(case_id)
    r, w = case.r, abs(case.omega)
    for key, x, carrier in sliding_pairs(m):
        slider = key.split("/")[0]
        G, u = k.pos.guides[key]
        X, vX, aX = k.pos.points[x], k.vel.points[x], k.acc.points[x]
        Q, vQ, aQ = carrier_point(m, k, carrier)
        om, ep = k.vel.omega[carrier], k.acc.epsilon[carrier]
        vr, ar = k.vel.sliding[key], k.acc.sliding[key]
        d = X - Q
        close(np.hypot(*u.T), 1.0, 1.0, f"|u| of {key}", EXACT_REL)
        close(vX, vQ + om[:, None] * turned(d) + vr[:, None] * u, r * w,
              f"velocity composition {key}", EXACT_REL)
        cor = 2 * (om * vr)[:, None] * turned(u)
        close(k.acc.coriolis[key], cor, r * w**2, f"Coriolis {key}", EXACT_REL)
        close(aX, aQ + ep[:, None] * turned(d) - (om**2)[:, None] * d + cor + ar[:, None] * u,
              r * w**2, f"acceleration composition {key}", EXACT_REL)
        rel_angle = wrap(np.arctan2(u[:, 1], u[:, 0]) - k.pos.theta[carrier])
        close(wrap(rel_angle - rel_angle[0]), 0.0, 1.0, f"guide {key} fixed on {carrier}",
              EXACT_REL)
        h = cross(u, d)
        close(h, h[0], r, f"{x} keeps its distance to the guide {key}", EXACT_REL)
        close(cross(u, X - G), 0.0, r, f"{x} on the guide line {key}", EXACT_REL)
        close(k.vel.omega[slider], om, w, f"ω{slider} = ω{carrier}", EXACT_REL)
        close(k.acc.epsilon[slider], ep, w**2, f"ε{slider} = ε{carrier}", EXACT_REL)
        if carrier == m.frame_link:
            close(vr, dot(vX, u), r * w, f"{key}: v_r = v_{x}·u", EXACT_REL)
            close(ar, dot(aX, u), r * w**2, f"{key}: a_r = a_{x}·u", EXACT_REL)
            close(k.acc.coriolis[key], 0.0, r * w**2, f"{key}: no Coriolis", EXACT_REL)


def test_catalogue_covers_every_kind_branch_and_moving_guides():
    """Bookkeeping: the catalogue has what the tests above claim to cover."""
    seen = set()
    moving = set()
    for case in CASES:
        m = g.loads(case.toml)
        for d in m.dyads:
            seen.add((d.kind, d.branch, case.direction))
            for gd in d.guides:
                if gd.link != m.frame_link:
                    moving.add(d.kind)
        for d in m.dyads:
            if d.kind in ("RPR", "RRR") and m.home_link(d.joints[-1]) != m.frame_link:
                moving.add(d.kind + " on a moving pivot")
    for kind in ("RRR", "RRP", "RPR"):
        for b in (1, -1):
            for direction in ("ccw", "cw"):
                assert (kind, b, direction) in seen
    for kind in ("PRP", "RPP"):
        for direction in ("ccw", "cw"):
            assert (kind, 1, direction) in seen
    assert {"RRP", "PRP", "RPP", "RPR on a moving pivot"} <= moving


# --------------------------------------------------------------------------------------
# Randomised mechanisms (hypothesis)
# --------------------------------------------------------------------------------------

RANDOM_PHI = np.radians(np.linspace(0.0, 360.0, 24, endpoint=False) + 1.7)


def _check_all(m, w, r, phi=RANDOM_PHI):
    k, kp, km, dt = fd_solutions(m, w, phi)
    aw = abs(w)
    for p in k.pos.points:
        close(k.vel.points[p], (kp.pos.points[p] - km.pos.points[p]) / (2 * dt), r * aw,
              f"v_{p}", FD_REL)
        close(k.acc.points[p], (kp.vel.points[p] - km.vel.points[p]) / (2 * dt), r * w**2,
              f"a_{p}", FD_REL)
    for link in k.pos.theta:
        close(k.vel.omega[link], wrap(kp.pos.theta[link] - km.pos.theta[link]) / (2 * dt),
              aw, f"ω{link}", FD_REL)
        close(k.acc.epsilon[link], (kp.vel.omega[link] - km.vel.omega[link]) / (2 * dt),
              w**2, f"ε{link}", FD_REL)
    for key, x, carrier in sliding_pairs(m):
        s_p = sliding_coordinate(m, kp, key, x, carrier)
        s_m = sliding_coordinate(m, km, key, x, carrier)
        close(k.vel.sliding[key], (s_p - s_m) / (2 * dt), r * aw, f"v_r {key}", FD_REL)
        close(k.acc.sliding[key], (kp.vel.sliding[key] - km.vel.sliding[key]) / (2 * dt),
              r * w**2, f"a_r {key}", FD_REL)
    _check_lengths(m, k, r)
    _check_rigid(m, k, r, aw)
    for d in m.dyads:
        sgn = _branch_sign(d, k)
        if sgn is not None:
            assert np.all(sgn == d.branch)


@settings(deadline=None, max_examples=30)
@given(
    b=st.floats(0.5, 1.5),
    c=st.floats(0.5, 1.5),
    d=st.floats(0.5, 1.5),
    frac=st.floats(0.05, 0.8),
    scale=st.floats(0.05, 1.0),
    gamma=st.floats(-180.0, 180.0),
    fraction=st.floats(-0.5, 1.5),
    across=st.floats(-0.5, 0.5),
    branch=st.sampled_from("+-"),
    direction=st.sampled_from(["ccw", "cw"]),
    rpm=st.floats(10.0, 600.0),
)
def test_random_grashof_crank_rocker(b, c, d, frac, scale, gamma, fraction, across, branch,
                                     direction, rpm):
    """Random Grashof crank–rockers (a < p + q − L, so a + L < p + q: the crank turns
    fully and never locks), with a random coupler point."""
    slack = b + c + d - 2 * max(b, c, d)
    assume(slack > 0.1)
    a = frac * slack
    a, b, c, d = (x * scale for x in (a, b, c, d))
    gm = math.radians(gamma)
    text = f"""
[frame]
link = "4"
points = {{ O = [0.0, 0.0], C = [{d * math.cos(gm)!r}, {d * math.sin(gm)!r}] }}
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
[[points]]
name = "S2"
link = "2"
from = "A"
toward = "B"
fraction = {fraction!r}
across = {across * b!r}
[[points]]
name = "S3"
link = "3"
from = "C"
along = {0.5 * c!r}
across = {0.1 * c!r}
"""
    m = g.loads(text, source="random-four-bar.toml")
    _check_all(m, omega1(rpm, direction), a)


@settings(deadline=None, max_examples=30)
@given(
    r=st.floats(0.01, 0.2),
    lam=st.floats(0.08, 0.45),
    e_frac=st.floats(-0.6, 0.6),
    gx=st.floats(-1.0, 1.0),
    alpha=st.floats(-180.0, 180.0),
    branch=st.sampled_from("+-"),
    direction=st.sampled_from(["ccw", "cw"]),
    rpm=st.floats(10.0, 1500.0),
)
def test_random_offset_crank_slider(r, lam, e_frac, gx, alpha, branch, direction, rpm):
    """Random crank–sliders on a frame guide at angle α with offset e, |e| ≤ 0.6(l − r)
    (the rod never stands perpendicular to the guide). The guide is given through a
    point shifted along it by gx·l (the same line)."""
    l = r / lam
    e = e_frac * (l - r)
    al = math.radians(alpha)
    px = -e * math.sin(al) + gx * l * math.cos(al)
    py = e * math.cos(al) + gx * l * math.sin(al)
    text = f"""
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
guide = {{ link = "4", through = [{px!r}, {py!r}], angle = {alpha!r} }}
branch = "{branch}"
[[points]]
name = "S2"
link = "2"
from = "A"
toward = "B"
fraction = 0.35
[[points]]
name = "S3"
link = "3"
from = "B"
along = {0.2 * r!r}
across = {0.1 * r!r}
"""
    m = g.loads(text, source="random-slider.toml")
    w = omega1(rpm, direction)
    _check_all(m, w, r)
    k = g.solve(m, RANDOM_PHI)
    u = np.array([math.cos(al), math.sin(al)])
    close(k.vel.sliding["3/4"], k.vel.points["B"] @ u, r * abs(w), "v_r = v_B·u", EXACT_REL)
    close(k.acc.sliding["3/4"], k.acc.points["B"] @ u, r * w**2, "a_r = a_B·u", EXACT_REL)


@settings(deadline=None, max_examples=25)
@given(
    r=st.floats(0.02, 0.2),
    dist=st.floats(0.2, 3.0),
    beta=st.floats(-180.0, 180.0),
    e_frac=st.floats(-0.8, 0.8),
    branch=st.sampled_from("+-"),
    direction=st.sampled_from(["ccw", "cw"]),
    rpm=st.floats(10.0, 600.0),
)
def test_random_slotted_link(r, dist, beta, e_frac, branch, direction, rpm):
    """Random slotted links (RPR), oscillating (|OO3| > r) or rotating (|OO3| < r), with a
    slot offset |e| < min |O3A| = | |OO3| − r | (so the block never reaches the pivot's
    foot)."""
    d = dist * r
    assume(abs(d - r) > 0.15 * r)
    e = e_frac * abs(d - r)
    bt = math.radians(beta)
    text = f"""
[frame]
link = "4"
points = {{ O = [0.0, 0.0], O3 = [{d * math.cos(bt)!r}, {d * math.sin(bt)!r}] }}
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
offset = {e!r}
branch = "{branch}"
[[points]]
name = "P2"
link = "2"
from = "A"
along = {0.1 * r!r}
across = {0.05 * r!r}
[[points]]
name = "K3"
link = "3"
from = "O3"
along = {2 * r!r}
across = {0.3 * r!r}
"""
    m = g.loads(text, source="random-slotted.toml")
    _check_all(m, omega1(rpm, direction), r)
