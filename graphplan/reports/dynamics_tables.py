"""The dynamics as a hand calculation (``dynamics.ru.md``, ``dynamics.en.md``) and as CSV.

The report follows sheet 3 line by line: the data, Mс and Jпр at the positions, the
graphical integration (Kφ, KM, the pole H, KA; the mean ordinate of every interval and
the chords' nodes in mm), Mд, ΔT, the energy–mass diagram (KJ, KT, tan ψ, the
intercepts k and l, kl), J_I and the flywheel, the motor and the gear ratio, the rim, and
the check by simulation. Every formula is written with its numbers, as a student writes
it and a teacher checks it.
"""

from __future__ import annotations

import csv
import io
import math
from typing import Any

import numpy as np

from ..dynamics import MachineUnit
from ..kinematics import cycle_angle_deg
from ..numbers import fmt, signed

T: dict[str, dict[str, Any]] = {
    "ru": {"title": "Динамический анализ машинного агрегата", "data": "Исходные данные",
           "pos": "Значения в положениях", "int": "Графическое интегрирование Mс (метод хорд)",
           "fly": "Маховик по диаграмме энергомасс (Виттенбауэр)", "motor": "Двигатель",
           "rim": "Размеры маховика", "check": "Проверка моделированием",
           "no_fw": "маховик не нужен",
           "no_fw_why": "маховик не нужен: JI = {ji} кг·м² не больше, чем уже есть у "
                        "кривошипа с ротором двигателя, Jкр + Jрот·u² = {have} кг·м²; Jм = 0",
           "no_fw_sim": "без маховика",
           "cols": ("Пол.", "φ, °", "Mс, Н·м", "Jпр, кг·м²", "Aс, Дж", "Aд, Дж", "ΔT, Дж"),
           "icols": ("Интервал", "φ от, °", "φ до, °", "Mс ср, Н·м", "yM, мм", "yA в конце, мм"),
           "none": "нет в каталоге", "shaft_crank": "на валу кривошипа",
           "shaft_motor": "на валу двигателя", "flat": "ψ < 20°: по отрезкам на оси ΔT, метод D.3",
           "sign": "φ — поворот кривошипа от первого положения по направлению вращения; "
                   "моменты положительны по направлению вращения (Mс < 0 — сопротивление)"},
    "en": {"title": "Dynamics of the machine unit", "data": "Data",
           "pos": "Values at the positions", "int": "Graphical integration of Mс (chords)",
           "fly": "Flywheel by the energy–mass diagram (Wittenbauer)", "motor": "Motor",
           "rim": "Flywheel dimensions", "check": "Check by simulation",
           "no_fw": "no flywheel is needed",
           "no_fw_why": "no flywheel is needed: JI = {ji} kg·m² is not more than the crank "
                        "and the motor's rotor already have, Jкр + Jрот·u² = {have} kg·m²; "
                        "Jм = 0",
           "no_fw_sim": "without a flywheel",
           "cols": ("Pos.", "φ, °", "Mс, N·m", "Jпр, kg·m²", "Aс, J", "Aд, J", "ΔT, J"),
           "icols": ("Interval", "φ from, °", "φ to, °", "mean Mс, N·m", "yM, mm",
                     "yA at the end, mm"),
           "none": "not in the catalogue", "shaft_crank": "on the crank shaft",
           "shaft_motor": "on the motor shaft", "flat": "ψ < 20°: from the intercepts, method D.3",
           "sign": "φ is the crank's travel from the first position in its sense of rotation; "
                   "moments are positive in the sense of rotation (Mс < 0 resists)"},
}


def _table(header, rows) -> list[str]:
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return out


