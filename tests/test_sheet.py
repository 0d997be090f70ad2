"""The sheet layer: page arithmetic, title block form 1, tables, layout checks, fonts."""

import dataclasses
import math

import pytest
from shapely.geometry import box

from graphplan import fonts
from graphplan.drawing import (
    DASHDOT,
    DASHDOTDOT,
    DASHED,
    FORM1_SEGMENTS,
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
    arc_point,
    arrow_parts,
    check_layout,
    frame_items,
    hatch_segments,
    iter_leaves,
    signatures,
    table_items,
    text_at_centre,
    text_box,
    title_block_items,
)
from graphplan.errors import InputError, LayoutError

# method.md A.2, "Computed frame rectangles": trim, frame x0..x1, y0..y1, title block
PAGES = {
    "A1": ((841, 594), (20, 836, 5, 589), (651, 836, 534, 589)),
    "A2": ((594, 420), (20, 589, 5, 415), (404, 589, 360, 415)),
    "A3": ((420, 297), (20, 415, 5, 292), (230, 415, 237, 292)),
}

TB = TitleBlock(
    designation="ТММ.КП.00.01",
    title="Кривошипный пресс. Кинематический анализ",
    litera="У",
    scale="1:2",
    sheet=1,
    sheets=3,
    organisation="Кафедра ТММ, гр. МТ-21",
    signatures=signatures("Иванов И.И.", "Петров П.П.", date="05.25"),
)


def by_id(items):
    return {it.id: it for it in iter_leaves(items) if it.id}


# ------------------------------------------------------------------------- page


@pytest.mark.parametrize("fmt", sorted(PAGES))
def test_page_frame_and_title_block_follow_the_table(fmt):
    (w, h), (fx0, fx1, fy0, fy1), (tx0, tx1, ty0, ty1) = PAGES[fmt]
    page = Page(fmt)
    assert (page.width, page.height) == (w, h)
    f = page.frame
    assert (f.x0, f.x1, f.y0, f.y1) == (fx0, fx1, fy0, fy1)
    # margins: 20 mm on the left, 5 mm elsewhere
    assert (f.x0, w - f.x1, f.y0, h - f.y1) == (20, 5, 5, 5)
    assert page.title_block_origin == (tx0, ty0)
    t = page.title_block_rect
    assert (t.x0, t.x1, t.y0, t.y1) == (tx0, tx1, ty0, ty1)
    assert (t.width, t.height) == (185, 55)
    g = page.graph26_rect
    assert (g.x0, g.y0, g.x1, g.y1) == (20, 5, 90, 19)
    free = page.drawing_area
    assert free.area == pytest.approx(f.width * f.height - 185 * 55 - 70 * 14)


def test_unknown_format_is_an_input_error():
    with pytest.raises(InputError, match="A1"):
        Page("A7")


def test_values_are_frozen():
    for value, attr in [(Page("A1"), "format"), (MAIN, "width"), (TB, "title"),
                        (Line((0, 0), (1, 1), THIN, layer="construction"), "p0"),
                        (Sheet(Page("A1")), "items")]:
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(value, attr, None)


# ------------------------------------------------------------------ line styles


def test_line_styles_follow_gost_2_303():
    assert MAIN.width == 0.7 and MAIN.dasharray is None
    assert THIN.width == 0.25 and MEDIUM.width == 0.5
    assert DASHDOT.dasharray == (15, 3, 1, 3) and DASHDOT.width == THIN.width
    assert DASHED.dasharray == (4, 1.5)
    assert DASHDOTDOT.dasharray == (15, 3, 1, 3, 1, 3)
    assert MAIN.colour == "black" and MAIN.fill is None
    assert Style(0.25, "15,3,1,3") == DASHDOT
    with pytest.raises(InputError):
        Style(0)
    with pytest.raises(InputError):
        Style(0.25, (4, -1))


# ------------------------------------------------------------------------ items


def test_items_validate_their_input():
    with pytest.raises(InputError, match="layer"):
        Line((0, 0), (1, 1), THIN, layer="nowhere")
    with pytest.raises(InputError, match=r"GOST 2\.304"):
        Text((0, 0), "x", 3.0, layer="text")
    with pytest.raises(InputError, match="one non-empty line"):
        Text((0, 0), "a\nb", 3.5, layer="text")
    with pytest.raises(InputError, match="finite"):
        Circle((math.nan, 0), 1, THIN, layer="construction")
    with pytest.raises(InputError, match="holds an item on layer"):
        Group((Line((0, 0), (1, 1), THIN, layer="text"),), "construction")
    # points given as numpy arrays or lists are stored as tuples of floats
    import numpy as np

    line = Line(np.array([1, 2]), [3, 4], THIN, layer="construction")
    assert line.p0 == (1.0, 2.0) and line.p1 == (3.0, 4.0)


