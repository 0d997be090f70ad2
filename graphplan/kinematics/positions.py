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

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..errors import AssemblyError
from ..geometry import norm, perp, scale, unit_of_angle
from ..model import Dyad, Guide, Mechanism

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


def as_complex(xy):
    """A vector array as complex numbers ``x + iy``, without copying where possible.

    A C-contiguous (N, 2) float64 array gives a complex (N,) *view*; a constant (a
    broadcast frame point, or a single 2-vector) gives a Python complex. The solvers
    work on these: ``k×v`` is ``1j·v``, ``a×b`` is ``Im(conj(a)·b)``, ``a·b`` its real part.
    """
    a = np.asarray(xy)
    if a.ndim == 1:
        return complex(a[0], a[1])
    if a.strides[0] == 0:
        return complex(a[0, 0], a[0, 1])
    if a.dtype == np.float64 and a.flags.c_contiguous:
        return a.view(np.complex128)[:, 0]
    return a[:, 0] + 1j * a[:, 1]


_XY = np.dtype((np.float64, 2))
"""A complex128 number seen as a pair of float64: ``z.view(_XY)`` is (N, 2)."""


def as_xy(z, n: int) -> Array:
    """Complex numbers back as an (N, 2) float array: a view of a complex array; a constant
    broadcast (read-only) as the frame points are, zero as a fresh array of zeros."""
    if type(z) is np.ndarray and z.ndim:
        if z.dtype == np.complex128 and z.flags.c_contiguous:
            return z.view(_XY)
        return np.ascontiguousarray(z, dtype=np.complex128).view(_XY)
    z = complex(z)
    if z == 0:
        return np.zeros((n, 2))
    return np.broadcast_to(np.array([z.real, z.imag]), (n, 2))


_TINY = float(np.finfo(float).tiny)
"""The smallest normal float: a distance below it gives no direction (its reciprocal overflows)."""


def cdiv(z, r):
    """``z / r`` for complex z and real r (a reciprocal, then a product: one rounding more
    than dividing each component, two numpy calls fewer)."""
    return z * (1.0 / r)


def translating_links(mech: Mechanism) -> set[str]:
    """Links that never turn (ω ≡ ε ≡ 0): the frame and the sliders on its guides, by structure."""
    still = {mech.frame_link}
    for d in mech.dyads:
        i, j = d.links
        if d.kind == "RRP" and d.guides[0].link in still:
            still.add(j)
        elif d.kind == "PRP":
            if d.guides[0].link in still:
                still.add(i)
            if d.guides[1].link in still:
                still.add(j)
        elif d.kind == "RPP" and d.guides[0].link in still:
            still.update((i, j))
    return still


def arg(z):
    """Angle of each complex vector in (−π, π], CCW from +x (``np.angle`` without its checks)."""
    if isinstance(z, np.ndarray):
        return np.arctan2(z.imag, z.real)
    return math.atan2(z.imag, z.real)


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
    pts, theta, guides = solve_complex(mech, phi, labels)
    n = phi.shape[0]
    return PositionState(phi, {k: as_xy(z, n) for k, z in pts.items()}, theta,
                         {k: (as_xy(G, n), as_xy(u, n)) for k, (G, u) in guides.items()})


def solve_complex(mech: Mechanism, phi: Array, labels=None):
    """:func:`solve_positions` on complex numbers ``x + iy``.

    Returns the points (complex arrays, or Python complex numbers for the frame's), the
    link angles and the guides (point, unit direction) by sliding pair.
    """
    n = phi.shape[0]
    pts: dict = {}
    theta: dict[str, Array] = {mech.frame_link: np.zeros(n)}
    axes: dict = {mech.frame_link: 1 + 0j}  # unit vector of a link's reference axis, once known
    guides: dict = {}
    for name, xy in mech.frame_points.items():
        pts[name] = complex(float(xy[0]), float(xy[1]))
    cr = mech.crank
    axes[cr.link] = np.exp(1j * phi)
    pts[cr.pin] = pts[cr.pivot] + cr.length * axes[cr.link]
    theta[cr.link] = phi.copy()
    _place_extra(mech, pts, theta, axes, n, phi)
    for d in mech.dyads:
        _place_dyad(mech, d, pts, theta, axes, guides, phi, labels)
        _place_extra(mech, pts, theta, axes, n, phi)
    return pts, theta, guides


