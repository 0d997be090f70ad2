"""Warnings where the machine is probably not the one meant (the variant is valid, but odd).

Each warning is one line that names the key to look at and the likely fix:

* **K < 1** — the working stroke is the *faster* one, while a working stroke (cutting,
  pressing) is the slow one of a quick-return mechanism: usually ``output.working`` or
  ``crank.direction`` is the other way round. Checked when the variant's loads act on the
  working stroke only (or it has none); an engine, a compressor or a pump loads both
  strokes and K means nothing there. A K within 1 % of 1 (a symmetric mechanism drawn
  with round-off) is not reported.
* **The piston against its working direction** — an indicator diagram (a gas force,
  ``bore``) counts s from ВМТ, the dead centre *farthest* from the crank (the cylinder's
  head is beyond the piston). When the assembly branch and the working sense put s = 0 at
  the dead centre *nearest* the crank, the gas would push the piston toward the crank's
  side and the piston moves against the stated working direction: the branch of its dyad
  or its ``working`` is the other way round from the machine meant.

(A crank that cannot make a full turn stops the analysis: :func:`graphplan.kinematics.cycle.
analyse_cycle` says so with the range of angles it reaches.)
"""

from __future__ import annotations

import math

import numpy as np

from ..kinematics import Cycle, link_coordinate, solve_positions
from ..model import Mechanism

K_MARGIN = 0.01
"""K below 1 − K_MARGIN is reported (0.998 of a nearly symmetric six-bar is not)."""


def _working_only(mech: Mechanism) -> bool:
    """The loads act on the output's working strokes only (or there are none)."""
    if not mech.resistances:
        return True
    for res in mech.resistances:
        if res.over != "stroke" or (res.travel_link or mech.output.link) != mech.output.link:
            continue
        diags = res.stroke_diagrams(round(mech.positions.period / math.pi))
        if any(d is not None for d in diags[1::2]):
            return False
        if res.sense == "resists":
            return True
    return False


def _cylinder_heads(mech: Mechanism, cycle: Cycle):
    """A gas force (``bore``) whose diagram starts (s = 0, ВМТ) at the dead centre where the
    piston is *nearest* the crank: the piston moves against the stated working direction —
    the head of the cylinder would be at the crank."""
    pivot = np.asarray(mech.frame_points[mech.crank.pivot], float)
    for n, res in enumerate(mech.resistances):
        if not res.gas or res.over != "stroke":
            continue
        tl = res.travel_link or mech.output.link
        lt = cycle.travels[(tl, res.working or mech.output.working)]
        pos = solve_positions(mech, np.asarray(lt.dead_centres))
        joint = link_coordinate(mech, tl, pos)[3]
        d0, d1 = np.hypot(*(pos.points[joint] - pivot).T)
        if d0 < d1 - 1e-9 * mech.crank.length:
            key = "output.working" if tl == mech.output.link else f"loads[{n}].working"
            w = res.working or mech.output.working
            other = "-" if w > 0 else "+"
            dyad = next((k for k, d in enumerate(mech.dyads) if tl in d.links), 0)
            yield (f"{mech.source}: loads[{n}]: the indicator diagram starts (s = 0, ВМТ) "
                   f"where piston {tl} is nearest the crank, so the gas would push it toward "
                   f"the crank's side and it moves against the stated working direction; "
                   f"likely fix: {key} = \"{other}\" (s from the dead centre farthest from "
                   f"the crank) or the other dyads[{dyad}].branch")


def machine_warnings(mech: Mechanism, cycle: Cycle) -> tuple[str, ...]:
    """The warnings of the module docstring, one line each (empty when all looks meant)."""
    out: list[str] = list(_cylinder_heads(mech, cycle))
    K = cycle.time_ratio
    if not (cycle.dead_centres and K < 1.0 - K_MARGIN and _working_only(mech)):
        return tuple(out)
    other = "+" if mech.output.working < 0 else "-"
    turn = math.degrees(cycle.working_turn)
    out.append(f"{mech.source}: output.working: K = {K:.3f} < 1 — the working stroke "
               f"({turn:.1f}° of crank) is the faster one, while a working stroke is usually "
               f"the slow one; likely fix: output.working = \"{other}\" (or the other "
               f"crank.direction), which gives K = {1.0 / K:.3f}")
    return tuple(out)


__all__ = ["K_MARGIN", "machine_warnings"]
