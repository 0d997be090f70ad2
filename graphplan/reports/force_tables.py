"""Tables of the force analysis, laid out as the seed's hand calculation (issue 4).

Position by position: the loads acting on the links (G2, G3, Pи2, Pи3, Mи…, Q, in N),
what the variant's neglect rule dropped and how much that changes Mур against the full
model (every load kept), the moment equations of the force plans with their arms in
millimetres of the position plan, the force scale Kp with its basis, the segments of the
force polygons in mm and their values (N and kN), the reactions, the arm h21, Mур from
the force plans, Mур from Zhukovsky's lever and their discrepancy. Every quantity is
given as an exact construction and as a drafted one (segments and arms read to the
variant's ``drawing.reading_mm``, default 0.5 mm), side by side, with the drafting error
and the bound :mod:`graphplan.plans.conditioning` states for that precision (``±``). A position
whose force plans close at less than ``ILL_ANGLE_DEG`` is marked as a draftsman marks it
(``lines meet at 1.3°, reading ±11 mm``).

Sign convention (stated once): moments are **counter-clockwise positive** in the
variant's axes, as in :mod:`graphplan.forces.kinetostatics`. **Mур** (``M_bal``) is the
balancing moment the motor applies to the crank so that it turns at constant ω1. The
moment of the resisting forces reduced to the crank (приведённый момент сил
сопротивления) is ``Mс = −Mур``. The seed plots Mур ("кривая моментов сил
сопротивления" built "по полученным значениям Мур"), and so does
:func:`graphplan.forces.moment_curve`.

:func:`forces_markdown` is for people (ru/en), :func:`forces_csv` for scripts,
:func:`curve_markdown` the table of the exact Mур(φ) (``project.curve``). The figures they
write are :func:`graphplan.reports.force_readings.force_readings`; the seed's figures beside
graphplan's (``examples/press.md``) are :mod:`graphplan.reports.seed_comparison`.
"""

from __future__ import annotations

import csv
import io
import math
import re

from ..forces import MomentCurve
from ..model import russian_kind
from ..numbers import csv_number, finite, fixed, fmt
from ..plans import (
    ForcePlan,
)
from ..project import Analysis
from ..safe_text import markdown_cell
from ..units import Scale
from .force_readings import TINY, PositionForces, force_readings

