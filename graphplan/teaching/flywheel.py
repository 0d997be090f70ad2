"""The lesson of the flywheel: work diagrams by graphical integration, then the
energy–mass (Wittenbauer) diagram and its two tangents (:mod:`graphplan.dynamics.flywheel`).

The lesson draws the machine unit of sheet 3 (:func:`graphplan.dynamics.machine.machine_unit`,
the project's ``analysis.unit``): the same L, Kφ, KM, H, KA, KT, KJ, the same motor (its
rotor's ``Jрот·u²`` counted), the same flywheel and its rim or disc on the shaft sheet 3
mounts it on, in the sheet's notation (KJ, JI, Jм, Jкр). Nothing is solved again.
Sign conventions are those of :mod:`graphplan.dynamics.reduction`: moments positive in
the sense of rotation, so the resisting moment Mс is negative where it resists and ``Aс``
falls; the abscissa is the crank travel from the first position, ``x = τ/Kφ`` mm.

Panel 1, the work diagrams (mm, y up): Mс(φ) on its axis at KM; the mean ordinate of
each interval, projected on the ordinate axis and joined to the pole P at H mm left of
the origin; the chords of Aс(φ) parallel to those rays (``Δy_A = y_M·Δx/H``) at
``KA = Kφ·KM·H``, on a second axis below; the straight line Aд (``Aд(2π) = −Aс(2π)``)
and ``ΔT = Aд + Aс``. The exact curves are drawn thin and dashed beside the graphical
ones. Panel 2, the energy–mass diagram: ``(JII/KJ, ΔT/KT)`` over the cycle (exact ΔT,
as the flywheel is computed), the tangents at ψmax and ψmin cutting the ΔT axis at k
and l, and the segment kl: ``JI = kl·KT/(ω²·δ)``, ``Jм = JI − Jкр − Jрот·u²``.
The quantities are scalars: the captions give their values, not a table of vectors.
"""

from __future__ import annotations

import math

import numpy as np

from ..dynamics import machine_unit
from ..numbers import signed
from .captions import WORDS, mm, num, plain
from .model import Lesson, LessonStep, Mark, Panel, Result

GAP = 14.0  #: between the Mс diagram and the work diagram below it, mm
MAX_POINTS = 361  #: points of a drawn curve (the grid is thinned to this)


def _xy(x, y) -> tuple[float, float]:
    return (float(x), float(y))


def _curve(name, xs, ys, role, dashed=False) -> Mark:
    xs, ys = np.asarray(xs, float), np.asarray(ys, float)
    step = max(1, math.ceil((len(xs) - 1) / (MAX_POINTS - 1)))
    idx = list(range(0, len(xs), step))
    if idx[-1] != len(xs) - 1:
        idx.append(len(xs) - 1)
    return Mark("curve", name, tuple(_xy(xs[i], ys[i]) for i in idx), role, dashed=dashed)


def _axes(name, x0, x1, y0, y1, oy, xlabel, ylabel) -> list[Mark]:
    return [Mark("vector", f"{name}-x", (_xy(x0, oy), _xy(x1, oy)), "context"),
            Mark("vector", f"{name}-y", (_xy(0, y0), _xy(0, y1)), "context"),
            Mark("text", f"{name}-xl", (_xy(x1 - 4, oy + 3),), "context", text=xlabel),
            Mark("text", f"{name}-yl", (_xy(2, y1 - 3),), "context", text=ylabel)]


def _two(en: str, ru: str) -> dict[str, str]:
    return {"en": en, "ru": ru}


