"""The scales of the sheets. Sheet 1: Kl so the plan of positions fits its column, Kv
and Ka so every plan fits its cell of the grid (see :mod:`graphplan.project.layout`). Sheet 2:
the positions it analyses, the room of its force plans (which fixes each Kp) and the Kv
of Zhukovsky's lever.

:func:`sheet_scales` and :func:`sheet2_scales` decide them; the JSON report, the tables
and the sheets all use them, so a segment in the tables is the segment on the sheet.
A scale fixed in the variant's ``[drawing]`` section is used as given.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError, LayoutError
from ..kinematics import in_working_stroke
from ..model import Mechanism
from ..numbers import fmt
from ..paper import GRAPH26_SIZE, Page
from ..plans import plan_name
from ..units import PLAN_SERIES, Scale, fit_scale, nice_ceil
from .equations import EQ_PITCH, equations_height, moment_lines
from .layout import (
    CAPTION,
    GAP,
    LABEL_ROOM,
    VECTOR_HARD,
    VECTOR_MAX,
    Rect,
    Sheet1Layout,
    Sheet2Layout,
    cell_room,
    diagram_min,
    sheet1_layout,
    sheet2_layout,
    sheet2_loads_table,
    sheet2_table_header,
    split_table_height,
)

PLAN_MARGIN = 14.0  #: room around the plan of positions for symbols and letters, mm
SLACK = 8.0  #: of a cell's margins a plan may take when that spares it the coarser scale, mm
READ_MIN = 53.0  #: a plan's longest vector, arrowhead included, is read at least this long
#: (its shaft 50 mm, the method's least main vector), mm
READ_MEDIAN = 50.0  #: the plans' longest vectors have at least this median (the method: 50–100)
LONGEST_READ = 40.0  #: a plan whose longest vector the cells keep shorter is not read: fewer
#: positions' plans are drawn, larger (the norm's least longest vector), mm
SLOT_OVER = 11.0  #: a slot runs this far past its block's centre at the ends of its travel, mm
TRAJECTORY_POINTS = 360
SHEET2_MAX_ROWS = 3  #: positions analysed in full on sheet 2


@dataclass(frozen=True, slots=True)
class Sheet1Scales:
    """Kl, Kv, Ka of sheet 1, the layout they were chosen for and the plan's extent."""

    kl: Scale
    kv: Scale
    ka: Scale
    layout: Sheet1Layout
    extent_m: tuple[float, float, float, float]  # xmin, ymin, xmax, ymax of the positions, m
    plans: tuple[int, ...] = ()  # positions whose plans are drawn, in cell order
    paths: dict[str, np.ndarray] | None = None  # the trajectories the extent was taken from
    slots: dict[str, tuple[float, float]] | None = None  # see :func:`slot_ranges`
    acc_plans: tuple[int, ...] = ()  # positions whose acceleration plans are drawn
    #: the first of them, the analysed positions: each with the scheme of its ω and ε (the
    #: others are further plans the grid had room for, :func:`_more_acceleration_plans`)
    analysed: tuple[int, ...] = ()


def slot_ranges(mech: Mechanism, fine) -> dict[str, tuple[float, float]]:
    """How far each slide on a moving link (a slot of a rocker or a yoke) reaches, m.

    For every guide ``slider/carrier`` carried by a moving link: the least and the greatest
    coordinate, along the guide from its base point, of the slider's point on the guide
    over one turn (``fine``: the kinematics of :func:`one_turn`). The slot is fixed on its
    link, so drawn over this range in every position it is the same slot, long enough for
    the block everywhere.
    """
    out: dict[str, tuple[float, float]] = {}
    for key, (G, u) in fine.pos.guides.items():
        slider, carrier = key.split("/")
        if carrier == mech.frame_link:
            continue
        G, u = np.asarray(G, float), np.asarray(u, float)
        n = np.stack([-u[:, 1], u[:, 0]], axis=1)
        best = None
        for p in mech.points_of(slider):
            if p not in fine.pos.points:
                continue
            r = fine.pos.points[p] - G
            off = float(np.median(np.abs(np.einsum("ij,ij->i", r, n))))
            if best is None or off < best[0]:
                best = (off, np.einsum("ij,ij->i", r, u))
        if best is not None:
            out[key] = (float(best[1].min()), float(best[1].max()))
    return out


def one_turn(mech: Mechanism, kin):
    """The kinematics over one turn from the first position, TRAJECTORY_POINTS steps."""
    from ..kinematics import solve

    return solve(mech, one_turn_grid(kin))


def one_turn_grid(kin) -> np.ndarray:
    """The crank angles of :func:`one_turn` (rad)."""
    return kin.phi[0] + np.linspace(0.0, 2 * math.pi, TRAJECTORY_POINTS + 1)


def trajectories(mech: Mechanism, kin, fine=None) -> dict[str, np.ndarray]:
    """Paths of the centres of mass and of every joint over one turn (m), closed."""
    fine = one_turn(mech, kin) if fine is None else fine
    return {name: p for name, p in fine.pos.points.items()}


def position_extent(mech: Mechanism, kin, paths: dict[str, np.ndarray]
                    ) -> tuple[float, float, float, float]:
    """Bounding box (m) of everything the plan of positions draws, about the crank pivot."""
    o = kin.pos.points[mech.crank.pivot][0]
    pts = [p for p in paths.values()] + [p for p in kin.pos.points.values()]
    allp = np.concatenate(pts) - o
    (x0, y0), (x1, y1) = allp.min(axis=0), allp.max(axis=0)
    return float(x0), float(y0), float(x1), float(y1)


