"""Two more assignment families of issue 17, written from docs/variant-format.md alone
(tests/data/variants): a double-acting piston pump with a crosshead, and a 60° V diesel with
an articulated (прицепной) rod. Their sheets, ``analyze --json``, power balance and norm
control are checked with every variant (tests/test_variants.py,
tests/test_norm_control_variants.py); here each is checked against numbers computed
independently, by the test's own geometry from the file's data:

* the pump: each chamber's force is p·A per stroke — A = πD²/4 at the head, π(D² − d²)/4 on
  the rod's side, the two pushing opposite ways — and the water resists on both strokes;
* the engine: the balancing moment of the two gas forces alone is, by virtual work,
  −Σ F·ds/dφ, with s_B, s_C the pistons' travels along their cylinders from the test's own
  closed-form positions (differentiated by the complex step, exact to rounding), and each
  force is the file's indicator table read at its own piston's s/H, stroke by stroke from
  that piston's own dead centres (the articulated piston's stroke is not 2r nor 180° of
  crank);
* the ``rod`` key's errors: one line naming the file and the key.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from graphplan.cli import main
from graphplan.forces import compute_loads, solve_forces
from graphplan.model import load
from graphplan.project import analyze

VARIANTS = Path(__file__).resolve().parent / "data" / "variants"


def _data(name: str) -> dict:
    return tomllib.loads((VARIANTS / f"{name}.toml").read_text(encoding="utf-8"))


# --- the double-acting pump ------------------------------------------------------------------


def test_each_chamber_of_the_double_acting_pump_presses_on_its_own_area():
    a = analyze(load(VARIANTS / "double_acting_pump.toml"))
    g = _data("double_acting_pump")["loads"]
    D, d = g[0]["bore"] / 1000, g[1]["rod"] / 1000
    head, annulus = math.pi * D**2 / 4, math.pi * (D**2 - d**2) / 4   # 0.020106, 0.018143 m²
    ld = compute_loads(a.mech, a.kin, a.cycle, kinds=("resistance",), inertia=False)
    f1, f2 = ld.all_forces()
    assert (f1.name, f2.name) == ("Fж1", "Fж2")
    vx = a.kin.vel.points["P"][:, 0]
    # positions 0…11 every 30° from ВМТ (the piston nearest the head at +x): 0…5 the stroke
    # away from the head (vx < 0), 6…11 back (НМТ belongs to the stroke it starts)
    out = np.arange(12) < 6
    assert np.all(vx[1:6] < 0) and np.all(vx[7:] > 0)
    # the head's chamber pushes the piston away from the head (−x) with its pressure:
    # suction −0.05 MPa on the way out (a pull toward the head, +1005.3 N), delivery
    # +0.60 MPa back (−12 063.7 N)
    p_head = np.where(out, -0.05e6, 0.60e6)
    np.testing.assert_allclose(f1.vector[:, 0], -p_head * head, rtol=1e-12)
    # the rod's chamber pushes toward the head (+x): delivery on the way out (+10 885.8 N),
    # suction back (−907.1 N)
    p_rod = np.where(out, 0.60e6, -0.05e6)
    np.testing.assert_allclose(f2.vector[:, 0], p_rod * annulus, rtol=1e-12)
    assert np.all(f1.vector[:, 1] == 0) and np.all(f2.vector[:, 1] == 0)
    # both resist on both strokes (zero at the dead centres)
    for f in (f1, f2):
        power = f.vector[:, 0] * vx
        assert np.all(power <= 1e-9 * np.abs(power).max())
    net = (f1.vector[:, 0] + f2.vector[:, 0]) * vx
    assert np.count_nonzero(net < -1e-9 * np.abs(net).max()) == 10   # all but the dead centres
    # the work over the turn, closed form: each stroke moves the piston H against a constant
    # force, so A = −H·(0.05 + 0.60)·10⁶·(A_head + A_rod) = −0.65·10⁶·0.25·0.038249
    # = −6215.5 J; the weights' work over a turn is nil. The dynamics' exact integral:
    from graphplan import dynamics as dyn

    H = 0.250
    wd = dyn.work_diagrams(dyn.dynamic_model(a))
    assert wd.A_c[-1] == pytest.approx(-0.65e6 * H * (head + annulus), rel=1e-9)
    assert wd.M_d == pytest.approx(0.65e6 * H * (head + annulus) / (2 * math.pi), rel=1e-9)


def test_a_double_acting_pump_assembled_behind_the_crank_warns_for_both_chambers():
    # the crosshead assembled on the other branch, behind the crank: ВМТ (s = 0, the head)
    # would be the dead centre nearest the crank, for both chambers' diagrams
    from graphplan.model import loads

    text = (VARIANTS / "double_acting_pump.toml").read_text(encoding="utf-8")
    old = 'branch = "+"            # the crosshead'
    assert old in text
    behind = text.replace(old, 'branch = "-"            # the crosshead')
    warns = analyze(loads(behind, source="dap-behind.toml")).warnings
    assert [w.split(": ")[1] for w in warns] == ["loads[0]", "loads[1]"]
    assert all("where piston 3 is nearest the crank" in w and "dyads[0].branch" in w
               for w in warns)
    assert analyze(loads(text, source="dap.toml")).warnings == ()


@pytest.mark.parametrize(("edit", "key", "words"), [
    ("rod = 50 ", "rod = 160 ", "the piston rod's diameter must be less than the bore"),
    ("rod = 50 ", "rod = -5 ", "must be > 0"),
])
def test_a_rod_wider_than_the_bore_is_one_line(tmp_path, capsys, edit, key, words):
    text = (VARIANTS / "double_acting_pump.toml").read_text(encoding="utf-8")
    assert edit in text
    path = tmp_path / "pump-bad.toml"
    path.write_text(text.replace(edit, key), encoding="utf-8")
    assert main(["analyze", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert err.startswith(f"graphplan: error: {path}: loads[1].rod: ") and words in err, err


def test_a_rod_without_a_bore_is_one_line(tmp_path, capsys):
    text = (VARIANTS / "double_acting_pump.toml").read_text(encoding="utf-8")
    old = 'name = "Fж1"\nlink = "3"\npoint = "P"\nbore = 160\n'
    assert old in text
    text = text.replace(old, 'name = "Fж1"\nkind = "force"\nlink = "3"\npoint = "P"\n'
                             'max = 1000\nrod = 50\ndiagram = [[0, 1], [1, 1]]\n')
    path = tmp_path / "pump-rod.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["analyze", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert err.startswith(f"graphplan: error: {path}: loads[0].rod: goes with 'bore'"), err


# --- the V diesel with an articulated rod -----------------------------------------------------


def _pistons(data: dict, phi):
    """The pistons' travels s_B, s_C (m) along their cylinders' axes from O at crank angles
    φ (real or complex: the complex step), by the test's own closed form: B on the 60° axis
    at l from A, ahead of the foot; the lug K = A + 30·e + 51.96·e⊥ (mm) with e along A→B;
    C on the 120° axis at l_KC from K, ahead of the foot."""
    r = data["crank"]["length"] / 1000
    l1, l2 = data["dyads"][0]["length"] / 1000, data["dyads"][1]["length"] / 1000
    lug = next(p for p in data["points"] if p["name"] == "K")
    along, across = lug["along"] / 1000, lug["across"] / 1000
    ax = [(math.cos(math.radians(d["guide"]["angle"])), math.sin(math.radians(d["guide"]["angle"])))
          for d in data["dyads"]]
    Ax, Ay = r * np.cos(phi), r * np.sin(phi)
    (u1x, u1y), (u2x, u2y) = ax
    foot, off = Ax * u1x + Ay * u1y, -Ax * u1y + Ay * u1x
    sB = foot + np.sqrt(l1**2 - off**2)
    ex, ey = (sB * u1x - Ax) / l1, (sB * u1y - Ay) / l1
    Kx, Ky = Ax + along * ex - across * ey, Ay + along * ey + across * ex
    foot2, off2 = Kx * u2x + Ky * u2y, -Kx * u2y + Ky * u2x
    sC = foot2 + np.sqrt(l2**2 - off2**2)
    return sB, sC


def _rate(data: dict, phi):
    """ds/dφ of both pistons (m/rad), by the complex step: Im f(φ + ih)/h."""
    h = 1e-20
    sB, sC = _pistons(data, np.asarray(phi, float) + 1j * h)
    return sB.imag / h, sC.imag / h


def test_the_articulated_piston_has_its_own_stroke_and_dead_centres():
    data = _data("v_engine_articulated")
    a = analyze(load(VARIANTS / "v_engine_articulated.toml"))
    fine = np.radians(np.arange(0, 360, 0.01))
    sB, sC = _pistons(data, fine)
    assert np.ptp(sB) == pytest.approx(0.140, abs=1e-9)           # the master's H = 2r
    assert np.ptp(sC) == pytest.approx(0.14006, abs=1e-5)         # the articulated one's not
    # the master's strokes take 180° of crank each; the articulated piston's ВМТ comes
    # 61.37° after the master's, its НМТ 237.88°: strokes of 176.5° and 183.5°
    dead = _dead_centres(data, 1, a.cycle.dead_centres[0])
    turns = [math.degrees(t) for t, _ in dead]
    assert [kind for _, kind in dead] == ["top", "bottom", "top", "bottom"]
    assert turns[0] == pytest.approx(61.366, abs=0.01)
    assert turns[1] - turns[0] == pytest.approx(176.51, abs=0.01)
    ms = a.mech.output
    assert ms.link == "3" and a.cycle.stroke == pytest.approx(0.140, abs=1e-9)
    q = a.kin.pos.points["C"] @ np.array([-0.5, math.sqrt(3) / 2])
    _, sC_pos = _pistons(data, a.kin.phi)
    np.testing.assert_allclose(q, sC_pos, atol=1e-12)              # graphplan's C = ours


def _table(load_data: dict):
    travel = np.array(load_data["travel"])
    return lambda k, x: np.interp(x, travel, np.array(load_data["strokes"][k]))


def _dead_centres(data: dict, s_index: int, t0: float):
    """The crank travels (rad, from the cycle's origin t0, in [0, 4π)) where piston s_index
    reaches ВМТ (its largest s, the guide pointing to the head) and НМТ, found on a fine
    grid by the sign change of ds/dφ and refined by bisection on the complex-step rate."""
    tau = np.linspace(-1e-3, 4 * math.pi - 1e-3, 28801)   # a dead centre at 0 inside
    rate = _rate(data, t0 + tau)[s_index]
    out = []
    for i in np.nonzero(np.sign(rate[:-1]) != np.sign(rate[1:]))[0]:
        lo, hi = tau[i], tau[i + 1]
        for _ in range(60):
            mid = (lo + hi) / 2
            if np.sign(_rate(data, t0 + mid)[s_index]) == np.sign(_rate(data, t0 + lo)[s_index]):
                lo = mid
            else:
                hi = mid
        top = _rate(data, t0 + lo)[s_index] > 0   # s rising to its top: ВМТ
        t = math.remainder((lo + hi) / 2, 4 * math.pi) % (4 * math.pi)
        out.append((0.0 if t > 4 * math.pi - 1e-9 else t, "top" if top else "bottom"))
    return out


def _stroke_and_x(data, s_index, t0, tau, phase):
    """Each position's stroke (0 intake … 3 exhaust) and s/H from ВМТ for one piston."""
    dead = _dead_centres(data, s_index, t0)
    tops = [t for t, kind in dead if kind == "top"]
    start = min((t for t in tops if t >= phase - 1e-9), default=None)
    if start is None:
        start = min(tops) + 4 * math.pi
    ends = sorted(t for t, _ in dead)
    s = _pistons(data, t0 + tau)[s_index]
    top = _pistons(data, t0 + start)[s_index]
    bottom = _pistons(data, t0 + next(t for t, kind in dead if kind == "bottom"))[s_index]
    x = (top - s) / (top - bottom)
    rel = np.mod(tau - start, 4 * math.pi)
    marks = np.sort(np.mod(np.array(ends) - start, 4 * math.pi))
    k = np.searchsorted(marks, rel + 1e-12, side="right") - 1
    gap = np.abs(rel[:, None] - marks[None, :])
    return np.mod(k, 4), x, np.min(np.minimum(gap, 4 * math.pi - gap), axis=1)


def test_the_gas_forces_of_the_master_and_articulated_pistons_by_virtual_work():
    data = _data("v_engine_articulated")
    a = analyze(load(VARIANTS / "v_engine_articulated.toml"))
    mech, kin = a.mech, a.kin
    t0 = a.cycle.dead_centres[0]                      # the cycle's origin: the master's ВМТ
    assert t0 == pytest.approx(math.radians(60), abs=1e-9)
    # 24 positions every 30° of the two turns from the origin (the file's [positions])
    tau = np.radians(30.0 * np.arange(24))
    np.testing.assert_allclose(np.cos(kin.phi - t0 - tau), 1.0, atol=1e-12)
    ld = compute_loads(mech, kin, a.cycle, kinds=("resistance",), inertia=False)
    forces = {f.name: f for f in ld.all_forces()}
    g = {ld_["name"]: ld_ for ld_ in data["loads"]}
    area = math.pi * (g["Fг1"]["bore"] / 1000) ** 2 / 4
    sizes = []
    for name, index, axis in (("Fг1", 0, 60), ("Fг2", 1, 120)):
        k, x, near = _stroke_and_x(data, index, t0, tau, math.radians(g[name].get("phase", 0)))
        p = np.array([_table(g[name])(ki, xi) for ki, xi in zip(k, x, strict=True)])
        F = (p - g[name]["p_ambient"]) * 1e6 * area    # away from the head: along −axis
        u = np.array([math.cos(math.radians(axis)), math.sin(math.radians(axis))])
        got = forces[name].vector @ u
        ok = near > 1e-6                                # off the dead centres' jumps
        np.testing.assert_allclose(got[ok], -F[ok], rtol=1e-9, atol=1e-6)
        sizes.append(got)
    # the articulated piston fires a turn after its own first ВМТ: at the positions of 60°
    # and 90° of the cycle it is expanding (about 50 kN), while the master is in its intake
    assert np.all(np.abs(sizes[1][2:4]) > 4e4) and np.all(np.abs(sizes[0][2:4]) < 200)
    # the balancing moment of the gas forces alone, by virtual work on our own geometry
    M_bal = solve_forces(mech, kin, ld).M_bal
    dB, dC = _rate(data, kin.phi)
    closed = -(sizes[0] * dB + sizes[1] * dC)
    np.testing.assert_allclose(M_bal, closed, rtol=1e-9, atol=1e-9 * np.abs(closed).max())


# --- sheet 2: which curve of the load diagram is which load -----------------------------------


def _q_group_texts(path: Path) -> list[str]:
    from graphplan.drawing import Group, Text, iter_leaves, kinetostatics_sheet

    a = analyze(load(path))
    (q,) = [it for it in kinetostatics_sheet(a).all_items()
            if isinstance(it, Group) and it.id == "s2-q-diagram"]
    return [it.text for it in iter_leaves([q]) if isinstance(it, Text)]


@pytest.mark.parametrize(("path", "names"), [
    # two stages, two diagrams: each curve named
    (VARIANTS / "opposed_compressor.toml", ["Fг1", "Fг2"]),
    # two cylinders of one diagram and one stroke draw one curve: named once for both
    (VARIANTS.parent.parent.parent / "examples" / "compressor.toml", ["Fг1, Fг2"]),
    # two chambers of one piston: four rectangles, two named by their tops
    (VARIANTS / "double_acting_pump.toml", ["Fж1", "Fж2"]),
    # an in-line twin: both cylinders draw one curve (a turn apart): named once for both
    (VARIANTS / "twin_engine.toml", ["Fг1, Fг2"]),
])
def test_each_curve_of_a_load_diagram_with_several_loads_is_named(path, names):
    """A teacher asked «which cylinder?» of the compressor's Q(s) (two curves, one title
    «Fг1, Fг2(s)»): each curve now carries its load's name by its highest free point."""
    texts = _q_group_texts(path)
    assert sorted(t for t in texts if t.startswith(("Fг", "Fж")) and "(" not in t) == names


# --- the inclined screen: a constant resistance on both strokes, a weight along the slope ----


def test_the_screens_resistance_on_both_strokes_does_exactly_minus_2_f_h():
    """A constant 600 N against the box's motion on both strokes does −2·F·H over the turn,
    whatever the motion between (H = 82.002 mm from the test's own sampling of the box's
    travel): −98.403 J, in the dynamics' exact integral to 1e-9; the box's weight pulls it
    down the 12° slope (helps on the down stroke, resists on the up one) and does no work
    over the turn."""
    from graphplan import dynamics as dyn
    from graphplan.kinematics import solve

    a = analyze(load(VARIANTS / "inclined_screen.toml"))
    fine = solve(a.mech, np.radians(np.arange(0.0, 360.0, 0.01)))
    u = np.array([math.cos(math.radians(-12)), math.sin(math.radians(-12))])
    H = float(np.ptp(fine.pos.points["E"] @ u))
    assert pytest.approx(a.cycle.stroke, abs=1e-7) == H
    wd = dyn.work_diagrams(dyn.dynamic_model(a))
    assert wd.A_c[-1] == pytest.approx(-2 * 600.0 * a.cycle.stroke, rel=1e-9)
    # the weight along the slope at every position: G5·sin 12° = 623.7 N down the slope
    ld = compute_loads(a.mech, a.kin, a.cycle, kinds=("gravity",), inertia=False)
    (g5,) = [f for f in ld.all_forces() if f.name == "G5"]
    np.testing.assert_allclose(g5.vector @ u, 3000.0 * math.sin(math.radians(12)), rtol=1e-12)
    # the resistance: 600 N along the guide against the box's velocity, 0 at the dead centres
    (fc,) = compute_loads(a.mech, a.kin, a.cycle, kinds=("resistance",),
                          inertia=False).all_forces()
    v = a.kin.vel.points["E"] @ u
    moving = np.abs(v) > 1e-9
    np.testing.assert_allclose((fc.vector @ u)[moving], -600.0 * np.sign(v[moving]), rtol=1e-12)
