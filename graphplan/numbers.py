"""Numbers as graphplan writes them: one module, one named format for each kind of place.

Every number a user reads (a sheet's lettering, a table cell, a report line, a lesson's
caption, a CSV cell, a coordinate in an SVG file) is written by one of these functions.
They differ on purpose — a sheet letters what a student would write, a CSV keeps every
digit for scripts — and each says where it is used; a number never reaches a file as
NaN or infinity (:func:`finite`).

========================  ==================================  ==============================
format                    for                                 e.g.
========================  ==================================  ==============================
:func:`fmt`               sheets, tables, reports: up to N    ``0.4608``, ``1.2·10^-5``
                          significant digits, no trailing 0
:func:`plain`             the same, never a power of ten      ``364220``, ``0.00001234``
:func:`decimal_comma`     a sheet's text, every number        ``Kφ = 0,0218``
:func:`sheet_text`        the same on a Russian sheet only    ``0,4608`` (ru), ``0.4608``
:func:`note_comma`        the note's text: numbers standing   ``0,021817``; ``ТММ.01.5`` kept
                          alone only
:func:`fixed`             cells and lengths with a fixed      ``12.30``, never ``-0.00``
                          number of decimals
:func:`signed`            a difference in %: a sign always,  ``+1.67``, ``0.00``, never
                          none on a zero                      ``-0.00``
:func:`figures`           lessons: N significant figures,     ``0.4600``
                          trailing zeros kept
:func:`cell`              the summary table of sheet 1: 3–4   ``1.234e+05`` … ``0.0123``
                          significant digits in 9 characters
:func:`report`            the checker's reports: N            ``4456,1`` (ru), ``—`` for None
                          significant digits, comma in ru
:func:`written`           an answer key written as a student  ``4456,1``, ``12,30``
                          writes it (always the comma)
:func:`rough`             an accuracy: 2 significant digits   ``11``, ``1.3``, ``0.52``, ``∞``
:func:`general`           error messages: Python's ``g``      ``1e-07``
:func:`csv_number`        CSV cells: repr precision, a dot    ``0.46083333333333337``
:func:`trimmed`           coordinates in an SVG file, in mm   ``12.3``, ``0``
========================  ==================================  ==============================
"""

from __future__ import annotations

import math
import re
from typing import SupportsFloat

_DECIMAL_POINT = re.compile(r"(?<=\d)\.(?=\d)")
_NUMBER_POINT = re.compile(r"(?<![\w.])(-?\d+)\.(\d+)")


def finite(x: float, where: str) -> float:
    """``x`` as a float, or ValueError: no NaN or infinity may reach ``where`` (a table, a
    report)."""
    x = float(x)
    if not math.isfinite(x):
        raise ValueError(f"a non-finite number ({x!r}) reached {where}")
    return x


def fmt(x: float, digits: int = 6) -> str:
    """A number as a student writes it: no trailing zeros, up to ``digits`` significant."""
    if x == 0:
        return "0"
    s = f"{x:.{digits}g}"
    if "e" in s:
        mant, exp = s.split("e")
        return f"{mant}·10^{int(exp)}"
    return s


def plain(x: float, digits: int = 6, *, sign: bool = False) -> str:
    """``x`` to ``digits`` significant figures as a student writes it, never with an
    exponent: no trailing zeros (``0.4608``, ``364220``, ``0.00001234``); ``sign`` writes
    ``+`` before a positive number (as ``{x:+g}``). Values that are not finite: ``str(x)``.
    """
    x = float(x)
    if not math.isfinite(x):
        return str(x)
    lead = "+" if sign and x > 0 else ""
    if x == 0:
        return lead + "0"
    s = f"{x:.{digits}g}"
    if "e" in s:
        mag = math.floor(math.log10(abs(float(s))))
        dec = max(0, digits - 1 - mag)
        s = f"{float(s):.{dec}f}"
        if "." in s:
            s = s.rstrip("0").rstrip(".")
    return lead + s


def decimal_comma(text: str) -> str:
    """Numbers of ``text`` with the decimal comma Russian drawings use (GOST 2.304):
    ``"Kφ = 0.0218"`` → ``"Kφ = 0,0218"`` (only a point between two digits)."""
    return _DECIMAL_POINT.sub(",", text)


def note_comma(text: str, lang: str) -> str:
    """``0.021817`` → ``0,021817`` on a Russian note (a decimal point stays in English).

    Unlike :func:`decimal_comma` only a number standing alone: one that follows a letter,
    a digit or a point (a designation ``ТММ.01.5``, ``A1.5``) is kept.
    """
    return _NUMBER_POINT.sub(r"\1,\2", text) if lang == "ru" else text


