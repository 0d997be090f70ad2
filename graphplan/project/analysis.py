"""A TMM project on one variant, solved once: :func:`solve_project` → :class:`Project`.

The stages in the textbook's order: structure, cycle and exact kinematics (solved by
:func:`solve_project`), then on first use and once per project — the loads with the
variant's neglect rule and with nothing neglected, the reactions and Mур of both, sheet 1's
scales (Kl, Kv, Ka), sheet 2's (the force plans' room, the lever's Kv) and the machine unit
of sheet 3. Every report, plan, sheet, lesson and check reads them off the project; nothing
solves a stage again. (``analyze`` and ``Analysis`` are the old names of the same.)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable
from dataclasses import dataclass, field, replace
from functools import cached_property
from typing import TYPE_CHECKING, TypeVar

from ..kinematics import Cycle, Kinematics, analyse_cycle, sweep
from ..model import Mechanism, Structure, analyse
from ..paper import Page
from ..plans import Reader, acceleration_plan, velocity_plan

if TYPE_CHECKING:
    from ..dynamics import MachineUnit
    from ..forces import Forces, Loads, MomentCurve
    from ..plans import ForcePlan, Lever, Plan
    from ..units import Scale
    from .scales import Sheet1Scales, Sheet2Scales

_T = TypeVar("_T")


@dataclass(frozen=True)
class Project:
    """One variant solved: structure, cycle, kinematics of its positions, the warnings where
    the machine is probably not the one meant (:mod:`graphplan.project.plausibility`), and
    the later stages as properties solved on first use and kept (a frozen value: a stage is
    never solved twice for one project, and never changes once solved)."""

    mech: Mechanism
    structure: Structure
    cycle: Cycle
    kin: Kinematics
    warnings: tuple[str, ...] = ()
    _stages: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    # --- the stages -------------------------------------------------------------------

    @cached_property
    def loads(self) -> Loads:
        """The applied loads at the positions, with the variant's neglect rule."""
        from ..forces import compute_loads

        return compute_loads(self.mech, self.kin, self.cycle)

    @cached_property
    def loads_full(self) -> Loads:
        """The applied loads at the positions with nothing neglected."""
        from ..forces import compute_loads

        return compute_loads(self.mech, self.kin, self.cycle, neglect_below=0.0)

    @cached_property
    def forces(self) -> Forces:
        """Reactions of every pair and Mур at the positions (of :attr:`loads`)."""
        from ..forces import solve_forces

        return solve_forces(self.mech, self.kin, self.loads)

    @cached_property
    def forces_full(self) -> Forces:
        """Reactions and Mур with nothing neglected (of :attr:`loads_full`)."""
        from ..forces import solve_forces

        return solve_forces(self.mech, self.kin, self.loads_full)

    @cached_property
    def sheet1(self) -> Sheet1Scales:
        """Sheet 1's layout and scales Kl, Kv, Ka (on the variant's page)."""
        from .scales import sheet_scales

        return sheet_scales(self.mech, self.kin, cycle=self.cycle, forces=self.forces,
                            fine=self.one_turn)

    def sheet1_on(self, page: Page) -> Sheet1Scales:
        """Sheet 1's layout and scales on another format than the variant's (solved once
        per format, like every stage)."""
        from .scales import sheet_scales

        if page.format == self._format:
            return self.sheet1
        return self.stage(("sheet1", page.format), lambda: sheet_scales(
            self.mech, self.kin, page, cycle=self.cycle, forces=self.forces, fine=self.one_turn))

    @cached_property
    def sheet2(self) -> Sheet2Scales:
        """Sheet 2's layout: the force plans' room, the lever's Kv (on the variant's page)."""
        from .scales import sheet2_scales

        return sheet2_scales(self.mech, self.kin, self.forces, self.cycle, loads=self.loads,
                             fine=self.one_turn)

    def sheet2_on(self, page: Page) -> Sheet2Scales:
        """Sheet 2's layout on another format than the variant's (solved once per format)."""
        from .scales import sheet2_scales

        if page.format == self._format:
            return self.sheet2
        return self.stage(("sheet2", page.format), lambda: sheet2_scales(
            self.mech, self.kin, self.forces, self.cycle, page, loads=self.loads,
            fine=self.one_turn))

    def solve_on(self, phi) -> Kinematics:
        """The exact kinematics at the crank angles ``phi`` (rad), solved once per grid: the
        sheets' fine turns (the trajectories and slots, the load diagrams' abscissas) ask
        for the same grids."""
        import numpy as np

        from ..kinematics import solve

        phi = np.asarray(phi, float)
        return self.stage(("solve", phi.tobytes()), lambda: solve(self.mech, phi))

    @property
    def one_turn(self) -> Kinematics:
        """The kinematics over one turn from the first position (the trajectories, the
        slots' ranges; :func:`graphplan.project.scales.one_turn`)."""
        from .scales import one_turn_grid

        return self.solve_on(one_turn_grid(self.kin))

    @property
    def _format(self) -> str:
        return self.mech.drawing.format

    # --- the plans of a position, as the sheets draw them and the lessons teach them -----

    def velocity_plan(self, k: int, precision: float = 0.0, page: Page | None = None) -> Plan:
        """Sheet 1's velocity plan of position k at sheet 1's Kl and Kv, built once: sheet 1
        draws it, the velocity lesson teaches it (``precision``: the draftsman's reading, mm;
        0 exact)."""
        sc = self.sheet1 if page is None else self.sheet1_on(page)
        return self.velocity_plan_at(k, sc.kl, sc.kv, precision)

    def velocity_plan_at(self, k: int, kl: Scale, kv: Scale, precision: float = 0.0) -> Plan:
        """The velocity plan of position k at ``kl``, ``kv``, built once per scales and
        precision: sheet 1's, and the lever's where its Kv is another (Zhukovsky's lever is
        that plan turned)."""
        plan = self.stage(("velocity_plan", k, precision, kl.per_mm, kv.per_mm),
                          lambda: velocity_plan(self.mech, self.kin, k, kl, kv, Reader(precision)))
        # the same construction under its own scale's name (the lever's Kv has its basis),
        # kept too: a stage is one value, whoever asks first
        if plan.scale == kv:
            return plan
        return self.stage(("velocity_plan as", k, precision, kl.per_mm, kv),
                          lambda: replace(plan, scale=kv))

    @property
    def force_memo(self) -> dict:
        """Every force plan built for the project, by what it is built from
        (:func:`graphplan.plans.forces.chain_plan`): sheet 2's, the tables' and the error
        bounds' probes build a plan of the same inputs once."""
        return self.stage(("force plans",), dict)

    def probes(self, precision: float) -> dict:
        """The error bounds' shifted velocity plans at ``precision`` (one reading moved),
        kept once per project: the kinematic bounds and the lever's build each once
        (:func:`graphplan.plans.kinematic_conditioning`)."""
        return self.stage(("probes", precision), dict)

    def acceleration_plan(self, k: int, precision: float = 0.0, page: Page | None = None
                          ) -> Plan:
        """Sheet 1's acceleration plan of position k (its Kl, Ka), on :meth:`velocity_plan`."""
        fmt = self._format if page is None else page.format
        sc = self.sheet1 if page is None else self.sheet1_on(page)
        return self.stage(("acceleration_plan", k, precision, fmt), lambda: acceleration_plan(
            self.mech, self.kin, k, sc.kl, sc.ka, self.velocity_plan(k, precision, page),
            Reader(precision)))

    def force_plans(self, k: int, page: Page | None = None) -> tuple[ForcePlan, ...]:
        """Sheet 2's force plans of position k, the groups from the last to the first and then
        the crank, built once, each figure at the Kl it is drawn at (a group's arms on its
        scheme, the crank's on its own: a short crank is drawn larger), each group taking the
        reactions as read off the plans drawn before it; sheet 2 draws them, the force lesson
        teaches them, the JSON reports them."""
        from ..plans import force_plans

        s2 = self.sheet2 if page is None else self.sheet2_on(page)
        kls = tuple(s2.figure_kl(i) for i in range(len(self.mech.dyads) + 1))
        fmt = self._format if page is None else page.format
        return self.stage(("force_plans", k, fmt), lambda: force_plans(
            self.mech, self.kin, self.forces, self.loads, k, kls, room_mm=s2.room_mm,
            memo=self.force_memo))

    def lever(self, k: int, page: Page | None = None) -> Lever:
        """Sheet 2's Zhukovsky lever of position k (its Kl, the lever's Kv), built once and
        compared with the force plans' Mур."""
        s2 = self.sheet2 if page is None else self.sheet2_on(page)
        kl = s2.kl
        assert kl is not None  # sheet2_scales sets it
        fmt = self._format if page is None else page.format
        kv = s2.lever_kv(self.kin, k)
        return self.stage(("lever", k, fmt), lambda: self.lever_at(
            k, kl, kv, reference=float(self.forces.M_bal[k])))

    def lever_at(self, k: int, kl: Scale, kv: Scale, precision: float = 0.0,
                 reference: float | None = None) -> Lever:
        """Zhukovsky's lever of position k at ``kl``, ``kv`` read at ``precision``, built once
        (its velocity plan turned: :meth:`velocity_plan_at`), with its discrepancy against
        ``reference`` (the force plans' Mур that the sheet or the table compares it with)."""
        from ..plans import discrepancy_pct, zhukovsky_lever

        lever = self.stage(("lever", k, kl.per_mm, kv.per_mm, precision), lambda: zhukovsky_lever(
            self.mech, self.kin, self.loads, k, kl, kv, Reader(precision),
            plan=self.velocity_plan_at(k, kl, kv, precision)))
        if reference is None:
            return lever
        return replace(lever, reference=reference,
                       discrepancy_pct=discrepancy_pct(reference, lever.M_bal))

    @cached_property
    def curve(self) -> MomentCurve:
        """Mур(φ) over one turn, exact on a fine grid, every load (sheet 2): the variant's
        neglect rule belongs to the force plans of the positions; on the curve it made false
        steps where it switched a load off."""
        from ..forces import moment_curve

        return moment_curve(self.mech, self.kin, self.cycle, neglect_below=0.0)

    @cached_property
    def unit(self) -> MachineUnit | None:
        """The machine unit of sheet 3 (flywheel, motor, simulation), when the variant gives
        ``dynamics.delta``; else None. Its scales (Kφ, KM, H, KA, KT, KJ) are those of sheet 3
        on the variant's ``drawing.format``."""
        from ..dynamics import DynamicsSettings

        if DynamicsSettings.of(self.mech).delta is None:
            return None
        return self.unit_on(Page(self.mech.drawing.format))

    def unit_on(self, page: Page) -> MachineUnit:
        """The machine unit with its diagrams sized for sheet 3 on ``page`` (solved once per
        format)."""
        from ..dynamics import DiagramSize, machine_unit

        f = page.frame
        return self.stage(("unit", page.format), lambda: machine_unit(
            self, diagrams=DiagramSize.for_frame(f.width, f.height)))

    def stage(self, key: Hashable, solve: Callable[[], _T]) -> _T:
        """A stage of a higher layer (a report's readings at a precision) solved once per
        project: ``solve()`` the first time ``key`` is asked for, the kept value after."""
        if key not in self._stages:
            self._stages[key] = solve()
        return self._stages[key]

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
        sc, note = _report_scales(self)
        kl, kv, ka = sc.kl, sc.kv, sc.ka
        mechanism["scales"] = {s.symbol: {"value": s.per_mm, "unit": s.unit, "basis": s.basis}
                               for s in (kl, kv, ka)}
        if note:
            mechanism["scales_note"] = note
        for k, entry in enumerate(positions):
            if sc is self.sheet1:  # sheet 1's own plans, built once (the sheet draws them)
                vp, ap = self.velocity_plan(k), self.acceleration_plan(k)
            else:
                vp = velocity_plan(m, self.kin, k, kl, kv)
                ap = acceleration_plan(m, self.kin, k, kl, ka, vp)
            segments = {r.name: r.mm for r in vp.readings.values()}
            segments.update({r.name: r.mm for r in ap.readings.values()})
            entry["plans"] = {"Kl": kl.per_mm, "Kv": kv.per_mm, "Ka": ka.per_mm,
                              "segments_mm": segments, **_marks(vp, ap)}
        self._add_forces(positions)
        out = {"mechanism": mechanism, "positions": positions, "warnings": list(self.warnings)}
        from ..dynamics import DynamicsSettings

        if DynamicsSettings.of(self.mech).delta is not None:
            from ..dynamics import machine_unit

            out["dynamics"] = (unit or self.unit or machine_unit(self)).to_json()
        return out

    def _add_forces(self, positions: list[dict]) -> None:
        """Per position: the exact kinetostatics (``forces``) with the variant's rules,
        ``M_bal_full``, the balancing moment with nothing neglected (N·m, CCW+), and the force
        plans and Zhukovsky's lever as sheet 2 draws them (each figure at its own Kl)."""
        forces, full, s2 = self.forces, self.forces_full, self.sheet2
        kls = [s2.figure_kl(i) for i in range(len(self.mech.dyads) + 1)]
        lever_kl = s2.kl
        assert lever_kl is not None  # sheet2_scales sets it
        for k, entry in enumerate(positions):
            f = forces.as_json(k)
            del f["label"], f["phi_deg"]
            entry["forces"] = f
            entry["M_bal_full"] = float(full.M_bal[k])
            entry["force_plans"] = [
                {"group": fp.group, "Kp": fp.scale.per_mm, "basis": fp.scale.basis,
                 "Kl": kl.per_mm,
                 "segments_mm": {r.name: r.mm for r in fp.readings.values()},
                 "values": {q: r.value for q, r in fp.readings.items()},
                 "equations": list(fp.equations),
                 "M_bal": fp.M_bal, **_marks(fp)}
                for fp, kl in zip(self.force_plans(k), kls, strict=True)]
            lever = self.lever(k)
            entry["zhukovsky"] = {"M_bal": lever.M_bal, "discrepancy_pct": lever.discrepancy_pct,
                                  "Kv": lever.plan.scale.per_mm, "Kl": lever_kl.per_mm,
                                  "arms_mm": {r.name: r.mm for r in lever.readings.values()},
                                  **_marks(lever)}