WORDS = {
    "en": {
        "title": "Force analysis (kinetostatics) by force plans",
        "position": "Position", "phi": "φ, °", "mode": "Mode", "plan": "Plan",
        "load": "Load", "link": "Link", "kind": "Kind", "value": "Value", "taken": "Taken",
        "yes": "yes", "neglected": "neglected",
        "gravity": "weight", "inertia": "inertia", "resistance": "resistance",
        "external": "external",
        "section": "Position {label}, φ = {phi:.2f}°",
        "loads": "Loads acting on the links",
        "rule": ("Neglected by the variant's rule (a load under {pct} % of the largest load "
                 "of its group): {names}."),
        "rule_none": "Nothing is neglected at this position (rule: {pct} %).",
        "rule_change": ("Mур with every load kept: {full} N·m; the rule changes Mур by "
                        "{d} N·m ({p} %)."),
        "equations": "Moment equations (arms measured on the position plan, mm)",
        "arm": "Arm", "exact_mm": "Exact, mm", "draft_mm": "Drafted, mm",
        "scales": "Force scales",
        "segments": "Force polygons",
        "quantity": "Quantity", "segment": "Segment",
        "exact": "Exact", "drafted": "Drafted", "error": "Error, %",
        "results": "Reactions and the balancing moment",
        "mbal_plans": "Mур (force plans), N·m", "mbal_lever": "Mур (Zhukovsky's lever), N·m",
        "discrepancy": "Discrepancy Δ, %", "h21": "h{n}, mm",
        "curve": "Curve of Mур at the positions",
        "curve_note": ("Mур: the balancing moment on the crank, N·m, counter-clockwise positive; "
                       "the moment of the resisting forces reduced to the crank is Mс = −Mур. "
                       "Exact, with the variant's neglect rule; travel from position {first} in "
                       "the direction of rotation."),
        "travel": "Travel, °", "mc": "Mс = −Mур, N·m",
        "note": ("Exact: the plans built exactly (lengths to 0.01 mm). Drafted: every segment "
                 "and arm read to {p} mm, the groups taking the reactions as read off the plans "
                 "before them. Error = (drafted − exact)/exact. Moments counter-clockwise "
                 "positive."),
        "N": "N", "kN": "kN", "N·m": "N·m", "mm": "mm", "m": "m",
        "bound": "±", "ill": "Ill-conditioned", "step": "step",
    },
    "ru": {
        "title": "Силовой расчёт (кинетостатика) методом планов сил",
        "position": "Положение", "phi": "φ, °", "mode": "Режим", "plan": "План",
        "load": "Нагрузка", "link": "Звено", "kind": "Вид", "value": "Значение",
        "taken": "Учтена", "yes": "да", "neglected": "пренебрегаем",
        "gravity": "сила тяжести", "inertia": "сила инерции",
        "resistance": "сила сопротивления", "external": "внешняя",
        "section": "Положение {label}, φ = {phi:.2f}°",
        "loads": "Силы, действующие на звенья",
        "rule": ("Пренебрегаем по правилу варианта (нагрузка меньше {pct} % наибольшей "
                 "нагрузки группы): {names}."),
        "rule_none": "В этом положении ничем не пренебрегаем (правило: {pct} %).",
        "rule_change": ("Мур с учётом всех нагрузок: {full} Н·м; правило изменяет Мур на "
                        "{d} Н·м ({p} %)."),
        "equations": "Уравнения моментов (плечи измерены на плане положений, мм)",
        "arm": "Плечо", "exact_mm": "Точно, мм", "draft_mm": "Чертёж, мм",
        "scales": "Масштабы планов сил",
        "segments": "Планы сил",
        "quantity": "Величина", "segment": "Отрезок",
        "exact": "Точно", "drafted": "Чертёж", "error": "Погрешность, %",
        "results": "Реакции и уравновешивающий момент",
        "mbal_plans": "Мур (планы сил), Н·м", "mbal_lever": "Мур (рычаг Жуковского), Н·м",
        "discrepancy": "Расхождение Δ, %", "h21": "h{n}, мм",
        "curve": "Мур в положениях (кривая моментов)",
        "curve_note": ("Мур — уравновешивающий момент на кривошипе, Н·м, против часовой "
                       "стрелки — плюс; приведённый момент сил сопротивления Мс = −Мур. Точно, "
                       "с правилом пренебрежения варианта; угол поворота от положения {first} "
                       "по направлению вращения."),
        "travel": "Поворот, °", "mc": "Мс = −Мур, Н·м",
        "note": ("Точно: планы построены точно (длины до 0.01 мм). Чертёж: каждый отрезок и "
                 "плечо прочитаны с точностью {p} мм, группы берут реакции, прочитанные на "
                 "предыдущих планах. Погрешность = (чертёж − точно)/точно. Моменты против "
                 "часовой стрелки — плюс."),
        "N": "Н", "kN": "кН", "N·m": "Н·м", "mm": "мм", "m": "м",
        "bound": "±", "ill": "Плохо обусловлено", "step": "шаг",
    },
}


# --- formatting ----------------------------------------------------------------------------


def _finite(x: float) -> float:
    return finite(x, "a force table")


def _m_bal(crank_plan) -> float:
    """Mур read off the crank's force plan (the last plan of a position; only it has one)."""
    assert crank_plan.M_bal is not None, crank_plan.group
    return float(crank_plan.M_bal)


def _f(x: float, d: int = 2) -> str:
    """A table's fixed decimals (:func:`~graphplan.numbers.fixed`), never NaN."""
    return fixed(_finite(x), d)


