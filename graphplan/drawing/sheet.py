"""Drawing sheets, renderer-independent: page, frame, title block, line styles, items.

Paper is measured in millimetres with the origin at the **top-left corner of the
sheet, x to the right and y down** (the SVG convention). A renderer draws these
values as they are (1 user unit = 1 mm) and never mirrors anything.

Angles on paper (``Arc`` start/end, ``Text.rotate_deg``, ``Hatch.angle_deg``) are in
degrees, measured from the +x axis and **counter-clockwise as seen on the sheet**:
the point at angle a of a circle is ``(cx + r·cos a, cy − r·sin a)``, and a text with
``rotate_deg=90`` reads from bottom to top.

Standards (see the method guide, section A):

* formats GOST 2.301 (A1 841×594, A2 594×420, A3 420×297, landscape);
* frame GOST 2.104: margins 20 mm left, 5 mm top, right and bottom;
* title block GOST 2.104 form 1, 185×55, in the bottom-right corner of the frame,
  plus graph 26 (70×14, designation turned 180°) in the top-left corner;
* lines GOST 2.303 with S = 0.7 mm (``MAIN``), thin lines 0.25 mm;
* lettering GOST 2.304 type B, slanted; a text's size is its capital height h.

Everything here is a frozen value; the functions return new tuples of items.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import KW_ONLY, dataclass, field

import numpy as np
import shapely
from shapely import affinity
from shapely.geometry import LinearRing, LineString, MultiLineString, Point, Polygon
from shapely.geometry.base import BaseGeometry

from .. import fonts
from ..errors import InputError, LayoutError
from ..paper import Page, Rect

Pt = tuple[float, float]

#: Layers, in drawing order (later layers are drawn on top).
LAYERS: tuple[str, ...] = (
    "frame",
    "title",
    "construction",
    "position_plan",
    "velocity_plan",
    "acceleration_plan",
    "force_plan",
    "diagrams",
    "dimensions",
    "tables",
    "text",
)
#: Layers whose texts may lie in the margins (graphs 31, 32 are under the frame).
MARGIN_LAYERS = frozenset({"frame", "title"})

#: Capital heights of lettering, GOST 2.304 (1.8 allowed for type B only).
TEXT_HEIGHTS: tuple[float, ...] = (1.8, 2.5, 3.5, 5.0, 7.0, 10.0, 14.0, 20.0, 28.0, 40.0)
#: GOST 2.304 type B slant: letters lean at 75° to the baseline.
SLANT_DEG = fonts.SLANT_DEG
#: Minimum line pitch of type B lettering, in units of h (baseline to baseline).
LINE_PITCH = 1.7


# ------------------------------------------------------------------------- styles


@dataclass(frozen=True, slots=True)
class Style:
    """Stroke of a line: width (mm), dash pattern (mm, None = solid), colour, fill.

    ``dasharray`` may be given as ``"15,3,1,3"`` or as a tuple; it is stored as a tuple.
    """

    width: float
    dasharray: tuple[float, ...] | None = None
    colour: str = "black"
    fill: str | None = None

    def __post_init__(self) -> None:
        if not (math.isfinite(self.width) and self.width > 0):
            raise InputError(f"line width must be > 0 mm (got {self.width!r})")
        dash = self.dasharray
        if isinstance(dash, str):
            dash = tuple(float(v) for v in dash.replace(" ", ",").split(",") if v)
        if dash is not None:
            dash = tuple(float(v) for v in dash)
            if not dash or any(not (math.isfinite(v) and v > 0) for v in dash):
                raise InputError(f"dasharray must be positive lengths in mm (got {dash!r})")
        object.__setattr__(self, "dasharray", dash)


S = 0.7  #: thickness of the solid main line, GOST 2.303 (0.5 … 1.4 mm)
MAIN = Style(S)  #: solid main line: links, frame, title block main lines
THIN = Style(0.25)  #: solid thin: construction, dimension, hatch, trim border
MEDIUM = Style(0.5)  #: vectors on the plans
DASHDOT = Style(0.25, (15.0, 3.0, 1.0, 3.0))  #: thin dash-dot: axes, trajectories
DASHED = Style(0.25, (4.0, 1.5))  #: dashed: hidden lines
DASHDOTDOT = Style(0.25, (15.0, 3.0, 1.0, 3.0, 1.0, 3.0))  #: extreme positions

# -------------------------------------------------------------------------- items


def _pt(p: object, what: str) -> Pt:
    try:
        x, y = (float(v) for v in p)  # type: ignore[attr-defined]
    except (TypeError, ValueError):
        raise InputError(f"{what} must be a point (x, y) in mm (got {p!r})") from None
    if not (math.isfinite(x) and math.isfinite(y)):
        raise InputError(f"{what} must be finite (got {p!r})")
    return (x, y)


def _positive(v: float, what: str) -> float:
    v = float(v)
    if not (math.isfinite(v) and v > 0):
        raise InputError(f"{what} must be > 0 (got {v!r})")
    return v


def _check_common(item: object) -> None:
    layer = item.layer  # type: ignore[attr-defined]
    if layer not in LAYERS:
        raise InputError(f"layer must be one of {', '.join(LAYERS)} (got {layer!r})")
    ident = item.id  # type: ignore[attr-defined]
    if ident is not None and (
        not isinstance(ident, str) or not ident or any(c.isspace() for c in ident)
        or ident.startswith("layer-")
    ):
        raise InputError(
            f"id must be a non-empty string without spaces, not 'layer-…' (got {ident!r})"
        )


@dataclass(frozen=True, slots=True)
class Line:
    """Straight segment p0–p1."""

    p0: Pt
    p1: Pt
    style: Style
    _: KW_ONLY
    layer: str
    id: str | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "p0", _pt(self.p0, "Line.p0"))
        object.__setattr__(self, "p1", _pt(self.p1, "Line.p1"))
        _check_common(self)


@dataclass(frozen=True, slots=True)
class Polyline:
    """Open or closed chain of points (closed and with ``style.fill``: a filled polygon)."""

    points: tuple[Pt, ...]
    style: Style
    closed: bool = False
    _: KW_ONLY
    layer: str
    id: str | None = None

    def __post_init__(self) -> None:
        pts = tuple(_pt(p, "Polyline point") for p in self.points)
        if len(pts) < 2:
            raise InputError(f"a polyline needs at least 2 points (got {len(pts)})")
        object.__setattr__(self, "points", pts)
        _check_common(self)


@dataclass(frozen=True, slots=True)
class Circle:
    """Circle of radius r (mm) about centre."""

    centre: Pt
    r: float
    style: Style
    _: KW_ONLY
    layer: str
    id: str | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "centre", _pt(self.centre, "Circle.centre"))
        object.__setattr__(self, "r", _positive(self.r, "Circle.r"))
        _check_common(self)


@dataclass(frozen=True, slots=True)
class Arc:
    """Arc of a circle from ``start_deg`` counter-clockwise (as seen) to ``end_deg``.

    The point at angle a is ``(cx + r·cos a, cy − r·sin a)`` on the y-down paper.
    """

    centre: Pt
    r: float
    start_deg: float
    end_deg: float
    style: Style
    _: KW_ONLY
    layer: str
    id: str | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "centre", _pt(self.centre, "Arc.centre"))
        object.__setattr__(self, "r", _positive(self.r, "Arc.r"))
        for name in ("start_deg", "end_deg"):
            v = float(getattr(self, name))
            if not math.isfinite(v):
                raise InputError(f"Arc.{name} must be finite (got {v!r})")
            object.__setattr__(self, name, v)
        _check_common(self)

    @property
    def sweep_deg(self) -> float:
        """Counter-clockwise extent in (0, 360]; equal angles give a full circle."""
        span = (self.end_deg - self.start_deg) % 360.0
        return 360.0 if span == 0.0 else span


@dataclass(frozen=True, slots=True)
class Arrow:
    """Vector p0→p1: a shaft and a filled arrowhead whose tip is at p1.

    ``head_width`` is the full width of the head's base. A vector shorter than its
    head is drawn as a head shrunk to the vector's length; a zero vector draws nothing.
    """

    p0: Pt
    p1: Pt
    style: Style
    head_length: float = 3.5
    head_width: float = 1.0
    _: KW_ONLY
    layer: str
    id: str | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "p0", _pt(self.p0, "Arrow.p0"))
        object.__setattr__(self, "p1", _pt(self.p1, "Arrow.p1"))
        object.__setattr__(self, "head_length", _positive(self.head_length, "Arrow.head_length"))
        object.__setattr__(self, "head_width", _positive(self.head_width, "Arrow.head_width"))
        _check_common(self)


@dataclass(frozen=True, slots=True)
class Text:
    """One line of lettering, GOST 2.304 type B.

    ``pos`` is the point on the **baseline** where the text is anchored (``anchor``:
    "start", "middle" or "end" of the line); ``height`` is the capital height in mm,
    one of TEXT_HEIGHTS; ``rotate_deg`` turns the text counter-clockwise (as seen)
    about ``pos``. Use :func:`text_at_centre` to centre the capitals on a point.
    """

    pos: Pt
    text: str
    height: float
    anchor: str = "start"
    rotate_deg: float = 0.0
    italic: bool = True
    _: KW_ONLY
    layer: str
    id: str | None = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "pos", _pt(self.pos, "Text.pos"))
        if not isinstance(self.text, str) or not self.text.strip() or "\n" in self.text:
            raise InputError(f"text must be one non-empty line (got {self.text!r})")
        if float(self.height) not in TEXT_HEIGHTS:
            raise InputError(
                f"text height must be a GOST 2.304 size {TEXT_HEIGHTS} mm (got {self.height!r})"
            )
        object.__setattr__(self, "height", float(self.height))
        if self.anchor not in ("start", "middle", "end"):
            raise InputError(f"text anchor must be start, middle or end (got {self.anchor!r})")
        rot = float(self.rotate_deg)
        if not math.isfinite(rot):
            raise InputError(f"Text.rotate_deg must be finite (got {self.rotate_deg!r})")
        object.__setattr__(self, "rotate_deg", rot)
        _check_common(self)


@dataclass(frozen=True, slots=True)
class Hatch:
    """Parallel hatch lines clipped to ``polygon`` (no outline; draw that separately).

    Lines run at ``angle_deg`` (counter-clockwise as seen) every ``spacing`` mm. Their
    phase is fixed to the sheet origin, so neighbouring hatches line up.
    """

    polygon: tuple[Pt, ...]
    spacing: float = 2.0
    angle_deg: float = 45.0
    style: Style = THIN
    _: KW_ONLY
    layer: str
    id: str | None = None

    def __post_init__(self) -> None:
        pts = tuple(_pt(p, "Hatch polygon point") for p in self.polygon)
        if len(pts) < 3 or Polygon(pts).area <= 0:
            raise InputError(f"a hatch needs a polygon of non-zero area (got {len(pts)} points)")
        object.__setattr__(self, "polygon", pts)
        object.__setattr__(self, "spacing", _positive(self.spacing, "Hatch.spacing"))
        object.__setattr__(self, "angle_deg", float(self.angle_deg))
        _check_common(self)


@dataclass(frozen=True, slots=True)
class Group:
    """Items drawn together (one ``<g>``); every child must be on the group's layer."""

    items: tuple[Item, ...]
    layer: str
    id: str | None = None

    def __post_init__(self) -> None:
        items = tuple(self.items)
        for it in items:
            if not isinstance(it, ITEM_TYPES):
                raise InputError(f"a group holds drawing items (got {type(it).__name__})")
            if it.layer != self.layer:
                raise InputError(
                    f"group {self.id!r} on layer {self.layer!r} holds an item on layer {it.layer!r}"
                )
        object.__setattr__(self, "items", items)
        _check_common(self)


