"""What graphplan says each figure should be: its exact results, and a few wrong models.

A :class:`Reference` runs graphplan on the student's variant once —
:func:`graphplan.project.analysis.analyze` (kinematics of every position),
:func:`graphplan.forces.loads.compute_loads` and
:func:`graphplan.forces.kinetostatics.solve_forces` (loads, reactions, Mур), the velocity and
acceleration plans of :mod:`graphplan.plans.constructions` at the student's own scales — and
answers :meth:`Reference.value`: the physical value (SI) of a quantity's key at a position
under a *model*:

``rule``
    the variant's model (its neglect rule): what the student should have;
``full``
    nothing neglected (a student who keeps a small load is not wrong);
``reversed``
    every inertia force and moment reversed (Pи = +m·a): the classic sign error;
``no-inertia``
    inertia left out.

Nothing of the mechanics is computed here: the values are graphplan's, only picked,
measured (arms on the position plan) and divided by the student's scales.

The pseudo-position ``max`` stands for the largest magnitude over one turn (a fine grid
of :data:`MAX_GRID` crank angles), for figures such as "the largest inertia force".
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import cached_property

import numpy as np

from ..forces import Forces, Loads, compute_loads, reaction_name, solve_forces
from ..kinematics import solve
from ..model import Mechanism, load
from ..project import Sheet1Scales, analyze, sheet_scales
from .quantities import Key, Quantity, Vocabulary
from .units import fold

MAX_GRID = 360
"""Crank angles of the grid over which the pseudo-position ``max`` takes its maxima."""

MODELS = ("rule", "full", "reversed", "no-inertia")


def _reverse_inertia(loads: Loads) -> Loads:
    fs = {ln: tuple(replace(f, vector=-f.vector) if f.kind == "inertia" else f for f in v)
          for ln, v in loads.forces.items()}
    ms = {ln: tuple(replace(m, moment=-m.moment) if m.kind == "inertia" else m for m in v)
          for ln, v in loads.moments.items()}
    return replace(loads, forces=fs, moments=ms)


class Reference:
    """graphplan's results for one variant, at its positions and at the student's extra ones.

    Parameters
    ----------
    mech : Mechanism
    extra : dict[str, float]
        Labels → crank angles (degrees) of positions the variant does not number.
    """

    def __init__(self, mech: Mechanism, extra: dict[str, float] | None = None):
        self.mech = mech
        self.analysis = analyze(mech)
        kin = self.analysis.kin
        extra = {k: v for k, v in (extra or {}).items() if k not in kin.labels}
        if extra:
            phi = np.concatenate([kin.phi, np.radians(list(extra.values()))])
            kin = solve(mech, phi, (*kin.labels, *extra))
        self.kin = kin
        self.cycle = self.analysis.cycle
        self.labels: tuple[str, ...] = kin.labels
        self._plans: dict = {}

    @classmethod
    def of(cls, variant, extra: dict[str, float] | None = None) -> Reference:
        """A reference for a variant file (or a loaded mechanism)."""
        mech = variant if isinstance(variant, Mechanism) else load(variant)
        return cls(mech, extra)

    # --- the models -------------------------------------------------------------------

    @cached_property
    def sheet1(self) -> Sheet1Scales:
        """Sheet 1's scales for these positions (the project's, or with the student's
        extra positions), solved once per reference."""
        if self.kin is self.analysis.kin:
            return self.analysis.sheet1
        return sheet_scales(self.mech, self.kin)

    @cached_property
    def loads(self) -> dict[str, Loads]:
        mech, kin, cy = self.mech, self.kin, self.cycle
        own = kin is self.analysis.kin  # the variant's positions: the project's loads
        rule = self.analysis.loads if own else compute_loads(mech, kin, cy)
        full = self.analysis.loads_full if own else compute_loads(mech, kin, cy, neglect_below=0.0)
        return {"rule": rule, "full": full,
                "reversed": _reverse_inertia(rule),
                "no-inertia": compute_loads(mech, kin, cy, inertia=False)}

    @cached_property
    def forces(self) -> dict[str, Forces]:
        return {m: solve_forces(self.mech, self.kin, ld) for m, ld in self.loads.items()}

    @cached_property
    def vocabulary_parts(self) -> tuple[dict[str, str], tuple[str, ...], tuple[str, ...]]:
        """Reading names of the plans, reaction names, load names (for a Vocabulary)."""
        from ..plans import acceleration_plan, velocity_plan
        from ..units import Scale

        k = 0
        kl = Scale("Kl", 1e-3, "m/mm")
        vp = velocity_plan(self.mech, self.kin, k, kl, Scale("Kv", 0.01, "(m/s)/mm"))
        ap = acceleration_plan(self.mech, self.kin, k, kl, Scale("Ka", 0.05, "(m/s²)/mm"), vp)
        readings = {r.name: r.quantity for r in (*vp.readings.values(), *ap.readings.values())}
        reactions = tuple(self.forces["rule"].reactions)
        names = tuple(f.name for f in self.loads["full"].all_forces()) + tuple(
            m.name for m in self.loads["full"].all_moments())
        return readings, reactions, names

    def vocabulary(self, arms=None) -> Vocabulary:
        """The names a student may use for this variant (with the declared arms)."""
        readings, reactions, loads = self.vocabulary_parts
        return Vocabulary(self.mech, readings, reactions, loads, arms)

    @cached_property
    def _max(self) -> tuple:
        """Kinematics, loads and forces on a fine grid over one turn (for ``max``)."""
        phi = self.kin.phi[0] + np.linspace(0.0, 2 * math.pi, MAX_GRID, endpoint=False)
        kin = solve(self.mech, phi)
        full = compute_loads(self.mech, kin, self.cycle, neglect_below=0.0)
        rule = compute_loads(self.mech, kin, self.cycle)
        return kin, {"rule": rule, "full": full}, {"rule": solve_forces(self.mech, kin, rule),
                                                  "full": solve_forces(self.mech, kin, full)}

    def index(self, label: str) -> int | None:
        """Index of a position label (``None`` if the variant has no such position)."""
        return self.labels.index(label) if label in self.labels else None

    # --- values -----------------------------------------------------------------------

    def point(self, name: str) -> str | None:
        """A point of the mechanism by name (look-alike letters folded)."""
        pts = self.kin.pos.points
        if name in pts:
            return name
        f = fold(name)
        hits = [p for p in pts if fold(p) == f] or [p for p in pts if fold(p).lower() ==
                                                    f.lower()]
        return hits[0] if len(hits) == 1 else None

    def value(self, key: Key, where: str | int, model: str = "rule") -> float | None:
        """The physical value (SI, a magnitude unless signed) of ``key`` at a position.

        ``where`` is a position index, a label, or ``"max"``; ``None`` when graphplan has
        no such value (an arm of a zero force, a key of another mechanism).
        """
        if where == "max":
            return self._max_value(key, model)
        k = where if isinstance(where, int) else self.index(where)
        if k is None:
            return None
        return self._value(key, k, self.kin, self.loads, self.forces, model)

    def _max_value(self, key: Key, model: str) -> float | None:
        if key[0] in ("mass", "weight", "g", "rpm", "omega1", "eps1", "inertia",
                      "resistance_max", "length", "time_ratio", "overlap_angle"):
            return self._value(key, 0, self.kin, self.loads, self.forces, model)
        kin, loads, forces = self._max
        model = model if model in loads else "rule"
        vals = [self._value(key, k, kin, loads, forces, model) for k in range(kin.n)]
        sizes = [abs(v) for v in vals if v is not None]
        return max(sizes) if sizes else None

    def _value(self, key: Key, k: int, kin, loads, forces, model: str) -> float | None:
        mech = self.mech
        what = key[0]
        P, V, A = kin.pos.points, kin.vel.points, kin.acc.points
        if what == "mass":
            return mech.links[key[1]].mass
        if what == "inertia":
            return mech.links[key[1]].inertia
        if what == "g":
            return float(np.hypot(*mech.gravity))
        if what == "weight":
            return mech.links[key[1]].mass * float(np.hypot(*mech.gravity))
        if what == "rpm":
            return mech.crank.rpm
        if what == "omega1":
            return abs(mech.crank.omega)
        if what == "eps1":
            return 0.0
        if what == "time_ratio":  # K = φ_working/φ_idle
            return float(self.cycle.time_ratio)
        if what == "overlap_angle":  # θ = 180°·(K − 1)/(K + 1)
            K = float(self.cycle.time_ratio)
            return 180.0 * (K - 1.0) / (K + 1.0)
        if what == "mbal_discrepancy":  # the student's own: see Checker
            return None
        if what == "resistance_max":
            return mech.resistances[0].maximum if mech.resistances else None
        if what == "length":
            return float(np.hypot(*(P[key[1]][k] - P[key[2]][k])))
        if what == "v":
            return float(np.hypot(*V[key[1]][k]))
        if what == "a":
            return float(np.hypot(*A[key[1]][k]))
        if what == "v_rel":
            return float(np.hypot(*(V[key[1]][k] - V[key[2]][k])))
        if what == "a_rel":
            return float(np.hypot(*(A[key[1]][k] - A[key[2]][k])))
        if what in ("a_n", "a_t"):
            link = self._common_link(key[1], key[2])
            if link is None:
                return None
            length = float(np.hypot(*(P[key[1]][k] - P[key[2]][k])))
            if what == "a_n":
                return float(kin.vel.omega[link][k]) ** 2 * length
            return abs(float(kin.acc.epsilon[link][k])) * length
        if what == "reading":  # a value of a plan (aᵏ_A3 …) at the reference positions
            if kin is not self.kin:
                return None
            return self.plan_value(key[1], k)
        if what == "omega":
            return abs(float(kin.vel.omega[key[1]][k]))
        if what == "eps":
            return abs(float(kin.acc.epsilon[key[1]][k]))
        ld = loads["full"] if "full" in loads else loads["rule"]
        if what == "inertia_force":
            f = self._load(ld, f"Pи{key[1]}")
            return None if f is None else float(np.hypot(*f.vector[k]))
        if what == "inertia_moment":
            m = next((m for m in ld.all_moments() if m.name == f"Mи{key[1]}"), None)
            return None if m is None else abs(float(m.moment[k]))
        if what == "resistance":
            f = self._load(ld, key[1])
            if f is not None:
                return float(np.hypot(*f.vector[k]))
            m = next((m for m in ld.all_moments() if m.name == key[1]), None)
            return None if m is None else abs(float(m.moment[k]))
        fs = forces.get(model) or forces["rule"]
        if what in ("reaction", "reaction_t", "reaction_n"):
            vec, r = self._reaction(fs, key[1], key[2], k)
            if vec is None:
                return None
            if what == "reaction":
                return float(np.hypot(*vec))
            return self._component(r, vec, k, kin, what == "reaction_n")
        if what == "crank_arm":
            name = reaction_name(key[1], mech.crank.link)
            arms = fs.crank_arms()
            return float(arms[name][k]) if name in arms else None
        if what == "M_bal":
            return float(fs.M_bal[k])
        if what == "arm":
            return self._arm(key[1], key[2], k, kin, ld, fs)
        return None

    @staticmethod
    def _load(loads: Loads, name: str):
        f = fold(name)
        return next((x for x in loads.all_forces() if fold(x.name) == f), None)

    def _common_link(self, p: str, q: str) -> str | None:
        for ln in self.mech.moving_links:
            pts = self.mech.points_of(ln)
            if p in pts and q in pts:
                return ln
        return None

    @staticmethod
    def _reaction(fs: Forces, i: str, j: str, k: int):
        for name, sign in ((f"R{i}{j}", 1.0), (f"R{j}{i}", -1.0)):
            if name in fs.reactions:
                r = fs.reactions[name]
                return sign * np.asarray(r.vector[k], float), r
        return None, None

    def _far_joint(self, r) -> tuple[str, str] | None:
        """(the dyad link, its other joint) of a revolute reaction ``r`` (its Rτ and Rn
        are taken across and along the line to it): a point the link shares with another
        link — a mass centre may stand at a joint, a piston's at its pin C, so centres are
        not left out. None for a pair of the frame and the crank, or a sliding pair."""
        link = next((ln for ln in (r.on, r.by) if ln != self.mech.frame_link and
                     ln != self.mech.crank.link), None)
        if link is None or r.pair != "R":
            return None
        own = self.mech.links[link].centre if link in self.mech.links else None
        shared = {p for ln in (*self.mech.moving_links, self.mech.frame_link) if ln != link
                  for p in self.mech.points_of(ln)}
        others = [p for p in self.mech.points_of(link) if p != r.point and p in shared] or [
            p for p in self.mech.points_of(link) if p != r.point and p != own]
        return (link, others[0]) if others else None

    def _component(self, r, vec, k, kin, normal: bool) -> float | None:
        """The part of a reaction along (normal) or across (tangential) its dyad link."""
        lf = self._far_joint(r)
        if lf is None:
            return None
        d = kin.pos.points[lf[1]][k] - kin.pos.points[r.point][k]
        u = d / float(np.hypot(*d))
        along = float(np.dot(vec, u))
        return abs(along) if normal else abs(float(vec[0] * u[1] - vec[1] * u[0]))

    def force_line(self, force: str, k: int, model: str = "rule", kin=None, loads=None,
                   forces=None):
        """Point (m) and vector (N) of a load or reaction by name at position k."""
        kin = kin or self.kin
        ld = (loads or self.loads)["full"]
        fs = (forces or self.forces).get(model) or (forces or self.forces)["rule"]
        f = self._load(ld, force)
        if f is not None:
            return np.asarray(f.at[k], float), np.asarray(f.vector[k], float)
        name = fold(force).replace("R", "R", 1)
        for r in fs.reactions.values():
            for nm, sign in ((r.name, 1.0), (reaction_name(r.on, r.by), -1.0)):
                if fold(nm) == name:
                    return np.asarray(r.at[k], float), sign * np.asarray(r.vector[k], float)
        return None

    def _arm(self, force: str, about: str, k: int, kin, loads, fs) -> float | None:
        pt = self.point(about)
        line = self.force_line(force, k, kin=kin, loads={"full": loads},
                               forces={"rule": fs})
        if pt is None or line is None:
            return None
        at, vec = line
        mag = float(np.hypot(*vec))
        if mag == 0:
            return None
        c = kin.pos.points[pt][k]
        return abs(float((at[0] - c[0]) * vec[1] - (at[1] - c[1]) * vec[0])) / mag

    def arm_limit(self, force: str, about: str, k: int) -> float | None:
        """The longest arm a force can have about a point: the distance from the point to
        the force's point of application (m)."""
        pt = self.point(about)
        line = self.force_line(force, k)
        if pt is None or line is None:
            return None
        return float(np.hypot(*(line[0] - self.kin.pos.points[pt][k])))

    # --- the student's own force analysis ---------------------------------------------

    def own_forces(self, k: int, sizes: dict[str, float], tangential: dict[str, float],
                   model: str = "rule", outer: dict[tuple[str, str], float] | None = None
                   ) -> tuple[Loads, Forces] | None:
        """The force analysis of position k as the student draws it: every load of
        ``sizes`` (name → the student's magnitude, N or N·m) at the student's size along
        graphplan's line of action, and every tangential reaction of ``tangential`` (name
        ``Rτ12`` → the student's magnitude) laid off as the student computed it.

        The force plans are solved group by group, the last group first, so a second
        group's reactions feed the first group and the crank (h21, Mур). A tangential
        reaction the student got wrong (``Rτ12`` from a wrong arm) is the plan closed
        with ``Rτ12' = Rτ12 + Δ``: the group's equilibrium with an extra couple
        ``C = −(r_A − r_B) × Δ`` on the link, which leaves every force sum as the
        student's polygon has it and makes the moment equation give ``Rτ12'``. A reaction
        of ``outer`` ((by, on) → the student's magnitude: ``("4", "2")`` for R42, a
        reaction the group solved first passes on to a later one) enters the later
        group at the student's size: an extra force ``Δ`` on ``on`` at the pair.
        Returns (loads, forces), or ``None`` when graphplan cannot solve it.
        """
        from ..errors import GraphplanError
        from ..forces import ForceLoad, MomentLoad

        base = self.loads[model if model in ("rule", "full") else "rule"]
        outer = outer or {}
        key = ("own", k, model, tuple(sorted(sizes.items())), tuple(sorted(tangential.items())),
               tuple(sorted(outer.items())))
        if key in self._plans:
            return self._plans[key]
        forces = {}
        for ln, fs in base.forces.items():
            out = []
            for f in fs:
                size = sizes.get(fold(f.name))
                mag = float(np.hypot(*f.vector[k]))
                if size is not None and mag > 0:
                    v = np.array(f.vector, float)
                    v[k] = v[k] * (size / mag)
                    f = replace(f, vector=v)
                out.append(f)
            forces[ln] = tuple(out)
        moments = {}
        for ln, ms in base.moments.items():
            out_m = []
            for m in ms:
                size = sizes.get(fold(m.name))
                if size is not None and m.moment[k] != 0:
                    mo = np.array(m.moment, float)
                    mo[k] = math.copysign(size, mo[k])
                    m = replace(m, moment=mo)
                out_m.append(m)
            moments[ln] = tuple(out_m)
        loads = replace(base, forces=forces, moments=moments)
        try:
            fs_ = solve_forces(self.mech, self.kin, loads)
            if outer:
                pushes = []
                for (by, on), want in outer.items():
                    vec, r = self._reaction(fs_, by, on, k)
                    size = 0.0 if vec is None else float(np.hypot(*vec))
                    if size <= 1e-9 * max(abs(want), 1.0):
                        continue
                    v = np.zeros((self.kin.n, 2))
                    v[k] = (abs(want) - size) * vec / size
                    at = np.array(r.at, float)
                    pushes.append(ForceLoad(f"ΔR{by}{on}", on, "external", None, at, v))
                if pushes:
                    loads = loads.with_loads(*pushes)
                    fs_ = solve_forces(self.mech, self.kin, loads)
            couples: dict[str, tuple[str, float]] = {}
            for _ in range(3):  # groups in order: a later group's Δ moves an earlier one's
                moved = False
                for name, want in tangential.items():
                    got = self._tangential_vector(fs_, name, k)
                    if got is None:
                        continue
                    link, rA, rB, t = got
                    size = float(np.hypot(*t))
                    if size <= 1e-9 * max(abs(want), 1.0) or abs(abs(want) - size) <= \
                            1e-9 * size:
                        continue
                    delta = (abs(want) - size) * t / size
                    c = -float((rA[0] - rB[0]) * delta[1] - (rA[1] - rB[1]) * delta[0])
                    couples[name] = (link, couples.get(name, (link, 0.0))[1] + c)
                    moved = True
                if not moved:
                    break
                extra = []
                for name, (link, c) in couples.items():
                    mo = np.zeros(self.kin.n)
                    mo[k] = c
                    extra.append(MomentLoad(f"Δ{name}", link, "external", mo))
                fs_ = solve_forces(self.mech, self.kin, loads.with_loads(*extra))
        except (GraphplanError, ValueError, TypeError, np.linalg.LinAlgError):
            self._plans[key] = None
            return None
        self._plans[key] = (loads, fs_)
        return loads, fs_

    def _tangential_vector(self, fs: Forces, name: str, k: int):
        """(link, r_A, r_B, Rτ) of ``Rτ12``: the reaction's part across its link, at its
        pair A, the link's other joint B (the point its moment equation is about)."""
        import re as _re

        m = _re.fullmatch(r"R[τt]?(\d)(\d)", fold(name).replace("τ", "t"))
        if m is None:
            return None
        i, j = m.groups()
        vec, r = self._reaction(fs, i, j, k)
        if vec is None or r.pair != "R":
            return None
        lf = self._far_joint(r)
        if lf is None:
            return None
        link, far = lf
        P = self.kin.pos.points
        rA, rB = np.asarray(P[r.point][k], float), np.asarray(P[far][k], float)
        d = rB - rA
        u = d / float(np.hypot(*d))
        t = vec - float(np.dot(vec, u)) * u
        return link, rA, rB, t

    def own_value(self, key: Key, k: int, own: tuple[Loads, Forces]) -> float | None:
        """:meth:`value` of ``key`` at position k in the student's own force analysis
        (:meth:`own_forces`)."""
        loads, fs = own
        return self._value(key, k, self.kin, {"full": loads}, {"rule": fs}, "rule")

    # --- plans at the student's scales ------------------------------------------------

    def plans(self, k: int, kl: float, kv: float | None, ka: float | None) -> tuple:
        """The velocity and acceleration plans of position k at the student's scales (Kv
        0.01, Ka 0.05 where the student gives none), built once for every student of the
        variant: the checks and the overlay read them."""
        from ..plans import acceleration_plan, velocity_plan
        from ..units import Scale

        key = (k, kl, kv, ka)
        if key not in self._plans:
            kv_ = Scale("Kv", kv or 0.01, "(m/s)/mm")
            vp = velocity_plan(self.mech, self.kin, k, Scale("Kl", kl, "m/mm"), kv_)
            ap = acceleration_plan(self.mech, self.kin, k, Scale("Kl", kl, "m/mm"),
                                   Scale("Ka", ka or 0.05, "(m/s²)/mm"), vp)
            self._plans[key] = (vp, ap)
        return self._plans[key]

    def force_plan(self, k: int, kl: float, kp: float | None):
        """The force plan of the last group of position k at the student's Kl and Kp (the
        series value where none is given), built once for every student of the variant."""
        from ..plans import force_plan
        from ..units import Scale

        key = ("force", k, kl, kp)
        if key not in self._plans:
            self._plans[key] = force_plan(
                self.mech, self.kin, self.forces["rule"], self.loads["rule"], k, 0,
                kl=Scale("Kl", kl, "m/mm"), kp=Scale("Kp", kp, "N/mm") if kp else None)
        return self._plans[key]

    def reading_mm(self, name: str, k: int, kl: float, kv: float | None,
                   ka: float | None) -> float | None:
        """Exact length (mm) of a segment of the velocity or acceleration plan of position
        k built by graphplan at the student's scales (``None`` without that scale)."""
        vp, ap = self.plans(k, kl, kv, ka)
        if name in vp.readings:
            return None if kv is None else vp.readings[name].exact_mm
        if name in ap.readings:
            return None if ka is None else ap.readings[name].exact_mm
        return None

    def reading_mm_coriolis(self, name: str, k: int, kl: float, kv: float, ka: float,
                            factor: float, normals: tuple[tuple[str, float], ...] = (),
                            each: tuple[tuple[str, float], ...] = ()) -> float | None:
        """The length (mm) of a segment of the acceleration plan built with every Coriolis
        component ``factor`` times its size (0: left out of the vector equations; 0.5:
        without its factor 2; s/e: the student's own) — the plan a student draws from
        their own Coriolis acceleration — and the normal components of the links of
        ``normals`` (link, factor) that many times theirs (``aⁿ = ω²·l`` with the
        student's own ω²: every point of the link follows from it by similarity). ``each``
        gives single Coriolis components (``("k_C43", 0.5)``) their own factor."""
        from dataclasses import replace as _replace

        from ..plans import acceleration_plan
        from ..units import Scale

        key = ("coriolis", k, kl, kv, ka, factor, normals, each)
        if key not in self._plans:
            self.reading_mm(name, k, kl, kv, ka)
            vp, _ap = self._plans[(k, kl, kv, ka)]
            sliding = {s: v * factor for s, v in vp.sliding.items()}
            pairs = self.coriolis_pairs(k)
            for cname, f in each:
                if cname in pairs:
                    sliding[pairs[cname]] = vp.sliding[pairs[cname]] * f
            rates = dict(vp.rates)
            for link, f in normals:
                if link in rates:
                    rates[link] = rates[link] * math.sqrt(max(f, 0.0))
            vp2 = _replace(vp, sliding=sliding, rates=rates)
            self._plans[key] = acceleration_plan(self.mech, self.kin, k,
                                                 Scale("Kl", kl, "m/mm"),
                                                 Scale("Ka", ka, "(m/s²)/mm"), vp2)
        ap = self._plans[key]
        return ap.readings[name].exact_mm if name in ap.readings else None

    def coriolis_pairs(self, k: int) -> dict[str, str]:
        """Each Coriolis segment of position k (``k_C43``) → the sliding pair whose
        relative velocity it is made of (``"4/3"``)."""
        from dataclasses import replace as _replace

        from ..plans import acceleration_plan
        from ..units import Scale

        key = ("coriolis-pairs", k)
        if key not in self._plans:
            names = self.coriolis_names(k)
            vp, _ap = self._plans[(k, 1e-3, 0.01, 0.05)]
            out: dict[str, str] = {}
            for s in vp.sliding:
                if len(out) == len(names):
                    break
                vp2 = _replace(vp, sliding={**vp.sliding, s: 0.0})
                ap = acceleration_plan(self.mech, self.kin, k, Scale("Kl", 1e-3, "m/mm"),
                                       Scale("Ka", 0.05, "(m/s²)/mm"), vp2)
                for n in names:
                    if n not in out and (n not in ap.readings or abs(
                            ap.readings[n].value) < 1e-9 * abs(_ap.readings[n].value)):
                        out[n] = s
            self._plans[key] = out
        return self._plans[key]

    def normal_link(self, p: str, q: str) -> str | None:
        """The link whose normal acceleration ``aⁿ_pq`` is (the link of both points)."""
        return self._common_link(p, q)

    def coriolis_names(self, k: int) -> list[str]:
        """The Coriolis segments (``k_A3``) of the acceleration plan of position k that are
        not zero."""
        self.reading_mm("πa", k, 1e-3, 0.01, 0.05)
        _vp, ap = self._plans[(k, 1e-3, 0.01, 0.05)]
        return [n for n, r in ap.readings.items() if r.quantity.startswith("aᵏ") and
                abs(r.value) > 1e-9]

    def plan_value(self, name: str, k: int) -> float | None:
        """The physical value (SI) of a segment of the velocity or acceleration plan of
        position k (``"k_A3"``: the Coriolis acceleration)."""
        self.reading_mm(name, k, 1e-3, 0.01, 0.05)
        vp, ap = self._plans[(k, 1e-3, 0.01, 0.05)]
        r = vp.readings.get(name) or ap.readings.get(name)
        return None if r is None else abs(float(r.value))

    def expected(self, q: Quantity, where: str | int, scales: dict[str, float],
                 model: str = "rule") -> float | None:
        """The value of ``q`` in its own unit (mm on paper, at the student's ``scales``)."""
        if q.kind == "scale":
            return None
        if q.kind == "segment" and where != "max":
            k = where if isinstance(where, int) else self.index(where)
            if k is not None and model in ("rule", "full") and q.scale in ("Kv", "Ka"):
                mm = self.reading_mm(q.name, k, scales.get("Kl", 1e-3), scales.get("Kv"),
                                     scales.get("Ka"))
                if mm is not None:
                    return mm
        key = q.key[1:] if q.kind == "segment" else q.key
        if q.kind == "drawn":
            key = ("length", *q.key[1:])
        v = self.value(key, where, model)
        if v is None:
            return None
        if q.on_paper:
            s = scales.get(q.scale or "")
            if not s:
                return None
            return abs(v / s)
        return v


__all__ = ["MAX_GRID", "MODELS", "Reference"]
