"""Sheet 1's schemes: the mechanism in each analysed position with the angular velocity ω
and the angular acceleration ε of its links, and the structural scheme — the initial
mechanism and each Assur group drawn apart, as the structural analysis splits them.

Each scheme is drawn at its own length scale from the usual series (GOST 2.302), large
enough to fill its cell (:class:`graphplan.project.layout.Sheet1Layout`: ``schemes``,
``groups``). The senses of ω and ε are the solver's signs (counter-clockwise positive,
the plans flip only y, so counter-clockwise stays counter-clockwise on paper); a link
that does not turn (a slider) gets no arrow, nor an ε of a crank turning uniformly.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from ..numbers import plain
from ..paper import Rect
from ..project import CAPTION
from ..units import nice_ceil
from .items import (
    MAIN,
    Circle,
    Hatch,
    Item,
    Line,
    Polyline,
    Pt,
    Style,
    Text,
    arc_point,
    item_geometry,
    iter_leaves,
    text_at_centre,
    text_box,
    text_width,
)
from .labels import LabelRequest, place_labels
from .linkage import (
    JOINT_R,
    SLIDER,
    WHITE_FILL,
    _joints,
    _Paper,
    _slider_block,
    _support,
    link_items,
    turning_arrow,
)

L = "position_plan"
MARGIN = 12.0  #: room around a scheme for its arrows and letters, mm
CAPTION_GAP = 9.0  #: from the foot of a scheme's caption (its scale) to the scheme's top, mm
OMEGA_R, EPS_R = 5.0, 8.5  #: radii of the arrows of ω and ε, mm
TURNING = 1e-9  #: |ω|, |ε| below this: the link does not turn (rad/s, rad/s²)
#: The schemes' length scales, m/mm: GOST 2.302's scales — enlargements 100:1 … 2:1, natural
#: 1:1, reductions 1:2 … 1:1000 (1:15 is 0.015 m/mm; 1:1.5 and 1:7.5 are not among them)
GOST_SCALES = tuple(0.001 * r for r in (
    0.01, 0.02, 0.025, 0.05, 0.1, 0.2, 0.25, 0.4, 0.5, 1.0, 2.0, 2.5, 4.0, 5.0, 10.0, 15.0,
    20.0, 25.0, 40.0, 50.0, 75.0, 100.0, 200.0, 400.0, 500.0, 800.0, 1000.0))


def gost_scale(need: float) -> float:
    """The finest scale of GOST 2.302 (m/mm) at least ``need``: a drawing ``need`` m/mm
    fits drawn at it (beyond 1:1000, ``need`` rounded up to the 1, 2, 5 series)."""
    for kl in GOST_SCALES:
        if kl >= need * (1 - 1e-9):
            return kl
    return nice_ceil(need, (1.0, 2.0, 5.0))


WORDS = {
    "ru": {"scheme": "ω и ε звеньев, пол. {k}", "groups": "Структурная схема: группы Ассура",
           "scale": "Kl = {v} м/мм"},
    "en": {"scheme": "ω and ε of the links, pos. {k}",
           "groups": "Structural scheme: the Assur groups", "scale": "Kl = {v} m/mm"},
}


def _fit(points: np.ndarray, room_w: float, room_h: float) -> float:
    """Length scale (m/mm) from the usual series that fits ``points`` into the room."""
    w, h = np.ptp(points, axis=0)
    need = max(float(w) / max(room_w, 1.0), float(h) / max(room_h, 1.0), 1e-12)
    return gost_scale(need)


def _drawn_to_fit(points: np.ndarray, box: Rect, draw, kl: float | None = None,
                  slack: float = 0.0):
    """``draw(P)`` at the finest scale of the series (or at ``kl``) whose drawing — blocks,
    slots and guides included, which the points alone do not bound — fits ``box`` grown by
    ``slack`` mm on every side (the margin kept round it may take that much), centred in
    it: ``(kl, P, items)``."""
    kl = _fit(points, box.width, box.height) if kl is None else kl
    best: tuple[float, float, _Paper] | None = None  # (overflow, kl, P) of the scale before
    for _ in range(6):
        P = _centred(points, kl, box)
        items = draw(P)
        geoms = [g for it in iter_leaves(items) if (g := item_geometry(it)) is not None]
        x0, y0, x1, y1 = shapely.union_all(geoms).bounds if geoms else (0, 0, 0, 0)
        dx = (box.x0 + box.x1) / 2 - (x0 + x1) / 2
        dy = (box.y0 + box.y1) / 2 - (y0 + y1) / 2
        P = _Paper((P.ox + dx, P.oy + dy), kl, P.pivot)
        over = max(x1 - x0 - box.width, y1 - y0 - box.height)
        if over <= 2.0 * slack + 1e-6:
            return kl, P, draw(P)
        if best is not None and over > best[0] - 0.5 and best[0] <= MARGIN / 2:
            # a coarser scale does not shrink it: what overflows is drawn at a fixed paper
            # size (a guide's hatched strip, a block), not the links — keep the scale before,
            # into at most half the margin kept round the box, rather than draw the links as
            # blobs (a rotating кулиса's scheme went to Kl 0.15 m/mm, the press's groups 0.01)
            return best[1], best[2], draw(best[2])
        best = (over, kl, P)
        kl = gost_scale(kl * 1.01)
    return kl, P, draw(P)


def _centred(points: np.ndarray, kl: float, box: Rect) -> _Paper:
    """Paper mapping that centres ``points`` (m) in ``box`` at ``kl``."""
    lo, hi = points.min(axis=0), points.max(axis=0)
    mid = (lo + hi) / 2
    return _Paper(((box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2), kl, mid)


def _frame_guides(mech, kin, k: int, P: _Paper, links: set[str], ident: str) -> list[Item]:
    """The frame's guides of the sliders among ``links`` at position k: the axis over the
    block and a hatched strip on one side."""
    items: list[Item] = []
    for key, (G, u) in kin.pos.guides.items():
        slider, carrier = key.split("/")
        if carrier != mech.frame_link or slider not in links:
            continue
        corners = _slider_block(mech, kin, k, slider, G[k], u[k], P)
        if not corners:
            continue
        c = np.mean(np.asarray(corners), axis=0)
        d = np.array([u[k][0], -u[k][1]], float)
        d /= float(np.hypot(*d))
        n = np.array([-d[1], d[0]])
        half = SLIDER[0] * 1.3
        a, b = c - half * d, c + half * d
        off1, off2 = n * (SLIDER[1] / 2 + 0.5), n * (SLIDER[1] / 2 + 3.0)
        strip = (tuple(a + off1), tuple(b + off1), tuple(b + off2), tuple(a + off2))
        items.append(Line(tuple(a + off1), tuple(b + off1), MAIN, layer=L,
                          id=f"{ident}-guide-{slider}-edge"))
        items.append(Hatch(strip, 2.0, 45.0, layer=L, id=f"{ident}-guide-{slider}-hatch"))
    return items


def _mechanism(mech, kin, k: int, P: _Paper, links: set[str], slots, ident: str
               ) -> list[Item]:
    """Links ``links`` at position k in main line: bars, slots, blocks, joints, supports."""
    items: list[Item] = [it for it in link_items(mech, kin, k, P, MAIN, ident, L, slots)
                         if any((it.id or "").startswith(f"{ident}-link-{n}") for n in links)]
    items += _frame_guides(mech, kin, k, P, links, ident)
    for key, (G, u) in kin.pos.guides.items():
        slider = key.split("/")[0]
        if slider not in links:
            continue
        corners = _slider_block(mech, kin, k, slider, G[k], u[k], P)
        if corners:
            items.append(Polyline(corners, Style(MAIN.width, fill="white"), True, layer=L,
                                  id=f"{ident}-slider-{key.replace('/', '-')}"))
    own = {p for n in links for p in mech.points_of(n)}
    for p in _joints(mech):
        if p in own:
            items.append(Circle(P(kin.pos.points[p][k]), JOINT_R, WHITE_FILL, layer=L,
                                id=f"{ident}-joint-{p}"))
    for fp in mech.frame_points:
        if fp in own:
            items += _support(P(mech.frame_points[fp]), f"{ident}-support-{fp}")
    return items


def _turn_centre(mech, kin, k: int, link: str, P: _Paper) -> Pt:
    """Where a link's arrows turn: about its pivot on the frame, else about the middle of
    its points."""
    pts = mech.points_of(link)
    fixed = [p for p in pts if p in mech.frame_points]
    if fixed:
        return P(mech.frame_points[fixed[0]])
    q = np.array([kin.pos.points[p][k] for p in pts if p in kin.pos.points])
    return P(q.mean(axis=0))


def _link_direction(mech, kin, k: int, link: str) -> float:
    """Direction (degrees, as seen) of a link at position k: its two farthest points."""
    pts = [kin.pos.points[p][k] for p in mech.points_of(link) if p in kin.pos.points]
    if len(pts) < 2:
        return 0.0
    a, b = max(((p, q) for p in pts for q in pts), key=lambda pq: float(np.hypot(*(pq[0] - pq[1]))))
    return math.degrees(math.atan2(b[1] - a[1], b[0] - a[0]))


def scheme_items(analysis, slots, k: int, cell: Rect, lang: str, ident: str) -> list[Item]:
    """The mechanism at position k with the curved arrows of ω and ε of every turning link,
    lettered ω2, ε2 … (their values are in the table of the plans)."""
    mech, kin = analysis.mech, analysis.kin
    w = WORDS[lang]
    box = Rect(cell.x0 + MARGIN, cell.y0 + CAPTION + MARGIN, cell.x1 - MARGIN,
               cell.y1 - MARGIN)
    pts = np.array([kin.pos.points[p][k] for p in kin.pos.points])
    kl, P, items = _drawn_to_fit(
        pts, box, lambda P: _mechanism(mech, kin, k, P, set(mech.moving_links), slots, ident))
    labels: list[LabelRequest] = []
    for link in mech.moving_links:
        om = float(kin.vel.omega[link][k])
        ep = float(kin.acc.epsilon[link][k])
        c = _turn_centre(mech, kin, k, link, P)
        base = _link_direction(mech, kin, k, link) + 35.0
        for r, val, sym, start in ((OMEGA_R, om, "ω", base), (EPS_R, ep, "ε", base + 180.0)):
            if abs(val) < TURNING:
                continue
            items += turning_arrow(c, r, start, 110.0, val > 0, 30.0, layer=L,
                                   ident=f"{ident}-{sym}{link}")
            labels.append(LabelRequest(arc_point(c, r + 1.0, start + 55.0), f"{sym}{link}", 3.5,
                                       group=ident))
    for p in mech.points_of(mech.crank.link) + tuple(q for d in mech.dyads for q in d.joints):
        if p in kin.pos.points:
            labels.append(LabelRequest(P(kin.pos.points[p][k]), p, 3.5, group=f"{ident}-pt"))
    return _lettered(items, labels, cell, w["scheme"].format(k=kin.labels[k]),
                     w["scale"].format(v=plain(kl)), ident)


def groups_items(analysis, slots, cell: Rect, lang: str, ident: str = "groups") -> list[Item]:
    """The structural scheme at the first position: the initial mechanism I(0,1) and each
    Assur group drawn apart, side by side at one scale, each under its formula."""
    mech, kin = analysis.mech, analysis.kin
    st = analysis.structure
    k = 0
    w = WORDS[lang]
    pieces = [(f"I({st.initial[0]},{st.initial[1]})", {mech.crank.link})]
    pieces += [(g.formula, set(g.links)) for g in st.groups]
    n = len(pieces)
    table, table_w = pairs_table(st, cell, n, lang, ident)
    # the pieces side by side, or in rows where the cell is too narrow for them in one
    avail = cell.width - 4.0 - table_w
    cols = max(1, min(n, int(avail // PIECE_MIN_W)))
    row_h = (cell.height - CAPTION) / math.ceil(n / cols)
    if row_h < ROW_MIN:  # too low for rows: side by side, however narrow
        cols, row_h = n, cell.height - CAPTION
    slot_w = avail / cols

    def points_of(links):
        names = {p for lk in links for p in mech.points_of(lk)}
        return np.array([kin.pos.points[p][k] for p in names if p in kin.pos.points])

    # the margin round each piece: MARGIN, but at most 15 % of a narrow slot (three pieces in
    # a 100 mm cell left 8 mm of box each: the slotter's groups went to Kl 0.25, 2 mm blobs)
    gm = min(MARGIN, 0.15 * slot_w)
    boxes = [Rect(cell.x0 + 2.0 + c * slot_w + gm, cell.y0 + CAPTION + r * row_h + MARGIN,
                  cell.x0 + 2.0 + (c + 1) * slot_w - gm,
                  cell.y0 + CAPTION + (r + 1) * row_h - MARGIN - 5.0)
             for r, c in (divmod(i, cols) for i in range(n))]

    def draw(i, links):
        return lambda P: _mechanism(mech, kin, k, P, links, slots, f"{ident}-{i}")

    # one scale for all the pieces: the coarsest any of them needs
    kl = max(_drawn_to_fit(points_of(links), boxes[i], draw(i, links), slack=gm / 2)[0]
             for i, (_, links) in enumerate(pieces))
    items: list[Item] = []
    labels: list[LabelRequest] = []
    for i, (formula, links) in enumerate(pieces):
        box = boxes[i]
        _, P, drawn = _drawn_to_fit(points_of(links), box, draw(i, links), kl, slack=gm / 2)
        items += drawn
        geoms = [g for it in iter_leaves(drawn) if (g := item_geometry(it)) is not None]
        under = shapely.union_all(geoms).bounds[3] + 7.0 if geoms else cell.y1 - 4.0
        items.append(text_at_centre(((box.x0 + box.x1) / 2, min(under, box.y1 + MARGIN + 1.0)),
                                    formula, 3.5, layer="text", id=f"{ident}-{i}-formula"))
        own = {p for lk in links for p in mech.points_of(lk)}
        for p in sorted(own):
            if p in kin.pos.points and (p in mech.frame_points or p in _joints(mech)
                                        or any(p in d.joints for d in mech.dyads)):
                labels.append(LabelRequest(P(kin.pos.points[p][k]), p, 3.5, group=f"{ident}-{i}"))
    return [*_lettered(items, labels, cell, w["groups"], w["scale"].format(v=plain(kl)), ident),
            *table]


PAIRS_ROW = 5.0  #: row height of the table of the kinematic pairs (2.5 mm lettering), mm
PIECE_MIN_W = 60.0  #: the least width of a piece of the structural scheme beside the table, mm
ROW_MIN = 2 * MARGIN + 35.0  #: the least height of a row of the structural scheme's pieces, mm
PAIR_WORDS = {
    "ru": {"title": "Кинематические пары", "R": "вращ.", "P": "поступ."},
    "en": {"title": "Kinematic pairs", "R": "revolute", "P": "prismatic"},
}
PAIR_HEADER = {"ru": ["Пара", "Звенья", "Вид", "Класс"], "en": ["Pair", "Links", "Kind", "Class"]}


def pairs_table(structure, cell: Rect, n_pieces: int, lang: str, ident: str
                ) -> tuple[list[Item], float]:
    """The table of the kinematic pairs the structural analysis counts (W = 3n − 2p5 − p4:
    each pair, the links it joins, revolute or prismatic, its class), in the right of the
    structural scheme's cell when the cell holds it beside ``n_pieces`` pieces at least
    PIECE_MIN_W wide: ``(items, width taken)``, or ``([], 0)``."""
    from .items import Text
    from .tables import table_items

    w = PAIR_WORDS[lang]
    rows = [[p.joint or "—", "–".join(p.links), w[p.kind], "5"] for p in structure.pairs]
    widths = [max(text_width(Text((0, 0), str(c), 2.5, layer="tables")) for c in col) + 3.0
              for col in zip(PAIR_HEADER[lang], *rows, strict=False)]
    table_w = sum(widths)
    height = CAPTION + 4.0 + PAIRS_ROW * (len(rows) + 1)
    if (cell.width - 4.0 - table_w - 6.0 < n_pieces * PIECE_MIN_W
            or cell.height - CAPTION < height):
        return [], 0.0
    x0 = cell.x1 - table_w - 2.0
    y0 = cell.y0 + CAPTION + 4.0
    out: list[Item] = [Text((x0, y0 + 3.5), w["title"], 3.5, layer="text",
                            id=f"{ident}-pairs-title")]
    out += table_items((x0, y0 + 5.0), widths, rows, PAIR_HEADER[lang], 2.5, row_height=PAIRS_ROW,
                       id=f"{ident}-pairs")
    return out, table_w + 6.0


def _lettered(items: list[Item], labels: list[LabelRequest], cell: Rect, caption: str,
              scale: str, ident: str) -> list[Item]:
    """``items`` with their letters placed clear of the lines, the caption over the cell
    and the scale in its bottom-left corner."""
    from shapely.geometry import box as shp_box

    obstacles = [g for it in iter_leaves(items) if (g := item_geometry(it)) is not None
                 and not isinstance(it, Hatch)]
    # the caption and the scale over the drawing (CAPTION_GAP above its top), not at the top
    # of a cell the drawing does not fill (a scheme 60 mm under its caption)
    top = min((g.bounds[1] for g in obstacles), default=cell.y0)
    y = max(cell.y0, top - CAPTION_GAP - CAPTION - 1.5)
    head = text_at_centre(((cell.x0 + cell.x1) / 2, y + CAPTION / 2), caption, 3.5,
                          layer="text", id=f"{ident}-caption")
    foot = text_at_centre(((cell.x0 + cell.x1) / 2, y + CAPTION + 1.5), scale, 2.5,
                          layer="text", id=f"{ident}-scale")
    outside = shp_box(cell.x0 - 500, cell.y0 - 500, cell.x1 + 500, cell.y1 + 500).difference(
        shp_box(cell.x0 + 0.5, cell.y0 + 0.5, cell.x1 - 0.5, cell.y1 - 0.5))
    keep = [outside, text_box(head).buffer(0.8), text_box(foot).buffer(0.8)]
    # the texts already there (the groups' formulas under their pieces) are kept clear too
    keep += [text_box(it).buffer(0.8) for it in iter_leaves(items) if isinstance(it, Text)]
    items += place_labels(labels, obstacles, layer=L, id_prefix=f"{ident}-t", merge_mm=1.0,
                          keep_out=keep, leaders=20.0)
    return [*items, head, foot]


__all__ = ["groups_items", "scheme_items"]