def position_rows(u: MachineUnit, lang: str | None = None) -> list[list[str]]:
    """Per position: label, φ (°), Mс, Jпр, Aс, Aд, ΔT; round-off next to the largest value
    written as 0; with the decimal comma for ``lang="ru"`` (a sheet).

    φ is the crank's angle (of O→A, as on sheets 1 and 2) over a one-turn cycle; over a
    four-stroke cycle (720°) it is the cycle angle, the crank's travel from the first position
    (0 … 690° for 24 positions, as the diagrams beside the table and the engine books count it
    from the ВМТ of intake), where the angle of O→A modulo 720° would read 90 … 690, 0, 30, 60."""
    m, wd = u.model, u.flywheel.work
    big_m, big_a = float(np.max(np.abs(m.moment.M))), float(np.max(np.abs(wd.A_c)))
    big_i = float(np.max(np.abs(m.inertia.I_red)))

    def v(x, big):
        return "0" if abs(x) < 1e-9 * big else fmt(x, 5)

    rows = []
    for k, lab in enumerate(m.moment.labels):
        t = float(m.moment.pos_tau[k])
        phi0 = float(m.moment.phi[0])
        phi = cycle_angle_deg(phi0 + m.moment.sense * t, phi0, m.moment.sense, m.period)
        rows.append([lab, f"{phi:.1f}", v(float(m.moment.pos_M[k]), big_m),
                     v(float(m.pos_inertia.I_red[k]), big_i),
                     v(float(np.interp(t, wd.tau, wd.A_c)), big_a),
                     v(float(np.interp(t, wd.tau, wd.A_d)), big_a),
                     v(float(np.interp(t, wd.tau, wd.dT)), big_a)])
    if lang == "ru":
        rows = [[c.replace(".", ",") for c in r] for r in rows]
    return rows


