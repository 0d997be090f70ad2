"""Exact kinetostatics (force analysis) of every position at once (method B.3, C, D.1).

Conventions, stated once for the force analysis (:mod:`graphplan.forces.loads` uses them too):
SI units (N, N·m, m); vectors in the variant's axes, x right, y up; moments and
couples **counter-clockwise positive**; **R_ij is the force exerted by link i on link
j** (so R_ji = −R_ij); friction is neglected and ω1 is constant (D.1).

Known loads (:class:`graphplan.forces.loads.Loads`: weights, d'Alembert inertia forces and
moments, the technological resistance) make every Assur group statically determinate.
The groups are solved from the last attached back to the crank, each reaction of a
group on an earlier link becoming a known load of that link's group.

**A dyad** (links i, j; three pairs) has 6 unknowns and 6 equations:

* a revolute pair at joint P: the reaction ``R = (R_x, R_y)`` through P (2 unknowns);
* a prismatic pair with guide direction ``u``: the reaction ``N·n`` normal to the guide,
  ``n = k×u``, and the couple ``M_P`` it carries about the slider's reference point X
  (2 unknowns). The normal force's line of action is the line ⟂ u through
  ``X + x·u``, with the offset ``x = M_P/N`` along the guide (undefined where N = 0:
  then the pair transmits a pure couple, or nothing);
* for each link ℓ ∈ {i, j}: ``ΣF = 0`` (2 equations) and ``ΣM_c = 0`` about one point c
  (the mean of the group's pair points; 1 equation), with every reaction entering with
  + on the link it acts on and − on the link that exerts it (the inner pair).

The 6×6 system is solved for all positions at once with :func:`numpy.linalg.solve`
(batched). It is made dimensionless before solving: the moment equations are divided
by the group's size L and the unknown couples are ``M_P/L``, so that every unknown is a
force and the condition number ``κ`` (2-norm, reported per dyad in
:attr:`Forces.conditioning`) grows like 1/sin of the angle between the two closing
lines of the force plan (method D.3: RRR Rⁿ12 ∥ AB against Rⁿ43 ∥ CB; RRP Rⁿ12 against
the guide's normal; PRP, RPP the two guides). A pose with ``κ > COND_LIMIT`` raises
:class:`~graphplan.errors.SingularPoseError`; otherwise the relative error of the
reactions is bounded, to first order, by ``6·ε·Σκ`` over the groups solved so far
(:attr:`Forces.error_bound`, ε the machine epsilon). The kinematics already refuses a
lock-up (|sin| ≤ 1e-9), so the limit is a guard: the examples have κ ≤ 7.2.

Pairs and names (``k_A`` is the link that carries the point A, ``g`` a guide's carrier):

======  =====================================================================
RRR     R_{k_A i} at A, R_ij at B, R_{k_C j} at C
RRP     R_{k_A i} at A, R_ij at B, R_{g j} ⟂ guide (X = B)
RPR     R_{k_A i} at A, R_ij ⟂ slot (X = A), R_{k_C j} at C
PRP     R_{g1 i} ⟂ guide 1 (X = B), R_ij at B, R_{g2 j} ⟂ guide 2 (X = B)
RPP     R_{k_A i} at A, R_ij ⟂ slot (X = A), R_{g j} ⟂ guide (X = D)
======  =====================================================================

so the press (frame 4) has R12, R23, R43 and R41; the shaper R12, R23, R63, R34, R45,
R65 and R61. A guide carried by a moving link receives −N·n at X and the couple −M_P.

**The crank** (pivot O on the frame) takes the reactions of the groups on it (e.g.
R21 = −R12 at A), its own loads, the frame's reaction R_{0 1} at O and the balancing
moment M_ур (``M_bal``): the moment the motor must apply to the crank so that it turns
at constant ω1,

    R_01 = −Σ F_crank,          M_ур = −Σ M_O(F_crank) − Σ M_crank,

which equals ``R21·h21`` of the method with its sign. By virtual power (the independent
check of the tests, Zhukovsky's lever) ``M_ур·ω1 + Σ F·v + Σ M·ω = 0``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import combinations
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import SingularPoseError
from ..geometry import cross, norm
from ..kinematics import Kinematics, as_complex, as_xy, cdiv, slide_key, where
from ..model import Dyad, Mechanism
from .loads import Loads

Array = NDArray[np.float64]

COND_LIMIT = 1e12
"""Above this condition number of a dyad's (dimensionless) 6×6 system the pose is singular."""


