"""Force plans and the arm h21 on a drawing, found by the names written along their lines.

A **force plan** is a polygon of forces laid head to tail: each force a line with its
name written beside it (``R43``, ``Q``, ``G3``, ``Pи3``, ``Rτ12``; a text may name several
forces drawn on one line, ``Rn12, R12``). A text of force names is given to the nearest
line (a line split into collinear pieces is taken whole); lines so named that touch form
one plan, and a group counts as a plan only when most of its forces meet others end to end
(the forces drawn on a scheme of the mechanism do not). Its scale is the ``Kp = …``
(``μF``, ``μP``) written at it or in its caption; its position the caption's, else the
position whose forces it fits best.

**h21** is the line nearest the text ``h21`` — the perpendicular from the crank's pivot to
the line of R21 on the scheme of the position — measured at the scheme's ``Kl``.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ..units import fold
from .plans import Boxed, caption_kind, caption_position, stated_scales
from .scene import Scene, point_segment, split_names

_FORCE = re.compile(r"^(?:R[τtnⁿ]?\d\d|G\d{1,2}|(?:Pи|Pu|Фи|Ф|Fи|Pin)\d{1,2}|Q\d{0,2}|"
                    r"[FP][а-яё]{1,3}\d{0,2}|F(?:pc|ps|g|c)\d{0,2})$")
"""A force's name: a reaction (``R43``, ``Rτ12``, ``Rn12``), a weight (``G3``), a force of
inertia (``Pи3``, ``Фи3``), the working load (``Q``, ``Fпс``, ``Pпс``), a gas or liquid
force (``Fг2``, ``Fж``)."""


_CRANK = re.compile(r"звена 1\b|звено 1\b|кривошип|\blink 1\b|\bcrank", re.IGNORECASE)
"""A caption of the crank's own scheme."""


def is_force_name(name: str) -> bool:
    return bool(_FORCE.match(fold(name)))


_TANGENTIAL = re.compile(r"R\^?[tτ](\d\d)")
_NORMAL = re.compile(r"R\^?[nⁿ](\d\d)")
_INERTIA = re.compile(r"(?:P|F|Ф)\^?(?:и|u|in)(\d{1,2})")


def canonical_name(name: str) -> str:
    """A force's name as graphplan writes it, from the ways students write it: ``Rt43``,
    ``R^t43`` → ``Rτ43``; ``R^n12`` → ``Rn12``; ``Fи3``, ``Фи3``, ``Pu3``, ``Pin3`` →
    ``Pи3`` (the calculation's vocabulary knows graphplan's names only)."""
    f = fold(name)
    if m := _TANGENTIAL.fullmatch(f):
        return f"Rτ{m[1]}"
    if m := _NORMAL.fullmatch(f):
        return f"Rn{m[1]}"
    if m := _INERTIA.fullmatch(f):
        return f"Pи{m[1]}"
    return name


_FOOTNOTE = "*∗"
"""A footnote's mark after a force's name (``G4*``): the footnote says the force is too
short to draw at the plan's scale and gives it in newtons — its name names no line."""


def _names(text: str, footnoted: bool = True) -> list[str]:
    """The force names of a text; without those marked by a footnote unless asked."""
    return [canonical_name(n.rstrip(_FOOTNOTE)) for n in split_names(text)
            if n.rstrip(_FOOTNOTE) and (footnoted or n[-1] not in _FOOTNOTE)]


@dataclass(slots=True)
class DrawnForce:
    """A force's line on the drawing: its ends (mm, the tip second when an arrowhead
    shows it, ``sense`` then True) and the segments it is made of."""

    name: str
    start: tuple[float, float]
    end: tuple[float, float]
    sense: bool
    segments: tuple[int, ...]
    options: tuple[DrawnForce, ...] = ()  # other lines the name is nearly as near

    @property
    def length(self) -> float:
        return math.hypot(self.end[0] - self.start[0], self.end[1] - self.start[1])


@dataclass(slots=True)
class FoundForcePlan(Boxed):
    """A force plan found on the drawing."""

    group: int
    forces: dict[str, DrawnForce]
    bbox: tuple[float, float, float, float]
    caption: object = None
    position: str | None = None
    kp: float | None = None
    kind: str = "force"
    closure_mm: float | None = None
    notes: list[str] = field(default_factory=list)
    unnamed: list[DrawnForce] = field(default_factory=list)  # arrows drawn, no name read


