"""The kinematic diagrams checked against the plans, position by position (method B.2.5, 7).

The student differentiates s(φ) graphically by the method of chords and then compares the
ordinates read off the v(φ) and a(φ) diagrams at the main positions with the values the
velocity and acceleration plans give there:

    Δv = (v_диагр − v_план) / v_план · 100 %,   Δa = (a_диагр − a_план) / a_план · 100 %.

What the diagram gives at a main position (a node τ_i of the chord method,
:class:`graphplan.plans.KinematicDiagrams`):

* **v**: the v polyline is drawn through the chord points at the intervals' middles, so at
  the node it reads the mean of the two chords either side,
  ``v_i = (v_chords[i−1] + v_chords[i]) / 2`` (periodic: ``v_chords[−1]`` before node 0);
* **a**: the chord points of a are at the nodes themselves, ``a_i = a_chords[i]``.

The plans' values are the output's velocity and acceleration at that position along its
working direction (``mech.output.working``), the diagrams' sign. Where the plan's value is
under ``ZERO_SHARE`` of its largest over the turn (a dead centre, a change of sign), the
ratio means nothing and Δ is given as «—», as a student writes it.
"""

from __future__ import annotations

import math

import numpy as np

from ..kinematics import output_coordinate, slide_key
from ..numbers import cell, signed
from ..plans import KinematicDiagrams
from ..project import Analysis

ZERO_SHARE = 0.05  #: |plan value| below this share of its largest: no Δ (a dead centre)
DASH = "—"

WORDS = {
    "en": {"title": "Diagrams against the plans", "pos": "Pos.", "diag": "diagr.",
           "plan": "plan", "m/s": "m/s", "m/s²": "m/s²", "1/s": "s⁻¹", "1/s²": "s⁻²"},
    "ru": {"title": "Сравнение диаграмм с планами", "pos": "Пол.", "diag": "диагр.",
           "plan": "план", "m/s": "м/с", "m/s²": "м/с²", "1/s": "с⁻¹", "1/s²": "с⁻²"},
}


def diagram_nodes(analysis: Analysis, d: KinematicDiagrams) -> list[tuple[int, int]]:
    """``(node i, position k)`` of every position of the first turn that is a node of the
    chord method, in the order of the nodes (matched by the crank's travel from the first
    position, ``τ = sense·(φ_k − φ_first)`` mod 2π, to 1e-6 rad)."""
    kin = analysis.kin
    h = 2 * math.pi / d.intervals
    out: dict[int, int] = {}
    for k in range(kin.n):
        tau = (d.sense * (float(kin.phi[k]) - d.phi_first)) % (2 * math.pi)
        i = round(tau / h)
        if abs(tau - i * h) < 1e-6 and i % d.intervals not in out:
            out[i % d.intervals] = k
    return sorted(out.items())


def plan_motion(analysis: Analysis) -> tuple[np.ndarray, np.ndarray]:
    """The output's velocity and acceleration at every position (the plans' values), along
    its working direction: m/s, m/s² for a slider; rad/s, rad/s² for a rocker."""
    mech, kin = analysis.mech, analysis.kin
    kind, _, rate, _ = output_coordinate(mech, kin.pos, kin.vel)
    out = mech.output.link
    acc = (kin.acc.sliding[slide_key(out, mech.frame_link)] if kind == "slider"
           else kin.acc.epsilon[out])
    w = float(mech.output.working)
    return w * np.asarray(rate, float), w * np.asarray(acc, float)


def diagram_values(d: KinematicDiagrams) -> tuple[np.ndarray, np.ndarray]:
    """v and a read off the diagrams at every node 0…n−1 (see the module docstring)."""
    v = 0.5 * (np.roll(d.v_chords, 1) + d.v_chords)
    return v, np.asarray(d.a_chords[:-1], float)


def _delta(diag: float, plan: float, big: float) -> str:
    if abs(plan) < ZERO_SHARE * big:
        return DASH
    pct = (diag - plan) / plan * 100.0
    if abs(pct) < 0.05:
        return "0.0"
    return signed(pct, 1) if abs(pct) < 1000 else signed(pct, 0)


def comparison_rows(analysis: Analysis, d: KinematicDiagrams, lang: str = "en"
                    ) -> tuple[str, list[str], list[list[str]]]:
    """The table of the diagrams against the plans: its title (with the units), header and
    rows — position, v off the diagram, v of the plan, Δv %, a off the diagram, a of the
    plan, Δa % (ω, ε of a rocker output)."""
    w = WORDS[lang]
    rocker = d.output_kind == "rocker"
    sv, sa = ("ω", "ε") if rocker else ("v", "a")
    uv, ua = (w["1/s"], w["1/s²"]) if rocker else (w["m/s"], w["m/s²"])
    o = d.output
    header = [w["pos"], f"{sv}{o} {w['diag']}", f"{sv}{o} {w['plan']}", f"Δ{sv}, %",
              f"{sa}{o} {w['diag']}", f"{sa}{o} {w['plan']}", f"Δ{sa}, %"]
    vp, ap = plan_motion(analysis)
    vd, ad = diagram_values(d)
    nodes = diagram_nodes(analysis, d)
    big_v = max((abs(float(vp[k])) for _, k in nodes), default=0.0)
    big_a = max((abs(float(ap[k])) for _, k in nodes), default=0.0)
    title = f"{w['title']} ({sv}, {uv}; {sa}, {ua})"
    rows = []
    for i, k in nodes:
        row = [analysis.kin.labels[k]]
        for diag, plan, big in ((float(vd[i]), float(vp[k]), big_v),
                                (float(ad[i]), float(ap[k]), big_a)):
            tidy = [0.0 if abs(x) <= 1e-9 * big else x for x in (diag, plan)]
            row += [cell(tidy[0], 7), cell(tidy[1], 7), _delta(diag, plan, big)]
        rows.append(row)
    return title, header, rows


__all__ = ["comparison_rows", "diagram_nodes", "diagram_values", "plan_motion"]
