"""Sheet 2, kinetostatic analysis: for the chosen positions, the scheme of the mechanism
with its loads and reactions, the force plan of every Assur group and of the crank, and
Zhukovsky's lever; below them the curve Mур(φ) and the table of the force analysis.

The positions are the variant's ``kinetostatics.positions`` (labels); by default the
working positions (the variant's extra positions off the dead centres: the press's (2),
(3)) and one idle position, the one of the largest |Mур| outside the working stroke
(the position of the largest |Mур| when no extra position is a working one), at most
three. Every plan is the construction of
:mod:`graphplan.plans.forces` / :mod:`graphplan.plans.zhukovsky`, placed by a translation and
the flip of y, as on sheet 1. The scheme is drawn at the plan of positions' Kl when it
fits its cell, else at the next coarser scale of the series (printed in its caption);
the arrows of loads and reactions on it show directions, not magnitudes.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from shapely.geometry import Point

from ..plans import force_plans, zhukovsky_lever
from ..project import (
    CAPTION,
    GAP,
    SHEET2_STRIP,
    sheet2_positions,
    sheet2_scales,
    sheet_scales,
    titled_table,
)
from ..units import Scale, fmt, nice_ceil
from .labels import LabelRequest, place_labels
from .sheet import (
    MAIN,
    THIN,
    Arrow,
    Circle,
    Item,
    Line,
    Page,
    Polyline,
    Rect,
    Sheet,
    Style,
    arc_point,
    item_geometry,
    text_at_centre,
)
from .sheet1 import (
    JOINT_R,
    WHITE_FILL,
    _joints,
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

ARROW_MM = 16.0  #: length of a load's or reaction's arrow on the scheme (direction only)

WORDS = {
    "ru": {"scheme": "Схема, пол.", "plan": "План сил", "crank": "Кривошип", "lever":
           "Рычаг Жуковского", "curve": "Уравновешивающий момент Mур(φ), все нагрузки",
           "table": "Силовой расчёт", "sheet": "Силовой анализ", "pos": "Пол.",
           "head": ("Пол.", "φ, °", "Kp, Н/мм"), "kN": "кН",
           "tail": ("h21, мм", "Mур, Н·м", "Mур(Ж), Н·м", "Δ, %")},
    "en": {"scheme": "Scheme, pos.", "plan": "Force plan", "crank": "Crank", "lever":
           "Zhukovsky's lever", "curve": "Balancing moment Mур(φ), all loads",
           "table": "Force analysis", "sheet": "Force analysis", "pos": "Pos.",
           "head": ("Pos.", "φ, °", "Kp, N/mm"), "kN": "kN",
           "tail": ("h21, mm", "Mур, N·m", "Mур(Zh), N·m", "Δ, %")},
}


def _scheme_items(analysis, loads, forces, k: int, cell: Rect, kl1: Scale, lang: str,
                  ident: str, slots=None) -> list[Item]:
    """The mechanism at position k with every load and reaction on it (directions)."""
    mech, kin = analysis.mech, analysis.kin
    pts = {n: p[k] for n, p in kin.pos.points.items()}
    allp = np.array(list(pts.values()))
    ext = np.ptp(allp, axis=0)
    room = np.array([cell.width, cell.height - CAPTION]) - 2 * (ARROW_MM + 8.0)
    kl = kl1.per_mm
    if np.any(ext / kl > room):
        kl = nice_ceil(float(np.max(ext / room)))
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    centre = np.array([(cell.x0 + cell.x1) / 2, (cell.y0 + CAPTION + cell.y1) / 2])
    pivot = kin.pos.points[mech.crank.pivot][k]
    mid = (lo + hi) / 2
    origin = (float(centre[0] + (pivot[0] - mid[0]) / kl),
              float(centre[1] - (pivot[1] - mid[1]) / kl))
    P = _Paper(origin, kl, pivot)
    L = "force_plan"
    items: list[Item] = []
    items += link_items(mech, kin, k, P, MAIN, ident, L, slots)
    for key, (G, u) in kin.pos.guides.items():
        slider, carrier = key.split("/")
        corners = _slider_block(mech, kin, k, slider, G[k], u[k], P)
        if corners:
            items.append(Polyline(corners, Style(0.5, fill="white"), True, layer=L,
                                  id=f"{ident}-slider-{key.replace('/', '-')}"))
        if carrier == mech.frame_link:
            d = np.array([u[k][0], -u[k][1]])
            at = pts[slider_point(mech, kin, k, slider, G[k], u[k])]
            c = np.asarray(P(G[k] + np.dot(at - G[k], u[k]) * u[k]))
            items.append(Line(tuple(c - 14 * d), tuple(c + 14 * d), Style(0.25, (15, 3, 1, 3)),
                              layer=L, id=f"{ident}-guide-{slider}"))
    for j in _joints(mech):
        items.append(Circle(P(pts[j]), JOINT_R, WHITE_FILL, layer=L, id=f"{ident}-joint-{j}"))
    for fp in mech.frame_points:
        items += [replace(it, layer=L)
                  for it in _support(P(mech.frame_points[fp]), f"{ident}-sup-{fp}")]
    reqs: list[LabelRequest] = []
    arrows = []
    for f in loads.all_forces():
        if np.hypot(*f.vector[k]) > 0:
            arrows.append((f.name, f.at[k], f.vector[k], False))
    inner = cell.polygon().buffer(-(ARROW_MM + 4.0))
    for r in forces.reactions.values():
        if r.on in analysis.mech.moving_links and np.hypot(*r.vector[k]) > 0:
            at = r.at[k]
            if not inner.contains(Point(P(at))):  # a slide's line of action far off: at X
                at = r.ref[k]
            arrows.append((r.name, at, r.vector[k], True))
    for n, (name, at, vec, reaction) in enumerate(arrows):
        tip = np.asarray(P(at))
        d = np.array([vec[0], -vec[1]]) / float(np.hypot(*vec))
        # a load starts at its point; a reaction ends at the joint it acts on
        p0, p1 = (tip - ARROW_MM * d, tip) if reaction else (tip, tip + ARROW_MM * d)
        items.append(Arrow(tuple(p0), tuple(p1), Style(0.35), 3.0, 1.0, layer=L,
                           id=f"{ident}-f{n}"))
        reqs.append(LabelRequest(tuple((p0 + p1) / 2), name, 3.5, group=ident))
    # the arm h21 of R21 about the crank's pivot: its line of action through the pin and
    # the perpendicular from the pivot
    try:
        r21 = forces.vector(f"R{mech.dyads[0].links[0]}{mech.crank.link}")[k]
    except KeyError:
        r21 = np.zeros(2)
    if np.hypot(*r21) > 0:
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
            reqs.append(LabelRequest(tuple((o + foot) / 2), "h21", 3.5, group=ident))
    # the balancing moment: a turning arrow about the crank's pivot
    c = P(pivot)
    a0 = math.degrees(float(kin.phi[k])) + 150.0
    items += turning_arrow(c, 9.0, a0, 60.0, float(forces.M_bal[k]) >= 0, 20.0, layer=L,
                           ident=f"{ident}-mbal")
    reqs.insert(0, LabelRequest(arc_point(c, 13.0, a0 + 30.0), "Mур", 3.5, group=ident))
    obstacles = [g for it in items if (g := item_geometry(it)) is not None]
    keep = [cell.polygon().exterior.buffer(0.5)]
    items += place_labels(reqs, obstacles, layer=L, id_prefix=f"{ident}-t", keep_out=keep)
    scale = Scale("Kl", kl, "m/mm").basis
    items.append(text_at_centre(((cell.x0 + cell.x1) / 2, cell.y0 + CAPTION / 2),
                                f"{WORDS[lang]['scheme']} {kin.labels[k]}, {_units(scale, lang)}",
                                3.5, layer="text", id=f"{ident}-caption"))
    return items


def kinetostatics_sheet(analysis, *, lang: str = "ru", page: Page | None = None) -> Sheet:
    """Sheet 2 of the project for ``analysis`` (see the module docstring)."""
    mech, kin = analysis.mech, analysis.kin
    own_page = page is not None  # else the variant's page: the project's scales
    page = page or Page(mech.settings.get("drawing", {}).get("format", "A1"))
    sc = sheet_scales(mech, kin, page) if own_page else analysis.sheet1
    loads, forces = analysis.loads, analysis.forces
    s2 = sheet2_scales(mech, kin, forces, analysis.cycle, page) if own_page else analysis.sheet2
    w = WORDS[lang]
    f = page.frame
    n_groups = len(mech.dyads)
    items: list[Item] = []
    summary = []
    mmax = float(np.max(np.abs(forces.M_bal)))
    for k, cells in zip(s2.positions, s2.cells, strict=True):
        ident = f"s2p{k}"
        items += _scheme_items(analysis, loads, forces, k, cells[0], sc.kl, lang, ident,
                               sc.slots)
        plans = force_plans(mech, kin, forces, loads, k, sc.kl, room_mm=s2.room_mm)
        for i, fp in enumerate(plans):
            title = (f"{w['plan']} {fp.group}" if i < n_groups else w["crank"])
            cap = f"{title}, {_kp(fp.scale, lang)}"
            items += plan_items(fp, cells[1 + i], cap, f"{ident}-fp{i}", segment_labels=True)
            items += ill_mark_items(fp, cells[1 + i], f"{ident}-fp{i}", lang)
        lever = zhukovsky_lever(mech, kin, loads, k, sc.kl, s2.lever_kv(kin, k),
                                reference=float(forces.M_bal[k]))
        cap = f"{w['lever']}, {_units(lever.plan.scale.basis, lang)}"
        items += plan_items(lever, cells[-1], cap, f"{ident}-lever", segment_labels=True)
        items += ill_mark_items(lever, cells[-1], f"{ident}-lever", lang)
        crank = plans[-1]
        h21 = next(iter(crank.arms_mm.values()), float("nan"))
        summary.append([kin.labels[k], f"{math.degrees(kin.phi[k]) % 360:.1f}",
                        fmt(plans[0].scale.per_mm)]
                       + [fmt(float(r.magnitude[k]) / 1000.0, 5)
                          for r in forces.reactions.values()]
                       + [f"{h21:.2f}" if math.isfinite(h21) else "—",
                          _moment(float(crank.M_bal), mmax), _moment(float(lever.M_bal), mmax),
                          f"{lever.discrepancy_pct:.2f}"
                          if abs(float(crank.M_bal)) >= 1e-9 * max(mmax, 1.0) else "—"])
    strip = Rect(s2.cells[0][0].x0, f.y1 - SHEET2_STRIP, f.x1 - 185.0 - GAP, f.y1 - 4.0)
    items += _curve_items(analysis, Rect(strip.x0, strip.y0, strip.x0 + 250.0, strip.y1), lang)
    tx = strip.x0 + 250.0 + GAP
    items += _table_items(forces, summary, Rect(tx, strip.y0, strip.x1, strip.y1), lang)
    return Sheet(page, tuple(items), title_block(mech, lang, 2, w["sheet"]), lang=lang)


def table_header(forces, lang: str) -> list[str]:
    """Columns of the table of sheet 2: position, φ, Kp of the first group, every reaction
    (kN, in the order solved), h21, Mур from the plans and from the lever, their difference."""
    w = WORDS[lang]
    return [*w["head"], *(f"{n}, {w['kN']}" for n in forces.reactions), *w["tail"]]


def _table_items(forces, summary, box: Rect, lang: str) -> list[Item]:
    """The table under its title; a table too wide loses its last columns and says so."""
    def notes(shown, total):
        return ([f" (столбцов {shown} из {total}; полностью — forces.ru.md)"] if lang == "ru"
                else [f" ({shown} of {total} columns; all in forces.en.md)"])

    return titled_table(box.x0, box.y0, box.width, WORDS[lang]["table"],
                        table_header(forces, lang), summary, ident="s2-table",
                        title_id="s2-table-title", notes=notes)


def _moment(m: float, scale: float) -> str:
    """A moment as written in the table: 0 where it is round-off next to the largest."""
    return "0" if abs(m) < 1e-9 * max(scale, 1.0) else fmt(m, 5)


def _kp(scale: Scale, lang: str) -> str:
    return f"Kp = {fmt(scale.per_mm)} {'Н/мм' if lang == 'ru' else scale.unit}"


def _curve_items(analysis, box: Rect, lang: str) -> list[Item]:
    """Mур(φ) over the turn (exact), the positions marked: matplotlib, played into the
    sheet's own items (:mod:`graphplan.drawing.mpl_items`: its letters stay text)."""
    from .mpl_items import figure_items

    # every load in every position (Project.curve): the neglect rule is the force plans'
    # rule for one position; on the curve it made false steps where it switched a load off
    curve = analysis.curve
    fig = moment_figure(curve, box.width, box.height, lang)
    return [figure_items(fig, (box.x0, box.y0), id="s2-moment-curve", lang=lang)]


