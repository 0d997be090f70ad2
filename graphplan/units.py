"""Scale factors of the plans (μ, written Kl, Kv, Ka, Kp on Russian sheets).

A scale factor is always the **physical value per millimetre of drawing**: a
segment of ``x`` mm on the velocity plan stands for ``x·Kv`` m/s. Worked
example: the press crank, l_OA = 0.08 m, drawn 80 mm long gives
``Kl = lOA/OA = 0.08/80 = 0.001 m/mm``.

Scales are chosen from the usual series 1, 2, 2.5, 4, 5 × 10^k (:data:`SERIES`), the
plans' Kv, Ka and Kp from the finer :data:`PLAN_SERIES`, as students choose them, so that
the largest vector just fits its place.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from .numbers import plain

UNITS_RU: dict[str, str] = {
    "mm": "мм", "m": "м", "m/s": "м/с", "m/s²": "м/с²", "N": "Н", "N·m": "Н·м", "N·mm": "Н·мм",
    "J": "Дж", "kg·m²": "кг·м²", "rad/s": "рад/с", "rad/s²": "рад/с²", "W": "Вт", "kg": "кг",
    "°": "°", "rpm": "об/мин", "(m/s)/mm": "(м/с)/мм", "(m/s²)/mm": "(м/с²)/мм", "m/mm": "м/мм",
    "N/mm": "Н/мм", "J/mm": "Дж/мм", "N·m/mm": "Н·м/мм", "rad/mm": "рад/мм",
    "kg·m²/mm": "кг·м²/мм",
}
"""SI units as lettered in Russian (the units of the scales are per mm of drawing)."""


def unit_text(unit: str, lang: str) -> str:
    """A unit as lettered in ``lang`` (``"ru"``: :data:`UNITS_RU`; otherwise as given)."""
    return UNITS_RU.get(unit, unit) if lang == "ru" else unit


SERIES = (1.0, 2.0, 2.5, 4.0, 5.0)
"""Mantissas of the usual scale factors."""

PLAN_SERIES = (1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)
"""Mantissas of the scales of the velocity and acceleration plans: round numbers a student
divides by (μv = 0,003 (м/с)/мм), close enough that a plan fills at least 3/4 of its place
(1.2 between 1 and 1.5: a shaper's plans at μv = 0,012 keep pa over 50 mm and the idle
stroke's fastest vector under VECTOR_HARD, where 0,01 and 0,015 give one or the other)."""


def nice_ceil(value: float, series: tuple[float, ...] = SERIES) -> float:
    """The smallest member of ``series`` × 10^k (default 1, 2, 2.5, 4, 5) that is ≥ ``value``."""
    if not value > 0 or not math.isfinite(value):
        raise ValueError(f"a scale needs a positive finite value (got {value!r})")
    k = math.floor(math.log10(value))
    for exp in (k, k + 1):
        for m in series:
            s = m * 10.0**exp
            if s >= value * (1 - 1e-12):
                return float(f"{s:.12g}")
    raise AssertionError("unreachable")  # pragma: no cover


_LETTER = "A-Za-zА-Яа-яЁёΑ-Ωα-ω"
#: A quantity's symbol and its index, written as a subscript on a drawing (GOST 2.304's
#: indices): vB, vBA, lO1A, h21, R12, ω1, S3, Mур, Aс, Pдв.тр, Jпр, JII, KM, Kφ, Kl. Capital
#: indices only after v, a, l, h, K, J (so a link "AB" stays as it is), Cyrillic ones after
#: M, A, P, J, F, n, and a single lower-case or Greek index only after K (the scales).
_SUBSCRIPT = re.compile(
    rf"(?<![{_LETTER}0-9])(?:"
    r"(?P<s1>[vahlKJs])(?P<i1>[A-Z][A-Z0-9]{0,3})"
    r"|(?P<s2>[MAPJFn])(?P<i2>[а-яё]+(?:\.[а-яё]+)?)"
    r"|(?P<s3>[RFGMmhωεφψSPTJnva])(?P<i3>[0-9]{1,3})"
    r"|(?P<s4>K)(?P<i4>[a-zφ])"
    rf")(?![{_LETTER}0-9])")


def subscript_runs(text: str) -> list[tuple[str, bool]]:
    """``text`` cut into runs, each ``(chars, is_subscript)``: the indices of the
    quantities' symbols (see ``_SUBSCRIPT``) as subscripts, the rest as written.

    >>> subscript_runs("vB = 0,5; Mур")
    [('v', False), ('B', True), (' = 0,5; M', False), ('ур', True)]
    """
    runs: list[tuple[str, bool]] = []
    at = 0
    for m in _SUBSCRIPT.finditer(text):
        sym = next(g for g in (m.group("s1"), m.group("s2"), m.group("s3"), m.group("s4")) if g)
        idx = next(g for g in (m.group("i1"), m.group("i2"), m.group("i3"), m.group("i4")) if g)
        runs.append((text[at:m.start()] + sym, False))
        runs.append((idx, True))
        at = m.end()
    runs.append((text[at:], False))
    return [r for r in runs if r[0]]


@dataclass(frozen=True, slots=True)
class Scale:
    """A scale factor: ``per_mm`` physical units per millimetre of the plan.

    Attributes
    ----------
    symbol : str
        ``"Kl"``, ``"Kv"``, ``"Ka"`` or ``"Kp"``.
    per_mm : float
        The factor μ (e.g. 0.001 for Kl in m/mm).
    unit : str
        Unit of ``per_mm`` (``"m/mm"``, ``"(m/s)/mm"``, ``"(m/s²)/mm"``, ``"N/mm"``).
    quantity : str
        What defined it, e.g. ``"lOA"``; with ``value`` and ``drawn_mm`` it is the
        basis ``Kl = lOA/OA = 0.08/80``.
    value : float
        Physical size of the defining quantity.
    drawn_mm : float
        Its length on the drawing.
    segment : str
        Name of the drawn segment (``"OA"``, ``"pa"``, ``"πa"``).
    """

    symbol: str
    per_mm: float
    unit: str
    quantity: str = ""
    value: float = 0.0
    drawn_mm: float = 0.0
    segment: str = ""

    def to_mm(self, value: float) -> float:
        """Drawing length (mm) of a physical value."""
        return value / self.per_mm

    def to_value(self, mm: float) -> float:
        """Physical value of a drawing length (mm)."""
        return mm * self.per_mm

    @property
    def basis(self) -> str:
        """How the scale is written on a sheet: ``Kl = lOA/OA = 0.08/80 = 0.001 m/mm``, its
        numbers as a draftsman writes them, never with a power of ten (:func:`plain`)."""
        if self.quantity and self.drawn_mm:
            return (f"{self.symbol} = {self.quantity}/{self.segment} = {plain(self.value, 5)}/"
                    f"{plain(self.drawn_mm, 5)} = {plain(self.per_mm)} {self.unit}")
        return f"{self.symbol} = {plain(self.per_mm)} {self.unit}"


def fit_scale(symbol: str, unit: str, largest: float, room_mm: float, *, quantity: str = "",
              defining: float = 0.0, segment: str = "", fixed: float | None = None,
              series: tuple[float, ...] = SERIES) -> Scale:
    """Choose a scale so that ``largest`` (physical) is at most ``room_mm`` long.

    Parameters
    ----------
    symbol, unit : str
        E.g. ``"Kv"``, ``"(m/s)/mm"``.
    largest : float
        The largest value the plan must hold.
    room_mm : float
        The length available for it.
    quantity, defining, segment
        The quantity the student draws first and divides by (``"vA"``, its value,
        ``"pa"``): recorded so the sheet can print the basis of the scale.
    fixed : float, optional
        A scale given in the variant file, used as is.
    series : tuple of float
        The mantissas to choose from (:data:`SERIES`, or :data:`PLAN_SERIES` for plans).
    """
    per_mm = fixed if fixed is not None else nice_ceil(max(largest, 1e-300) / room_mm, series)
    drawn = defining / per_mm if defining else 0.0
    return Scale(symbol, per_mm, unit, quantity, defining, drawn, segment)
