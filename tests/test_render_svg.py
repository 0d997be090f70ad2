"""SVG output, checked structurally (parsed XML), and its PNG preview."""

import math
import re
import xml.etree.ElementTree as ET

import pytest

from graphplan import fonts
from graphplan.drawing import (
    DASHDOT,
    DASHDOTDOT,
    FORM1_SEGMENTS,
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
    Page,
    Polyline,
    Sheet,
    Style,
    Text,
    TitleBlock,
    check_layout,
    signatures,
    table_items,
)
from graphplan.errors import GraphplanError, LayoutError
from graphplan.numbers import trimmed as num
from graphplan.render.svg import render_svg, write_svg

NS = {"svg": "http://www.w3.org/2000/svg"}
SVG = "{http://www.w3.org/2000/svg}"


def make_sheet(fmt="A1"):
    tb = TitleBlock(
        designation="ТММ.КП.00.01",
        title="Кривошипный пресс. Кинематический анализ",
        litera="У",
        sheet=1,
        sheets=3,
        organisation="Кафедра ТММ, гр. МТ-21",
        signatures=signatures("Иванов И.И.", "Петров П.П."),
    )
    items = (
        Line((100, 150), (140, 150), MAIN, layer="position_plan", id="ground"),
        Hatch(((100, 150), (140, 150), (140, 154), (100, 154)), layer="position_plan",
              id="ground-hatch"),
        Circle((120, 150), 1.5, Style(0.5, fill="white"), layer="position_plan", id="joint-o"),
        Line((60, 150), (300, 150), DASHDOT, layer="construction", id="axis"),
        Line((120, 60), (120, 250), DASHDOTDOT, layer="construction", id="extreme"),
        Arc((120, 150), 40, 0, 90, DASHDOT, layer="construction", id="traj"),
        Arrow((400, 200), (460, 160), MEDIUM, layer="velocity_plan", id="v-a"),
        Polyline(((400, 300), (450, 280), (500, 310)), THIN, layer="diagrams", id="curve"),
        Group((Text((395, 207), "p", 5, layer="velocity_plan", id="lbl-p"),
               Text((462, 157), "a", 5, layer="velocity_plan", id="lbl-a")),
              "velocity_plan", id="labels"),
        Text((400, 250), "ω₁ = 12,57 рад/с", 5, layer="text", id="omega"),
        Text((400, 265), "Ёмкость ε φ ∥ √2", 5, layer="text", id="yo"),
        Text((380, 300), "повёрнутый", 3.5, rotate_deg=90, layer="text", id="turned"),
        *table_items((60, 300), (15, 25), [(1, "0,50"), (2, "0,70")], header=("№", "v"),
                     id="tab"),
    )
    return Sheet(Page(fmt), items, tb)


@pytest.fixture(scope="module")
def root():
    return ET.fromstring(render_svg(make_sheet()))


def elements(root):
    return {el.get("id"): el for el in root.iter() if el.get("id")}


def test_root_is_in_millimetres(root):
    assert root.tag == f"{SVG}svg"
    assert root.get("width") == "841mm" and root.get("height") == "594mm"
    assert root.get("viewBox") == "0 0 841 594"


def test_a3_root():
    r = ET.fromstring(render_svg(Sheet(Page("A3"))))
    assert (r.get("width"), r.get("height"), r.get("viewBox")) == ("420mm", "297mm", "0 0 420 297")


def test_one_group_per_layer_in_order(root):
    groups = root.findall("svg:g", NS)
    assert [g.get("id") for g in groups] == [f"layer-{name}" for name in LAYERS]
    el = elements(root)
    layer_of = {}
    for g in groups:
        for child in g.iter():
            if child.get("id") and child is not g:
                layer_of[child.get("id")] = g.get("id")
    assert layer_of["frame"] == "layer-frame"
    assert layer_of["tb-line-01"] == "layer-title"
    assert layer_of["v-a"] == "layer-velocity_plan"
    assert layer_of["lbl-a"] == "layer-velocity_plan"
    assert el["labels"].tag == f"{SVG}g" and len(el["labels"]) == 2
    assert layer_of["tab-h0"] == "layer-tables"


