"""A generic numerical solver: Newton iteration on the loop-closure equations.

What a general-purpose multibody code does, written for the benchmark: the unknowns of
all dyads at once (the new joint of an RRR or RRP dyad, the rocker's angle of an RPR
one), the constraint equations

* RRR  ``(|B − A|² − l1²)/2l1 = 0``, ``(|B − C|² − l2²)/2l2 = 0``
* RRP  ``(|B − A|² − l²)/2l = 0``, ``(B − G)×u = 0`` (B on the guide)
* RPR  ``u(θ)×(A − C) − e = 0`` (the slot axis through A)

solved position after position by Newton's method from the previous solution
(continuation; the first from the variant's drawing, perturbed by 1 % of the crank),
the Jacobian by complex steps. Velocities from ``Φ_q·q̇ = −Φ_φ·ω1``; accelerations
from ``Φ_q·q̈ = −(d²Φ/dt²)|q̈=0``, that term by a central second difference along the
motion (step 1e-4/ω1) — the usual weak point of generic codes, and what limits
their acceleration accuracy to ~1e-8. Reactions and Mур from the whole mechanism's
equilibrium (:func:`benchmarks.reference.equilibrium_system`) in float64.
"""

from __future__ import annotations

import cmath
import math

import numpy as np

from . import reference as ref

H_CS = 1e-30
"""Complex step (exact first derivatives)."""


def _c2(x, y):
    return (x, y)


class LoopModel:
    """The loop equations and point functions of a mechanism (RRR, RRP, RPR dyads)."""

    def __init__(self, mech):
        self.mech = mech
        size = 0
        self.slots = []
        for d in mech.dyads:
            if d.kind in ("RRR", "RRP"):
                self.slots.append((size, 2))
                size += 2
            elif d.kind == "RPR":
                self.slots.append((size, 1))
                size += 1
            else:
                raise NotImplementedError(f"newton: dyad kind {d.kind}")
        self.n = size

    # Every function below takes q (sequence) and phi and works on real or complex numbers.
    def geometry(self, q, phi):
        """Points {name: (x, y)}, link directions {link: (dx, dy)}, guides, residuals."""
        m = self.mech
        pts = {n: (xy[0], xy[1]) for n, xy in m.frame_points.items()}
        axis = {m.frame_link: (1.0, 0.0)}
        guides = {}
        res = []
        cr = m.crank
        o = pts[cr.pivot]
        pts[cr.pin] = (o[0] + cr.length * cmath.cos(phi), o[1] + cr.length * cmath.sin(phi))
        axis[cr.link] = (pts[cr.pin][0] - o[0], pts[cr.pin][1] - o[1])
        self._points(pts, axis)
        for d, (k, _) in zip(m.dyads, self.slots, strict=True):
            i, j = d.links
            if d.kind == "RRR":
                a, b, c = d.joints
                A, C = pts[a], pts[c]
                B = (q[k], q[k + 1])
                l1, l2 = d.lengths
                res.append(((B[0] - A[0]) ** 2 + (B[1] - A[1]) ** 2 - l1**2) / (2 * l1))
                res.append(((B[0] - C[0]) ** 2 + (B[1] - C[1]) ** 2 - l2**2) / (2 * l2))
                pts[b] = B
                axis[i] = (B[0] - A[0], B[1] - A[1])
                axis[j] = (B[0] - C[0], B[1] - C[1])
            elif d.kind == "RRP":
                a, b = d.joints
                A = pts[a]
                B = (q[k], q[k + 1])
                (l1,) = d.lengths
                G, u = self._guide(d.guides[0], pts, axis)
                res.append(((B[0] - A[0]) ** 2 + (B[1] - A[1]) ** 2 - l1**2) / (2 * l1))
                res.append((B[0] - G[0]) * u[1] - (B[1] - G[1]) * u[0])
                pts[b] = B
                axis[i] = (B[0] - A[0], B[1] - A[1])
                axis[j] = u
                guides[f"{j}/{d.guides[0].link}"] = (G, u)
            else:  # RPR
                a, c = d.joints
                A, C = pts[a], pts[c]
                th = q[k]
                u = (cmath.cos(th), cmath.sin(th))
                res.append(u[0] * (A[1] - C[1]) - u[1] * (A[0] - C[0]) - d.offset)
                axis[i] = axis[j] = u
                guides[f"{i}/{j}"] = ((C[0] - d.offset * u[1], C[1] + d.offset * u[0]), u)
            self._points(pts, axis)
        return pts, axis, guides, res

    def _guide(self, g, pts, axis):
        base = pts[g.through] if g.through is not None else g.xy
        if g.toward is not None:
            d = (pts[g.toward][0] - base[0], pts[g.toward][1] - base[1])
        else:
            ax = axis[g.link]
            c, s = math.cos(g.angle), math.sin(g.angle)
            d = (ax[0] * c - ax[1] * s, ax[0] * s + ax[1] * c)
        nd = cmath.sqrt(d[0] ** 2 + d[1] ** 2)
        return base, (d[0] / nd, d[1] / nd)

    def _points(self, pts, axis):
        for p in self.mech.points:
            if p.name in pts or p.link not in axis or p.origin not in pts:
                continue
            if p.toward is not None and p.toward not in pts:
                continue
            o = pts[p.origin]
            if p.toward is not None:
                d = (pts[p.toward][0] - o[0], pts[p.toward][1] - o[1])
                dist = cmath.sqrt(d[0] ** 2 + d[1] ** 2)
                u = (d[0] / dist, d[1] / dist)
                along = p.fraction * dist if p.fraction is not None else p.along
            else:
                ax = axis[p.link]
                na = cmath.sqrt(ax[0] ** 2 + ax[1] ** 2)
                u = (ax[0] / na, ax[1] / na)
                along = p.along
            pts[p.name] = (o[0] + u[0] * along - u[1] * p.across,
                           o[1] + u[1] * along + u[0] * p.across)

    def residual(self, q, phi):
        return self.geometry(q, phi)[3]


