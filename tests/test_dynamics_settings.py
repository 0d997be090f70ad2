"""The [dynamics] table is read in one place, typed, with its defaults (issue 16), and the
machine unit is sized by the diagrams it is given, not by a sheet."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from graphplan.dynamics import (
    DEFAULT_SERIES,
    SHEET3_DIAGRAMS,
    STEEL,
    DiagramSize,
    DynamicsSettings,
    FlywheelSettings,
)
from graphplan.model import loads

ROOT = Path(__file__).resolve().parents[1]


def _variant(extra: str) -> str:
    return (ROOT / "examples" / "press.toml").read_text(encoding="utf-8").replace(
        "[dynamics]\n", "[dynamics]\n" + extra, 1)


def test_the_press_reads_its_dynamics_and_the_defaults_fill_the_rest():
    s = DynamicsSettings.of(loads(_variant(""), "press.toml"))
    # press.toml: delta = 0.1, efficiency = 0.85, intervals = 48; nothing else given
    assert (s.delta, s.efficiency, s.intervals) == (0.1, 0.85, 48)
    assert s.eta == 0.85 and s.intervals_for(99.0) == 48
    assert s.crank_inertia == 0.0 and s.grid == 720 and s.motor_speed is None
    assert s.motor_series == DEFAULT_SERIES
    assert s.flywheel == FlywheelSettings("rim", "crank", 0.2, 0.1, STEEL)


def test_given_values_override_every_default():
    text = _variant("crank_inertia = 1.5\ngrid = 360\nmotor_speed = 1500\n") + (
        '\n[dynamics.flywheel]\nshape = "disc"\nshaft = "motor"\nb_ratio = 0.3\n'
        "h_ratio = 0.2\ndensity = 7200\n")
    s = DynamicsSettings.of(loads(text, "press.toml"))
    assert (s.crank_inertia, s.grid, s.motor_speed) == (1.5, 360, 1500)
    assert s.flywheel == FlywheelSettings("disc", "motor", 0.3, 0.2, 7200.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        s.delta = 0.2  # type: ignore[misc]


def test_without_efficiency_eta_is_one_and_intervals_are_24_a_turn():
    s = DynamicsSettings()
    assert s.efficiency is None and s.eta == 1.0
    # 24 intervals a turn of the crank: 48 over a four-stroke cycle of 4π
    assert s.intervals_for(2 * 3.141592653589793) == 24
    assert s.intervals_for(4 * 3.141592653589793) == 48


def test_diagram_size_follows_the_frame():
    # A1's frame is 816×584 mm: L = 288 mm (6 × 48), height 120 mm, spans 500 mm, JII at
    # most 90 mm, H at most 80 mm (machine.DIAGRAM_*, SPANS_HEIGHT, ENERGY_WIDTH, MAX_POLE_MM)
    # H + JII at most 816 − 185 (title block) − 2 − 26 − 288 − 34 = 281 mm
    assert SHEET3_DIAGRAMS == DiagramSize(288.0, 120.0, 500.0, 90.0, 80.0, 281.0) \
        == DiagramSize.for_frame(816.0, 584.0)
    # A3's frame, 395×287 mm: kw = 395/816 = 0.484, kh = 287/584 = 0.491;
    # L = 48·⌊6·0.484⌋ = 96, ⌊120·0.491⌋ = 58, spans 287 − 84 = 203, ⌊90·0.484⌋ = 43,
    # H ≤ 5·⌊80·0.484/5⌋ = 5·⌊7.74⌋ = 35, H + JII ≤ 395 − 185 − 2 − 26 − 96 − 34 = 52
    assert DiagramSize.for_frame(395.0, 287.0) == DiagramSize(96.0, 58.0, 203.0, 43.0, 35.0,
                                                              52.0)
    assert DiagramSize.for_frame(2000.0, 1000.0) == SHEET3_DIAGRAMS  # never larger than A1's
