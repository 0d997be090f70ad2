"""Sheet 1 (kinematics): the drawing is the construction, laid out by the standards.

The plans on the sheet are read back from the SVG like a draftsman reads a
drawing (a vector's length in mm times its scale) and compared with the exact
kinematics; the layout is checked with shapely (no overlaps, nothing outside
the frame, plans inside their cells); the title block sits at its GOST place.
"""

import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from graphplan.drawing import (
    Arrow,
    Text,
    check_layout,
    iter_leaves,
    kinematics_sheet,
    text_box,
)
from graphplan.files import bundled_example
from graphplan.model import load
from graphplan.plans import acceleration_plan, velocity_plan
from graphplan.project import analyze, sheet_scales
from graphplan.render.svg import render_svg

SVG = "{http://www.w3.org/2000/svg}"
EXAMPLES = ["press", "fourbar", "shaper", "shaper_prp", "scotch_yoke", "sixbar_press",
            "offset_slider"]


@pytest.fixture
def built(solved):
    """``built(name)`` → (project, sheet 1, its SVG) of an example, from the session's
    solved projects (tests/conftest.py), drawn once."""

    def get(name):
        a = solved(name)
        sheet = a.stage(("sheet 1", "ru"), lambda: kinematics_sheet(a))
        return a, sheet, a.stage(("sheet 1 svg", "ru"), lambda: render_svg(sheet))

    return get


@pytest.mark.parametrize("name", EXAMPLES)
def test_layout_has_no_problems(built, name):
    _, sheet, _ = built(name)
    assert check_layout(sheet) == []


@pytest.mark.parametrize("name", EXAMPLES)
def test_plans_stay_in_their_cells_and_cells_do_not_overlap(built, name):
    a, sheet, _ = built(name)
    sc = sheet_scales(a.mech, a.kin)
    cells = sc.layout.cells
    # the velocity plans of every position, the acceleration plans of the chosen ones
    assert len(sc.layout.v_cells) == a.kin.n and sc.plans == tuple(range(a.kin.n))
    assert len(sc.layout.a_cells) == len(sc.acc_plans) >= 2
    polys = [c.polygon() for c in cells]
    for i in range(len(polys)):
        for j in range(i + 1, len(polys)):
            assert polys[i].intersection(polys[j]).area < 1e-6
    leaves = list(iter_leaves(sheet.items))
    placed = [(f"vp{k}-", sc.layout.v_cells[c]) for c, k in enumerate(sc.plans)]
    placed += [(f"ap{k}-", sc.layout.a_cells[c]) for c, k in enumerate(sc.acc_plans)]
    for prefix, cell in placed:
        mine = [it for it in leaves if it.id and it.id.startswith(prefix)]
        assert mine, prefix
        for it in mine:
            if isinstance(it, Text):
                assert cell.polygon().contains(text_box(it)), (prefix, it.text)
            elif isinstance(it, Arrow):
                for p in (it.p0, it.p1):
                    assert cell.x0 <= p[0] <= cell.x1 and cell.y0 <= p[1] <= cell.y1


def _arrow_length(root, ident):
    """Length (mm) of a drawn vector, from its shaft start to its arrowhead's tip."""
    g = root.find(f".//{SVG}g[@id='{ident}']")
    assert g is not None, ident
    tip = g.find(f"{SVG}polygon").get("points").split()[0].split(",")
    line = g.find(f"{SVG}line")
    start = (line.get("x1"), line.get("y1")) if line is not None else tip
    return math.dist(tuple(map(float, start)), tuple(map(float, tip)))


