"""Reading a vector PDF drawing with pypdf (BSD licence, pure Python).

The page's content stream is walked operator by operator: the graphics state
(``q``/``Q``, ``cm``), paths (``m l c v y h re``) painted by stroking (``S s B b``) or
filling (``f F f* B b``), colours (``G RG K g rg k SC SCN sc scn``), form XObjects
(``Do``, :data:`~.primitives.MAX_DEPTH` deep) and text: the text state (``Tf Tc Tw Tz
TL Ts Tr``), the text matrix (``BT Td TD Tm T*``) and every code shown (``Tj TJ ' "``),
each placed where the PDF puts it, with its character (:mod:`.pdf_fonts`: the font's
``ToUnicode`` map or encoding) and its advance (the font's widths). The characters are
then joined into texts as the drawing shows them (:func:`_texts`): PDF writers place
glyphs one by one (Typst, which makes graphplan's own PDFs, shows every glyph in its own
text object), leave out the spaces between words, and show a subscript as a smaller text
lower down — ``R`` then ``12`` is the text ``R12``. A page whose fonts this reader cannot
decode is read by pypdf's own text extraction instead.

Points (1/72 in) become mm; the page's y already points up; a page turned by ``/Rotate``
(a landscape sheet plotted on a portrait page) is read as it is shown. Only the first
:data:`MAX_PAGES` pages are read.
"""

from __future__ import annotations

import contextlib
import io
import math
from dataclasses import dataclass, replace
from pathlib import Path

from .pdf_fonts import PdfFont
from .primitives import (
    MAX_DEPTH,
    MAX_ITEMS,
    Collector,
    Drawing,
    DrawingError,
    fit_circle,
    read_bytes,
    text_centre,
)

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
        w, h = float(box.width), float(box.height)
        try:
            turn = int(page.get("/Rotate", 0) or 0) % 360
        except (TypeError, ValueError):
            turn = 0
        # the page as it is shown: /Rotate turns it clockwise (a landscape sheet plotted
        # on a portrait page and turned back), (x, y) → (a·x + c·y + e, b·x + d·y + f) pt
        a, b, c, d, e, f = {
            90: (0.0, -1.0, 1.0, 0.0, -y0, w + x0),
            180: (-1.0, 0.0, 0.0, -1.0, w + x0, h + y0),
            270: (0.0, 1.0, -1.0, 0.0, h + y0, -x0),
        }.get(turn, (1.0, 0.0, 0.0, 1.0, -x0, -y0))
        if turn in (90, 270):
            w, h = h, w
        # pages are stacked downwards, each in its own place
        base = (a * PT_MM, b * PT_MM, c * PT_MM, d * PT_MM, e * PT_MM,
                (f - (y_off if n else 0.0)) * PT_MM)
        if n == 0:
            size = (0.0, 0.0, w * PT_MM, h * PT_MM)
        try:
            walker = _Page(reader, col, base)
            walker.run(page, page.get("/Resources"), 0)
            if walker.unknown > 0.2 * (walker.unknown + len(walker.glyphs)):
                # fonts whose codes no map here decodes: pypdf's own extraction
                _pypdf_texts(page, col, base)
            else:
                _texts(walker.glyphs, col)
        except DrawingError:
            raise
        except Exception as exc:
            raise DrawingError(f"{path}: page {n + 1} cannot be read ({type(exc).__name__}: "
                               f"{' '.join(str(exc).split())[:120]})") from None
        y_off += h + 20.0
    return col.drawing("pdf", size)


class _Glyph:
    """One shown character: its text, where its origin and its advance end are (mm), the
    baseline's unit direction and the em height across it (mm), its colour."""

    __slots__ = ("char", "colour", "ex", "ey", "nx", "ny", "size", "ux", "uy", "x", "y")

    def __init__(self, char, origin, end, up, size, colour):
        self.char = char
        self.x, self.y = origin
        self.ex, self.ey = end
        L = math.hypot(self.ex - self.x, self.ey - self.y)
        if L > 1e-9:
            self.ux, self.uy = (self.ex - self.x) / L, (self.ey - self.y) / L
        else:  # a zero advance: the baseline's direction from the glyph's up
            self.ux, self.uy = up[1], -up[0]
        self.nx, self.ny = -self.uy, self.ux
        if self.nx * up[0] + self.ny * up[1] < 0:  # the text is mirrored: keep its up
            self.nx, self.ny = -self.nx, -self.ny
        self.size = size
        self.colour = colour


@dataclass(slots=True)
class _TextState:
    """The text state kept with the graphics state (``q``/``Q``): font and size (``Tf``),
    character and word spacing (``Tc``, ``Tw``), horizontal scaling (``Tz``, as a
    fraction), leading (``TL``), rise (``Ts``), render mode (``Tr``)."""

    font: PdfFont | None = None
    size: float = 1.0
    char_space: float = 0.0
    word_space: float = 0.0
    scale: float = 1.0
    leading: float = 0.0
    rise: float = 0.0
    mode: int = 0

    def set(self, op: str, value: float) -> None:
        if op == "Tc":
            self.char_space = value
        elif op == "Tw":
            self.word_space = value
        elif op == "Tz":
            self.scale = value / 100
        elif op == "TL":
            self.leading = value
        elif op == "Ts":
            self.rise = value
        elif op == "Tr":
            self.mode = int(value)


