"""Positions of every joint and link over a sweep of crank angles (plan of positions).

Each dyad is assembled by the draftsman's compass-and-straightedge step, in
closed form and vectorised over all crank angles φ (rad, CCW from +x):

* RRR — circle (A, l_AB) ∩ circle (C, l_CB);
* RRP — circle (A, l_AB) ∩ the guide line of the slider;
* RPR — the slot through the pivot C (at offset e) that passes through the pin A;
* PRP — guide line of link i ∩ guide line of link j;
* RPP — the slot of link j (at its angle to the guide) that passes through A.

The branch sign is fixed for the whole sweep, so the assembly never jumps to the
other configuration; the sweep instead fails with :class:`AssemblyError` where
the lengths cannot close.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .errors import AssemblyError
from .geometry import angle_of, cross, dot, norm, perp, scale, unit_of_angle
from .model import Dyad, Guide, Mechanism

Array = NDArray[np.float64]


@dataclass(frozen=True, slots=True)
class PositionState:
    """Solved positions over a sweep.

    Attributes
    ----------
    phi : ndarray (N,)
        Crank angles, rad.
    points : dict[str, ndarray (N, 2)]
        Coordinates of every named point, m.
    theta : dict[str, ndarray (N,)]
        Angle of each link's reference axis, rad (the frame's is 0).
    guides : dict[str, tuple[ndarray, ndarray]]
        For each sliding pair, keyed ``"j/k"`` (link j slides on link k): a point of
        the guide line (N, 2) and its unit direction (N, 2).
    """

    phi: Array
    points: dict[str, Array]
    theta: dict[str, Array]
    guides: dict[str, tuple[Array, Array]]


def guide_line(g: Guide, points: dict[str, Array], theta: dict[str, Array], n: int,
               where_: str = "", phi: Array | None = None, labels=None):
    """Point and unit direction of a guide at each position.

    ``where_`` (e.g. ``"press.toml: dyad RRP(2-3)"``) prefixes an error message, which
    names the position by its label and crank angle when ``phi`` is given.
    """
    if g.through is not None:
        base = points[g.through]
    else:
        base = np.broadcast_to(np.asarray(g.xy, float), (n, 2))
    if g.toward is not None:
        d = points[g.toward] - base
        if not np.all(norm(d) > 0):
            k = int(np.argmin(norm(d)))
            at = where(phi, k, labels) if phi is not None else f"position {k}"
            raise AssemblyError(f"{where_}: guide on link {g.link}: the direction from "
                                f"{g.through or g.xy} toward {g.toward} is undefined at {at} "
                                "(the two points coincide)")
        u = d / norm(d)[:, None]
    else:
        u = unit_of_angle(theta[g.link] + g.angle)
    return base, np.broadcast_to(u, (n, 2))


def slide_key(slider: str, carrier: str) -> str:
    """Key of a sliding pair: link ``slider`` moving along a guide of link ``carrier``."""
    return f"{slider}/{carrier}"


def place_point(origin: Array, direction: Array, along, across) -> Array:
    """``origin + along·d + across·(k×d)`` for unit directions ``d``."""
    return origin + scale(direction, along) + scale(perp(direction), across)


def where(phi: Array, k: int, labels=None) -> str:
    """Describe position k of a sweep for an error message: its label and crank angle."""
    deg = float(np.degrees(phi[k])) % 360.0
    if labels is not None:
        return f"position {labels[k]} (φ = {deg:.2f}°)"
    return f"φ = {deg:.2f}°"


def solve_positions(mech: Mechanism, phi, labels=None) -> PositionState:
    """Assemble the mechanism at each crank angle.

    Parameters
    ----------
    mech : Mechanism
    phi : array_like
        Absolute crank angles φ of O→A (rad, CCW from +x).
    labels : sequence of str, optional
        Position labels, used only to name a position in an error.

    Returns
    -------
    PositionState

    Raises
    ------
    AssemblyError
        At the first crank angle where a dyad cannot be assembled, naming the dyad
        and the violated length condition.
    """
    phi = np.atleast_1d(np.asarray(phi, float))
    n = phi.shape[0]
    pts: dict[str, Array] = {}
    theta: dict[str, Array] = {mech.frame_link: np.zeros(n)}
    guides: dict[str, tuple[Array, Array]] = {}
    for name, xy in mech.frame_points.items():
        pts[name] = np.broadcast_to(np.asarray(xy, float), (n, 2))
    cr = mech.crank
    pts[cr.pin] = pts[cr.pivot] + cr.length * unit_of_angle(phi)
    theta[cr.link] = phi.copy()
    _place_extra(mech, pts, theta, n, phi)
    for d in mech.dyads:
        _place_dyad(mech, d, pts, theta, guides, phi, labels)
        _place_extra(mech, pts, theta, n, phi)
    return PositionState(phi, pts, theta, guides)


def _place_extra(mech: Mechanism, pts, theta, n: int, phi) -> None:
    for p in mech.points:
        if p.name in pts or p.link not in theta or p.origin not in pts:
            continue
        if p.toward is not None and p.toward not in pts:
            continue
        origin = pts[p.origin]
        if p.toward is not None:
            d = pts[p.toward] - origin
            dist = norm(d)
            if not np.all(dist > 0):
                k = int(np.argmin(dist))
                raise AssemblyError(
                    f"{mech.source}: point {p.name}: the direction from {p.origin} toward "
                    f"{p.toward} is undefined at {where(phi, k)} (the two points coincide)")
            u = d / dist[:, None]
            along = p.fraction * dist if p.fraction is not None else np.full(n, p.along)
        else:
            u = unit_of_angle(theta[p.link])
            along = np.full(n, p.along)
        pts[p.name] = place_point(origin, u, along, np.full(n, p.across))


def _place_dyad(mech, d: Dyad, pts, theta, guides, phi, labels) -> None:
    def _fail(bad: NDArray[np.bool_], condition) -> None:
        k = int(np.argmax(bad))
        raise AssemblyError(f"{mech.source}: dyad {d.name} cannot be assembled at "
                            f"{where(phi, k, labels)}: {condition(k)}")

    n = phi.shape[0]
    i, j = d.links
    s = float(d.branch)
    if d.kind == "RRR":
        a_name, b_name, c_name = d.joints
        A, C = pts[a_name], pts[c_name]
        l1, l2 = d.lengths
        dv = C - A
        dist = norm(dv)
        # |AC| below 1e-12 of the links is a coincidence (the dyad cannot be assembled);
        # guarding with it keeps the square below from overflowing
        tiny = 1e-12 * (l1 + l2)
        h2 = l1**2 - ((l1**2 - l2**2 + dist**2) / (2 * np.maximum(dist, tiny))) ** 2
        bad = ~(h2 >= 0) | (dist <= tiny)
        if bad.any():
            _fail(bad, lambda k: (
                f"|{a_name}{c_name}| = {dist[k]:.6g} m is outside "
                f"[|l{a_name}{b_name} − l{c_name}{b_name}|, l{a_name}{b_name} + l{c_name}{b_name}] "
                f"= [{abs(l1 - l2):.6g}, {l1 + l2:.6g}] m"))
        e = dv / dist[:, None]
        a = (l1**2 - l2**2 + dist**2) / (2 * dist)
        B = A + scale(e, a) + scale(perp(e), s * np.sqrt(h2))
        pts[b_name] = B
        theta[i] = angle_of(B - A)
        theta[j] = angle_of(B - C)
    elif d.kind == "RRP":
        a_name, b_name = d.joints
        A = pts[a_name]
        (l1,) = d.lengths
        G, u = guide_line(d.guides[0], pts, theta, n, f"{mech.source}: dyad {d.name}",
                          phi, labels)
        w = A - G
        h = cross(u, w)  # signed distance of A to the left of the guide
        bad = ~(np.abs(h) <= l1)
        if bad.any():
            _fail(bad, lambda k: (
                f"the distance from {a_name} to the guide, {abs(h[k]):.6g} m, exceeds "
                f"l{a_name}{b_name} = {l1:.6g} m"))
        foot = G + scale(u, dot(w, u))
        B = foot + scale(u, s * np.sqrt(np.maximum(l1**2 - h**2, 0.0)))
        pts[b_name] = B
        theta[i] = angle_of(B - A)
        theta[j] = angle_of(u)
        guides[slide_key(j, d.guides[0].link)] = (G, u)
    elif d.kind == "RPR":
        a_name, c_name = d.joints
        A, C = pts[a_name], pts[c_name]
        dv = A - C
        dist = norm(dv)
        e = d.offset
        # the pin on the slot axis's foot (or on the pivot) leaves the rocker's angle undefined
        tol = 1e-9 * max(mech.crank.length, abs(e))
        bad = ~(np.sqrt(np.maximum(dist**2 - e**2, 0.0)) > tol)
        if bad.any():
            _fail(bad, lambda k: (
                f"|{c_name}{a_name}| = {dist[k]:.6g} m must exceed the slot offset {abs(e):.6g} m "
                f"(the pin {a_name} passes through the foot of the slot axis from {c_name})"))
        along = s * np.sqrt(dist**2 - e**2)
        th = angle_of(dv) - np.arctan2(e, along)
        theta[i] = th
        theta[j] = th.copy()
        guides[slide_key(i, j)] = (C + scale(perp(unit_of_angle(th)), np.full(n, e)),
                                   unit_of_angle(th))
    elif d.kind == "PRP":
        (b_name,) = d.joints
        G1, u1 = guide_line(d.guides[0], pts, theta, n, f"{mech.source}: dyad {d.name}",
                          phi, labels)
        G2, u2 = guide_line(d.guides[1], pts, theta, n, f"{mech.source}: dyad {d.name}",
                            phi, labels)
        den = cross(u1, u2)
        bad = ~(np.abs(den) > 1e-12)
        if bad.any():
            _fail(bad, lambda k: "its two guides are parallel")
        t = cross(G2 - G1, u2) / den
        pts[b_name] = G1 + scale(u1, t)
        theta[i] = angle_of(u1)
        theta[j] = angle_of(u2)
        guides[slide_key(i, d.guides[0].link)] = (G1, u1)
        guides[slide_key(j, d.guides[1].link)] = (G2, u2)
    elif d.kind == "RPP":
        a_name, d_name = d.joints
        A = pts[a_name]
        G, u = guide_line(d.guides[0], pts, theta, n, f"{mech.source}: dyad {d.name}",
                          phi, labels)
        th_j = angle_of(u)
        w = unit_of_angle(th_j + d.slot_angle)
        t = cross(w, A - G) / cross(w, u)
        D = G + scale(u, t)
        pts[d_name] = D
        theta[i] = angle_of(w)
        theta[j] = th_j
        guides[slide_key(j, d.guides[0].link)] = (G, u)
        guides[slide_key(i, j)] = (D, w)
