"""Zhukovsky's lever (рычаг Жуковского) of one position, drawn as a construction (method B.3, C.7).

Conventions, stated once: SI units for forces (N) and moments (N·m); lever lengths in
millimetres of the sheet; moments **counter-clockwise positive** (as in
:mod:`graphplan.forces.kinetostatics`); the velocity plan is turned by **+90°,
counter-clockwise**, about its pole p (method B.3 allows either sense, the same for
every point; this module always turns CCW, and the sign of the result below is derived
for that sense).

The construction
----------------
1. The velocity plan of position k (:func:`graphplan.plans.constructions.velocity_plan`, at
   the scale Kv, read by the same :class:`~graphplan.plans.constructions.Reader`) is turned by
   +90°: a plan point x becomes ``x' = R₉₀·x = k × x`` (``(x, y) → (−y, x)``).
2. Every force F_i of the loads (weights, inertia forces, the technological resistance,
   external forces) is applied, with its own magnitude and direction, at the image of its
   point of application X on the turned plan. The image of X on link L is the plan
   point of X when the plan has one; otherwise (a shifted inertia force, a force at an
   arbitrary point, a point whose plan letter is taken, e.g. ``P`` → the pole ``p``) it
   is found by the theorem of similarity from two known plan points G, H of the same
   link: ``x = g + (h − g)·(X − G)/(H − G)`` (complex numbers, position plan in mm); a
   link with a single known plan point (a slider block) uses the link's ω read off the
   plan: ``x = g + ω·(Kl/Kv)·k×(X − G)``.
3. A couple M on link L (inertia moment Mи = −J·ε, a resisting moment Mс) is replaced by
   two forces of size ``M/l_AB`` perpendicular to AB at the ends A, B of the link (its
   first two points): ``F_B = (M/l_AB)·k×e_AB`` at B and ``F_A = −F_B`` at A (so
   ``(B − A)×F_B = M``); on the lever they act at the images a', b'. Their moment about p
   is ``M·|ab|/l_AB`` up to sign, i.e. ``−M·ω_L/Kv`` (below).
4. The lever is in equilibrium about the pole: the arm ``h_i`` of each force is the
   perpendicular from p to its line of action, measured in mm (read by the reader), its
   moment ``M_p(F_i) = ±|F_i|·h_i`` (N·mm, CCW+), and the balancing force F_ур, applied at
   a' perpendicular to pa', balances them: ``F_ур·|pa| = |Σ M_p(F_i)|``.

The governing relation
----------------------
With the plan at Kv, ``v_X = Kv·(px)`` and the turned point is ``x' = R₉₀·v_X/Kv``. For any
force, ``(R₉₀ v)×F = −v·F``, so

    Σ M_p(F_i) = Σ x'_i × F_i = −(1/Kv)·(Σ F_i·v_i + Σ M_j·ω_j)          [N·mm]

(the couple's pair of forces has the power ``F_B·(v_B − v_A) = (M/l)·ω·l = M·ω``). The
power balance of the crank driven at constant ω1, ``M_ур·ω1 + Σ F·v + Σ M·ω = 0``
(:func:`graphplan.forces.loads.power_balance_moment`), then gives

    M_ур = Kv·Σ M_p(F_i)/ω1 = sgn(ω1)·(l_OA/|pa|)·Σ M_p(F_i)               [N·m]

because ``|pa| = |ω1|·l_OA/Kv``: the lever is a drawing of the crank at the length scale
``μ = l_OA/|pa| = Kv/|ω1|`` (m/mm), and ``F_ур = |Σ M_p|/|pa|``, ``M_ур = F_ур·l_OA`` with
the sign above (the lever's F_ур turns the lever against Σ M_p; turned back by −90° it is
the force at A perpendicular to OA whose moment about O is M_ур). In exact mode this is
an identity (method C.7) and M_ур equals :attr:`graphplan.forces.kinetostatics.Forces.M_bal` to
round-off; in drafting mode every plan reading, |pa| and each arm are rounded to the
reader's precision, and the result differs from the force plans' M_ур by the drafting
discrepancy ``Δ = |M_ур − M_ур(Ж)| / max(|M_ур|, |M_ур(Ж)|)·100 %`` (method B.3 step 6).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..forces import Loads, compute_loads, power_balance_moment
from ..geometry import cross, perp
from ..kinematics import Kinematics
from ..model import Mechanism
from ..numbers import plain
from ..units import Scale, fit_scale
from .constructions import (
    EXACT,
    Element,
    Plan,
    Reader,
    Reading,
    Step,
    as_xy,
    plan_name,
    position_mm,
    velocity_plan,
)

Vec2 = np.ndarray

FORCE_ARROW_MM = 30.0
"""Length of the largest force's arrow on the lever (the display scale Kp is fitted to it)."""


