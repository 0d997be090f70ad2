"""Sheet 2, kinetostatic analysis, as a ТММ teacher expects it: for each analysed position,
every Assur group drawn separately (from the last attached to the first) with all its
loads — weights G, inertia forces Pи, inertia moments Mи, the technological force Q — and
the reactions of the links taken away, the revolute ones in their tangential and normal
components; next to each group its force plan; the initial link (the crank) with R21, its
own loads, the arm h21 and the balancing moment Mур, and its force plan; Zhukovsky's lever.
Under them the diagram of the technological force Q(s) over the output's travel (working
and idle strokes), the curve Mур(φ) and the table of the force analysis (split into parts,
its header repeated, when it is wider than its place); under that table, on A1, the table
of the links' loads in the analysed positions (m, G, aS, Pи, JS, ε, Mи: the first step of
the force analysis), where it costs the figures no position and no room of their plans.

The positions are the variant's ``kinetostatics.positions`` (labels); by default the
working positions (the variant's extra positions off the dead centres: the press's (2),
(3)) and one idle position, the one of the largest |Mур| outside the working stroke
(the position of the largest |Mур| when no extra position is a working one), at most
three — on a smaller format as many of them as its page holds
(:func:`graphplan.project.layout.sheet2_layout`). Every plan is the construction of
:mod:`graphplan.plans.forces` / :mod:`graphplan.plans.zhukovsky` at the groups' Kl (one for the
sheet, :class:`graphplan.project.scales.Sheet2Scales`), placed by a translation and the flip of
y, as on sheet 1. The arrows of loads and reactions on the groups show directions, not
magnitudes; a force whose vector on a plan is shorter than 2 mm is written with its value
and «<2 мм» rather than left as a dot with a name.
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import Point

from ..forces import reaction_name
from ..kinematics import position_angles_deg
from ..model import russian_kind
from ..numbers import fmt
from ..paper import Page, Rect
from ..project import (
    CAPTION,
    EQ_H,
    EQ_PITCH,
    FORCE_TABLE_W,
    GROUP_EQ_ROOM,
    GROUP_ROOM,
    LOADS_GAP,
    SHEET2_LOADS_WORDS,
    group_links,
    moment_lines,
    path_sides,
    sheet2_loads_table,
    sheet2_positions,
    sheet2_table_header,
    split_table_height,
    wrapped_lines,
)
from ..units import Scale, nice_ceil
from .items import (
    MAIN,
    THIN,
    Arrow,
    Circle,
    Group,
    Item,
    Line,
    Polyline,
    Style,
    Text,
    arc_point,
    item_geometry,
    text_at_centre,
    text_box,
    text_width,
)
from .labels import LabelRequest, place_labels
from .sheet import Sheet
from .sheet1 import (
    JOINT_R,
    WHITE_FILL,
    _joints,
    _pair_points,
    _Paper,
    _slider_block,
    _support,
    _units,
    ill_mark_items,
    link_items,
    plan_items,
    slider_point,
    title_block,
    turning_arrow,
)
from .tables import split_table, table_items

ARROW_MM = 16.0  #: length of a load's or reaction's arrow on a group (direction only), mm
LEADERS = 30.0  #: a letter with no clear spot by its point is written up to this far, on a leader
SHORT_MM = 2.0  #: a force's vector on a plan shorter than this is written with its value

WORDS = {
    "ru": {"group": "Схема звеньев", "link": "Схема звена", "pos": "пол.", "plan": "План сил",
           "mechanism": "Механизм с нагрузками",
           "crank": "Кривошип", "lever": "Рычаг Жуковского", "lever_short": "Рычаг Ж.",
           "curve": "Уравновешивающий момент Mур(φ), все нагрузки",
           "qs": "Сила полезного сопротивления", "work": "р.х.", "idle": "х.х.",
           "qs_moment": "Момент полезного сопротивления", "qs_drive": "Движущая сила",
           "qs_drive_moment": "Движущий момент", "qs_gas": "Сила давления на поршень",
           "qs_gas_drive": "Движущая сила давления газов", "qs_mixed": "Внешние нагрузки",
           "Nm": "Н·м", "kNm": "кН·м",
           "table": "Силовой расчёт", "continued": "Продолжение таблицы «Силовой расчёт»",
           "continued_of": "Продолжение таблицы «{}»",
           "sheet": "Силовой анализ", "N": "Н", "kN": "кН", "short": "<2 мм",
           "header": ("Группы Ассура и кривошип вычерчены отдельно, Kl = {kl}; стрелки сил на "
                      "схемах показывают направления, их величины — на планах сил")},
    "en": {"group": "Scheme of links", "link": "Scheme of link", "pos": "pos.",
           "mechanism": "Mechanism with its loads",
           "plan": "Force plan", "crank": "Crank", "lever": "Zhukovsky's lever",
           "lever_short": "Lever",
           "curve": "Balancing moment Mур(φ), all loads",
           "qs": "Technological force", "work": "w.s.", "idle": "i.s.",
           "qs_moment": "Technological moment", "qs_drive": "Driving force",
           "qs_drive_moment": "Driving moment", "qs_gas": "Pressure force on the piston",
           "qs_gas_drive": "Driving gas force", "qs_mixed": "External loads",
           "Nm": "N·m", "kNm": "kN·m",
           "table": "Force analysis", "continued": "Table «Force analysis» continued",
           "continued_of": "Table «{}» continued",
           "sheet": "Force analysis", "N": "N", "kN": "kN", "short": "<2 mm",
           "header": ("The Assur groups and the crank drawn separately, Kl = {kl}; the arrows on "
                      "the schemes give directions, their sizes are on the force plans")},
}


def _caption(cell: Rect, text, ident: str, form_first: bool = False) -> Text:
    """A cell's caption: the first of ``text`` (a string or the longest form first) that
    fits the cell at 3.5 mm lettering, else at 2.5, else the last form at 1.8 (with
    ``form_first``: the first form that fits at 3.5 or 2.5 — a scheme's caption names its
    links at 2.5 mm rather than leave them out at 3.5)."""
    forms = [text] if isinstance(text, str) else list(text)
    pick = (forms[-1], 1.8)
    trials = [(f, h) for h in (3.5, 2.5) for f in forms]
    if form_first:  # every form but the last (which names no link) before the last
        trials = ([(f, h) for h in (3.5, 2.5) for f in forms[:-1]]
                  + [(forms[-1], h) for h in (3.5, 2.5)])
    for f, h in trials:
        if text_width(Text((0, 0), f, h, layer="text")) <= cell.width - 2.0:
            pick = (f, h)
            break
    return text_at_centre(((cell.x0 + cell.x1) / 2, cell.y0 + CAPTION / 2), pick[0], pick[1],
                          layer="text", id=ident)


def _fitted_text(box: Rect, forms, ident: str) -> Text:
    """One line at the left of ``box``: the first form that fits it at 3.5, else 2.5 mm."""
    for h in (3.5, 2.5):
        for f in forms:
            if text_width(Text((0, 0), f, h, layer="text")) <= box.width:
                return Text((box.x0, (box.y0 + box.y1) / 2 + h / 2), f, h, layer="text", id=ident)
    return Text((box.x0, (box.y0 + box.y1) / 2 + 0.9), forms[-1], 1.8, layer="text", id=ident)


def _figure_paper(kin, k: int, names, cell: Rect, kl: float, pivot) -> _Paper:
    """Paper of a figure drawn at Kl, its points centred in the cell below the caption."""
    pts = np.array([kin.pos.points[n][k] for n in names])
    mid = (pts.min(axis=0) + pts.max(axis=0)) / 2
    cx, cy = (cell.x0 + cell.x1) / 2, (cell.y0 + CAPTION + cell.y1) / 2
    return _Paper((cx + (pivot[0] - mid[0]) / kl, cy - (pivot[1] - mid[1]) / kl), kl, pivot)


def _segments(fp) -> dict[str, np.ndarray]:
    """The vectors (plan mm, y up) of a plan's named segments."""
    return {e.name: np.asarray(e.end, float) - np.asarray(e.start, float)
            for s in fp.steps for e in s.elements if e.kind == "segment"}


