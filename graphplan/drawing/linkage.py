"""The links of a mechanism at one position, as the sheets draw them: bars, outlines of
links with more points, slots of rockers and yokes, slider blocks on their guides, joints,
fixed supports, and the turning arrows of ω and ε (GOST 2.770 symbols, GOST 2.303 lines).

Model metres (y up, about a pivot) are put on paper by :class:`_Paper` (mm, y down): the
plans are only flipped in y, so a counter-clockwise turn stays counter-clockwise.
"""

from __future__ import annotations

import math

import numpy as np

from ..project import SLOT_OVER
from .items import (
    MAIN,
    THIN,
    Arc,
    Arrow,
    Circle,
    Hatch,
    Item,
    Line,
    Polyline,
    Pt,
    Style,
    arc_point,
)

WHITE_FILL = Style(0.5, fill="white")


JOINT_R = 1.5  #: radius of a revolute joint's circle, mm


SLIDER = (14.0, 7.0)  #: slider block, length along the guide × width, mm


class _Paper:
    """Model metres (y up, about the crank pivot) → paper mm (y down)."""

    def __init__(self, origin: Pt, kl: float, pivot: np.ndarray):
        self.ox, self.oy = origin
        self.kl = kl
        self.pivot = pivot

    def __call__(self, xy) -> Pt:
        x, y = (np.asarray(xy, float) - self.pivot) / self.kl
        return (self.ox + float(x), self.oy - float(y))


def _structural(mech) -> set[str]:
    """Points that shape the links: the pivots, pins and joints, the points guides pass
    through or point to, and the origins of other points (not a bare centre of mass)."""
    pts = set(mech.frame_points) | {mech.crank.pivot, mech.crank.pin}
    for d in mech.dyads:
        pts |= set(d.joints)
        pts |= {x for g in d.guides for x in (g.through, g.toward) if x}
    for q in mech.points:
        pts |= {x for x in (q.origin, q.toward) if x}
    centres = {lp.centre for lp in mech.links.values() if lp.centre}
    pts |= {q.name for q in mech.points if q.name not in centres}
    return pts


def _link_outline(mech, link: str, centres: set[str]) -> tuple[str, ...]:
    """The points a link is drawn through: all of its points but a bare centre of mass (a
    crank balanced at its pivot keeps the pivot, it is a joint too)."""
    keep = _structural(mech)
    return tuple(p for p in mech.points_of(link)
                 if p not in centres or p in keep or link == mech.frame_link)


def _joints(mech) -> list[str]:
    """Revolute joints of the moving links (crank pin, dyad joints on pins)."""
    out = []
    for d in mech.dyads:
        kinds = d.kind
        for letter, name in zip(kinds, _pair_points(d), strict=False):
            if letter == "R" and name and name not in out and name not in mech.frame_points:
                out.append(name)
    if mech.crank.pin not in out:
        out.insert(0, mech.crank.pin)
    return out


def _pair_points(d) -> tuple[str | None, ...]:
    """The point of each of a dyad's three pairs (outer, inner, outer); None for a slide."""
    j = d.joints
    pattern = {"RRR": (0, 1, 2), "RRP": (0, 1, None), "RPR": (0, None, 1),
               "PRP": (None, 0, None), "RPP": (0, None, None)}[d.kind]
    return tuple(None if i is None else j[i] for i in pattern)


def _collinear(pts) -> bool:
    a = np.asarray(pts[0])
    far = max(pts, key=lambda q: math.dist(pts[0], q))
    u = np.asarray(far) - a
    n = float(np.hypot(*u))
    if n == 0:
        return True
    return all(abs(float(np.cross(u, np.asarray(q) - a))) / n < 0.05 for q in pts)


def _span(pts) -> tuple[Pt, Pt]:
    best = max(((p, q) for p in pts for q in pts), key=lambda pq: math.dist(*pq))
    return best


def slider_point(mech, kin, k: int, slider: str, G, u) -> str | None:
    """The point of ``slider`` nearest its guide (G, u) at position k: where its block sits.

    Of points equally near the guide (a ram's joint and its centre of mass, both on the
    guide's axis) the block sits at a joint of the slider's dyad, where the next link is
    pinned to it, then at any point but a centre of mass: a block drawn at the centre of
    mass would stand off the rod it is pinned to."""
    names = [p for p in mech.points_of(slider) if p in kin.pos.points]
    if not names:
        return None
    n = np.array([-u[1], u[0]], float)
    joints = {j for d in mech.dyads if slider in d.links for j in _pair_points(d) if j}
    centres = {lp.centre for lp in mech.links.values() if lp.centre}

    def key(p: str) -> tuple[float, bool, bool]:
        off = abs(float(np.dot(kin.pos.points[p][k] - G, n)))
        return round(off, 9), p not in joints, p in centres

    return min(names, key=key)


