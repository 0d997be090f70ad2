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

from ..geometry import perp, scale
from ..model import Dyad, Guide, Mechanism
from .positions import PositionState, as_complex, as_xy, slide_key, translating_links
from .velocities import VelocityState, csolve2

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

    Notes
    -----
    Computed on complex numbers ``x + iy`` as
    :func:`graphplan.kinematics.velocities.solve_velocities`.
    """
    n = pos.phi.shape[0]
    P = {k: as_complex(x) for k, x in pos.points.items()}
    U = {k: as_complex(u) for k, (_, u) in pos.guides.items()}
    return state_of(accelerations_complex(mech, n, P, U, vel.omega, vel.sliding), n)


def state_of(solved, n: int) -> AccelerationState:
    """An :class:`AccelerationState` of the complex solution of :func:`accelerations_complex`."""
    a, eps, sliding, cor = solved
    return AccelerationState({k: as_xy(z, n) for k, z in a.items()}, eps, sliding,
                             {k: as_xy(z, n) for k, z in cor.items()})


def accelerations_complex(mech: Mechanism, n: int, P: dict, U: dict, W: dict, S: dict):
    """:func:`solve_accelerations` on complex numbers: positions ``P``, guides' directions
    ``U``, the links' ω ``W`` and the sliding speeds ``S``; returns (a, ε, sliding, Coriolis)."""
    a: dict = {name: 0j for name in mech.frame_points}
    eps: dict[str, Array] = {mech.frame_link: np.zeros(n)}
    sliding: dict[str, Array] = {}
    cor: dict = {}
    cr = mech.crank
    eps[cr.link] = np.zeros(n)
    a[cr.pin] = a[cr.pivot] - (P[cr.pin] - P[cr.pivot]) * cr.omega**2
    still = translating_links(mech)
    factor: dict = {}
    _extra(mech, P, W, a, eps, still, factor)
    for d in mech.dyads:
        _dyad(d, P, U, W, S, a, eps, sliding, cor, n)
        _extra(mech, P, W, a, eps, still, factor)
    return a, eps, sliding, cor


def _rigid(a_base, omega, eps, r):
    """``a_base + ε·k×r − ω²·r`` (complex)."""
    return a_base + (1j * r) * eps - r * omega**2


def _extra(mech, P, W, a, eps, still, factor) -> None:
    """The accelerations of the points of the links solved so far (``factor``: iε − ω²)."""
    for p in mech.points:
        if p.name not in a and p.origin in a and p.link in eps:
            if p.link in still:  # a translating link: every point moves alike
                a[p.name] = np.array(a[p.origin], copy=True)
            elif p.toward is not None and p.fraction is not None and p.toward in a:
                # on the segment origin→toward of a rigid link: a = a_O + f·(a_T − a_O)
                a[p.name] = a[p.origin] + (a[p.toward] - a[p.origin]) * p.fraction
            else:
                # a_O + ε·k×r − ω²·r = a_O + r·(iε − ω²), the factor once per link
                if p.link not in factor:
                    factor[p.link] = 1j * eps[p.link] - W[p.link] ** 2
                a[p.name] = a[p.origin] + (P[p.name] - P[p.origin]) * factor[p.link]


def _coincident(g: Guide, X, P, W, a, eps):
    if g.through is None:
        return 0j
    return _rigid(a[g.through], W[g.link], eps[g.link], X - P[g.through])


def _coriolis(omega_k, v_r, u):
    """``2·ω_k·k×(v_r·u)`` (complex)."""
    return (1j * u) * (2.0 * omega_k * v_r)


def _dyad(d: Dyad, P, U, W, S, a, eps, sliding, cor, n) -> None:
    i, j = d.links
    if d.kind == "RRR":
        pa, pb, pc = d.joints
        rA, rC = P[pb] - P[pa], P[pb] - P[pc]
        rhs = (a[pc] - rC * W[j] ** 2) - (a[pa] - rA * W[i] ** 2)
        ei, ej = csolve2(1j * rA, -1j * rC, rhs)
        eps[i], eps[j] = ei, ej
        a[pb] = _rigid(a[pa], W[i], ei, rA)
    elif d.kind == "RRP":
        pa, pb = d.joints
        g = d.guides[0]
        key = slide_key(j, g.link)
        u = U[key]
        r = P[pb] - P[pa]
        aBk = _coincident(g, P[pb], P, W, a, eps)
        cor[key] = _coriolis(W[g.link], S[key], u)
        rhs = aBk + cor[key] - (a[pa] - r * W[i] ** 2)
        ei, ar = csolve2(1j * r, -u, rhs)
        eps[i] = ei
        eps[j] = eps[g.link].copy()
        sliding[key] = ar
        a[pb] = _rigid(a[pa], W[i], ei, r)
    elif d.kind == "RPR":
        pa, pc = d.joints
        key = slide_key(i, j)
        u = U[key]
        r = P[pa] - P[pc]
        cor[key] = _coriolis(W[j], S[key], u)
        if isinstance(a[pc], complex) and a[pc] == 0:  # C fixed: a_C = 0
            rhs = a[pa] + r * W[j] ** 2 - cor[key]
        else:
            rhs = a[pa] - (a[pc] - r * W[j] ** 2) - cor[key]
        e, ar = csolve2(1j * r, u, rhs)
        eps[i], eps[j] = e, e.copy()
        sliding[key] = ar
    elif d.kind == "PRP":
        (pb,) = d.joints
        g1, g2 = d.guides
        k1, k2 = slide_key(i, g1.link), slide_key(j, g2.link)
        u1, u2 = U[k1], U[k2]
        cor[k1] = _coriolis(W[g1.link], S[k1], u1)
        cor[k2] = _coriolis(W[g2.link], S[k2], u2)
        aB1 = _coincident(g1, P[pb], P, W, a, eps) + cor[k1]
        aB2 = _coincident(g2, P[pb], P, W, a, eps) + cor[k2]
        ar1, ar2 = csolve2(u1, -u2, aB2 - aB1)
        ar1, ar2 = np.broadcast_to(ar1, (n,)).copy(), np.broadcast_to(ar2, (n,)).copy()
        eps[i], eps[j] = eps[g1.link].copy(), eps[g2.link].copy()
        sliding[k1], sliding[k2] = ar1, ar2
        a[pb] = aB1 + u1 * ar1
    elif d.kind == "RPP":
        pa, pd = d.joints
        g = d.guides[0]
        kj, ki = slide_key(j, g.link), slide_key(i, j)
        u, w = U[kj], U[ki]
        aAk = _coincident(g, P[pa], P, W, a, eps)
        cor[kj] = _coriolis(W[g.link], S[kj], u)
        cor[ki] = _coriolis(W[j], S[ki], w)
        as_, ar = csolve2(u, w, a[pa] - aAk - cor[kj] - cor[ki])
        eps[j] = eps[g.link].copy()
        eps[i] = eps[j].copy()
        sliding[kj], sliding[ki] = as_, ar
        a[pd] = _coincident(g, P[pd], P, W, a, eps) + cor[kj] + u * as_
