"""The vector paths of a :class:`graphplan.drawing.sheet.Figure`'s picture, in sheet millimetres.

A figure is a standalone matplotlib SVG stretched into its box on the sheet (see
:func:`graphplan.render.svg.embedded_svg`): its viewBox ``(vx, vy, vw, vh)`` is mapped
onto the box ``(x, y, w, h)`` mm without keeping the aspect ratio, so a point
``(u, v)`` of the picture lands on the sheet at::

    X = x + (u − vx)·w/vw,    Y = y + (v − vy)·h/vh        (mm, y down)

after the ``transform`` attributes of its ancestors (``<g>``, ``<use>``, the path
itself) are applied. This module follows those transforms and returns every stroke
as a polyline and every filled shape as closed loops, for the DXF export:

* paths ``M L H V C S Q T Z`` (absolute and relative); Bézier curves are flattened
  into chords no farther than :data:`TOLERANCE` mm from the curve; ``<rect>``,
  ``<line>``, ``<polyline>``, ``<polygon>``, ``<circle>`` and ``<ellipse>`` too;
* ``<use>`` (matplotlib's markers and text glyphs: glyphs are paths there, so the
  lettering of a figure comes out as filled outlines);
* ``clip-path`` made of rectangles or paths (strokes and fills are cut with shapely);
* colours, ``stroke-width`` (scaled to mm) and ``stroke-dasharray`` from presentation
  attributes and ``style``, inherited as in SVG; fill defaults to black, stroke to none.

White fills are dropped: they only paint the paper (matplotlib's figure and legend
backgrounds) and would hide the drawing on a CAD program's dark screen. ``<text>``,
``<image>`` and elliptical arcs (``A``) are not expected from matplotlib and raise.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from functools import reduce

import numpy as np
import shapely
from shapely.geometry import LinearRing, LineString, Polygon
from shapely.geometry.base import BaseGeometry

from ..drawing.sheet import Figure, Pt
from ..errors import LayoutError

#: Largest distance (mm) between a flattened Bézier curve and its chords.
TOLERANCE = 0.01
#: Chords of a full circle or ellipse of a picture.
CIRCLE_CHORDS = 72

_XLINK = "{http://www.w3.org/1999/xlink}href"
_SKIP = frozenset({"defs", "clipPath", "metadata", "style", "title", "desc", "mask", "symbol",
                   "marker", "linearGradient", "radialGradient", "pattern", "filter"})
_INHERITED = ("fill", "stroke", "stroke-width", "stroke-dasharray", "fill-rule")
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_TOKEN = re.compile(rf"([MmLlHhVvCcSsQqTtZzAa])|({_NUMBER})")
_TRANSFORM = re.compile(r"(matrix|translate|scale|rotate|skewX|skewY)\s*\(([^)]*)\)")
_WHITE = (1.0, 1.0, 1.0)


@dataclass(frozen=True, slots=True)
class Stroke:
    """A stroked polyline of the picture: points in sheet mm (y down)."""

    points: tuple[Pt, ...]
    closed: bool
    width: float  #: mm
    colour: tuple[float, float, float]  #: RGB in 0…1
    dasharray: tuple[float, ...] | None  #: mm


@dataclass(frozen=True, slots=True)
class Fill:
    """A filled area of the picture: its loops (holes by the even-odd rule), sheet mm."""

    loops: tuple[tuple[Pt, ...], ...]
    colour: tuple[float, float, float]


# ------------------------------------------------------------------- transforms

def _matrix(a: float, b: float, c: float, d: float, e: float, f: float) -> np.ndarray:
    """SVG ``matrix(a b c d e f)``: x' = a·x + c·y + e, y' = b·x + d·y + f."""
    return np.array([[a, c, e], [b, d, f], [0.0, 0.0, 1.0]])


def _numbers(text: str) -> list[float]:
    return [float(v) for v in re.findall(_NUMBER, text)]


def parse_transform(text: str | None) -> np.ndarray:
    """The 3×3 matrix of an SVG ``transform`` list (applied right to left)."""
    m = np.eye(3)
    for name, args in _TRANSFORM.findall(text or ""):
        v = _numbers(args)
        if name == "matrix" and len(v) == 6:
            t = _matrix(*v)
        elif name == "translate" and v:
            t = _matrix(1, 0, 0, 1, v[0], v[1] if len(v) > 1 else 0.0)
        elif name == "scale" and v:
            t = _matrix(v[0], 0, 0, v[1] if len(v) > 1 else v[0], 0, 0)
        elif name == "rotate" and v:
            a = math.radians(v[0])
            cx, cy = (v[1], v[2]) if len(v) == 3 else (0.0, 0.0)
            t = (_matrix(1, 0, 0, 1, cx, cy)
                 @ _matrix(math.cos(a), math.sin(a), -math.sin(a), math.cos(a), 0, 0)
                 @ _matrix(1, 0, 0, 1, -cx, -cy))
        elif name == "skewX" and v:
            t = _matrix(1, 0, math.tan(math.radians(v[0])), 1, 0, 0)
        elif name == "skewY" and v:
            t = _matrix(1, math.tan(math.radians(v[0])), 0, 1, 0, 0)
        else:
            raise LayoutError(f"SVG transform {name}({args}) has the wrong number of values")
        m = m @ t
    return m


def _apply(m: np.ndarray, pts: np.ndarray) -> np.ndarray:
    return pts @ m[:2, :2].T + m[:2, 2]


# ------------------------------------------------------------------------ paths

def _flatten(ctrl: np.ndarray) -> np.ndarray:
    """Points of a Bézier curve (control points already in mm), first point excluded.

    The chords of n equal parameter steps stay within ‖B''‖max/(8n²) of the curve, and
    ‖B''‖ ≤ k(k−1)·max‖Δ²P‖ for degree k: n = ⌈√(k(k−1)·max‖Δ²P‖ / (8·TOLERANCE))⌉.
    """
    k = len(ctrl) - 1
    dd = ctrl[:-2] - 2 * ctrl[1:-1] + ctrl[2:]
    bound = k * (k - 1) * float(np.max(np.hypot(dd[:, 0], dd[:, 1])))
    n = max(1, math.ceil(math.sqrt(bound / (8 * TOLERANCE))))
    t = np.linspace(0.0, 1.0, n + 1)[1:, None]
    if k == 2:
        return (1 - t) ** 2 * ctrl[0] + 2 * (1 - t) * t * ctrl[1] + t**2 * ctrl[2]
    return ((1 - t) ** 3 * ctrl[0] + 3 * (1 - t) ** 2 * t * ctrl[1]
            + 3 * (1 - t) * t**2 * ctrl[2] + t**3 * ctrl[3])


def path_subpaths(d: str, m: np.ndarray) -> list[tuple[np.ndarray, bool]]:
    """Subpaths of an SVG path ``d`` mapped by ``m``: (N×2 points, closed) each.

    Raises
    ------
    LayoutError
        On an elliptical arc command (``A``) or malformed data.
    """
    tokens = [(c, float(v) if v else None) for c, v in _TOKEN.findall(d)]
    out: list[tuple[np.ndarray, bool]] = []
    pts: list[np.ndarray] = []  # points of the current subpath, in mm
    cur = np.zeros(2)  # current point, picture units
    start = np.zeros(2)
    last_ctrl: np.ndarray | None = None  # for S and T
    last_cmd = ""
    i = 0

    def take(n: int) -> list[float]:
        nonlocal i
        vals = [tokens[j][1] for j in range(i, i + n)] if i + n <= len(tokens) else []
        if len(vals) != n or any(v is None for v in vals):
            raise LayoutError(f"SVG path data is malformed near {d[:40]!r}")
        i += n
        return vals  # type: ignore[return-value]

    def flush(closed: bool) -> None:
        nonlocal pts
        if len(pts) >= 2:
            out.append((np.array(pts), closed))
        pts = []

    def to_mm(p: np.ndarray) -> np.ndarray:
        return _apply(m, p[None, :])[0]

    cmd = ""
    while i < len(tokens):
        letter, _ = tokens[i]
        if letter:
            cmd = letter
            i += 1
        elif not cmd:
            raise LayoutError(f"SVG path data must start with a command (got {d[:40]!r})")
        rel = cmd.islower()
        base = cur if rel else np.zeros(2)
        c = cmd.upper()
        if c == "Z":
            if pts:
                flush(True)
            cur = start.copy()
            last_ctrl, last_cmd = None, "Z"
            continue
        if c == "A":
            raise LayoutError("SVG path arcs (A) are not supported in figures")
        if c == "M":
            flush(False)
            cur = base + take(2)
            start = cur.copy()
            pts = [to_mm(cur)]
            cmd = "l" if rel else "L"  # further pairs are line-tos
            last_ctrl, last_cmd = None, "M"
            continue
        if not pts:  # drawing after Z continues from the subpath's start
            pts = [to_mm(cur)]
        if c in "LHV":
            if c == "L":
                nxt = base + take(2)
            elif c == "H":
                nxt = np.array([(cur[0] if rel else 0.0) + take(1)[0], cur[1]])
            else:
                nxt = np.array([cur[0], (cur[1] if rel else 0.0) + take(1)[0]])
            pts.append(to_mm(nxt))
            cur, last_ctrl = nxt, None
        elif c in "QT":
            if c == "Q":
                q = base + take(2)
            else:
                q = 2 * cur - last_ctrl if last_cmd in "QT" and last_ctrl is not None else cur
            end = base + take(2)
            pts.extend(_flatten(_apply(m, np.array([cur, q, end]))))
            cur, last_ctrl = end, q
        elif c in "CS":
            if c == "C":
                c1 = base + take(2)
            else:
                c1 = 2 * cur - last_ctrl if last_cmd in "CS" and last_ctrl is not None else cur
            c2 = base + take(2)
            end = base + take(2)
            pts.extend(_flatten(_apply(m, np.array([cur, c1, c2, end]))))
            cur, last_ctrl = end, c2
        last_cmd = c
    flush(False)
    return out


def _shape_subpaths(el: ET.Element, tag: str, m: np.ndarray) -> list[tuple[np.ndarray, bool]]:
    """Subpaths of a basic shape (rect, line, polyline, polygon, circle, ellipse)."""
    def g(name: str) -> float:
        return float(el.get(name, "0") or 0)

    if tag == "rect":
        x, y, w, h = g("x"), g("y"), g("width"), g("height")
        if w <= 0 or h <= 0:
            return []
        pts = np.array([[x, y], [x + w, y], [x + w, y + h], [x, y + h]])
        return [(_apply(m, pts), True)]
    if tag == "line":
        pts = np.array([[g("x1"), g("y1")], [g("x2"), g("y2")]])
        return [(_apply(m, pts), False)]
    if tag in ("polyline", "polygon"):
        v = _numbers(el.get("points", ""))
        pts = np.array(v[: len(v) // 2 * 2]).reshape(-1, 2)
        return [(_apply(m, pts), tag == "polygon")] if len(pts) >= 2 else []
    if tag in ("circle", "ellipse"):
        rx, ry = (g("r"), g("r")) if tag == "circle" else (g("rx"), g("ry"))
        if rx <= 0 or ry <= 0:
            return []
        a = np.linspace(0.0, 2 * math.pi, CIRCLE_CHORDS, endpoint=False)
        pts = np.column_stack([g("cx") + rx * np.cos(a), g("cy") + ry * np.sin(a)])
        return [(_apply(m, pts), True)]
    return []


# ------------------------------------------------------------------------ styles

def _declarations(el: ET.Element) -> dict[str, str]:
    props = {k: el.get(k) for k in _INHERITED if el.get(k) is not None}
    for decl in (el.get("style") or "").split(";"):
        if ":" in decl:
            k, v = decl.split(":", 1)
            props[k.strip()] = v.strip()
    return props  # type: ignore[return-value]


def _colour(value: str | None) -> tuple[float, float, float] | None:
    """RGB of a paint value; None for ``none`` (or a paint server, which is not drawn)."""
    if value is None:
        return None
    v = value.strip().lower()
    if v in ("none", "transparent") or v.startswith("url("):
        return None
    from matplotlib.colors import to_rgb  # matplotlib is a dependency of graphplan

    try:
        return tuple(float(c) for c in to_rgb(v))  # type: ignore[return-value]
    except ValueError:
        raise LayoutError(f"figure colour {value!r} is not understood") from None


def _length_list(text: str | None) -> tuple[float, ...] | None:
    if text is None or text.strip().lower() == "none":
        return None
    v = _numbers(text)
    if not v or not any(x > 0 for x in v):
        return None
    return tuple(v) if len(v) % 2 == 0 else tuple(v) * 2


# ---------------------------------------------------------------------- clipping

def _clip_region(el: ET.Element, ids: dict[str, ET.Element], m: np.ndarray) -> BaseGeometry | None:
    """Union of a ``<clipPath>``'s shapes (userSpaceOnUse) mapped by ``m``, sheet mm."""
    ref = re.fullmatch(r"\s*url\(#([^)]+)\)\s*", el.get("clip-path") or "")
    if not ref or ref.group(1) not in ids:
        return None
    parts = []
    for child in ids[ref.group(1)]:
        tag = child.tag.rsplit("}", 1)[-1]
        cm = m @ parse_transform(child.get("transform"))
        subs = (path_subpaths(child.get("d", ""), cm) if tag == "path"
                else _shape_subpaths(child, tag, cm))
        parts += [Polygon(p) for p, _ in subs if len(p) >= 3]
    return shapely.union_all([shapely.make_valid(p) for p in parts]) if parts else None


