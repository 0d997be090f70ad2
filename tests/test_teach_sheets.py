"""The lessons teach the sheets' own figures (issue 23): for every example, the velocity and
acceleration lessons draw sheet 1's plans, the force and lever lessons sheet 2's — the same
scales, every vector the same length and direction in mm, the same letters.

Two routes for each lesson, both independent of the lesson's code:

* at the positions a sheet draws, the sheet itself: its arrows (``vp3-pb``, ``ap3-n_BA``,
  ``s2p3-fp0-R43``, ``s2p3-lever-h_Q5``) are read off the built sheet and compared with the
  lesson's vectors, its letters with the lesson's letters, its scale lines with the
  lesson's scales;
* at every position of the cycle (a lesson may be asked for any), the plan rebuilt here from
  the sheets' scales (:attr:`Project.sheet1`, :attr:`Project.sheet2`) by the construction
  functions themselves.

A lesson that built its plan at another Kl, Kv, Ka, Kp or Kv of the lever, or from another
construction, would fail both.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphplan.drawing.items import Arrow, Text
from graphplan.files import examples_dir
from graphplan.plans import acceleration_plan, force_plans, velocity_plan, zhukovsky_lever
from graphplan.teaching import lesson

EXAMPLES = sorted(examples_dir().glob("*.toml"))
TOL = 1e-6  # mm: the same construction, to rounding


def _walk(items):
    for it in items:
        yield it
        yield from _walk(getattr(it, "items", ()) or ())


def _sheet_arrows(sheet, prefix: str) -> dict[str, tuple[float, float]]:
    """The arrows of one figure of a sheet: name → (dx, dy) in mm, y up as in the plans."""
    out = {}
    for it in _walk(sheet.items):
        if isinstance(it, Arrow) and it.id and it.id.startswith(prefix):
            name = it.id[len(prefix):]
            out[name] = (it.p1[0] - it.p0[0], -(it.p1[1] - it.p0[1]))
    return out


def _sheet_letters(sheet, prefix: str) -> set[str]:
    """The letters a sheet writes at the points of a figure (merged ones split: «p, b, s3»)."""
    out: set[str] = set()
    for it in _walk(sheet.items):
        if isinstance(it, Text) and it.id and it.id.startswith(prefix + "t-"):
            out |= {t.strip() for t in it.text.split(",")}
    return out


def _vectors(marks) -> dict[str, tuple[float, float]]:
    """A lesson's vectors (first drawing of each name, zero vectors left out as the sheets
    leave them out)."""
    out: dict[str, tuple[float, float]] = {}
    for m in marks:
        if m.kind == "vector" and m.name not in out:
            (x0, y0), (x1, y1) = m.points[0], m.points[-1]
            if math.hypot(x1 - x0, y1 - y0) >= 1e-9:
                out[m.name] = (x1 - x0, y1 - y0)
    return out


def _plan_vectors(plan) -> dict[str, tuple[float, float]]:
    out: dict[str, tuple[float, float]] = {}
    for s in plan.steps:
        for e in s.elements:
            if e.kind == "segment" and e.name not in out and math.dist(e.start, e.end) >= 1e-9:
                out[e.name] = (e.end[0] - e.start[0], e.end[1] - e.start[1])
    return out


def _same(mine: dict, theirs: dict, what: str) -> None:
    assert set(mine) == set(theirs), (what, sorted(set(mine) ^ set(theirs)))
    for name, v in mine.items():
        assert np.allclose(v, theirs[name], rtol=0, atol=TOL), (what, name, v, theirs[name])


def _letters(les, panel: int | None = None) -> set[str]:
    return {m.text for s in les.steps if panel is None or s.panel == panel
            for m in s.marks if m.kind == "label" and m.role == "label"}


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_kinematic_lessons_draw_sheet_1s_plans(path, solved, drawn):
    """Velocity and acceleration lessons = sheet 1's plans, at the sheet's positions (read off
    the sheet) and at every position (rebuilt from sheet 1's Kl, Kv, Ka)."""
    p = solved(path)
    sc = p.sheet1
    sheet1 = drawn(path, 1, "en")  # English lettering: the scale lines as the lessons write them
    texts = {it.id: it.text for it in _walk(sheet1.items) if isinstance(it, Text) and it.id}
    compared = 0
    for kind, prefix, on_sheet in (("velocity", "vp", sc.plans), ("acceleration", "ap",
                                                                  sc.acc_plans)):
        for k, label in enumerate(p.kin.labels):
            les = lesson(p, kind, label)
            mine = _vectors(m for s in les.steps for m in s.marks)
            vp = velocity_plan(p.mech, p.kin, k, sc.kl, sc.kv)
            plan = vp if kind == "velocity" else acceleration_plan(p.mech, p.kin, k, sc.kl,
                                                                   sc.ka, vp)
            _same(mine, _plan_vectors(plan), f"{kind} {label}: rebuilt")
            assert _letters(les) == {n.replace("_", "") for n in plan.points}, (kind, label)
            scale = sc.kv if kind == "velocity" else sc.ka
            assert les.scales == (sc.kl.basis, sc.kv.basis) + (
                (sc.ka.basis,) if kind == "acceleration" else ())
            assert les.panels[0].scale == scale.basis
            if k in on_sheet:
                _same(mine, _sheet_arrows(sheet1, f"{prefix}{k}-"), f"{kind} {label}: sheet")
                assert _letters(les) == _sheet_letters(sheet1, f"{prefix}{k}-"), (kind, label)
                for s in les.scales:  # the scale lines of the sheet, word for word
                    assert s in texts.values(), s
                compared += 1
    assert compared == len(sc.plans) + len(sc.acc_plans) > 0


def _plan_panels(les) -> list[int]:
    return [i for i, pn in enumerate(les.panels) if pn.key.startswith("plan-")]


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_force_and_lever_lessons_draw_sheet_2s_plans(path, solved, drawn):
    """The force lesson = sheet 2's force plans (each group's arms at its scheme's Kl, the
    crank's at its own), the lever lesson = sheet 2's lever (its Kl and Kv), at the sheet's
    positions (read off the sheet) and at every position (rebuilt from sheet 2's scales)."""
    p = solved(path)
    s2 = p.sheet2
    sheet2 = drawn(path, 2, "en")
    compared = 0
    for k, label in enumerate(p.kin.labels):
        les = lesson(p, "forces", label)
        # each figure (the groups, then the crank) at its own Kl, as sheet 2 draws it, each
        # taking the reactions as read off the plans drawn before it
        kls = [s2.figure_kl(i) for i in range(len(p.mech.dyads) + 1)]
        plans = force_plans(p.mech, p.kin, p.forces, p.loads, k, tuple(kls), room_mm=s2.room_mm)
        panels = _plan_panels(les)
        assert len(panels) == len(plans)
        for i, (panel, fp) in enumerate(zip(panels, plans, strict=True)):
            assert les.panels[panel].key == f"plan-{fp.group}"
            assert les.panels[panel].scale == fp.scale.basis
            scheme = les.panels[panel - 1]
            assert scheme.key == f"scheme-{fp.group}"
            assert scheme.scale == kls[i].basis
            mine = _vectors(m for s in les.steps if s.panel == panel for m in s.marks)
            _same(mine, _plan_vectors(fp), f"forces {label} {fp.group}: rebuilt")
            assert _letters(les, panel) == set(fp.points), (label, fp.group)
            arms = {r.segment: r.mm for s in les.steps if s.panel == panel - 1
                    for r in s.results}
            for name, mm in arms.items():  # every arm quoted is the plan's, read at its Kl
                assert any(math.isclose(mm, h, abs_tol=TOL) for a, h in fp.arms_mm.items()
                           if a.startswith(name + "@")), (label, name, mm)
            if k in s2.positions:
                _same(mine, _sheet_arrows(sheet2, f"s2p{k}-fp{i}-"),
                      f"forces {label} {fp.group}: sheet")
                assert _letters(les, panel) <= _sheet_letters(sheet2, f"s2p{k}-fp{i}-")
        lev = lesson(p, "zhukovsky", label)
        lever = zhukovsky_lever(p.mech, p.kin, p.loads, k, s2.kl, s2.lever_kv(p.kin, k),
                                reference=float(p.forces.M_bal[k]))
        mine = _vectors(m for s in lev.steps for m in s.marks)
        _same(mine, _plan_vectors(lever), f"lever {label}: rebuilt")
        assert lev.scales == (s2.kl.basis, lever.plan.scale.basis, lever.kf.basis)
        arms = {r.segment: r.mm for r in lev.results if r.segment.startswith("h_")}
        assert arms == pytest.approx({n: r.mm for n, r in lever.readings.items()
                                      if n.startswith("h_")}, abs=TOL)
        if k in s2.positions:
            _same(mine, _sheet_arrows(sheet2, f"s2p{k}-lever-"), f"lever {label}: sheet")
            assert _letters(lev) <= _sheet_letters(sheet2, f"s2p{k}-lever-")
            compared += 1
    assert compared == len(s2.positions) > 0