Item = Line | Polyline | Circle | Arc | Arrow | Text | Hatch | Group
ITEM_TYPES = (Line, Polyline, Circle, Arc, Arrow, Text, Hatch, Group)
Leaf = Line | Polyline | Circle | Arc | Arrow | Text | Hatch


def iter_leaves(items: Iterable[Item]) -> Iterator[Leaf]:
    """All items with the groups opened, in drawing order."""
    for it in items:
        if isinstance(it, Group):
            yield from iter_leaves(it.items)
        else:
            yield it


# ------------------------------------------------------ geometry of the primitives


def _visual_dir(angle_deg: float) -> np.ndarray:
    a = math.radians(angle_deg)
    return np.array([math.cos(a), -math.sin(a)])


def arc_point(centre: Pt, r: float, angle_deg: float) -> Pt:
    """Point of a circle at ``angle_deg`` (counter-clockwise as seen, y down)."""
    d = _visual_dir(angle_deg)
    return (centre[0] + r * float(d[0]), centre[1] + r * float(d[1]))


def arc_points(arc: Arc, max_step_deg: float = 5.0) -> tuple[Pt, ...]:
    """Polyline approximation of an arc (for footprints and exporters)."""
    n = max(2, math.ceil(arc.sweep_deg / max_step_deg) + 1)
    return tuple(
        arc_point(arc.centre, arc.r, arc.start_deg + arc.sweep_deg * i / (n - 1)) for i in range(n)
    )


