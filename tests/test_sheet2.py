"""Sheet 2 (force analysis): laid out by the standards, and its figures are the constructions'."""

import math

import pytest

from graphplan.drawing import Figure, Text, check_layout, iter_leaves
from graphplan.drawing.sheet2 import kinetostatics_sheet, sheet2_positions
from graphplan.files import bundled_example
from graphplan.forces import compute_loads, solve_forces
from graphplan.model import load
from graphplan.project import analyze

EXAMPLES = ["press", "fourbar", "shaper", "shaper_prp", "scotch_yoke", "sixbar_press",
            "offset_slider"]
_cache: dict = {}


def built(name):
    if name not in _cache:
        a = analyze(load(bundled_example(name)))
        _cache[name] = (a, kinetostatics_sheet(a))
    return _cache[name]


@pytest.mark.parametrize("name", EXAMPLES)
def test_layout_has_no_problems(name):
    _, sheet = built(name)
    assert check_layout(sheet) == []


def _table(sheet):
    """The table of sheet 2 as {row label: {column header: text}}."""
    texts = {t.id: t.text for t in iter_leaves(sheet.items) if isinstance(t, Text) and t.id}
    ncol = max(int(i.split("c")[1]) for i in texts if i.startswith("s2-table-r0c"))
    header = [texts[f"s2-table-r0c{j}"] for j in range(1, ncol + 1)]
    rows, i = {}, 1
    while f"s2-table-r{i}c1" in texts:
        rows[texts[f"s2-table-r{i}c1"]] = {h: texts.get(f"s2-table-r{i}c{j}", "")
                                            for j, h in enumerate(header, 1)}
        i += 1
    return rows


def test_press_sheet_analyses_the_seeds_working_positions_and_one_idle():
    a, sheet = built("press")
    forces = solve_forces(a.mech, a.kin, compute_loads(a.mech, a.kin, a.cycle))
    labels = [a.kin.labels[k] for k in sheet2_positions(a.mech, a.kin, forces, a.cycle)]
    # the variant's extra positions (2), (3), then the idle position of the largest |Mур|:
    # the working stroke runs from position 5 (φ = 90°) to 1 (270°); of the idle 2, 3, 4 (the
    # seed's idle positions) |Mур| = 1153, 966, 462 N·m, so position 2
    m = {lab: abs(forces.M_bal[k]) for k, lab in enumerate(a.kin.labels)}
    assert m["2"] > m["3"] > m["4"]
    assert labels == ["(2)", "(3)", "2"]
    table = _table(sheet)
    assert list(table) == labels
    for lab, row in table.items():
        k = a.kin.labels.index(lab)
        # every reaction in kN, Mур in N·m from the force plans and the lever: the seed's
        # (2) is R12 = 424 kN, Mур = 424·37.39·0.001 = 15.85 kN·m
        for name, r in forces.reactions.items():
            assert float(row[f"{name}, кН"]) == pytest.approx(r.magnitude[k] / 1000, rel=1e-4)
        assert float(row["Mур, Н·м"]) == pytest.approx(forces.M_bal[k], rel=1e-4)
        assert float(row["Mур(Ж), Н·м"]) == pytest.approx(forces.M_bal[k], rel=1e-4)
        assert row["Δ, %"] == "0.00"  # exact constructions agree
    assert float(table["(2)"]["Mур, Н·м"]) == pytest.approx(15850, rel=1e-3)
    assert float(table["(2)"]["h21, мм"]) == pytest.approx(37.39, abs=0.01)
    assert table["(2)"]["Kp, Н/мм"] == "4000"  # Kp = Q/ab = 420000/105 (force_plans)


def test_dead_centre_extras_are_not_default_positions():
    """The four-bar's extra position 1' is a dead centre (Mур ≈ 0 there): sheet 2 takes the
    position of the largest |Mур| instead, and the idle one of the largest |Mур|."""
    a, _ = built("fourbar")
    forces = solve_forces(a.mech, a.kin, compute_loads(a.mech, a.kin, a.cycle))
    rows = sheet2_positions(a.mech, a.kin, forces, a.cycle)
    assert "1'" not in [a.kin.labels[k] for k in rows]
    m = abs(forces.M_bal)
    assert rows[0] == int(m.argmax())
    assert len(rows) == 2 and m[rows[1]] <= m[rows[0]]


def _parts(sheet) -> list[list[str]]:
    """The headers of the parts of the table of sheet 2 (the first, then its continuations)."""
    texts = {t.id: t.text for t in iter_leaves(sheet.items) if isinstance(t, Text) and t.id}
    out = []
    for pre in ["s2-table", *(f"s2-table-{n}" for n in range(2, 10))]:
        cols = [texts[f"{pre}-r0c{j}"] for j in range(1, 40) if f"{pre}-r0c{j}" in texts]
        if cols:
            out.append(cols)
    return out


@pytest.mark.parametrize("fmt", ["A1", "A2", "A3"])
def test_wide_table_is_split_not_cut(fmt):
    """The shaper's table (3 + 7 reactions + 4 columns) is never cut: where it is wider than
    its place it is continued under its title with the position column repeated."""
    from graphplan.drawing import Page

    a, _ = built("shaper")
    sheet = kinetostatics_sheet(a, page=Page(fmt))
    parts = _parts(sheet)
    header = [h for p in parts for h in p[(1 if p is not parts[0] else 0):]]
    total = 3 + 7 + 4  # head, the shaper's seven reactions, tail
    assert len(header) == total and len(set(header)) == total
    assert all(p[0] == "Пол." for p in parts)
    conts = [t.text for t in iter_leaves(sheet.items) if isinstance(t, Text)
             and (t.id or "").startswith("s2-table-title-")]
    assert len(conts) == len(parts) - 1
    assert all(c.startswith("Продолжение таблицы") for c in conts)


def test_arm_h21_is_drawn_at_the_schemes_scale():
    """The perpendicular from O to R21's line, on the scheme at Kl = 0.002 m/mm:
    h21 = 37.389 mm at Kl 0.001 is 18.69 mm on the scheme."""
    a, sheet = built("press")
    leaves = {it.id: it for it in iter_leaves(sheet.items) if it.id}
    k = a.kin.labels.index("(2)")
    h = leaves[f"s2p{k}-h21"]
    cap = leaves[f"s2p{k}-caption"].text
    kl = float(cap.split("Kl = ")[1].split()[0])
    assert math.dist(h.p0, h.p1) * kl == pytest.approx(0.037389, rel=1e-4)


def test_moment_curve_is_embedded_and_unknown_positions_are_errors(tmp_path):
    from graphplan.errors import InputError

    _, sheet = built("press")
    assert not [f for f in iter_leaves(sheet.items) if isinstance(f, Figure)]  # own items
    assert [g.id for g in sheet.items if getattr(g, "id", None) == "s2-moment-curve"]
    text = bundled_example("press").read_text(encoding="utf-8").replace(
        "[kinetostatics]\n", '[kinetostatics]\npositions = ["(4)"]\n')
    p = tmp_path / "press.toml"
    p.write_text(text, encoding="utf-8")
    with pytest.raises(InputError, match=r"press.toml: kinetostatics.positions: expected a "
                       r"position label .* got '\(4\)'"):
        kinetostatics_sheet(analyze(load(p)))
