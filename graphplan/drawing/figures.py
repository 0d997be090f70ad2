"""Figures drawn with matplotlib (imported lazily): the kinematic diagrams of sheet 1.

Sheet 1 carries the three diagrams at their own scales: one millimetre of the figure
is one millimetre of the sheet, so the abscissa is ``length_mm`` long and an ordinate
of y mm stands for ``y·Ks`` (``Kv``, ``Ka``). :func:`fit_diagrams` chooses the length
and the heights for the box the sheet gives, :func:`diagrams_figure` draws them with
matplotlib and :func:`diagrams_items` plays that drawing into the sheet's own items
(:mod:`graphplan.drawing.mpl_items`): its lines become polylines in sheet millimetres,
its letters :class:`~graphplan.drawing.sheet.Text` in the sheet's lettering (GOST 2.304 type
B, slanted; decimal comma on Russian sheets), so that they stay text in the SVG, the
DXF and the PDF and the layout checks see them. matplotlib lays the letters out in the
font the sheet letters them in (:func:`_font`: osifont, bundled, where it draws every
character of a text, else DejaVu Sans), so their widths agree.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from ..errors import LayoutError
from ..kinematics import Cycle
from ..model import Mechanism
from ..numbers import plain
from ..plans import MIN_NODES, KinematicDiagrams, kinematic_diagrams
from . import fonts

MM = 72 / 25.4  #: points per millimetre
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


@lru_cache(maxsize=8)
def _font_file(family: str):
    """matplotlib FontProperties of the bundled file of ``family`` (see graphplan.drawing.fonts).

    Given by file, not by name: matplotlib's own font lookup (its cache, the system's
    fonts, ``MPL_IGNORE_SYSTEM_FONTS``) never decides which font letters a figure.
    """
    from matplotlib.font_manager import FontProperties

    path = fonts.find_font_file(family)
    return FontProperties(fname=str(path)) if path is not None else FontProperties(family=family)


def _font(text: str, height_mm: float) -> dict:
    """Font keywords lettering ``text`` with capitals ``height_mm`` tall.

    osifont when it draws every character (its blank Ё ё Э э and missing −, ₁ … are
    checked by :mod:`graphplan.drawing.fonts`), else DejaVu Sans.
    """
    family = "osifont" if not fonts.missing_chars("osifont", text) else "DejaVu Sans"
    return {"fontproperties": _font_file(family),
            "fontsize": height_mm / fonts.cap_ratio(family) * MM}


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
                 max_length_mm: float = 360.0, max_height_mm: float = 80.0
                 ) -> KinematicDiagrams:
    """:func:`graphplan.plans.diagrams.kinematic_diagrams` sized to fill a box of the sheet.

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

    def make(length, h):
        d = kinematic_diagrams(mech, cycle, intervals=n, length_mm=float(length),
                               height_mm=float(h), reading_mm=reading_mm)
        w_need, h_need = diagrams_size(d)
        return d if w_need <= width_mm and h_need <= height_mm else None

    fixed = TOP + BOTTOM + 2 * GAP + 3 * (PAD_TOP + BELOW_AXIS)  # the most the pads take
    h = min(math.floor(max_height_mm), math.floor((height_mm - fixed) / 3))
    ok = isinstance(n, int) and n >= 4  # else kinematic_diagrams says what is wrong
    if h >= 10:
        for k in range(int(min(max_length_mm, width_mm) // n) if ok else 1, 0, -1):
            d = make(n * k, h)
            if d is not None:  # the pads took less than the most: try taller diagrams
                for taller in range(h + 1, math.floor(max_height_mm) + 1):
                    d = make(n * k, taller) or d
                return d
    raise LayoutError(f"kinematic diagrams do not fit a box of {width_mm:.0f}×{height_mm:.0f} "
                      "mm at any whole-mm length and height")


def _position_numbers(ax, d: KinematicDiagrams, k: int, K: float, x_per_mm: float,
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
        ax.text(x + (0.8 * x_per_mm if x <= 1e-9 else 0.0), gap if above else -gap, lab,
                ha="left" if x <= 1e-9 else "center", va="bottom" if above else "top",
                **_font("0123456789", SMALL_H))


def diagrams_items(d: KinematicDiagrams, origin, width_mm: float, height_mm: float,
                   lang: str = "ru", *, id: str = "kin-diagrams"):
    """The diagrams of :func:`diagrams_figure` as a group of sheet items whose box has its
    top-left corner at ``origin`` (mm)."""
    from .mpl_items import figure_items

    return figure_items(diagrams_figure(d, width_mm, height_mm, lang), origin, id=id,
                        lang=lang)


def diagrams_figure(d: KinematicDiagrams, width_mm: float, height_mm: float,
                    lang: str = "ru"):
    """matplotlib figure of the diagrams s(φ), v(φ), a(φ), ``width_mm`` × ``height_mm``.

    Three stacked axes share the φ axis (crank travel from the first position, the
    main positions numbered at the nodes), drawn at the scales of ``d`` and centred in
    the figure. The s diagram shows the exact curve (main line) with the node
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

    import matplotlib
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    with matplotlib.rc_context({"axes.unicode_minus": False, "lines.solid_capstyle": "round",
                                "lines.solid_joinstyle": "round"}):
        fig = Figure(figsize=(width_mm / 25.4, height_mm / 25.4))
        x0 = (width_mm - f.box_w) / 2
        y = height_mm - TOP - (height_mm - f.height) / 2  # top of the next panel, mm from below
        first = None
        for k, (lo, hi, K, pad_bot, box_h) in enumerate(f.panels):
            y -= box_h
            ax = fig.add_axes((x0 / width_mm, y / height_mm, f.box_w / width_mm,
                               box_h / height_mm), sharex=first)
            y -= GAP
            first = first or ax
            ax.set_xlim(f.xlo, f.xhi)
            ax.set_ylim(lo - pad_bot * K, hi + PAD_TOP * K)
            ax.patch.set_visible(False)
            for side in ("top", "right"):
                ax.spines[side].set_visible(False)
            pole = (0.0, d.H1, d.H2)[k]
            tip = hi + (PAD_TOP - 3.0) * K  # the ordinate axis' arrow
            ax.spines["left"].set_position(("data", 0.0))
            ax.spines["left"].set_bounds(lo - 1.5 * K, tip)
            ax.spines["bottom"].set_position(("data", 0.0))
            ax.spines["bottom"].set_bounds(-pole * x_per_mm, 360.0 + 6 * x_per_mm)
            for sp in ("left", "bottom"):
                ax.spines[sp].set_linewidth(THIN * MM)
            ax.set_yticks([])
            ax.set_xticks(d.node_deg[[bool(s) for s in d.node_labels]])
            ax.set_xticks([x for x, s in zip(d.node_deg, d.node_labels, strict=True) if not s],
                          minor=True)
            ax.set_xticklabels([])
            _position_numbers(ax, d, k, K, x_per_mm, v_end)
            ax.tick_params(axis="x", which="both", direction="inout", width=THIN * MM,
                           length=1.5 * MM, pad=0.6 * MM)
            ax.tick_params(axis="x", which="major", length=2.5 * MM)
            arrow: dict[str, Any] = {"clip_on": False, "color": "black",
                                     "markersize": 2.2 * MM, "lw": 0}
            ax.plot([360.0 + 6 * x_per_mm], [0.0], ">", **arrow)
            ax.plot([0.0], [tip], "^", **arrow)
            ax.text(360.0 + 7 * x_per_mm, 1.0 * K, "φ", ha="left", va="bottom",
                    **_font("φ", TEXT_H))
            label = f"{names[k]}, {units[k]}"
            ax.text(2.5 * x_per_mm, tip, label, ha="left", va="center", **_font(label, TEXT_H))
            unit = f"({units[k]})" if "/" in units[k] else units[k]
            scale = f"K{names[k]} = {plain(K, 4)} {unit}/{t['mm']}" + (
                f",  H{k} = {plain(pole)} {t['mm']}" if k else "")
            ax.text((4.5 + fonts.text_width(label, TEXT_H)) * x_per_mm, tip, scale,
                    ha="left", va="center", **_font(scale, SMALL_H))
            chords = (d.s_nodes, d.v_chords, d.a_chords)[k]
            if k == 0:  # s: the exact curve, the node ordinates and the chords between them
                ax.plot(d.phi_deg, d.s, "-k", lw=MAIN * MM)
                ax.vlines(d.node_deg, 0.0, chords, colors="black", lw=THIN * MM)
                ax.plot(d.node_deg, chords, "-k", lw=THIN * MM)
                continue
            px = -pole * x_per_mm
            for r in chords[: d.intervals]:  # rays from the pole, parallel to the chords
                ax.plot([px, 0.0], [0.0, r], "-", color="black", lw=THIN * MM)
            ax.plot([px], [0.0], "o", color="black", markersize=1.2 * MM, clip_on=False)
            ax.text(px - 2.5 * x_per_mm, 0.0, f"P{k}", ha="right", va="center",
                    **_font("P1", TEXT_H))  # left of the pole: clear of its rays
            ax.plot(d.phi_deg, (d.v, d.a)[k - 1], "-k", lw=THIN * MM)
            if k == 1:
                ax.plot(np.r_[0.0, d.mid_deg, 360.0], np.r_[v_end, chords, v_end], "-k",
                        lw=MAIN * MM)
            else:
                ax.plot(d.node_deg, chords, "-k", lw=MAIN * MM)
            at = (d.mid_deg, d.node_deg)[k - 1]  # where each ray's height is transferred
            ax.vlines(at, 0.0, chords, colors="black", lw=THIN * MM)
            ax.plot(at, chords, "o", color="black", markersize=1.0 * MM, lw=0)
        kphi = f"Kφ = {plain(d.Kphi, 4)} {t['rad']}/{t['mm']}"
        fig.text((x0 + 2) / width_mm, 1 - 1.5 / height_mm, kphi, ha="left", va="top",
                 **_font(kphi, SMALL_H))
        handles = [Line2D([], [], color="black", lw=THIN * MM),
                   Line2D([], [], color="black", lw=MAIN * MM, marker="o",
                          markersize=1.0 * MM)]
        legend = [t["exact"], t["chords"]]
        lf = _font("".join(legend), SMALL_H)
        legend_font = lf["fontproperties"].copy()
        legend_font.set_size(lf["fontsize"])
        fig.legend(handles, legend, loc="upper right", ncols=2, frameon=False,
                   bbox_to_anchor=((x0 + f.box_w) / width_mm, 1 - 0.5 / height_mm),
                   prop=legend_font,
                   handlelength=2.5, borderaxespad=0.0)
    return fig