def arrow_parts(arrow: Arrow) -> tuple[tuple[Pt, Pt] | None, tuple[Pt, ...]]:
    """Shaft segment (or None) and arrowhead triangle (tip first) of a vector.

    The shaft stops at the base of the head, so its butt end never shows past the tip.
    A zero vector returns ``(None, ())``.
    """
    p0, p1 = np.array(arrow.p0), np.array(arrow.p1)
    length = float(np.hypot(*(p1 - p0)))
    if length < 1e-9:
        return None, ()
    u = (p1 - p0) / length
    n = np.array([-u[1], u[0]])
    head = min(arrow.head_length, length)
    half = 0.5 * arrow.head_width * head / arrow.head_length
    base = p1 - u * head
    tri = (
        (float(p1[0]), float(p1[1])),
        (float(base[0] + n[0] * half), float(base[1] + n[1] * half)),
        (float(base[0] - n[0] * half), float(base[1] - n[1] * half)),
    )
    shaft = None
    if head < length:
        shaft = ((float(p0[0]), float(p0[1])), (float(base[0]), float(base[1])))
    return shaft, tri


def hatch_segments(hatch: Hatch) -> tuple[tuple[Pt, Pt], ...]:
    """The clipped hatch lines of ``hatch``, each as (start, end), in a stable order."""
    poly = shapely.make_valid(Polygon(hatch.polygon))
    d = _visual_dir(hatch.angle_deg)
    n = np.array([-d[1], d[0]])
    pts = np.asarray(hatch.polygon)
    offs = pts @ n
    ts = pts @ d
    t0, t1 = float(ts.min()) - 1.0, float(ts.max()) + 1.0
    # only lines strictly inside: none along an edge parallel to the hatch
    k0 = math.floor(float(offs.min()) / hatch.spacing + 1e-9) + 1
    k1 = math.ceil(float(offs.max()) / hatch.spacing - 1e-9) - 1
    out: list[tuple[Pt, Pt]] = []
    for k in range(k0, k1 + 1):
        c = n * (k * hatch.spacing)
        line = LineString([tuple(c + d * t0), tuple(c + d * t1)])
        cut = poly.intersection(line)
        for g in getattr(cut, "geoms", [cut]):
            if isinstance(g, LineString) and g.length > 1e-6:
                (ax, ay), (bx, by) = g.coords[0], g.coords[-1]
                out.append(((ax, ay), (bx, by)))
    return tuple(out)


