"""The moment equations written under each figure of sheet 2 (a group drawn separately, the
crank): their text, taken from the force plan's steps, and their lines wrapped to a cell's
width. The layout reserves their room (every line, never one dropped) before the sheet is
drawn; the sheet writes the same lines."""

from __future__ import annotations

import re

from ..fonts import lettering_width

EQ_H = 2.5  #: lettering of the equations written under the figures, mm
EQ_PITCH = 4.25  #: their line pitch (GOST 2.304: at least 1.7 h), mm

#: a unit stays on the line of its number («Mур = 119,109 Н·м» never leaves «Н·м» alone)
_UNIT_WORDS = frozenset({"Н", "Н·м", "кН", "кН·м", "мм", "м", "N", "N·m", "kN", "kN·m", "mm",
                         "m"})


def moment_lines(fp, lang: str) -> list[str]:
    """The moment equations of a group (of the crank) as written under its figure: the
    equation with the arms read on it, the numbers, the result («; Rτ12 = 86,9 Н»: the
    arrow «→» of the steps' text is not in osifont, and one such character set the whole
    line in upright DejaVu Sans beside the type-B lettering of the sheet)."""
    out = []
    for st in fp.steps:
        if not st.equation.startswith("ΣM"):
            continue
        text = (st.text_ru if lang == "ru" else st.text).split(" (")[0].rstrip(".")
        head, arrow, tail = text.partition(" → ")
        text = head + ("; " if arrow else "") + tail.split("; ")[0]
        text = re.sub(r"\(link ([^)]*)\)", r"(\1)", text).replace("_", "")
        out.append(text)
    return out


def _words(line: str) -> list[str]:
    """The words a line may break between: a unit joined to the number before it."""
    out: list[str] = []
    for word in line.split(" "):
        if out and word.rstrip(".,;)") in _UNIT_WORDS:
            out[-1] += " " + word
        else:
            out.append(word)
    return out


def wrapped_lines(lines: list[str], width: float) -> list[str]:
    """Lines broken at their spaces to ``width`` mm at EQ_H lettering (a unit kept with its
    number; a continued line indented)."""
    out = []
    for line in lines:
        cur = ""
        for word in _words(line):
            trial = f"{cur} {word}" if cur else word
            if cur and lettering_width(trial, EQ_H) > width:
                out.append(cur)
                cur = "  " + word
            else:
                cur = trial
        if cur.strip():
            out.append(cur)
    return out


#: the equations the layout sizes are read off force plans at a trial Kl: at the sheet's
#: Kl an arm's number may be a digit or two longer, so they are wrapped this much narrower
EQ_SLACK = 8.0


def equations_height(lines_by_lang, width: float) -> float:
    """Height (mm) the moment equations take under a figure ``width`` mm wide (the sheet
    wraps them to ``width`` − 4 mm): every line of the longer language, a 2 mm foot."""
    n = max((len(wrapped_lines(lines, width - 4.0 - EQ_SLACK)) for lines in lines_by_lang),
            default=0)
    return EQ_PITCH * n + 2.0 if n else 0.0
