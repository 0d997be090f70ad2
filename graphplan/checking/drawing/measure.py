"""A plan found on the drawing laid against graphplan's construction of the same plan.

graphplan builds the plan of the position (:func:`graphplan.plans.constructions.velocity_plan`,
:func:`~graphplan.plans.constructions.acceleration_plan`) at the **student's** scale; each
letter of the student's plan is matched to a point of the construction by name
(``nBA`` = ``n_BA``; a bare ``n`` or ``k`` to the nearest component's end of that
letter); every segment of the construction whose two ends the student lettered is
measured between the student's points (mm) and its direction compared (degrees).

Whole-plan explanations are tried before the segments are judged one by one
(:func:`judge_plan`):

* **another position** — the plan fits the construction of another position of the
  mechanism, and not the one its caption names;
* **scale** — the plan fits the construction scaled by one factor: it is drawn at another
  scale than the one written (``Kv = 0,01`` written, the plan drawn at 0,02);
* **a component left out** — a normal or Coriolis component of the construction
  (longer than the reading precision) has no letter on the student's plan.

The fit of a plan to a construction is the root mean square of the distances between
the student's points and the construction's (mm, poles laid on each other).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..units import fold
from .plans import FoundPlan

POLE_GAIN_MM = 0.3
"""A pole is moved off the node its letter names only when the plan then fits the
construction this much better (root mean square, mm) — and by half at least."""


@dataclass(frozen=True, slots=True)
class Segmenting:
    """A segment of the construction: its reading name, its ends and its role."""

    name: str
    start: str
    end: str
    role: str


@dataclass(slots=True)
class Laid:
    """A found plan against one construction.

    ``match`` maps the student's names to the construction's points; ``vectors`` the
    measured (student) and expected (construction) place of each matched point relative to
    the pole, mm; ``rms`` the fit; ``ratio`` the one factor that fits the student's plan
    to the construction best, and ``rms_scaled`` the fit after it; ``pole_at`` the
    student's pole on the sheet (mm).
    """

    position: str
    index: int
    match: dict[str, str]
    measured: dict[str, np.ndarray]
    expected: dict[str, np.ndarray]
    rms: float
    ratio: float
    rms_scaled: float
    size: float
    plan: Any = None  # the exact plan (plans.Plan) the match was made against
    segments: list[Segmenting] = field(default_factory=list)
    unknown: list[str] = field(default_factory=list)
    pole_at: tuple[float, float] = (0.0, 0.0)  # the student's pole on the sheet, mm


def norm(name: str) -> str:
    return fold(name).lower().replace("_", "").replace(" ", "").replace("'", "")


def construction(ref, kind: str, k: int, scales: dict[str, float]):
    """graphplan's plan of position k at the student's scales (``None`` without one)."""
    from ...plans import acceleration_plan, velocity_plan
    from ...units import Scale

    kl = Scale("Kl", scales.get("Kl", 1e-3), "m/mm")
    kv = Scale("Kv", scales.get("Kv") or 0.01, "(m/s)/mm")
    vp = velocity_plan(ref.mech, ref.kin, k, kl, kv)
    if kind == "velocity":
        return vp
    ka = Scale("Ka", scales.get("Ka") or 0.05, "(m/s²)/mm")
    return acceleration_plan(ref.mech, ref.kin, k, kl, ka, vp)


def plan_segments(plan) -> list[Segmenting]:
    """The construction's segments with the names of the points at their ends."""
    pts = plan.points
    names = list(pts)

    def at(xy) -> str:
        return min(names, key=lambda n: float(np.hypot(*(np.asarray(xy) - pts[n]))))

    out, seen = [], set()
    for st in plan.steps:
        for e in st.elements:
            if e.kind != "segment" or e.name in seen:
                continue
            seen.add(e.name)
            out.append(Segmenting(e.name, at(e.start), at(e.end), e.role))
    return out


def lay(found: FoundPlan, plan, position: str, index: int) -> Laid:
    """Match the student's letters to the construction's points and fit them.

    The pole is the node its letter names, or another node the letter is nearly as near
    (the end of a short component beside the pole) when the plan fits the construction
    better from there.
    """
    poles = [np.asarray(found.points[found.pole], float)]
    poles += [np.asarray(o, float) for o in found.options.get(found.pole, ())[1:]]
    best = None
    for p0 in poles:
        if best is not None and best[0] <= POLE_GAIN_MM:
            break  # the letter's own node fits: no other is tried
        laid = _lay_at(found, plan, position, index, p0)
        score = min(laid.rms, laid.rms_scaled)
        # another node only when it fits clearly better (not by the reading's noise)
        if best is None or score < min(best[0] - POLE_GAIN_MM, 0.5 * best[0]):
            best = (score, laid)
    assert best is not None
    return best[1]


