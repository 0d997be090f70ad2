"""DXF export of a :class:`graphplan.drawing.sheet.Sheet` (ezdxf, AutoCAD 2010 / R2010 format).

The drawing is the sheet at 1:1 in **model space, millimetres** ($INSUNITS = 4,
$MEASUREMENT = 1): the trim border runs from (0, 0) to (841, 594) for A1. DXF's y axis
points up, the sheet's down, so a point (x, y) of the sheet is written at
``(x, H − y)`` with H the sheet's height; angles stay counter-clockwise as seen, so
arcs and text rotations keep their values.

Layers
    one per layer of the sheet (:data:`graphplan.drawing.items.LAYERS`, same names: frame,
    title, construction, position_plan, velocity_plan, acceleration_plan,
    force_plan, diagrams, dimensions, tables, text), each with a description. Every layer
    is colour 7 (black on paper, white on a dark screen) and continuous; the entities
    carry their own line type and weight.
Lines (GOST 2.303)
    solid lines are ``Continuous``; the dash patterns of the sheet become line types
    defined in the file with the same lengths in mm ($LTSCALE = 1): ``GOST_DASHED``
    (4, 1.5), ``GOST_DASHDOT`` (15, 3, 1, 3), ``GOST_DASHDOTDOT`` (15, 3, 1, 3, 1, 3),
    any other pattern ``GP_DASH<n>``. Widths become the nearest standard DXF
    lineweight: S = 0.7 mm → 0.70, thin 0.25 → 0.25, vectors 0.5 → 0.50.
Items
    Line → LINE; Polyline → LWPOLYLINE; Circle → CIRCLE; Arc → ARC; Arrow → a LINE
    shaft and a solid HATCH head, joined in an unnamed GROUP; Hatch → one LINE per
    hatch line; Text → TEXT (capital height = DXF text height, GOST slant as an
    oblique angle of 15°, anchor start/middle/end on the baseline); a fill other than
    white (a dot, a filled polygon) → a solid HATCH under the outline. White fills are
    not exported: they only mask the paper. Nothing is raster.
Text styles
    ``GOST_B`` names the font of the sheets, osifont (``osifont.ttf``, an ISO 3098 /
    GOST 2.304-like CAD font); texts that osifont cannot letter (Ё, Э, −, ₁ …; see
    :mod:`graphplan.fonts`) use ``DEJAVU_SANS`` or ``DEJAVU_SANS_MONO``. A CAD
    program without the font substitutes its own.
Ids
    An item's id is attached as XDATA of application ``GRAPHPLAN`` (group code 1000).

The file has no timestamps or random GUIDs (ezdxf's fixed metadata): the same sheet
always gives the same bytes.
"""

from __future__ import annotations

import io
import math
from contextlib import contextmanager
from dataclasses import replace
from functools import lru_cache
from pathlib import Path

from .. import fonts
from ..drawing.items import (
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
    Pt,
    Style,
    Text,
    arrow_parts,
    hatch_segments,
)
from ..drawing.sheet import Sheet
from ..files import write_atomic
from ..numbers import decimal_comma
from .extra import require

APPID = "GRAPHPLAN"  #: XDATA application name that carries the items' ids

#: Layer descriptions (English / Russian), by sheet layer.
LAYER_DESCRIPTIONS: dict[str, str] = {
    "frame": "frame and trim border / рамка и граница формата",
    "title": "title block, GOST 2.104 / основная надпись",
    "construction": "construction lines / линии построения",
    "position_plan": "plan of positions / план положений",
    "velocity_plan": "velocity plans / планы скоростей",
    "acceleration_plan": "acceleration plans / планы ускорений",
    "force_plan": "force plans, schemes, Zhukovsky's lever / планы сил, рычаг Жуковского",
    "diagrams": "diagrams / диаграммы",
    "dimensions": "dimensions and arms / размеры и плечи",
    "tables": "tables / таблицы",
    "text": "captions and notes / надписи",
}

