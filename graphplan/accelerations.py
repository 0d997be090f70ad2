"""Accelerations of every point and angular accelerations of every link (plan of accelerations).

The crank turns at constant ω1, so ``a_A = −ω1²·OA`` (directed from A to O).
Each dyad's acceleration equation has the same two unknown directions as its
velocity equation; the known part gathers the normal components
``aⁿ = −ω²·r`` and the Coriolis components ``aᵏ = 2·ω_k·k×(v_r·u)`` (the
relative velocity turned 90° in the sense of the guide link's ω):

* RRR  ``a_B = a_A + aⁿ_BA + ε_i·k×AB = a_C + aⁿ_BC + ε_j·k×CB``
* RRP  ``a_B = a_A + aⁿ_BA + ε_i·k×AB = a_Bk + aᵏ + a_r·u``
* RPR  ``a_A = a_C + aⁿ_AC + ε·k×CA + aᵏ + a_r·u``
* PRP  ``a_B = a_Bk1 + aᵏ1 + a_r1·u1 = a_Bk2 + aᵏ2 + a_r2·u2``
* RPP  ``a_A = a_Ak + aᵏ_s + a_s·u + aᵏ_r + a_r·w``

with ``a_Xk = a_G + ε_k·k×GX − ω_k²·GX`` the acceleration of the point of the
guide's link that coincides with X.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .geometry import perp, scale, solve2
from .model import Dyad, Guide, Mechanism
from .positions import PositionState, slide_key
from .velocities import VelocityState

Array = NDArray[np.float64]


@dataclass(frozen=True, slots=True)
class AccelerationState:
    """Solved accelerations: points (m/s²), ε per link (rad/s², CCW+), sliding and Coriolis.

    ``sliding`` (``"j/k"``) is the relative acceleration of link j along its guide
    on link k; ``coriolis`` the Coriolis acceleration vector of that pair (N, 2).
    """

    points: dict[str, Array]
    epsilon: dict[str, Array]
    sliding: dict[str, Array]
    coriolis: dict[str, Array]


def rigid_acceleration(a_base: Array, omega: Array, eps: Array, r: Array) -> Array:
    """``a_P = a_base + ε·k×r − ω²·r`` with r from the base point to P."""
    return a_base + scale(perp(r), eps) - scale(r, omega**2)


def coriolis(omega_k: Array, v_r: Array, u: Array) -> Array:
    """Coriolis acceleration ``2·ω_k·k×(v_r·u)`` of a slide along ``u`` on a link turning at ω_k."""
    return scale(perp(u), 2.0 * omega_k * v_r)


def coincident_acceleration(g: Guide, X: Array, pos, vel, a, eps) -> Array:
    """Acceleration of the point of the guide's link coinciding with X."""
    n = X.shape[0]
    if g.through is None:
        return np.zeros((n, 2))
    G = pos.points[g.through]
    return rigid_acceleration(a[g.through], vel.omega[g.link], eps[g.link], X - G)


def solve_accelerations(mech: Mechanism, pos: PositionState, vel: VelocityState):
    """Solve the acceleration plans of all positions.

    Parameters
    ----------
    mech : Mechanism
    pos : PositionState
    vel : VelocityState
        The lock-up check was done there; the matrices here are the same.

    Returns
    -------
    AccelerationState
    """
    n = pos.phi.shape[0]
    P = pos.points
    a: dict[str, Array] = {name: np.zeros((n, 2)) for name in mech.frame_points}
    eps: dict[str, Array] = {mech.frame_link: np.zeros(n)}
    sliding: dict[str, Array] = {}
    cor: dict[str, Array] = {}
    cr = mech.crank
    eps[cr.link] = np.zeros(n)
    a[cr.pin] = rigid_acceleration(a[cr.pivot], vel.omega[cr.link], eps[cr.link],
                                   P[cr.pin] - P[cr.pivot])
    _extra(mech, pos, vel, a, eps)
    for d in mech.dyads:
        _dyad(d, pos, vel, a, eps, sliding, cor)
        _extra(mech, pos, vel, a, eps)
    return AccelerationState(a, eps, sliding, cor)


