"""Lessons of the velocity and acceleration plans, from the constructions' ordered steps.

Each :class:`graphplan.plans.constructions.Step` becomes one lesson step; its elements are
drawn as they are (segments as vectors, lines, points) and its readings become the
caption's results. The known and unknown parts of a dyad's equation are read off the
equation and the two lines that close it: the equation ``v_B = v_A + v_BA = v_B4 +
v_B3B4`` is drawn with the line ``⟂AB through a`` and the line ``∥ guide through p``,
so ``v_BA`` has the direction ⟂AB and an unknown magnitude, ``v_B3B4`` is ∥ guide,
every other term on the right is known (drawn before), and ``v_B`` is sought. In an
acceleration equation the unknown terms are the tangential and relative ones (``aτ``,
``aʳ``); the normal and Coriolis components were laid off before.

After a reading of a relative (tangential) segment the caption adds the angular
velocity (acceleration) of the link, ``ω2 = v_BA/l_AB``, with the sense the
construction found (:attr:`graphplan.plans.constructions.Plan.rates`, CCW positive).
"""

from __future__ import annotations

import re

import numpy as np

from ..plans import Plan, Step
from .captions import WORDS, ZERO_MM, num, shown, unit
from .model import Lesson, LessonStep, Mark, Panel, Result, Term

_POINT = re.compile(r"[A-Z][a-z]*\d*")


def plan_lesson(analysis, k: int, kind: str) -> Lesson:
    """The lesson of the velocity (``kind="velocity"``) or acceleration plan of position k.

    The plan is sheet 1's own (:meth:`graphplan.project.Project.velocity_plan`: its Kl, Kv, Ka,
    exact), so the lesson teaches the very plan the sheet draws.
    """
    mech, kin = analysis.mech, analysis.kin
    sc = analysis.sheet1
    plan = analysis.velocity_plan(k) if kind == "velocity" else analysis.acceleration_plan(k)
    label = kin.labels[k]
    scale = plan.scale
    panel = Panel(kind, {lang: f"{WORDS[lang][kind]}, {WORDS[lang]['position']} {label}"
                         for lang in ("ru", "en")}, scale.basis)
    steps = tuple(_step(mech, kin, k, plan, s) for s in plan.steps)
    title = {lang: f"{WORDS[lang][kind]} — {mech.name}, {WORDS[lang]['position']} {label}"
             for lang in ("ru", "en")}
    scales = (sc.kl.basis, sc.kv.basis) + ((sc.ka.basis,) if kind == "acceleration" else ())
    return Lesson(kind, mech.name, mech.source, label, title, (panel,), steps, scales)


# ------------------------------------------------------------------------ steps


def _kind(step: Step) -> str:
    roles = {e.role for e in step.elements}
    if not step.equation:
        return "pole"
    if any(e.kind == "line" for e in step.elements):
        return "intersect"
    if "similarity" in step.equation:
        return "similar" if step.readings else "point"
    if step.readings and (roles & {"normal", "coriolis"} or "ω1" in step.equation):
        return "lay"
    return "read" if step.readings else "point"


def _step(mech, kin, k: int, plan: Plan, step: Step) -> LessonStep:
    kind = _kind(step)
    marks = _marks(plan, step)
    results, notes, terms = [], [], []
    for name in step.readings:
        rd = plan.readings[name]
        results.append(Result(rd.name, rd.quantity, rd.mm, rd.value, rd.unit, rd.scale,
                              plan.scale.per_mm, laid=kind == "lay"))
    if kind == "intersect":
        terms = _equation_terms(mech, plan, step)
    elif kind == "lay":
        terms = [_laid_term(mech, plan, step, results[0])]
    elif kind == "read":
        for e in step.elements:
            if e.role in ("relative", "tangential"):
                note = _rate_note(mech, kin, k, plan, e.name)
            elif e.role == "absolute" and plan.kind == "velocity":
                note = _pivot_note(mech, kin, k, plan, e.name)
            else:
                note = None
            if note and note not in notes:
                notes.append(note)
        notes += _twin_notes(mech, plan, notes)
    return LessonStep(step.number, 0, kind, step.equation,
                      {"en": step.text, "ru": step.text_ru}, tuple(terms), tuple(results),
                      tuple(marks), tuple(notes))