def _clip_lines(pts: np.ndarray, closed: bool, clip: BaseGeometry | None
                ) -> list[tuple[np.ndarray, bool]]:
    if clip is None or shapely.contains_xy(clip, pts[:, 0], pts[:, 1]).all():
        return [(pts, closed)]
    geom = LinearRing(pts) if closed and len(pts) >= 3 else LineString(pts)
    cut = shapely.line_merge(geom.intersection(clip)) if not geom.disjoint(clip) else None
    if cut is None or cut.is_empty:
        return []
    return [(np.asarray(g.coords), False) for g in getattr(cut, "geoms", [cut])
            if isinstance(g, LineString) and len(g.coords) >= 2]


def _clip_loops(loops: list[np.ndarray], clip: BaseGeometry | None) -> list[np.ndarray]:
    if clip is None or all(shapely.contains_xy(clip, p[:, 0], p[:, 1]).all() for p in loops):
        return loops
    polys = [shapely.make_valid(Polygon(p)) for p in loops if len(p) >= 3]
    area = reduce(lambda a, b: a.symmetric_difference(b), polys).intersection(clip)
    out = []
    for poly in getattr(area, "geoms", [area]):
        if isinstance(poly, Polygon) and not poly.is_empty:
            out.append(np.asarray(poly.exterior.coords)[:-1])
            out += [np.asarray(r.coords)[:-1] for r in poly.interiors]
    return out


