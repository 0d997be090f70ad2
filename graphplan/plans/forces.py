"""Force plans (планы сил) of the Assur groups and the crank, built as constructions.

Method B.3, C.1–C.5 and D.3: for one position k, the groups are drawn from the last
attached back to the crank. Every moment equation is written with **arms measured on
the position plan** (mm at Kl, the perpendicular from the moment centre to the force's
line of action, read by the :class:`~graphplan.plans.constructions.Reader`), so a moment is
``F·h`` in N·mm of the drawing and a couple ``M`` (N·m) enters as ``M/Kl``. Every force
polygon is drawn **head to tail at Kp** (a segment is ``F/Kp`` mm, read by the reader),
closed by the two lines of known direction, and every reaction is read back as a
segment: ``R12 = (segment mm)·Kp``.

Conventions are those of :mod:`graphplan.forces.kinetostatics`: SI units, the variant's axes
(x right, y up; the plans in mm, same orientation), moments and couples **counter-
clockwise positive**, **R_ij is the force of link i on link j**, friction neglected,
ω1 constant. A prismatic pair's reaction ``R = N·n`` (``n = k×u``, u the guide's
direction) acts on the line ⟂ u through ``X + x·u`` (X the pair's reference point);
its ``couple`` about X is ``N·x``.

Per dyad kind (links i, j; outer pairs of i and j, inner pair i–j), with the group's
equation written as *closing 1 + loads of i + loads of j + closing 2 = 0* so that the
junction of the loads of i and of j joins the closing point in the inner reaction:

RRR (A, B, C)
    ``ΣM_B(i) = 0: Rτ12·AB + Σ±F·h + ΣM/Kl = 0`` and ``ΣM_B(j) = 0: Rτ43·CB + … = 0``;
    polygon ``Rτ12 + F_i + F_j + Rτ43 + Rⁿ43 + Rⁿ12 = 0`` closed by ``Rⁿ43 ∥ CB`` and
    ``Rⁿ12 ∥ AB``; ``R12 + F_i + R32 = 0`` gives the inner reaction.
RRP (A, B, slider on a guide)
    ``ΣM_B(i)`` gives Rτ12; polygon ``Rτ12 + F_i + F_j + R43 + Rⁿ12 = 0`` closed by
    ``R43 ⟂ guide`` and ``Rⁿ12 ∥ AB``; ``ΣM_B(j) = 0: N43·x43 + ΣM_B(F_j) = 0`` places R43.
RPR (A on the block i, C pivot of the rocker j)
    block along the slot: ``Rⁿ12 = −ΣF_i·u`` (0 for the usual massless block);
    ``ΣM_C(i+j) = 0`` gives ``Rτ12 ⟂ slot``; polygon ``R12 + F_i + F_j + R63 = 0``
    closed by the vector R63; ``R23 = R12 + F_i`` (⟂ slot); block ``ΣM_A`` places R23.
PRP (B; i on guide 1, j on guide 2)
    polygon ``R_{g1 i} + F_i + F_j + R_{g2 j} = 0`` closed by the two normals;
    ``R_ij`` from link i; ``ΣM_B`` of each link places each normal force.
RPP (A on the block i, D the reference point of the yoke j)
    polygon of j ``R23 + F_j + R43 = 0`` closed by the two normals, then the block's
    ``R32 + F_i + R12 = 0`` gives R12 as the closing vector; block ``ΣM_A`` places R23,
    yoke ``ΣM_D`` places R43.

Crank: ``ΣM_O = 0: Mур/Kl + Σ±F·h = 0`` with ``R21 = −R12`` at A, h21 from O,
so ``Mур = R21·h21·Kl`` with its sign (CCW positive); ``R41 = −(R21 + G1 + Pи1)`` closes
its polygon.

Where a normal force of a prismatic pair is zero (reads 0 mm), the offset ``x = M/N``
is undefined: the step says so and the pair carries the pure couple M from the same
moment equation (the fallback of the method's ordering). A moment equation whose
unknown's arm is zero raises :class:`~graphplan.errors.SingularPoseError`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import SingularPoseError
from ..forces import Forces, Loads, dyad_pairs, reaction_name
from ..geometry import cross, perp
from ..model import Mechanism
from ..numbers import plain
from ..units import PLAN_SERIES, Scale, fit_scale
from .constructions import (
    EXACT,
    Element,
    Reader,
    Reading,
    Step,
    as_xy,
    intersect_lines,
    intersection_error_mm,
    position_mm,
    tally,
    unit_vector,
)

Vec2 = np.ndarray

ROOM_MM = 150.0
"""Kp is the smallest of the plans' series (:data:`graphplan.units.PLAN_SERIES`: 1, 1.2, 1.5, 2,
2.5, 3, 4, 5, 6, 8 × 10^k) that keeps the plan within this."""

SMALL_ANGLE_DEG = 15.0
"""Closing lines meeting at less than this are flagged in the step's text (method D.3)."""