def dynamics_markdown(u: MachineUnit, lang: str = "ru") -> str:
    """The hand calculation of sheet 3 (see the module docstring)."""
    t = T[lang]
    ru = lang == "ru"
    fw, wd, mc, s = u.flywheel, u.flywheel.work, u.motor, u.simulation
    mo = None if mc is None else mc.motor
    w = fw.omega
    n1 = w * 30.0 / math.pi
    cyc = "4π" if u.model.period > 7.0 else "2π"  # a four-stroke process: 720°
    J, Nm, mm = ("Дж", "Н·м", "мм") if ru else ("J", "N·m", "mm")
    # units in the file's language (an English file in English units)
    rad_s, rad, kgm2, m_s = (("рад/с", "рад", "кг·м²", "м/с") if ru else
                             ("rad/s", "rad", "kg·m²", "m/s"))
    graph_pct = (fw.I_m_graph / fw.I_m - 1) * 100 if fw.I_m else 0.0
    L = [f"# {t['title']}", "", f"## {t['data']}", "",
         f"- ω1 = {fmt(w, 5)} {rad_s}, n1 = {fmt(n1, 5)} "
         f"{'об/мин' if ru else 'rpm'}; δ = {fw.delta:g}; η = "
         f"{u.efficiency:g}",
         f"- Jкр = {fmt(fw.I_const, 4)} {kgm2}",
         f"- {t['sign']}",
         "", f"## {t['pos']}", ""]
    L += _table(t["cols"], position_rows(u))
    L += ["", f"## {t['int']}", "",
          f"- Kφ = {cyc}/L = {cyc}/{fmt(wd.length_mm)} = {fmt(wd.Kphi, 5)} {rad}/{mm}",
          f"- KM = {fmt(wd.KM, 4)} {Nm}/{mm}; H = {fmt(wd.H)} {mm}",
          f"- KA = Kφ·KM·H = {fmt(wd.Kphi, 5)}·{fmt(wd.KM, 4)}·{fmt(wd.H)} = "
          f"{fmt(wd.KA, 5)} {J}/{mm}",
          "- yA(i+1) = yA(i) + yM(i)·Δx(i)/H", ""]
    rows = []
    for i in range(wd.intervals):
        a, b = wd.node_tau[i], wd.node_tau[i + 1]
        rows.append([str(i + 1), f"{math.degrees(a):.2f}", f"{math.degrees(b):.2f}",
                     fmt(float(wd.M_mid[i]), 5), f"{wd.yM_mm[i]:.2f}", f"{wd.yA_mm[i + 1]:.2f}"])
    L += _table(t["icols"], rows)
    L += ["",
          f"- Aс({cyc}) = yA·KA = {wd.yA_mm[-1]:.2f}·{fmt(wd.KA, 5)} = "
          f"{fmt(float(wd.A_c_graph[-1]), 6)} {J} "
          f"({'точно' if ru else 'exact'} {fmt(float(wd.A_c[-1]), 6)}, "
          f"{'погрешность' if ru else 'error'} {wd.error * 100:.2f} %)",
          f"- Mд = −Aс({cyc})/{cyc} = {fmt(wd.M_d_graph, 6)} {Nm} "
          f"({'точно' if ru else 'exact'} {fmt(fw.M_d, 6)})",
          f"- ΔT = Aд + Aс; ΔTmax − ΔTmin = {fmt(fw.dT_max, 6)} {J}", "",
          f"## {t['fly']}", "",
          f"- KJ = {fmt(fw.KI, 4)} {kgm2}/{mm}, KT = {fmt(fw.KT, 5)} {J}/{mm} "
          f"(KA/KT = {fmt(wd.KA / fw.KT, 5)})",
          f"- tg ψmax = KJ/(2·KT)·ω²·(1 + δ) = {fmt(fw.KI, 4)}/(2·{fmt(fw.KT, 5)})·"
          f"{fmt(w, 5)}²·{1 + fw.delta:g} = {fw.tan_max:.5f}, ψmax = {fw.psi_max:.3f}°",
          f"- tg ψmin = KJ/(2·KT)·ω²·(1 − δ) = {fw.tan_min:.5f}, ψmin = {fw.psi_min:.3f}°",
          f"- k = {fw.k_mm:.2f} {mm}, l = {fw.l_mm:.2f} {mm}, kl = {fw.segment_mm:.2f} {mm}"
          + (f" ({t['flat']})" if fw.tangents_flat else ""),
          f"- JI = kl·KT/(ω²·δ) = {fw.segment_mm:.2f}·{fmt(fw.KT, 5)}/({fmt(w, 5)}²·"
          f"{fw.delta:g}) = {fmt(fw.J_I, 6)} {kgm2}",
          f"- Jм = JI − Jкр − Jрот·u² = {fmt(fw.J_I, 6)} − {fmt(fw.I_const, 4)} − "
          f"{fmt(fw.I_rotor, 4)} = {fmt(fw.I_m_signed if not fw.needed else fw.I_m, 6)} "
          f"{kgm2}" + ("" if fw.needed else f" ≤ 0: {t['no_fw']}"),
          (f"- {'Мерцалов' if ru else 'Merkalov'}: {fmt(fw.I_m_approx, 6)} {kgm2} "
           f"({signed(fw.difference_pct, 3)} %); "
           f"{'по графическому ΔT' if ru else 'from the graphical ΔT'}: "
           f"{fmt(fw.I_m_graph, 6)} {kgm2} ({signed(graph_pct)} %)") if fw.needed else
          (f"- {'Мерцалов' if ru else 'Merkalov'}: Jм = {fmt(fw.I_m_approx, 6)} {kgm2}; "
           f"{'по графическому ΔT' if ru else 'from the graphical ΔT'}: Jм = "
           f"{fmt(fw.I_m_graph, 6)} {kgm2}"),
          "", f"## {t['motor']}", ""]
    if mc is None or mo is None:  # driven by its loads (an engine): the constant moment is Mс
        engine = ("нагрузки совершают положительную работу за цикл (двигатель): постоянный "
                  "момент — момент сопротивления потребителя Mс" if ru else
                  "the loads do positive work over the cycle (an engine): the constant moment "
                  "is the consumer’s resistance Mс")
        L += [f"- {engine} = {fmt(fw.M_d, 6)} {Nm}",
              f"- P = |Mс|·ω1·η = {fmt(u.power_W, 6)} {'Вт' if ru else 'W'}"]
    else:
        L += [f"- Pс = Mд·ω1 = {fmt(fw.M_d, 6)}·{fmt(w, 5)} = {fmt(fw.P_c, 6)} "
              f"{'Вт' if ru else 'W'}",
              f"- {'Pдв.тр' if ru else 'Preq'} = Pс/η = {fmt(fw.P_c, 6)}/{u.efficiency:g} = "
              f"{fmt(u.power_W, 6)} {'Вт' if ru else 'W'}",
              f"- {mc.reason}",
              f"- Jрот = "
              f"{fmt(mo.inertia_kg_m2, 4) if mo.inertia_kg_m2 is not None else t['none']}"
              + (f", Jрот·u² = {fmt(fw.I_rotor, 5)} {kgm2}"
                 if mo.inertia_kg_m2 is not None else "")]
    L += ["", f"## {t['rim']}", ""]
    m = u.mounted
    if fw.needed:
        L.append(f"- {m.shape}, {t['shaft_' + u.shaft]}: I = {fmt(m.inertia, 5)} {kgm2}, "
                 f"D = {fmt(m.D * 1000, 4)} {mm}, b = "
                 f"{fmt(m.b * 1000, 4)} {mm}, h = {fmt(m.h * 1000, 4)} {mm}, m = "
                 f"{fmt(m.mass, 4)} {'кг' if ru else 'kg'}, v = ω·D/2 = {fmt(m.speed, 3)} {m_s}"
                 + ("" if m.speed_ok else f" (> 40 {m_s}!)"))
    else:  # the crank (and the rotor) already have JI
        why = str(t["no_fw_why"]).format(ji=fmt(fw.J_I, 6),
                                         have=fmt(fw.I_const + fw.I_rotor, 6))
        L.append(f"- {why}")
    L += ["", f"## {t['check']}", "",
          f"- ω(φ) = √(2(T0 + ΔT)/(Jпр + Jрот·u² + Jм)): ωmax = {fmt(s.omega_max, 5)}, "
          f"ωmin = {fmt(s.omega_min, 5)}, δ = (ωmax − ωmin)/ωср = {s.delta_actual:.5f} "
          + (f"({signed(u.delta_error_pct, 3)} % {'от цели' if ru else 'off the target'})"
             if fw.needed else f"≤ δ = {fw.delta:g} ({t['no_fw_sim']})"),
          (f"- RK4 {'с характеристикой двигателя' if ru else 'with the motor characteristic'} "
           f"(s = {mo.slip:.3f}): δ = {float(s.cycle_delta[-1]):.5f}" if mo is not None else
           f"- RK4: δ = {float(s.cycle_delta[-1]):.5f}"), ""]
    return "\n".join(L)


def dynamics_csv(u: MachineUnit) -> str:
    """One row per position: φ, Mс, Jпр, Aс, Aд, ΔT (SI)."""
    buf = io.StringIO()
    wr = csv.writer(buf, lineterminator="\n")
    wr.writerow(["position", "travel_deg", "M_c_Nm", "I_red_kgm2", "A_c_J", "A_d_J", "dT_J"])
    m, wd = u.model, u.flywheel.work
    for k, lab in enumerate(m.moment.labels):
        t = float(m.moment.pos_tau[k])
        wr.writerow([lab, f"{math.degrees(t):.6f}", f"{float(m.moment.pos_M[k]):.9g}",
                     f"{float(m.pos_inertia.I_red[k]):.9g}",
                     f"{float(np.interp(t, wd.tau, wd.A_c)):.9g}",
                     f"{float(np.interp(t, wd.tau, wd.A_d)):.9g}",
                     f"{float(np.interp(t, wd.tau, wd.dT)):.9g}"])
    return buf.getvalue()


__all__ = ["dynamics_csv", "dynamics_markdown", "position_rows"]
