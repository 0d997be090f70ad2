"""Exports of the sheets: DXF (read back with ezdxf), PDF (read back with pypdf), PNG.

Every DXF check compares the DXF with the SVG of the same sheet, parsed here as XML
(not with the Sheet object): the SVG renderer and the DXF writer are two routes from
the items, so an error of either shows. The SVG is y-down, the DXF y-up: an SVG point
(x, y) must be the DXF point (x, H − y), H = 594 mm for A1.
"""

from __future__ import annotations

import io
import math
import re
import sys
import xml.etree.ElementTree as ET
from collections import Counter
from dataclasses import dataclass

import numpy as np
import pytest

ezdxf = pytest.importorskip("ezdxf")
pytest.importorskip("typst")
pytest.importorskip("resvg_py")
pypdf = pytest.importorskip("pypdf")

from graphplan.drawing.items import (  # noqa: E402
    DASHDOT,
    DASHDOTDOT,
    DASHED,
    LAYERS,
    MAIN,
    MEDIUM,
    THIN,
    Arc,
    Arrow,
    Circle,
    Group,
    Hatch,
    Line,
    Polyline,
    Style,
    Text,
)
from graphplan.drawing.sheet import Page, Sheet  # noqa: E402
from graphplan.drawing.title_block import TitleBlock  # noqa: E402
from graphplan.errors import GraphplanError, InputError  # noqa: E402
from graphplan.render import dxf as dxf_mod  # noqa: E402
from graphplan.render import (  # noqa: E402
    extra,
    pdf_bytes,
)
from graphplan.render import formats as exports  # noqa: E402
from graphplan.render.png import png_bytes, png_size, svg_to_png_bytes  # noqa: E402
from graphplan.render.svg import render_svg  # noqa: E402

SVG = "{http://www.w3.org/2000/svg}"
A1 = (841.0, 594.0)
TOL = 0.01  # mm: the SVG writes coordinates rounded to 0.01 mm


# ------------------------------------------------------------------ the sheets

def synthetic_sheet() -> Sheet:
    """Every kind of item, on layers the bundled sheets leave empty too."""
    items = (
        Line((100, 150), (140, 150), MAIN, layer="position_plan", id="ground"),
        Hatch(((100, 150), (140, 150), (140, 154), (100, 154)), layer="position_plan",
              id="ground-hatch"),
        Circle((120, 150), 1.5, Style(0.5, fill="white"), layer="position_plan", id="joint"),
        Circle((130, 120), 0.8, Style(0.25, fill="black"), layer="position_plan", id="dot"),
        Line((60, 150), (300, 150), DASHDOT, layer="construction", id="axis"),
        Line((120, 60), (120, 250), DASHDOTDOT, layer="construction", id="extreme"),
        Line((60, 260), (300, 260), DASHED, layer="construction", id="hidden"),
        Arc((120, 150), 40, 0, 90, DASHDOT, layer="construction", id="traj"),
        Arc((200, 150), 10, 300, 30, THIN, layer="construction", id="wrap-arc"),
        Arrow((400, 200), (460, 160), MEDIUM, layer="velocity_plan", id="v-a"),
        Polyline(((400, 300), (450, 280), (500, 310)), THIN, layer="diagrams", id="curve"),
        Polyline(((520, 300), (540, 300), (530, 320)), Style(0.25, fill="black"), True,
                 layer="force_plan", id="tri"),
        Group((Line((300, 400), (350, 420), THIN, layer="dimensions"),
               Text((320, 405), "h21 = 12 мм", 3.5, layer="dimensions")),
              layer="dimensions", id="arm"),
        Text((200, 80), "Ряд", 5.0, rotate_deg=90.0, layer="text", id="turned"),
        Text((200, 100), "ЭЁ ∥ √1", 3.5, anchor="end", layer="text", id="dejavu"),
    )
    tb = TitleBlock(designation="ТММ.00.01", title="Проверка экспорта", sheet=1, sheets=1)
    return Sheet(Page("A1"), items, tb)