class _Page:
    """Walks a page's (or a form's) content stream: paths to the collector, shown text to
    :attr:`glyphs` (module doc)."""

    def __init__(self, reader, col: Collector, base):
        self.reader = reader
        self.col = col
        self.base = base
        self.ops = 0
        self.glyphs: list[_Glyph] = []
        self.unknown = 0  # codes whose character no map gives
        self._fonts: dict[int, PdfFont] = {}

    def _font(self, resources, name) -> PdfFont | None:
        try:
            ref = resources["/Font"].get_object()[name]
        except (KeyError, TypeError, AttributeError):
            return None
        key = id(ref.get_object())
        if key not in self._fonts:
            self._fonts[key] = PdfFont(ref)
        return self._fonts[key]

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
        # text state (kept with the graphics state): font, size, Tc, Tw, Tz, TL, rise, Tr
        ts = _TextState()
        tm = tlm = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)
        sub: list[list[tuple[float, float]]] = []
        closed: list[bool] = []
        curve = False
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
                    "cm", "m", "l", "c", "v", "y", "re", "w", "Td", "TD", "Tm", "Tc", "Tw",
                    "Tz", "TL", "Ts", "Tr") else []
            except (TypeError, ValueError):
                continue
            if op == "q":
                stack.append((ctm, stroke, fill, width, replace(ts)))
                if len(stack) > 10_000:
                    raise DrawingError(f"{self.col.source}: graphics states nested too deep")
            elif op == "Q":
                if stack:
                    ctm, stroke, fill, width, ts = stack.pop()
            elif op == "cm" and len(v) == 6:
                ctm = _m(tuple(v), ctm)
            elif op == "w" and v:
                width = v[0]
            elif op in ("G", "RG", "K", "SC", "SCN"):
                stroke = _hex(operands)
            elif op in ("g", "rg", "k", "sc", "scn"):
                fill = _hex(operands)
            elif op == "BT":
                tm = tlm = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)
            elif op == "Tf" and len(operands) == 2:
                with contextlib.suppress(TypeError, ValueError):
                    ts.font, ts.size = self._font(resources, operands[0]), float(operands[1])
            elif op in ("Tc", "Tw", "Tz", "TL", "Ts", "Tr") and v:
                ts.set(op, v[0])
            elif op in ("Td", "TD") and len(v) == 2:
                if op == "TD":
                    ts.leading = -v[1]
                tm = tlm = _m((1.0, 0.0, 0.0, 1.0, v[0], v[1]), tlm)
            elif op == "Tm" and len(v) == 6:
                tm = tlm = (v[0], v[1], v[2], v[3], v[4], v[5])
            elif op in ("T*", "'", '"'):
                if op == '"' and len(operands) == 3:
                    with contextlib.suppress(TypeError, ValueError):
                        ts.word_space, ts.char_space = float(operands[0]), float(operands[1])
                tm = tlm = _m((1.0, 0.0, 0.0, 1.0, 0.0, -ts.leading), tlm)
                if op != "T*" and operands:
                    tm = self._show([operands[-1]], ts, tm, ctm, stroke, fill)
            elif op == "Tj" and operands:
                tm = self._show([operands[0]], ts, tm, ctm, stroke, fill)
            elif op == "TJ" and operands:
                try:
                    items = list(operands[0])
                except TypeError:
                    continue
                tm = self._show(items, ts, tm, ctm, stroke, fill)
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
                curve = True
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
                    if curve and len(tp) >= 12:
                        _circle(tp, self.col, stroke)
                    if op in ("S", "s", "B", "B*", "b", "b*"):
                        self.col.polyline(tp, cl, stroke, width * k, "", len(pts) > 2 and curve)
                    if op in ("f", "F", "f*", "B", "B*", "b", "b*") and len(tp) >= 3 and \
                            fill != "#ffffff":
                        self.col.fill(tp, fill)
                sub, closed, cur = [], [], None
                curve = False
            elif op == "Do" and operands:
                self._form(operands[0], resources, depth, ctm)

    def _show(self, items, ts, tm, ctm, stroke, fill):
        """Place the codes of a shown string (``TJ``'s numbers move the pen back by
        thousandths of the font size); the text matrix after them."""
        font, fs, tc, tw, th = ts.font, ts.size, ts.char_space, ts.word_space, ts.scale
        rise, mode = ts.rise, ts.mode
        for it in items:
            if isinstance(it, (int, float)) or type(it).__name__ in (
                    "FloatObject", "NumberObject"):
                with contextlib.suppress(TypeError, ValueError):
                    tm = _m((1.0, 0.0, 0.0, 1.0, -float(it) / 1000 * fs * th, 0.0), tm)
                continue
            raw = getattr(it, "original_bytes", None)
            if raw is None:
                try:
                    raw = bytes(it)
                except (TypeError, ValueError):
                    continue
            if font is None:
                continue
            for _code, text, adv, space in font.codes(raw):
                m = _m(_m(tm, ctm), self.base)
                tx = (adv * fs + tc + (tw if space else 0.0)) * th
                if mode not in (3, 7) and text is not None and text.strip():
                    # the em along the glyphs' own up (a slanted font's, as the SVG
                    # reader takes it)
                    up = (fs * m[2], fs * m[3])
                    size = math.hypot(*up)
                    self.glyphs.append(_Glyph(text, _pt(m, 0.0, rise),
                                              _pt(m, adv * fs * th, rise), up, size,
                                              stroke if mode in (1, 5) else fill))
                elif text is None:
                    self.unknown += 1
                tm = _m((1.0, 0.0, 0.0, 1.0, tx, 0.0), tm)
                if len(self.glyphs) > MAX_ITEMS:
                    raise DrawingError(f"{self.col.source}: more than {MAX_ITEMS} characters: "
                                       "not read")
        return tm

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


