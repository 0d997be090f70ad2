"""The seed, transcribed into examples/seed-check/seed.toml: what the checker finds in it.

Every expectation is the seed's own arithmetic or geometry worked by hand (in the
comments), or the known discrepancies listed in examples/press.md.
"""

from pathlib import Path

import pytest

from graphplan.checking.checks import check_file

SEED = Path(__file__).resolve().parent.parent / "examples" / "seed-check" / "seed.toml"


@pytest.fixture(scope="module")
def report():
    return check_file(SEED, lang="en")


def _find(report, position, quantity, kind=None):
    hits = [f for f in report.findings if f.position == position and
            quantity in f.quantity.split(" = ") and (kind is None or f.kind == kind)]
    assert hits, f"no finding {quantity} at {position} ({kind})"
    return hits[0]


def _figure(report, position, quantity):
    return next(f for f in report.figures if f.position == position and f.quantity == quantity)


def test_working_stroke_agrees_with_graphplan(report):
    # (2): R12 = 42,4·10 = 424 кН, h21 = 37,39 мм, Мур = 424·37,39·0,001 = 15,85 кН·м;
    # (3): R12 = 601,5 кН, h21 = 19,33 мм, Мур = 11,627 кН·м — all within drafting accuracy
    for pos, q in (("(2)", "Q"), ("(2)", "h21"), ("(2)", "Мур"), ("(3)", "Q"), ("(3)", "R12"),
                   ("(3)", "h21"), ("(3)", "Мур")):
        assert _figure(report, pos, q).verdict == "ok", (pos, q)
    assert _figure(report, "(2)", "R12").stated == pytest.approx(424000.0)


def test_r41_written_in_newtons_is_a_unit_slip(report):
    # "R41= R12=424Н" after "R12=42,4∙10=424 кН": 424 Н is 1/1000 of the reaction
    f = _find(report, "(2)", "R41", "unit")
    assert f.primary and f.stated == pytest.approx(424.0)
    assert f.expected / f.stated == pytest.approx(1000, rel=2e-3)


def test_r43_at_position_2_is_an_arithmetic_slip(report):
    # (299,7414·37,13 + 12262,5·56,57 + 2457,604·56,57 + 1265,49·19,8)/191,3
    # = (11129,40 + 693689,63 + 139026,66 + 25056,70)/191,3 = 868902,39/191,3 = 4542,09
    f = _find(report, "2", "R43", "arithmetic")
    assert f.primary and f.stated == pytest.approx(8145.71)
    assert "4542.1" in f.explanation
    line = next(ln for ln in report.lines if ln.text.startswith("R43=(299"))
    assert line.evaluated == pytest.approx(868902.39 / 191.3, rel=1e-6)


def test_the_consequences_of_the_slip_are_marked_as_such(report):
    # Кр = 8145,71/40,79, R12 = 90,47 мм, Мур = 1370,1 Нм all follow from R43 = 8145,71
    for q in ("R43_mm", "R12", "Мур", "h21"):
        f = _find(report, "2", q)
        assert not f.primary and f.kind == "propagated", q
    assert "R43 (2)" in _find(report, "2", "R12").follows_from


def test_inertia_force_of_the_wrong_sign_at_positions_3_and_4(report):
    # position 4 (φ = 45°): the ram decelerates upwards, Pи3 points up, against G3; the
    # seed adds G3·h3 + Pи3·h3. With the term reversed the formula gives graphplan's R43.
    f = _find(report, "4", "R43", "sign")
    assert f.primary and "Pи3·h3" in f.explanation
    # position 3: R12 = 80,65 мм at Kp = 200 matches the analysis with Pи reversed
    # (16 200 N / 200 = 81,0 mm), not graphplan's 65,2 mm
    g = _find(report, "3", "R12", "sign")
    assert "reversed" in g.explanation
    # position 3: the formula says −Pи3·h3 but the numbers add +1498,51·80
    assert _find(report, "3", "Pи3·h3", "sign").primary


def test_kl_stated_0_001_but_0_002_used(report):
    # "Кl= … =0.001м/мм", but Мур = R21·Кр·h21·Кl uses 0,002 at positions 2, 3, 4; the arms
    # h21 = 37,13 (3) and 19,8 (4) fit 0,002: 74,11/2 = 37,06 and 39,65/2 = 19,83 mm
    f = _find(report, "2", "Кl", "scale")
    assert f.stated == pytest.approx(0.002) and f.expected == pytest.approx(0.001)
    assert "h21 (3)" in f.explanation and "h21 (4)" in f.explanation
    assert _figure(report, "3", "h21").verdict == "ok"
    assert _figure(report, "3", "h21").scale_used.startswith("Kl = 0.002")


def test_mass_900_of_another_variant(report):
    # "Pи3 = m3aВ = 900∙(67∙0.02)": m3 = 1250 kg everywhere else, and Ka = 0,02654
    m3 = _find(report, "4", "m3", "consistency")
    assert m3.stated == 900.0 and m3.expected == 1250.0
    ka = next(f for f in report.findings if f.quantity == "Ka" and f.kind == "scale")
    assert ka.stated == pytest.approx(0.02)
    pi3 = _find(report, "4", "Pи3")
    assert set(pi3.follows_from) >= {"m3", "Ka"}


def test_lever_arm_of_another_force(report):
    # position 3 (φ = 0): "…+1265∙49)/28": h43 = 28 mm is the arm of G2 about A
    # (A–S2 = 0,35·200 = 70 mm; horizontal part 0,35·80 = 28 mm); h43 is 183,3 mm
    f = _find(report, "3", "h43", "lever-arm")
    assert f.stated == 28.0 and f.expected == pytest.approx((200**2 - 80**2) ** 0.5, rel=1e-6)


def test_mirror_positions_follow_from_their_images(report):
    # "Положение 6 симметрично положению 4, поэтому Мур=-643,7Нм": the symmetry holds
    # (graphplan: −462,15 = −(+462,15)); the value follows from position 4's Мур
    for pos, src in (("6", "Mур@4"), ("7", "Mур@3"), ("8", "Mур@2")):
        f = _find(report, pos, "Мур", "propagated")
        assert f.follows_from == (src,)
        assert f.expected == pytest.approx(-_figure(report, src[-1], "Мур").expected)


def test_crank_length_under_the_rod_length_name(report):
    # "Кl= lАВ/AB=0.08/80": 0,08 m and 80 mm are the crank's (lOA, OA), not the rod's
    f = next(f for f in report.findings if f.quantity == "lАВ")
    assert f.kind == "label" and "lOA" in f.explanation


def test_report_is_not_ok(report):
    assert not report.ok
    c = report.counts()
    assert c["primary"] < c["findings"]  # consequences are told apart from faults


def test_the_committed_report_is_up_to_date(report):
    # examples/seed-check/report.json is what `graphplan check … -o examples/seed-check`
    # writes; it must say what the checker says now (structure and values to 1e-6)
    import json

    committed = json.loads((SEED.parent / "report.json").read_text(encoding="utf-8"))
    fresh = check_file(SEED).to_json()

    def key(f):
        return (f["where"], f["quantity"], f["kind"], f["verdict"],
                round(f["stated"] or 0.0, 6), round(f["expected"] or 0.0, 6))

    assert [key(f) for f in committed["findings"]] == [key(f) for f in fresh["findings"]]
    assert committed["summary"] == fresh["summary"]
