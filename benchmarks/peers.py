"""The peer: the same mechanisms built in pylinkage (installed from the package index).

pylinkage's component API: ``Ground`` points, a ``Crank``, ``RRRDyad`` (circle ∩
circle), ``RRPDyad`` (circle ∩ line) and ``FixedDyad`` (a point at a fixed distance and
angle from two others) in a ``Linkage``. The slotted rocker of the shaper (an RPR dyad)
has no dyad of its own there, but its points are ``FixedDyad`` s on the line from the
pivot toward the crank pin, which is the same geometry. Points a FixedDyad cannot express
(a point off the axis of a translating slider: the shaper's S5 and T) are left out, so
pylinkage computes slightly fewer points than graphplan.

The crank turns ``2π/N`` per step; ``set_input_velocity`` gives ω1 in rad/s, so the
velocities and accelerations are physical. Two sweeps are measured:
``step_with_derivatives()`` (pure Python, the default) and
``step_fast_with_kinematics()`` (numba-compiled; its first call compiles, excluded from
the timings and reported apart).
"""

from __future__ import annotations

import math

import numpy as np


def available() -> str | None:
    """pylinkage's version, or None when it is not installed."""
    try:
        import pylinkage
    except ImportError:
        return None
    return pylinkage.__version__


def has_numba() -> bool:
    try:
        from pylinkage._numba_compat import HAS_NUMBA
    except ImportError:
        return False
    return bool(HAS_NUMBA)


class PylinkageModel:
    """A pylinkage Linkage of a graphplan mechanism and the names of its components."""

    def __init__(self, mech, kin0, k0: int, phi0: float, n: int):
        """Build it with the crank one step before ``phi0``; ``kin0`` (graphplan's assembly at
        position ``k0``) gives the hints that choose each dyad's branch."""
        from pylinkage import Crank, FixedDyad, Ground, Linkage, RRPDyad, RRRDyad

        self.mech = mech
        self.n = n
        sense = 1.0 if mech.crank.omega > 0 else -1.0
        self.step = sense * 2 * math.pi / n
        comps, names = [], []
        ref = {}

        def add(c, name):
            comps.append(c)
            names.append(name)
            ref[name] = c
            return c

        def hint(name):
            x, y = kin0.pos.points[name][k0]
            return float(x), float(y)

        for name, xy in mech.frame_points.items():
            add(Ground(float(xy[0]), float(xy[1]), name=name), name)
        cr = mech.crank
        crank = Crank(ref[cr.pivot], cr.length, angular_velocity=self.step,
                      initial_angle=phi0 - self.step, name=cr.pin)
        add(crank, cr.pin)
        self.crank = crank
        out = {cr.pin: crank.output}
        axis_from = {cr.link: (cr.pivot, cr.pin)}  # a link's axis: from one point toward another

        def anchor(name):
            return out[name] if name in out else ref[name]

        def points_of_links():
            for p in mech.points:
                if p.name in ref or p.link not in axis_from:
                    continue
                if p.origin not in ref or (p.toward is not None and p.toward not in ref):
                    continue
                base, tip = axis_from[p.link]
                if p.toward is not None and p.fraction is not None:
                    d = float(np.hypot(*(kin0.pos.points[p.toward][k0]
                                         - kin0.pos.points[p.origin][k0])))
                    dist, ang, a1, a2 = p.fraction * d, 0.0, p.origin, p.toward
                elif p.toward is None and p.origin == base and tip is not None:
                    dist, ang = math.hypot(p.along, p.across), math.atan2(p.across, p.along)
                    a1, a2 = base, tip
                else:
                    continue  # not expressible as a FixedDyad (e.g. off a slider's axis)
                if dist == 0.0:
                    out[p.name] = anchor(p.origin)
                    ref[p.name] = ref[p.origin]
                    continue
                add(FixedDyad(anchor(a1), anchor(a2), dist, ang, name=p.name), p.name)

        points_of_links()
        for d in mech.dyads:
            i, j = d.links
            if d.kind == "RRR":
                a, b, c = d.joints
                x, y = hint(b)
                dy = RRRDyad(anchor(a), anchor(c), distance1=d.lengths[0],
                             distance2=d.lengths[1], x=x, y=y, name=b)
                add(dy, b)
                axis_from[i], axis_from[j] = (a, b), (c, b)
            elif d.kind == "RRP":
                a, b = d.joints
                g = d.guides[0]
                if g.link != mech.frame_link or g.xy is None:
                    raise NotImplementedError("pylinkage peer: RRP on a frame guide only")
                ux, uy = math.cos(g.angle), math.sin(g.angle)
                l1 = add(Ground(g.xy[0], g.xy[1], name=f"{b}_rail0"), f"{b}_rail0")
                l2 = add(Ground(g.xy[0] + ux, g.xy[1] + uy, name=f"{b}_rail1"), f"{b}_rail1")
                x, y = hint(b)
                add(RRPDyad(anchor(a), l1, l2, d.lengths[0], x=x, y=y, name=b), b)
                axis_from[i], axis_from[j] = (a, b), (b, None)
            elif d.kind == "RPR" and d.offset == 0:
                a, c = d.joints
                axis_from[i] = axis_from[j] = (c, a)
            else:
                raise NotImplementedError(f"pylinkage peer: dyad {d.kind}")
            points_of_links()
        self.linkage = Linkage(comps, name=mech.name)
        self.linkage.set_input_velocity(crank, omega=mech.crank.omega)
        self.names = names
        self.index = {nm: k for k, nm in enumerate(names)}
        self.pin = cr.pin
        self.pivot = mech.frame_points.get(cr.pivot)

    def sweep_default(self):
        """``step_with_derivatives`` over one turn: arrays (N, n_components, 2)."""
        P, V, A = [], [], []
        for p, v, a in self.linkage.step_with_derivatives(iterations=self.n):
            P.append(p)
            V.append([x if x is not None else (math.nan, math.nan) for x in v])
            A.append([x if x is not None else (math.nan, math.nan) for x in a])
        return np.array(P, float), np.array(V, float), np.array(A, float)

    def sweep_numba(self):
        """``step_fast_with_kinematics`` over one turn (numba)."""
        return self.linkage.step_fast_with_kinematics(iterations=self.n)

    def result(self, arrays) -> dict:
        """Per named point: positions, velocities, accelerations; and the crank angles."""
        P, V, A = arrays
        k = self.index[self.pin]
        o = np.asarray(self.pivot, float)
        phi = np.arctan2(P[:, k, 1] - o[1], P[:, k, 0] - o[0])
        names = [n for n in self.names if n in self.mech.frame_points or "_rail" not in n]
        return {"phi": phi,
                "points": {n: P[:, self.index[n]] for n in names},
                "velocities": {n: V[:, self.index[n]] for n in names},
                "accelerations": {n: A[:, self.index[n]] for n in names}}


__all__ = ["PylinkageModel", "available", "has_numba"]
