"""Matplotlib figures turned into the sheet's own items, through matplotlib's backend hooks.

A diagram of a sheet is drawn with matplotlib in millimetres of the sheet (an axes box
``w`` mm wide whose data run over ``w`` mm, see :mod:`graphplan.drawing.figures`), then
*played* into :class:`Recorder`, a matplotlib renderer (``RendererBase``) that records
what matplotlib asks it to draw instead of painting pixels or writing SVG:

* ``draw_path`` (lines, curves, markers, arrowheads, patches) → :class:`~graphplan.drawing.sheet.
  Polyline` in sheet mm (curves flattened by matplotlib's own ``Path.to_polygons``;
  filled paths closed and filled; clipped to the axes where matplotlib clips);
* ``draw_text`` (labels, tick labels, legends) → :class:`~graphplan.drawing.sheet.Text`: the
  string itself, at matplotlib's baseline point and angle, its capital height the GOST
  2.304 size it was asked for, slanted 75° like every text of the sheet.

So a diagram is lettered like the rest of the sheet (GOST type B, the sheet's font and
its fallbacks, slanted by the sheet's renderer); its texts stay texts in the SVG and
become TEXT entities in the DXF; the layout checks see its letters and lines. Nothing is
parsed back from SVG.

Units: the figure is made at 72 dpi, so a display unit is a point (1/72 in); a point
(x, y) of the display (y up from the figure's bottom) is ``(X + x/MM, Y + (h − y)/MM)``
on the sheet (y down), for the figure's top-left corner (X, Y) and height h pt.
"""

from __future__ import annotations

import math

import numpy as np

from ..numbers import decimal_comma
from . import fonts
from .sheet import TEXT_HEIGHTS, Group, Item, Polyline, Style, Text

MM = 72 / 25.4  #: points per millimetre
MIN_WIDTH = 0.25  #: thinnest line of a sheet, mm (GOST 2.303 thin line S/3 … S/2, S = 0.7)


def _colour(rgba) -> str:
    r, g, b = (float(c) for c in rgba[:3])
    if max(r, g, b) < 1e-3:
        return "black"
    return "#{:02x}{:02x}{:02x}".format(*(round(255 * c) for c in (r, g, b)))


def _visible(rgba) -> bool:
    return rgba is not None and (len(rgba) < 4 or float(rgba[3]) > 0.0)


def _text_height(prop) -> float:
    """The GOST 2.304 capital height (mm) nearest to a font size asked in points."""
    name = (prop.get_family() or ["DejaVu Sans"])[0]
    family = "osifont" if "osifont" in name.lower() else "DejaVu Sans"
    h = prop.get_size_in_points() / MM * fonts.cap_ratio(family)
    return min(TEXT_HEIGHTS, key=lambda v: abs(v - h))




