"""Reading a vector PDF drawing with pypdf (BSD licence, pure Python).

The page's content stream is walked operator by operator: the graphics state
(``q``/``Q``, ``cm``), paths (``m l c v y h re``) painted by stroking (``S s B b``) or
filling (``f F f* B b``), colours (``G RG K g rg k SC SCN sc scn``) and form XObjects
(``Do``, :data:`~.primitives.MAX_DEPTH` deep). Texts are pypdf's own decoding
(``extract_text`` with a visitor: fonts, encodings, ToUnicode) with the text matrix of
each run; runs on one baseline that follow each other are joined. Points (1/72 in)
become mm; the page's y already points up. Only the first :data:`MAX_PAGES` pages are
read.
"""

from __future__ import annotations

import io
import math
from pathlib import Path

from .primitives import MAX_DEPTH, Collector, Drawing, DrawingError, read_bytes, text_centre

PT_MM = 25.4 / 72
MAX_PAGES = 8
MAX_OPERATIONS = 2_000_000


def _m(a, b):
    """Product of two PDF matrices [a b c d e f] (row vectors: apply a, then b)."""
    a0, a1, a2, a3, a4, a5 = a
    b0, b1, b2, b3, b4, b5 = b
    return (a0 * b0 + a1 * b2, a0 * b1 + a1 * b3, a2 * b0 + a3 * b2, a2 * b1 + a3 * b3,
            a4 * b0 + a5 * b2 + b4, a4 * b1 + a5 * b3 + b5)


def _pt(m, x, y):
    return (m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5])


def _hex(vals) -> str:
    try:
        v = [float(x) for x in vals]
    except (TypeError, ValueError):
        return "#000000"
    if len(v) == 1:
        v = v * 3
    elif len(v) == 4:  # CMYK
        c, m, y, k = v
        v = [(1 - c) * (1 - k), (1 - m) * (1 - k), (1 - y) * (1 - k)]
    elif len(v) != 3:
        return "#000000"
    return "#" + "".join(f"{max(0, min(255, round(x * 255))):02x}" for x in v)


def read_pdf(path: Path) -> Drawing:
    """Read a vector PDF into a :class:`~.primitives.Drawing` (mm, y up)."""
    try:
        from pypdf import PdfReader
        from pypdf.errors import PdfReadError
    except ImportError:
        raise DrawingError(f"{path}: reading PDF needs pypdf (pip install "
                           "'graphplan[drawing]')") from None
    data = read_bytes(path)
    try:
        reader = PdfReader(io.BytesIO(data), strict=False)
        if reader.is_encrypted:
            raise DrawingError(f"{path}: the PDF is encrypted: not read")
        pages = list(reader.pages)
    except DrawingError:
        raise
    except (PdfReadError, Exception) as exc:
        raise DrawingError(f"{path}: not a readable PDF ({type(exc).__name__}: "
                           f"{' '.join(str(exc).split())[:120]})") from None
    if not pages:
        raise DrawingError(f"{path}: the PDF has no pages")
    col = Collector(str(path))
    if len(pages) > MAX_PAGES:
        col.notes.append(f"only the first {MAX_PAGES} of {len(pages)} pages are read")
    y_off = 0.0
    size = (0.0, 0.0, 0.0, 0.0)
    for n, page in enumerate(pages[:MAX_PAGES]):
        box = page.mediabox
        x0, y0 = float(box.left), float(box.bottom)
        h = float(box.height)
        # pages are stacked downwards, each in its own place
        base = (PT_MM, 0.0, 0.0, PT_MM, -x0 * PT_MM, (-y0 - (y_off if n else 0.0)) * PT_MM)
        if n == 0:
            size = (0.0, 0.0, float(box.width) * PT_MM, h * PT_MM)
        try:
            _Paths(reader, col, base).run(page, page.get("/Resources"), 0)
            _texts(page, col, base)
        except DrawingError:
            raise
        except Exception as exc:
            raise DrawingError(f"{path}: page {n + 1} cannot be read ({type(exc).__name__}: "
                               f"{' '.join(str(exc).split())[:120]})") from None
        y_off += h + 20.0
    return col.drawing("pdf", size)


