"""Solve once: one run of a command solves each stage once per distinct model and grid.

Every stage function of :func:`graphplan.project.solve_project`, in the textbook's order —
the structure, the cycle, the kinematics, the loads with and without the neglect rule, the
reactions, Mур and its curve, the scales and positions of each sheet, the velocity and
acceleration plans, the force plans, the levers, the machine unit — is wrapped wherever a
module holds it, and each call is recorded with what makes it distinct (the positions, the
scales, how it is read, what it is built on). A second call with the same key is a stage
solved again — what the project exists to prevent. The error bounds' probes are distinct
constructions (one reading shifted: the plan they build is not the drawn one), keyed by the
reading they shift; a probe that shifts nothing reads exactly and is keyed as the exact
plan, so the bounds must take the plans built once. Before the project, one run of the
press solved the loads and reactions 10 times at the positions, sheet 1's scales 5 times
and sheet 2's 3 times; before the bounds took the plans built once, 43 velocity plans of
the press were built twice in one ``graphplan sheets``.
"""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

import graphplan.checking.checks as checks
import graphplan.cli
import graphplan.drawing
import graphplan.outputs
import graphplan.reports
import graphplan.teaching
from graphplan.files import bundled_example
from graphplan.project import solve_project

ROOT = Path(__file__).resolve().parent.parent


def _phi(kin) -> bytes:
    return np.asarray(kin.phi, float).tobytes()


def _at(kin, k: int) -> tuple:
    """Position k of these kinematics (its crank angle and the grid it belongs to)."""
    return (_phi(kin), k)


def _scale(s) -> object:
    return None if s is None else (s.symbol, s.per_mm)


def _reader(r) -> tuple:
    """How a plan is read: exactly, to a precision, or a probe shifting its i-th reading
    (counted from the readings it had taken before this plan: the index within the plan)."""
    if r is None:
        return ("read", 0.0)
    shift = getattr(r, "shift", None)
    if shift is None:
        return ("read", float(r.precision))
    local = shift - len(r.calls)
    if shift < 0 or local < 0:  # shifts nothing in this plan: it reads exactly
        return ("read", 0.0)
    return ("probe", float(r.precision), local, r.h)


def _plan(p) -> object:
    """What a construction built on another plan depends on: that plan's readings."""
    if p is None:
        return None
    return (p.kind, _scale(p.scale), tuple(sorted((r.name, r.mm) for r in p.readings.values())),
            tuple(sorted(p.rates.items())), tuple(sorted(p.sliding.items())))


def _known(known) -> object:
    if known is None:
        return None
    return tuple(sorted((n, np.asarray(r.vector, float).tobytes(),
                         np.asarray(r.at, float).tobytes(), float(r.couple), r.offset_mm)
                        for n, r in known.items()))


def _kls(kl) -> object:
    return tuple(_scale(x) for x in kl) if isinstance(kl, tuple) else _scale(kl)


def _id(x) -> object:
    """``x`` where it is a value, its identity where it is not hashable."""
    try:
        hash(x)
    except TypeError:
        return id(x)
    return x


#: stage → (package holding it, key of one distinct solve from the call's arguments)
STAGES = {
    "analyse": ("graphplan.model", lambda mech: ()),
    "analyse_cycle": ("graphplan.kinematics", lambda mech: ()),
    "sweep": ("graphplan.kinematics", lambda mech, cycle: ()),
    # the kinematics on any grid (the positions' sweep, a fine turn for the trajectories and
    # the slots, the diagrams' intervals, Mур's curve)
    "solve": ("graphplan.kinematics", lambda mech, phi, *a, **kw: (
        np.asarray(phi, float).tobytes(),)),
    # the diagrams at each size tried (their motion solved once: "solve" counts it)
    "kinematic_diagrams": ("graphplan.plans", lambda mech, cycle, **kw: tuple(sorted(
        (k, v) for k, v in kw.items() if k != "motion"))),
    "sheet2_positions": ("graphplan.project", lambda mech, kin, *a, **kw: (_phi(kin),)),
    "acceleration_positions": ("graphplan.project", lambda mech, kin, *a, **kw: (_phi(kin),)),
    "compute_loads": ("graphplan.forces", lambda mech, kin, cycle=None, **kw: (
        _phi(kin), kw.get("inertia"), kw.get("neglect_below"), kw.get("shift_inertia"),
        kw.get("kinds"))),
    "solve_forces": ("graphplan.forces", lambda mech, kin, loads, *a, **kw: (
        _phi(kin), loads.inertia, loads.neglect_below, id(loads))),
    "moment_curve": ("graphplan.forces", lambda mech, kin, cycle, *a, **kw: (
        _phi(kin), kw.get("neglect_below"))),
    "sheet_scales": ("graphplan.project",
                     lambda mech, kin, page=None, **kw: (_phi(kin), page)),
    "sheet2_scales": ("graphplan.project",
                      lambda mech, kin, forces, cycle, page=None, **kw: (_phi(kin), page)),
    "velocity_plan": ("graphplan.plans", lambda mech, kin, k, kl, kv, reader=None: (
        *_at(kin, k), _scale(kl), _scale(kv), _reader(reader))),
    "acceleration_plan": ("graphplan.plans", lambda mech, kin, k, kl, ka, vplan, reader=None: (
        *_at(kin, k), _scale(kl), _scale(ka), _reader(reader), _plan(vplan))),
    # the chain of sheet 2's (or the tables') force plans of a position
    "force_plans": ("graphplan.plans", lambda mech, kin, forces, loads, k, kl, reader=None,
                    room_mm=None, **kw: (*_at(kin, k), id(loads), _kls(kl), _reader(reader),
                                         room_mm, _id(kw.get("scales")))),
    # one plan of the chain (the error bounds' probes build them one by one)
    "force_plan": ("graphplan.plans", lambda mech, kin, forces, loads, k, gi, kp=None, *, kl,
                   reader=None, known=None, room_mm=None: (
        *_at(kin, k), id(loads), gi, _scale(kp), _scale(kl), _reader(reader), _known(known),
        room_mm)),
    "crank_plan": ("graphplan.plans", lambda mech, kin, forces, loads, k, kp=None, *, kl,
                   reader=None, known=None, room_mm=None: (
        *_at(kin, k), id(loads), _scale(kp), _scale(kl), _reader(reader), _known(known),
        room_mm)),
    "zhukovsky_lever": ("graphplan.plans", lambda mech, kin, loads, k, kl, kv, reader=None,
                        **kw: (*_at(kin, k), id(loads), _scale(kl), _scale(kv),
                               _reader(reader), _plan(kw.get("plan")))),
    "reduced_inertia": ("graphplan.dynamics", lambda mech, kin: (_phi(kin),)),
    "dynamic_model": ("graphplan.dynamics", lambda analysis, *a, **kw: ()),
    "machine_unit": ("graphplan.dynamics", lambda analysis, **kw: ()),
}


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