def _pct(err: float | None) -> str:
    return "—" if err is None else _f(err * 100)


def _rel(value: float, exact: float, big: float) -> float | None:
    """Relative error, None where the exact value is (relatively) zero."""
    if abs(exact) <= TINY * max(big, 1e-300):
        return None
    return (value - exact) / exact


def _words(lang: str) -> dict[str, str]:
    if lang not in WORDS:
        raise ValueError(f"unknown language {lang!r} (expected one of {', '.join(WORDS)})")
    return WORDS[lang]


def _group(name: str, lang: str) -> str:
    """``RRP(2-3)`` → ``ВВП(2-3)``, ``crank 1`` → ``кривошип 1`` in Russian."""
    return russian_kind(name.replace("crank", "кривошип")) if lang == "ru" else name


def _eq(text: str, lang: str) -> str:
    return text.replace("(link ", "(звено ") if lang == "ru" else text


def _basis(sc: Scale, lang: str) -> str:
    b = sc.basis
    return b.replace("N/mm", "Н/мм") if lang == "ru" else b


def _md_table(header: list[str], rows: list[list[str]], right: set[int]) -> list[str]:
    rule = ["---:" if c in right else "---" for c in range(len(header))]
    return ["| " + " | ".join(r) + " |" for r in (header, rule, *rows)]


def _decimals(precision: float) -> int:
    return next((d for d in range(6) if abs(round(precision, d) - precision) <= 1e-9), 6)


def _crank_arm(plan: ForcePlan) -> tuple[str, float] | None:
    """The crank's h21 (``"h21"`` and its mm)."""
    for key, mm in plan.arms_mm.items():
        if not key.startswith("h_"):
            return key, mm
    return None


def _reactions(pf: PositionForces) -> list[str]:
    """Reaction names in the order of the plans (each once)."""
    names: list[str] = []
    for p in pf.exact:
        for n in p.reactions:
            if n not in names:
                names.append(n)
    return names


def _reaction_value(plans: tuple[ForcePlan, ...], name: str) -> float:
    for p in plans:
        if name in p.reactions:
            return p.reactions[name].magnitude
    raise KeyError(name)


# --- Markdown ------------------------------------------------------------------------------


def _pm(bound: float | None) -> str:
    return "—" if bound is None else "±" + _f(bound)


def _marks(pf: PositionForces, lang: str) -> list[str]:
    """The draftsman's mark of a position whose force plans are ill-conditioned."""
    c = pf.conditioning
    if c is None or not c.marks:
        return []
    w = _words(lang)
    return [f"**{w['ill']}:** {x.note(lang)} ({_group(x.plan, lang)}, {w['step']} {x.step}: "
            f"`{_eq(x.equation, lang)}`)." for x in c.marks] + [""]


