"""Checking a drawing: the plans found on it, measured and judged like a calculation.

:func:`check_drawing` reads the drawing (:func:`~.read.read_drawing`), finds its plans by
their letters (:mod:`.plans`), lays each against graphplan's construction of its position
at the student's scale (:mod:`.measure`) and judges it:

1. **the whole plan** — another position's plan, a plan at another scale than the one
   written, a component left out (:func:`~.measure.fits`, :func:`~.measure.lay`);
2. **every segment** — the length between two lettered points, as a *figure* of the
   calculation checker (``pb = 42,19 мм`` at position 2): the same verdicts, tolerances
   and causes (:class:`graphplan.checking.checks.Checker`), each figure's place on the
   sheet as its "line";
3. **every direction** — the angle of each segment against the construction's
   (:func:`~.measure.directions`).

A finding that only follows from a whole-plan finding (every segment of a plan drawn at
another scale) says so (``follows_from``). The result is the checker's
:class:`~graphplan.checking.findings.Report` — the same text, HTML and JSON reports — with
the overlay of :mod:`.overlay`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from ..engine import Tolerances
from ..findings import FigureCheck, Finding, LineCheck, Report
from ..student import Line, StudentPosition, StudentWork
from ..words import num
from .judged import Judged
from .measure import (
    Laid,
    construction,
    directions,
    fits,
    lay,
    misplaced_points,
    missing_components,
    segment_lengths,
)
from .plans import KINDS, FoundPlan, assign_scales, caption_kind, find_plans, stated_scales
from .primitives import Drawing, DrawingError
from .read import read_drawing
from .scene import Scene

PLAN_WORDS = {"velocity": ("velocity plan", "план скоростей"),
              "acceleration": ("acceleration plan", "план ускорений")}
POLE = {"velocity": "p", "acceleration": "π"}


@dataclass(slots=True)
class DrawingCheck:
    """A checked drawing: the report, the drawing, and the plans as judged."""

    report: Report
    drawing: Drawing
    scene: Scene
    plans: list[Judged]
    scales: dict[str, float]
    ref: object = None


def _say(lang: str, en: str, ru: str) -> str:
    return ru if lang == "ru" else en


def check_drawing(path: str | Path, variant: str | Path, tolerances: dict | None = None,
                  lang: str = "ru", student: str = "", group: str = "",
                  drawing: Drawing | None = None) -> DrawingCheck:
    """Check a student's drawing against graphplan's constructions of the variant.

    Raises
    ------
    DrawingError
        The drawing cannot be read, or no plan at all is found on it (the message says
        what was looked for).
    """
    from ..checks import Checker, reference_for

    path = Path(path)
    d = drawing or read_drawing(path)
    scene = Scene(d)
    found = find_plans(scene)
    sheet = assign_scales(found, stated_scales(d.texts))
    notes: list[str] = list(d.notes)
    if not d.texts and d.fills:  # letters as outlines are filled shapes, no text
        raise DrawingError(
            f"{path}: no letters can be read: the drawing holds no text ({len(d.segments)} "
            f"lines, {len(d.fills)} filled shapes); if its letters are drawn as outlines, "
            f"export it with the text kept as text")
    if not found and not any(t.text.strip() in ("h21",) or "сил" in t.text.lower() or
                             caption_kind(t.text) == "scheme" for t in d.texts):
        raise DrawingError(
            f"{path}: no plan found: no text 'p' (velocity) or 'π' (acceleration) near a "
            f"line end, no force named along a line ({len(d.segments)} lines, "
            f"{len(d.texts)} texts read)")
    for kind in ("velocity", "acceleration"):
        if found and not any(p.kind == kind for p in found):
            pole = POLE[kind]
            notes.append(_say(lang, f"no {kind} plan found: no text '{pole}' near a line end",
                              f"план {'скоростей' if kind == 'velocity' else 'ускорений'} не "
                              f"найден: нет надписи «{pole}» у конца линии"))
    ref = reference_for(Path(variant))
    tol = Tolerances.of(tolerances)
    judged = [_judge(p, ref, sheet, tol, lang) for p in found]
    from .forces import find_force_plans, find_h21
    from .judge_forces import judge_arm, judge_force_plan

    judged += [judge_force_plan(fp, ref, tol, lang) for fp in find_force_plans(scene)]
    judged += [judge_arm(a, ref, sheet, lang) for a in find_h21(scene)]
    from .positions import find_schemes, judge_scheme

    judged += [judge_scheme(s, ref, tol, lang) for s in find_schemes(scene, ref)]
    from .position_plan import find_position_plans, judge_position_plan

    judged += [judge_position_plan(pp, scene, ref, tol, lang)
               for pp in find_position_plans(scene, ref)]
    order = {"velocity": 0, "acceleration": 1, "force": 2, "arm": 3, "scheme": 4,
             "positions": 5}
    judged.sort(key=lambda j: (ref.index(j.position) if j.position in ref.labels else 99,
                               order.get(j.found.kind, 4)))
    # one plan of each kind per position: a second one is reported and left out
    seen: dict[tuple[str, str, tuple[str, ...]], Judged] = {}
    for j in judged:
        if j.position is None:
            continue
        k = (j.found.kind, j.position, tuple(sorted(j.figures)))
        if k in seen and j.found.kind in PLAN_WORDS:
            notes.append(_say(lang, f"a second {j.found.kind} plan of position {j.position} "
                              f"({j.found.where}) is not checked",
                              f"второй {PLAN_WORDS[j.found.kind][1]} положения {j.position} "
                              f"({j.found.where_ru}) не проверяется"))
            j.figures = {}
            continue
        seen[k] = j
    # the figures of every plan, checked by the calculation checker
    scales = {s: v for s, v in sheet.items()}
    for j in judged:
        sym = KINDS.get(j.found.kind)
        if sym and j.scale and sym not in scales:
            scales[sym] = j.scale
    groups: dict[tuple, list[Judged]] = {}
    for j in judged:
        if j.figures:
            sc = dict(scales)
            if j.found.kind in KINDS:
                sym = KINDS[j.found.kind]
                sc[sym] = j.scale or scales.get(sym, 0.0)
            sc.update(j.scales)
            groups.setdefault(tuple(sorted(sc.items())), []).append(j)
    findings: list[Finding] = []
    figures: list[FigureCheck] = []
    lines: list[LineCheck] = []
    for sc_items, js in groups.items():
        sc = dict(sc_items)
        work = _work(path, Path(variant), sc, js, lang, student, group)
        checker = Checker(work, ref, tol, (), lang)
        rep = checker.run()
        by_key = {j.key: j for j in js}
        for f in rep.findings:
            hit = next((jj for key, jj in by_key.items() if key and key in f.where), None)
            if hit is not None and f.quantity in hit.causes and not f.follows_from:
                f = replace(f, follows_from=(hit.causes[f.quantity],))
            findings.append(f)
        figures += list(rep.figures)
        lines += list(rep.lines)
    for j in judged:
        findings = list(j.findings) + findings
    findings = _order(findings, judged)
    report = Report(
        source=str(path), variant=str(variant), student=student,
        title=_say(lang, "Drawing", "Чертёж"), lang=lang, tolerances=tol.as_dict(),
        findings=tuple(findings), figures=tuple(figures), lines=tuple(lines),
        positions=tuple(_positions(ref, judged)), group=group, notes=tuple(notes))
    return DrawingCheck(report, d, scene, judged, scales, ref)


def _order(findings: list[Finding], judged: list[Judged]) -> list[Finding]:
    order = {j.key: i for i, j in enumerate(judged)}

    def rank(f: Finding):
        i = next((v for k, v in order.items() if k and k in f.where), 10**6)
        return (i, not f.primary)

    return sorted(findings, key=rank)


def _positions(ref, judged):
    seen = []
    for j in judged:
        if j.position and j.position not in seen:
            seen.append(j.position)
    for lab in seen:
        k = ref.index(lab)
        if k is not None:
            yield lab, float(np.degrees(ref.kin.phi[k]) % 360.0)


def _work(path: Path, variant: Path, scales: dict[str, float], js: list[Judged], lang: str,
          student: str, group: str) -> StudentWork:
    """The figures measured on the drawing as a student's work (one figure a segment)."""
    units = {"Kl": "м/мм", "Kv": "(м/с)/мм", "Ka": "(м/с²)/мм"}
    general = tuple(Line(f"{s} = {v!r} {units[s]}", "general", f"sheet: {s}")
                    for s, v in scales.items() if s in units and v)
    by_pos: dict[str, list[Line]] = {}
    if scales.get("Kp"):  # a scale of each position's force plans
        for j in js:
            if j.position and j.position not in by_pos:
                by_pos[j.position] = [Line(f"Kp = {scales['Kp']!r} Н/мм", j.position,
                                           f"sheet: Kp ({j.position})")]
    for j in js:
        for name, mm in j.figures.items():
            by_pos.setdefault(j.position, []).append(  # type: ignore[arg-type]
                Line(f"{name} = {mm:.3f} мм", j.position or "", j.key))
    positions = tuple(StudentPosition(lab, tuple(lns)) for lab, lns in by_pos.items())
    return StudentWork(source=path, variant=variant, general=general, positions=positions,
                       student=student, group=group, lang=lang)


