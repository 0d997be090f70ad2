"""Sheet 3, dynamics of the machine unit, laid out as a ТММ sheet shows it (method B.4):

* on the left, one under the other at one Kφ: Mс(φ) with the mean ordinates, the pole P
  and its rays, the line Mд; Aс(φ) by chords and Aд(φ); ΔT(φ) = Aд + Aс;
* beside ΔT(φ) and level with it, Wittenbauer's energy–mass diagram ΔT(JII) with its
  tangents at ψmax, ψmin (tens of degrees: KT and KJ are chosen for it, see
  :func:`graphplan.dynamics.machine.energy_mass_scales`), k, l and kl; above it JII(φ)
  turned 90°;
* under ΔT(φ), where the diagram leaves the room (a ΔT that stays above its axis), the
  scheme of the machine unit: motor, transmission, flywheel and mechanism with their data;
* on the right: the check ω(φ), the flywheel (front view and profile section, dimensioned after
  GOST 2.307: outer and inner diameters and the width in whole mm, the axis drawn), the
  results in the order of the calculation, and the table of values at the positions.

One notation, the method's: J for moments of inertia (Jпр reduced, JI its constant
part, JII the variable one, Jм the flywheel, Jкр the crank, Jрот·u² the rotor reduced
to the crank); Pс = Mд·ω1 the mean power of the resistance, Pдв.тр = Pс/η the power
the motor must give. Sheet 3 takes the format of sheets 1 and 2 (``drawing.format``,
``--page``): its diagrams' scales are chosen for that format
(:class:`graphplan.dynamics.DiagramSize`), so the sheet, ``dynamics.*.md`` and the JSON
agree.
The diagrams are the sheet's own items (:mod:`graphplan.drawing.dynamics_figures`); the
numbers come from :func:`graphplan.dynamics.machine.machine_unit`, the same as in
``dynamics.*.md`` and the JSON report.
"""

from __future__ import annotations

import math

from ..dynamics import DynamicsSettings, MachineUnit, machine_unit
from ..errors import LayoutError
from ..numbers import fmt, sheet_text, signed
from ..paper import Page, Rect
from ..project import CAPTION, GAP, fit_columns
from ..reports import T as TABLE_WORDS
from ..reports import position_rows
from .items import (
    MAIN,
    THIN,
    Arrow,
    Circle,
    Hatch,
    Item,
    Line,
    Polyline,
    Style,
    Text,
    item_geometry,
    iter_leaves,
    text_box,
    text_width,
)
from .sheet import Sheet
from .sheet1 import title_block
from .tables import table_items, titled_table

WORDS = {
    "ru": {"sheet": "Динамический анализ", "flywheel": "Маховик", "rim": "обод",
           "disc": "диск", "results": "Результаты", "table": "Значения в положениях",
           "mass": "масса", "speed": "окружная скорость",
           "no_flywheel": "Маховик не нужен"},
    "en": {"sheet": "Dynamics", "flywheel": "Flywheel", "rim": "rim", "disc": "disc",
           "results": "Results", "table": "Values at the positions", "mass": "mass",
           "speed": "rim speed", "no_flywheel": "No flywheel is needed"},
}
RESULT_H = 3.5  #: lettering of the results, mm
LINE = 6.0  #: line pitch of the results, mm
AXIS = Style(0.25, (15.0, 3.0, 1.0, 3.0))  #: thin dash-dot: axes and centre lines
DIM = THIN  #: dimension and extension lines
ARROW_L, ARROW_W = 3.5, 1.0  #: dimension arrows, mm (GOST 2.307: 2.5…4 long)


