"""The lesson of Zhukovsky's lever of one position
(:func:`graphplan.plans.zhukovsky.zhukovsky_lever`).

Steps as the construction orders them: the velocity plan turned by 90°, each couple
replaced by two forces, each force applied at the image of its point with its arm
``h`` about the pole (the caption converts the arm into the force's moment about p,
``M_p = F·h``, N·mm of the lever), and the balancing force ``F_ур = |Σ M_p|/pa`` with
``M_ур(Ж) = F_ур·l_OA``, compared with the force plans' Mур. The lever is drawn at the
Kv of sheet 2's lever (:meth:`graphplan.project.scales.Sheet2Scales.lever_kv`), so its arms are
the sheet's and the tables'; the force arrows are at the display scale Kp (nothing is
read at it).
"""

from __future__ import annotations

import numpy as np

from ..plans import Lever
from .captions import WORDS, num, unit
from .model import Lesson, LessonStep, Mark, Panel, Result, Term


def lever_lesson(analysis, k: int) -> Lesson:
    """Zhukovsky's lever of position k as a lesson (module docstring)."""
    mech, kin = analysis.mech, analysis.kin
    kl = analysis.sheet2.kl
    lever = analysis.lever(k)  # sheet 2's own lever of position k
    label = kin.labels[k]
    panel = Panel("lever", {lang: f"{WORDS[lang]['zhukovsky']}, {WORDS[lang]['position']} "
                                  f"{label}" for lang in ("ru", "en")},
                  f"{lever.plan.scale.basis}; {lever.kf.basis}")
    steps = []
    forces_by_name = {f.name: f for f in lever.forces}
    labelled: set[str] = set()
    for s in lever.steps:
        marks, results, terms, notes = [], [], [], []
        for e in s.elements:
            role = e.role
            text = e.name if role == "force" else ""
            marks.append(Mark("vector", e.name, (e.start, e.end), role, text=text,
                              dashed=role == "arm"))
        for n, xy in lever.points.items():
            if n in labelled:
                continue
            if any(np.allclose(xy, e.end) for e in s.elements if e.role in ("absolute", "force")):
                labelled.add(n)
                marks.append(Mark("label", n, ((float(xy[0]), float(xy[1])),), "label", text=n))
        if s.number == 1:
            kind = "turn"
            labelled.add("p")
            marks.append(Mark("label", "p", ((0.0, 0.0),), "label", text="p"))
            pa = next(iter(lever.readings.values()))
            results.append(Result(pa.name, pa.quantity, pa.mm, pa.value, pa.unit, pa.scale,
                                  lever.plan.scale.per_mm))
        elif s.readings:
            kind = "force"
            rd = lever.readings[s.readings[0]]
            name = rd.name[2:]
            f = forces_by_name[name]
            terms = [Term(name, "✓", f"{num(f.magnitude)} N"), Term(rd.name, "⟂", None)]
            results.append(Result(rd.name, f"M_p({name})", rd.mm, f.magnitude * rd.mm, "N·mm",
                                  name, f.magnitude))
        elif s.elements:
            kind = "balance"
            terms = [Term("F_ур", f"⟂ p{mech.crank.pin.lower()}'", None)]
            notes = _balance_notes(lever)
        else:
            kind = "couple_pair"
        steps.append(LessonStep(s.number, 0, kind, s.equation, {"en": s.text, "ru": s.text_ru},
                                tuple(terms), tuple(results), tuple(marks), tuple(notes)))
    title = {lang: f"{WORDS[lang]['zhukovsky']} — {mech.name}, {WORDS[lang]['position']} "
                   f"{label}" for lang in ("ru", "en")}
    return Lesson("zhukovsky", mech.name, mech.source, label, title, (panel,), tuple(steps),
                  (kl.basis, lever.plan.scale.basis, lever.kf.basis))


def _balance_notes(lever: Lever) -> list[dict[str, str]]:
    notes = []
    if lever.reference is not None and lever.discrepancy_pct is not None:
        for_ru = (f"Mур по планам сил = {num(lever.reference, 5)} {unit('N·m', 'ru')}; "
                  f"Mур(Ж) = {num(lever.M_bal, 5)} {unit('N·m', 'ru')}; "
                  f"Δ = {lever.discrepancy_pct:.2f} %")
        for_en = (f"Mур from the force plans = {num(lever.reference, 5)} N·m; "
                  f"Mур(Ж) = {num(lever.M_bal, 5)} N·m; Δ = {lever.discrepancy_pct:.2f} %")
        notes.append({"ru": for_ru, "en": for_en})
    return notes


__all__ = ["lever_lesson"]
