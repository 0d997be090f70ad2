"""Tables of the velocity and acceleration plans, laid out as a hand calculation.

Position by position: the segments read off the velocity plan, then off the
acceleration plan, each turned into a value by its scale (``pb = 84.38 mm →
vB = pb·Kv = 0.4219 m/s``), then the angular rates of the links as a student
writes them (``ω2 = vBA/lAB = 0.3397/0.2 = 1.698 rad/s``). The plans are read
exactly, or to a drafting precision (e.g. 0.5 mm); then every value is set
against the exact plan's and its relative error (the drafting error) is given, with
the bound :mod:`graphplan.plans.conditioning` states for that precision (``±``). A position
whose plans intersect two lines at less than ``ILL_ANGLE_DEG`` is marked as a draftsman
marks it: ``lines meet at 1.3°, reading ±11 mm``.

:func:`plans_markdown` is for people, :func:`plans_csv` for scripts and
:func:`summary_rows` the compact table of main values on sheet 1. Angles are in
degrees here only; ω and ε are counter-clockwise positive.
"""

from __future__ import annotations

import csv
import io
import math
import re
from dataclasses import dataclass

import numpy as np

from ..geometry import norm
from ..kinematics import output_coordinate, position_angles_deg
from ..numbers import cell, csv_number, finite, fmt
from ..plans import (
    Bounded,
    Conditioning,
    Plan,
    Reader,
    Reading,
    intersections,
    kinematic_conditioning,
    plan_name,
)
from ..project import Analysis
from ..safe_text import markdown_cell
from ..units import Scale

TINY_MM = 1e-6
"""A segment shorter than this (mm) is zero: solver noise, with no relative error."""

WORDS = {
    "en": {
        "position": "Position", "phi": "φ, °", "segment": "Segment", "mm": "mm",
        "scale": "Scale", "quantity": "Quantity", "value": "Value", "exact": "Exact",
        "error": "Error, %", "link": "Link", "formula": "Calculation", "pos": "Pos.",
        "title": "Plans of velocities and accelerations",
        "scales": "Scales",
        "section": "Position {label}, φ = {phi:.2f}°",
        "velocity": "Velocity plan", "acceleration": "Acceleration plan",
        "rates": "Angular velocities and accelerations of the links (counter-clockwise +)",
        "exact_note": "Segments measured exactly (lengths to 0.01 mm).",
        "drafting_note": ("Segments read to {p} mm as on a hand drawing; exact values from the "
                          "exact plans; error = (value − exact)/exact; ± is the bound of the "
                          "drafting error for that reading precision."),
        "bound": "±", "ill": "Ill-conditioned", "step": "step",
        "translation": "translation",
        "m/s": "m/s", "m/s²": "m/s²", "rad/s": "rad/s", "rad/s²": "rad/s²", "1/s": "s⁻¹",
        "1/s²": "s⁻²",
    },
    "ru": {
        "position": "Положение", "phi": "φ, °", "segment": "Отрезок", "mm": "мм",
        "scale": "Масштаб", "quantity": "Величина", "value": "Значение", "exact": "Точно",
        "error": "Погрешность, %", "link": "Звено", "formula": "Расчёт", "pos": "Пол.",
        "title": "Планы скоростей и ускорений",
        "scales": "Масштабы",
        "section": "Положение {label}, φ = {phi:.2f}°",
        "velocity": "План скоростей", "acceleration": "План ускорений",
        "rates": "Угловые скорости и ускорения звеньев (против часовой стрелки +)",
        "exact_note": "Отрезки измерены точно (длины до 0.01 мм).",
        "drafting_note": ("Отрезки прочитаны с точностью {p} мм, как на чертеже от руки; точные "
                          "значения — по точным планам; погрешность = (значение − точно)/точно; "
                          "± — граница погрешности построения при этой точности чтения."),
        "bound": "±", "ill": "Плохо обусловлено", "step": "шаг",
        "translation": "поступательное движение",
        "m/s": "м/с", "m/s²": "м/с²", "rad/s": "рад/с", "rad/s²": "рад/с²", "1/s": "с⁻¹",
        "1/s²": "с⁻²",
    },
}

_RU_UNITS = (("(m/s²)/mm", "(м/с²)/мм"), ("(m/s)/mm", "(м/с)/мм"), ("N/mm", "Н/мм"),
             ("m/mm", "м/мм"))

_PLANS = ("velocity", "acceleration")