def _real(z):
    return z.real if isinstance(z, complex) else z


def _jacobian(model: LoopModel, q, phi):
    """Φ_q and Φ_φ by complex steps."""
    n = model.n
    J = np.empty((n, n))
    for c in range(n):
        qc = [complex(x) for x in q]
        qc[c] += 1j * H_CS
        J[:, c] = [r.imag / H_CS for r in model.residual(qc, phi)]
    dphi = np.array([r.imag / H_CS for r in model.residual(list(q), phi + 1j * H_CS)])
    return J, dphi


def solve_positions(model: LoopModel, phis, q0, tol=1e-14, max_iter=30):
    """Newton at every angle, each started from the previous solution."""
    qs = np.empty((len(phis), model.n))
    q = np.array(q0, float)
    iters = []
    for k, phi in enumerate(phis):
        for it in range(max_iter):  # noqa: B007 (its last value is counted)
            r = np.array([_real(x) for x in model.residual(q, phi)])
            J, _ = _jacobian(model, q, phi)
            dq = np.linalg.solve(J, -r)
            q = q + dq
            if np.max(np.abs(dq)) < tol * (1 + np.max(np.abs(q))):
                break
        iters.append(it + 1)
        qs[k] = q
    return qs, iters


def initial_guess(model: LoopModel, kin, k: int):
    """The variant's drawing at position k (graphplan's assembly), perturbed by 1 % of l_OA."""
    m = model.mech
    q = []
    for d in m.dyads:
        if d.kind in ("RRR", "RRP"):
            b = d.joints[1]
            q += list(kin.pos.points[b][k])
        else:
            q.append(float(kin.pos.theta[d.links[1]][k]))
    q = np.asarray(q, float)
    return q + 0.01 * m.crank.length * np.where(np.arange(len(q)) % 2, 1.0, -1.0)


def kinematics(model: LoopModel, phis, q0):
    """Positions, velocities, accelerations of every point and ω, ε of every link."""
    m = model.mech
    w1 = m.crank.omega
    qs, iters = solve_positions(model, phis, q0)
    h = 1e-4 / abs(w1)
    P, V, A = {}, {}, {}
    W, E = {}, {}
    G = {}
    for k, phi in enumerate(phis):
        q = qs[k]
        J, dphi = _jacobian(model, q, phi)
        qd = np.linalg.solve(J, -dphi * w1)
        rp = np.array([_real(x) for x in model.residual(q + h * qd, phi + h * w1)])
        rm = np.array([_real(x) for x in model.residual(q - h * qd, phi - h * w1)])
        r0 = np.array([_real(x) for x in model.residual(q, phi)])
        gamma = -(rp - 2 * r0 + rm) / h**2
        qdd = np.linalg.solve(J, gamma)
        pts, axis, guides, _ = model.geometry(list(q), phi)
        cs, _, _, _ = _geom_c(model, q + 1j * H_CS * qd, phi + 1j * H_CS * w1)
        ax_v = _geom_c(model, q + 1j * H_CS * qd, phi + 1j * H_CS * w1)[1]
        cq, ax_q = _geom_c(model, q + 1j * H_CS * qdd, phi)[:2]
        pp, axp = model.geometry(list(q + h * qd), phi + h * w1)[:2]
        pm, axm = model.geometry(list(q - h * qd), phi - h * w1)[:2]
        for n, xy in pts.items():
            P.setdefault(n, np.empty((len(phis), 2)))[k] = [_real(xy[0]), _real(xy[1])]
            V.setdefault(n, np.empty((len(phis), 2)))[k] = [cs[n][0].imag / H_CS,
                                                             cs[n][1].imag / H_CS]
            sec = [(_real(pp[n][c]) - 2 * _real(xy[c]) + _real(pm[n][c])) / h**2 for c in (0, 1)]
            A.setdefault(n, np.empty((len(phis), 2)))[k] = [cq[n][c].imag / H_CS + sec[c]
                                                             for c in (0, 1)]
        for ln, d in axis.items():
            dx, dy = _real(d[0]), _real(d[1])
            ddx, ddy = ax_v[ln][0].imag / H_CS, ax_v[ln][1].imag / H_CS
            sec = [(_real(axp[ln][c]) - 2 * _real(d[c]) + _real(axm[ln][c])) / h**2
                   for c in (0, 1)]
            d2x = ax_q[ln][0].imag / H_CS + sec[0]
            d2y = ax_q[ln][1].imag / H_CS + sec[1]
            n2 = dx * dx + dy * dy
            om = (dx * ddy - dy * ddx) / n2
            W.setdefault(ln, np.empty(len(phis)))[k] = om
            E.setdefault(ln, np.empty(len(phis)))[k] = ((dx * d2y - dy * d2x) / n2
                                                        - 2 * (dx * ddx + dy * ddy) * om / n2)
        for key, (_, u) in guides.items():
            G.setdefault(key, np.empty((len(phis), 2)))[k] = [_real(u[0]), _real(u[1])]
    return {"points": P, "velocities": V, "accelerations": A, "omega": W, "epsilon": E,
            "guides": G, "iterations": iters}


