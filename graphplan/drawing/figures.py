"""The kinematic diagrams of sheet 1, drawn as the sheet's own items.

Sheet 1 carries the three diagrams at their own scales: one millimetre of the figure
is one millimetre of the sheet, so the abscissa is ``length_mm`` long and an ordinate
of y mm stands for ``y·Ks`` (``Kv``, ``Ka``). :func:`fit_diagrams` chooses the length
and the heights for the box the sheet gives and :func:`diagrams_items` draws them
(:class:`graphplan.drawing.chart.Chart`): polylines in sheet millimetres and
:class:`~graphplan.drawing.items.Text` in the sheet's lettering (GOST 2.304 type B,
slanted; decimal comma on Russian sheets), so that they stay text in the SVG, the DXF
and the PDF and the layout checks see them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import fonts
from ..errors import LayoutError
from ..kinematics import Cycle
from ..model import Mechanism
from ..numbers import plain
from ..plans import MIN_NODES, KinematicDiagrams, diagram_motion, kinematic_diagrams
from .chart import MIN_DOT, Chart
from .items import Circle, Group, Item, Style

THIN, MAIN = 0.25, 0.5  #: line widths, mm
TEXT_H, SMALL_H = 3.5, 2.5  #: capital heights of labels and of position numbers, mm
#: Margins, mm: the legend strip on top, below, between panels, left and right of the axes
#: box; above each curve (the arrow and the label), below it, and the room the position
#: numbers need under the φ axis.
TOP, BOTTOM, GAP, MARGIN_X, PAD_TOP, PAD_BOT, BELOW_AXIS = 6.0, 1.0, 3.0, 2.0, 8.0, 1.5, 5.5

TEXT = {
    "en": {"exact": "exact", "chords": "method of chords", "m": "m", "s": "s", "rad": "rad",
           "mm": "mm"},
    "ru": {"exact": "точно", "chords": "метод хорд", "m": "м", "s": "с", "rad": "рад",
           "mm": "мм"},
}


def spaced_labels(xs, labels, mm_per_unit: float, height: float = SMALL_H) -> list[str]:
    """Labels of ticks at ``xs`` (data units, ``mm_per_unit`` mm each) with those that would
    touch the previous shown one left blank: close positions (a, 1; 0′, 7) never overprint."""
    out, last = [], -math.inf
    for x, lab in zip(xs, labels, strict=True):
        half = 0.5 * fonts.text_width(str(lab), height) + 0.3 * height
        if x * mm_per_unit - half - last < 1.0:
            out.append("")
        else:
            out.append(str(lab))
            last = x * mm_per_unit + half
    return out


@dataclass(frozen=True, slots=True)
class _Frame:
    """Geometry of the figure in mm: the axes box width and each panel's ordinate range."""

    xlo: float  # abscissa limits, degrees of travel
    xhi: float
    box_w: float  # width of the axes box, mm
    panels: tuple[tuple[float, float, float, float, float], ...]  # (lo, hi, K, pad_bot, box_h)
    width: float  # smallest figure that holds it all, mm
    height: float


def _frame(d: KinematicDiagrams) -> _Frame:
    x_per_mm = 360.0 / d.length_mm
    xlo = -(max(d.H1, d.H2) + 4.0) * x_per_mm  # room for the poles' letters
    xhi = 360.0 + 8.0 * x_per_mm  # room for the arrow and φ
    box_w = (xhi - xlo) / x_per_mm
    panels = []
    for curve, chords, K in ((d.s, d.s_nodes, d.Ks), (d.v, d.v_chords, d.Kv),
                             (d.a, d.a_chords, d.Ka)):
        lo = float(min(curve.min(), chords.min(), 0.0))
        hi = float(max(curve.max(), chords.max(), 0.0))
        pad_bot = max(PAD_BOT, BELOW_AXIS + lo / K)  # position numbers under the φ axis
        panels.append((lo, hi, K, pad_bot, (hi - lo) / K + pad_bot + PAD_TOP))
    return _Frame(xlo, xhi, box_w, tuple(panels), MARGIN_X + box_w + MARGIN_X,
                  TOP + BOTTOM + 2 * GAP + sum(p[-1] for p in panels))