#: Dash patterns of the sheets (mm) → GOST 2.303 line types written into the DXF.
GOST_LINETYPES: dict[tuple[float, ...], tuple[str, str]] = {
    (4.0, 1.5): ("GOST_DASHED", "GOST 2.303 dashed / штриховая __ __ __"),
    (15.0, 3.0, 1.0, 3.0): ("GOST_DASHDOT", "GOST 2.303 dash-dot / штрихпунктирная __ . __"),
    (15.0, 3.0, 1.0, 3.0, 1.0, 3.0): (
        "GOST_DASHDOTDOT", "GOST 2.303 dash-dot-dot / штрихпунктирная с двумя точками __ .. __"),
}

#: Font family (graphplan.fonts.FONT_CHAIN) → (DXF text style, font file).
TEXT_STYLES: dict[str, tuple[str, str]] = {
    "osifont": ("GOST_B", "osifont.ttf"),
    "DejaVu Sans": ("DEJAVU_SANS", "DejaVuSans.ttf"),
    "DejaVu Sans Mono": ("DEJAVU_SANS_MONO", "DejaVuSansMono.ttf"),
}
DEFAULT_TEXT_STYLE = "GOST_B"


@lru_cache(maxsize=64)
def _rgb(colour: str) -> tuple[float, float, float] | None:
    """RGB (0…1) of a CSS colour of the sheet; None for "none"."""
    if colour.strip().lower() in ("none", "transparent"):
        return None
    from matplotlib.colors import to_rgb

    return tuple(float(c) for c in to_rgb(colour))  # type: ignore[return-value]


def lineweight(width_mm: float) -> int:
    """The standard DXF lineweight (1/100 mm) nearest to a line width in mm."""
    from ezdxf.lldxf.const import VALID_DXF_LINEWEIGHTS

    return min((w for w in VALID_DXF_LINEWEIGHTS if w > 0),
               key=lambda w: (abs(w - width_mm * 100.0), w))


