"""Loads of the kinetostatic (force) analysis at every position, vectorised (method B.3, C.6).

Every load is an array over the N positions of a :class:`~graphplan.kinematics.exact.Kinematics`
(forces ``(N, 2)``, moments ``(N,)``), in SI units, in the variant's axes, moments
counter-clockwise positive (the conventions of :mod:`graphplan.forces.kinetostatics`).

* weight ``G_k = m_k·g`` at the centre of mass S_k (``g`` is ``Mechanism.gravity``);
* inertia force ``Pи_k = −m_k·a_Sk`` at S_k and inertia moment ``Mи_k = −J_Sk·ε_k``
  (d'Alembert); a slider has ε = ε of its guide's carrier, so none on a frame guide;
* the variant's loads (:func:`resistance_loads`, docs/variant-format.md §6.2): a force at a
  point or a couple on any moving link, of value ``f(x)·max − offset`` where ``f`` is the
  diagram of the stroke the position is in (or over the crank angle) and x the travel
  link's position in its stroke, 0 at its start dead centre and 1 at its end one
  (:meth:`~graphplan.kinematics.cycle.LinkTravel.fraction`); the cycle is 2π or 4π of
  crank travel from its origin (:func:`cycle_travel`), two strokes per turn.
  Signs: ``resists`` — against the motion (a slider's along its frame guide: ``−w·d·|Q|·u``
  with ``w`` the travel's working sense and ``d`` = ±1 on the strokes 0 → 1 and 1 → 0; a
  point's: ``−|Q|·v/|v|``; a couple: against ω); ``drives`` — along it; ``diagram`` — the
  value's sign: along ``angle`` or the slider's x, a couple CCW positive. The classical
  technological resistance (the seed's ``Q``) is the default: the output's working stroke,
  resisting, ``Q = −w·|Q|·u``.
* round-off of ε (≤ 1e-12·ω1², at a dead centre where it vanishes) gives no inertia couple.

Settings (``[kinetostatics]`` of the variant, overridable by keywords):

* ``inertia`` (default true): include ``Pи`` and ``Mи``;
* ``neglect_below`` (default 0): at each position, a load whose size is below this
  fraction of the largest load on the same group (the crank, or one Assur dyad) is
  dropped; a moment's size is ``|M|/ℓ``, ℓ the group's size (the largest distance
  between the points of its links, at least the crank length). The dropped loads are
  reported per position in :attr:`Loads.neglected` (the seed's 10 % rule: at the press's
  positions (2), (3) only Q is left);
* ``shift_inertia_force`` (default false): replace ``Pи`` and ``Mи`` of a link by ``Pи``
  alone, moved off S by ``h = Mи/|Pи|`` (:func:`shift_inertia_force`), an equivalent
  force system.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, replace
from functools import reduce
from itertools import combinations, pairwise

import numpy as np
from numpy.typing import NDArray

from ..geometry import dot, norm, perp, scale
from ..kinematics import (
    Cycle,
    Kinematics,
    LinkTravel,
    analyse_cycle,
    as_complex,
    link_coordinate,
    output_coordinate,
    solve_positions,
    travel_fraction,
)
from ..model import Mechanism, Resistance

Array = NDArray[np.float64]

JUMP_TOL = 1e-9
"""Travel fractions this close to a jump of the diagram take the larger of its two values."""


@dataclass(frozen=True, slots=True)
class ForceLoad:
    """A known force on a link at every position.

    Attributes
    ----------
    name : str
        ``"G2"``, ``"Pи3"``, ``"Q"`` …
    link : str
    kind : str
        ``"gravity"``, ``"inertia"``, ``"resistance"`` (or ``"external"`` for user loads).
    point : str | None
        Named point of application; ``None`` for a shifted inertia force.
    at : ndarray (N, 2)
        Point of application, m.
    vector : ndarray (N, 2)
        The force, N (zero where it is neglected or absent).
    """

    name: str
    link: str
    kind: str
    point: str | None
    at: Array
    vector: Array


@dataclass(frozen=True, slots=True)
class MomentLoad:
    """A known couple on a link at every position (N·m, CCW positive)."""

    name: str
    link: str
    kind: str
    moment: Array


@dataclass(frozen=True, slots=True)
class Loads:
    """The known loads of every position, per link.

    Attributes
    ----------
    phi : ndarray (N,)
    labels : tuple[str, ...]
    forces : dict[str, tuple[ForceLoad, ...]]
        Per moving link, its forces.
    moments : dict[str, tuple[MomentLoad, ...]]
        Per moving link, its couples.
    neglected : dict[str, ndarray (N,) of bool]
        Per load name, the positions where the ``neglect_below`` rule dropped it.
    shift : dict[str, ndarray (N,)]
        Per link whose inertia force was shifted, the signed shift h = Mи/|Pи| (m; 0
        where it was not shifted).
    inertia : bool
    neglect_below : float
    """

    phi: Array
    labels: tuple[str, ...]
    forces: dict[str, tuple[ForceLoad, ...]]
    moments: dict[str, tuple[MomentLoad, ...]]
    neglected: dict[str, NDArray[np.bool_]]
    shift: dict[str, Array]
    inertia: bool = True
    neglect_below: float = 0.0

    def all_forces(self) -> Iterator[ForceLoad]:
        """Every force, link by link."""
        for fs in self.forces.values():
            yield from fs

    def all_moments(self) -> Iterator[MomentLoad]:
        """Every couple, link by link."""
        for ms in self.moments.values():
            yield from ms

    def with_loads(self, *extra: ForceLoad | MomentLoad) -> Loads:
        """A copy with more loads (e.g. external forces for tests or variants)."""
        forces = {k: list(v) for k, v in self.forces.items()}
        moments = {k: list(v) for k, v in self.moments.items()}
        for ld in extra:
            if isinstance(ld, ForceLoad):
                forces.setdefault(ld.link, []).append(ld)
            else:
                moments.setdefault(ld.link, []).append(ld)
        return replace(self, forces={k: tuple(v) for k, v in forces.items()},
                       moments={k: tuple(v) for k, v in moments.items()})

    def as_json(self, k: int) -> dict:
        """Position k: every force (N, at m), couple (N·m), the neglected loads, shifts (m)."""
        return {
            "forces": {f.name: {"link": f.link, "kind": f.kind, "point": f.point,
                                "at": [float(c) for c in f.at[k]],
                                "vector": [float(c) for c in f.vector[k]],
                                "magnitude": float(np.hypot(*f.vector[k]))}
                       for f in self.all_forces()},
            "moments": {m.name: {"link": m.link, "kind": m.kind, "moment": float(m.moment[k])}
                        for m in self.all_moments()},
            "neglected": [name for name, mask in self.neglected.items() if mask[k]],
            "shift_m": {ln: float(h[k]) for ln, h in self.shift.items()},
        }


def diagram_value(diagram, travel, signed: bool = False) -> Array:
    """Value of a load diagram at the abscissae ``travel``.

    Linear between consecutive ``(x, value)`` pairs; zero outside the first and last x.
    At a jump (two pairs with the same x) and within :data:`JUMP_TOL` of it, the larger of
    the two values (the load is taken as acting at the position where it switches on or
    off) — for a ``signed`` diagram the one larger in size. Unsigned values are clipped at 0.
    """
    if signed:
        hi = diagram_value(diagram, travel)
        lo = diagram_value(tuple((x, -v) for x, v in diagram), travel)
        return np.where(hi >= lo, hi, -lo)
    s = np.asarray(travel, float)
    out = np.full(s.shape, -np.inf)
    for (s0, f0), (s1, f1) in pairwise(diagram):
        if f0 == 0 and f1 == 0:  # a zero piece: the clip at 0 below gives its value anyway
            continue
        if s1 - s0 <= JUMP_TOL:
            val = max(f0, f1)
            inside = np.abs(s - 0.5 * (s0 + s1)) <= JUMP_TOL + 0.5 * (s1 - s0)
        else:
            val = f0 + (f1 - f0) * (s - s0) / (s1 - s0)
            inside = (s >= s0 - JUMP_TOL) & (s <= s1 + JUMP_TOL)
        np.maximum(out, val, out=out, where=inside)
    return np.where(np.isfinite(out), np.clip(out, 0.0, None), 0.0)


def output_travel(mech: Mechanism, kin: Kinematics, cycle: Cycle) -> Array:
    """Travel of the output from the start of the working stroke, fraction of it, in [0, 1].

    A rocker's angle is taken on the turn nearest the middle of its swing.
    """
    kind, q, _, _ = output_coordinate(mech, kin.pos, kin.vel)
    if kind == "rocker":
        mid = 0.5 * (cycle.q_start + cycle.q_end)
        q = q + 2 * math.pi * np.round((mid - q) / (2 * math.pi))
    return np.clip(travel_fraction(mech, cycle, q), 0.0, 1.0)


#: Crank travel (rad) within which a τ just before a dead centre is taken as at it.
DEAD_CENTRE_TOL = 1e-9


def cycle_travel(mech: Mechanism, cycle: Cycle, phi) -> Array:
    """Crank travel τ (rad) from the cycle's origin in the sense of rotation, in [0, period).

    For a 720° cycle the positions' φ run over two turns (0 … 4π), so φ and φ + 2π are
    different moments of the process with the same kinematics.
    """
    sense = mech.crank.sense
    return np.mod((np.asarray(phi, float) - cycle.origin) * sense, cycle.period)


def _travel_of(res: Resistance, mech: Mechanism, cycle: Cycle) -> LinkTravel:
    return cycle.travels[(res.travel_link or mech.output.link, res.working or mech.output.working)]


def _first_start(res: Resistance, mech: Mechanism, cycle: Cycle, lt: LinkTravel) -> float:
    """τ of the travel link's first start dead centre at or after the load's phase."""
    # cycle_travel of one angle: Python's float % is numpy's np.mod, bit for bit
    t0 = ((float(lt.dead_centres[0]) - cycle.origin) * mech.crank.sense) % cycle.period
    two_pi = 2 * math.pi
    return t0 + two_pi * math.ceil((res.phase - t0) / two_pi - 1e-12)


def stroke_index(res: Resistance, mech: Mechanism, cycle: Cycle, tau) -> NDArray[np.int_]:
    """Which stroke of the cycle (0, 1, … from the load's first start dead centre) each τ is in.

    Even strokes run x 0 → 1 (the start dead centre belongs to them), odd ones 1 → 0.
    """
    lt = _travel_of(res, mech, cycle)
    # τ within DEAD_CENTRE_TOL before a dead centre is at it: a position set on a dead
    # centre belongs to the stroke it starts whatever the round-off of τ and of the dead
    # centres (1e-15 rad on a guide at 135°, which put a V-engine's ВМТ in the stroke before)
    u = np.mod(np.asarray(tau, float) - _first_start(res, mech, cycle, lt) + DEAD_CENTRE_TOL,
               cycle.period)
    turn = np.floor(u / (2 * math.pi))
    r = u - 2 * math.pi * turn
    return (2 * turn + (r >= lt.turn)).astype(int)


def load_values(res: Resistance, mech: Mechanism, cycle: Cycle, phi, q_travel=None
                ) -> tuple[Array, Array]:
    """The load's signed value ``value·max − offset`` (0 where no diagram) at crank angles φ,
    and the direction of motion of its stroke (±1 along the travel link's x, 0 for a
    crank-angle diagram).

    ``q_travel``: the travel link's coordinate at φ (needed for a diagram over a stroke).
    """
    tau = cycle_travel(mech, cycle, phi)
    if res.over == "crank":
        x = np.mod(tau - res.phase, cycle.period)
        val = diagram_value(res.strokes[0], x, signed=True)
        return val * res.maximum - res.offset, np.zeros_like(tau)
    lt = _travel_of(res, mech, cycle)
    k = stroke_index(res, mech, cycle, tau)
    x = lt.fraction(q_travel)
    signed = res.sense == "diagram"
    loaded = [(m, d) for m, d in enumerate(res.stroke_diagrams(round(cycle.period / math.pi)))
              if d is not None]
    if len(loaded) == 1:  # one loaded stroke (the classical case): no merging of strokes
        m, d = loaded[0]
        size = np.where(k == m, diagram_value(d, x, signed=signed) * res.maximum - res.offset,
                        0.0)
        return size, np.where(k % 2 == 0, 1.0, -1.0)
    val = np.zeros_like(tau)
    on = np.zeros(tau.shape, bool)
    for m, d in loaded:
        sel = k == m
        val = np.where(sel, diagram_value(d, x, signed=signed), val)
        on |= sel
    size = np.where(on, val * res.maximum - res.offset, 0.0)
    return size, np.where(k % 2 == 0, 1.0, -1.0)


def resistance_loads(mech: Mechanism, kin: Kinematics, cycle: Cycle | None = None
                     ) -> tuple[ForceLoad | MomentLoad, ...]:
    """The variant's loads at every position (module docstring, docs/variant-format.md §6.2).

    Names: the load's ``name``, else ``"Q"`` for a force, ``"Mс"`` for a moment (numbered
    ``Q1``, ``Q2`` … when the variant lists several of one kind).

    Directions. ``sense = "resists"`` (``"drives"``): a force on a slider acts along its
    frame guide against (along) the motion of its stroke, a force elsewhere against (along)
    its point's velocity, a moment against (along) the link's ω. ``"diagram"``: the
    value's sign gives it — a force along ``angle``, or along the direction in which its
    slider's x grows; a moment CCW positive.
    """
    if not mech.resistances:
        return ()
    cycle = cycle or analyse_cycle(mech)
    out: list[ForceLoad | MomentLoad] = []
    for res, name in zip(mech.resistances, resistance_names(mech), strict=True):
        q_tr = None
        tl = res.travel_link or mech.output.link
        if res.over == "stroke":
            q_tr = link_coordinate(mech, tl, kin.pos, kin.vel)[1]
        size, dirn = load_values(res, mech, cycle, kin.phi, q_tr)
        kind = "resistance" if res.sense == "resists" else "external"
        s = -1.0 if res.sense == "resists" else 1.0
        w = float(res.working or mech.output.working)
        own = res.over == "stroke" and tl == res.link
        if res.kind == "force":
            assert res.point is not None  # a force has its point (the loader requires it)
            at = kin.pos.points[res.point]
            u = _frame_guide(mech, kin, res.link)
            if res.sense == "diagram":
                if res.angle is not None:
                    e = np.broadcast_to([math.cos(res.angle), math.sin(res.angle)], at.shape)
                else:  # the loader asks for an angle off a frame guide
                    assert u is not None
                    e = scale(u, w if own else 1.0)
                vec = scale(e, size)
            elif u is not None:  # along the guide, with or against the motion
                motion = w * dirn if own else np.sign(kin.vel.sliding[_guide_key(mech, res.link)])
                vec = scale(u, s * motion * size)
            else:  # against (along) the velocity of its point
                v = point_velocity(mech, kin, res.link, at)
                sp = norm(v)
                vec = scale(v, s * size / np.where(sp > 0, sp, 1.0))
            out.append(ForceLoad(name, res.link, kind, res.point, at, vec))
        else:
            if res.sense == "diagram":
                mom = size
            else:
                motion = w * dirn if own else np.sign(kin.vel.omega[res.link])
                mom = s * motion * size
            out.append(MomentLoad(name, res.link, kind, np.asarray(mom, float)))
    return tuple(out)


def resistance_names(mech: Mechanism) -> tuple[str, ...]:
    """The name of each of the variant's loads: its ``name``, else ``"Q"`` for a force and
    ``"Mс"`` for a moment (``Q1``, ``Q2`` … when the variant lists several of one kind)."""
    count = {"force": 0, "moment": 0}
    for res in mech.resistances:
        count[res.kind] += res.name is None
    seen = {"force": 0, "moment": 0}
    names = []
    for res in mech.resistances:
        if res.name is None:
            seen[res.kind] += 1
            base = "Q" if res.kind == "force" else "Mс"
            names.append(base if count[res.kind] == 1 else f"{base}{seen[res.kind]}")
        else:
            names.append(res.name)
    return tuple(names)


def _guide_key(mech: Mechanism, link: str) -> str:
    return f"{link}/{mech.frame_link}"


def _frame_guide(mech: Mechanism, kin: Kinematics, link: str) -> Array | None:
    """The unit vectors (N, 2) of the frame guide ``link`` slides on (None if none)."""
    g = kin.pos.guides.get(_guide_key(mech, link))
    return None if g is None else np.asarray(g[1], float)


SHAPE_NODES = 6
"""A diagram of at most this many nodes is a *shape* (method.md E.3: rise, plateau, fall,
steps) whose every kink is a feature; a longer one is a tabulated curve (an indicator
diagram), whose kinks are only its sampling: only its jumps are drawing nodes."""


def load_breaks(mech: Mechanism, cycle: Cycle, ends: bool = False,
                every_kink: bool = True, memo: dict | None = None) -> tuple[float, ...]:
    """Crank travel τ (rad, from the cycle's origin, in [0, period)) of every place where a
    load of the variant jumps or kinks: each interior node of its diagrams where the value
    jumps or the slope changes; with ``ends`` also each end of a loaded stroke (the dead
    centres, where a load switches on or off while its point stands still: a kink of Mс)
    and the start of a crank-angle diagram. Exact integrals take all of them as nodes; the
    graphical integration (``every_kink=False``) takes the jumps, and the kinks of the
    diagrams of at most :data:`SHAPE_NODES` nodes. ``memo`` (a dict the caller keeps for
    calls on one mechanism and cycle) holds each node's τ, bisected once for all of them."""
    out: set[float] = set()
    two_pi = 2 * math.pi
    P = cycle.period
    nodes: dict[int, tuple[LinkTravel, list]] = {}  # per travel: (a, b, x, falling) to find
    for res in mech.resistances:
        if res.over == "crank":
            d = res.strokes[0]
            for i in _kinks(d, 0.0, P, every_kink):
                out.add(float((d[i][0] + res.phase) % P))
            if ends or d[0][1] != d[-1][1]:
                out.add(float(res.phase % P))
            continue
        lt = _travel_of(res, mech, cycle)
        t_s = _first_start(res, mech, cycle, lt)
        diags = res.stroke_diagrams(round(P / math.pi))
        for m, d in enumerate(diags):
            if d is None:
                continue
            turn, odd = divmod(m, 2)
            a = t_s + turn * two_pi + (lt.turn if odd else 0.0)
            b = t_s + turn * two_pi + (two_pi if odd else lt.turn)
            if ends:
                out.update((a % P, b % P))
            for i in _kinks(d, 0.0, 1.0, every_kink):
                nodes.setdefault(id(lt), (lt, []))[1].append((a, b, d[i][0], bool(odd)))
    for lt, todo in nodes.values():
        memo_lt = {} if memo is None else memo.setdefault(id(lt), {})
        new = [n for n in dict.fromkeys(todo) if n not in memo_lt]
        if new:
            memo_lt.update(zip(new, _travel_angles(mech, cycle, lt, *zip(*new, strict=True)),
                               strict=True))
        out.update(memo_lt[n] % P for n in todo)
    return tuple(sorted(round(t, 12) for t in out))


def _kinks(d, lo: float, hi: float, every_kink: bool = True) -> list[int]:
    """Indices of the interior nodes of a diagram where it jumps or its slope changes (only
    where it jumps, for a tabulated curve when not ``every_kink``)."""
    every_kink = every_kink or len(d) <= SHAPE_NODES
    out = []
    for i in range(1, len(d) - 1):
        (s0, l0), (s1, l1), (s2, l2) = d[i - 1], d[i], d[i + 1]
        if not lo < s1 < hi:
            continue
        if s1 == s0 or s2 == s1 or (every_kink and not math.isclose(
                (l1 - l0) * (s2 - s1), (l2 - l1) * (s1 - s0), rel_tol=1e-9, abs_tol=1e-12)):
            out.append(i)
    return out


def _travel_angles(mech: Mechanism, cycle: Cycle, lt: LinkTravel, a, b, x, falling
                   ) -> list[float]:
    """τ in [a, b] (one stroke of the travel link) where its x reaches ``x``, for each
    (a, b, x, falling): all bisected together, one assembly of every midpoint per step
    (each τ the same number as bisected alone: the arithmetic is elementwise, and a
    rocker's angle is taken as solved, not unwrapped across the different strokes)."""
    sense = mech.crank.sense
    lo, hi = np.array(a, float), np.array(b, float)
    x, falling = np.array(x, float), np.array(falling, bool)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        pos = solve_positions(mech, cycle.origin + sense * mid)
        q = (pos.theta[lt.link] if lt.kind == "rocker"
             else link_coordinate(mech, lt.link, pos)[1])
        up = (lt.fraction(q) < x) != falling
        lo2, hi2 = np.where(up, mid, lo), np.where(up, hi, mid)
        if np.array_equal(lo2, lo) and np.array_equal(hi2, hi):
            break  # every [lo, hi] at its floating-point limit: the next steps change nothing
        lo, hi = lo2, hi2
    return [float(t) for t in 0.5 * (lo + hi)]


def shift_inertia_force(vector, moment, centre, max_arm: float = math.inf):
    """Replace an inertia force and couple by the force alone, shifted (method B.3, C.6).

    The force ``Pи`` at S plus the couple ``Mи`` equal ``Pи`` acting at
    ``T = S + (Mи/|Pи|²)·(Pи_y, −Pи_x)``: T lies on the normal to Pи through S at the
    distance ``|h|``, ``h = Mи/|Pи|``, on the side that gives Pи the moment
    ``(T − S)×Pи = Mи`` about S. The shifted line of action is the line through T
    along Pи.

    Parameters
    ----------
    vector : array (N, 2)
        Pи, N.
    moment : array (N,)
        Mи, N·m (CCW positive).
    centre : array (N, 2)
        S, m.
    max_arm : float
        Do not shift where |h| would exceed this (m).

    Returns
    -------
    h : ndarray (N,)
        Signed shift Mи/|Pи|, m (0 where not shifted).
    at : ndarray (N, 2)
        T (S where not shifted).
    ok : ndarray (N,) of bool
        Where the shift was made (|Pи| > 0 and |h| ≤ max_arm); elsewhere keep the couple.
    """
    P = np.asarray(vector, float)
    M = np.asarray(moment, float)
    S = np.asarray(centre, float)
    mag = norm(P)
    ok = (mag > 0) & (np.abs(M) <= max_arm * mag)
    safe = np.where(ok, mag, 1.0)
    h = np.where(ok, M / safe, 0.0)
    at = S + scale(np.stack((P[..., 1], -P[..., 0]), axis=-1), np.where(ok, M / safe**2, 0.0))
    return h, at, ok


def compute_loads(mech: Mechanism, kin: Kinematics, cycle: Cycle | None = None, *,
                  inertia: bool | None = None, neglect_below: float | None = None,
                  shift_inertia: bool | None = None,
                  kinds: tuple[str, ...] = ("gravity", "inertia", "resistance")) -> Loads:
    """The loads of every position (see the module docstring).

    Parameters
    ----------
    mech : Mechanism
    kin : Kinematics
        From :func:`graphplan.kinematics.exact.solve` or :func:`graphplan.kinematics.cycle.sweep`.
    cycle : Cycle, optional
        Needed for the resistance; computed with :func:`analyse_cycle` when omitted
        and the variant has one.
    inertia, neglect_below, shift_inertia : optional
        Override ``[kinetostatics]`` ``inertia``, ``neglect_below``,
        ``shift_inertia_force`` (defaults true, 0, false).
    kinds : tuple of str
        Which kinds of load to build at all (e.g. ``("resistance",)`` for a load set
        with only Q).

    Returns
    -------
    Loads
    """
    st = mech.kinetostatics
    inertia = st.inertia if inertia is None else inertia
    frac = st.neglect_below if neglect_below is None else neglect_below
    shift = st.shift_inertia_force if shift_inertia is None else shift_inertia
    P, V = kin.pos.points, kin.acc.points
    gvec = np.asarray(mech.gravity, float)
    forces: dict[str, list[ForceLoad]] = {ln: [] for ln in mech.moving_links}
    moments: dict[str, list[MomentLoad]] = {ln: [] for ln in mech.moving_links}
    for ln in mech.moving_links:
        props = mech.links.get(ln)
        if props is None or props.centre is None:
            continue
        S = P[props.centre]
        if "gravity" in kinds and props.mass > 0 and gvec.any():
            forces[ln].append(ForceLoad(f"G{ln}", ln, "gravity", props.centre, S,
                                        np.broadcast_to(props.mass * gvec, S.shape).copy()))
        if "inertia" in kinds and inertia:
            if props.mass > 0:
                forces[ln].append(ForceLoad(f"Pи{ln}", ln, "inertia", props.centre, S,
                                            -props.mass * V[props.centre]))
            if props.inertia > 0:
                eps = kin.acc.epsilon[ln]
                # ε of round-off (1e-16 at a dead centre, where it vanishes) is 0: no couple
                eps = np.where(np.abs(eps) <= 1e-12 * mech.crank.omega**2, 0.0, eps)
                moments[ln].append(MomentLoad(f"Mи{ln}", ln, "inertia", -props.inertia * eps))
    if "resistance" in kinds:
        for ld in resistance_loads(mech, kin, cycle):
            if isinstance(ld, ForceLoad):
                forces[ld.link].append(ld)
            else:
                moments[ld.link].append(ld)

    neglected = _neglect(mech, kin, forces, moments, frac)
    shifts: dict[str, Array] = {}
    if shift:
        for ln in mech.moving_links:
            pf = [f for f in forces[ln] if f.name == f"Pи{ln}"]
            pm = [m for m in moments[ln] if m.name == f"Mи{ln}"]
            if not (pf and pm):
                continue
            f, m = pf[0], pm[0]
            h, at, ok = shift_inertia_force(f.vector, m.moment, f.at, 1e3 * mech.crank.length)
            forces[ln][forces[ln].index(f)] = replace(f, point=None if ok.any() else f.point,
                                                      at=at)
            moments[ln][moments[ln].index(m)] = replace(m, moment=np.where(ok, 0.0, m.moment))
            shifts[ln] = h
    return Loads(kin.phi, kin.labels, {k: tuple(v) for k, v in forces.items()},
                 {k: tuple(v) for k, v in moments.items()}, neglected, shifts, inertia, frac)


def group_size(mech: Mechanism, kin: Kinematics, links) -> Array:
    """ℓ of a group: the largest distance between the points of its links, ≥ l_OA (m)."""
    names = dict.fromkeys(p for ln in links for p in mech.points_of(ln))  # each point once
    pts = [as_complex(kin.pos.points[p]) for p in names]
    size = np.full(kin.n, mech.crank.length)
    for a, b in combinations(pts, 2):
        size = np.maximum(size, np.abs(a - b))
    return size


def _neglect(mech, kin, forces, moments, frac) -> dict[str, NDArray[np.bool_]]:
    """Drop (in place) the loads below ``frac`` of the largest of their group.

    The sizes of a group's loads are one (k, N) array: its largest per position is one
    reduction and the drops one comparison (the same values as load by load)."""
    neglected: dict[str, NDArray[np.bool_]] = {}
    if frac <= 0:
        return neglected
    groups = [(mech.crank.link,), *(d.links for d in mech.dyads)]
    for links in groups:
        fl = [f for ln in links for f in forces[ln]]
        ml = [m for ln in links for m in moments[ln]]
        if not (fl or ml):
            continue
        names = [f.name for f in fl] + [m.name for m in ml]
        if len(set(names)) < len(names):  # a name twice: the later load's size counts
            _neglect_by_name(mech, kin, links, forces, moments, frac, neglected)
            continue
        rows = []
        if fl:
            rows.append(np.abs(np.stack([as_complex(f.vector) for f in fl])))
        if ml:
            ell = group_size(mech, kin, links)  # the group's size, needed only for couples
            rows.append(np.abs(np.stack([m.moment for m in ml])) / ell)
        sizes = rows[0] if len(rows) == 1 else np.concatenate(rows)
        limit = frac * sizes.max(axis=0)
        drop = (sizes < limit) & (sizes > 0)
        hit = drop.any(axis=1).tolist()
        if not any(hit):
            continue
        kf, km = 0, len(fl)  # rows: the forces link by link, then the couples
        for ln in links:  # link by link, its forces then its couples (the report's order)
            for n, f in enumerate(forces[ln]):
                if hit[kf]:
                    forces[ln][n] = ForceLoad(f.name, f.link, f.kind, f.point, f.at,
                                              np.where(drop[kf][:, None], 0.0, f.vector))
                    neglected[f.name] = drop[kf]
                kf += 1
            for n, m in enumerate(moments[ln]):
                if hit[km]:
                    moments[ln][n] = MomentLoad(m.name, m.link, m.kind,
                                                np.where(drop[km], 0.0, m.moment))
                    neglected[m.name] = drop[km]
                km += 1
    return neglected


def _neglect_by_name(mech, kin, links, forces, moments, frac, neglected) -> None:
    """:func:`_neglect` of one group whose loads repeat a name (sizes kept by name)."""
    sizes = {}
    ell = None
    for ln in links:
        for f in forces[ln]:
            sizes[f.name] = np.abs(as_complex(f.vector))
        if moments[ln] and ell is None:
            ell = group_size(mech, kin, links)
        for m in moments[ln]:
            sizes[m.name] = np.abs(m.moment) / ell
    limit = frac * reduce(np.maximum, sizes.values())
    for ln in links:
        for n, f in enumerate(forces[ln]):
            drop = (sizes[f.name] < limit) & (sizes[f.name] > 0)
            if drop.any():
                forces[ln][n] = replace(f, vector=np.where(drop[:, None], 0.0, f.vector))
                neglected[f.name] = drop
        for n, m in enumerate(moments[ln]):
            drop = (sizes[m.name] < limit) & (sizes[m.name] > 0)
            if drop.any():
                moments[ln][n] = replace(m, moment=np.where(drop, 0.0, m.moment))
                neglected[m.name] = drop


def point_velocity(mech: Mechanism, kin: Kinematics, link: str, at) -> Array:
    """Velocity (N, 2) of the point of ``link`` at ``at``: v_Q + ω·k×(at − Q), Q on the link."""
    if link == mech.frame_link:
        return np.zeros_like(np.asarray(at, float))
    q = mech.points_of(link)[0]
    return kin.vel.points[q] + scale(perp(np.asarray(at, float) - kin.pos.points[q]),
                                     kin.vel.omega[link])


def load_power(mech: Mechanism, kin: Kinematics, loads: Loads) -> Array:
    """Total power of the loads, ``Σ F·v_point + Σ M·ω_link`` (W), per position."""
    total = np.zeros(kin.n)
    for f in loads.all_forces():
        total = total + dot(f.vector, point_velocity(mech, kin, f.link, f.at))
    for m in loads.all_moments():
        total = total + m.moment * kin.vel.omega[m.link]
    return total


def power_balance_moment(mech: Mechanism, kin: Kinematics, loads: Loads) -> Array:
    """Balancing moment by virtual power (Zhukovsky, method C.7): ``−Σ P/ω1`` (N·m, CCW+).

    ``M_ур·ω1 + Σ F·v + Σ M·ω = 0``; reactions do no net work without friction.
    """
    return -load_power(mech, kin, loads) / mech.crank.omega


__all__ = [
    "ForceLoad",
    "Loads",
    "MomentLoad",
    "compute_loads",
    "cycle_travel",
    "diagram_value",
    "group_size",
    "load_breaks",
    "load_power",
    "load_values",
    "output_travel",
    "point_velocity",
    "power_balance_moment",
    "resistance_loads",
    "resistance_names",
    "shift_inertia_force",
    "stroke_index",
]
