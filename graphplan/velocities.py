"""Velocities of every point and angular velocities of every link (plan of velocities).

The crank: ``v_A = ω1 × OA`` (ω1 constant, CCW positive). Each dyad then gives
one vector equation with two unknown magnitudes along two known directions,
exactly the two lines the draftsman draws on the velocity plan:

* RRR  ``v_B = v_A + ω_i·k×AB = v_C + ω_j·k×CB``                  unknowns ω_i, ω_j
* RRP  ``v_B = v_A + ω_i·k×AB = v_Bk + v_r·u``                    unknowns ω_i, v_r
* RPR  ``v_A = v_C + ω·k×CA + v_r·u``                             unknowns ω, v_r
* PRP  ``v_B = v_Bk1 + v_r1·u1 = v_Bk2 + v_r2·u2``                unknowns v_r1, v_r2
* RPP  ``v_A = v_Ak + v_s·u + v_r·w``                             unknowns v_s, v_r

where ``v_Xk = v_G + ω_k·k×GX`` is the velocity of the point of the guide's link
k that coincides with X, ``u`` (``w``) the unit direction of the guide (slot),
and ``v_r`` the sliding speed along it. Each 2×2 system is solved by Cramer's
rule over all positions at once.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .errors import SingularPoseError
from .geometry import perp, scale, sine_between, solve2
from .model import Dyad, Guide, Mechanism
from .positions import PositionState, slide_key, where

Array = NDArray[np.float64]

LOCKUP_SINE = 1e-9
"""Below this |sin| between the two lines of a dyad's equation, the pose is a lock-up."""


@dataclass(frozen=True, slots=True)
class VelocityState:
    """Solved velocities: points (m/s), ω per link (rad/s, CCW+), sliding speeds (m/s).

    ``sliding`` is keyed like :attr:`PositionState.guides` (``"j/k"``): the speed
    of link j relative to link k along the guide's direction. ``conditioning``
    gives, per dyad name, |sin| of the angle between the two lines of its vector
    equation (1 is best, 0 is a lock-up).
    """

    points: dict[str, Array]
    omega: dict[str, Array]
    sliding: dict[str, Array]
    conditioning: dict[str, Array]


def coincident_velocity(g: Guide, X: Array, pos: PositionState, v: dict, omega: dict) -> Array:
    """Velocity of the point of the guide's link that coincides with X: v_G + ω_k·k×GX."""
    n = X.shape[0]
    if g.through is None:
        return np.zeros((n, 2))
    G = pos.points[g.through]
    return v[g.through] + scale(perp(X - G), omega[g.link])


def rigid_velocity(v_base: Array, omega: Array, r: Array) -> Array:
    """``v_P = v_base + ω·k×r`` with r the vector from the base point to P."""
    return v_base + scale(perp(r), omega)


def solve_velocities(mech: Mechanism, pos: PositionState, labels=None) -> VelocityState:
    """Solve the velocity plans of all positions.

    Parameters
    ----------
    mech : Mechanism
    pos : PositionState
        From :func:`graphplan.positions.solve_positions`.
    labels : sequence of str, optional
        Position labels, used only to name a position in an error.

    Returns
    -------
    VelocityState

    Raises
    ------
    SingularPoseError
        Where a dyad's two directions are parallel (a lock-up), naming the angle.
    """
    n = pos.phi.shape[0]
    P = pos.points
    v: dict[str, Array] = {name: np.zeros((n, 2)) for name in mech.frame_points}
    omega: dict[str, Array] = {mech.frame_link: np.zeros(n)}
    sliding: dict[str, Array] = {}
    cond: dict[str, Array] = {}
    cr = mech.crank
    omega[cr.link] = np.full(n, cr.omega)
    v[cr.pin] = rigid_velocity(v[cr.pivot], omega[cr.link], P[cr.pin] - P[cr.pivot])
    _extra(mech, pos, v, omega)
    for d in mech.dyads:
        _dyad(mech, d, pos, v, omega, sliding, cond, labels)
        _extra(mech, pos, v, omega)
    return VelocityState(v, omega, sliding, cond)


