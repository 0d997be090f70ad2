"""The assignment families of issue 17: engine, compressor, pump, slotting machine, crusher.

Each family's example is solved through the whole chain and checked independently:

* the power balance Σ F·v + Σ M·ω + Mур·ω1 = 0 at every position (d'Alembert's
  kinetostatics against virtual power), to 1e-9 of the largest power term;
* the engine's turning moment of the gas force alone against the textbook closed form
  M = F·r·sin(α + β)/cos β (α the crank's turn from ВМТ, sin β = λ·sin α), the force read
  by the test itself from the variant's indicator table;
* the 720° flywheel against an independent energy integration (Simpson on a 0.05° grid of
  the loads' power and the links' kinetic energy, computed here from the kinematics);
* the loads' directions: the gas force drives on the expansion stroke and resists on
  compression; the compressor's and the pump's forces resist on both strokes;
* the warnings, the weights in N and ω1 in rad/s, and ``analyze --json`` of every family.
"""

import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from graphplan import dynamics as dyn
from graphplan.cli import main
from graphplan.forces import compute_loads, load_power, point_velocity, solve_forces
from graphplan.kinematics import solve
from graphplan.model import load, loads
from graphplan.project import analyze

ROOT = Path(__file__).resolve().parent.parent
FAMILIES = ("engine", "compressor", "pump", "slotter", "crusher", "shaper")


@pytest.fixture(scope="module")
def analyses():
    return {name: analyze(load(ROOT / "examples" / f"{name}.toml")) for name in FAMILIES}


def _terms(mech, kin, ld):
    """Every power term F·v and M·ω (W), positions along the last axis."""
    out = [np.einsum("ij,ij->i", f.vector, point_velocity(mech, kin, f.link, f.at))
           for f in ld.all_forces()]
    out += [m.moment * kin.vel.omega[m.link] for m in ld.all_moments()]
    return np.array(out)


@pytest.mark.parametrize("name", FAMILIES)
def test_power_balance_at_every_position(analyses, name):
    a = analyses[name]
    mech, kin = a.mech, a.kin
    for neglect in (None, 0.0):  # the variant's neglect rule, and everything kept
        ld = compute_loads(mech, kin, a.cycle, neglect_below=neglect)
        M_bal = solve_forces(mech, kin, ld).M_bal
        terms = _terms(mech, kin, ld)
        scale = np.max(np.abs(terms))
        resid = load_power(mech, kin, ld) + M_bal * mech.crank.omega
        assert np.max(np.abs(resid)) <= 1e-9 * scale, name