def _cguide(g: Guide, pts, theta, n: int, where_: str, phi, labels, frame: str):
    """Point and unit direction of a guide, as complex numbers (see :func:`guide_line`)."""
    if g.through is not None:
        base = pts[g.through]
    else:
        assert g.xy is not None  # a guide runs through a point or a fixed xy (the loader)
        base = complex(float(g.xy[0]), float(g.xy[1]))
    if g.toward is not None:
        d = pts[g.toward] - base
        dist = np.abs(d)
        if not np.all(dist >= _TINY):  # a subnormal distance: 1/dist would overflow
            k = int(np.argmin(np.broadcast_to(dist, (n,))))
            at = where(phi, k, labels) if phi is not None else f"position {k}"
            raise AssemblyError(f"{where_}: guide on link {g.link}: the direction from "
                                f"{g.through or g.xy} toward {g.toward} is undefined at {at} "
                                "(the two points coincide)")
        u = cdiv(d, dist)
    elif g.link == frame:  # a constant direction
        u = complex(math.cos(g.angle), math.sin(g.angle))
    else:
        u = np.exp(1j * (theta[g.link] + g.angle))
    return base, u


def _place_extra(mech: Mechanism, pts, theta, axes, n: int, phi) -> None:
    for p in mech.points:
        if p.name in pts or p.link not in theta or p.origin not in pts:
            continue
        if p.toward is not None and p.toward not in pts:
            continue
        origin = pts[p.origin]
        if p.toward is not None:
            d = pts[p.toward] - origin
            dist = np.abs(d)
            if not np.all(dist > 0):
                k = int(np.argmin(np.broadcast_to(dist, (n,))))
                raise AssemblyError(
                    f"{mech.source}: point {p.name}: the direction from {p.origin} toward "
                    f"{p.toward} is undefined at {where(phi, k)} (the two points coincide)")
            if p.fraction is not None:  # origin + fraction·(toward − origin)
                z = origin + d * p.fraction
                pts[p.name] = np.broadcast_to(z, (n,)).copy() if np.ndim(z) == 0 else z
                continue
            u = cdiv(d, dist)
            along = p.along
        else:
            if p.link not in axes:
                axes[p.link] = np.exp(1j * theta[p.link])
            u = axes[p.link]
            along = p.along
        z = origin + u * along
        if p.across:
            z = z + (1j * u) * p.across
        pts[p.name] = np.broadcast_to(z, (n,)).copy() if np.ndim(z) == 0 else z