def positions_by_label(mech: Mechanism, kin, section: str, key: str = "positions"
                       ) -> tuple[int, ...] | None:
    """Indices of the positions a section's ``positions`` (or ``key``) names (None if none)."""
    wanted = getattr({"drawing": mech.drawing, "kinetostatics": mech.kinetostatics}[section], key)
    if wanted is None:
        return None
    for lab in wanted:
        if lab not in kin.labels:
            raise InputError(f"{mech.source}: {section}.{key}: expected a position label "
                             f"({', '.join(kin.labels)}), got {lab!r}")
    return tuple(kin.labels.index(lab) for lab in wanted)


def plan_positions(mech: Mechanism, kin) -> tuple[int, ...]:
    """Indices of the positions whose plans sheet 1 draws (``drawing.positions``, or every
    position of :func:`distinct_positions`)."""
    which = positions_by_label(mech, kin, "drawing")
    return distinct_positions(kin) if which is None else which


def distinct_positions(kin) -> tuple[int, ...]:
    """The positions whose kinematics no earlier position repeats: all of a one-turn cycle;
    the first turn of a four-stroke cycle (720°), whose positions 12 … 23 stand where 0 … 11
    stand, with the same velocities and accelerations (the crank turns at constant ω1)."""
    kept: list[int] = []
    for k in range(kin.n):
        if kinematic_twin(kin, k, kept) is None:
            kept.append(k)
    return tuple(kept)


def kinematic_twin(kin, k: int, among) -> int | None:
    """The first of the positions ``among`` (other than ``k``) where the crank stands as in
    position ``k`` (the same angle of O→A: the other turn of a 720° cycle), or None."""
    turn = 2.0 * math.pi
    phi = float(kin.phi[k])
    return next((j for j in among if j != k
                 and abs((phi - float(kin.phi[j]) + math.pi) % turn - math.pi) < 1e-9), None)


def _plan_shapes(mech, kin, kl: Scale, which: tuple[int, ...], acc: tuple[int, ...],
                 memo: dict | None = None):
    """Width and height of the velocity plan of each of ``which`` and of the acceleration
    plan of each of ``acc`` (in that order), and the longest vector of each of them, all
    per mm of the plan's defining vector (pa, πa). ``memo`` keeps each position's trial
    plans' measures across the calls of one choice of scales (one Kl): each trial plan is
    built once."""
    from ..plans import acceleration_plan, velocity_plan

    cr = mech.crank
    va, aa = abs(cr.omega) * cr.length, cr.omega**2 * cr.length
    trial_v = Scale("Kv", va / 50.0, "(m/s)/mm")
    trial_a = Scale("Ka", max(aa, 1e-12) / 50.0, "(m/s²)/mm")
    v_shapes: dict[int, tuple[float, float]] = {}
    a_shapes: dict[int, tuple[float, float]] = {}
    v_long: dict[int, float] = {}
    a_long: dict[int, float] = {}
    memo = {} if memo is None else memo
    for k in sorted(set(which) | set(acc)):
        if ("v", k) not in memo:
            vp = memo["plan", k] = velocity_plan(mech, kin, k, kl, trial_v)
            w, h = _ptp(vp)
            memo["v", k] = ((w / 50, h / 50), _longest(vp) / 50)
        if k in acc and ("a", k) not in memo:
            ap = acceleration_plan(mech, kin, k, kl, trial_a, memo["plan", k])
            w, h = _ptp(ap)
            memo["a", k] = ((w / 50, h / 50), _longest(ap) / 50)
        if k in which:
            v_shapes[k], v_long[k] = memo["v", k]
        if k in acc:
            a_shapes[k], a_long[k] = memo["a", k]
    return (tuple(v_shapes[k] for k in which), tuple(a_shapes[k] for k in acc),
            tuple(v_long[k] for k in which), tuple(a_long[k] for k in acc))


def _ptp(plan) -> tuple[float, float]:
    pts = np.array(list(plan.points.values()))
    w, h = np.ptp(pts, axis=0)
    return float(w), float(h)


def _longest(plan) -> float:
    return max((r.exact_mm for r in plan.readings.values()), default=0.0)


def acceleration_positions(mech: Mechanism, kin, cycle=None, forces=None) -> tuple[int, ...]:
    """Positions whose acceleration plans sheet 1 draws, large, as students draw them.

    ``drawing.accelerations`` (labels) when the variant gives it; else the positions of
    the force analysis (``kinetostatics.positions``, or by default the working position(s)
    and one idle position, :func:`default_positions`): the plans sheet 2 is built on. Where
    the force analysis is of one position, a second plan beside it: the default's position
    of the other stroke (working or idle), as students draw at least two.
    ``cycle`` and ``forces`` are the project's (solved here when not given).
    """
    which = positions_by_label(mech, kin, "drawing", "accelerations")
    if which is not None:
        return which
    given = positions_by_label(mech, kin, "kinetostatics")
    if given is not None and len(given) >= 2:
        return given
    from ..forces import compute_loads, solve_forces
    from ..kinematics import analyse_cycle

    cycle = analyse_cycle(mech) if cycle is None else cycle
    if forces is None:
        forces = solve_forces(mech, kin, compute_loads(mech, kin, cycle))
    default = default_positions(mech, kin, forces, cycle)
    if given is None:
        return default
    # one position of the force analysis: the plan of a position of the other stroke
    # (the default's of the largest |Mур| there) beside it, as students draw two
    working = in_working_stroke(mech, cycle, kin.phi)
    other = [k for k in default if k not in given and working[k] != working[given[0]]]
    if not other:  # the default's are of the same stroke: the other's largest |Mур|
        dead = {ex.label for ex in mech.positions.extra
                if ex.from_dead_centre is not None and ex.turn == 0.0}
        m = np.abs(forces.M_bal)
        other = sorted((k for k in range(kin.n) if working[k] != working[given[0]]
                        and kin.labels[k] not in dead), key=lambda k: -m[k])
    rest = other or [k for k in default if k not in given]
    return (*given, *rest[:1])


