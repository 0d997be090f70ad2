"""The flywheel (sheet 3; method B.5): Wittenbauer's energy–mass diagram and Merkalov's
method give the constant reduced inertia J_I, the flywheel Iм and its rim or disc.

Sign conventions and equations: :mod:`graphplan.dynamics.reduction`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError
from ..units import nice_ceil
from .reduction import MAX_POLE_MM, RIM_SPEED_LIMIT, DynamicModel, DynamicsError, Solved, _model
from .settings import STEEL
from .work import WorkDiagrams, work_diagrams

Array = NDArray[np.float64]


@dataclass(frozen=True, slots=True)
class FlywheelSize:
    """Dimensions of a steel flywheel of moment of inertia ``I`` on its shaft.

    * ``"disc"`` (solid, width b = b_ratio·D): ``I = m·D²/8``, ``m = ρ·π·D²·b/4`` ⇒
      ``D = (32·I/(π·ρ·b_ratio))^(1/5)``;
    * ``"rim"`` (mass in the rim of mean diameter D, width b = b_ratio·D, thickness
      h = h_ratio·D): ``I = m·D²/4``, ``m = ρ·π·D·b·h`` ⇒
      ``D = (4·I/(π·ρ·b_ratio·h_ratio))^(1/5)``.

    (For a disc ``h`` is its radius D/2: the whole section is metal.)

    Mounted on a shaft turning u times faster than the crank, the flywheel needs only
    ``I = Iм/u²``. ``speed`` = ω_shaft·D/2 (m/s); ``speed_ok`` compares it with
    :data:`RIM_SPEED_LIMIT`.
    """

    shape: str
    ratio: float
    inertia: float
    D: float
    b: float
    h: float
    mass: float
    speed: float
    speed_ok: bool


def flywheel_size(I_m: float, omega1: float, *, shape: str = "rim", ratio: float = 1.0,
                  b_ratio: float = 0.2, h_ratio: float = 0.1,
                  density: float = STEEL) -> FlywheelSize:
    """Size a flywheel of reduced inertia ``I_m`` (on the crank) on a shaft of ratio u."""
    for name, val in (("ratio", ratio), ("b_ratio", b_ratio), ("h_ratio", h_ratio),
                      ("density", density)):
        if not (math.isfinite(val) and val > 0):
            raise InputError(f"flywheel: {name} must be positive (got {val!r})")
    if not (math.isfinite(I_m) and I_m >= 0):
        raise InputError(f"flywheel: the moment of inertia must be ≥ 0 (got {I_m!r})")
    J = I_m / ratio**2
    if shape == "disc":
        D = (32 * J / (math.pi * density * b_ratio)) ** 0.2
        b, h = b_ratio * D, 0.5 * D
        mass = density * math.pi * D**2 * b / 4
    elif shape == "rim":
        D = (4 * J / (math.pi * density * b_ratio * h_ratio)) ** 0.2
        b, h = b_ratio * D, h_ratio * D
        mass = density * math.pi * D * b * h
    else:
        raise InputError(f"flywheel: shape must be 'rim' or 'disc' (got {shape!r})")
    speed = abs(omega1) * ratio * D / 2
    return FlywheelSize(shape, float(ratio), J, D, b, h, mass, speed, speed <= RIM_SPEED_LIMIT)


@dataclass(frozen=True, slots=True)
class Flywheel:
    """The flywheel by Wittenbauer's energy–mass diagram and by Merkalov's method.

    Attributes
    ----------
    delta, omega : float
        Target δ and ω_avg = |ω1| (rad/s).
    M_d, dT_max : float
        Mд (N·m) and the span max ΔT − min ΔT (J).
    P_c, P_motor : float
        Mean power of resistance Mд·ω (W) and the motor's P_c/η (W; P_c if η is not given).
    KI, KT : float
        Scales of the energy–mass diagram: I_var (kg·m²/mm) and ΔT (J/mm; the KA of the
        work diagrams unless given).
    tan_max, tan_min, psi_max, psi_min : float
        ``tan ψ = (KI/(2·KT))·ω²·(1 ± δ)`` and ψ in degrees.
    b_max, b_min : float
        Intercepts of the upper and lower tangents on the ΔT axis (I_var = 0), J.
    k_mm, l_mm, segment_mm : float
        The points k, l on the drawing and the segment kl, mm.
    tangent_tau : tuple[float, float]
        Crank travel (rad) of the tangent points (upper, lower).
    J_I : float
        The constant reduced inertia needed (Wittenbauer), kg·m².
    I_const : float
        What the crank already has, kg·m² (its link and ``dynamics.crank_inertia``).
    I_rotor : float
        The motor's rotor reduced to the crank, ``J_рот·u²``, kg·m² (0 when not counted);
        ``I_m = max(J_I − I_const − I_rotor, 0)``.
    I_m, I_m_approx, I_m_crude, I_m_graph : float
        The flywheel by Wittenbauer (exact ΔT), by Merkalov (T_I = ΔT − I_var·ω²/2), by
        the crude ``dT_max/(ω²δ) − mean Iп``, and by Wittenbauer on the graphical ΔT
        of the nodes, kg·m².
    difference_pct : float
        ``(I_m_approx − I_m)/I_m·100``.
    size : FlywheelSize
    work : WorkDiagrams
    """

    delta: float
    omega: float
    M_d: float
    dT_max: float
    P_c: float
    P_motor: float
    KI: float
    KT: float
    tan_max: float
    tan_min: float
    psi_max: float
    psi_min: float
    b_max: float
    b_min: float
    k_mm: float
    l_mm: float
    segment_mm: float
    tangent_tau: tuple[float, float]
    J_I: float
    I_const: float
    I_m: float
    I_m_approx: float
    I_m_crude: float
    I_m_graph: float
    difference_pct: float
    size: FlywheelSize
    work: WorkDiagrams
    I_rotor: float = 0.0

    @property
    def needed(self) -> bool:
        """Whether the machine needs a flywheel: ``J_I > I_const + I_rotor``. When the crank
        and the rotor already have the inertia JI, ``I_m`` is 0 and ω stays within δ
        without one (:attr:`I_m_signed` ≤ 0 says by how much)."""
        return self.I_m > 0.0

    @property
    def I_m_signed(self) -> float:
        """``J_I − I_const − I_rotor`` before it is clipped at 0, kg·m² (≤ 0: no flywheel)."""
        return self.J_I - self.I_const - self.I_rotor

    @property
    def tangents_flat(self) -> bool:
        """ψ below 20°: the tangents are nearly parallel and meet far away; the flywheel is
        read from their intercepts k, l on the ΔT axis (method D.3)."""
        return self.psi_max < 20.0


def _wittenbauer(dT: Array, I_var: Array, w: float, delta: float) -> tuple[float, float, int, int]:
    kp, km = 0.5 * w * w * (1 + delta), 0.5 * w * w * (1 - delta)
    up, lo = dT - kp * I_var, dT - km * I_var
    i, j = int(np.argmax(up)), int(np.argmin(lo))
    return float(up[i]), float(lo[j]), i, j


def flywheel(obj: Solved | DynamicModel, delta: float | None = None, *,
             intervals: int = 24, width_mm: float = 100.0, KI: float | None = None,
             KT: float | None = None, shape: str = "rim",
             ratio: float = 1.0, b_ratio: float = 0.2, h_ratio: float = 0.1,
             density: float = STEEL, I_rotor: float = 0.0, length_mm: float = 240.0,
             height_mm: float = 60.0, max_pole_mm: float = MAX_POLE_MM) -> Flywheel:
    """The flywheel moment of inertia for the non-uniformity δ (method B.4.7–10).

    Parameters
    ----------
    obj : Project or DynamicModel
    delta : float, optional
        δ; default the variant's ``dynamics.delta``.
    intervals : int
        Intervals of the graphical integration (:func:`work_diagrams`).
    width_mm : float
        Largest drawn span of I_var on the energy–mass diagram: ``KI = nice_ceil(span/width)``.
    KI : float, optional
        The scale of I_var instead (kg·m²/mm), e.g. chosen so that ψ lies in 20…70° (D.3).
    KT : float, optional
        The scale of ΔT on the energy–mass diagram (J/mm); default the KA of the work
        diagrams (ΔT = Aд + Aс read at their scale). Sheet 3 draws ΔT(φ) and the
        energy–mass diagram at a KT of their own, so that the diagram is tall enough for
        the tangents to stand at readable angles.
    shape, ratio, b_ratio, h_ratio, density
        Of :func:`flywheel_size` (u = ``ratio``: the flywheel on a shaft u times faster).
    I_rotor : float
        Rotating masses of the drive reduced to the crank (the motor's rotor ``J_рот·u²``),
        kg·m²: part of the constant inertia, so the flywheel needs that much less.
    length_mm, height_mm, max_pole_mm : float
        Size of the work diagrams (:func:`work_diagrams`); they fix KA (and KT = KA
        unless ``KT`` is given).

    Raises
    ------
    InputError
        δ missing or not in (0, 1).
    DynamicsError
        The resistance does no work over the cycle.
    """
    m = _model(obj)
    delta = m.delta if delta is None else delta
    if delta is None:
        raise InputError(f"{m.source}: dynamics.delta is missing (the coefficient of speed "
                         "non-uniformity δ, e.g. delta = 0.1)")
    if not (math.isfinite(delta) and 0 < delta < 1):
        raise InputError(f"{m.source}: dynamics.delta must be in (0, 1) (got {delta!r})")
    if not (math.isfinite(width_mm) and width_mm > 0):
        raise InputError(f"flywheel: width_mm must be positive (got {width_mm!r})")
    wd = work_diagrams(m, intervals, length_mm=length_mm, height_mm=height_mm,
                       max_pole_mm=max_pole_mm)
    w = m.omega1
    I_var, I_const = m.inertia.I_var, m.inertia.I_const
    dT = wd.dT
    b_max, b_min, i, j = _wittenbauer(dT, I_var, w, delta)
    J_I = (b_max - b_min) / (w * w * delta)
    T_I = dT - 0.5 * w * w * I_var
    J_approx = float(np.ptp(T_I)) / (w * w * delta)
    span = float(np.ptp(dT))
    crude = span / (w * w * delta) - float(np.mean(m.inertia.I_red[:-1]))
    Ivn = np.interp(wd.node_tau, m.tau, I_var)
    bg, lg, _, _ = _wittenbauer(wd.dT_graph, Ivn, w, delta)
    J_graph = (bg - lg) / (w * w * delta)
    if KT is None:
        KT = wd.KA
    elif not (math.isfinite(KT) and KT > 0):
        raise InputError(f"flywheel: KT must be positive (got {KT!r})")
    span_I = float(np.ptp(np.append(I_var, 0.0)))
    if KI is None:
        KI = nice_ceil(span_I / width_mm) if span_I > 0 else 1.0
    elif not (math.isfinite(KI) and KI > 0):
        raise InputError(f"flywheel: KI must be positive (got {KI!r})")
    tmax = KI / (2 * KT) * w * w * (1 + delta)
    tmin = KI / (2 * KT) * w * w * (1 - delta)
    if not (math.isfinite(I_rotor) and I_rotor >= 0):
        raise InputError(f"flywheel: I_rotor must be ≥ 0 (got {I_rotor!r})")
    I_have = I_const + I_rotor
    I_m = max(J_I - I_have, 0.0)
    I_approx = max(J_approx - I_have, 0.0)
    diff = (I_approx - I_m) / I_m * 100 if I_m > 0 else 0.0
    P_c = wd.M_d * w
    eta = m.efficiency or 1.0
    out = Flywheel(delta, w, wd.M_d, span, P_c, P_c / eta, KI, KT, tmax, tmin,
                   math.degrees(math.atan(tmax)), math.degrees(math.atan(tmin)), b_max, b_min,
                   b_max / KT, b_min / KT, (b_max - b_min) / KT,
                   (float(m.tau[i]), float(m.tau[j])), J_I, I_const, I_m, I_approx,
                   max(crude - I_rotor, 0.0), max(J_graph - I_have, 0.0), diff,
                   flywheel_size(I_m, w, shape=shape, ratio=ratio, b_ratio=b_ratio,
                                 h_ratio=h_ratio, density=density), wd, float(I_rotor))
    _check_finite(m.source, out)
    return out


def _check_finite(source: str, obj) -> None:
    for name in type(obj).__slots__:
        v = getattr(obj, name)
        if isinstance(v, float) and not math.isfinite(v):
            raise DynamicsError(f"{source}: the dynamics produced a non-finite {name}")


__all__ = ["Flywheel", "FlywheelSize", "flywheel", "flywheel_size"]