class _Paths:
    def __init__(self, reader, col: Collector, base):
        self.reader = reader
        self.col = col
        self.base = base
        self.ops = 0

    def run(self, obj, resources, depth: int, ctm=None) -> None:
        from pypdf.generic import ContentStream

        if depth > MAX_DEPTH:
            raise DrawingError(f"{self.col.source}: forms nested more than {MAX_DEPTH} deep: "
                               "not read")
        contents = obj.get_contents() if hasattr(obj, "get_contents") else obj
        if contents is None:
            return
        cs = ContentStream(contents, self.reader)
        ctm = ctm or (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)
        stack = []
        stroke, fill, width = "#000000", "#000000", 1.0
        sub: list[list[tuple[float, float]]] = []
        closed: list[bool] = []
        cur = None
        op: bytes | str
        for operands, op in cs.operations:
            self.ops += 1
            if self.ops > MAX_OPERATIONS:
                raise DrawingError(f"{self.col.source}: more than {MAX_OPERATIONS} drawing "
                                   "operations: not read")
            op = op.decode("latin-1") if isinstance(op, bytes) else op
            try:
                v = [float(x) for x in operands] if op in (
                    "cm", "m", "l", "c", "v", "y", "re", "w") else []
            except (TypeError, ValueError):
                continue
            if op == "q":
                stack.append((ctm, stroke, fill, width))
                if len(stack) > 10_000:
                    raise DrawingError(f"{self.col.source}: graphics states nested too deep")
            elif op == "Q":
                if stack:
                    ctm, stroke, fill, width = stack.pop()
            elif op == "cm" and len(v) == 6:
                ctm = _m(tuple(v), ctm)
            elif op == "w" and v:
                width = v[0]
            elif op in ("G", "RG", "K", "SC", "SCN"):
                stroke = _hex(operands)
            elif op in ("g", "rg", "k", "sc", "scn"):
                fill = _hex(operands)
            elif op == "m" and len(v) == 2:
                cur = [(v[0], v[1])]
                sub.append(cur)
                closed.append(False)
            elif op == "l" and len(v) == 2 and cur is not None:
                cur.append((v[0], v[1]))
            elif op in ("c", "v", "y") and cur is not None and len(v) >= 4:
                p0 = cur[-1]
                if op == "c" and len(v) == 6:
                    c1, c2, p3 = (v[0], v[1]), (v[2], v[3]), (v[4], v[5])
                elif op == "v":
                    c1, c2, p3 = p0, (v[0], v[1]), (v[2], v[3])
                else:
                    c1, c2, p3 = (v[0], v[1]), (v[2], v[3]), (v[2], v[3])
                for t in (0.25, 0.5, 0.75, 1.0):
                    s = 1 - t
                    cur.append((s**3 * p0[0] + 3 * s * s * t * c1[0] + 3 * s * t * t * c2[0]
                                + t**3 * p3[0], s**3 * p0[1] + 3 * s * s * t * c1[1]
                                + 3 * s * t * t * c2[1] + t**3 * p3[1]))
                closed[-1] = closed[-1] or False
                sub[-1] = cur
                # mark as a curve by a sentinel in a parallel list
                self._curve = True
            elif op == "re" and len(v) == 4:
                x, y, w, h = v
                cur = [(x, y), (x + w, y), (x + w, y + h), (x, y + h)]
                sub.append(cur)
                closed.append(True)
            elif op == "h" and cur is not None and closed:
                closed[-1] = True
            elif op in ("S", "s", "f", "F", "f*", "B", "B*", "b", "b*", "n"):
                if op in ("s", "b", "b*") and closed:
                    closed[-1] = True
                m = _m(ctm, self.base)
                k = math.sqrt(abs(m[0] * m[3] - m[1] * m[2]))
                for pts, cl in zip(sub, closed, strict=False):
                    tp = [_pt(m, x, y) for x, y in pts]
                    if op in ("S", "s", "B", "B*", "b", "b*"):
                        self.col.polyline(tp, cl, stroke, width * k, "", len(pts) > 2 and
                                          getattr(self, "_curve", False))
                    if op in ("f", "F", "f*", "B", "B*", "b", "b*") and len(tp) >= 3 and \
                            fill != "#ffffff":
                        self.col.fill(tp, fill)
                sub, closed, cur = [], [], None
                self._curve = False
            elif op == "Do" and operands:
                self._form(operands[0], resources, depth, ctm)

    def _form(self, name, resources, depth, ctm) -> None:
        try:
            xobjs = resources["/XObject"].get_object() if resources else None
            x = xobjs[name].get_object() if xobjs is not None else None
        except (KeyError, TypeError, AttributeError):
            return
        if x is None or x.get("/Subtype") != "/Form":
            return
        mat = tuple(float(a) for a in x.get("/Matrix", (1, 0, 0, 1, 0, 0)))
        res = x.get("/Resources")
        res = res.get_object() if res is not None else resources
        self.run(x, res, depth + 1, _m(mat, ctm))


def _texts(page, col: Collector, base) -> None:
    runs: list[list] = []  # [text, x, y, size, angle, cm, tm]

    def visit(text, cm, tm, _font, size):
        if not text or not text.strip("\n"):
            return
        m = _m(tuple(float(a) for a in tm), tuple(float(a) for a in cm))
        m = _m(m, base)
        fs = float(size or 1.0)
        h = fs * math.hypot(m[2], m[3])
        angle = math.degrees(math.atan2(m[1], m[0]))
        x, y = m[4], m[5]
        for part in text.split("\n"):
            if not part.strip():
                continue
            if runs:
                r = runs[-1]
                a = math.radians(r[4])
                # along and across the last run's baseline, from its start
                dx, dy = x - r[1], y - r[2]
                along = dx * math.cos(a) + dy * math.sin(a)
                across = -dx * math.sin(a) + dy * math.cos(a)
                if abs(angle - r[4]) < 1 and abs(h - r[3]) < 0.2 * h and \
                        abs(across) < 0.3 * h and \
                        0.2 * h * len(r[0]) <= along <= (0.75 * len(r[0]) + 1.2) * h:
                    r[0] += part
                    continue
            runs.append([part, x, y, h, angle])

    page.extract_text(visitor_text=visit)
    for text, x, y, h, angle in runs:
        t = " ".join(text.split())
        cap = 0.72 * h
        cx, cy = text_centre(x, y, cap, angle, len(t), 0.0, 0.0)
        col.text(t, cx, cy, cap, angle)


__all__ = ["read_pdf"]