def sheet_scales(mech: Mechanism, kin, page: Page | None = None, *, cycle=None,
                 forces=None, fine=None) -> Sheet1Scales:
    """Choose Kl, Kv, Ka for sheet 1: Kl from the usual series (1, 2, 2.5, 4, 5 × 10^k),
    Kv and Ka from :data:`graphplan.units.PLAN_SERIES`.

    Kl: the plan of positions (all positions, the trajectories, the slots) fits the left
    column, at most 42 % of the frame's width and the height left above the diagrams.
    Kv, Ka: the layout (:func:`graphplan.project.layout.sheet1_layout`) shares the place
    between the velocity plans of the drawn positions and the acceleration plans of
    :func:`acceleration_positions` so that both are as large as they can be; then the
    largest plan of each kind fits its cell, construction lines included, and no vector is
    longer than VECTOR_MAX. ``cycle`` and ``forces``: the project's, for the positions of
    the force analysis (solved here when not given); ``fine``: its :func:`one_turn`.
    """
    page = page or Page(mech.drawing.format)
    return _sheet_scales(mech, kin, page, cycle, forces, fine)


def _sheet_scales(mech: Mechanism, kin, page: Page, cycle=None, forces=None,
                  fine=None) -> Sheet1Scales:
    fixed = mech.drawing
    fine = one_turn(mech, kin) if fine is None else fine
    paths = trajectories(mech, kin, fine)
    slots = slot_ranges(mech, fine)
    f = page.frame
    room_w = 0.42 * f.width - 2 * PLAN_MARGIN
    room_h = f.height - GRAPH26_SIZE[1] - 8.0 - GAP - diagram_min(page)[1] - 2 * PLAN_MARGIN
    cr = mech.crank
    kl_m = 0.0  # the slots run SLOT_OVER mm past their blocks' travel: at the scale found
    for _ in range(3):
        ends = {f"slot {key} {i}": fine.pos.guides[key][0] + t * fine.pos.guides[key][1]
                for key, (t0, t1) in slots.items()
                for i, t in enumerate((t0 - SLOT_OVER * kl_m, t1 + SLOT_OVER * kl_m))}
        ext = position_extent(mech, kin, {**paths, **ends})
        need = max((ext[2] - ext[0]) / room_w, (ext[3] - ext[1]) / room_h)
        kl = fit_scale("Kl", "m/mm", need, 1.0, quantity=f"l{cr.pivot}{cr.pin}",
                       defining=cr.length, segment=f"{cr.pivot}{cr.pin}", fixed=fixed.Kl)
        if kl.per_mm == kl_m:
            break
        kl_m = kl.per_mm
    acc = acceleration_positions(mech, kin, cycle, forces)
    shapes: dict = {}  # the trial plans' measures at this Kl (_plan_shapes)

    def at(acc: tuple[int, ...], n_schemes: int | None = None
           ) -> tuple[Sheet1Scales, list[float]]:
        """The scales and layout with the acceleration plans of ``acc`` (the first
        ``n_schemes`` with the scheme of their ω and ε, all by default), and the longest
        vector of every plan drawn, mm."""
        # an acceleration plan is built on its position's velocity plan: that one is drawn too
        plan_w = (ext[2] - ext[0]) / kl.per_mm + 2 * PLAN_MARGIN
        plan_h = (ext[3] - ext[1]) / kl.per_mm + 2 * PLAN_MARGIN
        # the velocity plans of every position; on a smaller format, as many as fit: every
        # second position, then the acceleration plans' positions only (of drawing.positions,
        # when the variant gives it: on its own format it is drawn as given)
        given = positions_by_label(mech, kin, "drawing")
        every = distinct_positions(kin) if given is None else given
        tries = [every, every[::2], ()]
        scheme_aspect = _scheme_aspect(mech, kin, acc)
        extent = _scheme_extent(kin, acc[:n_schemes] if n_schemes is not None else acc)
        for n_try, chosen in enumerate(tries):
            # an acceleration plan's velocity plan is drawn, once: a position of the second
            # turn of a 720° cycle is built on its twin's of the first turn
            which = tuple(sorted(set(chosen) | {k for k in acc
                                                if kinematic_twin(kin, k, chosen) is None}))
            v_shapes, a_shapes, v_long, a_long = _plan_shapes(mech, kin, kl, which, acc,
                                                               shapes)
            longest = (max(v_long, default=1.0), max(a_long, default=1.0))
            try:
                layout = sheet1_layout(page, plan_w, plan_h, kin.n, v_shapes, a_shapes, longest,
                                       len(mech.dyads), scheme_aspect, 1.0 + len(mech.dyads),
                                       n_schemes=n_schemes, scheme_extent=extent)
                # plans too small to read: fewer of them, larger
                if layout.plan_size * max(longest) >= LONGEST_READ or n_try == len(tries) - 1:
                    break
            except LayoutError:
                if n_try == len(tries) - 1:
                    raise
        va = abs(cr.omega) * cr.length
        aa = cr.omega**2 * cr.length

        def fit(cells, shapes, longs, defining) -> float:
            """Units per mm: of the series values whose plans all fit their cells (the room
            kept for letters and construction lines may be eaten by SLACK) with no vector over
            VECTOR_HARD, the one that draws the most plans with their longest vector READ_MIN
            to VECTOR_MAX mm long; of equals, the one whose plans are nearest those marks."""
            rooms = [cell_room(c) for c in cells]
            loose = min([min((iw + SLACK) / max(sw, 1e-9), (ih + SLACK) / max(sh, 1e-9))
                         for (iw, ih), (sw, sh) in zip(rooms, shapes, strict=True)]
                        + [VECTOR_HARD / max(max(longs), 1e-9)])
            d = max(defining, 1e-12)
            e0 = math.floor(math.log10(d / max(loose, 1e-9)))
            values = sorted(float(f"{m * 10.0**e:.12g}") for e in (e0 - 1, e0, e0 + 1)
                            for m in PLAN_SERIES)
            fitting = [u for u in values if d / u <= loose] or [values[-1]]

            def score(u):
                mm = [lg * d / u for lg in longs]
                good = sum(READ_MIN <= x <= VECTOR_MAX for x in mm)
                miss = sum(max(READ_MIN - x, 0.0) + max(x - VECTOR_MAX, 0.0) for x in mm)
                return good, -miss

            return max(fitting, key=score)

        kv = fit_scale("Kv", "(m/s)/mm", fit(layout.v_cells, v_shapes, v_long, va), 1.0,
                       quantity=f"v{cr.pin}", defining=va,
                       segment="p" + plan_name(mech, cr.pin, "p"), fixed=fixed.Kv,
                       series=PLAN_SERIES)
        ka_fit = fit(layout.a_cells, a_shapes, a_long, aa) if a_shapes else \
            nice_ceil(aa / 50.0, PLAN_SERIES)
        ka = fit_scale("Ka", "(m/s²)/mm", ka_fit, 1.0,
                       quantity=f"a{cr.pin}", defining=aa,
                       segment="π" + plan_name(mech, cr.pin, "π"), fixed=fixed.Ka,
                       series=PLAN_SERIES)
        # the cells cut again round the plans at the scales chosen: the place they leave to
        # the diagrams and the schemes
        sizes = (va / kv.per_mm, aa / ka.per_mm if a_shapes else 0.0)
        layout = sheet1_layout(page, plan_w, plan_h, kin.n, v_shapes, a_shapes, longest,
                               len(mech.dyads), scheme_aspect, 1.0 + len(mech.dyads), sizes,
                               n_schemes, extent)
        drawn = ([lg * sizes[0] for lg in v_long] + [lg * sizes[1] for lg in a_long])
        return Sheet1Scales(kl, kv, ka, layout, ext, which, paths, slots, acc,
                            acc[:n_schemes] if n_schemes is not None else acc), drawn

    sc, drawn = at(acc)
    given = positions_by_label(mech, kin, "kinetostatics")
    if given is not None and len(acc) > len(given) and not (
            min(drawn) >= LONGEST_READ and float(np.median(drawn)) >= READ_MEDIAN):
        # the second acceleration plan (acceleration_positions) makes the plans too small to
        # read: the force analysis's position alone
        sc, _ = at(given)
    if positions_by_label(mech, kin, "drawing", "accelerations") is None:
        sc = _more_acceleration_plans(kin, sc, at)
    return sc


