"""A plot's axes drawn straight as the sheet's own items (no plotting library).

The diagrams of the sheets (the kinematic diagrams of sheet 1, Q(s) and Mур(φ) of sheet 2,
ω(φ) of sheet 3) are drawn here in millimetres of the sheet: a :class:`Chart` is an axes
box on the sheet (top-left corner, width and height in mm, y down) with its data limits,
and turns data into sheet points by the linear map

    X = x0 + (x − x_lo) / (x_hi − x_lo) · width,   Y = y0 + (y_hi − y) / (y_hi − y_lo) · height.

Its lines are :class:`~graphplan.drawing.items.Polyline` (clipped to the box, as a plot's
curves are), its dots filled circles, its letters :class:`~graphplan.drawing.items.Text` of
GOST 2.304 capital height (slanted like every text of the sheet; the decimal comma on a
Russian sheet), so they stay texts in the SVG, the DXF and the PDF and the layout checks
see them. Text is placed by its capitals: ``va="top"`` puts the capitals' top on the
point, ``"center"`` their middle, ``"bottom"`` the descenders' foot (0.3 h below the
baseline, as :func:`~graphplan.drawing.items.text_box` counts them).

The ordinate's values are chosen like a drafter chooses them and as matplotlib's
``MaxNLocator`` does (:func:`nice_ticks`: steps 1, 2, 2.5, 5 × 10ⁿ, as many as fit the
axis at two label heights apart), written with the fewest decimals that tell them apart
(:func:`tick_labels`). Drawing a sheet so never imports matplotlib (a third of a second
of a cold ``graphplan sheets``).
"""

from __future__ import annotations

import math

import numpy as np

from .. import fonts
from ..numbers import decimal_comma
from .items import Circle, Item, Polyline, Style, Text

LAYER = "diagrams"
#: Space between a tick and its label, and between the tick labels and the axis' name, mm
#: (matplotlib's 3.5 pt and 4 pt).
TICK_PAD, LABEL_PAD = 1.2, 1.4
#: Descenders below the baseline, in capital heights (as :func:`sheet.text_box` counts).
DESCENT = 0.3
#: Steps of the ordinate's values in each decade (matplotlib's AutoLocator).
AUTO_STEPS = (1.0, 2.0, 2.5, 5.0, 10.0)
#: The steps a given number of values is chosen from (matplotlib's MaxNLocator default).
ALL_STEPS = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0)


def baseline(y: float, h: float, va: str) -> float:
    """The baseline (sheet y, down) of a text of capitals ``h`` aligned ``va`` at ``y``."""
    return y + {"top": h, "center": 0.5 * h, "baseline": 0.0, "bottom": -DESCENT * h}[va]