class Exports:
    """The sheets under test and their exports, each made once for this module (the ``ex``
    fixture): ``"press-1"``, ``"press-2"``, ``"shaper-1"``, ``"shaper-2"`` — an example's
    sheet, drawn once for the session (``drawn``, tests/conftest.py) — or ``"synthetic"``."""

    def __init__(self, drawn):
        self._drawn = drawn
        self._made: dict = {}

    def _once(self, key, make):
        if key not in self._made:
            self._made[key] = make()
        return self._made[key]

    def sheet(self, name: str) -> Sheet:
        if name == "synthetic":
            return self._once(name, synthetic_sheet)
        example, number = name.split("-")
        return self._drawn(example, int(number))

    def svg(self, name: str) -> str:
        return self._once(("svg", name), lambda: render_svg(self.sheet(name)))

    def dxf(self, name: str):
        """The DXF of the sheet, written to bytes and read back."""
        return self._once(("dxf", name), lambda: ezdxf.read(io.StringIO(
            dxf_mod.dxf_bytes(self.sheet(name)).decode("utf-8"))))

    def layers(self, name: str) -> dict[str, SvgLayer]:
        return self._once(("layers", name), lambda: svg_layers(self.svg(name)))

    def pdf(self, name: str):
        return self._once(("pdf", name), lambda: pypdf.PdfReader(io.BytesIO(
            pdf_bytes(self.sheet(name), self.svg(name)))))


@pytest.fixture(scope="module")
def ex(drawn) -> Exports:
    return Exports(drawn)


SHEETS = ["press-1", "press-2", "shaper-1", "shaper-2", "synthetic"]
REAL = ["press-1", "press-2", "shaper-1"]


# ------------------------------------------------------------ the SVG, parsed

@dataclass
class SvgLayer:
    lines: list  # (x1, y1, x2, y2, width, dash)
    hatch_segments: list  # (x1, y1, x2, y2)
    polys: list  # (points, closed, width, fill)
    heads: list  # arrowhead polygons
    arrows: int  # arrows with a shaft and a head
    circles: list  # (cx, cy, r, fill)
    arcs: list  # (start, end, r)
    texts: list  # (text, x, y, rotation, family)
    dashes: Counter  # (DXF entity type, dash pattern) of the dashed elements


def _f(el, name):
    return float(el.get(name))


def _points(text):
    v = [float(s) for s in re.split(r"[ ,]+", text.strip())]
    return list(zip(v[0::2], v[1::2], strict=True))


def svg_layers(svg_text: str) -> dict[str, SvgLayer]:
    """An SVG's layers, parsed as XML."""
    root = ET.fromstring(svg_text)
    out = {}
    for g in root.findall(f"{SVG}g"):
        layer = g.get("id").removeprefix("layer-")
        data = SvgLayer([], [], [], [], 0, [], [], [], Counter())

        def walk(el, in_arrow=False, data=data):
            for ch in el:
                tag = ch.tag.removeprefix(SVG)
                if ch.get("stroke-dasharray"):
                    dash = tuple(float(v) for v in ch.get("stroke-dasharray").split(","))
                    kind = {"line": "LINE", "polyline": "LWPOLYLINE", "polygon": "LWPOLYLINE",
                            "circle": "CIRCLE"}.get(tag)
                    if tag == "path":
                        kind = "ARC" if "A" in ch.get("d") else "LINE"
                    data.dashes[(kind, dash)] += (ch.get("d").count("M") if kind == "LINE"
                                                  and tag == "path" else 1)
                if tag == "g":
                    arrow = ch.get("class") == "arrow"
                    if arrow and ch.find(f"{SVG}line") is not None \
                            and ch.find(f"{SVG}polygon") is not None:
                        data.arrows += 1
                    walk(ch, arrow)
                elif tag == "line":
                    dash = ch.get("stroke-dasharray")
                    data.lines.append((_f(ch, "x1"), _f(ch, "y1"), _f(ch, "x2"), _f(ch, "y2"),
                                       _f(ch, "stroke-width"),
                                       tuple(float(v) for v in dash.split(",")) if dash else None))
                elif tag in ("polyline", "polygon"):
                    if in_arrow and ch.get("stroke") == "none":
                        data.heads.append(_points(ch.get("points")))
                    else:
                        data.polys.append((_points(ch.get("points")), tag == "polygon",
                                           _f(ch, "stroke-width"), ch.get("fill")))
                elif tag == "circle":
                    data.circles.append((_f(ch, "cx"), _f(ch, "cy"), _f(ch, "r"), ch.get("fill")))
                elif tag == "path":
                    d = ch.get("d")
                    if "A" in d:
                        nums = [float(v) for v in re.findall(r"-?\d+\.?\d*", d)]
                        # M x,y A r,r 0 large 0 x,y [A …]: start, radius, end of the last arc
                        data.arcs.append(((nums[0], nums[1]), (nums[-2], nums[-1]), nums[2]))
                    else:
                        for seg in re.findall(r"M([-\d.]+),([-\d.]+) L([-\d.]+),([-\d.]+)", d):
                            data.hatch_segments.append(tuple(float(v) for v in seg))
                elif tag == "text":
                    rot = re.search(r"rotate\(([-\d.]+)", ch.get("transform") or "")
                    family = ch.get("font-family").split(",")[0].strip().strip("'")
                    data.texts.append(("".join(ch.itertext()), _f(ch, "x"), _f(ch, "y"),
                                       -float(rot.group(1)) % 360 if rot else 0.0, family))

        walk(g)
        out[layer] = data
    return out


