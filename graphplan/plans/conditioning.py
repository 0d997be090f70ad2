"""How well each graphical figure is determined: the angles of the constructions and a bound.

A draftsman who intersects two lines at a small angle knows the point is poorly fixed:
a reading error ``p`` across either line moves the intersection by about ``p/sin α``
along the other. graphplan's constructions record that angle on every intersection
step (:attr:`graphplan.plans.constructions.Step.angle_deg`, ``error_mm`` ≈ p/sin α). This
module turns it into two things the sheets and tables show:

* **marks** — an intersection at less than :data:`ILL_ANGLE_DEG` makes its plan
  *ill-conditioned*, and the plan is marked as a careful draftsman would mark it:
  ``lines meet at 1.3°, reading ±11 mm`` (:meth:`Intersection.note`);
* **bounds** — every figure read off a plan (a segment and its value, ω and ε of a
  link, a sliding speed, a reaction, Mур from the force plans and from Zhukovsky's
  lever) gets an error bound for the reading precision ``p``.

The bound is the construction's own error propagation, to first order. Every length
the draftsman reads or lays off (a segment, a component laid off at the scale, a length
taken off the plan of positions, an arm) is rounded to ``p``: its error ``δ_i`` is at
most ``p/2``. A figure ``F`` of the drawing is a smooth function of those errors, so

    |F(δ) − F(0)| ≤ Σ_i |∂F/∂δ_i|·p/2 + O(p²),

and the partial derivatives are measured on the construction itself: the plans are
built again with one reading shifted by a small ``h`` (``∂F/∂δ_i ≈ (F_i − F_0)/h``).
``F_0`` and the drawn figures are those of the plans the sheets and tables built (each
plan records how many readings it took); only the shifted plans are built here, from the
shifted reading's plan on (the plans before it are the unshifted ones, and a later plan
whose inputs the shift left as they were is the plan built already). What an ill-conditioned
intersection does — ``p/sin α`` — is in those derivatives; the first-order bound is
multiplied by :data:`SAFETY` for the terms of second order, which stay small unless an
angle is small, and then the plan is marked: a figure is within its bound of the exact
value or its plan is marked (``tests/test_stability.py`` sweeps the cases where methods
fail and checks exactly that).

Units: bounds are in the figure's unit (m/s, m/s², rad/s, rad/s², N, N·m); the marks
give the angle in degrees and the intersection's uncertainty in mm of the drawing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..numbers import rough
from .constructions import Reader, acceleration_plan, velocity_plan

ILL_ANGLE_DEG = 10.0
"""An intersection at a smaller angle marks its plan as ill-conditioned (×5.8 the reading)."""

SAFETY = 1.5
"""Factor on the first-order bound (the second-order terms of a well-conditioned plan)."""

STEP_MM = 1e-6
"""The shift of one reading (mm) that measures a figure's derivative."""

FLOOR = 1e-10
"""Every bound is at least this fraction of the largest figure of its kind (the round-off
of the construction's arithmetic: a figure no reading moves is still a float)."""

WORDS = {
    "en": "lines meet at {angle}°, reading ±{err} mm",
    "ru": "линии пересекаются под углом {angle}°, точность ±{err} мм",
}


@dataclass(frozen=True, slots=True)
class Intersection:
    """One intersection of a construction: where two lines of known direction meet.

    Attributes
    ----------
    plan : str
        ``"velocity"``, ``"acceleration"``, or a force plan's group (``"RRP(2-3)"``,
        ``"crank 1"``).
    step : int
        The step's number in its plan.
    equation : str
        The vector equation the two lines belong to.
    angle_deg : float
        The angle between the lines, degrees in [0, 90].
    error_mm : float
        The new point's uncertainty for the reading precision, ≈ precision/sin(angle), mm.
    """

    plan: str
    step: int
    equation: str
    angle_deg: float
    error_mm: float

    @property
    def ill(self) -> bool:
        """True when the lines meet at less than :data:`ILL_ANGLE_DEG`."""
        return self.angle_deg < ILL_ANGLE_DEG

    def note(self, lang: str = "en") -> str:
        """``lines meet at 1.3°, reading ±11 mm`` (``ru``: ``линии пересекаются под углом …``)."""
        angle = f"{self.angle_deg:.1f}"
        text = WORDS[lang].format(angle=angle, err=rough(self.error_mm))
        return text.replace(".", ",") if lang == "ru" else text


