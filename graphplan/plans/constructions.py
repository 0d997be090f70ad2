"""Plans of velocities and accelerations built as the draftsman builds them.

Each plan is an ordered list of :class:`Step` objects drawn in millimetres of the
sheet, in the plan's own frame (pole at the origin, x right, y up, the same
orientation as the position plan). Every direction is taken off the *position
plan* (``⟂ AB``, ``∥ guide``), every known length is a reading of an earlier
plan converted with its scale, and each new point is the intersection of the two
lines of the dyad's vector equation. Values are then read back off the geometry:
``v_B = pb·Kv``.

A :class:`Reader` decides how lengths are read: exactly (``precision = 0``) or
rounded to a drafting precision (e.g. 0.5 mm), which then propagates through
every later step as on a hand drawing.

Naming, as on the sheets: plan points are lowercase (``p`` the velocity pole,
``π`` the acceleration pole, ``a``, ``b``, ``s2``); a point of link k coinciding
with joint B is ``b4`` (link number appended); the end of a normal component is
``n_BA``, of a Coriolis component ``k_…``. Segments are named by their end
points (``pb``, ``ab``, ``πb``) or by the component (``n_BA``, ``τ_BA``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..geometry import cross, perp
from ..model import Dyad, Mechanism
from ..numbers import plain
from ..units import Scale, unit_text

Vec2 = np.ndarray


@dataclass(frozen=True, slots=True)
class Element:
    """One drawn element of a step: a vector segment, a construction line or a point.

    ``role`` is ``absolute`` (from the pole), ``relative``, ``normal``,
    ``tangential``, ``coriolis``, ``sliding``, ``line`` (a construction line of
    known direction) or ``point``.
    """

    kind: str  # "segment" | "line" | "point"
    name: str
    start: tuple[float, float]
    end: tuple[float, float]
    role: str


ZERO_MM = 1e-9
"""A segment shorter than this (mm) is round-off of an exact construction: its value is
written 0 in the steps' texts (a dead centre's v_B of 1e-16 m/s)."""

def _written(value: float, vec_mm) -> float:
    """``value`` as a step's text writes it: 0 when its vector on the plan is round-off."""
    return 0.0 if float(np.hypot(*vec_mm)) < ZERO_MM else value


MAX_ERROR_MM = 1e6
"""The uncertainty written for lines that do not meet (parallel): finite, and off any sheet."""


def intersection_error_mm(precision: float, angle: float) -> float:
    """How far an intersection moves for a reading error: ``p / sin α``, mm.

    ``angle`` is the angle between the two lines (rad); ``precision`` the reading
    precision ``p`` (mm; 0, the exact reader, is taken as the draftsman's 0.5 mm). Never
    more than :data:`MAX_ERROR_MM`, so that no infinity reaches a table.
    """
    p = precision or 0.5
    s = math.sin(angle)
    return min(p / s, MAX_ERROR_MM) if s > 0 else MAX_ERROR_MM


@dataclass(frozen=True, slots=True)
class Step:
    """One step of a construction, in drawing order.

    ``equation`` is the vector equation being drawn; ``text``/``text_ru`` say what
    is drawn; ``angle_deg`` is the angle between the two intersecting lines (for
    an intersection step) and ``error_mm`` the resulting uncertainty of the new
    point for the reader's precision, ≈ precision / sin(angle).
    """

    number: int
    equation: str
    text: str
    text_ru: str
    elements: tuple[Element, ...]
    readings: tuple[str, ...] = ()
    angle_deg: float | None = None
    error_mm: float | None = None


@dataclass(frozen=True, slots=True)
class Reading:
    """A segment measured on a plan: ``mm`` as read, and its physical value."""

    name: str
    mm: float
    exact_mm: float
    quantity: str
    value: float
    unit: str
    scale: str


@dataclass(frozen=True, slots=True)
class Plan:
    """A velocity or acceleration plan of one position.

    Attributes
    ----------
    kind : str
        ``"velocity"`` or ``"acceleration"``.
    label : str
        The position's label.
    scale : Scale
    points : dict[str, ndarray]
        Plan points in mm (pole at the origin).
    steps : tuple[Step, ...]
    readings : dict[str, Reading]
    rates : dict[str, float]
        ω (velocity plan, rad/s) or ε (acceleration plan, rad/s²) of each link,
        derived from the readings, CCW positive.
    sliding : dict[str, float]
        Signed relative sliding speed (or acceleration) of each sliding pair ``j/k``.
    """

    kind: str
    label: str
    scale: Scale
    points: dict[str, Vec2]
    steps: tuple[Step, ...]
    readings: dict[str, Reading]
    rates: dict[str, float]
    sliding: dict[str, float] = field(default_factory=dict)
    reads: int = field(default=0, compare=False)  #: readings the reader took (:class:`Tally`)

    def measure(self, a: str, b: str) -> float:
        """Length (mm) between two plan points, measured exactly."""
        return float(np.hypot(*(self.points[b] - self.points[a])))

    def value(self, name: str) -> float:
        """Physical value of a reading."""
        return self.readings[name].value

    def _repr_svg_(self) -> str:
        """Jupyter: the whole construction, each vector in its role's colour."""
        from ..teaching.drawing import construction_svg

        return construction_svg(self)


@dataclass(frozen=True, slots=True)
class Reader:
    """How the draftsman reads a length: exactly, or rounded to ``precision`` mm."""

    precision: float = 0.0

    def __call__(self, mm: float) -> float:
        if self.precision <= 0:
            return float(mm)
        return float(round(mm / self.precision) * self.precision)


EXACT = Reader(0.0)


@dataclass(frozen=True)
class Tally(Reader):
    """Reads as ``of`` does and counts the readings taken: every plan records how many
    (``reads``), so that the error bounds can shift each in turn on the plans built once."""

    of: Reader = EXACT
    taken: list = field(default_factory=list, compare=False, repr=False)

    def __call__(self, mm: float) -> float:
        self.taken.append(mm)
        return self.of(mm)