@dataclass(frozen=True, slots=True)
class PlanReaction:
    """A reaction as read off a force plan: the force of ``by`` on ``on``.

    ``vector`` (N) is the read segment times Kp; ``ref`` (m) is the pair's point (the
    joint, or the slider's reference point X); ``at`` (m) a point of its line of action;
    ``couple`` (N·m) its moment about ``ref`` (prismatic pairs, ``N·x``); ``offset_mm``
    the offset x of the line of action along the guide on the position plan (``None``
    where N = 0 and the offset is undefined, or for a revolute pair).
    """

    name: str
    by: str
    on: str
    pair: str
    vector: Vec2
    ref: Vec2
    at: Vec2
    couple: float = 0.0
    offset_mm: float | None = None

    @property
    def magnitude(self) -> float:
        return float(np.hypot(*self.vector))


@dataclass(frozen=True, slots=True)
class ForcePlan:
    """The force plan of one group (or of the crank) at one position.

    Attributes
    ----------
    kind : str
        ``"force"``.
    label : str
        The position's label.
    group : str
        ``"RRP(2-3)"`` …, or ``"crank 1"``.
    scale : Scale
        Kp, N/mm.
    points : dict[str, ndarray]
        Vertices of the polygon in mm (``a`` at the origin, y up).
    steps : tuple[Step, ...]
    readings : dict[str, Reading]
        By quantity (``"R12"``, ``"Rτ12"``, ``"Rn12"``, ``"G2"`` …): the segment (its
        vertices in ``name``), mm as read, N.
    equations : tuple[str, ...]
        The moment equations used, with the arms in mm read on the position plan.
    polygons : dict[str, tuple[tuple[str, str, str], ...]]
        Closed chains ``(quantity, from, to)``: ``"group"`` and the link's sub-polygon
        that gives the inner reaction (``"link 2"``).
    reactions : dict[str, PlanReaction]
        The reactions found, named as :mod:`graphplan.forces.kinetostatics` names them.
    arms_mm : dict[str, float]
        Arms as read, ``"h_G2@B"`` (force G2 about B); the crank's ``"h21"``.
    M_bal : float | None
        The crank's balancing moment Mур, N·m, CCW positive.
    """

    kind: str
    label: str
    group: str
    scale: Scale
    points: dict[str, Vec2]
    steps: tuple[Step, ...]
    readings: dict[str, Reading]
    equations: tuple[str, ...]
    polygons: dict[str, tuple[tuple[str, str, str], ...]]
    reactions: dict[str, PlanReaction]
    arms_mm: dict[str, float]
    M_bal: float | None = None
    reads: int = field(default=0, compare=False)  #: readings the reader took (:class:`Tally`)

    def measure(self, a: str, b: str) -> float:
        """Length (mm) between two vertices, exactly."""
        return float(np.hypot(*(self.points[b] - self.points[a])))

    def value(self, quantity: str) -> float:
        """Magnitude (N) of a reading."""
        return self.readings[quantity].value

    def closure(self, polygon: str = "group") -> Vec2:
        """Sum (mm) of the vectors of a polygon: zero when it closes."""
        return sum((self.points[b] - self.points[a] for _, a, b in self.polygons[polygon]),
                   np.zeros(2))

    @property
    def extent_mm(self) -> float:
        """Largest distance between two vertices of the plan (its diameter), mm."""
        pts = np.array(list(self.points.values()))
        return float(np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1)).max())

    def _repr_svg_(self) -> str:
        """Jupyter: the whole force polygon, loads and reactions named."""
        from ..teaching.drawing import construction_svg

        return construction_svg(self)


@dataclass(frozen=True, slots=True)
class _F:
    """A known force on a link: name, vector (N), a point of its line (position plan, mm)."""

    name: str
    vec: Vec2
    at: Vec2


def _arm(c: Vec2, x: Vec2, d: Vec2) -> float:
    """Perpendicular distance (mm) from c to the line through x along d: ``|(c − x) × u|``.

    (A shapely distance to the line drawn past the foot of the perpendicular gave the
    same to round-off at five times the cost; the error bounds rebuild every force plan
    once per reading, so the arm is measured by the cross product.)
    """
    u = unit_vector(d)
    return abs(float((c[0] - x[0]) * u[1] - (c[1] - x[1]) * u[0]))


def _letter(n: int) -> str:
    s = "abcdefghijklmnopqrstuvwxyz"
    return s[n] if n < 26 else f"{s[n % 26]}{n // 26}"


def _sgn(x: float) -> str:
    return "−" if x < 0 else "+"


