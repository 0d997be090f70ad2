"""The breaks of the loads' diagrams (forces.load_breaks): each kink is found on its stroke.

Exact integrals over the cycle take every place where a load jumps or kinks as a node; a
node of a diagram over the output's travel is found by bisection on the crank's travel (all
the nodes of one travel link bisected together). Checked independently here: at each break
the travel link's x, from a fresh assembly at that crank angle, is the node's x.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from graphplan.forces import load_breaks
from graphplan.kinematics import link_coordinate, solve_positions

ROOT = Path(__file__).resolve().parent.parent


@pytest.mark.parametrize("case", ["examples/engine.toml", "examples/compressor.toml",
                                  "examples/press.toml", "tests/data/variants/loom_beater.toml",
                                  "tests/data/variants/v_twin_engine.toml"])
def test_every_kink_of_a_travel_diagram_is_a_break_on_its_stroke(case, solved):
    project = solved(str(ROOT / case))
    mech, cycle = project.mech, project.cycle
    breaks = np.array(load_breaks(mech, cycle))
    sense = mech.crank.sense
    found = 0
    for res in mech.resistances:
        if res.over != "stroke":
            continue
        lt = cycle.travels[(res.travel_link or mech.output.link,
                            res.working or mech.output.working)]
        pos = solve_positions(mech, cycle.origin + sense * breaks)
        q = link_coordinate(mech, lt.link, pos)[1]
        if lt.kind == "rocker":
            q = pos.theta[lt.link]
        x = lt.fraction(q)
        for d in res.stroke_diagrams(round(cycle.period / math.pi)):
            if d is None:
                continue
            for s0, s1, s2 in zip(d, d[1:], d[2:], strict=False):
                kink = s1[0] in (s0[0], s2[0]) or not math.isclose(
                    (s1[1] - s0[1]) * (s2[0] - s1[0]), (s2[1] - s1[1]) * (s1[0] - s0[0]),
                    rel_tol=1e-9, abs_tol=1e-12)
                if kink and 0.0 < s1[0] < 1.0:
                    # the bisection ends within 2^-80 of the stroke's crank travel
                    assert np.min(np.abs(x - s1[0])) < 1e-9, (case, s1)
                    found += 1
    assert found > 0


@pytest.mark.parametrize("case", ["examples/engine.toml", "examples/press.toml",
                                  "tests/data/variants/v_twin_engine.toml"])
def test_a_memo_bisects_each_node_once_and_changes_no_break(case, solved, monkeypatch):
    # the flywheel's reduction asks for the breaks twice (with the strokes' ends and every
    # kink, then without): with one memo the second call bisects nothing, and every break is
    # the same float as without the memo (the bisection stops only where [lo, hi] no longer
    # changes, so it ends where 80 steps would)
    import graphplan.forces.loads as loads_module

    project = solved(str(ROOT / case))
    mech, cycle = project.mech, project.cycle
    alone = (load_breaks(mech, cycle, ends=True), load_breaks(mech, cycle, every_kink=False))
    calls = []
    real = loads_module.solve_positions
    monkeypatch.setattr(loads_module, "solve_positions",
                        lambda *a, **k: calls.append(1) or real(*a, **k))
    memo: dict = {}
    first = load_breaks(mech, cycle, ends=True, memo=memo)
    n_first = len(calls)
    second = load_breaks(mech, cycle, every_kink=False, memo=memo)
    assert (first, second) == alone
    assert n_first > 0 and len(calls) == n_first  # the second call bisected nothing
    # each travel link's nodes stopped at the floating-point limit, not after 80 steps
    assert n_first < 80 * len(memo), (n_first, len(memo))
