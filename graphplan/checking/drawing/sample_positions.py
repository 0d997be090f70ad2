"""A plan of all positions drawn the way a student draws it in a CAD program, for trying
the drawing checker (:mod:`.position_plan`).

:func:`positions_sheet` draws every position of a variant — not with graphplan's sheet
code, but as a CAD user does: each link a line from hinge to hinge, some split in two
pieces, some polylines through three points; every hinge an INSERT of a block holding a
circle; the crank pins numbered with MTEXT set outwards (``3`` or ``A3``); the letters of
the first position; the slider guides; the trajectories: the crank pin's as a CIRCLE, a
centre of mass' as a SPLINE through 90 of its points over the turn; ``р.х.`` and ``х.х.``
by the strokes' arcs; the caption ``План положений, μl = 0,002 м/мм`` with a decimal
comma; the whole far from the origin and, optionally, in inches.

:class:`PositionPlant` puts one error of a student into it: a joint of one position moved
(its links with it), the scale written wrong, the positions numbered from another start
(each number at the next position's pin), an extreme position drawn at a wrong crank
angle or left out, or a trajectory drawn off its path.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .position_plan import revolute_joints


@dataclass(frozen=True, slots=True)
class PositionPlant:
    """One error to put into a plan of positions.

    ``kind``: ``moved`` (the joint ``point`` of position ``position`` moved by ``offset``
    mm), ``scale`` (Kl written ``factor`` times the one drawn), ``numbering`` (each number
    of the equally spaced positions written at the next one's pin), ``extreme`` (the dead
    centre position ``position`` drawn with the crank turned ``turn`` degrees on),
    ``missing`` (position ``position`` not drawn: its links, joints and number left out),
    ``path`` (the trajectory of ``point`` drawn moved by ``offset`` mm).
    """

    kind: str
    position: str = ""
    point: str = ""
    offset: tuple[float, float] = (2.4, 1.8)
    factor: float = 2.0
    turn: float = 8.0


def positions_sheet(variant, path: str | Path, *, plant: PositionPlant | None = None,
                    inches: bool = False, letter_numbers: bool = False,
                    origin: tuple[float, float] = (3150.0, -1720.0),
                    hinge_r: float = 1.2, kl: float | None = None,
                    scale_text: str | None = None) -> Path:
    """Write the plan of all positions of ``variant`` as a DXF (module docstring); the
    joints' circles of radius ``hinge_r`` mm, each centre of mass a filled dot of 0,8 mm.
    ``kl``: the plan drawn at this Kl, m/mm (graphplan's sheet 1's when None);
    ``scale_text``: the scale as written after the caption's words (``М 1:2``; else
    ``μl = … м/мм``), the plant's ``scale`` factor then not applied to it."""
    import ezdxf

    from ...kinematics import solve_positions
    from ..checks import reference_for

    path = Path(path)
    ref = reference_for(Path(variant))
    mech, kin = ref.mech, ref.kin
    kl = kl or ref.analysis.sheet1.kl.per_mm
    labels = list(ref.labels)
    phi = [float(p) for p in kin.phi]
    if plant is not None and plant.kind == "extreme":
        k = labels.index(plant.position)
        phi[k] += math.radians(plant.turn) * mech.crank.sense
    pos = solve_positions(mech, phi)
    P = pos.points
    piv = mech.crank.pivot
    o = np.asarray(P[piv][0])
    org = np.asarray(origin, float)

    def at(name: str, k: int) -> np.ndarray:
        xy = org + (np.asarray(P[name][k]) - o) / kl
        if plant is not None and plant.kind == "moved" and name == plant.point and \
                labels[k] == plant.position:
            xy = xy + np.asarray(plant.offset)
        return xy

    u = 1 / 25.4 if inches else 1.0
    doc = ezdxf.new("R2013")
    doc.header["$INSUNITS"] = 1 if inches else 4
    blk = doc.blocks.new("ШАРНИР")
    blk.add_circle((0, 0), hinge_r * u)
    dot = doc.blocks.new("ЦЕНТР_МАСС")
    dot.add_circle((0, 0), 0.8 * u)
    hatch = dot.add_hatch(color=7)
    hatch.paths.add_edge_path().add_arc((0, 0), 0.8 * u, 0, 360)
    doc.layers.add("МЕХАНИЗМ", color=7)
    doc.layers.add("ОСИ", color=1, linetype="DASHDOT" if "DASHDOT" in doc.linetypes else
                   "CONTINUOUS")
    msp = doc.modelspace()

    def X(v) -> tuple[float, float]:
        return (float(v[0] * u), float(v[1] * u))

    hinges = revolute_joints(mech)
    frames = [f for f in mech.frame_points]
    n_line = 0
    for k in range(len(labels)):
        if plant is not None and plant.kind == "missing" and labels[k] == plant.position:
            continue
        pts = {n: at(n, k) for n in P if not n.startswith("S")}
        for f in frames:
            pts[f] = org + (np.asarray(mech.frame_points[f]) - o) / kl
        for link in [mech.crank.link, *mech.links]:
            names = [q for q in mech.points_of(link) if q in pts]
            drawn = [q for q in names if q in hinges or q in frames]
            for a, b in itertools.pairwise(drawn):
                A, B = pts[a], pts[b]
                L = float(np.hypot(*(B - A)))
                if L < 2.6:
                    continue
                e = (B - A) / L
                A1, B1 = (A + hinge_r * e, B - hinge_r * e) if n_line % 2 else (A, B)  # rim
                if n_line % 3 == 0:
                    M = A1 + 0.45 * (B1 - A1)
                    msp.add_line(X(A1), X(M), dxfattribs={"layer": "МЕХАНИЗМ"})
                    msp.add_line(X(M), X(B1), dxfattribs={"layer": "МЕХАНИЗМ"})
                elif n_line % 3 == 1:
                    msp.add_lwpolyline([X(A1), X(A1 + 0.5 * (B1 - A1)), X(B1)],
                                       dxfattribs={"layer": "МЕХАНИЗМ"})
                else:
                    msp.add_line(X(A1), X(B1), dxfattribs={"layer": "МЕХАНИЗМ"})
                n_line += 1
        for n in hinges:
            if n in pts:
                msp.add_blockref("ШАРНИР", X(pts[n]), dxfattribs={"layer": "МЕХАНИЗМ"})
        for n in P:
            if n.startswith("S") and n not in frames:
                msp.add_blockref("ЦЕНТР_МАСС", X(at(n, k)), dxfattribs={"layer": "МЕХАНИЗМ"})
    for f in frames:
        c = org + (np.asarray(mech.frame_points[f]) - o) / kl
        msp.add_blockref("ШАРНИР", X(c), dxfattribs={"layer": "МЕХАНИЗМ"})
        msp.add_mtext(f, dxfattribs={"char_height": 5.0 * u}).set_location(
            X(c + np.array([-3.0, -4.0])), attachment_point=3)
    # the guides of sliders on the frame and the trajectory of a centre of mass
    for key, (G, g) in pos.guides.items():
        slider, carrier = key.split("/")
        if carrier != mech.frame_link:
            continue
        base = np.asarray(G[0])
        d = np.asarray(g[0])
        s = [float(np.dot(np.asarray(P[q]) - base, d).min()) for q in mech.points_of(slider)
             if q in P]
        e_ = [float(np.dot(np.asarray(P[q]) - base, d).max()) for q in mech.points_of(slider)
              if q in P]
        if s:
            a = org + (base + (min(s) - 15 * kl) * d - o) / kl
            b = org + (base + (max(e_) + 15 * kl) * d - o) / kl
            msp.add_line(X(a), X(b), dxfattribs={"layer": "ОСИ"})
    # the trajectories: the crank pin's circle, a centre of mass' closed curve
    turn = ref.analysis.one_turn.pos.points
    msp.add_circle(X(org), mech.crank.length / kl * u, dxfattribs={"layer": "ОСИ"})
    centres = sorted(n for n in turn if n.startswith("S") and n not in mech.frame_points)
    if centres:
        traced = plant.point if plant is not None and plant.kind == "path" else centres[0]
        shift = np.asarray(plant.offset) if plant is not None and plant.kind == "path" else 0.0
        fit = [X(org + (np.asarray(q) - o) / kl + shift) for q in turn[traced][:-1:4]]
        msp.add_spline(fit_points=[*fit, fit[0]], dxfattribs={"layer": "ОСИ"})
    # the numbers at the crank pins (outwards), the letters of the first position
    r = mech.crank.length / kl
    pin = mech.crank.pin
    order = list(range(len(labels)))
    if plant is not None and plant.kind == "numbering":
        # each number of the equally spaced positions written at the next one's pin
        even = _equally_spaced([float(p) for p in kin.phi], mech.crank.sense,
                              ref.analysis.cycle.period)
        nxt = {even[i]: even[(i + 1) % len(even)] for i in range(len(even))}
        order = [nxt.get(k, k) for k in order]
    for k, lab in enumerate(labels):
        if plant is not None and plant.kind == "missing" and lab == plant.position:
            continue
        q = at(pin, order[k])
        out = (q - org) / max(float(np.hypot(*(q - org))), 1e-9)
        text = f"{pin}{lab}" if letter_numbers else lab
        m = msp.add_mtext(text, dxfattribs={"char_height": 3.5 * u})
        m.set_location(X(q + (4.5 + 0.6 * len(text)) * out), attachment_point=5)
    for n in [piv, *hinges]:
        if n in P:
            q = at(n, 0)
            msp.add_mtext(n, dxfattribs={"char_height": 5.0 * u}).set_location(
                X(q + np.array([2.5, -2.5])), attachment_point=7)
    cy = ref.analysis.cycle
    if cy.dead_centres:
        sense = mech.crank.sense
        a0 = cy.dead_centres[0]
        for name, mid in (("р.х.", a0 + sense * cy.working_turn / 2),
                          ("х.х.", a0 + sense * (cy.working_turn + (2 * math.pi -
                                                                   cy.working_turn) / 2))):
            q = org + (r + 9.0) * np.array([math.cos(mid), math.sin(mid)])
            msp.add_text(name, dxfattribs={"height": 3.5 * u}).set_placement(
                X(q), align=ezdxf.enums.TextEntityAlignment.MIDDLE_CENTER)
    top = max(float(at(n, k)[1]) for n in P for k in range(len(labels))) + 15.0
    written = kl * (plant.factor if plant is not None and plant.kind == "scale" else 1.0)
    caption = f"План положений, μl = {written:g} м/мм".replace(".", ",")
    msp.add_mtext(f"План положений {scale_text}" if scale_text else caption,
                  dxfattribs={"char_height": 5.0 * u}).set_location(
        X((org[0] - 60.0, top)), attachment_point=7)
    doc.saveas(path)
    return path


def _equally_spaced(phi: list[float], sense: float, period: float) -> list[int]:
    """The positions of the main series (the crank turned by one step from each to the
    next, the step the commonest gap), in the order of the crank's turn over the whole
    cycle: the others (``a``, ``1'``) left out."""
    base = phi[0]
    turned = [((p - base) * sense) for p in phi]
    ring = sorted({round(t % (2 * math.pi), 9) for t in turned})
    gaps = [round(b - a, 6) for a, b in itertools.pairwise(ring)]
    step = max(set(gaps), key=gaps.count) if gaps else 2 * math.pi
    series = [k for k, t in enumerate(turned) if abs(t / step - round(t / step)) < 1e-3]
    return sorted(series, key=lambda k: turned[k] % period)


__all__ = ["PositionPlant", "positions_sheet"]
