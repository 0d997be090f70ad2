"""The overlay sheet: graphplan's correct construction with the student's wrong figures on it.

For every position with a wrong figure (or the first position, when nothing is wrong), one
row of three cells on an A1 sheet (more sheets when there are more than :data:`ROWS` such
positions):

1. the mechanism in that position with the line of action of R21, the arm h21 and the
   arms the student names (perpendiculars from their centres), drawn correctly;
2. the force plan of the group attached to the crank at the **student's** Kp;
3. the acceleration (or velocity) plan at the **student's** Ka (Kv).

Graphplan's construction is black. Each wrong figure is marked in red: a length on paper
as a red segment of the student's length laid along the right one from the same start,
with ``name: stated ≠ right``. The drawing is a :class:`graphplan.drawing.sheet.Sheet` rendered by
:func:`graphplan.render.svg.render_svg` (mm, ESKD frame); the red of the marks is one CSS
rule added to that SVG.
"""

from __future__ import annotations

import math
from itertools import pairwise
from typing import Any

import numpy as np

from ..drawing import (
    MEDIUM,
    THIN,
    Arrow,
    Circle,
    Item,
    Line,
    Page,
    Rect,
    Sheet,
    Style,
    text_at_centre,
)
from ..units import nice_ceil
from .findings import Report
from .words import num

ROWS = 3
"""Rows (positions) on one A1 sheet."""

RED = "#c8102e"
MARK = Style(0.5, None, RED)
MARK_DASHED = Style(0.35, (3.0, 1.5), RED)
CAPTION_H = 7.0
MAX_ZOOM = 2.5
"""A small plan is drawn up to this many times larger (its caption says ×z)."""
TEXT_H = 2.5


class _Cell:
    """Maps a plan's own mm (y up) into a cell of the sheet (y down), scaled to fit."""

    def __init__(self, cell: Rect, pts: np.ndarray, margin: float = 10.0):
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        span = np.maximum(hi - lo, 1e-9)
        room = np.array([cell.width - 2 * margin, cell.height - CAPTION_H - 2 * margin])
        self.z = float(min(MAX_ZOOM, *(room / span)))
        self.mid = (lo + hi) / 2
        self.c = ((cell.x0 + cell.x1) / 2, (cell.y0 + CAPTION_H + cell.y1) / 2)

    def __call__(self, q) -> tuple[float, float]:
        return (self.c[0] + self.z * float(q[0] - self.mid[0]),
                self.c[1] - self.z * float(q[1] - self.mid[1]))


def _plan_items(plan, cell: Rect, caption: str, ident: str, layer: str, extra=()):
    """A construction (velocity, acceleration or force plan) in its cell, and its mapping
    (``extra``: more points of the plan's frame that must fit, the students' marks)."""
    pts = [np.asarray(p, float) for p in plan.points.values()] + [np.asarray(p) for p in extra]
    for s in plan.steps:
        for e in s.elements:
            if e.kind != "point":
                pts += [np.asarray(e.start), np.asarray(e.end)]
    to = _Cell(cell, np.array(pts))
    items: list[Item] = []
    n = 0
    for s in plan.steps:
        for e in s.elements:
            n += 1
            if e.kind == "line":
                items.append(Line(to(e.start), to(e.end), THIN, layer=layer,
                                  id=f"{ident}-l{n}"))
            elif e.kind == "segment" and math.dist(e.start, e.end) > 1e-9:
                items.append(Arrow(to(e.start), to(e.end), MEDIUM, 2.5, 0.8, layer=layer,
                                   id=f"{ident}-s{n}"))
                mid = ((e.start[0] + e.end[0]) / 2, (e.start[1] + e.end[1]) / 2)
                items.append(text_at_centre(_nudge(to(mid), to(e.start), to(e.end)),
                                            e.name.replace("_", ""), TEXT_H, layer="text",
                                            id=f"{ident}-n{n}"))
    for i, (name, p) in enumerate(plan.points.items()):
        items.append(text_at_centre(_nudge(to(p), to(p), to(p), 3.0), name.replace("_", ""),
                                    TEXT_H, layer="text", id=f"{ident}-p{i}"))
    scale = plan.scale
    items.append(text_at_centre(((cell.x0 + cell.x1) / 2, cell.y0 + CAPTION_H / 2),
                                f"{caption}, {scale.symbol} = {num(scale.per_mm, 'ru', 6)}"
                                + (f" (×{num(to.z, 'ru', 3)})" if abs(to.z - 1) > 1e-3
                                   else ""),
                                3.5, layer="text", id=f"{ident}-caption"))
    return items, to