def _position_markdown(pf: PositionForces, lang: str) -> list[str]:
    w = _words(lang)
    d = _decimals(pf.precision)
    out = ["", f"## {w['section'].format(label=pf.label, phi=pf.phi_deg)}", "",
           *_marks(pf, lang), f"### {w['loads']}", ""]
    rows = [[r.name, r.link, w.get(r.kind, r.kind), f"{_f(r.value)} {w[r.unit]}",
             w["neglected"] if r.neglected else w["yes"]] for r in pf.loads]
    out += _md_table([w["load"], w["link"], w["kind"], w["value"], w["taken"]], rows, {3})
    pct = fmt(pf.rule * 100, 4)
    out.append("")
    if pf.neglected:
        out.append(w["rule"].format(pct=pct, names=", ".join(pf.neglected)))
        dm = pf.M_bal - pf.M_full
        p = _rel(pf.M_bal, pf.M_full, pf.M_scale)  # of a round-off Mур (a dead centre): "—"
        out.append(w["rule_change"].format(full=_f(pf.M_full), d=("+" if dm >= 0 else "")
                                           + _f(dm), p="—" if p is None else
                                           ("+" if p >= 0 else "") + _f(p * 100)))
    else:
        out.append(w["rule_none"].format(pct=pct))

    out += ["", f"### {w['equations']}", ""]
    arm_rows = []
    for pe, pd in zip(pf.exact, pf.drafted, strict=True):
        for eq in pe.equations:
            out.append(f"- {_group(pe.group, lang)}: `{_eq(eq, lang)}`")
        # the crank's h21 is also stored as h_R21@O: show it once
        alias = {f"h_R{k[1:]}@" for k in pe.arms_mm if not k.startswith("h_")}
        for key, mm in pe.arms_mm.items():
            if any(key.startswith(a) for a in alias):
                continue
            arm_rows.append([_group(pe.group, lang), key, _f(mm),
                             _f(pd.arms_mm.get(key, math.nan), d) if key in pd.arms_mm else "—"])
    out += ["", *_md_table([w["plan"], w["arm"], w["exact_mm"],
                            f"{w['draft_mm']} ({fmt(pf.precision)})"], arm_rows, {2, 3})]

    out += ["", f"### {w['scales']}", ""]
    for pe, pd in zip(pf.exact, pf.drafted, strict=True):
        line = f"- {_group(pe.group, lang)}: {w['exact']} `{_basis(pe.scale, lang)}`"
        if pd.scale.basis != pe.scale.basis:
            line += f"; {w['drafted']} `{_basis(pd.scale, lang)}`"
        out.append(line)

    out += ["", f"### {w['segments']}", ""]
    rows = []
    for pe, pd in zip(pf.exact, pf.drafted, strict=True):
        big = max((r.value for r in pe.readings.values()), default=0.0)
        for q, r in pe.readings.items():
            rd = pd.readings.get(q)
            cells = [_group(pe.group, lang), q, f"`{r.name}`", _f(r.mm), _f(r.value),
                     _f(r.value / 1000, 3)]
            if rd is None:
                cells += ["—", "—", "—", "—"]
            else:
                cells += [_f(rd.mm, d), _f(rd.value), _pm(pf.bound("force", q)),
                          _pct(_rel(rd.value, r.value, big))]
            rows.append(cells)
    head = [w["plan"], w["quantity"], w["segment"], f"{w['exact']}, {w['mm']}",
            f"{w['exact']}, {w['N']}", f"{w['exact']}, {w['kN']}",
            f"{w['drafted']}, {w['mm']}", f"{w['drafted']}, {w['N']}", f"{w['bound']}, {w['N']}",
            w["error"]]
    out += _md_table(head, rows, {3, 4, 5, 6, 7, 8, 9})

    out += ["", f"### {w['results']}", ""]
    rows = []
    big = max((_reaction_value(pf.exact, n) for n in _reactions(pf)), default=0.0)
    for n in _reactions(pf):
        e, rv = _reaction_value(pf.exact, n), _reaction_value(pf.drafted, n)
        rows.append([n, _f(e), _f(e / 1000, 3), _f(rv), _f(rv / 1000, 3),
                     _pm(pf.bound("force", f"vector {n}")), _pct(_rel(rv, e, big))])
    head = [w["quantity"], f"{w['exact']}, {w['N']}", f"{w['exact']}, {w['kN']}",
            f"{w['drafted']}, {w['N']}", f"{w['drafted']}, {w['kN']}", f"{w['bound']}, {w['N']}",
            w["error"]]
    out += [*_md_table(head, rows, {1, 2, 3, 4, 5, 6}), ""]
    rows = []
    he, hd = _crank_arm(pf.exact[-1]), _crank_arm(pf.drafted[-1])
    if he is not None:
        hdv = hd[1] if hd is not None else math.nan
        rows.append([w["h21"].format(n=he[0][1:]), _f(he[1]), _f(hdv, d) if hd else "—",
                     _pm(pf.precision / 2) if hd else "—",
                     _pct(_rel(hdv, he[1], 1.0)) if hd else "—"])
    me, md = _m_bal(pf.exact[-1]), _m_bal(pf.drafted[-1])
    mbig = max(abs(me), abs(pf.lever_exact.M_bal), pf.M_scale)
    rows.append([w["mbal_plans"], _f(me), _f(md), _pm(pf.bound("force", "Mур")),
                 _pct(_rel(md, me, mbig))])
    le, ld = pf.lever_exact.M_bal, pf.lever_drafted.M_bal
    rows.append([w["mbal_lever"], _f(le), _f(ld), _pm(pf.bound("lever", "Mур")),
                 _pct(_rel(ld, le, mbig))])
    rows.append([w["discrepancy"], _f(pf.lever_exact.discrepancy_pct or 0.0),
                 _f(pf.lever_drafted.discrepancy_pct or 0.0), "—", "—"])
    out += _md_table([w["quantity"], w["exact"], f"{w['drafted']} ({fmt(pf.precision)} "
                      f"{w['mm']})", w["bound"], w["error"]], rows, {1, 2, 3, 4})
    return out