def _circle(pts, col: Collector, colour: str) -> None:
    """A closed curve whose points are all as far from their middle (to 2 %): a circle
    (PDF has none: writers draw one as four Bézier arcs), kept as the SVG and DXF readers
    keep theirs — a joint, a pivot."""
    (x0, y0), (x1, y1) = pts[0], pts[-1]
    cx, cy, r = fit_circle(pts)
    rs = [math.hypot(p[0] - cx, p[1] - cy) for p in pts]
    if 0.1 <= r <= 100.0 and math.hypot(x1 - x0, y1 - y0) <= 0.02 * r and \
            max(abs(q - r) for q in rs) <= 0.02 * r:
        col.circle(cx, cy, r, colour)


def _pypdf_texts(page, col: Collector, base) -> None:
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


JOIN_ALONG = (-0.3, 0.6)
"""How far (em of the text so far) the next character's origin may sit behind or past the
pen for it to continue the text: nearer than a word's gap plus a space."""
JOIN_ACROSS = 0.45
"""How far (em) off the text's baseline a character continuing it may sit: a subscript
(graphplan's: 0.7 of the size, 0.22 em down) or a superscript."""
STACK_BACK = 0.75
"""How far back (em of the text so far) a smaller character may start: under the script
before it."""
SPACE_GAP = 0.16
"""A gap along the baseline wider than this (em) between two characters is a space: PDF
writers (Typst among them) often place words without a space character between them."""


def _texts(glyphs: list[_Glyph], col: Collector) -> None:
    """Join the characters of a page into texts, as the drawing shows them.

    A character continues the text before it (in the order they are shown) when it runs
    the same way (within 2°), is 0.45–1.6 times its size, starts within
    :data:`JOIN_ALONG` of its pen (the farthest any of its characters reaches) and within
    :data:`JOIN_ACROSS` of its baseline — so a subscript shown smaller and lower (``R``
    then ``12``) is one text ``R12``, and a label written glyph by glyph is one text. A
    smaller character may start under the one before, up to :data:`STACK_BACK` of the
    size back (a subscript set under a superscript: ``Rτ43`` as R^τ_43). A gap wider
    than :data:`SPACE_GAP` is a space. Each text's centre is the middle of its first
    character's origin and its pen, half a capital height (0.72 em) above the baseline."""
    runs: list[list] = []  # [chars, first glyph, pen (along the first's baseline), size]
    for g in glyphs:
        r = runs[-1] if runs else None
        if r is not None:
            f, pen, size = r[1], r[2], r[3]
            at = (g.x - f.x) * f.ux + (g.y - f.y) * f.uy
            along = at - pen
            across = (g.x - f.x) * f.nx + (g.y - f.y) * f.ny
            back = STACK_BACK if g.size < 0.85 * size else -JOIN_ALONG[0]
            if g.ux * f.ux + g.uy * f.uy > math.cos(math.radians(2.0)) and \
                    0.45 * size <= g.size <= 1.6 * size and \
                    -back * size <= along <= JOIN_ALONG[1] * size and \
                    abs(across) <= JOIN_ACROSS * size:
                if along > SPACE_GAP * min(size, g.size) and r[0][-1] != " " and \
                        g.char[:1] != " ":
                    r[0].append(" ")
                r[0].append(g.char)
                r[2] = max(pen, (g.ex - f.x) * f.ux + (g.ey - f.y) * f.uy)
                r[3] = max(size, g.size)
                continue
        runs.append([[g.char], g, (g.ex - g.x) * g.ux + (g.ey - g.y) * g.uy, g.size])
    for chars, f, pen, size in runs:
        text = " ".join("".join(chars).split())
        if not text:
            continue
        cap = 0.72 * size
        cx = f.x + 0.5 * pen * f.ux + 0.5 * cap * f.nx
        cy = f.y + 0.5 * pen * f.uy + 0.5 * cap * f.ny
        col.text(text, cx, cy, cap, math.degrees(math.atan2(f.uy, f.ux)), f.colour)


__all__ = ["read_pdf"]
