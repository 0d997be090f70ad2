"""Stability where the methods fail: every drafted figure is within its bound, or marked.

The variants are built from the examples' TOML text, swept toward the cases where a
graphical construction loses its footing:

* a four-bar whose frame is lengthened until the coupler and the rocker are nearly
  collinear once a turn (a toggle: the velocity plan's lines ⟂AB, ⟂CB and the force
  plan's closing lines ∥AB, ∥CB meet at a small angle);
* the press with its rod shortened toward the crank (l_AB → l_OA): at φ = 0° and 180°
  the rod is nearly perpendicular to the guide, so the line ⟂AB is nearly parallel to
  the guide (velocity plan) and Rⁿ12 ∥ AB nearly perpendicular to R43 (force plan);
* the press at its dead centres and next to them: v_B → 0, the arm h21 of R21 → 0,
  Mур → 0 (lever arms near zero).

At every position, for every figure the drafting reads (reading precision 0.5 and 1 mm),
the drafted value is compared with the *solver's* exact value (graphplan.kinematics.exact,
graphplan.forces.kinetostatics: an independent route from the constructions) and must be
within the bound :mod:`graphplan.plans.conditioning` states, unless the position is marked
ill-conditioned. The sweeps must reach marked positions where the angle is small and
none where it is not. Finally every output of the variants (tables, JSON report, the
sheets' SVG) is free of NaN and infinity.
"""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest

import graphplan as g
from graphplan.files import bundled_example
from graphplan.forces import compute_loads, solve_forces
from graphplan.outputs import project_files
from graphplan.plans import (
    ILL_ANGLE_DEG,
    Reader,
    acceleration_plan,
    force_conditioning,
    force_plans,
    kinematic_conditioning,
    velocity_plan,
    zhukovsky_lever,
)
from graphplan.project import analyze, sheet_scales

NAN_INF = re.compile(r"\b(nan|inf|infinity)\b", re.IGNORECASE)


def _extra(positions: list[tuple[str, str]]) -> str:
    return "extra = [" + ", ".join(f'{{ label = "{lab}", {how} }}' for lab, how in positions) + "]"


def _variant(tmp_path, example: str, name: str, subs: list[tuple[str, str]],
             extra: list[tuple[str, str]]):
    """The example's TOML with substitutions and extra positions, loaded from tmp_path."""
    text = bundled_example(example).read_text(encoding="utf-8")
    for old, new in subs:
        assert old in text, old
        text = text.replace(old, new)
    text = re.sub(r"extra = \[.*?\n\]", _extra(extra), text, count=1, flags=re.S)
    text = text.replace(f'name = "{example}"', f'name = "{name}"')
    path = tmp_path / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    return analyze(g.load(path))


def toggle(tmp_path, frame_mm: float):
    """The four-bar with its frame at ``frame_mm`` (400 in the example; toggle at 550)."""
    near = [(f"t{i}", f"phi = {p}") for i, p in enumerate((165.0, 172.0, 178.0, 180.0, 185.0))]
    return _variant(tmp_path, "fourbar", f"toggle-{frame_mm:g}",
                    [("C = [400, 0]", f"C = [{frame_mm}, 0]")], near)


def short_rod(tmp_path, rod_mm: float):
    """The press with its rod l_AB = ``rod_mm`` (200 in the example, the crank 80)."""
    near = [(f"r{i}", f"phi = {p}") for i, p in enumerate((0.0, 2.0, 178.0, 180.0))]
    return _variant(tmp_path, "press", f"rod-{rod_mm:g}",
                    [("length = 200           # l_AB", f"length = {rod_mm}           # l_AB")],
                    near)


def dead_centres(tmp_path):
    """The press with positions at its dead centres and within a degree of them."""
    near = [("BDC", 'from = "end", turn = 0'), ("BDC+0.2", 'from = "end", turn = 0.2'),
            ("BDC-1", 'from = "end", turn = -1'), ("TDC", 'from = "start", turn = 0'),
            ("TDC+0.5", 'from = "start", turn = 0.5'), ("(2)", 'from = "end", turn = -20')]
    return _variant(tmp_path, "press", "dead-centres", [], near)


def _within(drawn, exact, bound, flagged) -> bool:
    """|drawn − exact| (a vector's length) ≤ bound, or the position is marked."""
    return flagged or float(np.linalg.norm(np.atleast_1d(drawn - exact))) <= bound


