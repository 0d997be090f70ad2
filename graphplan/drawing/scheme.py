"""The mechanism at one position, small: the picture a lesson shows beside its plan.

The links as sheet 1 draws them (:func:`graphplan.drawing.sheet1.link_items`), sliders as
blocks on their guides, the frame's pivots with their supports, the joints and every
point lettered, fitted into a box of ``width_mm`` × ``height_mm`` at a round scale. Each
item's id names its link (``scheme-link-3``, ``scheme-slider-5-6``), so that a lesson can
draw the link its step is about in colour (:func:`scheme_links`).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace

import numpy as np

from ..units import nice_ceil
from .items import MAIN, Circle, Item, Line, Polyline, Style, Text
from .sheet1 import (
    JOINT_R,
    WHITE_FILL,
    _joints,
    _Paper,
    _slider_block,
    _support,
    link_items,
    slider_point,
)

LAYER = "position_plan"
_PAD = 14.0  #: room around the links for the supports and the letters, mm


def scheme_paper(analysis, k: int, width_mm: float = 120.0,
                 height_mm: float = 90.0) -> Callable[[object], tuple[float, float]]:
    """Model metres → the mm of :func:`mechanism_scheme`'s box (y down): the mechanism at
    position ``k`` centred in the box at the round Kl that fits it with a margin,
    ``(x, y) = origin + ((X, Y) − O)·(1, −1) / Kl``."""
    mech, kin = analysis.mech, analysis.kin
    allp = np.array([p[k] for p in kin.pos.points.values()]
                    + [np.asarray(v, float) for v in mech.frame_points.values()])
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    ext = np.maximum(hi - lo, 1e-9)
    kl = nice_ceil(float(np.max(ext / (np.array([width_mm, height_mm]) - 2 * _PAD))))
    pivot = np.asarray(kin.pos.points[mech.crank.pivot][k], float)
    mid = (lo + hi) / 2
    origin = (width_mm / 2 + float(pivot[0] - mid[0]) / kl,
              height_mm / 2 - float(pivot[1] - mid[1]) / kl)
    return _Paper(origin, kl, pivot)


def mechanism_scheme(analysis, k: int, width_mm: float = 120.0,
                     height_mm: float = 90.0) -> tuple[Item, ...]:
    """The mechanism at position ``k`` in a box (0, 0)–(width_mm, height_mm), y down."""
    mech, kin = analysis.mech, analysis.kin
    pts = {n: p[k] for n, p in kin.pos.points.items()}
    P = scheme_paper(analysis, k, width_mm, height_mm)
    items: list[Item] = list(link_items(mech, kin, k, P, MAIN, "scheme", LAYER))
    for key, (G, u) in kin.pos.guides.items():
        slider, carrier = key.split("/")
        corners = _slider_block(mech, kin, k, slider, G[k], u[k], P)
        if corners:
            items.append(Polyline(corners, Style(0.5, fill="white"), True, layer=LAYER,
                                  id=f"scheme-slider-{slider}-{carrier}"))
        if carrier == mech.frame_link:
            d = np.array([u[k][0], -u[k][1]])
            at = pts[slider_point(mech, kin, k, slider, G[k], u[k])]
            c = np.asarray(P(G[k] + np.dot(at - G[k], u[k]) * u[k]))
            items.append(Line(tuple(c - 12 * d), tuple(c + 12 * d), Style(0.25, (15, 3, 1, 3)),
                              layer=LAYER, id=f"scheme-guide-{slider}"))
    for fp, xy in mech.frame_points.items():
        items += [replace(it, layer=LAYER) for it in _support(P(xy), f"scheme-sup-{fp}")]
    for j in _joints(mech):
        items.append(Circle(P(pts[j]), JOINT_R, WHITE_FILL, layer=LAYER,
                            id=f"scheme-joint-{j}"))
    centres = {lp.centre for lp in mech.links.values() if lp.centre}
    for name, xy in pts.items():
        x, y = P(xy)
        items.append(Text((x + 2.0, y - 2.0), name, 2.5 if name in centres else 5.0,
                          layer=LAYER, id=f"scheme-label-{name}"))
    return tuple(items)


_LINK_ID = re.compile(r"^scheme-(?:link|slider)-(\w+?)(?:-|$)")


def scheme_links(item: Item) -> str | None:
    """The link an item of :func:`mechanism_scheme` draws (None for joints, labels…)."""
    m = _LINK_ID.match(getattr(item, "id", "") or "")
    return m.group(1) if m else None


__all__ = ["mechanism_scheme", "scheme_links"]
