"""Which links a step of a lesson is about: the ones its scheme draws in colour.

Read off the step's equation and sentence, and its panel's title:

* a quantity of two points (``v_BA``, ``aⁿ_AO3``, ``l_OA``): the link holding both, else the
  link its digit names (``v_A3O3``: A on link 3), else the moving link of its second point
  (``aⁿ_AO3``: link 3, turning about O3);
* a point on a named link (``v_A3``, ``aᵏ_A3``) and a rate (``ω3``, ``ε2``): that link;
* a step that names its link (``similarity on link 3``, ``ΣM_B(link 2)``): that link alone;
* a force or a reaction (``G2``, ``Pи3``, ``Mи3``, ``R12``) and a group (``links 2–3``): its
  links.

Only moving links count; a step that names none (the pole) colours nothing.
"""

from __future__ import annotations

import re

_SUB = re.compile(r"[_]([A-Za-z0-9]+)")
_RATE = re.compile(r"[ωε](\d+)")
_FORCE = re.compile(r"(?<![A-Za-z])(?:G|Pи|Mи|Fи|Ф)(\d+)|(?<![A-Za-z])R(\d)(\d)(?!\d)")
_GROUP = re.compile(r"links? (\d+)\s*[–-]\s*(\d+)")
_NAMED = re.compile(r"(?:on |\()link (\d+(?:\+\d+)*)")


def _points(mech, sub: str) -> list[tuple[str, str | None]]:
    """``A3O3`` → [(A, 3), (O3, None)]: the points of a subscript, each with the link its
    digits name when they are not part of a point's own name."""
    names = sorted(_all_points(mech), key=len, reverse=True)
    out: list[tuple[str, str | None]] = []
    i = 0
    while i < len(sub):
        for n in names:
            if sub.startswith(n, i):
                i += len(n)
                m = re.match(r"\d+", sub[i:])
                hint = None
                if m and m.group() in mech.moving_links:
                    hint = m.group()
                    i += len(m.group())
                out.append((n, hint))
                break
        else:
            i += 1
    return out


def _all_points(mech) -> set[str]:
    pts = set(mech.frame_points)
    for ln in mech.moving_links:
        pts.update(mech.points_of(ln))
    return pts


def step_links(mech, equation: str, text: str, panel_title: str = "") -> tuple[str, ...]:
    """The moving links a step is about, in the mechanism's order (module docstring)."""
    moving = list(mech.moving_links)
    source = f"{equation} {text}"
    named = {ln for m in _NAMED.findall(equation or text) for ln in m.split("+")}
    if named & set(moving):  # "similarity on link 3", "ΣM_B(link 2)": the step says which
        return tuple(ln for ln in moving if ln in named)
    found: set[str] = set()
    for sub in _SUB.findall(source):
        pts = _points(mech, sub)
        hints = {h for _, h in pts if h}
        found |= hints
        names = [p for p, _ in pts]
        if len(names) >= 2 and names[0] != names[1]:
            both = [ln for ln in moving if names[0] in mech.points_of(ln)
                    and names[1] in mech.points_of(ln)]
            if both:
                found.update(both)
            elif not hints:
                found.update(ln for ln in moving if names[1] in mech.points_of(ln)
                             and ln != mech.crank.link)
    found.update(m for m in _RATE.findall(source) if m in moving)
    for m in _FORCE.finditer(source):
        found.update(g for g in m.groups() if g and g in moving)
    for m in _GROUP.finditer(panel_title):
        found.update(g for g in m.groups() if g in moving)
    return tuple(ln for ln in moving if ln in found)


__all__ = ["step_links"]


#: The lesson's scheme: this wide; as tall as the mechanism needs, within these bounds (mm)
SCHEME_WIDTH_MM = 120.0
SCHEME_HEIGHT_MM = (90.0, 240.0)


def _scheme_height(analysis, k: int) -> float:
    """The lesson scheme's height: the mechanism's own proportion at
    :data:`SCHEME_WIDTH_MM`, within :data:`SCHEME_HEIGHT_MM`."""
    import numpy as np

    mech, kin = analysis.mech, analysis.kin
    pts = np.array([p[k] for p in kin.pos.points.values()]
                   + [np.asarray(v, float) for v in mech.frame_points.values()])
    ext = np.maximum(np.ptp(pts, axis=0), 1e-9)
    lo, hi = SCHEME_HEIGHT_MM
    return float(min(hi, max(lo, SCHEME_WIDTH_MM * ext[1] / ext[0])))


