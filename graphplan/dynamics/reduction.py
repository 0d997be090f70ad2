"""Dynamics of the machine unit and the flywheel (sheet 3; method B.4, B.5, D.2).

The machine is reduced to the crank (звено приведения): one degree of freedom, the
crank's rotation, carrying the reduced moment of the resisting forces Mс(φ), a constant
driving moment Mд of the motor and the reduced moment of inertia Iп(φ). Every array is
vectorised over a uniform grid of crank angles (``dynamics.grid``, default
:data:`GRID` intervals per turn); the only loop over time is the RK4 stepper of
:func:`simulate`.

Sign conventions (stated once, used everywhere below)
-----------------------------------------------------
* Abscissa: the crank **travel** τ from the first position (``positions.number_from``)
  **in the sense of rotation**, 0…2π; the absolute crank angle is
  ``φ = φ_first + sense·τ`` (sense = ±1 for a CCW / CW crank), ω = |ω1| = dτ/dt > 0.
  Below "dφ" means dτ.
* Moments of the dynamics are positive **in the sense of rotation** (they drive the
  crank). So the reduced moment of the resisting forces ``Mс = ΣP/|ω1|`` (P = Σ F·v +
  Σ M·ω of the weights and the technological resistance) is **negative where it
  resists**; for a CCW crank ``Mс = −Mур`` exactly as in
  :mod:`graphplan.reports.force_tables`, in general ``Mс = −sense·Mур``, with Mур the
  balancing moment of :func:`graphplan.forces.kinetostatics.solve_forces` computed **without
  the inertia forces** (they enter through Iп) and with no load neglected.
* Works: ``Aс(φ) = ∫₀^φ Mс dφ`` (negative), ``Aд(φ) = Mд·φ`` with the constant
  ``Mд = −Aс(2π)/2π > 0`` (equal work over the cycle: steady motion), and the excess
  work ``ΔT(φ) = Aд + Aс`` (= Aд − |Aс|), ΔT(0) = ΔT(2π) = 0.
* Scales are physical value per mm of drawing (:mod:`graphplan.units`).

Governing equations
-------------------
Reduced moment of inertia (ω1 constant in the kinematics, method D.1)::

    Iп(φ) = Σ_i [m_i·v_Si² + I_Si·ω_i²]/ω1² + Iкр,     Iкр = dynamics.crank_inertia
    dIп/dφ = 2·Σ_i [m_i·v_Si·a_Si + I_Si·ω_i·ε_i]/|ω1|³

split into the constant part ``I_const`` (the crank link and ``crank_inertia``) and the
variable part ``I_var(φ)`` of the dyads' links (J_II of the method).

Equation of motion of the crank, energy form (exact) and Lagrange's form::

    T(φ) = (Iп + Iм)·ω²/2 = T0 + ΔT(φ),        ω(φ) = sqrt(2T/(Iп + Iм))
    dω/dt = (Mд + Mс − ω²/2·dIп/dφ)/(Iп + Iм),   dφ/dt = ω

Flywheel by the energy–mass (Wittenbauer) diagram ΔT(I_var): with
``k± = ω_avg²·(1 ± δ)/2`` (``tan ψ = k·KI/KT`` on the drawing) the tangents touch the
curve where ``ΔT − k·I_var`` is largest (upper, k+) and smallest (lower, k−); they cut
the ΔT axis at b+ and b− (segment kl = (b+ − b−)/KT mm) and the constant reduced
inertia that keeps ω within ≈ ω_avg·(1 ± δ/2) is ``J_I = (b+ − b−)/(ω_avg²·δ)``, the
flywheel ``Iм = J_I − I_const``. Merkalov's method: ``T_I = ΔT − I_var·ω_avg²/2``,
``J_I ≈ (max T_I − min T_I)/(ω_avg²·δ)``. When I_var is constant (zero) both are
``(max ΔT − min ΔT)/(ω_avg²·δ)``: then ``ΔT − k·I_var`` differs from ΔT by a constant
and its extremes are those of ΔT, whatever k.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..errors import GraphplanError, InputError, LayoutError
from ..forces import compute_loads, cycle_travel, load_breaks, load_power, solve_forces
from ..kinematics import Cycle, Kinematics, solve
from ..model import Mechanism
from ..units import nice_ceil
from .settings import GRID, STEEL, DynamicsSettings

Array = NDArray[np.float64]

MAX_POLE_MM = 80.0
"""Largest pole distance H of the work diagrams, mm (the pole stays near the drawing)."""
RIM_SPEED_LIMIT = 40.0
"""Largest rim speed ω·D/2 of a steel flywheel, m/s (method B.4.10: 40–50 m/s)."""


class Solved(Protocol):
    """What the dynamics reads of a solved variant (a :class:`graphplan.project.Project`):
    the mechanism, its cycle and the kinematics of its positions."""

    @property
    def mech(self) -> Mechanism: ...

    @property
    def kin(self) -> Kinematics: ...

    @property
    def cycle(self) -> Cycle: ...


class DynamicsError(GraphplanError, ValueError):
    """The dynamics cannot be solved: no work of resistance, or ω would not stay positive."""


# --- the reduced model ---------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class ReducedMoment:
    """Mс(φ) on a uniform grid of one turn and at the variant's positions.

    Attributes
    ----------
    tau : ndarray (G+1,)
        Crank travel 0…2π (rad), uniform, the last point closing the turn.
    phi : ndarray (G+1,)
        Absolute crank angle there, rad.
    M : ndarray (G+1,)
        Mс, N·m, in the sense of rotation (negative where it resists); ``M[-1] = M[0]``.
    labels : tuple[str, ...]
        Labels of the positions.
    pos_tau, pos_M : ndarray (N,)
        Travel (rad, in [0, 2π)) and Mс at the positions.
    omega1 : float
        |ω1|, rad/s.
    sense : float
        +1 for a CCW crank, −1 for a CW one.
    breaks : tuple[float, ...]
        Travel (rad) of the breaks of the resistance diagrams (a jump or a kink of the
        load), where Mс is not smooth: the graphical integration puts a node there.
    A : ndarray (G+1,) or None
        The exact work ``∫₀^τ Mс dτ`` at ``tau`` (J): Gauss–Legendre on every smooth piece,
        the breaks and the ends of the loaded strokes being nodes (None: the trapezoid
        of ``M``, for models given as arrays).
    at : callable or None
        ``at(tau) -> Mс`` at any travel (exact, by virtual power); None for arrays.
    period : float
        The cycle, rad (2π, or 4π for a four-stroke process).
    """

    tau: Array
    phi: Array
    M: Array
    labels: tuple[str, ...]
    pos_tau: Array
    pos_M: Array
    omega1: float
    sense: float
    breaks: tuple[float, ...] = ()
    A: Array | None = None
    at: Callable[[Array], Array] | None = None
    period: float = 2 * math.pi


@dataclass(frozen=True, slots=True)
class ReducedInertia:
    """At a set of positions: Iп = ``I_red`` = I_const + I_var(φ) (kg·m²), dIп/dφ = ``dI``."""

    I_red: Array
    I_var: Array
    dI: Array
    I_const: float


@dataclass(frozen=True, slots=True)
class DynamicModel:
    """The machine reduced to the crank: Mс, Iп on the grid and at the positions.

    ``delta`` and ``efficiency`` are the variant's ``dynamics.delta`` and
    ``dynamics.efficiency`` (None when not given); ``source`` names the variant file.
    """

    moment: ReducedMoment
    inertia: ReducedInertia
    pos_inertia: ReducedInertia
    source: str
    delta: float | None = None
    efficiency: float | None = None

    @property
    def omega1(self) -> float:
        return self.moment.omega1

    @property
    def tau(self) -> Array:
        return self.moment.tau

    @property
    def period(self) -> float:
        """The cycle, rad of crank travel (2π or 4π)."""
        return self.moment.period

    @classmethod
    def from_arrays(cls, tau, M, I_var, dI, I_const: float, omega1: float, *,
                    delta: float | None = None, source: str = "<synthetic>") -> DynamicModel:
        """A model from given arrays on a uniform closed grid (hand-checkable cases, tests)."""
        tau, M = np.asarray(tau, float), np.asarray(M, float)
        I_var, dI = np.broadcast_to(I_var, tau.shape) * 1.0, np.broadcast_to(dI, tau.shape) * 1.0
        inert = ReducedInertia(I_const + I_var, I_var, dI, float(I_const))
        mom = ReducedMoment(tau, tau.copy(), M, (), tau[:0], M[:0], float(abs(omega1)), 1.0,
                            period=float(tau[-1] - tau[0]))
        return cls(mom, inert, ReducedInertia(tau[:0], tau[:0], tau[:0], float(I_const)),
                   source, delta)


def _first(mech: Mechanism, analysis: Solved) -> tuple[float, float]:
    """Absolute angle of the first position (rad) and the sense of rotation (±1)."""
    first = str(mech.positions.number_from)
    labels = analysis.kin.labels
    k = labels.index(first) if first in labels else 0
    return float(analysis.kin.phi[k]), mech.crank.sense


def _grid(mech: Mechanism, grid: int | None) -> int:
    g = DynamicsSettings.of(mech).grid if grid is None else grid
    if isinstance(g, bool) or not isinstance(g, int) or g < 12:
        raise InputError(f"{mech.source}: dynamics.grid must be an integer ≥ 12 (got {g!r})")
    return g


def _resisting_moment(analysis: Solved, kin: Kinematics, neglect_below: float) -> Array:
    """Mс = −sense·Mур without inertia forces, at the positions of ``kin``."""
    mech = analysis.mech
    loads = compute_loads(mech, kin, analysis.cycle, inertia=False, neglect_below=neglect_below)
    sense = mech.crank.sense
    return -sense * solve_forces(mech, kin, loads).M_bal


def _power_moment(analysis: Solved, phi: Array) -> Array:
    """Mс = (Σ F·v + Σ M·ω)/|ω1| of the weights and the variant's loads at crank angles φ
    (virtual power; equal to −sense·Mур without inertia, and cheaper)."""
    mech = analysis.mech
    if len(phi) == 0:
        return np.zeros(0)
    kin = solve(mech, phi)
    loads = compute_loads(mech, kin, analysis.cycle, inertia=False, neglect_below=0.0)
    return load_power(mech, kin, loads) / abs(mech.crank.omega)


GAUSS_NODES, GAUSS_WEIGHTS = np.polynomial.legendre.leggauss(6)
"""Gauss–Legendre rule of each smooth piece: exact for polynomials of degree 11."""


def exact_work(at, tau: Array, breaks) -> Array:
    """``∫₀^τ M dτ`` at every node of ``tau`` (J), ``at(τ)`` giving M.

    Each interval of ``tau`` is split at the ``breaks`` that fall inside it, and each
    piece (where M is smooth) is integrated by the 6-point Gauss–Legendre rule: with the
    0.5° grid the error is far below 10⁻⁹ of the work, a jump or a kink of the load
    being a node and never inside a piece.
    """
    tau = np.asarray(tau, float)
    br = np.asarray([b for b in breaks if tau[0] < b < tau[-1]], float)
    nodes = np.unique(np.concatenate((tau, br)))
    a, b = nodes[:-1], nodes[1:]
    mid, half = 0.5 * (a + b), 0.5 * (b - a)
    pts = (mid[:, None] + half[:, None] * GAUSS_NODES[None, :]).ravel()
    vals = np.asarray(at(pts), float).reshape(len(a), len(GAUSS_NODES))
    pieces = half * (vals @ GAUSS_WEIGHTS)
    cum = np.concatenate(([0.0], np.cumsum(pieces)))
    return cum[np.searchsorted(nodes, tau)]


def reduced_moment(analysis: Solved, grid: int | None = None, *,
                   neglect_below: float = 0.0) -> ReducedMoment:
    """Exact Mс(φ) over one turn (uniform grid of ``grid`` intervals) and at the positions.

    Mс = −sense·Mур of :func:`graphplan.forces.kinetostatics.solve_forces` with the weights and
    the technological resistance only (no inertia forces, nothing neglected unless
    ``neglect_below`` is given), i.e. ``Mс = (Σ F·v + Σ M·ω)/|ω1|`` (virtual power).
    """
    mech = analysis.mech
    g = _grid(mech, grid)
    phi0, sense = _first(mech, analysis)
    period = analysis.cycle.period
    turns = round(period / (2 * math.pi))
    tau = np.linspace(0.0, period, g * turns + 1)
    phi = phi0 + sense * tau
    M = _resisting_moment(analysis, solve(mech, phi[:-1]), neglect_below)
    M = np.append(M, M[0])
    pos_tau = (sense * (analysis.kin.phi - phi0)) % period
    pos_M = _resisting_moment(analysis, analysis.kin, neglect_below)
    every = resistance_breaks(analysis, ends=True)

    solved: dict[bytes, Array] = {}  # Mс at a set of travels, solved once per set

    def at(t):
        t = np.asarray(t, float)
        key = t.tobytes()
        if key not in solved:
            solved[key] = _power_moment(analysis, phi0 + sense * t)
            solved[key].flags.writeable = False
        return solved[key]

    A = exact_work(at, tau, every) if neglect_below == 0.0 else None
    return ReducedMoment(tau, phi, M, analysis.kin.labels, pos_tau, pos_M,
                         abs(mech.crank.omega), sense, resistance_breaks(analysis), A,
                         at if neglect_below == 0.0 else None, period)


def resistance_breaks(analysis: Solved, ends: bool = False) -> tuple[float, ...]:
    """Crank travel (rad, from the first position) of every interior break of the variant's
    load diagrams: the abscissae where a load jumps or its slope changes, in every loaded
    stroke (:func:`graphplan.forces.loads.load_breaks`); with ``ends`` also the ends of
    the loaded strokes (where a load may switch on or off at a dead centre: a kink of Mс)."""
    mech, cycle = analysis.mech, analysis.cycle
    if not mech.resistances:
        return ()
    phi0, _ = _first(mech, analysis)
    shift = float(cycle_travel(mech, cycle, phi0))
    return tuple(sorted({round((t - shift) % cycle.period, 12)
                         for t in load_breaks(mech, cycle, ends=ends, every_kink=ends)}))


def reduced_inertia(mech: Mechanism, kin: Kinematics) -> ReducedInertia:
    """Iп(φ) = Σ(m·vS² + IS·ω²)/ω1² + crank_inertia and dIп/dφ at the positions of ``kin``.

    The crank link and ``dynamics.crank_inertia`` form ``I_const`` (their transmission
    ratio is constant); the dyads' links form ``I_var``.
    """
    w1 = abs(mech.crank.omega)
    I_const = DynamicsSettings.of(mech).crank_inertia
    I_var, dI = np.zeros(kin.n), np.zeros(kin.n)
    crank = np.zeros(kin.n)
    for ln in mech.moving_links:
        p = mech.links.get(ln)
        if p is None:
            continue
        e = p.inertia * kin.vel.omega[ln] ** 2
        de = p.inertia * kin.vel.omega[ln] * kin.acc.epsilon[ln]
        if p.centre is not None and p.mass > 0:
            v, a = kin.vel.points[p.centre], kin.acc.points[p.centre]
            e = e + p.mass * np.einsum("ij,ij->i", v, v)
            de = de + p.mass * np.einsum("ij,ij->i", v, a)
        if ln == mech.crank.link:
            crank = crank + e / w1**2
        else:
            I_var, dI = I_var + e / w1**2, dI + 2 * de / w1**3
    if kin.n:
        I_const += float(np.mean(crank))  # the crank's |vS1|/ω1 and ω/ω1 are constant
    return ReducedInertia(I_const + I_var, I_var, dI, I_const)


def dynamic_model(analysis: Solved, grid: int | None = None, *,
                  neglect_below: float = 0.0) -> DynamicModel:
    """Mс and Iп of a variant on the grid and at its positions (one kinematic sweep each)."""
    mech = analysis.mech
    mom = reduced_moment(analysis, grid, neglect_below=neglect_below)
    inert = reduced_inertia(mech, solve(mech, mom.phi))
    s = DynamicsSettings.of(mech)
    return DynamicModel(mom, inert, reduced_inertia(mech, analysis.kin), mech.source,
                        s.delta, s.efficiency)


def _model(obj: Solved | DynamicModel) -> DynamicModel:
    return obj if isinstance(obj, DynamicModel) else dynamic_model(obj)


# --- work diagrams by graphical integration -------------------------------------------------


@dataclass(frozen=True, slots=True)
class WorkDiagrams:
    """Aс, Aд, ΔT exactly (grid) and by graphical integration (method of chords, nodes).

    Graphical integration (n equal intervals h = 2π/n, nodes τ_i = i·h, and one more node
    at each break of the resistance diagram, as a draftsman splits the interval where the
    load jumps or kinks): on each interval the mean ordinate of the Mс diagram is taken at
    its midpoint, ``y_M`` mm; the ray from the pole P at H mm left of the origin to its
    projection on the ordinate axis has the slope y_M/H; the chord of the Aс diagram
    parallel to it rises ``Δy_A = y_M·Δx/H`` mm over the interval of Δx mm (L/n for the
    equal ones). So ``Aс = y_A·KA`` with ``KA = Kφ·KM·H`` (J/mm), and
    the node values are the midpoint rule, ``Aс_graph − Aс = −h²/24·(M'(φ) − M'(0)) + O(h⁴)``
    where Mс is smooth: second order (the breaks being nodes, also across them).

    Attributes
    ----------
    tau, A_c, A_d, dT : ndarray (G+1,)
        Exact (cumulative trapezoid of Mс on the grid), J.
    M_d : float
        Mд = −Aс(2π)/2π, N·m (exact).
    node_tau, M_mid : ndarray (n+1,), (n,)
        Nodes (rad) and the mean ordinates (midpoint Mс) of the intervals, N·m.
    yM_mm, yA_mm : ndarray (n,), (n+1,)
        Drawn ordinates of the mean Mс and of the Aс chords' nodes, mm.
    A_c_graph, A_d_graph, dT_graph : ndarray (n+1,)
        The graphical Aс, Aд, ΔT at the nodes, J.
    A_c_exact_nodes, dT_exact_nodes : ndarray (n+1,)
        The exact values there.
    M_d_graph : float
        Mд from the graphical Aс(2π).
    length_mm, Kphi, KM, H, KA : float
        Abscissa L (mm), scales (rad/mm, N·m/mm, J/mm) and the pole distance (mm).
    error : float
        ``max|Aс_graph − Aс| / max|Aс|`` at the nodes.
    """

    tau: Array
    A_c: Array
    A_d: Array
    dT: Array
    M_d: float
    node_tau: Array
    M_mid: Array
    yM_mm: Array
    yA_mm: Array
    A_c_graph: Array
    A_d_graph: Array
    dT_graph: Array
    A_c_exact_nodes: Array
    dT_exact_nodes: Array
    M_d_graph: float
    length_mm: float
    Kphi: float
    KM: float
    H: float
    KA: float
    error: float

    @property
    def intervals(self) -> int:
        return len(self.node_tau) - 1


def _cumtrapz(y: Array, x: Array) -> Array:
    return np.concatenate(([0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(x))))


def work_diagrams(obj: Solved | DynamicModel, intervals: int = 24, *,
                  length_mm: float = 240.0, height_mm: float = 60.0,
                  reading_mm: float | None = None) -> WorkDiagrams:
    """Integrate Mс graphically (method of chords) and exactly; Mд, Aд and ΔT.

    Parameters
    ----------
    obj : Project or DynamicModel
    intervals : int
        Equal intervals n of the graphical integration (≥ 4); the default 24 puts a node
        at every main position of an 8- or 12-position cycle.
    length_mm, height_mm : float
        Abscissa L of one turn and the largest drawn span of the Mс and Aс diagrams, mm.
        ``KM = nice_ceil(span Mс/height)``; H is the pole distance that draws the span of
        Aс and Aд together ``height`` mm, rounded down to 5 mm (to 1 mm below 5 mm); where
        H would exceed :data:`MAX_POLE_MM`, KM is made coarser until it does not.
    reading_mm : float, optional
        Drafting precision to which the ordinates y_M and y_A are read; default exact.

    Raises
    ------
    InputError, LayoutError, DynamicsError
    """
    m = _model(obj)
    if isinstance(intervals, bool) or not isinstance(intervals, int) or intervals < 4:
        raise InputError(f"work diagrams: intervals must be an integer ≥ 4 (got {intervals!r})")
    for name, val in (("length_mm", length_mm), ("height_mm", height_mm),
                      ("reading_mm", 1.0 if reading_mm is None else reading_mm)):
        if not (math.isfinite(val) and val > 0):
            raise InputError(f"work diagrams: {name} must be positive (got {val!r})")
    tau, M = m.tau, m.moment.M
    P = m.period
    A_c = _cumtrapz(M, tau) if m.moment.A is None else m.moment.A
    if not abs(A_c[-1]) > 1e-9 * float(_cumtrapz(np.abs(M), tau)[-1]):
        raise DynamicsError(f"{m.source}: the loads do no work over the cycle "
                            f"(A({math.degrees(P):.0f}°) = {A_c[-1]:.6g} J); there is no "
                            "constant moment to find")
    M_d = -A_c[-1] / P
    A_d = M_d * tau
    n = intervals
    h = P / n
    nodes = np.arange(n + 1, dtype=np.float64) * h
    extra = [b for b in m.moment.breaks if np.min(np.abs(nodes - b)) > 1e-3 * h]
    nodes = np.sort(np.concatenate((nodes, extra)))
    widths = np.diff(nodes)
    mids = nodes[:-1] + 0.5 * widths
    M_mid = np.interp(mids, tau, M) if m.moment.at is None else np.asarray(m.moment.at(mids))
    Kphi = P / length_mm
    KM = nice_ceil(float(np.ptp(np.append(M, 0.0))) / height_mm)
    span_A = float(np.ptp(np.concatenate((A_c, A_d, [0.0]))))  # Aс below, Aд above the axis
    ideal = span_A / (Kphi * KM * height_mm)
    if ideal > MAX_POLE_MM:  # the pole would sit far left: a coarser KM brings it in
        KM = nice_ceil(span_A / (Kphi * MAX_POLE_MM * height_mm))
        ideal = span_A / (Kphi * KM * height_mm)
    step = 5.0 if ideal >= 5.0 else 1.0
    H = math.floor(ideal / step + 1e-9) * step
    if not H >= 1.0:
        raise LayoutError(f"{m.source}: the pole distance H of the work diagram would be "
                          f"{ideal:.2f} mm (< 1 mm); lengthen the abscissa")
    KA = Kphi * KM * H

    def read(x):
        return x if reading_mm is None else np.round(x / reading_mm) * reading_mm

    yM = read(M_mid / KM)
    yA = read(np.concatenate(([0.0], np.cumsum(yM * (widths / Kphi) / H))))
    A_c_graph = yA * KA
    M_d_graph = -A_c_graph[-1] / P
    A_d_graph = M_d_graph * nodes
    A_c_ex = np.interp(nodes, tau, A_c)
    err = float(np.max(np.abs(A_c_graph - A_c_ex)) / np.max(np.abs(A_c)))
    return WorkDiagrams(tau, A_c, A_d, A_d + A_c, float(M_d), nodes, M_mid, yM, yA,
                        A_c_graph, A_d_graph, A_d_graph + A_c_graph, A_c_ex,
                        np.interp(nodes, tau, A_d + A_c), float(M_d_graph), float(length_mm),
                        Kphi, KM, H, KA, err)


# --- flywheel -------------------------------------------------------------------------------


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
             height_mm: float = 60.0) -> Flywheel:
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
    length_mm, height_mm : float
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
    wd = work_diagrams(m, intervals, length_mm=length_mm, height_mm=height_mm)
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


# --- simulation -----------------------------------------------------------------------------


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


__all__ = ["GRID", "DynamicModel", "DynamicsError", "Flywheel", "FlywheelSize",
           "ReducedInertia", "ReducedMoment", "Simulation", "WorkDiagrams", "dynamic_model",
           "flywheel", "flywheel_size", "reduced_inertia", "reduced_moment", "simulate",
           "steady_omega", "work_diagrams"]
