"""Dynamics of the machine unit: Mс, Iп, work diagrams, flywheel, simulation (method B.4)."""

import dataclasses
import math

import numpy as np
import pytest

from graphplan import dynamics as dyn
from graphplan.errors import GraphplanError, InputError
from graphplan.files import bundled_example
from graphplan.forces import compute_loads, load_power
from graphplan.kinematics import solve, solve_positions
from graphplan.model import load
from graphplan.project import analyze

NAMES = ("press", "shaper", "offset_slider", "fourbar")


@pytest.fixture(scope="module")
def analyses():
    return {name: analyze(load(bundled_example(name))) for name in NAMES}


@pytest.fixture(scope="module")
def models(analyses):
    return {name: dyn.dynamic_model(a) for name, a in analyses.items()}


def sine_model(M0=100.0, I0=5.0, omega=6.0, delta=0.05, grid=7200, I_var=0.0):
    """Mс = −M0·(1 + sin φ) (resisting), Iп = I0 constant: ΔT = −M0·(1 − cos φ)."""
    tau = np.linspace(0.0, 2 * math.pi, grid + 1)
    return dyn.DynamicModel.from_arrays(tau, -M0 * (1 + np.sin(tau)), I_var, 0.0, I0 - I_var,
                                        omega, delta=delta, source="sine.toml")


# --- the hand-checkable case ------------------------------------------------------------------


@pytest.mark.parametrize("delta", [0.2, 0.1, 0.02])
def test_sinusoidal_resistance_constant_inertia_closed_form(delta):
    M0, I0, w = 100.0, 5.0, 6.0
    m = sine_model(M0, I0, w, delta)
    wd = dyn.work_diagrams(m)
    assert wd.M_d == pytest.approx(M0, rel=1e-9)  # Mд·2π = −∫Mс dφ = 2π·M0
    exact = -M0 * (1 - np.cos(m.tau))
    assert np.allclose(wd.dT, exact, atol=1e-6 * M0)
    f = dyn.flywheel(m)
    assert f.dT_max == pytest.approx(2 * M0, rel=1e-6)  # trapezoid on 7200 intervals
    need = f.dT_max / (w * w * delta)
    # Wittenbauer and Merkalov both give ΔTmax/(ω²δ): I_var ≡ 0, so ΔT − k·I_var = ΔT
    # for any slope k and the two tangents touch at the extremes of ΔT (τ = 0 and π).
    assert math.isclose(f.J_I, need, rel_tol=1e-12)
    assert math.isclose(f.J_I, 2 * M0 / (w * w * delta), rel_tol=1e-6)
    assert math.isclose(f.I_m, need - I0, rel_tol=1e-12)
    assert f.I_m_approx == f.I_m
    assert f.difference_pct == 0.0
    assert f.tangent_tau[1] == pytest.approx(math.pi)
    # the steady motion reproduces δ exactly: (ωmax² − ωmin²)·J/2 = ΔTmax and ωavg = ω
    s = dyn.simulate(m, f.I_m, cycles=2, steps_per_cycle=720)
    assert s.delta_actual == pytest.approx(delta, rel=1e-9)
    assert s.omega_avg == pytest.approx(w, rel=1e-12)


def test_wittenbauer_does_not_depend_on_the_split_of_the_constant_inertia():
    """Moving a constant c from I_const into I_var shifts both tangents' intercepts by
    −k±·c; kl shrinks by δω²·c and J_I by c, while I_const grows by c: Iм is unchanged."""
    a = dyn.flywheel(sine_model(I_var=0.0))
    b = dyn.flywheel(sine_model(I_var=2.0))
    assert b.I_m == pytest.approx(a.I_m, rel=1e-12)
    assert math.isclose(b.J_I, a.J_I - 2.0, rel_tol=1e-12)