def sheet_text(text: str, lang: str | None) -> str:
    """A sheet's text in ``lang``: :func:`decimal_comma` on a Russian sheet, as it is on an
    English one."""
    return decimal_comma(text) if lang == "ru" else text


def fixed(x: SupportsFloat, decimals: int = 2) -> str:
    """``decimals`` decimals, and no negative zero (``-0.00`` → ``0.00``)."""
    s = f"{float(x):.{decimals}f}"
    return s[1:] if re.fullmatch(r"-0\.?0*", s) else s


def signed(x: SupportsFloat, decimals: int = 2) -> str:
    """``decimals`` decimals with the sign written (``+1.67``, ``-0.40``), except on a value
    that rounds to zero (``0.00``: a difference of ``-0.001 %`` is no difference)."""
    s = fixed(x, decimals)
    return s if s.startswith("-") or not s.strip("0.") else "+" + s


def figures(x: float, sig: int = 4) -> str:
    """A value to ``sig`` significant figures (trailing zeros kept within 10⁻³ … 10⁶),
    never with an exponent (:func:`plain` outside that range)."""
    x = float(x)
    if x == 0 or not math.isfinite(x):
        return "0" if x == 0 else str(x)
    mag = math.floor(math.log10(abs(x)))
    if -3 <= mag < 6:
        dec = max(0, sig - 1 - mag)
        s = f"{x:.{dec}f}"
        return "0" if float(s) == 0 else s
    return plain(x, sig)


def cell(x: float, width: int = 9) -> str:
    """3–4 significant digits in at most ``width`` characters (a summary table's cell)."""
    if x == 0:
        return "0"
    for d in (4, 3, 2):
        s = f"{x:.{d}g}"
        if "e" not in s and len(s) <= width:
            return s
    s = f"{x:.0f}" if abs(x) >= 1 else f"{x:.1e}"
    return s if len(s) <= width else f"{x:.1e}"


def report(x: float | None, lang: str = "en", digits: int = 5) -> str:
    """A number with ``digits`` significant digits, no exponent for everyday sizes
    (10⁻⁴ … 10⁹), a decimal comma in Russian; ``—`` for None."""
    if x is None:
        return "—"
    if not math.isfinite(x):
        raise ValueError(f"a non-finite number ({x!r}) reached a report")
    if x == 0:
        return "0"
    mag = math.floor(math.log10(abs(x)))
    s = _significant(x, digits, mag) if -4 <= mag < 9 else f"{x:.{digits - 1}e}"
    if s in ("-0", "−0"):
        s = "0"
    return s.replace(".", ",") if lang == "ru" else s


def written(x: float, digits: int = 5, decimals: int | None = None) -> str:
    """A number as a student writes it in an answer: the decimal comma, ``digits``
    significant digits (or ``decimals`` decimals), never an exponent, no negative zero."""
    if decimals is not None:
        s = f"{x:.{decimals}f}"
    elif x == 0:
        s = "0"
    else:
        s = _significant(x, digits, math.floor(math.log10(abs(x))))
    if s.startswith("-") and float(s) == 0:
        s = s[1:]
    return s.replace(".", ",")


def _significant(x: float, digits: int, mag: int) -> str:
    """``x`` (of magnitude 10^``mag``) to ``digits`` significant digits, no trailing zeros."""
    s = f"{x:.{max(0, digits - 1 - mag)}f}"
    return s.rstrip("0").rstrip(".") if "." in s else s


def rough(x: float, digits: int = 2) -> str:
    """2 significant digits, at least one decimal below 10: ``11``, ``1.3``, ``0.52``;
    ``∞`` for no bound."""
    if not math.isfinite(x):
        return "∞"
    if x >= 10:
        return f"{x:.0f}"
    return f"{x:.{max(1, digits - 1 - math.floor(math.log10(x))) if x > 0 else 1}f}"


def general(x: float, digits: int = 6) -> str:
    """Python's general format (``1e-07``, ``0.333333``): numbers quoted in an error."""
    return f"{x:.{digits}g}"


def csv_number(x: float | None, where: str) -> str:
    """A number for scripts (a CSV cell): repr precision, a dot decimal, never ``-0.0``;
    empty for None."""
    return "" if x is None else repr(finite(x, where) + 0.0)  # + 0.0: no "-0.0"


def trimmed(v: float, decimals: int = 2) -> str:
    """A length in mm as written to a file: rounded to ``decimals``, no trailing zeros, no
    negative zero."""
    r = round(float(v), decimals)
    if r == 0:
        r = 0.0  # no "-0"
    return f"{r:.{decimals}f}".rstrip("0").rstrip(".")
