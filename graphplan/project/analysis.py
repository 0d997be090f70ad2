"""The first stages of a TMM project on one variant: structure, cycle, exact kinematics.

:func:`analyze` runs them in order and returns one frozen :class:`Analysis`,
the input of every report, plan and sheet.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..kinematics import Cycle, Kinematics, analyse_cycle, sweep
from ..model import Mechanism, Structure, analyse
from ..plans import acceleration_plan, velocity_plan


@dataclass(frozen=True, slots=True)
class Analysis:
    """Structure, cycle and kinematics of a variant's positions, and the warnings where the
    machine is probably not the one meant (:mod:`graphplan.project.plausibility`)."""

    mech: Mechanism
    structure: Structure
    cycle: Cycle
    kin: Kinematics
    warnings: tuple[str, ...] = ()

    def _repr_html_(self) -> str:
        """Jupyter: the tables of ``graphplan analyze`` (structure, cycle, kinematics)."""
        import html

        from ..reports import analysis_text

        return f"<pre>{html.escape(analysis_text(self, 'en'))}</pre>"

    def to_json(self, unit=None) -> dict:
        """The JSON report of ``graphplan analyze --json``.

        Keys are a promise to users' scripts: SI units, angles in degrees,
        angular quantities counter-clockwise positive, the variant's own frame; in
        ``"dynamics"`` (when the variant gives ``dynamics.delta``) moments are positive in
        the crank's sense of rotation (:mod:`graphplan.dynamics.reduction`). ``unit``: the
        :class:`~graphplan.dynamics.machine.MachineUnit` when the caller has it already.
        """
        m, st, cy = self.mech, self.structure, self.cycle
        moving = m.moving_links
        links = {ln: list(m.points_of(ln)) for ln in (m.frame_link, *moving)}
        mechanism = {
            "name": m.name,
            "source": m.source,
            "mobility": st.mobility,
            "mobility_equation": st.mobility_equation,
            "formula": st.formula,
            "pairs": [{"kind": p.kind, "links": list(p.links), "joint": p.joint} for p in st.pairs],
            "groups": [
                {
                    "kind": g.kind,
                    "links": list(g.links),
                    "class": g.group_class,
                    "order": g.order,
                    "kind_number": g.kind_number,
                }
                for g in st.groups
            ],
            "links": links,
            "frame_link": m.frame_link,
            "crank": {"link": m.crank.link, "rpm": m.crank.rpm, "omega": m.crank.omega,
                      "length_m": m.crank.length},
            "output": {"link": m.output.link, "kind": cy.output_kind,
                       "working": "+" if m.output.working > 0 else "-"},
            "stroke_m": cy.stroke,
            "swing_deg": math.degrees(cy.swing),
            "dead_centres_deg": [math.degrees(a) for a in cy.dead_centres],
            "working_stroke_deg": math.degrees(cy.working_turn),
            "time_ratio": cy.time_ratio,
            "cycle_deg": math.degrees(cy.period),
            "min_conditioning": {
                name: {"sine": s, "phi_deg": math.degrees(a) % 360.0}
                for name, (s, a) in cy.min_conditioning.items()
            },
        }
        positions = [self.kin.as_json(k, moving) for k in range(self.kin.n)]
        from ..forces import cycle_travel  # the process's phase: φ repeats in a 720° cycle

        for entry, t in zip(positions, cycle_travel(m, cy, self.kin.phi), strict=True):
            entry["cycle_phase_deg"] = math.degrees(float(t))
        from .scales import sheet_scales  # the sheet's layout: shapely, only when reporting

        sc, note = _report_scales(m, self.kin, sheet_scales)
        kl, kv, ka = sc.kl, sc.kv, sc.ka
        mechanism["scales"] = {s.symbol: {"value": s.per_mm, "unit": s.unit, "basis": s.basis}
                               for s in (kl, kv, ka)}
        if note:
            mechanism["scales_note"] = note
        for k, entry in enumerate(positions):
            vp = velocity_plan(m, self.kin, k, kl, kv)
            ap = acceleration_plan(m, self.kin, k, kl, ka, vp)
            segments = {r.name: r.mm for r in vp.readings.values()}
            segments.update({r.name: r.mm for r in ap.readings.values()})
            entry["plans"] = {"Kl": kl.per_mm, "Kv": kv.per_mm, "Ka": ka.per_mm,
                              "segments_mm": segments, **_marks(vp, ap)}
        self._add_forces(positions, sc)
        out = {"mechanism": mechanism, "positions": positions, "warnings": list(self.warnings)}
        if "delta" in self.mech.settings.get("dynamics", {}):
            from ..dynamics import machine_unit

            out["dynamics"] = (unit or machine_unit(self)).to_json()
        return out

    def _add_forces(self, positions: list[dict], sc) -> None:
        """Per position: the exact kinetostatics (``forces``) with the variant's rules, and
        ``M_bal_full``, the balancing moment with nothing neglected (N·m, CCW+)."""
        from ..forces import compute_loads, solve_forces

        loads = compute_loads(self.mech, self.kin, self.cycle)
        forces = solve_forces(self.mech, self.kin, loads)
        full = solve_forces(self.mech, self.kin,
                            compute_loads(self.mech, self.kin, self.cycle, neglect_below=0.0))
        from ..plans import force_plans, zhukovsky_lever
        from .scales import sheet2_scales

        s2 = sheet2_scales(self.mech, self.kin, forces, self.cycle)

        for k, entry in enumerate(positions):
            f = forces.as_json(k)
            del f["label"], f["phi_deg"]
            entry["forces"] = f
            entry["M_bal_full"] = float(full.M_bal[k])
            entry["force_plans"] = [
                {"group": fp.group, "Kp": fp.scale.per_mm, "basis": fp.scale.basis,
                 "segments_mm": {r.name: r.mm for r in fp.readings.values()},
                 "values": {q: r.value for q, r in fp.readings.items()},
                 "equations": list(fp.equations),
                 "M_bal": fp.M_bal, **_marks(fp)}
                for fp in force_plans(self.mech, self.kin, forces, loads, k, sc.kl,
                                      room_mm=s2.room_mm)]
            lever = zhukovsky_lever(self.mech, self.kin, loads, k, sc.kl, s2.lever_kv(self.kin, k),
                                    reference=float(forces.M_bal[k]))
            entry["zhukovsky"] = {"M_bal": lever.M_bal, "discrepancy_pct": lever.discrepancy_pct,
                                  "Kv": lever.plan.scale.per_mm,
                                  "arms_mm": {r.name: r.mm for r in lever.readings.values()},
                                  **_marks(lever)}


def _report_scales(m, kin, sheet_scales):
    """The scales of the report: sheet 1's, or — when sheet 1 cannot hold the plans of
    every position (48 positions and more) — those of a sheet drawing an even sample of
    them, so that the JSON never depends on a sheet's layout. Returns (scales, note)."""
    from dataclasses import replace

    from ..errors import LayoutError

    try:
        return sheet_scales(m, kin), ""
    except LayoutError as exc:
        first = str(exc)
    drawing = m.settings.get("drawing", {})
    for size in (8, 1):
        step = max(1, kin.n // size)
        sample = list(dict.fromkeys(kin.labels[k] for k in range(0, kin.n, step)))[:size]
        mm = replace(m, settings={**m.settings, "drawing": {**drawing, "positions": sample}})
        try:
            sc = sheet_scales(mm, kin)
        except LayoutError:
            continue
        return sc, (f"sheet 1 cannot hold the plans of all {kin.n} positions ({first}); the "
                    f"scales are those of a sheet drawing positions {', '.join(sample)}")
    raise LayoutError(first)


def _marks(*plans) -> dict:
    """How well the plans are drawn: every intersection's angle (deg) and uncertainty (mm,
    at the draftsman's 0.5 mm), and the mark of the ill-conditioned ones ("" when none)."""
    from ..plans import intersections, note

    return {"intersections": [{"plan": x.plan, "step": x.step, "equation": x.equation,
                               "angle_deg": x.angle_deg, "error_mm": x.error_mm, "ill": x.ill}
                              for p in plans for x in intersections(p)],
            "ill_conditioned": note(plans)}


def analyze(mech: Mechanism) -> Analysis:
    """Run structure, cycle and kinematics on a loaded variant.

    Raises
    ------
    StructureError, AssemblyError, SingularPoseError, InputError
    """
    from .plausibility import machine_warnings

    structure = analyse(mech)
    cycle = analyse_cycle(mech)
    kin = sweep(mech, cycle)  # the solver guarantees finite values (SingularPoseError otherwise)
    return Analysis(mech, structure, cycle, kin, machine_warnings(mech, cycle))
