"""Sheet 3, dynamics of the machine unit: the diagrams of Mс, Aс and Aд, ΔT at their
scales (graphical integration with the pole H), Wittenbauer's energy–mass diagram with
its tangents above Iп(φ) turned 90°, the check of the flywheel by simulation ω(φ), the
flywheel's sketch with its dimensions, the motor and the results, and the table of
values at the positions.

Sheet 3 is A1 whatever ``drawing.format`` says for sheets 1 and 2: its diagrams at their
scales and the energy–mass diagram beside them need the width (A2/A3 versions of it are
not laid out yet). The figures are matplotlib drawings in sheet millimetres (:mod:`graphplan.render.
dynamics_figures`), placed at their size, so a segment measured on the sheet times the
printed scale is the value. The numbers come from :func:`graphplan.machine_unit.
machine_unit`, the same as in ``dynamics.*.md`` and the JSON report.
"""

from __future__ import annotations

import math

from .errors import LayoutError
from .kinematics_sheet import title_block
from .layout import CAPTION, GAP, titled_table
from .machine_unit import MachineUnit, machine_unit
from .render.dynamics_tables import T as TABLE_WORDS
from .render.dynamics_tables import position_rows
from .sheet import (
    MAIN,
    THIN,
    Arrow,
    Circle,
    Figure,
    Hatch,
    Item,
    Line,
    Page,
    Polyline,
    Rect,
    Sheet,
    Style,
    Text,
)
from .units import fmt

WORDS = {
    "ru": {"sheet": "Динамический анализ", "flywheel": "Маховик", "rim": "обод",
           "disc": "диск", "results": "Результаты", "table": "Значения в положениях",
           "mass": "масса", "speed": "окружная скорость"},
    "en": {"sheet": "Dynamics", "flywheel": "Flywheel", "rim": "rim", "disc": "disc",
           "results": "Results", "table": "Values at the positions", "mass": "mass",
           "speed": "rim speed"},
}
RESULT_H = 3.5  #: lettering of the results, mm
RIGHT_MIN = 135.0  #: narrowest right column (ω(φ), the flywheel, the results), mm
LINE = 6.0  #: line pitch of the results, mm


def results_lines(u: MachineUnit, lang: str) -> list[str]:
    """The results of sheet 3, one line each, in the order of the calculation."""
    fw, mc = u.flywheel, u.motor
    ru = lang == "ru"
    if mc is None:  # driven by its loads (an engine): the constant moment is the consumer's
        return _engine_lines(u, lang)
    mo = mc.motor
    rot = ("J_рот нет в каталоге" if ru else "J_rot not in the catalogue") \
        if mo.inertia_kg_m2 is None else f"Iрот·u² = {fmt(fw.I_rotor, 4)} кг·м²"
    lines = [
        f"ω1 = {fmt(fw.omega, 4)} {'рад/с' if ru else 'rad/s'},  δ = {fw.delta:g}",
        f"Mд = {fmt(fw.M_d, 5)} {'Н·м' if ru else 'N·m'} "
        f"({'графически' if ru else 'graphical'} {fmt(fw.work.M_d_graph, 5)}, "
        f"{(fw.work.M_d_graph / fw.M_d - 1) * 100:+.2f} %)",
        f"Pс = Mд·ω1/η = {fmt(u.power_W / 1000, 4)} {'кВт' if ru else 'kW'}",
        f"{'Двигатель' if ru else 'Motor'} {mo.type}: {fmt(mo.power_kw)} "
        f"{'кВт' if ru else 'kW'}, {fmt(mo.rated_rpm)} {'об/мин' if ru else 'rpm'}"
        + (f", Mп/Mн = {fmt(mo.start_torque_ratio)}" if mo.start_torque_ratio else "")
        + (f", Mmax/Mн = {fmt(mo.max_torque_ratio)}" if mo.max_torque_ratio else ""),
        f"u = nдв/n1 = {fmt(mo.rated_rpm)}/{fmt(mc.crank_rpm, 4)} = {mc.u:.2f};  {rot}",
        f"ΔTmax = {fmt(fw.dT_max, 5)} {'Дж' if ru else 'J'}",
        f"JI = (k−l)·KT/(ω²·δ) = {fmt(fw.J_I, 5)} кг·м²",
        f"Iм = JI − Iкр − Iрот = {fmt(fw.I_m, 5)} кг·м² "
        f"({'Мерцалов' if ru else 'Merkalov'} {fmt(fw.I_m_approx, 5)}, "
        f"{fw.difference_pct:+.2f} %)",
        f"δ {'при моделировании' if ru else 'simulated'} = {u.simulation.delta_actual:.4f} "
        f"({u.delta_error_pct:+.2f} %)",
    ]
    return lines