def _whole_line(scene: Scene, i: int) -> tuple[list[int], int, int]:
    """The segment i carried on through collinear pieces (ends met by nothing else)."""
    segs = [i]
    a, b = scene.seg_nodes[i]
    s = scene.segments[i]
    d = (s.x2 - s.x1, s.y2 - s.y1)
    L = math.hypot(*d)
    ends = [a, b]
    for k in (0, 1):
        n = ends[k]
        cur = i
        for _ in range(50):
            nd = scene.nodes[n]
            others = [j for j in nd.segments if j != cur]
            # lines passing through along this one (forces drawn over each other on one
            # line, G2 down, Pи2 back up over it) do not cross it
            # nor does a line merely ending on this one (a name's leader overshooting it)
            crossing = [j for j in scene.on_segment[n] if not _along(scene.segments[j], d, L)
                        and _across(scene.segments[j], nd, d, L)]
            if nd.ends != 2 or crossing or len(others) != 1 or nd.tip:
                break  # a vertex, a crossing, or where one vector ends and the next begins
            j = others[0]
            t = scene.segments[j]
            e = (t.x2 - t.x1, t.y2 - t.y1)
            if abs(d[0] * e[1] - d[1] * e[0]) > 0.01 * L * math.hypot(*e):
                break
            segs.append(j)
            p, q = scene.seg_nodes[j]
            n = q if p == n else p
            cur = j
        ends[k] = n
    return segs, ends[0], ends[1]


def _across(t, nd, d: tuple[float, float], L: float) -> bool:
    """Whether segment t passing through node nd goes across the line of direction d (of
    length L) there: both its ends a millimetre or more off that line."""
    def off(x: float, y: float) -> float:
        return abs((x - nd.x) * d[1] - (y - nd.y) * d[0]) / L

    return min(off(t.x1, t.y1), off(t.x2, t.y2)) >= 1.0


def _along(t, d: tuple[float, float], L: float) -> bool:
    """Whether segment t runs along direction d (of length L), within 2°: a line passing
    at so small an angle is drawn over this one, not across it."""
    e = (t.x2 - t.x1, t.y2 - t.y1)
    return abs(d[0] * e[1] - d[1] * e[0]) <= 0.035 * L * math.hypot(*e)


def _nearest_line(scene: Scene, t, min_len: float = 2.0, forces: bool = True) -> int | None:
    """The line a text names: the nearest (a force's name is beside the middle of its
    arrow; a construction line, without an arrowhead, only when nothing else is near)."""
    near = _lines_near(scene, t, min_len, forces)
    return near[0][1] if near else None


def _lines_near(scene: Scene, t, min_len: float = 2.0, forces: bool = True
                ) -> list[tuple[float, int]]:
    """The lines within reach of a text, as (cost, segment), the likeliest first."""
    half_w = 0.35 * t.height * len(t.text)
    reach = 3.0 * t.height + half_w + 2.0
    out: list[tuple[float, int]] = []
    whole: dict[int, tuple[float, float, float, float, bool]] = {}
    for i, s in enumerate(scene.segments):
        if s.length < min_len:
            continue
        if min(s.x1, s.x2) - reach > t.x or max(s.x1, s.x2) + reach < t.x or \
                min(s.y1, s.y2) - reach > t.y or max(s.y1, s.y2) + reach < t.y:
            continue
        d = point_segment(t.x, t.y, s)
        if d > reach:
            continue
        if not forces:
            # an arm: a thin line from a pivot ending square on a force's line — not a
            # force's own arrow (R61 drawn into the pivot is square to the arm too)
            cost = d - (3.0 if _foot(scene, i) else 0.0) - (3.0 if _at_pivot(scene, s)
                                                            else 0.0)
            if any(scene.heads[i]):
                cost += 3.0 * t.height
            out.append((cost, i))
            continue
        # a force's name is written beside the middle of its line: along a long line,
        # beside its middle part; a short line's name (crowded out) within a few letters
        # of its middle, from the text's box. The line is taken whole: a line split into
        # pieces (a polyline through its middle) has its name by its pieces' ends
        if i not in whole:
            segs, na, nb = _whole_line(scene, i)
            whole[i] = (scene.nodes[na].x, scene.nodes[na].y, scene.nodes[nb].x,
                        scene.nodes[nb].y, any(any(scene.heads[j]) for j in segs))
        x1, y1, x2, y2, headed = whole[i]
        L2 = max((x2 - x1) ** 2 + (y2 - y1) ** 2, 1e-12)
        along = ((t.x - x1) * (x2 - x1) + (t.y - y1) * (y2 - y1)) / L2
        mx, my = (x1 + x2) / 2, (y1 + y2) / 2
        mid_box = math.hypot(max(abs(mx - t.x) - half_w, 0.0),
                             max(abs(my - t.y) - 0.5 * t.height, 0.0))
        if abs(along - 0.5) > 0.4 and mid_box > 3.0 * t.height:
            continue
        mid = math.hypot(t.x - mx, t.y - my)
        cost = d + 0.25 * mid if abs(along - 0.5) <= 0.4 else \
            max(d, mid_box) + 0.25 * mid + 0.5 * t.height
        if not headed:
            cost += 3.0 * t.height  # a construction line, not a force's arrow
        out.append((cost, i))
    return sorted(out)