def _judge(p: FoundPlan, ref, sheet: dict[str, float], tol: Tolerances, lang: str) -> Judged:
    sym = KINDS[p.kind]
    scale, source = (p.scale.value, "plan") if p.scale else (sheet.get(sym), "sheet")
    words_en, words_ru = PLAN_WORDS[p.kind]
    labels = list(ref.labels)
    sc = dict(sheet)
    if scale is None:
        # no scale written: the one the plan is drawn at, from the crank pin's segment
        base = {**sheet, sym: 0.01 if sym == "Kv" else 0.05}
        k0 = ref.index(p.position) if p.position in labels else 0
        probe = lay(p, construction(ref, p.kind, k0, base), labels[k0], k0)
        pin = next((sg for sg in probe.segments if sg.start == POLE[p.kind]), None)
        inv = {c: s for s, c in probe.match.items()}
        if pin is not None and pin.end in inv and probe.ratio > 0:
            mm = float(np.hypot(*probe.measured[pin.end]))
            exact = float(np.hypot(*probe.plan.points[pin.end]))
            if mm > 1.0:
                scale, source = base[sym] * exact / mm, "inferred"
    if scale is None:
        j = Judged(p, None, "none")
        j.findings.append(_plan_finding(
            p, None, sym, "scale", None, None, "",
            f"{sym} is not written on the sheet and cannot be taken from the plan (no "
            f"segment from the pole to the crank pin): the {words_en} is not checked.",
            f"{sym} не указан на листе и не определяется по плану (нет отрезка от полюса до "
            f"конца кривошипа): {words_ru} не проверяется.", lang, verdict="inaccurate"))
        return j
    sc[sym] = scale
    j = Judged(p, scale, source)
    lays = {lab: lay(p, construction(ref, p.kind, k, sc), lab, k)
            for k, lab in enumerate(labels)}

    def ok(L: Laid, rms: float) -> bool:
        return fits(L, rms, tol.reading_mm, tol.segment)

    best = min(lays.values(), key=lambda L: L.rms)
    j.best = best
    cap = p.position if p.position in lays else None
    if p.position is not None and cap is None:
        # "пол. 2" for a variant that numbers it "(2)", or the reverse
        alt = p.position.strip("()")
        cap = next((lab for lab in labels if lab.strip("()") == alt), None)
    laid = lays[cap] if cap else best
    j.laid = laid
    where_en = f"{words_en} {p.where}"
    where_ru = f"{words_ru}, {p.where_ru}"
    j.key = where_ru if lang == "ru" else where_en
    if source == "inferred":
        j.findings.append(_plan_finding(
            p, laid.position, sym, "scale", scale, None, "",
            f"{sym} is not written at the {words_en}: it is taken from the plan, "
            f"{sym} = {num(scale)}.",
            f"{sym} у плана не указан: он взят по плану, {sym} = {num(scale, 'ru')}.", lang,
            verdict="ok", key=j.key))
    if cap is None and p.position is None:
        j.findings.append(_plan_finding(
            p, laid.position, sym, "label", None, None, "",
            f"the {words_en} has no caption naming its position: it is taken as position "
            f"{laid.position}, whose construction it fits best.",
            f"у плана нет подписи с номером положения: он отнесён к положению "
            f"{laid.position}, с построением которого совпадает лучше всего.", lang,
            verdict="ok", key=j.key))
    # 1. the whole plan
    if not ok(laid, laid.rms):
        other = [L for L in lays.values() if L.position != laid.position and ok(L, L.rms)]
        if other:
            o = min(other, key=lambda L: L.rms)
            phi = float(np.degrees(ref.kin.phi[o.index]) % 360.0)
            j.findings.append(_plan_finding(
                p, laid.position, sym, "other-variant", None, None, "",
                f"the {words_en} captioned position {laid.position} is the plan of position "
                f"{o.position} (φ = {num(phi)}°): its points lie within "
                f"{num(o.rms, 'en', 2)} mm of that construction, {num(laid.rms, 'en', 3)} mm "
                f"off the construction of position {laid.position}.",
                f"{words_ru} с подписью «положение {laid.position}» — это план положения "
                f"{o.position} (φ = {num(phi, 'ru')}°): его точки в пределах "
                f"{num(o.rms, 'ru', 2)} мм от построения того положения и в "
                f"{num(laid.rms, 'ru', 3)} мм от построения положения {laid.position}.",
                lang, key=j.key))
        elif ok(laid, laid.rms_scaled) and abs(laid.ratio - 1.0) > tol.segment and \
                laid.ratio > 0:
            drawn = scale / laid.ratio
            j.findings.append(_plan_finding(
                p, laid.position, sym, "scale", drawn, scale, _UNIT[sym],
                f"the {words_en} is drawn at {sym} = {num(drawn)}, not at the {sym} = "
                f"{num(scale)} written: every segment is ×{num(laid.ratio, 'en', 3)} of "
                f"graphplan's at {num(scale)}, and fits it within "
                f"{num(laid.rms_scaled, 'en', 2)} mm at {num(drawn)}.",
                f"{words_ru} построен в масштабе {sym} = {num(drawn, 'ru')}, а не в "
                f"указанном {sym} = {num(scale, 'ru')}: все отрезки ×"
                f"{num(laid.ratio, 'ru', 3)} от построения при {num(scale, 'ru')} и "
                f"совпадают с ним в пределах {num(laid.rms_scaled, 'ru', 2)} мм при "
                f"{num(drawn, 'ru')}.", lang, key=j.key))
    for sg in missing_components(laid, tol.reading_mm):
        length = float(np.hypot(*(laid.plan.points[sg.end] - laid.plan.points[sg.start])))
        what_en = {"normal": "normal", "coriolis": "Coriolis"}[sg.role]
        what_ru = {"normal": "нормальное", "coriolis": "кориолисово"}[sg.role]
        j.findings.append(_plan_finding(
            p, laid.position, sg.name, "missing", 0.0, length, "mm",
            f"the {what_en} component {sg.name} ({num(length, 'en', 3)} mm) is left out: no "
            f"point of the {words_en} is lettered {_letter_hint(sg.end)}.",
            f"{what_ru} ускорение {sg.name} ({num(length, 'ru', 3)} мм) не отложено: на "
            f"плане нет точки {_letter_hint(sg.end)}.", lang, key=j.key))
    if laid.unknown:
        j.findings.append(_plan_finding(
            p, laid.position, ", ".join(laid.unknown), "label", None, None, "",
            f"letters not known as points of the {words_en}: {', '.join(laid.unknown)}.",
            f"буквы, которых нет среди точек плана: {', '.join(laid.unknown)}.", lang,
            verdict="inaccurate", key=j.key))
    # 2. the segments (checked by the calculation checker), 3. every point where the
    # construction puts it (off its place by more than the segment tolerance of its vector
    # from the pole: a point built wrong) and 4. the segments' directions. A segment or a
    # direction wrong only because the whole plan is (another scale, another position, a
    # component left out) or because one of its ends is misplaced follows from that.
    j.figures = segment_lengths(laid, tol.reading_mm)
    whole = next((f.quantity for f in j.findings if f.verdict == "wrong"), None)
    inv = {c: s for s, c in laid.match.items()}
    point_cause: dict[str, str] = {}
    for pt in misplaced_points(laid, tol):
        name = inv.get(pt.name, pt.name)
        en = (f"the point {name} is {num(pt.error_mm, 'en', 3)} mm from where the construction "
              f"puts it (its vector from the pole, {num(pt.length_mm, 'en', 4)} mm, allows "
              f"{num(pt.band_mm, 'en', 2)} mm).")
        ru = (f"точка {name} в {num(pt.error_mm, 'ru', 3)} мм от места, где её даёт построение "
              f"(для вектора из полюса длиной {num(pt.length_mm, 'ru', 4)} мм допустимо "
              f"{num(pt.band_mm, 'ru', 2)} мм).")
        f = _plan_finding(p, laid.position, f"•{name}", "point", pt.error_mm, 0.0, "mm", en,
                          ru, lang, verdict=pt.verdict, key=j.key)
        if whole:
            f = replace(f, follows_from=(whole,))
        elif pt.verdict == "wrong":
            point_cause[pt.name] = f.quantity
        j.findings.append(f)
    for sg in laid.segments:
        cause = whole or point_cause.get(sg.end) or point_cause.get(sg.start)
        if cause:
            j.causes[sg.name] = cause
            j.causes[f"∠{sg.name}"] = cause
    for dr in directions(laid, tol.reading_mm):
        if dr.verdict == "ok":
            continue
        reversed_ = abs(abs(dr.error_deg) - 180.0) < 5.0
        en = (f"{dr.name} is drawn in the opposite sense" if reversed_ else
              f"{dr.name} is drawn at {num(dr.measured_deg, 'en', 4)}°, graphplan's at "
              f"{num(dr.expected_deg, 'en', 4)}° ({'+' if dr.error_deg > 0 else ''}"
              f"{num(dr.error_deg, 'en', 3)}°)") + "."
        ru = (f"{dr.name} направлен в обратную сторону" if reversed_ else
              f"{dr.name} проведён под углом {num(dr.measured_deg, 'ru', 4)}°, по построению "
              f"{num(dr.expected_deg, 'ru', 4)}° ({'+' if dr.error_deg > 0 else ''}"
              f"{num(dr.error_deg, 'ru', 3)}°)") + "."
        # stated: the angle off graphplan's direction (expected 0), degrees
        f = _plan_finding(p, laid.position, f"∠{dr.name}", "direction", dr.error_deg, 0.0,
                          "°", en, ru, lang, verdict=dr.verdict, key=j.key)
        if f.quantity in j.causes:
            f = replace(f, follows_from=(j.causes[f.quantity],))
        j.findings.append(f)
    return j


_UNIT = {"Kl": "m/mm", "Kv": "(m/s)/mm", "Ka": "(m/s²)/mm", "Kp": "N/mm"}


def _letter_hint(point: str) -> str:
    return point.replace("_", "")


def _plan_finding(p: FoundPlan, position: str | None, quantity: str, kind: str,
                  stated: float | None, expected: float | None, unit: str, en: str, ru: str,
                  lang: str, verdict: str = "wrong", key: str = "") -> Finding:
    pos_en = f"position {position}" if position else "position ?"
    pos_ru = f"положение {position}" if position else "положение ?"
    where = f"{pos_ru}, {key}" if lang == "ru" else f"{pos_en}, {key}"
    for x in (stated, expected):
        if x is not None and not math.isfinite(x):
            stated = expected = None
    return Finding(where=where, quantity=quantity, stated=stated, expected=expected,
                   unit=unit, kind=kind, verdict=verdict,
                   explanation=ru if lang == "ru" else en, position=position,
                   line=p.caption.text if p.caption else "", explanation_en=en,
                   explanation_ru=ru)


__all__ = ["DrawingCheck", "Judged", "check_drawing"]