def _group_items(analysis, fp, k: int, links: tuple[str, ...], cell: Rect, kl: float,
                 ident: str, fig: str, slots, lang: str, whole: bool = False) -> list[Item]:
    """One Assur group (or the crank), freed from its neighbours, at position k: its links,
    its loads, the reactions of the links taken away (a revolute pair's in its components
    Rτ and Rn as the plan found them), the crank's h21 and Mур. With ``whole`` (``fp``
    None) the whole mechanism in the position, on its supports, its points lettered, with
    its loads and Mур but no reactions, and beside each slider's path the diagram of the
    force on it (:func:`_path_diagrams`)."""
    mech, kin, loads, forces = analysis.mech, analysis.kin, analysis.loads, analysis.forces
    crank = links == (mech.crank.link,)
    names = [p for ln in links for p in mech.points_of(ln) if p in kin.pos.points]
    pivot = kin.pos.points[mech.crank.pivot][k]
    eqs = [] if whole else wrapped_lines(moment_lines(fp, lang), cell.width - 4.0)
    P = _figure_paper(kin, k, names, Rect(cell.x0, cell.y0, cell.x1,
                                          cell.y1 - min(EQ_PITCH * len(eqs), GROUP_EQ_ROOM)), kl,
                                          pivot)
    L = "force_plan"
    pre = f"{ident}-{fig}"
    own = {f"{ident}-link-{ln}" for ln in links}

    def drawn_links(P) -> list[Item]:
        out = [it for it in link_items(mech, kin, k, P, MAIN, ident, L, slots)
               if it.id and (it.id in own or any(it.id.startswith(o + "-") for o in own))]
        for key, (G, u) in kin.pos.guides.items():
            slider, carrier = key.split("/")
            if slider not in links:
                continue
            corners = _slider_block(mech, kin, k, slider, G[k], u[k], P)
            if corners:
                out.append(Polyline(corners, Style(0.5, fill="white"), True, layer=L,
                                      id=f"{ident}-slider-{slider}-{carrier}"))
            if carrier not in links:  # the guide of the link taken away: its axis
                d = np.array([u[k][0], -u[k][1]])
                at = kin.pos.points[slider_point(mech, kin, k, slider, G[k], u[k])][k]
                c = np.asarray(P(G[k] + np.dot(at - G[k], u[k]) * u[k]))
                out.append(Line(tuple(c - 14 * d), tuple(c + 14 * d), Style(0.25, (15, 3, 1, 3)),
                                  layer=L, id=f"{pre}-guide-{slider}"))
        if whole:
            for fp_name, xy in mech.frame_points.items():
                out += [it for it in _support(P(xy), f"{pre}-sup-{fp_name}")]
        return out

    # centred on what is drawn (a slot runs past the points over its block's travel)
    area = Rect(cell.x0, cell.y0 + CAPTION, cell.x1,
                cell.y1 - min(EQ_PITCH * len(eqs), GROUP_EQ_ROOM))
    beside = path_sides(mech, kin, k) if whole else []
    if beside:  # the diagrams beside the sliders' paths take their side of the cell
        sx = max(float(sd[0]) for _, sd in beside), min(float(sd[0]) for _, sd in beside)
        sy = max(float(sd[1]) for _, sd in beside), min(float(sd[1]) for _, sd in beside)
        area = Rect(area.x0 - PATH_ROOM * min(sx[1], 0.0), area.y0 + PATH_ROOM * max(sy[0], 0.0),
                    area.x1 - PATH_ROOM * max(sx[0], 0.0), area.y1 + PATH_ROOM * min(sy[1], 0.0))
    geo = [g for it in drawn_links(P)
           if not isinstance(it, Group) and (g := item_geometry(it)) is not None]
    if geo:
        x0, y0, x1, y1 = shapely.union_all(geo).bounds
        # every line of the moment equations under the figure: the figure stands higher,
        # above all of them, where the cell leaves it the height (the equations were cut
        # from the top where it stood centred over two lines' room). Its points keep
        # GROUP_ROOM for their arrows, as its Kl was chosen (project.scales._group_kl)
        full = cell.y1 - 2.0 - EQ_PITCH * len(eqs)
        py = [float(P(kin.pos.points[n][k])[1]) for n in names]
        if eqs and full < area.y1 and max(py) - min(py) + 2 * GROUP_ROOM <= full - area.y0:
            area = Rect(area.x0, area.y0, area.x1, full)
        dx = (area.x0 + area.x1) / 2 - (x0 + x1) / 2
        dy = (area.y0 + area.y1) / 2 - (y0 + y1) / 2
        if eqs:  # centred on what is drawn, but the points' arrows clear of the equations
            over = max(py) + dy + GROUP_ROOM - full
            dy -= max(0.0, min(over, min(py) + dy - GROUP_ROOM - area.y0, y0 + dy - area.y0))
        P = _Paper((P.ox + dx, P.oy + dy), P.kl, P.pivot)
    items: list[Item] = drawn_links(P)
    if whole:
        joints = set(_joints(mech))
    elif crank:
        joints = {mech.crank.pivot, mech.crank.pin}
    else:
        dyad = next(dy for dy in mech.dyads if set(dy.links) == set(links))
        joints = {p for p, kind in zip(_pair_points(dyad), dyad.kind, strict=False)
                  if p and kind == "R"}
    for j in sorted(joints):
        items.append(Circle(P(kin.pos.points[j][k]), JOINT_R, WHITE_FILL, layer=L,
                            id=f"{pre}-joint-{j}"))
    inner = cell.polygon().buffer(-(ARROW_MM + 4.0))
    arrows: list[tuple[str, np.ndarray, np.ndarray, bool]] = []
    couples: list[tuple[str, str, float]] = []
    for ln in links:
        for f in loads.forces.get(ln, ()):
            if np.hypot(*f.vector[k]) > 0:
                arrows.append((f.name, f.at[k], f.vector[k], False))
        for m in loads.moments.get(ln, ()):
            if m.moment[k]:
                couples.append((m.name, ln, float(m.moment[k])))
    seg = {} if whole else _segments(fp)
    for r in () if whole else forces.reactions.values():
        vec, at = np.asarray(r.vector[k], float), np.asarray(r.at[k], float)
        if np.hypot(*vec) == 0:
            continue
        if r.on in links and r.by not in links:
            name = r.name
        elif r.by in links and r.on not in links and r.on != mech.frame_link:
            name, vec = reaction_name(r.on, r.by), -vec  # of a group solved before
        else:
            continue
        if not inner.contains(Point(P(at))):  # a slide's line of action far off
            at = np.asarray(r.ref[k], float)
        parts = [q for q in (f"Rτ{name[1:]}", f"Rn{name[1:]}") if q in seg
                 and np.hypot(*seg[q]) > 1e-9]
        for q in parts:
            arrows.append((q, at, seg[q], True))
        arrows.append((name, at, vec, True))
    reqs: list[LabelRequest] = []
    for n, (name, at, vec, reaction) in enumerate(arrows):
        tip = np.asarray(P(at))
        d = np.array([vec[0], -vec[1]]) / float(np.hypot(*vec))
        # a load starts at its point; a reaction ends at the joint it acts on — or the other
        # way round where that arrow would leave the figure's place (the caption above)
        back = reaction
        if not area.polygon().buffer(-1.0).contains(
                Point(*(tip - ARROW_MM * d if back else tip + ARROW_MM * d))):
            back = not back
        p0, p1 = (tip - ARROW_MM * d, tip) if back else (tip, tip + ARROW_MM * d)
        items.append(Arrow(tuple(p0), tuple(p1), Style(0.35), 3.0, 1.0, layer=L,
                           id=f"{pre}-f{n}"))
        free = p0 if back else p1  # the letter at the arrow's free end, off the joint
        reqs.append(LabelRequest(tuple(free + 1.0 * d * (1 if not back else -1)), name, 3.5,
                                 group=pre))
    centres = {ln: getattr(mech.links.get(ln), "centre", None) for ln in links}
    for n, (name, ln, m) in enumerate(couples):
        c_name = centres.get(ln)
        pts = [kin.pos.points[p][k] for p in mech.points_of(ln) if p in kin.pos.points]
        mc = P(kin.pos.points[c_name][k] if c_name in kin.pos.points else np.mean(pts, axis=0))
        a0 = 30.0 + 90.0 * n
        items += turning_arrow(mc, 7.0, a0, 120.0, m >= 0, 30.0, layer=L, ident=f"{pre}-m{n}")
        reqs.append(LabelRequest(arc_point(mc, 9.0, a0 + 60.0), name, 3.5, group=pre))
    if crank or whole:
        items += _crank_marks(analysis, k, P, pre, ident, reqs, reaction=not whole)
    if whole:
        items += _path_diagrams(analysis, k, P, cell, beside, pre, lang, reqs)
        # the moving points lettered; the frame's pivots (O …) by their supports only: the
        # drawing checker takes a lettered pivot under a caption for a scheme it judges
        for name in (n for n in names if n not in mech.frame_points):
            at = np.asarray(P(kin.pos.points[name][k]), float)
            reqs.append(LabelRequest((float(at[0]) + 1.5, float(at[1]) - 1.5), name, 3.5,
                                     group=pre))
    w = WORDS[lang]
    what = (w["mechanism"] if whole else f"{w['link']} {links[0]}" if crank
            else f"{w['group']} {'–'.join(links)}")
    scale = _units(Scale("Kl", kl, "m/mm").basis, lang)
    pos = f"{w['pos']} {kin.labels[k]}"
    short = what.split()[0] if whole else f"{what.split()[0]} {'–'.join(links)}"
    caption = _caption(cell, (f"{what}, {pos}, {scale}", f"{what}, {pos}, Kl = {fmt(kl)}",
                              f"{short}, {pos}, {scale}", f"{short}, {pos}, Kl = {fmt(kl)}",
                              f"{what.split()[0]}, {pos}, Kl = {fmt(kl)}"),
                       f"{pre}-caption" if not crank else f"{ident}-caption", form_first=True)
    obstacles = [g for it in items
                 if not isinstance(it, Group) and (g := item_geometry(it)) is not None]
    eq_items = _equation_items(moment_lines(fp, lang) if not whole else [], eqs, cell,
                               obstacles, f"{pre}-eq")
    # the letters stay inside the figure's cell, clear of its caption
    keep = [_outside(cell),
            text_box(caption).buffer(0.5), *(text_box(t).buffer(0.5) for t in eq_items)]
    items += place_labels(reqs, obstacles, layer=L, id_prefix=f"{pre}-t", keep_out=keep,
                          merge_mm=0.5, leaders=LEADERS)
    items.append(caption)
    items += eq_items
    return items


