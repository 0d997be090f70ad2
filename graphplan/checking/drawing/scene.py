"""The geometry of a drawing as a draftsman reads it: points where lines end, the lines
between them, arrowheads, and the letters placed near the points.

* **Arrowheads** — a small fill (a SOLID, a HATCH, a filled path: an arrowhead drawn as a
  block is exploded into these) or a "V" of two short lines — mark the tip of a vector: a
  line that stops short of a tip on its own line is carried on to the tip.
* **Nodes** are the ends of lines, the ends within :data:`SNAP_MM` of each other taken as
  one point; a line split into pieces or drawn as a polyline gives the same nodes.
* **Letters**: every short text that reads as names (``p``, ``b, s3``, ``nBA``, ``π``) is
  split into its names, and each name is given to the nearest node within reach of the
  text (a few letter heights), preferring a node where lines meet over the loose end of
  a construction line.
  A text joined to its point by a leader line (a short line with no arrowhead running
  away from the text) names the point at the leader's other end.
* **Groups**: lines that touch (an end on another line, or a shared end) are one group
  — one plan, unless the sheet draws plans over each other.
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass, field

from ..units import fold
from .primitives import Drawing, Segment, Text

SNAP_MM = 0.35
"""Ends closer than this are one point (mm)."""
TOUCH_MM = 0.3
"""A node this close to a line lies on it (mm)."""
ARROW_MM = 7.0
"""Largest arrowhead (mm): a line is carried on to a tip at most this far."""
LEADER_MM = 40.0
"""Longest leader line (выноска) from a letter to its point (mm)."""
LEADER_GAP_MM = 3.5
"""A leader may stop this far short of its point (mm)."""
CARRY_MM = 1.0
"""Shortest line carried on to an arrowhead's tip (mm): a vector a little longer than
its head is drawn as a stub and the head."""
STUB_MM = 0.2
"""Shortest stub carried on to a filled arrowhead (mm): a vector a fraction of a
millimetre longer than its head (a "V" of two short lines is not sure enough for that:
a curve drawn as a polyline of short pieces makes such "V"s at every vertex)."""
OPTION_H = 2.0
"""Nodes within this many letter heights of a letter's nearest node are kept as its
other options (for a letter placed between two points)."""

POLE_NAMES = {"p", "π", "п", "pi", "Π"}
"""Letters of the poles of velocity and acceleration plans (after look-alikes are folded)."""

_NAME = re.compile(r"^[A-Za-zА-Яа-яЁёπΠ][A-Za-zА-Яа-яЁёπ0-9_'′ʹ’()]{0,6}$|^\(?\d{1,2}\)?$")


@dataclass(slots=True)
class Node:
    """A point of the drawing where lines end."""

    x: float
    y: float
    ends: int = 0  # line ends here
    passes: int = 0  # lines passing through
    thick: float = 0.0  # the widest line ending here
    tip: bool = False  # an arrowhead points here
    segments: list[int] = field(default_factory=list)

    @property
    def degree(self) -> int:
        return self.ends + 2 * self.passes


@dataclass(frozen=True, slots=True)
class Letter:
    """One name of a text, and the node it names (``None`` if none is near)."""

    name: str
    text: Text
    node: int | None
    distance: float
    options: tuple[int, ...] = ()  # other nodes nearly as near (the nearest first)


def is_names(text: str) -> bool:
    """Whether a text reads as one or more point names (``"b, s3"``)."""
    parts = split_names(text)
    return bool(parts) and all(_NAME.match(p) for p in parts)


def split_names(text: str) -> list[str]:
    return [p for p in re.split(r"[,;\s]+", text.strip()) if p]


class Scene:
    """Nodes, lines, groups and letters of a drawing (see the module docstring)."""

    def __init__(self, drawing: Drawing):
        self.drawing = drawing
        segs = [s for s in drawing.segments if not s.curve and s.length > 1e-6]
        self.arrow_tips = self._tips(segs)
        self.segments = self._carry_to_tips(segs)
        self.segments += self._bare_heads()
        self.nodes: list[Node] = []
        self._grid: dict[tuple[int, int], list[int]] = {}
        self.seg_nodes: list[tuple[int, int]] = []
        for i, s in enumerate(self.segments):
            a = self._node(s.x1, s.y1)
            b = self._node(s.x2, s.y2)
            self.seg_nodes.append((a, b))
            for n in (a, b):
                nd = self.nodes[n]
                nd.ends += 1
                nd.thick = max(nd.thick, s.width)
                nd.segments.append(i)
        self._passes()
        self._mark_tips()
        self.heads = self._heads()
        self.group_of = self._groups()
        self.letters = self._letters()

    # --- arrowheads ---------------------------------------------------------------------

    def _tips(self, segs: list[Segment]) -> list[tuple[tuple[float, float], ...]]:
        """Arrowheads: small fills, and "V"s of two short lines meeting at a tip (as a
        triangle: one end, the tip, the other end)."""
        heads = [f.points for f in self.drawing.fills if _small(f.points)]
        short = [s for s in segs if s.length < ARROW_MM * 0.8]
        ends: dict[tuple[int, int], list[tuple[Segment, int]]] = {}
        for s in short:
            for e, (x, y) in enumerate(((s.x1, s.y1), (s.x2, s.y2))):
                ends.setdefault((round(x / SNAP_MM), round(y / SNAP_MM)), []).append((s, e))
        for lst in ends.values():
            if len(lst) == 2:
                (s1, e1), (s2, e2) = lst
                tip = (s1.x1, s1.y1) if e1 == 0 else (s1.x2, s1.y2)
                o1 = (s1.x2, s1.y2) if e1 == 0 else (s1.x1, s1.y1)
                o2 = (s2.x2, s2.y2) if e2 == 0 else (s2.x1, s2.y1)
                heads.append((o1, tip, o2))
        return heads

    def _bare_heads(self) -> list[Segment]:
        """A vector shorter than its arrowhead is drawn as the head alone: the head's own
        axis (the middle of its base to its tip) stands for the vector's line."""
        # the lines ending at each place, as unit vectors pointing to that end (and the
        # line's other end)
        ends: dict[tuple[int, int], list[tuple[float, float, float, float]]] = {}
        for s in self.segments:
            L = s.length
            for x, y, ox, oy in ((s.x1, s.y1, s.x2, s.y2), (s.x2, s.y2, s.x1, s.y1)):
                ends.setdefault((round(x / SNAP_MM), round(y / SNAP_MM)), []).append(
                    ((x - ox) / L, (y - oy) / L, ox, oy))
        # every head's tip and axis: a line with a head of its own at its far end,
        # pointing away, is a vector starting here (drawn over a short one ending here)
        axes: dict[tuple[int, int], list[tuple[float, float]]] = {}
        for pts in self.arrow_tips:
            if len(pts) < 3:
                continue
            tip = head_tip(pts)
            base = [p for p in pts if abs(p[0] - tip[0]) + abs(p[1] - tip[1]) > 1e-6]
            if base:
                bx = sum(p[0] for p in base) / len(base)
                by = sum(p[1] for p in base) / len(base)
                hl = math.hypot(tip[0] - bx, tip[1] - by)
                if hl > 0:
                    axes.setdefault((round(tip[0] / SNAP_MM), round(tip[1] / SNAP_MM)), []
                                    ).append(((tip[0] - bx) / hl, (tip[1] - by) / hl))

        def headed_away(ux: float, uy: float, ox: float, oy: float) -> bool:
            k = (round(ox / SNAP_MM), round(oy / SNAP_MM))
            around = [(k[0] + i, k[1] + j) for i in (-1, 0, 1) for j in (-1, 0, 1)]
            if sum(len(ends.get(c, ())) for c in around) > 2:
                return False  # a point where many lines end (a pole): whose head is it?
            return any(-ux * ax - uy * ay > 0.9 for c in around for ax, ay in axes.get(c, ()))

        out = []
        for pts in self.arrow_tips:
            if len(pts) < 3:
                continue
            tip = head_tip(pts)
            base = [p for p in pts if abs(p[0] - tip[0]) + abs(p[1] - tip[1]) > 1e-6]
            if not base:
                continue
            bx = sum(p[0] for p in base) / len(base)
            by = sum(p[1] for p in base) / len(base)
            hl = math.hypot(tip[0] - bx, tip[1] - by)
            k = (round(tip[0] / SNAP_MM), round(tip[1] / SNAP_MM))
            # a line that ends at the tip along the head is its vector's; another line
            # ending there (the next vector's start, a construction line) is not
            # (unless the head's tip is where several lines end — a pole: a line with a
            # head at each end, from it, is its own vector's)
            crowded = sum(len(ends.get((k[0] + i, k[1] + j), ()))
                          for i in (-1, 0, 1) for j in (-1, 0, 1)) > 2
            if hl > 0 and any((tip[0] - bx) * ux / hl + (tip[1] - by) * uy / hl > 0.9
                              and (crowded or not headed_away(ux, uy, ox, oy))
                              for i in (-1, 0, 1) for j in (-1, 0, 1)
                              for ux, uy, ox, oy in ends.get((k[0] + i, k[1] + j), ())):
                continue
            if math.hypot(tip[0] - bx, tip[1] - by) < 0.5:
                continue  # a dot, not an arrowhead
            out.append(Segment(bx, by, tip[0], tip[1], width=0.5))
        return out

    def _carry_to_tips(self, segs: list[Segment]) -> list[Segment]:
        """Lines that stop at the base of an arrowhead, carried on to its tip.

        A head carries the line that ends at its base along its axis. Where a line could
        be carried at both ends (a short vector drawn back over another: its end sits
        at the base of the other's head, pointing the other way), the heads go first to
        the lines that reach a head at one end only; a short line (under a head's
        length) is then carried at one end only, the one nearest its head."""
        if not self.arrow_tips:
            return segs
        cell = ARROW_MM
        grid: dict[tuple[int, int], list[int]] = {}
        cents = []
        tips = [head_tip(pts) for pts in self.arrow_tips]
        for h, pts in enumerate(self.arrow_tips):
            cx = sum(p[0] for p in pts) / len(pts)
            cy = sum(p[1] for p in pts) / len(pts)
            cents.append((cx, cy))
            grid.setdefault((int(cx // cell), int(cy // cell)), []).append(h)
        filled = len([f for f in self.drawing.fills if _small(f.points)])  # heads 0…filled-1
        bases = []  # the middle of each head's base: the vertices but its tip
        for h, pts in enumerate(self.arrow_tips):
            base = {(round(p[0], 6), round(p[1], 6)) for p in pts} - {
                (round(tips[h][0], 6), round(tips[h][1], 6))}
            bases.append((sum(p[0] for p in base) / len(base),
                          sum(p[1] for p in base) / len(base)) if base else tips[h])

        end_at: dict[tuple[int, int], list[tuple[float, float, float, float]]] = {}
        for sg in segs:
            for x, y, ox, oy in ((sg.x1, sg.y1, sg.x2, sg.y2), (sg.x2, sg.y2, sg.x1, sg.y1)):
                end_at.setdefault((round(x / SNAP_MM), round(y / SNAP_MM)), []).append(
                    (x, y, ox, oy))
        tip_at: dict[tuple[int, int], list[tuple[int, float, float, float, float]]] = {}
        for h, (tx, ty) in enumerate(tips):
            hx, hy = tx - cents[h][0], ty - cents[h][1]
            hl = math.hypot(hx, hy)
            if hl > 0:
                tip_at.setdefault((round(tx / SNAP_MM), round(ty / SNAP_MM)), []).append(
                    (h, tx, ty, hx / hl, hy / hl))

        def ends_near(x: float, y: float) -> list[tuple[float, float, float, float]]:
            k = (round(x / SNAP_MM), round(y / SNAP_MM))
            return [q for i in (-1, 0, 1) for j in (-1, 0, 1)
                    for q in end_at.get((k[0] + i, k[1] + j), ())
                    if math.hypot(q[0] - x, q[1] - y) <= SNAP_MM]

        def reached(ex: float, ey: float, dx: float, dy: float) -> list[int]:
            """The filled heads whose tip a line's end (pointing out along (dx, dy)) already
            reaches, along its axis (a line drawn through its head to the tip, as CAD
            users draw; the next force starting there leaves at an angle)."""
            k = (round(ex / SNAP_MM), round(ey / SNAP_MM))
            return [h for i in (-1, 0, 1) for j in (-1, 0, 1)
                    for h, tx, ty, ux, uy in tip_at.get((k[0] + i, k[1] + j), ())
                    if h < filled and math.hypot(tx - ex, ty - ey) <= SNAP_MM and
                    ux * dx + uy * dy > 0.99]

        def goes_on(ex: float, ey: float, dx: float, dy: float) -> bool:
            """Whether another line goes on from a line's end along it (a line split into
            pieces: the piece is continued, not stopped at a head)."""
            for _x, _y, ox, oy in ends_near(ex, ey):
                ahead = (ox - ex) * dx + (oy - ey) * dy
                if ahead > SNAP_MM and abs((ox - ex) * dy - (oy - ey) * dx) < 0.02 * ahead:
                    return True
            return False

        def candidates(s: Segment, e: int) -> list[tuple[float, int, float]]:
            """The heads line s may be carried on to at its end e: (how far, head,
            gap between the end and the head), the farthest first."""
            ex, ey = (s.x1, s.y1) if e == 0 else (s.x2, s.y2)
            ox, oy = (s.x2, s.y2) if e == 0 else (s.x1, s.y1)
            L = math.hypot(ex - ox, ey - oy)
            dx, dy = (ex - ox) / L, (ey - oy) / L
            cont = goes_on(ex, ey, dx, dy)
            ci, cj = int(ex // cell), int(ey // cell)
            cand = []
            for di in (-1, 0, 1):
                for dj in (-1, 0, 1):
                    for h in grid.get((ci + di, cj + dj), ()):
                        cx, cy = cents[h]
                        along_c = (cx - ex) * dx + (cy - ey) * dy
                        across_c = abs(-(cx - ex) * dy + (cy - ey) * dx)
                        if not (0 < along_c <= ARROW_MM and across_c < 0.6):
                            continue
                        pts = self.arrow_tips[h]
                        if min(math.hypot(px - ex, py - ey) for px, py in pts) > 1.0:
                            continue
                        gap = math.hypot(bases[h][0] - ex, bases[h][1] - ey)
                        # the head must point on along the line, its tip ahead (the
                        # head of the vector before, whose tip is here, does not)
                        tx, ty = tips[h]
                        far = (tx - ex) * dx + (ty - ey) * dy
                        hx, hy = tx - cx, ty - cy
                        hl = math.hypot(hx, hy)
                        if far <= 0.05 or hl == 0 or (hx * dx + hy * dy) / hl < 0.9:
                            continue
                        cand.append((far, h, gap))
            if cont:  # a piece continued: not to a filled head ("V"s as before)
                cand = [c for c in cand if c[1] >= filled]
            return sorted(cand, key=lambda c: (-c[0], c[1]))


        def alone(x: float, y: float) -> bool:
            """Whether only one line ends here (not a vertex of a polyline)."""
            return len(ends_near(x, y)) == 1

        def carried_on(s: Segment, e: int) -> list[tuple[float, int, float]]:
            if s.length >= CARRY_MM:
                return candidates(s, e)
            # a stub: to a filled head, from its base, where no other line goes on (the
            # pieces of a curve drawn as a polyline pass a head drawn on the curve)
            ex, ey = (s.x1, s.y1) if e == 0 else (s.x2, s.y2)
            if s.length >= STUB_MM and alone(ex, ey):
                return [c for c in candidates(s, e) if c[1] < filled and c[2] <= SNAP_MM]
            return []

        cands = [[carried_on(s, e) for e in (0, 1)] for s in segs]
        # an end already at a head's tip is complete — unless it is also at the base of a
        # head no line reaches the tip of, and the head whose tip it reaches has a line of
        # its own stopping at its base (forces drawn over each other on one line: G2 down
        # to c, G3 back down past c, its head's base by chance at G2's tip)
        at_tip = [[reached(*((sg.x1, sg.y1) if e == 0 else (sg.x2, sg.y2)),
                           *_unit(sg, e)) for e in (0, 1)] for sg in segs]
        tipped: dict[int, set[int]] = {}
        based: dict[int, set[int]] = {}
        for i in range(len(segs)):
            for e in (0, 1):
                for h in at_tip[i][e]:
                    tipped.setdefault(h, set()).add(i)
                for _f, h, _g in cands[i][e]:
                    based.setdefault(h, set()).add(i)
        for i in range(len(segs)):
            for e in (0, 1):
                if at_tip[i][e]:
                    cands[i][e] = [c for c in cands[i][e] if c[1] >= filled or (
                        not tipped.get(c[1], set()) - {i} and
                        all(based.get(h, set()) - {i} for h in at_tip[i][e]))]
        carried: dict[int, list[tuple[float, float]]] = {}  # head → the carried lines' starts
        chosen: list[list[tuple[int, float, float] | None]] = [[None, None] for _ in segs]
        # lines reaching a head at one end first: a head is theirs before a line's that
        # reaches one at each end
        order = sorted(range(len(segs)), key=lambda i: sum(bool(c) for c in cands[i]))
        for i in order:
            s = segs[i]
            both = all(cands[i])
            for e in (0, 1):
                cand = cands[i][e]
                ox, oy = (s.x2, s.y2) if e == 0 else (s.x1, s.y1)
                # one head carries one line: a second line from the same start to the
                # same base (a short vector drawn over a longer one, ending where the
                # longer one's head begins: ps3 on pb) ends at the base, unless it has a
                # head of its own there (vectors drawn over each other: pa, pc, ps4);
                # a line with a head in reach at each end leaves a head another line
                # was carried to
                best = max((f for f, _h, _g in cand), default=0.0)
                for far, h, gap in cand:
                    if far < best - SNAP_MM:
                        break
                    if both and carried.get(h):
                        continue
                    if not any(math.hypot(ox - qx, oy - qy) <= SNAP_MM
                               for qx, qy in carried.get(h, ())):
                        chosen[i][e] = (h, far, gap)
                        break
            # a stub shorter than a head between two heads pointing apart (a short
            # vector's stub by the head of the vector drawn back over it) is its own
            # head's: the one whose base it meets (nearest the middle of the base)
            if all(chosen[i]) and s.length < ARROW_MM:
                keep = min((0, 1), key=lambda e: chosen[i][e][2])  # type: ignore[index]
                chosen[i][1 - keep] = None
            for e, c in enumerate(chosen[i]):
                if c is not None:
                    carried.setdefault(c[0], []).append(
                        (s.x2, s.y2) if e == 0 else (s.x1, s.y1))
        out = []
        for s, ch in zip(segs, chosen, strict=True):
            ends = [(s.x1, s.y1), (s.x2, s.y2)]
            L = s.length
            for e, c in enumerate(ch):
                if c is None:
                    continue
                ex, ey = ends[e]
                ox, oy = ends[1 - e]
                dx, dy = (ex - ox) / L, (ey - oy) / L
                ends[e] = (ex + c[1] * dx, ey + c[1] * dy)
            if any(ch):
                out.append(Segment(ends[0][0], ends[0][1], ends[1][0], ends[1][1], s.colour,
                                   s.width, s.layer))
            else:
                out.append(s)
        return out

    # --- nodes --------------------------------------------------------------------------

    def _mark_tips(self) -> None:
        """Nodes an arrowhead points at: the vertex of a head farthest from the others."""
        for pts in self.arrow_tips:
            if len(pts) < 3:
                continue
            tip = head_tip(pts)
            ci, cj = math.floor(tip[0] / SNAP_MM), math.floor(tip[1] / SNAP_MM)
            for di in (-2, -1, 0, 1, 2):
                for dj in (-2, -1, 0, 1, 2):
                    for n in self._grid.get((ci + di, cj + dj), ()):
                        nd = self.nodes[n]
                        if math.hypot(nd.x - tip[0], nd.y - tip[1]) <= 2 * SNAP_MM:
                            nd.tip = True

    def _heads(self) -> list[tuple[bool, bool]]:
        """For each line, whether an arrowhead sits on its start and on its end, pointing
        along the line (in a polygon of forces every vertex is some arrow's tip: the
        sense of a force is its own arrowhead's)."""
        heads = []
        for pts in self.arrow_tips:
            if len(pts) < 3:
                continue
            tip = head_tip(pts)
            xs = [p[0] for p in pts]
            ys = [p[1] for p in pts]
            if max(xs) - min(xs) > ARROW_MM or max(ys) - min(ys) > ARROW_MM:
                continue
            cx, cy = sum(xs) / len(xs), sum(ys) / len(ys)
            L = math.hypot(tip[0] - cx, tip[1] - cy)
            if L > 0:
                heads.append((tip, ((tip[0] - cx) / L, (tip[1] - cy) / L)))
        cell = 2.0
        grid: dict[tuple[int, int], list[int]] = {}
        for h, (tip, _u) in enumerate(heads):
            grid.setdefault((math.floor(tip[0] / cell), math.floor(tip[1] / cell)), []
                            ).append(h)
        out = []
        for s in self.segments:
            L = s.length
            flags = []
            for ex, ey, ox, oy in ((s.x1, s.y1, s.x2, s.y2), (s.x2, s.y2, s.x1, s.y1)):
                dx, dy = (ex - ox) / L, (ey - oy) / L
                ci, cj = math.floor(ex / cell), math.floor(ey / cell)
                hit = False
                for di in (-1, 0, 1):
                    for dj in (-1, 0, 1):
                        for h in grid.get((ci + di, cj + dj), ()):
                            (tx, ty), (ux, uy) = heads[h]
                            if math.hypot(tx - ex, ty - ey) < 0.5 and ux * dx + uy * dy > 0.95:
                                hit = True
                flags.append(hit)
            out.append((flags[0], flags[1]))
        return out

    def _node(self, x: float, y: float) -> int:
        ci, cj = math.floor(x / SNAP_MM), math.floor(y / SNAP_MM)
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                for n in self._grid.get((ci + di, cj + dj), ()):
                    nd = self.nodes[n]
                    if math.hypot(nd.x - x, nd.y - y) <= SNAP_MM:
                        return n
        self.nodes.append(Node(x, y))
        n = len(self.nodes) - 1
        self._grid.setdefault((ci, cj), []).append(n)
        return n

    def _seg_cells(self, s: Segment, cell: float):
        i0, i1 = sorted((int(s.x1 // cell), int(s.x2 // cell)))
        j0, j1 = sorted((int(s.y1 // cell), int(s.y2 // cell)))
        if (i1 - i0 + 1) * (j1 - j0 + 1) > 4000:
            return
        for i in range(i0, i1 + 1):
            for j in range(j0, j1 + 1):
                yield (i, j)

    def _passes(self) -> None:
        """Count the lines passing through each node (not ending there)."""
        cell = 5.0
        grid: dict[tuple[int, int], list[int]] = {}
        for i, s in enumerate(self.segments):
            for c in self._seg_cells(s, cell):
                grid.setdefault(c, []).append(i)
        self._seg_grid = grid
        self.on_segment: list[list[int]] = [[] for _ in self.nodes]
        self._interior: dict[int, list[int]] = {}
        for n, nd in enumerate(self.nodes):
            for i in grid.get((int(nd.x // cell), int(nd.y // cell)), ()):
                if n in self.seg_nodes[i]:
                    continue
                if point_segment(nd.x, nd.y, self.segments[i]) <= TOUCH_MM:
                    nd.passes += 1
                    self.on_segment[n].append(i)
                    self._interior.setdefault(i, []).append(n)

    def _groups(self) -> list[int]:
        parent = list(range(len(self.segments)))

        def find(i):
            while parent[i] != i:
                parent[i] = parent[parent[i]]
                i = parent[i]
            return i

        def union(a, b):
            ra, rb = find(a), find(b)
            if ra != rb:
                parent[ra] = rb

        for n, nd in enumerate(self.nodes):
            segs = nd.segments + self.on_segment[n]
            for i in segs[1:]:
                union(segs[0], i)
        return [find(i) for i in range(len(self.segments))]

    def node_group(self, n: int) -> int:
        return self.group_of[self.nodes[n].segments[0]]

    @staticmethod
    def _swap(cands, choice, rounds: int = 4) -> None:
        """Two texts that would each be nearer the other's node swap nodes (letters set
        off the same way from points in a row: each text is nearest the next point)."""
        cost_of = [{n: c for c, n, _d in lst} for _t, lst in cands]
        dist_of = [{n: d for _c, n, d in lst} for _t, lst in cands]
        by_node: dict[int, list[int]] = {}
        for i, b in enumerate(choice):
            if b is not None:
                for n in cost_of[i]:
                    by_node.setdefault(n, []).append(i)
        for _ in range(rounds):
            changed = False
            for i, b in enumerate(choice):
                if b is None:
                    continue
                near = {k for n in cost_of[i] for k in by_node.get(n, ()) if k != i}
                for k in near:
                    bk = choice[k]
                    if bk is None or bk[1] == b[1]:
                        continue
                    ni, nk = b[1], bk[1]
                    if nk in cost_of[i] and ni in cost_of[k]:
                        now = cost_of[i][ni] + cost_of[k][nk]
                        then = cost_of[i][nk] + cost_of[k][ni]
                        if then < now - 1e-9:
                            choice[i] = (cost_of[i][nk], nk, dist_of[i][nk])
                            choice[k] = (cost_of[k][ni], ni, dist_of[k][ni])
                            b = choice[i]
                            changed = True
            if not changed:
                break

    def _overshoot(self, n: int) -> bool:
        """A loose end of lines that run on past a point (construction lines drawn
        through a point and a little beyond it — one line, or several ending together,
        like the direction lines drawn through a pole): no arrowhead here or on them,
        and each runs through another node near this end."""
        nd = self.nodes[n]
        if nd.tip:
            return False
        if nd.ends == 1:
            return bool(self._interior.get(nd.segments[0]))
        for i in nd.segments:
            if any(self.heads[i]):
                return False
            s = self.segments[i]
            near = min((math.hypot(self.nodes[m].x - nd.x, self.nodes[m].y - nd.y)
                        for m in self._interior.get(i, ())), default=math.inf)
            if near > max(10.0, 0.35 * s.length):
                return False
        return True

    def _leaders(self) -> tuple[dict[int, tuple[int, float]], set[int]]:
        """Leader lines of point names (see :meth:`leader_lines`). The text names the point
        at the leader's other end — where it touches other lines, or the node nearest that
        end on the leader's line run on (a leader stops a little short of its point).
        Returns, per text (by its index in the drawing), the node named and the leader's
        length, and the leaders' own loose ends (no point is there)."""
        named: dict[int, tuple[int, float]] = {}
        own: set[int] = set()
        for ti, (i, na, nb) in self.leader_lines(is_names).items():
            target = self._leader_target(nb, na, self.nodes[nb], self.nodes[na])
            if target is None:
                continue
            named[ti] = (target, self.segments[i].length)
            own.add(na)
            if nb != target:
                own.add(nb)
        return named, own

    def leader_lines(self, which, slack: float = 0.0) -> dict[int, tuple[int, int, int]]:
        """Leader lines (выноски) of the texts ``which(text)`` accepts: a short thin line
        with no arrowhead and no point on it, one free end at the text's box (within half
        a letter height, and ``slack`` letter heights more), running away from the text.
        Per text (by its index in the drawing): the line, its end at the text and its far
        end (nodes)."""
        out: dict[int, tuple[int, int, int]] = {}
        cell = 5.0
        # a leader is drawn as a thin line: none thicker than the thinnest lines drawn
        thin = min((s.width for s in self.segments if s.length > 1.0), default=0.0)
        for ti, t in enumerate(self.drawing.texts):
            if len(t.text) > 24 or not which(t.text):
                continue
            half_w = 0.35 * t.height * len(t.text)
            a = math.radians(t.angle)
            ca, sa = math.cos(a), math.sin(a)

            def box_d(x: float, y: float, t=t, ca=ca, sa=sa, half_w=half_w) -> float:
                u = (x - t.x) * ca + (y - t.y) * sa
                v = -(x - t.x) * sa + (y - t.y) * ca
                return math.hypot(max(abs(u) - half_w, 0.0), max(abs(v) - 0.5 * t.height, 0.0))

            best: tuple[float, int, int, int] | None = None
            r = int((half_w + LEADER_MM) // cell) + 1
            ci, cj = int(t.x // cell), int(t.y // cell)
            seen: set[int] = set()
            for di in range(-r, r + 1):
                for dj in range(-r, r + 1):
                    for i in self._seg_grid.get((ci + di, cj + dj), ()):
                        if i in seen:
                            continue
                        seen.add(i)
                        s = self.segments[i]
                        if not 1.0 <= s.length <= LEADER_MM or any(self.heads[i]) or \
                                s.width > 1.2 * thin + 1e-6 or self._crossed(i):
                            continue
                        na, nb = self.seg_nodes[i]
                        da, db = box_d(s.x1, s.y1), box_d(s.x2, s.y2)
                        if db < da:
                            na, nb, da, db = nb, na, db, da
                        near, far = self.nodes[na], self.nodes[nb]
                        # one end at the text's box, the line running away from the text
                        if da > (0.5 + slack) * t.height + 0.3 or db < da + 1.0 or \
                                (far.x - near.x) * (near.x - t.x) + \
                                (far.y - near.y) * (near.y - t.y) <= 0 or \
                                near.ends != 1 or near.passes or near.tip:
                            continue
                        if best is None or da < best[0]:
                            best = (da, i, na, nb)
            if best is not None:
                out[ti] = best[1:]
        return out

    def _crossed(self, i: int) -> bool:
        """Whether a point lies on line i: a node where lines meet or an arrowhead points
        (not a line drawn along it, not another line's loose end just touching it)."""
        for m in self._interior.get(i, ()):
            nd = self.nodes[m]
            if nd.tip:
                return True
            if nd.ends < 2:
                continue
            # the lines ending here, as unit vectors pointing away from the node
            out = []
            for j in nd.segments:
                q = self.segments[j]
                sgn = 1.0 if math.hypot(q.x1 - nd.x, q.y1 - nd.y) < \
                    math.hypot(q.x2 - nd.x, q.y2 - nd.y) else -1.0
                out.append((sgn * (q.x2 - q.x1) / q.length, sgn * (q.y2 - q.y1) / q.length))
            ox, oy = out[0]
            if all(abs(ox * qy - oy * qx) <= 0.02 for qx, qy in out[1:]) and \
                    any(ox * qx + oy * qy < 0 for qx, qy in out[1:]):
                continue  # pieces of one straight line meeting on it
            return True
        return False

    def _leader_target(self, nb: int, na: int, far: Node, near: Node) -> int | None:
        """The node a leader from ``near`` to ``far`` points at (see :meth:`_leaders`)."""
        others = [i for i in far.segments if set(self.seg_nodes[i]) != {na, nb}]
        if far.tip or len(others) >= 2 or any(any(self.heads[i]) for i in others):
            return nb  # drawn to the point itself
        L = math.hypot(far.x - near.x, far.y - near.y)
        ux, uy = (far.x - near.x) / L, (far.y - near.y) / L
        reach = LEADER_GAP_MM
        ci, cj = math.floor(far.x / SNAP_MM), math.floor(far.y / SNAP_MM)
        k = int(reach / SNAP_MM) + 1
        best: tuple[float, int] | None = None
        for di in range(-k, k + 1):
            for dj in range(-k, k + 1):
                for m in self._grid.get((ci + di, cj + dj), ()):
                    if m in (na, nb):
                        continue
                    nd = self.nodes[m]
                    dx, dy = nd.x - far.x, nd.y - far.y
                    d = math.hypot(dx, dy)
                    if d > reach or dx * ux + dy * uy < -0.3 * d:
                        continue  # too far, or behind the leader's end
                    across = abs(-dx * uy + dy * ux)
                    score = 0.5 * (dx * ux + dy * uy) + 3.0 * across  # aimed at it
                    if best is None or score < best[0]:
                        best = (score, m)
        if best is not None:
            return best[1]
        return nb if far.passes or others else None

    def is_join(self, n: int) -> bool:
        """Whether node n is only where pieces of one straight line meet (a line split in
        two, a polyline's vertex on a straight run, with perhaps a construction line drawn
        along it): no arrowhead, every line ending at or passing through it parallel."""
        nd = self.nodes[n]
        if nd.tip or nd.ends != 2:
            return False
        dirs = []
        for i in nd.segments + self.on_segment[n]:
            s = self.segments[i]
            L = s.length
            if L <= 0:
                return False
            dirs.append(((s.x2 - s.x1) / L, (s.y2 - s.y1) / L))
        ux, uy = dirs[0]
        return all(abs(ux * vy - uy * vx) < 0.01 for vx, vy in dirs[1:])

    # --- letters ------------------------------------------------------------------------

    def _letters(self) -> list[Letter]:
        """Each text of names to a node: the nearest one within reach of the text's box
        (a point where lines meet counts as a little nearer, the loose end of a line run
        on past a point as much farther). Texts are placed in order of how sure they are,
        and a node another text already names is taken only when no other node is
        nearly as near (two texts rarely name one point)."""
        cell = 5.0
        grid: dict[tuple[int, int], list[int]] = {}
        for n, nd in enumerate(self.nodes):
            grid.setdefault((int(nd.x // cell), int(nd.y // cell)), []).append(n)
        leaders, leader_ends = self._leaders()
        cands: list[tuple[Text, list[tuple[float, int, float]]]] = []
        for ti, t in enumerate(self.drawing.texts):
            if not is_names(t.text):
                continue
            names = split_names(t.text)
            # a pole alone (with other names, arrows of points at the pole may end there)
            pole = len(names) == 1 and fold(names[0]) in POLE_NAMES
            half_w = 0.35 * t.height * len(t.text)
            reach = 3.0 * t.height + 3.0  # from the text's box
            a = math.radians(t.angle)
            ca, sa = math.cos(a), math.sin(a)
            r = int((reach + half_w) // cell) + 1
            ci, cj = int(t.x // cell), int(t.y // cell)
            lst = []
            for di in range(-r, r + 1):
                for dj in range(-r, r + 1):
                    for n in grid.get((ci + di, cj + dj), ()):
                        if n in leader_ends:
                            continue  # a leader's own end: no point is there
                        nd = self.nodes[n]
                        u = (nd.x - t.x) * ca + (nd.y - t.y) * sa
                        v = -(nd.x - t.x) * sa + (nd.y - t.y) * ca
                        dv = max(abs(v) - 0.5 * t.height, 0.0)
                        d = math.hypot(max(abs(u) - half_w, 0.0), dv)
                        if len(names) > 1:
                            # a point named by a list is by its first or its last name,
                            # not under the middle of the list
                            w1 = 0.35 * t.height * len(names[0])
                            w2 = 0.35 * t.height * len(names[-1])
                            d1 = math.hypot(max(abs(u + half_w - w1) - w1, 0.0), dv)
                            d2 = math.hypot(max(abs(u - half_w + w2) - w2, 0.0), dv)
                            d = min(d1, d2, d + 0.8 * t.height)
                        if d > reach:
                            continue
                        cost = d - 0.25 * t.height * min(nd.degree - 1, 2)
                        if self._overshoot(n):
                            cost += 2.5 * t.height
                        elif self.is_join(n):  # where one line's pieces meet: no point
                            cost += 1.0 * t.height
                        if pole:  # vectors start at a pole: no arrowhead points there
                            # (a pole where many vectors start may be some short one's tip)
                            cost += 2.0 * t.height if nd.tip and nd.ends <= 2 else 0.0
                            cost -= 0.25 * t.height * min(max(nd.ends - 3, 0), 4)
                        elif nd.tip:
                            cost -= 0.3 * t.height
                        lst.append((cost, n, d))
            if ti in leaders:  # the leader's point before any point near the text
                n, length = leaders[ti]
                lst = [(-1.0 * t.height, n, length), *(c for c in lst if c[1] != n)]
            lst.sort()
            cands.append((t, lst))
        cands.sort(key=lambda c: c[1][0][0] if c[1] else math.inf)
        claimed: dict[int, int] = {}
        choice: list[tuple[float, int, float] | None] = []
        for i, (t, lst) in enumerate(cands):
            best = None
            for cost, n, d in lst:
                c = cost + (1.5 * t.height if n in claimed else 0.0)
                if best is None or c < best[0]:
                    best = (c, n, d)
            choice.append(best)
            if best is not None:
                claimed.setdefault(best[1], i)
        self._swap(cands, choice)
        out = []
        for (t, lst), best in zip(cands, choice, strict=True):
            node, dist = (best[1], best[2]) if best else (None, math.inf)
            opts = tuple(n for c, n, _d in lst if c <= best[0] + OPTION_H * t.height
                         and n != node) if best else ()
            for name in split_names(t.text):
                out.append(Letter(name, t, node, dist, (node, *opts) if node is not None
                                  else ()))
        return out


@functools.lru_cache(maxsize=65536)
def _tip(pts: tuple) -> tuple[float, float]:
    uniq: list[tuple[float, float]] = []
    for p in pts:
        if all(abs(p[0] - q[0]) + abs(p[1] - q[1]) > 1e-6 for q in uniq):
            uniq.append(p)
    return max(uniq, key=lambda p: sum(math.hypot(p[0] - q[0], p[1] - q[1]) for q in uniq))


def _unit(s: Segment, e: int) -> tuple[float, float]:
    """The direction out of segment s at its end e."""
    L = s.length
    return ((s.x1 - s.x2) / L, (s.y1 - s.y2) / L) if e == 0 else \
        ((s.x2 - s.x1) / L, (s.y2 - s.y1) / L)


def _small(pts) -> bool:
    """Whether a fill is small enough to be an arrowhead (the fills come first among
    :attr:`Scene.arrow_tips`)."""
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    return max(xs) - min(xs) <= ARROW_MM and max(ys) - min(ys) <= ARROW_MM


def head_tip(pts) -> tuple[float, float]:
    """The tip of an arrowhead: of its distinct vertices, the one farthest from the
    others (a closed outline repeats its first vertex)."""
    return _tip(tuple(tuple(p) for p in pts))


def point_segment(px: float, py: float, s: Segment) -> float:
    """Distance from a point to a segment (mm)."""
    dx, dy = s.x2 - s.x1, s.y2 - s.y1
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((px - s.x1) * dx + (py - s.y1) * dy) / L2))
    return math.hypot(px - s.x1 - t * dx, py - s.y1 - t * dy)


__all__ = ["ARROW_MM", "SNAP_MM", "TOUCH_MM", "Letter", "Node", "Scene", "is_names",
           "point_segment", "split_names"]