def test_arc_angles_are_counter_clockwise_as_seen_on_y_down_paper():
    assert arc_point((10, 10), 5, 0) == pytest.approx((15, 10))
    assert arc_point((10, 10), 5, 90) == pytest.approx((10, 5))  # up on the sheet
    assert Arc((0, 0), 1, 350, 10, THIN, layer="construction").sweep_deg == pytest.approx(20)
    assert Arc((0, 0), 1, 30, 30, THIN, layer="construction").sweep_deg == 360


def test_arrow_head_has_its_tip_at_p1_and_the_shaft_stops_at_its_base():
    shaft, head = arrow_parts(Arrow((0, 0), (20, 0), MEDIUM, layer="velocity_plan"))
    assert head[0] == (20, 0)
    assert {head[1], head[2]} == {(16.5, 0.5), (16.5, -0.5)}  # 3.5 long, 1.0 wide
    assert shaft == ((0, 0), (16.5, 0))
    shaft, head = arrow_parts(Arrow((0, 0), (0, 2), MEDIUM, layer="velocity_plan"))
    assert shaft is None and head[0] == (0, 2)  # shorter than its head: head shrunk
    assert max(abs(p[1]) for p in head) == pytest.approx(2)
    assert arrow_parts(Arrow((5, 5), (5, 5), MEDIUM, layer="velocity_plan")) == (None, ())


def test_hatch_lines_are_clipped_parallel_and_evenly_spaced():
    square = ((0, 0), (10, 0), (10, 10), (0, 10))
    flat = hatch_segments(Hatch(square, 2.0, 0.0, layer="position_plan"))
    assert flat == tuple(((0.0, y), (10.0, y)) for y in (2.0, 4.0, 6.0, 8.0))
    slanted = hatch_segments(Hatch(square, 2.0, 45.0, layer="position_plan"))
    assert len(slanted) == 7
    inside = box(0, 0, 10, 10).buffer(1e-6)
    for (x0, y0), (x1, y1) in slanted:
        assert inside.contains(box(min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1)))
        # 45° counter-clockwise as seen: going right goes up (y decreases)
        assert (x1 - x0) * (y1 - y0) < 0
    # perpendicular spacing 2 mm: intercepts on the x axis 2·√2 apart
    xs = sorted(max(x0, x1) for (x0, y0), (x1, y1) in slanted if min(y0, y1) == pytest.approx(0))
    assert xs[1] - xs[0] == pytest.approx(2 * math.sqrt(2))


def test_text_box_follows_anchor_rotation_and_height():
    t = Text((100, 100), "Масштаб", 5, layer="text")
    b = text_box(t)
    x0, y0, x1, y1 = b.bounds
    assert x0 == pytest.approx(100) and y0 == pytest.approx(95) and y1 == pytest.approx(101.5)
    assert 7 * 5 * 0.5 < x1 - x0 < 7 * 5 * 1.2
    mid = text_box(Text((100, 100), "Масштаб", 5, "middle", italic=False, layer="text"))
    assert (mid.bounds[0] + mid.bounds[2]) / 2 == pytest.approx(100)
    up = text_box(Text((100, 100), "Масштаб", 5, rotate_deg=90, layer="text"))
    ux0, uy0, ux1, uy1 = up.bounds
    assert uy1 - uy0 > ux1 - ux0  # reads from bottom to top: tall and narrow
    assert uy1 == pytest.approx(100) and ux0 == pytest.approx(95)
    # capitals centred on a point, also turned by 180° (graph 26)
    c = text_at_centre((50, 50), "ТММ", 5, rotate_deg=180, layer="title")
    assert c.pos == pytest.approx((50, 47.5))
    cb = text_box(c)
    assert cb.bounds[3] == pytest.approx(52.5)


# ------------------------------------------------------------------ title block


def test_frame_is_a_thin_trim_and_a_main_inner_frame():
    trim, frame = frame_items(Page("A1"))
    assert trim.style == THIN and trim.points == ((0, 0), (841, 0), (841, 594), (0, 594))
    assert frame.style == MAIN and frame.points == ((20, 5), (836, 5), (836, 589), (20, 589))
    assert trim.layer == frame.layer == "frame"