def _extra(mech, pos, vel, a, eps) -> None:
    for p in mech.points:
        if p.name not in a and p.origin in a and p.link in eps:
            a[p.name] = rigid_acceleration(a[p.origin], vel.omega[p.link], eps[p.link],
                                           pos.points[p.name] - pos.points[p.origin])


def _dyad(d: Dyad, pos: PositionState, vel: VelocityState, a, eps, sliding, cor) -> None:
    P = pos.points
    W = vel.omega
    i, j = d.links
    if d.kind == "RRR":
        pa, pb, pc = d.joints
        rA, rC = P[pb] - P[pa], P[pb] - P[pc]
        rhs = (a[pc] - scale(rC, W[j] ** 2)) - (a[pa] - scale(rA, W[i] ** 2))
        ei, ej = solve2(perp(rA), -perp(rC), rhs)
        eps[i], eps[j] = ei, ej
        a[pb] = rigid_acceleration(a[pa], W[i], ei, rA)
    elif d.kind == "RRP":
        pa, pb = d.joints
        g = d.guides[0]
        key = slide_key(j, g.link)
        u = pos.guides[key][1]
        r = P[pb] - P[pa]
        aBk = coincident_acceleration(g, P[pb], pos, vel, a, eps)
        cor[key] = coriolis(W[g.link], vel.sliding[key], u)
        rhs = aBk + cor[key] - (a[pa] - scale(r, W[i] ** 2))
        ei, ar = solve2(perp(r), -u, rhs)
        eps[i] = ei
        eps[j] = eps[g.link].copy()
        sliding[key] = ar
        a[pb] = rigid_acceleration(a[pa], W[i], ei, r)
    elif d.kind == "RPR":
        pa, pc = d.joints
        key = slide_key(i, j)
        u = pos.guides[key][1]
        r = P[pa] - P[pc]
        cor[key] = coriolis(W[j], vel.sliding[key], u)
        rhs = a[pa] - (a[pc] - scale(r, W[j] ** 2)) - cor[key]
        e, ar = solve2(perp(r), u, rhs)
        eps[i], eps[j] = e, e.copy()
        sliding[key] = ar
    elif d.kind == "PRP":
        (pb,) = d.joints
        g1, g2 = d.guides
        k1, k2 = slide_key(i, g1.link), slide_key(j, g2.link)
        u1, u2 = pos.guides[k1][1], pos.guides[k2][1]
        cor[k1] = coriolis(W[g1.link], vel.sliding[k1], u1)
        cor[k2] = coriolis(W[g2.link], vel.sliding[k2], u2)
        aB1 = coincident_acceleration(g1, P[pb], pos, vel, a, eps) + cor[k1]
        aB2 = coincident_acceleration(g2, P[pb], pos, vel, a, eps) + cor[k2]
        ar1, ar2 = solve2(u1, -u2, aB2 - aB1)
        eps[i], eps[j] = eps[g1.link].copy(), eps[g2.link].copy()
        sliding[k1], sliding[k2] = ar1, ar2
        a[pb] = aB1 + scale(u1, ar1)
    elif d.kind == "RPP":
        pa, pd = d.joints
        g = d.guides[0]
        kj, ki = slide_key(j, g.link), slide_key(i, j)
        u, w = pos.guides[kj][1], pos.guides[ki][1]
        aAk = coincident_acceleration(g, P[pa], pos, vel, a, eps)
        cor[kj] = coriolis(W[g.link], vel.sliding[kj], u)
        cor[ki] = coriolis(W[j], vel.sliding[ki], w)
        as_, ar = solve2(u, w, a[pa] - aAk - cor[kj] - cor[ki])
        eps[j] = eps[g.link].copy()
        eps[i] = eps[j].copy()
        sliding[kj], sliding[ki] = as_, ar
        a[pd] = coincident_acceleration(g, P[pd], pos, vel, a, eps) + cor[kj] + scale(u, as_)
