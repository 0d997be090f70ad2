"""Kinematic diagrams s, v, a of the output link and the method of chords; their figure."""

import math

import numpy as np
import pytest

from graphplan import fonts
from graphplan.drawing import (
    TEXT,
    Circle,
    Polyline,
    Text,
    diagrams_items,
    diagrams_size,
    fit_diagrams,
)
from graphplan.errors import InputError, LayoutError
from graphplan.files import bundled_example
from graphplan.kinematics import analyse_cycle
from graphplan.model import load
from graphplan.plans import KinematicDiagrams, kinematic_diagrams, output_motion
from graphplan.units import SERIES

NAMES = ("press", "fourbar", "shaper", "scotch_yoke", "offset_slider", "shaper_prp",
         "sixbar_press")


@pytest.fixture(scope="module")
def variants():
    out = {}
    for name in NAMES:
        mech = load(bundled_example(name))
        out[name] = (mech, analyse_cycle(mech))
    return out


@pytest.fixture(scope="module")
def diagrams(variants) -> dict[str, KinematicDiagrams]:
    return {name: kinematic_diagrams(m, c) for name, (m, c) in variants.items()}


@pytest.mark.parametrize("name", NAMES)
def test_exact_v_and_a_are_time_derivatives_of_s(variants, name):
    mech, cycle = variants[name]
    w, dt = abs(mech.crank.omega), 1e-5  # central differences in crank travel τ = |ω1|·t
    tau = np.linspace(0.1, 2 * math.pi - 0.1, 37)
    _, v, a = output_motion(mech, cycle, tau)
    sp, vp, _ = output_motion(mech, cycle, tau + dt)
    sm, vm, _ = output_motion(mech, cycle, tau - dt)
    assert np.allclose((sp - sm) / (2 * dt) * w, v, rtol=0, atol=1e-7 * np.abs(v).max())
    assert np.allclose((vp - vm) / (2 * dt) * w, a, rtol=0, atol=1e-6 * np.abs(a).max())


@pytest.mark.parametrize("name", NAMES)
def test_everything_is_finite_and_s_starts_at_the_start_dead_centre(diagrams, variants, name):
    d = diagrams[name]
    mech, cycle = variants[name]
    for f in ("phi_deg", "s", "v", "a", "node_deg", "s_nodes", "mid_deg", "v_chords",
              "v_exact_mid", "a_chords", "a_exact_node"):
        assert np.isfinite(getattr(d, f)).all(), f
    assert d.output_kind == cycle.output_kind
    top = cycle.swing if d.output_kind == "rocker" else cycle.stroke
    assert d.s.min() >= -1e-9 and d.s.max() <= top + 1e-9
    assert d.s.max() == pytest.approx(top, rel=1e-4)  # the 0.5° grid passes near the end
    assert d.phi_deg[0] == 0 and d.phi_deg[-1] == 360 and len(d.phi_deg) == 721
    assert d.node_labels[0] == d.node_labels[-1] == str(mech.positions.number_from)
    assert np.allclose(np.diff(d.node_deg), 360 / d.intervals)
    assert np.allclose(d.mid_deg, d.node_deg[:-1] + 180 / d.intervals)
    assert d.a_chords[0] == d.a_chords[-1]  # the v polyline is closed periodically


def test_press_dead_centres_and_nodes(diagrams, variants):
    d = diagrams["press"]
    # positions.count = 8 < 12 → 16 intervals of 22.5°; position 1 is the END dead centre
    # (first = "end"), so s = H = 2·lOA = 0.16 m there and s = 0 half a turn later
    # (central crank-slider: dead centres 180° apart).
    assert d.intervals == 16
    assert d.node_labels == ("1", "", "2", "", "3", "", "4", "", "5", "", "6", "", "7", "",
                             "8", "", "1")
    assert d.s_nodes[0] == pytest.approx(0.16, abs=1e-12)
    assert d.s_nodes[8] == pytest.approx(0.0, abs=1e-12)
    assert d.s_nodes[16] == pytest.approx(0.16, abs=1e-12)
    assert abs(d.v_exact_mid).max() > 0 and d.a_exact_node[0] < 0  # BDC: accelerated back up
    # extra positions (2), (3) at 20° and 10° before the BDC are not nodes
    assert "(2)" not in d.node_labels


def test_default_intervals(diagrams):
    assert diagrams["fourbar"].intervals == 12  # count 12 ≥ 12
    assert diagrams["fourbar"].node_labels[:3] == ("1", "2", "3")
    assert diagrams["shaper"].node_labels[:2] == ("0", "1")  # number_from = 0
    assert "0'" not in diagrams["shaper"].node_labels