def intersections(plan) -> tuple[Intersection, ...]:
    """The intersection steps of a plan (velocity, acceleration, force plan, lever)."""
    name = str(getattr(plan, "group", None) or getattr(plan, "kind", "lever"))
    return tuple(Intersection(name, s.number, s.equation, float(s.angle_deg),
                              float(s.error_mm if s.error_mm is not None else math.inf))
                 for s in plan.steps if s.angle_deg is not None)


def ill_conditioned(*plans) -> tuple[Intersection, ...]:
    """The ill-conditioned intersections of the plans, worst (smallest angle) first."""
    found = [x for p in plans for x in intersections(p) if x.ill]
    return tuple(sorted(found, key=lambda x: x.angle_deg))


def note(plans, lang: str = "en") -> str:
    """The mark of a set of plans: the note of the worst intersection, or ``""``."""
    ill = ill_conditioned(*plans)
    return ill[0].note(lang) if ill else ""


@dataclass(frozen=True, slots=True)
class Figure:
    """A figure read off a drawing, with its bound.

    Attributes
    ----------
    plan : str
        ``"velocity"``, ``"acceleration"``, ``"force"`` or ``"lever"``.
    name : str
        Its name in the plan: a segment (``"pb"``, ``"τ_BA"``), a rate (``"ω2"``), a
        sliding pair (``"slide 3/4"``), a force plan's quantity (``"R12"``), ``"Mур"``.
    unit : str
    value : float
        As drawn at the reading precision.
    exact : float
        The same figure of the exact construction.
    bound : float
        ± of ``value`` for the reading precision (in ``unit``).
    flagged : bool
        Its plans have an ill-conditioned intersection: the bound is not to be trusted.
    deviation : float | None
        For a vector (a plan point, a reaction): the length of the drawn vector's
        difference from the exact one (``value`` and ``exact`` are then the lengths).
    """

    plan: str
    name: str
    unit: str
    value: float
    exact: float
    bound: float
    flagged: bool = False
    deviation: float | None = None

    @property
    def error(self) -> float:
        """|value − exact| (for a vector, the length of the difference)."""
        return self.deviation if self.deviation is not None else abs(self.value - self.exact)

    @property
    def within(self) -> bool:
        """The drawn value is within its bound of the exact one."""
        return self.error <= self.bound


@dataclass(frozen=True, slots=True)
class Conditioning:
    """The conditioning of the drawings of one position at one reading precision.

    ``figures`` are keyed ``(plan, name)``; ``marks`` are the ill-conditioned
    intersections, worst first; ``bounded`` is False where a construction took another
    path when a reading was shifted (then every figure is flagged).
    """

    label: str
    precision: float
    intersections: tuple[Intersection, ...]
    figures: dict[tuple[str, str], Figure] = field(default_factory=dict)
    bounded: bool = True

    @property
    def marks(self) -> tuple[Intersection, ...]:
        return tuple(sorted((x for x in self.intersections if x.ill),
                            key=lambda x: x.angle_deg))

    @property
    def flagged(self) -> bool:
        """The drawings are ill-conditioned (or could not be bounded)."""
        return bool(self.marks) or not self.bounded

    def note(self, lang: str = "en") -> str:
        """The worst mark's note, or ``""``."""
        return self.marks[0].note(lang) if self.marks else ""

    def bound(self, plan: str, name: str) -> float | None:
        f = self.figures.get((plan, name))
        return None if f is None else f.bound


