"""Reading a DXF drawing (R12 … R2018, as КОМПАС-3D and AutoCAD write it) with ezdxf.

What is read, from model space (or, when model space is empty, from the paper-space
layouts): LINE; LWPOLYLINE and POLYLINE (bulges as arcs); ARC, CIRCLE, ELLIPSE, SPLINE
(as chains of short pieces); TEXT (its width factor narrowing the box; an oblique angle
leaves the centre) and MTEXT (plain text, the centre of the text's box);
SOLID, TRACE and HATCH (as fills: arrowheads); INSERT of blocks exploded with their
transformation (nested blocks too, :data:`~.primitives.MAX_DEPTH` deep), with their
attributes; DIMENSION as the block it is drawn with. Colours are the entities' own (true
colour, ACI, or the layer's). Coordinates are converted to mm by ``$INSUNITS`` (unitless
is taken as mm, and said so in the drawing's notes).
"""

from __future__ import annotations

import io
import math
import re
from pathlib import Path

from .primitives import MAX_DEPTH, Collector, Drawing, DrawingError, read_bytes, text_centre

#: $INSUNITS code → mm per drawing unit.
INSUNITS_MM = {1: 25.4, 2: 304.8, 3: 1_609_344.0, 4: 1.0, 5: 10.0, 6: 1000.0,
               7: 1_000_000.0, 8: 25.4e-6, 9: 0.0254, 10: 914.4, 14: 100.0}

_H_FRAC = {0: 0.0, 1: 0.5, 2: 1.0, 3: 0.5, 4: 0.5, 5: 0.5}
_V_FRAC = {0: 0.0, 1: -0.25, 2: 0.5, 3: 1.0}
# MTEXT attachment point → (h, v) fractions of the first line's box
_ATTACH = {1: (0.0, 1.0), 2: (0.5, 1.0), 3: (1.0, 1.0), 4: (0.0, 0.5), 5: (0.5, 0.5),
           6: (1.0, 0.5), 7: (0.0, 0.0), 8: (0.5, 0.0), 9: (1.0, 0.0)}


def read_dxf(path: Path) -> Drawing:
    """Read a DXF file into a :class:`~.primitives.Drawing` (mm, y up)."""
    try:
        import ezdxf
        from ezdxf import recover
    except ImportError:
        raise DrawingError(f"{path}: reading DXF needs ezdxf (pip install "
                           "'graphplan[drawing]')") from None
    data = read_bytes(path)
    try:
        doc, _auditor = recover.read(io.BytesIO(data))
    except ezdxf.DXFStructureError as exc:
        raise DrawingError(f"{path}: not a readable DXF ({' '.join(str(exc).split())})"
                           ) from None
    except Exception as exc:  # ezdxf raises many kinds on damaged files
        raise DrawingError(f"{path}: not a readable DXF ({type(exc).__name__}: "
                           f"{' '.join(str(exc).split())[:120]})") from None
    col = Collector(str(path))
    units = int(doc.header.get("$INSUNITS", 0) or 0)
    k = INSUNITS_MM.get(units)
    if k is None:
        k = 1.0
        col.notes.append("the DXF gives no units ($INSUNITS): read as millimetres")
    r = _Reader(doc, col, k)
    msp = doc.modelspace()
    r.entities(msp, 0)
    if not col.segments and not col.texts:
        for layout in doc.layouts:
            if layout.name.lower() != "model":
                r.entities(layout, 0)
    return col.drawing("dxf")


