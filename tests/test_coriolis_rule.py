"""The Coriolis step says the rule of the vector it draws (issue 23: a lesson taught the
rule on v_AA3 while the plan drew v_A3A turned — the opposite direction). The equation
names the sheets' v_AA3 (one notation with the tables); the sentence says that the rule
turns v_A3A = −v_AA3.

For every Coriolis vector laid off on an acceleration plan of every example with a
sliding pair on a moving link, at every position: the vector drawn (from where it is laid
to its end k) is the relative velocity the step names — read off the velocity plan as a
segment — turned by 90° in the sense of the step's ω, and 2·|ω|·|v_r| long at Ka.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from graphplan.model import load
from graphplan.plans import acceleration_plan, velocity_plan
from graphplan.project import analyze, sheet_scales

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def _segment(vp, name: str) -> np.ndarray | None:
    """v_A3A → the vector a→a3 of the velocity plan (tip A3, base A), v_AA3 → a3→a; None if
    unknown."""
    m = re.fullmatch(r"v_([A-Z][a-z]*)([A-Z][a-z]*)(\d+)", name)
    if m and m[1] == m[2]:  # v_AA3: tip A, base A3
        pts = {k.lower(): np.asarray(v, float) for k, v in vp.points.items()}
        tip, base = m[1].lower(), (m[2] + m[3]).lower()
        return pts[tip] - pts[base] if tip in pts and base in pts else None
    m = re.fullmatch(r"v_([A-Z][a-z]*)(\d+)([A-Z][a-z]*)(\d*)", name)
    if not m:
        return None
    tip = (m[1] + m[2]).lower()
    base = (m[3] + m[4]).lower()
    pts = {k.lower(): np.asarray(v, float) for k, v in vp.points.items()}
    if tip not in pts:
        tip = m[1].lower() if m[1].lower() in pts else None
    if base not in pts:
        base = m[3].lower() if m[3].lower() in pts else "p"
    if tip is None:
        return None
    return pts[tip] - pts[base]


@pytest.mark.parametrize("example", ["shaper", "slotter", "shaper_prp"])
def test_the_coriolis_rule_is_the_vector_drawn(example):
    mech = load(EXAMPLES / f"{example}.toml")
    a = analyze(mech)
    sc = sheet_scales(mech, a.kin)
    checked = 0
    for k in range(len(a.kin.labels)):
        vp = velocity_plan(mech, a.kin, k, sc.kl, sc.kv)
        ap = acceleration_plan(mech, a.kin, k, sc.kl, sc.ka, vp)
        for st in ap.steps:
            m = re.fullmatch(r"aᵏ_\w+ = 2·ω(\w+)·(v_\w+)", st.equation)
            if not m or "ω" + m[1] + " = 0" in st.text:
                continue
            rel = _segment(vp, m[2])
            if rel is None or np.hypot(*rel) < 1e-6:
                continue
            # the equation names the sheets' vector; the sentence says which one the rule
            # turns: «v_A3A = −v_AA3» (a slotted link's A3) turns the opposite of v_AA3
            said = re.search(r"turns (v_\w+) = −" + m[2], st.text)
            if said:
                assert "поворачивается " + said[1] + " = −" + m[2] in st.text_ru
                rel = -rel
            elif re.fullmatch(r"v_([A-Z][a-z]*)\1\d+", m[2]):  # v_AA3 needs its sentence
                raise AssertionError((example, st.text))
            (seg,) = [e for e in st.elements if e.kind == "segment"]
            drawn = np.asarray(seg.end, float) - np.asarray(seg.start, float)
            omega = vp.rates[m[1]]
            turned = np.array([-rel[1], rel[0]]) if omega > 0 else np.array([rel[1], -rel[0]])
            cos = float(np.dot(drawn, turned) / (np.hypot(*drawn) * np.hypot(*turned)))
            assert cos == pytest.approx(1.0, abs=1e-9), (example, a.kin.labels[k], st.text)
            # |aᵏ| = 2·|ω|·|v_r|: v_r read at Kv, aᵏ laid at Ka
            expect = 2 * abs(omega) * np.hypot(*rel) * sc.kv.per_mm / sc.ka.per_mm
            assert math.hypot(*drawn) == pytest.approx(expect, rel=1e-9)
            checked += 1
    assert checked >= 5