def flip(x, y, h=A1[1]):
    return (x, h - y)


def entities(doc, layer=None, kind=None):
    return [e for e in doc.modelspace()
            if (layer is None or e.dxf.layer == layer) and (kind is None or e.dxftype() == kind)]


# ----------------------------------------------------------------------- DXF

@pytest.mark.parametrize("name", SHEETS)
def test_dxf_reads_back_and_audits_clean(ex, name):
    doc = ex.dxf(name)
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e.message) for e in auditor.errors]
    assert not auditor.has_fixes, [str(e.message) for e in auditor.fixes]
    assert doc.dxfversion >= "AC1024"  # R2010 or later
    assert doc.header["$INSUNITS"] == 4 and doc.header["$MEASUREMENT"] == 1  # mm, metric
    assert not [e for e in doc.entitydb.values() if e.dxftype() in ("IMAGE", "OLE2FRAME",
                                                                    "WIPEOUT")]


@pytest.mark.parametrize("name", SHEETS)
def test_dxf_extents_are_the_sheet(ex, name):
    from ezdxf import bbox

    ext = bbox.extents(ex.dxf(name).modelspace())
    assert ext.extmin.x == pytest.approx(0.0, abs=1e-9)
    assert ext.extmin.y == pytest.approx(0.0, abs=1e-9)
    assert ext.extmax.x == pytest.approx(A1[0], abs=1e-9)
    assert ext.extmax.y == pytest.approx(A1[1], abs=1e-9)


@pytest.mark.parametrize("name", SHEETS)
def test_dxf_layers_are_the_sheets_layers_and_hold_their_content(ex, name):
    doc = ex.dxf(name)
    svg = ex.layers(name)
    for layer in LAYERS:
        assert layer in doc.layers
        assert doc.layers.get(layer).description  # says what the layer holds
    for layer, data in svg.items():
        drawn = (data.lines or data.hatch_segments or data.polys or data.heads or data.circles
                 or data.arcs or data.texts)
        assert bool(entities(doc, layer)) == bool(drawn), layer
    assert not entities(doc, "0")
    used = {e.dxf.layer for e in doc.modelspace()}
    expected = {k for k, d in svg.items() if d.lines or d.polys or d.texts or d.circles}
    assert expected <= used
    if name.startswith("press"):  # the press's sheets: the plans of their own
        assert {"frame", "title", "tables", "text"} <= used
        assert ({"position_plan", "velocity_plan", "acceleration_plan"} <= used
                if name == "press-1" else "force_plan" in used)
        if name in ("press-1", "press-2"):  # the plans' thin lines; h21 and the lever's arms
            assert "construction" in used
            assert ("dimensions" in used) == (name == "press-2")


@pytest.mark.parametrize("name", SHEETS)
def test_dxf_entity_counts_follow_the_svg(ex, name):
    doc = ex.dxf(name)
    for layer, d in ex.layers(name).items():
        count = Counter(e.dxftype() for e in entities(doc, layer))
        filled = sum(1 for *_, fill in d.circles if fill not in ("none", "white")) + sum(
            1 for _, closed, _, fill in d.polys if closed and fill not in ("none", "white"))
        assert count["LINE"] == len(d.lines) + len(d.hatch_segments), layer
        assert count["LWPOLYLINE"] == len(d.polys), layer
        assert count["CIRCLE"] == len(d.circles), layer
        assert count["ARC"] == len(d.arcs), layer
        assert count["TEXT"] == len(d.texts), layer
        assert count["HATCH"] == len(d.heads) + filled, layer
    # each vector's shaft and head are one group
    groups = [g for _, g in doc.groups]
    assert len(groups) == sum(d.arrows for d in ex.layers(name).values())
    assert all(sorted(e.dxftype() for e in g) == ["HATCH", "LINE"] for g in groups)


