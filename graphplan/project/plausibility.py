"""Warnings where the machine is probably not the one meant (the variant is valid, but odd).

Each warning is one line that names the key to look at and the likely fix:

* **K < 1** — the working stroke is the *faster* one, while a working stroke (cutting,
  pressing) is the slow one of a quick-return mechanism: usually ``output.working`` or
  ``crank.direction`` is the other way round. Checked when the variant's loads act on the
  working stroke only (or it has none); an engine, a compressor or a pump loads both
  strokes and K means nothing there. A K within 1 % of 1 (a symmetric mechanism drawn
  with round-off) is not reported.
* **The output against its working direction** — a load the variant gives with its own
  sign (``sense = "diagram"``: a force along ``angle`` or along its slider's guide, a
  couple CCW positive) on the working stroke only is the technological resistance: it
  must do negative work there. When it does positive work over the cycle (its work is
  integrated over a fine grid of the exact kinematics), the output moves in the working
  stroke against the direction the load opposes: the branch of a dyad, ``output.working``
  or ``crank.direction`` is the other way round from the machine meant. The warning names
  the changes that remove it, each tried on the variant (re-assembled and re-integrated),
  or the load's own sign when none does.
* **The piston against its working direction** — an indicator diagram (a gas force,
  ``bore``) counts s from ВМТ, the dead centre *farthest* from the crank (the cylinder's
  head is beyond the piston). When the assembly branch and the working sense put s = 0 at
  the dead centre *nearest* the crank, the gas would push the piston toward the crank's
  side and the piston moves against the stated working direction: the branch of its dyad
  or its ``working`` is the other way round from the machine meant; the fixes named are
  those that, tried on the variant, put ВМТ at the far dead centre.

* **A position twice** — an extra position (``positions.extra``) at the crank angle of
  another position (a dead centre that falls on the grid, given as ``from = "end"``): the
  sheets would draw, tabulate and analyse the same position under two labels.

(A crank that cannot make a full turn stops the analysis: :func:`graphplan.kinematics.cycle.
analyse_cycle` says so with the range of angles it reaches.)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from dataclasses import replace
from functools import partial

import numpy as np

from ..errors import GraphplanError
from ..forces import ForceLoad, point_velocity, resistance_loads, stroke_index
from ..kinematics import (
    Cycle,
    analyse_cycle,
    cycle_angle_deg,
    in_working_stroke,
    link_coordinate,
    solve,
    solve_positions,
)
from ..model import Mechanism, Resistance

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


def _variants(mech: Mechanism, n: int) -> Iterator[tuple[str, Mechanism]]:
    """The variant with one setting turned the other way, named as the variant writes it:
    the working sense of load ``n``'s travel (``output.working`` or ``loads[n].working``),
    each dyad's ``branch``, ``crank.direction``."""
    res = mech.resistances[n]
    w = res.working or mech.output.working
    sign = "-" if w > 0 else "+"
    if res.working and (res.travel_link or mech.output.link) != mech.output.link:
        loads = list(mech.resistances)
        loads[n] = replace(res, working=-res.working)
        yield f'loads[{n}].working = "{sign}"', replace(mech, resistances=tuple(loads))
    else:
        loads = [replace(r, working=-r.working) if r.working and (
            r.travel_link or mech.output.link) == mech.output.link else r
            for r in mech.resistances]
        yield (f'output.working = "{sign}"',
               replace(mech, output=replace(mech.output, working=-mech.output.working),
                       resistances=tuple(loads)))
    for k, d in enumerate(mech.dyads):
        if d.kind in ("RRR", "RRP"):  # the kinds whose two assemblies the branch chooses
            dyads = list(mech.dyads)
            dyads[k] = replace(d, branch=-d.branch)
            yield (f'dyads[{k}].branch = "{"+" if d.branch < 0 else "-"}"',
                   replace(mech, dyads=tuple(dyads)))
    other = "ccw" if mech.crank.sense < 0 else "cw"
    yield (f'crank.direction = "{other}"',
           replace(mech, crank=replace(mech.crank, omega=-mech.crank.omega)))


def _fixes(mech: Mechanism, n: int, wrong: Callable[[Mechanism, Cycle], bool]) -> list[str]:
    """The one-setting changes (:func:`_variants`) after which the variant assembles over
    the whole turn and load ``n`` is no longer ``wrong``."""
    out = []
    for name, other in _variants(mech, n):
        try:
            if not wrong(other, analyse_cycle(other)):
                out.append(name)
        except GraphplanError:  # that assembly fails somewhere in the turn: not a fix
            continue
    return out