@pytest.mark.parametrize("fmt", sorted(PAGES))
def test_title_block_lines_are_the_form1_segments_at_the_corner(fmt):
    page = Page(fmt)
    ox, oy = page.title_block_origin
    lines = [it for it in title_block_items(page, TB)
             if isinstance(it, Line) and it.id.startswith("tb-line")]
    got = {(("S" if ln.style == MAIN else "t"), ln.p0, ln.p1) for ln in lines}
    want = {(w, (ox + x0, oy + y0), (ox + x1, oy + y1)) for w, x0, y0, x1, y1 in FORM1_SEGMENTS}
    assert got == want
    assert len(lines) == 27
    assert sum(1 for w, *_ in FORM1_SEGMENTS if w == "S") == 17


def test_title_block_cells_on_a1_are_where_gost_puts_them():
    items = by_id(title_block_items(Page("A1"), TB))
    line = {(it.p0, it.p1): it.style for it in items.values() if isinstance(it, Line)}
    assert line[((716, 534), (716, 589))] == MAIN  # x = 65 of the block: full height
    assert line[((786, 549), (786, 589))] == MAIN  # x = 135, below graph 2
    assert line[((651, 539), (716, 539))] == THIN  # 5 mm rows of the change table
    assert line[((791, 554), (791, 569))] == THIN  # litera cells x = 140, 145
    assert line[((796, 554), (796, 569))] == THIN
    assert line[((806, 569), (806, 574))] == MAIN  # x = 155: Лист | Листов
    assert line[((90, 5), (90, 19))] == MAIN  # graph 26 box, 70×14
    assert line[((20, 19), (90, 19))] == MAIN
    # printed labels: capitals centred on the KiCad points, 2.5 mm lettering
    razrab = items["tb-role-1"]
    assert razrab.text == "Разраб." and razrab.anchor == "start"
    assert razrab.pos == (652, 534 + 27.5 + 1.25) and razrab.height == 2.5
    assert items["tb-label-masshtab"].pos == (651 + 176, 534 + 17.5 + 1.25)
    assert items["tb-label-izm"].text == "Изм."
    # filled-in values
    des = items["tb-designation"]
    assert des.pos[0] == 651 + 125 and des.pos[1] - des.height / 2 == pytest.approx(534 + 7.5)
    assert items["tb-sheet"].text == "1" and items["tb-sheet"].pos[0] == 651 + 149
    assert items["tb-sheets"].text == "3" and items["tb-sheets"].pos[0] == 651 + 175
    assert items["tb-surname-1"].text == "Иванов И.И." and items["tb-surname-1"].pos[0] == 668.5
    assert items["tb-date-1"].text == "05.25"
    assert items["tb-litera-1"].text == "У"
    assert items["tb-scale"].text == "1:2"
    g26 = items["tb-g26"]
    assert g26.text == "ТММ.КП.00.01" and g26.rotate_deg == 180
    assert g26.pos[0] == 55 and g26.pos[1] + g26.height / 2 == pytest.approx(12)


def _cell(x0, y0, x1, y1, ox=651, oy=534):
    return box(ox + x0, oy + y0, ox + x1, oy + y1).buffer(1e-6)


@pytest.mark.parametrize(
    ("prefix", "cell"),
    [
        ("tb-designation", (65, 0, 185, 15)),
        ("tb-title", (65, 15, 135, 40)),
        ("tb-organisation", (135, 40, 185, 55)),
        ("tb-surname-1", (17, 25, 40, 30)),
        ("tb-surname-2", (17, 30, 40, 35)),
        ("tb-date-1", (55, 25, 65, 30)),
        ("tb-litera-1", (135, 20, 140, 35)),
        ("tb-scale", (167, 20, 185, 35)),
        ("tb-label-doc", (17, 20, 40, 25)),
        ("tb-label-masshtab", (167, 15, 185, 20)),
        ("tb-role-3", (0, 35, 17, 40)),
    ],
)
def test_title_block_values_stay_inside_their_cells(prefix, cell):
    texts = [t for t in title_block_items(Page("A1"), TB)
             if isinstance(t, Text) and t.id.startswith(prefix)]
    assert texts
    for t in texts:
        assert _cell(*cell).contains(text_box(t)), t


def test_long_title_wraps_and_uses_the_largest_fitting_size():
    items = by_id(title_block_items(Page("A1"), TB))
    lines = [items[k] for k in sorted(items) if k.startswith("tb-title")]
    assert len(lines) >= 2 and " ".join(t.text for t in lines) == TB.title
    assert all(t.height == lines[0].height for t in lines) and lines[0].height >= 3.5
    assert [t.pos[1] for t in lines] == sorted(t.pos[1] for t in lines)
    short = by_id(title_block_items(Page("A1"), TitleBlock(designation="ТММ.01")))
    assert short["tb-designation"].height == 7