def _match(svg_segs, dxf_segs):
    """Largest distance of each SVG segment to its nearest DXF segment (either direction)."""
    a = np.asarray(svg_segs, dtype=float).reshape(-1, 1, 4)
    b = np.asarray(dxf_segs, dtype=float).reshape(1, -1, 4)
    fwd = np.max(np.abs(a - b), axis=2)
    rev = np.max(np.abs(a - b[..., [2, 3, 0, 1]]), axis=2)
    return np.min(np.minimum(fwd, rev), axis=1)


@pytest.mark.parametrize("name", SHEETS)
def test_dxf_lines_are_the_svg_lines_flipped(ex, name):
    """Every line: same length to 0.01 mm, same place with y turned up, same weight."""
    doc = ex.dxf(name)
    main_checked = 0
    for layer, d in ex.layers(name).items():
        dxf_lines = entities(doc, layer, "LINE")
        segs = [(*flip(x1, y1), *flip(x2, y2)) for x1, y1, x2, y2, *_ in d.lines]
        segs += [(*flip(x1, y1), *flip(x2, y2)) for x1, y1, x2, y2 in d.hatch_segments]
        got = [(e.dxf.start.x, e.dxf.start.y, e.dxf.end.x, e.dxf.end.y) for e in dxf_lines]
        assert len(got) == len(segs)
        if not segs:
            continue
        assert _match(segs, got).max() <= TOL / 2 + 1e-9  # each coordinate rounded to 0.01
        # the main lines (S = 0.7 mm) by length, as the issue asks
        svg_main = sorted(math.dist((x1, y1), (x2, y2))
                          for x1, y1, x2, y2, w, _ in d.lines if w == 0.7)
        dxf_main = sorted(e.dxf.start.distance(e.dxf.end) for e in dxf_lines
                          if e.dxf.lineweight == 70)
        assert len(svg_main) == len(dxf_main), layer
        assert np.allclose(svg_main, dxf_main, atol=TOL, rtol=0), layer
        main_checked += len(svg_main)
        # weights: the SVG widths in 1/100 mm (0.25 → 25, 0.5 → 50, 0.7 → 70)
        svg_w = Counter(round(w * 100) for *_, w, _ in d.lines)
        svg_w[25] += 0  # hatch lines are thin
        dxf_w = Counter(e.dxf.lineweight for e in dxf_lines)
        dxf_w.subtract({25: len(d.hatch_segments)})
        assert +svg_w == +dxf_w, layer
    if name != "synthetic":
        assert main_checked >= 20  # the title block alone has 19 main lines


@pytest.mark.parametrize("name", SHEETS)
def test_dxf_polylines_circles_and_arcs_are_in_place(ex, name):
    doc = ex.dxf(name)
    for layer, d in ex.layers(name).items():
        dxf_polys = entities(doc, layer, "LWPOLYLINE")
        assert len(dxf_polys) == len(d.polys)
        for pts, closed, width, _ in d.polys:  # each SVG polyline has its DXF twin
            twins = [e for e in dxf_polys if len(e) == len(pts) and np.allclose(
                [flip(x, y) for x, y in e.get_points("xy")], pts, atol=TOL / 2 + 1e-9)]
            assert twins, (layer, pts[:2])
            assert any(e.closed == closed and e.dxf.lineweight == round(width * 100)
                       for e in twins)
        circles = np.array([(*flip(e.dxf.center.x, e.dxf.center.y), e.dxf.radius)
                            for e in entities(doc, layer, "CIRCLE")]).reshape(-1, 3)
        assert len(circles) == len(d.circles)
        for x, y, r, _ in d.circles:
            assert np.abs(circles - (x, y, r)).max(axis=1).min() <= TOL / 2 + 1e-9
        arcs = entities(doc, layer, "ARC")
        assert len(arcs) == len(d.arcs)
        for start, end, r in d.arcs:
            # the arc runs counter-clockwise from start to end both on the sheet and in DXF
            assert any(flip(*e.start_point.vec2) == pytest.approx(start, abs=TOL)
                       and flip(*e.end_point.vec2) == pytest.approx(end, abs=TOL)
                       and e.dxf.radius == pytest.approx(r, abs=TOL / 2) for e in arcs)


