"""Plain-text tables of an analysis, in the order of a hand calculation.

Section 1 is always the structural analysis (the first step of a TMM project),
then the cycle, then the kinematics of each position. Russian or English.
"""

from __future__ import annotations

import math

from ..geometry import norm
from ..kinematics import position_angles_deg
from ..model import russian_kind
from ..numbers import fixed
from ..project import Analysis

TEXT = {
    "en": {
        "structure": "1. Structural analysis",
        "pairs": "Kinematic pairs: p5 = {p5} lower pairs of class V (R revolute, P prismatic), "
                 "p4 = {p4} higher pairs of class IV",
        "R": "revolute",
        "P": "prismatic",
        "groups": "Assur groups, in the order of attachment",
        "group": "Assur group of class II, order 2, {formula}: links {links}, kind {kind} ({num})",
        "initial": "initial mechanism I({frame},{crank}): frame {frame}, crank {crank}",
        "formula": "formula of structure",
        "cycle": "2. Cycle of the output link {link}",
        "omega1": "crank speed n1 = {rpm:g} rpm, ω1 = π·n1/30 = {w:.4f} rad/s ({sense})",
        "dead": "dead centres: start of working stroke φ = {a:.2f}°, end φ = {b:.2f}°",
        "nodead": "the output has no dead centres",
        "stroke": "stroke H = {h:.2f} mm",
        "swing": "swing ψ = {s:.2f}°",
        "ratio": "working stroke {w:.2f}° of crank, idle {i:.2f}°, K = {k:.4f}",
        "cond": "smallest |sin| between the lines of {name}: {s:.4f} at φ = {a:.2f}°",
        "kin": "3. Kinematics of the positions (exact)",
        "coords": "Coordinates of points, mm",
        "vel": "Velocities |v| of points, m/s; angular velocities ω, rad/s (CCW +)",
        "acc": "Accelerations |a| of points, m/s²; angular accelerations ε, rad/s² (CCW +)",
        "pos": "pos.",
        "ccw": "counter-clockwise",
        "cw": "clockwise",
    },
    "ru": {
        "structure": "1. Структурный анализ",
        "pairs": "Кинематические пары: p5 = {p5} низших пар V класса (В — вращательная, "
                 "П — поступательная), p4 = {p4} высших пар IV класса",
        "R": "вращательная",
        "P": "поступательная",
        "groups": "Группы Ассура в порядке присоединения",
        "group": ("группа Ассура II класса 2-го порядка {formula}: звенья {links}, "
                  "вид {kind} ({num})"),
        "initial": "начальный механизм I({frame},{crank}): стойка {frame}, кривошип {crank}",
        "formula": "формула строения",
        "cycle": "2. Цикл выходного звена {link}",
        "omega1": "частота вращения n1 = {rpm:g} об/мин, ω1 = π·n1/30 = {w:.4f} рад/с ({sense})",
        "dead": "крайние положения: начало рабочего хода φ = {a:.2f}°, конец φ = {b:.2f}°",
        "nodead": "у выходного звена нет крайних положений",
        "stroke": "ход H = {h:.2f} мм",
        "swing": "угол размаха ψ = {s:.2f}°",
        "ratio": "рабочий ход {w:.2f}° поворота кривошипа, холостой {i:.2f}°, K = {k:.4f}",
        "cond": "наименьший |sin| между линиями {name}: {s:.4f} при φ = {a:.2f}°",
        "kin": "3. Кинематика положений (точно)",
        "coords": "Координаты точек, мм",
        "vel": "Скорости |v| точек, м/с; угловые скорости ω, рад/с (против часовой +)",
        "acc": "Ускорения |a| точек, м/с²; угловые ускорения ε, рад/с² (против часовой +)",
        "pos": "пол.",
        "ccw": "против часовой стрелки",
        "cw": "по часовой стрелке",
    },
}


def format_table(header: list[str], rows: list[list[str]]) -> str:
    """Right-aligned columns with a rule under the header."""
    widths = [max(len(h), *(len(r[c]) for r in rows)) if rows else len(h)
              for c, h in enumerate(header)]
    line = "  ".join(h.rjust(w) for h, w in zip(header, widths, strict=True))
    rule = "  ".join("-" * w for w in widths)
    body = ["  ".join(v.rjust(w) for v, w in zip(r, widths, strict=True)) for r in rows]
    return "\n".join([line, rule, *body])