class _Draw:
    """Vertices, steps, readings and equations of one force plan."""

    def __init__(self, kp: Scale, kl: Scale, reader: Reader, big: float):
        self.kp, self.kl, self.reader = kp, kl, reader
        self.big = big  # the largest force of the plan (N): zero tests are relative to it
        self.points: dict[str, Vec2] = {"a": np.zeros(2)}
        self.steps: list[Step] = []
        self.readings: dict[str, Reading] = {}
        self.equations: list[str] = []
        self.arms: dict[str, float] = {}
        self.poly: list[tuple[str, str, str]] = []

    def vertex(self, xy: Vec2) -> str:
        name = _letter(len(self.points))
        self.points[name] = np.asarray(xy, float)
        return name

    def step(self, eq, en, ru, elements=(), readings=(), angle=None):
        err = None if angle is None else intersection_error_mm(self.reader.precision, angle)
        self.steps.append(Step(len(self.steps) + 1, eq, en, ru, tuple(elements), tuple(readings),
                               None if angle is None else math.degrees(angle), err))

    def seg(self, name, a, b, role) -> Element:
        return Element("segment", name, as_xy(self.points[a]), as_xy(self.points[b]), role)

    def read(self, q: str, a: str, b: str) -> Vec2:
        """Read the segment a→b as the force q; return the force (N) as read."""
        d = self.points[b] - self.points[a]
        exact = float(np.hypot(*d))
        mm = self.reader(exact)
        self.readings[q] = Reading(a + b, mm, exact, q, mm * self.kp.per_mm, "N", self.kp.symbol)
        return unit_vector(d) * mm * self.kp.per_mm

    def lay(self, q: str, frm: str, vec: Vec2, role: str = "load", poly: bool = True) -> str:
        """Lay a known force from ``frm`` at Kp; a zero force adds nothing."""
        mag = float(np.hypot(*vec))
        if mag == 0:
            return frm
        mm = self.reader(mag / self.kp.per_mm)
        to = self.vertex(self.points[frm] + mm * unit_vector(vec))
        self.read(q, frm, to)
        if poly:
            self.poly.append((q, frm, to))
        self.step(q, f"Lay {q} = {plain(mag, 6)} N: {frm}{to} = {q}/Kp = {mm:.2f} mm, ∥ {q}.",
                  f"Откладываем {q} = {plain(mag, 6)} Н: {frm}{to} = {q}/Kp = {mm:.2f} мм, ∥ {q}.",
                  [self.seg(q, frm, to, role)], (q,))
        return to

    def chain(self, frm: str, forces: list[_F], poly: bool = True) -> str:
        for f in forces:
            frm = self.lay(f.name, frm, f.vec, poly=poly)
        return frm

    def laid(self, forces: list[_F]) -> list[tuple[str, str, str]]:
        """The polygon's segments of these forces."""
        names = {f.name for f in forces}
        return [s for s in self.poly if s[0] in names]

    def moments(self, cname: str, c: Vec2, forces: list[_F], couples: list[tuple[str, float]]):
        """Σ moments about c (N·mm of the drawing), the symbolic and numeric terms."""
        total, sym, num = 0.0, [], []
        for f in forces:
            mag = float(np.hypot(*f.vec))
            if mag == 0:
                continue
            h = self.reader(_arm(c, f.at, f.vec))
            s = 1.0 if float(cross(f.at - c, f.vec)) >= 0 else -1.0
            self.arms[f"h_{f.name}@{cname}"] = h
            total += s * mag * h
            sym.append(f"{_sgn(s)} {f.name}·h_{f.name}")
            num.append(f"{_sgn(s)} {plain(mag, 6)}·{h:.2f}")
        for name, m in couples:
            if m != 0:
                total += m / self.kl.per_mm
                sym.append(f"{_sgn(m)} {name}/Kl")
                num.append(f"{_sgn(m)} {plain(abs(m), 6)}/{plain(self.kl.per_mm, 6)}")
        return total, sym, num

    def tangential(self, q, link, cname, c, x, e, arm_name, forces, couples) -> Vec2:
        """Solve ``τ·h + Σ = 0`` about c for the component τ·e (at x) of a reaction.

        ``e`` is the assumed sense, chosen so that the unknown turns CCW about c; a
        negative τ means the opposite sense.
        """
        h = self.reader(abs(float(cross(x - c, e))))
        if h == 0:
            raise SingularPoseError(f"force plan: the line of {q} passes through {cname}")
        self.arms[f"h_{q}@{cname}"] = h
        total, sym, num = self.moments(cname, c, forces, couples)
        tau = -total / h + 0.0
        eq = " ".join([f"ΣM_{cname}(link {link}): {q}·{arm_name}", *sym, "= 0"])
        self.equations.append(eq)
        # the text writes round-off of the moments (a dead centre: 1e-13 N) as 0
        shown = 0.0 if abs(tau) <= 1e-12 * self.big else tau
        nums = " ".join([f"{q}·{h:.2f}", *num, f"= 0 → {q} = {plain(shown, 6)}"])
        none = none_ru = ""
        if not sym:
            none = f" (no known load of link {link} has a moment about {cname})"
            none_ru = (f" (ни одна известная нагрузка звена {link} не даёт момента "
                       f"относительно {cname})")
        rev = " (negative: the sense is opposite to the assumed one)" if shown < 0 else ""
        rev_ru = " (знак минус: направление противоположно принятому)" if shown < 0 else ""
        self.step(eq, f"{eq}; {nums} N{none}{rev}.", f"{eq}; {nums} Н{none_ru}{rev_ru}.")
        return tau * e

    def couple(self, q, link, cname, c, vec, u, sign, forces, couples):
        """The couple (N·m) of a prismatic reaction about its point c and its offset (mm).

        ``sign`` is +1 for the equation of the link the reaction acts on, −1 for the link
        that exerts it: ``sign·N·x + Σ = 0``.
        """
        total, sym, num = self.moments(cname, c, forces, couples)
        n = float(np.dot(vec, perp(u)))
        eq = " ".join([f"ΣM_{cname}(link {link}): {'' if sign > 0 else '−'}{q}·x_{q}", *sym,
                       "= 0"])
        self.equations.append(eq)
        couple = -sign * total * self.kl.per_mm + 0.0
        if abs(n) > 1e-12 * self.big and n != 0:
            x = -sign * total / n + 0.0
            en = f"{eq} → x_{q} = {x:.2f} mm along the guide from {cname}"
            ru = f"{eq} → x_{q} = {x:.2f} мм вдоль направляющей от {cname}"
        else:
            x = None
            en = (f"{eq}: {q} = 0, so its point of application is undefined (x = M/N); the "
                  f"same equation gives the pure couple of the pair M = {plain(couple, 6)} N·m")
            ru = (f"{eq}: {q} = 0, точка приложения не определена (x = M/N); то же уравнение "
                  f"даёт момент пары M = {plain(couple, 6)} Н·м")
        tail = f"; {' '.join(num)}." if num else "."
        self.step(eq, en + tail, ru + tail)
        return couple, x

    def close(self, eq, p1, d1, n1, p2, d2, n2) -> str:
        x, ang = intersect_lines(self.points[p1], d1, self.points[p2], d2)
        if ang == 0:
            raise SingularPoseError(f"force plan: the closing lines {n1}, {n2} are parallel")
        name = self.vertex(x)
        els = []
        for p, dd, n in ((p1, d1, n1), (p2, d2, n2)):
            u, q = unit_vector(dd), self.points[p]
            t = float(np.dot(x - q, u))
            lo, hi = min(0.0, t) - 8.0, max(0.0, t) + 8.0
            els.append(Element("line", n, as_xy(q + lo * u), as_xy(q + hi * u), "line"))
        els.append(Element("point", name, as_xy(x), as_xy(x), "point"))
        warn = warn_ru = ""
        if math.degrees(ang) < SMALL_ANGLE_DEG:
            err = (self.reader.precision or 0.5) / math.sin(ang)
            warn = f" Small angle (D.3): a line error moves {name} by ≈ {err:.1f} mm."
            warn_ru = f" Малый угол (D.3): ошибка линии смещает {name} на ≈ {err:.1f} мм."
        self.step(eq, f"Line {n1} through {p1}, line {n2} through {p2}: they meet at {name} "
                  f"at {math.degrees(ang):.1f}°.{warn}",
                  f"Линия {n1} через {p1}, линия {n2} через {p2}: пересекаются в {name} под "
                  f"углом {math.degrees(ang):.1f}°.{warn_ru}", els, angle=ang)
        return name

    def result(self, eq, segs) -> dict[str, Vec2]:
        out, en, ru, els = {}, [], [], []
        for q, a, b in segs:
            out[q] = self.read(q, a, b)
            r = self.readings[q]
            els.append(self.seg(q, a, b, "reaction"))
            en.append(f"{q} = {a}{b} = {r.mm:.2f} mm → {q} = {r.mm:.2f}"
                      f"·{plain(self.kp.per_mm, 6)} = "
                      f"{plain(r.value, 6)} N")
            ru.append(f"{q} = {a}{b} = {r.mm:.2f} мм → {q} = {r.mm:.2f}"
                      f"·{plain(self.kp.per_mm, 6)} = "
                      f"{plain(r.value, 6)} Н")
        self.step(eq, "; ".join(en) + ".", "; ".join(ru) + ".", els, tuple(out))
        return out