@pytest.mark.parametrize("name", SHEETS)
def test_dxf_texts_are_the_svg_texts_with_the_gost_style(ex, name):
    doc = ex.dxf(name)
    for layer, d in ex.layers(name).items():
        got = []
        for e in entities(doc, layer, "TEXT"):
            anchor = e.dxf.insert if e.dxf.halign == 0 else e.dxf.align_point
            got.append((e.dxf.text, round(e.dxf.rotation % 360, 2), e.dxf.style,
                        anchor.x, anchor.y))
            assert e.dxf.oblique == 15.0  # GOST 2.304 type B slant
            assert e.dxf.valign == 0  # baseline, as the SVG's y
        want = [(t, round(rot, 2), dxf_mod.TEXT_STYLES[family][0], x, A1[1] - y)
                for t, x, y, rot, family in d.texts]
        # the same texts, styles and angles; each anchor at its SVG twin's to 0.01 mm (the
        # files keep 2 decimals, and y flipped from the SVG's can round the other way at a tie)
        assert Counter(g[:3] for g in got) == Counter(w[:3] for w in want), layer
        for g in got:
            twin = min((w for w in want if w[:3] == g[:3]),
                       key=lambda w: max(abs(w[3] - g[3]), abs(w[4] - g[4])))
            assert max(abs(twin[3] - g[3]), abs(twin[4] - g[4])) <= 0.011, (layer, g, twin)
            want.remove(twin)
    style = doc.styles.get("GOST_B")
    assert style.dxf.font == "osifont.ttf"
    assert doc.header["$TEXTSTYLE"] == "GOST_B"


@pytest.mark.parametrize("name", SHEETS)
def test_dxf_line_types_are_the_gost_dash_patterns(ex, name):
    doc = ex.dxf(name)
    for layer, d in ex.layers(name).items():
        got = Counter()
        for e in entities(doc, layer):
            lt = e.dxf.get("linetype", "BYLAYER")
            if lt not in ("BYLAYER", "Continuous"):
                tags = doc.linetypes.get(lt).pattern_tags.tags
                got[(e.dxftype(), tuple(abs(t.value) for t in tags if t.code == 49))] += 1
        assert got == d.dashes, layer
    for pattern, (lt, _) in dxf_mod.GOST_LINETYPES.items():
        tags = doc.linetypes.get(lt).pattern_tags.tags
        assert tuple(abs(t.value) for t in tags if t.code == 49) == pattern
    assert doc.header["$LTSCALE"] == 1.0


def test_synthetic_sheet_uses_every_gost_line_type_and_style(ex):
    doc = ex.dxf("synthetic")
    by_id = {}
    for e in doc.modelspace():
        if e.has_xdata(dxf_mod.APPID):
            by_id.setdefault(e.get_xdata(dxf_mod.APPID)[0].value, []).append(e)
    assert by_id["axis"][0].dxf.linetype == "GOST_DASHDOT"
    assert by_id["extreme"][0].dxf.linetype == "GOST_DASHDOTDOT"
    assert by_id["hidden"][0].dxf.linetype == "GOST_DASHED"
    assert by_id["traj"][0].dxf.linetype == "GOST_DASHDOT"
    assert by_id["ground"][0].dxf.lineweight == 70 and by_id["hidden"][0].dxf.lineweight == 25
    # ∥ and √ are not in osifont: DejaVu lettering, as on the SVG
    assert by_id["dejavu"][0].dxf.style == "DEJAVU_SANS"
    assert by_id["turned"][0].dxf.rotation == 90.0
    # the wrapping arc 300° → 30° (90° of sweep) keeps its sweep
    wrap = by_id["wrap-arc"][0]
    assert (wrap.dxf.end_angle - wrap.dxf.start_angle) % 360 == pytest.approx(90.0)
    # filled dot: a hatch; white joint: an outline only
    assert sorted(e.dxftype() for e in by_id["dot"]) == ["CIRCLE", "HATCH"]
    assert [e.dxftype() for e in by_id["joint"]] == ["CIRCLE"]
    # the vector: shaft to the head's base, head tip at p1 (460, 160) → (460, 434)
    head = next(e for e in by_id["v-a"] if e.dxftype() == "HATCH")
    tip = head.paths[0].vertices[0]
    assert (tip[0], tip[1]) == pytest.approx((460.0, A1[1] - 160.0))
    # the layers the bundled sheets leave empty are filled here
    assert entities(doc, "construction") and entities(doc, "dimensions")


