"""One lettering on every sheet, the diagrams included (issue 18): GOST 2.304 type B,
slanted, the sheet's font; the diagrams' letters are text (in the SVG, the DXF), not
glyph outlines nor a picture pasted in; no letter falls back to an upright font; the
decimal comma on Russian sheets."""

import re
import xml.etree.ElementTree as ET

import pytest

from graphplan import fonts
from graphplan.drawing import (
    Group,
    Page,
    Sheet,
    Text,
    decimal_comma,
    dynamics_sheet,
    iter_leaves,
    kinematics_sheet,
    kinetostatics_sheet,
)
from graphplan.render.svg import render_svg

EXAMPLES = ["press", "fourbar", "shaper", "shaper_prp", "scotch_yoke", "sixbar_press",
            "offset_slider"]
DIAGRAMS = {"sheet1": "kin-diagrams", "sheet2": "s2-moment-curve", "sheet3": "s3-omega"}
SVG = "{http://www.w3.org/2000/svg}"
SHEAR = re.compile(r"matrix\(1 0 -0\.26795 1 [-\d.]+ 0\)")  # tan 15° = 0.26795
NUMBER = re.compile(r"\d\.\d")


@pytest.fixture
def sheets(solved):
    """``sheets(name, lang)`` → the three sheets of an example's project (the session's,
    tests/conftest.py), drawn once per language."""

    def get(name, lang="ru"):
        a = solved(name)
        return a.stage(("sheets 1-3", lang), lambda: {
            "sheet1": kinematics_sheet(a, lang=lang),
            "sheet2": kinetostatics_sheet(a, lang=lang),
            "sheet3": dynamics_sheet(a, lang=lang)})

    return get


def _group(sheet, ident):
    found = [g for g in iter_leaves_groups(sheet.items) if g.id == ident]
    assert len(found) == 1, ident
    return found[0]


def iter_leaves_groups(items):
    for it in items:
        if isinstance(it, Group):
            yield it
            yield from iter_leaves_groups(it.items)


@pytest.mark.parametrize("name", EXAMPLES)
def test_diagrams_are_lettered_like_the_sheet(sheets, name):
    """Every matplotlib diagram is the sheet's items: its letters are slanted texts of GOST
    sizes in a font that draws every character (osifont, or the slanted fallback), on a
    Russian sheet with the decimal comma; no picture is pasted in."""
    for key, sheet in sheets(name).items():
        texts = [t for t in _group(sheet, DIAGRAMS[key]).items if isinstance(t, Text)]
        assert len(texts) >= 5, key
        for t in texts:
            assert t.italic
            family = fonts.choose_family(t.text)
            assert fonts.missing_chars(family, t.text) == "", (key, t.text)
            assert not NUMBER.search(t.text), (key, t.text)  # 0,5 not 0.5


@pytest.mark.parametrize("name", ["press", "shaper"])
def test_diagram_text_is_text_in_the_svg(sheets, name):
    for key, sheet in sheets(name).items():
        svg = render_svg(sheet)
        root = ET.fromstring(svg.encode("utf-8"))
        assert root.find(f".//{SVG}svg") is None  # no picture nested in the sheet
        g = root.find(f".//{SVG}g[@id='{DIAGRAMS[key]}']")
        texts = g.findall(f".//{SVG}text")
        assert len(texts) >= 5
        for el in texts:
            assert SHEAR.search(el.get("transform", "")), (key, el.text)
            assert el.get("font-style") == "normal"  # the slant is the shear, same everywhere
        assert g.findall(f".//{SVG}path") == []  # no glyph outlines: lines are polylines