def _known(mech, kin, loads: Loads, k: int, links, reactions, origin: Vec2, kl: float):
    """Known forces and couples on each of ``links``: the loads and the reactions of the
    groups solved before (reversed: the force on the link that exerts them there)."""
    F: dict[str, list[_F]] = {ln: [] for ln in links}
    M: dict[str, list[tuple[str, float]]] = {ln: [] for ln in links}
    for ln in links:
        for f in loads.forces.get(ln, ()):
            if np.any(f.vector[k]):
                F[ln].append(_F(f.name, np.asarray(f.vector[k], float), (f.at[k] - origin) / kl))
        for m in loads.moments.get(ln, ()):
            if m.moment[k]:
                M[ln].append((m.name, float(m.moment[k])))
    for r in reactions.values():
        if r.by in F and r.on not in F:
            name = reaction_name(r.on, r.by)
            F[r.by].append(_F(name, -r.vector, (r.at - origin) / kl))
            if r.pair == "P" and r.offset_mm is None and r.couple:
                M[r.by].append((f"M{name[1:]}", -r.couple))
    return F, M


def _from_forces(forces: Forces, k: int) -> dict[str, PlanReaction]:
    out = {}
    for r in forces.reactions.values():
        off = float(r.offset[k]) if (r.pair == "P" and r.defined[k]) else None
        out[r.name] = PlanReaction(r.name, r.by, r.on, r.pair, np.asarray(r.vector[k], float),
                                   np.asarray(r.ref[k], float), np.asarray(r.at[k], float),
                                   float(r.couple[k]), off)
    return out