@dataclass(frozen=True, slots=True)
class LeverForce:
    """One force applied to the lever.

    Attributes
    ----------
    name : str
        The load's name (``"Q"``, ``"G2"``, ``"Pи3"``); for a couple's pair of forces
        the moment's name primed, ``"F'Mи3"`` at the first end and ``"F''Mи3"`` at the second.
    load : str
        The load it comes from (``"Mи3"`` for both forces of the couple).
    link, kind : str
        As in :class:`graphplan.forces.loads.ForceLoad` / ``MomentLoad``.
    point : str | None
        The named point of application on the mechanism (``None`` for a shifted force).
    image : str
        The lever point it is applied at: the plan letter with a prime (``"b'"``,
        ``"s2'"``), or ``"x'(Pи2)"`` for an image found by similarity only.
    at_mm : tuple[float, float]
        The point of application on the lever (turned plan), mm.
    vector : tuple[float, float]
        The force, N (not turned).
    magnitude : float
        |F|, N.
    arm : Reading
        The arm h about the pole, mm (read), with ``value = h·μ`` in m (μ = l_OA/|pa|).
    moment : float
        ``M_p(F) = ±|F|·h`` with the read arm, N·mm, CCW positive.
    """

    name: str
    load: str
    link: str
    kind: str
    point: str | None
    image: str
    at_mm: tuple[float, float]
    vector: tuple[float, float]
    magnitude: float
    arm: Reading
    moment: float


@dataclass(frozen=True, slots=True)
class Lever:
    """Zhukovsky's lever of one position (module docstring).

    Attributes
    ----------
    label : str
        The position's label.
    k : int
        Its index in the kinematics.
    plan : Plan
        The velocity plan it was turned from (not turned).
    points : dict[str, ndarray]
        Points of the turned plan, mm, primed names (``"p"``, ``"a'"``, ``"b'"`` …),
        with the images of the points of application found by similarity.
    forces : tuple[LeverForce, ...]
        Every non-zero force applied, couples as their pairs of forces.
    steps : tuple[Step, ...]
        The construction in drawing order.
    readings : dict[str, Reading]
        ``pa`` (the crank pin's segment, mm) and every arm ``h_<force>`` (mm).
    moment_sum : float
        Σ M_p(F_i) with the read arms, N·mm, CCW positive.
    lever_scale : float
        μ = l_OA/|pa| (|pa| as read), m/mm.
    F_bal : float
        The balancing force at a' perpendicular to pa', ``|Σ M_p|/|pa|``, N.
    M_bal : float
        The balancing moment from the lever, ``sgn(ω1)·μ·Σ M_p``, N·m, CCW positive.
    power : float
        The exact M_ур by the power balance of the same loads, N·m.
    reference : float | None
        M_ур from the force plans given to :func:`zhukovsky_lever`.
    discrepancy_pct : float | None
        Δ against ``reference``, percent.
    kf : Scale
        Display scale of the force arrows (N/mm); nothing is read at it.
    """

    label: str
    k: int
    plan: Plan
    points: dict[str, Vec2]
    forces: tuple[LeverForce, ...]
    steps: tuple[Step, ...]
    readings: dict[str, Reading]
    moment_sum: float
    lever_scale: float
    F_bal: float
    M_bal: float
    power: float
    reference: float | None
    discrepancy_pct: float | None
    kf: Scale

    @property
    def reads(self) -> int:
        """Readings the lever took: its velocity plan's, then one arm per force."""
        return self.plan.reads + len(self.forces)

    def discrepancy(self, reference: float) -> float:
        """Δ = |M_ур − M_ур(Ж)| / max(|M_ур|, |M_ур(Ж)|)·100 % (0 when both are 0)."""
        return discrepancy_pct(reference, self.M_bal)


