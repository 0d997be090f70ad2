"""The lean full cycle (graphplan.forces.lean, issue 21) computes what the general path does.

:class:`FullCycle` generates one straight-line function per mechanism; these tests hold it to
the general path (:func:`solve`, :func:`compute_loads`, :func:`solve_forces`) on every example
and test variant — every point's position, velocity and acceleration, every link's ω and ε,
every reaction, the prismatic pairs' normal forces and couples, and M_ур — to 1e-12 of each
quantity's largest value over the cycle, with the neglect rule and without it, and on a grid
with the positions the sheets use. Its speed is the benchmark's (``python -m benchmarks``),
never a test's.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

import graphplan as g
from graphplan.forces import FullCycle

ROOT = Path(__file__).resolve().parent.parent
CASES = sorted(p.relative_to(ROOT).as_posix() for p in
               [*(ROOT / "examples").glob("*.toml"),
                *(ROOT / "tests/data/variants").glob("*.toml")])


def _grid(cycle, n: int) -> np.ndarray:
    """n angles over the whole cycle (both turns of a 720° one) plus the sheets' positions
    (dead centres among them): φ and φ + 2π are different moments of a four-stroke cycle."""
    fine = cycle.origin + (np.arange(n) + 0.37) * (cycle.period / n)
    return np.concatenate([fine, np.asarray(cycle.phi, float)])


def _rel(a, b) -> float:
    a = np.broadcast_to(a, np.shape(b))
    scale = float(np.max(np.abs(b)))
    return float(np.max(np.abs(a - b))) / scale if scale > 0 else float(np.max(np.abs(a)))


def _agree(lean, general, size: float) -> dict[str, float]:
    """The largest relative difference of each kind of quantity (the couples of prismatic
    pairs relative to their normal force times the group's size: a couple that is zero but
    for round-off has no scale of its own)."""
    worst: dict[str, float] = {}
    for table in ("points", "velocities", "accelerations", "omega", "epsilon", "reactions",
                  "normal"):
        got, want = getattr(lean, table), getattr(general, table)
        assert set(got) == set(want), (table, set(got) ^ set(want))
        worst[table] = max((_rel(got[k], want[k]) for k in want), default=0.0)
    assert set(lean.couple) == set(general.couple)
    worst["couple"] = max((float(np.max(np.abs(lean.couple[k] - general.couple[k])))
                           / max(size * float(np.max(np.abs(general.normal[k]))), 1e-300)
                           for k in general.couple), default=0.0)
    worst["M_bal"] = _rel(lean.M_bal, general.M_bal)
    return worst


@pytest.mark.parametrize("case", CASES)
def test_the_lean_path_equals_the_general_path_to_1e_12(case, solved):
    project = solved(str(ROOT / case))
    mech, cycle = project.mech, project.cycle
    size = max([mech.crank.length, *(ln for d in mech.dyads for ln in d.lengths)])
    phi = _grid(cycle, 360)
    # the variant's rule; every load kept; no inertia and a rule that drops loads often
    # (the dynamics' setting, where a group may have only its weights: decided once)
    for inertia, neglect in ((None, None), (None, 0.0), (False, 0.4)):
        fc = FullCycle(mech, cycle, inertia=inertia, neglect_below=neglect)
        assert fc.native, case  # compiled, not handed to the general path
        lean = fc(phi)
        assert lean.native
        worst = _agree(lean, fc.general(phi), size)
        assert max(worst.values()) < 1e-12, (case, inertia, neglect, worst)


def test_a_long_sweep_agrees(solved):
    # past 4,096 positions the check for NaN sums each output instead of copying them all
    project = solved(str(ROOT / "examples/sixbar_press.toml"))
    fc = FullCycle(project.mech, project.cycle)
    assert "; del " in fc.source  # each array deleted after its last use
    phi = _grid(project.cycle, 4100)
    worst = _agree(fc(phi), fc.general(phi), 1.0)
    assert max(worst.values()) < 1e-12, worst


def test_one_angle_a_list_and_a_scalar(solved):
    project = solved("press")
    fc = FullCycle(project.mech, project.cycle)
    one = fc(0.3)
    assert one.phi.shape == (1,) and one.M_bal.shape == (1,)
    assert one.M_bal[0] == pytest.approx(fc.general([0.3]).M_bal[0], rel=1e-12)
    two = fc([0.3, 1.2])
    assert two.M_bal.shape == (2,) and two.M_bal[0] == one.M_bal[0]
    # a constant is a number where the general path broadcasts it: xy gives both as (N, 2)
    assert np.array_equal(two.xy("points", "O"), np.zeros((2, 2)))
    assert np.allclose(two.xy("velocities", "B"), fc.general([0.3, 1.2]).xy("velocities", "B"),
                       rtol=0, atol=1e-12)


def test_a_pose_that_cannot_be_assembled_gets_the_general_paths_error(solved):
    # the rocker of the four-bar shortened so that it closes over part of the turn only:
    # the lean function's assembly check fails and the general path names dyad and position
    project = solved("fourbar")
    mech, cycle = project.mech, project.cycle
    (d,) = mech.dyads
    kin = g.solve(mech, cycle.phi)
    a, _, c = d.joints
    ac = np.hypot(*(kin.pos.points[c] - kin.pos.points[a]).T)
    l1 = d.lengths[0]
    l2 = float(np.max(ac)) - l1 - 1e-3  # too short at the longest |AC|
    short = replace(mech, dyads=(replace(d, lengths=(l1, l2)),))
    fc = FullCycle(short, cycle)
    at = float(cycle.phi[int(np.argmax(ac))])
    with pytest.raises(g.AssemblyError) as lean_err:
        fc([cycle.origin, at])
    with pytest.raises(g.AssemblyError) as general_err:
        fc.general([cycle.origin, at])
    assert str(lean_err.value) == str(general_err.value)
    assert "cannot be assembled" in str(lean_err.value)


def test_settings_it_does_not_compile_go_to_the_general_path(solved):
    project = solved("press")
    mech = project.mech
    shifted = replace(mech, settings={**mech.settings, "kinetostatics": {
        **mech.settings.get("kinetostatics", {}), "shift_inertia_force": True}})
    fc = FullCycle(shifted, project.cycle)
    assert not fc.native
    res = fc(project.cycle.phi)
    assert not res.native and res.M_bal.shape == project.cycle.phi.shape


def test_the_generated_code_folds_constants():
    # the press: a frame guide, a weight and the slider's ω = ε = 0 are constants, so the
    # Coriolis term and the guide's coincident point cost nothing; the velocity and
    # acceleration solves share one determinant
    mech = g.load(ROOT / "examples/press.toml")
    fc = FullCycle(mech)
    src = fc.source
    assert src.count("/ ") <= 4, src  # reciprocals only: 1/det of the dyad, of the forces
    assert "load_values" not in src and "np.interp" not in src  # the diagram is a bound helper
    lines = [ln for ln in src.splitlines() if " = " in ln]
    assert len(lines) < 90, len(lines)
    # every output bounded at generation: no isfinite over the outputs at run time
    assert all(b < 1e300 for b in fc.bounds.values()) and "isfinite" not in src
    # a vertical guide is i exactly (cos 90° = 6e-17 is not kept): its products fold
    consts = [complex(v) for k, v in fc._run.__globals__.items()
              if k[:1] == "k" and isinstance(v, np.ndarray) and v.ndim == 0]
    assert consts and not any(0 < abs(c.real) < 1e-15 or 0 < abs(c.imag) < 1e-15
                              for c in consts), consts


@pytest.mark.parametrize("case", CASES)
def test_the_bounds_that_replace_the_check_for_nan_hold(case, solved):
    # an output whose bound |x| ≤ B is known at generation (from the checks: |det| above
    # the lock-up margin, |AC| above the coincidence; from the geometry: a unit vector, a
    # point at a link's length from another) needs no isfinite at run time; every bound
    # must hold where the function answers: here on the fine grid and the sheets' positions
    project = solved(str(ROOT / case))
    fc = FullCycle(project.mech, project.cycle)
    phi = _grid(project.cycle, 720)
    res = fc(phi)
    assert res.native
    for (table, name), bound in fc.bounds.items():
        got = res.M_bal if table == "M_bal" else getattr(res, table)[name]
        # (1e-12: np.abs of a constant may differ from Python's abs by an ulp)
        assert float(np.max(np.abs(got))) <= bound * (1 + 1e-12), (case, table, name, bound)
    # an output without a bound (a load along a point's velocity divides by its speed) is
    # checked at run time, and only then
    open_ = [k for k, b in fc.bounds.items() if not b < 1e300]
    assert bool(open_) == ("isfinite(concatenate(" in fc.source), (case, open_)


def test_a_crank_angle_that_is_not_finite_goes_to_the_general_path():
    # φ finite is the premise of every bound: NaN is refused before anything is computed
    # (the general path then names the dyad and the position), as is an angle too large
    # for its square (no overflow in the check)
    mech = g.load(ROOT / "examples/press.toml")
    fc = FullCycle(mech)
    assert fc.source.splitlines()[1].strip() == "if count_nonzero(phi - phi): return None"
    with pytest.raises(g.AssemblyError, match="nan"):
        fc([np.nan, 0.3])
    huge = fc([1e200, 0.3])  # finite: the lean function answers, as the general path does
    assert np.array_equal(huge.M_bal, fc.general([1e200, 0.3]).M_bal) or np.allclose(
        huge.M_bal, fc.general([1e200, 0.3]).M_bal, rtol=1e-9, atol=1e-9 * np.max(
            np.abs(fc.general(fc.cycle.phi).M_bal)))


def test_a_diagram_near_its_nodes_is_the_general_functions():
    # np.interp is the diagram except within JUMP_TOL of a node where two pieces meet
    # (there the general function takes the larger piece, extrapolated): the lean helper
    # hands those x to the general function
    from graphplan.forces import JUMP_TOL, diagram_value
    from graphplan.forces.lean_loads import interp_diagram

    d = ((0.0, 0.0), (0.88513, 0.0), (0.98938, 1.0), (1.0, 1.0))
    xs, ys = np.array([p[0] for p in d]), np.array([p[1] for p in d])
    value = interp_diagram(xs, ys, xs[1:-1], d, False, False, 0.0, 1.0)
    rng = np.random.default_rng(7)
    for x in (rng.uniform(0, 1, 50), np.array([0.98938 + 0.5 * JUMP_TOL, 0.3]),
              np.array([0.88513 - 0.9 * JUMP_TOL]), np.array([-1e-16, 1.0 + 1e-16])):
        want = diagram_value(d, np.clip(x, 0, 1))
        assert np.allclose(value(x), want, rtol=0, atol=1e-15), (x, value(x), want)
    # beyond the ends it holds the end value where the diagram spans [0, 1], and is zero
    # where it stops short (the general function's zero outside its pieces)
    short = ((0.2, 0.5), (0.8, 1.0))
    xs, ys = np.array([0.2, 0.8]), np.array([0.5, 1.0])
    value = interp_diagram(xs, ys, xs, short, False, False, 0.0, 1.0)
    x = np.array([0.0, 0.1, 0.5, 0.95, 1.0])
    assert np.allclose(value(x), diagram_value(short, x), rtol=0, atol=1e-15)


def test_names_with_primes_are_quoted_in_the_generated_code():
    # point names may carry primes (B', S2''): the generated function holds them as string
    # literals (repr), never as code
    text = (ROOT / "examples/press.toml").read_text(encoding="utf-8")
    text = text.replace('name = "S2"', "name = \"S2''\"").replace('centre = "S2"',
                                                                 "centre = \"S2''\"")
    mech = g.loads(text, "primes.toml")
    assert any(p.name == "S2''" for p in mech.points)
    fc = FullCycle(mech)
    assert fc.native and "S2''" in fc.source
    phi = _grid(fc.cycle, 36)
    worst = _agree(fc(phi), fc.general(phi), 0.2)
    assert max(worst.values()) < 1e-12, worst
