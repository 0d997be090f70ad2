"""Kinematic diagrams of the output link and their graphical differentiation (method of chords).

Sheet 1 of the project carries three diagrams of the output link over one crank turn:
displacement s(φ), velocity v(φ) and acceleration a(φ). The draftsman builds s(φ)
from the plan of positions and gets v and a by graphical differentiation; here the
exact curves come from the vectorised solver and the chord construction is redone
from the node ordinates of s only, so the two can be compared.

Sign conventions (said once, used everywhere below)
---------------------------------------------------
* Abscissa: the crank **travel** τ from the first position (position
  ``positions.number_from``) in the sense of rotation, 0…2π (reported in degrees,
  ``phi_deg``); the absolute crank angle is ``φ = phi_first + sense·τ`` and the time
  ``t = τ/|ω1|``.
* Ordinate s: the output coordinate q (:func:`graphplan.kinematics.cycle.output_coordinate`: m
  along the slider's guide, or the rocker angle in rad, CCW) measured from the start
  dead centre toward the working stroke, ``s = w·(q − q_start)`` with ``w = ±1`` the
  variant's ``output.working``; so ``0 ≤ s ≤ H`` (or the swing ψ). Without dead centres
  (a rotating output link) s is measured from the first position.
* ``v = ds/dt = w·q̇`` and ``a = d²s/dt² = w·q̈`` (m/s, m/s² or rad/s, rad/s²).

Scales (physical value per mm of drawing, as in :mod:`graphplan.units`)
-----------------------------------------------------------------------
``Kφ = 2π/L`` rad/mm for the abscissa of length L mm; ``Ks`` from the series of
:func:`graphplan.units.nice_ceil`. Method of chords with the pole P1 at the distance
H1 (mm) to the left of the origin of the v diagram: the ray from P1 parallel to the
chord of the s curve over an interval cuts the ordinate axis at ``y_v = H1·Δy_s/Δx``
(mm), so ``v = y_v·Kv`` with

    Kv = Ks·|ω1| / (Kφ·H1),        Ka = Kv·|ω1| / (Kφ·H2)

(the second with the pole P2 of the a diagram at H2 mm).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..errors import InputError, LayoutError
from ..kinematics import Cycle, output_coordinate, slide_key, solve, solve_positions
from ..model import Mechanism
from ..units import nice_ceil

Array = NDArray[np.float64]

FINE = 721
"""Points of the exact curves over the turn (every 0.5°)."""
MIN_NODES = 12
"""The chord method uses at least this many intervals per turn."""


@dataclass(frozen=True, slots=True)
class KinematicDiagrams:
    """Exact s, v, a of the output link and their differentiation by the method of chords.

    Chord method (n = ``intervals`` equal steps h = 2π/n of crank travel, nodes
    τ_i = i·h, i = 0…n, midpoints m_i = τ_i + h/2, i = 0…n−1):

    * ``v_chords[i] = |ω1|·(s_{i+1} − s_i)/h`` at m_i: the slope of the chord of the s
      curve, i.e. the mean velocity over the interval. Its error is
      ``|ω1|·s'''(m_i)·h²/24 + O(h⁴)``: second order, ~4× smaller when n doubles.
    * ``a_chords[i] = |ω1|·(v_i − v_{i−1})/h`` at τ_i (the midpoint of m_{i−1}, m_i):
      the chord of the graphically obtained v polyline between consecutive points,
      closed periodically (v_{−1} = v_{n−1}, the motion repeats every turn), so
      ``a_chords[0] = a_chords[n]``. Also second order.

    Attributes
    ----------
    output_kind : str
        ``"slider"`` (s in m) or ``"rocker"`` (s in rad).
    omega1 : float
        |ω1|, rad/s.
    phi_first : float
        Absolute crank angle of node 0 (the first position), rad.
    sense : float
        +1 for a CCW crank, −1 for CW: ``φ = phi_first + sense·τ``.
    phi_deg, s, v, a : ndarray
        Crank travel (deg, 0…360, ``FINE`` points) and the exact s, v, a on it.
    node_deg, node_labels, s_nodes : ndarray, tuple[str, ...], ndarray
        Nodes of the method (n + 1, the last at 360°), the position number of nodes
        that are main positions ("" otherwise; the 360° node repeats the first), and s
        read at the nodes.
    mid_deg, v_chords, v_exact_mid : ndarray
        Interval midpoints, the chord velocities and the exact v there.
    a_chords, a_exact_node : ndarray
        The chord accelerations at ``node_deg`` and the exact a there.
    length_mm, height_mm : float
        Abscissa length L for 360° and the largest drawn span of a diagram.
    Kphi, Ks, Kv, Ka : float
        Scales, rad/mm and SI units per mm.
    H1, H2 : float
        Pole distances, mm.
    v_error, a_error : float
        ``max|v_chords − v_exact_mid| / max|v|`` and the same for a: the method's error.
    """

    output_kind: str
    omega1: float
    phi_first: float
    sense: float
    phi_deg: Array
    s: Array
    v: Array
    a: Array
    node_deg: Array
    node_labels: tuple[str, ...]
    s_nodes: Array
    mid_deg: Array
    v_chords: Array
    v_exact_mid: Array
    a_chords: Array
    a_exact_node: Array
    length_mm: float
    height_mm: float
    Kphi: float
    Ks: float
    Kv: float
    Ka: float
    H1: float
    H2: float
    v_error: float
    a_error: float
    output: str = ""  #: the index of s, v, a: the slider's point on its guide (B), or ψ, ω, ε:
    #: the rocker's link (3) — which of two pistons the diagrams show

    @property
    def intervals(self) -> int:
        """Number n of equal intervals of the chord method."""
        return len(self.node_deg) - 1


def output_motion(mech: Mechanism, cycle: Cycle, travel, solve_on=None
                  ) -> tuple[Array, Array, Array]:
    """Exact ``(s, v, a)`` of the output link at crank travels ``travel`` (rad) from position 1.

    ``s = w·(q − q_start)``, ``v = w·q̇``, ``a = w·q̈`` (see the module docstring). For a
    rocker the angle's turn is fixed per value, ``s − 2π·round((s − ψ/2)/2π)``, so s
    lies in [0, ψ] whatever the branch of the solver's unwrapping. ``solve_on(phi)``: the
    project's kinematics of a grid (:meth:`graphplan.project.Project.solve_on`), solved
    here by default.
    """
    travel = np.atleast_1d(np.asarray(travel, float))
    phi0, sense = _first(mech, cycle)
    phi = phi0 + sense * travel
    kin = solve(mech, phi) if solve_on is None else solve_on(phi)
    kind, q, qd, _ = output_coordinate(mech, kin.pos, kin.vel)
    out = mech.output.link
    key = slide_key(out, mech.frame_link)
    qdd = kin.acc.sliding[key] if kind == "slider" else kin.acc.epsilon[out]
    w = float(mech.output.working)
    if cycle.dead_centres:
        s = w * (q - cycle.q_start) + 0.0  # + 0.0: no negative zeros
        if kind == "rocker":
            s = s - 2 * math.pi * np.round((s - 0.5 * cycle.swing) / (2 * math.pi))
    else:  # a rotating output: s from the first position, on the turn nearest to it
        s = w * (q - output_coordinate(mech, solve_positions(mech, [phi0]))[1][0])
        s = s - 2 * math.pi * np.round(s[0] / (2 * math.pi))
    return s, w * np.asarray(qd, float), w * np.asarray(qdd, float)


def diagram_motion(mech: Mechanism, cycle: Cycle, intervals: int, solve_on=None) -> tuple:
    """The exact motion the chord method of ``intervals`` equal intervals reads: ``(s, v, a)``
    on the fine grid, at the nodes and at the intervals' middles (rad from position 1). It
    does not depend on the diagrams' size: :func:`kinematic_diagrams` tried at several sizes
    takes it solved once (``solve_on``: as in :func:`output_motion`)."""
    h = 2 * math.pi / intervals
    nodes = np.arange(intervals + 1) * h
    return (output_motion(mech, cycle, np.linspace(0.0, 2 * math.pi, FINE), solve_on),
            output_motion(mech, cycle, nodes, solve_on),
            output_motion(mech, cycle, nodes[:-1] + 0.5 * h, solve_on))


def kinematic_diagrams(mech: Mechanism, cycle: Cycle, *, intervals: int | None = None,
                       length_mm: float = 240.0, height_mm: float = 50.0,
                       reading_mm: float | None = None,
                       motion: tuple | None = None) -> KinematicDiagrams:
    """Build the diagrams s, v, a and differentiate s by the method of chords.

    Parameters
    ----------
    mech, cycle : Mechanism, Cycle
        The variant and its :func:`graphplan.kinematics.cycle.analyse_cycle`.
    intervals : int, optional
        Equal intervals n of the chord method from the first position. Default: the
        positions' ``count`` if ≥ 12, else its smallest multiple ≥ 12 (8 → 16), so the
        main positions are nodes (extra positions such as "(2)" are not).
    motion : tuple, optional
        :func:`diagram_motion` of these intervals, where solved already.
    length_mm : float
        Abscissa length L of one turn, mm: ``Kφ = 2π/L``.
    height_mm : float
        Largest drawn span (max − min, the φ axis included) of each diagram, mm.
    reading_mm : float, optional
        Drafting precision: when given, every ordinate the draftsman reads (s at the
        nodes, the pole-ray intercepts of v and a) is rounded to it. Default: exact.

    Returns
    -------
    KinematicDiagrams

    Notes
    -----
    ``Ks = nice_ceil(span_s/height)``. The pole distances are chosen so that each
    derivative is drawn about as large as its curve: ``H1* = Ks·|ω1|·height/(Kφ·span_v)``
    would draw the span of v exactly ``height`` mm; H1 is H1* rounded down to a multiple
    of 5 mm (to 1 mm below 5 mm), so v fits. Then ``Kv = Ks·|ω1|/(Kφ·H1)``; H2 and Ka
    likewise from Kv. Kv and Ka follow from the round pole distances, as on a student's
    sheet, so they are not members of the 1, 2, 2.5, 4, 5 series.

    Raises
    ------
    InputError
        Bad ``intervals``, ``length_mm``, ``height_mm`` or ``reading_mm``.
    LayoutError
        The output does not move, or a pole distance would be shorter than 1 mm.
    """
    count = mech.positions.count
    if intervals is None:
        intervals = count * math.ceil(MIN_NODES / count)
    if isinstance(intervals, bool) or not isinstance(intervals, int) or intervals < 4:
        raise InputError(f"chord method: intervals must be an integer ≥ 4 (got {intervals!r})")
    for name, val in (("length_mm", length_mm), ("height_mm", height_mm),
                      ("reading_mm", 1.0 if reading_mm is None else reading_mm)):
        if not (math.isfinite(val) and val > 0):
            raise InputError(f"kinematic diagrams: {name} must be positive (got {val!r})")
    phi0, sense = _first(mech, cycle)
    omega = abs(mech.crank.omega)
    n, h = intervals, 2 * math.pi / intervals
    fine = np.linspace(0.0, 2 * math.pi, FINE)
    nodes = np.arange(n + 1) * h
    mids = nodes[:-1] + 0.5 * h
    (s, v, a), (s_node, _, a_node), (_, v_mid, _) = (
        diagram_motion(mech, cycle, n) if motion is None else motion)

    def span(*arrays):
        x = np.concatenate(arrays)
        return float(max(x.max(), 0.0) - min(x.min(), 0.0))

    span_s, span_v, span_a = span(s, s_node), span(v, v_mid), span(a, a_node)
    if min(span_s, span_v, span_a) <= 1e-12 * max(span_s, 1.0):
        raise LayoutError(f"{mech.source}: the output link {mech.output.link!r} does not move; "
                          "there are no kinematic diagrams to draw")
    Kphi = 2 * math.pi / length_mm
    Ks = nice_ceil(span_s / height_mm)
    H1 = _pole(Ks * omega * height_mm / (Kphi * span_v), mech, "H1")
    Kv = Ks * omega / (Kphi * H1)
    H2 = _pole(Kv * omega * height_mm / (Kphi * span_a), mech, "H2")
    Ka = Kv * omega / (Kphi * H2)

    def read(x, K):
        return x if reading_mm is None else np.round(x / K / reading_mm) * reading_mm * K

    s_read = read(s_node, Ks)
    v_ch = read(omega * np.diff(s_read) / h, Kv)
    a_ch = read(omega * (v_ch - np.roll(v_ch, 1)) / h, Ka)
    a_ch = np.append(a_ch, a_ch[0])
    v_err = float(np.max(np.abs(v_ch - v_mid)) / max(np.abs(v).max(), np.abs(v_mid).max()))
    a_err = float(np.max(np.abs(a_ch - a_node)) / max(np.abs(a).max(), np.abs(a_node).max()))

    # the positions of one turn (a 720° cycle's second turn repeats the first's motion): a
    # node is a main position when it falls on one of them
    per_turn = count * 360 // mech.positions.cycle
    labels = []
    for i in range(n + 1):
        k, r = divmod((i % n) * per_turn, n)
        labels.append(str(mech.positions.number_from + k) if r == 0 else "")
    return KinematicDiagrams(
        output_kind=cycle.output_kind, omega1=omega, phi_first=phi0, sense=sense,
        phi_deg=np.degrees(fine), s=s, v=v, a=a,
        node_deg=np.degrees(nodes), node_labels=tuple(labels), s_nodes=s_read,
        mid_deg=np.degrees(mids), v_chords=v_ch, v_exact_mid=v_mid,
        a_chords=a_ch, a_exact_node=a_node,
        length_mm=float(length_mm), height_mm=float(height_mm),
        Kphi=Kphi, Ks=Ks, Kv=Kv, Ka=Ka, H1=H1, H2=H2, v_error=v_err, a_error=a_err,
        output=_output_index(mech, cycle.output_kind),
    )


def _output_index(mech: Mechanism, kind: str) -> str:
    """The index the diagrams' symbols take: the output link's number for a rocker, the
    point of the slider on its guide (as :func:`graphplan.kinematics.link_coordinate`
    measures s) for a slider."""
    out = mech.output.link
    if kind == "rocker":
        return out
    for d in mech.dyads:
        if out in d.links:
            return d.new_points[0] if d.new_points else d.joints[0]
    return mech.crank.pin


def _first(mech: Mechanism, cycle: Cycle) -> tuple[float, float]:
    """Absolute crank angle of the first position (rad) and the sense of rotation (±1)."""
    first = str(mech.positions.number_from)
    k = cycle.labels.index(first) if first in cycle.labels else 0
    return float(cycle.phi[k]), mech.crank.sense


def _pole(ideal: float, mech: Mechanism, name: str) -> float:
    """A pole distance: ``ideal`` mm rounded down to 5 mm (to 1 mm below 5 mm)."""
    step = 5.0 if ideal >= 5.0 else 1.0
    H = math.floor(ideal / step + 1e-9) * step
    if not H >= 1.0:
        raise LayoutError(f"{mech.source}: the pole distance {name} would be {ideal:.2f} mm "
                          "(< 1 mm); lengthen the abscissa or lower the diagrams")
    return H
