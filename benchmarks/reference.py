"""The 50-digit reference: positions, velocities, accelerations, reactions and Mур.

An independent route to every figure the benchmark checks, evaluated with mpmath:

* **positions** — the closed forms of each dyad (circle ∩ circle, circle ∩ line, the
  slot through the pivot), evaluated at 130 digits;
* **velocities, accelerations** — not graphplan's vector equations but the derivatives
  of the positions with respect to the crank angle, by central differences at 130
  digits with a step of 1e-35 rad (truncation ~1e-70, round-off ~1e-60): ``v = ω1·dP/dφ``,
  ``a = ω1²·d²P/dφ²`` (ω1 is constant);
* **reactions and Mур** — not graphplan's group-by-group solution but one linear system
  of the whole mechanism: ``ΣF = 0`` and ``ΣM = 0`` of every moving link with every
  pair's reaction and the balancing moment as unknowns, solved by LU at 50 digits;
* **loads** — weights, d'Alembert inertia forces and couples from the reference
  accelerations, and the technological resistance from the variant's diagram, with the
  dead centres found again (roots of dq/dφ, refined by mpmath.findroot).

Conventions are graphplan's (SI, x right, y up, CCW positive, ``R_ij`` the force of
link i on link j). The model's inputs are the float64 dimensions of the loaded
variant, converted exactly, so the reference is the exact answer to the same question.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import pairwise

import mpmath as mp

DIGITS = 50
"""Digits of the reference values."""
WORK_DIGITS = 130
"""Working digits of the positions and their differences."""
STEP = mp.mpf("1e-35")
"""Step of the central differences (rad)."""

Vec = tuple  # (mpf, mpf)


def _v(x, y) -> Vec:
    return (mp.mpf(x), mp.mpf(y))


def _add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def _mul(a, s):
    return (a[0] * s, a[1] * s)


def _perp(a):
    return (-a[1], a[0])


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def _norm(a):
    return mp.sqrt(a[0] ** 2 + a[1] ** 2)


def _unit_angle(t):
    return (mp.cos(t), mp.sin(t))


@dataclass(frozen=True)
class Pose:
    """Positions at one crank angle: points, link angles, guides (point, unit direction)."""

    points: dict
    theta: dict
    guides: dict


def _guide(g, pts, theta):
    base = pts[g.through] if g.through is not None else _v(*g.xy)
    if g.toward is not None:
        d = _sub(pts[g.toward], base)
        u = _mul(d, 1 / _norm(d))
    else:
        u = _unit_angle(theta[g.link] + mp.mpf(g.angle))
    return base, u


def _place_points(mech, pts, theta):
    for p in mech.points:
        if p.name in pts or p.link not in theta or p.origin not in pts:
            continue
        if p.toward is not None and p.toward not in pts:
            continue
        o = pts[p.origin]
        if p.toward is not None:
            d = _sub(pts[p.toward], o)
            dist = _norm(d)
            u = _mul(d, 1 / dist)
            along = mp.mpf(p.fraction) * dist if p.fraction is not None else mp.mpf(p.along)
        else:
            u = _unit_angle(theta[p.link])
            along = mp.mpf(p.along)
        pts[p.name] = _add(_add(o, _mul(u, along)), _mul(_perp(u), mp.mpf(p.across)))


def pose(mech, phi) -> Pose:
    """Assemble the mechanism at the crank angle ``phi`` (mpf, rad), at the working precision."""
    pts = {n: _v(*xy) for n, xy in mech.frame_points.items()}
    theta = {mech.frame_link: mp.mpf(0)}
    guides = {}
    cr = mech.crank
    pts[cr.pin] = _add(pts[cr.pivot], _mul(_unit_angle(phi), mp.mpf(cr.length)))
    theta[cr.link] = phi
    _place_points(mech, pts, theta)
    for d in mech.dyads:
        i, j = d.links
        s = d.branch
        if d.kind == "RRR":
            a, b, c = d.joints
            A, C = pts[a], pts[c]
            l1, l2 = (mp.mpf(x) for x in d.lengths)
            e = _sub(C, A)
            dist = _norm(e)
            e = _mul(e, 1 / dist)
            along = (l1**2 - l2**2 + dist**2) / (2 * dist)
            B = _add(_add(A, _mul(e, along)), _mul(_perp(e), s * mp.sqrt(l1**2 - along**2)))
            pts[b] = B
            theta[i] = mp.atan2(*reversed(_sub(B, A)))
            theta[j] = mp.atan2(*reversed(_sub(B, C)))
        elif d.kind == "RRP":
            a, b = d.joints
            A = pts[a]
            (l1,) = (mp.mpf(x) for x in d.lengths)
            G, u = _guide(d.guides[0], pts, theta)
            w = _sub(A, G)
            h = _cross(u, w)
            B = _add(G, _mul(u, _dot(w, u) + s * mp.sqrt(l1**2 - h**2)))
            pts[b] = B
            theta[i] = mp.atan2(*reversed(_sub(B, A)))
            theta[j] = mp.atan2(u[1], u[0])
            guides[f"{j}/{d.guides[0].link}"] = (G, u)
        elif d.kind == "RPR":
            a, c = d.joints
            A, C = pts[a], pts[c]
            e = mp.mpf(d.offset)
            dv = _sub(A, C)
            along = s * mp.sqrt(_dot(dv, dv) - e**2)
            th = mp.atan2(dv[1], dv[0]) - mp.atan2(e, along)
            theta[i] = theta[j] = th
            u = _unit_angle(th)
            guides[f"{i}/{j}"] = (_add(C, _mul(_perp(u), e)), u)
        else:
            raise NotImplementedError(f"reference: dyad kind {d.kind}")
        _place_points(mech, pts, theta)
    return Pose(pts, theta, guides)


def _wrap(d):
    """An angle difference wrapped into (−π, π]."""
    while d > mp.pi:
        d -= 2 * mp.pi
    while d <= -mp.pi:
        d += 2 * mp.pi
    return d


@dataclass(frozen=True)
class State:
    """Reference kinematics at one crank angle (mpf at DIGITS)."""

    phi: object
    points: dict
    velocities: dict
    accelerations: dict
    theta: dict
    omega: dict
    epsilon: dict
    guides: dict


def state(mech, phi) -> State:
    """Positions and their first two time derivatives at the crank angle ``phi`` (float)."""
    w1 = mp.mpf(mech.crank.omega)
    with mp.workdps(WORK_DIGITS):
        x = mp.mpf(phi)
        p0, pp, pm = pose(mech, x), pose(mech, x + STEP), pose(mech, x - STEP)
        v, a, om, ep = {}, {}, {}, {}
        for n, P in p0.points.items():
            v[n] = tuple((pp.points[n][c] - pm.points[n][c]) / (2 * STEP) * w1 for c in (0, 1))
            a[n] = tuple((pp.points[n][c] - 2 * P[c] + pm.points[n][c]) / STEP**2 * w1**2
                         for c in (0, 1))
        for ln, t in p0.theta.items():
            dp, dm = _wrap(pp.theta[ln] - t), _wrap(pm.theta[ln] - t)
            om[ln] = (dp - dm) / (2 * STEP) * w1
            ep[ln] = (dp + dm) / STEP**2 * w1**2
    with mp.workdps(DIGITS):
        def r(z):
            return +z
        return State(mp.mpf(phi), {n: tuple(map(r, P)) for n, P in p0.points.items()},
                     {n: tuple(map(r, P)) for n, P in v.items()},
                     {n: tuple(map(r, P)) for n, P in a.items()},
                     {n: r(t) for n, t in p0.theta.items()}, {n: r(t) for n, t in om.items()},
                     {n: r(t) for n, t in ep.items()}, p0.guides)


# ---------------------------------------------------------------- the cycle and the load


def _output(mech):
    """(kind, point or link, guide key) of the output coordinate, as graphplan defines it."""
    out = mech.output.link
    for d in mech.dyads:
        if out not in d.links:
            continue
        for g in d.guides:
            if d.kind in ("RRP", "RPP") and d.links[1] == out and g.link == mech.frame_link:
                point = d.new_points[0] if d.new_points else d.joints[0]
                return "slider", point, f"{out}/{mech.frame_link}"
        return "rocker", out, None
    return "rocker", out, None


def output_q(mech, ps: Pose):
    kind, what, key = _output(mech)
    if kind == "slider":
        G, u = ps.guides[key]
        return _dot(_sub(ps.points[what], G), u)
    return ps.theta[what]


@dataclass(frozen=True)
class RefCycle:
    dead_centres: tuple
    q_start: object
    q_end: object
    working_turn: object
    sense: int


def cycle(mech, guess: tuple[float, float]) -> RefCycle:
    """Dead centres refined at 50 digits from graphplan's (``guess``, rad)."""
    sense = 1 if mech.crank.omega > 0 else -1
    with mp.workdps(WORK_DIGITS):
        def rate(x):
            return (output_q(mech, pose(mech, x + STEP)) - output_q(mech, pose(mech, x - STEP))) \
                / (2 * STEP)

        roots = [mp.findroot(rate, mp.mpf(g), tol=mp.mpf(10) ** (-2 * DIGITS)) for g in guess]
        q = [output_q(mech, pose(mech, x)) for x in roots]
        turn = ((roots[1] - roots[0]) * sense) % (2 * mp.pi)
    return RefCycle(tuple(roots), q[0], q[1], turn, sense)


