"""«Проверь себя» beyond lengths: questions of direction and sense a ruler cannot answer.

From a step's own data (nothing is solved again):

* a derived ω or ε (a step's note ``ω3 = … , clockwise``): which way does the link turn?
* a normal acceleration ``aⁿ_BA = ω2²·l_BA``: which way does it point (from B toward A)?
* a Coriolis acceleration ``aᵏ_A3 = 2·ω3·v_AA3``: where does the vector laid point (the
  relative velocity turned by 90° in the sense of ω3 — for a slotted link's A3 that is
  v_A3A = −v_AA3, and turning v_AA3 itself is the tempting wrong answer)?

Each question is ``(prompt, options, correct)`` in one language; the options are put in
an order that depends on the step, so the right one is not always first.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from .model import LessonStep

SENSES = {"ru": ("по часовой стрелке", "против часовой стрелки"),
          "en": ("clockwise", "counter-clockwise")}


@dataclass(frozen=True, slots=True)
class Question:
    """A multiple-choice question of a step: ``options[correct]`` is the answer."""

    prompt: str
    options: tuple[str, ...]
    correct: int


def _ordered(step: LessonStep, right: str, wrong: list[str]) -> tuple[tuple[str, ...], int]:
    opts = [right, *wrong]
    shift = step.number % len(opts)
    opts = opts[shift:] + opts[:shift]
    return tuple(opts), opts.index(right)


def questions(step: LessonStep, lang: str) -> tuple[Question, ...]:
    """The direction and sense questions of ``step`` in ``lang`` (module docstring)."""
    out: list[Question] = []
    for note_en in (n["en"] for n in step.notes):
        m = re.match(r"([ωε])(\w+) = ", note_en)
        if not m or not note_en.endswith("clockwise"):
            continue
        sym, link = m[1], m[2]
        ccw = note_en.endswith("counter-clockwise")
        right, opposite = SENSES[lang][ccw], SENSES[lang][not ccw]
        if lang == "ru":
            what = ("направлена угловая скорость" if sym == "ω"
                    else "направлено угловое ускорение")
            prompt = f"Куда {what} {sym}{link} звена {link}?"
        else:
            what = "angular velocity" if sym == "ω" else "angular acceleration"
            prompt = f"Which way is the {what} {sym}{link} of link {link}?"
        opts, k = _ordered(step, right, [opposite])
        out.append(Question(prompt, opts, k))
    m = re.fullmatch(r"aⁿ_([A-Z][a-z]*\d*)([A-Z][a-z]*\d*) = ω\w+²·l_\w+", step.equation)
    if m:
        tip, base = m[1], m[2]
        if lang == "ru":
            prompt = f"Куда направлено нормальное ускорение aⁿ_{tip}{base}?"
            right, wrong = f"∥ {tip}{base}, от {tip} к {base}", [
                f"∥ {tip}{base}, от {base} к {tip}", f"⟂ {tip}{base}"]
        else:
            prompt = f"Which way does the normal acceleration aⁿ_{tip}{base} point?"
            right, wrong = f"∥ {tip}{base}, from {tip} toward {base}", [
                f"∥ {tip}{base}, from {base} toward {tip}", f"⟂ {tip}{base}"]
        opts, k = _ordered(step, right, wrong)
        out.append(Question(prompt, opts, k))
    m = re.fullmatch(r"aᵏ_\w+ = 2·ω(\w+)·(v_\w+)", step.equation)
    if m and f"ω{m[1]} = 0" not in step.text["en"]:
        link, rel = m[1], m[2]
        # a slotted link's aᵏ_A3 = 2·ω3·v_AA3 is laid along v_A3A = −v_AA3 turned: its
        # step says so («v_A3A = −v_AA3»); the tempting answer turns v_AA3 itself
        turned = f"−{rel}" if f"= −{rel}" in step.text["en"] else rel
        other = rel if turned != rel else None
        if lang == "ru":
            prompt = "Куда направлено ускорение Кориолиса, отложенное в этом шаге?"
            right = f"{turned}, повёрнутая на 90° в сторону вращения ω{link}"
            wrong = [f"{turned}, повёрнутая на 90° против вращения ω{link}", f"∥ {rel}"]
            if other:
                wrong[1] = f"{other}, повёрнутая на 90° в сторону вращения ω{link}"
        else:
            prompt = "Where does the Coriolis acceleration laid in this step point?"
            right = f"{turned} turned by 90° in the sense of ω{link}"
            wrong = [f"{turned} turned by 90° against ω{link}", f"∥ {rel}"]
            if other:
                wrong[1] = f"{other} turned by 90° in the sense of ω{link}"
        opts, k = _ordered(step, right, wrong)
        out.append(Question(prompt, opts, k))
    return tuple(out)


__all__ = ["Question", "questions"]
