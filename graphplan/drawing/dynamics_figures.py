"""The diagrams of sheet 3, drawn as the sheet's own items at their scales.

Every diagram is drawn in millimetres of the sheet, so a segment measured on the sheet
times the printed scale is the value (method B.4):

* :func:`work_items` — Mс(φ) with the mean ordinates of the intervals, the pole P at H mm
  and its rays, the line Mд; Aс(φ) by chords parallel to the rays, and Aд(φ); ΔT(φ) =
  Aд + Aс at the scale KT of the energy–mass diagram, its ordinates at the positions.
  The exact curves thin, the graphical ones main; position numbers on the φ axis on the
  side away from the curve.
* :func:`energy_mass_items` — Wittenbauer's diagram ΔT(JII) beside ΔT(φ), its ΔT axis
  level with ΔT(φ)'s (the ordinates project across), the tangents at ψmax and ψmin with
  their angles marked, the points k and l they cut on the ΔT axis and the segment kl;
  above it JII(φ) turned 90° (φ downwards) at the same KJ, or magnified when JII varies
  too little to be read (its scale written).
* :func:`omega_items` — the check ω(φ) of the steady motion with the flywheel, a plot
  drawn by :class:`graphplan.drawing.chart.Chart`.

The scales come from :func:`graphplan.dynamics.machine.machine_unit` (KT and KJ chosen so
that ψ is tens of degrees). Numbers on Russian sheets carry the decimal comma.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely import LineString, union_all
from shapely import box as shapely_box

from ..numbers import fmt, sheet_text
from ..paper import Rect
from .items import (
    Arc,
    Arrow,
    Circle,
    Group,
    Polyline,
    Style,
    Text,
    item_geometry,
    iter_leaves,
    text_box,
    text_width,
)
from .labels import LabelRequest, place_labels

THIN = Style(0.25)
MAIN = Style(0.5)
DASHED = Style(0.25, (4.0, 1.5))
DOT = Style(0.25, fill="black")
TEXT_H, SMALL_H = 3.5, 2.5
LAYER = "diagrams"
STRIP = 11.0  #: room above a panel's curve for its axis arrow, letters and scale, mm
BELOW = 7.0  #: room below a panel's curve, mm
LEFT_B = 20.0  #: room left of the ΔT axis of the energy–mass diagram (k, l, kl), mm
MIN_READ = 40.0  #: narrowest JII(φ) that can be read; narrower ones are magnified, mm
WORDS = {
    "ru": {"J": "Дж", "Nm": "Н·м", "mm": "мм", "rad": "рад", "kgm2": "кг·м²", "s": "с",
           "omega": "Проверка: ω(φ) с маховиком", "target": "цель",
           "omega_none": "Проверка: ω(φ) без маховика",
           "mag": "увеличено", "em": "Диаграмма энергомасс ΔT(JII)"},
    "en": {"J": "J", "Nm": "N·m", "mm": "mm", "rad": "rad", "kgm2": "kg·m²", "s": "s",
           "omega": "Check: ω(φ) with the flywheel", "target": "target",
           "omega_none": "Check: ω(φ) without a flywheel",
           "mag": "magnified", "em": "Energy–mass diagram ΔT(JII)"},
}


@dataclass
class Block:
    """Items of a drawn block and the labels still to place among its lines."""

    items: list
    labels: list
    right: float = 0.0
    bottom: float = 0.0

    def line(self, pts, style=THIN) -> None:
        pts = [(float(x), float(y)) for x, y in pts]
        if len(pts) >= 2:
            self.items.append(Polyline(tuple(pts), style, layer=LAYER))

    def text(self, pos, s, h=TEXT_H, anchor="start", rot=0.0) -> None:
        self.items.append(Text(pos, s, h, anchor, rot, layer=LAYER))

    def arrow(self, p0, p1) -> None:
        self.items.append(Arrow(p0, p1, THIN, 3.5, 1.0, layer=LAYER))

    def dot(self, p, r=0.5) -> None:
        self.items.append(Circle(p, r, DOT, layer=LAYER))

    def label(self, anchor, s, h=SMALL_H, prefer=None, group="") -> None:
        self.labels.append(LabelRequest((float(anchor[0]), float(anchor[1])), s, h, group,
                                        prefer))

    def finish(self, ident: str, keep_out=(), leaders: float = 0.0) -> list:
        """The items with the labels placed clear of the block's lines and texts (where
        none is clear near its point, up to ``leaders`` mm away on a thin leader)."""
        obstacles = [g for it in iter_leaves(self.items)
                     if not isinstance(it, Text) and (g := item_geometry(it)) is not None]
        keep = [text_box(t) for t in iter_leaves(self.items) if isinstance(t, Text)]
        texts = place_labels(self.labels, obstacles, layer=LAYER, id_prefix=ident,
                             merge_mm=0.5, max_radius=10.0, keep_out=[*keep, *keep_out],
                             leaders=leaders)
        return _broken_under(self.items, [text_box(t) for t in texts if isinstance(t, Text)]) \
            + texts


def _broken_under(items: list, boxes: list) -> list:
    """The thin straight ordinates (two-point lines across φ axes, where the intervals are
    closer than a position's number is wide) interrupted where a number still stands on
    them, as a drafter leaves a gap in a thin line for a number; other lines untouched."""
    if not boxes:
        return items
    inner = union_all([b.buffer(-0.15) for b in boxes])  # a line through a number's box
    gaps = union_all([b.buffer(0.4) for b in boxes])
    out: list = []
    for it in items:
        if not (isinstance(it, Polyline) and len(it.points) == 2 and it.style == THIN
                and abs(it.points[0][0] - it.points[1][0]) < 1e-9):
            out.append(it)
            continue
        line = LineString(it.points)
        if not line.intersects(inner):
            out.append(it)
            continue
        rest = line.difference(gaps)
        parts = getattr(rest, "geoms", [rest])
        out += [Polyline(tuple((float(x), float(y)) for x, y in g.coords), it.style,
                         layer=it.layer, id=it.id)
                for g in parts if not g.is_empty and g.length > 0.3]
    return out


def _axes(b: Block, x0: float, y0: float, x_from: float, x_to: float, y_lo: float,
          y_hi: float, ylabel: str, xlabel: str = "φ", left: bool = False,
          where: str = "above", shift: float = 0.0) -> None:
    """Abscissa from x_from to x_to at y0 and ordinate from y_lo up to y_hi at x0, arrows;
    the ordinate's letters right of its arrow (``left``: left of it), the abscissa's above
    its arrow's tip (``where``: "above", "below" or "beyond" it; ``shift`` mm back from it)."""
    b.arrow((x_from, y0), (x_to, y0))
    b.arrow((x0, y_lo), (x0, y_hi))
    if where == "beyond":
        b.text((x_to + 1.0, y0 + 0.5 * TEXT_H), xlabel, TEXT_H)
    else:
        b.text((x_to - 1.0 - shift, y0 + 5.0 if where == "below" else y0 - 2.0), xlabel,
               TEXT_H, "end")
    if left:
        b.text((x0 - 2.0, y_hi + 2.0), ylabel, TEXT_H, "end")
    else:
        b.text((x0 + 2.5, y_hi + 2.0), ylabel, TEXT_H)


def _ticks(b: Block, xs, y0: float, ys_curve, labels) -> None:
    """Marks at the positions on the φ axis; numbers on the side away from the curve."""
    for x, yc, lab in zip(xs, ys_curve, labels, strict=True):
        b.line(((x, y0 - 1.0), (x, y0 + 1.0)))
        b.label((x, y0), lab, SMALL_H, -90.0 if yc <= y0 else 90.0, group="pos")


def work_items(u, x_left: float, y_top: float, lang: str, leaders: float = 0.0
               ) -> tuple[list, dict]:
    """Mс(φ), Aс/Aд(φ) and ΔT(φ) stacked from (x_left, y_top) (``leaders`` as in
    :func:`energy_mass_items`); returns the items and the
    geometry the energy–mass diagram aligns with (``y_T0``, ``T_top``, ``T_bottom``,
    ``right``, ``bottom``)."""
    w = WORDS[lang]
    fw, m = unit_parts(u)
    wd = fw.work
    H, Kphi, KM, KA, KT = wd.H, wd.Kphi, wd.KM, wd.KA, fw.KT
    x0 = x_left + 6.0 + H
    x_tau = x0 + m.tau / Kphi
    x_end = x0 + float(m.tau[-1]) / Kphi
    xn = x0 + wd.node_tau / Kphi
    pos_x = x0 + m.moment.pos_tau / Kphi
    labels = list(m.moment.labels)
    # an engine (its loads drive it): the curve is the driving moment, the line resists
    curve_M, line_M, curve_A, line_A = (("Mд", "Mс", "Aд", "Aс") if u.motor is None
                                        else ("Mс", "Mд", "Aс", "Aд"))
    b = Block([], [])

    # --- Mс(φ) with the mean ordinates, the pole's rays and Mд
    yM = m.moment.M / KM
    yMd = wd.M_d / KM
    hi = max(float(yM.max()), float(wd.yM_mm.max()), yMd, 0.0)
    lo = min(float(yM.min()), float(wd.yM_mm.min()), 0.0)
    y0 = y_top + STRIP + hi
    _axes(b, x0, y0, x0 - H - 3.0, x_end + 10.0, y0 - lo + 3.0, y0 - hi - 8.0,
          f"Mс, Mд, {w['Nm']}")
    b.text((x0 + 4.0 + 30.0, y0 - hi - 6.0),
           sheet_text(f"KM = {fmt(KM, 4)} {w['Nm']}/{w['mm']},  H = {fmt(H)} {w['mm']},  "
                f"Kφ = {fmt(Kphi, 4)} {w['rad']}/{w['mm']}", lang), SMALL_H)
    b.line(np.column_stack((x_tau, y0 - yM)))
    stairs = []
    for i, y in enumerate(wd.yM_mm):
        stairs += [(xn[i], y0 - y), (xn[i + 1], y0 - y)]
    b.line(stairs, MAIN)
    for i in range(len(xn)):  # the intervals' bounds: ordinates up to their steps
        near = [wd.yM_mm[j] for j in (i - 1, i) if 0 <= j < len(wd.yM_mm)]
        reach = max(near, key=abs)
        b.line(((xn[i], y0 + (0.8 if reach > 0 else -0.8)), (xn[i], y0 - reach)))
    b.line(((x0, y0 - yMd), (x_end, y0 - yMd)), DASHED)
    b.label((x_end, y0 - yMd), line_M, TEXT_H, 0.0)
    k = int(np.argmin(yM)) if abs(lo) >= hi else int(np.argmax(yM))
    b.label((x_tau[k], y0 - yM[k]), curve_M, TEXT_H, -90.0 if yM[k] < 0 else 90.0)
    levels: list[float] = []  # each mean ordinate projected on the ordinate axis (where
    for i, y in enumerate(wd.yM_mm):  # it stands clear of the axis and of the others)
        if abs(y) >= 5.0 and all(abs(y - v) >= 2.0 for v in levels):
            levels.append(float(y))
            b.line((((xn[i] + xn[i + 1]) / 2, y0 - y), (x0, y0 - y)))
        b.line(((x0 - H, y0), (x0, y0 - y)))  # and the ray from P to its projection
    b.dot((x0 - H, y0), 0.7)
    b.label((x0 - H, y0), "P", TEXT_H, 135.0)
    pos_M = np.interp(m.moment.pos_tau, m.tau, yM)
    for x, y in zip(pos_x, pos_M, strict=True):
        if abs(y) > 1.0:
            b.line(((x, y0), (x, y0 - y)))
    _ticks(b, pos_x, y0, y0 - pos_M, labels)
    y_bottom = y0 - lo + BELOW

    # --- Aс(φ) by chords, Aд(φ)
    yAc, yAd = wd.A_c / KA, wd.A_d / KA
    yA_end = -float(wd.yA_mm[-1])
    every = np.concatenate((yAc, yAd, wd.yA_mm, [yA_end, 0.0]))
    hi, lo = float(every.max()), float(every.min())
    y0 = y_bottom + STRIP + hi
    _axes(b, x0, y0, x0 - 3.0, x_end + 10.0, y0 - lo + 3.0, y0 - hi - 8.0,
          f"Aс, Aд, {w['J']}")
    b.text((x0 + 34.0, y0 - hi - 6.0),
           sheet_text(f"KA = Kφ·KM·H = {fmt(KA, 4)} {w['J']}/{w['mm']}", lang), SMALL_H)
    b.line(np.column_stack((x_tau, y0 - yAc)))
    b.line(np.column_stack((x_tau, y0 - yAd)))
    b.line(np.column_stack((xn, y0 - wd.yA_mm)), MAIN)
    for x, y in zip(xn, wd.yA_mm, strict=True):
        b.dot((x, y0 - y))
    b.line(((x0, y0), (x_end, y0 - yA_end)), MAIN)
    b.label((x_end, y0 - yA_end), line_A, TEXT_H, 0.0)
    b.label((x_end, y0 - wd.yA_mm[-1]), curve_A, TEXT_H, 0.0)
    pos_c = np.interp(m.moment.pos_tau, m.tau, yAc)
    yAd_n = -wd.yA_mm[-1] * (wd.node_tau / float(wd.node_tau[-1]))
    for x, yc, yd in zip(xn, wd.yA_mm, yAd_n, strict=True):  # ΔT = Aд + Aс at the nodes
        if abs(yd - yc) > 1.0:
            b.line(((x, y0 - yc), (x, y0 - yd)))
    _ticks(b, pos_x, y0, y0 - pos_c, labels)
    y_bottom = y0 - lo + BELOW

    # --- ΔT(φ) at KT, the ordinates of the positions drawn
    yT = wd.dT / KT
    yTg = wd.dT_graph / KT
    hi = max(float(yT.max()), float(yTg.max()), fw.k_mm, 0.0)  # k and l of the energy–
    lo = min(float(yT.min()), float(yTg.min()), fw.l_mm, 0.0)  # mass diagram level with it
    T_top = y_bottom + 4.0
    y0 = T_top + STRIP + hi
    _axes(b, x0, y0, x0 - 3.0, x_end + 10.0, y0 - lo + 3.0, y0 - hi - 8.0,
          f"ΔT, {w['J']}")
    b.text((x0 + 24.0, y0 - hi - 6.0),
           sheet_text(f"ΔT = Aд + Aс;  KT = {fmt(KT, 4)} {w['J']}/{w['mm']} "
                f"(KA/KT = {fmt(KA / KT, 4)})", lang), SMALL_H)
    b.line(np.column_stack((x_tau, y0 - yT)))
    b.line(np.column_stack((xn, y0 - yTg)), MAIN)
    for x, y in zip(xn, yTg, strict=True):
        b.dot((x, y0 - y))
    pos_T = np.interp(m.moment.pos_tau, m.tau, yT)
    for x, y in zip(xn, yTg, strict=True):  # the ordinates carried over from Aс, Aд
        if abs(y) > 1.0:
            b.line(((x, y0), (x, y0 - y)))
    _ticks(b, pos_x, y0, y0 - pos_T, labels)
    bottom = y0 - lo + BELOW
    right = x_end + 12.0
    return b.finish("s3-work-label", leaders=leaders), {
        "y_T0": y0, "T_top": T_top, "T_bottom": bottom, "right": right, "bottom": bottom}


def unit_parts(u):
    return u.flywheel, u.model


def _magnify(width: float, least: float = MIN_READ) -> float:
    """Magnification of a JII(φ) only ``width`` mm wide (narrower than ``least``): 1, 2,
    2.5, 4, 5, 10 … ×."""
    if width >= least or width <= 0:
        return 1.0
    for k in (2.0, 2.5, 4.0, 5.0, 10.0, 20.0, 25.0, 40.0, 50.0, 100.0):
        if width * k >= least:
            return k
    return 100.0


def energy_mass_width(u, least: float = MIN_READ) -> float:
    """Width of the energy–mass block (both diagrams and their letters), mm; ``least`` the
    narrowest JII(φ) drawn unmagnified (:data:`MIN_READ` on A1)."""
    fw, m = unit_parts(u)
    W = float(m.inertia.I_var.max()) / fw.KI
    W2 = W * _magnify(W, least)
    return LEFT_B + max(W + 16.0, W2 + 8.0, 46.0)


def energy_mass_items(u, x_left: float, y_top: float, geo: dict, lang: str,
                      least: float = MIN_READ, width: float | None = None,
                      leaders: float = 0.0) -> list:
    """The energy–mass diagram level with ΔT(φ) and JII(φ) turned above it (``least`` as
    in :func:`energy_mass_width`; JII(φ)'s scales in two lines where they are wider than
    ``width``; a position's number with no clear spot near its point up to ``leaders`` mm
    away on a thin leader)."""
    w = WORDS[lang]
    fw, m = unit_parts(u)
    KJ, KT = fw.KI, fw.KT
    xJ0 = x_left + LEFT_B
    y0 = geo["y_T0"]
    xI = xJ0 + m.inertia.I_var / KJ
    W = float(m.inertia.I_var.max()) / KJ
    yT = y0 - fw.work.dT / KT
    b = Block([], [])
    top_T = float(yT.min())
    bot_T = float(yT.max())
    y_k, y_l = y0 - fw.k_mm, y0 - fw.l_mm
    x_far = xJ0 + W + 12.0
    # JII above its axis; under it where a tangent runs through the letters there (k or l
    # near the axis), past the arrow's tip where the tangents or the curve leave neither
    tw = text_width(Text((0.0, 0.0), "JII", TEXT_H, layer=LAYER))
    drawn = [LineString(((xJ0, yk), (x_far, yk - tan * (x_far - xJ0))))
             for yk, tan in ((y_k, fw.tan_max), (y_l, fw.tan_min))]
    drawn.append(LineString(np.column_stack((xI, yT))))
    r_psi = min(12.0, max(x_far - xJ0 - 2.0, 6.0))  # the ψ arcs and their bases
    drawn += [g for yk in (y_k, y_l) for g in (
        LineString(((xJ0, yk), (xJ0 + r_psi + 2.0, yk))),
        shapely_box(xJ0 - r_psi, yk - r_psi, xJ0 + r_psi, yk + r_psi).boundary)]
    where, shift = "beyond", 0.0
    for dx in (0.0, 3.0, 6.0, 9.0, 12.0):  # along the axis, nearest its tip first
        for place, (ya, yb) in (("above", (y0 - 2.0 - TEXT_H, y0 - 1.0)),
                                ("below", (y0 + 1.0, y0 + 5.5))):
            spot = shapely_box(x_far + 1.0 - tw - dx, ya, x_far + 1.0 - dx, yb)
            if x_far + 1.0 - tw - dx > xJ0 + 1.0 and not any(g.intersects(spot)
                                                              for g in drawn):
                where, shift = place, dx
                break
        if where != "beyond":
            break
    _axes(b, xJ0, y0, xJ0 - 3.0, x_far + 2.0, max(bot_T, y_l) + 4.0,
          min(top_T, y_k) - 9.0, f"ΔT, {w['J']}", "JII", left=True, where=where,
          shift=shift)
    b.line(np.column_stack((xI, yT)), MAIN)
    pos_I = xJ0 + np.interp(m.moment.pos_tau, m.tau, m.inertia.I_var) / KJ
    pos_T = y0 - np.interp(m.moment.pos_tau, m.tau, fw.work.dT) / KT
    for x, y in zip(pos_I, pos_T, strict=True):
        b.dot((x, y))
    # captions above the diagram, under JII(φ)
    yc = geo["T_top"] - 17.0
    caption_texts = [Text((x_left, yc + i * 5.0), sheet_text(s, lang), SMALL_H, "start", 0.0,
                          layer=LAYER) for i, s in enumerate((
            f"KJ = {fmt(KJ, 4)} {w['kgm2']}/{w['mm']}", f"KT = {fmt(KT, 4)} {w['J']}/{w['mm']}",
            "tg ψ = KJ·ω²·(1 ± δ)/(2·KT)",
            f"ψmax = {fw.psi_max:.1f}°,  ψmin = {fw.psi_min:.1f}°"))]
    captions = union_all([text_box(t).buffer(-0.15) for t in caption_texts])
    # the tangents: ΔT = b + k·JII, drawn from the ΔT axis past the curve
    for yk, tan, psi, name, angle_name in ((y_k, fw.tan_max, fw.psi_max, "k", "ψmax"),
                                           (y_l, fw.tan_min, fw.psi_min, "l", "ψmin")):
        length = x_far - xJ0
        reach = length  # a steep tangent stops under the captions above the diagram
        if tan > 0 and LineString(((xJ0, yk), (x_far, yk - tan * length))).intersects(
                captions):
            reach = (yk - geo["T_top"] - 1.0) / tan
        b.line(((xJ0, yk), (xJ0 + reach, yk - tan * reach)))
        b.dot((xJ0, yk), 0.6)
        b.labels.insert(0, LabelRequest((xJ0, yk), name, TEXT_H, "kl",
                                        150.0 if name == "k" else -150.0))
        r = min(12.0, max(length - 2.0, 6.0))
        b.line(((xJ0, yk), (xJ0 + r + 2.0, yk)))
        b.items.append(Arc((xJ0, yk), r, 0.0, psi, THIN, layer=LAYER))
        mid = math.radians(psi / 2)
        b.label((xJ0 + r * math.cos(mid), yk - r * math.sin(mid)), angle_name, SMALL_H, 0.0)
    # kl: a dimension on the left of the axis
    xd = xJ0 - 9.0
    b.line(((xJ0 - 1.0, y_k), (xd - 2.0, y_k)))
    b.line(((xJ0 - 1.0, y_l), (xd - 2.0, y_l)))
    b.items.append(Arrow(((xd, (y_k + y_l) / 2)), (xd, y_k), THIN, 3.5, 1.0, layer=LAYER))
    b.items.append(Arrow(((xd, (y_k + y_l) / 2)), (xd, y_l), THIN, 3.5, 1.0, layer=LAYER))
    kl = sheet_text(f"kl = {fw.segment_mm:.1f} {w['mm']}", lang)
    long = text_width(Text((0.0, 0.0), kl, SMALL_H, layer=LAYER))
    # the arrowheads reach the number: it stands clear of them; longer than kl itself: clear
    # of the extension lines' ends too
    off = 1.0 if long + 2 * 3.5 + 2.0 <= abs(y_l - y_k) else \
        2.0 if long + 1.0 <= abs(y_l - y_k) else 3.5
    b.text((xd - off, (y_k + y_l) / 2), kl, SMALL_H, "middle", 90.0)
    for x, y, lab in zip(pos_I, pos_T, m.moment.labels, strict=True):
        b.label((x, y), lab, SMALL_H, 0.0)
    for t in caption_texts:
        b.items.append(t)
    # JII(φ) turned 90°, φ downwards, above the diagram
    k = _magnify(W, least)
    KJ2 = KJ / k
    space = geo["T_top"] - y_top - 16.0 - 24.0
    L2 = float(min(240.0, 12.0 * math.floor(space / 12.0)))
    if L2 >= 60.0:
        cyc = float(m.tau[-1])
        Kphi2 = cyc / L2
        yA = y_top + 12.0
        b.arrow((xJ0 - 3.0, yA), (xJ0 + W * k + 10.0, yA))
        b.arrow((xJ0, yA - 2.0), (xJ0, yA + L2 + 6.0))
        b.text((xJ0 + 2.0, yA + L2 + 6.0), "φ", TEXT_H)
        b.text((xJ0 + W * k + 9.0, yA - 2.0), "JII", TEXT_H, "end")
        b.line(np.column_stack((xJ0 + m.inertia.I_var / KJ2, yA + m.tau / Kphi2)), MAIN)
        py = yA + m.moment.pos_tau / Kphi2
        px = xJ0 + np.interp(m.moment.pos_tau, m.tau, m.inertia.I_var) / KJ2
        for x, y, lab in zip(px, py, m.moment.labels, strict=True):
            if x - xJ0 > 0.5:
                b.line(((xJ0, y), (x, y)))
            b.line(((xJ0 - 1.0, y), (xJ0 + 1.0, y)))
            b.label((xJ0 - 1.0, y), lab, SMALL_H, 180.0, group="phi")
        cap = (f"JII(φ): KJ = {fmt(KJ2, 4)} {w['kgm2']}/{w['mm']}"
               + (f" ({w['mag']} {fmt(k)}×)" if k > 1 else "")
               + f", Kφ = {fmt(Kphi2, 4)} {w['rad']}/{w['mm']}")
        cap = sheet_text(cap, lang)
        cut = cap.find(", Kφ")
        if width is not None and cut > 0 and text_width(
                Text((0.0, 0.0), cap, SMALL_H, layer=LAYER)) > width:  # two lines
            b.text((x_left, y_top + 2.5), cap[:cut + 1], SMALL_H)
            b.text((x_left, y_top + 6.0), cap[cut + 2:], SMALL_H)
        else:
            b.text((x_left, y_top + 4.0), cap, SMALL_H)
    return b.finish("s3-em-label", leaders=leaders)


def omega_items(u, box: Rect, lang: str) -> list:
    """ω(φ) of the steady motion with Jп + Jрот + Jм and constant Mд (energy form), with
    ωmax, ωmin, ωср and δ, drawn in ``box`` (:class:`graphplan.drawing.chart.Chart`: its
    axes 24 mm in from the left, 10 mm from the top, 12 mm from the bottom, 6 mm from the
    right)."""
    from .chart import ALL_STEPS, Chart, auto_limits, tick_labels
    from .figures import spaced_labels

    w = WORDS[lang]
    s = u.simulation
    deg = np.degrees(s.tau)
    width_mm, height_mm = box.width, box.height
    levels = (s.omega_max, s.omega_min, s.omega_avg)
    ax = Chart(box.x0 + 24.0, box.y0 + 10.0, width_mm - 30.0, height_mm - 22.0,
               (0.0, float(deg[-1])), auto_limits([s.omega, levels]), lang)
    ticks = np.degrees(u.model.moment.pos_tau)
    # at most 5 values of ω, 8 mm apart at least (a low plot on a small format)
    yv = ax.y_values(most=min(5, max(2, int((height_mm - 22.0) / 8.0))), steps=ALL_STEPS)
    ax.grid(ticks, yv, 0.25)
    ax.plot(deg, s.omega, 0.5)
    for v in levels:
        ax.hline(v, 0.25, (4.0, 1.5))
    ax.frame(0.25)
    ax.xticks(ticks, spaced_labels(ticks, list(u.model.moment.labels),
                                   (width_mm - 30.0) / float(deg[-1])))
    ax.ylabel(f"ω, {w['rad']}/{w['s']}", ax.yticks(yv, tick_labels(yv)))
    title = (f"{w['omega' if u.flywheel.needed else 'omega_none']}: "
             f"δ = {s.delta_actual:.4f} "
             f"({w['target']} {s.delta_target:g})")
    ax.letter(box.x0 + 0.5 * width_mm, box.y0 + 1.5, title, TEXT_H, "center", "top")
    return [Group(tuple(ax.items), layer=LAYER, id="s3-omega")]




SCHEME_WORDS = {
    "ru": {"title": "Схема машинного агрегата", "motor": "Двигатель", "gear": "Передача",
           "mech": "Механизм", "engine": "Двигатель", "consumer": "Потребитель",
           "fly": "Маховик", "kw": "кВт", "rpm": "об/мин"},
    "en": {"title": "The machine unit", "motor": "Motor", "gear": "Transmission",
           "mech": "Mechanism", "engine": "Engine", "consumer": "Consumer",
           "fly": "Flywheel", "kw": "kW", "rpm": "rpm"},
}
SCHEME_HEIGHT = 66.0  #: the scheme of the machine unit with its captions, mm
SCHEME_WIDTH = 240.0  #: its blocks and shafts, mm


def unit_scheme_items(u, x: float, y: float, width: float, title: str, lang: str) -> list:
    """The scheme of the machine unit (схема машинного агрегата) whose dynamics sheet 3
    solves, at (x, y) within ``width`` mm: the motor, the transmission of ratio u (a
    gearbox, a belt or a coupling) and the mechanism on one shaft line, the flywheel on the
    shaft it is mounted on (the crank's or the motor's), each captioned with its data — or,
    where the loads drive the crank (an engine), the engine's mechanism, the flywheel and
    the consumer of the constant moment Mс. ``[]`` when ``width`` is less than
    :data:`SCHEME_WIDTH`."""
    if width < SCHEME_WIDTH:
        return []
    w, ww = SCHEME_WORDS[lang], WORDS[lang]
    fw = u.flywheel
    items: list = [Text((x, y + 5.0), w["title"], 5.0, layer=LAYER, id="s3-unit-title")]
    ys = y + 27.0  # the shaft line
    bw, bh = 44.0, 22.0
    fly = fw.I_m > 0
    if u.motor is None:  # an engine: its mechanism, the flywheel, the consumer
        blocks = [(w["engine"], [title, f"ω1 = {fmt(fw.omega, 4)} {ww['rad']}/{ww['s']}"]),
                  (w["consumer"], [f"Mс = {fmt(fw.M_d, 4)} {ww['Nm']}"])]
        fly_at = 1
    else:
        mc = u.motor
        blocks = [(w["motor"], [mc.motor.type, f"{fmt(mc.motor.power_kw, 3)} {w['kw']}, "
                                f"{fmt(mc.motor.rated_rpm, 4)} {w['rpm']}"]),
                  (w["gear"], [f"u = {fmt(mc.u, 4)}"]),
                  (w["mech"], [title, f"ω1 = {fmt(fw.omega, 4)} {ww['rad']}/{ww['s']}"])]
        fly_at = 1 if u.shaft == "motor" else 2
    n = len(blocks) + (1 if fly else 0)
    pitch = (SCHEME_WIDTH - bw) / max(n - 1, 1)

    def reach(j: int) -> float:  # a block's half width with its captions
        return max([bw] + [text_width(Text((0, 0), sheet_text(c, lang), 3.5, layer=LAYER))
                           for c in blocks[j][1]]) / 2

    first = x + reach(0)  # the captions inside ``width``: none over the ΔT axis on its left
    if first + pitch * (n - 1) + reach(len(blocks) - 1) > x + width:
        return []
    xs = [first + i * pitch for i in range(n)]
    where: dict[object, float] = {}
    k = 0
    for i in range(n):
        if fly and i == fly_at:
            where["fly"] = xs[i]
            continue
        where[k] = xs[i]
        k += 1
    # the shafts between the blocks (main lines), to the flywheel's faces
    half = [3.0 if fly and i == fly_at else bw / 2 for i in range(n)]
    for i in range(n - 1):
        items.append(Polyline(((xs[i] + half[i], ys), (xs[i + 1] - half[i + 1], ys)), MAIN,
                              layer=LAYER, id=f"s3-unit-shaft{i}"))
    for j, (name, caption) in enumerate(blocks):
        cx = where[j]
        x0, x1, y0, y1 = cx - bw / 2, cx + bw / 2, ys - bh / 2, ys + bh / 2
        items.append(Polyline(((x0, y0), (x1, y0), (x1, y1), (x0, y1)), MAIN, closed=True,
                              layer=LAYER, id=f"s3-unit-block{j}"))
        items.append(Text((cx, ys + 1.75), name, 3.5, "middle", layer=LAYER,
                          id=f"s3-unit-name{j}"))
        for i, line in enumerate(caption):
            items.append(Text((cx, y1 + 8.0 + 6.0 * i), sheet_text(line, lang), 3.5, "middle",
                              layer=LAYER, id=f"s3-unit-cap{j}-{i}"))
    if fly:  # the flywheel seen edgewise on its shaft (GOST 2.770), Jм under it
        cx = where["fly"]
        items.append(Polyline(((cx - 3.0, ys - 13.0), (cx + 3.0, ys - 13.0), (cx + 3.0, ys + 13.0),
                               (cx - 3.0, ys + 13.0)), MAIN, closed=True, layer=LAYER,
                              id="s3-unit-flywheel"))
        items.append(Text((cx, ys - 15.5), w["fly"], 3.5, "middle", layer=LAYER,
                          id="s3-unit-fly-name"))
        # on the motor's shaft the flywheel's own moment of inertia, Jм.дв = Jм/u² (the
        # Jм of the crank would be u² times too large for the wheel drawn there)
        cap = (f"{'Jм.дв' if lang == 'ru' else 'Jм,motor'} = {fmt(u.mounted.inertia, 4)}"
               if u.shaft == "motor" and u.motor is not None else f"Jм = {fmt(fw.I_m, 4)}")
        items.append(Text((cx, ys + 8.0 + bh / 2), sheet_text(f"{cap} {ww['kgm2']}", lang),
                          3.5, "middle", layer=LAYER, id="s3-unit-fly-cap"))
    return items


__all__ = ["energy_mass_items", "energy_mass_width", "omega_items", "unit_scheme_items",
           "work_items"]
