"""Sheet 3 and the machine unit: motor, rotor, flywheel, its check; the report and the JSON."""

import math
import re

import numpy as np
import pytest

from graphplan import dynamics as dyn
from graphplan.analysis import analyze
from graphplan.dynamics_sheet import dynamics_sheet, results_lines
from graphplan.errors import InputError
from graphplan.files import bundled_example
from graphplan.loader import load
from graphplan.machine_unit import machine_unit
from graphplan.motor import load_catalogue
from graphplan.render.dynamics_tables import dynamics_markdown, position_rows
from graphplan.sheet import Figure, Text, check_layout, iter_leaves

EXAMPLES = ["press", "fourbar", "shaper", "shaper_prp", "scotch_yoke", "sixbar_press",
            "offset_slider"]
_cache: dict = {}


def unit(name):
    if name not in _cache:
        a = analyze(load(bundled_example(name)))
        _cache[name] = (a, machine_unit(a))
    return _cache[name]


def test_json_keys_are_the_promised_ones_in_si():
    a, u = unit("press")
    d = a.to_json()["dynamics"]
    for key in ("delta_target", "delta_simulated", "I_flywheel", "I_flywheel_approx", "dT_max",
                "M_drive", "power_W", "motor", "gear_ratio"):
        assert key in d
    assert d["delta_target"] == 0.1
    assert d["I_flywheel"] == pytest.approx(u.flywheel.I_m)
    assert d["M_drive"] == pytest.approx(u.flywheel.M_d)
    # P = Mд·ω1/η: ω1 = 55 rpm = 5.7596 rad/s, η = 0.85
    assert d["power_W"] == pytest.approx(d["M_drive"] * 55 * math.pi / 30 / 0.85)
    # u = n_ном/n1
    assert d["gear_ratio"] == pytest.approx(d["motor"]["rated_rpm"] / 55.0)
    assert d["motor"]["power_W"] >= d["power_W"]


def test_press_flywheel_meets_its_delta_with_the_rotor_counted():
    _, u = unit("press")
    mo = u.motor.motor
    assert mo.inertia_kg_m2 is not None  # the default catalogue gives J_рот
    # the rotor reduced to the crank: J_рот·u², and the flywheel needs that much less
    assert u.flywheel.I_rotor == pytest.approx(mo.inertia_kg_m2 * u.motor.u ** 2)
    assert u.flywheel.I_m == pytest.approx(u.flywheel.J_I - u.flywheel.I_const
                                           - u.flywheel.I_rotor)
    assert abs(u.delta_error_pct) < 5.0  # done-when of the issue: within 5 % of δ
    assert abs(u.simulation.delta_actual - 0.1) < 1e-3
    # the motor is the smallest of its series at 1500 rpm with enough power
    at_speed = sorted((m for m in load_catalogue() if m.sync_rpm == 1500),
                      key=lambda m: m.power_kw)
    enough = [m for m in at_speed if m.power_w >= u.power_W]
    assert mo == enough[0]


def _delta(m, I_total):
    return dyn.simulate(m, I_total, cycles=1).delta_actual


@pytest.mark.parametrize("name", ["press", "shaper", "fourbar"])
def test_wittenbauer_against_the_brute_force_flywheel(name):
    """The smallest Iм whose simulated δ does not exceed the target (bisection on the
    steady motion), against Wittenbauer's Iм: within 2 %."""
    _, u = unit(name)
    m, target = u.model, u.flywheel.delta
    have = u.flywheel.I_rotor
    lo, hi = 0.0, 4.0 * (u.flywheel.I_m + 1.0)
    assert _delta(m, hi + have) < target
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        if _delta(m, mid + have) <= target:
            hi = mid
        else:
            lo = mid
    assert u.flywheel.I_m == pytest.approx(hi, rel=0.02)


@pytest.mark.parametrize("name", EXAMPLES)
def test_sheet_has_no_layout_problems_and_its_figures(name):
    a, u = unit(name)
    sheet = dynamics_sheet(a, unit=u)
    assert check_layout(sheet) == []
    ids = {f.id for f in iter_leaves(sheet.items) if isinstance(f, Figure)}
    assert ids == {"s3-work", "s3-energy-mass", "s3-omega"}


