"""The methods the benchmark compares, each run over a list of crank angles.

Every method returns a :class:`Result`: per named point its positions, velocities and
accelerations ((N, 2), SI), and where the method does forces the reactions (by
graphplan's names, (N, 2)) and the balancing moment Mур (N,). Positions the method does
not compute are absent.

* ``graphplan analytic`` — the vectorised solver: :func:`graphplan.kinematics.exact.solve`,
  :func:`graphplan.forces.loads.compute_loads` (nothing neglected), and
  :func:`graphplan.forces.kinetostatics.solve_forces`;
* ``graphplan constructions`` — the plans built as constructions and read back
  (velocity and acceleration plans, force plans of the groups and the crank, Zhukovsky's
  lever), read exactly or rounded to a drafting precision, at the sheet's scales or
  magnified; the plan of positions is the solver's (a construction reads its directions
  off it exactly), so their positions are not a separate figure;
* ``newton`` and the pylinkage peers: :mod:`benchmarks.newton`, :mod:`benchmarks.peers`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np


@dataclass
class Result:
    """What one method computed at the angles ``phi``."""

    phi: np.ndarray
    points: dict = field(default_factory=dict)
    velocities: dict = field(default_factory=dict)
    accelerations: dict = field(default_factory=dict)
    reactions: dict | None = None
    M_bal: np.ndarray | None = None
    M_bal_lever: np.ndarray | None = None


def analytic(mech, cycle, phi) -> Result:
    """graphplan's vectorised solver, kinematics and kinetostatics (nothing neglected)."""
    from graphplan.forces import compute_loads, solve_forces
    from graphplan.kinematics import solve

    kin = solve(mech, phi)
    forces = solve_forces(mech, kin, compute_loads(mech, kin, cycle, neglect_below=0.0))
    moving = {n: v for n, v in kin.pos.points.items() if n not in mech.frame_points}
    return Result(np.asarray(phi), dict(moving),
                  {n: kin.vel.points[n] for n in moving},
                  {n: kin.acc.points[n] for n in moving},
                  {n: r.vector for n, r in forces.reactions.items()}, forces.M_bal)


def full_cycle(mech, cycle, phi):
    """The timed unit of the target: kinematics + kinetostatics with the variant's settings."""
    from graphplan.forces import compute_loads, solve_forces
    from graphplan.kinematics import solve

    kin = solve(mech, phi)
    return solve_forces(mech, kin, compute_loads(mech, kin, cycle))


def kinematics_only(mech, phi):
    from graphplan.kinematics import solve

    return solve(mech, phi)


@dataclass(frozen=True)
class Drafting:
    """A setting of the constructions: reading precision (mm; 0 exact) and magnification."""

    precision: float = 0.0
    magnify: float = 1.0

    @property
    def name(self) -> str:
        if self.precision == 0:
            return "graphplan constructions, exact"
        return f"drafting {self.precision:g} mm, scale ×{self.magnify:g}"


class Constructions:
    """The plans of one mechanism at the angles ``phi``, built per position.

    The exact kinematics, loads and reactions (needed by the constructions as the plan of
    positions and the known loads) and the sheet's scales are computed once.
    """

    def __init__(self, mech, cycle, phi):
        from graphplan.forces import compute_loads, solve_forces
        from graphplan.kinematics import solve, sweep
        from graphplan.project import sheet_scales

        self.mech = mech
        self.phi = np.asarray(phi)
        self.kin = solve(mech, phi)
        self.loads = compute_loads(mech, self.kin, cycle, neglect_below=0.0)
        self.forces = solve_forces(mech, self.kin, self.loads)
        self.scales = sheet_scales(mech, sweep(mech, cycle))
        self.names = [n for n in self.kin.pos.points if n not in mech.frame_points
                      and n.lower() not in ("p", "π")]

    def scales_for(self, magnify: float):
        sc = self.scales

        def mag(s):
            return replace(s, per_mm=s.per_mm / magnify)

        return mag(sc.kl), mag(sc.kv), mag(sc.ka)

    def position(self, k: int, setting: Drafting, forces: bool = True):
        """Velocities, accelerations (by point), reactions and Mур (plans, lever) at k."""
        from graphplan.plans import (
            Reader,
            acceleration_plan,
            force_plans,
            velocity_plan,
            zhukovsky_lever,
        )

        reader = Reader(setting.precision)
        kl, kv, ka = self.scales_for(setting.magnify)
        vp = velocity_plan(self.mech, self.kin, k, kl, kv, reader)
        ap = acceleration_plan(self.mech, self.kin, k, kl, ka, vp, reader)
        vel = {n: vp.points[n.lower()] * kv.per_mm for n in self.names if n.lower() in vp.points}
        acc = {n: ap.points[n.lower()] * ka.per_mm for n in self.names if n.lower() in ap.points}
        if not forces:
            return vel, acc, None, None, None
        plans = force_plans(self.mech, self.kin, self.forces, self.loads, k, kl, reader,
                            room_mm=150.0 * setting.magnify)
        reactions = {}
        mbal = None
        for p in plans:
            for name, r in p.reactions.items():
                reactions[name] = np.asarray(r.vector, float)
            if p.M_bal is not None:
                mbal = p.M_bal
        lever = zhukovsky_lever(self.mech, self.kin, self.loads, k, kl, kv, reader)
        return vel, acc, reactions, mbal, lever.M_bal

    def run(self, setting: Drafting, which=None, forces: bool = True) -> Result:
        """All positions (or the indices ``which``)."""
        ks = range(len(self.phi)) if which is None else which
        n = len(ks)
        res = Result(self.phi[list(ks)])
        res.reactions = {} if forces else None
        mb, ml = np.zeros(n), np.zeros(n)
        for j, k in enumerate(ks):
            vel, acc, reac, m, lever = self.position(k, setting, forces)
            for nm, v in vel.items():
                res.velocities.setdefault(nm, np.zeros((n, 2)))[j] = v
            for nm, a in acc.items():
                res.accelerations.setdefault(nm, np.zeros((n, 2)))[j] = a
            if forces:
                for nm, r in reac.items():
                    res.reactions.setdefault(nm, np.zeros((n, 2)))[j] = r
                mb[j], ml[j] = m, lever
        if forces:
            res.M_bal, res.M_bal_lever = mb, ml
        return res