@dataclass(frozen=True, slots=True)
class PositionPlans(Bounded):
    """The velocity and acceleration plans of one position, as drawn and exact.

    Attributes
    ----------
    label : str
        The position's label (``"2"``, ``"(3)"``).
    phi_deg : float
        Crank angle φ, degrees in [0, 360) ([0, 720) in a four-stroke cycle).
    velocity, acceleration : Plan
        The plans as read with ``Reader(precision)``.
    exact_velocity, exact_acceleration : Plan
        The exact plans (the same objects when ``precision`` is 0).
    length_scale : Scale
        Kl, for the link lengths of the rates.
    index : int
        Index of the position in ``analysis.kin``.
    precision : float
        Reading precision, mm (0: exact).
    conditioning : Conditioning or None
        The plans' intersections (their marks) and, when ``precision`` > 0, the bound of
        every figure (:func:`graphplan.plans.conditioning.kinematic_conditioning`).
    """

    label: str
    phi_deg: float
    velocity: Plan
    acceleration: Plan
    exact_velocity: Plan
    exact_acceleration: Plan
    length_scale: Scale
    index: int
    precision: float = 0.0
    conditioning: Conditioning | None = None

    def plans(self, kind: str) -> tuple[Plan, Plan]:
        """The plan of ``kind`` (``"velocity"``/``"acceleration"``) as drawn, and exact."""
        if kind == "velocity":
            return self.velocity, self.exact_velocity
        return self.acceleration, self.exact_acceleration


def plan_readings(analysis: Analysis, precision: float = 0.0) -> list[PositionPlans]:
    """Build the plans of every position at sheet 1's scales (``analysis.sheet1``).

    Parameters
    ----------
    analysis : Analysis
    precision : float
        Reading precision in mm (0: exact). When > 0 the exact plans are built too.

    Returns
    -------
    list[PositionPlans]
        In the order of ``analysis.kin``.
    """
    if not (math.isfinite(precision) and precision >= 0):
        raise ValueError(f"the reading precision must be finite and ≥ 0 mm (got {precision!r})")
    # solved once per project and precision (the Markdown in two languages and the CSV
    # read it thrice)
    return list(analysis.stage(("plan_readings", float(precision)),
                               lambda: _plan_readings(analysis, float(precision))))


def _plan_readings(analysis: Analysis, precision: float) -> tuple[PositionPlans, ...]:
    mech, kin = analysis.mech, analysis.kin
    sc = analysis.sheet1
    kl, kv, ka = sc.kl, sc.kv, sc.ka
    out = []
    angles = position_angles_deg(mech, kin)
    for k in range(kin.n):  # sheet 1's plans, drafted and exact, each built once a project
        vp, ap = analysis.velocity_plan(k, precision), analysis.acceleration_plan(k, precision)
        ev, ea = analysis.velocity_plan(k), analysis.acceleration_plan(k)
        if precision > 0:
            # the bounds of the plans built once: only the probes are built there
            cond = kinematic_conditioning(mech, kin, k, kl, kv, ka, precision, exact=(ev, ea),
                                          drawn=(vp, ap), probes=analysis.probes(precision))
        else:
            cond = Conditioning(kin.labels[k], 0.0, intersections(vp) + intersections(ap))
        out.append(PositionPlans(kin.labels[k], float(angles[k]), vp, ap, ev, ea,
                                 kl, k, float(precision), cond))
    return tuple(out)


# --- records -------------------------------------------------------------------------------


def _finite(x: float) -> float:
    return finite(x, "a plan table")


def _n(x: float, digits: int = 4) -> str:
    """A number as a student writes it (no trailing zeros)."""
    return fmt(_finite(x), digits)


@dataclass(frozen=True, slots=True)
class _Line:
    """One segment read off a plan, with the exact plan's value of the same segment."""

    pos: PositionPlans
    plan: str
    reading: Reading
    scale: Scale
    exact_reading: Reading | None  # None: the exact plan has no such segment

    @property
    def symbol(self) -> str:
        """``v_BA`` → ``vBA``; the bare ``aᵏ``/``aʳ`` get the segment's subscript."""
        q, name = self.reading.quantity, self.reading.name
        if q in ("aᵏ", "aʳ") and "_" in name:
            q += name.split("_", 1)[1]
        return q.replace("_", "")

    @property
    def mm(self) -> float:
        """Length as read; solver noise below :data:`TINY_MM` is 0."""
        return self.reading.mm if self.reading.mm > TINY_MM else 0.0

    @property
    def value(self) -> float:
        return self.mm * self.scale.per_mm

    @property
    def exact(self) -> float | None:
        e = self.exact_reading
        if e is None:
            return None
        return e.value if e.mm > TINY_MM else 0.0

    @property
    def error(self) -> float | None:
        """Relative drafting error (value − exact)/exact, or None where exact is 0 or unknown."""
        e = self.exact
        return None if not e else (self.value - e) / e

    @property
    def bound(self) -> float | None:
        return self.pos.bound(self.plan, self.reading.name)


