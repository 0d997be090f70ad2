"""The explanatory note's content: the project's calculation in the textbook's order.

Sections: introduction (the variant), 1 structural analysis, 2 kinematic analysis (plan of
positions, scales, the velocity and acceleration plans of every position as hand
calculations and tables, the kinematic diagrams), 3 force analysis (loads, the neglect rule,
each position's force plans, reactions, h21, Mур and Zhukovsky's check), 4 dynamics (reduced
moments, work, flywheel by Wittenbauer and Merkalov, motor and gear ratio, the check by
simulation), conclusions and references.

The lines of the calculation are the answer key's (:func:`graphplan.checking.generate.generate`:
the lines ``graphplan check`` reads), the tables and the dynamics are the reports'
(``plans.*.md``, ``forces.*.md``, ``dynamics.*.md``), the figures are cut from the sheets: one
solved variant, the same figures everywhere.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

from ..dynamics import DynamicsSettings
from ..errors import InputError
from ..kinematics import position_angles_deg
from ..numbers import general, note_comma
from .blocks import Arm, Block, Figure, Formula, Heading, Note, Paragraph, Table
from .figures import sheet_part_svg, svg_png
from .markdown import markdown_blocks

PAGE_TEXT_WIDTH_MM = 170.0  #: the widest a figure may be on an A4 page inside the frame

WORDS: dict[str, dict[str, Any]] = {  # a heading or line, or a list of lines
    "ru": {
        "intro": "Введение", "structure": "Структурный анализ механизма",
        "kinematics": "Кинематический анализ механизма",
        "positions": "План положений механизма", "plans": "Планы скоростей и ускорений",
        "diagrams": "Кинематические диаграммы выходного звена",
        "forces": "Силовой анализ механизма", "loads": "Силы тяжести",
        "force_positions": "Силовой расчёт по положениям",
        "dynamics": "Динамический анализ машинного агрегата",
        "conclusions": "Заключение", "references": "Список использованных источников",
        "position": "Положение {label}, φ = {phi:.2f}°",
        "fig_positions": "План положений механизма (Kl = {kl} м/мм)",
        "fig_v": "План скоростей, положение {label}",
        "fig_a": "План ускорений, положение {label}",
        "fig_diagrams": "Кинематические диаграммы выходного звена",
        "fig_s2": "Схема нагружения, планы сил и рычаг Жуковского, положение {label}",
        "fig_moment": "Уравновешивающий момент Mур(φ) за оборот кривошипа",
        "fig_work": "Диаграммы моментов и работ", "fig_em": "Диаграмма энергия–масса",
        "fig_fw": "Маховик",
        "arm": "{name} — плечо силы {force} относительно точки {about}, мм",
        "intro_text": "Объект проектирования — {what}. Исходные данные варианта заданы в файле "
                      "{variant}. Расчёт выполнен графоаналитическим методом планов: планы "
                      "положений, скоростей, ускорений и сил построены в масштабах Kl, Kv, Ka, "
                      "Kp; отрезки измерены на планах, величины вычислены по масштабам.",
        "concl": [
            "Выполнен структурный анализ механизма: W = {w}, формула строения {formula}.",
            "Построены планы положений, скоростей и ускорений; ход выходного звена {stroke}, "
            "коэффициент изменения средней скорости K = {k}.",
            "Выполнен силовой расчёт методом планов сил; наибольший уравновешивающий момент "
            "|Mур| = {mbal} Н·м (положение {mbal_at}).",
        ],
        "concl_dyn": "Рассчитан маховик: момент инерции Jм = {jm} кг·м², {shape} массой "
                     "{mass} кг; выбран двигатель: {motor}.",
        "concl_no_fw": "Маховик не нужен: у кривошипа уже есть {have} кг·м², не меньше "
                       "требуемого JI = {ji} кг·м²; при моделировании без маховика "
                       "δ = {dsim} ≤ {delta}; выбран двигатель: {motor}.",
        "refs": [
            "Артоболевский И. И. Теория механизмов и машин. — М.: Наука, 1988. — 640 с.",
            "Попов С. А., Тимофеев Г. А. Курсовое проектирование по теории механизмов и "
            "механике машин. — М.: Высшая школа, 2002. — 411 с.",
            "Фролов К. В. и др. Теория механизмов и механика машин. — М.: Изд-во МГТУ им. "
            "Н. Э. Баумана, 2009. — 688 с.",
            "ГОСТ 2.105-2019. ЕСКД. Общие требования к текстовым документам.",
            "ГОСТ 2.104-2006. ЕСКД. Основные надписи.",
        ],
        "stroke_mm": "H = {h} мм", "swing": "ψ = {s}°",
    },
    "en": {
        "intro": "Introduction", "structure": "Structural analysis of the mechanism",
        "kinematics": "Kinematic analysis of the mechanism",
        "positions": "Plan of positions", "plans": "Velocity and acceleration plans",
        "diagrams": "Kinematic diagrams of the output link",
        "forces": "Force analysis of the mechanism", "loads": "Weights",
        "force_positions": "Force analysis of the positions",
        "dynamics": "Dynamics of the machine unit",
        "conclusions": "Conclusions", "references": "References",
        "position": "Position {label}, φ = {phi:.2f}°",
        "fig_positions": "Plan of positions (Kl = {kl} m/mm)",
        "fig_v": "Velocity plan, position {label}",
        "fig_a": "Acceleration plan, position {label}",
        "fig_diagrams": "Kinematic diagrams of the output link",
        "fig_s2": "Loads, force plans and Zhukovsky's lever, position {label}",
        "fig_moment": "Balancing moment Mур(φ) over a turn of the crank",
        "fig_work": "Diagrams of moments and work", "fig_em": "Energy–mass diagram",
        "fig_fw": "Flywheel",
        "arm": "{name} is the arm of {force} about point {about}, mm",
        "intro_text": "The object of the project is {what}. The variant's data are in the file "
                      "{variant}. The calculation follows the graphical method of plans: the "
                      "plans of positions, velocities, accelerations and forces are drawn at "
                      "the scales Kl, Kv, Ka, Kp; segments are measured on the plans and the "
                      "values computed from the scales.",
        "concl": [
            "The structural analysis gives W = {w}, formula of structure {formula}.",
            "The plans of positions, velocities and accelerations are drawn; the output's "
            "stroke is {stroke}, the time ratio K = {k}.",
            "The force analysis by force plans gives the largest balancing moment "
            "|Mур| = {mbal} N·m (position {mbal_at}).",
        ],
        "concl_dyn": "The flywheel: moment of inertia Jм = {jm} kg·m², a {shape} of {mass} kg; "
                     "the motor chosen: {motor}.",
        "concl_no_fw": "No flywheel is needed: the crank already has {have} kg·m², not less "
                       "than the JI = {ji} kg·m² required; simulated "
                       "without one, δ = {dsim} ≤ {delta}; the motor chosen: {motor}.",
        "refs": [
            "Artobolevsky I. I. Theory of Mechanisms and Machines. Moscow: Nauka, 1988.",
            "Popov S. A., Timofeev G. A. Course design in the theory of mechanisms and "
            "machines. Moscow: Vysshaya shkola, 2002.",
            "Frolov K. V. et al. Theory of Mechanisms and Machine Dynamics. Moscow: Bauman "
            "MSTU, 2009.",
            "GOST 2.105-2019. ESKD. General requirements for text documents.",
            "GOST 2.104-2006. ESKD. Title blocks.",
        ],
        "stroke_mm": "H = {h} mm", "swing": "ψ = {s}°",
    },
}

def _g(x: float, digits: int, lang: str) -> str:
    """A number of the note's own sentences: Python's ``g``, the note's decimal comma."""
    return note_comma(general(x, digits), lang)


