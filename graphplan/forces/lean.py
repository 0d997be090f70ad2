"""The full cycle, lean: kinematics, loads and kinetostatics compiled once per mechanism.

:func:`~graphplan.kinematics.solve`, :func:`~graphplan.forces.compute_loads` and
:func:`~graphplan.forces.solve_forces` build the general objects every consumer reads
(plans, tables, the JSON report): per point (N, 2) arrays, a :class:`Reaction` with its
line of action, offsets and flags, the loads with their neglect masks. For a sweep of
many positions — a simulation, a fine curve, the benchmark's N sweep — most of that is
not read, and at a course project's 36 positions numpy's fixed cost per call, not the
arithmetic, is the time. :class:`FullCycle` does the same work in fewer calls (the
generator: :mod:`~graphplan.forces.lean_code`; the kinematics, loads and groups:
:mod:`~graphplan.forces.lean_kinematics`, :mod:`~graphplan.forces.lean_loads` and
:class:`KinetostaticsCode` here):

* the mechanism's structure is read once, at construction: which values are constants
  (the frame's points, a frame guide's direction, the crank's ω and ε, a translating
  link's ω and ε, the weights), which distances a rigid link keeps (|AB| = l_AB, so
  ``|c1|`` of a dyad's equation and the Frobenius norm of its force system are known),
  and what each dyad, load and group needs;
* from it one straight-line function of the crank angles is generated (the same
  equations as the general path, per dyad kind: :mod:`graphplan.kinematics.positions`,
  :mod:`~graphplan.kinematics.velocities`, :mod:`~graphplan.kinematics.accelerations`,
  :mod:`graphplan.forces.loads`, :mod:`graphplan.forces.kinetostatics`), with every
  operation on constants folded, the determinant of each dyad's 2×2 factorised once for
  its velocities and accelerations, the constants held as 0-d arrays (numpy's fast
  path), and each array deleted after its last use;
* every check of the general path is kept — assembly, lock-up (|sin| > 1e-9), the force
  system's conditioning (bounded by ``‖A‖_F⁶/|det A|``, with a margin of 10⁴ for the
  other moment centre and scale the lean system uses) — each as one ``count_nonzero``
  of a mask; where one fails, the general path is run, which raises the error naming
  the dyad and the position (or, where the lean bound was only cautious, gives the
  result);
* no NaN or infinity in any output, proven at generation where it can be: φ is checked
  finite first, and each value carries a bound ``|x| ≤ B`` (from the checks and the
  geometry, with round-off), so an output with a finite bound needs no check at run
  time; the others (a load along a point's velocity divides by its speed) are checked
  with ``isfinite``;
* at a course project's 36 positions numpy's fixed cost per call is the time: constants
  are held in the dtype of the array they meet (a mixed pair costs twice), a product with
  a constant is one call, and numpy's C functions are called without their wrappers.

The result, :class:`CycleSolution`, holds complex numbers ``x + iy`` (a frame point or a
constant as a Python complex): every point's position, velocity and acceleration, every
link's ω and ε, every pair's reaction (named as :func:`solve_forces` names them; a
prismatic pair's normal force and couple too) and M_ур. It equals the general path's to
round-off (``tests/test_lean.py``: 1e-12 of each quantity's largest, every example and
test variant). A variant setting the lean path does not compile (``shift_inertia_force``,
a dyad of another pattern of pairs, two loads of one name in a group under the neglect
rule) is solved by the general path: :attr:`FullCycle.native` says which.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ..errors import GraphplanError
from ..kinematics import Cycle, analyse_cycle, solve
from ..model import Mechanism
from .kinetostatics import COND_LIMIT, dyad_pairs, reaction_name, solve_forces
from .lean_code import Code, NotCompiled, Value, py_number
from .lean_kinematics import KinematicsCode
from .lean_loads import LoadsCode
from .loads import compute_loads

Array = NDArray[np.float64]

_F8 = np.dtype(np.float64)
_new_tuple = tuple.__new__

LEAN_MARGIN = 1e4
"""The lean force systems (another moment centre and scale) refuse a pose ``LEAN_MARGIN``
times earlier than :data:`COND_LIMIT`, and leave the decision to the general path."""


class CycleSolution(NamedTuple):
    """The full cycle at the angles ``phi``: kinematics, loads' results and reactions.

    Vectors are complex ``x + iy`` (N,) arrays, or Python complex numbers where constant
    (the frame's points, a translating link's zero ω); :meth:`xy` gives an (N, 2) array.
    An immutable record (a named tuple rather than a frozen dataclass: made in 0.2 µs
    instead of 2–3 µs, which counts at a course project's 36 positions).

    Attributes
    ----------
    phi : ndarray (N,)
    points, velocities, accelerations : dict[str, complex array]
        Every named point (m, m/s, m/s²).
    omega, epsilon : dict[str, array]
        Every link's ω and ε (rad/s, rad/s², CCW positive).
    reactions : dict[str, complex array]
        R_ij by the names of :func:`~graphplan.forces.solve_forces` (N), the frame's
        reaction on the crank last.
    normal, couple : dict[str, array]
        Per prismatic pair: the signed normal force N (along ``k×u``) and the couple
        it carries about its reference point (N·m).
    M_bal : ndarray (N,)
        The balancing moment M_ур (N·m, CCW positive).
    native : bool
        False where the general path solved it (see :class:`FullCycle`).
    """

    phi: Array
    points: dict
    velocities: dict
    accelerations: dict
    omega: dict
    epsilon: dict
    reactions: dict
    normal: dict
    couple: dict
    M_bal: Array
    native: bool = True

    def xy(self, table: str, name: str) -> Array:
        """``getattr(self, table)[name]`` as an (N, 2) float array."""
        z = np.broadcast_to(getattr(self, table)[name], self.phi.shape)
        return np.stack((z.real, z.imag), axis=-1)


class FullCycle:
    """The full cycle of one mechanism, compiled once: ``FullCycle(mech, cycle)(phi)``.

    Parameters
    ----------
    mech : Mechanism
    cycle : Cycle, optional
        For the variant's loads (:func:`~graphplan.kinematics.analyse_cycle` when omitted).
    inertia, neglect_below : optional
        As :func:`~graphplan.forces.compute_loads` (default: the variant's settings).

    Calling it with crank angles φ (rad) returns a :class:`CycleSolution`.
    """

    def __init__(self, mech: Mechanism, cycle: Cycle | None = None, *,
                 inertia: bool | None = None, neglect_below: float | None = None):
        self.mech = mech
        self.cycle = cycle if cycle is not None else analyse_cycle(mech)
        st = mech.kinetostatics
        self.inertia = st.inertia if inertia is None else inertia
        self.neglect_below = st.neglect_below if neglect_below is None else neglect_below
        self.native = True
        self.source = ""
        self.bounds: dict[tuple[str, str], float] = {}
        try:
            if st.shift_inertia_force:
                raise NotCompiled("shift_inertia_force")
            self._compile()
        except (NotCompiled, GraphplanError):  # (the probe cannot be assembled: the general
            self.native = False                # path says where, when it is called)

    # -------------------------------------------------------------- the general path
    def general(self, phi) -> CycleSolution:
        """The same quantities through the general path (solve, compute_loads, solve_forces)."""
        mech = self.mech
        phi = np.atleast_1d(np.asarray(phi, float))
        kin = solve(mech, phi)
        loads = compute_loads(mech, kin, self.cycle, inertia=self.inertia,
                              neglect_below=self.neglect_below)
        forces = solve_forces(mech, kin, loads)

        def cx(table):
            return {k: v[:, 0] + 1j * v[:, 1] for k, v in table.items()}

        reac = {n: r.vector[:, 0] + 1j * r.vector[:, 1] for n, r in forces.reactions.items()}
        normal = {n: r.normal for n, r in forces.reactions.items() if r.pair == "P"}
        couple = {n: r.couple for n, r in forces.reactions.items() if r.pair == "P"}
        return CycleSolution(phi, cx(kin.pos.points), cx(kin.vel.points), cx(kin.acc.points),
                             dict(kin.vel.omega), dict(kin.acc.epsilon), reac, normal, couple,
                             forces.M_bal, native=False)

    def __call__(self, phi) -> CycleSolution:
        if not (type(phi) is np.ndarray and phi.dtype is _F8 and phi.ndim == 1):
            phi = np.atleast_1d(np.asarray(phi, float))
        out = self._run(phi) if self.native else None
        if out is None:  # a check failed: the general path raises (or was only cautious)
            return self.general(phi)
        return _new_tuple(CycleSolution, out)

    # -------------------------------------------------------------- compilation
    def _compile(self) -> None:
        mech, g = self.mech, Code()
        probe = solve(mech, [self.cycle.origin])  # distances a rigid link keeps
        self._g = g  # the generated code's names (for a look at the source with its values)
        st = KinematicsCode(mech, g, probe)
        st.positions()
        st.velocities()
        st.accelerations()
        loads = LoadsCode(st, self.cycle, self.inertia, self.neglect_below)
        reac, normal, couple, m_bal = KinetostaticsCode(st, loads).solve()
        # no NaN or infinity in any output (one reduction over all of them)
        tables = [st.P, st.V, st.A, st.W, st.E, reac, normal, couple]
        # (of the arrays without a bound; a finite sum of finite values that overflows only
        # sends the sweep to the general path)
        arrays = [v for t in tables for v in t.values() if v.const is None]
        finite = g.finite_check([*arrays, m_bal])
        if finite:
            g.check(finite)
        outputs = []  # the tables as dict displays, then M_ур
        names = ("points", "velocities", "accelerations", "omega", "epsilon", "reactions",
                 "normal", "couple")
        # |x| ≤ bound at every finite φ, for each output (inf: checked at run time)
        self.bounds = {(n, k): v.bound for n, t in zip(names, tables, strict=True)
                       for k, v in t.items()}
        self.bounds["M_bal", ""] = m_bal.bound
        for t in tables:
            items = (f"{name!r}: {g.ref(v) if v.const is None else repr(py_number(v.const))}"
                     for name, v in t.items())
            outputs.append("{" + ", ".join(items) + "}")
        outputs.append(g.ref(m_bal))
        self.source = g.source("full_cycle", "phi", ["phi", *outputs, "True"], free=True)
        ns = dict(g.ns)
        exec(compile(self.source, f"<graphplan lean {mech.name}>", "exec"), ns)
        self._run = ns["full_cycle"]


class KinetostaticsCode:
    """The groups' reactions and M_ур as Value (kinetostatics.solve_forces, lean)."""

    def __init__(self, st: KinematicsCode, loads: LoadsCode):
        self.st, self.loads = st, loads

    def solve(self):
        st, g, mech = self.st, self.st.g, self.st.mech
        ext_f = {ln: [(v, at) for _, v, at in fs] for ln, fs in self.loads.forces.items()}
        ext_m = {ln: [m for _, m in ms] for ln, ms in self.loads.moments.items()}
        reac: dict[str, Value] = {}
        normal: dict[str, Value] = {}
        couple: dict[str, Value] = {}
        for d in reversed(mech.dyads):
            pairs = dyad_pairs(mech, d)
            i, j = d.links
            p0, p1, p2 = pairs
            if not (p0.on == i and p0.by not in d.links and p1.by == i and p1.on == j
                    and p2.on == j and p2.by not in d.links):
                raise NotCompiled(f"dyad {d.name}: another pattern of pairs")
            centre = pairs[1].point  # the moment centre: the inner pair's point
            c = st.P[centre]
            L = self._scale(d, pairs)
            cols = []
            fro2 = g.K(0.0)
            for k, pr in enumerate(pairs):
                r = g.sub(st.P[pr.point], c)
                if pr.kind == "R":
                    col = ((g.K(1.0), g.mul(g.im(r), g.K(-1.0 / L))),
                           (g.K(1j), g.mul(g.re(r), g.K(1.0 / L))))
                    if pr.point == centre:
                        r2 = g.K(0.0)
                    elif st.on_one_link(pr.point, centre):
                        r2 = g.K(st.dist(pr.point, centre) ** 2)
                    else:
                        r2 = g.add(g.mul(g.re(r), g.re(r)), g.mul(g.im(r), g.im(r)))
                    sq = g.add(g.K(2.0), g.mul(r2, g.K(1.0 / (L * L))))
                else:
                    nv = g.mul(g.K(1j), st.guides[pr.slide_guide][1])
                    ma = g.mul(g.cross(r, nv), g.K(1.0 / L))
                    col = ((nv, ma), (g.K(0.0), g.K(1.0)))
                    sq = g.add(g.K(2.0), g.mul(ma, ma))
                fro2 = g.add(fro2, g.mul(sq, g.K(2.0 if k == 1 else 1.0)))
                cols.append((pr.kind, r, col))
            rhs_f, rhs_m = [], []
            for link in d.links:
                F, M = self._resultant(ext_f[link], ext_m[link], c)
                rhs_f.append(g.neg(F))
                rhs_m.append(g.mul(M, g.K(-1.0 / L)))
            x = self._solve_dyad(cols, rhs_f, rhs_m, L,
                                 lambda det, fro2=fro2, d=d: self._check(d, det, fro2))
            for pr, (kind, _r, col), (xa, xb) in zip(pairs, cols, x, strict=True):
                name = reaction_name(pr.by, pr.on)
                while name in reac:
                    name += "'"
                xc = st.P[pr.point]
                if kind == "R":
                    vc = xa if xb is None else g.add(xa, g.mul(g.K(1j), xb))
                    cpl = g.K(0.0)
                else:
                    nv = col[0][0]
                    vc = g.mul(nv, xa)
                    cpl = g.mul(xb, g.K(L))
                    normal[name], couple[name] = xa, cpl
                g.ref(vc)  # an output: made now, so that its negation (the reaction on
                g.ref(xa)  # the other link) is the pending sign of it, not a second array
                reac[name] = vc
                if pr.by not in d.links and pr.by != mech.frame_link:
                    ext_f[pr.by].append((g.neg(vc), xc))
                    if not cpl.is_const(0):
                        ext_m[pr.by].append(g.neg(cpl))
        cr = mech.crank
        pv = st.P[cr.pivot]
        F, M = self._resultant(ext_f[cr.link], ext_m[cr.link], pv)
        reac[reaction_name(mech.frame_link, cr.link)] = g.neg(F)
        m_bal = g.neg(M)
        if m_bal.const is not None:
            m_bal = g.tmp(f"np.full(phi.shape, {float(m_bal.const)!r})", "r",
                          abs(float(m_bal.const)))
        return reac, normal, couple, m_bal

    def _check(self, d, det: Value, fro2: Value) -> None:
        """The force system's conditioning, before det divides: ``‖A‖_F⁶/|det A|`` below
        :data:`COND_LIMIT` / :data:`LEAN_MARGIN` (as a bound of the condition number)."""
        g = self.st.g
        lim = COND_LIMIT / LEAN_MARGIN
        if det.const is not None and fro2.const is not None:
            if not abs(det.const) * lim > fro2.const ** 3:
                raise NotCompiled(f"dyad {d.name}: singular everywhere")
        elif det.const is not None:  # a constant determinant (the yoke's)
            g.refuse(f"{g.ref(fro2)} ** 3 >= {g.lit(abs(det.const) * lim)}")
        elif fro2.const is not None:  # ‖A‖_F constant: one reduction
            g.check_min(det, fro2.const ** 3 / lim)
        else:
            g.refuse(f"{g.ref(g.abs(det))} * {g.lit(lim)} <= {g.ref(fro2)} ** 3")
            g.set_low(det, 8.0 ** 3 / lim)  # ‖A‖_F² ≥ 8: each pair's ≥ 2, the inner twice

    def _scale(self, d, pairs) -> float:
        """L of the dimensionless system: the group's size at the probe, ≥ l_OA."""
        st = self.st
        pts = [pr.point for pr in pairs]
        size = st.mech.crank.length
        for k, a in enumerate(pts):
            for b in pts[k + 1:]:
                size = max(size, st.dist(a, b))
        return size

    def _resultant(self, forces, moments, centre: Value) -> tuple[Value, Value]:
        """ΣF and ΣM about ``centre`` of a link's loads (the forces at one point summed
        before their moment is taken)."""
        g = self.st.g
        at_point: dict = {}
        for v, at in forces:
            key = ("c", at.const) if at.const is not None else ("v", g.ref(at))
            prev = at_point.get(key)
            at_point[key] = (at, v if prev is None else g.add(prev[1], v))
        F, M = g.K(0.0), g.K(0.0)
        for at, v in at_point.values():
            F = g.add(F, v)
            M = g.add(M, g.cross(g.sub(at, centre), v))
        for m in moments:
            M = g.add(M, m)
        return F, M

    def _solve_dyad(self, cols, rhs_f, rhs_m, L: float, check):
        """kinetostatics._solve_dyad on Value: x per pair as (a, b); ``check(det A)`` is
        generated before det divides."""
        g = self.st.g

        def cross3(kind, r, col):
            """The normal ``a × b`` of a pair's two columns: a revolute pair's
            ``(1, −r_y/L) × (i, r_x/L) = (−i·r/L, 1)``, a prismatic pair's
            ``(n, m) × (0, 1) = (−i·n, 0)``."""
            if kind == "R":
                return g.mul(r, g.K(-1j / L)), g.K(1.0)
            return g.mul(col[0][0], g.K(-1j)), g.K(0.0)

        def dot3(u, col):
            (uf, um), (f, m) = u, col
            return g.add(g.dot(uf, f), g.mul(um, m))

        c2 = cols[2][2]
        v, w = cross3(*cols[0]), cross3(*cols[1])
        a2, b2 = c2
        d11, d12, d21, d22 = dot3(v, a2), dot3(v, b2), dot3(w, a2), dot3(w, b2)
        sf, sm = g.add(rhs_f[0], rhs_f[1]), g.add(rhs_m[0], rhs_m[1])
        g1, g2 = dot3(v, (sf, sm)), dot3(w, (rhs_f[1], rhs_m[1]))
        det = g.sub(g.mul(d11, d22), g.mul(d12, d21))
        check(det)
        inv = g.div(g.K(1.0), det)
        x2a = g.mul(g.sub(g.mul(g1, d22), g.mul(d12, g2)), inv)
        x2b = g.mul(g.sub(g.mul(d11, g2), g.mul(d21, g1)), inv)
        tf = g.add(g.mul(a2[0], x2a), g.mul(b2[0], x2b))
        tm = g.add(g.mul(a2[1], x2a), g.mul(b2[1], x2b))
        out: list[tuple[Value, Value | None]] = []
        for (kind, _r, cc), yf, ym in ((cols[0], g.sub(sf, tf), g.sub(sm, tm)),
                                      (cols[1], g.sub(rhs_f[1], tf), g.sub(rhs_m[1], tm))):
            if kind == "R":
                out.append((yf, None))
            else:
                (nv, ma), _ = cc
                nn = g.dot(nv, yf)
                out.append((nn, g.sub(ym, g.mul(nn, ma))))
        out.append((x2a, x2b))
        return out


__all__ = ["CycleSolution", "FullCycle"]