# ---------------------------------------------------------------- errors against the reference


def _vec(ref_pairs):
    return np.array([[float(x), float(y)] for x, y in ref_pairs])


def reference_arrays(ref) -> dict:
    """The reference as float arrays (for the comparison; its error is far below float's)."""
    out = {"points": {}, "velocities": {}, "accelerations": {}, "reactions": {}, "M_bal": None}
    for key, attr in (("points", "points"), ("velocities", "velocities"),
                      ("accelerations", "accelerations")):
        names = ref.states[0].__getattribute__(attr).keys()
        for n in names:
            out[key][n] = _vec([getattr(s, attr)[n] for s in ref.states])
    if ref.reactions:
        for n in ref.reactions[0]:
            out["reactions"][n] = _vec([r[n] for r in ref.reactions])
        out["M_bal"] = np.array([float(m) for m in ref.M_bal])
    return out


def _rel(values: dict, reference: dict, origin=None) -> float | None:
    """max |x − x_ref| over positions and items / max |x_ref| (vectors by their length)."""
    common = [n for n in values if n in reference]
    if not common:
        return None
    num = 0.0
    den = 0.0
    for n in common:
        x, r = np.asarray(values[n], float), np.asarray(reference[n], float)
        d = x - r
        num = max(num, float(np.max(np.hypot(d[..., 0], d[..., 1]) if d.ndim == 2
                                    else np.abs(d))))
        rr = r - origin if origin is not None else r
        den = max(den, float(np.max(np.hypot(rr[..., 0], rr[..., 1]) if rr.ndim == 2
                                    else np.abs(rr))))
    return num / den if den > 0 else None


def errors(result: Result, ref: dict, pivot) -> dict:
    """Relative errors of each kind of figure (None where the method has none)."""
    out = {
        "positions": _rel(result.points, ref["points"], np.asarray(pivot, float)),
        "velocities": _rel(result.velocities, ref["velocities"]),
        "accelerations": _rel(result.accelerations, ref["accelerations"]),
        "reactions": None,
        "M_bal": None,
        "M_bal_lever": None,
    }
    if result.reactions is not None and ref["reactions"]:
        out["reactions"] = _rel(result.reactions, ref["reactions"])
    if result.M_bal is not None and ref["M_bal"] is not None:
        out["M_bal"] = _rel({"M": result.M_bal}, {"M": ref["M_bal"]})
    if result.M_bal_lever is not None and ref["M_bal"] is not None:
        out["M_bal_lever"] = _rel({"M": result.M_bal_lever}, {"M": ref["M_bal"]})
    return out


def errors_per_position(result: Result, ref: dict, kind: str) -> np.ndarray:
    """Per position: max over items of |x − x_ref|, relative to the cycle's max |x_ref|."""
    values = getattr(result, kind) if kind != "M_bal" else {"M": result.M_bal}
    reference = ref[kind] if kind != "M_bal" else {"M": ref["M_bal"]}
    common = [n for n in values if n in reference]
    num = np.zeros(len(result.phi))
    den = 0.0
    for n in common:
        d = np.asarray(values[n], float) - np.asarray(reference[n], float)
        e = np.hypot(d[:, 0], d[:, 1]) if d.ndim == 2 else np.abs(d)
        num = np.maximum(num, e)
        r = np.asarray(reference[n], float)
        den = max(den, float(np.max(np.hypot(r[:, 0], r[:, 1]) if r.ndim == 2 else np.abs(r))))
    return num / den if den else num


__all__ = ["Constructions", "Drafting", "Result", "analytic", "errors", "errors_per_position",
           "full_cycle", "kinematics_only", "reference_arrays"]
