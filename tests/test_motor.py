"""Motor catalogues (graphplan/data/motors_*.csv) and the choice of motor and gear ratio."""

from __future__ import annotations

import dataclasses

import pytest

from graphplan.dynamics import (
    SYNC_SPEEDS,
    Motor,
    MotorSelectionError,
    catalogue_path,
    choose_motor,
    load_catalogue,
    required_power,
)
from graphplan.errors import GraphplanError, InputError

SERIES = ("AIR", "4A")


@pytest.fixture(scope="module", params=SERIES)
def catalogue(request):
    return load_catalogue(request.param)


def test_catalogue_files_are_package_data():
    for series in SERIES:
        path = catalogue_path(series)
        assert path.is_file()
        assert path.parent.name == "data" and path.parent.parent.name == "graphplan"
        head = path.read_text(encoding="utf-8").splitlines()[:3]
        assert all(line.startswith("#") for line in head)  # the header cites the source


def test_series_spellings():
    assert load_catalogue("АИР") == load_catalogue("air")
    # the default is the one catalogue with the rotor inertia
    assert load_catalogue() == load_catalogue("delphi") == load_catalogue("Motive")
    assert all(m.inertia_kg_m2 for m in load_catalogue())
    assert load_catalogue("4А") == load_catalogue("4a")
    with pytest.raises(MotorSelectionError, match="unknown motor series"):
        load_catalogue("5AM")


def test_catalogue_loads_with_enough_rows(catalogue):
    assert len(catalogue) >= 20
    assert all(isinstance(m, Motor) for m in catalogue)
    assert len({m.type for m in catalogue}) == len(catalogue)
    with pytest.raises(dataclasses.FrozenInstanceError):
        catalogue[0].power_kw = 1.0  # type: ignore[misc]


def test_every_synchronous_speed_is_present(catalogue):
    assert {m.sync_rpm for m in catalogue} == set(SYNC_SPEEDS)


def test_designation_matches_poles(catalogue):
    for m in catalogue:
        assert m.type[-1] == str(m.poles), m.type


def test_powers_grow_within_each_speed(catalogue):
    for sync in SYNC_SPEEDS:
        powers = [m.power_kw for m in catalogue if m.sync_rpm == sync]
        assert powers == sorted(powers) and len(set(powers)) == len(powers), sync
        speeds = [m.rated_rpm for m in catalogue if m.sync_rpm == sync]
        # larger motors slip less (not strictly row by row in the sources)
        assert speeds[-1] > speeds[0], sync


def test_rated_speed_below_synchronous_with_plausible_slip(catalogue):
    for m in catalogue:
        assert m.rated_rpm < m.sync_rpm, m.type
        assert 0.005 <= m.slip <= 0.12 + 1e-9, m.type
        if m.power_kw >= 0.37:  # only the smallest 4AA motors slip more than 10 %
            assert m.slip <= 0.10 + 1e-9, m.type


def test_printed_slip_agrees_with_the_speeds():
    # the 4A source prints the slip too; two 750 rpm rows disagree with their own speed
    known_outliers = {"4А71B8", "4А80B8"}
    for m in load_catalogue("4A"):
        assert m.slip_pct is not None
        if m.type not in known_outliers:
            assert abs(m.slip_pct - 100 * m.slip) <= 1.15, m.type


def test_torque_ratios_in_plausible_ranges(catalogue):
    for m in catalogue:
        for ratio in (m.start_torque_ratio, m.max_torque_ratio):
            if ratio is not None:
                assert 1.2 <= ratio <= 3.5, m.type
        assert m.max_torque_ratio is not None, m.type
        if m.start_torque_ratio is not None:
            assert m.start_torque_ratio <= m.max_torque_ratio, m.type


def test_start_torque_ratio_given_by_4a_only():
    assert all(m.start_torque_ratio is not None for m in load_catalogue("4A"))
    assert all(m.start_torque_ratio is None for m in load_catalogue("AIR"))


def test_inertia_positive_where_given(catalogue):
    for m in catalogue:
        if m.inertia_kg_m2 is not None:
            assert m.inertia_kg_m2 > 0, m.type


def test_reference_rows():
    air = {m.type: m for m in load_catalogue("AIR")}
    assert (air["АИР100L4"].power_kw, air["АИР100L4"].rated_rpm) == (4.0, 1410)
    # frame names of the 2-pole 100 frame, corrected against method.md B.5
    assert air["АИР100S2"].power_kw == 4.0 and air["АИР100L2"].power_kw == 5.5
    a4 = {m.type: m for m in load_catalogue("4A")}
    m = a4["4А100L4"]
    assert (m.power_kw, m.rated_rpm, m.slip_pct) == (4.0, 1430, 4.7)
    assert (m.start_torque_ratio, m.max_torque_ratio) == (2.0, 2.2)


