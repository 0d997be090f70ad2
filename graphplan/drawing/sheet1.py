"""Sheet 1, kinematic analysis: the plan of positions, the velocity and acceleration
plans of every position, the kinematic diagrams and the table of the plans.

Everything is drawn from the constructions (:mod:`graphplan.plans.constructions`): the
plan points are the intersections the draftsman gets, placed on paper by a pure
translation and the flip of y (the plans are built with y up, paper is y down).
Styles (GOST 2.303): the first position in main line, the other positions thin,
the extreme (dead-centre) positions dash-dot-dot, trajectories and axes dash-dot,
vectors of the plans 0.5 mm with filled arrowheads, construction lines thin.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from shapely.geometry import Polygon

from ..kinematics import link_coordinate, output_coordinate, translating_links
from ..paper import Page, Rect
from ..plans import Plan
from ..project import (
    CAPTION,
    GAP,
    PLAN_MARGIN,
    STRUCTURE_LINE,
    TABLE_PAD,
    Sheet1Scales,
    fit_columns,
    kinematic_twin,
)
from .items import (
    DASHDOT,
    DASHDOTDOT,
    MAIN,
    MEDIUM,
    THIN,
    Arc,
    Arrow,
    Circle,
    Group,
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
    SUPPORT_DROP,
    _joints,
    _Paper,
    _slider_block,
    _support,
    link_items,
    turning_arrow,
)
from .linkage import (  # re-exported: sheet 2 and the lessons' schemes import them from here
    WHITE_FILL as WHITE_FILL,
)
from .linkage import (
    _pair_points as _pair_points,
)
from .linkage import (
    slider_point as slider_point,
)
from .sheet import Sheet
from .tables import titled_table
from .title_block import TitleBlock, signatures

WORDS = {
    "ru": {"positions": "План положений", "velocity": "План скоростей",
           "acceleration": "План ускорений", "pos": "пол.", "scales": "Масштабные коэффициенты",
           "table": "Таблица планов", "sheet": "Кинематический анализ"},
    "en": {"positions": "Plan of positions", "velocity": "Velocity plan",
           "acceleration": "Acceleration plan", "pos": "pos.", "scales": "Scale factors",
           "table": "Table of the plans", "sheet": "Kinematic analysis"},
}




def _label(name: str) -> str:
    return name.replace("_", "")


def _arm_label(name: str) -> str:
    """The letter of a lever's arm ``h_<force>``: hG2, hPи3; h(F'Mи2) where the force's
    own name has a stroke (hF'Mи2 would read as h with the index F)."""
    force = name.removeprefix("h_")
    return f"h({force})" if "'" in force else f"h{force}"


# ------------------------------------------------------------------ plan of positions


def _position_styles(analysis) -> list[Style]:
    """Main line for the first position, dash-dot-dot at a dead centre, thin otherwise."""
    dead = [d % (2 * math.pi) for d in analysis.cycle.dead_centres]
    styles = []
    for k, phi in enumerate(analysis.kin.phi):
        at_dead = any(abs((phi - d + math.pi) % (2 * math.pi) - math.pi) < 1e-6 for d in dead)
        styles.append(MAIN if k == 0 else DASHDOTDOT if at_dead else THIN)
    return styles






def position_plan_items(analysis, sc: Sheet1Scales, lang: str) -> list[Item]:
    """The plan of positions: all positions, trajectories, guides, frame supports, letters."""
    mech, kin = analysis.mech, analysis.kin
    box = sc.layout.plan_box
    ext = sc.extent_m
    kl = sc.kl.per_mm
    origin = (box.x0 + PLAN_MARGIN - ext[0] / kl, box.y0 + PLAN_MARGIN + ext[3] / kl)
    pivot = kin.pos.points[mech.crank.pivot][0]
    P = _Paper(origin, kl, pivot)
    L = "position_plan"
    items: list[Item] = []
    labels: list[LabelRequest] = []
    centres = {lp.centre for lp in mech.links.values() if lp.centre}
    styles = _position_styles(analysis)
    paths = sc.paths
    assert paths is not None  # sheet_scales keeps the trajectories it measured
    # numbered in every position: the crank pin, the output's point and the point of every
    # other slider on a frame guide (the second piston of a two-cylinder machine)
    numbered = [mech.crank.pin, output_coordinate(mech, kin.pos)[3]]
    for key in kin.pos.guides:
        slider, carrier = key.split("/")
        if carrier == mech.frame_link:
            p = link_coordinate(mech, slider, kin.pos)[3]
            if p not in numbered:
                numbered.append(p)

    # trajectories of the centres of mass (closed curves), of the crank pin, and of every
    # point a load acts at or a coupler point of [[points]] (a kneading arm's end E: the
    # machine's working loop) on a link that turns and moves (not on the crank, nor a slider);
    # a loaded point there is numbered in every position as the output's point is
    moving = set(mech.moving_links) - translating_links(mech) - {mech.crank.link}
    traced = centres | {mech.crank.pin} | _traced_points(mech, moving)
    numbered += sorted(r.point for r in mech.resistances
                       if r.point and r.link in moving and r.point not in numbered)
    for name in sorted(traced):
        if name not in paths or name in mech.frame_points:
            continue
        pts = [P(q) for q in paths[name][:-1]]
        if max(math.dist(pts[0], q) for q in pts) < 0.5:
            continue
        items.append(Polyline(tuple(pts), DASHDOT, True, layer=L, id=f"pp-path-{name}"))

    # guides on the frame: the axis over the slider's travel and a hatched strip
    for key, (G, u) in kin.pos.guides.items():
        slider, carrier = key.split("/")
        if carrier != mech.frame_link:
            continue
        d = np.asarray(u[0], float)
        base = np.asarray(G[0], float)
        s = [float(np.dot(paths[p] - base, d).min()) for p in mech.points_of(slider)]
        e = [float(np.dot(paths[p] - base, d).max()) for p in mech.points_of(slider)]
        t0, t1 = min(s) - 12 * kl, max(e) + 12 * kl
        a, b = P(base + t0 * d), P(base + t1 * d)
        items.append(Line(a, b, DASHDOT, layer=L, id=f"pp-guide-{slider}"))
        n = np.array([-(b[1] - a[1]), b[0] - a[0]]) / math.dist(a, b)
        off1, off2 = n * (SLIDER[1] / 2 + 0.5), n * (SLIDER[1] / 2 + 3.0)
        strip = (tuple(np.add(a, off1)), tuple(np.add(b, off1)), tuple(np.add(b, off2)),
                 tuple(np.add(a, off2)))
        items.append(Line(strip[0], strip[1], MAIN, layer=L, id=f"pp-guide-{slider}-edge"))
        items.append(Hatch(strip, 2.0, 45.0, layer=L, id=f"pp-guide-{slider}-hatch"))

    # the frame's supports under the links; the pivot of a crank whose pins' circle would
    # cross its base (a base 16 mm wide, 3 mm deep: a crank under 15 mm) stands below them
    ring = mech.crank.length / kl
    low = ring + JOINT_R + 1.5 if ring < SUPPORT_DROP + 7.0 else SUPPORT_DROP
    pivots: list[Item] = []  # the supports' joint circles, drawn over the links
    for fp in mech.frame_points:
        for it in _support(P(mech.frame_points[fp]), f"pp-support-{fp}",
                           max(SUPPORT_DROP, low) if fp == mech.crank.pivot else SUPPORT_DROP):
            (pivots if isinstance(it, Circle) else items).append(it)
    # the links in every position; the main position (0) last, on top of the others
    for k in [*range(1, kin.n), 0]:
        st = styles[k]
        items += link_items(mech, kin, k, P, st, f"pp-{k}", L, sc.slots)
        for key, (G, u) in kin.pos.guides.items():
            slider = key.split("/")[0]
            corners = _slider_block(mech, kin, k, slider, G[k], u[k], P)
            if corners:
                items.append(Polyline(corners, Style(st.width, st.dasharray, fill="white"), True,
                                      layer=L, id=f"pp-{k}-slider-{key.replace('/', '-')}"))
        for p in _joints(mech):
            items.append(Circle(P(kin.pos.points[p][k]), JOINT_R,
                                Style(0.35 if st is not MAIN else 0.5, fill="white"),
                                layer=L, id=f"pp-{k}-joint-{p}"))
        for c in sorted(centres):
            if c in kin.pos.points:
                items.append(Circle(P(kin.pos.points[c][k]), 0.8, Style(0.25, fill="black"),
                                    layer=L, id=f"pp-{k}-centre-{c}"))
        # position numbers at the crank pin and at the output point
        for p in numbered:
            q = P(kin.pos.points[p][k])
            centre = P(pivot)
            away = math.degrees(math.atan2(-(q[1] - centre[1]), q[0] - centre[0]))
            labels.append(LabelRequest(q, f"{p}{kin.labels[k]}" if p != mech.crank.pin
                                       else kin.labels[k], 3.5, group=f"num-{p}",
                                       prefer_deg=away))

    items += pivots
    items += _rotation_arrow(P(pivot), mech.crank, float(kin.phi[0]), kl)
    labels += _stroke_arcs(analysis, P(pivot), kl, lang, items)
    labels.insert(0, LabelRequest(_rotation_label_anchor(P(pivot), mech.crank, float(kin.phi[0]),
                                                         kl), "ω1", 5.0, group="omega"))
    # letters of the first position
    first = 0
    pc = P(pivot)
    for p in mech.frame_points:
        labels.insert(0, LabelRequest(P(mech.frame_points[p]), p, 5.0, group="letters"))
    for link in mech.moving_links:
        for p in mech.points_of(link):
            if p in mech.frame_points:
                continue
            q = P(kin.pos.points[p][first])
            away = math.degrees(math.atan2(-(q[1] - pc[1]), q[0] - pc[0]))
            labels.insert(len(mech.frame_points), LabelRequest(q, p, 5.0, group="letters",
                                                               prefer_deg=away))
    labels = _dedupe(labels)
    obstacles = [g for it in iter_leaves(items) if (g := item_geometry(it)) is not None
                 and not isinstance(it, Hatch)]
    w = WORDS[lang]
    col = sc.layout.column or sc.layout.diagrams  # the caption keeps to the left column
    cap_text = f"{w['positions']}   {_units(sc.kl.basis, lang)}"
    cap_h = next((h for h in (5.0, 3.5, 2.5)
                  if text_width(Text((0, 0), cap_text, h, layer="text")) <= col.x1 - box.x0),
                 2.5)
    page = sc.layout.page
    others = [c.polygon() for c in (*sc.layout.schemes, sc.layout.groups) if c is not None]
    caption = _clear_caption(box, cap_text, cap_h, obstacles,
                             [page.graph26_rect.polygon(), *others], (col.x0, col.x1))
    margin = page.trim.polygon().buffer(500.0).difference(page.frame.polygon().buffer(-1.0))
    keep = [text_box(caption).buffer(1.0), page.graph26_rect.polygon(), margin, *others]
    # a letter on a guide's hatching is read badly (the B2…B10 of a pump's slider stood on
    # it): the hatching is a line to keep clear of, where the letters have room
    hatched = [Polygon(it.polygon) for it in iter_leaves(items) if isinstance(it, Hatch)]
    items += place_labels(labels, [*obstacles, *hatched], layer=L, id_prefix="pp-label",
                          merge_mm=1.2,
                          keep_out=keep, leaders=60.0)
    items.append(caption)
    return items


def _traced_points(mech, moving: set[str]) -> set[str]:
    """The points whose trajectory the plan of positions draws besides the centres of mass:
    a load's point and a coupler point (of [[points]], not a joint of a pair) on a link of
    ``moving``."""
    loaded = {r.point for r in mech.resistances if r.point and r.link in moving}
    joints = set(_joints(mech)) | set(mech.frame_points)
    coupler = {p.name for p in mech.points if p.link in moving and p.name not in joints}
    return loaded | coupler


def _clear_caption(box: Rect, text: str, h: float, obstacles, avoid,
                   span: tuple[float, float]) -> Text:
    """The caption of the plan of positions at the top left of its box, or, where a line
    of the plan runs there (a guide reaching up), the first place along the box's top
    (a little above it too, clear of ``avoid``: graph 26) and bottom that no line crosses."""
    from shapely import STRtree

    tree = STRtree(list(obstacles) + list(avoid))
    w = text_width(Text((0, 0), text, h, layer="text"))
    lo, hi = min(box.x0, span[0]), max(box.x1, span[1])  # the column the box is in
    xs = [box.x0] + ([lo + i * (hi - lo - w) / 8 for i in range(9)] if hi - lo > w else [])
    spots = [(x, y) for y in (box.y0 + 2.0, box.y0 - 1.0, box.y0 - 3.0, box.y1 - 1.0)
             for x in xs]
    for x, y in spots:
        t = Text((x, y), text, h, layer="text", id="pp-caption")
        if not len(tree.query(text_box(t).buffer(0.5), predicate="intersects")):
            return t
    return Text(spots[0], text, h, layer="text", id="pp-caption")


def _dedupe(reqs: list[LabelRequest]) -> list[LabelRequest]:
    seen, out = set(), []
    for r in reqs:
        key = (r.text, r.group, round(r.anchor[0], 1), round(r.anchor[1], 1))
        if key not in seen:
            seen.add(key)
            out.append(r)
    return out


















ARC_OFFSET = 7.0  #: the arcs of the working and idle strokes run this far outside the crank circle
ARC_GAP = 2.5  #: and stop this far short of the dead centres, mm
ARC_HEADS = 20.0  #: arcs of this radius (mm) and more end in arrowheads


def _stroke_arcs(analysis, c: Pt, kl: float, lang: str, items: list) -> list[LabelRequest]:
    """The crank's arcs of the working (р.х.) and idle (х.х.) strokes between the dead
    centres, thin, outside the crank circle (appended to ``items``); their letters."""
    cy, cr = analysis.cycle, analysis.mech.crank
    if not cy.dead_centres:
        return []
    r = cr.length / kl + ARC_OFFSET
    start = math.degrees(cy.dead_centres[0])
    work = math.degrees(cy.working_turn)
    full = math.degrees(cy.period) if cy.period <= 2 * math.pi + 1e-9 else 360.0
    sense = cr.sense
    names = ("р.х.", "х.х.") if lang == "ru" else ("w.s.", "i.s.")
    # each arc stops ARC_GAP mm short of the dead centres and ends in an arrowhead in the
    # sense of rotation: two arcs with ends, not one thin circle round the crank circle;
    # round a short crank (an arc under ARC_HEADS mm) the heads would crowd its numbers:
    # plain arcs 2° short of the dead centres there
    heads = r >= ARC_HEADS
    gap = math.degrees(ARC_GAP / r) if heads else 2.0
    out = []
    for n, (a0, sweep) in enumerate(((start, work), (start + sense * work, full - work))):
        lo, hi = (a0, a0 + sweep) if sense > 0 else (a0 - sweep, a0)
        if hi - lo <= 2.0 * gap + 1.0:
            continue
        ident = f"pp-arc-{'working' if n == 0 else 'idle'}"
        if not heads:
            items.append(Arc(c, r, lo + gap, hi - gap, THIN, layer="position_plan", id=ident))
        else:
            items += turning_arrow(c, r, lo + gap, hi - lo - 2.0 * gap, sense > 0,
                                   math.degrees(4.0 / r), layer="position_plan",
                                   ident=ident)
        out.append(LabelRequest(arc_point(c, r, (lo + hi) / 2), names[n], 3.5, group="arcs"))
    return out


def _rotation_radius(crank, kl: float) -> float:
    return max(6.0, min(12.0, 0.4 * crank.length / kl))




def _rotation_arrow(c: Pt, crank, phi0: float, kl: float) -> list[Item]:
    """The sense of rotation of the crank: a 70° arc opposite its first position."""
    return turning_arrow(c, _rotation_radius(crank, kl), math.degrees(phi0) + 145.0, 70.0,
                         crank.sense > 0, 25.0, layer="position_plan", ident="pp-omega")


def _rotation_label_anchor(c: Pt, crank, phi0: float, kl: float) -> Pt:
    return arc_point(c, _rotation_radius(crank, kl) + 1.0, math.degrees(phi0) + 180.0)




# ------------------------------------------------------------------------- plans


PLAN_LEADERS = 30.0  #: how far a plan's letter may go from its point, on a leader, mm
PLAN_LAYERS = {"velocity": "velocity_plan", "acceleration": "acceleration_plan",
               "force": "force_plan", "lever": "force_plan"}


def plan_items(plan: Plan, cell: Rect, caption: str, ident: str, *,
               segment_labels: bool = False, rename: dict[str, str] | None = None,
               leaders: float = 0.0, keep_out=(), arm_labels: bool = False) -> list[Item]:
    """A plan centred in its cell, with its caption and letters.

    Any construction with ``kind``, ``points`` and ``steps`` is drawn: velocity and
    acceleration plans, force plans, Zhukovsky's lever. With ``segment_labels`` every
    vector is also named at its middle (a force plan names its forces, not only its
    vertices); ``rename`` writes some of them otherwise (a force too short to see with its
    value, sheet 2); ``leaders`` as in :func:`graphplan.drawing.labels.place_labels`;
    ``keep_out``: more areas its letters must not enter; ``arm_labels``: the arms (the
    lever's h of each force, thin lines from the pole) named too, by their far part
    (sheet 2). The letters of the mechanism's
    points are placed first, those of the construction's own points (the ends of the
    normal and Coriolis components, n… and k…) after them, in the room left.
    """
    layer = PLAN_LAYERS[getattr(plan, "kind", "lever")]
    pts = np.array(list(plan.points.values()))
    elems = [e for s in plan.steps for e in s.elements]
    ends = np.array([q for e in elems if e.kind != "point" for q in (e.start, e.end)] or pts)
    allp = np.vstack([pts, ends])
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    cx = (cell.x0 + cell.x1) / 2
    cy = (cell.y0 + CAPTION + cell.y1) / 2
    mid = (lo + hi) / 2

    def to(q) -> Pt:
        return (cx + float(q[0] - mid[0]), cy - float(q[1] - mid[1]))

    items: list[Item] = []
    drawn: set[str] = set()
    for n, e in enumerate(elems):
        if e.kind == "line":
            items.append(Line(to(e.start), to(e.end), THIN, layer="construction",
                              id=f"{ident}-l{n}"))
        elif e.kind == "segment":
            key = e.name
            if key in drawn or math.dist(e.start, e.end) < 1e-9:
                continue
            drawn.add(key)
            style = MEDIUM if e.role in ("absolute", "relative", "load", "reaction",
                                         "force") else THIN
            items.append(Arrow(to(e.start), to(e.end), style, 3.0, 1.0,
                               layer="dimensions" if e.role == "arm" else layer,
                               id=f"{ident}-{e.name}"))
    order = sorted(plan.points, key=lambda name: name.startswith(("n_", "k_")))
    reqs = [LabelRequest(to(plan.points[name]), _label(name), 3.5, group=ident) for name in order]
    if segment_labels:
        named = {e.name: e for e in elems if e.kind == "segment"
                 and e.role not in ("absolute", "arm") and math.dist(e.start, e.end) > 1e-9}
        rename = rename or {}
        reqs += [LabelRequest(to(((e.start[0] + e.end[0]) / 2, (e.start[1] + e.end[1]) / 2)),
                              rename.get(name, _label(name)), 3.5,
                              group=f"{ident}-seg" if name not in rename else f"{ident}-{name}")
                 for name, e in named.items()]
    arms = [LabelRequest(to((e.start[0] + 0.7 * (e.end[0] - e.start[0]),
                             e.start[1] + 0.7 * (e.end[1] - e.start[1]))),
                         _arm_label(e.name), 3.5, group=f"{ident}-arm")
            for e in elems if arm_labels and e.kind == "segment" and e.role == "arm"
            and math.dist(e.start, e.end) > 1e-9]
    obstacles = [g for it in items
                 if not isinstance(it, Group) and (g := item_geometry(it)) is not None]
    inner = Polygon([(cell.x0, cell.y0), (cell.x1, cell.y0), (cell.x1, cell.y1),
                     (cell.x0, cell.y1)])
    cap = text_at_centre(((cell.x0 + cell.x1) / 2, cell.y0 + CAPTION / 2), caption, 3.5,
                         layer="text", id=f"{ident}-caption")
    keep = [inner.exterior.buffer(0.5), text_box(cap).buffer(0.5), *keep_out]
    if leaders:  # a letter sent farther out stays in the cell
        keep.append(inner.buffer(500.0).difference(inner))
    items += place_labels(reqs, obstacles, layer=layer, id_prefix=f"{ident}-t", merge_mm=1.0,
                          keep_out=keep, leaders=leaders)
    if arms:  # the arms' letters in the room the plan's own leave, each by its arm or none
        taken = [g for it in items
                 if not isinstance(it, Group) and (g := item_geometry(it)) is not None]
        taken += [text_box(it).buffer(0.3) for it in iter_leaves(items) if isinstance(it, Text)]
        for it in place_labels(arms, taken, layer=layer, id_prefix=f"{ident}-h", merge_mm=1.0,
                               keep_out=keep):
            box = text_box(it) if isinstance(it, Text) else None
            if box is not None and not any(box.intersects(g) for g in taken):
                items.append(it)
                taken.append(box.buffer(0.3))
    items.append(cap)
    return items


def ill_mark_items(plan, cell: Rect, ident: str, lang: str) -> list[Item]:
    """The draftsman's mark of an ill-conditioned plan, under its caption.

    A plan whose lines meet at less than :data:`graphplan.plans.conditioning.ILL_ANGLE_DEG` is
    marked ``lines meet at 1.3°, reading ±11 mm`` (:meth:`Intersection.note`); a
    well-conditioned plan gets nothing.
    """
    from ..plans import ill_conditioned

    ill = ill_conditioned(plan)
    if not ill:
        return []
    return [text_at_centre(((cell.x0 + cell.x1) / 2, cell.y0 + CAPTION + 1.0), ill[0].note(lang),
                           2.5, layer="text", id=f"{ident}-ill")]


# ------------------------------------------------------------------------ the sheet


def title_block(mech, lang: str, sheet_no: int, what: str) -> TitleBlock:
    """Form 1 filled from the variant's ``[title_block]``."""
    tb = mech.title_block
    title = " ".join(s for s in (tb.title or mech.name, ".", what) if s).replace(" .", ".")
    org = " ".join(s for s in (tb.school, tb.group) if s)
    sheet = sheet_no if tb.sheet is None else tb.sheet
    return TitleBlock(
        designation=tb.designation, title=title, litera=tb.litera, scale=tb.scale, sheet=sheet,
        # graph 8 "Листов": the number of sheets, on the first sheet only (GOST 2.104, 4.2)
        sheets=tb.sheets if sheet == 1 else None,
        organisation=org, mass=tb.mass,
        signatures=signatures(tb.author, tb.checker, date=tb.date),
    )


STRUCTURE_WORDS = {
    "ru": {"title": "Структурный анализ", "formula": "Формула строения",
           "group": "группа Ассура II класса {order}-го порядка {kind}-го вида",
           "stroke": "H = {v} м (ход звена {link})", "swing": "ψ = {v}° (размах звена {link})",
           "arcs": "φр.х = {w}°, φх.х = {i}° (рабочий и холостой ход)",
           "cycle": "φр.х = {w}° (рабочий ход) за цикл {c}°",
           "ratio": "K = {k}", "mech": "механизм II класса"},
    "en": {"title": "Structural analysis", "formula": "Formula of structure",
           "group": "class II group, order {order}, kind {kind}",
           "stroke": "H = {v} m (stroke of link {link})",
           "swing": "ψ = {v}° (swing of link {link})",
           "arcs": "φw = {w}°, φi = {i}° (working and idle strokes)",
           "cycle": "φw = {w}° (the working stroke) in a {c}° cycle",
           "ratio": "K = {k}", "mech": "a class II mechanism"},
}



def structure_lines(analysis, lang: str) -> list[str]:
    """The structural analysis as sheet 1 writes it: Chebyshev's W = 3n − 2p5 − p4, the
    formula of structure, each Assur group (class, order, kind), the stroke H of a sliding
    output or the swing ψ of a rocking one with the time ratio K, and the crank angles of
    the working and idle strokes (over a cycle of two turns, the working stroke's angle in
    the cycle: a four-stroke engine has no idle stroke of 540°)."""
    from ..numbers import decimal_comma

    w = STRUCTURE_WORDS[lang]
    st, cy, mech = analysis.structure, analysis.cycle, analysis.mech
    lines = [st.mobility_equation, f"{w['formula']}: {st.formula} — {w['mech']}"]
    for g in st.groups:
        kind = g.kind_ru if lang == "ru" else g.kind  # ВПВ, as Russian textbooks write it
        lines.append(f"{kind}({'-'.join(g.links)}): "
                     + w["group"].format(order=g.order, kind=g.kind_number))
    out = mech.output.link
    if cy.output_kind == "rocker":
        first = w["swing"].format(v=f"{math.degrees(cy.swing):.2f}", link=out)
    else:
        first = w["stroke"].format(v=f"{cy.stroke:.4g}", link=out)
    if cy.dead_centres:
        first += ", " + w["ratio"].format(k=f"{cy.time_ratio:.3f}")
        turn = math.degrees(cy.working_turn)
        period = math.degrees(cy.period)
        if cy.period > 2 * math.pi + 1e-9:  # a four-stroke engine: no idle 540° stroke
            arcs = w["cycle"].format(w=f"{turn:.1f}", c=f"{period:.0f}")
        else:
            arcs = w["arcs"].format(w=f"{turn:.1f}", i=f"{period - turn:.1f}")
        lines += [first, arcs]
    else:
        lines.append(first)
    return [decimal_comma(x) if lang == "ru" else x for x in lines]


def structure_items(analysis, sc: Sheet1Scales, lang: str) -> list[Item]:
    """The block of the structural analysis above the scales (lines of
    :func:`structure_lines`, 3.5 mm, or 2.5 mm where a line is wider than the block)."""
    r = sc.layout.structure
    if r is None:
        return []
    items: list[Item] = [Text((r.x0, r.y0 + 6.0), STRUCTURE_WORDS[lang]["title"], 5.0,
                              layer="text", id="structure-title")]
    for i, line in enumerate(structure_lines(analysis, lang)):
        h = 3.5 if text_width(Text((0, 0), line, 3.5, layer="text")) <= r.width else 2.5
        items.append(Text((r.x0, r.y0 + 9.0 + STRUCTURE_LINE * (i + 1) - 1.5), line, h,
                          layer="text", id=f"structure-{i}"))
    return items


def scales_items(sc: Sheet1Scales, lang: str) -> list[Item]:
    r = sc.layout.scales
    items: list[Item] = [Text((r.x0, r.y0 + 5.0), WORDS[lang]["scales"], 5.0, layer="text",
                              id="scales-title")]
    for i, s in enumerate((sc.kl, sc.kv, sc.ka)):
        text = _units(s.basis, lang)
        items.append(Text((r.x0, r.y0 + 12.0 + 6.5 * i), text, 3.5, layer="text",
                          id=f"scales-{s.symbol}"))
    return items


def _units(s: str, lang: str) -> str:
    """Units as lettered on a Russian sheet (м/мм, (м/с)/мм, …)."""
    if lang != "ru":
        return s
    return (s.replace("(m/s²)/mm", "(м/с²)/мм").replace("(m/s)/mm", "(м/с)/мм")
            .replace("m/mm", "м/мм"))


def kinematics_sheet(analysis, *, lang: str = "ru", precision: float = 0.0,
                     diagrams: bool = True, page: Page | None = None) -> Sheet:
    """Sheet 1 of the project for ``analysis`` (see the module docstring).

    Parameters
    ----------
    analysis : Analysis
    lang : {"ru", "en"}
        Language of the lettering (the title block's printed labels stay Russian).
    precision : float
        Reading precision of the plans, mm (0: exact constructions).
    diagrams : bool
        Draw the kinematic diagrams (matplotlib).
    page : Page, optional
        A1 by default, or the variant's ``drawing.format``.
    """
    mech, kin = analysis.mech, analysis.kin
    sc = analysis.sheet1 if page is None else analysis.sheet1_on(page)
    w = WORDS[lang]
    items: list[Item] = []
    items += position_plan_items(analysis, sc, lang)
    for c, k in enumerate(sc.plans):
        vp = analysis.velocity_plan(k, precision, page)  # the lessons' plan too
        cell = sc.layout.v_cells[c]
        # the plan of a position of the other turn (720°) whose acceleration plan is drawn
        same = [kin.labels[j] for j in sc.acc_plans if kinematic_twin(kin, j, (k,)) == k]
        items += plan_items(vp, cell, f"{w['velocity']}, {w['pos']} "
                            f"{', '.join([kin.labels[k], *same])}", f"vp{k}",
                            leaders=PLAN_LEADERS)
        items += ill_mark_items(vp, cell, f"vp{k}", lang)
    for c, k in enumerate(sc.acc_plans):
        ap = analysis.acceleration_plan(k, precision, page)
        cell = sc.layout.a_cells[c]
        items += plan_items(ap, cell, f"{w['acceleration']}, {w['pos']} {kin.labels[k]}",
                            f"ap{k}", leaders=PLAN_LEADERS)
        items += ill_mark_items(ap, cell, f"ap{k}", lang)
    from .sheet1_schemes import groups_items, scheme_items

    for c, k in enumerate(sc.analysed[:len(sc.layout.schemes)]):
        items += scheme_items(analysis, sc.slots, k, sc.layout.schemes[c], lang, f"sch{k}")
    if sc.layout.groups is not None:
        items += groups_items(analysis, sc.slots, sc.layout.groups, lang)
    items += scales_items(sc, lang)
    items += structure_items(analysis, sc, lang)
    d = fit_sheet_diagrams(analysis, sc) if diagrams else None
    items += table_block(analysis, sc, lang, d)
    if diagrams:
        items += diagram_block(analysis, sc, lang, d)
    return Sheet(sc.layout.page, tuple(items), title_block(mech, lang, 1, w["sheet"]),
                 lang=lang)


def table_block(analysis, sc: Sheet1Scales, lang: str, d=None) -> list[Item]:
    """The table of the plans (main values of every position) in the bottom strip, lettered
    3.5 mm, or 2.5 mm where that keeps every column (a six-bar's 18–20 columns); cut, with
    its title saying so, only where not even 2.5 mm fits (A2, A3). With the kinematic
    diagrams ``d``, the table comparing them with the plans (:func:`comparison_block`)
    right of it, where the strip holds both with every column (the table of the plans
    lettered 2.5 mm where that makes the room)."""
    from ..reports import summary_rows

    def notes(n, m):
        if lang == "ru":
            return [f" (столбцов {n} из {m}; полностью — plans.ru.md)", f" ({n}/{m}, plans.ru.md)",
                    f" ({n}/{m})"]
        return [f" ({n} of {m} columns; all in plans.en.md)", f" ({n}/{m}, plans.en.md)",
                f" ({n}/{m})"]

    header, rows = summary_rows(analysis, lang)
    r = sc.layout.table

    def plans(width: float) -> list[Item]:
        return titled_table(r.x0, r.y0, width, WORDS[lang]["table"], header, rows,
                            ident="plans-table", title_id="table-title", notes=notes,
                            lettering=(3.5, 2.5))

    if d is not None:
        from ..reports import comparison_rows

        title, c_head, c_rows = comparison_rows(analysis, d, lang)
        least = sum(fit_columns(c_head, c_rows, math.inf, 2.5, TABLE_PAD * 2.5).widths)
        width = r.width - least - GAP - 1.0  # 1 mm spare: no cut by round-off
        if c_rows and fit_columns(header, rows, width, 2.5, TABLE_PAD * 2.5).shown == len(header):
            table = plans(width)
            return table + comparison_block(sc, table, title, c_head, c_rows)
    return plans(r.width)


def comparison_block(sc: Sheet1Scales, table: list[Item], title: str, header, rows
                     ) -> list[Item]:
    """The table comparing the diagrams' v and a with the plans' at the main positions
    (method B.2.5, 7: Δ = (diagram − plan)/plan·100 %; :func:`graphplan.reports.
    comparison_rows`) in the bottom strip right of the table of the plans ``table``,
    lettered 3.5 mm or 2.5 mm, its title over its own width."""
    r = sc.layout.table
    right = max(g.bounds[2] for it in iter_leaves(table) if (g := item_geometry(it)))
    x0 = right + GAP
    out = titled_table(x0, r.y0, r.x1 - x0, title, header, rows, ident="diagram-check",
                       title_id="diagram-check-title", lettering=(3.5, 2.5))
    right = max(g.bounds[2] for it in iter_leaves(out[1:]) if (g := item_geometry(it)))
    head = out[0]
    assert isinstance(head, Text)
    for h in (5.0, 3.5, 2.5):  # 5 mm, or smaller where 5 mm runs past the table
        head = replace(head, height=h)
        if x0 + text_width(head) <= right:
            break
    return [head, *out[1:]]


DIAGRAM_LENGTH_MAX = 400.0  #: longest abscissa of one cycle on sheet 1, mm
DIAGRAM_HEIGHT_MAX = 100.0  #: tallest of the three diagrams, mm


def fit_sheet_diagrams(analysis, sc: Sheet1Scales):
    """The kinematic diagrams s(φ), v(φ), a(φ) sized to their box on the sheet."""
    from .figures import fit_diagrams

    r = sc.layout.diagrams
    return fit_diagrams(analysis.mech, analysis.cycle, r.width, r.height,
                        max_length_mm=DIAGRAM_LENGTH_MAX, max_height_mm=DIAGRAM_HEIGHT_MAX,
                        solve_on=analysis.solve_on)


def diagram_block(analysis, sc: Sheet1Scales, lang: str, d=None) -> list[Item]:
    """The kinematic diagrams s(φ), v(φ), a(φ) (matplotlib, embedded as vector graphics)."""
    from .figures import diagrams_items

    r = sc.layout.diagrams
    d = fit_sheet_diagrams(analysis, sc) if d is None else d
    return [diagrams_items(d, (r.x0, r.y0), r.width, r.height, lang, id="kin-diagrams")]


__all__ = ["kinematics_sheet", "plan_items", "position_plan_items", "title_block"]