def _room(layout: Sheet1Layout) -> tuple[float, float, float]:
    """The area of the kinematic diagrams' box, the smallest side of the schemes' cells
    (mm², mm) and the rows of plans, negated: what a further plan must not take from them
    (it goes into a row's room, not a row of its own)."""
    cells = [*layout.schemes, *([layout.groups] if layout.groups else [])]
    rows = len({round(c.y0, 3) for c in layout.cells})
    return (layout.diagrams.width * layout.diagrams.height,
            min((min(c.width, c.height) for c in cells), default=0.0), -float(rows))


ACC_PLANS_MAX = 4  #: acceleration plans sheet 1 draws at most by default (the method: of 1–3
#: positions, or of all), the analysed positions' first


def _more_acceleration_plans(kin, sc: Sheet1Scales, at) -> Sheet1Scales:
    """``sc`` with the acceleration plans of further positions (up to ACC_PLANS_MAX in all)
    where the grid holds them at the same Kv and Ka: each the position farthest round the
    cycle from those drawn whose plan is read (its longest vector READ_MIN mm or more),
    without a scheme of its own (the analysed positions keep theirs). ``at``: the scales
    and layout for a tuple of positions (:func:`_sheet_scales`)."""
    n_schemes = len(sc.acc_plans)
    turn = 2.0 * math.pi
    while len(sc.acc_plans) < ACC_PLANS_MAX:
        def apart(k: int, drawn: tuple[int, ...] = sc.acc_plans) -> float:
            return min(abs((float(kin.phi[k]) - float(kin.phi[j]) + math.pi) % turn - math.pi)
                       for j in drawn)

        candidates = sorted((k for k in distinct_positions(kin) if k not in sc.acc_plans
                             and kinematic_twin(kin, k, sc.acc_plans) is None),
                            key=lambda k: (-round(apart(k), 6), k))
        for k in candidates:
            try:
                more, drawn = at((*sc.acc_plans, k), n_schemes)
            except LayoutError:
                return sc
            if ((more.kv.per_mm, more.ka.per_mm) != (sc.kv.per_mm, sc.ka.per_mm)
                    or any(a < b - 1e-6 for a, b in zip(_room(more.layout), _room(sc.layout),
                                                       strict=True))):
                return sc  # the plans drawn, the diagrams or the schemes would shrink
            if drawn[-1] >= READ_MIN:
                sc = more
                break
        else:
            return sc
    return sc