def _at_pivot(scene: Scene, s) -> bool:
    """Whether a line starts at a drawn joint (a small circle): an arm from a pivot."""
    return any(c.r <= 3.0 and min(math.hypot(c.x - s.x1, c.y - s.y1),
                                  math.hypot(c.x - s.x2, c.y - s.y2)) <= 0.5
               for c in scene.drawing.circles)


def _foot(scene: Scene, i: int) -> bool:
    """Whether line i ends square on another line (an arm: the perpendicular from a
    point to a force's line)."""
    s = scene.segments[i]
    L = s.length
    for n in scene.seg_nodes[i]:
        for j in scene.on_segment[n] + [k for k in scene.nodes[n].segments if k != i]:
            t = scene.segments[j]
            M = t.length
            if M <= 0:
                continue
            dot = ((s.x2 - s.x1) * (t.x2 - t.x1) + (s.y2 - s.y1) * (t.y2 - t.y1)) / (L * M)
            if abs(dot) < 0.05:
                return True
    return False


def _drawn(scene: Scene, i: int) -> DrawnForce:
    """The force drawn along segment i (carried on through its collinear pieces): its
    ends, the tip second when its own arrowhead shows the sense."""
    segs, a, b = _whole_line(scene, i)
    na, nb = scene.nodes[a], scene.nodes[b]
    at_a = any(scene.heads[j][k] for j in segs for k in (0, 1) if scene.seg_nodes[j][k] == a)
    at_b = any(scene.heads[j][k] for j in segs for k in (0, 1) if scene.seg_nodes[j][k] == b)
    if at_a and not at_b:
        na, nb = nb, na
    return DrawnForce("", (na.x, na.y), (nb.x, nb.y), at_a != at_b, tuple(segs))


def find_force_plans(scene: Scene) -> list[FoundForcePlan]:
    """The force plans of a drawing (see the module docstring)."""
    by_group: dict[int, dict[str, DrawnForce]] = {}
    texts = []
    leaders = scene.leader_lines(_is_forces, slack=0.4)  # a sheared italic's corner
    leader_segs = {lead[0] for lead in leaders.values()}  # another name's leader names none
    cells = _table_entries(scene)
    for ti, t in enumerate(scene.drawing.texts):
        if ti in cells or not _is_forces(t.text):
            continue
        names = _names(t.text, footnoted=False)
        if not names:
            continue
        near = [c for c in _lines_near(scene, t, min_len=0.8) if c[1] not in leader_segs]
        if ti in leaders:
            led = _led_to(scene, *leaders[ti])
            near = led + [c for c in near if all(c[1] != k for _c, k in led) and
                          c[1] != leaders[ti][0]]
        if near:
            texts.append((t, names, near))
    lines_of = _assign(scene, texts)
    for (t, names, near), first in zip(texts, lines_of, strict=True):
        g = scene.group_of[first]
        # the other lines the text is nearly as near, of the same plan: in a crowded
        # polygon the name may stand nearer a neighbour's line (judged against the
        # construction, one name to a line)
        best = next(c for c, k in near if k == first)
        lines = [first] + [k for c, k in near[:8] if k != first and
                           c <= best + 2.0 * t.height + 2.0 and scene.group_of[k] == g]
        drawn: list = []
        for k in lines:
            f = _drawn(scene, k)
            if all(f.segments != o.segments for o in drawn):
                drawn.append(f)
        for n in names:
            by_group.setdefault(g, {}).setdefault(
                n, DrawnForce(n, drawn[0].start, drawn[0].end, drawn[0].sense,
                              drawn[0].segments, tuple(drawn[1:])))
    plans = []
    members: dict[int, list[int]] = {}
    for i, gg in enumerate(scene.group_of):
        members.setdefault(gg, []).append(i)
    for g, forces in by_group.items():
        if len(forces) < 2:
            continue
        named = {k for f in forces.values() for k in f.segments}
        unnamed: list[DrawnForce] = []
        seen: set[tuple[int, ...]] = set()
        for i in members[g]:
            if i not in named and any(scene.heads[i]) and scene.segments[i].length >= 0.8:
                f = _drawn(scene, i)
                if f.segments not in seen and not named & set(f.segments):
                    seen.add(f.segments)
                    unnamed.append(f)
        if not _laid_head_to_tail(forces, unnamed):
            continue
        ends = [p for f in forces.values() for p in (f.start, f.end)]
        xs = [p[0] for p in ends]
        ys = [p[1] for p in ends]
        fp = FoundForcePlan(g, forces, (min(xs), min(ys), max(xs), max(ys)))
        fp.unnamed = unnamed
        fp.closure_mm = _closure(forces, fp.unnamed)
        plans.append(fp)
    _captions(scene, plans)
    return [p for p in plans if p.kind == "force"]