class Bounded:
    """A mixin of a position's readings that carry their :class:`Conditioning` (None when
    read exactly): :meth:`bound` of a figure."""

    __slots__ = ()
    conditioning: Conditioning | None

    def bound(self, plan: str, name: str) -> float | None:
        """± of a figure (``("velocity", "pb")``, ``("force", "R12")``, ``("lever", "Mур")``),
        or None (exact mode, or a figure with no bound)."""
        c = self.conditioning
        return None if c is None else c.bound(plan, name)


# ------------------------------------------------------------------ the sensitivity engine


@dataclass(frozen=True)
class _Probe(Reader):
    """Reads exactly, but shifts the ``shift``-th reading by ``h`` mm; counts the readings."""

    shift: int = -1
    h: float = 0.0
    calls: list = field(default_factory=list, compare=False)

    def __call__(self, mm: float) -> float:
        k = len(self.calls)
        self.calls.append(k)
        return float(mm) + (self.h if k == self.shift else 0.0)


def _bounds(run, precision: float, kind=lambda key: None, base=None, drawn=None):
    """Figures of ``run(reader)`` exact, drawn, and their first-order bounds.

    ``run`` builds the drawings with the reader it is given and returns ``{key: value}``
    (a float, or a 2-vector whose bound is on its length); the readers are probes with
    one reading shifted at a time. ``kind(key)`` groups the figures for :data:`FLOOR`.
    ``base``: ``(figures, readings)`` of the exact construction where it is built already
    (a probe that shifts nothing reads exactly: it is that construction); ``drawn``: the
    figures of the construction read at ``precision``, where built already. Only the probes
    are built here then.
    """
    if base is None:
        probe = _Probe(precision)
        base = (run(probe), len(probe.calls))
    f0, n = base
    sens = {key: 0.0 for key in f0}
    same_path = True
    for i in range(n):
        probe = _Probe(precision, i, STEP_MM)
        fi = run(probe)
        if len(probe.calls) != n or fi.keys() != f0.keys():
            same_path = False
            break
        for key, v in fi.items():
            d = np.asarray(v, float) - np.asarray(f0[key], float)
            sens[key] += float(np.hypot(*d)) if d.ndim else abs(float(d))
    if drawn is None:
        drawn = run(Reader(precision))
    half = precision / 2.0
    largest: dict = {}
    for key, v in f0.items():
        size = float(np.hypot(*v)) if np.ndim(v) else abs(float(v))
        largest[kind(key)] = max(largest.get(kind(key), 0.0), size)
    bounds = {key: SAFETY * s / STEP_MM * half + FLOOR * largest[kind(key)]
              for key, s in sens.items()}
    return f0, drawn, bounds, same_path


def _shifted_velocity_plan(mech, kin, k: int, kl, kv, reader: _Probe, probes: dict | None):
    """The velocity plan a probe builds (its reading ``reader.shift`` moved by ``reader.h``).
    ``probes`` keeps them for the project (the kinematic bounds and the lever's shift the
    same readings of the same plan where the lever's Kv is sheet 1's): each built once."""
    if probes is None or reader.calls:
        return velocity_plan(mech, kin, k, kl, kv, reader)
    key = (k, kl.per_mm, kv.per_mm, reader.precision, reader.shift, reader.h)
    plan = probes.get(key)
    if plan is None:
        plan = probes[key] = velocity_plan(mech, kin, k, kl, kv, reader)
    else:
        reader.calls.extend(range(plan.reads))
    return plan


def _plan_figures(plan) -> dict:
    """A velocity or acceleration plan's figures: readings, rates, sliding, point vectors."""
    out = {}
    for name, r in plan.readings.items():
        out[("r", name)] = r.value
    for link, w in plan.rates.items():
        out[("rate", link)] = w
    for key, s in plan.sliding.items():
        out[("slide", key)] = s
    for name, xy in plan.points.items():
        out[("point", name)] = np.asarray(xy, float) * plan.scale.per_mm
    return out


