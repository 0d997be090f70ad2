"""The full cycle, lean: kinematics, loads and kinetostatics compiled once per mechanism.

:func:`~graphplan.kinematics.solve`, :func:`~graphplan.forces.compute_loads` and
:func:`~graphplan.forces.solve_forces` build the general objects every consumer reads
(plans, tables, the JSON report): per point (N, 2) arrays, a :class:`Reaction` with its
line of action, offsets and flags, the loads with their neglect masks. For a sweep of
many positions — the Mур curve, the dynamics, a simulation — most of that is not read,
and at a course project's 36 positions numpy's fixed cost per call, not the arithmetic,
is the time. :class:`FullCycle` does the same work in fewer calls:

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
  its velocities and accelerations, and the constants held as 0-d arrays (numpy's fast
  path);
* every check of the general path is kept — assembly, lock-up (|sin| > 1e-9), the force
  system's conditioning (bounded by ``‖A‖_F⁶/|det A|``, with a margin of 10⁴ for the
  other moment centre and scale the lean system uses) and no NaN or infinity in any
  output — each as one reduction; where one fails, the general path is run, which
  raises the error naming the dyad and the position (or, where the lean bound was only
  cautious, gives the result).

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

import math
import re
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..errors import GraphplanError
from ..kinematics import Cycle, analyse_cycle, slide_key, solve, translating_links
from ..model import Mechanism
from .kinetostatics import COND_LIMIT, dyad_pairs, reaction_name, solve_forces
from .loads import JUMP_TOL, compute_loads, diagram_value, resistance_names

Array = NDArray[np.float64]

LEAN_MARGIN = 1e4
"""The lean force systems (another moment centre and scale) refuse a pose ``LEAN_MARGIN``
times earlier than :data:`COND_LIMIT`, and leave the decision to the general path."""


_NAME = re.compile(r"\bt\d+\b")


@dataclass(frozen=True, slots=True)
class CycleSolution:
    """The full cycle at the angles ``phi``: kinematics, loads' results and reactions.

    Vectors are complex ``x + iy`` (N,) arrays, or Python complex numbers where constant
    (the frame's points, a translating link's zero ω); :meth:`xy` gives an (N, 2) array.

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


class _V:
    """A value of the generated code: an array's name, a constant, or the negation of
    another value not yet generated (``neg``: a sign is folded into the constant or the
    subtraction that uses it, and generated only where nothing can take it)."""

    __slots__ = ("code", "const", "neg", "parts")

    def __init__(self, code: str | None = None, const=None, neg: _V | None = None):
        self.code, self.const, self.neg = code, const, neg
        self.parts: tuple[_V, _V] | None = None  # (a, b) of a value generated as a + b

    def is_const(self, value=None) -> bool:
        return self.const is not None and (value is None or self.const == value)