def text_width(text: Text) -> float:
    """Advance width of a text in mm plus, if italic, the lean of its capitals."""
    return fonts.lettering_width(text.text, text.height, text.italic)


def text_box(text: Text) -> Polygon:
    """Footprint of a text on paper (shapely polygon, mm).

    Width from the advance widths of the font chosen for the text (or
    ``fonts.FALLBACK_ADVANCE``·h per character), plus the italic lean h·tan 15° on
    the right; from h above the baseline (capitals) to 0.3·h below (descenders);
    turned with the text about ``pos``.
    """
    x, y = text.pos
    h = text.height
    adv = fonts.text_width(text.text, h)
    lean = h * math.tan(math.radians(SLANT_DEG)) if text.italic else 0.0
    x0 = {"start": x, "middle": x - adv / 2, "end": x - adv}[text.anchor]
    # shapely.box: the polygon of shapely.geometry.box (same vertices, same order), built
    # in one call instead of from a list of tuples (text_box is in every label's search)
    poly = shapely.box(x0, y - h, x0 + adv + lean, y + 0.3 * h)
    if text.rotate_deg:
        poly = affinity.rotate(poly, -text.rotate_deg, origin=(x, y))
    return poly


def text_at_centre(centre: Pt, text: str, height: float, *, rotate_deg: float = 0.0,
                   anchor: str = "middle", layer: str, id: str | None = None,
                   italic: bool = True) -> Text:
    """A text whose capitals are centred vertically on ``centre`` (baseline h/2 below).

    With ``anchor="middle"`` the text is centred on the point both ways; with "start"
    or "end" the point is the middle of its left or right edge.
    """
    c, s = math.cos(math.radians(rotate_deg)), math.sin(math.radians(rotate_deg))
    off = (s * height / 2, c * height / 2)  # (0, h/2) turned counter-clockwise as seen
    return Text((centre[0] + off[0], centre[1] + off[1]), text, height, anchor, rotate_deg,
                italic, layer=layer, id=id)


def item_geometry(item: Leaf) -> BaseGeometry | None:
    """Shapely geometry of the strokes of a leaf item (None for texts)."""
    if isinstance(item, Line):
        return LineString([item.p0, item.p1])
    if isinstance(item, Polyline):
        if item.closed and len(item.points) >= 3:
            ring = LinearRing(item.points)
            return Polygon(ring) if item.style.fill else ring
        return LineString(item.points)
    if isinstance(item, Circle):
        disk = Point(item.centre).buffer(item.r, quad_segs=16)
        return disk if item.style.fill else disk.exterior
    if isinstance(item, Arc):
        return LineString(arc_points(item))
    if isinstance(item, Arrow):
        shaft, tri = arrow_parts(item)
        parts: list[BaseGeometry] = []
        if shaft:
            parts.append(LineString(shaft))
        if tri:
            parts.append(Polygon(tri))
        return shapely.union_all(parts) if parts else None
    if isinstance(item, Hatch):
        segs = hatch_segments(item)
        return MultiLineString(segs) if segs else None
    return None


# ---------------------------------------------------------------- frame and title


def _rect_items(r: Rect, style: Style, layer: str, id: str) -> Polyline:
    return Polyline(((r.x0, r.y0), (r.x1, r.y0), (r.x1, r.y1), (r.x0, r.y1)), style, True,
                    layer=layer, id=id)


def frame_items(page: Page) -> tuple[Item, ...]:
    """Trim border (thin) and inner frame (main line) of ``page``."""
    return (
        _rect_items(page.trim, THIN, "frame", "trim"),
        _rect_items(page.frame, MAIN, "frame", "frame"),
    )


#: Segments of form 1 (GOST 2.104, KiCad WS_Osn1), title-block coordinates (top-left
#: origin, y down): (weight, x0, y0, x1, y1), "S" main line, "t" thin. The bottom and
#: right edges of the block are the frame's own lines.
FORM1_SEGMENTS: tuple[tuple[str, float, float, float, float], ...] = (
    ("S", 0, 0, 185, 0), ("S", 0, 0, 0, 55), ("S", 7, 0, 7, 25), ("S", 17, 0, 17, 55),
    ("S", 40, 0, 40, 55), ("S", 55, 0, 55, 55), ("S", 65, 0, 65, 55), ("S", 65, 15, 185, 15),
    ("S", 65, 40, 185, 40), ("S", 0, 20, 65, 20), ("S", 0, 25, 65, 25), ("S", 135, 20, 185, 20),
    ("S", 135, 35, 185, 35), ("S", 135, 15, 135, 55), ("S", 150, 15, 150, 35),
    ("S", 167, 15, 167, 35), ("S", 155, 35, 155, 40),
    ("t", 0, 5, 65, 5), ("t", 0, 10, 65, 10), ("t", 0, 15, 65, 15), ("t", 0, 30, 65, 30),
    ("t", 0, 35, 65, 35), ("t", 0, 40, 65, 40), ("t", 0, 45, 65, 45), ("t", 0, 50, 65, 50),
    ("t", 140, 20, 140, 35), ("t", 145, 20, 145, 35),
)