def nice_ticks(lo: float, hi: float, nbins: int, steps=AUTO_STEPS) -> np.ndarray:
    """At most ``nbins`` + 1 round values spanning [lo, hi] (those inside it returned).

    As matplotlib's ``MaxNLocator``: the step is the smallest of ``steps`` × 10ⁿ at least
    (hi − lo)/nbins that still gives two values inside the range, the values its multiples.
    """
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi <= lo:
        return np.array([lo])
    nbins = max(1, int(nbins))
    span = hi - lo
    mean = 0.5 * (hi + lo)
    offset = 0.0 if abs(mean) / span < 100 else math.copysign(
        10 ** math.floor(math.log10(abs(mean))), mean)
    scale = 10 ** math.floor(math.log10(span / nbins))
    base = np.asarray(steps, dtype=float)
    ext = np.concatenate([0.1 * base[:-1], base, [10 * base[1]]]) * scale
    vlo, vhi = lo - offset, hi - offset
    raw = (vhi - vlo) / nbins
    first = int(np.nonzero(ext >= raw)[0][0])
    ticks = np.array([lo])
    for step in ext[: first + 1][::-1]:
        best = (vlo // step) * step
        d, m = divmod(vlo - best, step)
        low = d + 1 if abs(m / step - 1) < 1e-10 else d
        d, m = divmod(vhi - best, step)
        high = d if abs(m / step) < 1e-10 else d + 1
        ticks = np.arange(low, high + 1) * step + best
        if ((ticks <= vhi) & (ticks >= vlo)).sum() >= 2:
            break
    ticks = ticks + offset
    eps = 1e-10 * span
    return ticks[(ticks >= lo - eps) & (ticks <= hi + eps)]


def tick_labels(values) -> list[str]:
    """The values with the fewest decimals that tell them apart (as matplotlib's
    ``ScalarFormatter`` writes them, without its offset), ``-`` for minus, no ``-0``."""
    v = np.asarray(values, dtype=float)
    if len(v) < 2:
        return [f"{x:g}" for x in v]
    rng = float(np.ptp(v)) or max(float(np.max(np.abs(v))), 1.0)
    oom = math.floor(math.log10(rng))
    digits = max(0, 3 - oom)
    thresh = 1e-3 * 10 ** oom
    while digits >= 0 and np.max(np.abs(v - np.round(v, digits))) < thresh:
        digits -= 1
    digits += 1
    out = []
    for x in v:
        s = f"{x:.{digits}f}"
        out.append(s[1:] if s.startswith("-") and float(s) == 0.0 else s)
    return out


class Chart:
    """An axes box at ``(x0, y0)`` (top-left, sheet mm) ``width`` × ``height`` mm showing
    data ``xlim`` × ``ylim``; collects its items (see the module)."""

    def __init__(self, x0: float, y0: float, width: float, height: float, xlim, ylim,
                 lang: str = "ru", layer: str = LAYER) -> None:
        self.x0, self.y0, self.width, self.height = x0, y0, width, height
        self.xlo, self.xhi = (float(v) for v in xlim)
        self.ylo, self.yhi = (float(v) for v in ylim)
        self.lang, self.layer = lang, layer
        self.items: list[Item] = []

    # ------------------------------------------------------------------ mapping
    def sx(self, x) -> np.ndarray:
        """Sheet x (mm) of data abscissae."""
        return self.x0 + (np.asarray(x, dtype=float) - self.xlo) / (self.xhi - self.xlo) \
            * self.width

    def sy(self, y) -> np.ndarray:
        """Sheet y (mm, down) of data ordinates."""
        return self.y0 + (self.yhi - np.asarray(y, dtype=float)) / (self.yhi - self.ylo) \
            * self.height

    @property
    def left(self) -> float:
        return self.x0

    @property
    def bottom(self) -> float:
        return self.y0 + self.height

    # ------------------------------------------------------------------ lines
    def polyline(self, pts, style: Style, *, clip: bool = True, closed: bool = False) -> None:
        """A polyline through sheet points, cut to the box unless ``clip`` is False."""
        arr = np.asarray(pts, dtype=float).reshape(-1, 2)
        parts = _clip(arr, (self.x0, self.y0, self.x0 + self.width, self.bottom)) \
            if clip and not closed else [arr]
        for part in parts:
            p = [(float(x), float(y)) for x, y in part]
            p = [q for i, q in enumerate(p) if i == 0 or q != p[i - 1]]
            if len(p) >= 2:
                self.items.append(Polyline(tuple(p), style, closed, layer=self.layer))

    def plot(self, xs, ys, width: float, dash=None, *, clip: bool = True) -> None:
        """A curve through data points, ``width`` mm (``dash``: on/off lengths, mm)."""
        self.polyline(np.column_stack([self.sx(xs), self.sy(ys)]), Style(width, dash),
                      clip=clip)

    def vlines(self, xs, y_from, ys, width: float) -> None:
        """Ordinates from ``y_from`` to each of ``ys`` at ``xs`` (data)."""
        for x, y in zip(np.atleast_1d(xs), np.atleast_1d(ys), strict=True):
            self.plot([x, x], [y_from, y], width)

    def hline(self, y: float, width: float, dash=None) -> None:
        """A line across the box at ordinate ``y``."""
        self.plot([self.xlo, self.xhi], [y, y], width, dash)

    def dots(self, xs, ys, diameter: float) -> None:
        """Filled dots ``diameter`` mm at data points."""
        for x, y in zip(self.sx(np.atleast_1d(xs)), self.sy(np.atleast_1d(ys)), strict=True):
            self.items.append(Circle((float(x), float(y)), 0.5 * diameter,
                                     Style(MIN_DOT, fill="black"), layer=self.layer))

    def triangle(self, x: float, y: float, size: float, pointing: str) -> None:
        """A filled arrowhead ``size`` mm wide and long at data (x, y), pointing
        ``"right"`` or ``"up"`` (an axis' arrow)."""
        cx, cy = float(self.sx(x)), float(self.sy(y))
        r = 0.5 * size
        pts = (((cx + r, cy), (cx - r, cy + r), (cx - r, cy - r)) if pointing == "right"
               else ((cx, cy - r), (cx - r, cy + r), (cx + r, cy + r)))
        self.items.append(Polyline(pts, Style(MIN_DOT, fill="black"), True, layer=self.layer))

    def frame(self, width: float, sides=("left", "bottom", "right", "top")) -> None:
        """The box's sides (a plot's spines)."""
        x0, y0, x1, y1 = self.x0, self.y0, self.x0 + self.width, self.bottom
        ends = {"left": ((x0, y1), (x0, y0)), "bottom": ((x0, y1), (x1, y1)),
                "right": ((x1, y1), (x1, y0)), "top": ((x0, y0), (x1, y0))}
        for side in sides:
            self.polyline(ends[side], Style(width), clip=False)

    def grid(self, xs, ys, width: float) -> None:
        """Thin lines across the box at the abscissae ``xs`` and ordinates ``ys``."""
        for x in xs:
            self.plot([x, x], [self.ylo, self.yhi], width)
        for y in ys:
            self.hline(y, width)

    # ------------------------------------------------------------------ texts
    def letter(self, x: float, y: float, s: str, h: float, ha: str = "left",
               va: str = "baseline", rot: float = 0.0) -> Text | None:
        """A text at sheet (x, y) mm: ``ha`` left/center/right, ``va`` as :func:`baseline`
        (measured across the text's line when it is turned by ``rot`` degrees)."""
        s = s.strip()
        if not s:
            return None
        if self.lang == "ru":
            s = decimal_comma(s)
        anchor = {"left": "start", "center": "middle", "right": "end"}[ha]
        # a text read upwards (90°): "down" from its line is +x on the sheet
        pos = (x + baseline(0.0, h, va), y) if rot % 360.0 == 90.0 else (x, baseline(y, h, va))
        t = Text((float(pos[0]), float(pos[1])), s, h, anchor, rot % 360.0, layer=self.layer)
        self.items.append(t)
        return t

    def text(self, x: float, y: float, s: str, h: float, ha: str = "left",
             va: str = "baseline") -> Text | None:
        """A text at data (x, y)."""
        return self.letter(float(self.sx(x)), float(self.sy(y)), s, h, ha, va)

    # ------------------------------------------------------------------ axes
    def xticks(self, xs, labels, *, h: float = 2.5, length: float = 1.5, width: float = 0.25,
               at: float | None = None, direction: str = "out") -> float:
        """Marks at abscissae ``xs`` on the bottom side (or at ordinate ``at``), their
        ``labels`` under them; returns the sheet y of the labels' foot."""
        y = self.bottom if at is None else float(self.sy(at))
        inside, outside = {"out": (0.0, length), "in": (length, 0.0),
                           "inout": (0.5 * length, 0.5 * length)}[direction]
        for x in self.sx(np.atleast_1d(xs)):
            self.polyline(((float(x), y + outside), (float(x), y - inside)), Style(width),
                          clip=False)
        top = y + outside + TICK_PAD
        for x, lab in zip(self.sx(np.atleast_1d(xs)), labels, strict=False):
            self.letter(float(x), top, str(lab), h, "center", "top")
        return top + (1.0 + DESCENT) * h

    def yticks(self, ys, labels, *, h: float = 2.5, length: float = 1.5,
               width: float = 0.25) -> float:
        """Marks at ordinates ``ys`` out of the left side, their ``labels`` left of them;
        returns the sheet x of the widest label's left end."""
        right = self.x0 - length - TICK_PAD
        lefts = [right]
        for y, lab in zip(self.sy(np.atleast_1d(ys)), labels, strict=True):
            self.polyline(((self.x0 - length, float(y)), (self.x0, float(y))), Style(width),
                          clip=False)
            t = self.letter(right, float(y), str(lab), h, "right", "center")
            if t is not None:
                lefts.append(right - fonts.text_width(t.text, h))
        return min(lefts)

    def ylabel(self, s: str, left: float, h: float = 3.5) -> None:
        """The ordinate's name turned to read upwards, centred on the box's height, right
        of it ``LABEL_PAD`` mm from ``left`` (the tick labels' left end)."""
        self.letter(left - LABEL_PAD, self.y0 + 0.5 * self.height, s, h, "center", "bottom",
                    rot=90.0)

    def xlabel(self, s: str, top: float, h: float = 3.5) -> None:
        """The abscissa's name centred under the box, its top ``LABEL_PAD`` mm below ``top``."""
        self.letter(self.x0 + 0.5 * self.width, top + LABEL_PAD, s, h, "center", "top")

    def y_values(self, h: float = 2.5, most: int = 9, steps=AUTO_STEPS) -> np.ndarray:
        """Round ordinate values for the box's height, two label ems apart at least."""
        return axis_values(self.ylo, self.yhi, self.height, 2.0, h, most, steps)

    def x_values(self, h: float = 2.5, most: int = 9, steps=AUTO_STEPS) -> np.ndarray:
        """Round abscissa values for the box's width, three label ems apart at least."""
        return axis_values(self.xlo, self.xhi, self.width, 3.0, h, most, steps)


def axis_values(lo: float, hi: float, length: float, ems: float, h: float = 2.5,
                most: int = 9, steps=AUTO_STEPS) -> np.ndarray:
    """Round values from ``lo`` to ``hi`` along an axis ``length`` mm long, ``ems`` ems of
    labels of capital height ``h`` apart at least, ``most`` intervals at most (matplotlib's
    automatic ticks)."""
    em = h / fonts.cap_ratio("osifont")
    return nice_ticks(lo, hi, min(most, max(1, math.floor(length / (ems * em)))), steps)


#: outline width of filled marks (the fill is what shows), mm
MIN_DOT = 0.25


def auto_limits(values, margin: float = 0.05) -> tuple[float, float]:
    """The data range of ``values`` widened by ``margin`` of it on each side (a plot's
    automatic limits)."""
    v = np.concatenate([np.ravel(np.asarray(a, dtype=float)) for a in values])
    lo, hi = float(np.min(v)), float(np.max(v))
    if hi - lo <= 1e-12 * max(abs(lo), abs(hi), 1.0):
        pad = max(abs(lo) * 0.1, 1.0) if lo == hi else (hi - lo)
        return lo - pad, hi + pad
    d = (hi - lo) * margin
    return lo - d, hi + d


def _clip(pts: np.ndarray, box) -> list[np.ndarray]:
    """Parts of a polyline inside ``box`` (x0, y0, x1, y1)."""
    x0, y0, x1, y1 = box
    eps = 1e-6
    if (pts[:, 0].min() >= x0 - eps and pts[:, 0].max() <= x1 + eps
            and pts[:, 1].min() >= y0 - eps and pts[:, 1].max() <= y1 + eps):
        return [pts]
    from shapely.geometry import LineString
    from shapely.geometry import box as shapely_box

    cut = LineString(pts).intersection(shapely_box(x0, y0, x1, y1))
    parts = getattr(cut, "geoms", [cut])
    return [np.asarray(g.coords) for g in parts
            if g.geom_type == "LineString" and not g.is_empty and g.length > 1e-9]


__all__ = ["Chart", "auto_limits", "axis_values", "baseline", "nice_ticks", "tick_labels"]