@dataclass(frozen=True, slots=True)
class _Rate:
    """The angular velocity (velocity plan) or acceleration of one link.

    ``how`` is ``("ratio", quantity, length name, numerator, length m)``,
    ``("crank",)``, ``("const",)``, ``("same", other link)`` or ``("translation",)``.
    """

    pos: PositionPlans
    plan: str
    link: str
    value: float
    exact: float
    how: tuple

    @property
    def symbol(self) -> str:
        return ("ω" if self.plan == "velocity" else "ε") + self.link

    @property
    def error(self) -> float | None:
        return None if not self.exact else (self.value - self.exact) / self.exact

    @property
    def bound(self) -> float | None:
        return self.pos.bound(self.plan, self.symbol)


def _lines(pp: PositionPlans, plan: str) -> list[_Line]:
    drawn, exact = pp.plans(plan)
    return [_Line(pp, plan, r, drawn.scale, exact.readings.get(r.name))
            for r in drawn.readings.values()]


def _rates(analysis: Analysis, pp: PositionPlans, plan: str) -> list[_Rate]:
    """Rates of the moving links in the order of attachment, each with how it was found."""
    mech, kin = analysis.mech, analysis.kin
    drawn, exact = pp.plans(plan)
    vel = plan == "velocity"
    pole = "p" if vel else "π"
    kl, reader = pp.length_scale.per_mm, Reader(pp.precision)

    def key(point: str) -> str:
        return plan_name(mech, point, pole)

    found: dict[str, _Rate] = {}

    def ratio(link: str, seg: str, tip: str, base: str, length: float) -> None:
        r, e = drawn.readings[seg], exact.readings[seg]
        value = drawn.rates[link] if r.mm > TINY_MM else 0.0
        ex = exact.rates[link] if e.mm > TINY_MM else 0.0
        ln = _Line(pp, plan, r, drawn.scale, e)
        found[link] = _Rate(pp, plan, link, value, ex,
                            ("ratio", ln.symbol, f"l{base}{tip}", ln.value, length))

    def same(link: str, other: str) -> None:
        if other == mech.frame_link:
            found[link] = _Rate(pp, plan, link, 0.0, 0.0, ("translation",))
        else:
            src = found[other]
            found[link] = _Rate(pp, plan, link, src.value, src.exact, ("same", other))

    cr = mech.crank
    found[cr.link] = _Rate(pp, plan, cr.link, cr.omega if vel else 0.0, cr.omega if vel else 0.0,
                           ("crank",) if vel else ("const",))
    for dy in mech.dyads:
        i, j = dy.links
        if dy.kind == "RRR":
            A, B, C = dy.joints
            if vel:
                ratio(i, key(A) + key(B), B, A, dy.lengths[0])
                ratio(j, key(C) + key(B), B, C, dy.lengths[1])
            else:
                ratio(i, f"τ_{B}{A}", B, A, dy.lengths[0])
                ratio(j, f"τ_{B}{C}", B, C, dy.lengths[1])
        elif dy.kind == "RRP":
            A, B = dy.joints
            ratio(i, key(A) + key(B) if vel else f"τ_{B}{A}", B, A, dy.lengths[0])
            same(j, dy.guides[0].link)
        elif dy.kind == "RPR":
            A, C = dy.joints
            pts = kin.pos.points
            mm = float(norm(pts[A][pp.index] - pts[C][pp.index])) / kl
            ratio(j, key(C) + key(A) + j if vel else f"τ_{A}{C}", A, C, reader(mm) * kl)
            same(i, j)
        elif dy.kind == "PRP":
            same(i, dy.guides[0].link)
            same(j, dy.guides[1].link)
        elif dy.kind == "RPP":
            same(j, dy.guides[0].link)
            same(i, j)
    return [found[ln] for ln in mech.moving_links]