def results_lines(u: MachineUnit, lang: str) -> list[str]:
    """The results of sheet 3, one line each, in the order of the calculation."""
    fw, mc = u.flywheel, u.motor
    ru = lang == "ru"
    if mc is None:  # driven by its loads (an engine): the constant moment is the consumer's
        lines = _engine_lines(u, lang)
        return [sheet_text(x, lang) for x in lines]
    mo = mc.motor
    kg_m2 = "кг·м²" if ru else "kg·m²"
    rot = ("Jрот нет в каталоге" if ru else "Jрот not in the catalogue") \
        if mo.inertia_kg_m2 is None else f"Jрот·u² = {fmt(fw.I_rotor, 4)} {kg_m2}"
    kw = "кВт" if ru else "kW"
    lines = [
        f"ω1 = {fmt(fw.omega, 4)} {'рад/с' if ru else 'rad/s'},  δ = {fw.delta:g},  "
        f"η = {u.efficiency:g}",
        f"Mд = {fmt(fw.M_d, 5)} {'Н·м' if ru else 'N·m'} "
        f"({'графически' if ru else 'graphical'} {fmt(fw.work.M_d_graph, 5)}, "
        f"{signed((fw.work.M_d_graph / fw.M_d - 1) * 100)} %)",
        f"Pс = Mд·ω1 = {fmt(fw.P_c / 1000, 4)} {kw};  "
        + (f"Pдв.тр = Pс/η = {fmt(u.power_W / 1000, 4)} {kw}" if ru
           else f"Preq = Pс/η = {fmt(u.power_W / 1000, 4)} {kw}"),
        f"{'Двигатель' if ru else 'Motor'} {mo.type}: {fmt(mo.power_kw)} {kw}, "
        f"{fmt(mo.rated_rpm)} {'об/мин' if ru else 'rpm'}"
        + (f", Mп/Mн = {fmt(mo.start_torque_ratio)}" if mo.start_torque_ratio else "")
        + (f", Mmax/Mн = {fmt(mo.max_torque_ratio)}" if mo.max_torque_ratio else ""),
        f"u = nдв/n1 = {fmt(mo.rated_rpm)}/{fmt(mc.crank_rpm, 4)} = {mc.u:.2f};  {rot}",
        f"ΔTmax − ΔTmin = {fmt(fw.dT_max, 5)} {'Дж' if ru else 'J'}",
        f"JI = kl·KT/(ω1²·δ) = {fw.segment_mm:.1f}·{fmt(fw.KT, 4)}/({fmt(fw.omega, 4)}²·"
        f"{fw.delta:g}) = {fmt(fw.J_I, 5)} {kg_m2}",
        *_flywheel_lines(u, "JI − Jкр − Jрот·u²", lang),
    ]
    if u.shaft == "motor" and fw.needed:  # the flywheel drawn is the motor shaft's
        lines.insert(-1, f"{'Jм.дв' if ru else 'Jм,motor'} = Jм/u² = {fmt(fw.I_m, 5)}/"
                         f"{mc.u:.2f}² = {fmt(u.mounted.inertia, 4)} {kg_m2}")
    return [sheet_text(x, lang) for x in lines]


def _flywheel_lines(u: MachineUnit, what: str, lang: str) -> list[str]:
    """The last results: Jм (or that none is needed) and δ of the simulation."""
    fw, ru = u.flywheel, lang == "ru"
    kg_m2 = "кг·м²" if ru else "kg·m²"
    sim = ("при моделировании" if ru else "simulated")
    if not fw.needed:  # the crank and the rotor already hold ω within δ
        return [f"Jм = {what} = {fmt(fw.I_m_signed, 5)} {kg_m2} ≤ 0: "
                + ("маховик не нужен" if ru else "no flywheel is needed"),
                f"δ {sim} {'без маховика' if ru else 'without one'} = "
                f"{u.simulation.delta_actual:.4f} ≤ δ = {fw.delta:g}"]
    # the subtraction written out, each term as the results give it (Jкр: the crank's link
    # about O and dynamics.crank_inertia), so that a checker can follow it
    terms = [fmt(fw.J_I, 5), fmt(fw.I_const, 4)] + ([fmt(fw.I_rotor, 4)]
                                                    if u.motor is not None else [])
    return [f"Jм = {what} = {' − '.join(terms)} = {fmt(fw.I_m, 5)} {kg_m2} "
            f"({'Мерцалов' if ru else 'Merkalov'} {fmt(fw.I_m_approx, 5)}, "
            f"{signed(fw.difference_pct)} %)",
            f"δ {sim} = {u.simulation.delta_actual:.4f} ({signed(u.delta_error_pct)} %)"]