@dataclass(frozen=True, slots=True)
class Reaction:
    """The reaction of one kinematic pair at every position: the force of ``by`` on ``on``.

    Attributes
    ----------
    name : str
        ``R{by}{on}``, e.g. ``"R12"`` (``"R10,12"`` when a link number has two digits).
    by, on : str
        Links: the one that exerts the force and the one it acts on.
    pair : str
        ``"R"`` (revolute) or ``"P"`` (prismatic).
    point : str
        The joint (R), or the slider's reference point X (P).
    guide : str | None
        Key ``"j/k"`` of the sliding pair's guide in ``PositionState.guides`` (P only).
    vector : ndarray (N, 2)
        The force, N.
    at : ndarray (N, 2)
        A point of its line of action: the joint (R); ``X + offset·u`` (P, X where the
        offset is undefined).
    normal : ndarray (N,)
        P: the signed normal force N along ``n = k×u`` (vector = N·n); R: |vector|.
    couple : ndarray (N,)
        P: the moment of the pair's action about X, N·m (= N·offset); R: 0.
    offset : ndarray (N,)
        P: the offset of the line of action from X along u, m (0 where undefined); R: 0.
    defined : ndarray (N,) of bool
        P: where the offset is defined (N ≠ 0); R: all true.
    ref : ndarray (N, 2)
        The coordinates of ``point`` (the pair's action on ``on`` is ``vector`` at ref
        plus ``couple``).
    """

    name: str
    by: str
    on: str
    pair: str
    point: str
    guide: str | None
    vector: Array
    at: Array
    normal: Array
    couple: Array
    offset: Array
    defined: NDArray[np.bool_]
    ref: Array

    @property
    def magnitude(self) -> Array:
        """|R|, N."""
        return norm(self.vector)