def _marks(plan: Plan, step: Step) -> list[Mark]:
    """The step's elements as marks, plus the letters of the points it names first."""
    marks: list[Mark] = []
    for e in step.elements:
        if e.kind == "segment":
            marks.append(Mark("vector", e.name, (e.start, e.end), e.role))
        elif e.kind == "line":
            marks.append(Mark("line", e.name, (e.start, e.end), "line"))
        else:
            marks.append(Mark("point", e.name, (e.start,), "point"))
    for name in _named_points(plan, step):
        xy = plan.points[name]
        marks.append(Mark("label", name, ((float(xy[0]), float(xy[1])),), "label",
                          text=name.replace("_", "")))
    return marks


def _named_points(plan: Plan, step: Step) -> list[str]:
    """Plan points a step names for the first time: intersection points, segment ends.

    A segment ``ps2`` names ``p`` and ``s2`` (its name is the two letters), a laid
    component ``n_BA`` names its own end point.
    """
    seen = {n for s in plan.steps[: step.number - 1] for n in _step_points(plan, s)}
    out = []
    for n in _step_points(plan, step):
        if n not in seen and n not in out:
            out.append(n)
    return out


def _step_points(plan: Plan, step: Step) -> list[str]:
    names = []
    for e in step.elements:
        if e.kind == "point" and e.name in plan.points:
            names.append(e.name)
        elif e.kind == "segment":
            for xy, pick in ((e.start, str.startswith), (e.end, str.endswith)):
                at = [n for n, q in plan.points.items()
                      if abs(q[0] - xy[0]) < 1e-9 and abs(q[1] - xy[1]) < 1e-9]
                named = [n for n in at if n == e.name or pick(e.name, n)]
                if named:
                    names.append(max(named, key=len))
    return names


def _terms_of(side: str) -> list[str]:
    """The terms of one side of an equation, without their signs (``a_A + aᵏ_A3 − aʳ_AA3``
    → a_A, aᵏ_A3, aʳ_AA3: a term with a minus is the sheets' vector of the opposite sense)."""
    return [t.strip() for t in re.split(r"\s[+−]\s", side) if t.strip()]


def _is_unknown(term: str, kind: str) -> bool:
    """The terms whose magnitude an intersection finds: relative velocities; aτ and aʳ."""
    if kind == "velocity":
        sub = term.split("_", 1)[1] if "_" in term else ""
        return len(_POINT.findall(sub)) >= 2
    return term.startswith(("aτ", "aʳ"))


def _at_pole(mech, term: str) -> bool:
    """True for the absolute vector of a frame point (``v_O3``, ``v_B4`` with 4 the frame)."""
    sub = term.split("_", 1)[1] if "_" in term else ""
    pts = _POINT.findall(sub)
    if len(pts) != 1 or pts[0] != sub:
        return False
    m = re.fullmatch(r"([A-Z][a-z]*)(\d*)", sub)
    return sub in mech.frame_points or (m is not None and m.group(2) == mech.frame_link)


def _equation_terms(mech, plan: Plan, step: Step) -> list[Term]:
    """Known and unknown terms of an intersection step (module docstring)."""
    sides = [s.strip() for s in step.equation.split("=")]
    lines = [e.name.split(" through")[0].strip() for e in step.elements if e.kind == "line"]
    drawn = {rd.quantity: rd.name for rd in plan.readings.values()}
    terms = [Term(sides[0], None, None)]
    unknown = 0
    for side in sides[1:]:
        for t in _terms_of(side):
            if _is_unknown(t, plan.kind) and unknown < len(lines):
                terms.append(Term(t, lines[unknown], None))
                unknown += 1
            else:
                seg = drawn.get(t)
                known = "0" if _at_pole(mech, t) else f"= {seg}" if seg else "✓"
                terms.append(Term(t, known, known))
    return terms


