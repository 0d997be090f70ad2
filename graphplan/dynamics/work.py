"""Work diagrams by graphical integration (sheet 3; method B.4): Mс(φ) integrated
interval by interval as a draftsman does, Aс, Aд and ΔT read back at their scales.

Sign conventions and equations: :mod:`graphplan.dynamics.reduction`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError, LayoutError
from ..units import nice_ceil
from .reduction import MAX_POLE_MM, DynamicModel, DynamicsError, Solved, _model

Array = NDArray[np.float64]


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
                  reading_mm: float | None = None,
                  max_pole_mm: float = MAX_POLE_MM) -> WorkDiagrams:
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
        Aс and Aд together ``height`` mm, rounded down to 5 mm (to 1 mm below 10 mm); where
        H would exceed ``max_pole_mm`` (:data:`MAX_POLE_MM`, A1's), KM is made coarser
        until it does not.
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
    if ideal > max_pole_mm:  # the pole would sit far left: a coarser KM brings it in
        KM = nice_ceil(span_A / (Kphi * max_pole_mm * height_mm))
        ideal = span_A / (Kphi * KM * height_mm)
    step = 5.0 if ideal >= 10.0 else 1.0  # a short pole (a small sheet) to the mm
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


__all__ = ["WorkDiagrams", "work_diagrams"]
