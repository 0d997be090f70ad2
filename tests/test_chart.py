"""The sheets' own plot axes (graphplan.drawing.chart): the values and the labels on an
axis are chosen as matplotlib chooses them, the mapping to sheet mm is the linear one, and
drawing the sheets imports no plotting library."""

import random
import subprocess
import sys

import pytest

from graphplan.drawing.chart import (
    ALL_STEPS,
    AUTO_STEPS,
    Chart,
    auto_limits,
    baseline,
    nice_ticks,
    tick_labels,
)
from graphplan.drawing.items import Circle, Polyline, Text


def test_round_values_by_hand():
    # 0 … 0.163 in 8 intervals: raw step 0.0204 → the next step of 1, 2, 2.5, 5 × 10⁻² is 0.025
    assert nice_ticks(0.0, 0.163, 8) == pytest.approx([0.0, 0.025, 0.05, 0.075, 0.1, 0.125,
                                                       0.15])
    # −1 240 … 15 300 in 6: raw 2 757 → 5 000 (2 500 gives 7 intervals, more than 6)
    assert nice_ticks(-1240.0, 15300.0, 6) == pytest.approx([0.0, 5000.0, 10000.0, 15000.0])
    # 5.47 … 6.05 in 4 with 1.5 among the steps: raw 0.145 → 0.15
    assert nice_ticks(5.47, 6.05, 4, ALL_STEPS) == pytest.approx([5.55, 5.70, 5.85, 6.00])
    assert tick_labels([0.0, 0.025, 0.05]) == ["0.000", "0.025", "0.050"]
    assert tick_labels([-2500.0, 0.0, 2500.0]) == ["-2500", "0", "2500"]


def test_values_and_labels_are_matplotlibs():
    """Over random ranges, counts and both step sets the values are MaxNLocator's (those
    inside the range) and the labels ScalarFormatter's without its offset (a plain minus,
    as the sheets letter it)."""
    from matplotlib.axis import YAxis
    from matplotlib.figure import Figure
    from matplotlib.ticker import MaxNLocator, ScalarFormatter

    axis: YAxis = Figure().add_subplot().yaxis
    rng = random.Random(21)
    for _ in range(1500):
        lo = rng.uniform(-1000, 1000) * 10 ** rng.randint(-3, 3)
        hi = lo + rng.uniform(1e-3, 2000) * 10 ** rng.randint(-3, 3)
        n = rng.randint(1, 9)
        for steps in (AUTO_STEPS, ALL_STEPS):
            want = MaxNLocator(nbins=n, steps=list(steps)).tick_values(lo, hi)
            eps = 1e-10 * (hi - lo)
            want = want[(want >= lo - eps) & (want <= hi + eps)]
            got = nice_ticks(lo, hi, n, steps)
            assert got == pytest.approx(want, rel=1e-12, abs=1e-12 * (hi - lo)), (lo, hi, n)
            if len(got) > 1 and max(abs(lo), abs(hi)) < 1e5 and hi - lo > 1e-4:
                fmt = ScalarFormatter(useOffset=False)
                fmt.set_axis(axis)
                fmt.set_locs(want)
                assert tick_labels(got) == [fmt(v).replace("\N{MINUS SIGN}", "-")
                                            for v in want]


def test_chart_maps_data_linearly_and_clips_to_its_box():
    # x 0…360 over 180 mm from x0 = 10; y −1…1 over 40 mm from y0 = 20 (y down)
    ch = Chart(10.0, 20.0, 180.0, 40.0, (0.0, 360.0), (-1.0, 1.0), "en")
    assert ch.sx([0.0, 90.0, 360.0]) == pytest.approx([10.0, 55.0, 190.0])
    assert ch.sy([1.0, 0.0, -1.0]) == pytest.approx([20.0, 40.0, 60.0])
    ch.plot([0.0, 360.0], [0.0, 2.0], 0.5)  # leaves the box at y = 1 (x = 180°)
    (line,) = ch.items
    assert isinstance(line, Polyline)
    assert line.points[0] == pytest.approx((10.0, 40.0))
    assert line.points[-1] == pytest.approx((100.0, 20.0))
    ch.dots([90.0], [0.5], 1.2)
    assert isinstance(ch.items[-1], Circle) and ch.items[-1].r == pytest.approx(0.6)
    assert ch.items[-1].centre == pytest.approx((55.0, 30.0))


def test_letters_sit_by_their_capitals_and_get_the_decimal_comma():
    ch = Chart(0.0, 0.0, 100.0, 50.0, (0.0, 1.0), (0.0, 1.0), "ru")
    top = ch.letter(10.0, 5.0, "0.25", 2.5, "center", "top")
    assert isinstance(top, Text) and top.text == "0,25" and top.anchor == "middle"
    assert top.pos == pytest.approx((10.0, 7.5))  # capitals 2.5 mm tall hang from y = 5
    up = ch.letter(10.0, 25.0, "ω, рад/с", 3.5, "center", "bottom", rot=90.0)
    # read upwards, its descenders' foot at x = 10: the baseline 0.3·3.5 mm left of it
    assert up is not None and up.rotate_deg == 90.0
    assert up.pos == pytest.approx((10.0 - 1.05, 25.0))
    assert baseline(0.0, 2.0, "center") == pytest.approx(1.0)


def test_auto_limits_widen_the_data_by_five_percent():
    assert auto_limits([[0.0, 10.0], [4.0]]) == pytest.approx((-0.5, 10.5))
    lo, hi = auto_limits([[3.0, 3.0]])
    assert lo < 3.0 < hi


def test_drawing_the_sheets_imports_no_matplotlib(tmp_path):
    """matplotlib's import is a third of a second of a cold ``graphplan sheets``: drawing
    the three sheets of the press (every diagram kind) must not need it."""
    code = ("import sys, runpy; sys.argv = ['graphplan', 'sheets', 'examples/press.toml', "
            f"'-o', {str(tmp_path)!r}]\n"
            "try:\n    runpy.run_module('graphplan', run_name='__main__')\n"
            "except SystemExit as e:\n    assert not e.code, e.code\n"
            "print(sorted(m for m in sys.modules if m.split('.')[0] == 'matplotlib'))")
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    done = subprocess.run([sys.executable, "-c", code], cwd=root, capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.strip().splitlines()[-1] == "[]"
    assert (tmp_path / "sheet3.svg").is_file()
    svg = (tmp_path / "sheet1.svg").read_text(encoding="utf-8")
    assert 'id="kin-diagrams"' in svg