def vector_line(fp) -> str:
    """The vector equation a force plan draws, in the order of its polygon."""
    chain = [q for q, _, _ in fp.polygons.get("group", ())]
    return " + ".join(chain) + " = 0" if chain else ""


def _lowest(geoms) -> float:
    """The lowest paper y (y down) of some geometries."""
    return max((g.bounds[3] for g in geoms if not g.is_empty), default=-math.inf)


def _bottom_lines(lines: list[str], cell: Rect, ident: str, below: float) -> list[Text]:
    """``lines`` at the bottom of ``cell``, under the figure (whose lowest point is
    ``below``): the last lines that fit there (the results last, so kept first)."""
    # the last baseline 2.5 mm over the cell's foot: the subscripts and descenders of
    # «Rτ12 = 86,9 Н» keep 1.5 mm from the caption of the cell below
    room = len(lines) if below == -math.inf else int((cell.y1 - 2.0 - (below + 1.5)) // EQ_PITCH)
    keep = lines[-room:] if room > 0 else []
    out = []
    for n, line in enumerate(keep):
        y = cell.y1 - 2.5 - EQ_PITCH * (len(keep) - 1 - n)
        out.append(Text((cell.x0 + 2.0, y), line, EQ_H, layer="text", id=f"{ident}{n + 1}"))
    return out


def _equation_items(raw: list[str], eqs: list[str], cell: Rect, obstacles, ident: str
                    ) -> list[Text]:
    """The moment equations of a figure in its cell, never a line dropped: under the figure
    when they fit there (``eqs``: ``raw`` wrapped to the cell's width); else as a block in a
    corner of the cell the figure leaves empty (a slanting rod leaves two), wrapped to its
    width; only when no corner holds them, the last lines under the figure."""
    below = _lowest(obstacles)
    room = len(eqs) if below == -math.inf else int((cell.y1 - 2.0 - (below + 1.5)) // EQ_PITCH)
    if room >= len(eqs):
        return _bottom_lines(eqs, cell, ident, below)
    figure = shapely.union_all([g.buffer(1.5) for g in obstacles]) if obstacles else None
    for share in (1.0, 0.6, 0.45):
        lines = wrapped_lines(raw, share * cell.width - 4.0)
        w = max(text_width(Text((0, 0), ln, EQ_H, layer="text")) for ln in lines)
        h = EQ_PITCH * len(lines)
        for x0 in (cell.x0 + 2.0, cell.x1 - 2.0 - w):
            for y0 in (cell.y1 - 1.0 - h, cell.y0 + CAPTION + 1.0):
                box = shapely.box(x0, y0, x0 + w, y0 + h)
                if y0 < cell.y0 + CAPTION or (figure is not None and box.intersects(figure)):
                    continue
                return [Text((x0, y0 + EQ_PITCH * (n + 1) - 1.5), ln, EQ_H, layer="text",
                             id=f"{ident}{n + 1}") for n, ln in enumerate(lines)]
    return _bottom_lines(eqs, cell, ident, below)


def _crank_marks(analysis, k: int, P, pre: str, ident: str, reqs, reaction: bool = True
                 ) -> list[Item]:
    """The crank's line of R21 (dashed), the arm h21 from the pivot and the turning arrow
    of Mур about the pivot (without ``reaction``: the turning arrow only)."""
    mech, kin, forces = analysis.mech, analysis.kin, analysis.forces
    items: list[Item] = []
    pts = {n: p[k] for n, p in kin.pos.points.items()}
    pivot = pts[mech.crank.pivot]
    try:
        r21 = np.asarray(forces.vector(f"R{mech.dyads[0].links[0]}{mech.crank.link}")[k])
    except KeyError:
        r21 = np.zeros(2)
    if np.hypot(*r21) > 0 and reaction:
        a = np.asarray(P(pts[mech.crank.pin]))
        o = np.asarray(P(pivot))
        d = np.array([r21[0], -r21[1]]) / float(np.hypot(*r21))
        foot = a + float(np.dot(o - a, d)) * d
        ends = sorted([0.0, float(np.dot(foot - a, d))])
        items.append(Line(tuple(a + (ends[0] - 6.0) * d), tuple(a + (ends[1] + 6.0) * d),
                          Style(0.25, (4.0, 1.5)), layer="construction",
                          id=f"{ident}-r21-line"))
        if math.dist(foot, o) > 0.5:
            items.append(Line(tuple(o), tuple(foot), THIN, layer="dimensions",
                              id=f"{ident}-h21"))
            reqs.append(LabelRequest(tuple((o + foot) / 2), "h21", 3.5, group=pre))
    c = P(pivot)
    a0 = math.degrees(float(kin.phi[k])) + 150.0
    items += turning_arrow(c, 9.0, a0, 60.0, float(forces.M_bal[k]) >= 0, 20.0,
                           layer="force_plan", ident=f"{pre if not reaction else ident}-mbal")
    reqs.insert(0, LabelRequest(arc_point(c, 13.0, a0 + 30.0), "Mур", 3.5, group=pre))
    return items


PATH_ROOM = 42.0  #: beside a slider's path, the room of the diagram of the force on it, mm
PATH_OFF = 10.0  #: that diagram's axis stands this far from the path (clear of the block), mm
PATH_DASH = (4.0, 1.5)  #: its idle stroke's dashes, mm


def _path_diagrams(analysis, k: int, P, cell: Rect, beside, pre: str, lang: str,
                   reqs: list[LabelRequest]) -> list[Item]:
    """Beside the path of each slider a force of the variant acts on, the diagram of that
    force over the slider's travel, drawn against the path at the mechanism's Kl (the
    method's «F_пс(s) beside the slider path»): its axis parallel to the path PATH_OFF mm
    off it, on the side away from the crank (``beside``: :func:`graphplan.project.path_sides`),
    ordinates Q/Kq perpendicular to it — the working stroke solid, the idle one dashed —,
    the thin ordinates of the sheet's positions, the analysed one's dotted and numbered.
    Kq is the round value (1, 2, 2.5, 4, 5 × 10ⁿ) that keeps the largest ordinate within the
    room left beside the path (at most PATH_ROOM − PATH_OFF − 6 mm)."""
    from ..forces import resistance_loads

    mech, kin = analysis.mech, analysis.kin
    curves, _unit = q_curves(analysis)
    fine = analysis.solve_on(q_grid(analysis))  # the grid of q_curves: solved once
    on_fine = resistance_loads(mech, fine, analysis.cycle)
    at_positions = resistance_loads(mech, kin, analysis.cycle)
    w = WORDS[lang]
    box = cell.polygon()
    items: list[Item] = []
    for i, side in beside:
        name, _x, size, own, _ = curves[i]
        n = np.array([side[0], -side[1]], float)  # paper, y down
        path = np.array([P(p) for p in np.asarray(on_fine[i].at, float)])
        across = path @ n
        if np.ptp(across) > 0.5 or np.max(size) <= 0:  # not a straight path, or no load
            continue
        base = path + PATH_OFF * n
        # the room to the cell's edge beside the path, letters kept inside
        edge = min(_ray_to_edge(box, tuple(b), tuple(n)) for b in base[:: max(len(base) // 24, 1)])
        room = min(PATH_ROOM - PATH_OFF - 6.0, edge - PATH_OFF - 6.0)
        if room < 8.0:
            continue
        kq = nice_ceil(float(np.max(size)) / room)
        top = base + (size / kq)[:, None] * n
        inside = box.buffer(-2.0)
        if not inside.contains(shapely.MultiPoint(np.vstack([base, top]))):
            continue  # the path runs to the cell's edge: no room beside it
        along = path @ np.array([-n[1], n[0]])
        lo, hi = int(np.argmin(along)), int(np.argmax(along))
        items.append(Line(tuple(base[lo]), tuple(base[hi]), THIN, layer="diagrams",
                          id=f"{pre}-q{i}-axis"))
        edges = np.flatnonzero(np.diff(own.astype(int))) + 1
        for m, run in enumerate(np.split(np.arange(len(top)), edges)):
            run = np.append(run, run[-1] + 1) if run[-1] + 1 < len(top) else run
            if len(run) < 2:
                continue
            style = Style(0.5) if own[run[0]] else Style(0.3, PATH_DASH)
            items.append(Polyline(tuple(map(tuple, top[run])), style, layer="diagrams",
                                  id=f"{pre}-q{i}-curve{m}"))
        ld = at_positions[i]
        pts = np.asarray(ld.at, float)
        vals = np.hypot(*np.asarray(ld.vector, float).T)
        for j in range(len(kin.phi)):
            b = np.asarray(P(pts[j])) + PATH_OFF * n
            t = b + vals[j] / kq * n
            if vals[j] / kq > 0.3:
                items.append(Line(tuple(b), tuple(t), THIN, layer="diagrams",
                                  id=f"{pre}-q{i}-ord{j}"))
            if j == k:
                items.append(Circle(tuple(t), 0.6, Style(0.25, fill="black"), layer="diagrams",
                                    id=f"{pre}-q{i}-at"))
                reqs.append(LabelRequest(tuple(t + 2.0 * n), kin.labels[k], 2.5, group=pre))
        peak = int(np.argmax(size))
        mm = "мм" if lang == "ru" else "mm"
        reqs.append(LabelRequest(tuple(top[peak] + 2.5 * n),
                                 f"{name}(s), Kq = {fmt(kq)} {w['N']}/{mm}", 2.5, group=pre))
    return items


def _ray_to_edge(box, at, d) -> float:
    """How far from ``at`` along the unit vector ``d`` the polygon ``box``'s edge is, mm."""
    from shapely.geometry import LineString

    if not box.contains(Point(at)):
        return 0.0
    far = LineString([at, (at[0] + 1000.0 * d[0], at[1] + 1000.0 * d[1])])
    cut = far.intersection(box)  # a convex cell: one segment from ``at`` to the edge
    return float(cut.length) if not cut.is_empty else 0.0


def _outside(cell: Rect):
    """Everything around a cell: its figure's letters stay in it."""
    return cell.polygon().buffer(400.0).difference(cell.polygon().buffer(-0.5))


def _plan_items(plan, cell: Rect, captions, ident: str, rename, arms: bool = False,
                avoid=()) -> list[Item]:
    """A plan in its cell (:func:`graphplan.drawing.sheet1.plan_items`, every force named;
    with ``arms`` the lever's arms h too), its caption the first of ``captions`` that fits
    the cell."""
    caption = _caption(cell, captions, f"{ident}-caption")
    items = plan_items(plan, cell, captions[0], ident, segment_labels=True, rename=rename,
                       leaders=LEADERS, keep_out=[_outside(cell),
                                                  text_box(caption).buffer(0.5), *avoid],
                       arm_labels=arms)
    return [it for it in items if it.id != f"{ident}-caption"] + [caption]


FORCE_ROW = 5.0  #: row of the table of a plan's forces (2.5 mm lettering), mm


def _bounds(items) -> tuple[float, float, float, float]:
    """The bounding box of some items (paper mm)."""
    geo = [g for it in items if (g := item_geometry(it)) is not None]
    return shapely.union_all(geo).bounds


def _force_table(fp, cell: Rect, ident: str, lang: str, scheme: tuple[Rect, list] | None = None
                 ) -> list[Item]:
    """The table of a force plan's forces (method B.3: «a table of forces and reactions —
    name, mm, N»): each force of the plan, its vector's length on the plan (mm) and its value
    (N = mm · Kp), at 2.5 mm lettering. Beside the plan, at the right of its ``cell`` under
    the caption, where the cell is wider than the plan and its letters need; else in a
    corner of its group's cell that the group's drawing leaves empty (``scheme``: that
    cell and its items); else left out (the values are in the reports' tables)."""
    rows = [[q, f"{r.exact_mm:.1f}", f"{r.value:.0f}" if r.value >= 100 else fmt(r.value, 3)]
            for q, r in fp.readings.items() if r.unit == "N"]
    if not rows:
        return []
    header = ["Сила", "мм", "Н"] if lang == "ru" else ["Force", "mm", "N"]
    widths = [max(text_width(Text((0, 0), str(c), 2.5, layer="tables")) for c in col) + 3.0
              for col in zip(header, *rows, strict=False)]
    tw, th = sum(widths), FORCE_ROW * (len(rows) + 1)
    if tw > FORCE_TABLE_W:
        return []
    pts = np.array(list(fp.points.values()), float)
    need = float(np.ptp(pts[:, 0])) + 40.0 if len(pts) else 0.0
    at = None
    if cell.width - need >= FORCE_TABLE_W and th <= cell.height - CAPTION - 4.0:
        x0 = min(cell.x1 - FORCE_TABLE_W, (cell.x0 + cell.x1 - FORCE_TABLE_W) / 2 + need / 2)
        at = (x0 + (FORCE_TABLE_W - tw) / 2, cell.y0 + CAPTION + 2.0)
    elif scheme is not None:
        at = _free_corner(scheme[0], scheme[1], tw, th)
    if at is None:
        return []
    return list(table_items(at, widths, rows, header, 2.5, row_height=FORCE_ROW, id=ident))


def _free_corner(cell: Rect, items, w: float, h: float) -> tuple[float, float] | None:
    """The top-left corner of a ``w`` × ``h`` box in a corner of ``cell`` (under its
    caption) clear by 3 mm of every line and text of ``items``, or None."""
    geo = [text_box(it) if isinstance(it, Text) else item_geometry(it) for it in items
           if not isinstance(it, Group)]
    taken = shapely.union_all([g.buffer(2.5) for g in geo if g is not None and not g.is_empty])
    for y0 in (cell.y1 - 2.0 - h, cell.y0 + CAPTION + 2.0):
        for x0 in (cell.x0 + 2.0, cell.x1 - 2.0 - w):
            box = shapely.box(x0, y0, x0 + w, y0 + h)
            if y0 >= cell.y0 + CAPTION and not box.intersects(taken):
                return x0, y0
    return None


def _short_notes(plan, lang: str) -> dict[str, str]:
    """Forces of a plan whose vector is shorter than SHORT_MM: ``{name: note}``, the note
    giving the value and «<2 мм» (a dot with a name tells a reader nothing)."""
    w = WORDS[lang]
    return {q: f"{q} = {r.value:.0f} {w['N']}" if r.value >= 100 else
            f"{q} = {fmt(r.value, 3)} {w['N']}" for q, r in plan.readings.items()
            if 0.0 < r.exact_mm < SHORT_MM and r.unit == "N" and not q.startswith("h")}


def _note_items(notes: dict[str, str], cell: Rect, ident: str, lang: str) -> list[Item]:
    """The footnote of a plan's short forces at the bottom of its cell: «* Pи2 = 55,2 Н,
    … (<2 мм)», the forces' letters on the plan marked with the star."""
    if not notes:
        return []
    parts = [*notes.values()]
    parts[-1] += f" ({WORDS[lang]['short']})"
    lines: list[str] = []
    for p in parts:
        trial = f"{lines[-1]}, {p}" if lines else f"* {p}"
        if lines and text_width(Text((0, 0), trial, 2.5, layer="text")) <= cell.width - 2.0:
            lines[-1] = trial
        else:
            lines.append(trial if not lines else p)
    out: list[Item] = []
    for n, line in enumerate(reversed(lines)):
        out.append(text_at_centre(((cell.x0 + cell.x1) / 2, cell.y1 - 2.0 - 4.25 * n), line, 2.5,
                                  layer="text", id=f"{ident}-short{len(lines) - n}"))
    return out


def kinetostatics_sheet(analysis, *, lang: str = "ru", page: Page | None = None) -> Sheet:
    """Sheet 2 of the project for ``analysis`` (see the module docstring)."""
    mech, kin = analysis.mech, analysis.kin
    page = page or Page(mech.drawing.format)
    forces = analysis.forces
    s2 = analysis.sheet2_on(page)
    kl = s2.kl
    assert kl is not None and s2.kl_crank is not None and s2.layout is not None  # all set
    w = WORDS[lang]
    n_groups = len(mech.dyads)
    items: list[Item] = []
    summary = []
    mmax = float(np.max(np.abs(forces.M_bal)))
    figures = group_links(mech)
    kls = [s2.figure_kl(i) for i in range(len(figures))]
    for k, cells in zip(s2.positions, s2.cells, strict=True):
        ident = f"s2p{k}"
        plans = analysis.force_plans(k, page)  # the crank's arms at kl_crank; the lessons' too
        o = s2.first
        if s2.kl_mechanism is not None:
            items += _group_items(analysis, None, k, mech.moving_links, cells[0],
                                  s2.kl_mechanism.per_mm, f"s2m{k}", "m", s2.slots, lang,
                                  whole=True)
        for i, (fp, links) in enumerate(zip(plans, figures, strict=True)):
            fig_kl = kls[i]
            scheme = _group_items(analysis, fp, k, links, cells[2 * i + o], fig_kl.per_mm, ident,
                                  f"g{i}", s2.slots, lang)
            items += scheme
            group = russian_kind(fp.group) if lang == "ru" else fp.group  # ВВП(2-3)
            title = (f"{w['plan']} {group}" if i < n_groups else w["crank"])
            cap = f"{title}, {_kp(fp.scale, lang)}"
            cell = cells[2 * i + 1 + o]
            notes = _note_items(_short_notes(fp, lang), cell, f"{ident}-fp{i}", lang)
            vec = wrapped_lines([vector_line(fp)], cell.width - 4.0)
            under = Rect(cell.x0, cell.y0, cell.x1, cell.y1 - EQ_PITCH * len(notes))
            notes += _bottom_lines(vec, under, f"{ident}-fp{i}-eq", below=-math.inf)
            # the table of the plan's forces at the cell's right, under its caption
            tab = _force_table(fp, cell, f"{ident}-fp{i}-forces", lang,
                               (cells[2 * i + o], scheme))
            items += tab
            # the plan above its equation and footnote, its letters clear of its table
            room = Rect(cell.x0, cell.y0, cell.x1, cell.y1 - EQ_PITCH * len(notes))
            items += _plan_items(fp, room, (cap, cap.split(", ")[0].split()[-1] + ", "
                                            + cap.split(", ")[-1]), f"{ident}-fp{i}",
                                 {q: f"{q}*" for q in _short_notes(fp, lang)},
                                 avoid=[shapely.box(*_bounds(tab)).buffer(1.0)] if tab else [])
            items += notes
            items += ill_mark_items(fp, cell, f"{ident}-fp{i}", lang)
        lever = analysis.lever(k, page)
        kv = _units(lever.plan.scale.basis, lang)
        pos = f"{w['pos']} {kin.labels[k]}"
        items += _plan_items(lever, cells[-1], (f"{w['lever']}, {pos}, {kv}",
                                                f"{w['lever_short']}, {pos}, {kv}"),
                             f"{ident}-lever", {}, arms=True)
        items += ill_mark_items(lever, cells[-1], f"{ident}-lever", lang)
        crank = plans[-1]
        assert crank.M_bal is not None  # the crank's plan has Mур
        h21 = next(iter(crank.arms_mm.values()), float("nan"))
        summary.append([kin.labels[k], f"{position_angles_deg(mech, kin)[k]:.1f}",
                        fmt(plans[0].scale.per_mm)]
                       + [fmt(float(r.magnitude[k]) / 1000.0, 5)
                          for r in forces.reactions.values()]
                       + [f"{h21:.2f}" if math.isfinite(h21) else "—",
                          _moment(float(crank.M_bal), mmax), _moment(float(lever.M_bal), mmax),
                          f"{lever.discrepancy_pct:.2f}"
                          if abs(float(crank.M_bal)) >= 1e-9 * max(mmax, 1.0) else "—"])
    lay = s2.layout
    hb = lay.header
    group_kls = [(("–".join(f), fkl) for f, fkl in zip(figures[:-1], kls[:-1], strict=True))]
    distinct = sorted({fkl.per_mm for fkl in kls[:-1]})
    if len(distinct) == 1:
        kl_text = _units(f"{fmt(distinct[0])} m/mm", lang)
    else:
        kl_text = ", ".join(f"{_units(fmt(fkl.per_mm), lang)} ({name})"
                            for name, fkl in group_kls[0])
        kl_text = _units(kl_text + " m/mm", lang)
    note = w["header"].format(kl=kl_text + (
        f", {w['crank'].lower()}: {_units(fmt(kls[-1].per_mm), lang)}"
        if kls[-1].per_mm not in distinct else ""))
    items.append(_fitted_text(hb, (note, note.split(";")[0]), "s2-header"))
    items += _qs_items(analysis, s2, lay.qs, lang)
    items += _curve_items(analysis, lay.curve, lang)
    items += split_table(lay.table.x0, lay.table.y0, lay.table.width, w["table"],
                         table_header(forces, lang), summary, ident="s2-table",
                         title_id="s2-table-title", continued=w["continued"])
    if s2.loads_table:  # under it the links' loads, the first step of the force analysis
        head, rows = sheet2_loads_table(mech, kin, s2.positions, lang)
        y = lay.table.y0 + split_table_height(table_header(forces, lang), summary,
                                              lay.table.width) + LOADS_GAP
        l_title = str(SHEET2_LOADS_WORDS[lang]["title"])
        items += split_table(lay.table.x0, y, lay.table.width, l_title, head, rows,
                             ident="s2-loads", title_id="s2-loads-title",
                             continued=w["continued_of"].format(l_title.split(" (")[0]), key=2)
    return Sheet(page, tuple(items), title_block(mech, lang, 2, w["sheet"]), lang=lang)


def table_header(forces, lang: str) -> list[str]:
    """Columns of the table of sheet 2 (:func:`graphplan.project.sheet2_table_header`)."""
    return sheet2_table_header(forces.reactions, lang)


def q_curves(analysis, n: int = 361):
    """The technological loads over the cycle, for the diagram Q(s): per load its name, the
    travel s of the link it acts on from the start dead centre of its stroke (m; a rocker's
    in degrees; a load over the crank angle: the crank's travel, degrees), its size (N, N·m)
    and whether its link is in its working stroke there (x from 0 to 1: the even strokes of
    :func:`graphplan.forces.stroke_index`; over the crank angle, the crank's working arc;
    a four-stroke cycle: every stroke solid). Returns (curves, unit of s)."""
    from ..forces import cycle_travel, resistance_loads, stroke_index
    from ..kinematics import in_working_stroke, link_coordinate

    mech, kin, cycle = analysis.mech, analysis.kin, analysis.cycle
    if not mech.resistances:
        return [], ""
    phi = q_grid(analysis, n)
    tau = (phi - kin.phi[0]) * mech.crank.sense
    fine = analysis.solve_on(phi)  # solved once per grid (a fine turn of sheet 1's too)
    work = in_working_stroke(mech, cycle, np.mod(phi, 2 * math.pi))
    out = []
    common = _common_abscissa(mech, cycle)
    unit = common or "m"
    for res, load in zip(mech.resistances, resistance_loads(mech, fine, cycle), strict=False):
        size = (np.hypot(*np.asarray(load.vector).T) if hasattr(load, "vector")
                else np.abs(np.asarray(load.moment)))
        if res.over == "crank" or common:
            x, unit = np.degrees(tau), "deg_crank"
        else:
            tl = res.travel_link or mech.output.link
            lt = cycle.travels[(tl, res.working or mech.output.working)]
            q = link_coordinate(mech, tl, fine.pos, fine.vel)[1]
            x = lt.fraction(q) * abs(lt.q_end - lt.q_start)
            if lt.kind == "rocker":
                x, unit = np.degrees(x), "deg"
        own = work
        if cycle.period > 2 * math.pi + 1e-9:
            own = np.ones_like(work)
        elif res.over != "crank":
            own = stroke_index(res, mech, cycle, cycle_travel(mech, cycle, phi)) % 2 == 0
        out.append((load.name, x, size, own, kin.phi[0] + 0.0))
    return out, unit


def q_grid(analysis, n: int = 361) -> np.ndarray:
    """The crank angles (rad) over the cycle at which Q(s) is drawn: ``n`` per turn."""
    cycle = analysis.cycle
    m = max(n, int(n * cycle.period / (2 * math.pi)))
    return analysis.kin.phi[0] + analysis.mech.crank.sense * np.linspace(0.0, cycle.period, m)


def _common_abscissa(mech, cycle) -> str:
    """``"deg_crank"`` where the loads' own abscissae are not one quantity — two rockers'
    swings (the loom's Mс on the beater over ψ5 and Mтр over ψ3), sliders of different
    strokes, or a load over the crank angle beside one over a travel: then every load of
    Q(s) is drawn over the crank's travel φ, which they share; ``""`` where they share one
    travel (one link, or pistons of one stroke, whose s/H diagrams are drawn together)."""
    keys: set[tuple] = set()
    for res in mech.resistances:
        if res.over == "crank":
            keys.add(("crank",))
            continue
        tl = res.travel_link or mech.output.link
        lt = cycle.travels[(tl, res.working or mech.output.working)]
        span = abs(lt.q_end - lt.q_start)
        keys.add((lt.kind, tl) if lt.kind == "rocker" else (lt.kind, round(span, 9)))
    return "deg_crank" if len(keys) > 1 else ""


def _qs_items(analysis, s2, box: Rect, lang: str) -> list[Item]:
    """The diagram of the technological force Q(s) as the sheet's items, the analysed
    positions marked (:func:`q_items`)."""
    curves, unit = q_curves(analysis)
    if not curves:
        return []
    return [q_items(analysis, curves, unit, s2.positions, box, lang)]


def q_items(analysis, curves, unit: str, positions, box: Rect, lang: str) -> Group:
    """Q(s): each load's size against its link's travel, the working stroke solid, the
    idle one dashed, the analysed positions dotted and numbered; drawn in ``box`` (its
    axes 20 mm in from the left, 16 mm from the top and the bottom, 6 mm from the right)."""
    from .chart import Chart, tick_labels

    w = WORDS[lang]
    kin = analysis.kin
    big = max(float(np.max(c[2])) for c in curves)
    kilo = big >= 1e4
    word, symbol, moment = _qs_naming(analysis, [c[0] for c in curves])
    f_unit = w[("kNm" if moment else "kN") if kilo else ("Nm" if moment else "N")]
    div = 1000.0 if kilo else 1.0
    s_words = {"m": ("s, м" if lang == "ru" else "s, m"), "deg": "ψ, °",
               "deg_crank": "φ, °"}[unit]
    names = ", ".join(c[0] for c in curves)
    title = f"{w[word]} {names}({s_words.split(',')[0]})"
    width_mm, height_mm = box.width, box.height
    x_max = float(np.max(curves[0][1]))  # the first load's travel
    ax = Chart(box.x0 + 20.0, box.y0 + 16.0, width_mm - 26.0, height_mm - 32.0,
               (0.0, x_max * 1.02 if x_max > 0 else 1.0),
               (0.0, big / div * 1.15 if big > 0 else 1.0), lang)
    for _name, x, size, work, _ in curves:
        y = size / div
        # runs of one stroke: the working stroke solid, the idle stroke dashed
        edges = np.flatnonzero(np.diff(work.astype(int))) + 1
        for run in np.split(np.arange(len(x)), edges):
            # each run to the next one's first point: the jump where a stroke ends
            # (the beat-up's 600 N·m falling to 0) drawn, not left as a gap
            run = np.append(run, run[-1] + 1) if run[-1] + 1 < len(x) else run
            if len(run) < 2:
                continue
            if work[run[0]]:
                ax.plot(x[run], y[run], 0.5)
            else:
                ax.plot(x[run], y[run], 0.3, IDLE_DASH)
    # the analysed positions on the curve of the first load
    _name, x, size, work, _ = curves[0]
    from ..forces import resistance_loads

    at = resistance_loads(analysis.mech, kin, analysis.cycle)
    ld = at[0]
    vals = (np.hypot(*np.asarray(ld.vector).T) if hasattr(ld, "vector")
            else np.abs(np.asarray(ld.moment)))
    xs = _position_travel(analysis, unit)
    shown: list[tuple[float, float]] = []
    taken: list[tuple[float, float, float, float]] = []  # the numbers' boxes, mm in the axes
    x_mm = (width_mm - 26.0) / max(1.02 * float(np.max(x)), 1e-12)
    y_mm = (height_mm - 32.0) / max(big / div * 1.15, 1e-12)
    # the ordinates of the analysed positions (thin lines)
    sel = list(positions)
    ax.vlines(xs[sel], 0.0, vals[sel] / div, 0.25)
    for k in positions:
        px, py = float(xs[k]), float(vals[k]) / div
        ax.dots([px], [py], 1.2)
        if any(abs(px - a) * x_mm < 9.0 and abs(py - b) * y_mm < 6.0 for a, b in shown):
            continue
        shown.append((px, py))
        # written on the side the curve falls away from: left of a rising curve
        near = np.argsort(np.abs(x - px) + 1e9 * (np.abs(size / div - py) > 0.02 * big / div
                                                   + 1e-12))[:2]
        j0, j1 = sorted(int(j) for j in near)
        rising = (size[j1] - size[j0]) * (x[j1] - x[j0]) >= 0
        lines = [np.column_stack([c[1] * x_mm, c[2] / div * y_mm]) for c in curves]
        lines += [np.array([[xs[j] * x_mm, 0.0], [xs[j] * x_mm, vals[j] / div * y_mm]])
                  for j in sel if j != k]  # the other positions' ordinates
        dx, dy = _free_side(kin.labels[k], (px * x_mm, py * y_mm), rising, lines,
                            (width_mm - 26.0, height_mm - 32.0))
        ax.letter(float(ax.sx(px)) + dx, float(ax.sy(py)) - dy, kin.labels[k], 2.5,
                  "right" if dx < 0 else "left", "bottom")
        wk = text_width(Text((0, 0), kin.labels[k], 2.5, layer="text")) + 0.5
        x0 = px * x_mm + dx - (wk if dx < 0 else 0.0)
        taken.append((x0, py * y_mm + dy, x0 + wk, py * y_mm + dy + 3.0))
    if len(curves) > 1:  # several loads (two cylinders, two chambers): each curve named
        lines = [np.column_stack([c[1] * x_mm, c[2] / div * y_mm]) for c in curves]
        lines += [np.array([[xs[j] * x_mm, 0.0], [xs[j] * x_mm, vals[j] / div * y_mm]])
                  for j in sel]
        for label, px, py, dx, dy in _curve_names(curves, (x_mm, y_mm / div), lines, taken,
                                                  (width_mm - 26.0, height_mm - 32.0)):
            ax.letter(float(ax.sx(px)) + dx, float(ax.sy(py / div)) - dy, label, 2.5,
                      "right" if dx < 0 else "left", "bottom")
    ax.frame(0.25)
    xv, yv = ax.x_values(), ax.y_values()
    foot = ax.xticks(xv, tick_labels(xv))
    ax.xlabel(s_words, foot)
    ax.ylabel(f"{symbol}, {f_unit}", ax.yticks(yv, tick_labels(yv)))
    leg = f"— {w['work']}   - - {w['idle']}"
    if analysis.cycle.period <= 2 * math.pi + 1e-9:
        ax.letter(box.x0 + width_mm - 4.0, box.y0 + 9.0, leg, 2.5, "right", "top")
    ax.letter(box.x0 + 0.5 * width_mm, box.y0 + 2.5, title, 3.5, "center", "top")
    return Group(tuple(ax.items), layer="diagrams", id="s2-q-diagram")


#: the idle stroke's dashes on Q(s), mm (a 0.3 mm line's dashes 3.7 : 1.6 of its width)
IDLE_DASH = (1.1, 0.5)


def _qs_naming(analysis, names: list[str]) -> tuple[str, str, bool]:
    """What the diagram of the loads is called, by what its loads are: (the key of its
    title in :data:`WORDS`, the ordinate's symbol, whether it is in N·m). A load that does
    positive work over the cycle (:func:`graphplan.project.load_drives`: an engine's gas
    force) is a driving force, not a resistance; a pressure on a piston (``bore``) is the
    force of that pressure; the ordinate is named by the load (``Fг, кН``, ``Mс, Н·м``),
    ``F``/``M`` for several, ``Q`` where forces and moments share it."""
    from ..project import load_drives

    mech = analysis.mech
    res = mech.resistances[:len(names)]
    kinds = {r.kind for r in res}
    drives = [load_drives(mech, analysis.cycle, n, analysis.solve_on) for n in range(len(res))]
    moment = kinds == {"moment"}
    if len(kinds) > 1:
        return "qs_mixed", "Q", False
    if all(r.gas for r in res):
        word = "qs_gas_drive" if all(drives) else "qs_gas"
    elif all(drives):
        word = "qs_drive_moment" if moment else "qs_drive"
    else:
        word = "qs_moment" if moment else "qs"
    symbol = names[0] if len(names) == 1 else ("M" if moment else "F")
    return word, symbol, moment


def _curve_names(curves, scale, lines, taken, limits) -> list:
    """Where the name of each curve of Q(s) goes: (name, x, size, dx, dy), the text's nearer
    corner ``dx, dy`` mm from the curve's point (x, size). Curves that are one curve (the
    same diagram on two cylinders) share one name «Fг1, Fг2». Each name stands by the
    highest point of its curve where it crosses no curve, ordinate, position number
    (``taken``: boxes in mm) or name placed before, inside the axes (``limits``, mm)."""
    from shapely.geometry import LineString, box

    # one drawn line: two cylinders of one diagram, sampled at other crank angles (their
    # cycles a turn or the V angle apart), draw the same curve to within 0.3 mm
    groups: list[tuple[list[str], np.ndarray, np.ndarray, LineString]] = []
    for (name, x, size, *_), drawn in zip(curves, lines, strict=False):
        drawn = LineString(drawn)
        same = next((g for g in groups if g[3].hausdorff_distance(drawn) < 0.3), None)
        if same is None:
            groups.append(([name], x, size, drawn))
        else:
            same[0].append(name)
    obstacles = [LineString(c) for c in lines if len(c) > 1]
    obstacles += [box(*b) for b in taken]
    frame = box(0.0, 0.0, *limits)
    out = []
    for names, x, size, _ in groups:
        label = ", ".join(names)
        w = text_width(Text((0, 0), label, 2.5, layer="text")) + 0.5
        order = np.argsort(-size, kind="stable")
        for j in order[::max(1, len(order) // 60)]:
            at = (float(x[j]) * scale[0], float(size[j]) * scale[1])
            spot = next(((dx, dy) for dx, dy in ((1.5, 1.0), (-1.5, 1.0), (1.5, -4.5),
                                                 (-1.5, -4.5), (1.5, 4.5), (-1.5, 4.5))
                         if frame.contains(b := box(at[0] + dx - (w if dx < 0 else 0.0),
                                                    at[1] + dy,
                                                    at[0] + dx + (0.0 if dx < 0 else w),
                                                    at[1] + dy + 3.0))
                         and not any(b.intersects(o) for o in obstacles)), None)
            if spot is not None:
                dx, dy = spot
                x0 = at[0] + dx - (w if dx < 0 else 0.0)
                obstacles.append(box(x0, at[1] + dy, x0 + w, at[1] + dy + 3.0))
                out.append((label, float(x[j]), float(size[j]), dx, dy))
                break
    return out


def _free_side(label: str, at, rising: bool, curves, limits) -> tuple[float, float]:
    """Where a position's number goes by its point on Q(s) (offset in mm, the text's
    nearer corner): on the side the curve falls away from (left of a rising curve), else
    the first place next to the point, inside the axes (``limits``: their width and
    height, mm), that no curve crosses."""
    from shapely.geometry import LineString, box

    w = text_width(Text((0, 0), label, 2.5, layer="text")) + 0.5
    lines = [LineString(c) for c in curves if len(c) > 1]
    first = (-1.5, 1.0) if rising else (1.5, 1.0)
    frame = box(0.0, 0.0, *limits)
    for dx, dy in (first, (-first[0], 1.0), (first[0], -4.5), (-first[0], -4.5),
                   (first[0], 4.5), (-first[0], 4.5), (first[0], 8.0), (-first[0], 8.0)):
        x0 = at[0] + dx - (w if dx < 0 else 0.0)
        y0 = at[1] + dy
        b = box(x0, y0, x0 + w, y0 + 3.0)
        if frame.contains(b) and not any(b.intersects(ln) for ln in lines):
            return dx, dy
    return first


def _position_travel(analysis, unit: str) -> np.ndarray:
    """The abscissa of each position on Q(s) (the first load's travel)."""
    from ..kinematics import link_coordinate

    mech, kin, cycle = analysis.mech, analysis.kin, analysis.cycle
    res = mech.resistances[0]
    if res.over == "crank" or unit == "deg_crank":
        return np.degrees(np.mod((kin.phi - kin.phi[0]) * mech.crank.sense, cycle.period))
    tl = res.travel_link or mech.output.link
    lt = cycle.travels[(tl, res.working or mech.output.working)]
    q = link_coordinate(mech, tl, kin.pos, kin.vel)[1]
    x = lt.fraction(q) * abs(lt.q_end - lt.q_start)
    return np.degrees(x) if unit == "deg" else x


def _moment(m: float, scale: float) -> str:
    """A moment as written in the table: 0 where it is round-off next to the largest."""
    return "0" if abs(m) < 1e-9 * max(scale, 1.0) else fmt(m, 5)


def _kp(scale: Scale, lang: str) -> str:
    return f"Kp = {fmt(scale.per_mm)} {'Н/мм' if lang == 'ru' else scale.unit}"


def _curve_items(analysis, box: Rect, lang: str) -> list[Item]:
    """Mур(φ) over the turn (exact), the positions marked (:func:`moment_items`)."""
    # every load in every position (Project.curve): the neglect rule is the force plans'
    # rule for one position; on the curve it made false steps where it switched a load off
    return [moment_items(analysis.curve, box, lang)]


def moment_items(curve, box: Rect, lang: str) -> Group:
    """The curve Mур(φ) of crank travel, positions numbered, drawn in ``box`` (its axes
    22 mm in from the left, 10 mm from the top, 14 mm from the bottom, 6 mm from the
    right)."""
    from .chart import Chart, auto_limits, tick_labels
    from .figures import spaced_labels

    title = WORDS[lang]["curve"]
    unit = "Н·м" if lang == "ru" else "N·m"
    period = 720.0 if curve.travel_deg[-1] > 360 else 360.0  # a 720° cycle
    ax = Chart(box.x0 + 22.0, box.y0 + 10.0, box.width - 28.0, box.height - 24.0,
               (0.0, period), auto_limits([curve.M, curve.M_positions, [0.0]]), lang)
    # the curve is closed: the turn ends where it began
    ax.plot(np.append(curve.travel_deg, period), np.append(curve.M, curve.M[0]), 0.5)
    ax.dots(curve.position_travel_deg, curve.M_positions, 1.2)
    # the ordinates of the positions, the diagram's construction (thin lines)
    ax.vlines(curve.position_travel_deg, 0.0, curve.M_positions, 0.25)
    ax.hline(0.0, 0.25)
    ax.frame(0.25)
    ax.xticks(curve.position_travel_deg,
              spaced_labels(curve.position_travel_deg, list(curve.labels),
                            (box.width - 28.0) / period))
    yv = ax.y_values()
    ax.ylabel(f"Mур, {unit}", ax.yticks(yv, tick_labels(yv)))
    ax.letter(box.x0 + 0.5 * box.width, box.y0 + 2.5, title, 3.5, "center", "top")
    return Group(tuple(ax.items), layer="diagrams", id="s2-moment-curve")


__all__ = ["kinetostatics_sheet", "moment_items", "q_curves", "q_items", "sheet2_positions",
           "table_header"]