def test_required_power_by_hand():
    # P = M·ω1/η = 100 N·m · 10 rad/s / 0.8 = 1250 W
    assert required_power(100.0, 10.0, 0.8) == pytest.approx(1250.0)
    # the sign of the mean moment of resistance does not matter
    assert required_power(-100.0, 10.0, 0.8) == pytest.approx(1250.0)
    for bad in ((100.0, 0.0, 0.8), (100.0, 10.0, 0.0), (100.0, 10.0, 1.2), (float("nan"), 1, 1)):
        with pytest.raises(InputError):
            required_power(*bad)


def test_choose_motor_picks_the_smallest_sufficient():
    # AIR at 1500 rpm: АИР90L4 2.2 kW (1395 rpm) < 2.5 kW < АИР100S4 3.0 kW (1410 rpm)
    choice = choose_motor(2500.0, 60.0, series="AIR")
    assert choice.motor.type == "АИР100S4"
    # u = n_ном/n1 = 1410/60 = 23.5; reserve = 3000/2500 − 1 = 0.2
    assert choice.u == pytest.approx(23.5)
    assert choice.reserve == pytest.approx(0.2)
    assert choice.J_reduced is None  # the AIR source gives no rotor inertia
    assert "АИР100S4" in choice.reason and "\n" not in choice.reason
    with pytest.raises(dataclasses.FrozenInstanceError):
        choice.u = 1.0  # type: ignore[misc]
    # exactly a catalogue power: that motor, zero reserve
    exact = choose_motor(3000.0, 60.0, series="AIR")
    assert exact.motor.type == "АИР100S4" and exact.reserve == pytest.approx(0.0)


def test_choose_motor_other_speed_and_series():
    # 1000 rpm: АИР100L6 2.2 kW < 2.5 kW < АИР112MA6 3.0 kW, 950 rpm; u = 950/50 = 19
    choice = choose_motor(2500.0, 50.0, sync_rpm=1000, series="AIR")
    assert choice.motor.type == "АИР112MA6" and choice.u == pytest.approx(19.0)
    # the 4A source has no 1.1 kW motor at 1500 rpm: 1.0 kW gets 4А80B4 (1.5 kW, 1415 rpm)
    choice = choose_motor(1000.0, 100.0, series="4А")
    assert choice.motor.type == "4А80B4" and choice.u == pytest.approx(14.15)


def test_choose_motor_reduced_inertia_when_known():
    motor = Motor("X", 3.0, 1500, 1410.0, inertia_kg_m2=0.01)
    choice = choose_motor(2500.0, 60.0, catalogue=(motor,))
    # J_рот·u² = 0.01 · 23.5² = 5.5225 kg·m²
    assert choice.J_reduced == pytest.approx(5.5225)


def test_choose_motor_errors():
    with pytest.raises(MotorSelectionError, match="no motor at 1500 rpm is large enough"):
        choose_motor(31_000.0, 60.0, series="AIR")  # the largest AIR 4-pole motor is 30 kW
    with pytest.raises(GraphplanError):
        choose_motor(1_000_000.0, 60.0, series="4A")
    with pytest.raises(MotorSelectionError, match="synchronous speed"):
        choose_motor(1000.0, 60.0, sync_rpm=1200)
    with pytest.raises(InputError):
        choose_motor(-1.0, 60.0)
    with pytest.raises(InputError):
        choose_motor(1000.0, 0.0)


HEADER = "type,power_kw,sync_rpm,rated_rpm,max_torque_ratio\n"


@pytest.mark.parametrize(
    ("row", "column"),
    [
        ("АИР80A4,1.1,1500,abc,2.2", "rated_rpm"),
        ("АИР80A4,-1.1,1500,1395,2.2", "power_kw"),
        ("АИР80A4,1.1,1200,1150,2.2", "sync_rpm"),
        ("АИР80A4,1.1,1500,1550,2.2", "rated_rpm"),
        ("АИР80A4,,1500,1395,2.2", "power_kw"),
        ("АИР80A4,1.1,1500,1395,x", "max_torque_ratio"),
    ],
)
def test_bad_row_names_file_line_and_column(tmp_path, row, column):
    path = tmp_path / "bad.csv"
    path.write_text(
        "# comment\n" + HEADER + "АИР71B4,0.75,1500,1350,2.2\n" + row + "\n", encoding="utf-8"
    )
    with pytest.raises(InputError) as info:
        load_catalogue(path=path)
    message = str(info.value)
    assert "\n" not in message
    assert str(path) in message and "line 4" in message and repr(column) in message


def test_bad_files(tmp_path):
    short = tmp_path / "short.csv"
    short.write_text(HEADER + "АИР80A4,1.1,1500\n", encoding="utf-8")
    with pytest.raises(InputError, match="line 2: expected 5 cells"):
        load_catalogue(path=short)
    nohead = tmp_path / "nohead.csv"
    nohead.write_text("type,power_kw\nX,1\n", encoding="utf-8")
    with pytest.raises(InputError, match="header lacks"):
        load_catalogue(path=nohead)
    with pytest.raises(InputError, match="cannot read"):
        load_catalogue(path=tmp_path / "missing.csv")
