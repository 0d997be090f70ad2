"""A PDF font as the drawing reader needs it: the codes of a shown string, each code's
character and its advance width.

A string shown by ``Tj``/``TJ`` is a run of character codes: one byte each in a simple
font (Type1, TrueType, Type3), two bytes in a composite (Type0) font with the usual
``Identity-H`` encoding (or as many as the ``ToUnicode`` map's code space says). The
character of a code is the font's ``ToUnicode`` map (``bfchar``/``bfrange``) where it
has one, else — simple fonts — its ``/Encoding`` (a named base encoding and its
``/Differences`` glyph names). The advance of a code is ``/Widths`` from ``/FirstChar``
(simple fonts), or ``/W`` and ``/DW`` of the descendant font (Type0), in thousandths of
the text space unit (a Type3 font's in glyph space, scaled by its ``/FontMatrix``).

A code with no known character is ``None``: :mod:`.pdf` then lets pypdf's own text
extraction read the page.
"""

from __future__ import annotations

import re

DEFAULT_WIDTH = 0.55
"""Advance (em) of a code whose font gives no width (a standard font without ``/Widths``)."""


def _glyph_names() -> dict[str, str]:
    try:
        from pypdf._codecs import adobe_glyphs  # the Adobe Glyph List, as pypdf ships it
    except ImportError:  # pragma: no cover - pypdf moved it
        return {}
    return dict(adobe_glyphs)


def _base_encoding(name: str) -> list[str]:
    try:
        from pypdf._codecs import charset_encoding
    except ImportError:  # pragma: no cover - pypdf moved it
        charset_encoding = {}
    enc = charset_encoding.get(name) or charset_encoding.get("/StandardEncoding")
    if enc and len(enc) >= 256:
        return list(enc[:256])
    return [chr(i) if 32 <= i < 127 else "" for i in range(256)]


_NAMES: dict[str, str] | None = None


def _name_to_char(name: str) -> str:
    global _NAMES
    if _NAMES is None:
        _NAMES = _glyph_names()
    key = name if name.startswith("/") else "/" + name
    if key in _NAMES:
        return _NAMES[key]
    m = re.fullmatch(r"/?(?:uni([0-9A-Fa-f]{4})|u([0-9A-Fa-f]{4,6}))", key)
    if m:
        try:
            return chr(int(m[1] or m[2], 16))
        except ValueError:
            return ""
    return ""


def _hexes(token: bytes) -> list[bytes]:
    return re.findall(rb"<([0-9A-Fa-f\s]*)>", token)


def _hex_int(h: bytes) -> int:
    return int(b"".join(h.split()) or b"0", 16)


def _hex_text(h: bytes) -> str:
    raw = bytes.fromhex(b"".join(h.split()).decode("ascii"))
    if len(raw) % 2:
        return raw.decode("latin-1")
    return raw.decode("utf-16-be", errors="replace")