def test_symbols_osifont_cannot_draw_are_slanted_too():
    """∥ and √ are not in the bundled osifont: such a text is lettered in the fallback
    family, sheared to the same 75° (never upright)."""
    t = Text((100.0, 100.0), "AB ∥ CD, √2", 3.5, layer="text", id="t")
    assert fonts.choose_family(t.text) != "osifont"
    svg = render_svg(Sheet(Page("A3"), (t,)))
    el = ET.fromstring(svg.encode("utf-8")).find(f".//{SVG}text[@id='t']")
    assert SHEAR.search(el.get("transform"))
    assert el.get("font-family").startswith("'DejaVu Sans'")


def test_diagram_text_is_text_in_the_dxf(sheets):
    ezdxf = pytest.importorskip("ezdxf")
    from graphplan.render import dxf_bytes

    sheet = sheets("press")["sheet2"]
    doc = ezdxf.read(__import__("io").StringIO(dxf_bytes(sheet).decode("utf-8")))
    msp = doc.modelspace()
    words = {e.dxf.text for e in msp.query("TEXT")}
    curve = [t.text for t in _group(sheet, "s2-moment-curve").items if isinstance(t, Text)]
    assert set(curve) <= words  # the diagram's letters are editable TEXT entities
    assert not [ly.dxf.name for ly in doc.layers if ly.dxf.name.startswith("figure-")]
    for e in msp.query("TEXT"):
        if e.dxf.text in curve:
            assert doc.styles.get(e.dxf.style).dxf.oblique == pytest.approx(15.0) or \
                e.dxf.oblique == pytest.approx(15.0)


def test_decimal_comma_on_russian_point_on_english_sheets(sheets):
    assert decimal_comma("Kφ = 0.02182 рад/мм, 1:2.5, pos. 10") == \
        "Kφ = 0,02182 рад/мм, 1:2,5, pos. 10"
    ru = [t.text for t in iter_leaves(sheets("shaper")["sheet3"].items)
          if isinstance(t, Text)]
    en = [t.text for t in iter_leaves(sheets("shaper", "en")["sheet3"].items)
          if isinstance(t, Text)]
    assert not [s for s in ru if NUMBER.search(s)]
    assert [s for s in en if NUMBER.search(s)]


def test_the_sheets_letters_are_all_osifont(sheets):
    """Э, ё, the minus and → were not in the upstream osifont (the equations of sheet 2,
    «Силовой расчёт», «Этот» fell back to DejaVu Sans: two typefaces in one block); graphplan's
    build (docs/osifont_patch.py) draws them from its own glyphs: every text of the press's
    and the engine's three sheets is lettered in osifont, and the new glyphs draw (they are
    not the blank quadrilaterals of the upstream Ё ё Э э)."""
    text = "Энергия ёмкость Ё −5,0: ΣMB(2) = 0 → Rτ12"
    assert fonts.choose_family(text) == "osifont"
    assert fonts.blank_chars("osifont", "ЁёЭэ−→") == ""
    for name in ("press", "engine"):
        for key, sheet in sheets(name).items():
            bad = {t.text for t in iter_leaves(sheet.items) if isinstance(t, Text)
                   and t.text.strip() and fonts.choose_family(t.text) != "osifont"}
            assert not bad, (name, key, sorted(bad)[:5])


def test_a_minus_is_lettered_with_its_dash():
    """U+2212 was not in the upstream osifont (CAD programs' osifont, which the DXF's texts
    name): a text osifont can letter keeps the minus written as its en dash, which every
    osifont has (graphplan's minus is the en dash's outline, so the sheet looks the same)."""
    t = Text((100.0, 100.0), "Jм = JI − Jкр − Jрот·u²", 3.5, layer="text", id="t")
    assert fonts.drawable_minus(t.text) == "Jм = JI – Jкр – Jрот·u²"
    el = ET.fromstring(render_svg(Sheet(Page("A3"), (t,))).encode("utf-8")).find(
        f".//{SVG}text[@id='t']")
    assert el.get("font-family").startswith("'osifont'")
    assert "".join(el.itertext()) == "Jм = JI – Jкр – Jрот·u²"
    assert SHEAR.search(el.get("transform"))