def check_position(an, k: int, precision: float, forces_too: bool = True) -> bool:
    """Assert the figures of position k are within their bounds or marked; True if marked."""
    m, kin = an.mech, an.kin
    sc = sheet_scales(m, kin)
    kc = kinematic_conditioning(m, kin, k, sc.kl, sc.kv, sc.ka, precision)
    vp = velocity_plan(m, kin, k, sc.kl, sc.kv, Reader(precision))
    ap = acceleration_plan(m, kin, k, sc.kl, sc.ka, vp, Reader(precision))
    where = f"{m.name} position {kin.labels[k]} at {precision} mm"
    for plan, solved, rates in ((vp, kin.vel, kin.vel.omega), (ap, kin.acc, kin.acc.epsilon)):
        for p in kin.pos.points:
            key = p.lower()
            if p in m.frame_points or key in ("p", "π") or key not in plan.points:
                continue
            f = kc.figures[(plan.kind, f"point {key}")]
            got = plan.points[key] * plan.scale.per_mm
            assert _within(got, solved.points[p][k], f.bound, kc.flagged), (where, plan.kind, p)
        sym = "ω" if plan.kind == "velocity" else "ε"
        for link in m.moving_links:
            if link == m.crank.link:
                continue
            f = kc.figures[(plan.kind, sym + link)]
            assert _within(plan.rates[link], rates[link][k], f.bound, kc.flagged), (where, link)
    marked = kc.flagged
    if forces_too:
        loads = compute_loads(m, kin, an.cycle)
        forces = solve_forces(m, kin, loads)
        fc = force_conditioning(m, kin, forces, loads, k, sc.kl, sc.kv, precision)
        plans = force_plans(m, kin, forces, loads, k, sc.kl, Reader(precision))
        flagged = fc.flagged
        b = fc.figures[("force", "Mур")].bound
        assert _within(plans[-1].M_bal, forces.M_bal[k], b, flagged), (where, "Mур")
        for p in plans:
            for name, r in p.reactions.items():
                f = fc.figures[("force", f"vector {name}")]
                assert _within(np.asarray(r.vector), forces.vector(name)[k], f.bound,
                               flagged), (where, name)
        lever = zhukovsky_lever(m, kin, loads, k, sc.kl, sc.kv, Reader(precision))
        assert _within(lever.M_bal, forces.M_bal[k], fc.figures[("lever", "Mур")].bound,
                       flagged), (where, "Mур(Ж)")
        marked = marked or flagged
    return marked


def _min_angle(an, k: int) -> float:
    sc = sheet_scales(an.mech, an.kin)
    kc = kinematic_conditioning(an.mech, an.kin, k, sc.kl, sc.kv, sc.ka, 0.5)
    return min(x.angle_deg for x in kc.intersections)


@pytest.mark.parametrize("frame", [500.0, 549.0, 549.8])
def test_four_bar_toward_its_toggle(tmp_path, frame):
    an = toggle(tmp_path, frame)
    marked = [check_position(an, k, p, forces_too=(p == 0.5))
              for k in range(an.kin.n) for p in (0.5, 1.0)]
    angles = [_min_angle(an, k) for k in range(an.kin.n)]
    if min(angles) < ILL_ANGLE_DEG:
        assert any(marked), "the sweep reached small angles but marked nothing"
    else:
        assert not any(marked), "a well-conditioned four-bar was marked"
    if frame == 549.8:  # 0.2 mm from the toggle: the plans' lines meet at about 2°
        assert min(angles) < 3.0


@pytest.mark.parametrize("rod", [100.0, 85.0, 80.5])
def test_press_rod_toward_perpendicular_to_the_guide(tmp_path, rod):
    # at φ = 0 the lines ⟂AB and ∥guide meet at α, cos α = l_OA/l_AB: 80/80.5 → 6.4°,
    # 80/85 → 19.7°, 80/100 → 36.9°
    an = short_rod(tmp_path, rod)
    k0 = an.kin.labels.index("r0")
    assert _min_angle(an, k0) == pytest.approx(math.degrees(math.acos(80 / rod)), abs=1e-6)
    marked = [check_position(an, k, p, forces_too=(p == 0.5))
              for k in range(an.kin.n) for p in (0.5, 1.0)]
    assert any(marked) == (rod == 80.5)


def test_press_at_its_dead_centres(tmp_path):
    an = dead_centres(tmp_path)
    m, kin = an.mech, an.kin
    arms = solve_forces(m, kin, compute_loads(m, kin, an.cycle)).crank_arms()["R21"]
    bdc = kin.labels.index("BDC")
    # the dead centre: the rod along the guide, v_B = 0 and R21 passes through O (h21 = 0)
    assert float(np.hypot(*kin.vel.points["B"][bdc])) < 1e-12
    assert arms[bdc] < 1e-12
    for k in range(kin.n):
        assert not check_position(an, k, 0.5)
        assert not check_position(an, k, 1.0, forces_too=False)


def _no_nan_inf(files: dict[str, str]) -> None:
    for name, text in files.items():
        assert not NAN_INF.search(text), name
    json.loads(files["analysis.json"], parse_constant=lambda c: pytest.fail(f"JSON has {c}"))