def test_sheet_texts_are_the_calculation():
    a, u = unit("press")
    sheet = dynamics_sheet(a, unit=u)
    texts = {t.id: t.text for t in iter_leaves(sheet.items) if isinstance(t, Text) and t.id}
    lines = [texts[f"s3-result-{i}"] for i in range(len(results_lines(u, "ru")))]
    assert lines == results_lines(u, "ru")
    assert any(u.motor.motor.type in s for s in lines)
    rows = position_rows(u)
    for i, row in enumerate(rows, 1):  # the table of the sheet is the report's table
        assert [texts[f"s3-table-r{i}c{j}"] for j in range(1, len(row) + 1)] == row
    # the flywheel's dimension is its diameter in mm
    d = texts["s3-fw-dimD-t"].lstrip("⌀")
    assert float(d) == pytest.approx(u.mounted.D * 1000, rel=1e-3)


def test_round_off_is_written_as_zero():
    """The shaper's crank has no inertia of its own and the dyads stand still at the dead
    centres 0 and 0': Iп there is round-off (~1e-31 kg·m²), written 0 as in the moments."""
    _, u = unit("shaper")
    rows = {r[0]: r for r in position_rows(u)}
    assert rows["0"][3] == "0" and rows["0'"][3] == "0"
    assert all("·10" not in c for r in rows.values() for c in r)  # fmt writes 1.9·10^-31


def test_report_arithmetic_can_be_followed():
    """Every 'a·b·c = d' of the scales in the report multiplies out."""
    _, u = unit("press")
    md = dynamics_markdown(u, "en")
    m = re.search(r"KA = Kφ·KM·H = ([\d.]+)·([\d.]+)·([\d.]+) = ([\d.]+)", md)
    a, b, c, d = map(float, m.groups())
    assert a * b * c == pytest.approx(d, rel=1e-4)
    m = re.search(r"JI = kl·KT/\(ω²·δ\) = ([\d.]+)·([\d.]+)/\(([\d.]+)²·([\d.]+)\) = ([\d.]+)",
                  md)
    kl, kt, w, delta, ji = map(float, m.groups())
    assert kl * kt / (w * w * delta) == pytest.approx(ji, rel=2e-3)
    assert ji == pytest.approx(u.flywheel.J_I, rel=1e-4)
    assert "Delphi" in md and "nan" not in md.lower() and "inf" not in md


def test_nodes_at_the_breaks_of_the_resistance():
    """The press's Q ramps from travel 0.88513 to 0.98938 of the stroke: both kinks are
    nodes of the graphical integration."""
    _, u = unit("press")
    breaks = u.model.moment.breaks
    assert len(breaks) == 2
    for b in breaks:
        assert np.min(np.abs(u.flywheel.work.node_tau - b)) < 1e-12


@pytest.mark.parametrize(("text", "key", "expected"), [
    ('motor_series = "5AM"', "dynamics.motor_series", "expected a bundled motor series"),
    ("motor_speed = 1200", "dynamics.motor_speed", "expected a synchronous speed"),
    ('flywheel = { shape = "cube" }', "dynamics.flywheel.shape", "expected one of"),
    ('flywheel = { shaft = "gear" }', "dynamics.flywheel.shaft", "expected one of"),
    ("flywheel = { b_ratio = -1 }", "dynamics.flywheel.b_ratio", ""),
    ("intervals = 2", "dynamics.intervals", "must be from 4"),
])
def test_bad_dynamics_settings_are_one_line_errors(tmp_path, text, key, expected):
    src = bundled_example("press").read_text(encoding="utf-8")
    src = re.sub(r"(?m)^intervals = .*\n", "", src).replace("[dynamics]\n",
                                                              f"[dynamics]\n{text}\n")
    p = tmp_path / "v.toml"
    p.write_text(src, encoding="utf-8")
    with pytest.raises(InputError) as err:
        load(p)
    msg = str(err.value)
    assert "\n" not in msg and "v.toml" in msg and key in msg and expected in msg


def test_motor_shaft_flywheel_is_u_squared_lighter(tmp_path):
    src = bundled_example("press").read_text(encoding="utf-8").replace(
        "[dynamics]\n", '[dynamics]\nflywheel = { shaft = "motor", shape = "disc" }\n')
    p = tmp_path / "v.toml"
    p.write_text(src, encoding="utf-8")
    u2 = machine_unit(analyze(load(p)))
    _, u = unit("press")
    assert u2.mounted.inertia == pytest.approx(u.flywheel.I_m / u.motor.u ** 2)
    # disc: I = m·D²/8
    assert u2.mounted.mass * u2.mounted.D ** 2 / 8 == pytest.approx(u2.mounted.inertia)