@pytest.mark.parametrize("name", ["press", "shaper", "shaper_prp", "scotch_yoke", "fourbar"])
def test_vectors_read_off_the_svg_give_the_exact_kinematics(built, name):
    """pb (mm, measured between the SVG's coordinates) · Kv = |v_B| of the solver.

    The SVG rounds coordinates to 0.01 mm, so a length is good to about 0.015 mm:
    on a 40 mm vector that is 4e-4 relative.
    """
    a, _, svg = built(name)
    root = ET.fromstring(svg)
    sc = sheet_scales(a.mech, a.kin)
    kin = a.kin
    checked = 0
    for k in range(kin.n):
        vp = velocity_plan(a.mech, kin, k, sc.kl, sc.kv)
        ap = acceleration_plan(a.mech, kin, k, sc.kl, sc.ka, vp)
        drawn = [(vp, "p", kin.vel.points, "vp")]
        if k in sc.acc_plans:  # acceleration plans of the chosen positions only
            drawn.append((ap, "π", kin.acc.points, "ap"))
        for plan, pole, table, prefix in drawn:
            for rd in plan.readings.values():
                if not rd.name.startswith(pole) or rd.mm < 4.0:
                    continue
                point = rd.quantity.split("_", 1)[1]
                if point not in table:
                    continue  # a coincident point of another link (a3): no solver array
                mm = _arrow_length(root, f"{prefix}{k}-{rd.name}")
                exact = float(np.hypot(*table[point][k]))
                assert mm * plan.scale.per_mm == pytest.approx(
                    exact, rel=2e-3, abs=0.02 * plan.scale.per_mm)
                checked += 1
    assert checked >= kin.n + len(sc.acc_plans)


def test_svg_is_a1_in_millimetres_with_the_title_block_in_place(built):
    _, _sheet, svg = built("press")
    root = ET.fromstring(svg)
    assert root.get("width") == "841mm" and root.get("height") == "594mm"
    assert root.get("viewBox") == "0 0 841 594"
    # form 1: 185×55 in the bottom-right corner of the frame (836, 589): its top-left
    # line runs from x = 836 − 185 = 651 at y = 589 − 55 = 534
    line = root.find(f".//{SVG}line[@id='tb-line-01']")
    assert (line.get("x1"), line.get("y1"), line.get("x2"), line.get("y2")) == \
        ("651", "534", "836", "534")
    texts = {t.get("id"): "".join(t.itertext()) for t in root.iter(f"{SVG}text") if t.get("id")}
    assert texts["tb-designation"] == "ТММ.КП.00.00.00"
    assert texts["tb-sheet"] == "1"
    assert "Кривошипный пресс" in " ".join(v for k, v in texts.items() if k.startswith("tb-title"))


def test_press_sheet_shows_all_positions_and_the_scales_of_the_seed(built):
    a, sheet, _svg = built("press")
    texts = [t.text for t in iter_leaves(sheet.items) if isinstance(t, Text)]
    # Kl is the seed's: the crank, 0.08 m, drawn 80 mm
    assert "Kl = lOA/OA = 0.08/80 = 0.001 м/мм" in texts
    for lab in a.kin.labels:  # 8 positions and the working positions (2), (3)
        assert any(t == f"План скоростей, пол. {lab}" for t in texts)
    # acceleration plans: the positions of the force analysis, (2), (3) and the idle one
    # (further positions' plans where the grid holds them: their own test below)
    acc = sorted(t for t in texts if t.startswith("План ускорений"))
    assert [f"План ускорений, пол. {a.kin.labels[k]}" for k in a.sheet1.analysed] == [
        "План ускорений, пол. (2)", "План ускорений, пол. (3)", "План ускорений, пол. 2"]
    assert len(acc) == len(a.sheet1.acc_plans) and set(acc) >= {
        "План ускорений, пол. (2)", "План ускорений, пол. (3)", "План ускорений, пол. 2"}
    # the crank pin is numbered in every position on the plan of positions
    pp = [t.text for t in iter_leaves(sheet.items)
          if isinstance(t, Text) and t.id and t.id.startswith("pp-label")]
    for lab in a.kin.labels:
        assert any(lab in s.split(", ") for s in pp), lab


def test_first_position_is_drawn_in_main_line_and_dead_centres_dash_dot_dot(built):
    a, sheet, _ = built("press")
    leaves = {it.id: it for it in iter_leaves(sheet.items) if it.id}
    assert leaves["pp-0-link-1"].style.width == 0.7  # position 1, main line S = 0.7
    # position 5 is the top dead centre of the press (φ = 90°): an extreme position
    k5 = a.kin.labels.index("5")
    assert leaves[f"pp-{k5}-link-1"].style.dasharray == (15.0, 3.0, 1.0, 3.0, 1.0, 3.0)
    k3 = a.kin.labels.index("3")
    assert leaves[f"pp-{k3}-link-1"].style.width == 0.25