def _indicator(mech):
    """The engine's gas force (N, positive away from the head) per stroke, from the file."""
    data = tomllib.loads((ROOT / "examples" / "engine.toml").read_text(encoding="utf-8"))
    g = data["loads"][0]
    area = math.pi * (g["bore"] / 1000) ** 2 / 4
    travel = np.array(g["travel"])
    tables = [np.array(s) for s in g["strokes"]]

    def force(alpha):
        """α: crank turn from ВМТ (rad, 0 … 4π) → the force by the variant's table."""
        r, rod = mech.crank.length, mech.dyads[0].lengths[0]
        beta = np.arcsin(r / rod * np.sin(alpha))
        s = (r * (1 - np.cos(alpha)) + rod * (1 - np.cos(beta))) / (2 * r)   # s/H from ВМТ
        k = np.minimum((alpha // math.pi).astype(int), 3)                  # the stroke
        p = np.array([np.interp(si, travel, tables[ki]) for si, ki in zip(s, k, strict=True)])
        return (p - g["p_ambient"]) * 1e6 * area, beta

    return force


def test_engine_turning_moment_of_the_gas_force_is_the_closed_form(analyses):
    a = analyses["engine"]
    mech, kin = a.mech, a.kin
    ld = compute_loads(mech, kin, a.cycle, kinds=("resistance",), inertia=False)
    assert [f.name for f in ld.all_forces()] == ["Fг"]
    M_bal = solve_forces(mech, kin, ld).M_bal
    sense = 1.0 if mech.crank.omega > 0 else -1.0
    alpha = np.mod(sense * (kin.phi - a.cycle.dead_centres[0]), 4 * math.pi)
    # exactly at ВМТ/НМТ the table's value is the next stroke's (a dead centre belongs to
    # the stroke it starts); the moment is zero there either way
    F, beta = _indicator(mech)(alpha)
    r = mech.crank.length
    closed = F * r * np.sin(alpha + beta) / np.cos(beta)   # in the sense of rotation
    np.testing.assert_allclose(-sense * M_bal, closed, rtol=1e-9, atol=1e-9 * np.abs(closed).max())
    # and on a fine grid of the dynamics over the whole 720°, through the reduced moment
    tau = np.linspace(0.0, 4 * math.pi, 2881)[1:-1]
    tau = tau[np.abs(np.sin(tau)) > 1e-6]                   # off the dead centres' jumps
    M = dyn.dynamic_model(a).moment.at(tau)
    # the weights' share: G2, G3 reduced to the crank, exactly by virtual power
    fine = solve(mech, a.cycle.dead_centres[0] + sense * tau)
    grav = compute_loads(mech, fine, a.cycle, kinds=("gravity",), inertia=False)
    Mg = load_power(mech, fine, grav) / abs(mech.crank.omega)
    F, beta = _indicator(mech)(tau)
    np.testing.assert_allclose(M - Mg, F * r * np.sin(tau + beta) / np.cos(beta),
                               rtol=1e-9, atol=1e-9 * np.abs(M).max())


def test_engine_gas_drives_on_expansion_and_resists_on_compression(analyses):
    a = analyses["engine"]
    m = dyn.dynamic_model(a)
    tau = m.tau[:-1]
    kin = solve(a.mech, m.moment.phi[:-1])
    (gas,) = compute_loads(a.mech, kin, a.cycle, kinds=("resistance",), inertia=False
                           ).all_forces()
    power = np.einsum("ij,ij->i", gas.vector, kin.vel.points["B"])
    # compression from s = 0.6·H on (p ≥ 0.161 MPa > p_атм) to ВМТ; the whole expansion
    comp = (tau > 1.5 * math.pi) & (tau < 2 * math.pi - 1e-6)
    expa = (tau > 2 * math.pi + 1e-6) & (tau < 3 * math.pi - 1e-6)
    assert np.all(power[comp] < 0) and np.all(power[expa] > 0)
    # intake below the atmosphere: the piston is pulled back, a small resistance
    intake = (tau > 1e-6) & (tau < math.pi - 1e-6)
    assert np.all(power[intake] < 0)
    wd = dyn.work_diagrams(m)
    assert wd.M_d < 0  # the loads drive: the constant moment is the consumer's resistance
    assert m.period == pytest.approx(4 * math.pi)


def test_engine_720_flywheel_matches_an_independent_energy_integration(analyses):
    a = analyses["engine"]
    mech = a.mech
    fw = dyn.flywheel(dyn.dynamic_model(a))
    w1 = abs(mech.crank.omega)
    sense = 1.0 if mech.crank.omega > 0 else -1.0
    n = 14400                                   # 0.05° over 720°
    tau = np.linspace(0.0, 4 * math.pi, n + 1)
    kin = solve(mech, a.cycle.dead_centres[0] + sense * tau)
    ld = compute_loads(mech, kin, a.cycle, inertia=False, neglect_below=0.0)
    M = load_power(mech, kin, ld) / w1          # the loads' reduced moment (gas + weights)
    # Simpson per pair of steps (the jumps of the gas force sit at the dead centres, where
    # the piston stands still: M is continuous there, so the rule converges)
    h = tau[1] - tau[0]
    A = np.zeros(n + 1)
    A[2::2] = np.cumsum(h / 3 * (M[0:-2:2] + 4 * M[1:-1:2] + M[2::2]))
    A[1::2] = A[0:-1:2] + h / 2 * (M[0:-1:2] + M[1::2])
    Mc = -A[-1] / (4 * math.pi)
    dT = A + Mc * tau
    inertia = float(mech.settings["dynamics"]["crank_inertia"]) + fw.I_m
    for ln, p in mech.links.items():
        e = p.inertia * kin.vel.omega[ln] ** 2
        if p.mass > 0:
            v = kin.vel.points[p.centre]
            e = e + p.mass * np.einsum("ij,ij->i", v, v)
        inertia = inertia + e / w1**2

    def omega(T0):
        return np.sqrt(2 * (T0 + dT) / inertia)

    lo, hi = -dT.min() + 1e-9, -dT.min() + 10 * float(inertia.max()) * w1**2
    for _ in range(200):                         # T0: the mean of ωmax and ωmin is ω1
        mid = 0.5 * (lo + hi)
        om = omega(mid)
        lo, hi = (mid, hi) if 0.5 * (om.max() + om.min()) < w1 else (lo, mid)
    om = omega(0.5 * (lo + hi))
    delta = (om.max() - om.min()) / (0.5 * (om.max() + om.min()))
    assert Mc == pytest.approx(fw.M_d, rel=1e-6)
    assert np.ptp(dT) == pytest.approx(fw.dT_max, rel=1e-4)
    assert delta == pytest.approx(fw.delta, rel=2e-3)


def _load_powers(a):
    m = dyn.dynamic_model(a)
    kin = solve(a.mech, m.moment.phi[:-1])
    ld = compute_loads(a.mech, kin, a.cycle, kinds=("resistance",), inertia=False)
    return m, {f.name: np.einsum("ij,ij->i", f.vector, point_velocity(a.mech, kin, f.link, f.at))
               for f in ld.all_forces()}


def test_the_pumps_water_resists_on_both_strokes(analyses):
    m, powers = _load_powers(analyses["pump"])
    p = powers["Fж"]
    assert np.all(p <= 1e-9 * np.abs(p).max())
    assert np.count_nonzero(p < 0) > 0.95 * len(p)   # suction and delivery
    assert dyn.work_diagrams(m).M_d > 0               # a motor drives it


def test_the_compressors_gas_resists_but_for_the_re_expansion(analyses):
    a = analyses["compressor"]
    m, powers = _load_powers(a)
    tau = m.tau[:-1]
    for name, p in powers.items():
        # over the cycle the gas takes work; it gives a little back only where the pressure
        # on the piston is on the atmosphere's side of it: the clearance gas re-expanding
        # (s < 0.218·H, about 47° of crank) and the start of compression below 0.1 MPa
        # (s > 0.9·H, about 37°): 84° of the 360°
        assert np.sum(p) < 0
        assert np.count_nonzero(p > 1e-9 * np.abs(p).max()) < 90 / 360 * len(p), name
    comp = (tau > 1.3 * math.pi) & (tau < 2 * math.pi - 1e-6)
    assert np.all(powers["Fг1"][comp] < 0)
    assert dyn.work_diagrams(m).M_d > 0


def test_second_cylinder_starts_at_its_own_top_dead_centre(analyses):
    a = analyses["compressor"]
    ld = compute_loads(a.mech, a.kin, a.cycle, kinds=("resistance",), inertia=False)
    f1, f2 = ld.all_forces()
    # the cylinders' axes are 90° apart (135° and 45°): with the crank turning CCW, the crank
    # points at cylinder 2 (45°) 90° before it points at cylinder 1 (135°), so cylinder 2's
    # force at a position is cylinder 1's 90° = 3 positions later (every 30°, position 0
    # at cylinder 1's ВМТ)
    mag1 = np.hypot(*f1.vector.T)
    mag2 = np.hypot(*f2.vector.T)
    np.testing.assert_allclose(mag2, np.roll(mag1, -3), rtol=1e-9)


def test_crusher_weights_in_newtons_and_omega_in_rad_per_s(analyses):
    mech = analyses["crusher"].mech
    assert mech.crank.omega == 25.0
    assert mech.crank.rpm == pytest.approx(25 * 30 / math.pi)
    assert mech.links["2"].mass == pytest.approx(3000 / 9.81)
    assert mech.links["5"].mass == pytest.approx(5000 / 9.81)
    ld = compute_loads(mech, analyses["crusher"].kin, analyses["crusher"].cycle,
                       kinds=("gravity",), inertia=False)
    G2 = next(f for f in ld.all_forces() if f.name == "G2")
    assert G2.vector[0, 1] == pytest.approx(-3000.0)


def test_crusher_moment_resists_on_the_working_swing_only(analyses):
    a = analyses["crusher"]
    ld = compute_loads(a.mech, a.kin, a.cycle, kinds=("resistance",), inertia=False)
    (mc,) = ld.all_moments()
    w = a.kin.vel.omega["5"]
    power = mc.moment * w
    assert np.all(power <= 0)
    assert np.all((mc.moment != 0) <= (w < 0))   # only while the jaw swings clockwise


@pytest.mark.parametrize("name", FAMILIES)
def test_analyze_json_of_every_family(name, tmp_path, capsys):
    out = tmp_path / f"{name}.json"
    assert main(["analyze", str(ROOT / "examples" / f"{name}.toml"), "--json",
                 "-o", str(out)]) == 0
    report = json.loads(out.read_text(encoding="utf-8"))
    assert report["warnings"] == []
    assert report["mechanism"]["cycle_deg"] == (720.0 if name == "engine" else 360.0)
    if name == "engine":  # φ repeats over two turns; the process's phase does not
        phases = [p["cycle_phase_deg"] for p in report["positions"]]
        assert phases == pytest.approx([30.0 * k for k in range(24)], abs=1e-9)
        assert report["positions"][13]["phi_deg"] == pytest.approx(
            report["positions"][1]["phi_deg"])
    dynm = report["dynamics"]
    assert dynm["driven_by"] == ("loads" if name == "engine" else "motor")
    assert (dynm["motor"] is None) == (name == "engine")


# --- warnings ------------------------------------------------------------------------------


def _variant(name, **edits):
    text = (ROOT / "examples" / f"{name}.toml").read_text(encoding="utf-8")
    for old, new in edits.items():
        assert old in text
        text = text.replace(old, new)
    return text


def test_warning_when_the_working_stroke_is_the_fast_one(tmp_path, capsys):
    # the slotting machine with its crank turning the other way: the ram cuts on the short
    # arc, K = 144/216 = 0.667
    text = _variant("slotter", **{'direction = "cw"': 'direction = "ccw"'})
    a = analyze(loads(text, source="slotter-ccw.toml"))
    assert len(a.warnings) == 1
    w = a.warnings[0]
    assert w.startswith("slotter-ccw.toml: output.working: K = 0.667 < 1")
    assert "likely fix: output.working = \"+\"" in w and "K = 1.500" in w
    assert "\n" not in w
    path = tmp_path / "slotter-ccw.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["analyze", str(path), "--json", "-o", str(tmp_path / "o.json")]) == 0
    assert "graphplan: warning: " in capsys.readouterr().err
    assert json.loads((tmp_path / "o.json").read_text(encoding="utf-8"))["warnings"] == [
        w.replace("slotter-ccw.toml", str(path))]


def test_warning_when_the_piston_moves_against_its_working_direction():
    # the pump's plunger assembled behind the crank (branch "-"): its travel s is still
    # counted from the dead centre at −x… which is now the one nearest the crank, so the
    # water would press the plunger away from the crank: the cylinder's head is at the crank
    text = _variant("pump", **{'branch = "+"': 'branch = "-"'})
    a = analyze(loads(text, source="pump-behind.toml"))
    (w,) = a.warnings
    assert w.startswith("pump-behind.toml: loads[0]: the indicator diagram starts (s = 0, "
                        "ВМТ) where piston 3 is nearest the crank")
    assert "likely fix: output.working = \"+\"" in w and "dyads[0].branch" in w
    # the fix it names removes the warning
    fixed = text.replace('working = "-"', 'working = "+"')
    assert analyze(loads(fixed, source="pump-fixed.toml")).warnings == ()


def test_no_warning_for_the_examples():
    for path in sorted((ROOT / "examples").glob("*.toml")):
        assert analyze(load(path)).warnings == (), path


# --- bad input: one line naming the file and the key -----------------------------------------


@pytest.mark.parametrize(("edits", "key", "words"), [
    ({'link = "5"             # the swing jaw': 'link = "5"',
      'kind = "moment"\nlink = "5"': 'kind = "moment"\nlink = "8"'},
     "loads[0].link", "link '8' is not a link of this mechanism"),
    ({"diagram = [[0.0, 0.0], [0.5, 0.4], [1.0, 1.0]]": "diagram = [[0.0, 0.0], [0.5, 0.4]]"},
     "loads[0].diagram", "does not cover the stroke"),
    ({"count = 12": "count = 12\ncycle = 720"},
     "positions.cycle", "a 720° cycle needs a process over two turns"),
])
def test_bad_input_is_one_line_naming_file_and_key(tmp_path, capsys, edits, key, words):
    path = tmp_path / "crusher-bad.toml"
    path.write_text(_variant("crusher", **edits), encoding="utf-8")
    assert main(["analyze", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert err.startswith(f"graphplan: error: {path}: {key}: ") and words in err, err


# --- the other forms of the load model -------------------------------------------------------


def test_second_cylinder_of_an_in_line_four_stroke_engine_fires_a_turn_later():
    # the same piston loaded by its diagram twice, the copy with phase = 360: the copy's
    # force at a position equals the original's one turn (12 positions of 30°) earlier
    text = (ROOT / "examples" / "engine.toml").read_text(encoding="utf-8")
    start = text.index("[[loads]]")
    end = text.index("[positions]")
    copy = text[start:end].replace('name = "Fг"', 'name = "Fг2"').replace(
        "bore = 82", "phase = 360\nbore = 82")
    a = analyze(loads(text[:end] + copy + text[end:], source="twin.toml"))
    ld = compute_loads(a.mech, a.kin, a.cycle, kinds=("resistance",), inertia=False)
    f1, f2 = ld.all_forces()
    assert f2.name == "Fг2"
    np.testing.assert_allclose(f2.vector, np.roll(f1.vector, 12, axis=0), rtol=1e-12,
                               atol=1e-9)
    # with a phase between firing intervals the strokes start at the next ВМТ after it
    odd = copy.replace("phase = 360", "phase = 200")
    b = analyze(loads(text[:end] + odd + text[end:], source="twin2.toml"))
    g1, g2 = compute_loads(b.mech, b.kin, b.cycle, kinds=("resistance",),
                           inertia=False).all_forces()
    np.testing.assert_allclose(g2.vector, np.roll(g1.vector, 12, axis=0), rtol=1e-12,
                               atol=1e-9)


PRESS = (ROOT / "examples" / "press.toml").read_text(encoding="utf-8")


def _press_with(extra: str):
    return analyze(loads(PRESS + "\n" + extra, source="press-extra.toml"))


def test_a_constant_couple_on_the_crank_does_its_work_exactly():
    # value = 150 N·m on the crank shaft, resisting, over the whole cycle: −150·2π J
    base = dyn.work_diagrams(dyn.dynamic_model(_press_with(""))).A_c[-1]
    a = _press_with('[[loads]]\nkind = "moment"\nlink = "1"\nvalue = 150\n')
    A = dyn.work_diagrams(dyn.dynamic_model(a)).A_c[-1]
    assert A - base == pytest.approx(-150 * 2 * math.pi, rel=1e-12)


def test_a_crank_angle_diagram_is_read_over_the_cycle_with_its_sign():
    # a couple on the rod over the crank angle: +100 N·m for 0…90°, −100 N·m for 90…360°
    # (sense = diagram: CCW positive), counted from the start dead centre
    a = _press_with('[[loads]]\nname = "M2"\nkind = "moment"\nlink = "2"\nover = "crank"\n'
                    'sense = "diagram"\nmax = 100\n'
                    'diagram = [[0, 1], [90, 1], [90, -1], [360, -1]]\n')
    ld = compute_loads(a.mech, a.kin, a.cycle, kinds=("resistance",), inertia=False,
                       neglect_below=0.0)  # not the press's 10 % rule at (2), (3)
    m2 = next(m for m in ld.all_moments() if m.name == "M2")
    sense = np.sign(a.mech.crank.omega)
    start = a.cycle.dead_centres[0]
    tau = np.degrees(np.mod((a.kin.phi - start) * sense, 2 * math.pi))
    expected = np.where(tau < 90 - 1e-9, 100.0, -100.0)
    expected[np.abs(tau - 90) < 1e-6] = 100.0   # at the jump: the larger in size, +100 first
    np.testing.assert_allclose(m2.moment, expected)
    # its work over the cycle, exactly (the jump a node): ∫M·dθ2 = 100·(θ2(90°) − θ2(0))
    # − 100·(θ2(360°) − θ2(90°)) = 200·(θ2(90°) − θ2(0°)), θ2 the rod's angle
    th = solve(a.mech, start + sense * np.radians([0.0, 90.0])).pos.theta["2"]
    closed = 200.0 * float(th[1] - th[0])
    base = dyn.work_diagrams(dyn.dynamic_model(_press_with(""))).A_c[-1]
    A = dyn.work_diagrams(dyn.dynamic_model(a)).A_c[-1]
    assert A - base == pytest.approx(closed, rel=1e-9)
    assert abs(closed) > 10.0


def test_drives_is_resists_turned_round_and_a_force_off_a_slider_follows_its_point():
    res = ('[[loads]]\nname = "F2"\nkind = "force"\nlink = "2"\npoint = "S2"\nmax = 500\n'
           'diagram = [[0, 1], [1, 1]]\nstroke = "both"\nsense = "{s}"\n')
    a = _press_with(res.format(s="resists"))
    b = _press_with(res.format(s="drives"))
    fa = next(f for f in compute_loads(a.mech, a.kin, a.cycle, kinds=("resistance",),
                                       inertia=False, neglect_below=0.0).all_forces()
              if f.name == "F2")
    fb = next(f for f in compute_loads(b.mech, b.kin, b.cycle, kinds=("resistance",),
                                       inertia=False, neglect_below=0.0).all_forces()
              if f.name == "F2")
    np.testing.assert_allclose(fb.vector, -fa.vector)
    v = point_velocity(a.mech, a.kin, "2", fa.at)
    speed = np.hypot(*v.T)
    moving = speed > 1e-9
    # 500 N against the velocity of S2 wherever S2 moves
    np.testing.assert_allclose(np.hypot(*fa.vector[moving].T), 500.0)
    cosine = np.einsum("ij,ij->i", fa.vector[moving], v[moving]) / (500.0 * speed[moving])
    np.testing.assert_allclose(cosine, -1.0)


# --- the families on the sheets: a driving gas force is not a resistance; 720° labels -----


def _q_texts(name: str) -> list[str]:
    from graphplan.drawing import Text, iter_leaves, kinetostatics_sheet

    a = analyze(load(ROOT / "examples" / f"{name}.toml"))
    return [it.text for it in iter_leaves(kinetostatics_sheet(a).all_items())
            if isinstance(it, Text)]


@pytest.mark.parametrize(("name", "title", "ordinate"), [
    # the engine's gas force does positive work over the cycle: it drives the machine
    ("engine", "Движущая сила давления газов Fг(s)", "Fг, кН"),
    # the compressor's gas and the pump's water resist: a pressure on the piston
    ("compressor", "Сила давления на поршень Fг1, Fг2(s)", "F, Н"),
    ("pump", "Сила давления на поршень Fж(s)", "Fж, Н"),
    # a moment on the crusher's jaw, 200 kN·m at most: N·m, not N
    ("crusher", "Момент полезного сопротивления Mс(ψ)", "Mс, кН·м"),
    ("press", "Сила полезного сопротивления Q(s)", "Q, кН"),
])
def test_the_load_diagram_is_named_by_its_loads(name, title, ordinate):
    """Sheet 2's diagram of the loads: an engine's gas force is named as the driving force
    it is (it was 'Сила полезного сопротивления', ordinate Q), a moment in N·m."""
    texts = _q_texts(name)
    assert title in texts, texts
    assert ordinate in texts, texts


@pytest.mark.parametrize(("name", "drives"), [("engine", True), ("compressor", False),
                                              ("pump", False), ("crusher", False)])
def test_a_load_drives_when_it_does_positive_work_over_the_cycle(analyses, name, drives):
    """The engine's gas: its work over the 720° cycle is the driving work Aд = −Mс·4π of the
    machine (the consumer's constant moment Mс = −Aд/4π, from the dynamics' own grid; the
    weights and inertia do no work over a cycle)."""
    from graphplan.project import load_drives
    from graphplan.project.plausibility import load_work

    a = analyses[name]
    assert [load_drives(a.mech, a.cycle, n) for n in range(len(a.mech.resistances))] == (
        [drives] * len(a.mech.resistances))
    if name == "engine":
        fw = dyn.flywheel(dyn.dynamic_model(a))
        assert load_work(a.mech, a.cycle, 0)[0] == pytest.approx(-fw.M_d * 4 * math.pi,
                                                                 rel=1e-4)


def test_a_four_stroke_cycle_gives_the_cycle_angle_on_every_table(analyses):
    """docs/variant-format.md: φ of a position of a 720° cycle is the cycle angle, the crank's
    travel from the first position, 0 … 720°. The engine's positions start at ВМТ of intake
    (O→A at 90°), every 30° over two turns: position 12 is φ = 360° (the expansion stroke's
    ВМТ), not 90° again; position 14 is 420° — where the angle of O→A modulo 720° read 90,
    120 … 690, 0, 30, 60 (a jump in the middle of the table). Every table gives it from one
    function: sheet 1's plans table, sheet 2's force table, the Markdown reports, the text
    report of ``analyze`` and sheet 3's table."""
    from graphplan.drawing import Text, iter_leaves, kinematics_sheet, kinetostatics_sheet
    from graphplan.reports import analysis_text, forces_markdown, plans_markdown, position_rows

    a = analyses["engine"]
    want = {k: 30.0 * k for k in range(24)}                          # 0, 30 … 690
    # the O→A angles are 90 + 30k (mod 360 each turn): the cycle angle is their travel
    assert np.degrees(a.kin.phi - a.kin.phi[0]) % 720.0 == pytest.approx(list(want.values()))
    assert math.degrees(a.kin.phi[0]) % 360.0 == pytest.approx(90.0)
    # sheet 1's table of the plans: the column φ; sheet 2's force table (position 14)
    for sheet, table, angles in ((kinematics_sheet, "plans-table-r", list(want.values())),
                                 (kinetostatics_sheet, "s2-table-r", [420.0])):
        cells = {it.id: it.text for it in iter_leaves(sheet(a).all_items())
                 if isinstance(it, Text) and (it.id or "").startswith(table)}
        column = [float(t) for i, t in sorted(cells.items()) if i.endswith("c2")
                  and i != f"{table}0c2"]
        assert sorted(column) == sorted(angles), (sheet.__name__, column)
    assert "## Положение 14, φ = 420.00°" in forces_markdown(a, "ru", 0.0).splitlines()
    assert "## Положение 12, φ = 360.00°" in plans_markdown(a, "ru", 0.0).splitlines()
    # the text report of `analyze`: the first table's φ column, rows 0 … 23
    text = analysis_text(a).splitlines()
    head = next(n for n, ln in enumerate(text) if ln.split()[:2] == ["pos.", "φ,"])
    rows = [ln.split() for ln in text[head + 2:head + 26]]
    assert [r[0] for r in rows] == list(a.kin.labels)
    assert [float(r[1]) for r in rows] == pytest.approx(list(want.values()))
    # sheet 3's table gives the same angles
    assert a.unit is not None
    assert [float(r[1]) for r in position_rows(a.unit)] == pytest.approx(list(want.values()))
    # a one-turn cycle is unchanged: the angle of O→A in [0°, 360°), on sheet 3 as in the text
    press = analyze(load(ROOT / "examples" / "press.toml"))
    assert press.unit is not None
    got = [float(r[1]) for r in position_rows(press.unit)]
    assert got == pytest.approx([math.degrees(p) % 360.0 for p in press.kin.phi], abs=0.06)


def test_a_position_on_a_dead_centre_is_in_the_stroke_it_starts():
    """A 90° V-twin (tests/data/variants/v_twin_engine.toml), the left cylinder at 135°:
    its ВМТ and НМТ fall on positions 0, 6, 12, 18, whose τ came 1e-15 rad short of the
    dead centres, and each was put in the stroke before — at position 12, the firing ВМТ,
    the force was the compression's end 7,494 N instead of the expansion's start.
    Hand arithmetic: πD²/4 = π·0.076²/4 = 4.5365e-3 m²; (5.2 − 0.1) MPa·4.5365e-3 m² =
    23,136 N at ВМТ of the expansion, (1.752 − 0.1)·4.5365e-3 = 7,494 N at the end of the
    compression."""
    from graphplan.forces import cycle_travel, stroke_index

    a = analyze(load(ROOT / "tests" / "data" / "variants" / "v_twin_engine.toml"))
    left, right = a.mech.resistances
    tau = cycle_travel(a.mech, a.cycle, a.kin.phi)
    assert stroke_index(left, a.mech, a.cycle, tau).tolist() == (
        [0] * 6 + [1] * 6 + [2] * 6 + [3] * 6)
    # the right cylinder reaches its ВМТ 270° (9 positions) later and starts its intake there
    assert stroke_index(right, a.mech, a.cycle, tau).tolist() == (
        [2] * 3 + [3] * 6 + [0] * 6 + [1] * 6 + [2] * 3)
    ld = compute_loads(a.mech, a.kin, a.cycle, neglect_below=0.0)
    gas = {f.name: np.hypot(*f.vector.T) for f in ld.all_forces() if f.name.startswith("Fг")}
    area = math.pi * 0.076**2 / 4
    assert gas["Fг1"][12] == pytest.approx((5.2 - 0.1) * 1e6 * area, rel=1e-9)
    assert gas["Fг2"][21] == pytest.approx((5.2 - 0.1) * 1e6 * area, rel=1e-9)  # 630°
    assert gas["Fг1"][11] == pytest.approx(gas["Fг2"][20], rel=1e-9)  # 30° before each firing


def test_loads_on_two_rockers_share_the_crank_angle_on_q(solved):
    """Sheet 2's diagram of the loads: the loom's beat-up moment (on the beater 5, over its
    swing ψ5) and its friction (on the rocker 3, over ψ3) are two links' travels, which one ψ
    axis cannot carry: both are drawn over the crank's travel φ, 0 … 360°, each curve equal to
    its load at the positions (at their φ); the compressor's two pistons, of one stroke, keep
    the common s axis of their indicator diagrams."""
    from graphplan.drawing.sheet2 import _position_travel, q_curves
    from graphplan.forces import resistance_loads

    a = solved(ROOT / "tests" / "data" / "variants" / "loom_beater.toml")
    curves, unit = q_curves(a)
    assert unit == "deg_crank" and len(curves) == 2
    at = _position_travel(a, unit)
    by_crank = np.degrees(np.mod((a.kin.phi - a.kin.phi[0]) * a.mech.crank.sense, 2 * math.pi))
    assert at == pytest.approx(by_crank)
    for (name, x, size, _work, _), ld in zip(curves, resistance_loads(a.mech, a.kin, a.cycle),
                                           strict=True):
        assert float(x[0]) == 0.0 and float(x[-1]) == pytest.approx(360.0)
        want = np.abs(np.asarray(ld.moment))
        # the curve read at each position's φ away from the load's jumps (the beat-up's
        # end at the beater's dead centre), linearly between its 361 points
        got = np.interp(at, x, size)
        smooth = np.abs(np.interp(at + 1.0, x, size) - np.interp(at - 1.0, x, size)) \
            < 0.05 * float(size.max()) + 1e-9
        assert smooth.sum() >= 8, name
        assert got[smooth] == pytest.approx(want[smooth], rel=2e-3, abs=1e-6 * want.max()), name
    _, unit = q_curves(solved("compressor"))
    assert unit == "m"


def test_in_line_twin_with_cranks_at_180_turning_moment_is_two_closed_forms():
    """tests/data/variants/inline_twin_180.toml, written from the docs: the two gas forces'
    turning moment is the sum of two textbook closed forms F·r·sin(α + β)/cos β, cylinder 1's
    α the cycle angle τ from its ВМТ of intake, cylinder 2's α = τ − 180° (its pin opposite
    A puts its ВМТ half a turn later, and phase = 180 starts its intake there), each force
    read by this test from the file's indicator table — at every position and over the 720°
    of the dynamics."""
    path = ROOT / "tests" / "data" / "variants" / "inline_twin_180.toml"
    a = analyze(load(path))
    mech, kin = a.mech, a.kin
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    r, rod = mech.crank.length, mech.dyads[0].lengths[0]
    assert data["loads"][1]["phase"] == 180

    def moment(g, alpha):
        area = math.pi * (g["bore"] / 1000) ** 2 / 4
        beta = np.arcsin(r / rod * np.sin(alpha))
        s = (r * (1 - np.cos(alpha)) + rod * (1 - np.cos(beta))) / (2 * r)   # s/H from ВМТ
        k = np.minimum((alpha // math.pi).astype(int), 3)
        p = np.array([np.interp(si, g["travel"], g["strokes"][ki])
                      for si, ki in zip(s, k, strict=True)])
        F = (p - g["p_ambient"]) * 1e6 * area
        return F * r * np.sin(alpha + beta) / np.cos(beta)

    def closed(tau):
        return (moment(data["loads"][0], np.mod(tau, 4 * math.pi))
                + moment(data["loads"][1], np.mod(tau - math.pi, 4 * math.pi)))

    ld = compute_loads(mech, kin, a.cycle, kinds=("resistance",), inertia=False)
    assert [f.name for f in ld.all_forces()] == ["Fг1", "Fг2"]
    M_bal = solve_forces(mech, kin, ld).M_bal
    tau = np.mod(kin.phi - a.cycle.dead_centres[0], 4 * math.pi)   # CCW crank
    # the positions sit on the dead centres every 180°: each force there is the stroke's it
    # starts and its arm zero, so the comparison holds at all 24
    want = closed(tau)
    np.testing.assert_allclose(-M_bal, want, rtol=1e-9, atol=1e-9 * np.abs(want).max())
    fine = np.linspace(0.0, 4 * math.pi, 2881)[1:-1]
    fine = fine[np.abs(np.sin(fine)) > 1e-6]
    M = dyn.dynamic_model(a).moment.at(fine)
    sol = solve(mech, a.cycle.dead_centres[0] + fine)
    grav = compute_loads(mech, sol, a.cycle, kinds=("gravity",), inertia=False)
    Mg = load_power(mech, sol, grav) / abs(mech.crank.omega)
    np.testing.assert_allclose(M - Mg, closed(fine), rtol=1e-9, atol=1e-9 * np.abs(M).max())


# --- the variants' sheet 1 (issue 18's defects found on the families' variants) -------------

VARIANT_DIR = ROOT / "tests" / "data" / "variants"


def test_a_loaded_coupler_point_is_traced_and_numbered(drawn):
    """The dough mixer's load acts at E, the end of the kneading arm on the coupler: sheet 1's
    plan of positions draws E's trajectory (the machine's working loop, a closed dash-dot
    curve through E of every position) and numbers E in every position, as it numbers the
    crank pin; the centres of mass's paths stay drawn."""
    from graphplan.drawing import Polyline, Text, iter_leaves

    sheet = drawn(VARIANT_DIR / "dough_mixer.toml", 1)
    items = list(iter_leaves(sheet.items))
    paths = {it.id: it for it in items if isinstance(it, Polyline) and (it.id or "").startswith(
        "pp-path-")}
    assert {"pp-path-E", "pp-path-S2", "pp-path-S3"} <= set(paths)
    assert paths["pp-path-E"].closed
    texts = [it.text for it in items if isinstance(it, Text) and (it.id or "").startswith(
        "pp-label")]
    numbers = {t for t in " ".join(texts).replace(",", " ").split() if t.startswith("E")}
    assert {f"E{k}" for k in range(1, 13)} <= numbers, sorted(numbers)


def test_the_stroke_arcs_have_ends(drawn):
    """The arcs of the working and idle strokes round the crank stop short of the dead
    centres and end in arrowheads in the sense of rotation (the dough mixer's two arcs of
    183° and 177° closed into one thin circle round the crank circle, read as a second
    crank circle); round a short crank (the crusher's 6 mm) they stay plain arcs."""
    from graphplan.drawing import Arc, Arrow, iter_leaves

    items = list(iter_leaves(drawn(VARIANT_DIR / "dough_mixer.toml", 1).items))
    arcs = {it.id: it for it in items if isinstance(it, Arc) and (it.id or "").startswith(
        "pp-arc-")}
    heads = [it for it in items if isinstance(it, Arrow) and (it.id or "").startswith(
        "pp-arc-")]
    assert set(arcs) == {"pp-arc-working-arc", "pp-arc-idle-arc"} and len(heads) == 2
    r = next(iter(arcs.values())).r
    swept = sum(abs(a.end_deg - a.start_deg) for a in arcs.values())
    # two gaps of ARC_GAP = 2.5 mm at each of the two dead centres: 4 × 2.5 mm of arc
    assert swept == pytest.approx(360.0 - math.degrees(4 * 2.5 / r), abs=1e-6)
    crusher = [it for it in iter_leaves(drawn("crusher", 1).items)
               if (it.id or "").startswith("pp-arc-")]
    assert crusher and not any(isinstance(it, Arrow) for it in crusher)


def test_a_720_cycle_draws_the_velocity_plans_of_one_turn(solved, drawn):
    """The in-line twin's 24 positions over 720° repeat their kinematics each turn: sheet 1
    draws the 12 velocity plans of the first turn (it drew every second of the 24, so
    positions 12 … 22 repeated 0 … 10); an acceleration plan of the second turn (13, 19,
    the force analysis's) stands on its twin's velocity plan, captioned with both labels."""
    from graphplan.drawing import Text, iter_leaves
    from graphplan.project import distinct_positions

    a = solved(VARIANT_DIR / "inline_twin_180.toml")
    assert distinct_positions(a.kin) == tuple(range(12))
    sc = a.sheet1
    assert sc.plans == tuple(range(12)) and sc.analysed == (13, 19)
    caps = {it.text for it in iter_leaves(drawn(VARIANT_DIR / "inline_twin_180.toml", 1).items)
            if isinstance(it, Text) and it.text.startswith("План скоростей")}
    assert {"План скоростей, пол. 1, 13", "План скоростей, пол. 7, 19"} <= caps
    assert len(caps) == 12
    # a one-turn cycle keeps every position
    press = solved("press")
    assert distinct_positions(press.kin) == tuple(range(press.kin.n))


def test_a_scheme_is_not_coarsened_for_what_does_not_shrink():
    """sheet 1's schemes take the finest Kl of the series whose drawing fits their box; a
    part drawn at a fixed paper size (a guide's 36 mm hatched strip) that overflows the box
    at every Kl by less than half the margin must not raise Kl step after step (the rotating
    кулиса's ω/ε scheme went from 0.015 to 0.15 m/mm, its links a 3 mm blob)."""
    from graphplan.drawing import Line
    from graphplan.drawing.items import Style
    from graphplan.drawing.sheet1_schemes import MARGIN, _drawn_to_fit
    from graphplan.paper import Rect

    box = Rect(0.0, 0.0, 100.0, 35.0)
    pts = np.array([[0.0, 0.0], [0.3, 0.47]])        # 0.47 m tall: fits 35 mm at 0.015

    def draw(P):
        x, y = P(pts[1])
        x0, y0 = P(pts[0])
        # the links, and a fixed 36.4 mm strip: 1.4 mm over the box at any scale
        return [Line((x0, y0), (x, y), Style(0.5), layer="construction"),
                Line((x0 + 5.0, 17.5 - 18.2), (x0 + 5.0, 17.5 + 18.2), Style(0.5),
                     layer="construction")]

    kl, _, _ = _drawn_to_fit(pts, box, draw)
    assert kl == pytest.approx(0.015)
    assert MARGIN / 2 >= 1.4