def _choose_kp(build, kp: Scale | None, known: set[str], room_mm: float = ROOM_MM) -> Scale:
    """Kp of the series so that the plan's extent is at most ``room_mm`` (ROOM_MM).

    The smallest of the plans' series 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10^k (the one
    Kv and Ka are chosen from, :data:`graphplan.units.PLAN_SERIES`) that keeps the plan's
    diameter (the largest distance between two vertices, so also its longest segment)
    within ``room_mm``: 80–100 % of it (the series steps by 1.25–1.33 at most), where the
    coarser 1, 2, 2.5, 4, 5 left plans at 50–100 % of their cells.
    Its basis names the largest known force (``Kp = Q/ab = 419930/139.98 = 3000 N/mm``).
    """
    if kp is not None:
        return kp
    trial = build(Scale("Kp", 1.0, "N/mm"), EXACT)
    ext = trial.extent_mm
    if ext <= 0:
        return Scale("Kp", 1.0, "N/mm")
    laid = [r for r in trial.readings.values() if r.quantity in known] or list(
        trial.readings.values())
    largest = max(laid, key=lambda r: r.value)
    return fit_scale("Kp", "N/mm", ext, room_mm, quantity=largest.quantity,
                     defining=largest.value, segment=largest.name, series=PLAN_SERIES)


def force_plan(mech: Mechanism, kin, forces: Forces | None, loads: Loads, k: int,
               group_index: int, kp: Scale | None = None, *, kl: Scale,
               reader: Reader = EXACT, known: dict[str, PlanReaction] | None = None,
               room_mm: float = ROOM_MM) -> ForcePlan:
    """Build the force plan of the Assur group ``mech.dyads[group_index]`` at position k.

    Parameters
    ----------
    mech : Mechanism
    kin : Kinematics
        Only the positions are used (the position plan at Kl).
    forces : Forces or None
        Exact kinetostatics: the reactions of the groups solved before this one (the
        later dyads) are taken from it unless ``known`` gives them.
    loads : Loads
        Weights, inertia forces and couples, the technological resistance.
    k : int
        Index of the position.
    group_index : int
        Index of the dyad in ``mech.dyads``.
    kp : Scale, optional
        The force scale; by default the series value that fits the plan in ROOM_MM.
    kl : Scale
        The length scale of the position plan (arms are read on it, in mm).
    reader : Reader
        Exact, or rounding every length (arms and segments) to a drafting precision.
    known : dict[str, PlanReaction], optional
        Reactions read off the plans of the groups drawn before (drafting errors then
        propagate as on a hand drawing).
    room_mm : float
        The largest extent of the plan on its sheet (the cell of sheet 2), mm.

    Returns
    -------
    ForcePlan
    """
    d = mech.dyads[group_index]
    origin = np.asarray(kin.pos.points[mech.crank.pivot][k], float)
    P = position_mm(kin, k, kl.per_mm, mech.crank.pivot)
    prior = known if known is not None else (_from_forces(forces, k) if forces else {})
    F, M = _known(mech, kin, loads, k, d.links, prior, origin, kl.per_mm)
    big = max([float(np.hypot(*f.vec)) for fs in F.values() for f in fs] + [0.0])

    def build(kp_: Scale, rd: Reader) -> ForcePlan:
        return _build_group(mech, kin, k, d, F, M, P, origin, kp_, kl, rd, big)

    return build(_choose_kp(build, kp, {f.name for fs in F.values() for f in fs}, room_mm), reader)