def _head_at_the_crank(mech: Mechanism, cycle: Cycle, n: int) -> bool:
    """Gas force ``n``'s ВМТ (s = 0) is the dead centre where its piston is nearest the
    crank's pivot (the cylinder's head would be at the crank)."""
    res = mech.resistances[n]
    pivot = np.asarray(mech.frame_points[mech.crank.pivot], float)
    tl = res.travel_link or mech.output.link
    lt = cycle.travels.get((tl, res.working or mech.output.working))
    if lt is None or len(lt.dead_centres) < 2:
        return False
    pos = solve_positions(mech, np.asarray(lt.dead_centres))
    joint = link_coordinate(mech, tl, pos)[3]
    d0, d1 = np.hypot(*(pos.points[joint] - pivot).T)
    return bool(d0 < d1 - 1e-9 * mech.crank.length)


def _cylinder_head_warnings(mech: Mechanism, cycle: Cycle):
    """A gas force (``bore``) whose diagram starts (s = 0, ВМТ) at the dead centre where the
    piston is *nearest* the crank: the piston moves against the stated working direction —
    the head of the cylinder would be at the crank."""
    for n, res in enumerate(mech.resistances):
        if not res.gas or res.over != "stroke" or not _head_at_the_crank(mech, cycle, n):
            continue
        tl = res.travel_link or mech.output.link
        fix = " / ".join(_fixes(mech, n, partial(_head_at_the_crank, n=n)))
        yield (f"{mech.source}: loads[{n}]: the indicator diagram starts (s = 0, ВМТ) "
               f"where piston {tl} is nearest the crank, so the gas would push it toward "
               f"the crank's side and it moves against the stated working direction; "
               f"likely fix: {fix}" if fix else
               f"{mech.source}: loads[{n}]: the indicator diagram starts (s = 0, ВМТ) "
               f"where piston {tl} is nearest the crank, so the gas would push it toward "
               f"the crank's side and it moves against the stated working direction; "
               f"count s from the dead centre farthest from the crank")


WORK_GRID = 720
"""Intervals per turn of the crank over which a load's work is integrated (its sign only)."""
WORK_MARGIN = 1e-6
"""Positive work above this fraction of ∫|P|dt is reported (round-off is not)."""


def _meant_to_resist(res: Resistance) -> bool:
    """A load with its own sign on its travel's working strokes only: the technological
    resistance, given as a signed diagram or a force along ``angle``."""
    if res.sense != "diagram" or res.gas or res.over != "stroke":
        return False
    return _working_strokes_only(res)


def load_work(mech: Mechanism, cycle: Cycle, n: int, solve_on=None) -> tuple[float, float]:
    """Work of load ``n`` over the cycle and ``∫|P|dt`` (J), by the trapezoid rule on
    :data:`WORK_GRID` intervals a turn of the exact kinematics: ``P = F·v`` of its point or
    ``M·ω`` of its link, ``dt = dτ/|ω1|``. ``solve_on(phi)``: the project's kinematics of a
    grid (:meth:`graphplan.project.Project.solve_on`: one solve for every load), solved here
    by default."""
    res = mech.resistances[n]
    m = round(cycle.period / (2 * math.pi)) * WORK_GRID
    tau = np.linspace(0.0, cycle.period, m + 1)
    phi = cycle.origin + mech.crank.sense * tau
    kin = solve(mech, phi) if solve_on is None else solve_on(phi)
    load = resistance_loads(mech, kin, cycle)[n]
    if isinstance(load, ForceLoad):
        power = np.einsum("ij,ij->i", load.vector, point_velocity(mech, kin, res.link, load.at))
    else:
        power = load.moment * kin.vel.omega[res.link]
    w1 = abs(mech.crank.omega)
    dt = np.diff(tau) / w1
    return (float(np.sum(0.5 * (power[1:] + power[:-1]) * dt)),
            float(np.sum(0.5 * (np.abs(power[1:]) + np.abs(power[:-1])) * dt)))


def load_drives(mech: Mechanism, cycle: Cycle, n: int, solve_on=None) -> bool:
    """Whether load ``n`` is a driving force (or moment) of the machine: it does positive
    work over the cycle, ``A = ∫ P dt > 0`` (:func:`load_work`) — the gas force of an
    engine, which resists on the compression stroke and drives on the expansion stroke,
    drives; a compressor's or a pump's resists (``solve_on``: as in :func:`load_work`)."""
    work, scale = load_work(mech, cycle, n, solve_on)
    return work > WORK_MARGIN * scale


def _drives_in_the_working_stroke(mech: Mechanism, cycle: Cycle, n: int) -> bool:
    work, scale = load_work(mech, cycle, n)
    return work > WORK_MARGIN * scale


def _driving_resistance_warnings(mech: Mechanism, cycle: Cycle):
    """A signed load on the working stroke (:func:`_meant_to_resist`) that does positive
    work over it: the output moves in the working stroke the way the load pushes it."""
    for n, res in enumerate(mech.resistances):
        if not _meant_to_resist(res):
            continue
        work, scale = load_work(mech, cycle, n)
        if work <= WORK_MARGIN * scale:
            continue
        fix = " / ".join(_fixes(mech, n, partial(_drives_in_the_working_stroke, n=n)))
        label = res.name or ("Q" if res.kind == "force" else "Mс")
        yield (f"{mech.source}: loads[{n}] ({label}): given on the working stroke, it does "
               f"positive work over it ({work:+.4g} J a cycle), so the output moves the way "
               f"the load pushes, against the working direction; likely fix: {fix}" if fix else
               f"{mech.source}: loads[{n}] ({label}): given on the working stroke, it does "
               f"positive work over it ({work:+.4g} J a cycle), so the output moves the way "
               f"the load pushes, against the working direction; likely fix: the sign of its "
               f"diagram or its angle (sense = \"resists\" always opposes the motion)")