def test_stroke_widths_dashes_and_caps(root):
    el = elements(root)
    assert el["frame"].get("stroke-width") == "0.7"
    assert el["trim"].get("stroke-width") == "0.25"
    assert el["ground"].get("stroke-width") == "0.7"
    assert el["axis"].get("stroke-dasharray") == "15,3,1,3"
    assert el["extreme"].get("stroke-dasharray") == "15,3,1,3,1,3"
    assert el["axis"].get("stroke-width") == "0.25"
    for e in root.iter():
        if e.get("stroke-width") is not None:
            assert e.get("stroke-linecap") == "butt", e.attrib
            assert not e.get("stroke-width").endswith("mm")  # user units are mm already


def test_title_block_lines_at_their_coordinates(root):
    el = elements(root)
    for i, (w, x0, y0, x1, y1) in enumerate(FORM1_SEGMENTS, 1):
        line = el[f"tb-line-{i:02d}"]
        got = tuple(float(line.get(k)) for k in ("x1", "y1", "x2", "y2"))
        assert got == (651 + x0, 534 + y0, 651 + x1, 534 + y1)
        assert line.get("stroke-width") == ("0.7" if w == "S" else "0.25")
    x65 = el["tb-line-07"]
    assert [x65.get(k) for k in ("x1", "y1", "x2", "y2")] == ["716", "534", "716", "589"]


def _text_point(t):
    return float(t.get("x")), float(t.get("y"))


def test_no_text_outside_the_frame(root):
    margin_ids = {"tb-label-copied", "tb-label-format", "tb-format"}  # graphs 31, 32
    texts = list(root.iter(f"{SVG}text"))
    assert len(texts) > 30
    for t in texts:
        x, y = _text_point(t)
        if t.get("id") in margin_ids:
            assert 589 < y < 594 and 20 < x < 836
        else:
            assert 20 <= x <= 836 and 5 <= y <= 589, t.get("id")
    assert check_layout(make_sheet()) == []


def test_text_lettering_attributes(root):
    el = elements(root)
    omega = el["omega"]
    family = fonts.choose_family("ω₁ = 12,57 рад/с")
    assert omega.get("font-family") == fonts.font_family("ω₁ = 12,57 рад/с")
    assert omega.get("font-family").endswith("sans-serif")
    assert float(omega.get("font-size")) == pytest.approx(5 / fonts.cap_ratio(family), abs=1e-3)
    assert omega.text == "ω₁ = 12,57 рад/с"
    # type B slant: a shear of tan 15° about the baseline, never a mirror
    k = math.tan(math.radians(15))
    m = re.fullmatch(r"matrix\(1 0 (-?[\d.]+) 1 (-?[\d.]+) 0\)", omega.get("transform"))
    assert m and float(m.group(1)) == pytest.approx(-k, abs=1e-5)
    assert float(m.group(2)) == pytest.approx(k * 250, abs=0.01)
    turned = el["turned"]
    assert turned.get("transform").startswith("rotate(-90 380 300) matrix(")
    assert el["tb-g26"].get("transform").startswith("rotate(-180 ")
    assert el["tb-designation"].get("text-anchor") == "middle"
    svg = render_svg(make_sheet())
    assert "scale(" not in svg


def test_text_osifont_cannot_letter_is_lettered_in_the_fallback(root):
    el = elements(root)
    assert el["yo"].get("font-family").startswith("'DejaVu Sans', ")
    assert el["tb-designation"].get("font-family").startswith("'osifont', ")