def _report_scales(project: Project):
    """The scales of the report: sheet 1's, or — when sheet 1 cannot hold the plans of
    every position (48 positions and more) — those of a sheet drawing an even sample of
    them, so that the JSON never depends on a sheet's layout. Returns (scales, note)."""
    from ..errors import LayoutError
    from .scales import sheet_scales  # the sheet's layout: shapely, only when reporting

    m, kin = project.mech, project.kin
    try:
        return project.sheet1, ""
    except LayoutError as exc:
        first = str(exc)
    for size in (8, 1):
        step = max(1, kin.n // size)
        sample = list(dict.fromkeys(kin.labels[k] for k in range(0, kin.n, step)))[:size]
        mm = m.with_drawing(positions=tuple(sample))
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


def solve_project(mech: Mechanism) -> Project:
    """Solve a loaded variant: structure, cycle and kinematics now, the later stages of the
    :class:`Project` on first use, each once.

    Raises
    ------
    StructureError, AssemblyError, SingularPoseError, InputError
    """
    from .plausibility import machine_warnings

    structure = analyse(mech)
    cycle = analyse_cycle(mech)
    kin = sweep(mech, cycle)  # the solver guarantees finite values (SingularPoseError otherwise)
    return Project(mech, structure, cycle, kin, machine_warnings(mech, cycle))


Analysis = Project
"""The old name of :class:`Project`."""
analyze = solve_project
"""The old name of :func:`solve_project`."""