def discrepancy_pct(m_ref: float, m_lever: float) -> float:
    """Δ of method B.3 step 6, percent: ``|M − M_Ж| / max(|M|, |M_Ж|)·100``."""
    big = max(abs(m_ref), abs(m_lever))
    return 0.0 if big == 0 else abs(m_ref - m_lever) / big * 100.0


class _LinkImages:
    """Images on the (untouched) velocity plan of arbitrary points of each link."""

    def __init__(self, mech: Mechanism, plan: Plan, pos_mm: dict[str, Vec2], ratio: float):
        self.mech, self.plan, self.pos, self.ratio = mech, plan, pos_mm, ratio
        frame = set(mech.frame_points) | {mech.crank.pivot}
        # per link: (position mm, plan letter, model point) of its points the plan has
        self.known: dict[str, list[tuple[Vec2, str, str]]] = {}
        for ln in mech.moving_links:
            lst: list[tuple[Vec2, str, str]] = []

            def add(x, name, lst=lst):
                xy = np.asarray(pos_mm[x], float)
                if name in plan.points and all(np.hypot(*(xy - q)) > 1e-9 for q, _, _ in lst):
                    lst.append((xy, name, x))

            for x in mech.points_of(ln):
                if x in frame:
                    add(x, "p")
                else:  # a point P is p3 on the plan, never the pole's letter
                    add(x, plan_name(mech, x, "p"))
            for x in pos_mm:  # coincident points of the link: a3, b4 …
                add(x, x.lower() + ln)
            self.known[ln] = lst

    def name_of(self, link: str, point: str | None) -> str | None:
        """Plan letter of a named point of ``link`` if the plan has it."""
        if point is None or link == self.mech.frame_link:
            return None
        for _, name, x in self.known.get(link, []):
            if x == point and name in ("p", plan_name(self.mech, point, "p")):
                return name
        return None

    def place(self, link: str, X: Vec2) -> Vec2:
        """Plan point (mm, not turned) of the point X (position plan, mm) of ``link``."""
        if link == self.mech.frame_link:
            return np.zeros(2)
        lst = self.known[link]
        pts = self.plan.points
        if len(lst) >= 2:
            (G, g, _), (H, h, _) = lst[0], lst[1]
            zg, zh = complex(*pts[g]), complex(*pts[h])
            z = zg + (zh - zg) * complex(*(X - G)) / complex(*(H - G))
            return np.array([z.real, z.imag])
        G, g, _ = lst[0]
        return pts[g] + self.plan.rates[link] * self.ratio * perp(X - G)

    def ends(self, link: str) -> tuple[Vec2, Vec2, str, str | None]:
        """Two points A, B of the link for a couple: position plan (mm) and names.

        The link's first two points the plan has; a link with one (a slider block) gets
        a second point 50 mm to its right on the position plan (name ``None``).
        """
        lst = self.known[link]
        if len(lst) >= 2:
            (A, _, a), (B, _, b) = lst[0], lst[1]
            return A, B, a, b
        A, _, a = lst[0]
        return A, A + np.array([50.0, 0.0]), a, None