def diagram_value(diagram, s):
    """Load fraction of a piecewise linear diagram at travel s (largest value at a jump)."""
    best = None
    for (s0, f0), (s1, f1) in pairwise(diagram):
        s0, s1, f0, f1 = map(mp.mpf, (s0, s1, f0, f1))
        if s1 == s0:
            if s == s0:
                val = max(f0, f1)
            else:
                continue
        elif s0 <= s <= s1:
            val = f0 + (f1 - f0) * (s - s0) / (s1 - s0)
        else:
            continue
        best = val if best is None else max(best, val)
    return mp.mpf(0) if best is None else max(best, mp.mpf(0))


def loads(mech, st: State, cyc: RefCycle):
    """Per moving link: forces [(vector, point)] and couples [moment], the reference loads."""
    g = _v(*mech.gravity)
    forces = {ln: [] for ln in mech.moving_links}
    couples = {ln: [] for ln in mech.moving_links}
    for ln in mech.moving_links:
        props = mech.links.get(ln)
        if props is None or props.centre is None:
            continue
        S = props.centre
        m, J = mp.mpf(props.mass), mp.mpf(props.inertia)
        if m:
            forces[ln].append((_mul(g, m), st.points[S]))
            forces[ln].append((_mul(st.accelerations[S], -m), st.points[S]))
        if J:
            couples[ln].append(-J * st.epsilon[ln])
    if mech.resistances:
        ps = Pose(st.points, st.theta, st.guides)
        q = output_q(mech, ps)
        kind, _, _ = _output(mech)
        if kind == "rocker":
            mid = (cyc.q_start + cyc.q_end) / 2
            q = q + 2 * mp.pi * mp.nint((mid - q) / (2 * mp.pi))
        s = (q - cyc.q_start) / (cyc.q_end - cyc.q_start)
        s = min(max(s, mp.mpf(0)), mp.mpf(1))
        on = ((st.phi - cyc.dead_centres[0]) * cyc.sense) % (2 * mp.pi) < cyc.working_turn
        w = mech.output.working
        for res in mech.resistances:
            size = diagram_value(res.diagram, s) * mp.mpf(res.maximum) if on else mp.mpf(0)
            if res.kind == "force":
                _, u = st.guides[f"{res.link}/{mech.frame_link}"]
                forces[res.link].append((_mul(u, -w * size), st.points[res.point]))
            else:
                couples[res.link].append(-w * size)
    return forces, couples


