"""The seed's hand calculation of the crank press beside graphplan's figures: the document
``examples/press.md`` (:func:`seed_comparison_markdown`).
"""

from __future__ import annotations

import re

from ..numbers import fmt
from ..project import Analysis
from .force_readings import PositionForces, force_readings
from .force_tables import _crank_arm, _f, _m_bal, _md_table, _reaction_value

SEED_NAME = "000_27302160a71cc747.txt"
"""The seed: a student's force analysis of the crank press (Russian), ``shared/seed``."""

# (quantity, unit, the seed's value, how the seed has it). "stated": the figure is
# written in the seed; "derived": computed here from figures the seed states.
SEED: dict[str, tuple[tuple[str, str, float, str], ...]] = {
    "(2)": (
        ("Q", "N", 420000.0, "stated: `0,7Q0 = 0.7∙600000 = 420000 H`"),
        ("Kp", "N/mm", 10000.0, "stated: `Кр=420/42=10 кН/мм`"),
        ("R12", "N", 424000.0, "stated: `R12=42,4∙10=424 кН`"),
        ("h21", "mm", 37.39, "stated: `h21=37.39 мм`"),
        ("Mур", "N·m", 15850.0, "stated: `Мур=424∙37,39∙0,001=15,85кНм`"),
    ),
    "(3)": (
        ("Q", "N", 600000.0, "stated: `Q0 = 600000 H`"),
        ("Kp", "N/mm", 10000.0, "stated: `Кр=600/60=10 кН/мм`"),
        ("R12", "N", 601500.0, "stated: `R12=60,15∙10=601,5 кН`"),
        ("h21", "mm", 19.33, "stated: `h21=19,33 мм`"),
        ("Mур", "N·m", 11627.0, "stated: `Мур=601,5∙19,33∙0,001=11,627 кНм`"),
    ),
    "2": (
        ("G2", "N", 1265.49, "stated: `G2=129∙9.81=1265.49 H`"),
        ("G3", "N", 12262.5, "stated: `G3=1250∙9.81=12262.5 H`"),
        ("Pи2", "N", 299.7414, "stated: `Pи2=129∙(87,55∙0.02654)=299,7414H`"),
        ("Pи3", "N", 2457.604, "stated: `Pи3=1250∙(74,08∙0.02654)=2457,604H`"),
        ("R43", "N", 8145.71, "stated: `R43=…/191,3=8145,71 H`"),
        ("Kp", "N/mm", 200.0, "stated: `Кр=8145,71/40,79=200 Н/мм`"),
        ("R12", "N", 90.47 * 200.0, "derived: `R12=90,47мм` × 200 N/mm"),
        ("h21", "mm", 37.86, "stated: `37,86` in the equation of Mур"),
        ("Mур", "N·m", 1370.1, "stated: `Мур=90,47∙200∙37,86∙0,002=1370,1Нм`"),
    ),
    "3": (
        ("G2", "N", 1265.49, "stated (as for position 2)"),
        ("G3", "N", 12262.5, "stated (as for position 2)"),
        ("Pи2", "N", 236.609, "stated: `Pи2=129∙(69,11∙0.02654)=236,609H`"),
        ("Pи3", "N", 1498.51, "stated: `Pи3=1250∙(45,17∙0.02654)=1498,51H`"),
        ("R43", "N", 6229.37, "stated: `R43=…/28=6229,37 H`"),
        ("Kp", "N/mm", 200.0, "stated: `Кр=6229,37/31,15=200 Н/мм`"),
        ("R12", "N", 80.65 * 200.0, "derived: `R12=80,65мм` × 200 N/mm"),
        ("h21", "mm", 37.13, "stated: `h21=37,13 мм`"),
        ("Mур", "N·m", 1197.8, "stated: `Мур=80,65∙200∙37,13∙0,002=1197,8Нм`"),
    ),
    "4": (
        ("G2", "N", 1265.49, "stated (as for position 2)"),
        ("G3", "N", 12262.5, "stated (as for position 2)"),
        ("Pи3", "N", 1206.0, "stated: `Pи3=900∙(67∙0.02)=1206H`"),
        ("R43", "N", 4460.3, "stated: `R43=…/191,83=4460,3H`"),
        ("Kp", "N/mm", 200.0, "stated: `Кр=4460,3/22,3=200 Н/мм`"),
        ("R12", "N", 81.28 * 200.0, "derived: `R12=81,28мм` × 200 N/mm"),
        ("h21", "mm", 19.8, "stated: `h21=19,8 мм`"),
        ("Mур", "N·m", 643.7, "stated: `Мур=81,28∙200∙19,8∙0,002=643,7Нм`"),
    ),
    "6": (("Mур", "N·m", -643.7, "stated: `Мур=-643,7Нм` (position 6 mirrors 4)"),),
    "7": (("Mур", "N·m", -1197.8, "stated: `Мур=-1197,8Нм` (position 7 mirrors 3)"),),
    "8": (("Mур", "N·m", -1370.1, "stated: `Мур=-1370,1Нм` (position 8 mirrors 2)"),),
}

_SEED_TITLES = {
    "(2)": "Working stroke (рабочий ход), position (2)",
    "(3)": "Working stroke (рабочий ход), position (3)",
    "2": "Idle stroke (холостой ход), position 2",
    "3": "Idle stroke (холостой ход), position 3",
    "4": "Idle stroke (холостой ход), position 4",
    "6": "Idle stroke (холостой ход), position 6 (mirror image of 4)",
    "7": "Idle stroke (холостой ход), position 7 (mirror image of 3)",
    "8": "Idle stroke (холостой ход), position 8 (mirror image of 2)",
}