@pytest.mark.parametrize("name", ["press-1", "synthetic"])
def test_dxf_paper_space_plots_the_sheet_at_one_to_one(ex, name):
    doc = ex.dxf(name)
    layout = doc.layouts.get("A1")
    assert (layout.dxf.paper_width, layout.dxf.paper_height) == A1
    vp = [e for e in layout if e.dxftype() == "VIEWPORT" and e.dxf.id > 1]
    assert len(vp) == 1
    assert (vp[0].dxf.width, vp[0].dxf.height) == A1
    assert vp[0].dxf.view_height == A1[1]  # 594 mm of model in 594 mm of paper: 1:1
    assert not doc.layers.get("Defpoints").dxf.plot


def test_other_formats_keep_their_true_size():
    """An A3 sheet: DXF extents, paper-space layout and PDF page are 420×297 mm."""
    from ezdxf import bbox

    a3 = Sheet(Page("A3"), (), TitleBlock(designation="ТММ.00.03", title="A3"))
    doc = ezdxf.read(io.StringIO(dxf_mod.dxf_text(a3)))
    ext = bbox.extents(doc.modelspace())
    assert (ext.extmin.x, ext.extmin.y, ext.extmax.x, ext.extmax.y) == pytest.approx(
        (0, 0, 420, 297), abs=1e-9)
    layout = doc.layouts.get("A3")
    assert (layout.dxf.paper_width, layout.dxf.paper_height) == (420, 297)
    box = pypdf.PdfReader(io.BytesIO(pdf_bytes(a3))).pages[0].mediabox
    assert (float(box.width) * 25.4 / 72, float(box.height) * 25.4 / 72) == pytest.approx(
        (420, 297), abs=0.1)


def test_dxf_is_deterministic(ex):
    s = ex.sheet("press-2")
    assert dxf_mod.dxf_bytes(s) == dxf_mod.dxf_bytes(s)


# ----------------------------------------------------------------------- PDF

@pytest.mark.parametrize("name", REAL)
def test_pdf_is_one_page_at_true_size(ex, name):
    reader = ex.pdf(name)
    assert len(reader.pages) == 1
    box = reader.pages[0].mediabox
    assert float(box.width) * 25.4 / 72 == pytest.approx(A1[0], abs=0.1)
    assert float(box.height) * 25.4 / 72 == pytest.approx(A1[1], abs=0.1)


def _fonts(page):
    out = []
    for font in page["/Resources"]["/Font"].values():
        font = font.get_object()
        desc = (font["/DescendantFonts"][0].get_object()["/FontDescriptor"]
                if "/DescendantFonts" in font else font["/FontDescriptor"]).get_object()
        out.append((str(font["/BaseFont"]), any(k in desc for k in
                                               ("/FontFile", "/FontFile2", "/FontFile3"))))
    return out


@pytest.mark.parametrize("name", REAL)
def test_pdf_fonts_are_embedded_and_the_text_is_text(ex, name):
    page = ex.pdf(name).pages[0]
    fonts = _fonts(page)
    assert fonts and all(embedded for _, embedded in fonts), fonts
    assert any(base.split("+")[-1] == "osifont" for base, _ in fonts), fonts
    text = page.extract_text()
    assert ex.sheet(name).title_block.designation in text
    assert "Масштаб" in text  # a printed label of the title block
    xobjects = page["/Resources"].get("/XObject", {})
    assert not [x for x in xobjects.values() if x.get_object().get("/Subtype") == "/Image"]


def test_pdf_is_deterministic_and_titled(ex):
    s = ex.sheet("press-2")
    first = pdf_bytes(s)
    assert first == pdf_bytes(s)
    meta = pypdf.PdfReader(io.BytesIO(first)).metadata
    assert meta["/Title"].startswith(s.title_block.designation)
    assert "/CreationDate" not in meta


# ----------------------------------------------------------------------- PNG

@pytest.mark.parametrize("name", REAL)
def test_png_has_the_sheets_aspect_and_is_not_blank(ex, name):
    from PIL import Image

    dpi = 40
    img = Image.open(io.BytesIO(png_bytes(ex.sheet(name), dpi, ex.svg(name)))).convert("L")
    # 841 mm at 40 dpi: 841/25.4·40 = 1324.4 → 1324 px; 594 mm → 935.4 → 935 px
    assert img.size == png_size(ex.sheet(name), dpi) == (1324, 935)
    assert abs(img.size[0] / img.size[1] - A1[0] / A1[1]) <= 1 / img.size[1]
    px = np.asarray(img)
    dark = (px < 128).mean()
    assert 0.005 < dark < 0.3
    # the frame's main line shows: 20 mm from the left edge (column 31)
    assert (px[:, round(20 * dpi / 25.4)] < 160).mean() > 0.9
    assert px[0, 0] > 128 or px[5, 5] > 200  # white paper in the margin