class _Writer:
    """Adds the items of one sheet to a new ezdxf document."""

    def __init__(self, ezdxf, sheet: Sheet) -> None:
        self.ezdxf = ezdxf
        self.sheet = sheet
        self.height = sheet.page.height
        doc = ezdxf.new("R2010", setup=False, units=4)  # 4: millimetres
        self.doc = doc
        self.msp = doc.modelspace()
        self.linetypes: dict[tuple[float, ...], str] = {}
        self._setup()

    # ---------------------------------------------------------------- document

    def _setup(self) -> None:
        doc, page = self.doc, self.sheet.page
        hdr = doc.header
        hdr["$MEASUREMENT"] = 1  # metric
        hdr["$LUNITS"] = 2  # decimal
        hdr["$LUPREC"] = 2
        hdr["$LTSCALE"] = 1.0
        hdr["$PSLTSCALE"] = 1
        hdr["$CELTSCALE"] = 1.0
        hdr["$LWDISPLAY"] = 1  # show lineweights
        hdr["$LIMMIN"] = (0.0, 0.0)
        hdr["$LIMMAX"] = (page.width, page.height)
        hdr["$EXTMIN"] = (0.0, 0.0, 0.0)
        hdr["$EXTMAX"] = (page.width, page.height, 0.0)
        doc.appids.new(APPID)
        for family, (name, font) in TEXT_STYLES.items():
            style = doc.styles.new(name, dxfattribs={"font": font, "height": 0.0,
                                                     "width": 1.0})
            style.set_extended_font_data(family=family)
        hdr["$TEXTSTYLE"] = DEFAULT_TEXT_STYLE
        for pattern, (name, description) in GOST_LINETYPES.items():
            self._linetype(pattern, name, description)
        for name in LAYERS:
            self._layer(name, LAYER_DESCRIPTIONS.get(name, name))
        doc.set_modelspace_vport(height=page.height * 1.05,
                                 center=(page.width / 2, page.height / 2))
        self._paper_space()
        self.msp.dxf.extmin = (0.0, 0.0, 0.0)
        self.msp.dxf.extmax = (page.width, page.height, 0.0)
        self.msp.dxf.limmin = (0.0, 0.0)
        self.msp.dxf.limmax = (page.width, page.height)

    def _paper_space(self) -> None:
        """Layout named after the format (e.g. "A1"): the paper, and a viewport at 1:1.

        Plotting that layout at 1:1 prints the sheet at its true size. The viewport's
        border is on "Defpoints", which CAD programs never plot.
        """
        page = self.sheet.page
        self.doc.layouts.rename("Layout1", page.format)
        layout = self.doc.layouts.get(page.format)
        layout.page_setup(size=(page.width, page.height), margins=(0, 0, 0, 0), units="mm",
                          scale=(1, 1), name=f"ISO_full_bleed_{page.format}_("
                          f"{page.width:.2f}_x_{page.height:.2f}_MM)")
        defpoints = (self.doc.layers.get("Defpoints") if "Defpoints" in self.doc.layers
                     else self.doc.layers.add("Defpoints", color=7))
        defpoints.dxf.plot = 0
        centre = (page.width / 2, page.height / 2)
        layout.add_viewport(center=centre, size=(page.width, page.height),
                            view_center_point=centre, view_height=page.height,
                            dxfattribs={"layer": "Defpoints"})

    def _layer(self, name: str, description: str) -> None:
        layer = self.doc.layers.add(name, color=7, linetype="Continuous",
                                    lineweight=lineweight(0.25))
        layer.description = description

    def _linetype(self, pattern: tuple[float, ...], name: str | None = None,
                  description: str = "") -> str:
        key = tuple(round(v, 4) for v in pattern)
        if key in self.linetypes:
            return self.linetypes[key]
        if name is None:
            name = f"GP_DASH{len(self.linetypes) - len(GOST_LINETYPES) + 1}"
            description = "dashes / штрихи " + ", ".join(f"{v:g}" for v in key) + " mm"
        # ezdxf pattern: total length, then dashes (> 0) and gaps (< 0) in mm
        elements = [v if i % 2 == 0 else -v for i, v in enumerate(key)]
        self.doc.linetypes.add(name, [sum(key), *elements], description=description)
        self.linetypes[key] = name
        return name

    # ----------------------------------------------------------------- helpers

    def p(self, pt: Pt) -> tuple[float, float]:
        """Sheet point (y down) → DXF point (y up)."""
        return (pt[0], self.height - pt[1])

    def attribs(self, layer: str, width: float, colour: tuple[float, float, float] | None,
                dasharray: tuple[float, ...] | None = None) -> dict:
        a: dict = {"layer": layer, "lineweight": lineweight(width)}
        if dasharray:
            pattern = dasharray if len(dasharray) % 2 == 0 else dasharray * 2
            a["linetype"] = self._linetype(tuple(pattern))
        if colour is not None and colour != (0.0, 0.0, 0.0):
            a["true_color"] = self.ezdxf.colors.rgb2int(
                tuple(round(255 * c) for c in colour))
        return a

    def style_attribs(self, style: Style, layer: str) -> dict:
        return self.attribs(layer, style.width, _rgb(style.colour), style.dasharray)

    def tag(self, entity, ident: str | None):
        if ident is not None:
            entity.set_xdata(APPID, [(1000, ident)])
        return entity

    def solid(self, loops, layer: str, colour: tuple[float, float, float],
              ident: str | None = None):
        """A solid HATCH filling ``loops`` (sheet points) by the even-odd rule.

        Hatch style 0 ("normal": odd parity), so a loop inside another is a hole and a
        loop inside that is filled again, as a glyph's outlines need. The outermost
        loops are flagged external, the others default.
        """
        from ezdxf.lldxf.const import BOUNDARY_PATH_DEFAULT, BOUNDARY_PATH_EXTERNAL
        from shapely import Point
        from shapely.geometry import Polygon

        loops = [loop for loop in loops if len(loop) >= 3]
        polys = [Polygon(loop) for loop in loops]
        attribs = {"layer": layer}
        hatch = self.msp.add_hatch(color=256, dxfattribs=attribs)  # 256: BYLAYER
        hatch.dxf.hatch_style = 0
        if colour != (0.0, 0.0, 0.0):
            hatch.set_solid_fill(color=256, rgb=tuple(round(255 * c) for c in colour))
        for i, loop in enumerate(loops):
            probe = Point(loop[0])
            outer = not any(j != i and q.is_valid and q.contains(probe)
                            for j, q in enumerate(polys))
            hatch.paths.add_polyline_path(
                [self.p(q) for q in loop], is_closed=True,
                flags=BOUNDARY_PATH_EXTERNAL if outer else BOUNDARY_PATH_DEFAULT)
        return self.tag(hatch, ident)

    def fill_colour(self, style: Style) -> tuple[float, float, float] | None:
        fill = _rgb(style.fill) if style.fill else None
        return None if fill is None or fill == (1.0, 1.0, 1.0) else fill

    # ------------------------------------------------------------------- items

    def add(self, item: Item) -> None:
        msp = self.msp
        if isinstance(item, Group):
            for child in item.items:
                self.add(child)
        elif isinstance(item, Line):
            self.tag(msp.add_line(self.p(item.p0), self.p(item.p1),
                                  dxfattribs=self.style_attribs(item.style, item.layer)), item.id)
        elif isinstance(item, Polyline):
            fill = self.fill_colour(item.style) if item.closed else None
            if fill is not None:
                self.solid([item.points], item.layer, fill, item.id)
            self.tag(msp.add_lwpolyline([self.p(q) for q in item.points], close=item.closed,
                                        dxfattribs=self.style_attribs(item.style, item.layer)),
                     item.id)
        elif isinstance(item, Circle):
            fill = self.fill_colour(item.style)
            if fill is not None:
                n = 72
                ring = [(item.centre[0] + item.r * math.cos(2 * math.pi * k / n),
                         item.centre[1] + item.r * math.sin(2 * math.pi * k / n))
                        for k in range(n)]
                self.solid([ring], item.layer, fill, item.id)
            self.tag(msp.add_circle(self.p(item.centre), item.r,
                                    dxfattribs=self.style_attribs(item.style, item.layer)),
                     item.id)
        elif isinstance(item, Arc):
            # counter-clockwise as seen on the sheet is counter-clockwise in DXF's y-up
            self.tag(msp.add_arc(self.p(item.centre), item.r, item.start_deg,
                                 item.start_deg + item.sweep_deg,
                                 dxfattribs=self.style_attribs(item.style, item.layer)), item.id)
        elif isinstance(item, Arrow):
            shaft, head = arrow_parts(item)
            parts = []
            if shaft is not None:
                parts.append(self.tag(msp.add_line(
                    self.p(shaft[0]), self.p(shaft[1]),
                    dxfattribs=self.style_attribs(item.style, item.layer)), item.id))
            if head:
                parts.append(self.solid([head], item.layer,
                                        _rgb(item.style.colour) or (0.0, 0.0, 0.0), item.id))
            if len(parts) > 1:
                self.doc.groups.new().set_data(parts)
        elif isinstance(item, Hatch):
            attribs = self.style_attribs(item.style, item.layer)
            for a, b in hatch_segments(item):
                self.tag(msp.add_line(self.p(a), self.p(b), dxfattribs=attribs), item.id)
        elif isinstance(item, Text):
            self.add_text(item)
        else:
            raise TypeError(f"cannot export {type(item).__name__} to DXF")

    def add_text(self, t: Text) -> None:
        from ezdxf.enums import TextEntityAlignment

        if t.layer != "title":
            t = replace(t, text=fonts.drawable_minus(t.text))  # as the SVG letters it
        family = fonts.choose_family(t.text)
        style = TEXT_STYLES.get(family, (DEFAULT_TEXT_STYLE, ""))[0]
        attribs: dict[str, object] = {"layer": t.layer, "style": style}
        if t.italic:
            attribs["oblique"] = SLANT_DEG  # GOST 2.304 type B: 15° from the vertical
        align = {"start": TextEntityAlignment.LEFT, "middle": TextEntityAlignment.CENTER,
                 "end": TextEntityAlignment.RIGHT}[t.anchor]
        text = t.text
        if self.sheet.lang == "ru" and t.layer != "title":
            text = decimal_comma(text)  # a Russian sheet's decimal comma, as in the SVG
        entity = self.msp.add_text(text, height=t.height, rotation=t.rotate_deg % 360.0,
                                   dxfattribs=attribs)
        entity.set_placement(self.p(t.pos), align=align)
        self.tag(entity, t.id)