def _scheme_extent(kin, acc: tuple[int, ...]) -> tuple[float, float] | None:
    """Width and height (m) of the mechanism's points in the analysed positions, the most
    of them: what the schemes of ω and ε draw."""
    if not acc:
        return None
    sizes = [np.ptp(np.array([p[k] for p in kin.pos.points.values()]), axis=0) for k in acc]
    return float(max(s[0] for s in sizes)), float(max(s[1] for s in sizes))


def _scheme_aspect(mech: Mechanism, kin, acc: tuple[int, ...]) -> float:
    """Width over height of the mechanism in the analysed positions (its joints and frame
    points, with room for the arrows of ω and ε): the shape of their schemes' cells."""
    if not acc:
        return 1.0
    pts = np.concatenate([np.array([p[k] for p in kin.pos.points.values()]) for k in acc])
    w, h = np.ptp(pts, axis=0)
    span = max(float(w), float(h), 1e-12)
    return float(np.clip((w + 0.25 * span) / (h + 0.25 * span), 0.6, 6.0))


def default_positions(mech, kin, forces, cycle) -> tuple[int, ...]:
    """The working positions and the idle position of the largest |Mур| (module docstring)."""
    at_dead_centre = {ex.label for ex in mech.positions.extra
                      if ex.from_dead_centre is not None and ex.turn == 0.0}
    working = in_working_stroke(mech, cycle, kin.phi)
    extra = {ex.label for ex in mech.positions.extra} - at_dead_centre
    chosen = [k for k, lab in enumerate(kin.labels) if lab in extra][:SHEET2_MAX_ROWS - 1]
    m = np.abs(forces.M_bal)
    idle = [k for k in range(len(kin.phi)) if not working[k] and k not in chosen
            and kin.labels[k] not in at_dead_centre]
    if not chosen:
        chosen = [int(np.argmax(m))]
        idle = [k for k in idle if k != chosen[0]]
    if idle:
        chosen.append(max(idle, key=lambda k: m[k]))
    return tuple(chosen)


def sheet2_positions(mech, kin, forces, cycle) -> tuple[int, ...]:
    """Indices of the positions sheet 2 analyses in full (see the module docstring)."""
    which = positions_by_label(mech, kin, "kinetostatics")
    if which is None:
        which = default_positions(mech, kin, forces, cycle)
    if len(which) > SHEET2_MAX_ROWS:
        raise LayoutError(f"{mech.source}: sheet 2 draws at most {SHEET2_MAX_ROWS} positions "
                          f"in full (got {len(which)}): choose them in kinetostatics.positions")
    return which


@dataclass(frozen=True, slots=True)
class Sheet2Scales:
    """What sheet 2 is drawn at: its positions (as many of the wanted ones as its page
    holds), its cells, the room of a force plan (each Kp is the series value that fits the
    plan into it), Kl of the groups drawn separately and of the crank, the lever's cell."""

    positions: tuple[int, ...]
    cells: tuple[tuple[Rect, ...], ...]
    room_mm: float | tuple[float, ...]  #: of each force plan, in their order
    kl: Scale | None = None  #: of the groups
    kl_crank: Scale | None = None  #: of the crank (its own: a short crank is drawn larger)
    layout: Sheet2Layout | None = None
    slots: dict[str, tuple[float, float]] | None = None
    wanted: tuple[int, ...] = ()
    kls: tuple[Scale, ...] = ()  #: Kl of each figure: the groups, then the crank
    kl_mechanism: Scale | None = None  #: of the mechanism in the analysed position (cells[0])
    loads_table: bool = False  #: the table of the links' loads under the table of sheet 2

    def lever_kv(self, kin, k: int) -> Scale:
        """Kv of Zhukovsky's lever at position k: the turned velocity plan fills its cell
        (any Kv gives the same Mур; the arms in mm are read at this one)."""
        row = self.positions.index(k) if k in self.positions else 0
        cell = self.cells[row][-1]
        v = np.array([np.zeros(2)] + [p[k] for p in kin.vel.points.values()])
        w, h = (float(x) for x in np.ptp(v, axis=0))
        # the loads are drawn up to FORCE_ARROW_MM (30 mm) from their points; the plan is
        # turned by 90°: its width is the cell's height
        tall = max(cell.height - CAPTION - LEVER_PAD, 0.25 * (cell.height - CAPTION))
        wide = max(cell.width - LEVER_PAD, 0.25 * cell.width)
        room = min(tall / max(w, 1e-12), wide / max(h, 1e-12)) * max(w, h, 1e-12)
        room = min(room, LEVER_CAP)
        return Scale("Kv", nice_ceil(max(w, h, 1e-12) / room, PLAN_SERIES), "(m/s)/mm")

    @property
    def first(self) -> int:
        """Index of the first group's cell in a row: 1 after the mechanism's cell, else 0."""
        return 1 if self.layout is None or self.layout.mechanism else 0

    def figure_kl(self, i: int) -> Scale:
        """Kl of the i-th figure (the groups from the last attached, then the crank)."""
        if self.kls and i < len(self.kls):
            return self.kls[i]
        assert self.kl is not None and self.kl_crank is not None
        return self.kl_crank if i == (len(self.cells[0]) - 1 - self.first) // 2 - 1 else self.kl