def tally(reader: Reader) -> Tally:
    """``reader``, counting its readings."""
    return Tally(reader.precision, reader)


def lower(name: str) -> str:
    """Plan name of a point: ``B`` → ``b``, ``S2`` → ``s2``."""
    return name.lower()


def as_xy(v) -> tuple[float, float]:
    return (float(v[0]), float(v[1]))


def unit_vector(v: Vec2) -> Vec2:
    n = math.hypot(float(v[0]), float(v[1]))  # a 2-vector: math is 3× numpy's hypot
    return v / n if n > 0 else np.zeros(2)


def intersect_lines(p1: Vec2, d1: Vec2, p2: Vec2, d2: Vec2) -> tuple[Vec2, float]:
    """Intersection of the lines ``p1 + t·d1`` and ``p2 + s·d2``; and their angle (rad).

    The angle is in [0, π/2]; it is 0 for parallel lines, where the point is
    undefined and ``p2`` is returned (the caller reports the step as singular).
    """
    den = float(cross(d1, d2))
    n1, n2 = float(np.hypot(*d1)), float(np.hypot(*d2))
    sine = abs(den) / (n1 * n2) if n1 > 0 and n2 > 0 else 0.0
    angle = math.asin(min(1.0, sine))
    if sine < 1e-12:
        return p2.copy(), 0.0
    t = float(cross(p2 - p1, d2)) / den
    return p1 + t * d1, angle


POLES = ("p", "π")
"""Names of the poles of the velocity and acceleration plans."""


def plan_name(mech: Mechanism, point: str, pole: str) -> str:
    """Plan letter of the model point ``point`` on a plan whose pole is ``pole``.

    A frame point is the pole; any other point is its lowercase letter, except a point
    whose letter is a pole's (the piston ``P`` → ``p``, a ``Π``): it takes the number of
    the link it was defined on (``p3``), so it never reads as the pole. Every reader of a
    plan names its points through this function.
    """
    if point in mech.frame_points or point == mech.crank.pivot:
        return pole
    name = point.lower()
    if name in POLES:
        name += mech.home_link(point)
    return name


class _Builder:
    """Accumulates the steps, points and readings of one plan."""

    def __init__(self, kind: str, pole: str, scale: Scale, reader: Reader, fixed=(),
                 home=None):
        self.home = home
        self.kind = kind
        self.pole = pole
        self.fixed = set(fixed)
        self.scale = scale
        self.reader = reader
        self.points: dict[str, Vec2] = {pole: np.zeros(2)}
        self.steps: list[Step] = []
        self.readings: dict[str, Reading] = {}
        self.ends: dict[str, tuple[str, str]] = {}  # reading name -> (from point, to point)

    def add_step(self, equation, text, text_ru, elements, readings=(), angle=None):
        err = None if angle is None else intersection_error_mm(self.reader.precision, angle)
        self.steps.append(Step(len(self.steps) + 1, equation, text, text_ru, tuple(elements),
                               tuple(readings), None if angle is None else math.degrees(angle),
                               err))

    def key(self, point: str) -> str:
        """Plan name of a model point: the pole for a frame point, else lowercase.

        A point whose letter is a pole's (the punch ``P`` → ``p``) takes its link's
        number, ``p5``, so it never reads as the pole.
        """
        if point in self.fixed:
            return self.pole
        name = point.lower()
        if name in POLES and self.home is not None:
            name += self.home(point)
        return name

    def read(self, name: str, a: str, b: str, quantity: str) -> Reading:
        exact = float(np.hypot(*(self.points[b] - self.points[a])))
        mm = self.reader(exact)
        self.ends[name] = (a, b)
        r = Reading(name, mm, exact, quantity, mm * self.scale.per_mm,
                    self.scale.unit.rsplit("/", 1)[0].strip("()"), self.scale.symbol)
        self.readings[name] = r
        return r

    def segment(self, name: str, a: str, b: str, role: str) -> Element:
        return Element("segment", name, as_xy(self.points[a]), as_xy(self.points[b]), role)

    def line(self, name: str, through: Vec2, direction: Vec2, hit: Vec2) -> Element:
        """A construction line through ``through`` drawn past the point ``hit`` it meets."""
        d = unit_vector(direction)
        t_hit = float(np.dot(hit - through, d))
        lo, hi = min(0.0, t_hit) - 8.0, max(0.0, t_hit) + 8.0
        return Element("line", name, as_xy(through + lo * d), as_xy(through + hi * d), "line")

    def build(self, label: str, rates, sliding) -> Plan:
        reads = len(self.reader.taken) if isinstance(self.reader, Tally) else 0
        return Plan(self.kind, label, self.scale, dict(self.points), tuple(self.steps),
                    dict(self.readings), dict(rates), dict(sliding), reads)


class _Images:
    """Plan images of the links: which plan point stands for which point of a link.

    A point of a link whose image is known at two points is placed by the theorem
    of similarity (the image of a link is similar to the link); with only one
    known point, from the link's rate read off the plan.
    """

    def __init__(self, mech: Mechanism, pos_mm: dict[str, Vec2], scale_l: float, pole: str):
        self.mech = mech
        self.pos = pos_mm
        self.kl = scale_l
        self.known: dict[str, list[tuple[Vec2, str]]] = {mech.frame_link: []}
        self.names: dict[tuple[str, str], str] = {}
        self.pole = pole

    def add(self, link: str, model_point: str | Vec2, plan_point: str) -> None:
        xy = self.pos[model_point] if isinstance(model_point, str) else model_point
        lst = self.known.setdefault(link, [])
        if all(np.hypot(*(xy - q)) > 1e-9 for q, _ in lst):
            lst.append((np.asarray(xy, float), plan_point))
            if isinstance(model_point, str):
                self.names[(link, plan_point)] = model_point

    def add_all(self, *entries: tuple[str, str | Vec2, str]) -> None:
        """:meth:`add` each (link, model point, plan point)."""
        for link, model_point, plan_point in entries:
            self.add(link, model_point, plan_point)

    def basis(self, link: str) -> tuple[tuple[str, Vec2, str], tuple[str, Vec2, str]] | None:
        """The two named points (model name, position mm, plan point) similarity uses."""
        lst = self.known.get(link, [])
        if len(lst) < 2:
            return None
        (G, g), (H, h) = lst[0], lst[1]
        gn, hn = self.names.get((link, g)), self.names.get((link, h))
        if gn is None or hn is None:
            return None
        return (gn, G, g), (hn, H, h)

    def place(self, b: _Builder, link: str, X: Vec2, rate_map) -> Vec2:
        """Plan point of the point X (position-plan mm) of ``link``."""
        if link == self.mech.frame_link:
            return np.zeros(2)
        lst = self.known.get(link, [])
        if len(lst) >= 2:
            (G, g), (H, h) = lst[0], lst[1]
            zg, zh = complex(*b.points[g]), complex(*b.points[h])
            z = zg + (zh - zg) * complex(*(X - G)) / complex(*(H - G))
            return np.array([z.real, z.imag])
        G, g = lst[0]
        return b.points[g] + rate_map(link, (X - G))