def test_png_dpi_is_checked(ex):
    with pytest.raises(InputError, match="dpi"):
        png_bytes(ex.sheet("synthetic"), 0)
    with pytest.raises(InputError, match="dpi"):
        png_bytes(ex.sheet("synthetic"), float("nan"))
    with pytest.raises(InputError, match="px"):
        png_bytes(ex.sheet("synthetic"), 1000)


# ------------------------------------------------------- formats and writing

def test_parse_formats():
    assert exports.parse_formats("png, SVG,dxf,svg") == ("svg", "dxf", "png")
    assert exports.parse_formats("all") == exports.FORMATS
    assert exports.parse_formats(["pdf"]) == ("pdf",)
    for bad in ("svg,jpg", "", " , "):
        with pytest.raises(InputError) as err:
            exports.parse_formats(bad)
        assert "\n" not in str(err.value) and "svg, dxf, pdf, png" in str(err.value)


def test_write_exports_writes_every_format_atomically(ex, tmp_path):
    sheets = {"sheet1": ex.sheet("synthetic")}
    written = exports.write_exports(sheets, tmp_path / "out", "svg,dxf,pdf,png", dpi=20)
    names = [p.name for p in written]
    assert names == ["sheet1.svg", "sheet1.dxf", "sheet1.pdf", "sheet1.png"]
    assert (tmp_path / "out/sheet1.svg").read_text(encoding="utf-8") == render_svg(
        sheets["sheet1"])
    assert (tmp_path / "out/sheet1.dxf").read_bytes() == dxf_mod.dxf_bytes(sheets["sheet1"])
    assert (tmp_path / "out/sheet1.pdf").read_bytes().startswith(b"%PDF")
    assert (tmp_path / "out/sheet1.png").read_bytes().startswith(b"\x89PNG")
    assert not [p for p in (tmp_path / "out").iterdir() if p.name.endswith(".tmp")]
    variant = tmp_path / "out" / "sheet1.dxf"
    with pytest.raises(InputError, match="refusing"):
        exports.write_exports(sheets, tmp_path / "out", ["dxf"], protect=(variant,))
    (tmp_path / "file").write_text("x")
    with pytest.raises(InputError, match="directory"):
        exports.write_exports(sheets, tmp_path / "file", ["svg"])


# ---------------------------------------------------- missing optional extras

@pytest.mark.parametrize("module, fmt, call", [
    ("ezdxf", "dxf", lambda s: dxf_mod.dxf_bytes(s)),
    ("typst", "pdf", lambda s: pdf_bytes(s)),
    ("resvg_py", "png", lambda s: png_bytes(s, 10)),
    ("ezdxf", "dxf", lambda s: exports.sheet_files({"s": s}, ["svg", "dxf"])),
])
def test_a_missing_extra_is_one_line_naming_it(ex, monkeypatch, module, fmt, call):
    monkeypatch.delenv(extra.ENGINE_ENV, raising=False)
    monkeypatch.setitem(sys.modules, module, None)  # `import module` now fails
    with pytest.raises(extra.MissingExtraError) as err:
        call(ex.sheet("synthetic"))
    msg = str(err.value)
    assert isinstance(err.value, GraphplanError) and isinstance(err.value, ImportError)
    assert "\n" not in msg
    assert f"'{module}'" in msg and "pip install 'graphplan[export]'" in msg
    assert msg.startswith(fmt.upper())


def test_a_missing_cairo_library_is_reported_too(monkeypatch):
    def no_cairo(name):
        raise OSError("no library called \"cairo-2\" was found\ncannot load library 'x'")

    monkeypatch.setattr(extra.importlib, "import_module", no_cairo)
    with pytest.raises(extra.MissingExtraError) as err:
        exports.check_formats(["svg", "png"], engine="cairo")
    assert "\n" not in str(err.value) and "cairo" in str(err.value)
    assert "graphplan[export]" in str(err.value)
    exports.check_formats(["svg"])  # SVG needs no extra


# ------------------------------------------------------------------ engines

