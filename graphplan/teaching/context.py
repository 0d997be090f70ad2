"""What every lesson of a variant shares: the scales of sheets 1 and 2, the loads and
the exact kinetostatics (computed once per analysis and kept for the next lessons)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Context:
    """Sheet 1's scales (Kl, Kv, Ka), sheet 2's (the force plans' room, the lever's Kv),
    the loads and the exact reactions, as the sheets use them."""

    sheet1: object
    loads: object
    forces: object
    sheet2: object


_KEEP = 8
_CACHE: dict[int, tuple[object, Context]] = {}


def context(analysis) -> Context:
    """The context of ``analysis`` (the same object for the same analysis)."""
    hit = _CACHE.get(id(analysis))
    if hit is not None and hit[0] is analysis:
        return hit[1]
    from ..forces import compute_loads, solve_forces
    from ..project import sheet2_scales, sheet_scales

    mech, kin = analysis.mech, analysis.kin
    loads = compute_loads(mech, kin, analysis.cycle)
    forces = solve_forces(mech, kin, loads)
    ctx = Context(sheet_scales(mech, kin), loads, forces,
                  sheet2_scales(mech, kin, forces, analysis.cycle))
    while len(_CACHE) >= _KEEP:
        _CACHE.pop(next(iter(_CACHE)))
    _CACHE[id(analysis)] = (analysis, ctx)
    return ctx
