"""Tables of the force analysis (graphplan.reports.force_tables) on the seed's press.

* Every number of the CSV is a force plan's reading (or arm, or Mур), and in exact mode
  equals the exact kinetostatics (solve_forces) to 1e-9; ``mm·scale = value``.
* The ru and en Markdown differ in their words, not in their columns; no nan/inf.
* The press's working position (2) lands on the seed's figures (hand arithmetic below).
* The curve of Mур at the positions equals solve_forces' M_bal there, every load counted.
* examples/press.md is a fresh generation of seed_comparison_markdown.
"""

from __future__ import annotations

import csv
import io
import math
import re
from pathlib import Path

import numpy as np
import pytest

import graphplan as g
from graphplan.files import bundled_example
from graphplan.forces import compute_loads, solve_forces
from graphplan.project import analyze
from graphplan.reports import force_readings, forces_csv, forces_markdown, seed_comparison_markdown
from graphplan.reports.force_tables import CSV_COLUMNS

REL = 1e-9
PRESS_MD = Path(__file__).resolve().parents[1] / "examples" / "press.md"
NUMBER = re.compile(r"-?\d+(?:\.\d+)?")


@pytest.fixture(scope="module")
def press(solved):
    an = solved("press")  # the session's project (tests/conftest.py)
    return an, an.forces


@pytest.fixture(scope="module")
def rows(press):
    an, _ = press
    return list(csv.DictReader(io.StringIO(forces_csv(an))))


@pytest.fixture(scope="module")
def readings(press):
    return {pf.label: pf for pf in force_readings(press[0])}


def _close(a: float, b: float, big: float) -> bool:
    return abs(a - b) <= REL * abs(b) + 1e-12 * big


def test_csv_is_the_force_plans(rows, readings):
    assert rows and tuple(rows[0]) == CSV_COLUMNS
    seen = 0
    for r in rows:
        pf = readings[r["position"]]
        plans = pf.plans(r["mode"])
        for key in ("mm", "scale_per_mm", "value", "exact_value", "error_pct", "phi_deg"):
            if r[key]:
                assert math.isfinite(float(r[key])), r
        if r["kind"] == "segment":
            p = next(p for p in plans if p.group == r["plan"])
            rd = p.readings[r["quantity"]]
            assert (float(r["mm"]), float(r["value"]), r["segment"]) == (rd.mm, rd.value, rd.name)
            assert float(r["scale_per_mm"]) == p.scale.per_mm
            assert float(r["mm"]) * float(r["scale_per_mm"]) == pytest.approx(
                float(r["value"]), rel=1e-12, abs=1e-9)
            seen += 1
        elif r["kind"] == "arm":
            p = next(p for p in plans if p.group == r["plan"])
            assert float(r["mm"]) == p.arms_mm[r["quantity"]]
            assert float(r["mm"]) * float(r["scale_per_mm"]) == pytest.approx(
                float(r["value"]), rel=1e-12, abs=1e-15)
        elif r["kind"] == "moment" and r["quantity"] == "Mур":
            assert float(r["value"]) == plans[-1].M_bal
        elif r["kind"] == "moment" and r["quantity"] == "Mур(Ж)":
            assert float(r["value"]) == pf.lever(r["mode"]).M_bal
        if r["mode"] == "exact" and r["exact_value"]:
            assert float(r["value"]) == float(r["exact_value"])
    assert seen > 50


def test_exact_csv_equals_the_kinetostatics(press, rows):
    an, forces = press
    m_big = float(np.abs(forces.M_bal).max())
    arms = forces.crank_arms()
    kl = 0.001  # the variant's Kl
    for r in rows:
        if r["mode"] != "exact":
            continue
        k = an.kin.labels.index(r["position"])
        v = float(r["value"])
        if r["kind"] == "segment" and r["quantity"] in forces.reactions:
            ex = forces.reactions[r["quantity"]]
            big = max(float(np.hypot(*x.vector[k])) for x in forces.reactions.values())
            assert _close(v, float(ex.magnitude[k]), big), r
        elif r["kind"] == "moment" and r["quantity"] in ("Mур", "Mур(Ж)"):
            assert _close(v, float(forces.M_bal[k]), m_big), r
        elif r["kind"] == "arm" and r["quantity"] == "h21":
            assert _close(float(r["mm"]) * kl, float(arms["R21"][k]), 1.0), r


def test_markdown_languages_and_finiteness(press):
    an, _ = press
    ru, en = forces_markdown(an, "ru"), forces_markdown(an, "en")
    assert not re.search(r"\b(nan|inf)\b", ru + en, re.IGNORECASE)
    head_ru = [ln for ln in ru.splitlines() if ln.startswith("| ") and "---" not in ln]
    head_en = [ln for ln in en.splitlines() if ln.startswith("| ") and "---" not in ln]
    assert len(head_ru) == len(head_en)
    differ = 0
    for a, b in zip(head_ru, head_en, strict=True):
        assert a.count("|") == b.count("|")
        differ += a != b
    assert differ > 0
    assert "Положение (2)" in ru and "Position (2)" in en
    assert "Мур (планы сил)" in ru and "Mур (force plans)" in en
    with pytest.raises(ValueError):
        forces_markdown(an, "de")