def test_plan_of_positions_is_at_scale(built):
    """The crank drawn on the sheet is l_OA/Kl = 0.08/0.001 = 80 mm long in every position."""
    a, sheet, _ = built("press")
    leaves = {it.id: it for it in iter_leaves(sheet.items) if it.id}
    for k in range(a.kin.n):
        ln = leaves[f"pp-{k}-link-1"]
        assert math.dist(ln.p0, ln.p1) == pytest.approx(80.0, abs=1e-9)


def test_diagrams_are_the_sheets_own_vector_items(built):
    """The kinematic diagrams are polylines and slanted texts of the sheet (issue 18), not a
    picture pasted in: no nested SVG, no glyph outlines, nothing raster."""
    _, _, svg = built("press")
    root = ET.fromstring(svg)
    g = root.find(f".//{SVG}g[@id='kin-diagrams']")
    assert g.find(f".//{SVG}svg") is None
    assert len(g.findall(f".//{SVG}polyline")) > 20 and len(g.findall(f".//{SVG}text")) > 10
    assert root.find(f".//{SVG}image") is None  # nothing raster
    ids = [e.get("id") for e in root.iter() if e.get("id")]
    assert len(ids) == len(set(ids))


def test_english_lettering(built):
    a, _, _ = built("fourbar")
    sheet = kinematics_sheet(a, lang="en", diagrams=False)
    texts = [t.text for t in iter_leaves(sheet.items) if isinstance(t, Text)]
    assert any(t.startswith("Velocity plan, pos.") for t in texts)
    assert check_layout(sheet) == []


def _variant_with(tmp_path, extra: str, name="press"):
    text = bundled_example(name).read_text(encoding="utf-8")
    text = text.replace("[drawing]\n", "[drawing]\n" + extra + "\n")
    p = tmp_path / f"{name}.toml"
    p.write_text(text, encoding="utf-8")
    return p


def test_a3_sheet_draws_the_chosen_positions(tmp_path):
    """On A3 the press fits at Kl = 0.004 with the plans of (2) and (3) only."""
    from graphplan.drawing import Page

    p = _variant_with(tmp_path, 'positions = ["(2)", "(3)"]').read_text(encoding="utf-8")
    p = p.replace("Kl = 0.001", "Kl = 0.004")
    (tmp_path / "a3.toml").write_text(p, encoding="utf-8")
    a = analyze(load(tmp_path / "a3.toml"))
    sheet = kinematics_sheet(a, page=Page("A3"))
    assert sheet.page.format == "A3"
    assert check_layout(sheet) == []
    caps = sorted(t.text for t in iter_leaves(sheet.items)
                  if isinstance(t, Text) and t.id and t.id.endswith("-caption")
                  and t.id[:2] in ("vp", "ap"))
    # the acceleration plans of the force analysis' positions, (2), (3) and the idle 2, each
    # on its velocity plan
    assert caps == ["План скоростей, пол. (2)", "План скоростей, пол. (3)",
                    "План скоростей, пол. 2",
                    "План ускорений, пол. (2)", "План ускорений, пол. (3)",
                    "План ускорений, пол. 2"]


def test_unknown_position_to_draw_is_a_one_line_error(tmp_path):
    from graphplan.errors import InputError

    a = analyze(load(_variant_with(tmp_path, 'positions = ["1", "9"]')))
    with pytest.raises(InputError, match=r"press.toml: drawing.positions: expected a position "
                       r"label \(1, 2, .*\), got '9'"):
        kinematics_sheet(a, diagrams=False)


def test_a_plan_of_positions_too_large_for_the_format_is_a_layout_error(built):
    from graphplan.drawing import Page
    from graphplan.errors import LayoutError

    a, _, _ = built("press")  # Kl = 0.001 fixed: 388 mm tall
    with pytest.raises(LayoutError, match="choose a smaller Kl"):
        kinematics_sheet(a, page=Page("A3"))