def _laid_term(mech, plan: Plan, step: Step, r: Result) -> Term:
    """Direction and magnitude of a known vector laid off: ω1·l_OA, ω²·l, 2·ω·v_r."""
    q = step.equation.split(" =")[0].strip()
    expr = step.equation.split("=", 1)[1].strip() if "=" in step.equation else ""
    cr = mech.crank
    if plan.kind == "velocity":
        direction = f"⟂ {cr.pivot}{cr.pin}, ω1"
    elif q.startswith("aⁿ"):
        tip, base = _POINT.findall(q.split("_", 1)[1])[:2]
        direction = f"∥ {tip}{base}: {tip} → {base}"
    elif q.startswith("aᵏ"):  # aᵏ_X = 2·ω3·v_r: the relative velocity turned as ω3 turns
        m = re.search(r"2·ω(\w+)·(v_\w+)", step.equation)
        # a slotted link's aᵏ_A3 turns v_A3A = −v_AA3 (the sheets read v_AA3 on a3→a)
        rel = f"−{m[2]}" if m and f"= −{m[2]}" in step.text else m[2] if m else "v_r"
        direction = f"{rel} ↻ 90° ω{m[1]}" if m else "v_r ↻ 90°, ω"
    else:
        direction = f"∥ {cr.pin}{cr.pivot}: {cr.pin} → {cr.pivot}"
    return Term(q, direction, f"{expr} = {num(shown(r))} {r.unit}")


def _model_point(kin, name: str) -> tuple[str | None, str | None]:
    """Model point of a plan letter and the link its digit suffix names (``a3`` → A, 3)."""
    up = name.upper()
    if up in kin.pos.points:
        return up, None
    m = re.fullmatch(r"([A-Z][a-z]*)(\d+)", up)
    if m and m.group(1) in kin.pos.points:
        return m.group(1), m.group(2)
    return None, None


def _rate_note(mech, kin, k: int, plan: Plan, seg: str) -> dict[str, str] | None:
    """``ω2 = v_BA/l_AB = 0.3397/0.2 = 1.698 rad/s, clockwise`` for a relative segment."""
    rd = plan.readings.get(seg)
    if rd is None:
        return None
    if plan.kind == "velocity":
        letters = _split_plan_segment(plan, seg)
    else:
        m = re.fullmatch(r"τ_(.+)", seg)
        pts = _POINT.findall(m.group(1)) if m else []
        letters = [p.lower() for p in pts[:2]] if len(pts) >= 2 else None
    if not letters:
        return None
    (p1, h1), (p2, h2) = (_model_point(kin, n) for n in letters)
    if p1 is None or p2 is None:
        return None
    hint = h1 or h2
    links = [ln for ln in mech.moving_links
             if (hint is None or ln == hint) and p1 in mech.points_of(ln)
             and (p2 in mech.points_of(ln) or hint is not None)]
    if not links:  # a slotted link's coincident point: τ_AO3 is of link 3, pivoted at O3
        links = [ln for ln in mech.moving_links if ln != mech.crank.link and any(
            q in mech.frame_points and q in mech.points_of(ln) for q in (p1, p2))]
    if len(links) != 1 or links[0] not in plan.rates:
        return None
    link = links[0]
    length = float(np.hypot(*(kin.pos.points[p1][k] - kin.pos.points[p2][k])))
    if length <= 0:
        return None
    rate = plan.rates[link]
    sym = "ω" if plan.kind == "velocity" else "ε"
    u = "rad/s" if plan.kind == "velocity" else "rad/s²"
    if rd.mm < ZERO_MM:  # the link is at rest (a dead centre) at this instant
        return {lang: f"{sym}{link} = {rd.quantity}/l_{p1}{p2} = 0" for lang in ("ru", "en")}
    sense = {"en": "counter-clockwise" if rate > 0 else "clockwise",
             "ru": "против часовой стрелки" if rate > 0 else "по часовой стрелке"}
    return {lang: f"{sym}{link} = {rd.quantity}/l_{p1}{p2} = {num(rd.value)}/{num(length)} = "
                  f"{num(abs(rate))} {unit(u, lang)}, {sense[lang]}" for lang in ("ru", "en")}