def test_values_that_cannot_fit_raise_layout_error():
    with pytest.raises(LayoutError, match="graph 2"):
        title_block_items(Page("A1"), TitleBlock(designation="Ж" * 60))
    with pytest.raises(InputError, match="litera"):
        TitleBlock(litera="УДЕН")


def test_empty_title_block_has_lines_and_labels_only():
    items = title_block_items(Page("A3"), TitleBlock())
    texts = {t.text for t in items if isinstance(t, Text)}
    assert {"Изм.", "Лист", "Листов", "Масштаб", "Разраб.", "Утв.", "Копировал", "А3"} <= texts
    assert all(t.layer == "title" for t in items)


# ------------------------------------------------------------------------ table


def test_table_geometry():
    items = table_items((100, 100), (10, 20, 30), [(1, "0,35", "a"), (2, "1,20", "b")],
                        header=("№", "v", "ω"), text_height=3.5, id="tab")
    got = by_id(items)
    hs = [got[f"tab-h{i}"] for i in range(4)]
    assert [(h.p0, h.p1) for h in hs] == [((100, y), (160, y)) for y in (100, 107, 114, 121)]
    assert [h.style for h in hs] == [MAIN, MAIN, THIN, MAIN]  # border and header rule main
    vs = [got[f"tab-v{j}"] for j in range(4)]
    assert [(v.p0, v.p1) for v in vs] == [((x, 100), (x, 121)) for x in (100, 110, 130, 160)]
    assert [v.style for v in vs] == [MAIN, THIN, THIN, MAIN]
    cell = got["tab-r1c2"]
    assert cell.text == "0,35" and cell.anchor == "middle"
    assert cell.pos == (120, 107 + 3.5 + 1.75)
    assert got["tab-r0c3"].text == "ω"
    texts = [it for it in items if isinstance(it, Text)]
    assert len(texts) == 9 and all(t.layer == "tables" for t in texts)
    left = table_items((0, 0), (20,), [("x",)], align=("start",), text_height=5, id="t")
    assert by_id(left)["t-r1c1"].pos == (1, 5 + 2.5)  # 10 mm row, 1 mm padding


def test_table_errors():
    with pytest.raises(InputError, match="2 cells for 3 columns"):
        table_items((0, 0), (10, 10, 10), [(1, 2)])
    with pytest.raises(LayoutError, match="wider"):
        table_items((0, 0), (5,), [("123456789",)], id="t")


# ------------------------------------------------------------------------ layout


def _clean_sheet(extra=()):
    items = [
        Line((100, 100), (200, 100), MAIN, layer="position_plan", id="ab"),
        Text((100, 95), "A", 5, layer="position_plan", id="lbl-a"),
        Text((300, 100), "План скоростей", 7, layer="text", id="cap"),
        Arrow((300, 200), (360, 170), MEDIUM, layer="velocity_plan", id="va"),
        Hatch(((100, 100), (140, 100), (140, 104), (100, 104)), layer="position_plan"),
        *table_items((60, 300), (15, 25), [(1, "0,5"), (2, "0,7")], header=("№", "v"),
                     id="t1"),
    ]
    return Sheet(Page("A1"), tuple(items) + tuple(extra), TB)


def test_check_layout_is_quiet_on_a_clean_sheet():
    assert check_layout(_clean_sheet()) == []


def test_check_layout_finds_overlapping_texts():
    problems = check_layout(_clean_sheet([Text((305, 101), "План", 7, layer="text", id="dup")]))
    assert len(problems) == 1 and "overlaps" in problems[0] and "'dup'" in problems[0]


def test_check_layout_finds_text_outside_the_frame():
    problems = check_layout(_clean_sheet([Text((5, 300), "вне рамки", 5, layer="text", id="out")]))
    assert any("'out'" in p and "outside the inner frame" in p for p in problems)
    # a text partly over the right frame line
    problems = check_layout(_clean_sheet([Text((830, 300), "край", 5, layer="text", id="edge")]))
    assert any("'edge'" in p and "outside" in p for p in problems)


def test_check_layout_finds_text_crossed_by_a_line_of_another_layer():
    problems = check_layout(_clean_sheet([
        Line((310, 80), (310, 120), THIN, layer="construction", id="cut"),
    ]))
    assert any("'cap'" in p and "crossed by line 'cut'" in p for p in problems)
    # the same line on the text's own layer is not a problem
    assert check_layout(_clean_sheet([Line((310, 80), (310, 120), THIN, layer="text")])) == []