def _engine_lines(u: MachineUnit, lang: str) -> list[str]:
    """Sheet 3's results of a machine its loads drive (an engine): Mс constant, no motor."""
    fw, ru = u.flywheel, lang == "ru"
    cyc = f"{math.degrees(u.model.period):.0f}°"
    return [
        f"ω1 = {fmt(fw.omega, 4)} {'рад/с' if ru else 'rad/s'},  δ = {fw.delta:g}",
        f"Mс = −Aд({cyc})/{'4π' if u.model.period > 7 else '2π'} = {fmt(fw.M_d, 5)} "
        f"{'Н·м' if ru else 'N·m'} ({'графически' if ru else 'graphical'} "
        f"{fmt(fw.work.M_d_graph, 5)}, {(fw.work.M_d_graph / fw.M_d - 1) * 100:+.2f} %)",
        f"P = |Mс|·ω1 = {fmt(u.power_W / 1000, 4)} {'кВт' if ru else 'kW'}",
        f"ΔTmax = {fmt(fw.dT_max, 5)} {'Дж' if ru else 'J'}",
        f"JI = (k−l)·KT/(ω²·δ) = {fmt(fw.J_I, 5)} кг·м²",
        f"Iм = JI − Iкр = {fmt(fw.I_m, 5)} кг·м² "
        f"({'Мерцалов' if ru else 'Merkalov'} {fmt(fw.I_m_approx, 5)}, "
        f"{fw.difference_pct:+.2f} %)",
        f"δ {'при моделировании' if ru else 'simulated'} = {u.simulation.delta_actual:.4f} "
        f"({u.delta_error_pct:+.2f} %)",
    ]