def _again(calls: Counter) -> list[str]:
    return sorted({f"{name} ×{n}" for (name, _), n in calls.items() if n > 1})


COMMANDS = {
    "sheets": lambda ex, tmp: ["sheets", str(bundled_example(ex)), "-o", str(tmp)],
    "analyze --json": lambda ex, tmp: ["analyze", str(bundled_example(ex)), "--json"],
    "teach": lambda ex, tmp: ["teach", str(bundled_example(ex)), "--position", "1", "--plan",
                              "velocity", "acceleration", "forces", "zhukovsky", "-o", str(tmp)],
}


EXAMPLES = sorted(p.stem for p in (ROOT / "examples").glob("*.toml"))


@pytest.mark.parametrize("example", EXAMPLES)
def test_one_sheets_run_solves_each_stage_once(example, count_stages, tmp_path):
    assert graphplan.cli.main(COMMANDS["sheets"](example, tmp_path)) == 0
    assert not _again(count_stages), f"stages solved again in one run: {_again(count_stages)}"
    solved = Counter(name for name, _ in count_stages)
    assert solved["analyse"] == solved["analyse_cycle"] == solved["sweep"] == 1
    # at the positions, with the variant's neglect rule and with nothing neglected
    assert solved["compute_loads"] >= 2 and solved["solve_forces"] >= 2
    assert solved["sheet_scales"] == solved["sheet2_scales"] == 1
    assert solved["moment_curve"] == 1
    mech = graphplan.load(bundled_example(example))
    unit = int("delta" in mech.settings.get("dynamics", {}))  # sheet 3's machine unit
    assert solved["machine_unit"] == solved["dynamic_model"] == unit
    # every position's plans, force plans and lever seen (the count is not empty)
    n = mech.positions.count
    for stage in ("velocity_plan", "acceleration_plan", "force_plans", "zhukovsky_lever",
                  "force_plan", "crank_plan"):
        assert solved[stage] >= n, stage
    # the error bounds' probes are counted too: one per reading of the drawn plans
    probes = sum(1 for name, key in count_stages if name == "velocity_plan"
                 and key[-1][0] == "probe")
    assert probes >= n


@pytest.mark.parametrize("command", ["analyze --json", "teach"])
def test_the_report_and_the_lessons_solve_each_stage_once(command, count_stages, tmp_path):
    assert graphplan.cli.main(COMMANDS[command]("press", tmp_path)) == 0
    assert not _again(count_stages), f"stages solved again: {_again(count_stages)}"
    solved = Counter(name for name, _ in count_stages)
    assert solved["analyse"] == solved["sweep"] == 1
    assert solved["velocity_plan"] >= 1 and solved["force_plans"] >= 1


def test_checking_students_solves_each_variant_once(count_stages, tmp_path, monkeypatch):
    """``graphplan check`` of several students' files (in this process; a class folder is
    checked by bounded workers, each its own process): the students of one variant are
    checked against one solved project (the hand-written engine works: correct and with
    carried mistakes)."""
    # a fresh process's cache of solved variants: another test of this worker may have
    # checked the engine already, and its reference would then be solved 0 times here
    monkeypatch.setattr(checks, "_REFERENCES", {})
    work = tmp_path / "class"
    work.mkdir()
    for name in ("engine_ok.toml", "engine_faults.toml"):
        text = (ROOT / "tests" / "data" / "students" / name).read_text(encoding="utf-8")
        variant = (ROOT / "examples" / "engine.toml").as_posix()
        (work / name).write_text(text.replace('"../../../examples/engine.toml"',
                                              f'"{variant}"'), encoding="utf-8")
    graphplan.cli.main(["check", str(work / "engine_ok.toml"), str(work / "engine_faults.toml"),
                        "-o", str(tmp_path / "out")])
    assert not _again(count_stages), f"stages solved again: {_again(count_stages)}"
    solved = Counter(name for name, _ in count_stages)
    assert solved["analyse"] == solved["sweep"] == 1


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
