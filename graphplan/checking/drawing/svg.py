"""Reading an SVG drawing with the standard library's XML parser.

Follows ``<g>``, nested ``<svg>`` (viewport and viewBox) and ``<use>`` with their
``transform`` (matrix, translate, scale, rotate, skewX, skewY); draws ``line``,
``polyline``, ``polygon``, ``rect``, ``circle``, ``ellipse`` and ``path`` (M L H V Z, and
C S Q T A as chains of short pieces) with their stroke and fill (attributes, inherited,
or ``style``), and ``text`` (with its ``tspan``s, ``text-anchor`` and ``font-size``).
The root's ``width``/``height`` in mm, cm, in, pt or px (96 per inch) and its
``viewBox`` give the millimetres; y is turned up. Entity declarations are refused
(no expansion attacks); nesting is bounded (:data:`~.primitives.MAX_DEPTH`).
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

from .primitives import MAX_DEPTH, Collector, Drawing, DrawingError, read_bytes, text_centre

_UNIT_MM = {"mm": 1.0, "cm": 10.0, "in": 25.4, "pt": 25.4 / 72, "pc": 25.4 / 6,
            "px": 25.4 / 96, "": 25.4 / 96}
_SKIP = {"defs", "symbol", "clipPath", "mask", "marker", "pattern", "title", "desc",
         "metadata", "style", "script", "linearGradient", "radialGradient", "filter"}
_NUM = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")

Affine = tuple[float, float, float, float, float, float]
ID: Affine = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)


def mul(m: Affine, n: Affine) -> Affine:
    """m∘n: apply n first, then m."""
    a, b, c, d, e, f = m
    A, B, C, D, E, F = n
    return (a * A + c * B, b * A + d * B, a * C + c * D, b * C + d * D,
            a * E + c * F + e, b * E + d * F + f)


def apply(m: Affine, x: float, y: float) -> tuple[float, float]:
    a, b, c, d, e, f = m
    return (a * x + c * y + e, b * x + d * y + f)


def parse_transform(text: str) -> Affine:
    """An SVG ``transform`` attribute as one affine map."""
    m = ID
    for name, args in re.findall(r"(\w+)\s*\(([^)]*)\)", text or ""):
        v = [float(x) for x in _NUM.findall(args)]
        if name == "matrix" and len(v) == 6:
            t = tuple(v)
        elif name == "translate" and v:
            t = (1, 0, 0, 1, v[0], v[1] if len(v) > 1 else 0.0)
        elif name == "scale" and v:
            t = (v[0], 0, 0, v[1] if len(v) > 1 else v[0], 0, 0)
        elif name == "rotate" and v:
            r = math.radians(v[0])
            c, s = math.cos(r), math.sin(r)
            t = (c, s, -s, c, 0, 0)
            if len(v) == 3:
                t = mul(mul((1, 0, 0, 1, v[1], v[2]), t), (1, 0, 0, 1, -v[1], -v[2]))
        elif name == "skewX" and v:
            t = (1, 0, math.tan(math.radians(v[0])), 1, 0, 0)
        elif name == "skewY" and v:
            t = (1, math.tan(math.radians(v[0])), 0, 1, 0, 0)
        else:
            continue
        m = mul(m, t)  # type: ignore[arg-type]
    return m


def _length(text: str | None, default: float | None = None) -> float | None:
    """A length with its unit, in mm (``None`` if absent or a percentage)."""
    if not text:
        return default
    m = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([a-z%]*)\s*", text)
    if not m or m.group(2) == "%" or m.group(2) not in _UNIT_MM:
        return default
    return float(m.group(1)) * _UNIT_MM[m.group(2)]


def _num(text: str | None, default: float = 0.0) -> float:
    if text is None:
        return default
    v = _NUM.findall(text)
    return float(v[0]) if v else default


def _tag(el) -> str:
    return el.tag.rsplit("}", 1)[-1] if isinstance(el.tag, str) else ""


def _style(el, inherited: dict) -> dict:
    st = dict(inherited)
    for k in ("stroke", "fill", "font-size", "text-anchor", "stroke-width", "display",
              "visibility"):
        if el.get(k) is not None:
            st[k] = el.get(k)
    for part in (el.get("style") or "").split(";"):
        if ":" in part:
            k, v = part.split(":", 1)
            st[k.strip()] = v.strip()
    return st


def _colour(v: str | None) -> str | None:
    if v is None:
        return None
    v = v.strip().lower()
    if v in ("none", "transparent", "") or v.startswith("url("):
        return None
    if v in ("black", "currentcolor"):
        return "#000000"
    if re.fullmatch(r"#[0-9a-f]{6}", v):
        return v
    if re.fullmatch(r"#[0-9a-f]{3}", v):
        return "#" + "".join(c * 2 for c in v[1:])
    m = re.fullmatch(r"rgb\((\d+),\s*(\d+),\s*(\d+)\)", v)
    if m:
        return "#" + "".join(f"{min(int(x), 255):02x}" for x in m.groups())
    return {"red": "#ff0000", "blue": "#0000ff", "green": "#008000", "white": "#ffffff",
            "gray": "#808080", "grey": "#808080"}.get(v, "#000000")


def read_svg(path: Path) -> Drawing:
    """Read an SVG file into a :class:`~.primitives.Drawing` (mm, y up)."""
    data = read_bytes(path)
    head = data[:4096].lower()
    if b"<!entity" in data.lower() if len(data) < 1 << 20 else b"<!entity" in head:
        raise DrawingError(f"{path}: the SVG declares XML entities: not read")
    try:
        root = ET.fromstring(data)
    except ET.ParseError as exc:
        raise DrawingError(f"{path}: not a readable SVG (XML: {exc})") from None
    if _tag(root) != "svg":
        raise DrawingError(f"{path}: not an SVG (the root element is <{_tag(root)}>)")
    col = Collector(str(path))
    ids = {el.get("id"): el for el in root.iter() if el.get("id")}
    vb = [float(x) for x in _NUM.findall(root.get("viewBox") or "")]
    w_mm, h_mm = _length(root.get("width")), _length(root.get("height"))
    if len(vb) == 4 and vb[2] > 0 and vb[3] > 0:
        kx = (w_mm / vb[2]) if w_mm else 25.4 / 96
        ky = (h_mm / vb[3]) if h_mm else kx
        base: Affine = (kx, 0, 0, ky, -vb[0] * kx, -vb[1] * ky)
        height = h_mm or vb[3] * ky
    else:
        base = (25.4 / 96, 0, 0, 25.4 / 96, 0, 0)
        height = h_mm or 0.0
    flip: Affine = (1, 0, 0, -1, 0, height)
    r = _Reader(col, ids)
    r.children(root, mul(flip, base), {}, 0)
    return col.drawing("svg", (0.0, 0.0, w_mm or 0.0, height))


class _Reader:
    def __init__(self, col: Collector, ids: dict):
        self.col = col
        self.ids = ids

    def children(self, el, m: Affine, st: dict, depth: int) -> None:
        if depth > MAX_DEPTH:
            raise DrawingError(f"{self.col.source}: elements nested more than {MAX_DEPTH} deep"
                               ": not read")
        for ch in el:
            self.element(ch, m, st, depth + 1)

    def element(self, el, m: Affine, inherited: dict, depth: int) -> None:
        tag = _tag(el)
        if tag in _SKIP or not tag:
            return
        st = _style(el, inherited)
        if st.get("display") == "none":
            return
        m = mul(m, parse_transform(el.get("transform", "")))
        if tag == "g" or tag == "a" or tag == "switch":
            self.children(el, m, st, depth)
        elif tag == "svg":
            x, y = _num(el.get("x")), _num(el.get("y"))
            w, h = _num(el.get("width"), 0), _num(el.get("height"), 0)
            vb = [float(v) for v in _NUM.findall(el.get("viewBox") or "")]
            inner: Affine = (1, 0, 0, 1, x, y)
            if len(vb) == 4 and vb[2] > 0 and vb[3] > 0 and w > 0 and h > 0:
                inner = mul(inner, (w / vb[2], 0, 0, h / vb[3], -vb[0] * w / vb[2],
                                    -vb[1] * h / vb[3]))
            self.children(el, mul(m, inner), st, depth)
        elif tag == "use":
            href = el.get("{http://www.w3.org/1999/xlink}href") or el.get("href") or ""
            target = self.ids.get(href.lstrip("#"))
            if target is None or target is el:
                return
            m2 = mul(m, (1, 0, 0, 1, _num(el.get("x")), _num(el.get("y"))))
            if _tag(target) == "symbol":
                self.children(target, m2, st, depth)
            else:
                self.element(target, m2, st, depth + 1)
        elif tag == "text":
            self.text(el, m, st)
        else:
            self.shape(el, tag, m, st)

    def shape(self, el, tag: str, m: Affine, st: dict) -> None:
        subpaths: list[tuple[list[tuple[float, float]], bool, bool]] = []  # pts, closed, curve
        g = el.get
        if tag == "line":
            subpaths.append(([(_num(g("x1")), _num(g("y1"))), (_num(g("x2")), _num(g("y2")))],
                             False, False))
        elif tag in ("polyline", "polygon"):
            v = [float(x) for x in _NUM.findall(g("points") or "")]
            pts = list(zip(v[0::2], v[1::2], strict=False))
            subpaths.append((pts, tag == "polygon", False))
        elif tag == "rect":
            x, y, w, h = (_num(g(k)) for k in ("x", "y", "width", "height"))
            subpaths.append(([(x, y), (x + w, y), (x + w, y + h), (x, y + h)], True, False))
        elif tag in ("circle", "ellipse"):
            cx, cy = _num(g("cx")), _num(g("cy"))
            rx = _num(g("r")) if tag == "circle" else _num(g("rx"))
            ry = _num(g("r")) if tag == "circle" else _num(g("ry"))
            pts = [(cx + rx * math.cos(t), cy + ry * math.sin(t))
                   for t in (2 * math.pi * i / 24 for i in range(24))]
            subpaths.append((pts, True, True))
            if tag == "circle":
                X, Y = apply(m, cx, cy)
                k = math.sqrt(abs(m[0] * m[3] - m[1] * m[2]))
                self.col.circle(X, Y, rx * k, _colour(st.get("stroke")) or "#000000")
        elif tag == "path":
            subpaths += path_points(g("d") or "")
        else:
            return
        stroke = _colour(st.get("stroke"))
        fill = _colour(st.get("fill", "black"))
        k = math.sqrt(abs(m[0] * m[3] - m[1] * m[2]))
        width = _num(st.get("stroke-width"), 1.0) * k
        for pts, closed, curve in subpaths:
            tp = [apply(m, x, y) for x, y in pts]
            if stroke:
                self.col.polyline(tp, closed, stroke, width, "", curve)
            if fill and fill != "#ffffff" and len(tp) >= 3 and tag != "line" and (
                    closed or tag != "polyline"):
                self.col.fill(tp, fill)

    def text(self, el, m: Affine, st: dict) -> None:
        pieces = [(el, st)]
        for ts in el.iter():
            if ts is not el and _tag(ts) == "tspan" and (ts.get("x") or ts.get("y")):
                pieces.append((ts, _style(ts, st)))
        if len(pieces) == 1:
            self._text_piece("".join(el.itertext()), el, m, st)
            return
        own = (el.text or "").strip()
        if own:
            self._text_piece(own, el, m, st)
        for ts, sts in pieces[1:]:
            self._text_piece("".join(ts.itertext()), ts, m, sts, el)

    def _text_piece(self, s: str, el, m: Affine, st: dict, parent=None) -> None:
        s = " ".join(s.split())
        if not s:
            return
        x = _num(el.get("x"), _num(parent.get("x")) if parent is not None else 0.0)
        y = _num(el.get("y"), _num(parent.get("y")) if parent is not None else 0.0)
        fs = _length(st.get("font-size"), None)
        fs = fs / (25.4 / 96) if fs else 16.0  # in user units
        anchor = {"middle": 0.5, "end": 1.0}.get(st.get("text-anchor", "start"), 0.0)
        X, Y = apply(m, x, y)
        ux, uy = m[0], m[1]  # the text's baseline direction
        scale = math.hypot(m[2], m[3])
        angle = math.degrees(math.atan2(uy, ux))
        h = 0.72 * fs * scale
        cx, cy = text_centre(X, Y, h, angle, len(s), anchor, 0.0)
        self.col.text(s, cx, cy, h, angle, _colour(st.get("fill", "black")) or "#000000")


def _tokens(d: str):
    for m in re.finditer(r"([MmLlHhVvZzCcSsQqTtAa])|([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)",
                         d):
        yield (m.group(1), None) if m.group(1) else (None, float(m.group(2)))


def path_points(d: str) -> list[tuple[list[tuple[float, float]], bool, bool]]:
    """The subpaths of a path's ``d``: (points, closed, has curves)."""
    toks = list(_tokens(d))
    out: list[tuple[list[tuple[float, float]], bool, bool]] = []
    pts: list[tuple[float, float]] = []
    curve = False
    cmd = None
    i = 0
    x = y = sx = sy = 0.0
    last_ctrl = None

    def nums(n):
        nonlocal i
        vals = []
        while len(vals) < n and i < len(toks) and toks[i][0] is None:
            vals.append(toks[i][1])
            i += 1
        return vals if len(vals) == n else None

    def flush(closed=False):
        nonlocal pts, curve
        if len(pts) >= 2:
            out.append((pts, closed, curve))
        pts, curve = [], False

    while i < len(toks):
        if toks[i][0] is not None:
            cmd = toks[i][0]
            i += 1
            if cmd in "Zz":
                flush(True)
                x, y = sx, sy
                pts = [(x, y)]
                continue
        if cmd is None:
            break
        rel = cmd.islower()
        c = cmd.upper()
        if c == "M":
            v = nums(2)
            if v is None:
                break
            flush()
            x, y = (x + v[0], y + v[1]) if rel else (v[0], v[1])
            sx, sy = x, y
            pts = [(x, y)]
            cmd = "l" if rel else "L"
        elif c in "LHV":
            v = nums(2 if c == "L" else 1)
            if v is None:
                break
            if c == "L":
                x, y = (x + v[0], y + v[1]) if rel else (v[0], v[1])
            elif c == "H":
                x = x + v[0] if rel else v[0]
            else:
                y = y + v[0] if rel else v[0]
            pts.append((x, y))
        elif c in "CSQT":
            n = {"C": 6, "S": 4, "Q": 4, "T": 2}[c]
            v = nums(n)
            if v is None:
                break
            if rel:
                v = [v[j] + (x if j % 2 == 0 else y) for j in range(n)]
            p0 = (x, y)
            if c == "C":
                c1, c2, p3 = (v[0], v[1]), (v[2], v[3]), (v[4], v[5])
            elif c == "S":
                c1 = (2 * x - last_ctrl[0], 2 * y - last_ctrl[1]) if last_ctrl else p0
                c2, p3 = (v[0], v[1]), (v[2], v[3])
            elif c == "Q":
                q, p3 = (v[0], v[1]), (v[2], v[3])
                c1 = (x + 2 / 3 * (q[0] - x), y + 2 / 3 * (q[1] - y))
                c2 = (p3[0] + 2 / 3 * (q[0] - p3[0]), p3[1] + 2 / 3 * (q[1] - p3[1]))
            else:
                c1 = c2 = p0
                p3 = (v[0], v[1])
            for t in (0.25, 0.5, 0.75, 1.0):
                s = 1 - t
                pts.append((s**3 * p0[0] + 3 * s * s * t * c1[0] + 3 * s * t * t * c2[0]
                            + t**3 * p3[0], s**3 * p0[1] + 3 * s * s * t * c1[1]
                            + 3 * s * t * t * c2[1] + t**3 * p3[1]))
            last_ctrl = c2
            x, y = p3
            curve = True
            continue
        elif c == "A":
            v = nums(7)
            if v is None:
                break
            x, y = (x + v[5], y + v[6]) if rel else (v[5], v[6])
            pts.append((x, y))
            curve = True
        else:
            break
        last_ctrl = None
    flush()
    return out


__all__ = ["parse_transform", "path_points", "read_svg"]