def parse_to_unicode(data: bytes) -> tuple[dict[int, str], int]:
    """The code → text map of a ``ToUnicode`` CMap, and its code length in bytes
    (0 when it declares no code space)."""
    out: dict[int, str] = {}
    nbytes = 0
    for block in re.findall(rb"begincodespacerange(.*?)endcodespacerange", data, re.S):
        hx = _hexes(block)
        if hx:
            nbytes = max(nbytes, len(b"".join(hx[0].split())) // 2)
    for block in re.findall(rb"beginbfchar(.*?)endbfchar", data, re.S):
        hx = _hexes(block)
        for src, dst in zip(hx[0::2], hx[1::2], strict=False):
            out[_hex_int(src)] = _hex_text(dst)
    for block in re.findall(rb"beginbfrange(.*?)endbfrange", data, re.S):
        for m in re.finditer(rb"<([0-9A-Fa-f]+)>\s*<([0-9A-Fa-f]+)>\s*"
                             rb"(<[0-9A-Fa-f\s]*>|\[[^\]]*\])", block):
            lo, hi = int(m[1], 16), int(m[2], 16)
            if hi - lo > 65_535 or hi < lo:
                continue
            dst = m[3]
            if dst.startswith(b"["):
                for i, h in enumerate(_hexes(dst)):
                    if lo + i <= hi:
                        out[lo + i] = _hex_text(h)
                continue
            first = _hex_text(dst[1:-1])
            if not first:
                continue
            for i in range(hi - lo + 1):
                out[lo + i] = first[:-1] + chr(min(ord(first[-1]) + i, 0x10FFFF))
    return out, nbytes


class PdfFont:
    """Codes, characters and advances of one font dictionary (module doc)."""

    def __init__(self, font):
        font = font.get_object() if hasattr(font, "get_object") else font
        sub = str(font.get("/Subtype", ""))
        self.composite = sub == "/Type0"
        self.nbytes = 2 if self.composite else 1
        self.scale = 0.001  # glyph space → text space
        if sub == "/Type3":
            try:
                self.scale = float(font["/FontMatrix"][0])
            except (KeyError, TypeError, ValueError, IndexError):
                self.scale = 0.001
        self.unicode: dict[int, str] = {}
        tu = font.get("/ToUnicode")
        if tu is not None:
            try:
                self.unicode, nb = parse_to_unicode(tu.get_object().get_data())
                if nb and self.composite:
                    self.nbytes = nb
            except Exception:
                self.unicode = {}
        self.encoding: list[str] = []
        if not self.composite:
            self.encoding = self._simple_encoding(font)
        self.widths: dict[int, float] = {}
        self.default = DEFAULT_WIDTH / self.scale
        if self.composite:
            self._cid_widths(font)
        else:
            try:
                first = int(font.get("/FirstChar", 0))
                for i, w in enumerate(font.get("/Widths", None) or []):
                    self.widths[first + i] = float(w)
                fd = font.get("/FontDescriptor")
                fd = fd.get_object() if fd is not None else None
                if fd is not None and "/MissingWidth" in fd:
                    self.default = float(fd["/MissingWidth"])
            except (TypeError, ValueError):
                pass

    @staticmethod
    def _simple_encoding(font) -> list[str]:
        enc = font.get("/Encoding")
        enc = enc.get_object() if hasattr(enc, "get_object") else enc
        if enc is None or isinstance(enc, str):
            table = _base_encoding(str(enc) if enc else "/StandardEncoding")
            if enc is None and str(font.get("/Subtype")) == "/TrueType":
                table = _base_encoding("/WinAnsiEncoding")
            return table
        table = _base_encoding(str(enc.get("/BaseEncoding", "/StandardEncoding")))
        code = 0
        for item in enc.get("/Differences", None) or []:
            if isinstance(item, int) or str(item).lstrip("-").isdigit():
                code = int(item)
            else:
                if 0 <= code < 256:
                    table[code] = _name_to_char(str(item))
                code += 1
        return table

    def _cid_widths(self, font) -> None:
        try:
            desc = font["/DescendantFonts"][0].get_object()
            self.default = float(desc.get("/DW", 1000))
            w = list(desc.get("/W", None) or [])
        except (KeyError, TypeError, ValueError, IndexError):
            return
        i = 0
        while i < len(w) and len(self.widths) < 70_000:
            try:
                first = int(w[i])
                nxt = w[i + 1].get_object() if hasattr(w[i + 1], "get_object") else w[i + 1]
                if isinstance(nxt, list):
                    for k, x in enumerate(nxt):
                        self.widths[first + k] = float(x)
                    i += 2
                else:
                    last, width = int(nxt), float(w[i + 2])
                    for c in range(first, min(last, first + 70_000) + 1):
                        self.widths[c] = width
                    i += 3
            except (TypeError, ValueError, IndexError):
                return

    def codes(self, raw: bytes) -> list[tuple[int, str | None, float, bool]]:
        """Each code of a shown string: (code, its text or ``None`` when unknown, its
        advance in text space units per unit font size, whether it is a word space — the
        single-byte code 32, which ``Tw`` widens)."""
        out: list[tuple[int, str | None, float, bool]] = []
        n = self.nbytes
        for i in range(0, len(raw) - n + 1, n):
            code = int.from_bytes(raw[i:i + n], "big")
            text: str | None = self.unicode.get(code)
            if text is None and not self.composite and code < len(self.encoding):
                text = self.encoding[code] or None
            adv = self.widths.get(code, self.default) * self.scale
            out.append((code, text, adv, n == 1 and code == 32))
        return out


__all__ = ["DEFAULT_WIDTH", "PdfFont", "parse_to_unicode"]