def position_mm(kin, k: int, scale_l: float, origin: str) -> dict[str, Vec2]:
    """The position plan of position k: model points in mm about the crank pivot."""
    o = kin.pos.points[origin][k]
    return {n: (p[k] - o) / scale_l for n, p in kin.pos.points.items()}


def _guide_dir(kin, k: int, key: str) -> Vec2:
    return np.asarray(kin.pos.guides[key][1][k], float)


def velocity_plan(mech: Mechanism, kin, k: int, kl: Scale, kv: Scale,
                  reader: Reader = EXACT) -> Plan:
    """Build the velocity plan of position k.

    The equations per dyad are those of :mod:`graphplan.kinematics.velocities`; here each is
    drawn: from the known end a line of the first direction, from the other known
    end a line of the second, and the unknown point at their intersection.

    Parameters
    ----------
    mech : Mechanism
    kin : Kinematics
        Only the *positions* are used (the position plan); velocities are
        constructed, not copied.
    k : int
        Index of the position in ``kin``.
    kl, kv : Scale
        Length and velocity scales.
    reader : Reader
        Exact, or rounding every reading to a drafting precision.

    Returns
    -------
    Plan
    """
    P = position_mm(kin, k, kl.per_mm, mech.crank.pivot)
    reader = tally(reader)
    b = _Builder("velocity", "p", kv, reader, mech.frame_points, mech.home_link)
    img = _Images(mech, P, kl.per_mm, "p")
    lower = b.key
    rates: dict[str, float] = {mech.frame_link: 0.0}
    sliding: dict[str, float] = {}
    ratio = kl.per_mm / kv.per_mm

    def rate_map(link, r_mm):
        return rates[link] * ratio * perp(r_mm)

    def length_m(p1: str, p2: str) -> float:
        """A length read on the position plan, in metres."""
        return reader(float(np.hypot(*(P[p2] - P[p1])))) * kl.per_mm

    b.add_step("", "Pole p: points of the frame (zero velocity) are at p.",
               "Полюс p: точки стойки (скорость равна нулю) находятся в p.",
               [Element("point", "p", (0.0, 0.0), (0.0, 0.0), "point")])
    for fp in mech.frame_points:
        img.add(mech.frame_link, fp, "p")
    cr = mech.crank
    o, a = cr.pivot, cr.pin
    va = abs(cr.omega) * cr.length
    pa_mm = reader(va / kv.per_mm)
    d = unit_vector(perp(P[a] - P[o])) * cr.sense
    b.points[lower(a)] = pa_mm * d
    b.read("p" + lower(a), "p", lower(a), f"v_{a}")
    b.add_step(f"v_{a} = ω1·l_{o}{a}",
               f"v_{a} = ω1·l_{o}{a} = {plain(abs(cr.omega), 4)}·{plain(cr.length, 4)} = "
               f"{plain(va, 4)} m/s; "
               f"p{lower(a)} = v_{a}/Kv = {pa_mm:.2f} mm, ⟂ {o}{a} in the sense of ω1.",
               f"v_{a} = ω1·l_{o}{a} = {plain(abs(cr.omega), 4)}·{plain(cr.length, 4)} = "
               f"{plain(va, 4)} м/с; "
               f"p{lower(a)} = v_{a}/Kv = {pa_mm:.2f} мм, ⟂ {o}{a} в сторону ω1.",
               [b.segment("p" + lower(a), "p", lower(a), "absolute")], ("p" + lower(a),))
    rates[cr.link] = cr.omega
    img.add(cr.link, o, "p")
    img.add(cr.link, a, lower(a))
    _similar_points(mech, b, img, cr.link, P, rate_map, "velocity")

    for dy in mech.dyads:
        _velocity_dyad(mech, dy, kin, k, b, img, P, rates, sliding, rate_map, length_m)
        for ln in dy.links:
            _similar_points(mech, b, img, ln, P, rate_map, "velocity")
    return b.build(kin.labels[k], rates, sliding)


def _similar_points(mech, b: _Builder, img: _Images, link: str, P, rate_map, kind: str) -> None:
    """Place the other points of a link on the plan by the theorem of similarity."""
    pole = b.pole
    for name in mech.points_of(link):
        pn = b.key(name)
        if pn in b.points or link == mech.frame_link:
            continue
        b.points[pn] = img.place(b, link, P[name], rate_map)
        en, ru = _proportion(b, img, link, name, pn, P)  # of the images known before it
        img.add(link, name, pn)
        seg = pole + pn
        q = "v" if kind == "velocity" else "a"
        b.read(seg, pole, pn, f"{q}_{name}")
        b.add_step(
            f"{q}_{name}: similarity on link {link}",
            f"Point {pn} of link {link} by the theorem of similarity: the image of the link "
            f"is similar to the link{en}; {seg} = {b.readings[seg].mm:.2f} mm.",
            f"Точка {pn} звена {link} по теореме подобия: изображение звена подобно звену"
            f"{ru}; {seg} = {b.readings[seg].mm:.2f} мм.",
            [b.segment(seg, pole, pn, "absolute")], (seg,))