def _laid_head_to_tail(forces: dict[str, DrawnForce], unnamed: list[DrawnForce]) -> bool:
    """Whether named lines form a force polygon: the forces are laid head to tail, so most
    ends of the named lines meet another line's end (an arrow drawn without a name — a
    force too short to name, named in a footnote — carries the chain on), and somewhere
    one force's tip is another's tail. Forces drawn from their points of application on
    a scheme of the mechanism meet tail to tail only. A plan is a few forces, a few of
    them too short to name: a curve's names on a diagram among its hundreds of ordinates
    and hatching strokes (whose ends meeting the curve look like heads) are not a plan."""
    lines: list[DrawnForce] = []
    for f in forces.values():
        if all(f.segments != g.segments for g in lines):
            lines.append(f)
    if len(unnamed) > 10 * len(forces):
        return False
    every = lines + list(unnamed)

    def ends(f: DrawnForce):
        # (point, role): the tail first; a line without its own head shows no sense
        return ((f.start, "tail" if f.sense else None), (f.end, "tip" if f.sense else None))

    met = 0
    head_to_tail = False
    for f in lines:
        for p, role in ends(f):
            at = [r for g in every if g is not f for q, r in ends(g)
                  if math.hypot(p[0] - q[0], p[1] - q[1]) < 0.5]
            met += bool(at)
            head_to_tail |= any(role is None or r is None or r != role for r in at)
    return head_to_tail and met >= 0.6 * 2 * len(lines)


def _table_entries(scene: Scene) -> set[int]:
    """The texts written in a table's cells (a force's name in a table of the forces is
    not a name on a line): a text boxed by lines without arrowheads — a horizontal line
    above and below it, a vertical one left and right, within two letter heights of its
    box, closing a cell round it."""
    hs: list[tuple[float, float, float]] = []  # x from, x to, y
    vs: list[tuple[float, float, float]] = []  # y from, y to, x
    for i, s in enumerate(scene.segments):
        L = s.length
        if L < 2.0 or any(scene.heads[i]):
            continue
        if abs(s.y2 - s.y1) <= 0.01 * L:
            hs.append((min(s.x1, s.x2), max(s.x1, s.x2), 0.5 * (s.y1 + s.y2)))
        elif abs(s.x2 - s.x1) <= 0.01 * L:
            vs.append((min(s.y1, s.y2), max(s.y1, s.y2), 0.5 * (s.x1 + s.x2)))
    out: set[int] = set()
    if len(hs) < 2 or len(vs) < 2:
        return out
    for ti, t in enumerate(scene.drawing.texts):
        if t.angle % 180.0 or not _is_forces(t.text):
            continue
        half_w, half_h = 0.35 * t.height * len(t.text), 0.5 * t.height
        reach = 2.0 * t.height
        above = [y for x0, x1, y in hs if 0 < y - t.y <= half_h + reach and
                 x0 <= t.x - half_w and x1 >= t.x + half_w]
        below = [y for x0, x1, y in hs if 0 < t.y - y <= half_h + reach and
                 x0 <= t.x - half_w and x1 >= t.x + half_w]
        if not above or not below:
            continue
        top, foot = min(above), max(below)
        left = [x for y0, y1, x in vs if 0 < t.x - x <= half_w + reach and
                y0 <= foot + 0.3 and y1 >= top - 0.3]
        right = [x for y0, y1, x in vs if 0 < x - t.x <= half_w + reach and
                 y0 <= foot + 0.3 and y1 >= top - 0.3]
        if left and right:
            out.add(ti)
    return out


