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

from ..errors import SingularPoseError
from ..geometry import perp, scale
from ..model import Dyad, Guide, Mechanism
from .positions import PositionState, as_complex, as_xy, slide_key, translating_links, where

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
        From :func:`graphplan.kinematics.positions.solve_positions`.
    labels : sequence of str, optional
        Position labels, used only to name a position in an error.

    Returns
    -------
    VelocityState

    Raises
    ------
    SingularPoseError
        Where a dyad's two directions are parallel (a lock-up), naming the angle.

    Notes
    -----
    The arithmetic is done on complex numbers ``x + iy`` (``k×v = i·v``; the 2×2
    system of a dyad by Cramer's rule with ``a×b = Im(conj(a)·b)``); the results are
    (N, 2) float views of them.
    """
    P = {k: as_complex(x) for k, x in pos.points.items()}
    U = {k: as_complex(u) for k, (_, u) in pos.guides.items()}
    return state_of(velocities_complex(mech, pos.phi, P, U, labels), pos.phi.shape[0])


def state_of(solved, n: int) -> VelocityState:
    """A :class:`VelocityState` of the complex solution of :func:`velocities_complex`."""
    v, omega, sliding, cond = solved
    return VelocityState({k: as_xy(z, n) for k, z in v.items()}, omega, sliding, cond)


def velocities_complex(mech: Mechanism, phi: Array, P: dict, U: dict, labels=None):
    """:func:`solve_velocities` on complex numbers: the positions ``P`` and the guides'
    directions ``U`` as complex numbers; returns (v, ω, sliding, conditioning)."""
    n = phi.shape[0]
    v: dict = {name: 0j for name in mech.frame_points}
    omega: dict[str, Array] = {mech.frame_link: np.zeros(n)}
    sliding: dict[str, Array] = {}
    cond: dict[str, Array] = {}
    cr = mech.crank
    omega[cr.link] = np.full(n, cr.omega)
    v[cr.pin] = v[cr.pivot] + 1j * (P[cr.pin] - P[cr.pivot]) * cr.omega
    still = translating_links(mech)
    cache: dict = {}
    _extra(mech, P, v, omega, still, cache)
    for d in mech.dyads:
        _dyad(mech, d, phi, P, U, v, omega, sliding, cond, labels)
        _extra(mech, P, v, omega, still, cache)
    return v, omega, sliding, cond


def _extra(mech, P, v, omega, still, omega_i) -> None:
    """The velocities of the points of the links solved so far (``omega_i`` caches iω)."""
    for p in mech.points:
        if p.name not in v and p.origin in v and p.link in omega:
            if p.link in still:  # a translating link: every point moves alike
                v[p.name] = np.array(v[p.origin], copy=True)
            elif p.toward is not None and p.fraction is not None and p.toward in v:
                # on the segment origin→toward of a rigid link: v = v_O + f·(v_T − v_O)
                v[p.name] = v[p.origin] + (v[p.toward] - v[p.origin]) * p.fraction
            else:
                if (p.link, "iω") not in omega_i:
                    omega_i[(p.link, "iω")] = 1j * omega[p.link]
                v[p.name] = v[p.origin] + (P[p.name] - P[p.origin]) * omega_i[(p.link, "iω")]


def check_conditioning(mech: Mechanism, d: Dyad, phi: Array, sine: Array, labels=None) -> None:
    """Raise :class:`SingularPoseError` where a dyad's equation lines are parallel."""
    good = sine > LOCKUP_SINE
    if not good.all():
        k = int(np.argmin(good))
        raise SingularPoseError(
            f"{mech.source}: dyad {d.name} passes through a lock-up at {where(phi, k, labels)} "
            "(the two lines of its vector equation are parallel)"
        )


def csolve2(c1, c2, rhs):
    """Solve ``x1·c1 + x2·c2 = rhs`` (complex vectors) by Cramer's rule; also ``det``.

    ``det = c1×c2``; the caller has checked that it is not zero.
    """
    det = (np.conj(c1) * c2).imag
    return (np.conj(rhs) * c2).imag / det, (np.conj(c1) * rhs).imag / det


def csine(c1, c2, n: int) -> Array:
    """|sin| of the angle between the lines of c1 and c2 (0 for a zero vector), shape (N,)."""
    den = np.abs(c1) * np.abs(c2)
    ok = den > 0
    s = np.abs((np.conj(c1) * c2).imag) / np.where(ok, den, 1.0)
    return np.broadcast_to(np.where(ok, s, 0.0), (n,))


def _solve_lines(mech, d: Dyad, phi, c1, c2, rhs, cond, labels):
    """The dyad's 2×2 system ``x1·c1 + x2·c2 = rhs`` after its lock-up check.

    ``cond[d.name]`` gets |sin| of the angle between c1 and c2 (``|c1×c2|/(|c1|·|c2|)``);
    Cramer's rule then shares the determinant ``c1×c2`` with it.
    """
    n = phi.shape[0]
    cc1 = np.conj(c1)
    det = (cc1 * c2).imag
    # |det| ≤ |c1|·|c2|: a zero vector gives 0/1e-300 = 0, never 0/0
    sine = np.abs(det) / (np.abs(c1) * np.abs(c2) + 1e-300)
    cond[d.name] = sine if np.shape(sine) == (n,) else np.broadcast_to(sine, (n,))
    check_conditioning(mech, d, phi, cond[d.name], labels)
    return (np.conj(rhs) * c2).imag / det, (cc1 * rhs).imag / det


def _ccoincident(g: Guide, X, P, v, omega):
    """Velocity of the point of the guide's link that coincides with X (complex)."""
    if g.through is None:
        return 0j
    return v[g.through] + (1j * (X - P[g.through])) * omega[g.link]


def _dyad(mech, d: Dyad, phi, P, U, v, omega, sliding, cond, labels) -> None:
    i, j = d.links
    n = phi.shape[0]
    if d.kind == "RRR":
        a, b, c = d.joints
        rA, rC = P[b] - P[a], P[b] - P[c]
        c1, c2 = 1j * rA, -1j * rC
        wi, wj = _solve_lines(mech, d, phi, c1, c2, v[c] - v[a], cond, labels)
        omega[i], omega[j] = wi, wj
        v[b] = v[a] + c1 * wi
    elif d.kind == "RRP":
        a, b = d.joints
        g = d.guides[0]
        key = slide_key(j, g.link)
        u = U[key]
        r = P[b] - P[a]
        c1, c2 = 1j * r, -u
        vBk = _ccoincident(g, P[b], P, v, omega)
        wi, vr = _solve_lines(mech, d, phi, c1, c2, vBk - v[a], cond, labels)
        omega[i] = wi
        omega[j] = omega[g.link].copy()
        sliding[key] = vr
        v[b] = v[a] + c1 * wi
    elif d.kind == "RPR":
        a, c = d.joints
        key = slide_key(i, j)
        u = U[key]
        r = P[a] - P[c]
        rel = v[a] if isinstance(v[c], complex) and v[c] == 0 else v[a] - v[c]  # C fixed: v_C = 0
        w, vr = _solve_lines(mech, d, phi, 1j * r, u, rel, cond, labels)
        omega[i], omega[j] = w, w.copy()
        sliding[key] = vr
    elif d.kind == "PRP":
        (b,) = d.joints
        g1, g2 = d.guides
        k1, k2 = slide_key(i, g1.link), slide_key(j, g2.link)
        u1, u2 = U[k1], U[k2]
        vB1 = _ccoincident(g1, P[b], P, v, omega)
        vB2 = _ccoincident(g2, P[b], P, v, omega)
        vr1, vr2 = _solve_lines(mech, d, phi, u1, -u2, vB2 - vB1, cond, labels)
        vr1, vr2 = np.broadcast_to(vr1, (n,)).copy(), np.broadcast_to(vr2, (n,)).copy()
        omega[i], omega[j] = omega[g1.link].copy(), omega[g2.link].copy()
        sliding[k1], sliding[k2] = vr1, vr2
        v[b] = vB1 + u1 * vr1
    elif d.kind == "RPP":
        a, dn = d.joints
        g = d.guides[0]
        kj, ki = slide_key(j, g.link), slide_key(i, j)
        u, w = U[kj], U[ki]
        vAk = _ccoincident(g, P[a], P, v, omega)
        vs, vr = _solve_lines(mech, d, phi, u, w, v[a] - vAk, cond, labels)
        omega[j] = omega[g.link].copy()
        omega[i] = omega[j].copy()
        sliding[kj], sliding[ki] = vs, vr
        v[dn] = _ccoincident(g, P[dn], P, v, omega) + u * vs