def _engine_lines(u: MachineUnit, lang: str) -> list[str]:
    """Sheet 3's results of a machine its loads drive (an engine): Mс constant, no motor."""
    fw, ru = u.flywheel, lang == "ru"
    kg_m2 = "кг·м²" if ru else "kg·m²"
    cyc = f"{math.degrees(u.model.period):.0f}°"
    return [
        f"ω1 = {fmt(fw.omega, 4)} {'рад/с' if ru else 'rad/s'},  δ = {fw.delta:g}",
        f"Mс = −Aд({cyc})/{'4π' if u.model.period > 7 else '2π'} = {fmt(fw.M_d, 5)} "
        f"{'Н·м' if ru else 'N·m'} ({'графически' if ru else 'graphical'} "
        f"{fmt(fw.work.M_d_graph, 5)}, {signed((fw.work.M_d_graph / fw.M_d - 1) * 100)} %)",
        f"P = |Mс|·ω1·η = {fmt(u.power_W / 1000, 4)} {'кВт' if ru else 'kW'}",
        f"ΔTmax − ΔTmin = {fmt(fw.dT_max, 5)} {'Дж' if ru else 'J'}",
        f"JI = kl·KT/(ω1²·δ) = {fw.segment_mm:.1f}·{fmt(fw.KT, 4)}/({fmt(fw.omega, 4)}²·"
        f"{fw.delta:g}) = {fmt(fw.J_I, 5)} {kg_m2}",
        *_flywheel_lines(u, "JI − Jкр", lang),
    ]


def _scale_ratio(need: float) -> float:
    """The smallest GOST 2.302 reduction 1:n with n ≥ need."""
    for n in (1, 2, 2.5, 4, 5, 10, 15, 20, 25, 40, 50, 75, 100, 200, 400, 500, 800, 1000):
        if n >= need * (1.0 - 1e-9):  # a box sized for 1:n gives n back, not the next one
            return float(n)
    return float(math.ceil(need / 1000.0) * 1000)


def dimension(p0, p1, text: str, ident: str, *, side: float = 1.0,
              shelf_at_start: bool = False) -> list[Item]:
    """A linear dimension between the ends p0, p1 of its dimension line (GOST 2.307).

    The arrows' tips touch the extension lines at p0 and p1; the number stands above the
    line (``side`` = +1: on the left of p0→p1, as read), parallel to it. Between ends
    closer than two arrows the arrows are drawn outside, pointing in; a number wider than
    the space between the extension lines stands on the dimension line drawn on past p1
    (``shelf_at_start``: past p0).
    """
    (x0, y0), (x1, y1) = p0, p1
    length = math.hypot(x1 - x0, y1 - y0)
    ux, uy = (x1 - x0) / length, (y1 - y0) / length
    items: list[Item] = []
    if length >= 2.5 * ARROW_L:
        mx, my = (x0 + x1) / 2, (y0 + y1) / 2
        items += [Arrow((mx, my), (x0, y0), DIM, ARROW_L, ARROW_W, layer="dimensions",
                        id=f"{ident}-a"),
                  Arrow((mx, my), (x1, y1), DIM, ARROW_L, ARROW_W, layer="dimensions",
                        id=f"{ident}-b")]
    else:
        out = ARROW_L + 2.0
        items += [Arrow((x0 - ux * out, y0 - uy * out), (x0, y0), DIM, ARROW_L, ARROW_W,
                        layer="dimensions", id=f"{ident}-a"),
                  Arrow((x1 + ux * out, y1 + uy * out), (x1, y1), DIM, ARROW_L, ARROW_W,
                        layer="dimensions", id=f"{ident}-b"),
                  Line((x0, y0), (x1, y1), DIM, layer="dimensions", id=f"{ident}-l")]
    angle = math.degrees(math.atan2(-(y1 - y0), x1 - x0))
    mx, my = (x0 + x1) / 2, (y0 + y1) / 2
    tw = text_width(Text((0.0, 0.0), text, 3.5, layer="dimensions"))
    if tw + 1.0 > length:  # no room between the extension lines: the number stands on the
        out = (ARROW_L + 2.0 if length < 2.5 * ARROW_L else 0.0) + 1.0  # dimension line
        (ex, ey), sx, sy = ((x0, y0), -ux, -uy) if shelf_at_start else ((x1, y1), ux, uy)
        mx, my = ex + sx * (out + tw / 2), ey + sy * (out + tw / 2)  # drawn on past an end
        items.append(Line((ex, ey), (ex + sx * (out + tw + 1.0), ey + sy * (out + tw + 1.0)),
                          DIM, layer="dimensions", id=f"{ident}-shelf"))
    if angle <= -90.0 or angle > 90.0:  # numbers read from the bottom or the right
        angle = (angle + 180.0) % 360.0
        ux, uy = -ux, -uy
    nx, ny = uy, -ux  # "above" the line as read
    gap = 0.3 * 3.5 + 0.8  # the number's descenders clear of the line
    items.append(Text((mx + nx * gap * side, my + ny * gap * side), text, 3.5, "middle",
                      angle % 360.0, layer="dimensions", id=f"{ident}-t"))
    return items


