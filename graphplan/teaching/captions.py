"""The words and numbers of the captions, in Russian and English.

Numbers are written as a student writes them: lengths on the drawing to 0.01 mm, values
to four significant figures (``423918 N``, ``0.4219 m/s``), a scale with up to six
figures (:func:`graphplan.numbers.plain`) — never with an exponent, which a student does not
write in a calculation (``18260000 N·mm``, not ``1.826·10^7``).
"""

from __future__ import annotations

import re

from ..model import russian_kind
from ..numbers import figures as num  # a lesson's values: 4 significant figures
from ..numbers import fixed as mm  # a length on the drawing, to 0.01 mm
from ..numbers import plain
from ..plans import ZERO_MM
from ..units import UNITS_RU, unit_text
from .model import Result

WORDS = {
    "en": {
        "velocity": "Velocity plan", "acceleration": "Acceleration plan",
        "forces": "Force plans", "zhukovsky": "Zhukovsky's lever", "flywheel": "Flywheel",
        "position": "position", "step": "Step", "of": "of", "prev": "Previous", "next": "Next",
        "try": "Try it yourself", "print": "All steps / print", "check": "Check",
        "vector": "Vector", "direction": "Direction", "magnitude": "Magnitude",
        "unknown": "?", "known": "known", "drawn": "drawn", "yours": "your reading",
        "correct": "correct", "deviation": "deviation", "scales": "Scales",
        "enter": "enter the length in mm", "keys": "Keys: ← → (or PgUp/PgDn, Space) step, "
        "Home/End, T try it yourself, P all steps",
        "try_hint": "Try it yourself: each result is hidden until you enter your reading "
        "(measure on the print-out, where the drawing is at its true size, or compute it); "
        "then the correct value and your deviation are shown.",
        "scale_bar": "10 mm",
        "no_script": "Without scripts the page shows every step one after another.",
        "units": "Units: SI; lengths on the drawing in mm; angles CCW positive.",
    },
    "ru": {
        "velocity": "План скоростей", "acceleration": "План ускорений",
        "forces": "Планы сил", "zhukovsky": "Рычаг Жуковского", "flywheel": "Маховик",
        "position": "положение", "step": "Шаг", "of": "из", "prev": "Назад", "next": "Далее",
        "try": "Проверь себя", "print": "Все шаги / печать", "check": "Проверить",
        "vector": "Вектор", "direction": "Направление", "magnitude": "Величина",
        "unknown": "?", "known": "известен", "drawn": "построен", "yours": "ваш отсчёт",
        "correct": "верно", "deviation": "отклонение", "scales": "Масштабы",
        "enter": "введите длину в мм", "keys": "Клавиши: ← → (или PgUp/PgDn, пробел) — шаг, "
        "Home/End, T — проверь себя, P — все шаги",
        "try_hint": "Проверь себя: результат шага скрыт, пока вы не введёте свой отсчёт "
        "(измерьте на распечатке, где чертёж в натуральную величину, или вычислите); "
        "затем показаны верное значение и ваше отклонение.",
        "scale_bar": "10 мм",
        "no_script": "Без сценариев страница показывает все шаги подряд.",
        "units": "Единицы СИ; длины на чертеже в мм; углы против часовой стрелки — плюс.",
    },
}

KIND_TITLES = {
    "en": {
        "pole": "The pole", "lay": "Lay off a known vector", "intersect": "Draw the two lines "
        "of the equation", "read": "Measure the result", "similar": "Theorem of similarity",
        "point": "A coincident point", "moment": "Equation of moments",
        "projection": "Projection on the slot", "couple":
        "Point of application", "turn": "Turn the velocity plan", "force": "Apply a force",
        "balance": "Balancing force", "couple_pair": "A couple as two forces",
        "diagram": "Diagram", "integrate": "Graphical integration", "tangent": "Tangent",
        "result": "Result", "size": "Dimensions",
    },
    "ru": {
        "pole": "Полюс", "lay": "Откладываем известный вектор", "intersect": "Проводим две "
        "линии уравнения", "read": "Измеряем результат", "similar": "Теорема подобия",
        "point": "Совпадающая точка", "moment": "Уравнение моментов",
        "projection": "Уравнение проекций на направление кулисы", "couple":
        "Точка приложения", "turn": "Поворачиваем план скоростей", "force": "Прикладываем силу",
        "balance": "Уравновешивающая сила", "couple_pair": "Момент — пара сил",
        "diagram": "Диаграмма", "integrate": "Графическое интегрирование",
        "tangent": "Касательная", "result": "Результат", "size": "Размеры",
    },
}