class _RecorderMixin:
    """Records the drawing calls of a matplotlib figure as sheet items (see module)."""

    def _setup(self, width_pt: float, height_pt: float, origin, layer: str, lang: str) -> None:
        self.width_pt, self.height_pt = width_pt, height_pt
        self.ox, self.oy = origin
        self.layer = layer
        self.lang = lang
        self.items: list[Item] = []

    # ------------------------------------------------------------------ canvas
    def get_canvas_width_height(self):
        return self.width_pt, self.height_pt

    def flipy(self):  # texts get y from the top, like the sheet
        return True

    def points_to_pixels(self, points):
        return points

    def option_image_nocomposite(self):
        return True

    def draw_image(self, gc, x, y, im, transform=None):  # pragma: no cover - never asked
        raise TypeError("a sheet's diagram has no raster images")

    # ------------------------------------------------------------------ paths
    def _sheet(self, pts: np.ndarray) -> list[tuple[float, float]]:
        return [(self.ox + float(x) / MM, self.oy + (self.height_pt - float(y)) / MM)
                for x, y in pts]

    def draw_path(self, gc, path, transform, rgbFace=None):
        stroke_rgba = gc.get_rgb()
        lw = float(gc.get_linewidth()) / MM
        stroke = lw > 0 and _visible(stroke_rgba) and (gc.get_alpha() or 1.0) > 0
        # a white face (axes, legend) only masks the paper: the sheet does not paint it
        fill = _visible(rgbFace) and min(float(c) for c in rgbFace[:3]) < 1.0 - 1e-3
        if not (stroke or fill):
            return
        _offset, dashes = gc.get_dashes()
        dash = (tuple(max(float(d) / MM, 0.5) for d in dashes)
                if dashes is not None and len(dashes) and stroke else None)
        colour = _colour(stroke_rgba if stroke else rgbFace)
        style = Style(max(lw, MIN_WIDTH), dash, colour,
                      _colour(rgbFace) if fill else None)
        clip = gc.get_clip_rectangle()
        for poly in path.to_polygons(transform, closed_only=bool(fill)):
            if len(poly) < 2:
                continue
            closed = len(poly) > 2 and np.allclose(poly[0], poly[-1])
            if closed:
                poly = poly[:-1]
            if clip is not None and not fill:
                for part in _clip(poly, clip, closed):
                    self._add(part, style, False)
            else:
                self._add(poly, style, closed or fill)

    def _add(self, poly: np.ndarray, style: Style, closed: bool) -> None:
        pts = self._sheet(poly)
        pts = [p for i, p in enumerate(pts) if i == 0 or p != pts[i - 1]]
        if len(pts) >= 2 and not (closed and len(pts) < 3):
            self.items.append(Polyline(tuple(pts), style, closed, layer=self.layer))

    # ------------------------------------------------------------------ texts
    def draw_text(self, gc, x, y, s, prop, angle, ismath=False, mtext=None):
        text = s.strip()
        if not text:
            return
        if self.lang == "ru":
            text = decimal_comma(text)
        height = _text_height(prop)
        a = math.radians(angle)
        ux, uy = math.cos(a), -math.sin(a)  # the baseline's direction on the y-down sheet
        lead = len(s) - len(s.lstrip())
        x0, y0 = self.ox + float(x) / MM, self.oy + float(y) / MM
        if lead:  # matplotlib placed the string with its leading blanks
            w = self.get_text_width_height_descent(s[:lead], prop, ismath)[0] / MM
            x0, y0 = x0 + ux * w, y0 + uy * w
        anchor = "start"
        ha = mtext.get_horizontalalignment() if mtext is not None else "left"
        if ha in ("center", "right") and angle % 360.0 == 0.0:
            w = self.get_text_width_height_descent(text, prop, ismath)[0] / MM
            k = 0.5 if ha == "center" else 1.0
            x0, y0 = x0 + ux * w * k, y0 + uy * w * k
            anchor = "middle" if ha == "center" else "end"
        self.items.append(Text((x0, y0), text, height, anchor, float(angle) % 360.0,
                               layer=self.layer))


def _clip(poly: np.ndarray, clip, closed: bool) -> list[np.ndarray]:
    """Parts of a polyline inside matplotlib's clip box (display units)."""
    (x0, y0), (x1, y1) = clip.get_points()
    eps = 1e-6
    if (poly[:, 0].min() >= x0 - eps and poly[:, 0].max() <= x1 + eps
            and poly[:, 1].min() >= y0 - eps and poly[:, 1].max() <= y1 + eps):
        return [np.vstack((poly, poly[:1]))] if closed else [poly]
    from shapely.geometry import LineString, box

    ring = np.vstack((poly, poly[:1])) if closed else poly
    cut = LineString(ring).intersection(box(x0, y0, x1, y1))
    parts = getattr(cut, "geoms", [cut])
    return [np.asarray(g.coords) for g in parts
            if g.geom_type == "LineString" and not g.is_empty and g.length > 1e-9]


def figure_items(fig, origin, *, layer: str = "diagrams", id: str, lang: str = "ru"
                 ) -> Group:
    """The items of a matplotlib figure placed with its top-left corner at ``origin`` (mm).

    The figure must have been made with ``figsize`` in inches of its size in mm /25.4;
    it is drawn at 72 dpi so that one display unit is one point. Texts on a Russian
    sheet (``lang="ru"``) get the decimal comma.
    """
    from matplotlib.backend_bases import FigureCanvasBase, RendererBase

    class Recorder(_RecorderMixin, RendererBase):
        pass

    fig.set_dpi(72)
    if fig.canvas is None or type(fig.canvas) is not FigureCanvasBase:
        FigureCanvasBase(fig)
    fig.patch.set_visible(False)
    w, h = fig.bbox.width, fig.bbox.height
    rec = Recorder()
    rec._setup(w, h, origin, layer, lang)
    import matplotlib

    with matplotlib.rc_context({"axes.unicode_minus": False}):  # osifont has no U+2212
        fig.draw(rec)
    return Group(tuple(rec.items), layer=layer, id=id)


__all__ = ["MIN_WIDTH", "MM", "figure_items"]