def _proportion(b: _Builder, img: _Images, link: str, name: str, pn: str, P
                ) -> tuple[str, str]:
    """The proportion of similarity written out, ``as2 = ab·l_AS2/l_AB = 46.08·0.1/0.2 =
    23.04 mm``, with the angle to lay it at when X is off the line GH (en, ru)."""
    basis = img.basis(link)
    if basis is None:
        return "", ""
    (gn, G, g), (hn, H, h) = basis
    X = np.asarray(P[name], float)
    gh, gx = b.points[h] - b.points[g], b.points[pn] - b.points[g]
    l_gh, l_gx = float(np.hypot(*(H - G))) * img.kl, float(np.hypot(*(X - G))) * img.kl
    head = f"{g}{pn} = {g}{h}·l_{gn}{name}/l_{gn}{hn} = {float(np.hypot(*gh)):.2f}·" \
           f"{plain(l_gx, 4)}/{plain(l_gh, 4)} = {float(np.hypot(*gx)):.2f}"
    ang = math.degrees(math.atan2(cross(H - G, X - G), float(np.dot(H - G, X - G))))
    en, ru = f": {head} mm", f": {head} мм"
    if 0.05 < abs(ang) < 179.95:
        turn = ("counter-clockwise", "против часовой стрелки") if ang > 0 else (
            "clockwise", "по часовой стрелке")
        en += f", at {abs(ang):.1f}° from {g}{h} {turn[0]} (∠({gn}{hn}, {gn}{name}) on the link)"
        ru += f", под углом {abs(ang):.1f}° к {g}{h} {turn[1]} (∠({gn}{hn}, {gn}{name}) на звене)"
    elif abs(ang) >= 179.95:
        en += f", on the other side of {g}"
        ru += f", по другую сторону от {g}"
    return en, ru


_LINE_RU = ((" through ", " через "), ("∥ guide of ", "∥ направляющей звена "),
            ("∥ guide", "∥ направляющей"), ("∥ slot", "∥ оси кулисы"))


def _line_ru(name: str) -> str:
    """A construction line's name in Russian: ``∥ guide through p`` → ``∥ направляющей через p``."""
    for en, ru in _LINE_RU:
        name = name.replace(en, ru)
    return name


def _close_two_lines(b: _Builder, eq: str, new: str, p1: Vec2, d1: Vec2, n1: str,
                     p2: Vec2, d2: Vec2, n2: str) -> None:
    """Draw the two lines of a vector equation and take their intersection as ``new``."""
    x, ang = intersect_lines(p1, d1, p2, d2)
    b.points[new] = x
    b.add_step(eq, f"Line {n1}, line {n2}; they meet at {new} at {math.degrees(ang):.1f}°.",
               f"Линия {_line_ru(n1)}, линия {_line_ru(n2)}; пересекаются в точке {new} под углом "
               f"{math.degrees(ang):.1f}°.",
               [b.line(n1, p1, d1, x), b.line(n2, p2, d2, x),
                Element("point", new, as_xy(x), as_xy(x), "point")], angle=ang)


def _result(b: _Builder, eq: str, segments) -> None:
    """Draw the vectors an intersection gave and read them: ``pb = 56.20 mm → v_B = 1.124 m/s``."""
    elements, names, en, ru = [], [], [], []
    for name, frm, to, role, quantity in segments:
        if name in names:  # e.g. cb is pb when C is on the frame
            continue
        rd = b.read(name, frm, to, quantity)
        elements.append(b.segment(name, frm, to, role))
        names.append(name)
        value = 0.0 if abs(rd.mm) < ZERO_MM else rd.value  # round-off written as 0
        said = f"{quantity} = {name}·{rd.scale} = {plain(value, 4)}"
        en.append(f"{name} = {rd.mm:.2f} mm → {said} {rd.unit}")
        ru.append(f"{name} = {rd.mm:.2f} мм → {said} {unit_text(rd.unit, 'ru')}")
    b.add_step(eq, "; ".join(en) + ".", "; ".join(ru) + ".", elements, tuple(names))


def _turn(b: _Builder, name: str, r_m: Vec2, length: float) -> float:
    """Rate of a link from its relative segment ``name``: (segment·K)/l, CCW positive."""
    rd = b.readings[name]
    frm, to = b.ends[name]
    rel = b.points[to] - b.points[frm]
    if rd.mm == 0 or length <= 0:
        return 0.0
    return math.copysign(rd.value / length, float(cross(r_m, rel)))


def _slide(b: _Builder, name: str, u: Vec2) -> float:
    """Signed sliding speed along u from the segment ``name``."""
    rd = b.readings[name]
    frm, to = b.ends[name]
    rel = b.points[to] - b.points[frm]
    return math.copysign(rd.value, float(np.dot(rel, u))) if rd.mm else 0.0


