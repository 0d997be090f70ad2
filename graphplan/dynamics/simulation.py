"""The machine's motion with its flywheel (method D.2): the steady ω(φ) from the energy
equation and an RK4 run of Lagrange's equation from rest that checks it.

Sign conventions and equations: :mod:`graphplan.dynamics.reduction`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError
from .flywheel import flywheel
from .reduction import DynamicModel, DynamicsError, Solved, _model
from .work import work_diagrams

Array = NDArray[np.float64]


@dataclass(frozen=True, slots=True)
class Simulation:
    """ω(φ) of the steady motion with a flywheel, by the energy form and by RK4 in time.

    Attributes
    ----------
    I_flywheel : float
        Iм, kg·m².
    tau, omega : ndarray (G+1,)
        Steady ω(φ) of the energy form, rad/s (plot-ready over one turn).
    T0 : float
        Kinetic energy at τ = 0, chosen so that (ω_max + ω_min)/2 = |ω1|, J.
    omega_max, omega_min, omega_avg : float
    delta_actual, delta_target : float
        ``(ω_max − ω_min)/ω_avg`` and the target δ (None if not given).
    t, rk4_tau, rk4_omega : ndarray
        The RK4 integration of Lagrange's equation in time: t (s), travel τ (rad,
        unwrapped) and ω at every step, from ``omega_start`` at τ = 0.
    cycle_delta, cycle_mean : ndarray (cycles,)
        δ and (ω_max + ω_min)/2 of each completed cycle of the RK4 run.
    rk4_difference : float
        ``max|ω_RK4 − ω_energy|/ω_avg`` over the last cycle (constant Mд only: with a
        motor characteristic the steady level differs; see ``slip``).
    slip : float | None
        The motor characteristic used by RK4: ``Mд(ω) = Mд·(1 + (|ω1| − ω)/(slip·|ω1|))``
        (None: constant Mд).
    """

    I_flywheel: float
    tau: Array
    omega: Array
    T0: float
    omega_max: float
    omega_min: float
    omega_avg: float
    delta_actual: float
    delta_target: float | None
    t: Array
    rk4_tau: Array
    rk4_omega: Array
    cycle_delta: Array
    cycle_mean: Array
    rk4_difference: float
    slip: float | None


def steady_omega(m: DynamicModel, I_flywheel: float, dT: Array | None = None
                 ) -> tuple[Array, float]:
    """ω(φ) = sqrt(2(T0 + ΔT)/(Iп + Iм)) with T0 making (ω_max + ω_min)/2 = |ω1| (bisection).

    Raises
    ------
    DynamicsError
        When no T0 keeps ω positive with that mean (the flywheel is far too small).
    """
    if dT is None:
        dT = work_diagrams(m).dT
    inert = m.inertia.I_red + I_flywheel
    floor = 1e-9 * float(inert.max())
    if not np.all(inert > floor):
        raise DynamicsError(f"{m.source}: the reduced moment of inertia Iп + Iм vanishes at "
                            "some angle (give dynamics.crank_inertia or a flywheel)")
    w1 = m.omega1

    def mean(T0):
        om = np.sqrt(np.maximum(2 * (T0 + dT), 0.0) / inert)
        return 0.5 * (om.max() + om.min()) - w1, om

    lo = -float(dT.min())
    if mean(lo)[0] >= 0:
        raise DynamicsError(f"{m.source}: with Iм = {I_flywheel:.6g} kg·m² the crank stops "
                            f"within the cycle at a mean speed of {w1:.6g} rad/s")
    hi = lo + 2.0 * float(inert.max()) * w1 * w1 + 1.0
    while mean(hi)[0] <= 0:
        hi = lo + 2 * (hi - lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mean(mid)[0] > 0:
            hi = mid
        else:
            lo = mid
        if hi - lo <= 1e-15 * hi:
            break
    T0 = 0.5 * (lo + hi)
    return mean(T0)[1], T0


def simulate(obj: Solved | DynamicModel, I_flywheel: float | None = None, *,
             cycles: int = 5, steps_per_cycle: int | None = None,
             omega_start: float | None = None, slip: float | None = None,
             delta: float | None = None) -> Simulation:
    """Check a flywheel: the steady ω(φ) (energy form) and an RK4 run of Lagrange's equation.

    Parameters
    ----------
    obj : Project or DynamicModel
    I_flywheel : float, optional
        Iм, kg·m²; default the Wittenbauer result of :func:`flywheel` for ``delta``.
    cycles : int
        Turns of the crank integrated in time (≥ 1).
    steps_per_cycle : int, optional
        RK4 steps per mean period 2π/|ω1|; default the grid's intervals.
    omega_start : float, optional
        ω at τ = 0 of the RK4 run; default the energy form's ω(0) (then, with constant Mд,
        RK4 must retrace it: ``rk4_difference`` measures the time integration).
    slip : float, optional
        With a value, Mд follows the linear static characteristic of an induction motor,
        ``Mд(ω) = Mд·(1 + (|ω1| − ω)/(slip·|ω1|))`` (its angle-mean speed is |ω1|), and the
        run converges from any ``omega_start`` to the steady motion.
    """
    m = _model(obj)
    if isinstance(cycles, bool) or not isinstance(cycles, int) or cycles < 1:
        raise InputError(f"simulate: cycles must be an integer ≥ 1 (got {cycles!r})")
    wd = work_diagrams(m)
    target = m.delta if delta is None else delta
    if I_flywheel is None:
        I_flywheel = flywheel(m, target).I_m
    if not (math.isfinite(I_flywheel) and I_flywheel >= 0):
        raise InputError(f"simulate: I_flywheel must be ≥ 0 (got {I_flywheel!r})")
    omega, T0 = steady_omega(m, I_flywheel, wd.dT)
    wmax, wmin = float(omega.max()), float(omega.min())
    avg = 0.5 * (wmax + wmin)
    w1, Md = m.omega1, wd.M_d
    tau_g, M_g, I_g, dI_g = m.tau, m.moment.M, m.inertia.I_red + I_flywheel, m.inertia.dI
    two_pi = m.period  # one cycle of the process (2π, or 4π for a four-stroke one)
    if slip is not None and not (math.isfinite(slip) and slip > 0):
        raise InputError(f"simulate: slip must be positive (got {slip!r})")
    gain = 0.0 if slip is None else Md / (slip * w1)

    G = len(tau_g) - 1
    h = two_pi / G
    table = list(zip(M_g.tolist(), I_g.tolist(), dI_g.tolist(), strict=True))

    def rhs(tau: float, w: float) -> float:  # periodic linear interpolation on the grid
        x = (tau % two_pi) / h
        i = min(int(x), G - 1)
        f = x - i
        (M0, I0, d0), (M1, I1, d1) = table[i], table[i + 1]
        M, J, dI = M0 + f * (M1 - M0), I0 + f * (I1 - I0), d0 + f * (d1 - d0)
        return (Md + gain * (w1 - w) + M - 0.5 * w * w * dI) / J

    steps = (len(tau_g) - 1) if steps_per_cycle is None else int(steps_per_cycle)
    if steps < 12:
        raise InputError(f"simulate: steps_per_cycle must be ≥ 12 (got {steps_per_cycle!r})")
    dt = two_pi / (w1 * steps)
    total = math.ceil(cycles * steps * w1 / max(wmin, 0.2 * w1)) + steps
    w = float(omega[0]) if omega_start is None else float(omega_start)
    if not (math.isfinite(w) and w > 0):
        raise InputError(f"simulate: omega_start must be positive (got {omega_start!r})")
    ts, taus, ws = [0.0], [0.0], [w]
    tau = 0.0
    for k in range(total):  # the only loop over time: RK4 on (τ, ω)
        k1t, k1w = w, rhs(tau, w)
        k2t, k2w = w + 0.5 * dt * k1w, rhs(tau + 0.5 * dt * k1t, w + 0.5 * dt * k1w)
        k3t, k3w = w + 0.5 * dt * k2w, rhs(tau + 0.5 * dt * k2t, w + 0.5 * dt * k2w)
        k4t, k4w = w + dt * k3w, rhs(tau + dt * k3t, w + dt * k3w)
        tau += dt * (k1t + 2 * k2t + 2 * k3t + k4t) / 6
        w += dt * (k1w + 2 * k2w + 2 * k3w + k4w) / 6
        if not (math.isfinite(w) and w > 0):
            raise DynamicsError(f"{m.source}: the crank stops in the RK4 run (step {k}); "
                                "start faster or take a larger flywheel")
        ts.append((k + 1) * dt)
        taus.append(tau)
        ws.append(w)
        if tau >= cycles * two_pi:
            break
    t, rt, rw = np.array(ts), np.array(taus), np.array(ws)
    if rt[-1] < cycles * two_pi:
        raise DynamicsError(f"{m.source}: the RK4 run did not complete {cycles} cycles in "
                            f"{total} steps (the crank is too slow)")
    idx = np.floor(rt / two_pi).astype(int)
    cd, cm = [], []
    for c in range(cycles):
        sel = rw[idx == c]
        hi_, lo_ = sel.max(), sel.min()
        cd.append((hi_ - lo_) / (0.5 * (hi_ + lo_)))
        cm.append(0.5 * (hi_ + lo_))
    last = idx == cycles - 1
    ref = np.interp(rt[last] % two_pi, tau_g, omega)
    diff = float(np.max(np.abs(rw[last] - ref)) / avg)
    return Simulation(float(I_flywheel), tau_g, omega, float(T0), wmax, wmin, avg,
                      (wmax - wmin) / avg, target, t, rt, rw, np.array(cd), np.array(cm),
                      diff, slip)


__all__ = ["Simulation", "simulate", "steady_omega"]