def _slider_block(mech, kin, k, slider, G, u, P) -> tuple[Pt, ...] | None:
    """Corners of the block of ``slider`` on its guide at position k (paper mm)."""
    name = slider_point(mech, kin, k, slider, G, u)
    if name is None:
        return None
    u = np.asarray(u, float)
    c = np.asarray(P(kin.pos.points[name][k]))
    du = np.array([u[0], -u[1]])  # paper direction (y flipped)
    dn = np.array([-du[1], du[0]])
    hl, hw = SLIDER[0] / 2, SLIDER[1] / 2
    corners = [c + sx * hl * du + sy * hw * dn for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    return tuple((float(q[0]), float(q[1])) for q in corners)


def link_items(mech, kin, k: int, P, style: Style, ident: str, layer: str,
               slots: dict[str, tuple[float, float]] | None = None) -> list[Item]:
    """The moving links at position k: a line per two-point (or straight) link, a closed
    outline for a link with more points; centres of mass are not corners.

    A link carrying a slide (a rocker, a yoke: ``slots`` from
    :func:`graphplan.project.scales.slot_ranges`) is drawn with its slot: the slot's axis over the
    block's travel and the link's own points, and a tie from a point off the axis (a
    pivot offset from the slot) to it. A slider is drawn as its block (:func:`_slider_block`).
    """
    centres = {lp.centre for lp in mech.links.values() if lp.centre}
    items: list[Item] = []
    slots = slots or {}
    for link in mech.moving_links:
        names = _link_outline(mech, link, centres)
        ident_link = f"{ident}-link-{link}"
        if len(names) >= 2:
            pts = [P(kin.pos.points[p][k]) for p in names]
            if len(pts) == 2 or _collinear(pts):
                a, b = _span(pts)
                items.append(Line(a, b, style, layer=layer, id=ident_link))
            else:
                items.append(Polyline(tuple(pts), style, True, layer=layer, id=ident_link))
            ident_link += "-slot"
        for key, (t0, t1) in slots.items():
            if key.split("/")[1] != link:
                continue
            G = np.asarray(kin.pos.guides[key][0][k], float)
            u = np.asarray(kin.pos.guides[key][1][k], float)
            own = [float(np.dot(kin.pos.points[p][k] - G, u)) for p in mech.points_of(link)]
            kl = P.kl
            lo = min([t0 - SLOT_OVER * kl, *own])
            hi = max([t1 + SLOT_OVER * kl, *own])
            items.append(Line(P(G + lo * u), P(G + hi * u), style, layer=layer,
                              id=f"{ident_link}-{key.split('/')[0]}"))
            for p in mech.points_of(link):
                q = kin.pos.points[p][k]
                foot = G + float(np.dot(q - G, u)) * u
                if p not in centres and math.dist(P(q), P(foot)) > 0.5:
                    items.append(Line(P(q), P(foot), style, layer=layer,
                                      id=f"{ident_link}-{key.split('/')[0]}-{p}"))
    return items


def turning_arrow(c: Pt, r: float, start_deg: float, sweep_deg: float, ccw: bool,
                  head_deg: float, *, layer: str, ident: str) -> list[Item]:
    """A turning arrow: an arc about ``c`` from ``start_deg`` over ``sweep_deg`` (as seen)
    with its head at the counter-clockwise end when ``ccw``, else at the start.

    Model angles are sheet angles (the plans are only flipped in y, so counter-clockwise
    stays counter-clockwise). Ids ``{ident}-arc`` and ``{ident}-head``.
    """
    a0, a1 = start_deg, start_deg + sweep_deg
    tip_deg, back = (a1, -1.0) if ccw else (a0, 1.0)
    return [Arc(c, r, a0, a1, THIN, layer=layer, id=f"{ident}-arc"),
            Arrow(arc_point(c, r, tip_deg + back * head_deg), arc_point(c, r, tip_deg), THIN,
                  3.0, 1.0, layer=layer, id=f"{ident}-head")]


SUPPORT_DROP = 8.0  #: height of a fixed pivot's triangle, from the joint to its base, mm


def _support(c: Pt, ident: str, drop: float = SUPPORT_DROP) -> list[Item]:
    """Fixed pivot of the frame: a triangle under the joint and a hatched base ``drop`` mm
    below it (more than SUPPORT_DROP under a crank shorter than its base: clear of its pins)."""
    x, y = c
    tri = ((x, y), (x - 5.0, y + drop), (x + 5.0, y + drop))
    base = ((x - 8.0, y + drop), (x + 8.0, y + drop), (x + 8.0, y + drop + 3.0),
            (x - 8.0, y + drop + 3.0))
    return [Polyline(tri, THIN, True, layer="position_plan", id=f"{ident}-tri"),
            Line(base[0], base[1], MAIN, layer="position_plan", id=f"{ident}-base"),
            Hatch(base, 2.0, 45.0, layer="position_plan", id=f"{ident}-hatch"),
            Circle(c, JOINT_R, WHITE_FILL, layer="position_plan", id=f"{ident}-joint")]
