"""graphplan's own Markdown reports (``plans.*.md``, ``forces.*.md``, ``dynamics.*.md``) read
back into note blocks, so that the note shows the very tables and lines the reports do."""

from __future__ import annotations

import re

from ..numbers import note_comma
from .blocks import Block, Formula, Heading, Paragraph, Table

_POSITION = re.compile(r"^(?:Положение|Position)\s+(\S+?),")


def _cells(line: str) -> tuple[str, ...]:
    return tuple(c.strip().replace("`", "") for c in line.strip().strip("|").split("|"))


def markdown_blocks(md: str, lang: str, *, top: int = 2, caption: str = "") -> list[Block]:
    """Blocks of a report's Markdown: headings of level ≥ ``top`` (``top`` becomes level 2 of
    the note), bullet lines with a ``=`` as shown formulas, pipe tables as tables (captioned
    by the heading above them), other lines as paragraphs; the report's own title is dropped.
    """
    out: list[Block] = []
    last_heading = caption
    lines = md.splitlines()
    i = 0
    while i < len(lines):
        raw = lines[i].rstrip()
        i += 1
        if not raw.strip():
            continue
        if raw.startswith("#"):
            hashes = len(raw) - len(raw.lstrip("#"))
            text = note_comma(raw[hashes:].strip(), lang)
            if hashes < top:
                continue
            m = _POSITION.match(text)
            out.append(Heading(text, level=min(hashes - top + 2, 3),
                               position=m.group(1) if m else None))
            last_heading = text
            continue
        if raw.startswith("|"):
            block = [raw]
            while i < len(lines) and lines[i].startswith("|"):
                block.append(lines[i].rstrip())
                i += 1
            header = tuple(note_comma(c, lang) for c in _cells(block[0]))
            rows = tuple(tuple(note_comma(c, lang) for c in _cells(r)) for r in block[2:])
            out.append(Table(last_heading, header, rows))
            continue
        text = note_comma(raw.lstrip("- ").replace("`", ""), lang)
        if raw.startswith("- ") and " = " in text:
            out.append(Formula(text, checkable=False))
        else:
            out.append(Paragraph(text))
    return out