def _graphplan_value(pf: PositionForces, mode: str, quantity: str) -> float | None:
    """graphplan's value of a seed quantity at one position (None: not in this mode)."""
    plans = pf.plans(mode)
    if quantity == "Kp":
        return plans[0].scale.per_mm
    if quantity == "Mур":
        return _m_bal(plans[-1])
    if quantity == "h21":
        arm = _crank_arm(plans[-1])
        return None if arm is None else arm[1]
    if quantity.startswith("R"):
        return _reaction_value(plans, quantity)
    row = next((r for r in pf.loads if r.name == quantity), None)
    if mode == "exact":
        return None if row is None else row.value
    for p in plans:
        if quantity in p.readings:
            return p.readings[quantity].value
    return None


def _seed_cell(x: float | None) -> str:
    return "—" if x is None else _f(x)


def seed_comparison_markdown(analysis: Analysis, precision: float | None = None) -> str:
    """"The seed beside graphplan": the seed's figures next to graphplan's (examples/press.md).

    For the working positions (2), (3), the idle positions 2, 3, 4 and their mirror
    images 6, 7, 8: each figure of the seed (:data:`SEED`, stated or derived from stated
    figures), graphplan's exact and drafted values (the variant's ``drawing.reading_mm``
    unless ``precision`` is given) and the relative differences ``(graphplan − seed)/|seed|``.
    Loads are the full model's values in exact mode (also where the neglect rule drops
    them) and the force plan's reading in drafted mode ("—" where they are dropped). No
    difference is explained here: that is the checker's job.

    Parameters
    ----------
    analysis : Analysis
        Of ``examples/press.toml`` (the seed's variant).
    precision : float or None
        Drafting reading precision, mm.
    """
    positions = {pf.label: pf for pf in force_readings(analysis, precision)}
    missing = [lab for lab in SEED if lab not in positions]
    if missing:
        raise ValueError(f"the variant has no position {', '.join(missing)} of the seed")
    prec = next(iter(positions.values())).precision
    pm = fmt(prec)
    out = [
        "# The seed beside graphplan",
        "",
        "<!-- Generated by graphplan.reports.force_tables.seed_comparison_markdown("
        "analyze(load('examples/press.toml'))); tests/test_force_tables.py checks it is "
        "up to date. -->",
        "",
        f"The seed (`{SEED_NAME}`, a student's force analysis of the crank press, "
        "«Динамический анализ основного механизма пресса») beside graphplan's force plans "
        "of its variant, `examples/press.toml`. Per position: each figure of the seed, "
        "whether the seed states it or it is derived here from figures the seed states, "
        f"graphplan's exact value and its drafted value (segments and arms read to {pm} mm), "
        "and the relative difference (graphplan − seed)/|seed|.",
        "",
        "Units: N, N/mm (Kp, масштаб плана сил), mm (h21, on the position plan at "
        "Kl = 0.001 m/mm), N·m (Mур, уравновешивающий момент, counter-clockwise positive). "
        "Loads (G, Pи, Q): exact, the full model's magnitude; drafted, the segment read off "
        "the force plan, — where the variant's 10 % rule neglects the load. R12, R43: "
        "magnitudes. Kp: graphplan's force scale of the group's plan (a choice of scale from "
        "the plans' series 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 × 10ⁿ, finer than the seed's "
        "1, 2, 2.5, 4, 5, so no Δ is given; at the seed's own Kp graphplan reads the seed's "
        "segments, e.g. R12 = 42.4 mm at 10 kN/mm in position (2), tests/test_force_plans.py).",
        "",
        "The differences are not explained here; explaining them is the job of the checker "
        "(a later issue).",
    ]
    summary = []
    for lab, rows in SEED.items():
        pf = positions[lab]
        out += ["", f"## {_SEED_TITLES[lab]}", "",
                f"φ = {_f(pf.phi_deg)}°. Neglected by graphplan's rule: "
                f"{', '.join(pf.neglected) or 'nothing'}.", ""]
        table = []
        for q, unit, seed, how in rows:
            ex = _graphplan_value(pf, "exact", q)
            dr = _graphplan_value(pf, "drafted", q)
            table.append([q, unit, _seed_cell(seed), how, _seed_cell(ex),
                          _seed_cell(dr),
                          "—" if ex is None or q == "Kp" else _f((ex - seed) / abs(seed) * 100),
                          "—" if dr is None or q == "Kp" else _f((dr - seed) / abs(seed) * 100)])
            if q == "Mур" and ex is not None and dr is not None:
                summary.append([lab, _f(seed), _f(ex), _f(dr),
                                _f(pf.lever_exact.M_bal), _f(pf.lever_drafted.M_bal),
                                _f((ex - seed) / abs(seed) * 100),
                                _f((dr - seed) / abs(seed) * 100)])
        out += _md_table(["Quantity", "Unit", "Seed", "In the seed",
                          "graphplan, exact", f"graphplan, drafted ({pm} mm)",
                          "Δ exact, %", "Δ drafted, %"], table, {2, 4, 5, 6, 7})
    out += ["", "## Mур at the seed's positions", "",
            "The seed's curve of moments (кривая моментов сил сопротивления) is drawn from "
            "these Mур values. graphplan: the force plans (exact, drafted) and Zhukovsky's "
            "lever (рычаг Жуковского, exact, drafted); Δ against the seed.", ""]
    out += _md_table(["Position", "Seed, N·m", "Plans exact", "Plans drafted",
                      "Lever exact", "Lever drafted", "Δ exact, %", "Δ drafted, %"], summary,
                     {1, 2, 3, 4, 5, 6, 7})
    text = "\n".join(out) + "\n"
    if re.search(r"\b(nan|inf)\b", text, re.IGNORECASE):
        raise ValueError("NaN or infinity in the seed comparison")
    return text


__all__ = ["SEED", "SEED_NAME", "seed_comparison_markdown"]
