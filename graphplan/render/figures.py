"""Figures drawn with matplotlib (imported lazily): the kinematic diagrams of sheet 1.

Sheet 1 carries the three diagrams at their own scales: one millimetre of the figure
is one millimetre of the sheet, so the abscissa is ``length_mm`` long and an ordinate
of y mm stands for ``y·Ks`` (``Kv``, ``Ka``). :func:`fit_diagrams` chooses the length
and the heights for the box the sheet gives, :func:`diagrams_svg` draws them.

The figure is a standalone SVG whose root has ``width``/``height`` in pt
(1 pt = 25.4/72 mm) and ``viewBox="0 0 w h"`` in the same pt. A sheet embeds it as a
nested SVG element in millimetres (:class:`graphplan.sheet.Figure`, written by
:func:`graphplan.render.svg.embedded_svg`)::

    <svg x="X" y="Y" width="W" height="H" viewBox="0 0 w h"> …the figure's content… </svg>

with X, Y the top-left corner on the sheet and W×H the size the figure was drawn for
(mm, the sheet's user unit), so the content is scaled 25.4/72 and not distorted; its
ids get the figure's prefix so that pictures never clash. Glyphs are paths
(``svg.fonttype = "path"``): the figure does not depend on installed fonts when
rendered. No date and a fixed ``svg.hashsalt``: the same diagrams give the same text.
"""

from __future__ import annotations

import io
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import fonts
from ..cycle import Cycle
from ..diagrams import MIN_NODES, KinematicDiagrams, kinematic_diagrams
from ..errors import LayoutError
from ..model import Mechanism
from ..units import fmt

MM = 72 / 25.4  #: points per millimetre
THIN, MAIN = 0.25, 0.5  #: line widths, mm
TEXT_H, SMALL_H = 3.5, 2.5  #: capital heights of labels and of position numbers, mm
#: Margins, mm: the legend strip on top, below, between panels, left and right of the axes
#: box; above each curve (the arrow and the label), below it, and the room the position
#: numbers need under the φ axis.
TOP, BOTTOM, GAP, MARGIN_X, PAD_TOP, PAD_BOT, BELOW_AXIS = 6.0, 1.0, 3.0, 2.0, 8.0, 1.5, 5.5
HASH_SALT = "graphplan"  #: fixed salt of matplotlib's SVG ids: the same figure, the same text

TEXT = {
    "en": {"exact": "exact", "chords": "method of chords", "m": "m", "s": "s", "rad": "rad",
           "mm": "mm"},
    "ru": {"exact": "точно", "chords": "метод хорд", "m": "м", "s": "с", "rad": "рад",
           "mm": "мм"},
}


@lru_cache(maxsize=8)
def _font_file(family: str):
    """matplotlib FontProperties of the bundled file of ``family`` (see graphplan.fonts).

    Given by file, not by name: matplotlib's own font lookup (its cache, the system's
    fonts, ``MPL_IGNORE_SYSTEM_FONTS``) never decides which font letters a figure.
    """
    from matplotlib.font_manager import FontProperties

    path = fonts.find_font_file(family)
    return FontProperties(fname=str(path)) if path is not None else FontProperties(family=family)


def _font(text: str, height_mm: float) -> dict:
    """Font keywords lettering ``text`` with capitals ``height_mm`` tall.

    osifont when it draws every character (its blank Ё ё Э э and missing −, ₁ … are
    checked by :mod:`graphplan.fonts`), else DejaVu Sans.
    """
    family = "osifont" if not fonts.missing_chars("osifont", text) else "DejaVu Sans"
    return {"fontproperties": _font_file(family),
            "fontsize": height_mm / fonts.cap_ratio(family) * MM}


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
    """The smallest ``(width, height)`` in mm that :func:`diagrams_svg` can draw ``d`` in."""
    f = _frame(d)
    return f.width, f.height


def fit_diagrams(mech: Mechanism, cycle: Cycle, width_mm: float, height_mm: float, *,
                 intervals: int | None = None, reading_mm: float | None = None,
                 max_length_mm: float = 360.0, max_height_mm: float = 80.0
                 ) -> KinematicDiagrams:
    """:func:`graphplan.diagrams.kinematic_diagrams` sized to fill a box of the sheet.

    The abscissa gets the largest length L = n·k mm (n intervals, k a whole number of
    mm, so every node falls on a whole mm; L ≤ ``max_length_mm``) with which the
    figure, poles included, fits the box's width; then each diagram the largest whole-mm
    height (``height_mm`` of :func:`~graphplan.diagrams.kinematic_diagrams`, at most
    ``max_height_mm``) that still fits the box.

    Raises
    ------
    LayoutError
        If no such length fits (the box is too small for the diagrams).
    InputError
        Bad ``intervals`` or ``reading_mm`` (from :func:`~graphplan.diagrams.kinematic_diagrams`).
    """
    count = mech.positions.count
    n = intervals if intervals is not None else count * math.ceil(MIN_NODES / count)

    def make(length, h):
        d = kinematic_diagrams(mech, cycle, intervals=n, length_mm=float(length),
                               height_mm=float(h), reading_mm=reading_mm)
        w_need, h_need = diagrams_size(d)
        return d if w_need <= width_mm and h_need <= height_mm else None

    fixed = TOP + BOTTOM + 2 * GAP + 3 * (PAD_TOP + BELOW_AXIS)  # the most the pads take
    h = min(max_height_mm, math.floor((height_mm - fixed) / 3))
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