@pytest.mark.parametrize("name, ccw", [("press", True), ("offset_slider", False)])
def test_sense_of_rotation_is_drawn_at_the_crank(built, name, ccw):
    """The arrowhead of ω1 points counter-clockwise for a ccw crank, clockwise for cw."""
    _, sheet, _ = built(name)
    leaves = {it.id: it for it in iter_leaves(sheet.items) if it.id}
    arc, head = leaves["pp-omega-arc"], leaves["pp-omega-head"]
    c = np.array(arc.centre)
    t0, t1 = np.array(head.p0) - c, np.array(head.p1) - c
    # on paper (y down) a counter-clockwise turn as seen has a negative cross product
    turn = t0[0] * t1[1] - t0[1] * t1[0]
    assert (turn < 0) == ccw
    assert any(isinstance(t, Text) and t.text == "ω1" for t in iter_leaves(sheet.items))


@pytest.mark.parametrize("name", ["press", "shaper", "fourbar", "scotch_yoke"])
def test_analysed_positions_show_omega_and_epsilon_of_every_turning_link(built, name):
    """A scheme of the mechanism in each position of the acceleration plans, with a curved
    arrow and a letter ω2, ε2 … for every link that turns there, its head at the end the
    solver's sign turns to (counter-clockwise positive; the plans flip only y)."""
    from graphplan.drawing import Arc
    from graphplan.drawing.items import arc_point

    a, sheet, _ = built(name)
    sc = sheet_scales(a.mech, a.kin)
    leaves = {it.id: it for it in iter_leaves(sheet.items) if it.id}
    texts = {it.text for it in leaves.values() if isinstance(it, Text)}
    assert sc.analysed and len(sc.layout.schemes) == len(sc.analysed)
    assert sc.acc_plans[:len(sc.analysed)] == sc.analysed
    for k in sc.analysed:
        for link in a.mech.moving_links:
            for sym, value in (("ω", a.kin.vel.omega[link][k]), ("ε", a.kin.acc.epsilon[link][k])):
                ident = f"sch{k}-{sym}{link}"
                if abs(value) < 1e-9:
                    assert f"{ident}-arc" not in leaves
                    continue
                arc, head = leaves[f"{ident}-arc"], leaves[f"{ident}-head"]
                assert isinstance(arc, Arc) and f"{sym}{link}" in texts
                # the head sits at the arc's counter-clockwise end (as seen) when value > 0
                end = arc_point(arc.centre, arc.r, arc.end_deg if value > 0 else arc.start_deg)
                assert math.dist(end, head.p1) < 1e-6, (ident, value)


@pytest.mark.parametrize("name", ["press", "shaper", "sixbar_press"])
def test_structural_scheme_draws_each_assur_group_apart(built, name):
    a, sheet, _ = built(name)
    leaves = [it for it in iter_leaves(sheet.items) if it.id and it.id.startswith("groups-")]
    formulas = [it.text for it in leaves if it.id.endswith("-formula")]
    assert formulas == [f"I({a.structure.initial[0]},{a.structure.initial[1]})"] + [
        g.formula for g in a.structure.groups]
    for i, g in enumerate(a.structure.groups, start=1):
        drawn = {it.id.split("-")[3] for it in leaves
                 if it.id.startswith((f"groups-{i}-link-", f"groups-{i}-slider-"))}
        assert set(g.links) <= drawn, (g.formula, drawn)


@pytest.mark.parametrize("path", ["sixbar_press", "crusher",
                                  "tests/data/variants/crusher_force.toml",
                                  "tests/data/variants/loom_beater.toml"])
def test_the_table_of_the_plans_keeps_every_column_on_a1(drawn, solved, path):
    """Issue 18: a table is split or moved, never cut. The six-bar's 18 columns and the
    crushers' and loom's 20 are 401–443 mm wide at 3.5 mm, their place 309–330 mm: lettered
    2.5 mm they take 286–316 mm (3.5 → 2.5 mm: widths × 5/7, pads 3 → 2.14 mm), every column
    is drawn and the title says nothing is left out."""
    from graphplan.reports import summary_rows

    a, sheet = solved(path), drawn(path, 1)
    header, _ = summary_rows(a, "ru")
    heads = [it for it in iter_leaves(sheet.items) if isinstance(it, Text)
             and re.fullmatch(r"plans-table-r0c\d+", it.id or "")]
    assert [h.text for h in sorted(heads, key=lambda t: int(t.id.rsplit("c", 1)[1]))] == [
        str(h) for h in header]
    title = next(it for it in iter_leaves(sheet.items) if it.id == "table-title")
    assert title.text == "Таблица планов"
    assert {it.height for it in iter_leaves(sheet.items) if isinstance(it, Text)
            and (it.id or "").startswith("plans-table-r")} == {2.5}
    # the table stays left of the title block, inside the frame
    xs = [it.p0[0] for it in iter_leaves(sheet.items) if (it.id or "").startswith("plans-table-v")]
    assert max(xs) <= sheet.page.title_block_rect.x0 and min(xs) >= sheet.page.frame.x0