#: Printed labels of form 1: (id, text, cell x0, y0, x1, y1, anchor). A label is
#: centred in its cell, or starts 1 mm inside it; the cells put the capitals' centres
#: on KiCad's points, e.g. "Изм." c(3.5, 22.5), "Лист" l(136, 37.5).
FORM1_LABELS: tuple[tuple[str, str, float, float, float, float, str], ...] = (
    ("izm", "Изм.", 0, 20, 7, 25, "middle"), ("list", "Лист", 7, 20, 17, 25, "middle"),
    ("doc", "№ докум.", 17, 20, 40, 25, "middle"), ("podp", "Подп.", 40, 20, 55, 25, "middle"),
    ("data", "Дата", 55, 20, 65, 25, "middle"),
    ("lit", "Лит.", 135, 15, 150, 20, "middle"), ("massa", "Масса", 150, 15, 167, 20, "middle"),
    ("masshtab", "Масштаб", 167, 15, 185, 20, "middle"),
    ("sheet", "Лист", 135, 35, 146, 40, "start"), ("sheets", "Листов", 155, 35, 173, 40, "start"),
)
LABEL_HEIGHTS = (2.5, 1.8)  #: printed labels: 2.5 mm, 1.8 if a font is too wide

#: Signature rows (role, surname, date) of graphs 10, 11 and 13, rows y = 25..55.
DEFAULT_SIGNATURES: tuple[tuple[str, str, str], ...] = (
    ("Разраб.", "", ""), ("Пров.", "", ""), ("Т.контр.", "", ""), ("", "", ""),
    ("Н.контр.", "", ""), ("Утв.", "", ""),
)


def signatures(author: str = "", checker: str = "", *, tech_control: str = "",
               extra: tuple[str, str] = ("", ""), norm_control: str = "", approved: str = "",
               date: str = "") -> tuple[tuple[str, str, str], ...]:
    """The six signature rows of form 1 filled with surnames (one date for the author).

    ``extra`` is (role, surname) of the free fourth row, e.g. ("Консульт.", "Петров").
    """
    return (
        ("Разраб.", author, date), ("Пров.", checker, ""), ("Т.контр.", tech_control, ""),
        (extra[0], extra[1], ""), ("Н.контр.", norm_control, ""), ("Утв.", approved, ""),
    )


@dataclass(frozen=True, slots=True)
class TitleBlock:
    """Contents of the main title block, GOST 2.104 form 1 (graph numbers in brackets).

    designation [2], title [1] (wrapped as needed), material [3], litera [4] (up to
    three characters, one per cell), mass [5], scale [6], sheet [7], sheets [8],
    organisation [9], signatures [10, 11, 13] as up to six (role, surname, date) rows.
    ``margin_labels`` prints "Копировал" and "Формат А1" under the frame (graphs 31, 32).
    """

    designation: str = ""
    title: str = ""
    material: str = ""
    litera: str = ""
    mass: str = ""
    scale: str = ""
    sheet: int | None = None
    sheets: int | None = None
    organisation: str = ""
    signatures: tuple[tuple[str, str, str], ...] = DEFAULT_SIGNATURES
    margin_labels: bool = True

    def __post_init__(self) -> None:
        for name in ("designation", "title", "material", "litera", "mass", "scale",
                     "organisation"):
            v = getattr(self, name)
            if not isinstance(v, str) or "\n" in v:
                raise InputError(f"title block {name} must be a one-line string (got {v!r})")
        if len(self.litera.replace(" ", "")) > 3:
            raise InputError(f"title block litera has 3 cells (got {self.litera!r})")
        for name in ("sheet", "sheets"):
            v = getattr(self, name)
            if v is not None and (not isinstance(v, int) or v < 1):
                raise InputError(f"title block {name} must be a positive integer (got {v!r})")
        rows = tuple(tuple(str(c) for c in row) for row in self.signatures)
        if len(rows) > 6 or any(len(r) != 3 for r in rows):
            raise InputError("title block signatures: up to 6 rows of (role, surname, date)")
        object.__setattr__(self, "signatures", rows)


def _wrap(text: str, height: float, width: float) -> list[str] | None:
    """Word wrap at capital height ``height`` into as few lines as fit ``width``.

    The number of lines is the greedy one; the breaks are then chosen to make the
    longest line as short as possible (balanced lines: "Кафедра ТММ, / гр. МТ-21"
    rather than "Кафедра ТММ, гр. / МТ-21"). None if one word alone is too wide.
    """
    words = text.split()
    lines: list[str] = []
    for word in words:
        trial = f"{lines[-1]} {word}" if lines else word
        if lines and _width(trial, height) <= width:
            lines[-1] = trial
        elif _width(word, height) <= width:
            lines.append(word)
        else:
            return None
    n = len(lines)
    if n < 2 or len(words) > 16:
        return lines
    best, best_key = lines, None
    for cuts in itertools.combinations(range(1, len(words)), n - 1):
        bounds = (0, *cuts, len(words))
        cand = [" ".join(words[a:b]) for a, b in itertools.pairwise(bounds)]
        ws = [_width(c, height) for c in cand]
        if max(ws) > width:
            continue
        key = (round(max(ws), 6), sum(w * w for w in ws))
        if best_key is None or key < best_key:
            best, best_key = cand, key
    return best