def test_engines_are_chosen_by_name_or_environment(monkeypatch):
    monkeypatch.delenv(extra.ENGINE_ENV, raising=False)
    assert extra.engine_for("pdf") == "typst" and extra.engine_for("png") == "resvg"
    assert extra.engine_for("dxf") == ""
    monkeypatch.setenv(extra.ENGINE_ENV, "cairo")
    assert extra.engine_for("pdf") == "cairo" and extra.package_for("png") == "cairosvg"
    assert extra.engine_for("pdf", "typst") == "typst"  # the argument wins
    with pytest.raises(InputError, match="engine") as err:
        extra.engine_for("pdf", "ghostscript")
    assert "\n" not in str(err.value)


def test_the_pdf_letters_in_the_bundled_fonts_without_system_fonts(ex, monkeypatch, tmp_path):
    # the same bytes whatever the machine has: typst is given the bundled fonts only
    from graphplan import fonts as fonts_mod

    monkeypatch.delenv(extra.ENGINE_ENV, raising=False)
    s, text = ex.sheet("press-1"), ex.svg("press-1")
    seen = pdf_bytes(s, text)
    monkeypatch.setenv(fonts_mod.FONT_PATH_ENV, str(tmp_path / "nowhere"))
    assert pdf_bytes(s, text) == seen
    names = {base.split("+")[-1] for base, _ in _fonts(pypdf.PdfReader(io.BytesIO(seen)).pages[0])}
    assert names <= {"osifont", "DejaVuSans", "DejaVuSansMono"}, names


def test_the_png_is_the_same_pixels_without_system_fonts(ex, monkeypatch, tmp_path):
    from graphplan import fonts as fonts_mod

    monkeypatch.delenv(extra.ENGINE_ENV, raising=False)
    text = ex.svg("press-2")
    seen = svg_to_png_bytes(text, 15)
    monkeypatch.setenv(fonts_mod.FONT_PATH_ENV, str(tmp_path / "nowhere"))
    assert svg_to_png_bytes(text, 15) == seen


def _cairo_or_skip():
    try:
        extra.require_format("pdf", "cairo")
    except extra.MissingExtraError as exc:
        pytest.skip(str(exc))


def test_the_cairo_engine_stays_an_option(ex):
    _cairo_or_skip()
    s, text = ex.sheet("press-2"), ex.svg("press-2")
    reader = pypdf.PdfReader(io.BytesIO(pdf_bytes(s, text, engine="cairo")))
    box = reader.pages[0].mediabox
    assert float(box.width) * 25.4 / 72 == pytest.approx(A1[0], abs=0.1)
    assert reader.metadata["/Creator"] == "graphplan" and "/CreationDate" not in reader.metadata
    assert png_bytes(s, 20, text, engine="cairo").startswith(b"\x89PNG")


def test_a_character_no_bundled_font_draws_comes_from_a_system_font(ex, monkeypatch, tmp_path):
    # '⌢' (U+2322) is in none of osifont, DejaVu Sans, DejaVu Sans Mono; matplotlib's
    # STIX font has it. Put that font in the only folder searched for system fonts.
    import shutil

    import matplotlib

    from graphplan import fonts as fonts_mod

    monkeypatch.delenv(extra.ENGINE_ENV, raising=False)
    folder = tmp_path / "fonts"
    folder.mkdir()
    shutil.copy(f"{matplotlib.get_data_path()}/fonts/ttf/STIXGeneral.ttf", folder)
    a3 = Sheet(Page("A3"), (), TitleBlock(designation="ТММ.00.03", title="Дуга ⌢ AB"))
    text = render_svg(a3)
    assert fonts_mod.uncovered_chars("Дуга ⌢ AB") == "⌢"
    monkeypatch.setenv(fonts_mod.FONT_PATH_ENV, str(folder))
    assert fonts_mod.fallback_font_files(fonts_mod.text_of_svg(text)) == (
        folder / "STIXGeneral.ttf",)
    names = {b.split("+")[-1] for b, _ in _fonts(pypdf.PdfReader(io.BytesIO(
        pdf_bytes(a3, text))).pages[0])}
    assert "STIXGeneral-Regular" in names and "osifont" in names, names
    with_stix = svg_to_png_bytes(text, 20)
    monkeypatch.setenv(fonts_mod.FONT_PATH_ENV, str(tmp_path / "nowhere"))
    assert fonts_mod.fallback_font_files(fonts_mod.text_of_svg(text)) == ()
    assert svg_to_png_bytes(text, 20) != with_stix  # the arc is drawn only with STIX
    # a sheet of Russian and English text needs no system font at all
    assert fonts_mod.fallback_font_files(fonts_mod.text_of_svg(ex.svg("press-1"))) == ()
