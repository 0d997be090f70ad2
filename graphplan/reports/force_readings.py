"""The force analysis of each position as the tables read it (issue 4): the loads acting and
neglected, the force plans and Zhukovsky's lever exact and drafted at the variant's reading
precision, with their conditioning; solved once per project and precision
(:func:`force_readings`). The tables that write them: :mod:`graphplan.reports.force_tables`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..forces import Loads
from ..kinematics import position_angles_deg
from ..plans import (
    EXACT,
    Bounded,
    Conditioning,
    ForcePlan,
    Lever,
    Reader,
    force_conditioning,
    force_plans,
)
from ..project import Analysis
from ..units import Scale

TINY = 1e-9
"""Relative size below which a value is zero (solver noise) in the tables."""


@dataclass(frozen=True, slots=True)
class LoadRow:
    """One load of the full model at one position.

    ``value`` is |F| (N) for a force, M (N·m, CCW +) for a couple; ``neglected`` says
    whether the variant's rule dropped it there.
    """

    name: str
    link: str
    kind: str
    value: float
    unit: str
    neglected: bool


@dataclass(frozen=True, slots=True)
class PositionForces(Bounded):
    """The force analysis of one position, built exactly and drafted.

    Attributes
    ----------
    label : str
    phi_deg : float
        Crank angle φ, degrees in [0, 360) ([0, 720) in a four-stroke cycle).
    index : int
        Index of the position in ``analysis.kin``.
    precision : float
        The drafting reading precision, mm.
    exact, drafted : tuple[ForcePlan, ...]
        :func:`graphplan.plans.forces.force_plans` with the exact and the drafting reader
        (the groups from the last to the first, then the crank).
    lever_exact, lever_drafted : Lever
        Zhukovsky's lever in both modes, each with the discrepancy against the plans' Mур
        of the same mode.
    M_bal : float
        Mур of the exact kinetostatics (the variant's rule), N·m.
    M_full : float
        Mур with every load kept (``neglect_below = 0``), N·m.
    loads : tuple[LoadRow, ...]
        Every non-zero load of the full model.
    rule : float
        The variant's ``neglect_below``.
    kl : Scale
        Kl of the position plan the arms are measured on.
    M_scale : float
        The largest |Mур| of all positions (N·m): a moment below ``TINY`` of it is zero.
    conditioning : Conditioning or None
        The force plans' intersections (their marks) and the bound of every drafted
        figure (:func:`graphplan.plans.conditioning.force_conditioning`).
    """

    label: str
    phi_deg: float
    index: int
    precision: float
    exact: tuple[ForcePlan, ...]
    drafted: tuple[ForcePlan, ...]
    lever_exact: Lever
    lever_drafted: Lever
    M_bal: float
    M_full: float
    loads: tuple[LoadRow, ...]
    rule: float
    kl: Scale
    M_scale: float = 0.0
    conditioning: Conditioning | None = None

    @property
    def neglected(self) -> tuple[str, ...]:
        """Names of the loads the rule dropped here."""
        return tuple(r.name for r in self.loads if r.neglected)

    def plans(self, mode: str) -> tuple[ForcePlan, ...]:
        """The plans of ``mode`` (``"exact"`` or ``"drafted"``)."""
        return self.exact if mode == "exact" else self.drafted

    def lever(self, mode: str) -> Lever:
        """Zhukovsky's lever of ``mode``."""
        return self.lever_exact if mode == "exact" else self.lever_drafted


def _precision(analysis: Analysis, precision: float | None) -> float:
    if precision is None:
        precision = analysis.mech.drawing.reading_mm
    if not (math.isfinite(precision) and precision >= 0):
        raise ValueError(f"the drafting precision must be finite and >= 0 mm (got {precision!r})")
    return float(precision)  # 0: exact readings (the drafted plans are the exact ones)


def _load_rows(loads: Loads, full: Loads, k: int) -> tuple[LoadRow, ...]:
    rows = []
    for f in full.all_forces():
        mag = float(np.hypot(*f.vector[k]))
        if mag > 0:
            dropped = bool(loads.neglected[f.name][k]) if f.name in loads.neglected else False
            rows.append(LoadRow(f.name, f.link, f.kind, mag, "N", dropped))
    for m in full.all_moments():
        val = float(m.moment[k])
        if val != 0:
            dropped = bool(loads.neglected[m.name][k]) if m.name in loads.neglected else False
            rows.append(LoadRow(m.name, m.link, m.kind, val, "N·m", dropped))
    return tuple(rows)


def force_readings(analysis: Analysis, precision: float | None = 0.5) -> list[PositionForces]:
    """Build the force plans and Zhukovsky's lever of every position, exact and drafted.

    Parameters
    ----------
    analysis : Analysis
    precision : float or None
        Drafting reading precision, mm (> 0); ``None`` takes the variant's
        ``drawing.reading_mm`` (default 0.5).

    Returns
    -------
    list[PositionForces]
        In the order of ``analysis.kin``.
    """
    prec = _precision(analysis, precision)
    # solved once per project and precision (the Markdown in two languages and the CSV
    # read it thrice)
    return list(analysis.stage(("force_readings", prec), lambda: _force_readings(analysis, prec)))


def _force_readings(analysis: Analysis, prec: float) -> tuple[PositionForces, ...]:
    mech, kin = analysis.mech, analysis.kin
    sc, s2 = analysis.sheet1, analysis.sheet2
    loads, full, forces = analysis.loads, analysis.loads_full, analysis.forces
    m_full = analysis.forces_full.M_bal
    draft = Reader(prec)
    out = []
    angles = position_angles_deg(mech, kin)
    for k in range(kin.n):
        memo = analysis.force_memo  # a plan of the same inputs as sheet 2's is built once
        ex = force_plans(mech, kin, forces, loads, k, sc.kl, EXACT, s2.room_mm, memo=memo)
        dr = force_plans(mech, kin, forces, loads, k, sc.kl, draft, s2.room_mm, memo=memo)
        kv = s2.lever_kv(kin, k)
        # the lever built once at these scales (sheet 2's where its Kl is sheet 1's)
        lx = analysis.lever_at(k, sc.kl, kv, reference=ex[-1].M_bal)
        ld = analysis.lever_at(k, sc.kl, kv, prec, reference=dr[-1].M_bal)
        # the bounds of the plans built here (only the probes are built there); exact
        # readings have no reading error to bound
        cond = (force_conditioning(mech, kin, forces, loads, k, sc.kl, kv, prec, s2.room_mm,
                                   exact=ex, drawn=dr, lever_exact=lx, lever_drawn=ld,
                                   probes=analysis.probes(prec), memo=memo)
                if prec > 0 else None)
        out.append(PositionForces(kin.labels[k], float(angles[k]), k, prec,
                                  ex, dr, lx, ld, float(forces.M_bal[k]), float(m_full[k]),
                                  _load_rows(loads, full, k), loads.neglect_below,
                                  sc.kl, float(np.max(np.abs(forces.M_bal))), cond))
    return tuple(out)


__all__ = ["TINY", "LoadRow", "PositionForces", "force_readings"]