def _width(s: str, h: float) -> float:
    return fonts.lettering_width(s, h)


def _fit(text: str, cell: Rect, heights: Sequence[float], what: str, *, wrap: bool = False,
         pad: float = 1.0) -> tuple[float, list[str]]:
    """Largest height of ``heights`` at which ``text`` fits ``cell`` (wrapped if allowed)."""
    w, hmax = cell.width - 2 * pad, cell.height - 1.0  # 0.5 mm clear above and below
    for h in heights:
        lines = _wrap(text, h, w) if wrap else ([text] if _width(text, h) <= w else None)
        if lines and h + (len(lines) - 1) * LINE_PITCH * h + 0.3 * h <= hmax + 1e-9:
            return h, lines
    raise LayoutError(
        f"title block {what}: {text!r} does not fit its {cell.width:g}×{cell.height:g} mm cell "
        f"even at {heights[-1]:g} mm lettering"
    )


def _cell_texts(text: str, cell: Rect, heights: Sequence[float], what: str, id: str,
                *, wrap: bool = False, anchor: str = "middle", pad: float = 1.0,
                rotate_deg: float = 0.0) -> list[Text]:
    """Texts of one cell: largest fitting height, lines centred as a block in the cell."""
    if not text.strip():
        return []
    h, lines = _fit(text.strip(), cell, heights, what, wrap=wrap, pad=pad)
    cy = (cell.y0 + cell.y1) / 2
    cx = {"middle": (cell.x0 + cell.x1) / 2, "start": cell.x0 + pad, "end": cell.x1 - pad}[anchor]
    pitch = LINE_PITCH * h
    out = []
    for i, line in enumerate(lines):
        dy = (i - (len(lines) - 1) / 2) * pitch
        if rotate_deg == 180.0:  # upside down: the first line is lowest on the paper
            dy = -dy
        ident = id if len(lines) == 1 else f"{id}-{i + 1}"
        out.append(text_at_centre((cx, cy + dy), line, h, anchor=anchor, rotate_deg=rotate_deg,
                                  layer="title", id=ident))
    return out


def title_block_items(page: Page, tb: TitleBlock) -> tuple[Item, ...]:
    """Lines, printed labels and filled-in values of form 1, plus graph 26.

    Placed in the bottom-right corner of the frame of ``page`` (origin
    ``page.title_block_origin``); all items are on the "title" layer. Values take the
    largest GOST lettering that fits their cell: designation 7/5/3.5 mm, title
    7/5/3.5/2.5 (wrapped), organisation 5/3.5/2.5 (wrapped), surnames 3.5/2.5/1.8,
    labels 2.5. Raises LayoutError if a value does not fit even at the smallest size.
    """
    ox, oy = page.title_block_origin

    def R(x0: float, y0: float, x1: float, y1: float) -> Rect:
        return Rect(ox + x0, oy + y0, ox + x1, oy + y1)

    items: list[Item] = []
    for i, (w, x0, y0, x1, y1) in enumerate(FORM1_SEGMENTS, 1):
        items.append(Line((ox + x0, oy + y0), (ox + x1, oy + y1), MAIN if w == "S" else THIN,
                          layer="title", id=f"tb-line-{i:02d}"))
    for slug, text, x0, y0, x1, y1, anchor in FORM1_LABELS:
        items += _cell_texts(text, R(x0, y0, x1, y1), LABEL_HEIGHTS, f"label {text!r}",
                             f"tb-label-{slug}", anchor=anchor,
                             pad=1.0 if anchor == "start" else S / 2 + 0.1)  # clear of the line
    for i, (role, surname, date) in enumerate(tb.signatures):
        y0 = 25 + 5 * i
        items += _cell_texts(role, R(0, y0, 17, y0 + 5), LABEL_HEIGHTS, f"role row {i + 1}",
                             f"tb-role-{i + 1}", anchor="start", pad=1.0)
        items += _cell_texts(surname, R(17, y0, 40, y0 + 5), (3.5, 2.5, 1.8),
                             f"surname row {i + 1}", f"tb-surname-{i + 1}", anchor="start", pad=0.5)
        items += _cell_texts(date, R(55, y0, 65, y0 + 5), (2.5, 1.8), f"date row {i + 1}",
                             f"tb-date-{i + 1}", pad=0.3)
    items += _cell_texts(tb.designation, R(65, 0, 185, 15), (7.0, 5.0, 3.5),
                         "graph 2 (designation)", "tb-designation", pad=2.0)
    items += _cell_texts(tb.title, R(65, 15, 135, 40), (7.0, 5.0, 3.5, 2.5), "graph 1 (title)",
                         "tb-title", wrap=True, pad=1.5)
    items += _cell_texts(tb.material, R(65, 40, 135, 55), (5.0, 3.5, 2.5), "graph 3 (material)",
                         "tb-material", wrap=True, pad=1.5)
    for i, ch in enumerate(tb.litera.replace(" ", "")):
        items += _cell_texts(ch, R(135 + 5 * i, 20, 140 + 5 * i, 35), (3.5, 2.5),
                             "graph 4 (litera)", f"tb-litera-{i + 1}", pad=0.5)
    items += _cell_texts(tb.mass, R(150, 20, 167, 35), (5.0, 3.5, 2.5), "graph 5 (mass)",
                         "tb-mass")
    items += _cell_texts(tb.scale, R(167, 20, 185, 35), (5.0, 3.5, 2.5), "graph 6 (scale)",
                         "tb-scale")
    if tb.sheet is not None:
        items.append(text_at_centre((ox + 149, oy + 37.5), str(tb.sheet), 2.5, layer="title",
                                    id="tb-sheet"))
    if tb.sheets is not None:
        items.append(text_at_centre((ox + 175, oy + 37.5), str(tb.sheets), 2.5, anchor="start",
                                    layer="title", id="tb-sheets"))
    items += _cell_texts(tb.organisation, R(135, 40, 185, 55), (5.0, 3.5, 2.5),
                         "graph 9 (organisation)", "tb-organisation", wrap=True, pad=1.5)
    if tb.margin_labels:
        fmt = "А" + page.format[1:]  # Cyrillic А, as printed on Russian sheets
        items.append(text_at_centre((ox + 75, oy + 57.5), "Копировал", 2.5, anchor="start",
                                    layer="title", id="tb-label-copied"))
        items.append(text_at_centre((ox + 145, oy + 57.5), "Формат", 2.5, anchor="start",
                                    layer="title", id="tb-label-format"))
        items.append(text_at_centre((ox + 165, oy + 57.5), fmt, 2.5, anchor="start",
                                    layer="title", id="tb-format"))
    # graph 26: the designation turned 180° in a 70×14 box at the frame's top-left
    g = page.graph26_rect
    items.append(Line((g.x1, g.y0), (g.x1, g.y1), MAIN, layer="title", id="tb-g26-right"))
    items.append(Line((g.x0, g.y1), (g.x1, g.y1), MAIN, layer="title", id="tb-g26-bottom"))
    items += _cell_texts(tb.designation, g, (5.0, 3.5, 2.5), "graph 26 (designation)",
                         "tb-g26", pad=2.0, rotate_deg=180.0)
    return tuple(items)