# the lines of the answer key that belong to the force analysis (the rest is kinematics)
_FORCE_TAGS = {"load", "reaction", "tangential", "M_bal"}


def _figure(sheet, caption: str, *prefixes: str, width_mm: float | None = None
            ) -> Figure | None:
    part = sheet_part_svg(sheet, *prefixes)
    if part is None:
        return None
    svg, w = part
    return Figure(caption, svg_png(svg), min(width_mm or w, PAGE_TEXT_WIDTH_MM))


def _is_force_line(line) -> bool:
    if _FORCE_TAGS.intersection(line.tags):
        return True
    # the force plan's scale and the arm h21 carry no load tag
    return line.lhs in ("Кр", "Kp", "h21") or line.lhs.startswith(("Pи", "Mи", "Q", "R"))


def _position_sections(md: str, lang: str) -> dict[str, list[Block]]:
    """A report's blocks split by position label (None: before the first position)."""
    out: dict[str, list[Block]] = {}
    label = ""
    for b in markdown_blocks(md, lang):
        if isinstance(b, Heading) and b.position is not None:
            label = b.position
            continue
        if isinstance(b, Heading) and b.level <= 2:
            label = ""
        out.setdefault(label, []).append(b)
    return out


def build_note(variant: str | Path, *, lang: str = "ru", out_dir: str | Path | None = None,
               figures: bool = True) -> Note:
    """The explanatory note of ``variant`` (see the module docstring).

    Parameters
    ----------
    variant : path
        The variant file (TOML).
    lang : {"ru", "en"}
        The note's language; a Russian note writes decimal commas.
    out_dir : path, optional
        Where the note will be written: the variant is named relative to it, so that
        ``graphplan check`` finds it from the note.
    figures : bool
        Cut the figures out of the sheets (needs the export extra for the pictures).
    """
    from ..checking.generate import generate
    from ..drawing import kinematics_sheet, kinetostatics_sheet
    from ..model import load
    from ..project import analyze
    from ..reports import cycle_text, forces_markdown, plans_markdown, structure_text

    if lang not in WORDS:
        raise InputError(f"note: lang: expected 'ru' or 'en' (got {lang!r})")
    w = WORDS[lang]
    variant = Path(variant)
    mech = load(variant)
    analysis = analyze(mech)
    ref = os.path.relpath(variant.resolve(), Path(out_dir or ".").resolve())
    key = generate(variant, variant_ref=Path(ref).as_posix())
    labels = analysis.kin.labels
    angles = position_angles_deg(analysis.mech, analysis.kin)
    prec = mech.drawing.reading_mm
    blocks: list[Block] = []

    # introduction
    tb = mech.title_block
    title, description = tb.title, mech.description
    what = ((title or description) if lang == "ru" else (description or title)) or mech.name
    blocks += [Heading(w["intro"], 1, numbered=False),
               Paragraph(w["intro_text"].format(what=what, variant=variant.name))]

    # 1 structure
    blocks.append(Heading(w["structure"], 1))
    for line in structure_text(analysis, lang).splitlines()[1:]:
        if line.strip():
            blocks.append(Paragraph(note_comma(line.strip(), lang)))

    # 2 kinematics
    sheet1 = kinematics_sheet(analysis, lang=lang) if figures else None
    blocks += [Heading(w["kinematics"], 1), Heading(w["positions"], 2)]
    for line in cycle_text(analysis, lang).splitlines()[1:]:
        if line.strip():
            blocks.append(Paragraph(note_comma(line.strip(), lang)))
    general = list(key.general)
    scale_lines = [ln for ln in general if "scale" in ln.tags or ln.lhs in ("ω1", "vA", "aA")]
    load_lines = [ln for ln in general if ln not in scale_lines]
    for ln in scale_lines[:1]:
        blocks.append(Formula(ln.text()))
    if sheet1 is not None:
        kl = _g(float(key.general[0].result), 4, lang)
        fig = _figure(sheet1, w["fig_positions"].format(kl=kl), "pp-")
        if fig:
            blocks.append(fig)
    blocks.append(Heading(w["plans"], 2))
    for ln in scale_lines[1:]:
        blocks.append(Formula(ln.text()))
    plan_md = _position_sections(plans_markdown(analysis, lang, prec), lang)
    force_md = _position_sections(forces_markdown(analysis, lang, prec), lang)
    by_label = {p.label: p for p in key.positions}
    for k, label in enumerate(labels):
        phi = float(angles[k])
        blocks.append(Heading(note_comma(w["position"].format(label=label, phi=phi), lang),
                              3, position=label))
        gp = by_label.get(label)
        if gp is not None:
            blocks += [Formula(ln.text()) for ln in gp.lines if not _is_force_line(ln)]
        blocks += [_without_scale(b) for b in plan_md.get(label, []) if isinstance(b, Table)]
        if sheet1 is not None and k == _main_position(analysis):
            for word, prefix in (("fig_v", "vp"), ("fig_a", "ap")):
                fig = _figure(sheet1, w[word].format(label=label), f"{prefix}{k}-")
                if fig:
                    blocks.append(fig)
    if sheet1 is not None:
        fig = _figure(sheet1, w["fig_diagrams"], "kin-diagrams")
        if fig:
            blocks.append(fig)

    # 3 forces
    sheet2 = kinetostatics_sheet(analysis, lang=lang) if figures else None
    blocks += [Heading(w["forces"], 1), Heading(w["loads"], 2)]
    blocks += [Formula(ln.text()) for ln in load_lines]
    blocks.append(Heading(w["force_positions"], 2))
    for k, label in enumerate(labels):
        gp = by_label.get(label)
        lines = [ln for ln in gp.lines if _is_force_line(ln)] if gp is not None else []
        if gp is None or not lines:
            continue
        phi = float(angles[k])
        blocks.append(Heading(note_comma(w["position"].format(label=label, phi=phi), lang),
                              3, position=label))
        blocks += [Paragraph(b.text) for b in force_md.get(label, [])
                   if isinstance(b, Paragraph)]
        blocks += [Arm(n, f, a) for n, f, a in gp.arms]
        blocks += [Formula(ln.text()) for ln in lines]
        blocks += [b for b in force_md.get(label, []) if isinstance(b, Table)]
        if sheet2 is not None:
            fig = _figure(sheet2, w["fig_s2"].format(label=label), f"s2p{k}-")
            if fig:
                blocks.append(fig)
    if sheet2 is not None:
        fig = _figure(sheet2, w["fig_moment"], "s2-moment")
        if fig:
            blocks.append(fig)

    # 4 dynamics
    unit = None
    if DynamicsSettings.of(mech).delta is not None:
        from ..drawing import dynamics_sheet
        from ..dynamics import machine_unit
        from ..reports import dynamics_markdown

        unit = machine_unit(analysis)
        blocks.append(Heading(w["dynamics"], 1))
        blocks += markdown_blocks(dynamics_markdown(unit, lang), lang)
        if figures:
            sheet3 = dynamics_sheet(analysis, lang=lang, unit=unit)
            figs = (("fig_work", "s3-work"), ("fig_em", "s3-em"))
            for word, prefix in figs + ((("fig_fw", "s3-fw"),) if unit.flywheel_needed
                                        else ()):
                fig = _figure(sheet3, w[word], prefix)
                if fig:
                    blocks.append(fig)

    # conclusions and references
    blocks.append(Heading(w["conclusions"], 1, numbered=False))
    blocks += [Paragraph(t) for t in _conclusions(analysis, key, unit, lang)]
    blocks.append(Heading(w["references"], 1, numbered=False))
    blocks += [Paragraph(f"{i}. {r}") for i, r in enumerate(w["refs"], 1)]

    return Note(
        title=tb.title or what,
        designation=tb.designation,
        organisation=" ".join(s for s in (tb.school, tb.group) if s),
        author=tb.author, checker=tb.checker,
        variant=Path(ref).as_posix(), lang=lang, blocks=tuple(blocks))


