"""The trajectories drawn on a plan of all positions, against the exact paths.

A sheet 1 traces the paths of points over the turn on its plan of positions (thin
dash-dot curves: the crank pin's circle, the centres of mass' closed curves, a coupler
point's шатунная кривая through its positions). They are read as a draftsman reads them:

1. **The curves** — chains of drawn pieces joined end to end (a polyline, a spline or an
   arc as its pieces, a curve of short lines drawn by hand; where other lines end on it,
   followed on by the piece running straightest on, turning less than 30°), cut where
   they turn by more than 60° at once, that bend (a vertex farther than 0,3 mm off the
   chord), span more than 8 mm and are of six pieces or more, none longer than 0,4 of
   the span: a link (straight, or split into collinear pieces, or run on into the next
   through a joint), a joint's circle, a slider's block and a zigzag of hatching are
   not. (A dashed curve is one entity with a line type, or one path with a dash
   pattern, in DXF, SVG and PDF alike.)
2. **Whose path** — each curve's vertices against the exact path of every moving point
   (one turn of the crank in 360 steps), laid from the drawn pivot at the Kl the plan is
   read at: the point whose path is nearest along the curve (the median distance of its
   vertices) is the one it traces.
3. **Judged** — the curve's distance from that path, the 95th percentile over its
   vertices (a curve drawn through the positions' points as a polyline is right at
   them): ok within the reading precision, inaccurate within twice it, wrong beyond (a
   ``point`` finding, quantity ``⌒S2``).

Not judged: an arc about the crank's pivot that keeps farther than twice the reading from
every path — the strokes' arcs ``р.х.``/``х.х.``, the crank's rotation arrow — and a
curve farther than :data:`GATE` from every path (a curve of something else). An arc
about a rocker's pivot is judged: a centre of mass' arc drawn at another radius is a
wrong trajectory (an angle's arc drawn within :data:`GATE` of a path would be read as
one).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

GATE = 10.0  #: a curve farther than this (median, mm) from every exact path traces none
MIN_SPAN = 8.0  #: a curve's smallest extent, mm (a joint's circle is smaller)
BEND = 0.3  #: a curve's farthest vertex off its chord, at least, mm


@dataclass(frozen=True, slots=True)
class DrawnPath:
    """A curve read on the plan of positions: its vertices (mm), the point whose exact
    path it follows best, its median and 95th-percentile distances from that path (mm)."""

    points: np.ndarray
    point: str
    median: float
    worst: float


def drawn_curves(segments, box: tuple[float, float, float, float]) -> list[np.ndarray]:
    """The bending chains of pieces inside ``box`` (x0, y0, x1, y1; mm), each as its
    vertices in order (module docstring, 1)."""
    x0, y0, x1, y1 = box
    segs = [s for s in segments if s.length > 1e-6 and
            x0 <= min(s.x1, s.x2) and max(s.x1, s.x2) <= x1 and
            y0 <= min(s.y1, s.y2) and max(s.y1, s.y2) <= y1]
    key: dict[tuple[int, int], int] = {}
    at: list[list[int]] = []  # the pieces at each node
    xy: list[tuple[float, float]] = []

    def node(x: float, y: float) -> int:
        k = (round(x * 50), round(y * 50))  # 0.02 mm
        if k not in key:
            key[k] = len(xy)
            xy.append((x, y))
            at.append([])
        return key[k]

    ends: list[tuple[int, int]] = []
    once: set[tuple[int, int]] = set()
    for s in segs:
        a, b = node(s.x1, s.y1), node(s.x2, s.y2)
        # a path drawn there and back over the same points (a rocker's) counts once
        if a == b or (min(a, b), max(a, b)) in once:
            continue
        once.add((min(a, b), max(a, b)))
        i = len(ends)
        ends.append((a, b))
        at[a].append(i)
        at[b].append(i)
    used = [False] * len(ends)
    chains: list[list[int]] = []
    for i in range(len(ends)):
        if used[i]:
            continue
        used[i] = True
        nodes = list(ends[i])
        for forward in (True, False):
            while True:
                n = nodes[-1] if forward else nodes[0]
                prev = nodes[-2] if forward else nodes[1]
                free = [j for j in at[n] if not used[j]]
                if not free:
                    break
                if len(at[n]) == 2:
                    j = free[0]
                else:
                    # where other lines end on it (a link at the point's positions), the
                    # curve goes on by the piece running straightest on, turning < 30°
                    j, c = _straightest(xy, ends, free, prev, n)
                    if c < 0.866:
                        break
                used[j] = True
                a, b = ends[j]
                nxt = b if a == n else a
                if forward:
                    nodes.append(nxt)
                else:
                    nodes.insert(0, nxt)
                if nxt == (nodes[0] if forward else nodes[-1]):
                    break  # closed
        chains.append(nodes)
    pieces = [q for c in chains for q in _smooth_runs(np.array([xy[n] for n in c], float))]
    return [p for p in pieces if _bends(p)]


def _straightest(xy, ends, free: list[int], prev: int, n: int) -> tuple[int, float]:
    """Of the pieces ``free`` at node ``n``, the one running on straightest from the
    piece ``prev``→``n``, and the cosine of its turn."""
    u = np.subtract(xy[n], xy[prev])
    u = u / max(float(np.hypot(*u)), 1e-12)
    best = (free[0], -2.0)
    for j in free:
        a, b = ends[j]
        v = np.subtract(xy[b if a == n else a], xy[n])
        c = float(np.dot(u, v)) / max(float(np.hypot(*v)), 1e-12)
        if c > best[1]:
            best = (j, c)
    return best


def _thinned(p: np.ndarray, step: float = 0.15) -> np.ndarray:
    """The chain's vertices less those within ``step`` mm of the last kept (a path
    sampled finely where its point moves slowly turns by noise between them); its last
    vertex kept."""
    keep = [0]
    for i in range(1, len(p)):
        if float(np.hypot(*(p[i] - p[keep[-1]]))) >= step:
            keep.append(i)
    if keep[-1] != len(p) - 1:
        if len(keep) > 1:
            keep[-1] = len(p) - 1  # the end in place of the last kept, within step of it
        else:
            keep.append(len(p) - 1)
    return p[keep]


def _smooth_runs(p: np.ndarray) -> list[np.ndarray]:
    """A chain cut at its corners (a turn of more than 60°): a curve turns gently, while
    a slider's block, a zigzag of hatching or a line run on into a curve turn at once
    (a cusp of a coupler curve leaves two runs, each on the same path)."""
    p = _thinned(p)
    if len(p) < 3:
        return [p]
    d = np.diff(p, axis=0)
    u = d / np.hypot(d[:, 0], d[:, 1])[:, None]
    cos = (u[1:] * u[:-1]).sum(axis=1)
    cuts = [int(i) + 1 for i in np.flatnonzero(cos < 0.5)]
    out, start = [], 0
    for c in cuts:
        out.append(p[start:c + 1])
        start = c
    out.append(p[start:])
    return out


def _bends(p: np.ndarray) -> bool:
    """A curve: wide enough, not straight, of six pieces or more each short beside its
    span (links run on through a joint where only their two lines meet are not)."""
    if len(p) < 7:
        return False
    lo, hi = p.min(axis=0), p.max(axis=0)
    span = float(np.hypot(*(hi - lo)))
    if span < MIN_SPAN or float(np.hypot(*np.diff(p, axis=0).T).max()) > 0.4 * span:
        return False
    a, b = p[0], p[-1]
    if float(np.hypot(*(b - a))) < 1e-6:  # closed: not straight
        return True
    u = (b - a) / float(np.hypot(*(b - a)))
    off = np.abs((p[:, 0] - a[0]) * u[1] - (p[:, 1] - a[1]) * u[0])
    return float(off.max()) > BEND


def distance_to_path(pts: np.ndarray, path: np.ndarray) -> np.ndarray:
    """The distance of each of ``pts`` from the polyline ``path`` (mm)."""
    a, b = path[:-1], path[1:]
    d = b - a
    L2 = np.maximum((d ** 2).sum(axis=1), 1e-12)
    w = pts[:, None, :] - a[None, :, :]
    t = np.clip((w * d[None]).sum(axis=2) / L2[None], 0.0, 1.0)
    q = a[None] + t[..., None] * d[None]
    return np.sqrt(((pts[:, None, :] - q) ** 2).sum(axis=2)).min(axis=1)


def _about(p: np.ndarray, c, tol: float) -> bool:
    """An arc about ``c``: every vertex at one distance from it."""
    r = np.hypot(p[:, 0] - c[0], p[:, 1] - c[1])
    return float(r.max() - r.min()) <= tol


def read_paths(segments, paths: dict[str, np.ndarray], pivot, reading: float
               ) -> list[DrawnPath]:
    """The curves drawn near the exact ``paths`` (name → (N, 2) mm, laid on the sheet),
    each with the point whose path it traces (module docstring, 2); ``pivot``: the
    crank's pivot as drawn, mm."""
    if not paths:
        return []
    allp = np.concatenate(list(paths.values()))
    lo, hi = allp.min(axis=0) - 15.0, allp.max(axis=0) + 15.0
    out = []
    for c in drawn_curves(segments, (lo[0], lo[1], hi[0], hi[1])):
        best = None
        for name, path in paths.items():
            d = distance_to_path(c, path)
            med = float(np.median(d))
            if best is None or med < best[0]:
                best = (med, name, d)
        if best is None:
            continue
        med, name, d = best
        if med > GATE:
            continue
        if med > 2 * reading and _about(c, pivot, max(reading, 0.3)):
            continue
        out.append(DrawnPath(c, name, med, float(np.percentile(d, 95))))
    return out


def sheet_paths(ref, pivot, kl: float) -> dict[str, np.ndarray]:
    """The exact path of every moving point over one turn, laid from the drawn ``pivot``
    at ``kl`` (mm on the sheet); points that do not move (frame points) left out."""
    mech = ref.mech
    P = ref.analysis.one_turn.pos.points
    o = np.asarray(P[mech.crank.pivot][0], float)
    out = {}
    for name, xy in P.items():
        if name in mech.frame_points:
            continue
        q = np.asarray(pivot, float) + (np.asarray(xy, float) - o) / kl
        if float(np.ptp(q[:, 0])) + float(np.ptp(q[:, 1])) < 1.0:
            continue
        out[name] = q
    return out


def path_verdict(worst: float, reading: float) -> str:
    """ok within the reading, inaccurate within twice it, wrong beyond."""
    if worst <= reading:
        return "ok"
    return "inaccurate" if worst <= 2 * reading else "wrong"


__all__ = ["GATE", "DrawnPath", "distance_to_path", "drawn_curves", "path_verdict",
           "read_paths", "sheet_paths"]