def _nudge(p, a, b, d: float = 2.5):
    """A point moved ``d`` mm off the segment a–b, to the left of it (as seen)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy)
    if n < 1e-9:
        return (p[0] + d, p[1] - d)
    return (p[0] + d * dy / n, p[1] - d * dx / n)


def _segment_ends(plan, name: str):
    for s in plan.steps:
        for e in s.elements:
            if e.kind == "segment" and e.name == name:
                return np.asarray(e.start, float), np.asarray(e.end, float)
    return None


def _marks(plan, figs, rename=lambda q: q):
    """(start, end, stated mm, label) of the wrong lengths of a plan, and their tips."""
    out, tips = [], []
    for f in figs.values():
        if f.verdict != "wrong" or f.unit != "mm":
            continue
        q = rename(f.quantity)
        ends = _segment_ends(plan, q)
        if ends is None:
            continue
        d = ends[1] - ends[0]
        n = float(np.hypot(*d))
        if n > 1e-9:
            tips.append(ends[0] + d / n * f.stated)
        out.append((ends[0], ends[1], f.stated,
                    f"{q}: {num(f.stated, 'ru')} ≠ {num(f.expected, 'ru')} мм"))
    return out, tips


def _mark(items, to, start, end, stated_mm: float, label: str, ident: str):
    """The student's length laid from ``start`` along start→end, in red, with a label."""
    d = end - start
    n = float(np.hypot(*d))
    if n < 1e-9:
        return
    tip = start + d / n * stated_mm
    items.append(Line(to(start), to(tip), MARK_DASHED, layer="construction", id=f"{ident}-mk"))
    items.append(Circle(to(tip), 1.2, MARK, layer="construction", id=f"{ident}-mkc"))
    items.append(text_at_centre(_nudge(to(tip), to(start), to(tip), -4.0), label, TEXT_H,
                                layer="text", id=f"{ident}-mark"))


def overlay_sheets(report: Report, ref, work) -> list[str]:
    """The overlay sheets of a checked work as SVG texts (see the module docstring).

    Parameters
    ----------
    report : Report
    ref : Reference
        graphplan's results for the variant (the checker's).
    work : Work
        The checker's reading of the student's lines (its scales).
    """
    from ..render.svg import render_svg

    by_pos: dict[str, list] = {}
    for f in report.figures:
        if f.position is not None and f.position in ref.labels and f.expected is not None:
            by_pos.setdefault(f.position, []).append(f)
    rows = [lab for lab in (p.label for p in work.work.positions) if lab in by_pos and any(
        f.verdict == "wrong" for f in by_pos[lab])]
    if not rows:
        rows = [lab for lab in (p.label for p in work.work.positions) if lab in ref.labels][:1]
    pages = []
    for first in range(0, max(len(rows), 1), ROWS):
        page = Page("A1")
        fr = page.frame
        items: list[Item] = []
        top = fr.y0 + 16.0
        items.append(text_at_centre(((fr.x0 + fr.x1) / 2, fr.y0 + 8.0),
                                    f"Проверка: {report.student or report.source} — чёрным "
                                    "точное построение graphplan, красным цифры студента",
                                    5.0, layer="text", id="ov-title"))
        height = (fr.y1 - 60.0 - top) / ROWS
        width = (fr.width - 16.0) / 3
        for r, label in enumerate(rows[first:first + ROWS]):
            k = ref.index(label)
            y0 = top + r * height
            cells = [Rect(fr.x0 + 4 + i * (width + 4), y0, fr.x0 + 4 + i * (width + 4) + width,
                          y0 + height - 4) for i in range(3)]
            figs = {f.quantity: f for f in by_pos.get(label, [])}
            sc = work.stated_scales(label)
            kl = sc.get("Kl") or 1e-3
            ident = f"ov{first + r}"
            items += _scheme(ref, k, label, cells[0], kl, figs, work, ident)
            try:
                fp = ref.force_plan(k, kl, sc.get("Kp"))
                marks, tips = _marks(fp, figs, lambda q: q.replace("_mm", ""))
                its, to = _plan_items(fp, cells[1], f"План сил {fp.group}, пол. {label}",
                                      f"{ident}-fp", "force_plan", tips)
                items += its
                for i, (a, b, mm, text) in enumerate(marks):
                    _mark(items, to, a, b, mm, text, f"{ident}-fpm{i}")
            except Exception:
                pass
            kv, ka = sc.get("Kv"), sc.get("Ka")
            try:
                vp, ap = ref.plans(k, kl, kv, ka)  # built once for the class
                plan: Any
                plan, what = vp, "План скоростей"
                if ka:
                    plan, what = ap, "План ускорений"
                elif not kv:
                    plan = None
                if plan is not None:
                    marks, tips = _marks(plan, figs)
                    its, to = _plan_items(plan, cells[2], f"{what}, пол. {label}",
                                          f"{ident}-kp", "acceleration_plan", tips)
                    items += its
                    for i, (a, b, mm, text) in enumerate(marks):
                        _mark(items, to, a, b, mm, text, f"{ident}-kpm{i}")
            except Exception:
                pass
        sheet = Sheet(page, tuple(items), None)
        svg = render_svg(sheet)
        style = (f'<style>[id$="-mark"] {{ fill: {RED}; }}</style>')
        svg = svg.replace(">", ">" + style, 1) if svg.startswith("<svg") else \
            svg.replace("<defs />", "<defs />" + style, 1)
        if style not in svg:
            i = svg.find("<svg")
            j = svg.find(">", i)
            svg = svg[:j + 1] + style + svg[j + 1:]
        pages.append(svg)
    return pages