def forces_markdown(analysis: Analysis, lang: str = "ru", precision: float | None = 0.5) -> str:
    """The force analysis of every position as a Markdown document (ru or en).

    Per position: the loads acting (value, whether the neglect rule dropped them, and the
    change of Mур against the full model), the moment equations and their arms (mm),
    Kp with its basis, the segments of the force polygons (mm, N, kN), the reactions,
    h21, Mур from the plans and from Zhukovsky's lever and their discrepancy — exact and
    drafted side by side; at the end, the curve of Mур at the positions.

    Parameters
    ----------
    analysis : Analysis
    lang : str
        ``"ru"`` or ``"en"``.
    precision : float or None
        Drafting reading precision, mm; ``None``: the variant's ``drawing.reading_mm``.
    """
    w = _words(lang)
    positions = force_readings(analysis, precision)
    prec = positions[0].precision
    out = [f"# {w['title']} — {markdown_cell(analysis.mech.name)}", "",
           w["note"].format(p=fmt(prec))]
    for pf in positions:
        out += _position_markdown(pf, lang)
    out += ["", *curve_markdown(analysis, lang)]
    text = "\n".join(out) + "\n"
    if re.search(r"\b(nan|inf)\b", text, re.IGNORECASE):
        raise ValueError("NaN or infinity in the force tables' Markdown")
    return text


def curve_markdown(analysis: Analysis, lang: str = "ru",
                   curve: MomentCurve | None = None) -> list[str]:
    """Lines of the Markdown table of the curve of Mур at the positions."""
    w = _words(lang)
    c = curve if curve is not None else analysis.curve
    rows = [[lab, _f(t), _f(p), _f(m), _f(-m)] for lab, t, p, m in
            zip(c.labels, c.position_travel_deg, c.position_phi_deg, c.M_positions,
                strict=True)]
    rows.sort(key=lambda r: float(r[1]))
    return [f"## {w['curve']}", "", w["curve_note"].format(first=c.labels[0]), "",
            *_md_table([w["position"], w["travel"], w["phi"], f"Мур, {w['N·m']}"
                        if lang == "ru" else "Mур, N·m", w["mc"]], rows, {1, 2, 3, 4})]


# --- CSV -----------------------------------------------------------------------------------


CSV_COLUMNS = ("position", "phi_deg", "mode", "precision_mm", "plan", "kind", "quantity",
               "segment", "mm", "scale", "scale_per_mm", "value", "unit", "exact_value",
               "error_pct", "bound", "ill_conditioned")
"""Columns of :func:`forces_csv`.

``kind`` is ``segment`` (a force polygon's segment: ``value = mm·scale_per_mm``, N),
``arm`` (an arm on the position plan: ``value = mm·Kl``, m), ``moment`` (``Mур`` of the
crank's plan, ``Mур(Ж)`` of the lever, N·m; ``Mур(full)``, the exact Mур with every load
kept), ``discrepancy`` (Δ between the plans and the lever, %) or ``neglected`` (a load
the rule dropped, its full-model value). ``mode`` is ``exact`` or ``drafted``;
``exact_value`` is the exact mode's value of the same quantity, ``error_pct`` the
relative drafting error (empty where the exact value is zero). ``bound`` is ± of a
drafted value for the reading precision (:mod:`graphplan.plans.conditioning`; an arm's is its own
reading, p/2), empty in exact mode; ``ill_conditioned`` the draftsman's mark of the
position (``lines meet at 1.3°, reading ±11 mm``), empty where its plans are well
conditioned."""


