"""SVG output of a :class:`graphplan.drawing.sheet.Sheet`. The ONLY module importing svgwrite.

The root is ``width="841mm" height="594mm" viewBox="0 0 841 594"`` (for A1), so one
user unit is one millimetre: coordinates, stroke widths and font sizes are written as
plain numbers of mm, rounded to 0.01 mm. Each layer of ``sheet.LAYERS`` is a
``<g id="layer-NAME">`` (also an Inkscape layer), in that order, each holding its
items in the order of ``Sheet.all_items()``. Nothing is mirrored: the sheet is already
y-down, and a text turned by ``rotate_deg`` gets ``transform="rotate(-rotate_deg x y)"``.
Lettering is upright type sheared to GOST 2.304's 75° slant (see ``_text_attrs``).
Arrowheads are filled polygons, not markers, so they survive conversion to DXF or PDF.
The output has no timestamps: the same sheet always gives the same bytes.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import replace
from pathlib import Path

import svgwrite

from .. import fonts
from ..drawing import (
    LAYERS,
    SLANT_DEG,
    Arc,
    Arrow,
    Circle,
    Group,
    Hatch,
    Item,
    Line,
    Polyline,
    Sheet,
    Style,
    Text,
    arc_point,
    arrow_parts,
    hatch_segments,
)
from ..errors import LayoutError
from ..files import write_atomic
from ..numbers import sheet_text
from ..numbers import trimmed as num  # the SVG's lengths, in mm
from ..units import subscript_runs

_INKSCAPE = "http://www.inkscape.org/namespaces/inkscape"


def _pts(points) -> list[tuple[str, str]]:
    # svgwrite joins the pairs as "x,y x,y"; the numbers are already rounded strings
    return [(num(x), num(y)) for x, y in points]


def _stroke(style: Style, *, filled: bool = False) -> dict[str, str]:
    attrs = {
        "stroke": style.colour,
        "stroke-width": num(style.width),
        "stroke-linecap": "butt",
        "fill": (style.fill or "none") if filled else "none",
    }
    if style.dasharray:
        attrs["stroke-dasharray"] = ",".join(num(v) for v in style.dasharray)
    return attrs


def _with_id(attrs: Mapping[str, object], ident: str | None) -> dict[str, object]:
    if ident is not None:
        return {"id": ident, **attrs}
    return dict(attrs)


def _arc_path(arc: Arc) -> str:
    r = num(arc.r)
    sweep = arc.sweep_deg
    if sweep >= 360.0:  # a full turn: two half arcs
        a, b = arc_point(arc.centre, arc.r, arc.start_deg), arc_point(
            arc.centre, arc.r, arc.start_deg + 180.0)
        return (f"M{num(a[0])},{num(a[1])} A{r},{r} 0 0 0 {num(b[0])},{num(b[1])} "
                f"A{r},{r} 0 0 0 {num(a[0])},{num(a[1])}")
    a = arc_point(arc.centre, arc.r, arc.start_deg)
    b = arc_point(arc.centre, arc.r, arc.end_deg)
    large = 1 if sweep > 180.0 else 0
    # counter-clockwise as seen on y-down paper is SVG's negative direction: sweep-flag 0
    return f"M{num(a[0])},{num(a[1])} A{r},{r} 0 {large} 0 {num(b[0])},{num(b[1])}"


def _text_attrs(t: Text) -> dict[str, object]:
    """Attributes of a text: capital height exact, slant by a shear, turn by a rotation.

    GOST 2.304 type B leans at 75° (15° from the vertical). osifont has no italic face
    and renderers synthesise different obliques (CairoSVG none at all), so the slant is
    a shear about the baseline, ``matrix(1 0 −tan15° 1 tan15°·y 0)``, with an upright
    face (``font-style="normal"``): the same 75° in every renderer and font.
    """
    family = fonts.choose_family(t.text)
    size = t.height / fonts.cap_ratio(family)
    x, y = t.pos
    attrs: dict[str, object] = {
        "insert": (num(x), num(y)),
        "font-family": fonts.font_family(t.text),
        "font-size": num(size, 3),
        "font-style": "normal",
        "text-anchor": t.anchor,
        "fill": "black",
        "stroke": "none",
    }
    transforms = []
    if t.rotate_deg % 360.0:
        # counter-clockwise as seen is a negative SVG rotation (SVG's y points down)
        transforms.append(f"rotate({num(-t.rotate_deg)} {num(x)} {num(y)})")
    if t.italic:
        k = math.tan(math.radians(SLANT_DEG))
        transforms.append(f"matrix(1 0 {-k:.5f} 1 {num(k * y)} 0)")
    if transforms:
        attrs["transform"] = " ".join(transforms)
    return attrs


SUB_SIZE, SUB_DROP = 0.7, 0.3  #: an index: 0.7 of the letters' size, dropped 0.3·h


def _text(dwg: svgwrite.Drawing, t: Text, lang: str | None):
    """A text element: the decimal comma on a Russian sheet, the indices of quantities as
    subscripts (``tspan``: smaller, dropped under the baseline, then back); the title
    block's texts as written."""
    if t.layer == "title":
        return dwg.text(t.text, **_with_id(_text_attrs(t), t.id))
    t = replace(t, text=fonts.drawable_minus(t.text))  # osifont's dash for the minus
    attrs = _with_id(_text_attrs(t), t.id)
    text = sheet_text(t.text, lang)
    runs = subscript_runs(text)
    if len(runs) == 1 and not runs[0][1]:
        return dwg.text(text, **attrs)
    el = dwg.text("", **attrs)
    size = float(str(attrs["font-size"])) * SUB_SIZE
    drop, down = SUB_DROP * t.height, False
    for chars, sub in runs:
        if sub:
            el.add(dwg.tspan(chars, dy=[num(0.0 if down else drop)],
                             **{"font-size": num(size, 3)}))
            down = True
        else:
            el.add(dwg.tspan(chars, dy=[num(-drop)]) if down else dwg.tspan(chars))
            down = False
    return el