def _is_forces(text: str) -> bool:
    names = _names(text)
    return bool(names) and all(is_force_name(n) for n in names)


def _led_to(scene: Scene, i: int, na: int, nb: int) -> list[tuple[float, int]]:
    """The lines a force's name on a leader names: the arrows passing within 3 mm of the
    point the leader is aimed at (2 mm on from its end: a name's leader starts just off
    the middle of its force), the nearest (then the one whose middle is nearest) first,
    before any line merely near the text."""
    near, far = scene.nodes[na], scene.nodes[nb]
    L = math.hypot(far.x - near.x, far.y - near.y)
    ax = far.x + 2.0 * (far.x - near.x) / L
    ay = far.y + 2.0 * (far.y - near.y) / L
    out = []
    for k, s in enumerate(scene.segments):
        if k == i or s.length < 0.8 or not any(scene.heads[k]):
            continue
        d = point_segment(ax, ay, s)
        if d <= 3.0:
            # the middle of the whole line (a line in pieces has its name by its middle,
            # not by a piece's)
            _segs, na_, nb_ = _whole_line(scene, k)
            mx = (scene.nodes[na_].x + scene.nodes[nb_].x) / 2
            my = (scene.nodes[na_].y + scene.nodes[nb_].y) / 2
            mid = math.hypot(ax - mx, ay - my)
            out.append((-100.0 + d + 0.1 * mid, k))
    return sorted(out)


def _assign(scene: Scene, texts) -> list[int]:
    """Each text's line: the nearest, texts placed surest first; a line another text
    already names is taken only when no other line is nearly as near (two texts rarely
    name one force's line: a text lists the forces drawn on one line)."""
    order = sorted(range(len(texts)), key=lambda i: texts[i][2][0][0])
    taken: dict[tuple[int, ...], int] = {}
    out = [texts[i][2][0][1] for i in range(len(texts))]
    for i in order:
        t, _names, near = texts[i]
        best = None
        for c, k in near:
            whole = _whole_line(scene, k)[0]
            key = tuple(sorted(whole))
            cc = c + (1.5 * t.height if key in taken else 0.0)
            if best is None or cc < best[0]:
                best = (cc, k, key)
        assert best is not None
        out[i] = best[1]
        taken.setdefault(best[2], i)
    return out


def _closure(forces: dict[str, DrawnForce], unnamed=()) -> float | None:
    """The gap of the polygon (mm): the distance between its two loose ends when the
    forces drawn (one line per place) leave exactly two, else ``None``. Arrows drawn in
    the polygon whose names were not read (``unnamed``: a force too short to name, a
    name not read) carry a loose end on: to the other loose end, the polygon is closed;
    to another force's end, its shape is not read (``None``)."""
    lines: list[DrawnForce] = []
    for f in forces.values():
        if not any(f.segments == g.segments for g in lines):
            lines.append(f)
    loose = _loose(lines)
    if len(loose) != 2:
        return None
    ends = [p for f in lines for p in (f.start, f.end)]

    def at(p, q, tol: float = 0.5) -> bool:
        return math.hypot(p[0] - q[0], p[1] - q[1]) < tol

    # a force shorter than its arrowhead is drawn as a stub whose ends stand within about
    # a millimetre (twice the reading) of the polygon's corners, not on them
    stub = 1.0
    for a, b in ((loose[0], loose[1]), (loose[1], loose[0])):
        left = [f for f in unnamed if f.length > 0]
        end = a
        for _ in range(3):
            nxt = min((f for f in left if at(f.start, end, stub) or at(f.end, end, stub)),
                      key=lambda f: min(math.dist(f.start, end), math.dist(f.end, end)),
                      default=None)
            if nxt is None:
                break
            left.remove(nxt)
            end = nxt.end if math.dist(nxt.start, end) <= math.dist(nxt.end, end) \
                else nxt.start
            if at(end, b, stub):
                return 0.0
            if any(at(end, p) for p in ends):
                return None
    return math.hypot(loose[0][0] - loose[1][0], loose[0][1] - loose[1][1])


def _loose(lines: list[DrawnForce]) -> list[tuple[float, float]]:
    """The ends of lines that meet no other line's end."""
    pts: list[tuple[float, float]] = []
    count: list[int] = []
    for f in lines:
        for p in (f.start, f.end):
            for k, q in enumerate(pts):
                if math.hypot(p[0] - q[0], p[1] - q[1]) < 0.5:
                    count[k] += 1
                    break
            else:
                pts.append(p)
                count.append(1)
    return [p for p, c in zip(pts, count, strict=True) if c == 1]