def _flywheel_items(u: MachineUnit, box: Rect, lang: str) -> list[Item]:
    """Sketch of the rim (or disc): front view and section, with ⌀D, b and h."""
    w = WORDS[lang]
    s = u.mounted
    items: list[Item] = []
    shaft = TABLE_WORDS[lang]["shaft_" + u.shaft]
    title = (f"{w['flywheel']} ({w[s.shape]}, {shaft}), {w['mass']} {fmt(s.mass, 4)} "
             f"{'кг' if lang == 'ru' else 'kg'}")
    items.append(Text((box.x0, box.y0 + 5.0), title, 3.5, layer="text", id="s3-fw-title"))
    outer = s.D + (s.h if s.shape == "rim" else 0.0)
    room = min((box.width - 40.0) / 2.0, box.height - CAPTION - 22.0)
    scale_n = _scale_ratio(outer * 1000.0 / room)
    k = 1000.0 / scale_n  # mm of paper per m
    R_out = outer / 2 * k
    cy = box.y0 + CAPTION + 6.0 + R_out
    cx = box.x0 + 6.0 + R_out
    items.append(Circle((cx, cy), R_out, MAIN, layer="diagrams", id="s3-fw-outer"))
    hub = 0.18 * outer / 2 * k
    if s.shape == "rim":
        R_in = (s.D - s.h) / 2 * k
        items.append(Circle((cx, cy), R_in, MAIN, layer="diagrams", id="s3-fw-inner"))
    items.append(Circle((cx, cy), hub, MAIN, layer="diagrams", id="s3-fw-hub"))
    items.append(Circle((cx, cy), hub * 0.5, MAIN, layer="diagrams", id="s3-fw-shaft"))
    items.append(Line((cx - R_out - 3, cy), (cx + R_out + 3, cy), Style(0.25, (15, 3, 1, 3)),
                      layer="diagrams", id="s3-fw-axis-h"))
    items.append(Line((cx, cy - R_out - 3), (cx, cy + R_out + 3), Style(0.25, (15, 3, 1, 3)),
                      layer="diagrams", id="s3-fw-axis-v"))
    # section A–A beside the front view: rim (b × h) above and below, the hub between
    sx = cx + R_out + 18.0
    b = s.b * k
    hb = max(b * 0.6, 4.0)
    sec: list[tuple[float, float, float, float]] = []
    if s.shape == "rim":
        R_in = (s.D - s.h) / 2 * k
        sec += [(sx, cy - R_out, sx + b, cy - R_in), (sx, cy + R_in, sx + b, cy + R_out)]
        web = max(0.15 * b, 1.0)
        sec += [(sx + b / 2 - web / 2, cy - R_in, sx + b / 2 + web / 2, cy - hub),
                (sx + b / 2 - web / 2, cy + hub, sx + b / 2 + web / 2, cy + R_in)]
        sec += [(sx + b / 2 - hb / 2, cy - hub, sx + b / 2 + hb / 2, cy - hub * 0.5),
                (sx + b / 2 - hb / 2, cy + hub * 0.5, sx + b / 2 + hb / 2, cy + hub)]
    else:
        sec += [(sx, cy - R_out, sx + b, cy - hub * 0.5), (sx, cy + hub * 0.5, sx + b, cy + R_out)]
    for i, (x0, y0, x1, y1) in enumerate(sec):
        poly = ((x0, y0), (x1, y0), (x1, y1), (x0, y1))
        items.append(Polyline(poly, MAIN, True, layer="diagrams", id=f"s3-fw-sec{i}"))
        if (x1 - x0) > 0.5 and (y1 - y0) > 0.5:
            items.append(Hatch(poly, 1.5, 45.0, layer="diagrams", id=f"s3-fw-hatch{i}"))
    items.append(Line((sx + b / 2, cy - R_out - 3), (sx + b / 2, cy + R_out + 3),
                      Style(0.25, (15, 3, 1, 3)), layer="diagrams", id="s3-fw-sec-axis"))
    # dimensions: ⌀D (mean diameter of the rim, or the disc's), b, h
    dx = sx + b + 8.0
    d_half = s.D / 2 * k if s.shape == "rim" else R_out
    items += _dimension((dx, cy - d_half), (dx, cy + d_half), f"⌀{fmt(s.D * 1000, 4)}",
                        "s3-fw-dimD", vertical=True)
    items += _dimension((sx, cy + R_out + 8.0), (sx + b, cy + R_out + 8.0),
                        fmt(s.b * 1000, 4), "s3-fw-dimb")
    if s.shape == "rim":
        items += _dimension((sx - 6.0, cy - R_out), (sx - 6.0, cy - (s.D - s.h) / 2 * k),
                            fmt(s.h * 1000, 4), "s3-fw-dimh", vertical=True)
    note = (f"М 1:{scale_n:g};  {w['speed']} {fmt(s.speed, 3)} м/с"
            + ("" if s.speed_ok else " > 40 м/с!"))
    items.append(Text((box.x0, cy + R_out + 18.0), note, 2.5, layer="text", id="s3-fw-note"))
    return items


def _scale_ratio(need: float) -> float:
    """The smallest GOST 2.302 reduction 1:n with n ≥ need."""
    for n in (1, 2, 2.5, 4, 5, 10, 15, 20, 25, 40, 50, 75, 100):
        if n >= need:
            return float(n)
    return float(math.ceil(need / 100.0) * 100)