def test_press_scales_by_hand(diagrams):
    d = diagrams["press"]
    # Ks = nice_ceil(0.16 m / 50 mm = 0.0032) = 0.004 m/mm; Kφ = 2π/240 rad/mm;
    # ω1 = π·55/30; H1 = H2 = 40 mm:
    # Kv = Ks·ω1/(Kφ·H1) = 0.004·(55π/30)·240/(2π·40) = 0.004·5.5 = 0.022 (m/s)/mm,
    # Ka = Kv·ω1/(Kφ·H2) = 0.022·5.5 = 0.121 (m/s²)/mm.
    assert d.Ks == 0.004 and d.Kphi == pytest.approx(2 * math.pi / 240)
    assert (d.H1, d.H2) == (40.0, 40.0)
    assert d.Kv == pytest.approx(0.022, rel=1e-12)
    assert d.Ka == pytest.approx(0.121, rel=1e-12)


@pytest.mark.parametrize("name", NAMES)
def test_scale_relations_and_fit(diagrams, name):
    d = diagrams[name]
    assert d.Kphi == pytest.approx(2 * math.pi / d.length_mm, rel=1e-15)
    assert d.Kv == pytest.approx(d.Ks * d.omega1 / (d.Kphi * d.H1), rel=1e-12)
    assert d.Ka == pytest.approx(d.Kv * d.omega1 / (d.Kphi * d.H2), rel=1e-12)
    mant = d.Ks / 10 ** math.floor(math.log10(d.Ks))
    assert any(math.isclose(mant, m) for m in SERIES)
    for H in (d.H1, d.H2):
        assert H >= 1 and (H % 5 == 0 or H < 5)

    def span(*xs):
        x = np.concatenate(xs)
        return max(x.max(), 0) - min(x.min(), 0)

    for curve, chords, K in ((d.s, d.s_nodes, d.Ks), (d.v, d.v_chords, d.Kv),
                             (d.a, d.a_chords, d.Ka)):
        drawn = span(curve, chords) / K
        assert 0.35 * d.height_mm < drawn <= d.height_mm + 1e-9


def test_pole_rays_give_the_chord_velocities(diagrams):
    # the ray from P1 (at −H1 mm on the φ axis) parallel to a chord of s cuts the ordinate
    # axis at y = H1·Δy_s/Δx mm; read at Kv it is the chord velocity
    d = diagrams["press"]
    dy = np.diff(d.s_nodes) / d.Ks
    dx = np.radians(np.diff(d.node_deg)) / d.Kphi
    assert np.allclose(d.H1 * dy / dx * d.Kv, d.v_chords, rtol=1e-12, atol=0)


@pytest.mark.parametrize("name", NAMES)
def test_chords_come_from_the_node_ordinates_of_s_only(diagrams, name):
    d = diagrams[name]
    h = 2 * math.pi / d.intervals
    assert np.allclose(d.v_chords, d.omega1 * np.diff(d.s_nodes) / h, rtol=1e-13, atol=0)
    a = d.omega1 * (d.v_chords - np.roll(d.v_chords, 1)) / h
    assert np.allclose(d.a_chords, np.append(a, a[0]), rtol=1e-13, atol=0)


def test_chord_method_on_the_sine_mechanism_closed_form(diagrams):
    # Scotch yoke: s = r·(1 − cos τ), r = 0.08 m, from the start dead centre.
    # The chord over [τ_i, τ_i + h]: |ω|·r·(cos τ_i − cos τ_{i+1})/h = |ω|·r·sin(m_i)·k with
    # k = sin(h/2)/(h/2); n = 12, h = 30°: k = sin 15°/(π/12) = 0.258819/0.261799 = 0.988616.
    # Chords of the v points: |ω|²·r·k·(sin m_i − sin m_{i−1})/h = |ω|²·r·cos(τ_i)·k².
    d = diagrams["scotch_yoke"]
    tau = np.radians(d.phi_deg)
    assert np.allclose(d.s, 0.08 * (1 - np.cos(tau)), atol=1e-12)
    k = math.sin(math.pi / 12) / (math.pi / 12)
    assert k == pytest.approx(0.988616, abs=1e-6)
    assert np.allclose(d.v_chords, k * d.v_exact_mid, atol=1e-12)
    assert np.allclose(d.a_chords, k * k * d.a_exact_node, atol=1e-9)
    # the largest error is at the midpoint nearest 90°, m = 75°: (1 − k)·sin 75° of |ω|·r
    # = 0.011384·0.965926 = 0.010996
    assert d.v_error == pytest.approx((1 - k) * math.sin(math.radians(75)), rel=1e-9)
    assert d.v_error == pytest.approx(0.010996, abs=1e-6)


@pytest.mark.parametrize("name", ["press", "fourbar", "shaper", "sixbar_press"])
def test_chord_error_is_second_order(variants, name):
    mech, cycle = variants[name]
    n = mech.positions.count * 2
    coarse = kinematic_diagrams(mech, cycle, intervals=n)
    fine = kinematic_diagrams(mech, cycle, intervals=2 * n)
    # error ≈ |ω|·s'''·h²/24 at the midpoints: halving h divides it by about 4
    assert 3.0 < coarse.v_error / fine.v_error < 4.6
    assert 3.0 < coarse.a_error / fine.a_error < 4.6
    assert fine.v_error < 0.01


