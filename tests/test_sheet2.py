"""Sheet 2 (force analysis): laid out by the standards, and its figures are the constructions'."""

import math

import pytest

from graphplan.analysis import analyze
from graphplan.applied_loads import compute_loads
from graphplan.files import bundled_example
from graphplan.kinetostatics import solve_forces
from graphplan.kinetostatics_sheet import kinetostatics_sheet, sheet2_positions
from graphplan.loader import load
from graphplan.sheet import Figure, Text, check_layout, iter_leaves

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


def test_press_sheet_analyses_the_seeds_working_positions():
    a, sheet = built("press")
    texts = {t.id: t.text for t in iter_leaves(sheet.items) if isinstance(t, Text) and t.id}
    labels = [a.kin.labels[k] for k in sheet2_positions(a.mech, a.kin, None)]
    assert labels == ["(2)", "(3)"]  # the variant's extra positions
    rows = {texts[f"s2-table-r{i}c1"]: i for i in (1, 2)}
    forces = solve_forces(a.mech, a.kin, compute_loads(a.mech, a.kin, a.cycle))
    for lab, i in rows.items():
        k = a.kin.labels.index(lab)
        # R12 in kN, Mур in N·m from the force plans and the lever: the seed's (2) is
        # R12 = 424 kN, Mур = 424·37.39·0.001 = 15.85 kN·m
        r12 = float(texts[f"s2-table-r{i}c3"])
        assert r12 == pytest.approx(forces.reactions["R12"].magnitude[k] / 1000, rel=1e-4)
        assert float(texts[f"s2-table-r{i}c5"]) == pytest.approx(forces.M_bal[k], rel=1e-4)
        assert float(texts[f"s2-table-r{i}c6"]) == pytest.approx(forces.M_bal[k], rel=1e-4)
        assert texts[f"s2-table-r{i}c7"] == "0.00"  # exact constructions agree
    assert float(texts["s2-table-r1c5"]) == pytest.approx(15850, rel=1e-3)
    assert float(texts["s2-table-r1c4"]) == pytest.approx(37.39, abs=0.01)


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
    assert [f.id for f in iter_leaves(sheet.items) if isinstance(f, Figure)] == ["s2-moment-curve"]
    text = bundled_example("press").read_text(encoding="utf-8").replace(
        "[kinetostatics]\n", '[kinetostatics]\npositions = ["(4)"]\n')
    p = tmp_path / "press.toml"
    p.write_text(text, encoding="utf-8")
    with pytest.raises(InputError, match=r"press.toml: kinetostatics.positions: expected a "
                       r"position label .* got '\(4\)'"):
        kinetostatics_sheet(analyze(load(p)))