def test_graphical_integration_is_second_order():
    m = sine_model(grid=15360)
    errs = np.array([dyn.work_diagrams(m, n).error for n in (12, 24, 48, 96)])
    ratios = errs[:-1] / errs[1:]
    assert np.all((ratios > 3.6) & (ratios < 4.4)), ratios
    # the midpoint rule: Aс_graph(τ) − Aс(τ) = −h²/24·(M'(τ) − M'(0)) + O(h⁴), M' = −M0·cos
    wd = dyn.work_diagrams(m, 24)
    h = 2 * math.pi / 24
    predicted = h**2 / 24 * 100.0 * (np.cos(wd.node_tau) - 1)
    assert np.allclose(wd.A_c_graph - wd.A_c_exact_nodes, predicted, atol=2e-3)


def test_pole_scale_of_the_work_diagram():
    wd = dyn.work_diagrams(sine_model(), 12, reading_mm=0.5)
    assert math.isclose(wd.KA, wd.Kphi * wd.KM * wd.H, rel_tol=1e-12)
    assert np.allclose(wd.yM_mm % 0.5, 0) and np.allclose(wd.yA_mm % 0.5, 0)
    assert np.ptp(np.append(wd.yA_mm, 0)) <= 60.0 + 1.0


# --- the variants -----------------------------------------------------------------------------


@pytest.mark.parametrize("name", NAMES)
def test_resisting_moment_is_the_power_of_weights_and_resistance(analyses, models, name):
    a, m = analyses[name], models[name]
    loads = compute_loads(a.mech, a.kin, a.cycle, inertia=False, neglect_below=0.0)
    expected = load_power(a.mech, a.kin, loads) / abs(a.mech.crank.omega)
    scale = np.abs(m.moment.M).max()
    assert np.allclose(m.moment.pos_M, expected, atol=1e-9 * scale)
    # the positions lie on the grid's curve (Mс is continuous at least where it is smooth)
    on = np.interp(m.moment.pos_tau, m.tau, m.moment.M)
    assert np.median(np.abs(on - m.moment.pos_M)) < 0.02 * scale
    assert m.moment.M[0] == m.moment.M[-1]


@pytest.mark.parametrize("name", NAMES)
def test_reduced_inertia_equals_kinetic_energy_by_finite_differences(analyses, name):
    """½·Iп·ω1² = Σ ½m·vS² + ½IS·ω² (+ the crank's constant part), with every velocity
    from central differences of the position solver (independent of the velocity solver)."""
    a = analyses[name]
    mech = dataclasses.replace(a.mech, settings={**a.mech.settings,
                                                 "dynamics": {"crank_inertia": 0.25}})
    phi = np.linspace(0.05, 2 * math.pi, 23)
    h = 1e-6
    w1 = mech.crank.omega
    p_plus, p_minus = solve_positions(mech, phi + h), solve_positions(mech, phi - h)
    T = np.full(phi.shape, 0.5 * 0.25 * w1**2)
    for ln in mech.moving_links:
        pr = mech.links.get(ln)
        if pr is None:
            continue
        om = (np.unwrap(np.stack([p_minus.theta[ln], p_plus.theta[ln]]), axis=0)[1]
              - p_minus.theta[ln]) / (2 * h) * w1
        T += 0.5 * pr.inertia * om**2
        if pr.centre is not None and pr.mass > 0:
            v = (p_plus.points[pr.centre] - p_minus.points[pr.centre]) / (2 * h) * w1
            T += 0.5 * pr.mass * np.sum(v * v, axis=1)
    ri = dyn.reduced_inertia(mech, solve(mech, phi))
    assert np.allclose(0.5 * ri.I_red * w1**2, T, rtol=1e-6, atol=1e-9 * T.max())
    assert ri.I_const >= 0.25
    # dIп/dφ against central differences of Iп (travel in the sense of rotation)
    sense = 1.0 if w1 > 0 else -1.0
    ip = dyn.reduced_inertia(mech, solve(mech, phi + sense * 1e-5)).I_red
    im = dyn.reduced_inertia(mech, solve(mech, phi - sense * 1e-5)).I_red
    assert np.allclose(ri.dI, (ip - im) / 2e-5, atol=1e-5 * max(ri.I_var.max(), 1e-9))