def _scheme(ref, k: int, label: str, cell: Rect, kl: float, figs, work, ident: str):
    """The mechanism at position k, the line of R21 and the arms (correct), marks in red."""
    from ..drawing import MAIN
    from ..forces import reaction_name

    mech, kin = ref.mech, ref.kin
    pts = {n: np.asarray(p[k], float) for n, p in kin.pos.points.items()}
    allp = np.array(list(pts.values()))
    ext = np.ptp(allp, axis=0)
    room = np.array([cell.width - 30, cell.height - CAPTION_H - 30])
    scale = nice_ceil(float(np.max(ext / room)))
    mm = {n: p / scale for n, p in pts.items()}
    to = _Cell(cell, np.array(list(mm.values())), 15.0)
    items: list[Item] = []
    for ln in mech.moving_links:
        names = [p for p in mech.points_of(ln) if p in mm]
        for a, b in pairwise(names):
            items.append(Line(to(mm[a]), to(mm[b]), MAIN, layer="position_plan",
                              id=f"{ident}-ln-{ln}-{a}{b}"))
    for i, (n, p) in enumerate(mm.items()):
        items.append(Circle(to(p), 1.0, Style(0.35, fill="white"), layer="position_plan",
                            id=f"{ident}-j{i}"))
        items.append(text_at_centre(_nudge(to(p), to(p), to(p), 3.5), n, 3.5, layer="text",
                                    id=f"{ident}-jt{i}"))
    arms = []
    for p in work.work.positions:
        if p.label == label:
            arms = [(a.name, a.force, a.about) for a in p.arms.values()]
    r21 = reaction_name(mech.dyads[0].links[0], mech.crank.link) if mech.dyads else None
    if r21:
        arms.append((f"h{r21[1:]}", r21, mech.crank.pivot))
    for i, (name, force, about) in enumerate(arms):
        line = ref.force_line(force, k)
        c = ref.point(about)
        if line is None or c is None or not np.hypot(*line[1]):
            continue
        at, vec = line[0] / scale, line[1]
        u = vec / float(np.hypot(*vec))
        cc = pts[c] / scale
        foot = at + float(np.dot(cc - at, u)) * u
        t = sorted([0.0, float(np.dot(foot - at, u))])
        items.append(Line(to(at + (t[0] - 8) * u), to(at + (t[1] + 8) * u),
                          Style(0.25, (4.0, 1.5)), layer="construction", id=f"{ident}-fl{i}"))
        if np.hypot(*(foot - cc)) > 0.5:
            items.append(Line(to(cc), to(foot), THIN, layer="construction",
                              id=f"{ident}-arm{i}"))
            items.append(text_at_centre(_nudge(to((cc + foot) / 2), to(cc), to(foot)), name,
                                        TEXT_H, layer="text", id=f"{ident}-armt{i}"))
        f = figs.get(name)
        if f is not None and f.verdict == "wrong" and f.expected:
            # the student's length, drawn at the scheme's scale: stated/expected of the arm
            stated_here = f.stated * np.hypot(*(foot - cc)) / f.expected
            _mark(items, to, cc, foot, stated_here,
                  f"{name}: {num(f.stated, 'ru')} ≠ {num(f.expected, 'ru')} мм",
                  f"{ident}-am{i}")
    items.append(text_at_centre(((cell.x0 + cell.x1) / 2, cell.y0 + CAPTION_H / 2),
                                f"Положение {label}, Kl = {num(scale, 'ru', 6)} м/мм", 3.5,
                                layer="text", id=f"{ident}-caption"))
    return items


__all__ = ["ROWS", "overlay_sheets"]
