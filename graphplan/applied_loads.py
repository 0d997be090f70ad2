"""Loads of the kinetostatic (force) analysis at every position, vectorised (method B.3, C.6).

Every load is an array over the N positions of a :class:`~graphplan.kinematics.Kinematics`
(forces ``(N, 2)``, moments ``(N,)``), in SI units, in the variant's axes, moments
counter-clockwise positive (the conventions of :mod:`graphplan.kinetostatics`).

* weight ``G_k = m_k·g`` at the centre of mass S_k (``g`` is ``Mechanism.gravity``);
* inertia force ``Pи_k = −m_k·a_Sk`` at S_k and inertia moment ``Mи_k = −J_Sk·ε_k``
  (d'Alembert); a slider has ε = ε of its guide's carrier, so none on a frame guide;
* technological resistance (F_пс, the seed's ``Q``), only in the working stroke
  (:func:`graphplan.cycle.in_working_stroke`), of size ``f(s)·max`` where ``s`` is the
  travel fraction of the working stroke and ``f`` the variant's diagram
  (:func:`diagram_value`). A force acts at its point along the output's frame guide
  ``u``: ``Q = −w·|Q|·u`` with ``w = output.working`` (±1), i.e. against the slider's
  velocity, which points along ``w·u`` throughout the working stroke; a moment on a
  rocker is ``Mс = −w·|M|``, against ω.

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

from .cycle import Cycle, analyse_cycle, in_working_stroke, output_coordinate, travel_fraction
from .geometry import dot, norm, perp, scale
from .kinematics import Kinematics
from .model import Mechanism, Resistance
from .positions import as_complex

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
            (forces if isinstance(ld, ForceLoad) else moments).setdefault(ld.link, []).append(ld)
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


def diagram_value(diagram, travel) -> Array:
    """Load fraction of a resistance diagram at the travel fractions ``travel``.

    Linear between consecutive ``(travel, load)`` pairs; zero outside the first and
    last travel. At a jump (two pairs with the same travel) and within
    :data:`JUMP_TOL` of it, the larger of the two values (the load is taken as
    acting at the position where it switches on or off).
    """
    s = np.asarray(travel, float)
    out = np.full(s.shape, -np.inf)
    for (s0, f0), (s1, f1) in pairwise(diagram):
        if s1 - s0 <= JUMP_TOL:
            val = np.full(s.shape, max(f0, f1))
            inside = np.abs(s - 0.5 * (s0 + s1)) <= JUMP_TOL + 0.5 * (s1 - s0)
        else:
            val = f0 + (f1 - f0) * (s - s0) / (s1 - s0)
            inside = (s >= s0 - JUMP_TOL) & (s <= s1 + JUMP_TOL)
        out = np.where(inside, np.maximum(out, val), out)
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


def resistance_loads(mech: Mechanism, kin: Kinematics, cycle: Cycle | None = None
                     ) -> tuple[ForceLoad | MomentLoad, ...]:
    """The technological resistances of the variant at every position (module docstring).

    Names: ``"Q"`` for a force, ``"Mс"`` for a moment (numbered ``Q1``, ``Q2`` … when the
    variant lists several of one kind).
    """
    if not mech.resistances:
        return ()
    cycle = cycle or analyse_cycle(mech)
    on = in_working_stroke(mech, cycle, kin.phi)
    travel = output_travel(mech, kin, cycle)
    w = float(mech.output.working)
    out: list[ForceLoad | MomentLoad] = []
    count = {"force": 0, "moment": 0}
    for res in mech.resistances:
        count[res.kind] += 1
    seen = {"force": 0, "moment": 0}
    for res in mech.resistances:
        seen[res.kind] += 1
        base = "Q" if res.kind == "force" else "Mс"
        name = base if count[res.kind] == 1 else f"{base}{seen[res.kind]}"
        size = np.where(on, diagram_value(res.diagram, travel), 0.0) * res.maximum
        if res.kind == "force":
            u = _frame_guide(mech, kin, res)
            out.append(ForceLoad(name, res.link, "resistance", res.point,
                                 kin.pos.points[res.point], scale(u, -w * size)))
        else:
            out.append(MomentLoad(name, res.link, "resistance", -w * size))
    return tuple(out)


def _frame_guide(mech: Mechanism, kin: Kinematics, res: Resistance) -> Array:
    for key, (_, u) in kin.pos.guides.items():
        if key == f"{res.link}/{mech.frame_link}":
            return np.asarray(u, float)
    raise KeyError(f"link {res.link} slides on no frame guide")  # the loader prevents this


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
        From :func:`graphplan.kinematics.solve` or :func:`graphplan.cycle.sweep`.
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
    st = mech.settings.get("kinetostatics", {})
    inertia = bool(st.get("inertia", True)) if inertia is None else inertia
    frac = float(st.get("neglect_below", 0.0)) if neglect_below is None else neglect_below
    shift = bool(st.get("shift_inertia_force", False)) if shift_inertia is None else shift_inertia
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
                moments[ln].append(MomentLoad(f"Mи{ln}", ln, "inertia",
                                              -props.inertia * kin.acc.epsilon[ln]))
    if "resistance" in kinds:
        for ld in resistance_loads(mech, kin, cycle):
            (forces if isinstance(ld, ForceLoad) else moments)[ld.link].append(ld)

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
    """Drop (in place) the loads below ``frac`` of the largest of their group."""
    neglected: dict[str, NDArray[np.bool_]] = {}
    if frac <= 0:
        return neglected
    groups = [(mech.crank.link,), *(d.links for d in mech.dyads)]
    for links in groups:
        sizes = {}
        ell = None  # the group's size, needed only for its couples
        for ln in links:
            for f in forces[ln]:
                sizes[f.name] = np.abs(as_complex(f.vector))
            if moments[ln] and ell is None:
                ell = group_size(mech, kin, links)
            for m in moments[ln]:
                sizes[m.name] = np.abs(m.moment) / ell
        if not sizes:
            continue
        biggest = reduce(np.maximum, sizes.values())
        limit = frac * biggest
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
    return neglected


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


__all__ = ["ForceLoad", "Loads", "MomentLoad", "compute_loads", "diagram_value",
           "group_size", "load_power", "output_travel", "point_velocity",
           "power_balance_moment", "resistance_loads", "shift_inertia_force"]