FW_ABOVE, FW_BELOW = CAPTION + 14.0, 14.0  #: the flywheel block above and below its views


def _flywheel_scale(u: MachineUnit, width: float, height: float) -> float:
    """GOST reduction 1:n of the flywheel's views in a box ``width`` × ``height`` mm: the
    front view (⌀ outer) and the section (b) with its dimensions side by side."""
    s = u.mounted
    D_out = s.D + (s.h if s.shape == "rim" else 0.0)
    need = max(D_out * 1000.0 / (height - FW_ABOVE - FW_BELOW),
               (D_out + s.b) * 1000.0 / (width - 70.0))
    return _scale_ratio(need)


def flywheel_height(u: MachineUnit, width: float, height: float) -> float:
    """Height the flywheel block takes at the scale it gets in a box of that size, mm."""
    if not u.flywheel_needed:
        return CAPTION + 3.0 + len(_no_flywheel_lines(u, "ru")) * LINE
    s = u.mounted
    D_out = s.D + (s.h if s.shape == "rim" else 0.0)
    return FW_ABOVE + D_out * 1000.0 / _flywheel_scale(u, width, height) + FW_BELOW


def _no_flywheel_lines(u: MachineUnit, lang: str) -> list[str]:
    """Why a machine needs no flywheel: JI against what the crank and the rotor have,
    and δ of the run without one."""
    fw, ru = u.flywheel, lang == "ru"
    kg_m2 = "кг·м²" if ru else "kg·m²"
    have = f"Jкр + Jрот·u² = {fmt(fw.I_const, 5)} + {fmt(fw.I_rotor, 4)}" if fw.I_rotor > 0 \
        else f"Jкр = {fmt(fw.I_const, 5)}"
    total = f" = {fmt(fw.I_const + fw.I_rotor, 5)}" if fw.I_rotor > 0 else ""
    lines = [f"JI = {fmt(fw.J_I, 5)} {kg_m2} ≤ {have}{total} {kg_m2}:",
             ("кривошип с ротором двигателя уже держат ω в пределах δ;" if fw.I_rotor > 0
              else "кривошип уже держит ω в пределах δ;") if ru else
             ("the crank and the motor's rotor already hold ω within δ;" if fw.I_rotor > 0
              else "the crank already holds ω within δ;"),
             f"{'δ без маховика' if ru else 'δ without a flywheel'} = "
             f"{u.simulation.delta_actual:.4f} ≤ {fw.delta:g} "
             f"({'моделирование' if ru else 'simulation'}); Jм = 0."]
    return [sheet_text(x, lang) for x in lines]