def _build_group(mech, kin, k, d, F, M, P, origin, kp, kl, reader, big) -> ForcePlan:
    reader = tally(reader)
    b = _Draw(kp, kl, reader, big)
    i, j = d.links
    pairs = dyad_pairs(mech, d)
    names = [reaction_name(p.by, p.on) for p in pairs]
    guide = {p.guide: np.asarray(kin.pos.guides[p.guide][1][k], float) for p in pairs if p.guide}
    Fi, Fj, Mi, Mj = F[i], F[j], M[i], M[j]
    sub: list[tuple[str, str, str]] = []
    offsets: dict[int, tuple[float, float | None]] = {}
    res: dict[str, Vec2] = {}
    n0, n1, n2 = names
    kind = d.kind
    if kind in ("RRR", "RRP"):
        A, B = d.joints[:2]
        e1 = perp(unit_vector(P[A] - P[B]))
        t1 = b.tangential(f"Rτ{n0[1:]}", i, B, P[B], P[A], e1, f"{A}{B}", Fi, Mi)
        if kind == "RRR":
            C = d.joints[2]
            e2 = perp(unit_vector(P[C] - P[B]))
            t2 = b.tangential(f"Rτ{n2[1:]}", j, B, P[B], P[C], e2, f"{C}{B}", Fj, Mj)
        v1 = b.lay(f"Rτ{n0[1:]}", "a", t1, "tangential")
        J = b.chain(v1, Fi)
        e0 = b.chain(J, Fj)
        if kind == "RRR":
            e = b.lay(f"Rτ{n2[1:]}", e0, t2, "tangential")
            eq = f"Rτ{n0[1:]} + ΣF{i} + ΣF{j} + Rτ{n2[1:]} + Rn{n2[1:]} + Rn{n0[1:]} = 0"
            X = b.close(eq, e, P[B] - P[C], f"Rn{n2[1:]} ∥ {C}{B}", "a", P[B] - P[A],
                        f"Rn{n0[1:]} ∥ {A}{B}")
            b.poly += [(f"Rn{n2[1:]}", e, X), (f"Rn{n0[1:]}", X, "a")]
            res = b.result(eq, [(f"Rn{n0[1:]}", X, "a"), (n0, X, v1), (f"Rn{n2[1:]}", e, X),
                                (n2, e0, X), (n1, X, J)])
        else:
            u = guide[pairs[2].slide_guide]
            eq = f"Rτ{n0[1:]} + ΣF{i} + ΣF{j} + {n2} + Rn{n0[1:]} = 0"
            X = b.close(eq, e0, perp(u), f"{n2} ⟂ guide", "a", P[B] - P[A],
                        f"Rn{n0[1:]} ∥ {A}{B}")
            b.poly += [(n2, e0, X), (f"Rn{n0[1:]}", X, "a")]
            res = b.result(eq, [(f"Rn{n0[1:]}", X, "a"), (n0, X, v1), (n2, e0, X), (n1, X, J)])
            offsets[2] = b.couple(n2, j, B, P[B], res[n2], u, 1, Fj, Mj)
        sub = [(n0, X, v1), *b.laid(Fi), (f"R{j}{i}", J, X)]
    elif kind == "RPR":
        A, C = d.joints
        u = guide[pairs[1].slide_guide]
        nrm = perp(u)
        e1 = nrm * (1.0 if float(np.dot(P[A] - P[C], u)) >= 0 else -1.0)
        along = -sum((float(np.dot(f.vec, u)) for f in Fi), 0.0) + 0.0
        rn = along * u
        b.step(f"Rn{n0[1:]} + ΣF{i}·u = 0",
               f"The forces on block {i} projected on the slot, where u is the unit vector "
               f"along the slot; R{j}{i} ⟂ slot (no friction) has no projection, "
               f"Rn{n0[1:]} is the component of R{n0[1:]} along u and ΣF{i}·u the sum of the "
               f"projections of the known forces on block {i}: Rn{n0[1:]} = −ΣF{i}·u = "
               f"{plain(along, 6)} N.",
               f"Проекция сил, действующих на камень {i}, на направление кулисы, где u — "
               f"единичный вектор вдоль кулисы; R{j}{i} ⟂ кулисе (трения нет) проекции не "
               f"даёт, Rn{n0[1:]} — составляющая R{n0[1:]} вдоль u, ΣF{i}·u — сумма проекций "
               f"известных сил камня {i}: Rn{n0[1:]} = −ΣF{i}·u = {plain(along, 6)} Н.")
        extra = [_F(f"Rn{n0[1:]}", rn, P[A])] if along else []
        t1 = b.tangential(f"Rτ{n0[1:]}", f"{i}+{j}", C, P[C], P[A], e1, f"h_Rτ{n0[1:]}",
                          Fi + Fj + extra, Mi + Mj)
        v1 = b.lay(f"Rτ{n0[1:]}", "a", t1, "tangential")
        v2 = b.lay(f"Rn{n0[1:]}", v1, rn, "normal")
        J = b.chain(v2, Fi)
        e = b.chain(J, Fj)
        eq = f"{n0} + ΣF{i} + ΣF{j} + {n2} = 0"
        b.poly.append((n2, e, "a"))
        res = b.result(eq, [(n0, "a", v2), (n2, e, "a"), (n1, "a", J)])
        offsets[1] = b.couple(n1, i, A, P[A], res[n1], u, -1, Fi, Mi)
        sub = [(n0, "a", v2), *b.laid(Fi), (f"R{j}{i}", J, "a")]
    elif kind == "PRP":
        (B,) = d.joints
        u1, u2 = guide[pairs[0].slide_guide], guide[pairs[2].slide_guide]
        J = b.chain("a", Fi)
        e = b.chain(J, Fj)
        eq = f"{n0} + ΣF{i} + ΣF{j} + {n2} = 0"
        X = b.close(eq, e, perp(u2), f"{n2} ⟂ guide of {j}", "a", perp(u1),
                    f"{n0} ⟂ guide of {i}")
        b.poly += [(n2, e, X), (n0, X, "a")]
        res = b.result(eq, [(n0, X, "a"), (n2, e, X), (n1, X, J)])
        offsets[0] = b.couple(n0, i, B, P[B], res[n0], u1, 1, Fi, Mi)
        offsets[2] = b.couple(n2, j, B, P[B], res[n2], u2, 1, Fj, Mj)
        sub = [(n0, X, "a"), *b.laid(Fi), (f"R{j}{i}", J, X)]
    else:  # RPP
        A, D = d.joints
        us, ug = guide[pairs[1].slide_guide], guide[pairs[2].slide_guide]
        e = b.chain("a", Fj)
        eq = f"{n1} + ΣF{j} + {n2} = 0"
        X = b.close(eq, e, perp(ug), f"{n2} ⟂ guide", "a", perp(us), f"{n1} ⟂ slot")
        r = b.result(eq, [(n1, X, "a"), (n2, e, X)])
        group = [*b.poly, (n2, e, X)]
        b.poly = []
        w = b.chain(X, Fi)
        eq2 = f"R{j}{i} + ΣF{i} + {n0} = 0"
        res = {**r, **b.result(eq2, [(n0, w, "a")])}
        sub = [(f"R{j}{i}", "a", X), *b.poly, (n0, w, "a")]
        b.poly = [(n0, w, "a"), *group, *sub[1:-1]]
        offsets[1] = b.couple(n1, i, A, P[A], res[n1], us, -1, Fi, Mi)
        c1, x1 = offsets[1]
        at1 = P[A] + (x1 if x1 is not None else 0.0) * us
        mj = Mj + ([(f"M{n1[1:]}", c1)] if x1 is None and c1 else [])
        offsets[2] = b.couple(n2, j, D, P[D], res[n2], ug, 1, [*Fj, _F(n1, res[n1], at1)], mj)
    reactions = {}
    for idx, (pr, nm) in enumerate(zip(pairs, names, strict=True)):
        ref = np.asarray(kin.pos.points[pr.point][k], float)
        couple, x = offsets.get(idx, (0.0, None))
        at = ref if x is None else ref + x * kl.per_mm * guide[pr.slide_guide]
        reactions[nm] = PlanReaction(nm, pr.by, pr.on, pr.kind, res[nm], ref, at, couple, x)
    return ForcePlan("force", kin.labels[k], d.name, kp, dict(b.points), tuple(b.steps),
                     dict(b.readings), tuple(b.equations),
                     {"group": tuple(b.poly), f"link {i}": tuple(sub)}, reactions, dict(b.arms),
                     reads=len(reader.taken))