@pytest.mark.parametrize("name", NAMES)
def test_equal_work_over_the_cycle(analyses, models, name):
    m = models[name]
    wd = dyn.work_diagrams(m)
    # the exact integral against the closed form: the weights do no work over a cycle and
    # the resistance does −max·(stroke or swing)·∫f(s)ds (the diagram's area), so
    # Mд·2π = max·travel·area to round-off (Gauss on the pieces between the breaks)
    a = analyses[name]
    res = a.mech.resistances[0]
    d = np.array(res.diagram)
    area = float(np.sum(0.5 * (d[1:, 1] + d[:-1, 1]) * np.diff(d[:, 0])))
    travel = a.cycle.swing if a.cycle.output_kind == "rocker" else a.cycle.stroke
    assert wd.M_d * 2 * math.pi == pytest.approx(res.maximum * travel * area, rel=1e-9)
    # the trapezoid of the 0.5° grid is close but not exact (a jump inside a cell)
    integral = np.trapezoid(m.moment.M, m.tau)
    assert wd.M_d * 2 * math.pi == pytest.approx(-integral, rel=2e-3)
    assert wd.M_d > 0
    assert wd.dT[0] == 0 and abs(wd.dT[-1]) < 1e-9 * np.abs(wd.A_c).max()
    assert wd.dT_graph[-1] == pytest.approx(0, abs=1e-9 * np.abs(wd.A_c).max())
    # graphical integration converges at second order, across the resistance's jumps too
    # (they are nodes): against the exact integral on a 0.05° grid (on the 0.5° grid the
    # trapezoid smears a jump over one cell and is the less accurate of the two),
    # 24 → 96 intervals is two halvings, ×1/16 ideally; at least ×1/8
    fine = dyn.dynamic_model(analyses[name], grid=7200)
    errs = [dyn.work_diagrams(fine, n).error for n in (24, 96)]
    assert errs[1] < errs[0] / 8 and errs[1] < 0.01


@pytest.mark.parametrize("name", NAMES)
def test_simulated_delta_meets_the_target_and_falls_with_the_flywheel(models, name):
    m = models[name]
    f = dyn.flywheel(m)
    assert abs(f.difference_pct) < 1.0  # Merkalov within 1 % of Wittenbauer (D.2)
    s = dyn.simulate(m, f.I_m, cycles=2)
    assert s.delta_actual == pytest.approx(m.delta, rel=0.03)
    assert s.rk4_difference < 1e-3  # energy form and RK4 in time agree
    assert np.allclose(s.cycle_delta, s.delta_actual, rtol=0.01)
    deltas = [dyn.steady_omega(m, k * f.I_m) for k in (0.5, 1.0, 2.0, 4.0)]
    d = [(o.max() - o.min()) / (0.5 * (o.max() + o.min())) for o, _ in deltas]
    assert d[0] > d[1] > d[2] > d[3]
    assert np.isfinite(s.omega).all() and np.isfinite(s.rk4_omega).all()


def test_rk4_with_a_motor_characteristic_converges_from_a_slow_start(models):
    m = models["press"]
    f = dyn.flywheel(m)
    s = dyn.simulate(m, f.I_m, cycles=8, omega_start=0.8 * m.omega1, slip=0.05)
    assert abs(s.cycle_delta[0] - m.delta) > 0.05  # far from the steady motion at first
    assert abs(s.cycle_delta[-1] - s.cycle_delta[-2]) < 1e-3
    assert s.cycle_delta[-1] == pytest.approx(m.delta, rel=0.03)
    assert s.cycle_mean[-1] == pytest.approx(m.omega1, rel=0.01)