def _captions(scene: Scene, plans: list[FoundForcePlan]) -> None:
    """Each plan's caption: the nearest above it (a caption below counts three times as
    far) within reach, else the nearest above it in its column (a sheet in rows, its
    captions along the top of each row); captions and plans one to one, nearest pairs
    first. A plan's position is its caption's, else the one a caption on the same line
    names (the row's «Схема, пол. 4» above the row's force plans)."""
    scales = stated_scales(scene.drawing.texts)
    caps = [(t, k) for t in scene.drawing.texts if (k := caption_kind(t.text))
            in ("force", "scheme", "lever") and len(t.text) >= 6]
    pairs = []
    for i, p in enumerate(plans):
        x0, y0, x1, y1 = p.bbox
        reach = 0.5 * math.hypot(x1 - x0, y1 - y0) + 40.0
        for j, (t, _k) in enumerate(caps):
            dx = max(x0 - t.x, 0.0, t.x - x1)
            dy = max(y0 - t.y, 0.0, t.y - y1)
            d = math.hypot(dx, dy) * (3.0 if t.y < y0 else 1.0)
            if d <= reach:
                pairs.append((d, i, j))
            elif t.y > y1 and dx <= 40.0 and t.y - y1 <= 250.0:
                pairs.append((1000.0 + (t.y - y1) + dx, i, j))  # the column's caption
    done_p: set[int] = set()
    done_c: set[int] = set()
    for _d, i, j in sorted(pairs):
        if i in done_p or j in done_c:
            continue
        done_p.add(i)
        done_c.add(j)
        t, kind = caps[j]
        p = plans[i]
        p.caption = t
        p.kind = kind
        p.position = caption_position(t.text)
        if p.position is None:
            row = [c for c, _k in caps if abs(c.y - t.y) <= 0.5 * max(t.height, 1.0) and
                   caption_position(c.text) is not None]
            if row:
                p.position = caption_position(min(row, key=lambda c: abs(c.x - t.x)).text)
    for p in plans:
        own = [s for s in scales if s.symbol == "Kp" and (s.text is p.caption or _near(
            s.text, p.bbox, 12.0))]
        if own:
            p.kp = own[0].value


def _near(t, bbox, reach: float) -> bool:
    x0, y0, x1, y1 = bbox
    return math.hypot(max(x0 - t.x, 0.0, t.x - x1), max(y0 - t.y, 0.0, t.y - y1)) <= reach


@dataclass(frozen=True, slots=True)
class DrawnArm:
    """h21 as drawn: its length (mm), the scheme's position and Kl, where it is."""

    length: float
    position: str | None
    kl: float | None
    x: float
    y: float


def find_h21(scene: Scene) -> list[DrawnArm]:
    """Every ``h21`` drawn on the schemes of the mechanism."""
    out = []
    scales = stated_scales(scene.drawing.texts)
    for t in scene.drawing.texts:
        if fold(t.text).strip().lower() not in ("h21", "h₂₁"):
            continue
        i = _nearest_line(scene, t, min_len=0.5, forces=False)
        if i is None:
            continue
        _segs, a, b = _whole_line(scene, i)
        na, nb = scene.nodes[a], scene.nodes[b]
        length = math.hypot(nb.x - na.x, nb.y - na.y)
        # its scheme's caption: the nearest above it (one below counts three times as
        # far), a caption of the crank's own scheme (where h21 is drawn) at half the
        # distance — a crank drawn large puts its caption far from the arm
        cap = None
        for c in scene.drawing.texts:
            if caption_kind(c.text) != "scheme" or caption_position(c.text) is None:
                continue
            d = math.hypot(c.x - t.x, c.y - t.y) * (3.0 if c.y < t.y else 1.0)
            if _CRANK.search(c.text):
                d *= 0.5
            if d < 150 and (cap is None or d < cap[0]):
                cap = (d, c)
        kl = None
        if cap:
            own = [s for s in scales if s.symbol == "Kl" and s.text is cap[1]]
            kl = own[0].value if own else None
        out.append(DrawnArm(length, caption_position(cap[1].text) if cap else None, kl,
                            t.x, t.y))
    return out


__all__ = ["DrawnArm", "DrawnForce", "FoundForcePlan", "find_force_plans", "find_h21",
           "is_force_name"]