def _r(x: float | None) -> str:
    return csv_number(x, "a force table")


def forces_csv(analysis: Analysis, precision: float | None = 0.5) -> str:
    """Every reading of every force plan, exact and drafted, in one flat CSV.

    One row per reading (:data:`CSV_COLUMNS`), in SI units, dot decimals, full precision;
    exact rows first, then the drafted rows of the same position.
    """
    buf = io.StringIO()
    wr = csv.writer(buf, lineterminator="\n")
    wr.writerow(CSV_COLUMNS)
    for pf in force_readings(analysis, precision):
        kl = pf.kl.per_mm
        mark = pf.conditioning.note("en") if pf.conditioning is not None else ""
        for mode in ("exact", "drafted"):
            where = [pf.label, _r(pf.phi_deg), mode, _r(0.0 if mode == "exact" else pf.precision)]

            def bound(plan, name, mode=mode, pf=pf):
                return _r(pf.bound(plan, name)) if mode == "drafted" else ""

            for p, pe in zip(pf.plans(mode), pf.exact, strict=True):
                big = max((r.value for r in pe.readings.values()), default=0.0)
                for q, r in p.readings.items():
                    ex = pe.readings[q].value if q in pe.readings else None
                    err = None if ex is None else _rel(r.value, ex, big)
                    wr.writerow([*where, p.group, "segment", q, r.name, _r(r.mm),
                                 p.scale.symbol, _r(p.scale.per_mm), _r(r.value), "N", _r(ex),
                                 _r(None if err is None else err * 100), bound("force", q), mark])
                for key, mm in p.arms_mm.items():
                    ex = pe.arms_mm.get(key)
                    err = None if ex is None else _rel(mm, ex, 1.0)
                    wr.writerow([*where, p.group, "arm", key, "", _r(mm), "Kl", _r(kl),
                                 _r(mm * kl), "m", _r(None if ex is None else ex * kl),
                                 _r(None if err is None else err * 100),
                                 _r(pf.precision / 2 * kl) if mode == "drafted" else "", mark])
            crank = pf.plans(mode)[-1]
            me = _m_bal(pf.exact[-1])
            big = max(abs(me), abs(pf.lever_exact.M_bal), pf.M_scale)
            lev, lex = pf.lever(mode), pf.lever_exact
            for q, v, e, src in (("Mур", _m_bal(crank), me, "force"),
                                 ("Mур(Ж)", lev.M_bal, lex.M_bal, "lever")):
                err = _rel(v, e, big)
                wr.writerow([*where, crank.group, "moment", q, "", "", "", "", _r(v), "N·m",
                             _r(e), _r(None if err is None else err * 100), bound(src, "Mур"),
                             mark])
            wr.writerow([*where, "", "moment", "Mур(full)", "", "", "", "", _r(pf.M_full),
                         "N·m", _r(pf.M_full), "", "", mark])
            wr.writerow([*where, "lever", "discrepancy", "Δ", "", "", "", "",
                         _r(lev.discrepancy_pct or 0.0), "%", _r(lex.discrepancy_pct or 0.0),
                         "", "", mark])
            for ld in pf.loads:
                if ld.neglected:
                    wr.writerow([*where, f"link {ld.link}", "neglected", ld.name, "", "", "", "",
                                 _r(ld.value), ld.unit, _r(ld.value), "", "", mark])
    return buf.getvalue()



__all__ = ["CSV_COLUMNS", "curve_markdown", "forces_csv", "forces_markdown"]