def _lay_at(found: FoundPlan, plan, position: str, index: int, p0: np.ndarray) -> Laid:
    pole = (plan.kind == "velocity" and "p") or "π"
    by_norm = {norm(n): n for n in plan.points}
    match: dict[str, str] = {}
    unknown = []
    for name in found.points:
        if name == found.pole:
            match[name] = pole
        elif norm(name) in by_norm:
            match[name] = by_norm[norm(name)]
    taken = set(match.values())
    for name in found.points:
        if name in match:
            continue
        n = norm(name)
        cands = [c for c in plan.points if c not in taken and norm(c)[:1] == n[:1] and
                 "_" in c]
        if not cands:
            unknown.append(name)
            continue
        m = np.asarray(found.points[name]) - p0
        best = min(cands, key=lambda c: float(np.hypot(*(m - plan.points[c]))))
        match[name] = best
        taken.add(best)
    # the one factor between the student's plan and the construction, from the letters'
    # nearest points (a plan drawn at another scale is still matched point by point)
    first = {c: (np.asarray(found.points[s]) - p0 if s != found.pole else np.zeros(2))
             for s, c in match.items()}
    E0 = np.array([plan.points[c] for c in first], float)
    M0 = np.array(list(first.values()), float)
    ee0 = float(np.sum(E0 * E0))
    k0 = float(np.sum(M0 * E0) / ee0) if ee0 > 0 else 1.0
    k0 = k0 if k0 > 0.05 else 1.0
    # a letter between two points: the point that fits the construction scaled by the
    # one factor that fits best — from the scale written (1) and from the letters'
    # nearest points (k0), each refined on the points it chooses; the better fit wins
    best_fit: tuple[float, dict[str, np.ndarray]] | None = None
    for k in (1.0, k0) if abs(k0 - 1.0) > 1e-3 else (1.0,):
        for _round in range(3):
            measured = _choose(found, match, first, plan, p0, k)
            M = np.array([measured[c] for c in measured], float)
            E = np.array([plan.points[c] for c in measured], float)
            ee = float(np.sum(E * E))
            k_new = float(np.sum(M * E) / ee) if ee > 0 else 1.0
            if k_new <= 0.05 or abs(k_new - k) < 1e-9:
                break
            k = k_new
        resid = float(np.sum((M - k * E) ** 2))
        if best_fit is None or resid < best_fit[0] - 1e-9:
            best_fit = (resid, measured)
    assert best_fit is not None
    measured = best_fit[1]
    expected = {c: np.asarray(plan.points[c], float) for c in match.values()}
    keys = [c for c in measured if c != pole]
    size = max((float(np.hypot(*plan.points[c])) for c in plan.points), default=1.0)
    if keys:
        M = np.array([measured[c] for c in keys])
        E = np.array([expected[c] for c in keys])
        rms = float(np.sqrt(np.mean(np.sum((M - E) ** 2, axis=1))))
        ee = float(np.sum(E * E))
        ratio = float(np.sum(M * E) / ee) if ee > 0 else 1.0
        rms_s = float(np.sqrt(np.mean(np.sum((M - ratio * E) ** 2, axis=1))))
    else:
        rms, ratio, rms_s = math.inf, 1.0, math.inf
    return Laid(position, index, match, measured, expected, rms, ratio, rms_s, size, plan,
                plan_segments(plan), unknown, (float(p0[0]), float(p0[1])))


def _choose(found: FoundPlan, match: dict[str, str], first: dict[str, np.ndarray], plan,
            p0: np.ndarray, k: float) -> dict[str, np.ndarray]:
    """Each matched letter's point: of the nodes its text is nearly as near (its options),
    the one nearest the construction's point scaled by ``k`` (mm from the pole)."""
    measured = {}
    for s, c in match.items():
        m = first[c]
        want = k * np.asarray(plan.points[c], float)
        for o in found.options.get(s, ())[1:] if s != found.pole else ():
            mo = np.asarray(o) - p0
            if np.hypot(*(mo - want)) < np.hypot(*(m - want)):
                m = mo
        measured[c] = m
    return measured


def fits(laid: Laid, rms: float, reading_mm: float, segment: float) -> bool:
    """A fit within the drafting tolerance: the reading precision or the segment
    tolerance of the plan's size, whichever is larger."""
    return rms <= max(reading_mm, segment * laid.size)


