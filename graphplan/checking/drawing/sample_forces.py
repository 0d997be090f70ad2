"""Force plans drawn the way students draw them, for trying the drawing checker (issue 22).

:func:`student_force_sheet` draws the force plans of some positions of a variant — every
group's and the crank's, as sheet 2 builds them (:meth:`Analysis.force_plans`) — not with
graphplan's sheet code but as a student draws them in a CAD program or with a plotting
library:

* **DXF** (ezdxf), as a КОМПАС or AutoCAD user draws: each force a line split in two, a
  polyline through three points or a two-point polyline; arrowheads INSERTs of a block
  holding a SOLID; the names written as such a user writes them — MTEXT with its index
  stacked (``R\\S^ 12;``, ``R\\Sτ^ 43;`` for R^τ_43, ``F\\Sи^ 3;`` for Pи3 written Fи3),
  MTEXT with font and height codes, or plain TEXT ``Rt43``; captions «Положение 2. План
  сил группы 2–3» and the scale as ``μF = 200 Н/мм`` or ``Kp = 0,2 кН/мм``; the whole
  5 m from the origin, in mm or in inches.
* **PDF** by matplotlib's PDF backend (not graphplan's Typst path): forces as lines
  with filled arrowheads, the names in mathtext (``$R^{\\tau}_{43}$``: glyphs set one by
  one, the index stacked under the superscript), captions ``План сил группы 2–3, пол. 2``.

:class:`ForcePlant` puts one error of a student into a plan: a vertex of the polygon
moved (the forces meeting there wrong), the scale written twice the one drawn at, a force
left out of the polygon (closed all the same: the reactions found wrong), the plan of
another position drawn under the caption, or two names swapped.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

SHORT_MM = 2.0
"""A force shorter than this (mm) is drawn as a short line without a name."""
STUB_MM = 0.8
"""A force shorter than this (mm) is drawn as a bare line (a dot on paper)."""
HEAD_MM = 3.0
"""An arrowhead's length (mm, a third of it wide); a force shorter than twice it gets a
head half its length."""


def _head(length: float) -> float:
    return min(HEAD_MM, 0.5 * length)


@dataclass(frozen=True, slots=True)
class ForcePlant:
    """One error to put into a force plan.

    ``kind``: ``moved`` (the vertex where ``force`` ends moved ``offset`` mm along it:
    ``force`` and the forces from that vertex wrong), ``scale`` (Kp written ``factor``
    times the one drawn at), ``omit`` (``force`` left out of the polygon, the polygon
    closed without it), ``position`` (the plan of position ``other`` drawn at the same
    Kp under this position's caption) or ``swap`` (the names ``force`` and ``other``
    written at each other's lines). ``plan``: which plan of the position, in sheet 2's
    order (the groups from the last, then the crank).
    """

    kind: str
    position: str
    plan: int
    force: str = ""
    other: str = ""
    offset: float = 3.2
    factor: float = 2.0


@dataclass(slots=True)
class _Plan:
    """A force plan as it is to be drawn (plan mm, y up)."""

    position: str
    group: str
    kp: float  # the scale it is drawn at, N/mm
    written: float  # the scale written
    vectors: list[tuple[str, np.ndarray, np.ndarray]]
    lines: list[tuple[np.ndarray, np.ndarray]]
    names: dict[str, str]  # force → the name written at its line

    @property
    def caption(self) -> str:
        if self.group.startswith("crank"):
            return f"План сил кривошипа, положение {self.position}"
        return f"План сил группы {self.group.split('(')[-1].rstrip(')')}, положение " \
               f"{self.position}"

    def extent(self, lines: bool = True) -> tuple[float, float, float, float]:
        """(x0, y0, x1, y1) of the forces, and of the construction lines with ``lines``."""
        pts = [q for _n, a, b in self.vectors for q in (a, b)]
        pts += [q for a, b in self.lines for q in (a, b)] if lines else []
        xs = [float(q[0]) for q in pts]
        ys = [float(q[1]) for q in pts]
        return min(xs), min(ys), max(xs), max(ys)


def _vectors(p) -> list[tuple[str, np.ndarray, np.ndarray]]:
    out, seen = [], set()
    for st in p.steps:
        for e in st.elements:
            if e.kind == "segment" and e.name not in seen and e.role != "arm" and \
                    math.dist(e.start, e.end) > 1e-9:
                seen.add(e.name)
                out.append((e.name, np.asarray(e.start, float), np.asarray(e.end, float)))
    return out


def _lines(p) -> list[tuple[np.ndarray, np.ndarray]]:
    return [(np.asarray(e.start, float), np.asarray(e.end, float))
            for st in p.steps for e in st.elements if e.kind == "line"]


def _vertex(p, xy) -> str:
    return min(p.points, key=lambda n: float(np.hypot(*(np.asarray(p.points[n]) - xy))))


def _roles(p) -> dict[str, str]:
    return {e.name: e.role for st in p.steps for e in st.elements if e.kind == "segment"}


def omitted(p, force: str) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """The vectors of force plan ``p`` drawn with ``force`` (a load or a tangential
    component) left out of its polygon and the polygon closed all the same: the forces
    after it laid on from where it began, the closing reactions met again on their own
    lines (two: where their lines cross; one: from the chain's end back to its start), the
    other reactions drawn between the vertices they join.

    Raises
    ------
    ValueError
        If the force is a reaction, or the polygon is not closed so.
    """
    chain = list(p.polygons["group"])
    roles = _roles(p)
    names = [q for q, _a, _b in chain]
    if force not in names or roles.get(force) == "reaction":
        raise ValueError(f"{force} is no load of the polygon")
    tail: list[str] = []
    for q, _a, _b in reversed(chain):
        if roles.get(q) != "reaction":
            break
        tail.insert(0, q)
    if len(tail) not in (1, 2):
        raise ValueError("the polygon is not closed by one or two reactions")
    pts = {n: np.asarray(v, float).copy() for n, v in p.points.items()}
    i = names.index(force)
    _q, a, b = chain[i]
    shift = pts[a] - pts[b]
    for _q, _s, e in chain[i:len(chain) - len(tail)]:
        pts[e] = np.asarray(p.points[e], float) + shift
    start = chain[0][1]
    if len(tail) == 2:
        (_q1, e1, f1), (_q2, f2, s2) = chain[-2], chain[-1]
        d1 = np.asarray(p.points[f1]) - np.asarray(p.points[e1])
        d2 = np.asarray(p.points[s2]) - np.asarray(p.points[f2])
        A = np.array([d1, -d2]).T
        if abs(np.linalg.det(A)) < 1e-9 * (np.hypot(*d1) * np.hypot(*d2) + 1e-12):
            raise ValueError("the closing lines are parallel")
        t = np.linalg.solve(A, pts[s2] - pts[e1])
        f_new = pts[e1] + t[0] * d1
        for n, v in p.points.items():  # every vertex at the closing point moves with it
            if np.allclose(v, p.points[f1]):
                pts[n] = f_new
    del start
    out = []
    for name, s, e in _vectors(p):
        if name == force:
            continue
        out.append((name, pts[_vertex(p, s)], pts[_vertex(p, e)]))
    return out


def _moved(p, force: str, offset: float) -> list[tuple[str, np.ndarray, np.ndarray]]:
    vs = _vectors(p)
    s, e = next((a, b) for n, a, b in vs if n == force)
    u = (e - s) / float(np.hypot(*(e - s)))
    out = []
    for n, a, b in vs:
        a2 = a + offset * u if np.allclose(a, e) else a
        b2 = b + offset * u if np.allclose(b, e) else b
        out.append((n, a2, b2))
    return out


def _layout(ref, labels, plant: ForcePlant | None) -> list[_Plan]:
    out = []
    for lab in labels:
        plans = ref.analysis.force_plans(ref.index(lab))
        for i, p in enumerate(plans):
            kp = p.scale.per_mm
            vectors, lines = _vectors(p), _lines(p)
            written = kp
            names = {n: n for n, _a, _b in vectors}
            if plant and plant.position == lab and plant.plan % len(plans) == i:
                if plant.kind == "scale":
                    written = kp * plant.factor
                elif plant.kind == "moved":
                    vectors, lines = _moved(p, plant.force, plant.offset), []
                elif plant.kind == "omit":
                    vectors, lines = omitted(p, plant.force), []
                    names.pop(plant.force, None)
                elif plant.kind == "position":  # at its own Kp, written
                    q = ref.analysis.force_plans(ref.index(plant.other))[i]
                    kp = written = q.scale.per_mm
                    vectors, lines = _vectors(q), _lines(q)
                    names = {n: n for n, _a, _b in vectors}
                elif plant.kind == "swap":
                    names[plant.force], names[plant.other] = plant.other, plant.force
                else:
                    raise ValueError(f"unknown plant {plant.kind!r}")
            out.append(_Plan(lab, p.group, kp, written, vectors, lines, names))
    return out


def _points(a: np.ndarray, b: np.ndarray, step: float = 0.5) -> np.ndarray:
    n = 2 + int(float(np.hypot(*(b - a))) / step)
    return a + np.linspace(0.0, 1.0, n)[:, None] * (b - a)


def _labels(plan: _Plan) -> list[tuple[str, np.ndarray, tuple | None]]:
    """Each name to write, the centre of its text (plan mm) and its leader (or None), set
    beside the middle of its line as a careful student sets it: on the side, and as
    little out, where it is clearly nearer its own line than any other line and clear of
    the names already written; where lines crowd, out on a leader. Forces drawn on one
    line (both ends within 1.5 mm) get one text (``Rn12, R12``); forces under
    :data:`SHORT_MM` none."""
    groups: list[tuple[list[str], np.ndarray, np.ndarray]] = []
    for n, a, b in plan.vectors:
        if n not in plan.names or float(np.hypot(*(b - a))) < SHORT_MM:
            continue
        for names, a0, b0 in groups:
            if (np.hypot(*(a - a0)) < 1.5 and np.hypot(*(b - b0)) < 1.5) or \
                    (np.hypot(*(a - b0)) < 1.5 and np.hypot(*(b - a0)) < 1.5):
                names.append(plan.names[n])
                break
        else:
            groups.append(([plan.names[n]], a, b))
    lines = [(a, b) for _n, a, b in plan.vectors] + list(plan.lines)
    boxes: list[tuple[float, float, float, float]] = []
    out = []
    for names, a, b in groups:
        text = ", ".join(names)
        hw, hh = 0.35 * 3.0 * len(text), 1.5
        d = (b - a) / float(np.hypot(*(b - a)))
        u = np.array([-d[1], d[0]])
        own = _points(a, b)
        others = [_points(p, q) for p, q in lines
                  if not (np.allclose(p, a) and np.allclose(q, b))]
        pts = np.vstack(others) if others else np.zeros((0, 2))
        best = None
        m = (a + b) / 2
        for off, side in ((o, sd) for o in (1.0, 2.0, 3.5, 5.0, 7.0) for sd in (u, -u)):
            c = m + (off + abs(side[0]) * hw + abs(side[1]) * hh) * side
            d_own = float(np.min(np.hypot(*(own - c).T)))
            d_other = float(np.min(np.hypot(*(pts - c).T))) if len(pts) else 1e9
            gap = np.hypot(np.maximum(abs(pts[:, 0] - c[0]) - hw, 0.0),
                           np.maximum(abs(pts[:, 1] - c[1]) - hh, 0.0)) if len(pts) \
                else np.array([1e9])
            free = all(abs(c[0] - x) > hw + w + 0.5 or abs(c[1] - y) > hh + h + 0.5
                       for x, y, w, h in boxes)
            score = min(d_other - d_own, float(gap.min()))
            if free and d_other - d_own >= 1.5 and float(gap.min()) >= 0.8:
                best = (1e9, c)
                break
            if free and (best is None or score > best[0]):
                best = (score, c)
        leader = None
        if best is None or best[0] != 1e9:
            # crowded: the name set out on a leader (выноска) that stops 2 mm short of
            # the middle of its arrow, square to it, clear of every other line
            for lead, side in ((ld, sd) for ld in (4.0, 7.0, 10.0) for sd in (u, -u)):
                p0 = m + 2.0 * side
                p1 = p0 + lead * side
                c = p1 + (abs(side[0]) * hw + abs(side[1]) * hh + 0.2) * side
                run = _points(p0, p1, 0.25)
                near = float(np.min(np.hypot(run[:, None, 0] - pts[None, :, 0],
                                             run[:, None, 1] - pts[None, :, 1]))) \
                    if len(pts) else 1e9
                gap = float(np.min(np.hypot(np.maximum(abs(pts[:, 0] - c[0]) - hw, 0.0),
                                            np.maximum(abs(pts[:, 1] - c[1]) - hh, 0.0)))) \
                    if len(pts) else 1e9
                free = all(abs(c[0] - x) > hw + w + 0.5 or abs(c[1] - y) > hh + h + 0.5
                           for x, y, w, h in boxes)
                if near >= 0.5 and gap >= 0.8 and free:
                    best, leader = (1e9, c), (p0, p1)
                    break
        c = best[1] if best is not None else (a + b) / 2 + 3.0 * u
        boxes.append((float(c[0]), float(c[1]), hw, hh))
        out.append((text, c, leader))
    return out


def _cells(plans: list[_Plan], labels) -> list[tuple[_Plan, np.ndarray]]:
    """Each plan's offset: a column per position, a row per plan, the cells as large as
    the largest plan and 45 mm between them."""
    ext = [p.extent() for p in plans]
    w = max(e[2] - e[0] for e in ext) + 45.0
    h = max(e[3] - e[1] for e in ext) + 45.0
    rows = len(plans) // len(labels)
    out = []
    for i, (p, e) in enumerate(zip(plans, ext, strict=True)):
        col, row = divmod(i, rows)
        out.append((p, np.array([20.0 + col * w - e[0], 20.0 + (rows - 1 - row) * h - e[1]])))
    return out


def sheet2_positions(variant) -> list[str]:
    """The positions sheet 2 of the variant analyses (a student's assignment)."""
    from ..checks import reference_for

    ref = reference_for(Path(variant))
    return [ref.labels[k] for k in ref.analysis.sheet2.positions]


def student_force_sheet(variant, path: str | Path, labels, fmt: str = "dxf",
                        plant: ForcePlant | None = None, origin=(5000.0, -3000.0),
                        inches: bool = False) -> Path:
    """Draw the force plans of ``labels`` of a variant as a student's DXF or PDF (module
    doc); returns the path."""
    from ..checks import reference_for

    ref = reference_for(Path(variant))
    plans = _layout(ref, list(labels), plant)
    path = Path(path)
    if fmt == "pdf":
        _pdf(_cells(plans, labels), path)
    else:
        _dxf(_cells(plans, labels), path, np.asarray(origin, float), inches)
    return path


# ----------------------------------------------------------------------- names as written

def _parts(name: str) -> tuple[str, str, str]:
    """A force's name as letter, superscript and index: ``Rτ43`` → (R, τ, 43), ``Pи3``
    → (P, и, 3), ``R12`` → (R, "", 12), ``Fпс`` → (F, "", пс), ``Q`` → (Q, "", "")."""
    head, rest = name[:1], name[1:]
    digits = rest.lstrip("τtnⁿиuабвгдежзклмнопрстфхцчшщыэюя")
    mod = rest[:len(rest) - len(digits)]
    if head in "R" and mod in ("τ", "t", "n", "ⁿ"):
        return head, mod, digits
    if head in "PF" and mod == "и":
        return head, mod, digits
    return head, "", rest


def _dxf_name(name: str, i: int) -> tuple[str, bool]:
    """The name as a CAD user writes it (``i`` picks the way), and whether it is MTEXT."""
    head, sup, idx = _parts(name)
    way = i % 3
    if head == "P" and sup == "и" and way != 1:
        head = "F"  # Fи3: the force of inertia, as some write it
    if not idx and not sup:
        return name, False
    if way == 0:  # the index stacked, as AutoCAD's and КОМПАС's text editors write it
        return (f"{head}\\S{sup}^ {idx};" if sup else f"{head}\\S^ {idx};"), True
    if way == 1:  # a font, the index smaller
        return (f"{{\\fGOST type A|b0|i1|c204|p34;{head}{{\\H0.7x;{sup}{idx}}}}}"), True
    return f"{head}{'t' if sup == 'τ' else sup}{idx}", False  # plain: Rt43


def _mpl_name(name: str) -> str:
    head, sup, idx = _parts(name)
    if not sup and not idx:
        return name

    def tex(s: str) -> str:
        if s == "τ":
            return r"\tau"
        return "".join(rf"\mathrm{{{c}}}" if c.isalpha() and not c.isascii() else c
                       for c in s)

    return f"${head}^{{{tex(sup)}}}_{{{tex(idx)}}}$" if sup else f"${head}_{{{tex(idx)}}}$"


# ------------------------------------------------------------------------------- writers

def _scale_text(p: _Plan, n: int) -> str:
    if n % 2:
        return f"Kp = {p.written / 1000:.4g} кН/мм".replace(".", ",")
    return f"μF = {p.written:.4g} Н/мм".replace(".", ",")


def _twin(a: np.ndarray, b: np.ndarray, done, atol: float = 1e-6) -> bool:
    """Whether a force joins the same two points (to ``atol`` mm) as one of ``done``."""
    return any((np.allclose(a, p, atol=atol) and np.allclose(b, q, atol=atol)) or
               (np.allclose(a, q, atol=atol) and np.allclose(b, p, atol=atol))
               for p, q in done)


def _overlapping(a: np.ndarray, b: np.ndarray, plan: _Plan) -> bool:
    """Whether another force or a construction line runs along a force's line over part of
    it: a CAD user then draws the force whole, snapped to its ends."""
    L = float(np.hypot(*(b - a)))
    if L < 1e-9:
        return False
    d = (b - a) / L
    for p, q in [(p, q) for _n, p, q in plan.vectors] + list(plan.lines):
        if np.allclose(p, a) and np.allclose(q, b):
            continue
        off = [abs(float(d[0] * (r - a)[1] - d[1] * (r - a)[0])) for r in (p, q)]
        if max(off) > 0.05:
            continue
        t = sorted(float(np.dot(r - a, d)) for r in (p, q))
        if min(t[1], L) - max(t[0], 0.0) > 0.3:
            return True
    return False


def _dxf(cells, path: Path, origin: np.ndarray, inches: bool) -> None:
    import ezdxf
    from ezdxf.enums import TextEntityAlignment as TA


    doc = ezdxf.new("R2013")
    doc.header["$INSUNITS"] = 1 if inches else 4
    k = 1 / 25.4 if inches else 1.0
    blk = doc.blocks.new("СТРЕЛКА")
    blk.add_solid([(0, 0), (-3 * k, 0.5 * k), (-3 * k, -0.5 * k)])
    doc.layers.add("СИЛЫ", color=7)
    doc.layers.add("ОБОЗНАЧЕНИЯ", color=3)
    doc.layers.add("ВСПОМОГАТЕЛЬНЫЕ", color=8)
    msp = doc.modelspace()

    def X(v) -> tuple[float, float]:
        return (float((v[0] + origin[0]) * k), float((v[1] + origin[1]) * k))

    n_text = 0
    for n, (p, c) in enumerate(cells):
        # the caption above the forces, the scale under it (within a few mm of them)
        x0, _y0, _x1, y1 = p.extent(lines=False)
        cap = msp.add_mtext(p.caption, dxfattribs={"char_height": 3.5 * k,
                                                   "layer": "ОБОЗНАЧЕНИЯ"})
        cap.set_location(X(c + np.array([x0 - 10.0, y1 + 11.0])), attachment_point=7)
        msp.add_text(_scale_text(p, n), dxfattribs={"height": 2.5 * k,
                                                    "layer": "ОБОЗНАЧЕНИЯ"}).set_placement(
            X(c + np.array([x0 - 10.0, y1 + 4.0])))
        for a, b in p.lines:
            msp.add_line(X(c + a), X(c + b), dxfattribs={"layer": "ВСПОМОГАТЕЛЬНЫЕ"})
        done: list[tuple[np.ndarray, np.ndarray]] = []
        for i, (_name, a, b) in enumerate(p.vectors):
            A, B = c + a, c + b
            L = float(np.hypot(*(B - A)))
            if L < 1e-9:
                continue
            if _twin(a, b, done):
                pass  # a force drawn back along another (R41 = −R21): its head only
            elif _overlapping(a, b, p) or L < 10.0 or _twin(
                    a, b, [(q1, q2) for m2, q1, q2 in p.vectors if m2 != _name], 1.5):
                msp.add_line(X(A), X(B), dxfattribs={"layer": "СИЛЫ"})
            elif i % 3 == 0:
                M = A + 0.4 * (B - A)
                msp.add_line(X(A), X(M), dxfattribs={"layer": "СИЛЫ"})
                msp.add_line(X(M), X(B), dxfattribs={"layer": "СИЛЫ"})
            elif i % 3 == 1:
                msp.add_lwpolyline([X(A), X(A + 0.5 * (B - A)), X(B)],
                                   dxfattribs={"layer": "СИЛЫ"})
            else:
                msp.add_lwpolyline([X(A), X(B)], dxfattribs={"layer": "СИЛЫ"})
            done.append((a, b))
            if L >= STUB_MM:  # a short force's head smaller, as a draftsman draws it
                ang = math.degrees(math.atan2(float(B[1] - A[1]), float(B[0] - A[0])))
                f = _head(L) / 3.0
                msp.add_blockref("СТРЕЛКА", X(B), dxfattribs={
                    "rotation": ang, "layer": "СИЛЫ", "xscale": f, "yscale": f})
        for text, at, leader in _labels(p):
            if leader is not None:
                msp.add_line(X(c + leader[0]), X(c + leader[1]),
                             dxfattribs={"layer": "ВСПОМОГАТЕЛЬНЫЕ"})
            parts = [_dxf_name(nm, n_text + j) for j, nm in enumerate(text.split(", "))]
            n_text += 1
            if len(parts) == 1 and not parts[0][1]:
                t = msp.add_text(parts[0][0], dxfattribs={"height": 3.0 * k,
                                                          "layer": "ОБОЗНАЧЕНИЯ"})
                t.set_placement(X(c + at), align=TA.MIDDLE_CENTER)
                continue
            mt = msp.add_mtext(", ".join(s for s, _m in parts),
                               dxfattribs={"char_height": 3.0 * k, "layer": "ОБОЗНАЧЕНИЯ"})
            mt.set_location(X(c + at), attachment_point=5)
    doc.saveas(path)


def _pdf(cells, path: Path) -> None:
    import matplotlib

    from .sample import mpl_page

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.patches import Polygon

    with matplotlib.rc_context({"pdf.fonttype": 42, "font.family": "DejaVu Sans",
                                "mathtext.fontset": "dejavusans"}):
        corners = [c + q for p, c in cells for q in (np.array(p.extent()[:2]),
                                                      np.array(p.extent()[2:]))]
        W = max(594.0, max(float(q[0]) for q in corners) + 40.0)
        H = max(420.0, max(float(q[1]) for q in corners) + 40.0)
        fig, ax = mpl_page(W, H)
        pt = 72 / 25.4
        for n, (p, c) in enumerate(cells):
            x0, _y0, _x1, y1 = p.extent(lines=False)
            ax.text(c[0] + x0 - 10.0, c[1] + y1 + 11.0,
                    p.caption.replace(", положение ", ", пол. "), fontsize=3.5 * pt / 0.72)
            ax.text(c[0] + x0 - 10.0, c[1] + y1 + 4.0, _scale_text(p, n),
                    fontsize=2.5 * pt / 0.72)
            for a, b in p.lines:
                ax.plot([c[0] + a[0], c[0] + b[0]], [c[1] + a[1], c[1] + b[1]], "-",
                        color="0.5", lw=0.25 * pt)
            done: list[tuple[np.ndarray, np.ndarray]] = []
            for _name, a, b in p.vectors:
                A, B = c + a, c + b
                L = float(np.hypot(*(B - A)))
                if L < 1e-9:
                    continue
                u = (B - A) / L
                twin = _twin(a, b, done)
                done.append((a, b))
                if L >= STUB_MM:
                    hl = _head(L)
                    S = B - hl * u
                    nn = hl / 6.0 * np.array([-u[1], u[0]])
                    if not twin:
                        ax.plot([A[0], S[0]], [A[1], S[1]], "-", color="k", lw=0.5 * pt)
                    ax.add_patch(Polygon([B, S + nn, S - nn], closed=True,
                                         facecolor="k", edgecolor="none"))
                else:
                    ax.plot([A[0], B[0]], [A[1], B[1]], "-", color="k", lw=0.5 * pt)
            for text, at, leader in _labels(p):
                if leader is not None:
                    ax.plot([c[0] + leader[0][0], c[0] + leader[1][0]],
                            [c[1] + leader[0][1], c[1] + leader[1][1]], "-", color="0.5",
                            lw=0.25 * pt)
                ax.text(c[0] + at[0], c[1] + at[1],
                        ", ".join(_mpl_name(nm) for nm in text.split(", ")),
                        fontsize=3.0 * pt / 0.72, ha="center", va="center")
        with PdfPages(path, metadata={"CreationDate": None}) as pdf:
            pdf.savefig(fig)
        plt.close(fig)


__all__ = ["ForcePlant", "omitted", "sheet2_positions", "student_force_sheet"]