def test_no_nan_or_infinity_reaches_an_output(tmp_path):
    for an in (toggle(tmp_path, 549.8), short_rod(tmp_path, 80.5), dead_centres(tmp_path)):
        files = project_files(an, lang="en")
        _no_nan_inf(files)
        assert {"sheet1.svg", "sheet2.svg", "plans.csv", "forces.csv"} <= set(files)
        if an.mech.name == "toggle-549.8":  # its plans at t2 (178°) are marked in the tables
            assert "**Ill-conditioned:** lines meet at" in files["plans.en.md"]
            assert "lines meet at" in files["plans.csv"]
            # and on sheet 1, under the captions of its velocity and acceleration plans
            assert re.search(r'id="vp\d+-ill"', files["sheet1.svg"])
            assert re.search(r'id="ap\d+-ill"', files["sheet1.svg"])
        if an.mech.name == "rod-80.5":  # its force plans at φ = 0, 180° on sheet 2: 6.4°
            assert re.search(r'id="s2p\d+-fp0-ill"[^>]*>lines meet at 6\.4°',
                             files["sheet2.svg"])
        if an.mech.name == "dead-centres":  # well-conditioned: nothing is marked
            assert "-ill" not in files["sheet1.svg"] + files["sheet2.svg"]
        # the JSON gives every intersection's angle, and the same marks
        pos = json.loads(files["analysis.json"])["positions"]
        angles = [x["angle_deg"] for p in pos for x in p["plans"]["intersections"]]
        marked = {p["label"] for p in pos if p["plans"]["ill_conditioned"]}
        fmarked = {p["label"] for p in pos
                   if any(fp["ill_conditioned"] for fp in p["force_plans"])}
        assert marked == {p["label"] for p in pos
                          if min(x["angle_deg"] for x in p["plans"]["intersections"]) < 10}
        if an.mech.name == "toggle-549.8":
            assert {"t1", "t2", "t3"} <= marked and min(angles) < 3
        elif an.mech.name == "rod-80.5":  # the rod's lines at φ = 0: cos α = 80/80.5
            assert {"r0", "r3"} <= fmarked
            assert min(angles) == pytest.approx(math.degrees(math.acos(80 / 80.5)), abs=1e-6)
        else:
            assert not marked and not fmarked


def test_benchmark_command_runs_end_to_end(tmp_path):
    # a smoke test of `python -m benchmarks` with a tiny run (12 positions, one repetition):
    # the speed is measured by the benchmark itself, never here
    pytest.importorskip("mpmath")
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    out = tmp_path / "results.json"
    subprocess.run([sys.executable, "-m", "benchmarks", "--positions", "12", "--reps", "1",
                    "--no-drafting", "--no-charts", "--sweep", "12", "--no-commands",
                    "--mechanisms", "press", "--out", str(out),
                    "--docs", str(tmp_path)], cwd=root, check=True, capture_output=True,
                   timeout=900)  # a loaded 2-core machine: minutes
    res = json.loads(out.read_text(encoding="utf-8"),
                     parse_constant=lambda c: pytest.fail(f"results.json has {c}"))
    methods = res["mechanisms"]["press"]["methods"]
    # the analytic solver and the exact constructions agree with the 50-digit reference
    for name in ("graphplan analytic", "graphplan constructions, exact"):
        errs = [v for v in methods[name]["errors"].values() if v is not None]
        assert errs and max(errs) < 1e-9, (name, errs)
    # the generic Newton solver is good to its finite differences, not to round-off
    assert 1e-14 < methods["newton (generic, loop equations)"]["errors"]["accelerations"] < 1e-5
    assert res["targets"] and all("met" in t for t in res["targets"])
    # the N sweep (issue 21): every method at N = 12, each judged against its target
    assert res["sweep"]["sizes"] == [12]
    assert any(t["target"].startswith("sweep N = 12: full cycle ≥ 20×") for t in res["targets"])
    assert res["stability"]["min_angle_deg"] < 90
    assert "press" in res["simplifications"]
    assert (tmp_path / "simplifications.md").read_text(encoding="utf-8").startswith("# Model")


@pytest.mark.parametrize("where", ["eps", "translating point", "velocity"])
def test_a_non_finite_value_never_leaves_the_solver(monkeypatch, where):
    # the solver's check looks at the accelerations, velocities, ω, ε and the positions of
    # the points of translating links (every other position enters its acceleration):
    # a NaN planted in any of them raises SingularPoseError naming the array
    import graphplan.kinematics.exact as K

    mech = g.load(bundled_example("shaper"))
    real_acc, real_pos = K.accelerations_complex, K.solve_complex

    def acc(*args):
        a, eps, sliding, cor = real_acc(*args)
        if where == "eps":
            eps["3"] = eps["3"].copy()
            eps["3"][1] = np.nan
        return a, eps, sliding, cor

    def pos(*args):
        P, theta, G = real_pos(*args)
        if where == "translating point":  # T on the ram (link 5, sliding on the frame)
            P["T"] = P["T"].copy()
            P["T"][2] = complex(np.inf, 0.0)
        return P, theta, G

    real_vel = K.velocities_complex

    def vel(*args):
        v, omega, sliding, cond = real_vel(*args)
        if where == "velocity":
            v["S4"] = v["S4"].copy()
            v["S4"][0] = complex(0.0, np.nan)
        return v, omega, sliding, cond

    monkeypatch.setattr(K, "accelerations_complex", acc)
    monkeypatch.setattr(K, "solve_complex", pos)
    monkeypatch.setattr(K, "velocities_complex", vel)
    with pytest.raises(g.SingularPoseError, match="not finite"):
        K.solve(mech, np.radians([10.0, 20.0, 30.0]))