def crank_plan(mech: Mechanism, kin, forces: Forces | None, loads: Loads, k: int,
               kp: Scale | None = None, *, kl: Scale, reader: Reader = EXACT,
               known: dict[str, PlanReaction] | None = None,
               room_mm: float = ROOM_MM) -> ForcePlan:
    """The crank: the balancing moment from ``ΣM_O = 0`` and R41 from its force polygon.

    ``Mур/Kl + Σ±F·h = 0`` about the pivot O, the forces being the groups' reactions on
    the crank (``R21 = −R12`` at A) and its own loads, the arms (``h21``) measured on the
    position plan in mm; so ``Mур = −Σ±F·h·Kl`` (N·m, CCW positive) —
    ``Mур = R21·h21·Kl`` with its sign when R21 is the only moment. The polygon
    ``R21 + G1 + Pи1 + R41 = 0`` is closed by the frame's reaction R41.

    Parameters are those of :func:`force_plan`; ``known`` holds the reactions read off the
    first group's plan (by default the exact ones of ``forces``).
    """
    cr = mech.crank
    origin = np.asarray(kin.pos.points[cr.pivot][k], float)
    P = position_mm(kin, k, kl.per_mm, cr.pivot)
    prior = known if known is not None else (_from_forces(forces, k) if forces else {})
    F, M = _known(mech, kin, loads, k, (cr.link,), prior, origin, kl.per_mm)
    fs = sorted(F[cr.link], key=lambda f: not f.name.startswith("R"))
    big = max([float(np.hypot(*f.vec)) for f in fs] + [0.0])
    r41 = reaction_name(mech.frame_link, cr.link)

    def build(kp_, rd):
        rd = tally(rd)
        b = _Draw(kp_, kl, rd, big)
        total, sym, num = b.moments(cr.pivot, P[cr.pivot], fs, M[cr.link])
        mb = -total * kl.per_mm
        for f in fs:
            if f.name.startswith("R") and f"h_{f.name}@{cr.pivot}" in b.arms:
                b.arms["h" + f.name[1:]] = b.arms[f"h_{f.name}@{cr.pivot}"]
        mb += 0.0
        eq = " ".join([f"ΣM_{cr.pivot}(link {cr.link}): Mур/Kl", *sym, "= 0"])
        b.equations.append(eq)
        # round-off of the moments (a dead centre: 1e-13 N·m) is written 0
        shown = 0.0 if abs(mb) <= 1e-12 * max(big, 1.0) * cr.length else mb
        nums = " ".join([f"Mур/{plain(kl.per_mm, 6)}", *num, f"= 0 → Mур = {plain(shown, 6)}"])
        b.step(eq, f"{eq}; {nums} N·m (CCW positive).",
               f"{eq}; {nums} Н·м (против часовой стрелки — плюс).")
        e = b.chain("a", fs)
        b.poly.append((r41, e, "a"))
        res = b.result(f"ΣF{cr.link} + {r41} = 0", [(r41, e, "a")])
        ref = origin.copy()
        reac = {r41: PlanReaction(r41, mech.frame_link, cr.link, "R", res[r41], ref, ref)}
        return ForcePlan("force", kin.labels[k], f"crank {cr.link}", kp_, dict(b.points),
                         tuple(b.steps), dict(b.readings), tuple(b.equations),
                         {"group": tuple(b.poly)}, reac, dict(b.arms), mb, len(rd.taken))

    return build(_choose_kp(build, kp, {f.name for f in fs}, room_mm), reader)