LEVER_PAD = 60.0  #: kept around Zhukovsky's lever in its cell for the loads' arrows, mm
LEVER_CAP = 110.0  #: the longest side of the lever's turned velocity plan at most, mm
PLAN_CAP = 110.0  #: a force plan's extent at most (its longest vector within 100 mm), mm
GROUP_CAP = 160.0  #: the longest side of a group drawn separately at most, mm
CRANK_CAP = 140.0  #: the longest side of the crank drawn separately at most, mm
A1_FRAME_H = 584.0  #: height of A1's frame, mm (the formats below it leave the loads' table out)
LOADS_GAP = 6.0  #: between sheet 2's table of the force analysis and that of the loads, mm
LOADS_KEEP = 0.9  #: the loads' table is drawn while the force plans keep this share of their room
PLAN_CELL_W = 90.0  #: least width of a force plan's cell (its letters crowd a thin plan), mm


FORCE_TABLE_W = 48.0  #: width kept in a force plan's cell for the table of its forces, mm
GROUP_ROOM = 18.0  #: kept on each side of a group drawn on sheet 2 for its loads' arrows, mm
GROUP_EQ_ROOM = 9.0  #: kept under a group for its moment equations (two lines), mm


def group_links(mech: Mechanism) -> list[tuple[str, ...]]:
    """The links of each figure sheet 2 draws separately, in the order of the force plans:
    the Assur groups from the last attached to the first, then the crank."""
    return [tuple(mech.dyads[i].links) for i in reversed(range(len(mech.dyads)))] + [
        (mech.crank.link,)]


def _points_of(mech, kin, links, k):
    return np.array([kin.pos.points[p][k] for ln in links for p in mech.points_of(ln)
                     if p in kin.pos.points])


def _group_kl(mech: Mechanism, kin, positions, rows, fig: int, first: int = 1,
              eqs=None) -> Scale:
    """Kl of figure ``fig`` (a group drawn separately, or the crank): the usual series
    value (1, 2, 2.5, 4, 5 × 10^k) at which it fits its cell, with its arrows and
    equations, in every position (``eqs``: per position, the figures' moment equations
    in each language, :func:`trial_plans`: every line of them under the figure)."""
    need = 0.0
    links = group_links(mech)[fig]
    for k, cells in zip(positions, rows, strict=False):
        cell = cells[first + 2 * fig]
        pts = _points_of(mech, kin, links, k)
        if len(pts) < 2:
            continue
        w, h = np.ptp(pts, axis=0)
        under = (min(max(GROUP_EQ_ROOM, equations_height(eqs[k][fig], cell.width)),
                     EQ_SHARE * cell.height) if eqs else GROUP_EQ_ROOM)
        rw = max(cell.width - 2 * GROUP_ROOM, 10.0)
        rh = max(cell.height - CAPTION - 2 * GROUP_ROOM - under, 10.0)
        need = max(need, float(w) / rw, float(h) / rh)
    return Scale("Kl", nice_ceil(max(need, 1e-6)), "m/mm")


def mechanism_points(mech: Mechanism, kin, k: int, slots=None) -> np.ndarray:
    """The points of the whole mechanism at position k: every moving link's, the frame's and
    the ends of the slots on moving links (``slots``: :func:`slot_ranges`)."""
    ends = []
    for key, (lo, hi) in (slots or {}).items():
        G, u = kin.pos.guides[key]
        ends += [np.asarray(G[k], float) + t * np.asarray(u[k], float) for t in (lo, hi)]
    return np.array([*_points_of(mech, kin, mech.moving_links, k),
                     *(np.asarray(v, float) for v in mech.frame_points.values()), *ends])


def path_sides(mech: Mechanism, kin, k: int) -> list[tuple[int, np.ndarray]]:
    """The variant's loads that sheet 2 draws as a diagram beside their slider's path: per
    force on a slider moving along a frame guide, its index among ``mech.resistances`` and
    the unit vector (model, y up) from the path to the side the diagram stands on (away
    from the crank's pivot)."""
    out = []
    o = np.asarray(kin.pos.points[mech.crank.pivot][k], float)
    for i, res in enumerate(mech.resistances):
        if res.kind != "force":
            continue
        for key, (G, u) in kin.pos.guides.items():
            slider, carrier = key.split("/")
            if slider == res.link and carrier == mech.frame_link:
                n = np.array([-u[k][1], u[k][0]], float)
                out.append((i, n if float(np.dot(np.asarray(G[k], float) - o, n)) >= 0 else -n))
                break
    return out


MECHANISM_CAP = 200.0  #: the longest side of the mechanism in the analysed position at most, mm
PATH_DIAGRAM = 42.0  #: room beside the slider's path for the diagram of its force, mm


def _mechanism_pad(mech: Mechanism, kin, k: int) -> tuple[float, float]:
    """Room (width, height) a cell keeps round the mechanism in position k: its loads'
    arrows and letters, and beside the slider's path the diagram of the force on it."""
    pw, ph = 2 * GROUP_ROOM, CAPTION + 2 * GROUP_ROOM
    sides = [side for _, side in path_sides(mech, kin, k)]
    if sides:
        pw += PATH_DIAGRAM * max(abs(float(side[0])) for side in sides)
        ph += PATH_DIAGRAM * max(abs(float(side[1])) for side in sides)
    return pw, ph