_RU_PHRASES = (
    (" through ", " через "), ("∥ guide of ", "∥ направляющей звена "),
    ("⟂ guide of ", "⟂ направляющей звена "), ("∥ guide", "∥ направляющей"),
    ("⟂ guide", "⟂ направляющей"), ("∥ slot", "∥ кулисе"), ("⟂ slot", "⟂ кулисе"),
    (": similarity on link ", ": подобие, звено "), ("(link ", "(звено "),
)
#: The units of the scales, longest first (``(m/s)/mm`` before ``m/mm``).
_RU_UNITS = tuple(sorted(((en, ru) for en, ru in UNITS_RU.items() if en.endswith("/mm")),
                         key=lambda p: -len(p[0])))


def localise(text: str, lang: str) -> str:
    """The construction's words for ``lang``: the names of its lines and equations are
    English in both texts of a step (``⟂AB through a``, ``ΣM_B(link 2)``)."""
    if lang != "ru":
        return text
    for en, ru in _RU_PHRASES:
        text = text.replace(en, ru)
    return text


_POWER = re.compile(r"([-−]?\d+(?:\.\d+)?)·10\^(-?\d+)")


def scale_text(text: str, lang: str) -> str:
    """A scale as written on a sheet of ``lang``: ``Kv = 0.01 (м/с)/мм``; a value the
    scale's basis writes with a power of ten is written out (``1.3483·10^5`` → ``134830``:
    a lesson writes no exponent)."""
    text = _POWER.sub(lambda m: plain(float(m[1].replace("−", "-")) * 10.0 ** int(m[2]),
                                      max(1, len(m[1].replace(".", "").lstrip("-−0")))), text)
    if lang != "ru":
        return text
    for en, ru in _RU_UNITS:
        text = text.replace(en, ru)
    return re.sub(r"(\d) mm\b", r"\1 мм", text)  # a length on the drawing: H = 20.00 мм


_GROUP = re.compile(r"([RP]{3})\((\d+)-(\d+)\)")


def group_name(group: str, lang: str) -> str:
    """An Assur group as the textbook of ``lang`` names it: ``RRP(2-3)`` →
    «группа Ассура II класса 2-го порядка ВВП (звенья 2–3)» (В — вращательная пара,
    П — поступательная), "Assur group of class II, order 2, RRP (links 2–3)"."""
    m = _GROUP.fullmatch(group)
    if m is None:
        return group
    if lang == "ru":
        return f"группа Ассура II класса 2-го порядка {russian_kind(m[1])} (звенья {m[2]}–{m[3]})"
    return f"Assur group of class II, order 2, {m[1]} (links {m[2]}–{m[3]})"


def unit(u: str, lang: str) -> str:
    """A unit as lettered in ``lang``."""
    return unit_text(u, lang)


def shown(r: Result) -> float:
    """A result's value as written: 0 when its length is round-off (a dead centre)."""
    return 0.0 if abs(r.mm) < ZERO_MM else r.value


def result_text(r: Result, lang: str) -> str:
    """``pb = 42.19 mm → v_B = pb·Kv = 42.19·0.01 = 0.4219 m/s`` (or the laid-off form)."""
    u_mm, u = unit("mm", lang), unit(r.unit, lang)
    k = plain(r.per_mm)
    if abs(r.mm) < ZERO_MM:  # a dead centre: round-off, not a length
        r = Result(r.segment, r.quantity, 0.0, shown(r), r.unit, r.factor, r.per_mm, r.laid)
    if r.laid:
        return (f"{r.quantity} = {num(r.value)} {u} → {r.segment} = {r.quantity}/{r.factor} = "
                f"{num(r.value)}/{k} = {mm(r.mm)} {u_mm}")
    return (f"{r.segment} = {mm(r.mm)} {u_mm} → {r.quantity} = {r.segment}·{r.factor} = "
            f"{mm(r.mm)}·{k} = {num(r.value)} {u}")


__all__ = ["KIND_TITLES", "UNITS_RU", "WORDS", "ZERO_MM", "group_name", "localise", "mm",
           "num", "plain", "result_text", "scale_text", "shown", "unit"]