def test_both_pistons_of_a_two_cylinder_machine_are_numbered_in_every_position(drawn, solved):
    """DEFECTS.md: the compressor's piston C was drawn in its 12 positions but only B's were
    numbered (B0…B11). Every slider on a frame guide has its positions numbered: the letters
    of the plan of positions name C0…C11 as they name B0…B11 (coincident ones written
    together, "C1, C5")."""
    a, sheet = solved("compressor"), drawn("compressor", 1)
    texts = " , ".join(it.text for it in iter_leaves(sheet.items) if isinstance(it, Text)
                       and (it.id or "").startswith("pp-label"))
    named = set(re.findall(r"\b([BC])(\d+)\b", texts))
    for p in "BC":
        assert {(p, lab) for lab in a.kin.labels} <= named, (p, sorted(named))


@pytest.mark.parametrize("name, index", [("compressor", "B"), ("press", "B"), ("fourbar", "3")])
def test_the_diagrams_name_the_point_or_link_they_show(drawn, name, index):
    """DEFECTS.md: a two-piston machine's s, v, a diagrams did not say which piston. The
    ordinates are lettered with the output's index: sB, vB, aB of the piston B (the output
    the variant names), ψ3, ω3, ε3 of a rocker 3."""
    sheet = drawn(name, 1)
    texts = {it.text for it in iter_leaves(sheet.all_items()) if isinstance(it, Text)}
    symbols = ("s", "v", "a") if index.isalpha() else ("ψ", "ω", "ε")
    for sym in symbols:
        assert any(t.startswith(f"{sym}{index}, ") for t in texts), (sym, sorted(texts)[:20])


def test_a_four_stroke_cycle_has_no_idle_stroke_of_540_degrees(solved):
    """DEFECTS.md (families): the engines' structural analysis read "φр.х = 180,0°, φх.х =
    540,0° (рабочий и холостой ход)" — over a 720° cycle an engine has the expansion stroke
    (180°) and three more strokes, no idle stroke of 540°. A cycle of two turns gives the
    working stroke's angle in its cycle; a one-turn cycle (the press) keeps both arcs."""
    from graphplan.drawing.sheet1 import structure_lines

    engine = structure_lines(solved("engine"), "ru")
    assert engine[-1] == "φр.х = 180,0° (рабочий ход) за цикл 720°"
    assert not any("φх.х" in line for line in engine)
    assert structure_lines(solved("press"), "ru")[-1] == (
        "φр.х = 180,0°, φх.х = 180,0° (рабочий и холостой ход)")


# ------------------------------------------- the diagrams against the plans (B.2.5, 7)


def _table_cells(sheet, ident: str) -> dict[tuple[int, int], str]:
    out = {}
    for it in iter_leaves(sheet.all_items()):
        m = re.fullmatch(rf"{ident}-r(\d+)c(\d+)", it.id or "")
        if m and isinstance(it, Text):
            out[int(m[1]), int(m[2])] = it.text.replace(",", ".").replace("−", "-")
    return out