# ------------------------------------------------------------------------- tables


def table_items(origin: Pt, column_widths: Sequence[float], rows: Sequence[Sequence[object]],
                header: Sequence[object] | None = None, text_height: float = 3.5, *,
                row_height: float | None = None, align: Sequence[str] | None = None,
                layer: str = "tables", id: str | None = None) -> tuple[Item, ...]:
    """A ruled table: border and header rule in main line, inner rules thin, texts centred.

    ``origin`` is the top-left corner. Every row is ``row_height`` tall (default
    2·text_height, e.g. 7 mm for 3.5 mm lettering); the table is
    ``sum(column_widths)`` wide and ``row_height·(len(rows) + (header is not None))``
    tall. ``align`` gives "start"/"middle"/"end" per column (default "middle"); cell
    values are formatted with ``str``. Ids: ``{id}-r{i}c{j}`` (header row 0).
    Raises LayoutError if a value is wider than its cell.
    """
    ox, oy = _pt(origin, "table origin")
    widths = [_positive(w, "table column width") for w in column_widths]
    if not widths:
        raise InputError("a table needs at least one column")
    rh = _positive(row_height if row_height is not None else 2 * text_height, "table row height")
    al = list(align) if align is not None else ["middle"] * len(widths)
    if len(al) != len(widths):
        raise InputError(f"table align has {len(al)} entries for {len(widths)} columns")
    body = [list(r) for r in rows]
    all_rows = ([list(header)] if header is not None else []) + body
    for i, r in enumerate(all_rows):
        if len(r) != len(widths):
            raise InputError(f"table row {i}: {len(r)} cells for {len(widths)} columns")
    xs = [ox]
    for w in widths:
        xs.append(xs[-1] + w)
    n = len(all_rows)
    ys = [oy + rh * i for i in range(n + 1)]
    pre = f"{id}-" if id else ""
    items: list[Item] = []
    for i, y in enumerate(ys):
        main = i in (0, n) or (header is not None and i == 1)
        items.append(Line((xs[0], y), (xs[-1], y), MAIN if main else THIN, layer=layer,
                          id=f"{pre}h{i}" if id else None))
    for j, x in enumerate(xs):
        main = j in (0, len(widths))
        items.append(Line((x, ys[0]), (x, ys[-1]), MAIN if main else THIN, layer=layer,
                          id=f"{pre}v{j}" if id else None))
    pad = 1.0
    for i, r in enumerate(all_rows):
        row_no = i if header is not None else i + 1
        for j, value in enumerate(r):
            s = str(value).strip()
            if not s:
                continue
            if _width(s, text_height) > widths[j] - 2 * pad:
                raise LayoutError(
                    f"table {id or ''} row {row_no} column {j + 1}: {s!r} is wider than "
                    f"{widths[j]:g} mm at {text_height:g} mm lettering"
                )
            x = {"start": xs[j] + pad, "middle": (xs[j] + xs[j + 1]) / 2,
                 "end": xs[j + 1] - pad}[al[j]]
            items.append(text_at_centre((x, (ys[i] + ys[i + 1]) / 2), s, text_height, anchor=al[j],
                                        layer=layer, id=f"{pre}r{row_no}c{j + 1}" if id else None))
    return tuple(items)


# -------------------------------------------------------------------------- sheet


