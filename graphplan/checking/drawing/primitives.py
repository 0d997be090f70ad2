"""What a drawing is made of, once read: segments, fills, circles and texts in sheet mm.

Every reader (:mod:`.dxf`, :mod:`.svg`, :mod:`.pdf`) turns a file into one
:class:`Drawing`: coordinates in **millimetres of paper, y up** (the DXF convention; SVG's
and PDF's own units and axes are converted once, in the reader). A curve (an arc, a
Bézier) becomes a chain of short segments marked ``curve``; a filled shape (a SOLID, a
HATCH, a filled SVG or PDF path) is a :class:`Fill` — the arrowheads of most drawings.

Untrusted files are bounded (:data:`MAX_BYTES`, :data:`MAX_ITEMS`, :data:`MAX_DEPTH`): a
file past a bound is refused with one line naming the file and the bound
(:class:`DrawingError`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import pairwise
from pathlib import Path

from ..errors import StudentFileError

MAX_BYTES = 64 * 1024 * 1024
"""Largest drawing file read (bytes)."""
MAX_ITEMS = 300_000
"""Most segments, fills and texts one drawing may give (after blocks are exploded)."""
MAX_DEPTH = 12
"""Deepest nesting of blocks, groups, nested SVGs or PDF forms followed."""


class DrawingError(StudentFileError):
    """A drawing cannot be read: not a DXF, SVG or PDF, damaged, or past a bound."""


@dataclass(frozen=True, slots=True)
class Segment:
    """A straight piece of a drawn line, mm (y up). ``curve``: a piece of an arc or curve."""

    x1: float
    y1: float
    x2: float
    y2: float
    colour: str = "#000000"
    width: float = 0.25
    layer: str = ""
    curve: bool = False

    @property
    def length(self) -> float:
        return math.hypot(self.x2 - self.x1, self.y2 - self.y1)


@dataclass(frozen=True, slots=True)
class Fill:
    """A filled outline (an arrowhead, a dot): its vertices, mm."""

    points: tuple[tuple[float, float], ...]
    colour: str = "#000000"
    layer: str = ""


@dataclass(frozen=True, slots=True)
class Circle:
    """A circle (a joint, a pivot), mm."""

    x: float
    y: float
    r: float
    colour: str = "#000000"
    layer: str = ""


@dataclass(frozen=True, slots=True)
class Text:
    """A text as placed: its string, the centre of its box, its capital height and angle
    (degrees, counter-clockwise), mm."""

    text: str
    x: float
    y: float
    height: float
    angle: float = 0.0
    colour: str = "#000000"
    layer: str = ""


@dataclass(frozen=True, slots=True)
class Drawing:
    """A whole drawing as read."""

    source: str
    format: str
    segments: tuple[Segment, ...]
    fills: tuple[Fill, ...] = ()
    circles: tuple[Circle, ...] = ()
    texts: tuple[Text, ...] = ()
    notes: tuple[str, ...] = ()
    size: tuple[float, float, float, float] = field(default=(0.0, 0.0, 0.0, 0.0))

    def bounds(self) -> tuple[float, float, float, float]:
        """(xmin, ymin, xmax, ymax) of everything drawn, mm."""
        xs = [c for s in self.segments for c in (s.x1, s.x2)]
        ys = [c for s in self.segments for c in (s.y1, s.y2)]
        xs += [t.x for t in self.texts]
        ys += [t.y for t in self.texts]
        if not xs:
            return (0.0, 0.0, 1.0, 1.0)
        return (min(xs), min(ys), max(xs), max(ys))


class Collector:
    """Gathers what a reader finds, counting against :data:`MAX_ITEMS`."""

    def __init__(self, source: str):
        self.source = source
        self.segments: list[Segment] = []
        self.fills: list[Fill] = []
        self.circles: list[Circle] = []
        self.texts: list[Text] = []
        self.notes: list[str] = []
        self.count = 0

    def _tick(self, n: int = 1) -> None:
        self.count += n
        if self.count > MAX_ITEMS:
            raise DrawingError(f"{self.source}: more than {MAX_ITEMS} drawn items (lines, "
                               "fills, texts): not read (a drawing of a project has far fewer)")

    def line(self, x1, y1, x2, y2, colour="#000000", width=0.25, layer="", curve=False):
        vals = (float(x1), float(y1), float(x2), float(y2))
        if not all(math.isfinite(v) for v in vals):
            return
        self._tick()
        self.segments.append(Segment(*vals, colour, float(width), layer, curve))

    def polyline(self, pts, closed=False, colour="#000000", width=0.25, layer="", curve=False):
        pts = list(pts)
        if closed and len(pts) > 2:
            pts.append(pts[0])
        for (a, b), (c, d) in pairwise(pts):
            if (a, b) != (c, d):
                self.line(a, b, c, d, colour, width, layer, curve)

    def fill(self, pts, colour="#000000", layer=""):
        pts = tuple((float(x), float(y)) for x, y in pts)
        if len(pts) < 3 or not all(math.isfinite(v) for p in pts for v in p):
            return
        self._tick()
        self.fills.append(Fill(pts, colour, layer))

    def circle(self, x, y, r, colour="#000000", layer=""):
        if not all(math.isfinite(float(v)) for v in (x, y, r)) or r <= 0:
            return
        self._tick()
        self.circles.append(Circle(float(x), float(y), float(r), colour, layer))

    def text(self, text, x, y, height, angle=0.0, colour="#000000", layer=""):
        text = " ".join(str(text).split())
        if not text or not all(math.isfinite(float(v)) for v in (x, y, height, angle)):
            return
        self._tick()
        self.texts.append(Text(text, float(x), float(y), abs(float(height)), float(angle),
                               colour, layer))

    def drawing(self, fmt: str, size=(0.0, 0.0, 0.0, 0.0)) -> Drawing:
        return Drawing(self.source, fmt, tuple(self.segments), tuple(self.fills),
                       tuple(self.circles), tuple(self.texts), tuple(self.notes), size)


def text_centre(x: float, y: float, height: float, angle: float, n_chars: float,
                h_frac: float, v_frac: float) -> tuple[float, float]:
    """Centre of a text's box from its anchor: ``h_frac`` is where along the width the
    anchor is (0 start, 0.5 middle, 1 end), ``v_frac`` where up the capital height (0 the
    baseline, 0.5 the middle, 1 the top). Letters are taken 0.7 of their height wide."""
    w = 0.7 * height * max(n_chars, 1)
    dx, dy = (0.5 - h_frac) * w, (0.5 - v_frac) * height
    a = math.radians(angle)
    return (x + dx * math.cos(a) - dy * math.sin(a), y + dx * math.sin(a) + dy * math.cos(a))


def fit_circle(pts) -> tuple[float, float, float]:
    """The circle nearest the points (least squares: x² + y² = 2·cx·x + 2·cy·y + c),
    ``(cx, cy, r)``; unlike their mean, its centre does not lean toward where a writer
    set its points more densely."""
    import numpy as np

    p = np.asarray(pts, float)
    A = np.column_stack([2 * p[:, 0], 2 * p[:, 1], np.ones(len(p))])
    b = (p ** 2).sum(axis=1)
    (cx, cy, c), *_ = np.linalg.lstsq(A, b, rcond=None)
    return float(cx), float(cy), float(math.sqrt(max(c + cx * cx + cy * cy, 0.0)))


def read_bytes(path: Path) -> bytes:
    """The file's bytes, refused past :data:`MAX_BYTES` (one-line errors)."""
    try:
        size = path.stat().st_size
    except FileNotFoundError:
        raise DrawingError(f"{path}: file not found") from None
    except OSError as exc:
        raise DrawingError(f"{path}: cannot read ({exc.strerror})") from None
    if path.is_dir():
        raise DrawingError(f"{path}: is a folder (expected a drawing: .dxf, .svg or .pdf)")
    if size > MAX_BYTES:
        raise DrawingError(f"{path}: {size / 2**20:.0f} MB: a drawing larger than "
                           f"{MAX_BYTES // 2**20} MB is not read")
    try:
        return path.read_bytes()
    except OSError as exc:
        raise DrawingError(f"{path}: cannot read ({exc.strerror})") from None


__all__ = ["MAX_BYTES", "MAX_DEPTH", "MAX_ITEMS", "Circle", "Collector", "Drawing",
           "DrawingError", "Fill", "Segment", "Text", "fit_circle", "read_bytes",
           "text_centre"]
