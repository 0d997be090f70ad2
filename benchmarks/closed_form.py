"""The limit: the press as a crank–slider written out in closed form with numpy.

A hand-written solver of one mechanism — no model, no dyads, no bookkeeping — is as fast
as numpy gets on this problem: it is the yardstick of "near the limit" (issue 21). It
does the same work as graphplan's full cycle on the press, every load kept:

* positions: ``A = O + r·e^{iφ}``; B on the guide (point G, unit u) at
  ``s = u·(A − G) + b·√(l² − e²)``, e the offset of A from the guide, b the branch;
* velocities and accelerations from the vector equations ``v_B = v_A + iω2·AB = ṡ·u``
  and ``a_B = a_A + (iε2 − ω2²)·AB = s̈·u`` by Cramer's rule; ``S2 = A + f·AB``;
* loads: the weights, the inertia forces ``−m·a_S`` and couple ``−I_S·ε2``, and the
  technological force on the slider, against its motion on the working stroke, of
  size ``Q_max·diagram(x)`` (x the travel from the start of that stroke, as a fraction);
* reactions of the group 2–3 (ΣF of both links, ΣM of the rod about B) and the
  balancing moment ``Mур = (A − O)×R12``.

:func:`check` proves it computes what graphplan computes (Mур and the reactions against
graphplan's, every load kept, to 1e-9 of the cycle's largest).
"""

from __future__ import annotations

import math

import numpy as np


class CrankSlider:
    """The press's data, read once from graphplan's model (not timed)."""

    def __init__(self, mech):
        cr = mech.crank
        (d,) = mech.dyads
        if d.kind != "RRP" or len(mech.dyads) != 1:
            raise ValueError("the closed form is written for a one-dyad crank–slider")
        g = d.guides[0]
        self.O = complex(*mech.frame_points[cr.pivot])
        self.r, self.w = cr.length, cr.omega
        self.l = d.lengths[0]
        self.G = complex(*g.xy)
        self.u = complex(math.cos(g.angle), math.sin(g.angle))
        self.branch = float(d.branch)
        s2 = next(p for p in mech.points if p.name == mech.links["2"].centre)
        self.f = s2.fraction
        self.m2, self.I2 = mech.links["2"].mass, mech.links["2"].inertia
        self.m3 = mech.links["3"].mass
        self.g = complex(*mech.gravity)
        (res,) = mech.resistances
        self.q_max = res.maximum
        diagram = res.strokes[0]
        self.dx = np.array([x for x, _ in diagram])
        self.dy = np.array([y for _, y in diagram])
        working = float(res.working or mech.output.working)
        # the guide coordinate s at the two dead centres (A and B on one line)
        e0 = ((self.O - self.G) * self.u.conjugate()).imag
        s0 = ((self.O - self.G) * self.u.conjugate()).real
        far = s0 + self.branch * math.sqrt((self.l + self.r) ** 2 - e0 ** 2)
        near = s0 + self.branch * math.sqrt((self.l - self.r) ** 2 - e0 ** 2)
        lo, hi = min(far, near), max(far, near)
        # the working stroke runs along +u (working = +1) from lo to hi, or back
        self.start, self.span, self.working = (lo, hi - lo, 1.0) if working > 0 \
            else (hi, lo - hi, -1.0)

    def kinematics(self, phi):
        """Positions, velocities, accelerations of A, B, S2 and ω2, ε2, s, ṡ (complex)."""
        u, uc, w = self.u, self.u.conjugate(), self.w
        OA = self.r * np.exp(1j * phi)
        A = self.O + OA
        AG = (A - self.G) * uc
        s = AG.real + self.branch * np.sqrt(self.l ** 2 - AG.imag ** 2)
        B = self.G + s * u
        AB = B - A
        den = (AB * uc).real
        vA = 1j * w * OA
        w2 = -(vA * uc).imag / den
        vB = vA + 1j * w2 * AB
        aA = -w * w * OA
        e2 = -((aA - w2 * w2 * AB) * uc).imag / den
        aB = aA + (1j * e2 - w2 * w2) * AB
        f = self.f
        return {"A": A, "B": B, "S2": A + f * AB, "vA": vA, "vB": vB, "vS2": vA + f * (vB - vA),
                "aA": aA, "aB": aB, "aS2": aA + f * (aB - aA), "w2": w2, "e2": e2, "s": s,
                "ds": (vB * uc).real}

    def full_cycle(self, phi):
        """The kinematics, the loads, the reactions R12, R23, N43 and Mур."""
        k = self.kinematics(phi)
        A, B, S2 = k["A"], k["B"], k["S2"]
        x = (k["s"] - self.start) / self.span
        on = k["ds"] * self.working > 0  # the working stroke
        size = np.where(on, self.q_max * np.interp(x, self.dx, self.dy, 0.0, 0.0), 0.0)
        Q = -self.u * self.working * size  # against the motion
        F2 = self.m2 * (self.g - k["aS2"])
        F3 = self.m3 * (self.g - k["aB"]) + Q
        M2 = -self.I2 * k["e2"]
        n = 1j * self.u
        BA = A - B
        # ΣF of links 2 and 3: R12 + N·n + F2 + F3 = 0; ΣM of the rod about B
        F23 = F2 + F3
        N = (-(BA.conjugate() * F23).imag + ((S2 - B).conjugate() * F2).imag + M2) \
            / (BA.conjugate() * n).imag
        R12 = -F23 - N * n
        R23 = -(F3 + N * n)
        M_bal = ((A - self.O).conjugate() * R12).imag
        return {**k, "Q": Q, "R12": R12, "R23": R23, "N43": N, "M_bal": M_bal}


def check(mech, cycle, phi) -> dict:
    """Largest differences from graphplan's full cycle (every load kept), relative to the
    cycle's largest value of each."""
    from graphplan.forces import compute_loads, solve_forces
    from graphplan.kinematics import solve

    kin = solve(mech, phi)
    forces = solve_forces(mech, kin, compute_loads(mech, kin, cycle, neglect_below=0.0))
    got = CrankSlider(mech).full_cycle(phi)

    def rel(a, b):
        return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))

    def c(xy):
        return xy[:, 0] + 1j * xy[:, 1]

    return {"points": rel(got["B"], c(kin.pos.points["B"])),
            "accelerations": rel(got["aB"], c(kin.acc.points["B"])),
            "R12": rel(got["R12"], c(forces.vector("R12"))),
            "R23": rel(got["R23"], c(forces.vector("R23"))),
            "M_bal": rel(got["M_bal"], forces.M_bal)}


__all__ = ["CrankSlider", "check"]