def _flywheel_items(u: MachineUnit, box: Rect, lang: str) -> list[Item]:
    """The flywheel: front view and the profile section at a GOST scale; ⌀ outer, ⌀ inner (rim)
    and the width b in whole mm with extension lines from the outline; the axis of
    rotation and the centre lines dash-dot. A machine that needs none gets the reason in
    its place."""
    w = WORDS[lang]
    ru = lang == "ru"
    if not u.flywheel_needed:
        none: list[Item] = [Text((box.x0, box.y0 + 5.0), w["no_flywheel"], 5.0, layer="text",
                                 id="s3-fw-title")]
        return none + [
            Text((box.x0, box.y0 + CAPTION + 5.0 + i * LINE), line, RESULT_H, layer="text",
                 id=f"s3-fw-none-{i}")
            for i, line in enumerate(_no_flywheel_lines(u, lang))]
    s = u.mounted
    shaft = TABLE_WORDS[lang]["shaft_" + u.shaft]
    title = (f"{w['flywheel']} ({w[s.shape]}, {shaft}), {w['mass']} "
             f"{fmt(s.mass, 4)} {'кг' if ru else 'kg'}")
    title = sheet_text(title, lang)
    h_title = 5.0 if text_width(Text((0.0, 0.0), title, 5.0, layer="text")) <= box.width \
        else RESULT_H  # a narrow column (A3): the title in the results' lettering
    items: list[Item] = [Text((box.x0, box.y0 + 5.0), title, h_title, layer="text",
                              id="s3-fw-title")]
    D_out = s.D + (s.h if s.shape == "rim" else 0.0)
    D_in = s.D - s.h if s.shape == "rim" else 0.0
    n = _flywheel_scale(u, box.width, box.height)
    k = 1000.0 / n  # mm of paper per m
    R_out, R_in = D_out / 2 * k, D_in / 2 * k
    hub, bore = 0.2 * R_out, 0.1 * R_out
    b = s.b * k
    cy = box.y0 + FW_ABOVE + R_out
    cx = box.x0 + 6.0 + R_out
    lay = "diagrams"
    items.append(Circle((cx, cy), R_out, MAIN, layer=lay, id="s3-fw-outer"))
    if s.shape == "rim":
        items.append(Circle((cx, cy), R_in, MAIN, layer=lay, id="s3-fw-inner"))
    items.append(Circle((cx, cy), hub, MAIN, layer=lay, id="s3-fw-hub"))
    items.append(Circle((cx, cy), bore, MAIN, layer=lay, id="s3-fw-bore"))
    items.append(Line((cx - R_out - 4, cy), (cx + R_out + 4, cy), AXIS, layer=lay,
                      id="s3-fw-axis-h"))
    items.append(Line((cx, cy - R_out - 4), (cx, cy + R_out + 4), AXIS, layer=lay,
                      id="s3-fw-axis-v"))
    # the profile section through the axis, in projection connection with the front view
    # (the rim or the disc, the web and the hub cut, hatched): the flywheel is symmetric
    # about that plane, so GOST 2.305 neither marks the cutting plane nor letters the section
    sx = cx + R_out + 22.0
    web = max(0.3 * b, 1.0)
    hb = max(0.8 * b, 4.0)
    xm = sx + b / 2
    if s.shape == "rim":
        outline = [(sx, cy - R_out), (sx + b, cy - R_out), (sx + b, cy - R_in),
                   (xm + web / 2, cy - R_in), (xm + web / 2, cy - hub),
                   (xm + hb / 2, cy - hub), (xm + hb / 2, cy - bore),
                   (xm - hb / 2, cy - bore), (xm - hb / 2, cy - hub),
                   (xm - web / 2, cy - hub), (xm - web / 2, cy - R_in), (sx, cy - R_in)]
    else:
        outline = [(sx, cy - R_out), (sx + b, cy - R_out), (sx + b, cy - hub),
                   (xm + hb / 2, cy - hub), (xm + hb / 2, cy - bore),
                   (xm - hb / 2, cy - bore), (xm - hb / 2, cy - hub), (sx, cy - hub)]
    lower = [(x, 2 * cy - y) for x, y in outline]
    for i, poly in enumerate((outline, lower)):
        items.append(Polyline(tuple(poly), MAIN, True, layer=lay, id=f"s3-fw-sec{i}"))
        items.append(Hatch(tuple(poly), 2.0, 45.0, layer=lay, id=f"s3-fw-hatch{i}"))
    right = sx + max(b, xm - sx + hb / 2)
    items.append(Line((sx - 6.0, cy), (right + 3.0, cy), AXIS, layer=lay,
                      id="s3-fw-sec-axis"))
    # dimensions, whole mm: ⌀ inner nearer the section, ⌀ outer outside it, b on top
    dims = [(R_out, D_out, "out")] + ([(R_in, D_in, "in")] if s.shape == "rim" else [])
    dims.sort()
    for i, (R, D, name) in enumerate(dims):
        xd = right + 10.0 + 9.0 * i
        items.append(Line((sx + b, cy - R), (xd + 2.0, cy - R), DIM, layer="dimensions",
                          id=f"s3-fw-ext-{name}-t"))
        items.append(Line((sx + b, cy + R), (xd + 2.0, cy + R), DIM, layer="dimensions",
                          id=f"s3-fw-ext-{name}-b"))
        items += dimension((xd, cy + R), (xd, cy - R), f"⌀{round(D * 1000)}",
                           f"s3-fw-dim-{name}")
    yd = cy - R_out - 7.0
    items.append(Line((sx, cy - R_out), (sx, yd - 2.0), DIM, layer="dimensions",
                      id="s3-fw-ext-b0"))
    items.append(Line((sx + b, cy - R_out), (sx + b, yd - 2.0), DIM,
                      layer="dimensions", id="s3-fw-ext-b1"))
    items += dimension((sx, yd), (sx + b, yd), f"{round(s.b * 1000)}", "s3-fw-dim-b",
                       shelf_at_start=True)  # a narrow b's number left, clear of the ⌀
    note = (f"М 1:{fmt(n)};  {w['speed']} v = ω·D/2 = {fmt(s.speed, 3)} м/с"
            + ("" if s.speed_ok else " > 40 м/с!"))
    items.append(Text((box.x0, cy + R_out + 9.0), sheet_text(note, lang), 3.5,
                      layer="text", id="s3-fw-note"))
    # the flywheel's data beside its views, where there is room
    kg, mm_ = ("кг", "мм") if ru else ("kg", "mm")
    data = [f"Jм = {fmt(s.inertia, 5)} {'кг·м²' if ru else 'kg·m²'}",
            f"Dср = {round(s.D * 1000)} {mm_}" if s.shape == "rim" else
            f"D = {round(s.D * 1000)} {mm_}",
            f"b = {round(s.b * 1000)} {mm_},  h = {round(s.h * 1000)} {mm_}"
            if s.shape == "rim" else f"b = {round(s.b * 1000)} {mm_}",
            f"m = {fmt(s.mass, 4)} {kg},  ρ = {fmt(u_density(u))} {kg}/м³",
            f"{'материал: сталь' if ru else 'material: steel'}"
            if u_density(u) == 7800.0 else ""]
    x_data = right + 10.0 + 9.0 * len(dims) + 6.0
    data = [sheet_text(d, lang) for d in data if d]
    widest = max(text_width(Text((0.0, 0.0), d, 3.5, layer="text")) for d in data)
    if box.x1 - x_data >= max(60.0, widest):
        # a line apart beside a small flywheel, its top above the note under the views
        pitch = 2 * LINE if R_out >= 26.0 else LINE
        first = cy - 3.0 * LINE if R_out >= 26.0 else \
            min(cy - 2 * LINE, cy + R_out + 4.5 - (len(data) - 1) * LINE)
        for i, line in enumerate(data):
            items.append(Text((x_data, first + i * pitch), line, 3.5, layer="text",
                              id=f"s3-fw-data-{i}"))
    return items