def _place_dyad(mech, d: Dyad, pts, theta, axes, guides, phi, labels) -> None:
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
        dist = np.abs(dv)
        # |AC| below 1e-12 of the links is a coincidence (the dyad cannot be assembled);
        # guarding with it keeps the square below from overflowing
        tiny = 1e-12 * (l1 + l2)
        a = (l1**2 - l2**2 + dist**2) / (2 * np.maximum(dist, tiny))
        h2 = l1**2 - a**2
        bad = ~(h2 >= 0) | (dist <= tiny)
        if bad.any():
            _fail(bad, lambda k: (
                f"|{a_name}{c_name}| = {dist[k]:.6g} m is outside "
                f"[|l{a_name}{b_name} − l{c_name}{b_name}|, l{a_name}{b_name} + l{c_name}{b_name}] "
                f"= [{abs(l1 - l2):.6g}, {l1 + l2:.6g}] m"))
        e = cdiv(dv, dist)
        B = A + e * a + (1j * e) * (s * np.sqrt(h2))
        pts[b_name] = B
        theta[i] = arg(B - A)
        theta[j] = arg(B - C)
    elif d.kind == "RRP":
        a_name, b_name = d.joints
        A = pts[a_name]
        (l1,) = d.lengths
        G, u = _cguide(d.guides[0], pts, theta, n, f"{mech.source}: dyad {d.name}", phi, labels,
                       mech.frame_link)
        w = A - G
        cw = np.conj(u) * w
        h = cw.imag  # signed distance of A to the left of the guide
        bad = ~(np.abs(h) <= l1)
        if bad.any():
            _fail(bad, lambda k: (
                f"the distance from {a_name} to the guide, {abs(h[k]):.6g} m, exceeds "
                f"l{a_name}{b_name} = {l1:.6g} m"))
        # |h| ≤ l1, so l1² − h² ≥ 0 in floating point too
        B = G + u * (cw.real + s * np.sqrt(l1**2 - h**2))
        pts[b_name] = B
        theta[i] = arg(B - A)
        theta[j] = arg(u) if isinstance(u, np.ndarray) else np.full(n, arg(u))
        axes[j] = u
        guides[slide_key(j, d.guides[0].link)] = (G, u)
    elif d.kind == "RPR":
        a_name, c_name = d.joints
        A, C = pts[a_name], pts[c_name]
        dv = A - C
        dist = np.abs(dv)
        e = d.offset
        # the pin on the slot axis's foot (or on the pivot) leaves the rocker's angle undefined
        tol = 1e-9 * max(mech.crank.length, abs(e))
        bad = ~((dist if e == 0 else np.sqrt(np.maximum(dist**2 - e**2, 0.0))) > tol)
        if bad.any():
            _fail(bad, lambda k: (
                f"|{c_name}{a_name}| = {dist[k]:.6g} m must exceed the slot offset {abs(e):.6g} m "
                f"(the pin {a_name} passes through the foot of the slot axis from {c_name})"))
        if e == 0:  # the slot through the pivot: along C→A (branch +) or A→C
            th = arg(dv) if s > 0 else arg(-dv)
            u = cdiv(dv if s > 0 else -dv, dist)
        else:
            along = s * np.sqrt(dist**2 - e**2)
            th = arg(dv) - np.arctan2(e, along)
            u = np.exp(1j * th)
        theta[i] = th
        theta[j] = th.copy()
        axes[i] = axes[j] = u
        guides[slide_key(i, j)] = (C + (1j * u) * e, u)
    elif d.kind == "PRP":
        (b_name,) = d.joints
        where_ = f"{mech.source}: dyad {d.name}"
        G1, u1 = _cguide(d.guides[0], pts, theta, n, where_, phi, labels, mech.frame_link)
        G2, u2 = _cguide(d.guides[1], pts, theta, n, where_, phi, labels, mech.frame_link)
        den = (np.conj(u1) * u2).imag
        bad = np.broadcast_to(~(np.abs(den) > 1e-12), (n,))
        if bad.any():
            _fail(bad, lambda k: "its two guides are parallel")
        t = (np.conj(G2 - G1) * u2).imag / den
        B = G1 + u1 * t
        pts[b_name] = np.broadcast_to(B, (n,)).copy() if np.ndim(B) == 0 else B
        theta[i] = np.broadcast_to(arg(u1), (n,)).copy()
        theta[j] = np.broadcast_to(arg(u2), (n,)).copy()
        guides[slide_key(i, d.guides[0].link)] = (G1, u1)
        guides[slide_key(j, d.guides[1].link)] = (G2, u2)
    elif d.kind == "RPP":
        a_name, d_name = d.joints
        A = pts[a_name]
        G, u = _cguide(d.guides[0], pts, theta, n, f"{mech.source}: dyad {d.name}", phi, labels,
                       mech.frame_link)
        th_j = np.broadcast_to(arg(u), (n,)).copy()
        w = np.exp(1j * (th_j + d.slot_angle))
        t = (np.conj(w) * (A - G)).imag / (np.conj(w) * u).imag
        D = G + u * t
        pts[d_name] = D
        theta[i] = arg(w)
        theta[j] = th_j
        guides[slide_key(j, d.guides[0].link)] = (G, u)
        guides[slide_key(i, j)] = (D, w)
