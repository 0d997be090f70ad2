"""The machine reduced to the crank (sheet 3; method B.4, B.5, D.2): Mс(φ), Iп(φ), the model.

This module holds the reduced model (:class:`DynamicModel`) and states the conventions
and equations of the dynamics once; the stages built on it are :mod:`.work` (the work
diagrams by graphical integration), :mod:`.flywheel` (Wittenbauer, Merkalov, the rim)
and :mod:`.simulation` (the steady ω(φ) and the RK4 run).

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

from ..errors import GraphplanError, InputError
from ..forces import compute_loads, cycle_travel, load_breaks, load_power, solve_forces
from ..kinematics import Cycle, Kinematics, first_position_phi, solve
from ..model import Mechanism
from .settings import GRID, DynamicsSettings

Array = NDArray[np.float64]

MAX_POLE_MM = 80.0
"""Largest pole distance H of the work diagrams, mm (the pole stays near the drawing)."""
RIM_SPEED_LIMIT = 40.0
"""Largest rim speed ω·D/2 of a steel flywheel, m/s (method B.4.10: 40–50 m/s)."""


class Solved(Protocol):
    """What the dynamics reads of a solved variant (a :class:`graphplan.project.Project`):
    the mechanism, its cycle, the kinematics of its positions and of any grid."""

    @property
    def mech(self) -> Mechanism: ...

    @property
    def kin(self) -> Kinematics: ...

    @property
    def cycle(self) -> Cycle: ...

    def solve_on(self, phi) -> Kinematics:
        """The exact kinematics at the crank angles ``phi``, solved once per grid."""
        ...


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
    return first_position_phi(mech, analysis.kin), mech.crank.sense


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
    memo: dict = {}  # the nodes' τ, bisected once for both calls
    every = resistance_breaks(analysis, ends=True, memo=memo)

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
                         abs(mech.crank.omega), sense, resistance_breaks(analysis, memo=memo), A,
                         at if neglect_below == 0.0 else None, period)


def resistance_breaks(analysis: Solved, ends: bool = False, memo: dict | None = None
                      ) -> tuple[float, ...]:
    """Crank travel (rad, from the first position) of every interior break of the variant's
    load diagrams: the abscissae where a load jumps or its slope changes, in every loaded
    stroke (:func:`graphplan.forces.loads.load_breaks`); with ``ends`` also the ends of
    the loaded strokes (where a load may switch on or off at a dead centre: a kink of Mс).
    ``memo``: as load_breaks' (one bisection per node for calls on one analysis)."""
    mech, cycle = analysis.mech, analysis.cycle
    if not mech.resistances:
        return ()
    phi0, _ = _first(mech, analysis)
    shift = float(cycle_travel(mech, cycle, phi0))
    return tuple(sorted({round((t - shift) % cycle.period, 12)
                         for t in load_breaks(mech, cycle, ends=ends, every_kink=ends,
                                              memo=memo)}))


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
    inert = reduced_inertia(mech, analysis.solve_on(mom.phi))  # sheet 1's diagrams' grid too
    s = DynamicsSettings.of(mech)
    return DynamicModel(mom, inert, reduced_inertia(mech, analysis.kin), mech.source,
                        s.delta, s.efficiency)


def _model(obj: Solved | DynamicModel) -> DynamicModel:
    return obj if isinstance(obj, DynamicModel) else dynamic_model(obj)


__all__ = ["GRID", "MAX_POLE_MM", "RIM_SPEED_LIMIT", "DynamicModel", "DynamicsError",
           "ReducedInertia", "ReducedMoment", "Solved", "dynamic_model", "exact_work",
           "reduced_inertia", "reduced_moment", "resistance_breaks"]