class _Gen:
    """Straight-line numpy code with constants folded (see the module docstring)."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.ns: dict = {"np": np, "sqrt": np.sqrt, "exp": np.exp, "arctan2": np.arctan2,
                         "maximum": np.maximum, "isfinite": np.isfinite,
                         "concatenate": np.concatenate}
        self._n = 0
        self._seen: dict[str, _V] = {}
        self._consts: dict = {}

    # values
    def K(self, value) -> _V:
        return _V(None, value)

    def ref(self, v: _V) -> str:
        if v.neg is not None and v.code is None:  # a negation nothing could take
            v.code = self.tmp(f"-{self.ref(v.neg)}").code
        if v.const is None:
            assert v.code is not None
            return v.code
        key = (type(v.const), v.const)
        if key not in self._consts:
            name = self._consts[key] = f"k{self._n}"
            self._n += 1
            self.ns[name] = np.array(v.const)  # a 0-d array: numpy's fast path for a scalar
        return self._consts[key]

    def tmp(self, expr: str) -> _V:
        """A new array ``expr`` (an expression already generated is reused: the values
        are never changed once made)."""
        if expr in self._seen:
            return self._seen[expr]
        name = f"t{self._n}"
        self._n += 1
        self.lines.append(f"{name} = {expr}")
        self._seen[expr] = v = _V(name)
        return v

    def bind(self, name: str, value) -> str:
        self.ns[name] = value
        return name

    def check(self, condition: str) -> None:
        """Return None (the general path decides) where ``condition`` is not true."""
        self.lines.append(f"if not ({condition}): return None")

    # arithmetic, folded
    def add(self, a: _V, b: _V) -> _V:
        if a.const is not None and b.const is not None:
            return self.K(a.const + b.const)
        if a.is_const(0):
            return b
        if b.is_const(0):
            return a
        if b.neg is not None:
            return self.sub(a, b.neg)
        if a.neg is not None:
            return self.sub(b, a.neg)
        v = self.tmp(f"{self.ref(a)} + {self.ref(b)}")
        v.parts = (a, b)
        return v

    def sub(self, a: _V, b: _V) -> _V:
        if a.const is not None and b.const is not None:
            return self.K(a.const - b.const)
        if b.is_const(0):
            return a
        if a.is_const(0):
            return self.neg(b)
        if a is b or (a.code is not None and a.code == b.code):
            return self.K(0.0)
        if b.neg is not None:
            return self.add(a, b.neg)
        if a.neg is not None:
            return self.neg(self.add(a.neg, b))
        if a.parts is not None and b in a.parts:  # (x + y) − x = y
            return a.parts[1] if a.parts[0] is b else a.parts[0]
        return self.tmp(f"{self.ref(a)} - {self.ref(b)}")

    def mul(self, a: _V, b: _V) -> _V:
        if a.const is not None and b.const is not None:
            return self.K(a.const * b.const)
        if a.is_const(0) or b.is_const(0):
            return self.K(0.0)
        if b.const is not None and a.const is None:
            a, b = b, a  # the constant first
        if b.neg is not None:
            if a.const is not None:
                return self.mul(self.K(-a.const), b.neg)
            return self.neg(self.mul(a, b.neg))
        if a.neg is not None:
            return self.neg(self.mul(a.neg, b))
        if a.is_const(1):
            return b
        if a.is_const(-1):
            return self.neg(b)
        return self.tmp(f"{self.ref(a)} * {self.ref(b)}")

    def div(self, a: _V, b: _V) -> _V:
        if b.const is not None:
            return self.mul(a, self.K(1.0 / b.const))
        if a.is_const(0):
            return self.K(0.0)
        if a.neg is not None:
            return self.neg(self.div(a.neg, b))
        if b.neg is not None:
            return self.neg(self.div(a, b.neg))
        return self.tmp(f"{self.ref(a)} / {self.ref(b)}")

    def neg(self, a: _V) -> _V:
        if a.const is not None:
            return self.K(-a.const)
        if a.neg is not None:
            return a.neg
        return _V(neg=a)

    def conj(self, a: _V) -> _V:
        if a.const is not None:
            return self.K(complex(a.const).conjugate())
        if a.neg is not None:
            return self.neg(self.conj(a.neg))
        return self.tmp(f"{self.ref(a)}.conjugate()")

    def re(self, a: _V) -> _V:
        if a.const is not None:
            return self.K(complex(a.const).real)
        if a.neg is not None:
            return self.neg(self.re(a.neg))
        return _V(f"{self.ref(a)}.real")

    def im(self, a: _V) -> _V:
        if a.const is not None:
            return self.K(complex(a.const).imag)
        if a.neg is not None:
            return self.neg(self.im(a.neg))
        return _V(f"{self.ref(a)}.imag")

    def cross(self, a: _V, b: _V) -> _V:
        """``a×b = Im(conj(a)·b)``."""
        return self.im(self.mul(self.conj(a), b))

    def dot(self, a: _V, b: _V) -> _V:
        """``a·b = Re(conj(a)·b)``."""
        return self.re(self.mul(self.conj(a), b))

    def fn(self, name: str, *args: _V, fold=None) -> _V:
        if fold is not None and all(a.const is not None for a in args):
            return self.K(fold(*(a.const for a in args)))
        return self.tmp(f"{name}({', '.join(self.ref(a) for a in args)})")

    def abs(self, a: _V) -> _V:
        if a.neg is not None:
            return self.abs(a.neg)
        return self.fn("abs", a, fold=abs)

    def sqrt(self, a: _V) -> _V:
        return self.fn("sqrt", a, fold=math.sqrt)

    def maximum(self, a: _V, b: _V) -> _V:
        return self.fn("maximum", a, b, fold=max)

    def arg(self, a: _V) -> _V:
        if a.const is not None:
            z = complex(a.const)
            return self.K(math.atan2(z.imag, z.real))
        return self.fn("arctan2", self.im(a), self.re(a))

    def source(self, name: str, args: str, outputs: list[str], free: bool = False) -> str:
        """The function's text; with ``free``, each array is deleted after its last use:
        the next array of its size reuses its memory (numpy's cache of small blocks at 36
        positions, the allocator's free memory at 3,600) instead of all of them being
        held to the end and fresh pages faulted in on every call — faster at every N
        (press: 54 → 50 µs at 36 positions, 1.56 → 0.42 ms at 3,600)."""
        lines = _live(self.lines, outputs)
        if free:
            keep = {m for o in outputs for m in _NAME.findall(o)}
            last: dict[str, int] = {}
            for k, ln in enumerate(lines):
                for m in _NAME.findall(ln.split(" = ", 1)[1] if " = " in ln[:8] else ln):
                    last[m] = k
            dead: dict[int, list[str]] = {}
            for m, k in last.items():
                if m not in keep:
                    dead.setdefault(k, []).append(m)
            lines = [ln + (f"; del {', '.join(sorted(dead[k]))}" if k in dead else "")
                     for k, ln in enumerate(lines)]
        body = "\n".join("    " + ln for ln in lines)
        return f"def {name}({args}):\n{body}\n    return ({', '.join(outputs)},)\n"


class _NotNative(Exception):
    """A variant's setting the lean path does not compile (the general path solves it)."""


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
        st = mech.settings.get("kinetostatics", {})
        self.inertia = bool(st.get("inertia", True)) if inertia is None else inertia
        self.neglect_below = (float(st.get("neglect_below", 0.0)) if neglect_below is None
                              else neglect_below)
        self.native = True
        self.source = ""
        try:
            if st.get("shift_inertia_force", False):
                raise _NotNative("shift_inertia_force")
            self._compile()
        except (_NotNative, GraphplanError):  # (the probe cannot be assembled: the general
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
        if not (type(phi) is np.ndarray and phi.dtype == np.float64 and phi.ndim == 1):
            phi = np.atleast_1d(np.asarray(phi, float))
        if not self.native:
            return self.general(phi)
        out = self._run(phi)
        if out is None:  # a check failed: the general path raises (or was only cautious)
            return self.general(phi)
        return CycleSolution(phi, *out)

    # -------------------------------------------------------------- compilation
    def _compile(self) -> None:
        mech, g = self.mech, _Gen()
        probe = solve(mech, [self.cycle.origin])  # distances a rigid link keeps
        self._g = g  # the generated code's names (for a look at the source with its values)
        st = _State(mech, g, probe)
        st.positions()
        st.velocities()
        st.accelerations()
        loads = _Loads(st, self.cycle, self.inertia, self.neglect_below)
        reac, normal, couple, m_bal = _Kinetostatics(st, loads).solve()
        # no NaN or infinity in any output (one reduction over all of them)
        tables = [st.P, st.V, st.A, st.W, st.E, reac, normal, couple]
        arrays = [g.ref(v) for t in tables for v in t.values() if v.const is None]
        arrays = list(dict.fromkeys([*arrays, g.ref(m_bal)]))
        # (a long sweep: the sum of each, not a copy of all; a finite sum of finite values
        # that overflows only sends the sweep to the general path)
        listed = f"({', '.join(arrays)},)"
        g.lines.append(f"ok = (isfinite(concatenate({listed})).all() if phi.shape[0] <= 4096 "
                       f"else isfinite(sum([x.sum() for x in {listed}])))")
        g.check("ok")
        outputs = []  # the tables as dict displays, then M_ур
        for t in tables:
            items = (f"{name!r}: {g.ref(v) if v.const is None else repr(_py(v.const))}"
                     for name, v in t.items())
            outputs.append("{" + ", ".join(items) + "}")
        outputs.append(g.ref(m_bal))
        self.source = g.source("full_cycle", "phi", outputs, free=True)
        ns = dict(g.ns)
        exec(compile(self.source, f"<graphplan lean {mech.name}>", "exec"), ns)
        self._run = ns["full_cycle"]


def _live(lines: list[str], outputs: list[str]) -> list[str]:
    """The lines whose values are used: by a later line kept, a check, or the outputs."""
    needed = {m for o in outputs for m in _NAME.findall(o)}
    kept = []
    for ln in reversed(lines):
        target, _, expr = ln.partition(" = ")
        if _NAME.fullmatch(target) and not ln.startswith("if "):
            if target not in needed:
                continue
            needed.update(_NAME.findall(expr))
        else:
            needed.update(_NAME.findall(ln))
        kept.append(ln)
    return kept[::-1]


def _py(c):
    """A folded constant as a Python number (for the generated code's literals)."""
    c = complex(c)
    return c if c.imag else c.real


class _State:
    """The kinematics being generated: positions, velocities, accelerations as _V."""

    def __init__(self, mech: Mechanism, g: _Gen, probe):
        self.mech, self.g, self.probe = mech, g, probe
        self.P: dict[str, _V] = {}
        self.V: dict[str, _V] = {}
        self.A: dict[str, _V] = {}
        self.W: dict[str, _V] = {}
        self.E: dict[str, _V] = {}
        self.axis: dict[str, _V] = {}    # unit vector of a link's reference axis
        self.theta: dict[str, _V] = {}
        self.guides: dict[str, tuple[_V, _V]] = {}
        self.SV: dict = {}               # sliding speeds by pair key (see sv)
        self.along: dict[str, _V] = {}   # an RRP slider's coordinate along its guide
        self.dyad: dict[str, dict] = {}  # per dyad what its velocity solve shares
        self.still = translating_links(mech)

    def dist(self, a: str, b: str) -> float:
        """|ab| at the probe (for two points of one rigid link: constant)."""
        pa, pb = self.probe.pos.points[a][0], self.probe.pos.points[b][0]
        return float(math.hypot(*(pa - pb)))

    def on_one_link(self, a: str, b: str) -> bool:
        m = self.mech
        return any(a in m.points_of(ln) and b in m.points_of(ln)
                   for ln in (m.frame_link, *m.moving_links))

    # ------------------------------------------------------------ positions
    def positions(self) -> None:
        mech, g = self.mech, self.g
        for name, xy in mech.frame_points.items():
            self.P[name] = g.K(complex(float(xy[0]), float(xy[1])))
        cr = mech.crank
        self.theta[mech.frame_link] = g.K(0.0)
        self.axis[mech.frame_link] = g.K(1.0)
        self.theta[cr.link] = _V("phi")
        e1 = g.fn("exp", g.mul(g.K(1j), _V("phi")))
        self.axis[cr.link] = e1
        self.P[cr.pin] = g.add(self.P[cr.pivot], g.mul(g.K(cr.length), e1))
        self._extra_points()
        for d in mech.dyads:
            getattr(self, f"_place_{d.kind}")(d)
            self._extra_points()
        missing = [p.name for p in mech.points if p.name not in self.P]
        if missing:
            raise _NotNative(f"points not placed: {missing}")

    def theta_of(self, link: str) -> _V:
        if link not in self.theta:
            self.theta[link] = self.g.arg(self.axis[link])
        return self.theta[link]

    def _extra_points(self) -> None:
        g = self.g
        for p in self.mech.points:
            if p.name in self.P or p.link not in self.axis or p.origin not in self.P:
                continue
            if p.toward is not None and p.toward not in self.P:
                continue
            origin = self.P[p.origin]
            if p.toward is not None:
                if not self.on_one_link(p.origin, p.toward):
                    raise _NotNative(f"point {p.name}: {p.origin}, {p.toward} on two links")
                dist = self.dist(p.origin, p.toward)
                if not dist > 0:
                    raise _NotNative(f"point {p.name}: {p.origin} = {p.toward}")
                d = g.sub(self.P[p.toward], origin)
                if p.fraction is not None:
                    self.P[p.name] = g.add(origin, g.mul(d, g.K(p.fraction)))
                    continue
                u = g.mul(d, g.K(1.0 / dist))
            else:
                u = self.axis[p.link]
            self.P[p.name] = g.add(origin, g.mul(u, g.K(complex(p.along, p.across))))

    def _guide(self, gd) -> tuple[_V, _V]:
        g = self.g
        if gd.through is not None:
            base = self.P[gd.through]
        else:
            base = g.K(complex(float(gd.xy[0]), float(gd.xy[1])))
        if gd.toward is not None:
            if gd.through is None or not self.on_one_link(gd.through, gd.toward):
                raise _NotNative("a guide toward a point of another link")
            dist = self.dist(gd.through, gd.toward)
            u = g.mul(g.sub(self.P[gd.toward], base), g.K(1.0 / dist))
        elif gd.link == self.mech.frame_link:
            u = g.K(complex(math.cos(gd.angle), math.sin(gd.angle)))
        else:
            u = g.mul(self.axis[gd.link], g.K(complex(math.cos(gd.angle), math.sin(gd.angle))))
        return base, u

    def _place_RRR(self, d) -> None:
        g = self.g
        a, b, c = d.joints
        i, j = d.links
        A, C = self.P[a], self.P[c]
        l1, l2 = d.lengths
        s = float(d.branch)
        dv = g.sub(C, A)
        dist = g.abs(dv)
        tiny = 1e-12 * (l1 + l2)
        g.check(f"{g.ref(dist)}.min() > {tiny!r}")
        inv = g.div(g.K(1.0), dist)
        aa = g.mul(g.add(g.mul(dist, dist), g.K(l1 * l1 - l2 * l2)), g.mul(inv, g.K(0.5)))
        h2 = g.sub(g.K(l1 * l1), g.mul(aa, aa))
        g.check(f"{g.ref(h2)}.min() >= 0")
        e = g.mul(dv, inv)
        B = g.add(A, g.mul(e, g.add(aa, g.mul(g.K(1j * s), g.sqrt(h2)))))
        self.P[b] = B
        self.axis[i] = g.mul(g.sub(B, A), g.K(1.0 / l1))
        self.axis[j] = g.mul(g.sub(B, C), g.K(1.0 / l2))

    def _place_RRP(self, d) -> None:
        g = self.g
        a, b = d.joints
        i, j = d.links
        (l1,) = d.lengths
        s = float(d.branch)
        G, u = self._guide(d.guides[0])
        cw = g.mul(g.conj(u), g.sub(self.P[a], G))
        h = g.im(cw)
        g.check(f"{g.ref(g.abs(h))}.max() <= {l1!r}")
        root = g.sqrt(g.sub(g.K(l1 * l1), g.mul(h, h)))
        along = g.add(g.re(cw), g.mul(g.K(s), root))
        B = g.add(G, g.mul(u, along))
        self.P[b] = B
        self.along[slide_key(j, d.guides[0].link)] = along  # (B − G)·u
        self.axis[i] = g.mul(g.sub(B, self.P[a]), g.K(1.0 / l1))
        self.axis[j] = u
        self.guides[slide_key(j, d.guides[0].link)] = (G, u)

    def _place_RPR(self, d) -> None:
        g = self.g
        a, c = d.joints
        i, j = d.links
        s = float(d.branch)
        e = d.offset
        dv = g.sub(self.P[a], self.P[c])
        dist2 = g.add(g.mul(g.re(dv), g.re(dv)), g.mul(g.im(dv), g.im(dv)))
        tol = 1e-9 * max(self.mech.crank.length, abs(e))
        g.check(f"{g.ref(dist2)}.min() > {tol * tol + e * e!r}")
        if e == 0:
            dist = g.sqrt(dist2)
            u = g.mul(g.div(dv, dist), g.K(s))
            self.dyad[d.name] = {"r_abs": dist}
        else:
            along = g.mul(g.K(s), g.sqrt(g.sub(dist2, g.K(e * e))))
            u = g.div(g.mul(dv, g.add(along, g.K(-1j * e))), dist2)
            self.dyad[d.name] = {"r_abs": g.sqrt(dist2)}
        self.axis[i] = self.axis[j] = u
        self.guides[slide_key(i, j)] = (g.add(self.P[c], g.mul(u, g.K(1j * e))), u)

    def _place_PRP(self, d) -> None:
        g = self.g
        (b,) = d.joints
        i, j = d.links
        G1, u1 = self._guide(d.guides[0])
        G2, u2 = self._guide(d.guides[1])
        den = g.cross(u1, u2)
        g.check(f"{g.ref(g.abs(den))}.min() > 1e-12" if den.const is None
                else repr(abs(den.const) > 1e-12))
        t = g.div(g.cross(g.sub(G2, G1), u2), den)
        self.P[b] = g.add(G1, g.mul(u1, t))
        self.axis[i], self.axis[j] = u1, u2
        self.guides[slide_key(i, d.guides[0].link)] = (G1, u1)
        self.guides[slide_key(j, d.guides[1].link)] = (G2, u2)

    def _place_RPP(self, d) -> None:
        g = self.g
        a, dn = d.joints
        i, j = d.links
        G, u = self._guide(d.guides[0])
        w = g.mul(u, g.K(complex(math.cos(d.slot_angle), math.sin(d.slot_angle))))
        t = g.div(g.cross(w, g.sub(self.P[a], G)), g.cross(w, u))
        D = g.add(G, g.mul(u, t))
        self.P[dn] = D
        self.axis[i], self.axis[j] = w, u
        self.guides[slide_key(j, d.guides[0].link)] = (G, u)
        self.guides[slide_key(i, j)] = (D, w)

    # ------------------------------------------------------------ velocities
    def velocities(self) -> None:
        mech, g = self.mech, self.g
        for name in mech.frame_points:
            self.V[name] = g.K(0.0)
        self.W[mech.frame_link] = g.K(0.0)
        cr = mech.crank
        self.W[cr.link] = g.K(float(cr.omega))
        self.V[cr.pin] = g.add(self.V[cr.pivot],
                               g.mul(g.sub(self.P[cr.pin], self.P[cr.pivot]),
                                     g.K(1j * cr.omega)))
        self._extra_rates(self.V, self.W, self._rigid_v)
        for d in mech.dyads:
            getattr(self, f"_vel_{d.kind}")(d)
            self._extra_rates(self.V, self.W, self._rigid_v)

    def _rigid_v(self, p) -> _V:
        g = self.g
        return g.add(self.V[p.origin], g.mul(g.sub(self.P[p.name], self.P[p.origin]),
                                             g.mul(g.K(1j), self.W[p.link])))

    def _extra_rates(self, T, R, rigid) -> None:
        g = self.g
        for p in self.mech.points:
            if p.name in T or p.origin not in T or p.link not in R:
                continue
            if p.link in self.still:
                T[p.name] = T[p.origin]
            elif p.toward is not None and p.fraction is not None and p.toward in T:
                T[p.name] = g.add(T[p.origin],
                                  g.mul(g.sub(T[p.toward], T[p.origin]), g.K(p.fraction)))
            else:
                T[p.name] = rigid(p)

    def _lines(self, d, c1: _V, c2: _V, n1, n2) -> dict:
        """The dyad's two lines: ``det = c1×c2`` (checked against the lock-up, |c1|·|c2|
        = n1·n2) and its reciprocal, shared by the velocity and acceleration solves."""
        g = self.g
        det = g.cross(c1, c2)
        scale = g.mul(n1, n2)
        if scale.const is not None:
            g.check(f"{g.ref(g.abs(det))}.min() > {1e-9 * scale.const!r}")
        else:
            g.check(f"({g.ref(g.abs(det))} > {g.ref(scale)} * 1e-9).all()")
        info = {"c1": c1, "c2": c2, "cc1": g.conj(c1), "inv": g.div(g.K(1.0), det)}
        stored = self.dyad.setdefault(d.name, {})
        stored.update(info)
        return stored

    def _solve2(self, info, rhs: _V) -> tuple[_V, Callable[[], _V]]:
        """``x1·c1 + x2·c2 = rhs`` by Cramer's rule: x1, and x2 as a function that
        generates it when it is asked for (a sliding speed only where it is read)."""
        g = self.g
        x1 = g.mul(g.cross(rhs, info["c2"]), info["inv"])
        return x1, lambda: g.mul(g.im(g.mul(info["cc1"], rhs)), info["inv"])

    def sv(self, key: str) -> _V:
        """The sliding speed of a pair (generated on first use)."""
        x = self.SV[key]
        if not isinstance(x, _V):
            x = self.SV[key] = x()
        return x

    def _coincident_v(self, gd, X: _V) -> _V:
        g = self.g
        if gd.through is None:
            return g.K(0.0)
        return g.add(self.V[gd.through], g.mul(g.sub(X, self.P[gd.through]),
                                               g.mul(g.K(1j), self.W[gd.link])))

    def _vel_RRR(self, d) -> None:
        g = self.g
        a, b, c = d.joints
        i, j = d.links
        rA, rC = g.sub(self.P[b], self.P[a]), g.sub(self.P[b], self.P[c])
        info = self._lines(d, g.mul(g.K(1j), rA), g.mul(g.K(-1j), rC),
                           g.K(d.lengths[0]), g.K(d.lengths[1]))
        info.update(rA=rA, rC=rC)
        wi, wj = self._solve2(info, g.sub(self.V[c], self.V[a]))
        self.W[i], self.W[j] = wi, wj()
        self.V[b] = g.add(self.V[a], g.mul(info["c1"], wi))

    def _vel_RRP(self, d) -> None:
        g = self.g
        a, b = d.joints
        i, j = d.links
        gd = d.guides[0]
        key = slide_key(j, gd.link)
        u = self.guides[key][1]
        r = g.sub(self.P[b], self.P[a])
        info = self._lines(d, g.mul(g.K(1j), r), g.neg(u), g.K(d.lengths[0]), g.K(1.0))
        info.update(r=r)
        vBk = self._coincident_v(gd, self.P[b])
        wi, vr = self._solve2(info, g.sub(vBk, self.V[a]))
        self.W[i] = wi
        self.W[j] = self.W[gd.link]
        self.SV[key] = vr
        self.V[b] = g.add(self.V[a], g.mul(info["c1"], wi))

    def _vel_RPR(self, d) -> None:
        g = self.g
        a, c = d.joints
        i, j = d.links
        key = slide_key(i, j)
        u = self.guides[key][1]
        r = g.sub(self.P[a], self.P[c])
        info = self._lines(d, g.mul(g.K(1j), r), u, self.dyad[d.name]["r_abs"], g.K(1.0))
        info.update(r=r)
        w, vr = self._solve2(info, g.sub(self.V[a], self.V[c]))
        self.W[i] = self.W[j] = w
        self.SV[key] = vr

    def _vel_PRP(self, d) -> None:
        g = self.g
        (b,) = d.joints
        i, j = d.links
        g1, g2 = d.guides
        k1, k2 = slide_key(i, g1.link), slide_key(j, g2.link)
        u1, u2 = self.guides[k1][1], self.guides[k2][1]
        info = self._lines(d, u1, g.neg(u2), g.K(1.0), g.K(1.0))
        vB1 = self._coincident_v(g1, self.P[b])
        vB2 = self._coincident_v(g2, self.P[b])
        vr1, vr2 = self._solve2(info, g.sub(vB2, vB1))
        self.W[i], self.W[j] = self.W[g1.link], self.W[g2.link]
        self.SV[k1], self.SV[k2] = vr1, vr2
        self.V[b] = g.add(vB1, g.mul(u1, vr1))

    def _vel_RPP(self, d) -> None:
        g = self.g
        a, dn = d.joints
        i, j = d.links
        gd = d.guides[0]
        kj, ki = slide_key(j, gd.link), slide_key(i, j)
        u, w = self.guides[kj][1], self.guides[ki][1]
        info = self._lines(d, u, w, g.K(1.0), g.K(1.0))
        vAk = self._coincident_v(gd, self.P[a])
        vs, vr = self._solve2(info, g.sub(self.V[a], vAk))
        self.W[j] = self.W[gd.link]
        self.W[i] = self.W[j]
        self.SV[kj], self.SV[ki] = vs, vr
        self.V[dn] = g.add(self._coincident_v(gd, self.P[dn]), g.mul(u, vs))

    # ------------------------------------------------------------ accelerations
    def accelerations(self) -> None:
        mech, g = self.mech, self.g
        for name in mech.frame_points:
            self.A[name] = g.K(0.0)
        self.E[mech.frame_link] = g.K(0.0)
        cr = mech.crank
        self.E[cr.link] = g.K(0.0)
        self.A[cr.pin] = g.add(self.A[cr.pivot],
                               g.mul(g.sub(self.P[cr.pin], self.P[cr.pivot]),
                                     g.K(-float(cr.omega) ** 2)))
        self._factor: dict[str, _V] = {}
        self._extra_rates(self.A, self.E, self._rigid_a)
        for d in mech.dyads:
            getattr(self, f"_acc_{d.kind}")(d)
            self._extra_rates(self.A, self.E, self._rigid_a)

    def _w2(self, link: str) -> _V:
        return self.g.mul(self.W[link], self.W[link])

    def _rigid_a(self, p) -> _V:
        g = self.g
        if p.link not in self._factor:  # iε − ω², once per link
            self._factor[p.link] = g.sub(g.mul(g.K(1j), self.E[p.link]), self._w2(p.link))
        return g.add(self.A[p.origin],
                     g.mul(g.sub(self.P[p.name], self.P[p.origin]), self._factor[p.link]))

    def _rigid(self, a_base: _V, link: str, r: _V) -> _V:
        """``a_base + ε·k×r − ω²·r``."""
        g = self.g
        return g.add(a_base, g.sub(g.mul(g.mul(g.K(1j), r), self.E[link]),
                                   g.mul(r, self._w2(link))))

    def _coincident_a(self, gd, X: _V) -> _V:
        if gd.through is None:
            return self.g.K(0.0)
        return self._rigid(self.A[gd.through], gd.link, self.g.sub(X, self.P[gd.through]))

    def _coriolis(self, link: str, key: str, u: _V) -> _V:
        g = self.g
        if self.W[link].is_const(0):
            return g.K(0.0)
        return g.mul(g.mul(g.K(1j), u), g.mul(g.K(2.0), g.mul(self.W[link], self.sv(key))))

    def _acc_RRR(self, d) -> None:
        g = self.g
        pa, pb, pc = d.joints
        i, j = d.links
        info = self.dyad[d.name]
        rA, rC = info["rA"], info["rC"]
        nA, nC = g.mul(rA, self._w2(i)), g.mul(rC, self._w2(j))
        rhs = g.sub(g.sub(self.A[pc], nC), g.sub(self.A[pa], nA))
        ei, ej = self._solve2(info, rhs)
        self.E[i], self.E[j] = ei, ej()
        self.A[pb] = g.add(g.sub(self.A[pa], nA), g.mul(info["c1"], ei))

    def _acc_RRP(self, d) -> None:
        g = self.g
        pa, pb = d.joints
        i, j = d.links
        gd = d.guides[0]
        key = slide_key(j, gd.link)
        u = self.guides[key][1]
        info = self.dyad[d.name]
        r = info["r"]
        aBk = self._coincident_a(gd, self.P[pb])
        cor = self._coriolis(gd.link, key, u)
        nA = g.sub(self.A[pa], g.mul(r, self._w2(i)))
        ei, _ = self._solve2(info, g.sub(g.add(aBk, cor), nA))
        self.E[i] = ei
        self.E[j] = self.E[gd.link]
        self.A[pb] = g.add(nA, g.mul(info["c1"], ei))

    def _acc_RPR(self, d) -> None:
        g = self.g
        pa, pc = d.joints
        i, j = d.links
        key = slide_key(i, j)
        u = self.guides[key][1]
        info = self.dyad[d.name]
        r = info["r"]
        cor = self._coriolis(j, key, u)
        rhs = g.sub(g.sub(self.A[pa], g.sub(self.A[pc], g.mul(r, self._w2(j)))), cor)
        e, _ = self._solve2(info, rhs)
        self.E[i] = self.E[j] = e

    def _acc_PRP(self, d) -> None:
        g = self.g
        (pb,) = d.joints
        i, j = d.links
        g1, g2 = d.guides
        k1, k2 = slide_key(i, g1.link), slide_key(j, g2.link)
        u1 = self.guides[k1][1]
        u2 = self.guides[k2][1]
        info = self.dyad[d.name]
        aB1 = g.add(self._coincident_a(g1, self.P[pb]), self._coriolis(g1.link, k1, u1))
        aB2 = g.add(self._coincident_a(g2, self.P[pb]), self._coriolis(g2.link, k2, u2))
        ar1, _ = self._solve2(info, g.sub(aB2, aB1))
        self.E[i], self.E[j] = self.E[g1.link], self.E[g2.link]
        self.A[pb] = g.add(aB1, g.mul(u1, ar1))

    def _acc_RPP(self, d) -> None:
        g = self.g
        pa, pd = d.joints
        i, j = d.links
        gd = d.guides[0]
        kj, ki = slide_key(j, gd.link), slide_key(i, j)
        u, w = self.guides[kj][1], self.guides[ki][1]
        info = self.dyad[d.name]
        aAk = self._coincident_a(gd, self.P[pa])
        corj = self._coriolis(gd.link, kj, u)
        cori = self._coriolis(j, ki, w)
        as_, _ = self._solve2(info, g.sub(g.sub(g.sub(self.A[pa], aAk), corj), cori))
        self.E[j] = self.E[gd.link]
        self.E[i] = self.E[j]
        self.A[pd] = g.add(g.add(self._coincident_a(gd, self.P[pd]), corj), g.mul(u, as_))


def _interp(xs, ys, nodes, d, signed: bool, clip: bool, lo: float, hi: float):
    """The diagram ``d`` as ``np.interp`` (see _Loads._diagram); x is clipped to [lo, hi]
    only where the general function is called (np.interp holds its end values beyond the
    ends, and x leaves [0, 1] by round-off only)."""
    tol = 2 * JUMP_TOL
    # zero beyond an end inside [lo, hi]; an end at or beyond lo or hi holds its value
    left = 0.0 if xs[0] > lo else None
    right = 0.0 if xs[-1] < hi else None
    # a step function 1 within 2·tol of a node, 0 elsewhere: one interpolation finds
    # whether any x is near a node
    gx = np.array([v for n in nodes for v in (n - 2 * tol, n - tol, n + tol, n + 2 * tol)])
    gy = np.array([v for _ in nodes for v in (0.0, 1.0, 1.0, 0.0)])

    def value(x):
        if gx.size and np.interp(x, gx, gy).any():
            return diagram_value(d, np.clip(x, lo, hi), signed=signed)
        v = np.interp(x, xs, ys, left, right)
        return np.maximum(v, 0.0) if clip else v

    return value


class _Loads:
    """The loads of every moving link as _V: forces ``(name, vector, at)`` and couples."""

    def __init__(self, st: _State, cycle: Cycle, inertia: bool, frac: float):
        self.st = st
        mech, g = st.mech, st.g
        self.forces: dict[str, list] = {ln: [] for ln in mech.moving_links}
        self.moments: dict[str, list] = {ln: [] for ln in mech.moving_links}
        gvec = complex(*mech.gravity)
        w1sq = float(mech.crank.omega) ** 2
        for ln in mech.moving_links:
            props = mech.links.get(ln)
            if props is None or props.centre is None:
                continue
            S = st.P[props.centre]
            if props.mass > 0 and gvec != 0:
                self.forces[ln].append((f"G{ln}", g.K(props.mass * gvec), S))
            if inertia and props.mass > 0:
                self.forces[ln].append((f"Pи{ln}", g.mul(g.K(-props.mass), st.A[props.centre]),
                                        S))
            if inertia and props.inertia > 0:
                eps = st.E[ln]
                if eps.const is None:  # ε of round-off at a dead centre: no couple
                    keep = g.tmp(f"{g.ref(g.abs(eps))} > {1e-12 * w1sq!r}")
                    self.moments[ln].append((f"Mи{ln}",
                                             g.mul(g.mul(eps, keep), g.K(-props.inertia))))
                elif eps.const != 0:
                    self.moments[ln].append((f"Mи{ln}", g.K(-props.inertia * eps.const)))
        self._resistances(cycle)
        if frac > 0:
            self._neglect(frac)

    def _resistances(self, cycle: Cycle) -> None:
        st, g, mech = self.st, self.st.g, self.st.mech
        for n_res, (res, name) in enumerate(zip(mech.resistances, resistance_names(mech),
                                                strict=True)):
            tl = res.travel_link or mech.output.link
            q = g.K(0.0)
            if res.over == "stroke":
                q = self._coordinate(tl)
            size, dirn = self._values(res, n_res, cycle, q)
            s = -1.0 if res.sense == "resists" else 1.0
            w = float(res.working or mech.output.working)
            own = res.over == "stroke" and tl == res.link
            if res.kind == "force":
                assert res.point is not None  # a force has its point (the loader)
                at = st.P[res.point]
                key = f"{res.link}/{mech.frame_link}"
                u = st.guides[key][1] if key in st.guides else None
                if res.sense == "diagram":
                    if res.angle is not None:
                        e = g.K(complex(math.cos(res.angle), math.sin(res.angle)))
                    else:
                        assert u is not None
                        e = g.mul(u, g.K(w if own else 1.0))
                    vec = g.mul(e, size)
                elif u is not None:
                    motion = (g.mul(g.K(w), dirn()) if own
                              else g.fn("np.sign", st.sv(key)))
                    vec = g.mul(u, g.mul(g.K(s), g.mul(motion, size)))
                else:
                    v = self._point_velocity(res.link, at)
                    sp = g.abs(v)
                    safe = g.tmp(f"np.where({g.ref(sp)} > 0, {g.ref(sp)}, 1.0)")
                    vec = g.mul(v, g.div(g.mul(g.K(s), size), safe))
                self.forces[res.link].append((name, vec, at))
            else:
                if res.sense == "diagram":
                    mom = size
                else:
                    motion = (g.mul(g.K(w), dirn()) if own
                              else g.fn("np.sign", st.W[res.link]))
                    mom = g.mul(g.K(s), g.mul(motion, size))
                self.moments[res.link].append((name, mom))

    def _values(self, res, n_res: int, cycle: Cycle, q: _V):
        """:func:`~graphplan.forces.load_values`: the signed size and the stroke's
        direction of motion (a function generating it when asked for)."""
        g, mech = self.st.g, self.st.mech
        period = cycle.period
        tau = g.mul(g.sub(_V("phi"), g.K(cycle.origin)), g.K(float(mech.crank.sense)))
        tau = g.fn("np.mod", tau, g.K(period))
        if res.over == "crank":
            x = g.fn("np.mod", g.sub(tau, g.K(res.phase)), g.K(period))
            val = self._diagram(res.strokes[0], x, True, (0.0, period), n_res, 0, clip_x=False)
            return g.sub(g.mul(val, g.K(res.maximum)), g.K(res.offset)), None
        lt = cycle.travels[(res.travel_link or mech.output.link,
                            res.working or mech.output.working)]
        from .loads import DEAD_CENTRE_TOL, _first_start

        two_pi = 2 * math.pi
        loaded = [m for m, d in enumerate(res.stroke_diagrams(round(period / math.pi)))
                  if d is not None]
        # u: the crank's travel from the load's first start dead centre (one reduction
        # modulo the period; loads.stroke_index takes τ modulo it first: the two differ by
        # round-off, 1e-15 rad, well inside DEAD_CENTRE_TOL that decides at a dead centre)
        u = g.fn("np.mod", g.add(g.mul(_V("phi"), g.K(float(mech.crank.sense))),
                                 g.K(-cycle.origin * mech.crank.sense + DEAD_CENTRE_TOL
                                     - _first_start(res, mech, cycle, lt))), g.K(period))
        if period == two_pi and loaded == [0]:
            # one turn, one loaded stroke: stroke_index's k is 0 exactly where u < lt.turn
            # (its other turn starts where u/2π rounds to 1, after lt.turn)
            k = None
            sel0 = g.tmp(f"{g.ref(u)} < {lt.turn!r}")
        else:
            turn = g.fn("np.floor", g.tmp(f"{g.ref(u)} / {two_pi!r}"))
            r = g.sub(u, g.mul(turn, g.K(two_pi)))
            k = g.add(g.mul(turn, g.K(2.0)), g.tmp(f"{g.ref(r)} >= {lt.turn!r}"))
        if lt.kind == "rocker":
            mid = 0.5 * (lt.q_start + lt.q_end)
            q = g.add(q, g.mul(g.fn("np.round", g.mul(g.sub(g.K(mid), q), g.K(1 / two_pi))),
                               g.K(two_pi)))
        xr = g.mul(g.sub(q, g.K(lt.q_start)), g.K(1.0 / (lt.q_end - lt.q_start)))
        x = xr  # in [0, 1] but for round-off: clipped where the general function reads it
        signed = res.sense == "diagram"
        size = g.K(0.0)
        for m in loaded:
            d = res.stroke_diagrams(round(period / math.pi))[m]
            sel = sel0 if k is None else g.tmp(f"{g.ref(k)} == {float(m)!r}")
            val = self._diagram(d, x, signed, (0.0, 1.0), n_res, m)
            size = g.add(size, g.mul(g.sub(g.mul(val, g.K(res.maximum)), g.K(res.offset)), sel))

        def dirn():
            """±1 on the strokes 0 → 1 and 1 → 0 (where the size is not 0)."""
            if len(loaded) == 1:
                return g.K(1.0 if loaded[0] % 2 == 0 else -1.0)
            assert k is not None
            return g.sub(g.K(1.0), g.mul(g.fn("np.mod", k, g.K(2.0)), g.K(2.0)))
        return size, dirn

    def _diagram(self, d, x: _V, signed: bool, span, n_res: int, m: int,
                 clip_x: bool = True) -> _V:
        """:func:`~graphplan.forces.diagram_value` of ``d`` at x: ``np.interp`` for a diagram
        without jumps, which is the same function except within :data:`JUMP_TOL` of a node
        where two pieces meet (or of an end inside ``span``); there, or for a diagram with
        jumps, the general function itself."""
        g = self.st.g
        xs = np.array([p[0] for p in d], float)
        ys = np.array([p[1] for p in d], float)
        name = f"_{n_res}_{m}"
        if not np.all(np.diff(xs) > 10 * JUMP_TOL):
            fn = g.bind(f"diagram{name}", lambda x, d=d, s=signed: diagram_value(d, x, signed=s))
            if clip_x:
                x = g.fn("np.clip", x, g.K(float(span[0])), g.K(float(span[1])))
            return g.tmp(f"{fn}({g.ref(x)})")
        nodes = [float(v) for v in xs[1:-1]]
        nodes += [float(v) for v in (xs[0], xs[-1]) if span[0] < v < span[1]]
        clip = not signed and ys.min() < 0
        fn = g.bind(f"diagram{name}",
                    _interp(xs, ys, np.array(sorted(nodes)), d, signed, clip, *span))
        return g.tmp(f"{fn}({g.ref(x)})")

    def _coordinate(self, link: str) -> _V:
        """The travel link's coordinate (:func:`~graphplan.kinematics.link_coordinate`)."""
        st, g, mech = self.st, self.st.g, self.st.mech
        for d in mech.dyads:
            if link not in d.links:
                continue
            for key, (G, u) in st.guides.items():
                slider, carrier = key.split("/")
                if slider == link and carrier == mech.frame_link:
                    point = d.new_points[0] if d.new_points else d.joints[0]
                    if d.kind == "RRP" and key in st.along:  # B = G + u·(B − G)·u
                        return st.along[key]
                    return g.dot(u, g.sub(st.P[point], G))
            break
        theta = st.theta_of(link)
        return g.fn("np.unwrap", theta)

    def _point_velocity(self, link: str, at: _V) -> _V:
        st, g = self.st, self.st.g
        q = st.mech.points_of(link)[0]
        return g.add(st.V[q], g.mul(g.sub(at, st.P[q]), g.mul(g.K(1j), st.W[link])))

    def _neglect(self, frac: float) -> None:
        """Drop the loads below ``frac`` of the largest of their group (loads._neglect)."""
        g, mech = self.st.g, self.st.mech
        groups = [(mech.crank.link,), *(d.links for d in mech.dyads)]
        for links in groups:
            fl = [(ln, k) for ln in links for k in range(len(self.forces[ln]))]
            ml = [(ln, k) for ln in links for k in range(len(self.moments[ln]))]
            if not (fl or ml):
                continue
            names = [self.forces[ln][k][0] for ln, k in fl] + \
                [self.moments[ln][k][0] for ln, k in ml]
            if len(set(names)) < len(names):
                raise _NotNative("two loads of one name in a group")
            ell = self._group_size(links) if ml else g.K(1.0)
            # the loads that vary (a force by its vector, a couple by M/ℓ) and the constants
            rows: list[tuple[str, tuple[str, int], _V]] = []
            consts: list[tuple[str, tuple[str, int], float]] = []
            for kind, keys in (("f", fl), ("m", ml)):
                for ln, k in keys:
                    v = self.forces[ln][k][1] if kind == "f" else \
                        g.div(self.moments[ln][k][1], ell)
                    if v.const is not None:
                        consts.append((kind, (ln, k), abs(v.const)))
                    else:
                        rows.append((kind, (ln, k), v))
            if not rows:  # constants only (the weights, without inertia): decided here
                limit_c = frac * max(c for _, _, c in consts)
                for kind, (ln, k), size in consts:
                    if size < limit_c:
                        if kind == "f":
                            nm, _, at = self.forces[ln][k]
                            self.forces[ln][k] = (nm, g.K(0.0), at)
                        else:
                            self.moments[ln][k] = (self.moments[ln][k][0], g.K(0.0))
                continue
            # the largest size, position by position (np.maximum of each: numpy's stack
            # and a reduction over its axis cost more at a course project's 36 positions)
            sizes = [g.abs(v) for _, _, v in rows]
            big = g.K(max(c for _, _, c in consts)) if consts else sizes[0]
            for sz in (sizes if consts else sizes[1:]):
                big = g.maximum(big, sz)
            limit = g.mul(big, g.K(frac))
            # where a size is 0 its load is 0: keeping the loads at or above the limit is
            # the general rule's drop of those below it and above 0
            for (kind, (ln, k), _), sz in zip(rows, sizes, strict=True):
                keep = g.tmp(f"{g.ref(sz)} >= {g.ref(limit)}")
                if kind == "f":
                    nm, vec, at = self.forces[ln][k]
                    self.forces[ln][k] = (nm, g.mul(vec, keep), at)
                else:
                    nm, mom = self.moments[ln][k]
                    self.moments[ln][k] = (nm, g.mul(mom, keep))
            for kind, (ln, k), size in consts:
                keep = g.tmp(f"{g.ref(limit)} <= {size!r}")
                if kind == "f":
                    nm, vec, at = self.forces[ln][k]
                    self.forces[ln][k] = (nm, g.mul(vec, keep), at)
                else:
                    nm, mom = self.moments[ln][k]
                    self.moments[ln][k] = (nm, g.mul(mom, keep))

    def _group_size(self, links) -> _V:
        """ℓ of a group (loads.group_size): pairs on one rigid link are constants."""
        st, g, mech = self.st, self.st.g, self.st.mech
        names = list(dict.fromkeys(p for ln in links for p in mech.points_of(ln)))
        const = mech.crank.length
        arrays: list[_V] = []
        for k, a in enumerate(names):
            for b in names[k + 1:]:
                if st.on_one_link(a, b):
                    const = max(const, st.dist(a, b))
                else:
                    arrays.append(g.abs(g.sub(st.P[a], st.P[b])))
        size = g.K(const)
        for x in arrays:
            size = g.maximum(size, x)
        return size


class _Kinetostatics:
    """The groups' reactions and M_ур as _V (kinetostatics.solve_forces, lean)."""

    def __init__(self, st: _State, loads: _Loads):
        self.st, self.loads = st, loads

    def solve(self):
        st, g, mech = self.st, self.st.g, self.st.mech
        ext_f = {ln: [(v, at) for _, v, at in fs] for ln, fs in self.loads.forces.items()}
        ext_m = {ln: [m for _, m in ms] for ln, ms in self.loads.moments.items()}
        reac: dict[str, _V] = {}
        normal: dict[str, _V] = {}
        couple: dict[str, _V] = {}
        for d in reversed(mech.dyads):
            pairs = dyad_pairs(mech, d)
            i, j = d.links
            p0, p1, p2 = pairs
            if not (p0.on == i and p0.by not in d.links and p1.by == i and p1.on == j
                    and p2.on == j and p2.by not in d.links):
                raise _NotNative(f"dyad {d.name}: another pattern of pairs")
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
            x, det = self._solve_dyad(cols, rhs_f, rhs_m, L)
            lim = COND_LIMIT / LEAN_MARGIN
            if det.const is not None and fro2.const is not None:
                if not abs(det.const) * lim > fro2.const ** 3:
                    raise _NotNative(f"dyad {d.name}: singular everywhere")
            elif det.const is not None:  # a constant determinant (the yoke's)
                g.check(f"({g.ref(fro2)} ** 3).max() < {abs(det.const) * lim!r}")
            elif fro2.const is not None:  # ‖A‖_F constant: one reduction
                g.check(f"{g.ref(g.abs(det))}.min() > {fro2.const ** 3 / lim!r}")
            else:
                g.check(f"({g.ref(g.abs(det))} * {lim!r} > {g.ref(fro2)} ** 3).all()")
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
            m_bal = g.tmp(f"np.full(phi.shape, {float(m_bal.const)!r})")
        return reac, normal, couple, m_bal

    def _scale(self, d, pairs) -> float:
        """L of the dimensionless system: the group's size at the probe, ≥ l_OA."""
        st = self.st
        pts = [pr.point for pr in pairs]
        size = st.mech.crank.length
        for k, a in enumerate(pts):
            for b in pts[k + 1:]:
                size = max(size, st.dist(a, b))
        return size

    def _resultant(self, forces, moments, centre: _V) -> tuple[_V, _V]:
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

    def _solve_dyad(self, cols, rhs_f, rhs_m, L: float):
        """kinetostatics._solve_dyad on _V: x per pair as (a, b) and det A."""
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
        inv = g.div(g.K(1.0), det)
        x2a = g.mul(g.sub(g.mul(g1, d22), g.mul(d12, g2)), inv)
        x2b = g.mul(g.sub(g.mul(d11, g2), g.mul(d21, g1)), inv)
        tf = g.add(g.mul(a2[0], x2a), g.mul(b2[0], x2b))
        tm = g.add(g.mul(a2[1], x2a), g.mul(b2[1], x2b))
        out: list[tuple[_V, _V | None]] = []
        for (kind, _r, cc), yf, ym in ((cols[0], g.sub(sf, tf), g.sub(sm, tm)),
                                      (cols[1], g.sub(rhs_f[1], tf), g.sub(rhs_m[1], tm))):
            if kind == "R":
                out.append((yf, None))
            else:
                (nv, ma), _ = cc
                nn = g.dot(nv, yf)
                out.append((nn, g.sub(ym, g.mul(nn, ma))))
        out.append((x2a, x2b))
        return out, det


__all__ = ["CycleSolution", "FullCycle"]