def _element(dwg: svgwrite.Drawing, item: Item, lang: str | None = None):
    """The svgwrite element of one item (groups recursively)."""
    if isinstance(item, Group):
        g = dwg.g(**_with_id({}, item.id))
        for child in item.items:
            g.add(_element(dwg, child, lang))
        return g
    if isinstance(item, Line):
        return dwg.line(start=(num(item.p0[0]), num(item.p0[1])),
                        end=(num(item.p1[0]), num(item.p1[1])),
                        **_with_id(_stroke(item.style), item.id))
    if isinstance(item, Polyline):
        if item.closed:
            return dwg.polygon(**_with_id({"points": _pts(item.points),
                                           **_stroke(item.style, filled=True)}, item.id))
        return dwg.polyline(**_with_id({"points": _pts(item.points), **_stroke(item.style)},
                                       item.id))
    if isinstance(item, Circle):
        return dwg.circle(center=(num(item.centre[0]), num(item.centre[1])), r=num(item.r),
                          **_with_id(_stroke(item.style, filled=True), item.id))
    if isinstance(item, Arc):
        return dwg.path(**_with_id({"d": _arc_path(item), **_stroke(item.style)}, item.id))
    if isinstance(item, Arrow):
        g = dwg.g(**_with_id({"class": "arrow"}, item.id))
        shaft, head = arrow_parts(item)
        if shaft is not None:
            (x0, y0), (x1, y1) = shaft
            g.add(dwg.line(start=(num(x0), num(y0)), end=(num(x1), num(y1)),
                           **_stroke(item.style)))
        if head:
            g.add(dwg.polygon(points=_pts(head), fill=item.style.colour, stroke="none"))
        return g
    if isinstance(item, Hatch):
        d = " ".join(f"M{num(a[0])},{num(a[1])} L{num(b[0])},{num(b[1])}"
                     for a, b in hatch_segments(item))
        return dwg.path(**_with_id({"d": d or "M0,0", **_stroke(item.style)}, item.id))
    if isinstance(item, Text):
        return _text(dwg, item, lang)
    raise TypeError(f"cannot draw {type(item).__name__}")


def _check_ids(items) -> None:
    seen: set[str] = set()

    def walk(its) -> None:
        for it in its:
            if it.id is not None:
                if it.id in seen:
                    raise LayoutError(f"SVG id {it.id!r} is used by more than one item")
                seen.add(it.id)
            if isinstance(it, Group):
                walk(it.items)

    walk(items)


def render_svg(sheet: Sheet) -> str:
    """The SVG text of ``sheet`` (deterministic; 1 user unit = 1 mm).

    Raises
    ------
    LayoutError
        If two items carry the same id.
    """
    page = sheet.page
    items = sheet.all_items()
    _check_ids(items)
    dwg = svgwrite.Drawing(
        size=(f"{num(page.width)}mm", f"{num(page.height)}mm"),
        viewBox=f"0 0 {num(page.width)} {num(page.height)}",
        profile="full",
        debug=False,
    )
    dwg.attribs["xmlns:inkscape"] = _INKSCAPE
    tb = sheet.title_block
    if tb is not None and (tb.title or tb.designation):
        dwg.set_desc(title=" ".join(s for s in (tb.designation, tb.title) if s))
    groups = {}
    for name in LAYERS:
        groups[name] = dwg.g(id=f"layer-{name}", **{"inkscape:groupmode": "layer",
                                                   "inkscape:label": name})
        dwg.add(groups[name])
    for it in items:
        groups[it.layer].add(_element(dwg, it, sheet.lang))
    text = dwg.tostring()
    return text + "\n"


def write_svg(sheet: Sheet, path: str | Path, protect: tuple[Path, ...] = ()) -> Path:
    """Write ``render_svg(sheet)`` to ``path`` atomically; returns the path."""
    return write_atomic(path, render_svg(sheet), protect=protect)


__all__ = ["render_svg", "write_svg"]