def _mechanism_kl(mech: Mechanism, kin, positions, rows, slots=None) -> Scale:
    """Kl of the mechanism drawn in the analysed positions (cells[0]): the usual series
    value at which it fits its cell with its loads in every position."""
    need = 0.0
    for k, cells in zip(positions, rows, strict=False):
        w, h = np.ptp(mechanism_points(mech, kin, k, slots), axis=0)
        pw, ph = _mechanism_pad(mech, kin, k)
        need = max(need, float(w) / max(cells[0].width - pw, 10.0),
                   float(h) / max(cells[0].height - ph, 10.0))
    return Scale("Kl", nice_ceil(max(need, 1e-6)), "m/mm")


#: a group's cell is at least as wide as its moment equations take this many lines in (two
#: equations of three lines and a continued one), but no wider than this (A1, mm): a wider
#: cell would narrow its neighbours; longer equations take more lines
EQ_CELL = (7, 90.0)
SCHEME_ROW = 120.0  #: a usual row of sheet 2's figures on A1, mm
EQ_SHARE = 0.35  #: the equations take at most this share of a figure's cell height (A3's)


def equations_cell(eqs, least: float, widest: float, lines: int = 7) -> tuple[float, float]:
    """The least width of the cell of a figure with the moment equations ``eqs`` (per
    language) — the narrowest in which they take at most ``lines`` lines, ``least`` at
    least, ``widest`` at most — and the height they take in it, mm."""
    w = least
    while w < widest and equations_height(eqs, w) > EQ_PITCH * lines + 2.0:
        w += 4.0
    w = min(w, widest)
    return w, max(GROUP_EQ_ROOM, equations_height(eqs, w))


def figure_shapes(mech: Mechanism, kin, units, k: int, page: Page, slots=None, eqs=None,
                  eq_cell: tuple[int, float] = EQ_CELL):
    """The :class:`FigureShape` of each figure sheet 2 draws for position k, in the order
    of its cells: the mechanism in the position with its loads, then per group (from the
    last attached) its scheme and its force plan, the crank and its plan, Zhukovsky's
    lever. Shapes from the kinematics (the schemes, the lever's velocity plan) and from the
    force plans' ``units`` (:func:`trial_plans`)."""
    from .layout import FigureShape

    s = min(1.0, page.frame.height / 584.0)
    least = max(45.0, 60.0 * s)

    def aspect(w: float, h: float) -> float:
        return float(np.clip(w / max(h, 1e-12), 0.08, 8.0)) if max(w, h) > 0 else 1.0

    mw, mh = (float(x) for x in np.ptp(mechanism_points(mech, kin, k, slots), axis=0))
    out = [FigureShape(aspect(mw, mh), MECHANISM_CAP * s, *_mechanism_pad(mech, kin, k),
                       max(least, 90.0 * s))]
    # the letters at the sides (the table of the plan's forces where the cell has room)
    pad_p = (2 * LABEL_ROOM + 16.0, CAPTION + 2 * LABEL_ROOM + 9.0)
    for n, (links, (uw, uh)) in enumerate(zip(group_links(mech), units, strict=True)):
        w, h = (float(x) for x in np.ptp(_points_of(mech, kin, links, k), axis=0))
        crank = n == len(units) - 1
        # the cell wide enough for the moment equations in a few lines, and tall enough
        # for every one of them under the figure
        wide, under = equations_cell(eqs[n], least, eq_cell[1] * s, eq_cell[0]) if eqs else (
            least, GROUP_EQ_ROOM)
        under = min(under, EQ_SHARE * SCHEME_ROW * s)
        out.append(FigureShape(aspect(w, h), (CRANK_CAP if crank else GROUP_CAP) * s,
                               2 * GROUP_ROOM, CAPTION + 2 * GROUP_ROOM + under, wide))
        # the plan's extent is PLAN_CAP at most: its longest side that share of it
        out.append(FigureShape(aspect(uw, uh), PLAN_CAP * s * max(uw, uh), *pad_p,
                               max(least, PLAN_CELL_W * s)))
    v = np.array([np.zeros(2)] + [p[k] for p in kin.vel.points.values()])
    vw, vh = (float(x) for x in np.ptp(v, axis=0))
    # its loads' arrows are FORCE_ARROW_MM long on any format: the cell keeps room for them
    out.append(FigureShape(aspect(vh, vw), LEVER_CAP * s, LEVER_PAD, CAPTION + LEVER_PAD,
                           max(least, LEVER_PAD + 40.0)))
    return out


def trial_plans(mech: Mechanism, kin, forces, loads, k: int, kl: Scale
                ) -> tuple[list[tuple[float, float]], list[tuple[list[str], list[str]]]]:
    """The force plans of position k at a trial ``kl``: the width and height of each per mm
    of its extent, and each figure's moment equations (Russian, English) as the sheet
    writes them under it."""
    from ..plans import force_plans

    units, eqs = [], []
    for fp in force_plans(mech, kin, forces, loads, k, kl, room_mm=100.0):
        pts = np.array(list(fp.points.values()))
        ext = max(fp.extent_mm, 1e-9)
        pw, ph = (float(x) for x in np.ptp(pts, axis=0))
        units.append((pw / ext, ph / ext))
        eqs.append((moment_lines(fp, "ru"), moment_lines(fp, "en")))
    return units, eqs


#: the mechanism's cell is kept while the force plans keep this share of their room
MECHANISM_KEEP = 0.8


def _plans_room(lay, shapes, units, wanted, mechanism: bool) -> float:
    """The smallest room (mm of extent, PLAN_CAP at most) a force plan of ``lay`` gets in
    any position."""
    o = 1 if mechanism else 0
    room = PLAN_CAP * min(1.0, lay.page.frame.height / 584.0)
    for k, cells, sh in zip(wanted, lay.rows, shapes, strict=False):
        for i, (uw, uh) in enumerate(units[k]):
            cell, fs = cells[2 * i + 1 + o], sh[2 * i + 2]
            room = min(room, (cell.width - fs.pad_w) / max(uw, 1e-9),
                       (cell.height - fs.pad_h) / max(uh, 1e-9))
    return room