def _dimension(p0, p1, text: str, ident: str, vertical: bool = False) -> list[Item]:
    """A dimension line with arrows at both ends and its number above (or left of) it."""
    (x0, y0), (x1, y1) = p0, p1
    mx, my = (x0 + x1) / 2, (y0 + y1) / 2
    items: list[Item] = [
        Arrow((mx, my), (x0, y0), THIN, 2.5, 0.8, layer="dimensions", id=f"{ident}-a"),
        Arrow((mx, my), (x1, y1), THIN, 2.5, 0.8, layer="dimensions", id=f"{ident}-b"),
    ]
    if vertical:
        items.append(Text((mx - 1.0, my), text, 2.5, "middle", 90.0, layer="dimensions",
                          id=f"{ident}-t"))
    else:
        items.append(Text((mx, my - 1.0), text, 2.5, "middle", layer="dimensions",
                          id=f"{ident}-t"))
    return items


def dynamics_sheet(analysis, *, lang: str = "ru", page: Page | None = None,
                   unit: MachineUnit | None = None) -> Sheet:
    """Sheet 3 of the project for ``analysis`` (see the module docstring).

    Raises
    ------
    LayoutError
        When the diagrams at their scales do not fit the page.
    """
    from .render.dynamics_figures import energy_mass_svg, omega_svg, work_svg

    mech = analysis.mech
    page = page or Page("A1")
    u = unit or machine_unit(analysis)
    w = WORDS[lang]
    f = page.frame
    x0, y0 = f.x0 + 4.0, f.y0 + 22.0
    tb_top = page.title_block_rect.y0
    items: list[Item] = []
    svg1, w1, h1 = work_svg(u, lang)
    svg2, w2, h2 = energy_mass_svg(u, lang)
    if y0 + max(h1, h2) > f.y1 - 4.0 or x0 + w1 + GAP + w2 > f.x1 - RIGHT_MIN:
        raise LayoutError(f"sheet 3: the diagrams need {w1 + w2:.0f}×{max(h1, h2):.0f} mm at "
                          f"their scales; the {page.format} sheet has no room (choose a "
                          "larger format or dynamics.intervals)")
    items.append(Figure((x0, y0), w1, h1, svg1, layer="diagrams", id="s3-work"))
    x2 = x0 + w1 + GAP
    items.append(Figure((x2, y0), w2, h2, svg2, layer="diagrams", id="s3-energy-mass"))
    x3 = x2 + w2 + GAP
    right = Rect(x3, y0, f.x1 - 4.0, tb_top - GAP)
    om_h = 95.0
    items.append(Figure((right.x0, right.y0), right.width, om_h,
                        omega_svg(u, right.width, om_h, lang), layer="diagrams",
                        id="s3-omega"))
    fw_box = Rect(right.x0, right.y0 + om_h + GAP, right.x1, right.y0 + om_h + GAP + 130.0)
    items += _flywheel_items(u, fw_box, lang)
    ry = fw_box.y1 + GAP
    items.append(Text((right.x0, ry + 5.0), w["results"], 5.0, layer="text",
                      id="s3-results-title"))
    for i, line in enumerate(results_lines(u, lang)):
        items.append(Text((right.x0, ry + CAPTION + 5.0 + i * LINE), line, RESULT_H,
                          layer="text", id=f"s3-result-{i}"))
    # the table of values under the diagrams, left of the title block
    ty = y0 + max(h1, h2) + GAP
    rows = position_rows(u)
    if ty + CAPTION + 7.0 * (len(rows) + 1) <= f.y1 - 4.0:
        items += titled_table(
            x0, ty, page.title_block_rect.x0 - GAP - x0, w["table"],
            list(TABLE_WORDS[lang]["cols"]), rows, ident="s3-table", title_id="s3-table-title",
            notes=lambda n, m: [f" ({n}/{m}, dynamics.{lang}.md)"])
    return Sheet(page, tuple(items), title_block(mech, lang, 3, w["sheet"]))


__all__ = ["dynamics_sheet", "results_lines"]