def u_density(u: MachineUnit) -> float:
    """Density of the flywheel's material, kg/m³, from its mass and size: a rim
    ``m = ρ·π·D·b·h``, a disc ``m = ρ·π·D²·b/4``."""
    s = u.mounted
    vol = math.pi * s.D * s.b * s.h if s.shape == "rim" else math.pi * s.D**2 * s.b / 4
    return round(s.mass / vol, 6) if vol > 0 else 0.0


def wrap_line(line: str, width: float, height: float = RESULT_H) -> list[str]:
    """``line`` broken after its ``;``, ``,`` or before a ``(`` into pieces no wider than
    ``width`` mm at ``height`` where it can be (a piece without a break stays whole); the
    pieces after the first indented."""
    def wide(s: str) -> float:
        return text_width(Text((0.0, 0.0), s, height, layer="text"))

    if wide(line) <= width:
        return [line]
    cuts = [i + 1 for i, c in enumerate(line) if c in ";," and line[i + 1:i + 2] == " "]
    cuts += [i for i, c in enumerate(line) if c == "(" and i > 0]
    for i in sorted(cuts, reverse=True):
        head, tail = line[:i].rstrip(), "   " + line[i:].lstrip()
        if wide(head) <= width:
            return [head, *wrap_line(tail, width, height)]
    return [line]