@dataclass(frozen=True, slots=True)
class Forces:
    """Reactions of every pair and the balancing moment at every position.

    Attributes
    ----------
    phi : ndarray (N,)
    labels : tuple[str, ...]
    reactions : dict[str, Reaction]
        In the order solved: the last dyad's pairs first, the frame's reaction on the
        crank last.
    M_bal : ndarray (N,)
        Balancing moment M_ур on the crank, N·m, CCW positive.
    crank : str
        The crank's link (the frame's reaction on it, at its pivot, is the last reaction).
    systems : dict[str, ndarray (N, 6, 6)]
        Per dyad, the matrix of its dimensionless equilibrium equations.
    loads : Loads
        The loads the analysis was made with.

    Properties ``conditioning`` (per dyad, the 2-norm condition number of its system) and
    ``error_bound`` (first-order bound of the relative round-off error of the reactions
    and M_ур, ``6·ε·Σκ``) are computed from ``systems`` on first use: a singular value
    decomposition of every 6×6 matrix costs more than the whole force analysis.
    """

    phi: Array
    labels: tuple[str, ...]
    reactions: dict[str, Reaction]
    M_bal: Array
    crank: str
    systems: dict[str, Array]
    loads: Loads
    _kappa: dict[str, Array] = field(default_factory=dict, repr=False, compare=False)

    @property
    def conditioning(self) -> dict[str, Array]:
        """Per dyad, the condition number κ (2-norm) of its dimensionless 6×6 system."""
        for name, A in self.systems.items():
            if name not in self._kappa:
                with np.errstate(divide="ignore", invalid="ignore"):
                    self._kappa[name] = np.linalg.cond(A)
        return self._kappa

    @property
    def error_bound(self) -> Array:
        """First-order bound of the relative round-off error of the reactions and M_ур."""
        eps = np.finfo(float).eps
        bound = np.zeros(self.phi.shape[0])
        for kappa in self.conditioning.values():
            bound = bound + 6 * eps * kappa
        return bound

    def vector(self, name: str) -> Array:
        """R_ij by name, also reversed (``"R21"`` gives −R12)."""
        if name in self.reactions:
            return self.reactions[name].vector
        for r in self.reactions.values():
            if name == reaction_name(r.on, r.by):
                return -r.vector
        raise KeyError(name)

    def on_link(self, link: str) -> list[tuple[str, Array, Array, Array]]:
        """The reactions acting on ``link``: (name, force, point of application X, couple)."""
        out = []
        for r in self.reactions.values():
            if r.on == link:
                out.append((r.name, r.vector, r.ref, r.couple))
            elif r.by == link:
                out.append((reaction_name(r.on, r.by), -r.vector, r.ref, -r.couple))
        return out

    def crank_arms(self) -> dict[str, Array]:
        """Arm h (m) about the crank's pivot of each reaction of a group on the crank (h21)."""
        pivot_xy = self.reactions[next(reversed(self.reactions))].ref
        arms = {}
        for r in self.reactions.values():
            if r.by == self.crank:
                m = norm(r.vector)
                arms[reaction_name(r.on, r.by)] = np.where(
                    m > 0, np.abs(cross(r.at - pivot_xy, r.vector)) / np.where(m > 0, m, 1), 0.0)
        return arms

    def as_json(self, k: int) -> dict:
        """Position k: reactions (N, as [x, y] and magnitude), M_bal (N·m), loads, bounds."""
        reac = {}
        for r in self.reactions.values():
            d = {"by": r.by, "on": r.on, "pair": r.pair, "point": r.point,
                 "vector": [float(c) for c in r.vector[k]], "magnitude": float(r.magnitude[k]),
                 "at": [float(c) for c in r.at[k]]}
            if r.pair == "P":
                d.update(guide=r.guide, normal=float(r.normal[k]), couple=float(r.couple[k]),
                         offset_m=float(r.offset[k]) if r.defined[k] else None)
            reac[r.name] = d
        arms = self.crank_arms()
        return {
            "label": self.labels[k],
            "phi_deg": float(np.degrees(self.phi[k]) % 360.0),
            "M_bal": float(self.M_bal[k]),
            "reactions": reac,
            "crank_arms_m": {n: float(h[k]) for n, h in arms.items()},
            "conditioning": {n: float(c[k]) for n, c in self.conditioning.items()},
            "error_bound": float(self.error_bound[k]),
            "loads": self.loads.as_json(k),
        }


def reaction_name(by: str, on: str) -> str:
    return f"R{by}{on}" if len(by) == 1 and len(on) == 1 else f"R{by},{on}"


@dataclass(frozen=True, slots=True)
class _Pair:
    kind: str  # "R" | "P"
    by: str
    on: str
    point: str
    guide: str | None = None

    @property
    def slide_guide(self) -> str:
        """The guide of a sliding pair (every "P" pair has one)."""
        assert self.guide is not None, self
        return self.guide


def dyad_pairs(mech: Mechanism, d: Dyad) -> tuple[_Pair, _Pair, _Pair]:
    """The three pairs of a dyad, each as the force of ``by`` on the dyad's link ``on``."""
    i, j = d.links
    jt = d.joints
    home = mech.home_link
    if d.kind == "RRR":
        return (_Pair("R", home(jt[0]), i, jt[0]), _Pair("R", i, j, jt[1]),
                _Pair("R", home(jt[2]), j, jt[2]))
    if d.kind == "RRP":
        g = d.guides[0].link
        return (_Pair("R", home(jt[0]), i, jt[0]), _Pair("R", i, j, jt[1]),
                _Pair("P", g, j, jt[1], slide_key(j, g)))
    if d.kind == "RPR":
        return (_Pair("R", home(jt[0]), i, jt[0]), _Pair("P", i, j, jt[0], slide_key(i, j)),
                _Pair("R", home(jt[1]), j, jt[1]))
    if d.kind == "PRP":
        g1, g2 = (gd.link for gd in d.guides)
        return (_Pair("P", g1, i, jt[0], slide_key(i, g1)), _Pair("R", i, j, jt[0]),
                _Pair("P", g2, j, jt[0], slide_key(j, g2)))
    g = d.guides[0].link  # RPP
    return (_Pair("R", home(jt[0]), i, jt[0]), _Pair("P", i, j, jt[0], slide_key(i, j)),
            _Pair("P", g, j, jt[1], slide_key(j, g)))