def _rate_link(note_en: str) -> str:
    """The link of a rate note ``ω3 = …`` / ``ε3 = …`` (the notes are written so)."""
    m = re.match(r"[ωε](\w+) =", note_en)
    if m is None:
        raise ValueError(f"not a rate note: {note_en!r}")
    return m[1]


def _twin_notes(mech, plan: Plan, notes: list[dict[str, str]]) -> list[dict[str, str]]:
    """``ε2 = ε3 = 7.512 rad/s²`` for a link that slides along a derived one without turning
    relative to it (a block in a slot, a slider on a rocking guide): same ω, same ε."""
    out = []
    sym = "ω" if plan.kind == "velocity" else "ε"
    u = "rad/s" if plan.kind == "velocity" else "rad/s²"
    done = {_rate_link(n["en"]) for n in notes}
    for n in list(notes):
        link = _rate_link(n["en"])
        rate = plan.rates.get(link)
        for pair in plan.sliding:
            a_, _, b_ = pair.partition("/")
            other = b_ if a_ == link else a_ if b_ == link else None
            if (other is None or other in done or other == mech.frame_link
                    or other not in plan.rates or rate is None
                    or abs(plan.rates[other] - rate) > 1e-9 * max(1.0, abs(rate))):
                continue
            done.add(other)
            if abs(rate) < 1e-12:
                out.append({lang: f"{sym}{other} = {sym}{link} = 0" for lang in ("ru", "en")})
                continue
            sense = {"en": "counter-clockwise" if rate > 0 else "clockwise",
                     "ru": "против часовой стрелки" if rate > 0 else "по часовой стрелке"}
            out.append({lang: f"{sym}{other} = {sym}{link} = {num(abs(rate))} "
                               f"{unit(u, lang)}, {sense[lang]}" for lang in ("ru", "en")})
    return out


def _pivot_note(mech, kin, k: int, plan: Plan, seg: str) -> dict[str, str] | None:
    """``ω3 = v_A3/l_O3A = 0.3317/0.4258 = 0.779 rad/s`` for the absolute velocity of a point
    of a link turning about a frame point (a rocker, a slotted link: its point A3 coincides
    with the block's A), where no relative segment of the step gives that ω."""
    rd = plan.readings.get(seg)
    if rd is None or not seg.startswith("p"):
        return None
    point, hint = _model_point(kin, seg[1:])
    if point is None:
        return None
    if hint is None:  # a joint: the one link through it that turns about a frame point
        links = [ln for ln in mech.moving_links if ln != mech.crank.link
                 and point in mech.points_of(ln) and point not in mech.frame_points
                 and any(q in mech.frame_points for q in mech.points_of(ln))]
        if len(links) != 1:
            return None
        hint = links[0]
    if hint not in plan.rates or hint == mech.crank.link:
        return None
    pivots = [q for q in mech.points_of(hint) if q in mech.frame_points and q != point]
    if len(pivots) != 1:
        return None
    pivot = pivots[0]
    length = float(np.hypot(*(kin.pos.points[point][k] - kin.pos.points[pivot][k])))
    if length <= 0:
        return None
    rate = plan.rates[hint]
    q = rd.quantity
    if rd.mm < ZERO_MM:
        return {lang: f"ω{hint} = {q}/l_{pivot}{point} = 0" for lang in ("ru", "en")}
    sense = {"en": "counter-clockwise" if rate > 0 else "clockwise",
             "ru": "против часовой стрелки" if rate > 0 else "по часовой стрелке"}
    return {lang: f"ω{hint} = {q}/l_{pivot}{point} = {num(rd.value)}/{num(length)} = "
                  f"{num(abs(rate))} {unit('rad/s', lang)}, {sense[lang]}"
            for lang in ("ru", "en")}


def _split_plan_segment(plan: Plan, seg: str) -> list[str] | None:
    """The two plan points a velocity segment joins (``ab`` → a, b; ``ca3`` → c, a3)."""
    for n in sorted(plan.points, key=len, reverse=True):
        if seg.startswith(n) and seg[len(n):] in plan.points:
            return [n, seg[len(n):]]
    return None


__all__ = ["plan_lesson"]