def diagrams_size(d: KinematicDiagrams) -> tuple[float, float]:
    """The smallest ``(width, height)`` in mm that :func:`diagrams_figure` can draw ``d`` in."""
    f = _frame(d)
    return f.width, f.height


def fit_diagrams(mech: Mechanism, cycle: Cycle, width_mm: float, height_mm: float, *,
                 intervals: int | None = None, reading_mm: float | None = None,
                 max_length_mm: float = 360.0, max_height_mm: float = 80.0, solve_on=None
                 ) -> KinematicDiagrams:
    """:func:`graphplan.plans.diagrams.kinematic_diagrams` sized to fill a box of the sheet
    (the motion solved once for every size tried; ``solve_on``: the project's kinematics of
    a grid, :meth:`graphplan.project.Project.solve_on`).

    The abscissa gets the largest length L = n·k mm (n intervals, k a whole number of
    mm, so every node falls on a whole mm; L ≤ ``max_length_mm``) with which the
    figure, poles included, fits the box's width; then each diagram the largest whole-mm
    height (``height_mm`` of :func:`~graphplan.plans.diagrams.kinematic_diagrams`, at most
    ``max_height_mm``) that still fits the box.

    Raises
    ------
    LayoutError
        If no such length fits (the box is too small for the diagrams).
    InputError
        Bad ``intervals`` or ``reading_mm`` (from
        :func:`~graphplan.plans.diagrams.kinematic_diagrams`).
    """
    count = mech.positions.count
    n = intervals if intervals is not None else count * math.ceil(MIN_NODES / count)

    ok = isinstance(n, int) and n >= 4  # else kinematic_diagrams says what is wrong
    # the same at every size tried
    motion = diagram_motion(mech, cycle, n, solve_on) if ok else None

    def make(length, h):
        d = kinematic_diagrams(mech, cycle, intervals=n, length_mm=float(length),
                               height_mm=float(h), reading_mm=reading_mm, motion=motion)
        w_need, h_need = diagrams_size(d)
        return d if w_need <= width_mm and h_need <= height_mm else None

    fixed = TOP + BOTTOM + 2 * GAP + 3 * (PAD_TOP + BELOW_AXIS)  # the most the pads take
    h = min(math.floor(max_height_mm), math.floor((height_mm - fixed) / 3))
    if h >= 10:
        for k in range(int(min(max_length_mm, width_mm) // n) if ok else 1, 0, -1):
            d = make(n * k, h)
            if d is not None:  # the pads took less than the most: try taller diagrams
                for taller in range(h + 1, math.floor(max_height_mm) + 1):
                    d = make(n * k, taller) or d
                return d
    raise LayoutError(f"kinematic diagrams do not fit a box of {width_mm:.0f}×{height_mm:.0f} "
                      "mm at any whole-mm length and height")


def _position_numbers(ch: Chart, d: KinematicDiagrams, k: int, K: float, x_per_mm: float,
                      v_end: float) -> None:
    """The numbers of the main positions on the φ axis of panel k, each on the side of the
    axis away from the curve and the chords there (below where they run above), the one
    at the origin right of the ordinate axis, close ones left out (:func:`spaced_labels`)."""
    curve = (d.s, d.v, d.a)[k]
    if k == 1:
        cx, cy = np.r_[0.0, d.mid_deg, 360.0], np.r_[v_end, d.v_chords, v_end]
    else:
        cx, cy = d.node_deg, (d.s_nodes, d.v_chords, d.a_chords)[k]
    named = [(x, s) for x, s in zip(d.node_deg, d.node_labels, strict=True) if s]
    shown = spaced_labels([x for x, _ in named], [s for _, s in named], 1.0 / x_per_mm)
    gap = 1.6 * K
    for (x, _), lab in zip(named, shown, strict=True):
        if not lab:
            continue
        half = (0.5 * fonts.text_width(lab, SMALL_H) + 1.0) * x_per_mm
        lo_x, hi_x = (x, x + 2 * half) if x <= 1e-9 else (x - half, x + half)
        sel = (d.phi_deg >= lo_x) & (d.phi_deg <= hi_x)
        vals = np.r_[curve[sel], np.interp([lo_x, x, hi_x], cx, cy)]
        above = vals.max() <= 0.0 or (vals.min() < 0.0 < vals.max() and vals.mean() < 0.0)
        ch.text(x + (0.8 * x_per_mm if x <= 1e-9 else 0.0), gap if above else -gap, lab,
                SMALL_H, "left" if x <= 1e-9 else "center", "bottom" if above else "top")


def diagrams_items(d: KinematicDiagrams, origin, width_mm: float, height_mm: float,
                   lang: str = "ru", *, id: str = "kin-diagrams") -> Group:
    """The diagrams s(φ), v(φ), a(φ) in a box ``width_mm`` × ``height_mm`` whose top-left
    corner is at ``origin`` (sheet mm), as a group of the sheet's items.

    Three stacked panels share the φ axis (crank travel from the first position, the
    main positions numbered at the nodes), drawn at the scales of ``d`` and centred in
    the box. The s diagram shows the exact curve (main line) with the node
    ordinates and the chords between them; the v and a diagrams show the exact curve
    (thin) and the method of chords: the pole P1 (P2) at H1 (H2) mm left of the
    origin, its rays parallel to the chords, the ordinates their heights are transferred
    to (the middle of each interval for v, the nodes for a), and the points and polyline
    so obtained.

    Raises
    ------
    LayoutError
        If the diagrams at their scales do not fit ``width_mm`` × ``height_mm`` (see
        :func:`diagrams_size`, :func:`fit_diagrams`).
    KeyError
        For a language other than ``"ru"`` or ``"en"``.
    """
    t = TEXT[lang]
    f = _frame(d)
    if f.width > width_mm + 1e-9 or f.height > height_mm + 1e-9:
        raise LayoutError(f"kinematic diagrams need {f.width:.0f}×{f.height:.0f} mm at their "
                          f"scales, the place is {width_mm:.0f}×{height_mm:.0f} mm")
    rocker = d.output_kind == "rocker"
    x_per_mm = 360.0 / d.length_mm
    per = f"{t['rad'] if rocker else t['m']}/{t['s']}"
    names = (("ψ", "ω", "ε") if rocker else ("s", "v", "a"))
    units = (t["rad"] if rocker else t["m"], per, per + "²")
    v_end = 0.5 * (d.v_chords[0] + d.v_chords[-1])  # the periodic v polyline at 0° and 360°

    ox, oy = (float(v) for v in origin)
    left = ox + (width_mm - f.box_w) / 2  # the panels' left side, sheet mm
    top = oy + TOP + (height_mm - f.height) / 2  # top of the next panel, sheet mm
    items: list[Item] = []
    for k, (lo, hi, K, pad_bot, box_h) in enumerate(f.panels):
        ch = Chart(left, top, f.box_w, box_h, (f.xlo, f.xhi), (lo - pad_bot * K,
                                                                hi + PAD_TOP * K), lang)
        top += box_h + GAP
        pole = (0.0, d.H1, d.H2)[k]
        tip = hi + (PAD_TOP - 3.0) * K  # the ordinate axis' arrow
        # the axes through the origin: φ from the pole to its arrow, the ordinate up to its
        ch.plot([-pole * x_per_mm, 360.0 + 6 * x_per_mm], [0.0, 0.0], THIN, clip=False)
        ch.plot([0.0, 0.0], [lo - 1.5 * K, tip], THIN, clip=False)
        ch.xticks([x for x, s in zip(d.node_deg, d.node_labels, strict=True) if not s],
                  [], length=1.5, width=THIN, at=0.0, direction="inout")
        ch.xticks(d.node_deg[[bool(s) for s in d.node_labels]], [], length=2.5, width=THIN,
                  at=0.0, direction="inout")
        _position_numbers(ch, d, k, K, x_per_mm, v_end)
        ch.triangle(360.0 + 6 * x_per_mm, 0.0, ARROW_MM, "right")
        ch.triangle(0.0, tip, ARROW_MM, "up")
        ch.text(360.0 + 7 * x_per_mm, 1.0 * K, "φ", TEXT_H, "left", "bottom")
        label = f"{names[k]}{d.output.replace('_', '')}, {units[k]}"
        ch.text(2.5 * x_per_mm, tip, label, TEXT_H, "left", "center")
        unit = f"({units[k]})" if "/" in units[k] else units[k]
        scale = f"K{names[k]} = {plain(K, 4)} {unit}/{t['mm']}" + (
            f",  H{k} = {plain(pole)} {t['mm']}" if k else "")
        ch.text((4.5 + fonts.text_width(label, TEXT_H)) * x_per_mm, tip, scale, SMALL_H,
                "left", "center")
        chords = (d.s_nodes, d.v_chords, d.a_chords)[k]
        if k == 0:  # s: the exact curve, the node ordinates and the chords between them
            ch.plot(d.phi_deg, d.s, MAIN)
            ch.vlines(d.node_deg, 0.0, chords, THIN)
            ch.plot(d.node_deg, chords, THIN)
        else:
            px = -pole * x_per_mm
            for r in chords[: d.intervals]:  # rays from the pole, parallel to the chords
                ch.plot([px, 0.0], [0.0, r], THIN)
            ch.dots([px], [0.0], 1.2)
            ch.text(px - 2.5 * x_per_mm, 0.0, f"P{k}", TEXT_H, "right", "center")
            ch.plot(d.phi_deg, (d.v, d.a)[k - 1], THIN)
            if k == 1:
                ch.plot(np.r_[0.0, d.mid_deg, 360.0], np.r_[v_end, chords, v_end], MAIN)
            else:
                ch.plot(d.node_deg, chords, MAIN)
            at = (d.mid_deg, d.node_deg)[k - 1]  # where each ray's height is transferred
            ch.vlines(at, 0.0, chords, THIN)
            ch.dots(at, chords, 1.0)
        items += ch.items
    kphi = f"Kφ = {plain(d.Kphi, 4)} {t['rad']}/{t['mm']}"
    page = Chart(ox, oy, width_mm, height_mm, (0.0, 1.0), (0.0, 1.0), lang)  # its letters
    page.letter(left + 2.0, oy + 1.5, kphi, SMALL_H, "left", "top")  # the box's top strip
    _legend(page, left + f.box_w, oy + 0.5,
            [(t["exact"], THIN, False), (t["chords"], MAIN, True)])
    return Group(tuple(items + page.items), layer="diagrams", id=id)


#: the axes' arrowheads, mm long and wide
ARROW_MM = 2.2


def _legend(ch: Chart, right: float, top: float, entries) -> None:
    """A legend of one row ending at ``right``, its letters' top ``top`` (sheet mm): per
    entry a line sample 2.5 em long (with a dot for a graphical construction) and its
    words."""
    em = SMALL_H / fonts.cap_ratio("osifont")  # the letters' em, mm
    x = right - 0.4 * em
    y = top + 0.4 * em
    mid = y + 0.5 * SMALL_H  # the samples level with the capitals' middle
    for k, (words, width, dot) in enumerate(reversed(entries)):
        x -= fonts.text_width(words, SMALL_H)
        ch.letter(x, y, words, SMALL_H, "left", "top")
        x -= 0.8 * em
        ch.polyline(((x - 2.5 * em, mid), (x, mid)), Style(width), clip=False)
        if dot:
            ch.items.append(Circle((x - 1.25 * em, mid), 0.5, Style(MIN_DOT, fill="black"),
                                   layer=ch.layer))
        x -= 2.5 * em + (2.0 * em if k < len(entries) - 1 else 0.0)