def _extra(mech, pos, v, omega) -> None:
    for p in mech.points:
        if p.name not in v and p.origin in v and p.link in omega:
            v[p.name] = rigid_velocity(
                v[p.origin], omega[p.link], pos.points[p.name] - pos.points[p.origin]
            )


def check_conditioning(mech: Mechanism, d: Dyad, phi: Array, sine: Array, labels=None) -> None:
    """Raise :class:`SingularPoseError` where a dyad's equation lines are parallel."""
    bad = ~(sine > LOCKUP_SINE)
    if bad.any():
        k = int(np.argmax(bad))
        raise SingularPoseError(
            f"{mech.source}: dyad {d.name} passes through a lock-up at {where(phi, k, labels)} "
            "(the two lines of its vector equation are parallel)"
        )


def _dyad(mech, d: Dyad, pos: PositionState, v, omega, sliding, cond, labels) -> None:
    P = pos.points
    i, j = d.links
    if d.kind == "RRR":
        a, b, c = d.joints
        rA, rC = P[b] - P[a], P[b] - P[c]
        c1, c2 = perp(rA), -perp(rC)
        cond[d.name] = sine_between(c1, c2)
        check_conditioning(mech, d, pos.phi, cond[d.name], labels)
        wi, wj = solve2(c1, c2, v[c] - v[a])
        omega[i], omega[j] = wi, wj
        v[b] = rigid_velocity(v[a], wi, rA)
    elif d.kind == "RRP":
        a, b = d.joints
        g = d.guides[0]
        key = slide_key(j, g.link)
        _, u = pos.guides[key]
        r = P[b] - P[a]
        c1, c2 = perp(r), -u
        cond[d.name] = sine_between(c1, c2)
        check_conditioning(mech, d, pos.phi, cond[d.name], labels)
        vBk = coincident_velocity(g, P[b], pos, v, omega)
        wi, vr = solve2(c1, c2, vBk - v[a])
        omega[i] = wi
        omega[j] = omega[g.link].copy()
        sliding[key] = vr
        v[b] = rigid_velocity(v[a], wi, r)
    elif d.kind == "RPR":
        a, c = d.joints
        key = slide_key(i, j)
        _, u = pos.guides[key]
        r = P[a] - P[c]
        c1, c2 = perp(r), u
        cond[d.name] = sine_between(c1, c2)
        check_conditioning(mech, d, pos.phi, cond[d.name], labels)
        w, vr = solve2(c1, c2, v[a] - v[c])
        omega[i], omega[j] = w, w.copy()
        sliding[key] = vr
    elif d.kind == "PRP":
        (b,) = d.joints
        g1, g2 = d.guides
        k1, k2 = slide_key(i, g1.link), slide_key(j, g2.link)
        u1, u2 = pos.guides[k1][1], pos.guides[k2][1]
        cond[d.name] = sine_between(u1, u2)
        check_conditioning(mech, d, pos.phi, cond[d.name], labels)
        vB1 = coincident_velocity(g1, P[b], pos, v, omega)
        vB2 = coincident_velocity(g2, P[b], pos, v, omega)
        vr1, vr2 = solve2(u1, -u2, vB2 - vB1)
        omega[i], omega[j] = omega[g1.link].copy(), omega[g2.link].copy()
        sliding[k1], sliding[k2] = vr1, vr2
        v[b] = vB1 + scale(u1, vr1)
    elif d.kind == "RPP":
        a, dn = d.joints
        g = d.guides[0]
        kj, ki = slide_key(j, g.link), slide_key(i, j)
        u, w = pos.guides[kj][1], pos.guides[ki][1]
        cond[d.name] = sine_between(u, w)
        check_conditioning(mech, d, pos.phi, cond[d.name], labels)
        vAk = coincident_velocity(g, P[a], pos, v, omega)
        vs, vr = solve2(u, w, v[a] - vAk)
        omega[j] = omega[g.link].copy()
        omega[i] = omega[j].copy()
        sliding[kj], sliding[ki] = vs, vr
        v[dn] = coincident_velocity(g, P[dn], pos, v, omega) + scale(u, vs)