def _scheme_below(u: MachineUnit, work: list, geo: dict, x_left: float, x_right: float,
                  y_frame: float, mech, lang: str) -> list[Item]:
    """The scheme of the machine unit (:func:`~.dynamics_figures.unit_scheme_items`) under
    ΔT(φ), where the diagram leaves the room free: below the lowest line or letter of the
    work diagrams right of the ΔT axis (which runs on down to the energy–mass diagram's
    intercept l), down to the frame; nothing where that room is too small for it."""
    from shapely.geometry import box as shapely_box

    from .dynamics_figures import SCHEME_HEIGHT, unit_scheme_items

    axis_x = x_left + 6.0 + u.flywheel.work.H  # the ordinate axes of the work diagrams
    strip = shapely_box(axis_x + 2.0, geo["T_top"], x_right - 2.0, y_frame)
    low = geo["T_top"]
    for it in iter_leaves(work):
        g = text_box(it) if isinstance(it, Text) else item_geometry(it)
        if g is not None and g.intersects(strip):
            low = max(low, g.intersection(strip).bounds[3])
    y, width = low + 8.0, x_right - 2.0 - (axis_x + 10.0)
    if y_frame - 4.0 - y < SCHEME_HEIGHT:
        return []
    title = (mech.title_block.title or mech.name)
    return unit_scheme_items(u, axis_x + 10.0, y, width, title, lang)


def _page_of(analysis) -> Page:
    """The variant's ``drawing.format`` (A1 when it gives none)."""
    return Page(analysis.mech.drawing.format)