def solve_forces(mech: Mechanism, kin: Kinematics, loads: Loads) -> Forces:
    """Reactions of all pairs and the balancing moment, all positions at once.

    Parameters
    ----------
    mech : Mechanism
    kin : Kinematics
        The positions to analyse (:func:`graphplan.kinematics.cycle.sweep` or
        :func:`graphplan.kinematics.exact.solve`).
    loads : Loads
        From :func:`graphplan.forces.loads.compute_loads` on the same ``kin``.

    Returns
    -------
    Forces

    Raises
    ------
    SingularPoseError
        Where a dyad's equilibrium equations are (nearly) singular, or a result is not
        finite, naming the dyad and the position (label and φ).
    ValueError
        If ``loads`` was computed for other positions.
    """
    n = kin.n
    if loads.phi.shape != kin.phi.shape or not np.array_equal(loads.phi, kin.phi):
        raise ValueError("solve_forces: the loads were computed for other positions")
    P = kin.pos.points
    C: dict = {}  # the points as complex numbers x + iy (k×v = i·v, a×b = Im(conj(a)·b))

    def pc(name: str):
        if name not in C:
            C[name] = as_complex(P[name])
        return C[name]

    ext_f: dict[str, list] = {ln: [] for ln in mech.moving_links}
    ext_m: dict[str, list[Array]] = {ln: [] for ln in mech.moving_links}
    for f in loads.all_forces():  # a load on the frame (not a moving link) changes nothing
        ext_f.get(f.link, []).append((as_complex(f.vector), as_complex(f.at)))
    for m in loads.all_moments():
        ext_m.get(m.link, []).append(m.moment)
    reactions: dict[str, Reaction] = {}
    systems: dict[str, Array] = {}
    solutions: list[Array] = []

    def fail(k: int, what: str, dyad: str) -> SingularPoseError:
        return SingularPoseError(f"{mech.source}: {dyad}: {what} at "
                                 f"{where(kin.phi, k, kin.labels)}")

    zeros, trues = np.zeros(n), np.ones(n, bool)
    for d in reversed(mech.dyads):
        pairs = dyad_pairs(mech, d)
        X = [P[p.point] for p in pairs]
        Xc = [pc(p.point) for p in pairs]
        c = cdiv(Xc[0] + Xc[1] + Xc[2], 3.0)
        L = np.full(n, mech.crank.length)
        for a, b in combinations(Xc, 2):
            L = np.maximum(L, np.abs(a - b))
        # filled entry by entry along the positions (contiguous rows), then viewed as
        # N matrices: LAPACK copies each into its own buffer anyway
        T = np.zeros((6, 6, n))
        R = np.zeros((6, n))
        # per pair, the entries of its columns (the same for both links, but the sign)
        cols: list[tuple[Any, Any, Any]] = []  # e2 is None for a turning pair
        for pr, xj in zip(pairs, Xc, strict=True):
            r = xj - c
            if pr.kind == "R":
                cols.append((r.imag / L, r.real / L, None))
            else:
                nv = 1j * as_complex(kin.pos.guides[pr.slide_guide][1])
                cols.append((nv.real, nv.imag, (np.conj(r) * nv).imag / L))
        for li, link in enumerate(d.links):
            row = 3 * li
            F = sum((v for v, _ in ext_f[link]), 0j)
            M = sum(((np.conj(at - c) * v).imag for v, at in ext_f[link]), zeros)
            M = M + sum(ext_m[link], zeros)
            R[row] = -np.real(F)
            R[row + 1] = -np.imag(F)
            R[row + 2] = -M / L
            for p, (pr, (e0, e1, e2)) in enumerate(zip(pairs, cols, strict=True)):
                s = 1.0 if pr.on == link else -1.0 if pr.by == link else 0.0
                if not s:
                    continue
                col = 2 * p
                if pr.kind == "R":
                    T[row, col] = s
                    T[row + 1, col + 1] = s
                    T[row + 2, col] = -e0 if s > 0 else e0
                    T[row + 2, col + 1] = e1 if s > 0 else -e1
                else:
                    T[row, col] = e0 if s > 0 else -e0
                    T[row + 1, col] = e1 if s > 0 else -e1
                    T[row + 2, col] = e2 if s > 0 else -e2
                    T[row + 2, col + 1] = s
        A = T.transpose(2, 0, 1)
        rhs = R.T
        if not np.isfinite(rhs).all():
            raise fail(int(np.argmin(np.isfinite(rhs).all(axis=1))), "the loads are not finite",
                       d.name)
        _check_singular(A, lambda k, kappa, name=d.name: fail(
            k, f"the force analysis is singular (condition number {kappa:.3g}; "
            "the closing lines of its force plan are parallel)", name))
        x = np.linalg.solve(A, rhs[..., None])[..., 0].astype(float, copy=False)
        systems[d.name] = A
        solutions.append(x)
        big = np.max(np.abs(x), axis=1)
        for p, (pr, xp, xc) in enumerate(zip(pairs, X, Xc, strict=True)):
            a, b = x[:, 2 * p], x[:, 2 * p + 1]
            if pr.kind == "R":
                vec = x[:, 2 * p:2 * p + 2].copy()
                vc = as_complex(vec)
                normal, couple = np.hypot(a, b), zeros
                offset, defined, at = zeros, trues, xp
            else:
                u = as_complex(kin.pos.guides[pr.slide_guide][1])
                vc = (1j * u) * a
                vec, normal, couple = as_xy(vc, n), a, b * L
                defined = np.abs(a) > 1e-12 * big
                offset = np.where(defined, couple / np.where(defined, a, 1.0), 0.0)
                at = as_xy(xc + u * offset, n)
            name = reaction_name(pr.by, pr.on)
            while name in reactions:
                name += "'"
            reactions[name] = Reaction(name, pr.by, pr.on, pr.kind, pr.point, pr.guide, vec, at,
                                       normal, couple.copy(), offset.copy(), defined.copy(), xp)
            if pr.by not in d.links and pr.by != mech.frame_link:
                ext_f[pr.by].append((-vc, xc))
                ext_m[pr.by].append(-couple)

    cr = mech.crank
    pivot = P[cr.pivot]
    pv = pc(cr.pivot)
    F = sum((v for v, _ in ext_f[cr.link]), 0j)
    M = sum(((np.conj(at - pv) * v).imag for v, at in ext_f[cr.link]), zeros)
    M = M + sum(ext_m[cr.link], zeros)
    F = as_xy(F, n)
    name = reaction_name(mech.frame_link, cr.link)
    reactions[name] = Reaction(name, mech.frame_link, cr.link, "R", cr.pivot, None, -F,
                               np.asarray(pivot, float), norm(F), np.zeros(n), np.zeros(n),
                               np.ones(n, bool), np.asarray(pivot, float))
    M_bal = -M
    if not np.isfinite(np.concatenate([*(s.ravel() for s in solutions), F.ravel()])).all():
        for r in reactions.values():
            if not (np.isfinite(r.vector).all() and np.isfinite(r.couple).all()):
                k = int(np.argmin(np.isfinite(r.vector).all(axis=1)))
                raise fail(k, f"reaction {r.name} is not finite", "force analysis")
    return Forces(kin.phi, kin.labels, reactions, M_bal, cr.link, systems, loads)


def _check_singular(A: Array, fail) -> None:
    """Raise ``fail(k, κ)`` at the first position whose system has ``κ > COND_LIMIT``.

    The condition number is bounded without a singular value decomposition:
    ``|det A| = σ1···σ6 ≤ σ1⁵·σ6`` and ``σ1 ≤ ‖A‖_F`` give ``κ = σ1/σ6 ≤ ‖A‖_F⁶/|det A|``,
    so only where that bound passes the limit is κ computed (and the pose refused if
    it really does).
    """
    fro6 = np.einsum("nij,nij->n", A, A) ** 3
    suspect = ~(np.abs(np.linalg.det(A)) * COND_LIMIT > fro6)
    if not suspect.any():
        return
    idx = np.flatnonzero(suspect)
    with np.errstate(divide="ignore", invalid="ignore"):
        kappa = np.linalg.cond(A[idx])
    bad = ~(kappa <= COND_LIMIT)
    if bad.any():
        j = int(np.argmax(bad))
        raise fail(int(idx[j]), float(kappa[j]))


__all__ = ["COND_LIMIT", "Forces", "Reaction", "solve_forces"]