@dataclass(frozen=True, slots=True)
class Sheet:
    """One drawing sheet: its page, its items and its title block (None: no block).

    ``lang`` is the language of its lettering: on a Russian sheet (``"ru"``) the
    renderers write numbers with the decimal comma (:func:`graphplan.units.
    decimal_comma`; the title block's designation is left as it is). Every sheet's
    renderers write the indices of the quantities as subscripts (vB, R12, Mур:
    :func:`graphplan.units.subscript_runs`) where the format can (SVG, PDF, PNG).
    """

    page: Page = field(default_factory=Page)
    items: tuple[Item, ...] = ()
    title_block: TitleBlock | None = None
    lang: str | None = None

    def __post_init__(self) -> None:
        items = tuple(self.items)
        for it in items:
            if not isinstance(it, ITEM_TYPES):
                raise InputError(f"sheet items must be drawing items (got {type(it).__name__})")
        object.__setattr__(self, "items", items)

    def all_items(self) -> tuple[Item, ...]:
        """Frame, title block (if any), then the sheet's own items, in drawing order."""
        tb = title_block_items(self.page, self.title_block) if self.title_block else ()
        return frame_items(self.page) + tb + self.items

    def _repr_svg_(self) -> str:
        """Jupyter: the sheet as SVG, as wide as the notebook (the viewBox keeps its mm)."""
        import re

        from ..render.svg import render_svg

        svg = render_svg(self)
        return re.sub(r'<svg([^>]*?) height="[^"]*"([^>]*?) width="[^"]*"',
                      r'<svg\1\2 width="100%"', svg, count=1)


# ----------------------------------------------------------------- layout checks


def _describe(t: Leaf) -> str:
    name = f"{type(t).__name__.lower()}"
    if t.id:
        name += f" {t.id!r}"
    if isinstance(t, Text):
        name += f" {t.text!r} at ({t.pos[0]:.1f}, {t.pos[1]:.1f})"
    return f"{name} [{t.layer}]"


#: Layers that hold the construction lines and the arms of the plans drawn in these layers.
_PLAN_LAYERS = frozenset({"position_plan", "velocity_plan", "acceleration_plan", "force_plan"})


def _same_figure(text_layer: str, item_layer: str) -> bool:
    """A plan's letters may cross its own construction lines and arms (other layers)."""
    return text_layer == item_layer or (text_layer in _PLAN_LAYERS
                                        and item_layer in ("construction", "dimensions"))


def check_layout(sheet: Sheet) -> list[str]:
    """Problems of a sheet's layout, one line each (empty list: nothing found).

    Reported: duplicate element ids; a text outside the inner frame (outside the
    sheet, for the frame and title layers, whose graphs 31–32 sit in the margin); a
    text of another layer over the title block or graph 26; a drawing item leaving
    the inner frame; two texts whose boxes overlap; a text box crossed by a line of
    another layer (a plan's letters may cross its construction lines and arms).
    """
    problems: list[str] = []
    all_items = sheet.all_items()
    seen: dict[str, int] = {}

    def walk(items: Iterable[Item]) -> None:
        for it in items:
            if it.id is not None:
                seen[it.id] = seen.get(it.id, 0) + 1
            if isinstance(it, Group):
                walk(it.items)

    walk(all_items)
    problems += [f"id {k!r} is used {v} times" for k, v in seen.items() if v > 1]

    leaves = list(iter_leaves(all_items))
    page = sheet.page
    frame = page.frame.polygon().buffer(1e-6)
    trim = page.trim.polygon().buffer(1e-6)
    reserved = page.title_block_rect.polygon().union(page.graph26_rect.polygon())
    texts = [t for t in leaves if isinstance(t, Text)]
    boxes = [text_box(t) for t in texts]
    for t, b in zip(texts, boxes, strict=True):
        if t.layer in MARGIN_LAYERS:
            if not trim.contains(b):
                problems.append(f"{_describe(t)} is outside the sheet")
        elif not frame.contains(b):
            problems.append(f"{_describe(t)} is outside the inner frame")
        elif b.intersection(reserved).area > 1e-6:
            problems.append(f"{_describe(t)} is over the title block")

    geoms: list[tuple[Leaf, BaseGeometry]] = []
    for it in leaves:
        g = item_geometry(it) if not isinstance(it, Text) else None
        if g is None or g.is_empty:
            continue
        geoms.append((it, g))
        if it.layer not in MARGIN_LAYERS and not frame.contains(g):
            problems.append(f"{_describe(it)} leaves the inner frame")

    if boxes:
        tree = shapely.STRtree(boxes)
        left, right = tree.query(boxes, predicate="intersects")
        for i, j in zip(left.tolist(), right.tolist(), strict=True):
            if i < j and boxes[i].intersection(boxes[j]).area > 1e-6:
                problems.append(f"{_describe(texts[i])} overlaps {_describe(texts[j])}")
    if boxes and geoms:
        tree = shapely.STRtree([g for _, g in geoms])
        for i, b in enumerate(boxes):
            for j in tree.query(b, predicate="intersects").tolist():
                it, g = geoms[j]
                if not _same_figure(texts[i].layer, it.layer) and not g.touches(b):
                    problems.append(f"{_describe(texts[i])} is crossed by {_describe(it)}")
    return problems