def _velocity_dyad(mech, dy: Dyad, kin, k, b: _Builder, img: _Images, P, rates, sliding,
                   rate_map, length_m) -> None:
    lower = b.key
    i, j = dy.links
    kl = img.kl
    if dy.kind == "RRR":
        A, B, C = dy.joints
        a, bb, c = lower(A), lower(B), lower(C)
        eq = f"v_{B} = v_{A} + v_{B}{A} = v_{C} + v_{B}{C}"
        _close_two_lines(b, eq, bb,
                         b.points[a], perp(P[B] - P[A]), f"⟂{A}{B} through {a}",
                         b.points[c], perp(P[B] - P[C]), f"⟂{C}{B} through {c}")
        _result(b, eq, [("p" + bb, "p", bb, "absolute", f"v_{B}"),
                        (a + bb, a, bb, "relative", f"v_{B}{A}"),
                        (c + bb, c, bb, "relative", f"v_{B}{C}")])
        rates[i] = _turn(b, a + bb, (P[B] - P[A]) * kl, dy.lengths[0])
        rates[j] = _turn(b, c + bb, (P[B] - P[C]) * kl, dy.lengths[1])
        img.add_all((i, A, a), (i, B, bb), (j, C, c), (j, B, bb))
    elif dy.kind == "RRP":
        A, B = dy.joints
        a, bb = lower(A), lower(B)
        g = dy.guides[0]
        key = f"{j}/{g.link}"
        u = _guide_dir(kin, k, key)
        bk = _coincident(b, img, g.link, B, P, rate_map)
        eq = f"v_{B} = v_{A} + v_{B}{A} = v_{B}{g.link} + v_{B}{j}{B}{g.link}"
        _close_two_lines(b, eq, bb,
                         b.points[a], perp(P[B] - P[A]), f"⟂{A}{B} through {a}",
                         b.points[bk], u, f"∥ guide through {bk}")
        segs = [("p" + bb, "p", bb, "absolute", f"v_{B}"),
                (a + bb, a, bb, "relative", f"v_{B}{A}")]
        if bk != "p":
            segs.append((bk + bb, bk, bb, "sliding", f"v_{B}{j}{B}{g.link}"))
        _result(b, eq, segs)
        rates[i] = _turn(b, a + bb, (P[B] - P[A]) * kl, dy.lengths[0])
        rates[j] = rates[g.link]
        sliding[key] = _slide(b, segs[-1][0] if bk != "p" else "p" + bb, u)
        img.add_all((i, A, a), (i, B, bb), (j, B, bb))
    elif dy.kind == "RPR":
        A, C = dy.joints
        a, c = lower(A), lower(C)
        key = f"{i}/{j}"
        u = _guide_dir(kin, k, key)
        a3 = a + j
        # v_A3 = v_A − v_AA3: the sheets' v_AA3 (the segment a3→a, the block's A relative to
        # the slotted link's A3), one notation with the tables
        eq = f"v_{A}{j} = v_{C} + v_{A}{j}{C} = v_{A} − v_{A}{A}{j}"
        _close_two_lines(b, eq, a3,
                         b.points[c], perp(P[A] - P[C]), f"⟂{C}{A} through {c}",
                         b.points[a], u, f"∥ slot through {a}")
        _result(b, eq, [("p" + a3, "p", a3, "absolute", f"v_{A}{j}"),
                        (c + a3, c, a3, "relative", f"v_{A}{j}{C}"),
                        (a3 + a, a3, a, "sliding", f"v_{A}{A}{j}")])
        rates[j] = _turn(b, c + a3, (P[A] - P[C]) * kl, length_m(C, A))
        rates[i] = rates[j]
        sliding[key] = _slide(b, a3 + a, u)
        img.add_all((j, C, c), (j, A, a3), (i, A, a))
    elif dy.kind == "PRP":
        (B,) = dy.joints
        bb = lower(B)
        g1, g2 = dy.guides
        k1, k2 = f"{i}/{g1.link}", f"{j}/{g2.link}"
        u1, u2 = _guide_dir(kin, k, k1), _guide_dir(kin, k, k2)
        b1 = _coincident(b, img, g1.link, B, P, rate_map)
        b2 = _coincident(b, img, g2.link, B, P, rate_map)
        eq = (f"v_{B} = v_{B}{g1.link} + v_{B}{i}{B}{g1.link} "
              f"= v_{B}{g2.link} + v_{B}{j}{B}{g2.link}")
        _close_two_lines(b, eq, bb,
                         b.points[b1], u1, f"∥ guide of {i} through {b1}",
                         b.points[b2], u2, f"∥ guide of {j} through {b2}")
        n1 = b1 + bb if b1 != "p" else "p" + bb
        n2 = b2 + bb if b2 != "p" else "p" + bb
        segs = [("p" + bb, "p", bb, "absolute", f"v_{B}")]
        segs += [(n, f, bb, "sliding", q) for n, f, q in
                 ((n1, b1, f"v_{B}{i}{B}{g1.link}"), (n2, b2, f"v_{B}{j}{B}{g2.link}"))
                 if n != "p" + bb]
        _result(b, eq, segs)
        rates[i], rates[j] = rates[g1.link], rates[g2.link]
        sliding[k1], sliding[k2] = _slide(b, n1, u1), _slide(b, n2, u2)
        img.add_all((i, B, bb), (j, B, bb))
    elif dy.kind == "RPP":
        A = dy.joints[0]  # the yoke's point D follows by similarity, with the links' points
        a = lower(A)
        g = dy.guides[0]
        kj, ki = f"{j}/{g.link}", f"{i}/{j}"
        u, w = _guide_dir(kin, k, kj), _guide_dir(kin, k, ki)
        ak = _coincident(b, img, g.link, A, P, rate_map)
        aj = a + j
        eq = f"v_{A} = v_{A}{g.link} + v_{A}{j}{A}{g.link} + v_{A}{A}{j}"
        _close_two_lines(b, eq, aj,
                         b.points[ak], u, f"∥ guide through {ak}",
                         b.points[a], w, f"∥ slot through {a}")
        ns = ak + aj if ak != "p" else "p" + aj
        _result(b, eq, [(ns, ak, aj, "sliding" if ak != "p" else "absolute",
                         f"v_{A}{j}{A}{g.link}"),
                        (aj + a, aj, a, "sliding", f"v_{A}{A}{j}")])
        rates[j] = rates[g.link]
        rates[i] = rates[j]
        sliding[kj] = _slide(b, ns, u)
        sliding[ki] = _slide(b, aj + a, w)
        img.add_all((j, A, aj), (i, A, a))