def test_the_diagrams_are_compared_with_the_plans_against_the_closed_form(built):
    """The press (central slider-crank, guide straight down through O, l1 = 0.08 m,
    l2 = 0.2 m): B = (0, yB), yB = l1·sin φ − √(l2² − l1²·cos²φ), s measured along the guide
    (down) in the working direction w. The plan's v is the closed form's derivative,
    v = w·(−yB'(φ))·ω1; the diagram's v at a node is the mean of the two chords either side,
    |ω1|·(s(τ+h) − s(τ−h))/(2h), h = 2π/n: the sheet's table must give both, and
    Δ = (diagram − plan)/plan·100 % to its printed 0.1 %."""
    from graphplan.drawing.sheet1 import fit_sheet_diagrams

    a, sheet, _ = built("press")
    d = fit_sheet_diagrams(a, a.sheet1)
    l1, l2, om = 0.08, 0.2, a.mech.crank.omega
    w = float(a.mech.output.working)

    def q(phi):  # the slider's coordinate along the guide (pointing down)
        return -(l1 * np.sin(phi) - np.sqrt(l2**2 - (l1 * np.cos(phi))**2))

    def dq(phi):
        return -(l1 * np.cos(phi) - l1**2 * np.cos(phi) * np.sin(phi)
                 / np.sqrt(l2**2 - (l1 * np.cos(phi))**2))

    h = 2 * math.pi / d.intervals
    cells = _table_cells(sheet, "diagram-check")
    rows = {cells[i, 1]: i for (i, j) in cells if j == 1 and i > 0}  # ids r<row>c<column>, 1-based
    assert set(rows) == {str(n) for n in range(1, 9)}  # the press's positions 1…8
    checked = 0
    for label, i in rows.items():
        k = a.kin.labels.index(label)
        phi = float(a.kin.phi[k])
        v_plan = w * dq(phi) * om
        tau = phi - d.phi_first  # the crank turns counter-clockwise (sense +1)
        v_diag = abs(om) * w * (q(d.phi_first + tau + h) - q(d.phi_first + tau - h)) / (2 * h)
        assert float(cells[i, 2]) == pytest.approx(v_diag, rel=1e-3, abs=1e-4)
        assert float(cells[i, 3]) == pytest.approx(v_plan, rel=1e-3, abs=1e-4)
        if abs(v_plan) > 0.05 * 0.47:  # away from the dead centres (max |v| = 0.47 m/s)
            delta = (v_diag - v_plan) / v_plan * 100
            assert float(cells[i, 4]) == pytest.approx(delta, abs=0.051)
            checked += 1
        else:
            assert cells[i, 4] == "—"
    assert checked == 6  # positions 2, 3, 4, 6, 7, 8 (1 and 5 are the dead centres)


@pytest.mark.parametrize("name", EXAMPLES)
def test_the_comparison_table_stands_in_the_strip_clear_of_the_table_of_the_plans(built, name):
    """Where the strip holds it, the comparison table stands right of the table of the
    plans, inside the strip, and every column of both is there (nothing cut)."""
    from graphplan.drawing import item_geometry

    a, sheet, _ = built(name)
    strip = a.sheet1.layout.table
    plans = [it for it in iter_leaves(sheet.all_items())
             if (it.id or "").startswith("plans-table-")]
    check = [it for it in iter_leaves(sheet.all_items())
             if (it.id or "").startswith("diagram-check-")]
    if name == "sixbar_press":  # its table of the plans (20 columns) spans the strip
        assert check == []
        return
    assert check, "no comparison table"
    def bounds(it):
        return (text_box(it) if isinstance(it, Text) else item_geometry(it)).bounds

    right = max(bounds(it)[2] for it in plans)
    for it in check:
        x0, y0, x1, y1 = bounds(it)
        assert right < x0 and x1 <= strip.x1 + 1e-6 and strip.y0 - 1e-6 <= y0 and y1 <= strip.y1
    cells = _table_cells(sheet, "diagram-check")
    assert max(j for _, j in cells) == 7
    assert "столбцов" not in next(it.text for it in iter_leaves(sheet.all_items())
                                  if it.id == "table-title")