def moment_figure(curve, width_mm: float, height_mm: float, lang: str):
    """The curve Mур(φ) of crank travel, positions numbered, as a matplotlib figure."""
    import matplotlib
    from matplotlib.figure import Figure as MplFigure

    from .figures import MM, _font, spaced_labels

    rc = {"axes.unicode_minus": False}
    title = WORDS[lang]["curve"]
    unit = "Н·м" if lang == "ru" else "N·m"
    with matplotlib.rc_context(rc):
        fig = MplFigure(figsize=(width_mm / 25.4, height_mm / 25.4))
        ax = fig.add_axes((22 / width_mm, 14 / height_mm, 1 - 28 / width_mm,
                           1 - 24 / height_mm))
        period = 720.0 if curve.travel_deg[-1] > 360 else 360.0  # a 720° cycle
        # the curve is closed: the turn ends where it began
        ax.plot(np.append(curve.travel_deg, period), np.append(curve.M, curve.M[0]), "-k",
                lw=0.5 * MM)
        ax.plot(curve.position_travel_deg, curve.M_positions, "o", color="black",
                markersize=1.2 * MM)
        ax.axhline(0.0, color="black", lw=0.25 * MM)
        ax.set_xlim(0, period)
        ax.set_xticks(curve.position_travel_deg)
        ax.set_xticklabels(spaced_labels(curve.position_travel_deg, list(curve.labels),
                                         (width_mm - 28.0) / 360.0),
                           **_font("0123456789()", 2.5))
        for lab in ax.get_yticklabels():
            lab.set(**_font("0123456789-", 2.5))
        ax.tick_params(width=0.25 * MM, length=1.5 * MM, labelsize=_font("0", 2.5)["fontsize"])
        for sp in ax.spines.values():
            sp.set_linewidth(0.25 * MM)
        ax.set_ylabel(f"Mур, {unit}", **_font(f"Mур, {unit}", 3.5))
        fig.text(0.5, 1 - 2.5 / height_mm, title, ha="center", va="top", **_font(title, 3.5))
    return fig


__all__ = ["kinetostatics_sheet", "moment_figure", "sheet2_positions"]