def force_plans(mech: Mechanism, kin, forces: Forces | None, loads: Loads, k: int,
                kl: Scale | tuple[Scale, ...], reader: Reader = EXACT,
                room_mm: float | tuple[float, ...] = ROOM_MM, *,
                scales: dict[int, Scale] | None = None, memo: dict | None = None
                ) -> tuple[ForcePlan, ...]:
    """All force plans of position k: the groups from the last to the first, then the crank.

    Each group takes the reactions of the groups drawn before it as read off their plans
    (so a drafting reader's errors propagate), each plan with its own Kp of the series.
    ``scales`` (plan number → Kp), when given, keeps the Kp of each plan: one chosen (by a
    trial build) is stored there, one found there is used — the error bounds build the
    plans again with one reading shifted, at the scales of the unshifted plans. ``room_mm``:
    one room for every plan, or one per plan in their order (sheet 2 sizes each plan's cell
    to its shape). ``kl``: the Kl of the position plan every plan's arms are read on, or one
    per plan (sheet 2 draws each group and the crank at its own Kl; each group then takes
    the reactions as read off the plans drawn before it, at theirs). ``memo``: the project's
    store of the plans built (:func:`chain_plan`), each plan of the same inputs built once.
    """
    n = len(mech.dyads) + 1
    rooms = tuple(room_mm) if isinstance(room_mm, tuple) else (room_mm,) * n
    kls = tuple(kl) if isinstance(kl, tuple) else (kl,) * n
    known: dict[str, PlanReaction] = {}
    plans: list[ForcePlan] = []
    kps = scales if scales is not None else {}
    how = ("read", reader.precision) if type(reader) is Reader else None
    for m in range(n):
        p, _ = chain_plan(mech, kin, forces, loads, k, m, kps.get(m), kls[m], reader, known,
                          rooms[m], memo if how is not None else None, how)
        kps.setdefault(m, p.scale)
        known.update(p.reactions)
        plans.append(p)
    return tuple(plans)


def _known_key(known: dict[str, PlanReaction]) -> tuple:
    """The reactions a plan takes from the plans before it, bit for bit."""
    return tuple(sorted((n, r.by, r.on, r.pair, np.asarray(r.vector, float).tobytes(),
                         np.asarray(r.ref, float).tobytes(), np.asarray(r.at, float).tobytes(),
                         float(r.couple), r.offset_mm) for n, r in known.items()))


def chain_plan(mech: Mechanism, kin, forces: Forces | None, loads: Loads, k: int, m: int,
               kp: Scale | None, kl: Scale, reader: Reader, known: dict[str, PlanReaction],
               room_mm: float, memo: dict | None = None, how: tuple | None = None,
               found_as: tuple[tuple, ...] = ()) -> tuple[ForcePlan, bool]:
    """Plan ``m`` of position k's chain (the groups from the last attached, then the crank),
    built once per project: ``memo`` keeps every plan by what it is built from (its Kl, Kp,
    room, the reactions it takes, ``how`` it is read), so the tables, sheet 2 and the error
    bounds' probes build a plan of the same inputs once; ``found_as``: other ways of reading
    that give the same figures (a probe that shifts no reading of this plan reads it
    exactly), whose plans are taken but not kept under ``how``. Returns (plan, found)."""
    if memo is None or how is None:
        return _build_plan(mech, kin, forces, loads, k, m, kp, kl, reader, known, room_mm), False
    inputs = (id(loads), k, m, kl.per_mm, room_mm, _known_key(known))
    kps = None if kp is None else kp.per_mm
    for h in (how, *found_as):
        if (*inputs, kps, h) in memo:
            return memo[(*inputs, kps, h)], True
    p = _build_plan(mech, kin, forces, loads, k, m, kp, kl, reader, known, room_mm)
    memo[(*inputs, kps, how)] = p
    if kp is None:  # chosen by its trial build: the same plan as at that Kp given
        memo[(*inputs, p.scale.per_mm, how)] = p
    return p, False


def _build_plan(mech, kin, forces, loads, k, m, kp, kl, reader, known, room_mm) -> ForcePlan:
    gi = len(mech.dyads) - 1 - m
    if gi < 0:
        return crank_plan(mech, kin, forces, loads, k, kp, kl=kl, reader=reader, known=known,
                          room_mm=room_mm)
    return force_plan(mech, kin, forces, loads, k, gi, kp, kl=kl, reader=reader, known=known,
                      room_mm=room_mm)


__all__ = ["ROOM_MM", "ForcePlan", "PlanReaction", "chain_plan", "crank_plan", "force_plan",
           "force_plans"]