def flywheel_lesson(analysis) -> Lesson:
    """The flywheel of a variant as a lesson (module docstring).

    Raises
    ------
    InputError, DynamicsError, LayoutError
        As :func:`graphplan.dynamics.flywheel.flywheel` (no δ in the variant, no work of the
        resistance, a pole distance under 1 mm).
    """
    mech = analysis.mech
    unit_ = analysis.unit or machine_unit(analysis)  # the last: the error without δ
    model, fw = unit_.model, unit_.flywheel
    wd = fw.work
    L, KM, KA, H, Kphi = wd.length_mm, wd.KM, wd.KA, wd.H, wd.Kphi
    n = wd.intervals
    dx = L / n
    w, delta = fw.omega, fw.delta
    x_grid = wd.tau / Kphi
    x_nodes = wd.node_tau / Kphi
    yM_exact = model.moment.M / KM
    steps: list[LessonStep] = []

    def add(panel, kind, eq, text, terms=(), results=(), marks=(), notes=()):
        steps.append(LessonStep(len(steps) + 1, panel, kind, eq, text, tuple(terms),
                                tuple(results), tuple(marks), tuple(notes)))

    # --- panel 0: Mс(φ), mean ordinates, rays, chords, Aд, ΔT
    m_lo, m_hi = min(0.0, float(yM_exact.min())), max(0.0, float(yM_exact.max()))
    a_vals = np.concatenate([wd.yA_mm, wd.A_d / KA, wd.dT / KA, wd.A_c / KA, [0.0]])
    oy = m_lo - GAP - float(a_vals.max())  # the ordinate 0 of the work diagram
    i_ext = int(np.argmax(np.abs(model.moment.M)))
    M_ext = float(model.moment.M[i_ext])
    marks = _axes("M", -H - 6.0, L + 10.0, m_lo - 4.0, m_hi + 10.0, 0.0, "φ", "Mс")
    marks.append(_curve("Mс", x_grid, yM_exact, "curve"))
    add(0, "diagram", "Mс = ΣP/|ω1|",
        _two(f"The reduced moment of the resisting forces Mс(φ) (weights and the technological "
             f"resistance, no inertia: they enter through Jпр), drawn at KM = {plain(KM)} N·m/mm "
             f"over the abscissa L = {mm(L)} mm of one turn: Kφ = 2π/L = {plain(Kphi, 4)} rad/mm.",
             f"Приведённый момент сил сопротивления Mс(φ) (веса и технологическое "
             f"сопротивление, без сил инерции: они входят через Jпр) в масштабе KM = {plain(KM)} "
             f"Н·м/мм на отрезке L = {mm(L)} мм за оборот: Kφ = 2π/L = {plain(Kphi, 4)} рад/мм."),
        (),
        [Result("y_M", "Mс", abs(M_ext) / KM, abs(M_ext), "N·m", "KM", KM, laid=True)], marks)

    stair = []
    rays = []
    for i in range(n):
        stair += [_xy(x_nodes[i], wd.yM_mm[i]), _xy(x_nodes[i + 1], wd.yM_mm[i])]
        rays.append(Mark("line", f"ray{i + 1}", (_xy(-H, 0.0), _xy(0.0, wd.yM_mm[i])), "ray"))
    marks = [Mark("curve", "mean", tuple(stair), "relative"), *rays,
             Mark("point", "P", (_xy(-H, 0.0),), "point"),
             Mark("label", "P", (_xy(-H, 0.0),), "label", text="P")]
    add(0, "integrate", "KA = Kφ·KM·H",
        _two(f"Graphical integration: {n} intervals of Δx = {mm(dx)} mm; the mean ordinate y_M "
             f"of each (at its midpoint) is projected on the ordinate axis and joined to the "
             f"pole P, H = {mm(H)} mm to the left of the origin.",
             f"Графическое интегрирование: {n} интервалов по Δx = {mm(dx)} мм; средняя ордината "
             f"y_M каждого (в его середине) проецируется на ось ординат и соединяется с полюсом "
             f"P на расстоянии H = {mm(H)} мм левее начала координат."),
        (), (), marks)

    marks = _axes("A", -6.0, L + 10.0, oy + float(a_vals.min()) - 4.0,
                  oy + float(a_vals.max()) + 10.0, oy, "φ", "A")
    marks.append(_curve("Aс exact", x_grid, oy + wd.A_c / KA, "exact", dashed=True))
    marks.append(Mark("curve", "Aс", tuple(_xy(x, oy + y) for x, y in zip(x_nodes, wd.yA_mm,
                                                                          strict=True)),
                      "curve", text=""))
    marks.append(Mark("label", "Aс", (_xy(x_nodes[-1], oy + wd.yA_mm[-1]),), "label", text="Aс"))
    yA_end = float(wd.yA_mm[-1])
    add(0, "integrate", "Δy_A = y_M·Δx/H",
        _two(f"Aс(φ) by chords: on each interval a chord parallel to its ray, rising "
             f"Δy_A = y_M·Δx/H mm; KA = Kφ·KM·H = {plain(KA, 5)} J/mm. The exact integral is "
             f"dashed; the chords' largest error is {100 * wd.error:.2f} % of max|Aс|.",
             f"Aс(φ) по хордам: на каждом интервале хорда параллельна своему лучу и "
             f"поднимается на Δy_A = y_M·Δx/H мм; KA = Kφ·KM·H = {plain(KA, 5)} Дж/мм. Точный "
             f"интеграл — штрихами; наибольшая ошибка хорд {100 * wd.error:.2f} % от max|Aс|."),
        (),
        [Result("y_A(2π)", "|Aс(2π)|", abs(yA_end), abs(yA_end) * KA, "J", "KA", KA)], marks)

    Md = wd.M_d_graph
    marks = [Mark("line", "Aд", (_xy(0.0, oy), _xy(L, oy - yA_end)), "tangent", text="Aд"),
             Mark("line", "Mд", (_xy(0.0, Md / KM), _xy(L, Md / KM)), "tangent", text="Mд")]
    add(0, "result", "Mд = −Aс(2π)/2π",
        _two(f"Steady motion: the driving work over the cycle equals the resisting one. Aд is "
             f"the straight line to Aд(2π) = −Aс(2π); its moment Mд = −Aс(2π)/2π = "
             f"{num(Md, 5)} N·m (the exact integral gives {num(wd.M_d, 5)} N·m) is drawn on "
             f"the Mс diagram.",
             f"Установившееся движение: работа движущих сил за цикл равна работе сил "
             f"сопротивления. Aд — прямая до Aд(2π) = −Aс(2π); её момент Mд = −Aс(2π)/2π = "
             f"{num(Md, 5)} Н·м (точный интеграл даёт {num(wd.M_d, 5)} Н·м) проведён на "
             f"диаграмме Mс."),
        (),
        [Result("y_Mд", "Mд", Md / KM, Md, "N·m", "KM", KM, laid=True)], marks)

    span_mm = fw.dT_max / KA
    marks = [_curve("ΔT exact", x_grid, oy + wd.dT / KA, "exact", dashed=True),
             Mark("curve", "ΔT", tuple(_xy(x, oy + y / KA) for x, y in
                                       zip(x_nodes, wd.dT_graph, strict=True)), "curve"),
             Mark("label", "ΔT", (_xy(x_nodes[int(np.argmax(wd.dT_graph))],
                                      oy + float(wd.dT_graph.max()) / KA),), "label", text="ΔT")]
    add(0, "diagram", "ΔT = Aд + Aс",
        _two("The excess work ΔT(φ) = Aд + Aс: the sum of the ordinates of Aд and Aс at "
             "every node (exact: dashed). Its span max ΔT − min ΔT is the energy the flywheel "
             "must store and give back.",
             "Избыточная работа ΔT(φ) = Aд + Aс: сумма ординат Aд и Aс в каждом узле (точно — "
             "штрихами). Её размах max ΔT − min ΔT — энергия, которую маховик накапливает и "
             "отдаёт."),
        (),
        [Result("y_ΔT", "ΔTmax", span_mm, fw.dT_max, "J", "KA", KA)], marks)

    # --- panel 1: energy–mass diagram (KT and KJ of sheet 3)
    KJ, KT = fw.KI, fw.KT
    xs = model.inertia.I_var / KJ
    ys = wd.dT / KT
    x_hi = max(float(xs.max()), 20.0)
    y_lo, y_hi = min(0.0, float(ys.min()), fw.l_mm), max(float(ys.max()), fw.k_mm)
    marks = _axes("E", -6.0, x_hi + 12.0, y_lo - 8.0, y_hi + 12.0, 0.0, "JII", "ΔT")
    marks.append(_curve("ΔT(JII)", xs, ys, "curve"))
    add(1, "diagram", "ΔT(JII)",
        _two(f"The energy–mass diagram: for every crank angle the point (JII/KJ, ΔT/KT), "
             f"KJ = {plain(KJ)} kg·m²/mm, KT = {plain(KT, 5)} J/mm (KA/KT = "
             f"{plain(KA / KT, 5)}: ΔT is laid off anew at KT); JII is the variable part of "
             f"the reduced moment of inertia (the links of the groups), the crank's constant "
             f"part is Jкр = {num(fw.I_const, 6)} kg·m².",
             f"Диаграмма энергомасс: для каждого угла кривошипа точка (JII/KJ, ΔT/KT), "
             f"KJ = {plain(KJ)} кг·м²/мм, KT = {plain(KT, 5)} Дж/мм (KA/KT = "
             f"{plain(KA / KT, 5)}: ΔT откладывается заново в масштабе KT); JII — переменная "
             f"часть приведённого момента инерции (звенья групп), постоянная часть "
             f"кривошипа Jкр = {num(fw.I_const, 6)} кг·м²."),
        (), (), marks)

    for which, tau_t, tan_, psi, y0, letter, sign in (
            ("max", fw.tangent_tau[0], fw.tan_max, fw.psi_max, fw.k_mm, "k", "+"),
            ("min", fw.tangent_tau[1], fw.tan_min, fw.psi_min, fw.l_mm, "l", "−")):
        xt = float(np.interp(tau_t, model.tau, model.inertia.I_var)) / KJ
        x_end = max(x_hi, xt) + 8.0
        marks = [Mark("line", f"tangent-{which}", (_xy(-4.0, y0 - 4.0 * tan_),
                                                  _xy(x_end, y0 + x_end * tan_)), "tangent"),
                 Mark("point", letter, (_xy(0.0, y0),), "point"),
                 Mark("label", letter, (_xy(0.0, y0),), "label", text=letter),
                 Mark("point", f"touch-{which}", (_xy(xt, y0 + xt * tan_),), "point")]
        where = "above" if which == "max" else "below"
        where_ru = "сверху" if which == "max" else "снизу"
        sub = (f"{plain(KJ)}/(2·{plain(KT, 5)})·{num(w, 5)}²·(1 {sign} {plain(delta)}) "
               f"= {tan_:.5f}, ψ{which} = {psi:.3f}°")
        add(1, "tangent", f"tg ψ{which} = KJ/(2·KT)·ω²·(1 {sign} δ)",
            _two(f"tg ψ{which} = {sub}: the tangent at this angle to the JII axis, touching "
                 f"the curve from {where}, cuts the ΔT axis at {letter}.",
                 f"tg ψ{which} = {sub}: касательная под этим углом к оси JII, касающаяся "
                 f"кривой {where_ru}, пересекает ось ΔT в точке {letter}."),
            (), (), marks)

    marks = [Mark("vector", "kl", (_xy(0.0, fw.l_mm), _xy(0.0, fw.k_mm)), "absolute", text="kl")]
    factor = KT / (w * w * delta)
    rotor = fw.I_rotor
    minus = f" − {num(rotor, 6)}" if rotor > 0 else ""
    what = ("JI − Jкр − Jрот·u²" if rotor > 0 else "JI − Jкр")
    jm = f"Jм = {what} = {num(fw.J_I, 6)} − {num(fw.I_const, 6)}{minus} = "
    if fw.needed:
        notes = [_two(f"{jm}{num(fw.I_m, 6)} kg·m²; by Merkalov {num(fw.I_m_approx, 6)} "
                      f"kg·m² ({signed(fw.difference_pct)} %)",
                      f"{jm}{num(fw.I_m, 6)} кг·м²; по Мерцалову {num(fw.I_m_approx, 6)} "
                      f"кг·м² ({signed(fw.difference_pct)} %)")]
    else:  # the crank (and the rotor) already have JI: Jм = 0
        notes = [_two(f"{jm}{num(fw.I_m_signed, 6)} kg·m² ≤ 0: no flywheel is needed, Jм = 0",
                      f"{jm}{num(fw.I_m_signed, 6)} кг·м² ≤ 0: маховик не нужен, Jм = 0")]
    motor = unit_.motor
    rotor_en = rotor_ru = ""
    j_rot = None if motor is None else motor.motor.inertia_kg_m2
    if rotor > 0 and motor is not None and j_rot is not None:
        rotor_en = (f" The motor's rotor already gives Jрот·u² = {plain(j_rot)}"
                    f"·{plain(motor.u, 4)}² = {num(rotor, 6)} kg·m² (u = n_ном/n1).")
        rotor_ru = (f" Ротор двигателя уже даёт Jрот·u² = {plain(j_rot)}"
                    f"·{plain(motor.u, 4)}² = {num(rotor, 6)} кг·м² (u = n_ном/n1).")
    add(1, "result", "JI = kl·KT/(ω²·δ)",
        _two(f"The segment kl between the tangents on the ΔT axis gives the constant reduced "
             f"moment of inertia that keeps ω within δ = {plain(delta)}: JI = kl·KT/(ω²·δ) = "
             f"{mm(fw.segment_mm)}·{plain(KT, 5)}/({num(w, 5)}²·{plain(delta)}) = "
             f"{num(fw.J_I, 6)} kg·m².{rotor_en}",
             f"Отрезок kl между касательными на оси ΔT даёт постоянный приведённый момент "
             f"инерции, при котором неравномерность не больше δ = {plain(delta)}: "
             f"JI = kl·KT/(ω²·δ) = {mm(fw.segment_mm)}·{plain(KT, 5)}/({num(w, 5)}²·"
             f"{plain(delta)}) = {num(fw.J_I, 6)} кг·м².{rotor_ru}"),
        (),
        [Result("kl", "JI", fw.segment_mm, fw.segment_mm * factor, "kg·m²", "KT/(ω²·δ)",
                factor)], marks, notes)

    sz = unit_.mounted  # sheet 3's flywheel, on the shaft it is mounted on
    if not fw.needed:
        d_sim = unit_.simulation.delta_actual
        add(1, "size", "JI ≤ Jкр + Jрот·u²",
            _two(f"No flywheel is needed: the crank already has {num(fw.I_const + rotor, 6)} "
                 f"kg·m², not less than JI = {num(fw.J_I, 6)} kg·m². Simulated without a "
                 f"flywheel, ω varies by δ = {d_sim:.4f} ≤ {plain(delta)}.",
                 f"Маховик не нужен: у кривошипа уже есть {num(fw.I_const + rotor, 6)} кг·м², "
                 f"не меньше JI = {num(fw.J_I, 6)} кг·м². При моделировании без маховика "
                 f"неравномерность δ = {d_sim:.4f} ≤ {plain(delta)}."))
    else:
        ok = {"en": "within" if sz.speed_ok else "above", "ru": "не больше" if sz.speed_ok
              else "больше"}
        shape = {"en": "rim" if sz.shape == "rim" else "disc",
                 "ru": "обод" if sz.shape == "rim" else "диск"}
        on_motor = unit_.shaft == "motor"
        shaft = {"en": "motor" if on_motor else "crank", "ru": "двигателя" if on_motor
                 else "кривошипа"}
        reduce_en = reduce_ru = ""
        if on_motor:
            reduce_en = (f" it needs only I = Jм/u² = {num(fw.I_m, 6)}/{plain(sz.ratio, 4)}² = "
                         f"{num(sz.inertia, 5)} kg·m²;")
            reduce_ru = (f" ему нужно лишь I = Jм/u² = {num(fw.I_m, 6)}/{plain(sz.ratio, 4)}² = "
                         f"{num(sz.inertia, 5)} кг·м²;")
        add(1, "size", "I = m·D²/4" if sz.shape == "rim" else "I = m·D²/8",
            _two(f"A steel {shape['en']} on the {shaft['en']} shaft (u = {plain(sz.ratio, 4)}):"
                 f"{reduce_en} D = {num(sz.D)} m, b = {num(sz.b)} m, h = {num(sz.h)} m, mass "
                 f"m = {num(sz.mass)} kg; rim speed v = ω·D/2 = {num(sz.speed)} m/s, "
                 f"{ok['en']} the 40 m/s limit.",
                 f"Стальной {shape['ru']} на валу {shaft['ru']} (u = {plain(sz.ratio, 4)}):"
                 f"{reduce_ru} D = {num(sz.D)} м, b = {num(sz.b)} м, h = {num(sz.h)} м, масса "
                 f"m = {num(sz.mass)} кг; окружная скорость v = ω·D/2 = {num(sz.speed)} м/с, "
                 f"{ok['ru']} предела 40 м/с."))

    panels = (Panel("work", _two("Work diagrams: Mс(φ), Aс, Aд, ΔT", "Диаграммы работ: Mс(φ), "
                                 "Aс, Aд, ΔT"),
                    f"KM = {plain(KM)} N·m/mm; KA = {plain(KA, 5)} J/mm"),
              Panel("energy-mass", _two("Energy–mass diagram", "Диаграмма энергомасс"),
                    f"KJ = {plain(KJ)} kg·m²/mm; KT = {plain(KT, 5)} J/mm"))
    title = {lang: f"{WORDS[lang]['flywheel']} — {mech.name}" for lang in ("ru", "en")}
    scales = (f"Kφ = 2π/L = {plain(Kphi, 4)} rad/mm", f"KM = {plain(KM)} N·m/mm",
              f"H = {mm(H)} mm", f"KA = Kφ·KM·H = {plain(KA, 5)} J/mm",
              f"KT = {plain(KT, 5)} J/mm", f"KJ = {plain(KJ)} kg·m²/mm")
    return Lesson("flywheel", mech.name, mech.source, None, title, panels, tuple(steps), scales)


__all__ = ["flywheel_lesson"]