def test_check_layout_finds_text_over_the_title_block_and_duplicate_ids():
    problems = check_layout(_clean_sheet([
        Text((700, 560), "тут", 5, layer="text", id="tb-over"),
        Circle((400, 400), 2, THIN, layer="construction", id="ab"),
    ]))
    assert any("'tb-over'" in p and "title block" in p for p in problems)
    assert any("id 'ab' is used 2 times" in p for p in problems)


def test_check_layout_finds_drawing_leaving_the_frame():
    problems = check_layout(_clean_sheet([
        Polyline(((800, 300), (850, 300)), THIN, layer="diagrams", id="long"),
    ]))
    assert any("'long'" in p and "leaves the inner frame" in p for p in problems)


# ------------------------------------------------------------------------ fonts

def test_osifont_metrics_and_its_blank_glyphs():
    # the bundled build (Debian's 0.1.20220224 with docs/osifont_patch.py): capitals
    # 1515/2048 em, Ё ё Э э drawn over the upstream build's blank placeholders, − and →
    assert fonts.cap_ratio("osifont") == pytest.approx(1515 / 2048, abs=1e-9)
    assert fonts.blank_chars("osifont", "АЁёЭэЖ−→") == ""
    assert fonts.missing_chars("osifont", "Масштаб 1:2 ω ε φ − → Ёё Ээ") == ""


def test_texts_osifont_cannot_draw_fall_back_to_dejavu():
    assert fonts.choose_family("Масштаб") == "osifont"
    assert fonts.font_family("Масштаб").startswith("'osifont', ")
    assert fonts.choose_family("Ёмкость ε = −3,5 → 0") == "osifont"
    assert fonts.choose_family("AB ∥ CD") == "DejaVu Sans"
    assert fonts.font_family("AB ∥ CD").startswith("'DejaVu Sans', 'osifont'")
    assert fonts.font_family("x").endswith(", sans-serif")


def test_every_required_symbol_is_drawn_by_the_chain():
    report = fonts.coverage_report()
    assert set(report) == set(fonts.REQUIRED_CHARS)
    for ch, family in report.items():
        assert family in fonts.FONT_CHAIN, ch
        assert fonts.missing_chars(family, ch) == "", (ch, family)


def test_which_font_draws_which_symbol():
    report = fonts.coverage_report()
    for ch in "ωεφπμδΔΣ°±×ψτАБЖЯабжяЁёЭэ−₁₂₃":
        assert report[ch] == "osifont", ch
    for ch in "∥":
        assert report[ch] == "DejaVu Sans", ch
    assert report["⟂"] == "DejaVu Sans Mono"


@pytest.fixture
def no_fonts(monkeypatch):
    def clear():
        fonts.find_font_file.cache_clear()
        fonts.load_font.cache_clear()
        fonts.choose_family.cache_clear()

    clear()
    monkeypatch.setattr(fonts, "find_font_file", lambda family: None)
    yield
    monkeypatch.undo()
    clear()


def test_everything_works_without_font_files(no_fonts):
    assert not fonts.is_installed("osifont")
    assert fonts.cap_ratio("osifont") == pytest.approx(1515 / 2048)
    assert fonts.cap_ratio("Unknown") == fonts.FALLBACK_CAP_RATIO
    assert fonts.text_width("abc", 5) == pytest.approx(3 * 5 * fonts.FALLBACK_ADVANCE)
    narrow = fonts.FALLBACK_NARROW
    assert fonts.text_width("a.", 5) == pytest.approx(5 * (fonts.FALLBACK_ADVANCE + narrow))
    # the known gaps of the reference osifont build still steer the choice
    assert fonts.choose_family("Масштаб") == "osifont"
    assert fonts.choose_family("Ёмкость → −1") == "osifont"
    assert fonts.choose_family("AB ∥ CD") == "DejaVu Sans"
    assert fonts.choose_family("a ⟂ b") == "DejaVu Sans Mono"
    assert check_layout(_clean_sheet()) == []


def test_a_plans_letters_may_cross_its_construction_lines_and_arms():
    # 'A' (position_plan) at (100, 95), 5 mm high: a construction line and an arm through it
    # are the plan's own; the same line through the caption (layer "text") is not
    problems = check_layout(_clean_sheet([
        Line((102, 85), (102, 99), THIN, layer="construction", id="through-a"),
        Line((101, 85), (101, 99), THIN, layer="dimensions", id="arm-a"),
        Line((310, 80), (310, 120), THIN, layer="construction", id="cut"),
    ]))
    assert [p for p in problems if "'lbl-a'" in p] == []
    assert any("'cap'" in p and "crossed by line 'cut'" in p for p in problems)