def test_reading_precision(variants):
    mech, cycle = variants["press"]
    d = kinematic_diagrams(mech, cycle, reading_mm=0.5)
    y = d.s_nodes / d.Ks / 0.5
    assert np.allclose(y, np.round(y), atol=1e-9)
    yv = d.v_chords / d.Kv / 0.5
    assert np.allclose(yv, np.round(yv), atol=1e-9)
    assert d.v_error < 0.05


def test_bad_arguments(variants):
    mech, cycle = variants["press"]
    for bad in (3, 12.0, True):
        with pytest.raises(InputError, match="intervals"):
            kinematic_diagrams(mech, cycle, intervals=bad)
    with pytest.raises(InputError, match="length_mm"):
        kinematic_diagrams(mech, cycle, length_mm=float("nan"))
    with pytest.raises(LayoutError, match="pole distance"):
        kinematic_diagrams(mech, cycle, length_mm=2.0)  # H1* ≈ L/(2π)·… < 1 mm


# ------------------------------------------------------------------------------- figure

def _bounds(group):
    xs, ys = [], []
    for it in group.items:
        pts = (it.points if isinstance(it, Polyline)
               else [(it.centre[0] - it.r, it.centre[1] - it.r),
                     (it.centre[0] + it.r, it.centre[1] + it.r)] if isinstance(it, Circle)
               else [it.pos])
        xs += [p[0] for p in pts]
        ys += [p[1] for p in pts]
    return min(xs), min(ys), max(xs), max(ys)


@pytest.fixture(scope="module")
def press_items(diagrams):
    return diagrams_items(diagrams["press"], (10.0, 20.0), 340, 230, "ru")


def test_figure_size_items_and_determinism(diagrams, press_items):
    """The diagrams are the sheet's own items inside their box: lines as polylines in sheet
    mm, letters as texts (not glyph outlines); the same diagrams give the same items."""
    x0, y0, x1, y1 = _bounds(press_items)
    assert x0 >= 10.0 - 1e-6 and y0 >= 20.0 - 1e-6 and x1 <= 350.0 + 1e-6 and y1 <= 250.0 + 1e-6
    lines = [it for it in press_items.items if isinstance(it, Polyline)]
    texts = [it for it in press_items.items if isinstance(it, Text)]
    assert len(lines) > 50 and len(texts) > 20
    assert all(t.italic for t in texts)  # slanted like every text of the sheet
    assert any(t.text.startswith("Kφ = ") and "," in t.text for t in texts)  # decimal comma
    assert diagrams_items(diagrams["press"], (10.0, 20.0), 340, 230, "ru") == press_items


@pytest.mark.parametrize(("name", "lang"), [("press", "en"), ("fourbar", "ru"),
                                            ("shaper", "en")])
def test_figure_other_languages_and_rockers(diagrams, name, lang):
    g = diagrams_items(diagrams[name], (0.0, 0.0), 330, 220, lang)
    x0, y0, x1, y1 = _bounds(g)
    assert x0 >= -1e-6 and y0 >= -1e-6 and x1 <= 330 + 1e-6 and y1 <= 220 + 1e-6
    words = " ".join(t.text for t in g.items if isinstance(t, Text))
    assert TEXT[lang]["chords"] in words and "Kφ = " in words


def test_figure_does_not_fit(diagrams):
    with pytest.raises(LayoutError, match="kinematic diagrams need"):
        diagrams_items(diagrams["press"], (0.0, 0.0), 200, 230)


def test_labels_avoid_blank_osifont_letters():
    # osifont's Ё ё Э э are blank quadrilaterals: no label may use them
    for lang in TEXT.values():
        for text in lang.values():
            assert not set(text) & set("ЁёЭэ")
            assert fonts.missing_chars("osifont", text) == ""


def test_fit_to_a_box_of_the_sheet(variants):
    mech, cycle = variants["press"]
    # the smallest diagram box of sheet 1 (graphplan.project.layout.DIAGRAM_MIN) is 200×130 mm
    d = fit_diagrams(mech, cycle, 200, 130)
    w, h = diagrams_size(d)
    assert w <= 200 and h <= 130
    assert d.length_mm % d.intervals == 0  # nodes on whole millimetres
    assert d.length_mm >= 120 and d.height_mm >= 25
    g = diagrams_items(d, (0.0, 0.0), 200, 130, "ru")
    assert _bounds(g)[3] <= 130.0 + 1e-6
    with pytest.raises(LayoutError, match="do not fit"):
        fit_diagrams(mech, cycle, 90, 60)
    with pytest.raises(InputError, match="intervals"):
        fit_diagrams(mech, cycle, 200, 130, intervals=2)


def test_diagrams_module_needs_numpy_only():
    import graphplan.plans.diagrams as mod

    with open(mod.__file__, encoding="utf-8") as fh:
        assert "matplotlib" not in fh.read()