def _without_scale(t: Table) -> Table:
    """A plan's table without its scale column (the scale is written out above it)."""
    drop = [j for j, h in enumerate(t.header) if h in ("Масштаб", "Scale")]
    if not drop:
        return t
    keep = [j for j in range(len(t.header)) if j not in drop]
    return Table(t.caption, tuple(t.header[j] for j in keep),
                 tuple(tuple(r[j] for j in keep if j < len(r)) for r in t.rows))


def _main_position(analysis) -> int:
    """The position whose plans the note draws: the first extra (working) position, else 0."""
    labels = analysis.kin.labels
    for k, label in enumerate(labels):
        if label.startswith("("):
            return k
    return 0


def _conclusions(analysis, key, unit, lang: str) -> list[str]:
    w = WORDS[lang]
    st, cy = analysis.structure, analysis.cycle
    if cy.stroke:
        stroke = w["stroke_mm"].format(h=_g(cy.stroke * 1000.0, 5, lang))
    else:
        stroke = w["swing"].format(s=_g(math.degrees(cy.swing), 4, lang))
    mbal, at = 0.0, "—"
    for p in key.positions:
        for ln in p.lines:
            if "M_bal" in ln.tags and abs(ln.result) > abs(mbal):
                mbal, at = ln.result, p.label
    out = [t.format(w=st.mobility, formula=st.formula, stroke=stroke,
                    k=_g(cy.time_ratio, 4, lang), mbal=_g(abs(mbal), 5, lang), mbal_at=at)
           for t in w["concl"]]
    if unit is not None:
        m = unit.mounted
        mo = unit.motor.motor if unit.motor is not None else None
        motor = (f"{mo.type}, {_g(mo.power_kw, 4, lang)} {'кВт' if lang == 'ru' else 'kW'}, "
                 f"{_g(mo.rated_rpm, 5, lang)} {'об/мин' if lang == 'ru' else 'rpm'}"
                 if mo is not None else "—")
        fw = unit.flywheel
        if fw.needed:
            out.append(w["concl_dyn"].format(jm=_g(fw.I_m, 5, lang), shape=m.shape,
                                             mass=_g(m.mass, 4, lang), motor=motor))
        else:
            out.append(w["concl_no_fw"].format(
                have=(f"Jкр + Jрот·u² = {_g(fw.I_const + fw.I_rotor, 5, lang)}"
                      if fw.I_rotor > 0 else f"Jкр = {_g(fw.I_const, 5, lang)}"),
                ji=_g(fw.J_I, 5, lang),
                dsim=_g(unit.simulation.delta_actual, 3, lang), delta=_g(fw.delta, 3, lang),
                motor=motor))
    return out