def diagrams_svg(d: KinematicDiagrams, width_mm: float, height_mm: float,
                 lang: str = "ru") -> str:
    """SVG text of the diagrams s(φ), v(φ), a(φ), exactly ``width_mm`` × ``height_mm``.

    Three stacked axes share the φ axis (crank travel from the first position, the
    main positions numbered at the nodes), drawn at the scales of ``d`` and centred in
    the figure. The s diagram shows the exact curve (main line) with the node
    ordinates and the chords between them; the v and a diagrams show the exact curve
    (thin) and the method of chords: the pole P1 (P2) at H1 (H2) mm left of the
    origin, its rays parallel to the chords, and the points and polyline so obtained.

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

    rc = {"svg.fonttype": "path", "svg.hashsalt": HASH_SALT, "axes.unicode_minus": False,
          "lines.solid_capstyle": "round", "lines.solid_joinstyle": "round"}
    with matplotlib.rc_context(rc):
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
            ax.set_xticklabels([s for s in d.node_labels if s], **_font("0123456789", SMALL_H))
            ax.tick_params(axis="x", which="both", direction="inout", width=THIN * MM,
                           length=1.5 * MM, pad=0.6 * MM)
            ax.tick_params(axis="x", which="major", length=2.5 * MM)
            arrow = {"clip_on": False, "color": "black", "markersize": 2.2 * MM, "lw": 0}
            ax.plot([360.0 + 6 * x_per_mm], [0.0], ">", **arrow)
            ax.plot([0.0], [tip], "^", **arrow)
            ax.text(360.0 + 7 * x_per_mm, 1.0 * K, "φ", ha="left", va="bottom",
                    **_font("φ", TEXT_H))
            label = f"{names[k]}, {units[k]}"
            ax.text(2.5 * x_per_mm, tip, label, ha="left", va="center", **_font(label, TEXT_H))
            unit = f"({units[k]})" if "/" in units[k] else units[k]
            scale = f"K{names[k]} = {fmt(K, 4)} {unit}/{t['mm']}" + (
                f",  H{k} = {fmt(pole)} {t['mm']}" if k else "")
            ax.text((4.5 + fonts.text_width(label, TEXT_H)) * x_per_mm, tip, scale,
                    ha="left", va="center", **_font(scale, SMALL_H))
            chords = (d.s_nodes, d.v_chords, d.a_chords)[k]
            if k == 0:  # s: the exact curve, the node ordinates and the chords between them
                ax.plot(d.phi_deg, d.s, "-k", lw=MAIN * MM)
                ax.vlines(d.node_deg, 0.0, chords, colors="black", lw=0.6 * THIN * MM)
                ax.plot(d.node_deg, chords, "-k", lw=THIN * MM)
                continue
            px = -pole * x_per_mm
            for r in chords[: d.intervals]:  # rays from the pole, parallel to the chords
                ax.plot([px, 0.0], [0.0, r], "-", color="0.45", lw=0.7 * THIN * MM)
            ax.plot([px], [0.0], "o", color="black", markersize=1.2 * MM, clip_on=False)
            ax.text(px, 1.2 * K, f"P{k}", ha="center", va="bottom", **_font("P1", TEXT_H))
            ax.plot(d.phi_deg, (d.v, d.a)[k - 1], "-k", lw=THIN * MM)
            if k == 1:
                ax.plot(np.r_[0.0, d.mid_deg, 360.0], np.r_[v_end, chords, v_end], "-k",
                        lw=MAIN * MM)
            else:
                ax.plot(d.node_deg, chords, "-k", lw=MAIN * MM)
            ax.plot((d.mid_deg, d.node_deg)[k - 1], chords, "o", color="black",
                    markersize=1.0 * MM, lw=0)
        kphi = f"Kφ = {fmt(d.Kphi, 4)} {t['rad']}/{t['mm']}"
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
        buf = io.StringIO()
        fig.savefig(buf, format="svg", metadata={"Date": None})
    return buf.getvalue()


def svg_viewbox(svg_text: str) -> tuple[float, float]:
    """Width and height of the root ``viewBox`` of ``svg_text`` (user units: pt here)."""
    root = ET.fromstring(svg_text.encode("utf-8"))
    _, _, w, h = (float(v) for v in root.get("viewBox", "").replace(",", " ").split())
    return w, h