def lesson_scheme(analysis, k: int) -> tuple:
    """The mechanism at position k for the column beside a lesson's plan, readable however
    tall it is.

    :func:`graphplan.drawing.mechanism_scheme` fits the mechanism in a box; a box of a fixed
    shape shrinks a tall machine (a shaper's rocker, a slotter's ram, a six-bar press) until
    its crank is a few mm and the letters of O1, A, B, O3 sit on each other. Here the box is
    as tall as the mechanism's shape asks (within :data:`SCHEME_HEIGHT_MM`), and the letters
    are placed again, clear of each other and of the links
    (:func:`graphplan.drawing.place_labels`, letters of coincident points written as one).
    """
    from ..drawing import (
        Group,
        LabelRequest,
        Text,
        item_geometry,
        mechanism_scheme,
        place_labels,
    )

    items = mechanism_scheme(analysis, k, SCHEME_WIDTH_MM, _scheme_height(analysis, k))
    labels = [it for it in items if isinstance(it, Text)
              and (it.id or "").startswith("scheme-label-")]
    rest = [it for it in items if it not in labels]
    obstacles = [g for it in rest if not isinstance(it, Group)
                 and (g := item_geometry(it)) is not None]
    # mechanism_scheme writes a letter at (x + 2, y − 2) of its point: the point is back there
    reqs = [LabelRequest((t.pos[0] - 2.0, t.pos[1] + 2.0), t.text, t.height, group="scheme")
            for t in labels]
    placed = place_labels(reqs, obstacles, layer=labels[0].layer if labels else "scheme",
                          id_prefix="scheme-label", merge_mm=0.5)
    return (*rest, *placed)


def mechanism_picture(analysis, lang: str = "ru") -> str:
    """A quick picture of the mechanism for ``graphplan analyze --picture``: the mechanism
    at its first position (the start of the working stroke when the output has dead
    centres), the path of every joint of the output link over the cycle (dashed), and three
    lines saying the position, the crank's sense of rotation and K — so that a wrong
    assembly branch or a reversed direction is seen before the sheets are drawn.

    Returns the SVG text (sizes in mm; the letters in the fonts of the machine that shows
    it, as the lessons' schemes are).
    """
    import math

    from ..drawing import Polyline, Style, Text, scheme_paper
    from ..numbers import plain
    from ..render import svg as svg_render
    from .drawing import svg_document

    mech, kin, cycle = analysis.mech, analysis.kin, analysis.cycle
    items = list(lesson_scheme(analysis, 0))
    paper = scheme_paper(analysis, 0, SCHEME_WIDTH_MM, _scheme_height(analysis, 0))
    out_pts = [p for p in mech.points_of(mech.output.link) if p in kin.pos.points
               and p not in mech.frame_points]
    for p in out_pts:  # the scheme's own transform: its paths fall on its joints
        items.append(Polyline(tuple(paper(xy) for xy in kin.pos.points[p]),
                              Style(0.25, (3.0, 1.5)), True, layer="position_plan",
                              id=f"path-{p}"))
    ru = lang == "ru"
    sense = (("против часовой стрелки" if ru else "counter-clockwise") if mech.crank.sense > 0
             else ("по часовой стрелке" if ru else "clockwise"))
    phi = math.degrees(float(kin.phi[0])) % 360
    start = (", начало рабочего хода" if ru else ", the start of the working stroke"
             ) if cycle.dead_centres else ""
    lines = [f"{'положение' if ru else 'position'} {kin.labels[0]}, φ = {plain(phi, 4)}°{start}",
             f"ω1 {sense}" + (f", K = {plain(cycle.time_ratio, 4)}" if cycle.dead_centres
                              else ""),
             (f"штрихами — траектории точек {', '.join(out_pts)} звена {mech.output.link} "
              "за цикл" if ru else f"dashed: the paths of {', '.join(out_pts)} of link "
              f"{mech.output.link} over the cycle")]
    xs, ys = [], []
    from ..drawing import Group, item_geometry, text_box

    for it in items:
        g = (text_box(it) if isinstance(it, Text) else None if isinstance(it, Group)
             else item_geometry(it))
        if g is not None:
            x0, y0, x1, y1 = g.bounds
            xs += [x0, x1]
            ys += [y0, y1]
    x0, y0 = min(xs) - 4.0, min(ys) - 4.0
    width = max(max(xs) - x0 + 4.0, 110.0)
    top = max(ys) + 8.0
    for n, line in enumerate(lines):
        items.append(Text((x0 + 2.0, top + 6.0 * n), line, 3.5, layer="text",
                          id=f"picture-line-{n}"))
        width = max(width, text_box(items[-1]).bounds[2] - x0 + 4.0)
    height = top + 6.0 * len(lines) - y0
    dwg = svg_document((x0, y0, width, height))
    dwg.add(dwg.rect((x0, y0), (width, height), fill="white"))
    for it in items:
        dwg.add(svg_render._element(dwg, it))
    return '<?xml version="1.0" encoding="utf-8"?>\n' + dwg.tostring() + "\n"
