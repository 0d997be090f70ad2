"""The likely mistake behind an error in a file a student typed, said with its fix.

Two slips are common on a Russian keyboard: a decimal comma (``length = 0,08``: TOML needs
``0.08``) and a Cyrillic letter that looks like a Latin one in a point name (``О`` for ``O``,
``А`` for ``A``, ``С`` for ``C``…). The readers of variant and student files add these
hints to their one-line errors.
"""

from __future__ import annotations

import re

#: Cyrillic letters that look like Latin ones, and the Latin letter meant
LOOKALIKES = dict(zip("АВЕКМНОРСТХаеорсхуі", "ABEKMHOPCTXaeopcxyi", strict=True))
_AT_LINE = re.compile(r"at line (\d+)")
_AT_COLUMN = re.compile(r"column (\d+)")
_DECIMAL_COMMA = re.compile(r"(?<![\w.])([-+]?\d+),(\d+)")


def toml_hint(text: str, message: str) -> str:
    """A hint for a TOML syntax error (``message`` names the line and the column): a decimal
    comma next to where the reader stopped becomes "— a decimal comma: write 0.08
    (десятичная точка…)"; else ""."""
    m = _AT_LINE.search(message)
    lines = text.splitlines()
    if not m or not 1 <= int(m.group(1)) <= len(lines):
        return ""
    line = lines[int(m.group(1)) - 1]
    col = _AT_COLUMN.search(message)
    column = int(col.group(1)) if col else len(line)
    for c in _DECIMAL_COMMA.finditer(line):
        comma = c.start(2)  # 1-based column of the comma
        inside_text = line[:comma].count('"') % 2 == 1 or line[:comma].count("'") % 2 == 1
        if "#" in line[:comma] or inside_text or not comma <= column <= c.end() + 2:
            continue
        return (f" — a decimal comma: write {c.group(1)}.{c.group(2)} with a point "
                f"(десятичная точка, а не запятая)")
    return ""


def lookalike_hint(name: str) -> str:
    """" — 'О' is a Cyrillic letter: write 'O3'" when ``name`` has Cyrillic look-alikes."""
    if not any(ch in LOOKALIKES for ch in name):
        return ""
    latin = "".join(LOOKALIKES.get(ch, ch) for ch in name)
    found = list(dict.fromkeys(ch for ch in name if ch in LOOKALIKES))
    letters = ", ".join(f"'{ch}'" for ch in found)
    what = "is a Cyrillic letter" if len(found) == 1 else "are Cyrillic letters"
    return f" — {letters} {what}: write {latin!r} in Latin letters (латинскими буквами)"
