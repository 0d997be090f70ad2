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

The 6×6 system is solved for all positions at once in closed form (:func:`_solve_dyad`:
the inner pair eliminated by the normals of the pairs' columns, leaving the 2×2 of the
force plan's two closing lines, by Cramer's rule; its determinant is det A, so the
singularity check needs no second factorisation). It is made dimensionless before
solving: the moment equations are divided by the group's size L and the unknown couples
are ``M_P/L``, so that every unknown is a force and the condition number ``κ`` (2-norm,
reported per dyad in :attr:`Forces.conditioning`) grows like 1/sin of the angle between
the two closing lines of the force plan (method D.3: RRR Rⁿ12 ∥ AB against Rⁿ43 ∥ CB;
RRP Rⁿ12 against the guide's normal; PRP, RPP the two guides).
A pose with ``κ > COND_LIMIT`` raises
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

from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from itertools import combinations

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
        Per dyad, the matrix of its dimensionless equilibrium equations (built on first
        access: the solve does without it).
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
    systems: Mapping[str, Array]
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
    systems = _Systems()
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
        cols = []
        for pr, x in zip(pairs, Xc, strict=True):
            r = x - c
            if pr.kind == "R":
                cols.append(("R", r, None))
            else:
                cols.append(("P", r, 1j * as_complex(kin.pos.guides[pr.slide_guide][1])))
        rhs_f, rhs_m = [], []
        for link in d.links:
            F = sum((v for v, _ in ext_f[link]), 0j)
            M = sum(((np.conj(at - c) * v).imag for v, at in ext_f[link]), zeros)
            M = M + sum(ext_m[link], zeros)
            rhs_f.append(-F)
            rhs_m.append(-M / L)
        if not all(np.isfinite(z).all() for z in (*rhs_f, *rhs_m)):
            rhs = np.stack([np.broadcast_to(z, (n,)) for f, m in zip(rhs_f, rhs_m, strict=True)
                            for z in (np.real(f), np.imag(f), m)], axis=1)
            raise fail(int(np.argmin(np.isfinite(rhs).all(axis=1))),
                       "the loads are not finite", d.name)

        def singular(k, kappa, name=d.name):
            return fail(k, f"the force analysis is singular (condition number {kappa:.3g}; "
                        "the closing lines of its force plan are parallel)", name)

        build = _MatrixOf(pairs, d.links, cols, L, n)
        if _standard_dyad(pairs, d.links):
            x, det, fro2 = _solve_dyad(cols, L, rhs_f, rhs_m, n)
            _check_singular(build, singular, det, fro2)
        else:  # a dyad of another pattern of pairs: the general 6×6 solve
            rhs = np.stack([np.broadcast_to(z, (n,)) for f, m in zip(rhs_f, rhs_m, strict=True)
                            for z in (np.real(f), np.imag(f), m)], axis=1)
            A = build()
            _check_singular(build, singular, np.linalg.det(A), np.einsum("nij,nij->n", A, A))
            x = np.linalg.solve(A, rhs[..., None])[..., 0]
        systems.add(d.name, build)
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


def _check_singular(build, fail, det: Array, fro2: Array) -> None:
    """Raise ``fail(k, κ)`` at the first position whose system has ``κ > COND_LIMIT``.

    The condition number is bounded without a singular value decomposition:
    ``|det A| = σ1···σ6 ≤ σ1⁵·σ6`` and ``σ1 ≤ ‖A‖_F`` give ``κ = σ1/σ6 ≤ ‖A‖_F⁶/|det A|``,
    so only where that bound passes the limit is κ computed (and the pose refused if
    it really does). ``det`` and ``fro2 = ‖A‖_F²`` come from the solve itself
    (:func:`_solve_dyad`); ``build(idx)`` gives the matrices of the positions ``idx``.
    """
    suspect = ~(np.abs(det) * COND_LIMIT > fro2 ** 3)
    if not suspect.any():
        return
    idx = np.flatnonzero(suspect)
    with np.errstate(divide="ignore", invalid="ignore"):
        kappa = np.linalg.cond(build(idx))
    bad = ~(kappa <= COND_LIMIT)
    if bad.any():
        j = int(np.argmax(bad))
        raise fail(int(idx[j]), float(kappa[j]))


def _standard_dyad(pairs, links) -> bool:
    """The pairs of a dyad (i, j) in the pattern :func:`_solve_dyad` solves: the first
    acts on i only, the second is i's on j, the third acts on j only."""
    i, j = links
    p0, p1, p2 = pairs
    return (p0.on == i and p0.by not in links and p1.by == i and p1.on == j
            and p2.on == j and p2.by not in links)


def _cross(col_a, col_b):
    """The 3-vector ``a × b`` of two columns ``(force, moment)`` of the system, as
    ``(force, moment)``: ``(i·(m_a·f_b − m_b·f_a), f_a × f_b)``."""
    (fa, ma), (fb, mb) = col_a, col_b
    return 1j * (ma * fb - mb * fa), (np.conj(fa) * fb).imag


def _dot(u, col):
    """The scalar product of two 3-vectors ``(force, moment)``."""
    (uf, um), (f, m) = u, col
    return (np.conj(uf) * f).real + um * m


def _columns(col, L):
    """A pair's two columns ``(force, moment)`` on the link it acts on (dimensionless):
    a revolute pair's R_x, R_y at r (from the moment centre c; moments over L); a
    prismatic pair's N along the normal n and its couple M/L."""
    kind, r, nv = col
    if kind == "R":
        return (1.0, -(r.imag / L)), (1j, r.real / L)
    return (nv, (np.conj(r) * nv).imag / L), (0.0, 1.0)


def _solve_dyad(cols, L, rhs_f, rhs_m, n: int):
    """A dyad's six equilibrium equations solved in closed form, all positions at once.

    With the unknowns of the pairs x0 (on link i), x1 (of i on j) and x2 (on j), each
    pair's two columns ``(a, b)`` (3-vectors: force, moment/L), the system is::

        A0·x0 − B1·x1 = r_i          (link i: ΣF = 0, ΣM = 0)
                B1·x1 + C2·x2 = r_j  (link j)

    ``v = a0 × b0`` is normal to A0's columns and ``w = a1 × b1`` to B1's, so the sum
    of the two links' equations dotted with v, and link j's dotted with w, leave x2
    alone — the 2×2 of the two closing lines of the force plan::

        [v·C2] x2 = v·(r_i + r_j),    [w·C2] x2 = w·r_j,

    solved by Cramer's rule; then x0 and x1 from ``A0·x0 = r_i + r_j − C2·x2`` and
    ``B1·x1 = r_j − C2·x2`` (a revolute pair's force is the force part itself; a
    prismatic pair's N is its projection on n, its couple what remains of the moment).
    The same elimination applied to det A gives ``det A = det D`` (the Gram determinants
    of A0 and B1 are |v|² and |w|², and they cancel), so the singularity check of
    :func:`_check_singular` costs nothing more; ``‖A‖_F²`` is the sum of the columns'
    squares (B1's twice). Returns ``(x (N, 6), det A, ‖A‖_F²)``.
    """
    c0, c1, c2 = (_columns(c, L) for c in cols)
    v, w = _cross(*c0), _cross(*c1)
    a2, b2 = c2
    d11, d12, d21, d22 = _dot(v, a2), _dot(v, b2), _dot(w, a2), _dot(w, b2)
    sf, sm = rhs_f[0] + rhs_f[1], rhs_m[0] + rhs_m[1]
    g1, g2 = _dot(v, (sf, sm)), _dot(w, (rhs_f[1], rhs_m[1]))
    det = d11 * d22 - d12 * d21
    if np.ndim(det) == 0:
        det = np.full(n, det)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = 1.0 / det
        x2a, x2b = (g1 * d22 - d12 * g2) * inv, (d11 * g2 - d21 * g1) * inv
    tf = a2[0] * x2a + b2[0] * x2b  # C2·x2
    tm = a2[1] * x2a + b2[1] * x2b
    x = np.empty((n, 6))
    for p, (col, cc, yf, ym) in enumerate(((cols[0], c0, sf - tf, sm - tm),
                                           (cols[1], c1, rhs_f[1] - tf, rhs_m[1] - tm))):
        if col[0] == "R":
            x[:, 2 * p:2 * p + 2] = as_xy(yf, n)
        else:
            (nv, ma), _ = cc
            nn = (np.conj(nv) * yf).real
            x[:, 2 * p] = nn
            x[:, 2 * p + 1] = ym - nn * ma
    x[:, 4], x[:, 5] = x2a, x2b
    fro2 = 0.0
    for k, (col, ((_, ma), (_, mb))) in enumerate(zip(cols, (c0, c1, c2), strict=True)):
        sq = 2.0 + ma * ma + (mb * mb if col[0] == "R" else 0.0)
        fro2 = fro2 + (2.0 * sq if k == 1 else sq)
    return x, det, fro2


class _MatrixOf:
    """The (dimensionless) 6×6 matrices of one dyad, built when asked for: the solve
    (:func:`_solve_dyad`) does without them; the condition numbers need them."""

    __slots__ = ("L", "cols", "links", "n", "pairs")

    def __init__(self, pairs, links, cols, L, n):
        self.pairs, self.links, self.cols, self.L, self.n = pairs, links, cols, L, n

    def __call__(self, idx=None) -> Array:
        """The matrices of the positions ``idx`` (all by default), (len, 6, 6)."""
        L = self.L
        T = np.zeros((6, 6, self.n))
        for li, link in enumerate(self.links):
            row = 3 * li
            for p, (pr, (kind, r, nv)) in enumerate(zip(self.pairs, self.cols, strict=True)):
                s = 1.0 if pr.on == link else -1.0 if pr.by == link else 0.0
                if not s:
                    continue
                col = 2 * p
                if kind == "R":
                    T[row, col] = s
                    T[row + 1, col + 1] = s
                    T[row + 2, col] = -s * (r.imag / L)
                    T[row + 2, col + 1] = s * (r.real / L)
                else:
                    T[row, col] = s * nv.real
                    T[row + 1, col] = s * nv.imag
                    T[row + 2, col] = s * ((np.conj(r) * nv).imag / L)
                    T[row + 2, col + 1] = s
        A = T.transpose(2, 0, 1)
        return A if idx is None else A[idx]


class _Systems(Mapping[str, Array]):
    """Per dyad, its matrices ``(N, 6, 6)``, each built on first access."""

    def __init__(self) -> None:
        self._builders: dict[str, _MatrixOf] = {}
        self._built: dict[str, Array] = {}

    def add(self, name: str, build: _MatrixOf) -> None:
        self._builders[name] = build

    def __getitem__(self, name: str) -> Array:
        if name not in self._built:
            self._built[name] = self._builders[name]()
        return self._built[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._builders)

    def __len__(self) -> int:
        return len(self._builders)


__all__ = ["COND_LIMIT", "Forces", "Reaction", "solve_forces"]
