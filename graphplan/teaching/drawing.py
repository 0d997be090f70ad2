"""The frames of a lesson: one SVG per step, the step's lines in colour over the grey
lines of the steps before it.

A panel's marks (:class:`graphplan.teaching.model.Mark`, mm with y up) become the
sheets' own drawing items (:mod:`graphplan.drawing.items`: arrows with filled heads, thin
construction lines, lettering sized by its capital height) on paper with **y down**,
``(x, y) → (x, −y)``, the one flip of the module; the letters of the points are placed
once per panel with the sheets' label placer (:func:`graphplan.drawing.labels.place_labels`),
so a letter never moves from one frame to the next, and every item is written by the
sheets' SVG renderer (:mod:`graphplan.render.svg`). The frame's ``viewBox`` is the
panel's extent plus a margin, and its ``width``/``height`` are that extent in mm: printed,
a frame is at the plan's true size (1 mm of the plan = 1 mm of paper), as on the sheet.

In a frame the marks of the current step carry ``class="new"`` and their role's colour
(:data:`COLOURS`), the marks of earlier steps of the same panel ``class="old"`` and grey,
and the background of the panel (``context``: links of a scheme, axes) stays black.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import lru_cache

import svgwrite

from ..drawing import (
    TEXT_HEIGHTS,
    Arrow,
    Circle,
    LabelRequest,
    Leaf,
    Line,
    Polyline,
    Style,
    Text,
    item_geometry,
    merge_coincident,
    place_labels,
    text_box,
)
from ..render import svg as svg_render
from .captions import localise
from .model import Lesson, Mark

#: Colour of each role in the current step (earlier steps are GREY).
COLOURS: dict[str, str] = {
    "absolute": "#d0021b",
    "relative": "#1f5fd1",
    "normal": "#1a9a3a",
    "tangential": "#e07b00",
    "coriolis": "#8e44ad",
    "sliding": "#8c564b",
    "line": "#1f8fb4",
    "point": "#000000",
    "label": "#000000",
    "load": "#d0021b",
    "reaction": "#1f5fd1",
    "force": "#d0021b",
    "arm": "#1a9a3a",
    "curve": "#d0021b",
    "exact": "#7f7f7f",
    "tangent": "#1f5fd1",
    "ray": "#1f8fb4",
    "text": "#000000",
    "context": "#000000",
}
GREY = "#a3a3a3"  #: strokes of the earlier steps
GREY_TEXT = "#8a8a8a"  #: letters of the earlier steps
MARGIN = 8.0  #: room around a panel's drawing, mm
LETTER = 3.5  #: height of the letters, mm
HEAD = (3.0, 1.0)  #: arrowhead length and width, mm (as on the sheets)
_LAYER = "construction"  # items are written one by one; the layer only has to be valid


@dataclass(frozen=True, slots=True)
class _Drawn:
    step: int
    role: str
    item: Leaf


def _paper(p) -> tuple[float, float]:
    return (float(p[0]), -float(p[1]))


def _style(mark: Mark, zoom: float) -> Style:
    if mark.kind == "vector":
        width = 0.5 if mark.role in ("absolute", "relative", "load", "reaction", "force",
                                     "tangential", "normal", "coriolis", "sliding") else 0.35
    elif mark.kind == "curve":
        width = 0.5 if mark.role not in ("exact", "context") else 0.25
    else:
        width = 0.25
    z = math.sqrt(zoom)
    return Style(width * z, (3.0 * zoom, 1.5 * zoom) if mark.dashed else None)


def _zoom(lesson: Lesson, panel: int) -> float:
    """Letters, arrowheads and strokes follow the panel's size so that they keep their
    proportion when the frame is shown whole on a screen: 1 for a panel of 50 to 120 mm,
    in proportion outside (at least 0.7: letters of 2.5 mm; at most 3)."""
    pts = [p for s in lesson.steps if s.panel == panel for m in s.marks for p in m.points]
    if not pts:
        return 1.0
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    size = max(max(xs) - min(xs), max(ys) - min(ys))
    return min(3.0, max(0.7, size / 50.0)) if size < 50.0 else min(3.0, max(1.0, size / 120))


def _letter(zoom: float) -> float:
    """The GOST height (2.5, 3.5, 5, 7, 10 mm) nearest 3.5·zoom."""
    return min(TEXT_HEIGHTS[1:6], key=lambda h: abs(h - LETTER * zoom))


def _items(mark: Mark, zoom: float = 1.0) -> list[Leaf]:
    st = _style(mark, zoom)
    pts = [_paper(p) for p in mark.points]
    if mark.kind == "vector":
        if math.dist(pts[0], pts[-1]) < 1e-9:
            return []
        return [Arrow(pts[0], pts[-1], st, HEAD[0] * zoom, HEAD[1] * zoom, layer=_LAYER)]
    if mark.kind == "line":
        return [Line(pts[0], pts[-1], st, layer=_LAYER)]
    if mark.kind == "curve":
        return [Polyline(tuple(pts), st, layer=_LAYER)] if len(pts) >= 2 else []
    if mark.kind == "point":
        return [Circle(pts[0], 0.6 * zoom, Style(0.25, fill="black"), layer=_LAYER)]
    if mark.kind == "text":
        return [Text(pts[0], mark.text, _letter(zoom), "start", layer=_LAYER)]
    return []


@lru_cache(maxsize=32)
def _panel_items(lesson: Lesson, panel: int) -> tuple[tuple[_Drawn, ...], tuple[float, ...]]:
    """Every item of a panel with its step and role, and the panel's bounds (paper mm)."""
    drawn: list[_Drawn] = []
    reqs: list[LabelRequest] = []
    zoom = _zoom(lesson, panel)
    letter = _letter(zoom)
    for s in lesson.steps:
        if s.panel != panel:
            continue
        for m in s.marks:
            for it in _items(m, zoom):
                drawn.append(_Drawn(s.number, m.role, it))
            if m.kind == "label" and m.text:
                reqs.append(LabelRequest(_paper(m.points[0]), m.text, letter,
                                         group=f"s{s.number}"))
            elif m.kind in ("vector", "line") and m.text:
                a, b = _paper(m.points[0]), _paper(m.points[-1])
                if math.dist(a, b) > 1e-9:
                    reqs.append(LabelRequest(((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), m.text,
                                             letter, group=f"m{s.number}"))
    obstacles = [g for d in drawn if (g := item_geometry(d.item)) is not None]
    # coincident letters of one step are written together (``b, s3``); a group is a step
    merged = merge_coincident(reqs, 1.0)
    texts = place_labels(merged, obstacles, layer=_LAYER, id_prefix="t", merge_mm=1.0,
                         gap=0.8 * zoom, max_radius=14.0 * zoom) if merged else []
    for r, t in zip(merged, texts, strict=True):
        drawn.append(_Drawn(int(r.group[1:]), "label", replace(t, id=None)))
    geoms = []
    for d in drawn:
        if isinstance(d.item, Text):
            geoms.append(text_box(d.item))
        else:
            g = item_geometry(d.item)
            if g is not None:
                geoms.append(g)
    if geoms:
        x0 = min(g.bounds[0] for g in geoms)
        y0 = min(g.bounds[1] for g in geoms)
        x1 = max(g.bounds[2] for g in geoms)
        y1 = max(g.bounds[3] for g in geoms)
    else:
        x0 = y0 = 0.0
        x1 = y1 = 20.0
    # room for the scale bar under the drawing
    pad = MARGIN * zoom
    bounds = (x0 - pad, y0 - pad, max(x1 - x0, 30.0) + 2 * pad, (y1 - y0) + 2 * pad + 8.0 * zoom)
    return tuple(drawn), bounds


def _coloured(item: Leaf, colour: str) -> Leaf:
    if isinstance(item, Text):
        return item
    st = item.style
    fill = colour if st.fill else None
    return replace(item, style=replace(st, colour=colour, fill=fill))


def _add(dwg, group, item: Leaf, colour: str, text_colour: str) -> None:
    el = svg_render._element(dwg, _coloured(item, colour))
    if isinstance(item, Text):
        el["fill"] = text_colour
    group.add(el)


def frame_svg(lesson: Lesson, number: int, *, lang: str = "ru", standalone: bool = False,
              font_css: str = "") -> str:
    """The SVG of step ``number`` (1-based): its marks coloured, earlier ones grey.

    ``standalone`` adds the XML prologue, a heading (the panel's title, the step and its
    equation, for slides) and ``font_css`` (``@font-face`` rules) in a ``<style>``;
    without it the SVG is for inlining into the page (the page carries the fonts).
    """
    if not 1 <= number <= len(lesson.steps):
        raise ValueError(f"step {number} of a lesson of {len(lesson.steps)} steps")
    step = lesson.steps[number - 1]
    drawn, (x0, y0, w, h) = _panel_items(lesson, step.panel)
    head = 0.0
    heading: list[Text] = []
    if standalone:
        panel = lesson.panels[step.panel]
        lines = [f"{panel.title[lang]} — {number}/{len(lesson.steps)}"]
        if step.equation:
            lines.append(localise(step.equation, lang))
        hh = _letter(_zoom(lesson, step.panel))
        head = 1.7 * hh * len(lines) + hh
        for i, s in enumerate(lines):
            heading.append(Text((x0 + 2.0, y0 - head + 1.5 * hh + 1.7 * hh * i), s, hh,
                                layer=_LAYER))
        w = max(w, max(text_box(t).bounds[2] for t in heading) - x0 + 4.0)
    vb = (x0, y0 - head, w, h + head)
    dwg = svg_document(vb)
    dwg.attribs["class"] = "frame"
    dwg.attribs["data-step"] = str(number)
    if standalone and font_css:
        dwg.defs.add(dwg.style(font_css))
    ctx, old, new = (dwg.g(**{"class": c}) for c in ("context", "old", "new"))
    for d in drawn:
        if d.step > number:
            continue
        if d.role == "context":
            _add(dwg, ctx, d.item, COLOURS["context"], "black")
        elif d.step == number:
            _add(dwg, new, d.item, COLOURS.get(d.role, "#000000"), "black")
        else:
            _add(dwg, old, d.item, GREY, GREY_TEXT)
    for g in (ctx, old, new):
        dwg.add(g)
    bar = dwg.g(**{"class": "bar"})
    zoom = _zoom(lesson, step.panel)
    length = bar_mm(zoom)
    bx, by = x0 + MARGIN * zoom, y0 + h - 4.0 * zoom
    t = 1.0 * zoom
    for it in (Line((bx, by), (bx + length, by), Style(0.35 * zoom), layer=_LAYER),
               Line((bx, by - t), (bx, by + t), Style(0.25 * zoom), layer=_LAYER),
               Line((bx + length, by - t), (bx + length, by + t), Style(0.25 * zoom),
                    layer=_LAYER),
               Text((bx + length + 2.0 * zoom, by + 1.2 * zoom),
                    f"{length:g} мм" if lang == "ru" else f"{length:g} mm",
                    min(TEXT_HEIGHTS[:5], key=lambda v: abs(v - 2.5 * zoom)), layer=_LAYER)):
        _add(dwg, bar, it, "#000000", "black")
    dwg.add(bar)
    if heading:
        hg = dwg.g(**{"class": "heading"})
        for ht in heading:
            _add(dwg, hg, ht, "#000000", "black")
        dwg.add(hg)
    text = dwg.tostring()
    return ('<?xml version="1.0" encoding="utf-8"?>\n' + text + "\n") if standalone else text


SCHEME_COLOUR = "#c8102e"  #: the links a step is about, on the scheme beside the plan
SCHEME_GREY = "#555555"


def scheme_svg(lesson: Lesson, number: int) -> str:
    """The mechanism at the lesson's position, small, with step ``number``'s links in
    colour (empty when the lesson has no scheme: the flywheel's)."""
    if not lesson.scheme:
        return ""
    from ..drawing import scheme_links

    step = lesson.steps[number - 1]
    lit = set(step.links)
    xs, ys = [], []
    for it in lesson.scheme:
        if isinstance(it, Text):
            x0, y0, x1, y1 = (*it.pos, *it.pos)
        else:
            g = item_geometry(it)
            assert g is not None  # the scheme's strokes all have one
            x0, y0, x1, y1 = g.bounds
        xs += [x0, x1]
        ys += [y0, y1]
    vb = (min(xs) - 3.0, min(ys) - 5.0, max(xs) - min(xs) + 8.0, max(ys) - min(ys) + 8.0)
    dwg = svg_document(vb)
    dwg.attribs["class"] = "scheme"
    dwg.attribs["data-links"] = " ".join(step.links)
    rest, lit_g = dwg.g(**{"class": "links"}), dwg.g(**{"class": "lit"})
    for it in lesson.scheme:
        link = scheme_links(it)
        on = link is not None and link in lit
        colour = SCHEME_COLOUR if on else SCHEME_GREY if link is not None else "#000000"
        if isinstance(it, Text):
            el = svg_render._element(dwg, it)
            el["fill"] = "black"
        else:  # white fills (joints, blocks) stay white: only the lines take the colour
            st = it.style
            fill = st.fill if st.fill in ("white", "#ffffff", "#fff") else (
                colour if st.fill else None)
            st = replace(st, colour=colour, fill=fill, width=st.width * (1.6 if on else 1.0))
            el = svg_render._element(dwg, replace(it, style=st))
        (lit_g if on else rest).add(el)
    dwg.add(rest)
    dwg.add(lit_g)
    return dwg.tostring()



def svg_document(vb: tuple[float, float, float, float]) -> svgwrite.Drawing:
    """An empty SVG of the view box ``vb`` = (x, y, width, height) in mm (a user unit is a
    mm), for a lesson's frame, its scheme or ``analyze --picture``."""
    return svgwrite.Drawing(size=(f"{svg_render.num(vb[2])}mm", f"{svg_render.num(vb[3])}mm"),
                            viewBox=" ".join(svg_render.num(v) for v in vb), profile="full",
                            debug=False)

def bar_mm(zoom: float) -> float:
    """Length of a frame's scale bar: 10 mm, or 20, 50 mm on a large panel."""
    return 10.0 if zoom < 1.5 else 20.0 if zoom < 2.5 else 50.0


def frame_texts(lesson: Lesson, lang: str = "ru") -> str:
    """Every character the frames letter (to subset the fonts)."""
    out = ["мм mm"]
    for p in range(len(lesson.panels)):
        drawn, _ = _panel_items(lesson, p)
        out += [d.item.text for d in drawn if isinstance(d.item, Text)]
    out += [localise(s.equation, lang) for s in lesson.steps]
    out += [pn.title[lang] for pn in lesson.panels]
    out += [it.text for it in lesson.scheme if isinstance(it, Text)]
    return "".join(out) + "0123456789/— "




def construction_svg(plan, lang: str = "en") -> str:
    """The whole of a construction (a velocity, acceleration or force plan: anything with
    ``kind``, ``points`` and ``steps``) in one picture, each element in its role's colour
    and every point lettered: the notebook view of a plan (``Plan._repr_svg_``)."""
    from .model import LessonStep, Panel

    marks: list[Mark] = []
    for s in plan.steps:
        for e in s.elements:
            if e.kind == "segment":
                text = e.name if plan.kind == "force" else ""
                marks.append(Mark("vector", e.name, (e.start, e.end), e.role, text=text))
            elif e.kind == "line":
                marks.append(Mark("line", e.name, (e.start, e.end), "line"))
    for name, xy in plan.points.items():
        marks.append(Mark("label", name, ((float(xy[0]), float(xy[1])),), "label",
                          text=name.replace("_", "")))
    title = {"ru": f"{plan.kind} {plan.label}", "en": f"{plan.kind} {plan.label}"}
    step = LessonStep(1, 0, "plan", "", {"ru": "", "en": ""}, marks=tuple(marks))
    les = Lesson(plan.kind, "", "", plan.label, title, (Panel(plan.kind, title),), (step,))
    return frame_svg(les, 1, lang=lang)


__all__ = ["COLOURS", "GREY", "construction_svg", "frame_svg", "frame_texts"]