def kinematic_conditioning(mech, kin, k: int, kl, kv, ka, precision: float, *,
                           exact: tuple | None = None, drawn: tuple | None = None,
                           probes: dict | None = None) -> Conditioning:
    """Bounds of every figure of the velocity and acceleration plans of position k.

    Parameters
    ----------
    mech : Mechanism
    kin : Kinematics
    k : int
        Index of the position in ``kin``.
    kl, kv, ka : Scale
        The scales of the plans.
    precision : float
        The reading precision, mm (> 0).
    exact, drawn : (Plan, Plan), optional
        The velocity and acceleration plans of position k at these scales, read exactly
        and at ``precision``, where they are built already (the project's): only the
        probes are built then.
    probes : dict, optional
        The project's store of shifted velocity plans (each built once; see
        :func:`force_conditioning`).

    Returns
    -------
    Conditioning
        ``figures`` keyed ``("velocity"|"acceleration", name)``: the readings by segment
        name (``"pb"``), the rates ``"ω2"``/``"ε2"``, sliding ``"slide 3/4"`` and the
        points' vectors ``"point b"`` (their bound is on the vector's length).
    """
    if not precision > 0:
        raise ValueError(f"a reading precision > 0 mm is needed (got {precision!r})")

    last: list = []  # the plans of the last run

    unshifted: list = []  # the unshifted probe's velocity plan and its readings

    def run(reader):
        if isinstance(reader, _Probe):
            ra = _Probe(precision)
            # the shift counts over both plans: v readings first, then a readings; a
            # shifted acceleration reading leaves the velocity plan the unshifted one
            if unshifted and 0 <= unshifted[1] <= reader.shift:
                vp, nv = unshifted
                reader.calls.extend(range(nv))
            else:
                vp = _shifted_velocity_plan(mech, kin, k, kl, kv, reader, probes)
                nv = len(reader.calls)
                if reader.shift < 0:
                    unshifted[:] = (vp, nv)
            if reader.shift >= nv and reader.shift >= 0:
                ra = _Probe(precision, reader.shift - nv, reader.h)
            ap = acceleration_plan(mech, kin, k, kl, ka, vp, ra)
            reader.calls.extend(range(len(ra.calls)))
        else:
            vp = velocity_plan(mech, kin, k, kl, kv, reader)
            ap = acceleration_plan(mech, kin, k, kl, ka, vp, reader)
        last[:] = (vp, ap)
        return plan_figures(vp, ap)

    def plan_figures(vp, ap) -> dict:
        return {(plan.kind, key): v for plan in (vp, ap) for key, v in _plan_figures(plan).items()}

    base = None
    if exact is not None:
        unshifted[:] = (exact[0], exact[0].reads)
        base = (plan_figures(*exact), exact[0].reads + exact[1].reads)
    f0, shown, bounds, same = _bounds(run, precision, lambda key: (key[0], key[1][0]), base,
                                      None if drawn is None else plan_figures(*drawn))
    vp, ap = last if drawn is None else drawn  # the drawn plans (the last run, or given)
    marks = intersections(vp) + intersections(ap)
    flagged = any(x.ill for x in marks) or not same
    figures = {}
    for (plan, (kind, name)), v0 in f0.items():
        fig_name, unit = _kinematic_name(plan, kind, name, vp if plan == "velocity" else ap)
        if (plan, (kind, name)) not in shown:
            if kind == "point":  # e.g. the end of a Coriolis component that reads 0 mm
                continue
            value: Any = 0.0  # a component that reads 0 mm is not laid off: it is zero
        else:
            value = shown[(plan, (kind, name))]
        if kind == "point":
            figures[(plan, fig_name)] = Figure(plan, fig_name, unit, float(np.hypot(*value)),
                                               float(np.hypot(*v0)), bounds[(plan, (kind, name))],
                                               flagged, float(np.hypot(*(value - v0))))
            continue
        figures[(plan, fig_name)] = Figure(plan, fig_name, unit, float(value), float(v0),
                                           bounds[(plan, (kind, name))], flagged)
    return Conditioning(kin.labels[k], float(precision), marks, figures, same)