def test_press_working_position_2(readings):
    # Seed, position (2): Kp = 420/42 = 10 kN/mm, R12 = 42.4·10 = 424 kN, h21 = 37.39 mm,
    # Mур = R21·h21·Kl = 424·37.39·0.001 = 15.85 kN·m. By hand for the model: Q = 0.7·Q0
    # = 420 kN acts along the guide; Rτ12 = 0 (no load on the rod), so R12 ∥ AB and
    # R12 = Q/cos β with sin β = r·sin 20°/L = 80·0.34202/200 = 0.136808, cos β = 0.990597:
    # 420/0.990597 = 424.0 kN; h21 = r·sin(20° + β) = 80·sin(20° + 7.8631°) = 80·0.46736
    # = 37.39 mm; Mур = 424.0·37.39·0.001 = 15.85 kN·m.
    pf = readings["(2)"]
    crank = pf.exact[-1]
    r12 = pf.exact[0].reactions["R12"].magnitude
    assert r12 == pytest.approx(424e3, rel=2e-3)
    assert crank.arms_mm["h21"] == pytest.approx(37.39, abs=0.01)
    assert crank.M_bal == pytest.approx(15.85e3, rel=1e-3)
    assert pf.lever_exact.M_bal == pytest.approx(crank.M_bal, rel=REL)
    assert {"G3", "Pи3"} <= set(pf.neglected)
    assert "Q" not in pf.neglected
    # drafting at 0.5 mm stays within a few percent
    assert pf.drafted[-1].M_bal == pytest.approx(crank.M_bal, rel=0.03)
    assert pf.M_full != pytest.approx(pf.M_bal, rel=1e-6)  # the rule changes Mур


def test_moment_curve_at_the_positions(press):
    an, forces = press
    c = an.curve
    travel, M = c
    assert len(travel) == len(M) >= 360
    assert np.all(np.diff(travel) > 0) and travel[0] == 0.0 and travel[-1] < 360.0
    assert np.isfinite(M).all()
    big = float(np.abs(forces.M_bal).max())
    # the curve carries every load (issue 18: the neglect rule is the positions' force plans',
    # it made false steps on the curve): at the positions, the kinetostatics of every load
    from graphplan.forces import compute_loads, solve_forces

    every = solve_forces(an.mech, an.kin, compute_loads(an.mech, an.kin, an.cycle,
                                                        neglect_below=0.0)).M_bal
    assert np.allclose(c.M_positions, every, rtol=REL, atol=1e-12 * big)
    assert np.array_equal(M[c.index], c.M_positions)
    assert np.allclose(c.position_travel_deg, travel[c.index])
    # the seed's press: M_ур is positive in the idle stroke's first half (the motor lifts
    # the ram) and mirrors to negative in its second half
    lab = dict(zip(an.kin.labels, c.M_positions, strict=True))
    assert lab["2"] > 0 and lab["8"] == pytest.approx(-lab["2"], rel=1e-6)


def _split(text: str) -> tuple[str, list[float]]:
    return NUMBER.sub("#", text), [float(x) for x in NUMBER.findall(text)]


def test_examples_press_md_is_up_to_date(press):
    an, _ = press
    fresh, committed = seed_comparison_markdown(an), PRESS_MD.read_text(encoding="utf-8")
    (s1, n1), (s2, n2) = _split(fresh), _split(committed)
    assert s1 == s2, "examples/press.md is out of date: regenerate it with " \
        "seed_comparison_markdown(analyze(load('examples/press.toml')))"
    assert len(n1) == len(n2)
    assert all(abs(a - b) <= 0.01 + 1e-9 for a, b in zip(n1, n2, strict=True))


@pytest.mark.parametrize("name", ["fourbar", "shaper", "shaper_prp", "scotch_yoke",
                                  "sixbar_press", "offset_slider"])
def test_every_example(name):
    an = analyze(g.load(bundled_example(name)))
    forces = solve_forces(an.mech, an.kin, compute_loads(an.mech, an.kin, an.cycle))
    text = forces_markdown(an, "en") + forces_csv(an)
    assert not re.search(r"\b(nan|inf)\b", text, re.IGNORECASE)
    c = an.curve  # every load (issue 18)
    every = solve_forces(an.mech, an.kin, compute_loads(an.mech, an.kin, an.cycle,
                                                        neglect_below=0.0)).M_bal
    big = float(np.abs(forces.M_bal).max())
    assert np.allclose(c.M_positions, every, rtol=REL, atol=1e-12 * big)