def dynamics_sheet(analysis, *, lang: str = "ru", page: Page | None = None,
                   unit: MachineUnit | None = None) -> Sheet:
    """Sheet 3 of the project for ``analysis`` (see the module docstring), on ``page``
    (default: the variant's ``drawing.format``), its diagrams at the scales of that format
    (:meth:`graphplan.project.Project.unit_on`) unless ``unit`` is given.

    On A2 and A3 the blocks keep their places at smaller scales; where the table of values
    at the positions leaves ω(φ) and the flywheel too little room (A3) it is moved to
    ``dynamics.*.md`` and the sheet says so.

    Raises
    ------
    LayoutError
        When the diagrams at their scales do not fit the page.
    """
    from .dynamics_figures import (
        MIN_READ,
        energy_mass_items,
        energy_mass_width,
        omega_items,
        work_items,
    )

    mech = analysis.mech
    page = page or _page_of(analysis)
    if unit is not None:
        u = unit
    elif DynamicsSettings.of(mech).delta is not None and hasattr(analysis, "unit_on"):
        u = analysis.unit_on(page)
    else:
        u = machine_unit(analysis)  # the error without δ
    w = WORDS[lang]
    f = page.frame
    tb = page.title_block_rect
    a1 = page.format == "A1"
    kw = min(1.0, f.width / 816.0)  # the format against A1's frame
    kh = min(1.0, f.height / 584.0)
    x0, y0 = f.x0 + 4.0, f.y0 + 18.0
    items: list[Item] = []
    work, geo = work_items(u, x0, y0, lang, 0.0 if a1 else 15.0)
    xB = geo["right"] + 4.0
    least = MIN_READ * kw
    wB = energy_mass_width(u, least)
    xC = xB + wB + GAP
    lines = results_lines(u, lang)
    if not a1:  # long lines broken where the column is narrower than they are
        lines = [p for line in lines for p in wrap_line(line, f.x1 - 4.0 - xC)]
    widest = max(text_width(Text((0, 0), s, RESULT_H, layer="text")) for s in lines)
    need_w = 200.0 if a1 else max(widest, 120.0)
    if geo["bottom"] > f.y1 - 2.0 or f.x1 - 4.0 - xC < need_w:
        raise LayoutError(f"sheet 3: the diagrams at their scales need {xC - x0:.0f}×"
                          f"{geo['bottom'] - y0:.0f} mm; the {page.format} sheet has no room "
                          "(choose fewer dynamics.intervals)")
    items += work
    items += _scheme_below(u, work, geo, x0, xB, f.y1, mech, lang)
    top = f.y0 + 4.0  # right of graph 26 the columns start at the frame
    items += energy_mass_items(u, xB, top, geo, lang, least, None if a1 else wB + GAP - 2.0,
                               0.0 if a1 else 15.0)
    right = Rect(xC, top, f.x1 - 4.0, tb.y0 - GAP)
    rows = position_rows(u, lang)
    header = list(TABLE_WORDS[lang]["cols"])
    table_h = CAPTION + 7.0 * (len(rows) + 1)
    results_h = CAPTION + 3.0 + len(lines) * LINE
    omega_min = 80.0 if a1 else max(45.0, 80.0 * kh)  # ω(φ) is read down to this height
    fw_min = 70.0 if a1 else 90.0 * kh
    free = right.height - table_h - results_h - 3 * GAP
    moved = not a1 and free < omega_min + fw_min
    if moved:  # the table goes to dynamics.*.md: one line says where
        table_h = CAPTION
        free = right.height - table_h - results_h - 3 * GAP
    if free < (150.0 if a1 else omega_min + fw_min):
        raise LayoutError("sheet 3: no room for ω(φ) and the flywheel beside the diagrams")
    fw_h = flywheel_height(u, right.width, free - omega_min)
    om_h = min(free - fw_h, 170.0)
    items += omega_items(u, Rect(right.x0, right.y0, right.x1, right.y0 + om_h), lang)
    fw_box = Rect(right.x0, right.y0 + om_h + GAP, right.x1, right.y0 + om_h + GAP + fw_h)
    items += _flywheel_items(u, fw_box, lang)
    ty = right.y1 - table_h  # the table on the title block, the results above it
    ry = ty - GAP - results_h
    items.append(Text((right.x0, ry + 5.0), w["results"], 5.0, layer="text",
                      id="s3-results-title"))
    for i, line in enumerate(lines):
        items.append(Text((right.x0, ry + CAPTION + 5.0 + i * LINE), line, RESULT_H,
                          layer="text", id=f"s3-result-{i}"))
    fit = fit_columns(header, rows, right.width)
    if moved:
        note = f"{w['table']}: dynamics.{lang}.md"
        items.append(Text((right.x0, ty + 5.0), note, RESULT_H, layer="text",
                          id="s3-table-title"))
    elif fit.shown == fit.total:  # the columns share the whole width of the place
        stretch = right.width / sum(fit.widths)
        items.append(Text((right.x0, ty + 5.0), w["table"], 5.0, layer="text",
                          id="s3-table-title"))
        items += table_items((right.x0, ty + CAPTION), [c * stretch for c in fit.widths],
                             fit.rows, fit.header, 3.5, id="s3-table")
    else:
        items += titled_table(
            right.x0, ty, right.width, w["table"], header, rows,
            ident="s3-table", title_id="s3-table-title",
            notes=lambda n, m: [f" ({n}/{m}, dynamics.{lang}.md)"])
    return Sheet(page, tuple(items), title_block(mech, lang, 3, w["sheet"]), lang=lang)


__all__ = ["dimension", "dynamics_sheet", "results_lines"]