def _formula(rate: _Rate, analysis: Analysis, lang: str) -> str:
    """``ω2 = vBA/lAB = 0.3397/0.2 = 1.698 rad/s``, magnitudes (the sign is in the value)."""
    w = WORDS[lang]
    unit = w["rad/s"] if rate.plan == "velocity" else w["rad/s²"]
    s, how = rate.symbol, rate.how
    if how[0] == "ratio":
        _, q, lname, num, length = how
        return f"{s} = {q}/{lname} = {_n(num)}/{_n(length)} = {_n(abs(rate.value))} {unit}"
    if how[0] == "crank":
        rpm = analysis.mech.crank.rpm
        return f"{s} = π·n1/30 = π·{_n(rpm, 6)}/30 = {_n(abs(rate.value))} {unit}"
    if how[0] == "const":
        return f"{s} = 0 (ω{rate.link} = const)"
    if how[0] == "translation":
        return f"{s} = 0 ({w['translation']})"
    sym = s[0] + how[1]
    return f"{s} = {sym} = {_n(abs(rate.value))} {unit}"


# --- cells ---------------------------------------------------------------------------------


def _words(lang: str) -> dict[str, str]:
    if lang not in WORDS:
        raise ValueError(f"unknown language {lang!r} (expected one of {', '.join(WORDS)})")
    return WORDS[lang]


def _localise(text: str, lang: str) -> str:
    if lang == "ru":
        for en, ru in _RU_UNITS:
            text = text.replace(en, ru)
    return text


def _decimals(precision: float) -> int:
    """Decimals that show a length read to ``precision`` mm (2 when exact)."""
    if precision <= 0:
        return 2
    return next((d for d in range(6) if abs(round(precision, d) - precision) <= 1e-9 * precision),
                6)


def _unit(plan: str, lang: str) -> str:
    return WORDS[lang]["m/s" if plan == "velocity" else "m/s²"]


def _pct(err: float | None) -> str:
    return "—" if err is None else f"{_finite(err * 100):.2f}"


def _line_cells(ln: _Line, lang: str) -> list[str]:
    """Segment, mm, scale, quantity, value [, exact, error] of one reading."""
    unit, sc = _unit(ln.plan, lang), ln.scale
    cells = [ln.reading.name, f"{_finite(ln.mm):.{_decimals(ln.pos.precision)}f}",
             f"{sc.symbol} = {_n(sc.per_mm, 6)} {_localise(sc.unit, lang)}", ln.symbol,
             f"{_n(ln.value)} {unit}"]
    if ln.pos.precision > 0:
        cells += [_pm(ln.bound, unit), "—" if ln.exact is None else f"{_n(ln.exact)} {unit}",
                  _pct(ln.error)]
    return cells


def _pm(bound: float | None, unit: str) -> str:
    """``±0.0025 m/s`` (2 significant digits), or ``—``."""
    return "—" if bound is None else f"±{fmt(_finite(bound), 2)} {unit}"


def _rate_cells(rate: _Rate, analysis: Analysis, lang: str) -> list[str]:
    w = WORDS[lang]
    unit = w["rad/s"] if rate.plan == "velocity" else w["rad/s²"]
    cells = [rate.link, _formula(rate, analysis, lang), f"{_n(rate.value)} {unit}"]
    if rate.pos.precision > 0:
        b = None if rate.how[0] in ("crank", "const", "translation") else rate.bound
        cells += [_pm(b, unit) if b is not None else "—", f"{_n(rate.exact)} {unit}",
                  _pct(rate.error)]
    return cells


def _line_header(w: dict[str, str], precision: float) -> list[str]:
    head = [w["segment"], w["mm"], w["scale"], w["quantity"], w["value"]]
    return head + ([w["bound"], w["exact"], w["error"]] if precision > 0 else [])


def _rate_header(w: dict[str, str], precision: float) -> list[str]:
    head = [w["link"], w["formula"], w["value"]]
    return head + ([w["bound"], w["exact"], w["error"]] if precision > 0 else [])


def _marks(pp: PositionPlans, lang: str) -> list[str]:
    """The draftsman's mark of an ill-conditioned position: one line per intersection."""
    c = pp.conditioning
    if c is None or not c.marks:
        return []
    w = WORDS[lang]
    out = []
    for x in c.marks:
        out.append(f"**{w['ill']}:** {x.note(lang)} ({w[x.plan]}, {w['step']} {x.step}: "
                   f"`{x.equation}`).")
    return out


def _where(pp: PositionPlans) -> list[str]:
    return [pp.label, f"{_finite(pp.phi_deg):.2f}"]


# --- public tables -------------------------------------------------------------------------