@dataclass(frozen=True, slots=True)
class Direction:
    """A segment's direction on the drawing against the construction's (degrees)."""

    name: str
    measured_deg: float
    expected_deg: float
    error_deg: float
    length_mm: float
    verdict: str


def directions(laid: Laid, reading_mm: float) -> list[Direction]:
    """The direction of every segment the student lettered at both ends."""
    inv = {c: s for s, c in laid.match.items()}
    out = []
    for sg in laid.segments:
        if sg.start not in inv or sg.end not in inv:
            continue
        m = laid.measured[sg.end] - laid.measured[sg.start]
        e = laid.expected[sg.end] - laid.expected[sg.start]
        lm, le = float(np.hypot(*m)), float(np.hypot(*e))
        if min(lm, le) < max(2.0, 4 * reading_mm):
            continue  # too short to show a direction
        am, ae = math.degrees(math.atan2(m[1], m[0])), math.degrees(math.atan2(e[1], e[0]))
        err = (am - ae + 180.0) % 360.0 - 180.0
        ok = max(1.0, math.degrees(math.atan(reading_mm / le)))
        tol = max(2.0, math.degrees(math.atan(2 * reading_mm / le)))
        v = "ok" if abs(err) <= ok else ("inaccurate" if abs(err) <= tol else "wrong")
        out.append(Direction(sg.name, am % 360.0, ae % 360.0, err, lm, v))
    return out


@dataclass(frozen=True, slots=True)
class Misplaced:
    """A point of the student's plan away from the construction's (mm)."""

    name: str  # the construction's name
    error_mm: float  # distance between the student's point and the construction's
    length_mm: float  # the construction's vector from the pole to the point
    band_mm: float  # the distance allowed before the point is wrong
    verdict: str


def misplaced_points(laid: Laid, tol) -> list[Misplaced]:
    """Points farther from the construction's than a segment of the same length may be
    off: ``|m − e| ≤ max(segment_ok·|e|, reading)`` is ok, ``≤ max(segment·|e|,
    2·reading)`` inaccurate, beyond wrong (a point has two coordinates to read); ``m`` and
    ``e`` are the student's and the construction's vectors from the pole (mm, the scale
    written). A vector's error as a whole, its length and direction at once: a point 3 mm
    off a 95 mm vector square to it changes its length by nothing and its direction by
    under 2°, and is still built wrong."""
    pole = (laid.plan.kind == "velocity" and "p") or "π"
    out = []
    for c, m in laid.measured.items():
        if c == pole:
            continue
        e = laid.expected[c]
        err = float(np.hypot(*(m - e)))
        length = float(np.hypot(*e))
        ok = max(tol.segment_ok * length, tol.reading_mm)
        band = max(tol.segment * length, 2.0 * tol.reading_mm)
        if err <= ok:
            continue
        out.append(Misplaced(c, err, length, band, "inaccurate" if err <= band else "wrong"))
    return out


def missing_components(laid: Laid, reading_mm: float) -> list[Segmenting]:
    """Normal and Coriolis components of the construction the student did not letter
    (those shorter than twice the reading precision may well be left out)."""
    inv = set(laid.match.values())
    out = []
    for sg in laid.segments:
        if sg.role not in ("normal", "coriolis") or sg.end in inv:
            continue
        plan = laid.plan
        length = float(np.hypot(*(plan.points[sg.end] - plan.points[sg.start])))
        if length >= 2 * reading_mm:
            out.append(sg)
    return out


def segment_lengths(laid: Laid, reading_mm: float = 0.5) -> dict[str, float]:
    """The length (mm) on the student's plan of every reading of the construction whose
    two ends the student lettered (a normal or Coriolis component shorter than twice the
    reading precision, which may be left out, is not judged)."""
    inv = {c: s for s, c in laid.match.items()}
    out = {}
    readings = getattr(laid.plan, "readings", {})
    for sg in laid.segments:
        if sg.name not in readings or sg.start not in inv or sg.end not in inv:
            continue
        if sg.role in ("normal", "coriolis") and float(np.hypot(
                *(laid.plan.points[sg.end] - laid.plan.points[sg.start]))) < 2 * reading_mm:
            continue
        out[sg.name] = float(np.hypot(*(laid.measured[sg.end] - laid.measured[sg.start])))
    return out


__all__ = [
    "Direction",
    "Laid",
    "Misplaced",
    "Segmenting",
    "construction",
    "directions",
    "fits",
    "lay",
    "misplaced_points",
    "missing_components",
    "norm",
    "plan_segments",
    "segment_lengths",
]