# ---------------------------------------------------------------- equilibrium of the whole


@dataclass(frozen=True)
class Pair:
    kind: str  # "R" | "P"
    by: str
    on: str
    point: str
    guide: str | None = None

    @property
    def name(self) -> str:
        return f"R{self.by}{self.on}" if len(self.by) == len(self.on) == 1 \
            else f"R{self.by},{self.on}"


def pairs(mech) -> list[Pair]:
    """Every kinematic pair, each as the force of ``by`` on ``on`` (graphplan's naming)."""
    home = mech.home_link
    cr = mech.crank
    out = [Pair("R", mech.frame_link, cr.link, cr.pivot)]
    for d in mech.dyads:
        i, j = d.links
        jt = d.joints
        if d.kind == "RRR":
            out += [Pair("R", home(jt[0]), i, jt[0]), Pair("R", i, j, jt[1]),
                    Pair("R", home(jt[2]), j, jt[2])]
        elif d.kind == "RRP":
            g = d.guides[0].link
            out += [Pair("R", home(jt[0]), i, jt[0]), Pair("R", i, j, jt[1]),
                    Pair("P", g, j, jt[1], f"{j}/{g}")]
        elif d.kind == "RPR":
            out += [Pair("R", home(jt[0]), i, jt[0]), Pair("P", i, j, jt[0], f"{i}/{j}"),
                    Pair("R", home(jt[1]), j, jt[1])]
        else:
            raise NotImplementedError(d.kind)
    return out