def _geom_c(model, q, phi):
    return model.geometry([complex(x) for x in q], complex(phi))


def forces(model: LoopModel, kin: dict, cycle, phis):
    """Reactions and Mур from the whole mechanism's equilibrium, float64, every position."""
    m = model.mech
    prs = ref.pairs(m)
    out_r = {p.name: np.empty((len(phis), 2)) for p in prs}
    out_m = np.empty(len(phis))
    g = m.gravity
    for k, phi in enumerate(phis):
        pts = {n: tuple(a[k]) for n, a in kin["points"].items()}
        guides = {key: (None, tuple(u[k])) for key, u in kin["guides"].items()}
        F = {ln: [] for ln in m.moving_links}
        C = {ln: [] for ln in m.moving_links}
        for ln in m.moving_links:
            props = m.links.get(ln)
            if props is None or props.centre is None:
                continue
            S = props.centre
            if props.mass:
                aS = kin["accelerations"][S][k]
                F[ln].append(((props.mass * g[0], props.mass * g[1]), pts[S]))
                F[ln].append(((-props.mass * aS[0], -props.mass * aS[1]), pts[S]))
            if props.inertia:
                C[ln].append(-props.inertia * kin["epsilon"][ln][k])
        _resistance(m, kin, cycle, k, phi, pts, guides, F, C)
        _, A, b = ref.equilibrium_system(m, pts, guides, F, C)
        x = np.linalg.solve(np.array(A, float), np.array(b, float))
        R, M = ref.unpack(prs, x, guides)
        for name, vec in R.items():
            out_r[name][k] = vec
        out_m[k] = M
    return out_r, out_m


def _resistance(m, kin, cycle, k, phi, pts, guides, F, C):
    if not m.resistances:
        return
    from graphplan.forces import diagram_value

    kind, what, key = ref._output(m)
    if kind == "slider":
        # q along the frame guide: the guide's point is fixed, so any point of it will do
        g = next(d.guides[0] for d in m.dyads if f"{d.links[1]}/{m.frame_link}" == key)
        G = g.xy if g.xy is not None else pts[g.through]
        u = guides[key][1]
        q = (pts[what][0] - G[0]) * u[0] + (pts[what][1] - G[1]) * u[1]
    else:
        ax = kin["axis_angle"][what][k] if "axis_angle" in kin else None
        d = np.arctan2(*reversed(_axis_of(kin, m, what, k))) if ax is None else ax
        mid = 0.5 * (cycle.q_start + cycle.q_end)
        q = d + 2 * math.pi * round((mid - d) / (2 * math.pi))
    span = cycle.q_end - cycle.q_start
    s = min(max((q - cycle.q_start) / span, 0.0), 1.0)
    sense = 1.0 if m.crank.omega > 0 else -1.0
    on = ((phi - cycle.dead_centres[0]) * sense) % (2 * math.pi) < cycle.working_turn
    w = m.output.working
    for res in m.resistances:
        size = float(diagram_value(res.diagram, np.array([s]))[0]) * res.maximum if on else 0.0
        if res.kind == "force":
            u = guides[f"{res.link}/{m.frame_link}"][1]
            F[res.link].append(((-w * size * u[0], -w * size * u[1]), pts[res.point]))
        else:
            C[res.link].append(-w * size)


def _axis_of(kin, m, link, k):
    for d in m.dyads:
        if link in d.links and d.kind == "RRR":
            a, b, c = d.joints
            base = a if link == d.links[0] else c
            return kin["points"][b][k] - kin["points"][base][k]
    raise NotImplementedError(link)


__all__ = ["LoopModel", "forces", "initial_guess", "kinematics", "solve_positions"]