def plan_table_rows(analysis: Analysis, lang: str = "en",
                    precision: float = 0.0) -> tuple[list[str], list[list[str]]]:
    """Every segment read off the plans: one row per reading per position.

    Columns: position, φ (°), segment (as labelled on the sheet: ``pb``, ``πb``,
    ``n_BA``), its length in mm (2 decimals when exact, else to the reading
    precision), the scale (``Kv = 0.005 (m/s)/mm``), the quantity (``vB``,
    ``aτBA``) and its value with units; when ``precision`` > 0 also the exact
    value and the drafting error in %. Velocity-plan rows come before the
    acceleration-plan rows of each position.

    Returns
    -------
    header : list[str]
    rows : list[list[str]]
    """
    w = _words(lang)
    rows = [_where(pp) + _line_cells(ln, lang)
            for pp in plan_readings(analysis, precision) for plan in _PLANS
            for ln in _lines(pp, plan)]
    return [w["position"], w["phi"], *_line_header(w, precision)], rows


def rate_table_rows(analysis: Analysis, lang: str = "en",
                    precision: float = 0.0) -> tuple[list[str], list[list[str]]]:
    """The angular velocities then accelerations of the moving links, position by position.

    Columns: position, φ (°), link, the calculation as a student writes it
    (``ω2 = vBA/lAB = 0.3397/0.2 = 1.698 rad/s``, magnitudes), the signed value
    (counter-clockwise +); when ``precision`` > 0 the exact value and the error in %.
    """
    w = _words(lang)
    rows = [_where(pp) + _rate_cells(r, analysis, lang)
            for pp in plan_readings(analysis, precision) for plan in _PLANS
            for r in _rates(analysis, pp, plan)]
    return [w["position"], w["phi"], *_rate_header(w, precision)], rows


def _md_table(header: list[str], rows: list[list[str]], right: set[int]) -> list[str]:
    rule = ["---:" if c in right else "---" for c in range(len(header))]
    return ["| " + " | ".join(r) + " |" for r in (header, rule, *rows)]


def plans_markdown(analysis: Analysis, lang: str = "en", precision: float = 0.0) -> str:
    """The plans' tables as a Markdown document, in the order of a hand calculation.

    Title, the scales with their basis (``Kl = lOA/OA = 0.08/80 = 0.001 m/mm``),
    then per position: the velocity plan's table, the acceleration plan's table
    and the angular rates of the links.
    """
    w = _words(lang)
    m = analysis.mech
    positions = plan_readings(analysis, precision)
    note = (w["drafting_note"].format(p=_n(precision)) if precision > 0 else w["exact_note"])
    out = [f"# {w['title']} — {markdown_cell(m.name)}", "", note, "", f"## {w['scales']}", ""]
    first = positions[0]
    for sc in (first.length_scale, first.velocity.scale, first.acceleration.scale):
        out.append(f"- {_localise(sc.basis, lang)}")
    for pp in positions:
        out += ["", f"## {w['section'].format(label=pp.label, phi=pp.phi_deg)}"]
        marks = _marks(pp, lang)
        if marks:
            out += ["", *marks]
        for plan in _PLANS:
            rows = [_line_cells(ln, lang) for ln in _lines(pp, plan)]
            for r in rows:
                r[0] = f"`{r[0]}`"
            out += ["", f"### {w[plan]}", "",
                    *_md_table(_line_header(w, precision), rows, {1, 4, 5, 6, 7})]
        rows = [_rate_cells(r, analysis, lang)
                for plan in _PLANS for r in _rates(analysis, pp, plan)]
        out += ["", f"### {w['rates']}", "",
                *_md_table(_rate_header(w, precision), rows, {2, 3, 4, 5})]
    text = "\n".join(out) + "\n"
    if re.search(r"\b(nan|inf)\b", text, re.IGNORECASE):
        raise ValueError("NaN or infinity in the plans' Markdown")
    return text


CSV_COLUMNS = ("position", "phi_deg", "plan", "kind", "name", "mm", "scale", "scale_per_mm",
               "quantity", "value", "unit", "exact_value", "error_pct", "bound",
               "ill_conditioned")
"""Columns of :func:`plans_csv`; ``kind`` is ``segment`` or ``rate`` (``name`` is then the link).

``bound`` is ± of ``value`` for the reading precision (empty in exact mode);
``ill_conditioned`` the draftsman's mark of the position (``lines meet at 1.3°, reading
±11 mm``), empty where its plans are well conditioned."""


def _r(x: float | None) -> str:
    return csv_number(x, "a plan table")