def sheet2_scales(mech: Mechanism, kin, forces, cycle, page: Page | None = None,
                  loads=None, fine=None) -> Sheet2Scales:
    """Positions, cells, plan room and Kl of sheet 2 (see :mod:`graphplan.drawing.sheet2`);
    ``loads``, ``fine`` (:func:`one_turn`): the project's (solved here when not given)."""
    from ..forces import compute_loads
    from .layout import _column_widths

    page = page or Page(mech.drawing.format)
    wanted = sheet2_positions(mech, kin, forces, cycle)
    header = sheet2_table_header(forces.reactions, "ru")
    # the table's rows as wide as its widest values are likely to be (the layout is cut
    # before the plans are built); 10 % kept for what they are not
    mb = [fmt(float(forces.M_bal[k]), 5) for k in wanted]
    sample = [[kin.labels[k], "000.0", "10000",
               *(fmt(float(r.magnitude[k]) / 1000.0, 5) for r in forces.reactions.values()),
               "000.00", mb[i], mb[i], "00.00"] for i, k in enumerate(wanted)]

    # under it, on A1, the table of the links' loads (on a smaller page the figures first)
    l_header, l_rows = sheet2_loads_table(mech, kin, wanted, "ru")
    with_loads = [page.frame.height >= A1_FRAME_H - 1e-6 and bool(l_rows)]

    def table_height(width: float) -> float:
        h = split_table_height(header, sample, 0.9 * width)
        if with_loads[0]:
            h += LOADS_GAP + split_table_height(l_header, l_rows, 0.9 * width, key=2)
        return h

    loads = compute_loads(mech, kin, cycle) if loads is None else loads
    trial = Scale("Kl", 0.001, "m/mm")
    trials = {k: trial_plans(mech, kin, forces, loads, k, trial) for k in wanted}
    units = {k: u for k, (u, _) in trials.items()}
    eqs = {k: e for k, (_, e) in trials.items()}
    slots = slot_ranges(mech, one_turn(mech, kin) if fine is None else fine) if any(
        key.split("/")[1] != mech.frame_link for key in kin.pos.guides) else {}
    def lay_out(mechanism: bool) -> Sheet2Layout | None:
        try:
            return sheet2_layout(page, len(mech.dyads), len(wanted), table_height,
                                 shapes if mechanism else [sh[1:] for sh in shapes],
                                 sum(_column_widths(header, sample)) / 0.9, mechanism)
        except LayoutError:
            if mechanism:
                return None
            raise

    # the mechanism in the analysed position first; on a page too small for it and the
    # positions wanted, the groups, their plans and the levers of more positions instead
    # — and where it would take from the force plans' room (the plans are what the sheet
    # reads: drawn smaller, the reactions read off them drift past the reading accuracy)
    def chosen() -> Sheet2Layout:
        lay = lay_out(True)
        alt = lay_out(False)
        if lay is None or (alt is not None and (
                len(alt.rows) > len(lay.rows)
                or _plans_room(lay, shapes, units, wanted, True)
                < MECHANISM_KEEP * _plans_room(alt, shapes, units, wanted, False))):
            lay = alt
        assert lay is not None
        return lay

    def plans_room(lay: Sheet2Layout) -> float:
        return _plans_room(lay, shapes, units, wanted, lay.mechanism)

    shapes = [figure_shapes(mech, kin, units[k], k, page, slots, eqs[k], EQ_CELL)
              for k in wanted]
    lay = chosen()
    if with_loads[0]:
        # the table of the loads only where the figures keep their positions and room
        with_loads[0] = False
        bare = chosen()
        if (len(lay.rows) < len(bare.rows) or lay.mechanism != bare.mechanism
                or plans_room(lay) < LOADS_KEEP * plans_room(bare)):
            lay = bare
        else:
            with_loads[0] = True
    o = 1 if lay.mechanism else 0
    positions = wanted[:len(lay.rows)]
    n_fig = len(mech.dyads) + 1
    kls = tuple(_group_kl(mech, kin, positions, lay.rows, i, o, eqs) for i in range(n_fig))
    kl_mech = _mechanism_kl(mech, kin, positions, lay.rows, slots) if lay.mechanism else None
    # the crank drawn larger than the groups (a short crank), at most 4x: at 8-10x their
    # Kl it was a 250 mm diagonal beside them (the engines)
    least = nice_ceil(min(kl.per_mm for kl in kls[:-1]) / 4.0)
    if kls[-1].per_mm < least:
        kls = (*kls[:-1], Scale("Kl", least, "m/mm"))
    # each plan's room: the extent its cells hold in every position (PLAN_CAP at most)
    s = min(1.0, page.frame.height / 584.0)
    rooms = []
    for i in range(n_fig):
        room = PLAN_CAP * s
        for k, cells, sh in zip(positions, lay.rows, shapes, strict=False):
            cell, (uw, uh), fs = cells[2 * i + 1 + o], units[k][i], sh[2 * i + 2]
            room = min(room, (cell.width - fs.pad_w) / max(uw, 1e-9),
                       (cell.height - fs.pad_h) / max(uh, 1e-9))
        rooms.append(max(room, 20.0))
    return Sheet2Scales(positions, lay.rows, tuple(rooms), kls[0], kls[-1], lay, slots, wanted,
                        kls, kl_mech, with_loads[0])