def equilibrium_system(mech, points, guides, forces, couples):
    """Rows ``A·x = b`` of ΣFx, ΣFy, ΣM_O = 0 of every moving link (plain lists).

    Unknowns: per revolute pair (R_x, R_y) of ``by`` on ``on``; per prismatic pair the
    normal force N (along n = k×u) and its couple C about the pair's point; then Mур.
    Works on any number type (mpf, float).
    """
    links = list(mech.moving_links)
    prs = pairs(mech)
    n = 2 * len(prs) + 1
    rows = {ln: [[0] * n for _ in range(3)] for ln in links}
    rhs = {ln: [0, 0, 0] for ln in links}
    o = points[mech.crank.pivot]
    for k, p in enumerate(prs):
        r = _sub(points[p.point], o)
        for ln, sgn in ((p.on, 1), (p.by, -1)):
            if ln not in rows:
                continue
            R = rows[ln]
            if p.kind == "R":
                R[0][2 * k] += sgn
                R[1][2 * k + 1] += sgn
                R[2][2 * k] += -sgn * r[1]
                R[2][2 * k + 1] += sgn * r[0]
            else:
                nv = _perp(guides[p.guide][1])
                R[0][2 * k] += sgn * nv[0]
                R[1][2 * k] += sgn * nv[1]
                R[2][2 * k] += sgn * _cross(r, nv)
                R[2][2 * k + 1] += sgn
    rows[mech.crank.link][2][n - 1] = 1
    for ln in links:
        for F, at in forces[ln]:
            rhs[ln][0] -= F[0]
            rhs[ln][1] -= F[1]
            rhs[ln][2] -= _cross(_sub(at, o), F)
        for M in couples[ln]:
            rhs[ln][2] -= M
    A = [row for ln in links for row in rows[ln]]
    b = [v for ln in links for v in rhs[ln]]
    return prs, A, b


def unpack(prs, x, guides):
    """Reaction vectors by name and Mур from the solution vector."""
    out = {}
    for k, p in enumerate(prs):
        if p.kind == "R":
            out[p.name] = (x[2 * k], x[2 * k + 1])
        else:
            nv = _perp(guides[p.guide][1])
            out[p.name] = (x[2 * k] * nv[0], x[2 * k] * nv[1])
    return out, x[-1]


@dataclass(frozen=True)
class Reference:
    """The reference of one mechanism at a list of crank angles (floats, as mpf at 50 digits)."""

    phi: list
    states: list
    reactions: list  # per position: name -> (Rx, Ry)
    M_bal: list


def reference(mech, phis, cyc_guess=None, forces: bool = True) -> Reference:
    """Evaluate the reference at the float crank angles ``phis``."""
    states = [state(mech, float(p)) for p in phis]
    reactions, mbal = [], []
    if forces:
        cyc = cycle(mech, cyc_guess) if mech.resistances else None
        with mp.workdps(DIGITS):
            for st in states:
                F, C = loads(mech, st, cyc)
                prs, A, b = equilibrium_system(mech, st.points, st.guides, F, C)
                x = mp.lu_solve(mp.matrix(A), mp.matrix(b))
                R, M = unpack(prs, [x[i] for i in range(len(b))], st.guides)
                reactions.append(R)
                mbal.append(M)
    return Reference(list(phis), states, reactions, mbal)


__all__ = ["DIGITS", "Reference", "State", "cycle", "equilibrium_system", "pairs",
           "reference", "state"]