# -------------------------------------------------------------------------- walk

def _pts(p: np.ndarray) -> tuple[Pt, ...]:
    return tuple((float(x), float(y)) for x, y in p)


def _viewbox_matrix(fig: Figure, root: ET.Element) -> np.ndarray:
    vb = _numbers(root.get("viewBox") or "")
    if len(vb) != 4 or vb[2] <= 0 or vb[3] <= 0:
        raise LayoutError(f"figure {fig.id!r}: its picture has no usable viewBox")
    x, y = fig.origin
    sx, sy = fig.width / vb[2], fig.height / vb[3]
    return _matrix(sx, 0, 0, sy, x - vb[0] * sx, y - vb[1] * sy)


def figure_paths(fig: Figure) -> tuple[tuple[Stroke, ...], tuple[Fill, ...]]:
    """Strokes and fills of ``fig``'s picture, in sheet mm (y down), in drawing order.

    Raises
    ------
    LayoutError
        If the picture is not an SVG document with a viewBox, or holds something that
        has no vector outline here (``<text>``, ``<image>``, elliptical arcs).
    """
    try:
        root = ET.fromstring(fig.svg.encode("utf-8"))
    except ET.ParseError as exc:
        raise LayoutError(f"figure {fig.id!r}: its picture is not valid XML ({exc})") from None
    if root.tag.rsplit("}", 1)[-1] != "svg":
        raise LayoutError(f"figure {fig.id!r}: its picture is not an <svg> document")
    ids = {el.get("id"): el for el in root.iter() if el.get("id")}
    strokes: list[Stroke] = []
    fills: list[Fill] = []

    def walk(el: ET.Element, m: np.ndarray, style: dict[str, str],
             clip: BaseGeometry | None, depth: int) -> None:
        tag = el.tag.rsplit("}", 1)[-1]
        if tag in _SKIP or depth > 50:
            return
        if tag in ("text", "image", "foreignObject"):
            raise LayoutError(f"figure {fig.id!r}: <{tag}> cannot be exported as vector paths "
                              "(draw the picture with glyphs as paths)")
        m = m @ parse_transform(el.get("transform"))
        style = {**style, **_declarations(el)}
        if el.get("clip-path"):
            region = _clip_region(el, ids, m)
            if region is not None:
                clip = region if clip is None else clip.intersection(region)
        if tag in ("svg", "g", "a", "switch"):
            for child in el:
                walk(child, m, style, clip, depth + 1)
            return
        if tag == "use":
            ref = (el.get(_XLINK) or el.get("href") or "").lstrip("#")
            if ref in ids:
                shift = _matrix(1, 0, 0, 1, float(el.get("x", 0)), float(el.get("y", 0)))
                walk(ids[ref], m @ shift, style, clip, depth + 1)
            return
        subs = (path_subpaths(el.get("d", ""), m) if tag == "path"
                else _shape_subpaths(el, tag, m))
        if not subs:
            return
        fill = _colour(style.get("fill", "black"))
        if fill is not None and fill != _WHITE:
            loops = [p for p, _ in subs if len(p) >= 3 and Polygon(p).area > 1e-12]
            loops = _clip_loops(loops, clip) if loops else []
            if loops:
                fills.append(Fill(tuple(_pts(p) for p in loops), fill))
        stroke = _colour(style.get("stroke"))
        if stroke is not None:
            scale = math.sqrt(abs(float(np.linalg.det(m[:2, :2]))))
            width = float(_numbers(style.get("stroke-width", "1"))[0]) * scale
            if width <= 0:
                return
            dash = _length_list(style.get("stroke-dasharray"))
            dash = tuple(v * scale for v in dash) if dash else None
            for p, closed in subs:
                for q, c in _clip_lines(p, closed, clip):
                    if len(q) >= 2:
                        strokes.append(Stroke(_pts(q), c, width, stroke, dash))

    root_m = _viewbox_matrix(fig, root)
    for child in root:
        walk(child, root_m, {}, None, 0)
    return tuple(strokes), tuple(fills)


__all__ = ["CIRCLE_CHORDS", "TOLERANCE", "Fill", "Stroke", "figure_paths", "parse_transform",
           "path_subpaths"]
