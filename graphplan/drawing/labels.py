"""Placing the letters of points on a drawing so that they clear each other and the lines.

A draftsman writes a point's letter next to the point, on the side where there is
room, and writes coincident points together (``p, b``). :func:`place_labels` does
the same: labels whose anchors lie within ``merge_mm`` of each other (and share a
``group``) become one text; each text then takes the first free spot of a ring of
candidates around its anchor, nearest first, that overlaps no placed text and
crosses as few lines as possible. Where every spot near the point is crossed by a line
(the centre of a plan of positions, where a dozen cranks meet), a placer asked for
``leaders`` looks farther out for a clear spot and joins the letter to its point with a
thin leader line (выноска, GOST 2.316), as a draftsman does.

Paper coordinates, mm, y down (see :mod:`graphplan.drawing.items`).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry

from .. import fonts
from .items import SLANT_DEG, THIN, Line, Pt, Text, text_at_centre, text_box

#: Directions tried around an anchor (degrees, counter-clockwise as seen), best first.
_DIRECTIONS = (45, 135, -45, -135, 0, 180, 90, -90, 22.5, 157.5, -22.5, -157.5,
               67.5, 112.5, -67.5, -112.5)


@dataclass(frozen=True, slots=True)
class LabelRequest:
    """A letter to write next to a point.

    ``prefer_deg`` (as seen, CCW from +x) is tried first, e.g. away from the
    centre of the figure; ``group`` limits merging to labels of one figure.
    """

    anchor: Pt
    text: str
    height: float = 3.5
    group: str = ""
    prefer_deg: float | None = None


def merge_coincident(requests: Sequence[LabelRequest], merge_mm: float) -> list[LabelRequest]:
    """Join labels of one group whose anchors are closer than ``merge_mm``: ``p, b``."""
    out: list[LabelRequest] = []
    used = [False] * len(requests)
    for i, r in enumerate(requests):
        if used[i]:
            continue
        names = [r.text]
        for j in range(i + 1, len(requests)):
            q = requests[j]
            if not used[j] and q.group == r.group and math.dist(q.anchor, r.anchor) < merge_mm:
                used[j] = True
                if q.text not in names:
                    names.append(q.text)
        out.append(LabelRequest(r.anchor, ", ".join(names), r.height, r.group, r.prefer_deg))
    return out


def place_labels(requests: Sequence[LabelRequest], obstacles: Sequence[BaseGeometry], *,
                 layer: str, id_prefix: str, merge_mm: float = 1.0, gap: float = 0.8,
                 max_radius: float = 14.0, keep_out: Sequence[BaseGeometry] = (),
                 leaders: float = 0.0) -> list[Text | Line]:
    """Texts for ``requests``, clear of each other and, where possible, of the lines.

    Parameters
    ----------
    requests : sequence of LabelRequest
        In order of priority (earlier labels get the better spots).
    obstacles : sequence of shapely geometries
        Lines the texts should not cross (crossing one costs a penalty).
    layer, id_prefix : str
        Layer of the texts and prefix of their ids (``{id_prefix}-{i}``).
    merge_mm : float
        Anchors closer than this (same group) are written as one label.
    gap : float
        Clearance between a text's box and its anchor, mm.
    max_radius : float
        Farthest ring tried before the least bad spot is taken.
    keep_out : sequence of shapely geometries
        Areas a text must not enter at all (other figures, the title block).
    leaders : float
        When no spot within ``max_radius`` is clear of the lines, look up to this far
        (mm) for a clear one and draw a thin leader from the point to the text (0: never;
        the least bad spot near the point is taken).

    Returns
    -------
    list of Text (and of Line: the leaders, ids ``{id_prefix}-{i}-leader``)
    """
    reqs = merge_coincident(requests, merge_mm)
    obst_tree = shapely.STRtree(list(obstacles)) if obstacles else None
    keep_tree = shapely.STRtree(list(keep_out)) if keep_out else None
    placed: list[BaseGeometry] = []
    texts: list[Text | Line] = []
    for n, r in enumerate(reqs):
        probe = text_at_centre((0.0, 0.0), r.text, r.height, layer=layer)
        b0 = text_box(probe)
        x0, y0, x1, y1 = b0.bounds
        half = np.array([(x1 - x0) / 2, (y1 - y0) / 2])
        dirs = list(_DIRECTIONS)
        if r.prefer_deg is not None:
            dirs = [r.prefer_deg, r.prefer_deg + 30, r.prefer_deg - 30, *dirs]
        steps = []
        for d in dirs:
            u = np.array([math.cos(math.radians(d)), -math.sin(math.radians(d))])
            # distance from the anchor to the box's edge along u (the ring is added)
            steps.append((u, min(half[0] / abs(u[0]) if abs(u[0]) > 1e-9 else math.inf,
                                 half[1] / abs(u[1]) if abs(u[1]) > 1e-9 else math.inf)))
        taken = np.asarray(placed, dtype=object)
        found: tuple[float, np.ndarray, BaseGeometry] | None = None  # score, centre, box
        ring = gap
        while ring <= max_radius + 1e-9:
            # the spots of a ring in batches (the first alone: it is often the one), each
            # judged as one by one: no placed text, no kept-out area, fewest lines crossed
            k, clear = 0, False
            while k < len(steps) and not clear:
                batch = steps[k:k + (1 if k == 0 else _BATCH)]
                k += len(batch)
                cs = [np.asarray(r.anchor) + u * (reach + ring) for u, reach in batch]
                boxes = _label_boxes(cs, r)
                free = ~shapely.intersects(boxes[:, None], taken[None, :]).any(axis=1) \
                    if len(taken) else np.ones(len(cs), bool)
                if keep_tree is not None:
                    free &= np.bincount(keep_tree.query(boxes, predicate="intersects")[0],
                                        minlength=len(cs)) == 0
                crossed = (np.bincount(obst_tree.query(boxes, predicate="intersects")[0],
                                       minlength=len(cs)) if obst_tree is not None
                           else np.zeros(len(cs), int))
                for j in np.flatnonzero(free):
                    score = int(crossed[j]) * 10.0 + ring
                    if found is None or score < found[0]:
                        found = (score, cs[j], boxes[j])
                    if crossed[j] == 0:
                        clear = True
                        break
            if found is not None and found[0] < 10.0:
                break
            ring += 1.5
        best: tuple[float, Text, BaseGeometry] | None = None
        if found is not None:
            c = found[1]
            best = (found[0], text_at_centre((float(c[0]), float(c[1])), r.text, r.height,
                                             layer=layer, id=f"{id_prefix}-{n + 1}"), found[2])
        if leaders > 0 and (best is None or best[0] >= 10.0):
            far = _leader_spot(r, dirs, half, max_radius, leaders, placed, obst_tree,
                               keep_tree, layer, f"{id_prefix}-{n + 1}")
            if far is not None:
                t, box, line = far
                placed += [box, line.buffer(0.3)]
                texts += [t, Line(line.coords[0], line.coords[-1], THIN, layer=layer,
                                  id=f"{id_prefix}-{n + 1}-leader")]
                continue
        if best is None and keep_tree is not None:
            # everything near is taken: the least crossed spot farther out, still inside
            # the figure's place (the kept-out area: another cell, the frame)
            ring = max_radius
            while ring <= max_radius + max(leaders, 20.0) + 1e-9:
                for d in [*dirs, *(x + 11.25 for x in _DIRECTIONS)]:
                    u = np.array([math.cos(math.radians(d)), -math.sin(math.radians(d))])
                    c = np.asarray(r.anchor) + u * (ring + float(half.max()))
                    t = text_at_centre((float(c[0]), float(c[1])), r.text, r.height,
                                       layer=layer, id=f"{id_prefix}-{n + 1}")
                    box = text_box(t).buffer(0.3)
                    if any(box.intersects(p) for p in placed) or len(
                            keep_tree.query(box, predicate="intersects")):
                        continue
                    hits = (len(obst_tree.query(box, predicate="intersects"))
                            if obst_tree is not None else 0)
                    if best is None or hits * 10.0 + ring < best[0]:
                        best = (hits * 10.0 + ring, t, box)
                ring += 2.0
        if best is None:  # everything near is taken: go outwards until free
            ring = max_radius
            while best is None:
                ring += 2.0
                u = np.array([math.cos(math.radians(dirs[0])), -math.sin(math.radians(dirs[0]))])
                c = np.asarray(r.anchor) + u * (ring + float(half.max()))
                t = text_at_centre((float(c[0]), float(c[1])), r.text, r.height, layer=layer,
                                   id=f"{id_prefix}-{n + 1}")
                box = text_box(t).buffer(0.3)
                if not any(box.intersects(p) for p in placed):
                    best = (0.0, t, box)
        placed.append(best[2])
        texts.append(best[1])
    return texts


#: spots of a ring judged at once after the first (shapely's vectorised predicates)
_BATCH = 6


def _label_boxes(centres, r: LabelRequest) -> np.ndarray:
    """The boxes, 0.3 mm clear, of ``r``'s text centred on each of ``centres``: the same
    polygons as ``text_box(text_at_centre(c, …)).buffer(0.3)`` (the same arithmetic, in
    arrays; tests/test_labels checks it), made in one call each."""
    h = float(r.height)
    adv = fonts.text_width(r.text, h)
    lean = h * math.tan(math.radians(SLANT_DEG))
    c = np.asarray(centres, dtype=float).reshape(-1, 2)
    x = c[:, 0] + 0.0
    y = c[:, 1] + h / 2
    x0 = x - adv / 2
    return shapely.buffer(shapely.box(x0, y - h, x0 + adv + lean, y + 0.3 * h), 0.3,
                          quad_segs=16)  # as BaseGeometry.buffer


def _leader_spot(r: LabelRequest, dirs, half, start: float, stop: float, placed, obst_tree,
                 keep_tree, layer: str, ident: str):
    """A spot between ``start`` and ``stop`` mm from the anchor whose text and leader cross
    no line, no placed text and no kept-out area (the leader neither): ``(text, box,
    leader)`` or None."""
    from shapely.geometry import LineString, Point

    ring = start
    while ring <= stop + 1e-9:
        for d in [*dirs, *(x + 11.25 for x in _DIRECTIONS)]:
            u = np.array([math.cos(math.radians(d)), -math.sin(math.radians(d))])
            reach = min(half[0] / abs(u[0]) if abs(u[0]) > 1e-9 else math.inf,
                        half[1] / abs(u[1]) if abs(u[1]) > 1e-9 else math.inf)
            c = np.asarray(r.anchor) + u * (reach + ring)
            t = text_at_centre((float(c[0]), float(c[1])), r.text, r.height, layer=layer,
                               id=ident)
            box = text_box(t).buffer(0.3)
            if any(box.intersects(p) for p in placed):
                continue
            if keep_tree is not None and len(keep_tree.query(box, predicate="intersects")):
                continue
            if obst_tree is not None and len(obst_tree.query(box, predicate="intersects")):
                continue
            # the leader: from just off the point to just off the text's box
            a = np.asarray(r.anchor) + u * 2.0
            edge = box.buffer(0.4).exterior
            b = edge.interpolate(edge.project(Point(*r.anchor)))
            line = LineString([tuple(a), (b.x, b.y)])
            if line.length < 1.0 or any(line.intersects(p) for p in placed):
                continue
            if keep_tree is not None and len(keep_tree.query(line, predicate="intersects")):
                continue  # a leader through a kept-out area (a caption) crosses its text
            return t, box, line
        ring += 2.0
    return None