def _coincident(b: _Builder, img: _Images, link: str, X: str, P, rate_map) -> str:
    """Plan point of the point of ``link`` that coincides with joint X (``p`` for the frame)."""
    if link == img.mech.frame_link:
        return b.pole
    name = lower(X) + link
    if name not in b.points:
        b.points[name] = img.place(b, link, P[X], rate_map)
        b.add_step(f"{name}: similarity on link {link}",
                   f"Point {name} of link {link} coinciding with {X}, by similarity.",
                   f"Точка {name} звена {link}, совпадающая с {X}, по теореме подобия.",
                   [Element("point", name, as_xy(b.points[name]), as_xy(b.points[name]), "point")])
    return name




def _lay(b: _Builder, name: str, frm: str, vec_mm: Vec2, role: str, eq: str, what: str,
         what_ru: str) -> str:
    """Lay off a known component (normal, Coriolis) of length read to the reader's precision."""
    length = b.reader(float(np.hypot(*vec_mm)))
    d = unit_vector(vec_mm)
    b.points[name] = b.points[frm] + length * d
    b.read(name, frm, name, eq.split(" =")[0])
    b.add_step(eq, f"{what}: {length:.2f} mm from {frm}.", f"{what_ru}: {length:.2f} мм от {frm}.",
               [Element("segment", name, as_xy(b.points[frm]), as_xy(b.points[name]), role)],
               (name,))
    return name