def _kinematic_name(plan: str, kind: str, name: str, p) -> tuple[str, str]:
    vel = plan == "velocity"
    if kind == "r":
        return name, ("m/s" if vel else "m/s²")
    if kind == "rate":
        return ("ω" if vel else "ε") + name, ("rad/s" if vel else "rad/s²")
    if kind == "slide":
        return f"slide {name}", ("m/s" if vel else "m/s²")
    return f"point {name}", ("m/s" if vel else "m/s²")


def point_error(cond: Conditioning, plan: str, point: str) -> float | None:
    """The bound on the vector of a plan point (``"b"``), or None."""
    f = cond.figures.get((plan, f"point {point}"))
    return None if f is None else f.bound


def force_conditioning(mech, kin, forces, loads, k: int, kl, kv, precision: float,
                       room_mm: float | tuple[float, ...] | None = None, *,
                       exact: tuple | None = None, drawn: tuple | None = None,
                       lever_exact=None, lever_drawn=None, probes: dict | None = None,
                       memo: dict | None = None) -> Conditioning:
    """Bounds of the force plans' figures and of Zhukovsky's lever at position k.

    The loads are the exact ones (graphplan draws the force plans from them); the
    reading errors are those of the force plans (segments laid off at Kp and read back,
    arms on the plan of positions) and of the lever (its velocity plan and arms).
    ``exact``, ``drawn`` (the force plans of position k at ``kl`` and ``room_mm``, read
    exactly and at ``precision``) and ``lever_exact``, ``lever_drawn`` (the lever at ``kl``,
    ``kv``), where they are built already: only the probes are built then. ``probes``: the
    project's store of shifted velocity plans, shared with :func:`kinematic_conditioning`;
    ``memo``: its store of force plans (:func:`graphplan.plans.forces.chain_plan`): a probe's
    plan of the same inputs as one built already is that plan.

    Returns
    -------
    Conditioning
        ``figures`` keyed ``("force", quantity)`` — every force plan's readings by
        quantity (``"R12"``, ``"Rτ12"``), the reactions' vectors ``"vector R12"`` (bound
        on the length) and ``"Mур"`` of the crank's plan — and ``("lever", "Mур")``.
    """
    if not precision > 0:
        raise ValueError(f"a reading precision > 0 mm is needed (got {precision!r})")
    from .forces import ROOM_MM, force_plans
    from .zhukovsky import zhukovsky_lever

    extra = {"room_mm": room_mm} if room_mm is not None else {}
    last_plans: list = []  # the force plans of the last run
    # the probes build at the Kp of the unshifted plans; those plans, each with the
    # readings it took, stand for themselves in a probe that shifts a later reading
    base: list = [] if exact is None else [(p, p.reads) for p in exact]
    scales: dict = {m: p.scale for m, (p, _) in enumerate(base)}

    def probe_plans(reader: _Probe) -> tuple:
        """:func:`force_plans` (the same order: the groups from the last, then the crank)
        for a probe: the plans before the one whose reading is shifted are the unshifted
        plans themselves, and a later plan whose inputs are those of a plan built already
        (the shift left the reactions it takes as they were) is that plan, not built again."""
        from .forces import chain_plan

        known: dict = {}
        plans: list = []
        end = 0  # readings taken by the plans so far
        for m in range(len(mech.dyads) + 1):
            if base and reader.shift >= 0 and m < len(base) and reader.shift >= end + base[m][1]:
                p, used = base[m]
                reader.calls.extend(range(used))
            else:
                before = len(reader.calls)
                # this plan's room (sheet 2 gives one per plan)
                room = extra.get("room_mm", ROOM_MM)
                room = room[m] if isinstance(room, tuple) else room
                local = reader.shift - before
                shifted = m < len(base) and 0 <= local < base[m][1]  # a reading of this plan
                how = ("probe", precision, local, reader.h) if shifted else ("probe-exact",
                                                                             precision)
                p, _ = chain_plan(mech, kin, forces, loads, k, m, scales.get(m), kl, reader,
                                  known, room, memo, how, () if shifted else (("read", 0.0),))
                if len(reader.calls) == before:  # found, not built: its readings taken
                    reader.calls.extend(range(p.reads))
                scales.setdefault(m, p.scale)
                used = len(reader.calls) - before
                if reader.shift < 0:
                    base.append((p, used))
            end += used
            known.update(p.reactions)
            plans.append(p)
        return tuple(plans)

    def figures(plans) -> dict:
        out = {}
        for p in plans:
            for q, r in p.readings.items():
                out[q] = r.value
            for name, r in p.reactions.items():
                out[f"vector {name}"] = np.asarray(r.vector, float)
            if p.M_bal is not None:
                out["Mур"] = p.M_bal
        return out

    def run_plans(reader):
        if isinstance(reader, _Probe):
            plans = probe_plans(reader)
        else:
            plans = force_plans(mech, kin, forces, loads, k, kl, reader, **extra, memo=memo)
        last_plans[:] = plans
        return figures(plans)

    # the unshifted lever's velocity plan and the readings it took
    lever_base: list = [] if lever_exact is None else [lever_exact.plan, lever_exact.plan.reads]

    def run_lever(reader):
        plan = None  # a shifted arm of the lever reuses the unshifted velocity plan
        if isinstance(reader, _Probe):
            if lever_base and 0 <= lever_base[1] <= reader.shift:
                plan, nv = lever_base
                reader.calls.extend(range(nv))
            else:
                plan = _shifted_velocity_plan(mech, kin, k, kl, kv, reader, probes)
                if reader.shift < 0:
                    lever_base[:] = (plan, len(reader.calls))
        lv = zhukovsky_lever(mech, kin, loads, k, kl, kv, reader, plan=plan)
        return {"Mур": lv.M_bal}

    f0, shown, bounds, same = _bounds(
        run_plans, precision, lambda q: q == "Mур",
        None if exact is None else (figures(exact), sum(p.reads for p in exact)),
        None if drawn is None else figures(drawn))
    l0, ldrawn, lbounds, lsame = _bounds(
        run_lever, precision, base=None if lever_exact is None else (
            {"Mур": lever_exact.M_bal}, lever_exact.reads),
        drawn=None if lever_drawn is None else {"Mур": lever_drawn.M_bal})
    plans = tuple(last_plans) if drawn is None else tuple(drawn)  # as drawn
    marks = tuple(x for p in plans for x in intersections(p))
    flagged = any(x.ill for x in marks) or not (same and lsame)
    found = {}
    for q, v0 in f0.items():
        # a reading the drawing does without (a component that reads 0 mm is not laid off)
        value = shown.get(q, np.zeros(2) if np.ndim(v0) else 0.0)
        unit = "N·m" if q == "Mур" else "N"
        if q.startswith("vector "):
            found[("force", q)] = Figure("force", q, unit, float(np.hypot(*value)),
                                         float(np.hypot(*v0)), bounds[q], flagged,
                                         float(np.hypot(*(value - v0))))
        else:
            found[("force", q)] = Figure("force", q, unit, float(value), float(v0), bounds[q],
                                         flagged)
    found[("lever", "Mур")] = Figure("lever", "Mур", "N·m", float(ldrawn["Mур"]),
                                     float(l0["Mур"]), lbounds["Mур"], flagged)
    return Conditioning(kin.labels[k], float(precision), marks, found, same and lsame)


__all__ = ["ILL_ANGLE_DEG", "SAFETY", "Bounded", "Conditioning", "Figure", "Intersection",
           "force_conditioning", "ill_conditioned", "intersections", "kinematic_conditioning",
           "note", "point_error"]
