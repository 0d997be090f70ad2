"""Solve once: one ``graphplan sheets`` run solves each stage once per distinct model and grid.

Every stage function is wrapped, wherever a module holds it, and each call is recorded with
what makes it distinct (the crank angles it is solved at, the neglect rule, the inertia
flag, the page). A second call with the same key is a stage solved again — what the
project (:func:`graphplan.project.solve_project`) exists to prevent. Before the project, one
run of the press solved the loads and reactions 10 times at the positions, sheet 1's
scales 5 times and sheet 2's 3 times.
"""

from __future__ import annotations

import sys
from collections import Counter

import numpy as np
import pytest

import graphplan.cli
import graphplan.drawing
import graphplan.outputs
import graphplan.reports
from graphplan.files import bundled_example
from graphplan.project import solve_project


def _phi(kin) -> bytes:
    return np.asarray(kin.phi, float).tobytes()


#: stage → (package holding it, key of one distinct solve from the call's arguments)
STAGES = {
    "analyse_cycle": ("graphplan.kinematics", lambda mech: ()),
    "sweep": ("graphplan.kinematics", lambda mech, cycle: ()),
    "compute_loads": ("graphplan.forces", lambda mech, kin, cycle=None, **kw: (
        _phi(kin), kw.get("inertia"), kw.get("neglect_below"), kw.get("shift_inertia"),
        kw.get("kinds"))),
    "solve_forces": ("graphplan.forces", lambda mech, kin, loads, *a, **kw: (
        _phi(kin), loads.inertia, loads.neglect_below, id(loads))),
    "sheet_scales": ("graphplan.project",
                     lambda mech, kin, page=None, **kw: (_phi(kin), page)),
    "sheet2_scales": ("graphplan.project",
                      lambda mech, kin, forces, cycle, page=None, **kw: (_phi(kin), page)),
    "moment_curve": ("graphplan.forces", lambda mech, kin, cycle, *a, **kw: (_phi(kin),)),
    "machine_unit": ("graphplan.dynamics", lambda analysis, **kw: ()),
    "dynamic_model": ("graphplan.dynamics", lambda analysis, *a, **kw: ()),
    "reduced_inertia": ("graphplan.dynamics", lambda mech, kin: (_phi(kin),)),
    # the plans of the positions: sheet 1's and sheet 2's, the reports', the JSON's
    "force_plans": ("graphplan.plans", lambda mech, kin, forces, loads, k, kl, reader=None,
                    room_mm=None, **kw: (_phi(kin), id(loads), k, kl, _id(reader), room_mm,
                                         _id(kw.get("scales")))),
    "zhukovsky_lever": ("graphplan.plans", lambda mech, kin, loads, k, kl, kv, reader=None,
                        **kw: (_phi(kin), id(loads), k, kl, kv, _id(reader),
                               kw.get("reference"))),
}


def _id(x) -> object:
    """``x`` where it is a value (a Scale, the exact reader), its identity where it is not
    hashable (a drafting probe, a dict of scales)."""
    try:
        hash(x)
    except TypeError:
        return id(x)
    return x


@pytest.fixture
def count_stages(monkeypatch):
    """Wrap every stage function in every graphplan module that holds it."""
    calls: Counter = Counter()
    for name, (package, key) in STAGES.items():
        original = getattr(sys.modules[package], name)

        def wrapper(*args, _f=original, _name=name, _key=key, **kwargs):
            calls[(_name, _key(*args, **kwargs))] += 1
            return _f(*args, **kwargs)

        for mod in [m for n, m in sys.modules.items() if n.startswith("graphplan")]:
            if getattr(mod, name, None) is original:
                monkeypatch.setattr(mod, name, wrapper)
    return calls


@pytest.mark.parametrize("example", ["press", "fourbar"])
def test_one_sheets_run_solves_each_stage_once(example, count_stages, tmp_path):
    assert graphplan.cli.main(["sheets", str(bundled_example(example)), "-o",
                               str(tmp_path)]) == 0
    again = {f"{name} ×{n}" for (name, _), n in count_stages.items() if n > 1}
    assert not again, f"stages solved again in one run: {sorted(again)}"
    solved = Counter(name for name, _ in count_stages)
    # at the positions, with the variant's neglect rule and with nothing neglected
    assert solved["sheet_scales"] == solved["sheet2_scales"] == 1
    assert solved["moment_curve"] == 1
    assert solved["machine_unit"] <= 1 and solved["dynamic_model"] <= 1
    assert solved["analyse_cycle"] == solved["sweep"] == 1
    # every position's force plans and lever seen (the count is not empty), none twice
    n = graphplan.load(bundled_example(example)).positions.count
    assert solved["force_plans"] >= n and solved["zhukovsky_lever"] >= n


def test_the_count_sees_a_stage_solved_twice(count_stages):
    """The wrapper itself: two sheet 1 scales of the same project are two solves."""
    from graphplan.project import sheet_scales, solve_project

    p = solve_project(graphplan.load(bundled_example("fourbar")))
    sheet_scales(p.mech, p.kin)
    sheet_scales(p.mech, p.kin)
    assert count_stages[("sheet_scales", (_phi(p.kin), None))] == 2
    assert p.sheet1 is p.sheet1  # the project's: solved once, kept


@pytest.mark.parametrize("example", ["press", "sixbar_press"])
def test_the_json_reports_the_figures_sheet_2_draws(example):
    """analyze --json's force plans and lever are sheet 2's, each figure at the Kl it is drawn
    at (the groups' schemes, the crank's own), each group taking the reactions as read off
    the plans drawn before it: the same objects the sheet and the lessons draw."""
    from graphplan.plans import crank_plan, force_plan

    p = solve_project(graphplan.load(bundled_example(example)))
    s2 = p.sheet2
    out = p.to_json()
    n_fig = len(p.mech.dyads) + 1
    for k, entry in enumerate(out["positions"]):
        plans = p.force_plans(k)
        # the chain built by hand: each figure at its own Kl, knowing the plans before it
        known: dict = {}
        for i, gi in enumerate([*reversed(range(len(p.mech.dyads))), None]):
            kl = s2.figure_kl(i)
            room = s2.room_mm[i] if isinstance(s2.room_mm, tuple) else s2.room_mm
            by_hand = (crank_plan(p.mech, p.kin, p.forces, p.loads, k, kl=kl, known=known,
                                  room_mm=room) if gi is None else
                       force_plan(p.mech, p.kin, p.forces, p.loads, k, gi, kl=kl, known=known,
                                  room_mm=room))
            known.update(by_hand.reactions)
            assert {r.name: r.mm for r in by_hand.readings.values()} == {
                r.name: r.mm for r in plans[i].readings.values()}
            assert by_hand.arms_mm == plans[i].arms_mm
        assert len(entry["force_plans"]) == n_fig
        for i, (fj, fp) in enumerate(zip(entry["force_plans"], plans, strict=True)):
            assert fj["Kl"] == s2.figure_kl(i).per_mm
            assert fj["segments_mm"] == {r.name: r.mm for r in fp.readings.values()}
            assert fj["M_bal"] == fp.M_bal
        lever = p.lever(k)
        assert entry["zhukovsky"]["Kl"] == s2.kl.per_mm
        assert entry["zhukovsky"]["Kv"] == s2.lever_kv(p.kin, k).per_mm
        assert entry["zhukovsky"]["arms_mm"] == {r.name: r.mm for r in lever.readings.values()}
        assert entry["zhukovsky"]["M_bal"] == lever.M_bal
