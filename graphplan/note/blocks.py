"""The pieces of an explanatory note, independent of the file format that shows them."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Heading:
    """A numbered section heading (``level`` 1 = section, 2 = subsection, 3 = paragraph).

    ``position`` names the mechanism's position the heading opens (its label, as the
    variant numbers them), so the lines under it are read back as that position's.
    """

    text: str
    level: int = 1
    position: str | None = None
    numbered: bool = True


@dataclass(frozen=True, slots=True)
class Paragraph:
    """Plain text of the note."""

    text: str


@dataclass(frozen=True, slots=True)
class Formula:
    """One line of the calculation, ``name = formula = numbers = result unit``.

    ``checkable`` lines are the ones ``graphplan check`` reads back from the note (the lines
    of the student file format, ``docs/check-format.md``); the others are shown only.
    """

    text: str
    checkable: bool = True


@dataclass(frozen=True, slots=True)
class Table:
    """A table with its caption (the caption is numbered when the note is written)."""

    caption: str
    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]


@dataclass(frozen=True, slots=True)
class Figure:
    """A picture (PNG bytes) with its caption and its width on the page, mm."""

    caption: str
    png: bytes
    width_mm: float


@dataclass(frozen=True, slots=True)
class Arm:
    """An arm the calculation names: ``name`` is the arm of ``force`` about point ``about``."""

    name: str
    force: str
    about: str


Block = Heading | Paragraph | Formula | Table | Figure | Arm


@dataclass(frozen=True, slots=True)
class Note:
    """The whole note: the title page's data and the blocks of the text in order.

    ``variant`` is the variant file as the note names it (relative to where the note is
    written), ``lang`` the language ("ru" or "en").
    """

    title: str
    designation: str
    organisation: str
    author: str
    checker: str
    variant: str
    lang: str
    blocks: tuple[Block, ...]

    @property
    def formulas(self) -> tuple[Formula, ...]:
        return tuple(b for b in self.blocks if isinstance(b, Formula))