def zhukovsky_lever(mech: Mechanism, kin: Kinematics, loads: Loads | None, k: int, kl: Scale,
                    kv: Scale, reader: Reader = EXACT, *, reference: float | None = None,
                    plan: Plan | None = None) -> Lever:
    """Build Zhukovsky's lever of position k and read the balancing moment off it.

    Governing equations (module docstring): the plan turned +90° (CCW) about p,
    ``Σ M_p(F_i) = −(Σ F·v + Σ M·ω)/Kv``, and

        M_ур = Kv·Σ M_p(F_i)/ω1 = sgn(ω1)·(l_OA/|pa|)·Σ M_p(F_i),   F_ур = |Σ M_p|/|pa|,

    the power balance ``M_ур·ω1 + Σ F·v + Σ M·ω = 0`` read off the lever.

    Parameters
    ----------
    mech : Mechanism
    kin : Kinematics
    loads : Loads or None
        The loads of ``kin`` (:func:`graphplan.forces.loads.compute_loads`); ``None``
        computes them with the variant's ``[kinetostatics]`` settings.
    k : int
        Index of the position.
    kl, kv : Scale
        Length and velocity scales of the plans.
    reader : Reader
        Exact, or rounding every plan reading, |pa| and every arm to a precision (mm).
    reference : float, optional
        M_ур from the force plans (e.g. ``solve_forces(...).M_bal[k]``), N·m: the lever
        reports its discrepancy against it.
    plan : Plan, optional
        The velocity plan of position k at ``kl``, ``kv`` already built with a reader that
        read it as ``reader`` would (the error bounds' probes whose shifted reading is an
        arm of the lever reuse the unshifted plan); built here by default.

    Returns
    -------
    Lever
    """
    if loads is None:
        loads = compute_loads(mech, kin)
    if loads.phi.shape != kin.phi.shape or not np.array_equal(loads.phi, kin.phi):
        raise ValueError("zhukovsky_lever: the loads were computed for other positions")
    if plan is None:
        plan = velocity_plan(mech, kin, k, kl, kv, reader)
    cr = mech.crank
    pos = position_mm(kin, k, kl.per_mm, cr.pivot)
    origin = kin.pos.points[cr.pivot][k]
    images = _LinkImages(mech, plan, pos, kl.per_mm / kv.per_mm)
    pin = plan_name(mech, cr.pin, "p")
    pa_name = "p" + pin
    pa = plan.readings[pa_name]
    mu = cr.length / pa.mm  # m of the crank per mm of the lever
    turned: dict[str, Vec2] = {("p" if n == "p" else n + "'"): perp(v)
                               for n, v in plan.points.items()}
    steps: list[Step] = []

    def step(eq, text, text_ru, elements, readings=()):
        steps.append(Step(len(steps) + 1, eq, text, text_ru, tuple(elements), tuple(readings)))

    step("x' = R₉₀·x",
         f"Turn the velocity plan of position {plan.label} by 90° counter-clockwise about p.",
         f"Поворачиваем план скоростей положения {plan.label} на 90° против часовой стрелки "
         "вокруг полюса p.",
         [Element("segment", "p" + n, (0.0, 0.0), as_xy(v), "absolute")
          for n, v in turned.items() if n != "p"])

    # the forces to apply: (name, load, link, kind, point, X position mm, F)
    applied: list[tuple[str, str, str, str, str | None, Vec2, Vec2]] = []
    for f in loads.all_forces():
        vec = np.asarray(f.vector[k], float)
        if not vec.any() or f.link == mech.frame_link:
            continue
        X = (np.asarray(f.at[k], float) - origin) / kl.per_mm
        applied.append((f.name, f.name, f.link, f.kind, f.point, X, vec))
    for m in loads.all_moments():
        M = float(m.moment[k])
        if M == 0 or m.link == mech.frame_link:
            continue
        A, B, a, b = images.ends(m.link)
        AB = (B - A) * kl.per_mm
        l_ab = float(np.hypot(*AB))
        fb = (M / l_ab) * perp(AB / l_ab)
        pa_, pb_ = a, b or f"{a}+"
        applied.append((f"F'{m.name}", m.name, m.link, m.kind, a, A, -fb))
        applied.append((f"F''{m.name}", m.name, m.link, m.kind, b, B, fb))
        step(f"{m.name} = ±F·l_{pa_}{pb_}",
             f"Couple {m.name} = {plain(M, 4)} N·m on link {m.link}: two forces "
             f"{m.name}/l_{pa_}{pb_} = {plain(abs(M), 4)}/{plain(l_ab, 4)} = "
             f"{plain(abs(M) / l_ab, 4)} N "
             f"⟂ {pa_}{pb_} at {pa_} and {pb_}.",
             f"Момент {m.name} = {plain(M, 4)} Н·м на звене {m.link}: пара сил "
             f"{m.name}/l_{pa_}{pb_} = {plain(abs(M), 4)}/{plain(l_ab, 4)} = "
             f"{plain(abs(M) / l_ab, 4)} Н "
             f"⟂ {pa_}{pb_} в точках {pa_} и {pb_}.", [])

    biggest = max((float(np.hypot(*F)) for *_, F in applied), default=0.0)
    # F_ур is drawn at the same Kf: the scale holds it too (|Σ M_p|/pa, exact arms; a short
    # pa makes it many times the applied forces, and its arrow ran off the sheet)
    exact_total = 0.0
    for _name, _load, link, _kind, point, X, F in applied:
        letter = images.name_of(link, point)
        x = (turned["p" if letter == "p" else letter + "'"] if letter is not None
             else perp(images.place(link, X)))
        exact_total += float(cross(x, F))
    biggest = max(biggest, abs(exact_total) / max(pa.mm, 1e-12))
    kf = fit_scale("Kp", "N/mm", max(biggest, 1e-9), FORCE_ARROW_MM)
    forces: list[LeverForce] = []
    readings: dict[str, Reading] = {pa_name: pa}
    total = 0.0
    for name, load, link, kind, point, X, F in applied:
        letter = images.name_of(link, point)
        if letter is not None:
            x = turned["p" if letter == "p" else letter + "'"]
            image = "p" if letter == "p" else letter + "'"
            how = f"at {image}, the image of {point}"
            how_ru = f"в точке {image}, изображении точки {point}"
        else:
            x = perp(images.place(link, X))
            image = f"x'({name})"
            turned[image] = x
            how = f"at {image}, the image of its point found by similarity on link {link}"
            how_ru = f"в точке {image}, найденной по теореме подобия на звене {link}"
        mag = float(np.hypot(*F))
        c = float(cross(x, F))
        h_exact = abs(c) / mag
        h = reader(h_exact)
        moment = math.copysign(mag * h, c) if h else 0.0
        total += moment
        rd = Reading(f"h_{name}", h, h_exact, f"h_{name}", h * mu, "m", "μ")
        readings[rd.name] = rd
        forces.append(LeverForce(name, load, link, kind, point, image, as_xy(x), as_xy(F), mag, rd,
                                 moment))
        e = F / mag
        foot = x - float(np.dot(x, e)) * e
        step(f"M_p({name}) = ±{name}·h_{name}",
             f"Force {name} = {plain(mag, 4)} N {how}; arm h_{name} = {h:.2f} mm, "
             f"M_p = {plain(moment, 5, sign=True)} N·mm.",
             f"Сила {name} = {plain(mag, 4)} Н {how_ru}; плечо h_{name} = {h:.2f} мм, "
             f"M_p = {plain(moment, 5, sign=True)} Н·мм.",
             [Element("segment", name, as_xy(x), as_xy(x + F / kf.per_mm), "force"),
              Element("segment", f"h_{name}", (0.0, 0.0), as_xy(foot), "arm")], (rd.name,))

    f_bal = abs(total) / pa.mm
    m_bal = cr.sense * mu * total
    a_t = turned[pin + "'"]
    fvec = -math.copysign(f_bal, total) * perp(a_t / pa.mm)  # its moment about p is −Σ M_p
    # the text writes round-off (a dead centre: every arm ~0) as 0, relative to the moments
    # the forces could make on a lever of this size
    size = sum(f.magnitude for f in forces) * pa.mm
    t_s = 0.0 if abs(total) <= 1e-12 * size else total
    f_s, m_s = abs(t_s) / pa.mm, cr.sense * mu * t_s
    step("Σ M_p = 0: F_ур·pa + Σ M_p(F_i) = 0",
         f"Σ M_p(F_i) = {plain(t_s, 5, sign=True)} N·mm; F_ур = |Σ M_p|/pa = "
         f"{plain(abs(t_s), 5)}/{pa.mm:.2f} = "
         f"{plain(f_s, 5)} N at {pin}' ⟂ p{pin}'; "
         f"M_ур(Ж) = F_ур·l_{cr.pivot}{cr.pin} = {plain(m_s, 5, sign=True)} N·m (CCW positive).",
         f"Σ M_p(F_i) = {plain(t_s, 5, sign=True)} Н·мм; F_ур = |Σ M_p|/pa = "
         f"{plain(abs(t_s), 5)}/{pa.mm:.2f} = "
         f"{plain(f_s, 5)} Н в точке {pin}' ⟂ p{pin}'; "
         f"M_ур(Ж) = F_ур·l_{cr.pivot}{cr.pin} = {plain(m_s, 5, sign=True)} Н·м (против "
         f"часовой — плюс).",
         [Element("segment", "F_ур", as_xy(a_t), as_xy(a_t + fvec / kf.per_mm), "force")])
    power = float(power_balance_moment(mech, kin, loads)[k])
    return Lever(plan.label, k, plan, turned, tuple(forces), tuple(steps), readings, total, mu,
                 f_bal, m_bal, power, reference,
                 None if reference is None else discrepancy_pct(reference, m_bal), kf)


__all__ = ["FORCE_ARROW_MM", "Lever", "LeverForce", "discrepancy_pct", "zhukovsky_lever"]
