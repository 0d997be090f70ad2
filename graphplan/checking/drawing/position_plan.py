"""The plan of positions with every position drawn at once, against the exact positions.

A sheet 1 draws the mechanism in all its positions on one figure: the crank pin of each
position numbered (``1`` … ``12``, ``(2)``, ``1'``, or ``A0`` … ``A11``), the extreme
positions among them, the working and idle strokes marked ``р.х.`` / ``х.х.``. It is
found by its caption (``План положений``, no position named) and the crank's pivot
lettered near it, and read as a draftsman reads it:

1. **The pivot** — the joint circle by the pivot's letter (``O``, ``O1``) whose lines
   (ending on it, or through it: a two-throw crank ``A–O–D`` drawn as one line) lead to
   the most joint circles at one distance (the crank of every position starts there). A
   joint's circle is 0,6–3,5 mm in radius, not filled (a filled dot is a centre of mass).
2. **The crank pins** — the joint circles at the far ends of the lines from the pivot
   (lines split into pieces followed on); the drawn crank radius ``r`` is their median
   distance, so the plan's Kl as drawn is ``l_OA / r``.
3. **The numbers** — each text of position labels near the crank circle goes to a pin,
   each pin numbered once, at the least total cost over all numbers (the Hungarian
   method: a number set nearer a neighbour's pin is still its own pin's when its
   neighbours' numbers sit at theirs): the distance from the text, plus how far round
   the circle it is from the pin, a leader followed to the pin it ends at (a line whose
   end by the text is on a joint is a link, not a leader), and a number between two
   pins given to the one its position puts there (by at most its height). Circles drawn
   at one place are one pin, numbered as many times as positions of the cycle fall at
   one crank angle (twice over a 720° cycle); one more number there (a two-throw crank's
   pins drawn at one place) at the cost of its height, up to the circles drawn there.
4. **The joints of each position** — the exact position at its number's crank angle
   (where the pin is off it, at the angle drawn), laid from the drawn pivot at the Kl
   used, gives where each revolute joint should be. A joint is the circle the position's
   own links lead to from its pin (the lines ending on a circle's rim or centre); where
   that leaves it open (crowded positions near a dead centre, a line led past a circle
   drawn at the exact place), the remaining circles are given to the places at the
   least total distance (each circle once; one circle for two places only where they
   coincide), within 6 mm.

Judged (:func:`judge_position_plan`), with the calculation checker's verdicts:

* **Kl** — a drawn crank radius off ``l_OA/Kl`` (beyond the segment tolerance) is a
  ``scale`` finding; the rest is then laid at the Kl as drawn.
* **The numbering** — each number's crank angle against the exact position's. All of
  them turned by one angle: the positions are numbered from another start (``label``).
  One off: a position of another crank angle (``other-variant``), or, for a dead-centre
  position, a wrong extreme position (``extreme``). Within max(1°, atan(reading/r)) ok,
  within max(2°, atan(2·reading/r)) inaccurate.
* **Each joint** off its exact place at its position (``point``: ok within the reading,
  inaccurate within twice it), and each link with both ends found drawn at another
  length (``model``: the segment tolerance; following from a misplaced end).
* **The strokes** — ``р.х.`` (``w.s.``) written by the arc of the crank's working turn
  between the dead centres and ``х.х.`` (``i.s.``) by the idle one; swapped or on the
  wrong side is an ``extreme`` finding.

* **A position not drawn** (no number of it at the crank circle): ``extreme`` at a dead
  centre, ``missing`` elsewhere; wrong.
* **The trajectories** drawn (:mod:`.trajectories`): each point's curves against its
  exact path over the turn (``point``, quantity ``⌒S2``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from ..units import fold
from .plans import caption_kind, caption_position, stated_scales
from .positions import PivotPlaced
from .primitives import Text, fit_circle
from .scene import Scene, split_names

Pt = tuple[float, float]
HINGE_R = (0.6, 3.5)  #: radii of a drawn joint's circle, mm (a filled dot is a centre of mass)
GATE = 6.0  #: a drawn joint farther than this from its exact place is not taken as it, mm
STROKES = {"р.х.": "working", "рх": "working", "w.s.": "working",
           "х.х.": "idle", "хх": "idle", "i.s.": "idle"}


@dataclass(slots=True)
class PositionPlan(PivotPlaced):
    """A plan of all positions as read (module docstring). ``angles``: the drawn crank
    angle of each numbered position, rad; ``expected``: where the exact position at that
    angle puts each joint, ``(label, joint) → (x, y)`` mm; ``joints``/``links``: as
    drawn."""

    caption: Text
    kl: float | None  # as written (the caption's, else the sheet's)
    pivot: Pt
    radius: float  # the drawn crank radius, mm
    pins: dict[str, Pt] = field(default_factory=dict)
    angles: dict[str, float] = field(default_factory=dict)
    joints: dict[tuple[str, str], Pt] = field(default_factory=dict)
    expected: dict[tuple[str, str], Pt] = field(default_factory=dict)
    links: dict[tuple[str, str], tuple[Pt, Pt]] = field(default_factory=dict)
    strokes: list[tuple[str, Text]] = field(default_factory=list)
    kl_used: float | None = None
    paths: list = field(default_factory=list)  # the trajectories drawn (DrawnPath)
    exact_paths: dict = field(default_factory=dict)  # point → its exact path on the sheet
    kind: str = "positions"
    position: str | None = None

    def _points(self) -> list[Pt]:
        return [self.pivot, *self.pins.values(), *self.joints.values()]


def revolute_joints(mech) -> list[str]:
    """The points a draftsman draws as hinges: the crank pin and the revolute pairs of
    the dyads (a slide's point is not one); frame points left out."""
    patterns = {"RRR": (0, 1, 2), "RRP": (0, 1), "RPR": (0, 1), "PRP": (0,), "RPP": (0,)}
    out = [mech.crank.pin]
    for d in mech.dyads:
        idx = patterns.get(d.kind, ())
        if d.kind == "RPR":
            idx = (0,)  # the outer joint; the other end turns on the frame or a link
            if len(d.joints) > 1 and d.joints[1] not in mech.frame_points:
                idx = (0, 1)
        for i in idx:
            if i < len(d.joints):
                n = d.joints[i]
                if n not in out and n not in mech.frame_points:
                    out.append(n)
    return out


def _hinges(scene: Scene) -> np.ndarray:
    """The drawn joints, ``(x, y, r)`` rows: circles of a hinge's size, and closed round
    loops of curve pieces of that size (a PDF draws a circle as four Bézier arcs)."""
    got = getattr(scene, "_pp_hinges", None)
    if got is not None:
        return got
    dots = _dots(scene)
    cs = [(c.x, c.y, c.r) for c in scene.drawing.circles if HINGE_R[0] <= c.r <= HINGE_R[1]
          and not _is_dot(dots, c.x, c.y, c.r)]
    # a reader that gives a circle also as its curve pieces (DXF) counts it once
    loops = [lp for lp in _round_loops([s for s in scene.drawing.segments
                                        if s.curve and s.length < 2.0])
             if not _is_dot(dots, *lp)]
    left = list(cs)
    for lp in loops:
        twin = next((c for c in left if math.hypot(c[0] - lp[0], c[1] - lp[1]) < 0.2 and
                     abs(c[2] - lp[2]) < 0.2), None)
        if twin is not None:
            left.remove(twin)
        else:
            cs.append(lp)
    out = np.array(cs, float).reshape(-1, 3)
    scene._pp_hinges = out  # type: ignore[attr-defined]
    return out


def _dots(scene: Scene) -> np.ndarray:
    """The filled round shapes of the drawing as ``(x, y, r)`` rows: a dot (a centre of
    mass) is filled, a joint's circle is not."""
    out = []
    for f in scene.drawing.fills:
        if len(f.points) < 8 or f.colour == "#ffffff":
            continue
        pts = np.asarray(f.points, float)
        c = (pts.min(axis=0) + pts.max(axis=0)) / 2  # a closing point repeats the first
        r = np.hypot(pts[:, 0] - c[0], pts[:, 1] - c[1])
        if float(r.mean()) <= HINGE_R[1] + 0.5 and float(r.max() - r.min()) <= 0.1 * r.mean():
            out.append((float(c[0]), float(c[1]), float(r.mean())))
    return np.array(out, float).reshape(-1, 3)


def _is_dot(dots: np.ndarray, x: float, y: float, r: float) -> bool:
    """A circle that is the outline of a filled dot of its size."""
    if not len(dots):
        return False
    d = np.hypot(dots[:, 0] - x, dots[:, 1] - y)
    return bool(np.any((d <= 0.25 * r) & (np.abs(dots[:, 2] - r) <= 0.2 * r + 0.05)))


def _round_loops(segs) -> list[tuple[float, float, float]]:
    """Circles drawn as closed chains of short curve pieces: each chain whose every end
    meets one other, its points all at one distance (within 5 %) from their middle."""
    key = {}
    parent: list[int] = []

    def node(x: float, y: float) -> int:
        k = (round(x, 2), round(y, 2))
        if k not in key:
            key[k] = len(parent)
            parent.append(len(parent))
        return key[k]

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    ends = []
    for s in segs:
        a, b = node(s.x1, s.y1), node(s.x2, s.y2)
        ends.append((a, b))
        parent[find(a)] = find(b)
    groups: dict[int, list[int]] = {}
    for i, (a, _b) in enumerate(ends):
        groups.setdefault(find(a), []).append(i)
    out = []
    for idx in groups.values():
        if len(idx) < 4:
            continue
        deg: dict[int, int] = {}
        for i in idx:
            for n in ends[i]:
                deg[n] = deg.get(n, 0) + 1
        # one loop: every end meets one other; the same circle drawn twice (two
        # positions' joints at one place): every end meets three
        many = set(deg.values())
        if len(many) != 1 or min(many) % 2:
            continue
        pts = np.array([(segs[i].x1, segs[i].y1) for i in idx])
        c = np.array(fit_circle(pts)[:2])
        r = np.hypot(pts[:, 0] - c[0], pts[:, 1] - c[1])
        rm = float(r.mean())
        if HINGE_R[0] <= rm <= HINGE_R[1] and float(r.max() - r.min()) <= 0.05 * rm:
            out += [(float(c[0]), float(c[1]), rm)] * (min(many) // 2)
    return out


def _ends_on(scene: Scene, c) -> list[int]:
    """Indices of the lines with an end on (or in) circle ``c``."""
    ends = getattr(scene, "_pp_ends", None)
    if ends is None:
        ends = np.array([(s.x1, s.y1, s.x2, s.y2, s.length) for s in scene.segments],
                        float).reshape(-1, 5)
        scene._pp_ends = ends  # type: ignore[attr-defined]
    x, y, r = c
    on = ((np.hypot(ends[:, 0] - x, ends[:, 1] - y) <= r + 0.6) |
          (np.hypot(ends[:, 2] - x, ends[:, 3] - y) <= r + 0.6)) & (ends[:, 4] >= 0.5)
    return [int(i) for i in np.flatnonzero(on)]


def _through(scene: Scene, c) -> list[int]:
    """Indices of the lines that pass through circle ``c``'s centre (within its radius)
    with both ends off it: the crank of a two-pin crankshaft (``A–O–D``) drawn as one line."""
    _ends_on(scene, (0.0, 0.0, 0.0))  # the lines' ends, once
    e = scene._pp_ends  # type: ignore[attr-defined]
    x, y, r = c
    d = e[:, 2:4] - e[:, 0:2]
    L = np.maximum(e[:, 4], 1e-9)
    w = np.stack([x - e[:, 0], y - e[:, 1]], axis=1)
    t = (w[:, 0] * d[:, 0] + w[:, 1] * d[:, 1]) / L
    perp = np.abs(w[:, 0] * d[:, 1] - w[:, 1] * d[:, 0]) / L
    on = (perp <= 0.3) & (t > r + 0.6) & (t < L - r - 0.6) & (e[:, 4] >= 2.0)
    return [int(i) for i in np.flatnonzero(on)]


def _from_centre(scene: Scene, c) -> list[tuple[np.ndarray, np.ndarray]]:
    """The far ends (and directions) of every line leaving circle ``c``: those ending on
    it, and both halves of those passing through its centre."""
    out = [_far_end(scene, i, c) for i in _ends_on(scene, c)]
    for i in _through(scene, c):
        out += [_far_end(scene, i, c, end) for end in (0, 1)]
    return out


def _far_end(scene: Scene, i: int, c, end: int | None = None
             ) -> tuple[np.ndarray, np.ndarray]:
    """The far end of line ``i`` from circle ``c`` (or its end ``end``: 0 the first, 1 the
    second), followed on through the pieces it is split into (a collinear piece starting
    where it stops), and its direction."""
    s = scene.segments[i]
    a, b = np.array([s.x1, s.y1]), np.array([s.x2, s.y2])
    if end is not None:
        a, b = (np.array(c[:2], float), b) if end == 1 else (np.array(c[:2], float), a)
    elif np.hypot(*(a - c[:2])) > np.hypot(*(b - c[:2])):
        a, b = b, a
    u = (b - a) / max(float(np.hypot(*(b - a))), 1e-9)
    seen = {i}
    hinges = _hinges(scene)
    for _ in range(30):
        if len(hinges) and np.any(np.hypot(hinges[:, 0] - b[0], hinges[:, 1] - b[1]) <=
                                  hinges[:, 2] + 0.6):
            return b, u  # on a joint: the line of the next link goes on from there
        nxt = None
        n = _node_at(scene, b)
        for j in scene.nodes[n].segments if n is not None else ():
            if j in seen:
                continue
            t = scene.segments[j]
            p, q = np.array([t.x1, t.y1]), np.array([t.x2, t.y2])
            if np.hypot(*(q - b)) < np.hypot(*(p - b)):
                p, q = q, p
            L = float(np.hypot(*(q - p)))
            if L < 0.3 or abs(float(u[0] * (q - p)[1] - u[1] * (q - p)[0])) / L > 0.01 or \
                    float(np.dot(u, q - p)) <= 0:
                continue
            nxt = (j, q)
            break
        if nxt is None:
            return b, u
        seen.add(nxt[0])
        b = nxt[1]
    return b, u


def _node_at(scene: Scene, xy) -> int | None:
    """The node at ``xy`` (within the scene's snap), if any."""
    from .scene import SNAP_MM

    ci, cj = math.floor(xy[0] / SNAP_MM), math.floor(xy[1] / SNAP_MM)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            for n in scene._grid.get((ci + di, cj + dj), ()):
                nd = scene.nodes[n]
                if math.hypot(nd.x - xy[0], nd.y - xy[1]) <= SNAP_MM:
                    return n
    return None


def _hinge_at_end(hinges: np.ndarray, q, u=None, skip=None) -> int | None:
    """The hinge a line ending at ``q`` (running on along ``u``) ends on: at its centre,
    or on its rim with the centre straight on; within 0,8 mm; ``skip``: a centre left
    out."""
    if not len(hinges):
        return None
    w = hinges[:, :2] - np.asarray(q, float)[None, :]
    if u is None:
        d = np.hypot(w[:, 0], w[:, 1])
        score = np.minimum(np.abs(d - hinges[:, 2]), d)
    else:
        along = w @ np.asarray(u, float)
        perp = np.abs(w[:, 0] * u[1] - w[:, 1] * u[0])
        score = perp + np.minimum(np.abs(along - hinges[:, 2]), np.abs(along))
    if skip is not None:
        score[np.hypot(hinges[:, 0] - skip[0], hinges[:, 1] - skip[1]) < 1.0] = np.inf
    j = int(np.argmin(score))
    return j if score[j] <= 0.8 else None


def _leader_ends(scene: Scene, t: Text) -> list[np.ndarray]:
    """The far ends of the lines that start at a text's box (its leaders). A line whose
    end by the text is on a joint's circle is a link drawn from that joint, not a leader:
    a leader starts at its text, free."""
    _ends_on(scene, (0.0, 0.0, 0.0))  # the lines' ends, once
    ends = scene._pp_ends  # type: ignore[attr-defined]
    hinges = _hinges(scene)
    hw, hh = 0.35 * t.height * len(t.text) + 2.5, 0.5 * t.height + 2.0
    out = []
    for a, b in ((0, 2), (2, 0)):
        near = (np.abs(ends[:, a] - t.x) <= hw) & (np.abs(ends[:, a + 1] - t.y) <= hh) & \
            (ends[:, 4] >= 2.0) & (ends[:, 4] <= 60.0)
        for i in np.flatnonzero(near):
            q = ends[i, a:a + 2]
            if len(hinges) and bool(np.any(np.hypot(hinges[:, 0] - q[0], hinges[:, 1] - q[1])
                                           <= hinges[:, 2] + 0.6)):
                continue
            out.append(ends[i, b:b + 2])
    return out


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def _assign(pairs: list[tuple[float, str, int, float]], slots: dict[int, int],
            twins: int = 1, reach: float = 25.0) -> dict[str, int]:
    """Labels to pin places at the whole set's least total cost (the Hungarian method): a
    number set nearer a neighbour's pin than its own is still read at its own when its
    neighbours' numbers sit at theirs, as a teacher reads them in turn. ``pairs``: (cost,
    label, place, the number's height); ``slots``: how many circles are drawn at each
    place; ``twins``: how many positions of the cycle fall at one crank angle (2 over a
    720° cycle). A place takes that many numbers; one more (circles drawn at one place
    for another reason: a two-throw crank's pins) only at the cost of its height more,
    where no free pin by it takes it."""
    labs = sorted({lab for _d, lab, _i, _h in pairs})
    cols = [(i, k) for i in sorted(slots) for k in range(max(slots[i], 1))]
    if not labs or not cols:
        return {}
    big = 1e6
    C = np.full((len(labs), max(len(cols), len(labs))), big)
    li = {lab: n for n, lab in enumerate(labs)}
    ci: dict[int, list[int]] = {}
    for n, (i, _k) in enumerate(cols):
        ci.setdefault(i, []).append(n)
    for d, lab, i, h in pairs:
        if d <= reach and i in ci:
            for k, c in enumerate(ci[i]):
                C[li[lab], c] = min(C[li[lab], c], d + max(k - twins + 1, 0) * h)
    got = _hungarian(C)
    return {lab: cols[c][0] for lab, c in zip(labs, got, strict=True)
            if c < len(cols) and C[li[lab], c] < big}


def _hungarian(C: np.ndarray) -> list[int]:
    """The column of each row at the least total cost, rows ≤ columns (Kuhn–Munkres with
    potentials, O(n²m))."""
    n, m = C.shape
    u, v = np.zeros(n + 1), np.zeros(m + 1)
    p = np.zeros(m + 1, int)  # p[j]: the row (1-based) in column j
    way = np.zeros(m + 1, int)
    for i in range(1, n + 1):
        p[0] = i
        j0 = 0
        minv = np.full(m + 1, np.inf)
        used = np.zeros(m + 1, bool)
        while True:
            used[j0] = True
            i0 = p[j0]
            cur = C[i0 - 1, :] - u[i0] - v[1:]
            free = ~used[1:]
            upd = free & (cur < minv[1:])
            minv[1:][upd] = cur[upd]
            way[1:][upd] = j0
            cand = np.where(free, minv[1:], np.inf)
            j1 = int(np.argmin(cand)) + 1
            delta = cand[j1 - 1]
            u[p[used]] += delta
            v[used] -= delta
            minv[1:][free] -= delta
            j0 = j1
            if p[j0] == 0:
                break
        while j0:
            j1 = way[j0]
            p[j0] = p[j1]
            j0 = j1
    cols = [0] * n
    for j in range(1, m + 1):
        if p[j]:
            cols[p[j] - 1] = j - 1
    return cols


def _crank_pins(scene: Scene, hinges: np.ndarray, pc) -> tuple[list[int], float]:
    """The hinges at the far ends of the lines from ``pc`` that lie on one circle about it
    (within 5 % + 0,5 mm of the median distance), and that circle's radius, mm."""
    o = pc[:2]
    pins_i: set[int] = set()
    for e, u in _from_centre(scene, pc):
        j = _hinge_at_end(hinges, e, u, skip=o)
        if j is not None:
            pins_i |= {int(i) for i in np.flatnonzero(
                np.hypot(hinges[:, 0] - hinges[j, 0], hinges[:, 1] - hinges[j, 1]) < 0.3)}
    if len(pins_i) < 3:
        return [], 0.0
    dist = {i: float(np.hypot(*(hinges[i, :2] - o))) for i in pins_i}
    r = float(np.median(list(dist.values())))
    pins = [i for i in pins_i if abs(dist[i] - r) <= 0.05 * r + 0.5]
    if len(pins) < 3:
        return [], 0.0
    return pins, float(np.median([dist[i] for i in pins]))


def find_position_plans(scene: Scene, ref) -> list[PositionPlan]:
    """The plans of all positions of a drawing (module docstring)."""
    mech = ref.mech
    pivot_name = mech.crank.pivot
    scales = stated_scales(scene.drawing.texts)
    sheet_kl = next((s.value for s in scales if s.symbol == "Kl" and
                     caption_kind(s.text.text) is None), None)
    caps = [t for t in scene.drawing.texts if caption_kind(t.text) == "scheme" and
            caption_position(t.text) is None]
    hinges = _hinges(scene)
    if not caps or not len(hinges):
        return []
    letters = [t for t in scene.drawing.texts if fold(t.text.strip()) == pivot_name]
    out = []
    used: set[int] = set()
    for cap in caps:
        kl = next((s.value for s in scales if s.symbol == "Kl" and s.text is cap), sheet_kl)
        near = [t for t in letters if math.hypot(t.x - cap.x, t.y - cap.y) <= 400.0]
        if not near:
            continue
        # the pivot: of the hinges within 60 mm of its letter, the one whose lines lead to
        # the most joints on one circle (the crank of every position: a pin, where many
        # positions' rods meet, leads to few), the nearer first among equals
        best = None
        seen: set[int] = set()
        for t in near:
            d = np.hypot(hinges[:, 0] - t.x, hinges[:, 1] - t.y)
            for i in np.flatnonzero(d <= 60.0):
                if int(i) in used or int(i) in seen:
                    continue
                seen.add(int(i))
                if len(_ends_on(scene, hinges[i])) + len(_through(scene, hinges[i])) < 3:
                    continue
                n = len(_crank_pins(scene, hinges, hinges[i])[0])
                key = (n, -float(d[i]))
                if best is None or key > best[0]:
                    best = (key, int(i))
        if best is None or best[0][0] < 3:
            continue
        used.add(best[1])
        pc = hinges[best[1]]
        plan = _read(scene, ref, cap, kl, pc, hinges)
        if plan is not None:
            out.append(plan)
    return out


def _read(scene: Scene, ref, cap: Text, kl, pc, hinges) -> PositionPlan | None:
    o = pc[:2]
    # 2. the crank pins: hinges at the far ends of the lines from the pivot
    pins, r = _crank_pins(scene, hinges, pc)
    if len(pins) < 3:
        return None
    # a pin whose crank line is broken (by a slide block drawn over it) is on the circle too
    dh = np.hypot(hinges[:, 0] - o[0], hinges[:, 1] - o[1])
    pins = sorted(set(pins) | {int(i) for i in np.flatnonzero(np.abs(dh - r) <= 0.02 * r + 0.3)})
    # the circles drawn at one place (two positions' pins, a two-throw crank's A and D)
    # are one pin place, numbered as many times as circles are drawn there
    slots: dict[int, int] = {}
    for i in pins:
        k0 = next((k for k in slots if math.hypot(*(hinges[k, :2] - hinges[i, :2])) < 0.3), i)
        slots[k0] = slots.get(k0, 0) + 1
    pins = sorted(slots)
    plan = PositionPlan(cap, kl, (float(o[0]), float(o[1])), r)
    # 3. the numbers
    labels = list(ref.labels)
    phi = {lab: float(ref.kin.phi[k]) for k, lab in enumerate(labels)}
    pin_letter = ref.mech.crank.pin
    by_text = {id(L.text): L for L in scene.letters}
    # the texts the scene reads on a leader (the letter's node is that leader's point;
    # else it is only the node nearest the text)
    on_leader = getattr(scene, "_pp_leaders", None)
    if on_leader is None:
        on_leader = set(scene._leaders()[0])
        scene._pp_leaders = on_leader  # type: ignore[attr-defined]
    pairs = []
    for ti, t in enumerate(scene.drawing.texts):
        names = split_names(t.text)
        labs: list[str] = []
        for n in names:
            n = n.strip()
            lab = n if n in labels else n[len(pin_letter):] if (
                n.startswith(pin_letter) and n[len(pin_letter):] in labels) else None
            if lab is None:
                labs = []
                break
            labs.append(lab)
        if not labs:
            continue
        dt = math.hypot(t.x - o[0], t.y - o[1])
        if not (0.4 * r - 10.0 <= dt <= r + 60.0):
            continue
        leads = _leader_ends(scene, t)
        if dt > r + 30.0 and not any(
                np.min(np.hypot(hinges[pins, 0] - q[0], hinges[pins, 1] - q[1]) -
                       hinges[pins, 2]) <= 1.6 for q in leads):
            continue  # far out only on a leader to a pin
        L = by_text.get(id(t))
        lead = None
        if L is not None and L.node is not None and ti in on_leader:
            nd = scene.nodes[L.node]
            lead = (nd.x, nd.y)
        at = math.atan2(t.y - o[1], t.x - o[0])
        for i in pins:
            c = hinges[i]
            # the text's distance from the pin, and how far round the crank circle it is
            # from it (a number is set outwards from its pin)
            d = max(math.hypot(c[0] - t.x, c[1] - t.y) - 0.35 * t.height * len(t.text), 0.0)
            d += 0.5 * dt * abs(_wrap(at - math.atan2(c[1] - o[1], c[0] - o[0])))
            if (lead is not None and math.hypot(lead[0] - c[0], lead[1] - c[1]) <= c[2] + 1.0) \
                    or any(math.hypot(q[0] - c[0], q[1] - c[1]) <= c[2] + 1.6 for q in leads):
                d = min(d, 0.5)  # a leader from the number to the pin
            ang = math.atan2(c[1] - o[1], c[0] - o[0])
            for lab in labs:
                # a number between two pins goes to the one its position puts there (by
                # at most its height: it only settles what the sheet leaves open)
                prior = min(r * abs(_wrap(ang - phi[lab])), t.height)
                pairs.append((d + prior, lab, i, t.height))
    at_angle: dict[float, int] = {}
    for a in phi.values():
        turn = round(a % (2 * math.pi), 6) % round(2 * math.pi, 6)
        at_angle[turn] = at_angle.get(turn, 0) + 1
    for lab, i in _assign(pairs, slots, max(at_angle.values(), default=1)).items():
        c = hinges[i]
        plan.pins[lab] = (float(c[0]), float(c[1]))
        plan.angles[lab] = math.atan2(c[1] - o[1], c[0] - o[0])
    # the strokes' letters
    for t in scene.drawing.texts:
        key = STROKES.get(t.text.strip().lower())
        if key and math.hypot(t.x - o[0], t.y - o[1]) <= r + 40.0:
            plan.strokes.append((key, t))
    if len(plan.pins) < 2:
        return None
    return plan


def _expected_at(ref, pivot: Pt, kl: float, angle: float) -> dict[str, Pt] | None:
    """Where the exact position at crank angle ``angle`` (rad) puts each point, laid from
    the drawn pivot at ``kl``; None where the mechanism cannot take that angle."""
    from ...kinematics import solve_positions

    try:
        P = solve_positions(ref.mech, [angle]).points
    except Exception:
        return None
    o = np.asarray(P[ref.mech.crank.pivot][0])
    return {n: (float(pivot[0] + (xy[0][0] - o[0]) / kl), float(pivot[1] + (xy[0][1] - o[1]) / kl))
            for n, xy in P.items()}


def lay_joints(plan: PositionPlan, scene: Scene, ref, kl: float, laid_at: dict[str, float]
               ) -> None:
    """Where each joint of each numbered position should be (the exact position at the
    crank angle ``laid_at[label]``, rad, at ``kl`` from the drawn pivot), and the drawn
    hinges given to those places nearest first (module docstring, 4)."""
    from ...kinematics import solve_positions

    mech = ref.mech
    names = [n for n in revolute_joints(mech) if n != mech.crank.pin]
    o = np.asarray(plan.pivot)
    labs = [lab for lab in plan.pins if lab in laid_at]
    if not labs:
        return
    try:
        pos = solve_positions(mech, [laid_at[lab] for lab in labs])
    except Exception:
        return
    P = pos.points
    piv = mech.crank.pivot
    for j, lab in enumerate(labs):
        for n in [mech.crank.pin, *names, *(f for f in mech.frame_points if f != piv)]:
            if n in P:
                e = o + (np.asarray(P[n][j]) - np.asarray(P[piv][j])) / kl
                plan.expected[(lab, n)] = (float(e[0]), float(e[1]))
    hinges = _hinges(scene)
    frames = set(mech.frame_points)
    # (a) along the links: from a joint found, the lines that end on its circle lead to
    # the next joint of the same position (coinciding places told apart by their links)
    neighbours: dict[str, set[str]] = {}
    for link in [mech.crank.link, *mech.links]:
        try:
            pts = [q for q in mech.points_of(link) if not q.startswith("S")]
        except (KeyError, ValueError):
            continue
        for q in pts:
            neighbours.setdefault(q, set()).update(x for x in pts if x != q)
    by_xy = {(round(float(h[0]), 3), round(float(h[1]), 3)): h for h in hinges}

    def hinge_of(xy):
        return by_xy.get((round(float(xy[0]), 3), round(float(xy[1]), 3)),
                         np.array([xy[0], xy[1], 0.5]))

    owner: dict[int, tuple[str, str]] = {}
    for lab in labs:
        found = {mech.crank.pin: plan.pins[lab], piv: plan.pivot}
        for f in frames - {piv}:
            e = np.asarray(plan.expected[(lab, f)])
            d = np.hypot(hinges[:, 0] - e[0], hinges[:, 1] - e[1])
            if len(d) and float(d.min()) <= GATE:
                found[f] = (float(hinges[int(d.argmin()), 0]), float(hinges[int(d.argmin()), 1]))
                plan.joints[(lab, f)] = found[f]
        pending = [n for n in names if (lab, n) in plan.expected]
        progress = True
        while pending and progress:
            progress = False
            for n in list(pending):
                e = np.asarray(plan.expected[(lab, n)])
                # the hinges each moving neighbour found leads to by its lines, near the
                # place; those all of them lead to
                sets = []
                for m in neighbours.get(n, ()):
                    if m not in found or m in frames:
                        continue  # a frame pivot's lines lead to every position's joint
                    c = hinge_of(found[m])
                    got = set()
                    for i in _ends_on(scene, c):
                        q, u = _far_end(scene, i, c)
                        h = _hinge_at_end(hinges, q, u)
                        if h is not None and float(np.hypot(*(hinges[h, :2] - e))) <= GATE:
                            got.add(h)
                    if got:
                        sets.append(got)
                if not sets:
                    continue
                both = set.intersection(*sets) or set.union(*sets)
                # each hinge once: two positions whose joints coincide each take a circle
                # of their own, where the student drew two
                opts = sorted((float(np.hypot(*(hinges[h, :2] - e))), h) for h in both)
                opts = [o for o in opts if o[1] not in owner]
                if (len(opts) > 1 and opts[1][0] < 2.0 * opts[0][0] + 0.3) or (opts and \
                        opts[0][0] > 0.3 and bool(np.any(np.hypot(
                            hinges[:, 0] - e[0], hinges[:, 1] - e[1]) <= 0.3))):
                    # the lines leave it open, or lead past a circle drawn at the exact
                    # place (crowded positions' lines run through each other's
                    # joints): the whole set's best below
                    opts = []
                best = opts[0] if opts else None
                if best is not None:
                    h = best[1]
                    owner[h] = (lab, n)
                    found[n] = (float(hinges[h, 0]), float(hinges[h, 1]))
                    plan.joints[(lab, n)] = found[n]
                    pending.remove(n)
                    progress = True
    # (b) the joints no line leads to: the free hinges nearest their places
    pins = np.array([*list(plan.pins.values()), plan.pivot])
    free = [i for i in range(len(hinges))
            if np.min(np.hypot(pins[:, 0] - hinges[i, 0], pins[:, 1] - hinges[i, 1])) > 0.3]
    keys = [k for k in plan.expected if k not in plan.joints and k[1] != mech.crank.pin]
    E = np.array([plan.expected[k] for k in keys]).reshape(-1, 2)
    H = hinges[free, :2] if free else np.zeros((0, 2))
    if len(H) and len(E):
        D = np.hypot(E[:, None, 0] - H[None, :, 0], E[:, None, 1] - H[None, :, 1])
        claimed: dict[int, np.ndarray] = {}
        for key, xy in plan.joints.items():  # taken along the links, for its own place
            # (of circles drawn at one place, one each: the places' own circles)
            hit = [int(h) for h in np.flatnonzero(np.hypot(H[:, 0] - xy[0], H[:, 1] - xy[1])
                                                  < 1e-6) if int(h) not in claimed]
            if hit:
                claimed[hit[0]] = np.asarray(plan.expected[key])
        # each hinge once, the whole set's least total distance (crowded joints near a
        # dead centre each at their own circle); then a hinge drawn once for two places
        # where they coincide
        C = np.where(D <= GATE, D, 1e6)
        C[:, list(claimed)] = 1e6
        if len(E) > len(H):
            C = np.hstack([C, np.full((len(E), len(E) - len(H)), 1e6)])
        for ei, hi in enumerate(_hungarian(C)):
            if hi < len(H) and C[ei, hi] < 1e6:
                claimed[hi] = E[ei]
                plan.joints[keys[ei]] = (float(H[hi, 0]), float(H[hi, 1]))
        for ei in np.argsort(D.min(axis=1)):
            key = keys[int(ei)]
            if key in plan.joints:
                continue
            for hi in np.argsort(D[ei]):
                hi = int(hi)
                if D[ei, hi] > GATE:
                    break
                if hi in claimed and float(np.hypot(*(claimed[hi] - E[ei]))) <= 0.5:
                    plan.joints[key] = (float(H[hi, 0]), float(H[hi, 1]))
                    break
    # (c) a second pin of the crank (a throw at 180°: A2 opposite A) is drawn where
    # another position's pin is: the nearest hinge, pins included
    on_crank = set(mech.points_of(mech.crank.link)) - {mech.crank.pin, piv}
    for key in [k for k in plan.expected if k not in plan.joints and k[1] in on_crank]:
        e = np.asarray(plan.expected[key])
        d = np.hypot(hinges[:, 0] - e[0], hinges[:, 1] - e[1])
        if float(d.min()) <= GATE:
            plan.joints[key] = (float(hinges[int(d.argmin()), 0]),
                                float(hinges[int(d.argmin()), 1]))
    # each link with both ends found (the crank from the pivot)
    for lab in labs:
        at = {n: plan.joints[(lab, n)] for n in names if (lab, n) in plan.joints}
        at[mech.crank.pin] = plan.pins[lab]
        at[piv] = plan.pivot
        for f in frames:
            if (lab, f) in plan.joints:
                at[f] = plan.joints[(lab, f)]
        for link in [mech.crank.link, *mech.links]:
            try:
                pts = [q for q in mech.points_of(link) if q in at]
            except (KeyError, ValueError):
                continue
            for a_i, a in enumerate(pts):
                for b in pts[a_i + 1:]:
                    if a in frames and b in frames:
                        continue
                    plan.links[(lab, a + "|" + b)] = (at[a], at[b])


def _angle_finding(plan: PositionPlan, ref, lab: str, d: float, v: str, phi, dead, ok_a,
                   finding):
    """A position drawn at another crank angle than its number's (``d``, rad): an
    ``extreme`` finding at a dead centre, ``other-variant`` elsewhere."""
    from ..words import num

    drawn = math.degrees(plan.angles[lab]) % 360
    exp = math.degrees(phi[lab]) % 360
    extreme = any(abs(_wrap(phi[lab] - dd)) < 1e-6 for dd in dead)
    other = min(phi, key=lambda x: abs(_wrap(plan.angles[lab] - phi[x])))
    also_en = also_ru = ""
    if abs(_wrap(plan.angles[lab] - phi[other])) <= ok_a and other != lab:
        also_en, also_ru = (f" (position {other}'s angle)", f" (угол положения {other})")
    dd_en, dd_ru = num(math.degrees(d), "en", 3), num(math.degrees(d), "ru", 3)
    if extreme:
        en = (f"the extreme position {lab} is drawn with the crank at {num(drawn, 'en', 4)}°"
              f"{also_en}, the dead centre is at φ = {num(exp, 'en', 4)}° ({dd_en}°).")
        ru = (f"крайнее положение {lab} построено при угле кривошипа {num(drawn, 'ru', 4)}°"
              f"{also_ru}, мёртвое положение при φ = {num(exp, 'ru', 4)}° ({dd_ru}°).")
    else:
        en = (f"position {lab} is drawn with the crank at {num(drawn, 'en', 4)}°{also_en}, "
              f"position {lab} is at φ = {num(exp, 'en', 4)}° ({dd_en}°).")
        ru = (f"положение {lab} построено при угле кривошипа {num(drawn, 'ru', 4)}°{also_ru}, "
              f"а положение {lab} при φ = {num(exp, 'ru', 4)}° ({dd_ru}°).")
    return finding(lab, f"φ{lab}", "extreme" if extreme else "other-variant",
                   math.degrees(d), 0.0, "°", en, ru, v)


def judge_position_plan(plan: PositionPlan, scene: Scene, ref, tol, lang: str):
    """The plan of positions against the exact positions (module docstring)."""
    from ..findings import Finding
    from ..words import num
    from .judged import Judged

    mech = ref.mech
    lOA = float(mech.crank.length)
    labels = list(ref.labels)
    phi = {lab: float(ref.kin.phi[k]) for k, lab in enumerate(labels)}
    j = Judged(plan, plan.kl, "plan")  # type: ignore[arg-type]
    j.key = (f"план положений, {plan.where_ru}" if lang == "ru" else
             f"plan of positions {plan.where}")

    def finding(pos, quantity, kind, stated, expected, unit, en, ru, verdict,
                follows=()):
        at = (f"положение {pos}, {j.key}" if lang == "ru" else f"position {pos}, {j.key}") \
            if pos else j.key
        return Finding(where=at, quantity=quantity, stated=stated, expected=expected,
                       unit=unit, kind=kind, verdict=verdict,
                       explanation=ru if lang == "ru" else en, position=pos,
                       line=plan.caption.text, explanation_en=en, explanation_ru=ru,
                       follows_from=tuple(follows))

    # Kl: the drawn crank radius against lOA/Kl
    drawn_kl = lOA / plan.radius
    kl = plan.kl
    scale_cause = None
    if not kl:
        kl = drawn_kl
        j.scale_source = "inferred"
        j.findings.append(finding(
            None, "Kl", "scale", kl, None, "m/mm",
            f"Kl is not written at the plan of positions: it is taken from the crank, "
            f"Kl = lOA/OA = {num(lOA)}/{num(plan.radius, 'en', 4)} = {num(kl, 'en', 4)}.",
            f"Kl у плана положений не указан: он взят по кривошипу, Kl = lOA/OA = "
            f"{num(lOA, 'ru')}/{num(plan.radius, 'ru', 4)} = {num(kl, 'ru', 4)}.", "ok"))
    else:
        r_exp = lOA / kl
        err = abs(plan.radius - r_exp)
        if err > max(tol.segment_ok * r_exp, 0.5 * tol.reading_mm):
            v = "inaccurate" if err <= max(tol.segment * r_exp, tol.reading_mm) else "wrong"
            j.findings.append(finding(
                None, "Kl", "scale", drawn_kl, kl, "m/mm",
                f"the plan of positions is drawn at Kl = {num(drawn_kl, 'en', 4)}, not at "
                f"the Kl = {num(kl)} written: the crank OA is {num(plan.radius, 'en', 4)} "
                f"mm, lOA/Kl = {num(r_exp, 'en', 4)} mm.",
                f"план положений построен в масштабе Kl = {num(drawn_kl, 'ru', 4)}, а не в "
                f"указанном Kl = {num(kl, 'ru')}: кривошип OA {num(plan.radius, 'ru', 4)} мм, "
                f"lOA/Kl = {num(r_exp, 'ru', 4)} мм.", v))
            if v == "wrong":
                scale_cause = "Kl"
                kl = drawn_kl
    plan.kl_used = kl
    j.scale = kl
    # the numbering: each number's crank angle against its position's
    ok_a = max(math.radians(1.0), math.atan(tol.reading_mm / plan.radius))
    band = max(math.radians(2.0), math.atan(2 * tol.reading_mm / plan.radius))
    dev = {lab: _wrap(a - phi[lab]) for lab, a in plan.angles.items() if lab in phi}
    off = [lab for lab, d in dev.items() if abs(d) > band]
    laid_at = {lab: phi[lab] for lab in dev}
    dead = [d % (2 * math.pi) for d in ref.analysis.cycle.dead_centres]

    def nearest_label(a: float) -> str:
        return min(labels, key=lambda lab: abs(_wrap(a - phi[lab])))

    numbered: list[str] = []
    if off:
        shift = float(np.median([dev[lab] for lab in off]))
        agree = [lab for lab in off if abs(_wrap(dev[lab] - shift)) <= band]
        if len(agree) >= max(4, 0.6 * len(dev)):
            numbered = agree
    if numbered:
        first = min(numbered, key=lambda lab: labels.index(lab))
        other = nearest_label(plan.angles[first])
        for lab in numbered:
            laid_at[lab] = plan.angles[lab]
        sdeg = math.degrees(shift)
        j.findings.append(finding(
            None, "№", "label", sdeg, 0.0, "°",
            f"the positions are numbered from another start: {len(numbered)} numbers are "
            f"at a crank angle {num(sdeg, 'en', 3)}° off their positions'; position {first} "
            f"is drawn where the exact position {other} is (φ = "
            f"{num(math.degrees(phi[other]) % 360, 'en', 4)}°).",
            f"положения пронумерованы не от того начала: {len(numbered)} номеров стоят при "
            f"угле кривошипа на {num(sdeg, 'ru', 3)}° от своих положений; положение {first} "
            f"нарисовано там, где точное положение {other} (φ = "
            f"{num(math.degrees(phi[other]) % 360, 'ru', 4)}°).", "wrong"))
    angle_finding: dict[str, int] = {}
    for lab, d in dev.items():
        if lab in numbered or abs(d) <= ok_a:
            continue
        v = "inaccurate" if abs(d) <= band else "wrong"
        if v == "wrong":
            laid_at[lab] = plan.angles[lab]
        angle_finding[lab] = len(j.findings)
        j.findings.append(_angle_finding(plan, ref, lab, d, v, phi, dead, ok_a, finding))
    # the strokes' letters by their arcs
    # the strokes' letters by their arcs
    cy = ref.analysis.cycle
    if cy.dead_centres and plan.strokes:
        sense = mech.crank.sense
        start = cy.dead_centres[0]
        for key, t in plan.strokes:
            a = math.atan2(t.y - plan.pivot[1], t.x - plan.pivot[0])
            along = ((a - start) * sense) % (2 * math.pi)
            working = along <= cy.working_turn
            if working == (key == "working"):
                continue
            j.findings.append(finding(
                None, t.text.strip(), "extreme", None, None, "",
                f"'{t.text.strip()}' is written by the crank's "
                f"{'idle' if working is False else 'working'} stroke: the working stroke "
                f"turns the crank from φ = {num(math.degrees(start) % 360, 'en', 4)}° "
                f"through {num(math.degrees(cy.working_turn), 'en', 4)}°.",
                f"«{t.text.strip()}» написано у дуги "
                f"{'холостого' if working is False else 'рабочего'} хода: рабочий ход — "
                f"поворот кривошипа от φ = {num(math.degrees(start) % 360, 'ru', 4)}° на "
                f"{num(math.degrees(cy.working_turn), 'ru', 4)}°.", "wrong"))
    # the joints and links of every position
    lay_joints(plan, scene, ref, kl, laid_at)
    # a position whose pin is a little off its angle and whose joints are off with it is
    # drawn at that crank angle (a small crank shows the angle less than its links)
    for lab, i in angle_finding.items():
        if j.findings[i].verdict != "inaccurate":
            continue
        mine = [n for (lb, n) in plan.joints if lb == lab]
        if not mine:
            continue
        at = _expected_at(ref, plan.pivot, kl, plan.angles[lab])
        if at is None:
            continue
        err_e = [float(np.hypot(*np.subtract(plan.joints[(lab, n)], plan.expected[(lab, n)])))
                 for n in mine]
        err_d = [float(np.hypot(*np.subtract(plan.joints[(lab, n)], at[n]))) for n in mine]
        if max(err_e) > 2 * tol.reading_mm and max(err_d) <= tol.reading_mm:
            j.findings[i] = replace(j.findings[i], verdict="wrong")
            for n in mine:
                plan.expected[(lab, n)] = at[n]
    follows = (scale_cause,) if scale_cause else ()
    # a position the plan does not draw (no number at the crank circle)
    for lab in labels:
        if lab in plan.pins:
            continue
        at_deg = math.degrees(phi[lab]) % 360
        if any(abs(_wrap(phi[lab] - dd)) < 1e-6 for dd in dead):
            en = (f"the extreme position {lab} is not drawn: no number {lab} at the crank "
                  f"circle (the dead centre at φ = {num(at_deg, 'en', 4)}°).")
            ru = (f"крайнее положение {lab} не построено: у окружности кривошипа нет номера "
                  f"{lab} (мёртвое положение при φ = {num(at_deg, 'ru', 4)}°).")
            kind = "extreme"
        else:
            en = (f"position {lab} is not drawn: no number {lab} at the crank circle "
                  f"(φ = {num(at_deg, 'en', 4)}°).")
            ru = (f"положение {lab} не построено: у окружности кривошипа нет номера {lab} "
                  f"(φ = {num(at_deg, 'ru', 4)}°).")
            kind = "missing"
        j.findings.append(finding(lab, f"φ{lab}", kind, None, at_deg, "°", en, ru, "wrong"))
    _judge_paths(plan, scene, ref, kl, tol, j, finding, follows)
    bad_point: dict[tuple[str, str], str] = {}
    for (lab, name), xy in sorted(plan.joints.items()):
        e = np.asarray(plan.expected[(lab, name)])
        err = float(np.hypot(*(np.asarray(xy) - e)))
        if err <= tol.reading_mm:
            continue
        v = "inaccurate" if err <= 2 * tol.reading_mm else "wrong"
        q = f"•{name}"
        if v == "wrong":
            bad_point[(lab, name)] = q
        j.findings.append(finding(
            lab, q, "point", err, 0.0, "mm",
            f"the joint {name} of position {lab} is {num(err, 'en', 3)} mm from its exact "
            f"place at Kl = {num(kl, 'en', 4)}.",
            f"шарнир {name} положения {lab} в {num(err, 'ru', 3)} мм от точного места при "
            f"Kl = {num(kl, 'ru', 4)}.", v, follows))
    for (lab, link), (ma, mb) in sorted(plan.links.items()):
        pa, pb = link.split("|")
        ea = plan.expected.get((lab, pa), plan.pins[lab] if pa == mech.crank.pin else None)
        eb = plan.expected.get((lab, pb), plan.pins[lab] if pb == mech.crank.pin else None)
        if pa == mech.crank.pivot:
            ea = plan.pivot
        if pb == mech.crank.pivot:
            eb = plan.pivot
        if ea is None or eb is None:
            continue
        le = float(np.hypot(*np.subtract(eb, ea)))
        lm = float(np.hypot(*np.subtract(mb, ma)))
        if {pa, pb} == {mech.crank.pivot, mech.crank.pin}:
            le = lOA / kl  # the crank: its drawn length is the radius read
        err = abs(lm - le)
        if err <= max(tol.segment_ok * le, 0.5 * tol.reading_mm):
            continue
        v = "inaccurate" if err <= max(tol.segment * le, tol.reading_mm) else "wrong"
        cause = bad_point.get((lab, pa)) or bad_point.get((lab, pb))
        name = pa + pb
        j.findings.append(finding(
            lab, name, "model", lm, le, "mm",
            f"the link {name} of position {lab} is drawn {num(lm, 'en', 4)} mm long, "
            f"l_{name}/Kl = {num(le, 'en', 4)} mm.",
            f"звено {name} положения {lab} длиной {num(lm, 'ru', 4)} мм, а "
            f"l_{name}/Kl = {num(le, 'ru', 4)} мм.", v,
            (cause,) if cause else follows))
    return j


def _judge_paths(plan: PositionPlan, scene: Scene, ref, kl: float, tol, j, finding,
                 follows) -> None:
    """The trajectories drawn on the plan against the exact paths
    (:mod:`.trajectories`): each point's curves together, their 95th-percentile distance
    from its path."""
    from ..words import num
    from .trajectories import path_verdict, read_paths, sheet_paths

    plan.exact_paths = sheet_paths(ref, plan.pivot, kl)
    plan.paths = read_paths(scene.drawing.segments, plan.exact_paths,
                            plan.pivot, tol.reading_mm)
    by_point: dict[str, list] = {}
    for p in plan.paths:
        by_point.setdefault(p.point, []).append(p)
    for name, ps in sorted(by_point.items()):
        worst = max(p.worst for p in ps)
        v = path_verdict(worst, tol.reading_mm)
        if v == "ok":
            continue
        j.findings.append(finding(
            None, f"⌒{name}", "point", worst, 0.0, "mm",
            f"the trajectory of {name} is drawn up to {num(worst, 'en', 3)} mm off the exact "
            f"path of {name} at Kl = {num(kl, 'en', 4)}.",
            f"траектория точки {name} проведена до {num(worst, 'ru', 3)} мм от точной "
            f"траектории {name} при Kl = {num(kl, 'ru', 4)}.", v, follows))


__all__ = ["PositionPlan", "find_position_plans", "judge_position_plan", "lay_joints",
           "revolute_joints"]
