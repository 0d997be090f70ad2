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

import math
from collections.abc import Iterable, Iterator
from dataclasses import KW_ONLY, dataclass

import numpy as np
import shapely
from shapely import affinity
from shapely.geometry import LinearRing, LineString, MultiLineString, Point, Polygon
from shapely.geometry.base import BaseGeometry

from .. import fonts
from ..errors import InputError

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