@contextmanager
def _fixed_metadata(ezdxf):
    """ezdxf's fixed metadata (dates of 2000-01-01, constant GUIDs, no ezdxf timestamp)."""
    before = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        yield
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = before


def dxf_document(sheet: Sheet):
    """A new ezdxf document holding ``sheet`` at 1:1 in model space (mm).

    Raises
    ------
    MissingExtraError
        If ezdxf is not installed.
    """
    ezdxf = require("ezdxf", "dxf")
    with _fixed_metadata(ezdxf):
        w = _Writer(ezdxf, sheet)
    for item in sheet.all_items():
        w.add(item)
    return w.doc


def dxf_text(sheet: Sheet) -> str:
    """The DXF file of ``sheet`` as text (UTF-8 when written; no timestamps)."""
    ezdxf = require("ezdxf", "dxf")
    doc = dxf_document(sheet)
    _stable_classes(doc)
    stream = io.StringIO()
    with _fixed_metadata(ezdxf):
        doc.write(stream)
    return stream.getvalue()


def _stable_classes(doc) -> None:
    """Register the CLASS entries of the document in an order that is the same every run.

    On writing, ezdxf registers the classes its version requires (a list: a fixed order)
    and then one per entity type in use, iterating over a *set* of type names, whose order
    changes with Python's string hashing (``PYTHONHASHSEED``): the CLASSES section, and so
    the file's bytes, changed from run to run. Registered here first — the required ones
    in ezdxf's order, the others sorted — ezdxf's own registration on writing adds nothing.
    """
    classes = doc.classes.classes  # key (name, C++ class) → DXFClass, in file order
    before = list(classes)
    doc.classes.add_required_classes(doc.dxfversion)
    try:
        from ezdxf.sections.classes import REQ_R2004, REQUIRED_CLASSES

        required = list(REQUIRED_CLASSES.get(doc.dxfversion, REQ_R2004))
    except ImportError:  # another ezdxf: sort them all
        required = []
    rank = {name: i for i, name in enumerate(required)}
    added = [k for k in classes if k not in before]
    order = before + sorted(added, key=lambda k: (rank.get(k[0], len(rank)), k))
    entries = {k: classes[k] for k in order}
    classes.clear()
    classes.update(entries)


def dxf_bytes(sheet: Sheet) -> bytes:
    """The bytes of the DXF file of ``sheet`` (R2010 text DXF, UTF-8)."""
    return dxf_text(sheet).encode("utf-8")


def write_dxf(sheet: Sheet, path: str | Path, protect: tuple[Path, ...] = ()) -> Path:
    """Write the DXF of ``sheet`` to ``path`` atomically; returns the path."""
    return write_atomic(path, dxf_bytes(sheet), protect=protect)


__all__ = ["APPID", "GOST_LINETYPES", "LAYER_DESCRIPTIONS", "TEXT_STYLES", "dxf_bytes",
           "dxf_document", "dxf_text", "lineweight", "write_dxf"]