def acceleration_plan(mech: Mechanism, kin, k: int, kl: Scale, ka: Scale, vplan: Plan,
                      reader: Reader = EXACT) -> Plan:
    """Build the acceleration plan of position k from the position and velocity plans.

    Normal components ``aⁿ = ω²·l`` and Coriolis components ``aᵏ = 2·ω_k·v_r``
    are computed from the *velocity plan's readings* and laid off as segments
    (``aⁿ_BA`` from a toward A along BA; ``aᵏ`` along the relative velocity turned
    90° in the sense of ω_k); the tangential and relative directions close each
    dyad's equation (see :mod:`graphplan.kinematics.accelerations`). The crank turns at
    constant ω1, so ``a_A = ω1²·l_OA`` directed from A to O.
    """
    P = position_mm(kin, k, kl.per_mm, mech.crank.pivot)
    reader = tally(reader)
    b = _Builder("acceleration", "π", ka, reader, mech.frame_points, mech.home_link)
    img = _Images(mech, P, kl.per_mm, "π")
    W = vplan.rates
    eps: dict[str, float] = {mech.frame_link: 0.0}
    rel: dict[str, float] = {}
    ratio = kl.per_mm / ka.per_mm
    key = b.key

    def rate_map(link, r_mm):
        return (eps[link] * perp(r_mm) - W[link] ** 2 * r_mm) * ratio

    def length_m(p1: str, p2: str) -> float:
        return reader(float(np.hypot(*(P[p2] - P[p1])))) * kl.per_mm

    b.add_step("", "Pole π: points of the frame are at π.", "Полюс π: точки стойки в π.",
               [Element("point", "π", (0.0, 0.0), (0.0, 0.0), "point")])
    for fp in mech.frame_points:
        img.add(mech.frame_link, fp, "π")
    cr = mech.crank
    o, a = cr.pivot, cr.pin
    aa = W[cr.link] ** 2 * cr.length
    length = reader(aa / ka.per_mm)
    b.points[key(a)] = length * unit_vector(P[o] - P[a])
    b.read("π" + key(a), "π", key(a), f"a_{a}")
    b.add_step(f"a_{a} = ω1²·l_{o}{a}",
               f"a_{a} = ω1²·l_{o}{a} = {plain(W[cr.link] ** 2, 4)}·{plain(cr.length, 4)} = "
               f"{plain(aa, 4)} m/s²; "
               f"π{key(a)} = a_{a}/Ka = {length:.2f} mm, from {a} toward {o} (ε1 = 0).",
               f"a_{a} = ω1²·l_{o}{a} = {plain(W[cr.link] ** 2, 4)}·{plain(cr.length, 4)} = "
               f"{plain(aa, 4)} м/с²; "
               f"π{key(a)} = a_{a}/Ka = {length:.2f} мм, от {a} к {o} (ε1 = 0).",
               [b.segment("π" + key(a), "π", key(a), "absolute")], ("π" + key(a),))
    eps[cr.link] = 0.0
    img.add(cr.link, o, "π")
    img.add(cr.link, a, key(a))
    _similar_points(mech, b, img, cr.link, P, rate_map, "acceleration")

    def normal(frm: str, tip: str, base: str, link: str, l_m: float) -> str:
        """aⁿ of ``tip`` about ``base`` on ``link``: ω²·l, from tip toward base."""
        name = f"n_{tip}{base}"
        vec = unit_vector(P[base] - P[tip]) * (W[link] ** 2 * l_m / ka.per_mm)
        an = _written(W[link] ** 2 * l_m, vec)
        w = abs(W[link]) if an else 0.0
        said = (f"aⁿ_{tip}{base} = ω{link}²·l_{tip}{base} = {plain(w, 4)}²·{plain(l_m, 4)} = "
                f"{plain(an, 4)}")
        _lay(b, name, frm, vec, "normal", f"aⁿ_{tip}{base} = ω{link}²·l_{tip}{base}",
             f"{said} m/s², ∥ {tip}{base}, from {tip} toward {base}",
             f"{said} м/с², ∥ {tip}{base}, от {tip} к {base}")
        return name

    def coriolis_from(frm: str, name: str, omega_k: float, v_r: float, u: Vec2, link: str,
                      rel: str, sign=1.0, reverse: tuple[str, str] = ("", "")) -> str:
        """Lay the Coriolis acceleration ``aᵏ = 2·ω_link·v_rel``: the relative velocity
        ``rel`` turned by 90° in the sense of ω of the guiding ``link``.

        ``reverse`` (the sheet's name of the opposite vector, the segment of ``rel`` on the
        velocity plan) where the sheet reads that one: a slotted link's v_AA3 is the
        segment a3→a, the rule turns v_A3A = −v_AA3, the segment a→a3 (laid from a,
        ``sign`` −1). The equation and the magnitude then name the sheets' vector
        (``aᵏ_A3 = 2·ω3·v_AA3``: one notation with the tables) and the sentence says which
        vector the rule turns."""
        vec = sign * 2.0 * omega_k * v_r * perp(u) / ka.per_mm
        if np.hypot(*vec) == 0:
            return frm
        # a factor that is round-off (a dead centre) is written 0: ω against ω1, v_r
        # against the crank pin's speed
        w = omega_k if abs(omega_k) > 1e-12 * abs(cr.omega) else 0.0
        vr = abs(v_r) if abs(v_r) > 1e-12 * abs(cr.omega) * cr.length else 0.0
        ak = _written(abs(2 * omega_k * v_r), vec)
        sense = ("counter-clockwise", "против часовой стрелки") if w > 0 else (
            "clockwise", "по часовой стрелке")
        shown = reverse[0] or rel  # the sheets' name of the relative velocity (its magnitude)
        what = (f"aᵏ = 2·|ω{link}|·{shown} = 2·{plain(abs(w), 4)}·{plain(vr, 4)} = "
                f"{plain(ak, 4)}")
        if w == 0:
            return _lay(b, name, frm, vec, "coriolis", f"aᵏ_{name[2:]} = 2·ω{link}·{shown}",
                        f"Coriolis acceleration {what} m/s²: ω{link} = 0, no Coriolis "
                        "acceleration in this position",
                        f"Ускорение Кориолиса {what} м/с²: ω{link} = 0, ускорения Кориолиса "
                        "в этом положении нет")
        eq = f"aᵏ_{name[2:]} = 2·ω{link}·{shown}"
        if reverse[0]:  # the sheets read the opposite segment: say which vector is turned
            return _lay(b, name, frm, vec, "coriolis", eq,
                        f"Coriolis acceleration {what} m/s² (ω{link} {sense[0]}); its "
                        f"direction — the rule: the relative velocity turned by 90° in the "
                        f"sense of ω{link}. Laid from {frm} is aᵏ_{name[2:]}: the rule turns "
                        f"{rel} = −{shown} (the vector {reverse[1]} of the velocity plan, "
                        f"opposite to the segment {shown} is read on) by 90° {sense[0]}",
                        f"Ускорение Кориолиса {what} м/с² (ω{link} {sense[1]}); направление — "
                        f"правило: вектор относительной скорости, повёрнутый на 90° в сторону "
                        f"вращения ω{link}. От {frm} откладывается aᵏ_{name[2:]}: по правилу "
                        f"поворачивается {rel} = −{shown} (вектор {reverse[1]} плана "
                        f"скоростей, противоположный отрезку, на котором прочитана {shown}) — "
                        f"на 90° {sense[1]}")
        return _lay(b, name, frm, vec, "coriolis", eq,
                    f"Coriolis acceleration {what} m/s² (ω{link} {sense[0]}); its direction: "
                    f"the relative velocity {rel} turned by 90° in the sense of ω{link}, "
                    f"i.e. {sense[0]}",
                    f"Ускорение Кориолиса {what} м/с² (ω{link} {sense[1]}); направление — "
                    f"правило: вектор относительной скорости {rel}, повёрнутый на 90° в "
                    f"сторону вращения ω{link}, то есть {sense[1]}")

    S = vplan.sliding
    for dy in mech.dyads:
        i, j = dy.links
        if dy.kind == "RRR":
            A, B, C = dy.joints
            pa, pb, pc = key(A), key(B), key(C)
            n1 = normal(pa, B, A, i, dy.lengths[0])
            n2 = normal(pc, B, C, j, dy.lengths[1])
            eq = f"a_{B} = a_{A} + aⁿ_{B}{A} + aτ_{B}{A} = a_{C} + aⁿ_{B}{C} + aτ_{B}{C}"
            _close_two_lines(b, eq, pb, b.points[n1], perp(P[B] - P[A]), f"⟂{A}{B} through {n1}",
                             b.points[n2], perp(P[B] - P[C]), f"⟂{C}{B} through {n2}")
            _result(b, eq, [("π" + pb, "π", pb, "absolute", f"a_{B}"),
                            (f"τ_{B}{A}", n1, pb, "tangential", f"aτ_{B}{A}"),
                            (f"τ_{B}{C}", n2, pb, "tangential", f"aτ_{B}{C}")])
            eps[i] = _turn(b, f"τ_{B}{A}", (P[B] - P[A]) * kl.per_mm, dy.lengths[0])
            eps[j] = _turn(b, f"τ_{B}{C}", (P[B] - P[C]) * kl.per_mm, dy.lengths[1])
            img.add_all((i, A, pa), (i, B, pb), (j, C, pc), (j, B, pb))
        elif dy.kind == "RRP":
            A, B = dy.joints
            pa, pb = key(A), key(B)
            g = dy.guides[0]
            sk = f"{j}/{g.link}"
            u = _guide_dir(kin, k, sk)
            n1 = normal(pa, B, A, i, dy.lengths[0])
            bk = _coincident(b, img, g.link, B, P, rate_map)
            kk = coriolis_from(bk, f"k_{B}{j}{g.link}", W[g.link], S[sk], u, g.link,
                               f"v_{B}{j}{B}{g.link}")
            eq = f"a_{B} = a_{A} + aⁿ_{B}{A} + aτ_{B}{A} = a_{B}{g.link} + aᵏ + aʳ"
            _close_two_lines(b, eq, pb, b.points[n1], perp(P[B] - P[A]), f"⟂{A}{B} through {n1}",
                             b.points[kk], u, f"∥ guide through {kk}")
            segs = [("π" + pb, "π", pb, "absolute", f"a_{B}"),
                    (f"τ_{B}{A}", n1, pb, "tangential", f"aτ_{B}{A}")]
            if kk != "π":
                segs.append((f"r_{B}{j}{g.link}", kk, pb, "sliding", f"aʳ_{B}{j}{g.link}"))
            _result(b, eq, segs)
            eps[i] = _turn(b, f"τ_{B}{A}", (P[B] - P[A]) * kl.per_mm, dy.lengths[0])
            eps[j] = eps[g.link]
            rel[sk] = _slide(b, segs[-1][0] if kk != "π" else "π" + pb, u)
            img.add_all((i, A, pa), (i, B, pb), (j, B, pb))
        elif dy.kind == "RPR":
            A, C = dy.joints
            pa, pc = key(A), key(C)
            sk = f"{i}/{j}"
            u = _guide_dir(kin, k, sk)
            a3 = pa + j
            n1 = normal(pc, A, C, j, length_m(C, A))
            kk = coriolis_from(pa, f"k_{A}{j}", W[j], S[sk], u, j, f"v_{A}{j}{A}", sign=-1.0,
                               reverse=(f"v_{A}{A}{j}", f"{pa.lower()}→{pa.lower()}{j}"))
            # the Coriolis vector laid from a is aᵏ_A3 (of A3 relative to A); the relative one
            # is the sheets' aʳ_AA3 (the segment a3→k), hence its minus
            eq = f"a_{A}{j} = a_{C} + aⁿ_{A}{C} + aτ_{A}{C} = a_{A} + aᵏ_{A}{j} − aʳ_{A}{A}{j}"
            _close_two_lines(b, eq, a3, b.points[n1], perp(P[A] - P[C]), f"⟂{C}{A} through {n1}",
                             b.points[kk], u, f"∥ slot through {kk}")
            _result(b, eq, [("π" + a3, "π", a3, "absolute", f"a_{A}{j}"),
                            (f"τ_{A}{C}", n1, a3, "tangential", f"aτ_{A}{C}"),
                            (f"r_{A}{j}", a3, kk, "sliding", f"aʳ_{A}{A}{j}")])
            eps[j] = _turn(b, f"τ_{A}{C}", (P[A] - P[C]) * kl.per_mm, length_m(C, A))
            eps[i] = eps[j]
            rel[sk] = _slide(b, f"r_{A}{j}", u)
            img.add_all((j, C, pc), (j, A, a3), (i, A, pa))
        elif dy.kind == "PRP":
            (B,) = dy.joints
            pb = key(B)
            g1, g2 = dy.guides
            k1, k2 = f"{i}/{g1.link}", f"{j}/{g2.link}"
            u1, u2 = _guide_dir(kin, k, k1), _guide_dir(kin, k, k2)
            b1 = _coincident(b, img, g1.link, B, P, rate_map)
            b2 = _coincident(b, img, g2.link, B, P, rate_map)
            c1 = coriolis_from(b1, f"k_{B}{i}{g1.link}", W[g1.link], S[k1], u1, g1.link,
                               f"v_{B}{i}{B}{g1.link}")
            c2 = coriolis_from(b2, f"k_{B}{j}{g2.link}", W[g2.link], S[k2], u2, g2.link,
                               f"v_{B}{j}{B}{g2.link}")
            eq = f"a_{B} = a_{B}{g1.link} + aᵏ1 + aʳ1 = a_{B}{g2.link} + aᵏ2 + aʳ2"
            _close_two_lines(b, eq, pb, b.points[c1], u1, f"∥ guide of {i} through {c1}",
                             b.points[c2], u2, f"∥ guide of {j} through {c2}")
            segs = [("π" + pb, "π", pb, "absolute", f"a_{B}")]
            r1 = f"r_{B}{i}{g1.link}" if c1 != "π" else "π" + pb
            r2 = f"r_{B}{j}{g2.link}" if c2 != "π" else "π" + pb
            for r, c in ((r1, c1), (r2, c2)):
                if r != "π" + pb:
                    segs.append((r, c, pb, "sliding", f"aʳ_{r[2:]}"))
            _result(b, eq, segs)
            eps[i], eps[j] = eps[g1.link], eps[g2.link]
            rel[k1], rel[k2] = _slide(b, r1, u1), _slide(b, r2, u2)
            img.add_all((i, B, pb), (j, B, pb))
        elif dy.kind == "RPP":
            A, _ = dy.joints
            pa = key(A)
            g = dy.guides[0]
            kj, ki = f"{j}/{g.link}", f"{i}/{j}"
            u, w = _guide_dir(kin, k, kj), _guide_dir(kin, k, ki)
            ak = _coincident(b, img, g.link, A, P, rate_map)
            cs = coriolis_from(ak, f"k_{A}{j}{g.link}", W[g.link], S[kj], u, g.link,
                               f"v_{A}{j}{A}{g.link}")
            cr_ = coriolis_from(pa, f"k_{A}{i}{j}", W[j], S[ki], w, j, f"v_{A}{j}{A}", sign=-1.0,
                                reverse=(f"v_{A}{A}{j}", f"{pa.lower()}→{pa.lower()}{j}"))
            aj = pa + j
            eq = f"a_{A} = a_{A}{g.link} + aᵏ + aʳ_{A}{j}{A}{g.link} + aᵏ + aʳ_{A}{A}{j}"
            _close_two_lines(b, eq, aj, b.points[cs], u, f"∥ guide through {cs}",
                             b.points[cr_], w, f"∥ slot through {cr_}")
            rs = f"r_{A}{j}{g.link}" if cs != "π" else "π" + aj
            slid = cs != "π"
            _result(b, eq, [(rs, cs, aj, "sliding" if slid else "absolute",
                             f"aʳ_{A}{j}{g.link}" if slid else f"a_{A}{j}"),
                            (f"r_{A}{i}{j}", aj, cr_, "sliding", f"aʳ_{A}{i}{j}")])
            eps[j] = eps[g.link]
            eps[i] = eps[j]
            rel[kj] = _slide(b, rs, u)
            rel[ki] = _slide(b, f"r_{A}{i}{j}", w)
            img.add_all((j, A, aj), (i, A, pa))
        for ln in dy.links:
            _similar_points(mech, b, img, ln, P, rate_map, "acceleration")
    return b.build(kin.labels[k], eps, rel)