class _Reader:
    def __init__(self, doc, col: Collector, k: float):
        self.doc = doc
        self.col = col
        self.k = k

    def colour(self, e) -> str:
        from ezdxf import colors

        try:
            if e.dxf.hasattr("true_color"):
                r, g, b = e.rgb
                return f"#{r:02x}{g:02x}{b:02x}"
            aci = e.dxf.get("color", 256)
            if aci == 256:  # by layer
                layer = self.doc.layers.get(e.dxf.get("layer", "0"))
                aci = abs(layer.color) if layer is not None else 7
            if aci in (0, 7, 256) or not 0 < aci < 256:
                return "#000000"
            r, g, b = colors.aci2rgb(aci)
            return f"#{r:02x}{g:02x}{b:02x}"
        except Exception:
            return "#000000"

    def entities(self, space, depth: int) -> None:
        if depth > MAX_DEPTH:
            raise DrawingError(f"{self.col.source}: blocks nested more than {MAX_DEPTH} deep: "
                               "not read")
        for e in space:
            self.entity(e, depth)

    def entity(self, e, depth: int) -> None:
        t = e.dxftype()
        k = self.k
        col = self.col
        layer = e.dxf.get("layer", "")
        try:
            if t == "LINE":
                s, f = e.dxf.start, e.dxf.end
                col.line(s.x * k, s.y * k, f.x * k, f.y * k, self.colour(e),
                         self._weight(e), layer)
            elif t in ("LWPOLYLINE", "POLYLINE", "ARC", "ELLIPSE", "SPLINE", "CIRCLE"):
                if t == "POLYLINE" and (e.is_poly_face_mesh or e.is_polygon_mesh):
                    return
                if t == "CIRCLE":
                    c = e.dxf.center
                    col.circle(c.x * k, c.y * k, e.dxf.radius * k, self.colour(e), layer)
                self._path(e, t in ("ARC", "ELLIPSE", "SPLINE", "CIRCLE"), layer)
            elif t in ("SOLID", "TRACE", "3DFACE"):
                vs = [e.dxf.get(f"vtx{i}") for i in range(4)]
                vs = [v for v in (vs[0], vs[1], vs[3], vs[2]) if v is not None]
                col.fill([(v.x * k, v.y * k) for v in vs], self.colour(e), layer)
            elif t == "HATCH":
                from ezdxf import path as dpath

                for p in dpath.from_hatch(e):
                    pts = [(v.x * k, v.y * k) for v in p.flattening(0.05 / k)]
                    col.fill(pts, self.colour(e), layer)
            elif t == "TEXT" or t == "ATTRIB":
                self._text(e, layer)
            elif t == "MTEXT":
                self._mtext(e, layer)
            elif t == "INSERT":
                for a in getattr(e, "attribs", ()):
                    self._text(a, layer)
                self.entities(e.virtual_entities(), depth + 1)
            elif t == "DIMENSION":
                self.entities(e.virtual_entities(), depth + 1)
        except DrawingError:
            raise
        except Exception as exc:  # one damaged entity does not stop the drawing
            col.notes.append(f"a {t} entity could not be read ({type(exc).__name__})")

    def _weight(self, e) -> float:
        w = e.dxf.get("lineweight", -1)
        return w / 100.0 if isinstance(w, int) and w > 0 else 0.25

    def _path(self, e, curve: bool, layer: str) -> None:
        from ezdxf import path as dpath

        k = self.k
        p = dpath.make_path(e)
        colour, width = self.colour(e), self._weight(e)
        start = p.start
        for cmd in p.commands():
            end = cmd.end
            if cmd.type == dpath.Command.LINE_TO:
                self.col.line(start.x * k, start.y * k, end.x * k, end.y * k, colour, width,
                              layer, curve)
            elif cmd.type == dpath.Command.MOVE_TO:
                pass
            else:
                sub = dpath.Path(start)
                if isinstance(cmd, dpath.Curve3To):
                    sub.curve3_to(end, cmd.ctrl)
                elif isinstance(cmd, dpath.Curve4To):
                    sub.curve4_to(end, cmd.ctrl1, cmd.ctrl2)
                pts = [(v.x * k, v.y * k) for v in sub.flattening(0.05 / k, segments=4)]
                self.col.polyline(pts, False, colour, width, layer, True)
            start = end

    def _text(self, e, layer: str) -> None:
        k = self.k
        try:
            text = e.plain_text()
        except Exception:
            text = e.dxf.get("text", "")
        h = e.dxf.get("height", 2.5) * k
        rot = e.dxf.get("rotation", 0.0)
        ha, va = e.dxf.get("halign", 0), e.dxf.get("valign", 0)
        p = e.dxf.insert
        if (ha or va) and e.dxf.hasattr("align_point") and ha not in (3, 5):
            p = e.dxf.align_point
        elif ha in (3, 5) and e.dxf.hasattr("align_point"):
            q = e.dxf.align_point
            p = (p + q) / 2
            ha = 1
        vf = 0.5 if ha == 4 else _V_FRAC.get(va, 0.0)
        # a width factor (КОМПАС's narrow lettering, 0,8 or so) narrows the text's box
        wide = float(e.dxf.get("width", 1.0) or 1.0)
        x, y = text_centre(p.x * k, p.y * k, h, rot, len(text) * min(max(wide, 0.2), 5.0),
                           _H_FRAC.get(ha, 0.0), vf)
        self.col.text(text, x, y, h, rot, self.colour(e), layer)

    def _mtext(self, e, layer: str) -> None:
        k = self.k
        try:
            from ezdxf.tools.text import plain_mtext

            lines = [ln for ln in plain_mtext(unstack(e.text), split=True) if ln.strip()]
        except Exception:
            lines = [e.dxf.get("text", "")]
        h = e.dxf.get("char_height", 2.5) * k
        try:
            rot = e.get_rotation()
        except Exception:
            rot = e.dxf.get("rotation", 0.0)
        hf, vf = _ATTACH.get(e.dxf.get("attachment_point", 1), (0.0, 1.0))
        p = e.dxf.insert
        n = len(lines)
        step = 1.67 * h  # MTEXT's default line spacing
        # where the first line's baseline is, relative to the insertion point
        top = {1.0: 0.0, 0.5: (n - 1) * step / 2, 0.0: (n - 1) * step}[vf]
        a = math.radians(rot)
        for i, ln in enumerate(lines):
            dy = top - i * step
            x0 = p.x * k - dy * math.sin(a)
            y0 = p.y * k + dy * math.cos(a)
            x, y = text_centre(x0, y0, h, rot, len(ln), hf, vf)
            self.col.text(ln, x, y, h, rot, self.colour(e), layer)


_STACK = re.compile(r"\\S([^;]*?)(\^ ?|/|#)([^;]*);")


def unstack(mtext: str) -> str:
    """MTEXT with its stacked texts (``\\S…;``) written on one line: an index stacked
    under nothing or under a superscript (``R\\S^ 12;``, ``R\\Sτ^ 43;``: how AutoCAD's and
    КОМПАС's editors write R₁₂ and R^τ₄₃) as the letters in a row (``R12``, ``Rτ43``); a
    fraction ``\\S1/2;`` or ``\\S1#2;`` as ``1/2``. (ezdxf's plain text reads the caret of
    ``^ 12`` as DXF's caret escape.)"""
    def one(m: re.Match) -> str:
        up, kind, low = m.group(1), m.group(2), m.group(3)
        return f"{up}{low}" if kind.startswith("^") else f"{up}/{low}"

    return _STACK.sub(one, mtext)


__all__ = ["INSUNITS_MM", "read_dxf", "unstack"]
