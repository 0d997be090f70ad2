"""The cycle of the output link: dead centres, stroke, and the positions to analyse.

The output coordinate ``q`` is the displacement of the output slider along its
frame guide (m, positive along the guide's direction), or the angle of an output
rocker (rad, CCW). Its extremes over one crank turn are the dead (extreme)
positions: the working stroke runs from the *start* dead centre to the *end* one
in the sense of rotation; with ``output.working = "+"`` q grows on the way, so
the start is the minimum of q and the end its maximum.

The positions are ``count`` equal steps of the crank from the first one, in the
sense of rotation, numbered from ``number_from``, plus the named extra positions;
all sorted by crank travel from the first.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from ..errors import AssemblyError, InputError, SingularPoseError
from ..model import Mechanism
from ..model import analyse as analyse_structure
from .exact import Kinematics, solve
from .positions import solve_positions
from .velocities import LOCKUP_SINE, solve_velocities

Array = NDArray[np.float64]

CHECK_GRID = 3600
"""Crank angles per turn at which the whole cycle is assembled and checked."""


@dataclass(frozen=True, slots=True)
class Cycle:
    """Dead centres, stroke and the list of analysed positions.

    Attributes
    ----------
    output_kind : str
        ``"slider"`` (q in m) or ``"rocker"`` (q in rad).
    dead_centres : tuple[float, float] | tuple[()]
        Crank angles (rad, in [0, 2π)) of the start and the end of the working stroke.
    q_start, q_end : float
        Output coordinate at those dead centres.
    stroke : float
        Travel of the output point between the dead centres, m (chord for a rocker).
    swing : float
        Swing of an output rocker, rad (0 for a slider).
    working_turn : float
        Crank turn of the working stroke, rad (0 when there are no dead centres).
    labels : tuple[str, ...]
    phi : ndarray
        Crank angle of each position, rad.
    min_conditioning : dict[str, tuple[float, float]]
        Per dyad: the smallest |sin| between its equation lines over the turn, and
        the crank angle (rad) where it occurs.
    period : float
        The cycle, rad of crank travel: 2π, or 4π for a four-stroke process
        (``positions.cycle = 720``); the positions' φ lie in [0, period).
    origin : float
        Crank angle (rad) where the cycle starts: the start dead centre, or without dead
        centres the first position. A load's crank-angle diagram and its strokes are
        counted from here in the sense of rotation.
    travels : dict[tuple[str, int], LinkTravel]
        The stroke of every link whose travel is the abscissa of a load diagram, keyed by
        (link, working sense).
    """

    output_kind: str
    dead_centres: tuple[float, ...]
    q_start: float
    q_end: float
    stroke: float
    swing: float
    working_turn: float
    labels: tuple[str, ...]
    phi: Array
    min_conditioning: dict[str, tuple[float, float]]
    period: float = 2 * math.pi
    origin: float = 0.0
    travels: dict = field(default_factory=dict)

    @property
    def time_ratio(self) -> float:
        """Coefficient of change of average speed K = φ_working / φ_idle."""
        if not self.working_turn:
            return 1.0
        return self.working_turn / (2 * math.pi - self.working_turn)


@dataclass(frozen=True, slots=True)
class LinkTravel:
    """The stroke of one link: its dead centres and its coordinate there.

    ``x = (q − q_start)/(q_end − q_start)`` runs from 0 at the start dead centre to 1 at the
    end one; ``working`` (±1) says whether x grows with q. ``turn`` is the crank's travel
    (rad) from the start to the end dead centre in the sense of rotation.
    """

    link: str
    kind: str
    dead_centres: tuple[float, float]
    q_start: float
    q_end: float
    turn: float
    working: int

    def fraction(self, q) -> Array:
        """x of the coordinate q (a rocker's angle taken on the turn nearest its swing)."""
        q = np.asarray(q, float)
        if self.kind == "rocker":
            mid = 0.5 * (self.q_start + self.q_end)
            q = q + 2 * math.pi * np.round((mid - q) / (2 * math.pi))
        return np.clip((q - self.q_start) / (self.q_end - self.q_start), 0.0, 1.0)


def output_coordinate(mech: Mechanism, kin_pos, kin_vel=None):
    """Return ``(kind, q, dq/dt, point)`` of the output link over a sweep."""
    return link_coordinate(mech, mech.output.link, kin_pos, kin_vel)


def link_coordinate(mech: Mechanism, out: str, kin_pos, kin_vel=None):
    """Return ``(kind, q, dq/dt, point)`` of link ``out``: a slider's displacement along its
    frame guide (m) or, for any other link, its angle θ (rad, unwrapped)."""
    for d in mech.dyads:
        if out not in d.links:
            continue
        for key, (G, u) in kin_pos.guides.items():
            slider, carrier = key.split("/")
            if slider == out and carrier == mech.frame_link:
                point = d.new_points[0] if d.new_points else d.joints[0]
                q = np.sum((kin_pos.points[point] - G) * u, axis=-1)
                rate = kin_vel.sliding[key] if kin_vel is not None else None
                return "slider", q, rate, point
        point = d.joints[1] if d.kind == "RRR" else d.joints[0]
        q = np.unwrap(kin_pos.theta[out])
        rate = kin_vel.omega[out] if kin_vel is not None else None
        return "rocker", q, rate, point
    q = np.unwrap(kin_pos.theta[out])
    rate = kin_vel.omega[out] if kin_vel is not None else None
    return "rocker", q, rate, mech.crank.pin


DRAWABLE_SINE = 0.002
"""Smallest |sin| between the two lines of a dyad with a guide (a prismatic pair)
anywhere in the turn that a drawing can show (0.11°): below it the variant is refused at
load, with the reason — guides 0.1° from parallel make strokes of hundreds of metres and
intersections that move metres for a reading's 0.5 mm. (A revolute dyad passing a
change point keeps its marks of ill-conditioning on the plans.)"""


def _travel(phi, phi0, sense):
    """Crank turn from phi0 to phi in the sense of rotation, in [0, 2π)."""
    return np.mod((np.asarray(phi) - phi0) * sense, 2 * math.pi)


def analyse_cycle(mech: Mechanism) -> Cycle:
    """Check the whole turn and find dead centres, stroke and positions.

    Raises
    ------
    AssemblyError, SingularPoseError
        If some dyad cannot be assembled, or locks up, anywhere in the turn.
    InputError
        If the positions refer to dead centres that the output does not have.
    StructureError
        If the mobility is not 1 (e.g. a dyad reuses a link number).
    """
    analyse_structure(mech)  # W = 1 and class-II groups, before any link angle is trusted
    sense = mech.crank.sense
    grid = np.linspace(0.0, 2 * math.pi, CHECK_GRID, endpoint=False)
    try:
        turn = solve(mech, grid)  # assembles, checks lock-ups and finiteness over the turn
    except AssemblyError as exc:
        if isinstance(exc, SingularPoseError):
            raise
        raise type(exc)(_reachable_hint(mech, str(exc))) from None
    pos, vel = turn.pos, turn.vel
    min_cond = {}
    for name, s in vel.conditioning.items():
        k = int(np.argmin(s))
        a0, a1 = grid[k] - 2 * math.pi / CHECK_GRID, grid[k] + 2 * math.pi / CHECK_GRID
        phi_min, s_min = _golden_min(lambda x, name=name: _cond(mech, x, name), a0, a1)
        if s_min <= LOCKUP_SINE:
            raise SingularPoseError(
                f"{mech.source}: dyad {name} passes through a lock-up at "
                f"φ = {math.degrees(phi_min) % 360:.2f}° (the two lines of its vector equation "
                "become parallel)"
            )
        min_cond[name] = (min(s_min, float(s[k])), phi_min if s_min < s[k] else float(grid[k]))
        if min_cond[name][0] < DRAWABLE_SINE and "P" in name.split("(", 1)[0]:
            raise SingularPoseError(
                f"{mech.source}: dyad {name}: its two lines are nearly parallel (smallest "
                f"|sin| = {min_cond[name][0]:.2g} at φ = "
                f"{math.degrees(min_cond[name][1]) % 360:.2f}°, below {DRAWABLE_SINE:g}): no "
                "plan of it can be drawn or read (a stroke of kilometres, a point off any "
                "sheet); check the guides' and slots' angles and the lengths")
    _check_slot_clearance(mech, grid, pos)

    kind, dead, q_start, q_end, stroke, turn = _dead_centres(
        mech, mech.output.link, mech.output.working, grid, pos, vel)
    swing = abs(q_end - q_start) if (kind == "rocker" and dead) else 0.0

    def dead_centre(which: str, path: str) -> float:
        if not dead:
            raise InputError(f"{mech.source}: {path}: the output link {mech.output.link!r} has "
                             "no dead centres; give a crank angle instead")
        return dead[0] if which == "start" else dead[1]

    P = mech.positions
    period = P.period
    first = (dead_centre(P.first, "positions.first") if isinstance(P.first, str)
             else float(P.first))
    step = period / P.count
    phis = [first + sense * k * step for k in range(P.count)]
    labels = [str(P.number_from + k) for k in range(P.count)]
    for n, ex in enumerate(P.extra):
        path = f"positions.extra[{n}]"
        if ex.phi is not None:
            phis.append(ex.phi)
        elif ex.from_dead_centre is not None:
            phis.append(dead_centre(ex.from_dead_centre, f"{path}.from") + sense * ex.turn)
        else:
            dead_centre("start", f"{path}.stroke")
            phis.append(_stroke_angle(mech, dead[0], turn, sense, q_start, q_end, ex.stroke))
        labels.append(ex.label)
    phis_a = np.mod(np.asarray(phis), period)
    order = np.argsort(np.mod((phis_a - first) * sense, period), kind="stable")
    origin = dead[0] if dead else first % (2 * math.pi)
    travels: dict[tuple[str, int], LinkTravel] = {}
    for n, res in enumerate(mech.resistances):
        tl = res.travel_link or mech.output.link
        w = res.working or mech.output.working
        if res.over != "stroke" or (tl, w) in travels:
            continue
        k_, d_, qs, qe, _, t_ = _dead_centres(mech, tl, w, grid, pos, vel)
        if not d_:
            raise InputError(f"{mech.source}: loads[{n}].over: link {tl!r} has no dead "
                             "centres (it turns fully), so its stroke cannot be the abscissa; "
                             "give over = \"crank\" (a diagram over the crank angle)")
        travels[(tl, w)] = LinkTravel(tl, k_, (float(d_[0]), float(d_[1])), qs, qe, t_, w)
    return Cycle(
        output_kind=kind,
        dead_centres=dead,
        q_start=q_start,
        q_end=q_end,
        stroke=stroke,
        swing=swing,
        working_turn=turn,
        labels=tuple(labels[k] for k in order),
        phi=phis_a[order],
        min_conditioning=min_cond,
        period=period,
        origin=float(origin),
        travels=travels,
    )


def _dead_centres(mech: Mechanism, link: str, working: int, grid, pos, vel):
    """Dead centres of ``link`` over the turn: ``(kind, (start, end), q_start, q_end, chord,
    turn)``; ``()`` and zeros when its coordinate never stops."""
    sense = mech.crank.sense
    kind, q, rate, point = link_coordinate(mech, link, pos, vel)
    zero = np.sign(rate) != np.sign(np.roll(rate, -1))
    if not (zero.any() and np.ptp(q) > 1e-12):
        return kind, (), 0.0, 0.0, 0.0, 0.0
    idx = np.nonzero(zero)[0]
    lo = grid[idx]
    hi = lo + 2 * math.pi / CHECK_GRID
    roots = _bisect_rate(mech, lo, hi, link)
    rp = solve_positions(mech, roots)
    _, qr, _, _ = link_coordinate(mech, link, rp)
    if kind == "rocker":  # unwrap a rocker angle consistently with the grid's branch
        qr = qr + 2 * math.pi * np.round((np.interp(roots, grid, q) - qr) / (2 * math.pi))
    k_min, k_max = int(np.argmin(qr)), int(np.argmax(qr))
    ks, ke = (k_min, k_max) if working > 0 else (k_max, k_min)
    dead = (float(roots[ks] % (2 * math.pi)), float(roots[ke] % (2 * math.pi)))
    p_s, p_e = rp.points[point][ks], rp.points[point][ke]
    chord = float(np.hypot(*(p_e - p_s)))
    turn = float(_travel(dead[1], dead[0], sense))
    return kind, dead, float(qr[ks]), float(qr[ke]), chord, turn


def _closing_arcs(mech: Mechanism, n: int = 720) -> list[tuple[float, float]]:
    """The arcs of crank angle (rad, from → to counter-clockwise) where the chain closes:
    every run of a grid of ``n`` angles that assemble, its ends refined by bisection."""
    grid = np.linspace(0.0, 2 * math.pi, n, endpoint=False)

    def closes(x) -> bool:
        try:
            solve_positions(mech, np.atleast_1d(x))
            return True
        except AssemblyError:
            return False

    ok = np.array([closes(x) for x in grid])
    if np.count_nonzero(~ok) < 3 or not ok.any():  # isolated angles (parallel lines): not
        return []  # a question of reach; or it closes nowhere
    start = int(np.argmin(ok))  # a failing angle: every run is whole after it
    step = 2 * math.pi / n

    def edge(inside, outside):
        for _ in range(50):
            mid = 0.5 * (inside + outside)
            inside, outside = (mid, outside) if closes(mid) else (inside, mid)
        return inside

    arcs, run = [], None
    for k in range(n + 1):
        idx = (start + k) % n
        v = bool(ok[idx]) and k < n
        if v and run is None:
            run = k
        elif not v and run is not None:
            a0 = grid[(start + run) % n]
            a1 = a0 + (k - 1 - run) * step
            arcs.append((edge(a0, a0 - step), edge(a1, a1 + step)))
            run = None
    return arcs


def _four_bar_hint(mech: Mechanism) -> str:
    """Grashof's condition in numbers when the crank, one RRR dyad and the frame make a
    four-bar: the crank turns fully only if it is the shortest link and
    ``l_min + l_max ≤ l' + l''``."""
    if len(mech.dyads) != 1 or mech.dyads[0].kind != "RRR":
        return ""
    d = mech.dyads[0]
    a, _, c = d.joints
    if a != mech.crank.pin or c not in mech.frame_points:
        return ""
    o = np.asarray(mech.frame_points[mech.crank.pivot], float)
    frame = float(np.hypot(*(np.asarray(mech.frame_points[c], float) - o)))
    ls = sorted([mech.crank.length, *d.lengths[:2], frame])
    if mech.crank.length > ls[0] + 1e-12:
        four = ", ".join(f"{x:.6g}" for x in (mech.crank.length, *d.lengths[:2], frame))
        return (f" (the crank is not the shortest of the four links crank, coupler, rocker, "
                f"frame: {four} m)")
    return (f" (Grashof: l_min + l_max = {ls[0]:.6g} + {ls[3]:.6g} = {ls[0] + ls[3]:.6g} m "
            f"> {ls[1]:.6g} + {ls[2]:.6g} = {ls[1] + ls[2]:.6g} m)")


def _reachable_hint(mech: Mechanism, error: str) -> str:
    """``error`` (a dyad that cannot be assembled) with why the crank does not turn fully:
    the arcs of crank angles where the chain closes."""
    arcs = _closing_arcs(mech)
    if not arcs:  # it closes nowhere (the first message says why), or only fails at
        return error  # isolated angles (parallel lines): not a question of reach
    if 2 * math.pi - sum(hi - lo for lo, hi in arcs) < math.radians(1.0):
        return error  # gaps of a fraction of a degree: isolated angles, not a reach
    ranges = ", ".join(f"{math.degrees(lo) % 360:.2f}°…{math.degrees(hi) % 360:.2f}° "
                       f"({math.degrees(hi - lo):.1f}°)" for lo, hi in arcs)
    cause = _four_bar_hint(mech)
    return (f"{error}; the crank cannot make a full turn: the chain closes only for φ in "
            f"{ranges}, so link {mech.crank.link} can only rock within that range{cause} — "
            "shorten crank.length or lengthen the dyad's links" if len(arcs) == 1 else
            f"{error}; the crank cannot make a full turn: the chain closes only for φ in "
            f"{ranges}, "
            f"so link {mech.crank.link} can only rock within one of these ranges{cause} — "
            "shorten crank.length or lengthen the dyad's links")


def travel_fraction(mech: Mechanism, cycle: Cycle, q) -> Array:
    """Travel of the output from the start of the working stroke, as a fraction of it."""
    span = cycle.q_end - cycle.q_start
    if span == 0:
        return np.zeros_like(np.asarray(q, float))
    return (np.asarray(q, float) - cycle.q_start) / span


def in_working_stroke(mech: Mechanism, cycle: Cycle, phi) -> NDArray[np.bool_]:
    """True where the crank is between the start and end dead centres (in rotation sense)."""
    if not cycle.dead_centres:
        return np.zeros(np.shape(phi), bool)
    sense = mech.crank.sense
    t = _travel(phi, cycle.dead_centres[0], sense)
    return t < cycle.working_turn


def sweep(mech: Mechanism, cycle: Cycle) -> Kinematics:
    """Kinematics at the cycle's positions, labelled."""
    return solve(mech, cycle.phi, cycle.labels)


def _check_slot_clearance(mech: Mechanism, grid, pos) -> None:
    """An RPR pin must not reach the foot of the slot axis between two grid angles either.

    On the grid, ``√(|CA|² − e²)`` may stay positive while the pin runs through the
    foot (the pivot, for e = 0) between two angles; its minimum is refined by a golden
    section search around the grid's minimum, as for the lock-ups.
    """
    step = 2 * math.pi / CHECK_GRID
    for d in mech.dyads:
        if d.kind != "RPR":
            continue
        a_name, c_name = d.joints
        e = d.offset
        tol = 1e-9 * max(mech.crank.length, abs(e))

        def clearance(x, a_name=a_name, c_name=c_name, e=e):
            try:
                p = solve_positions(mech, np.atleast_1d(x))
            except AssemblyError:
                return np.zeros(1)
            dist = np.hypot(*(p.points[a_name] - p.points[c_name]).T)
            return np.sqrt(np.maximum(dist**2 - e**2, 0.0))

        dist = np.hypot(*(pos.points[a_name] - pos.points[c_name]).T)
        k = int(np.argmin(dist))
        phi_min, c_min = _golden_min(clearance, grid[k] - step, grid[k] + step)
        if c_min <= tol:
            raise AssemblyError(
                f"{mech.source}: dyad {d.name}: the pin {a_name} passes through the foot of the "
                f"slot axis from {c_name} at φ = {math.degrees(phi_min) % 360:.2f}° (the "
                "rocker's angle is undefined there)")


def _cond(mech, x, name):
    pos = solve_positions(mech, np.atleast_1d(x))
    return solve_velocities(mech, pos).conditioning[name]


def _golden_min(f, a, b, iters=60):
    g = (math.sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = float(f(c)[0]), float(f(d)[0])
    for _ in range(iters):
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = float(f(c)[0])
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = float(f(d)[0])
    x = (a + b) / 2
    return x, float(f(x)[0])


def _rate(mech, phi, link=None):
    pos = solve_positions(mech, phi)
    vel = solve_velocities(mech, pos)
    return link_coordinate(mech, link or mech.output.link, pos, vel)[2]


def _bisect_rate(mech, lo, hi, link=None, iters=60):
    """Bisection, vectorised over brackets, for zeros of a link's rate (the output's)."""
    f_lo = _rate(mech, lo, link)
    for _ in range(iters):
        mid = 0.5 * (lo + hi)
        f_mid = _rate(mech, mid, link)
        left = np.sign(f_mid) == np.sign(f_lo)
        lo = np.where(left, mid, lo)
        f_lo = np.where(left, f_mid, f_lo)
        hi = np.where(left, hi, mid)
    return 0.5 * (lo + hi)


def _stroke_angle(mech, phi_start, turn, sense, q_start, q_end, fraction) -> float:
    """Crank angle in the working stroke where the output has travelled ``fraction``."""
    lo, hi = 0.0, turn
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        pos = solve_positions(mech, [phi_start + sense * mid])
        kind, q, _, _ = output_coordinate(mech, pos)
        q = float(q[0])
        if kind == "rocker":  # the same turn of the angle as the start
            q += 2 * math.pi * round((q_start - q) / (2 * math.pi))
        f = (q - q_start) / (q_end - q_start)
        if f < fraction:
            lo = mid
        else:
            hi = mid
    return phi_start + sense * 0.5 * (lo + hi)


def stroke_angle(mech: Mechanism, cycle: Cycle, fraction: float) -> float:
    """Crank angle (rad) in the working stroke where the output has travelled ``fraction``
    (0…1) of it; needs the dead centres."""
    if not cycle.dead_centres:
        raise InputError(f"{mech.source}: the output has no dead centres, so no working stroke")
    sense = mech.crank.sense
    return _stroke_angle(mech, cycle.dead_centres[0], cycle.working_turn, sense,
                         cycle.q_start, cycle.q_end, fraction) % (2 * math.pi)
