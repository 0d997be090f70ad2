"""Units as students write them after a result: ``Н``, ``кН``, ``Нм``, ``мм``, ``рад/с``,
``м/с²``, ``Н/мм``, ``(м/с)/мм`` … in Cyrillic or Latin letters.

A unit is a spelling, a *dimension* (a short SI name such as ``"N"`` or ``"m/s²"``) and
the factor that turns a number in that unit into SI (``кН`` → ``("N", 1000)``).
Lengths on paper are lengths too: ``мм`` is ``("m", 0.001)``; a quantity measured on a
plan keeps its value in millimetres (see :mod:`graphplan.checking.quantities`).

Cyrillic letters that look like Latin ones (``Н``/``H``, ``м``/``m``, ``К``/``K``, ``р``/``p``,
``с``/``c`` …) are *folded* to Latin before units and names are compared
(:func:`fold`), because students mix them freely (``420000 H`` with a Latin H).
"""

from __future__ import annotations

from dataclasses import dataclass

_HOMOGLYPHS = str.maketrans({
    "А": "A", "В": "B", "Е": "E", "К": "K", "М": "M", "Н": "H", "О": "O", "Р": "P",
    "С": "C", "Т": "T", "Х": "X", "а": "a", "е": "e", "к": "k", "м": "m", "о": "o",
    "р": "p", "с": "c", "у": "y", "х": "x", "ё": "e",
    "₀": "0", "₁": "1", "₂": "2", "₃": "3", "₄": "4", "₅": "5", "₆": "6", "₇": "7",
    "₈": "8", "₉": "9",
    "\u2219": "·", "\u22c5": "·", "*": "·", "×": "·",
})


def fold(text: str) -> str:
    """Text with Cyrillic look-alikes replaced by Latin letters, subscript digits by
    digits and every multiplication dot by ``·`` (for comparing names and units)."""
    return text.translate(_HOMOGLYPHS)


@dataclass(frozen=True, slots=True)
class Unit:
    """A unit as written: its spelling, dimension and factor to SI."""

    text: str
    dimension: str
    factor: float


# (spellings, dimension, factor). Spellings are folded and stripped of spaces for lookup.
_TABLE: tuple[tuple[tuple[str, ...], str, float], ...] = (
    (("Н", "N"), "N", 1.0),
    (("кН", "kN"), "N", 1e3),
    (("МН", "MN"), "N", 1e6),
    (("Нм", "Н·м", "N·m", "Nm", "Дж", "J"), "N·m", 1.0),
    (("кНм", "кН·м", "kN·m", "kNm", "кДж", "kJ"), "N·m", 1e3),
    (("м", "m"), "m", 1.0),
    (("мм", "mm"), "m", 1e-3),
    (("см", "cm"), "m", 1e-2),
    (("м/с", "m/s", "м·с-1", "м·с^-1"), "m/s", 1.0),
    (("м/с²", "м/с2", "м/с^2", "m/s²", "m/s2", "m/s^2", "м·с-2", "м·с^-2"), "m/s²", 1.0),
    (("рад/с", "rad/s", "1/с", "1/s", "с-1", "с^-1", "s-1", "s^-1"), "rad/s", 1.0),
    (("рад/с²", "рад/с2", "рад/с^2", "rad/s²", "rad/s2", "rad/s^2", "1/с²", "1/с2",
      "1/s²", "1/s2", "с-2", "с^-2", "s-2", "s^-2"), "rad/s²", 1.0),
    (("об/мин", "rpm", "мин-1", "мин^-1", "1/мин"), "rpm", 1.0),
    (("кг", "kg"), "kg", 1.0),
    (("т",), "kg", 1e3),
    (("кг·м²", "кг·м2", "кг·м^2", "kg·m²", "kg·m2", "kg·m^2"), "kg·m²", 1.0),
    (("м/мм", "m/mm"), "m/mm", 1.0),
    (("(м/с)/мм", "м/с/мм", "м/(с·мм)", "м·с-1/мм", "м·с^-1/мм", "(m/s)/mm", "m/s/mm",
      "m/(s·mm)"), "(m/s)/mm", 1.0),
    (("(м/с²)/мм", "(м/с2)/мм", "(м/с^2)/мм", "м/с²/мм", "м/с2/мм", "м/с^2/мм",
      "м/(с²·мм)", "м/(с2·мм)", "м/(с^2·мм)", "м·с-2/мм", "м·с^-2/мм", "(m/s²)/mm",
      "(m/s2)/mm", "(m/s^2)/mm", "m/s²/mm", "m/s2/mm", "m/(s²·mm)", "m/(s2·mm)"),
     "(m/s²)/mm", 1.0),
    (("Н/мм", "N/mm"), "N/mm", 1.0),
    (("кН/мм", "kN/mm"), "N/mm", 1e3),
    (("Нм/мм", "Н·м/мм", "N·m/mm"), "N·m/mm", 1.0),
    (("°", "град", "deg"), "deg", 1.0),
    (("рад", "rad"), "rad", 1.0),
    (("%",), "1", 0.01),
)


def _key(spelling: str) -> str:
    return "".join(fold(spelling).split())


UNITS: dict[str, Unit] = {}
for _spellings, _dim, _factor in _TABLE:
    for _s in _spellings:
        UNITS[_key(_s)] = Unit(_s, _dim, _factor)

_LONGEST_FIRST = sorted(UNITS, key=len, reverse=True)


def lookup(text: str) -> Unit | None:
    """The unit spelled ``text`` (spaces, look-alike letters and dots do not matter)."""
    u = UNITS.get(_key(text))
    return None if u is None else Unit(text.strip(), u.dimension, u.factor)


def split_unit(text: str) -> tuple[str, Unit | None]:
    """Split a trailing unit off ``text``: ``"15,85кНм"`` → ``("15,85", Unit(кНм))``.

    The unit must follow a digit, ``)``, ``]``, ``°``, ``²`` or ``³`` (spaces between do
    not matter), so that a name ending in a unit's letters is never cut.
    """
    body = text.rstrip()
    folded = fold(body)
    squeezed = []  # index map from squeezed (no spaces) folded text back to body
    for i, ch in enumerate(folded):
        if not ch.isspace():
            squeezed.append(i)
    flat = "".join(folded[i] for i in squeezed)
    for key in _LONGEST_FIRST:
        if not flat.endswith(key) or len(key) == len(flat):
            continue
        start = squeezed[len(flat) - len(key)]
        head = body[:start].rstrip()
        prev = head[-1:]
        if prev.isdigit() or (prev and prev in ")]°²³"):
            u = UNITS[key]
            return head, Unit(body[start:].strip(), u.dimension, u.factor)
    return body, None


__all__ = ["UNITS", "Unit", "fold", "lookup", "split_unit"]