def structure_text(a: Analysis, lang: str = "en") -> str:
    """Section 1: mobility by Chebyshev's formula, pairs, Assur groups."""
    t = TEXT[lang]
    st, m = a.structure, a.mech
    lines = [t["structure"], "", st.mobility_equation, "",
             t["pairs"].format(p5=st.p5, p4=st.p4) + ":"]
    for p in st.pairs:
        lines.append(f"  {p.label_ru if lang == 'ru' else p.label} — {t[p.kind]}")
    lines += ["", t["groups"] + ":",
              "  " + t["initial"].format(frame=m.frame_link, crank=m.crank.link)]
    for g in st.groups:
        lines.append("  " + t["group"].format(formula=g.formula,
                                              links=f"{g.links[0]}, {g.links[1]}",
                                              kind=g.kind_ru if lang == "ru" else g.kind,
                                              num=g.kind_number))
    lines += ["", f"{t['formula']}: {st.formula}"]
    return "\n".join(lines)


def cycle_text(a: Analysis, lang: str = "en") -> str:
    """Section 2: crank speed, dead centres, stroke, time ratio, conditioning."""
    t = TEXT[lang]
    m, cy = a.mech, a.cycle
    lines = [t["cycle"].format(link=m.output.link), ""]
    lines.append(t["omega1"].format(rpm=m.crank.rpm, w=abs(m.crank.omega),
                                    sense=t["ccw"] if m.crank.sense > 0 else t["cw"]))
    if cy.dead_centres:
        lines.append(t["dead"].format(a=math.degrees(cy.dead_centres[0]),
                                      b=math.degrees(cy.dead_centres[1])))
        lines.append(t["stroke"].format(h=cy.stroke * 1e3))
        if cy.output_kind == "rocker":
            lines.append(t["swing"].format(s=math.degrees(cy.swing)))
        w = math.degrees(cy.working_turn)
        lines.append(t["ratio"].format(w=w, i=360 - w, k=cy.time_ratio))
    else:
        lines.append(t["nodead"])
    for name, (s, ang) in cy.min_conditioning.items():
        lines.append(t["cond"].format(name=russian_kind(name) if lang == "ru" else name, s=s,
                                      a=math.degrees(ang) % 360))
    return "\n".join(lines)


def kinematics_text(a: Analysis, lang: str = "en") -> str:
    """Section 3: coordinates, velocities, accelerations of every position."""
    t = TEXT[lang]
    kin, m = a.kin, a.mech
    names = [p for p in kin.point_names() if p not in m.frame_points]
    angles = position_angles_deg(m, kin)
    links = list(m.moving_links)
    head = [t["pos"], "φ, °"]
    out = [t["kin"], "", t["coords"]]
    rows = []
    for k in range(kin.n):
        row = [kin.labels[k], f"{angles[k]:.2f}"]
        for p in names:
            x, y = kin.pos.points[p][k] * 1e3
            row.append(f"({fixed(x, 2)}, {fixed(y, 2)})")
        rows.append(row)
    out += [format_table(head + names, rows), "", t["vel"]]
    rows = []
    for k in range(kin.n):
        row = [kin.labels[k], f"{angles[k]:.2f}"]
        row += [fixed(norm(kin.vel.points[p][k])) for p in names]
        row += [fixed(kin.vel.omega[ln][k]) for ln in links]
        rows.append(row)
    out += [format_table(head + [f"v_{p}" for p in names] + [f"ω{ln}" for ln in links], rows),
            "", t["acc"]]
    rows = []
    for k in range(kin.n):
        row = [kin.labels[k], f"{angles[k]:.2f}"]
        row += [fixed(norm(kin.acc.points[p][k])) for p in names]
        row += [fixed(kin.acc.epsilon[ln][k]) for ln in links]
        rows.append(row)
    out.append(format_table(head + [f"a_{p}" for p in names] + [f"ε{ln}" for ln in links], rows))
    return "\n".join(out)


def analysis_text(a: Analysis, lang: str = "en") -> str:
    """The whole text report of ``graphplan analyze``."""
    title = f"graphplan — {a.mech.name} ({a.mech.source})"
    parts = [title, "=" * len(title), "", structure_text(a, lang), "", cycle_text(a, lang), "",
             kinematics_text(a, lang)]
    return "\n".join(parts) + "\n"


__all__ = ["analysis_text", "format_table"]