def plans_csv(analysis: Analysis, lang: str = "en", precision: float = 0.0) -> str:
    """Every reading and rate of every position in one flat CSV, for scripts.

    The columns are :data:`CSV_COLUMNS` whatever the language (``lang`` only
    chooses the units' spelling); ``plan`` is ``velocity`` or ``acceleration``.
    Segment rows satisfy ``value = mm·scale_per_mm``; rate rows (``kind = rate``)
    hold ω or ε of a link, CCW +, and leave ``mm`` and the scale empty. In exact
    mode ``exact_value`` equals ``value``; ``error_pct`` is empty where the
    exact value is zero.
    """
    w = _words(lang)
    buf = io.StringIO()
    wr = csv.writer(buf, lineterminator="\n")
    wr.writerow(CSV_COLUMNS)
    for pp in plan_readings(analysis, precision):
        where = [pp.label, _r(pp.phi_deg)]
        mark = pp.conditioning.note("en") if pp.conditioning is not None else ""
        for plan in _PLANS:
            for ln in _lines(pp, plan):
                err = None if ln.error is None else ln.error * 100
                wr.writerow([*where, plan, "segment", ln.reading.name, _r(ln.mm),
                             ln.scale.symbol, _r(ln.scale.per_mm), ln.symbol, _r(ln.value),
                             _unit(plan, lang), _r(ln.exact), _r(err), _r(ln.bound), mark])
        for plan in _PLANS:
            for rt in _rates(analysis, pp, plan):
                err = rt.error
                b = None if rt.how[0] in ("crank", "const", "translation") else rt.bound
                wr.writerow([*where, plan, "rate", rt.link, "", "", "", rt.symbol, _r(rt.value),
                             w["rad/s" if plan == "velocity" else "rad/s²"], _r(rt.exact),
                             _r(None if err is None else err * 100), _r(b), mark])
    return buf.getvalue()


SUMMARY_CELL = 9
"""Longest cell of the sheet's summary table (3.5 mm lettering on A1)."""


def summary_rows(analysis: Analysis, lang: str = "en") -> tuple[list[str], list[list[str]]]:
    """The compact table of main values for sheet 1: one row per position.

    Columns: position, φ, |v| and |a| of the output point and of the links'
    centres of mass, then ω and ε (CCW +) of every link past the crank that
    turns (a link that turns with a later one, as a block with its rocker, is
    given once, by the later). Exact values, 3–4 significant digits, every cell
    at most :data:`SUMMARY_CELL` characters.
    """
    w = _words(lang)
    m, kin = analysis.mech, analysis.kin
    points = [output_coordinate(m, kin.pos)[3]]
    for ln in m.moving_links:
        c = m.links[ln].centre if ln in m.links else None
        if c and c not in points and c not in m.frame_points and c != m.crank.pivot:
            points.append(c)
    cols: list[tuple[str, np.ndarray]] = []
    for p in points:
        cols += [(f"v{p}, {w['m/s']}", norm(kin.vel.points[p])),
                 (f"a{p}, {w['m/s²']}", norm(kin.acc.points[p]))]
    turning = abs(m.crank.omega) * 1e-9
    links = [ln for ln in m.moving_links
             if ln != m.crank.link and np.max(np.abs(kin.vel.omega[ln])) > turning]

    def same(a: str, b: str) -> bool:
        return (np.allclose(kin.vel.omega[a], kin.vel.omega[b], rtol=1e-9, atol=turning)
                and np.allclose(kin.acc.epsilon[a], kin.acc.epsilon[b], rtol=1e-9,
                                atol=turning * abs(m.crank.omega)))

    for n, ln in enumerate(links):
        if not any(same(ln, later) for later in links[n + 1:]):  # a block turns with its rocker
            cols += [(f"ω{ln}, {w['1/s']}", kin.vel.omega[ln]),
                     (f"ε{ln}, {w['1/s²']}", kin.acc.epsilon[ln])]
    header = [w["pos"], w["phi"], *(h for h, _ in cols)]
    rows = []
    angles = position_angles_deg(m, kin)
    for k in range(kin.n):
        row = [kin.labels[k], f"{angles[k]:.1f}"]
        for _, arr in cols:
            big = float(np.max(np.abs(arr)))
            x = float(arr[k])
            row.append(cell(_finite(0.0 if abs(x) <= 1e-9 * big else x), SUMMARY_CELL))
        rows.append(row)
    return header, rows


__all__ = ["CSV_COLUMNS", "PositionPlans", "plan_readings", "plan_table_rows", "plans_csv",
           "plans_markdown", "rate_table_rows", "summary_rows"]
