"""Paper: the sheet formats (GOST 2.301), the frame's margins and the title block's size.

Millimetres, origin at the top-left corner of the sheet, x to the right and y down
(see :mod:`graphplan.drawing.items`). The base layer: the draftsman's decisions
(:mod:`graphplan.project`) and the dynamics' diagram sizes need the page, not the drawing.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from .errors import InputError

if TYPE_CHECKING:
    from shapely.geometry import Polygon

Pt = tuple[float, float]

#: Sheet formats, GOST 2.301, landscape: (width, height) in mm.
FORMATS: dict[str, tuple[float, float]] = {
    "A1": (841.0, 594.0),
    "A2": (594.0, 420.0),
    "A3": (420.0, 297.0),
}
MARGIN_LEFT = 20.0  #: binding margin, mm
MARGIN = 5.0  #: top, right and bottom margins, mm
TITLE_BLOCK_SIZE = (185.0, 55.0)  #: form 1, GOST 2.104
GRAPH26_SIZE = (70.0, 14.0)  #: designation turned 180°, top-left corner of the frame


@dataclass(frozen=True, slots=True)
class Rect:
    """Axis-parallel rectangle on paper, mm: x0 < x1, y0 < y1 (y down)."""

    x0: float
    y0: float
    x1: float
    y1: float

    @property
    def width(self) -> float:
        return self.x1 - self.x0

    @property
    def height(self) -> float:
        return self.y1 - self.y0

    def polygon(self) -> Polygon:
        from shapely.geometry import box  # shapely only where a footprint is asked for

        return box(self.x0, self.y0, self.x1, self.y1)


@dataclass(frozen=True, slots=True)
class Page:
    """A sheet format in landscape: ``Page("A1")`` is 841×594 mm.

    >>> Page("A1").frame
    Rect(x0=20.0, y0=5.0, x1=836.0, y1=589.0)
    >>> Page("A1").title_block_origin
    (651.0, 534.0)
    """

    format: str = "A1"

    def __post_init__(self) -> None:
        if self.format not in FORMATS:
            raise InputError(f"page format must be one of {sorted(FORMATS)} (got {self.format!r})")

    @property
    def width(self) -> float:
        return FORMATS[self.format][0]

    @property
    def height(self) -> float:
        return FORMATS[self.format][1]

    @property
    def trim(self) -> Rect:
        """The format itself (outer trim border, drawn thin)."""
        return Rect(0.0, 0.0, self.width, self.height)

    @property
    def frame(self) -> Rect:
        """Inner frame: 20 mm from the left edge, 5 mm from the others (main line)."""
        return Rect(MARGIN_LEFT, MARGIN, self.width - MARGIN, self.height - MARGIN)

    @property
    def title_block_origin(self) -> Pt:
        """Top-left corner of the 185×55 title block, which sits in the frame's bottom-right."""
        f = self.frame
        return (f.x1 - TITLE_BLOCK_SIZE[0], f.y1 - TITLE_BLOCK_SIZE[1])

    @property
    def title_block_rect(self) -> Rect:
        x, y = self.title_block_origin
        return Rect(x, y, x + TITLE_BLOCK_SIZE[0], y + TITLE_BLOCK_SIZE[1])

    @property
    def graph26_rect(self) -> Rect:
        """Graph 26: 70×14 box in the top-left corner of the frame."""
        f = self.frame
        return Rect(f.x0, f.y0, f.x0 + GRAPH26_SIZE[0], f.y0 + GRAPH26_SIZE[1])

    @property
    def drawing_area(self) -> Polygon:
        """The frame without the title block and graph 26: where plans may go."""
        return self.frame.polygon().difference(self.title_block_rect.polygon()).difference(
            self.graph26_rect.polygon()
        )