def test_a_720_degree_cycle_numbers_the_diagrams_nodes_by_the_positions_of_one_turn(solved):
    """The engine: 24 positions every 30° over 720°, 24 intervals of 15° over one turn: the
    positions 0…11 of the first turn fall on every second node (the second turn repeats
    them); before, the nodes were numbered 0…23 one by one, position 1 at 15°."""
    from graphplan.drawing.sheet1 import fit_sheet_diagrams

    a = solved("engine")
    d = fit_sheet_diagrams(a, a.sheet1)
    assert d.intervals == 24
    assert d.node_labels == (*(str(i // 2) if i % 2 == 0 else "" for i in range(24)), "0")


@pytest.mark.parametrize("name", ["compressor", "engine", "pump", "slotter", "crusher"])
def test_a_force_analysis_of_one_position_gets_a_second_acceleration_plan(built, name):
    """Students draw at least two acceleration plans (issue 18: 'by default the working
    and one idle position'): where kinetostatics.positions names one, sheet 1 draws it and
    a position of the other stroke, each with its cell and its ω/ε scheme, every plan
    readable (longest ≥ 40 mm)."""
    from graphplan.kinematics import in_working_stroke

    a, sheet, _ = built(name)
    sc = a.sheet1
    given = [a.kin.labels.index(x) for x in a.mech.settings["kinetostatics"]["positions"]]
    assert len(given) == 1 and sc.analysed[0] == given[0] and len(sc.analysed) == 2
    working = in_working_stroke(a.mech, a.cycle, a.kin.phi)
    assert working[sc.analysed[0]] != working[sc.analysed[1]]
    assert len(sc.layout.a_cells) == len(sc.acc_plans) and len(sc.layout.schemes) == 2
    ids = {it.id for it in iter_leaves(sheet.all_items())}
    for k in sc.analysed:
        assert f"sch{k}-caption" in ids and any((i or "").startswith(f"ap{k}-") for i in ids)


#: GOST 2.302's scales as m/mm (1:1 = 0.001): 2:1, 1:1, 1:2, 1:2.5, 1:4, 1:5, 1:10, 1:15, 1:20,
#: 1:25, 1:40, 1:50, 1:75, 1:100, 1:200, 1:400, 1:500 — written out here, not taken from the
#: code under test
GOST_2_302 = {"0.0005", "0.001", "0.002", "0.0025", "0.004", "0.005", "0.01", "0.015", "0.02",
              "0.025", "0.04", "0.05", "0.075", "0.1", "0.2", "0.4", "0.5"}


@pytest.mark.parametrize("name", [*EXAMPLES, "compressor", "engine", "pump", "slotter",
                                  "crusher"])
def test_the_schemes_are_drawn_at_gost_scales(built, name):
    """The ω/ε schemes and the structural scheme give their Kl under their captions; each is
    one of GOST 2.302's scales (1:7.5 = 0.0075 m/mm and 1:1.5 are not)."""
    _, sheet, _ = built(name)
    scales = [it.text for it in iter_leaves(sheet.all_items())
              if isinstance(it, Text) and re.fullmatch(r"(sch.+|groups)-scale", it.id or "")]
    assert scales
    for text in scales:
        value = re.search(r"Kl = ([0-9.,]+)", text)[1].replace(",", ".")
        assert value in GOST_2_302, text


def test_the_structural_scheme_lists_the_kinematic_pairs_of_the_shaper(built):
    """The shaper (method B.2.1: crank, block, rocker, rod, ram; n = 5, p5 = 7, W = 1):
    the table of the kinematic pairs beside the structural scheme has the 7 lower pairs —
    5 revolute (O1, A, O3, B, C) and 2 prismatic (block 2 in rocker 3, ram 5 on the frame
    6) — each of class 5, and 3·5 − 2·7 = 1 is the W the structural analysis writes."""
    _, sheet, _ = built("shaper")
    cells = _table_cells(sheet, "groups-pairs")
    rows = [[cells[i, j] for j in range(1, 5)] for i in range(1, 1 + max(i for i, _ in cells))]
    assert len(rows) == 7
    assert sorted(r[0] for r in rows if r[2] == "вращ.") == ["A", "B", "C", "O1", "O3"]
    assert sorted(r[1] for r in rows if r[2] == "поступ.") == ["2–3", "5–6"]
    assert {r[3] for r in rows} == {"5"}
    assert 3 * 5 - 2 * len(rows) == 1


@pytest.mark.parametrize("name", ["engine", "offset_slider", "slotter", "press", "shaper"])
def test_a_grid_with_room_draws_further_acceleration_plans_at_the_same_scales(built, name):
    """The method draws acceleration plans of 1–3 positions or of all: where the grid of
    plans holds more at the Kv and Ka the analysed positions' plans get, sheet 1 draws the
    plans of further positions (up to four in all), spread round the cycle, each read (its
    longest vector ≥ 53 mm: a 50 mm shaft and its head) and without a scheme of its own;
    the analysed positions come first, their plans and schemes as before. The same
    project laid out with the analysed positions alone has the same Kv and Ka and no more
    rows of plans."""
    from graphplan.project.scales import ACC_PLANS_MAX

    a, sheet, _ = built(name)
    sc = a.sheet1
    extra = sc.acc_plans[len(sc.analysed):]
    assert extra, f"{name}: no further acceleration plan (the grid held one when written)"
    assert len(sc.acc_plans) <= ACC_PLANS_MAX and len(set(sc.acc_plans)) == len(sc.acc_plans)
    longest = {}
    for it in iter_leaves(sheet.items):
        m = re.match(r"^ap(\d+)-", it.id or "")
        if m and isinstance(it, Arrow):
            k = int(m.group(1))
            longest[k] = max(longest.get(k, 0.0), math.dist(it.p0, it.p1))
    assert set(longest) == set(sc.acc_plans)
    assert all(longest[k] >= 53.0 - 1e-6 for k in extra), longest
    ids = {it.id for it in iter_leaves(sheet.items)}
    assert not any(i and i.startswith(tuple(f"sch{k}-" for k in extra)) for i in ids)
    # each further position is at least as far round the cycle from the plans before it
    # as any other position not drawn (the farthest was taken)
    turn = 2 * math.pi

    def apart(k, among):
        return min(abs((a.kin.phi[k] - a.kin.phi[j] + math.pi) % turn - math.pi) for j in among)

    for i, k in enumerate(extra):
        before = sc.acc_plans[:len(sc.analysed) + i]
        assert apart(k, before) >= apart(extra[-1], before) - 1e-9


def test_flat_schemes_under_the_plan_of_positions_leave_the_height_to_the_diagrams():
    """Under the plan of positions a row of ω/ε schemes grows only as far as its mechanism,
    drawn as wide as its cell, can use; the kinematic diagrams take the rest (up to
    DIAGRAM_MAX_H). Hand-checked: three cells in one row, 64 + 64 + 120 mm in a 300 mm
    column, each 17.3 mm wider (81.3, 81.3, 137.3); a mechanism 0.9 × 0.09 m drawn 113.3 mm
    wide (137.3 − 2·12) is 11.3 mm tall: with 10 mm of arrows and blocks, 2·12 mm of room
    and the 7 mm caption, 52.3 mm — under the row's 67 mm, so the row stays 67 mm; a
    0.5 × 0.5 m mechanism asks 113.3 + 41 − 67 = 87.3 mm more, capped at SCHEME_H's 80.
    The column under a 200 mm plan of positions has 585 − (23 + 200 + 8) = 354 mm: 279 for
    the diagrams under the flat schemes (under DIAGRAM_MAX_H, so nothing goes back to the
    schemes), 199 under the square ones."""
    from graphplan.paper import Page
    from graphplan.project.layout import DIAGRAM_MAX_H, SCHEME_H, sheet1_layout

    def laid(extent):
        return sheet1_layout(Page("A1"), 300.0, 200.0, 12, ((1.0, 0.5),) * 12,
                             ((1.0, 0.6),) * 2, scheme_extent=extent, n_groups=1)

    flat, square = laid((0.9, 0.09)), laid((0.5, 0.5))
    for lay in (flat, square):
        assert len({round(c.y0, 6) for c in (*lay.schemes, lay.groups)}) == 1  # one row
        assert lay.diagrams.y0 >= max(c.y1 for c in (*lay.schemes, lay.groups))
    assert flat.schemes[0].height == pytest.approx(SCHEME_H[0] + 7.0)
    assert square.schemes[0].height == pytest.approx(SCHEME_H[1] + 7.0)
    column_foot = flat.diagrams.y1
    assert flat.diagrams.height == pytest.approx(
        min(DIAGRAM_MAX_H, column_foot - flat.schemes[0].y1 - 8.0))
    assert flat.diagrams.height == pytest.approx(279.0)
    assert square.diagrams.height == pytest.approx(199.0)