def test_press_and_shaper_numbers(models, capsys):
    out = {}
    for name in ("press", "shaper"):
        m = models[name]
        f = dyn.flywheel(m)
        s = dyn.simulate(m, f.I_m, cycles=2)
        wd = f.work
        out[name] = (f, s)
        with capsys.disabled():
            print(f"\n{name}: ω1 = {m.omega1:.4f} rad/s, δ = {f.delta}; Mд = {f.M_d:.2f} N·m "
                  f"(graphical {wd.M_d_graph:.2f}, n = {wd.intervals}, KM = {wd.KM}, "
                  f"H = {wd.H} mm, KA = {wd.KA:.4g} J/mm, error {wd.error:.2%}); "
                  f"ΔTmax = {f.dT_max:.1f} J; P = {f.P_c:.0f} W, motor {f.P_motor:.0f} W; "
                  f"Iп ∈ [{m.inertia.I_red.min():.3f}, {m.inertia.I_red.max():.3f}] kg·m²; "
                  f"Iм: Wittenbauer {f.I_m:.2f}, Merkalov {f.I_m_approx:.2f} "
                  f"({f.difference_pct:+.3f} %), crude {f.I_m_crude:.2f}, graphical "
                  f"{f.I_m_graph:.2f} kg·m²; ψ = {f.psi_max:.3f}°/{f.psi_min:.3f}° "
                  f"(KI = {f.KI}), kl = {f.segment_mm:.2f} mm; rim D = {f.size.D:.3f} m, "
                  f"b = {f.size.b:.3f} m, h = {f.size.h:.3f} m, m = {f.size.mass:.0f} kg, "
                  f"v = {f.size.speed:.2f} m/s; simulated δ = {s.delta_actual:.5f}")
    f, s = out["press"]
    assert f.M_d == pytest.approx(958.6, rel=0.01)
    assert f.I_m == pytest.approx(1553, rel=0.01)
    size = f.size
    assert size.inertia == pytest.approx(size.mass * size.D**2 / 4, rel=1e-12)
    assert size.mass == pytest.approx(dyn.STEEL * math.pi * size.D * size.b * size.h)


# --- sizing and errors ------------------------------------------------------------------------


def test_flywheel_sizes():
    disc = dyn.flywheel_size(100.0, 6.0, shape="disc", b_ratio=0.2)
    assert disc.inertia == pytest.approx(disc.mass * disc.D**2 / 8)
    assert disc.mass == pytest.approx(dyn.STEEL * math.pi * disc.D**2 * disc.b / 4)
    rim = dyn.flywheel_size(100.0, 6.0, shape="rim", ratio=4.0)
    assert rim.inertia == pytest.approx(100.0 / 16)
    assert rim.speed == pytest.approx(6.0 * 4.0 * rim.D / 2)
    with pytest.raises(InputError):
        dyn.flywheel_size(100.0, 6.0, shape="cone")


def test_missing_delta_names_the_file_and_key(analyses):
    a = analyses["press"]
    mech = dataclasses.replace(a.mech, settings={k: v for k, v in a.mech.settings.items()
                                                 if k != "dynamics"})
    with pytest.raises(InputError, match=r"press\.toml.*dynamics\.delta") as e:
        dyn.flywheel(dataclasses.replace(a, mech=mech))
    assert "\n" not in str(e.value)


def test_errors_are_graphplan_errors():
    tau = np.linspace(0, 2 * math.pi, 73)
    no_work = dyn.DynamicModel.from_arrays(tau, 10 * np.sin(tau), 0.0, 0.0, 1.0, 5.0, delta=0.1)
    with pytest.raises(dyn.DynamicsError, match="no work"):
        dyn.work_diagrams(no_work)
    m = sine_model(M0=1e4, I0=0.01)
    with pytest.raises(GraphplanError, match="stops"):
        dyn.simulate(m, 0.0)
    with pytest.raises(InputError):
        dyn.flywheel(m, delta=1.5)
    with pytest.raises(InputError):
        dyn.work_diagrams(m, 3)