def _in_step(mech: Mechanism, cycle: Cycle, n: int) -> float:
    """The share of load ``n``'s loaded strokes that falls in the output's working
    strokes (1: in step with them, 0: on the output's idle strokes only)."""
    res = mech.resistances[n]
    tau = np.linspace(0.0, cycle.period, round(cycle.period / (2 * math.pi)) * WORK_GRID,
                      endpoint=False)
    diags = res.stroke_diagrams(round(cycle.period / math.pi))
    k = stroke_index(res, mech, cycle, tau)
    on = np.array([diags[i] is not None for i in k])
    if not on.any():
        return 1.0
    working = in_working_stroke(mech, cycle, cycle.origin + mech.crank.sense * tau)
    return float(np.mean(working[on]))


def _out_of_step_warnings(mech: Mechanism, cycle: Cycle):
    """A load on the working strokes of a link other than the output (its x runs with
    ``loads[n].working``, by default the output's sense) that comes while the output makes
    its idle stroke: that link's "working" sense is probably the other one."""
    if not cycle.dead_centres:
        return
    for n, res in enumerate(mech.resistances):
        tl = res.travel_link or mech.output.link
        if (res.over != "stroke" or res.gas or tl == mech.output.link
                or not _working_strokes_only(res)):
            continue
        share = _in_step(mech, cycle, n)
        if share >= 0.5:
            continue
        w = res.working or mech.output.working
        loads = list(mech.resistances)
        loads[n] = replace(res, working=-w)
        other = replace(mech, resistances=tuple(loads))
        try:
            better = _in_step(other, analyse_cycle(other), n) > share
        except GraphplanError:
            better = False
        label = res.name or ("Q" if res.kind == "force" else "Mс")
        sign, flip = ("+" if w > 0 else "-"), ("-" if w > 0 else "+")
        yield (f"{mech.source}: loads[{n}] ({label}): given on the working stroke of link "
               f"{tl}, whose x runs with working = \"{sign}\", it comes while the output "
               f"makes its idle stroke ({share * 100:.0f} % of it in the working stroke); "
               f"likely fix: loads[{n}].working = \"{flip}\"" if better else
               f"{mech.source}: loads[{n}] ({label}): given on the working stroke of link "
               f"{tl}, whose x runs with working = \"{sign}\", it comes while the output "
               f"makes its idle stroke ({share * 100:.0f} % of it in the working stroke); "
               f"likely fix: travel_link = the output, or stroke = \"idle\"")


def _working_strokes_only(res: Resistance) -> bool:
    diags = res.stroke_diagrams(len(res.strokes) or 2)
    return any(d is not None for d in diags[0::2]) and all(d is None for d in diags[1::2])


def _twin_position_warnings(mech: Mechanism, cycle: Cycle):
    """An extra position at the crank angle of another one (to 1e-6 rad)."""
    period = mech.positions.period
    extra = {e.label: i for i, e in enumerate(mech.positions.extra)}
    tau = np.mod(np.asarray(cycle.phi, float) - float(cycle.phi[0]), period)
    order = np.argsort(tau, kind="stable")
    for a, b in zip(order, np.roll(order, -1), strict=True):
        gap = float(np.mod(tau[b] - tau[a], period))
        if a == b or min(gap, period - gap) > 1e-6:
            continue
        lab, oth = cycle.labels[b], cycle.labels[a]
        if lab not in extra:
            lab, oth = oth, lab
        if lab not in extra:
            continue
        angle = cycle_angle_deg(float(cycle.phi[b]), float(cycle.phi[0]), mech.crank.sense, period)
        yield (f"{mech.source}: positions.extra[{extra[lab]}] ('{lab}'): φ = "
               f"{angle:.2f}°, the crank angle of "
               f"position '{oth}': the sheets would draw the same position twice; likely "
               f"fix: leave '{lab}' out (an extra position is needed only off the grid)")


def machine_warnings(mech: Mechanism, cycle: Cycle) -> tuple[str, ...]:
    """The warnings of the module docstring, one line each (empty when all looks meant)."""
    out: list[str] = list(_cylinder_head_warnings(mech, cycle))
    out += _twin_position_warnings(mech, cycle)
    out += _driving_resistance_warnings(mech, cycle)
    out += _out_of_step_warnings(mech, cycle)
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


__all__ = ["K_MARGIN", "WORK_GRID", "WORK_MARGIN", "load_work", "machine_warnings"]
