"""Warnings where the machine is probably not the one meant (the variant is valid, but odd).

Each warning is one line that names the key to look at and the likely fix:

* **K < 1** — the working stroke is the *faster* one, while a working stroke (cutting,
  pressing) is the slow one of a quick-return mechanism: usually ``output.working`` or
  ``crank.direction`` is the other way round. Checked when the variant's loads act on the
  working stroke only (or it has none); an engine, a compressor or a pump loads both
  strokes and K means nothing there. A K within 1 % of 1 (a symmetric mechanism drawn
  with round-off) is not reported.
* **The assembly branch** — when flipping one dyad's ``branch`` turns the fast working
  stroke into the slow one, that dyad is assembled the other way round from the machine
  meant: the output moves against the stated working direction on its slow stroke.

(A crank that cannot make a full turn stops the analysis: :func:`graphplan.kinematics.cycle.
analyse_cycle` says so with the range of angles it reaches.)
"""

from __future__ import annotations

import math
from dataclasses import replace

from ..errors import GraphplanError
from ..kinematics import Cycle, analyse_cycle
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
        diags = res.stroke_diagrams(int(round(mech.positions.period / math.pi)))
        if any(d is not None for d in diags[1::2]):
            return False
        if res.sense == "resists":
            return True
    return False


def _time_ratio(mech: Mechanism) -> float | None:
    try:
        return analyse_cycle(mech).time_ratio
    except GraphplanError:
        return None


def machine_warnings(mech: Mechanism, cycle: Cycle) -> tuple[str, ...]:
    """The warnings of the module docstring, one line each (empty when all looks meant)."""
    out: list[str] = []
    K = cycle.time_ratio
    if not (cycle.dead_centres and K < 1.0 - K_MARGIN and _working_only(mech)):
        return ()
    other = "+" if mech.output.working < 0 else "-"
    turn = math.degrees(cycle.working_turn)
    out.append(f"{mech.source}: output.working: K = {K:.3f} < 1 — the working stroke "
               f"({turn:.1f}° of crank) is the faster one, while a working stroke is usually "
               f"the slow one; likely fix: output.working = \"{other}\" (or the other "
               f"crank.direction), which gives K = {1.0 / K:.3f}")
    for n, d in enumerate(mech.dyads):
        if d.kind not in ("RRR", "RRP", "RPR"):
            continue
        flipped = replace(mech, dyads=tuple(replace(x, branch=-x.branch) if k == n else x
                                            for k, x in enumerate(mech.dyads)))
        K2 = _time_ratio(flipped)
        if K2 is not None and K2 > 1.0 + K_MARGIN:
            now = "+" if d.branch > 0 else "-"
            new = "-" if d.branch > 0 else "+"
            out.append(f"{mech.source}: dyads[{n}].branch: the assembly \"{now}\" of "
                       f"{d.name} makes the output move against output.working on its slow "
                       f"stroke; likely fix: branch = \"{new}\", which gives K = {K2:.3f}")
    return tuple(out)


__all__ = ["K_MARGIN", "machine_warnings"]
