"""The kinematics of the lean full cycle: positions, velocities and accelerations generated
per dyad kind from the equations of :mod:`graphplan.kinematics` (see
:mod:`graphplan.forces.lean`)."""

from __future__ import annotations

import math
from collections.abc import Callable

from ..kinematics import slide_key, translating_links
from ..model import Mechanism
from .lean_code import Code, NotCompiled, Value


class KinematicsCode:
    """The kinematics being generated: positions, velocities, accelerations as Value."""

    def __init__(self, mech: Mechanism, g: Code, probe):
        self.mech, self.g, self.probe = mech, g, probe
        self.P: dict[str, Value] = {}
        self.V: dict[str, Value] = {}
        self.A: dict[str, Value] = {}
        self.W: dict[str, Value] = {}
        self.E: dict[str, Value] = {}
        self.axis: dict[str, Value] = {}    # unit vector of a link's reference axis
        self.theta: dict[str, Value] = {}
        self.guides: dict[str, tuple[Value, Value]] = {}
        self.SV: dict = {}               # sliding speeds by pair key (see sv)
        self.along: dict[str, Value] = {}   # an RRP slider's coordinate along its guide
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
        self.theta[cr.link] = Value("phi", kind="r")
        e1 = g.fn("exp", g.mul(g.K(1j), Value("phi", kind="r")), kind="c", bound=1.0)
        self.axis[cr.link] = e1
        self.P[cr.pin] = g.add(self.P[cr.pivot], g.mul(g.K(cr.length), e1))
        self._extra_points()
        for d in mech.dyads:
            getattr(self, f"_place_{d.kind}")(d)
            self._extra_points()
        missing = [p.name for p in mech.points if p.name not in self.P]
        if missing:
            raise NotCompiled(f"points not placed: {missing}")

    def theta_of(self, link: str) -> Value:
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
                    raise NotCompiled(f"point {p.name}: {p.origin}, {p.toward} on two links")
                dist = self.dist(p.origin, p.toward)
                if not dist > 0:
                    raise NotCompiled(f"point {p.name}: {p.origin} = {p.toward}")
                d = g.sub(self.P[p.toward], origin)
                if p.fraction is not None:
                    self.P[p.name] = g.add(origin, g.mul(d, g.K(p.fraction)))
                    continue
                u = g.mul(d, g.K(1.0 / dist))
            else:
                u = self.axis[p.link]
            self.P[p.name] = g.add(origin, g.mul(u, g.K(complex(p.along, p.across))))

    def _guide(self, gd) -> tuple[Value, Value]:
        g = self.g
        if gd.through is not None:
            base = self.P[gd.through]
        else:
            base = g.K(complex(float(gd.xy[0]), float(gd.xy[1])))
        if gd.toward is not None:
            if gd.through is None or not self.on_one_link(gd.through, gd.toward):
                raise NotCompiled("a guide toward a point of another link")
            dist = self.dist(gd.through, gd.toward)
            u = g.mul(g.sub(self.P[gd.toward], base), g.K(1.0 / dist))
        elif gd.link == self.mech.frame_link:
            u = g.K(g.unit(gd.angle))
        else:
            u = g.mul(self.axis[gd.link], g.K(g.unit(gd.angle)))
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
        g.check_min(dist, tiny, absolute=False)
        inv = g.div(g.K(1.0), dist)
        aa = g.mul(g.add(g.mul(dist, dist), g.K(l1 * l1 - l2 * l2)), g.mul(inv, g.K(0.5)))
        h2 = g.sub(g.K(l1 * l1), g.mul(aa, aa))
        g.refuse(f"{g.ref(h2)} < 0")
        e = g.mul(dv, inv)
        g.within(e, 2.0)  # (bounds with a margin of 2 for round-off: |e| = 1, |AB| = l1)
        B = g.add(A, g.mul(e, g.add(aa, g.mul(g.K(1j * s), g.sqrt(h2)))))
        g.within(B, A.bound + 2 * l1)
        self.P[b] = B
        self.axis[i] = g.mul(g.sub(B, A), g.K(1.0 / l1))
        self.axis[j] = g.mul(g.sub(B, C), g.K(1.0 / l2))
        g.within(self.axis[i], 2.0)
        g.within(self.axis[j], 2.0)

    def _place_RRP(self, d) -> None:
        g = self.g
        a, b = d.joints
        i, j = d.links
        (l1,) = d.lengths
        s = float(d.branch)
        G, u = self._guide(d.guides[0])
        cw = g.mul(g.conj(u), g.sub(self.P[a], G))
        h = g.im(cw)
        g.refuse(f"{g.ref(g.abs(h))} > {g.lit(l1)}")
        root = g.sqrt(g.sub(g.K(l1 * l1), g.mul(h, h)))
        along = g.add(g.re(cw), g.mul(g.K(s), root))
        B = g.add(G, g.mul(u, along))
        self.P[b] = B
        self.along[slide_key(j, d.guides[0].link)] = along  # (B − G)·u
        self.axis[i] = g.within(g.mul(g.sub(B, self.P[a]), g.K(1.0 / l1)), 2.0)
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
        g.check_min(dist2, tol * tol + e * e, absolute=False)
        if e == 0:
            dist = g.sqrt(dist2)
            g.set_low(dist, math.sqrt(g.low(dist2)))
            u = g.mul(g.div(dv, dist), g.K(s))
            self.dyad[d.name] = {"r_abs": dist}
        else:
            along = g.mul(g.K(s), g.sqrt(g.sub(dist2, g.K(e * e))))
            u = g.div(g.mul(dv, g.add(along, g.K(-1j * e))), dist2)
            self.dyad[d.name] = {"r_abs": g.sqrt(dist2)}
        self.axis[i] = self.axis[j] = g.within(u, 2.0)  # a unit vector
        self.guides[slide_key(i, j)] = (g.add(self.P[c], g.mul(u, g.K(1j * e))), u)

    def _place_PRP(self, d) -> None:
        g = self.g
        (b,) = d.joints
        i, j = d.links
        G1, u1 = self._guide(d.guides[0])
        G2, u2 = self._guide(d.guides[1])
        den = g.cross(u1, u2)
        if den.const is None:
            g.check_min(den, 1e-12)
        else:
            g.check(repr(abs(den.const) > 1e-12))
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
        w = g.mul(u, g.K(g.unit(d.slot_angle)))
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

    def _rigid_v(self, p) -> Value:
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

    def _lines(self, d, c1: Value, c2: Value, n1, n2) -> dict:
        """The dyad's two lines: ``det = c1×c2`` (checked against the lock-up, |c1|·|c2|
        = n1·n2) and its reciprocal, shared by the velocity and acceleration solves."""
        g = self.g
        det = g.cross(c1, c2)
        scale = g.mul(n1, n2)
        if scale.const is not None:
            g.check_min(det, 1e-9 * scale.const)
        else:
            g.refuse(f"{g.ref(g.abs(det))} <= {g.ref(scale)} * {g.lit(1e-9)}")
            g.set_low(det, 1e-9 * g.low(n1) * g.low(n2))
        info = {"c1": c1, "c2": c2, "cc1": g.conj(c1), "inv": g.div(g.K(1.0), det)}
        stored = self.dyad.setdefault(d.name, {})
        stored.update(info)
        return stored

    def _solve2(self, info, rhs: Value) -> tuple[Value, Callable[[], Value]]:
        """``x1·c1 + x2·c2 = rhs`` by Cramer's rule: x1, and x2 as a function that
        generates it when it is asked for (a sliding speed only where it is read)."""
        g = self.g
        x1 = g.mul(g.cross(rhs, info["c2"]), info["inv"])
        return x1, lambda: g.mul(g.im(g.mul(info["cc1"], rhs)), info["inv"])

    def sv(self, key: str) -> Value:
        """The sliding speed of a pair (generated on first use)."""
        x = self.SV[key]
        if not isinstance(x, Value):
            x = self.SV[key] = x()
        return x

    def _coincident_v(self, gd, X: Value) -> Value:
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
        self._factor: dict[str, Value] = {}
        self._extra_rates(self.A, self.E, self._rigid_a)
        for d in mech.dyads:
            getattr(self, f"_acc_{d.kind}")(d)
            self._extra_rates(self.A, self.E, self._rigid_a)

    def _w2(self, link: str) -> Value:
        return self.g.mul(self.W[link], self.W[link])

    def _rigid_a(self, p) -> Value:
        g = self.g
        if p.link not in self._factor:  # iε − ω², once per link
            self._factor[p.link] = g.sub(g.mul(g.K(1j), self.E[p.link]), self._w2(p.link))
        return g.add(self.A[p.origin],
                     g.mul(g.sub(self.P[p.name], self.P[p.origin]), self._factor[p.link]))

    def _rigid(self, a_base: Value, link: str, r: Value) -> Value:
        """``a_base + ε·k×r − ω²·r``."""
        g = self.g
        return g.add(a_base, g.sub(g.mul(g.mul(g.K(1j), r), self.E[link]),
                                   g.mul(r, self._w2(link))))

    def _coincident_a(self, gd, X: Value) -> Value:
        if gd.through is None:
            return self.g.K(0.0)
        return self._rigid(self.A[gd.through], gd.link, self.g.sub(X, self.P[gd.through]))

    def _coriolis(self, link: str, key: str, u: Value) -> Value:
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


__all__ = ["KinematicsCode"]