def test_arrowheads_are_filled_polygons_not_markers(root):
    arrow = elements(root)["v-a"]
    line, head = arrow.find("svg:line", NS), arrow.find("svg:polygon", NS)
    assert head.get("fill") == "black" and head.get("stroke") == "none"
    tip = head.get("points").split()[0]
    assert tip == "460,160"
    assert (line.get("x1"), line.get("y1")) == ("400", "200")
    assert not list(root.iter(f"{SVG}marker"))
    assert "marker-end" not in render_svg(make_sheet())


def test_arc_hatch_circle_and_polyline(root):
    el = elements(root)
    # 0° → 90° counter-clockwise as seen: from the right point up to the top point
    assert el["traj"].get("d") == "M160,150 A40,40 0 0 0 120,110"
    hatch = el["ground-hatch"].get("d")
    assert hatch.startswith("M") and hatch.count("M") >= 10
    assert el["joint-o"].get("fill") == "white" and el["joint-o"].get("r") == "1.5"
    assert el["curve"].tag == f"{SVG}polyline" and el["curve"].get("fill") == "none"
    assert el["frame"].tag == f"{SVG}polygon"


def test_coordinates_are_rounded_to_hundredths():
    svg = render_svg(make_sheet())
    for attr in re.findall(r' (?:x|y|x1|y1|x2|y2|cx|cy|r|points|d)="([^"]*)"', svg):
        for number in re.findall(r"-?\d+(?:\.\d+)?", attr):
            assert len(number.partition(".")[2]) <= 2, attr
    assert num(1 / 3) == "0.33" and num(-0.001) == "0" and num(651.0) == "651"


def test_output_is_deterministic(tmp_path):
    a = render_svg(make_sheet())
    b = render_svg(make_sheet())
    assert a == b
    path = write_svg(make_sheet(), tmp_path / "sheet.svg")
    assert path.read_text(encoding="utf-8") == a


def test_duplicate_ids_are_refused():
    sheet = Sheet(Page("A1"), (Line((30, 30), (40, 40), THIN, layer="construction", id="x"),
                               Circle((50, 50), 2, THIN, layer="construction", id="x")))
    with pytest.raises(LayoutError, match="'x'"):
        render_svg(sheet)


def test_png_preview_is_not_blank_and_has_the_sheet_aspect(tmp_path):
    pytest.importorskip("resvg_py")
    Image = pytest.importorskip("PIL.Image")
    from graphplan.render.raster import svg_to_png

    path = svg_to_png(render_svg(make_sheet()), tmp_path / "sheet.png", dpi=20)
    with Image.open(path) as im:
        w, h = im.size
        gray = im.convert("L")
        hist = gray.histogram()  # counts of the 256 grey levels
        # the title block region (bottom-right 185×55 mm) is full of ink
        px = 20 / 25.4
        tb = gray.crop((int(651 * px), int(534 * px), int(836 * px), int(589 * px)))
        tb_dark = sum(tb.histogram()[:128])
    assert w == pytest.approx(841 / 25.4 * 20, abs=1) and h == pytest.approx(594 / 25.4 * 20, abs=1)
    assert w / h == pytest.approx(841 / 594, rel=0.01)
    n = sum(hist)
    mean = sum(level * c for level, c in enumerate(hist)) / n
    var = sum((level - mean) ** 2 * c for level, c in enumerate(hist)) / n
    assert var > 100 and mean > 200  # mostly white paper with black lines
    assert tb_dark > 0.05 * tb.size[0] * tb.size[1]


def test_missing_png_engine_is_a_one_line_error(monkeypatch, tmp_path):
    import sys

    from graphplan.render import raster

    monkeypatch.delenv("GRAPHPLAN_EXPORT_ENGINE", raising=False)
    monkeypatch.setitem(sys.modules, "resvg_py", None)
    with pytest.raises(GraphplanError, match="resvg_py") as info:
        raster.svg_to_png("<svg/>", tmp_path / "x.png")
    assert "\n" not in str(info.value)
    assert not (tmp_path / "x.png").exists()
