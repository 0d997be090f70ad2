"""The sheets' fonts inlined into a page: ``@font-face`` rules with ``data:`` URLs.

A teaching page must open on a laptop with no network and without graphplan's fonts
installed, so the families of :data:`graphplan.fonts.FONT_CHAIN` (osifont, the GOST-like
lettering of the drawings; DejaVu Sans and DejaVu Sans Mono for the symbols osifont
lacks, and for the captions) are embedded, each **subset to the characters the page
uses** (fontTools, which comes with matplotlib) and packed as WOFF: a few tens of kB
instead of the 0.3–0.8 MB of the whole files. The ``@font-face`` rules keep the families'
own names, so the SVG's ``font-family`` lists (:func:`graphplan.fonts.font_family`) pick
them up unchanged. A family whose file is not installed is left out; the page then
falls back on the reader's fonts (it still loads nothing).
"""

from __future__ import annotations

import base64
import io
from functools import lru_cache

from .. import fonts

#: Characters every page embeds, whatever it letters: Latin, Cyrillic, Greek, digits and
#: the symbols of the method. A page's own characters outside it are added; so nearly
#: every page embeds the same subsets (computed once per process) and the fonts of two
#: pages are byte for byte the same.
BASE_CHARS = ("".join(chr(c) for c in range(0x20, 0x7F))
              + "".join(chr(c) for c in range(0x410, 0x450)) + "Ёё"
              + "ΑΒΓΔΕΖΗΘΙΚΛΜΝΞΟΠΡΣΤΥΦΧΨΩαβγδεζηθικλμνξοπρστυφχψω"
              + "⟂∥⊥→←↻·−°±×₀₁₂₃₄₅₆₇₈₉⁰¹²³ⁿᵏʳ✓—–…«»\u00a0′″√")


def _chars(text: str) -> str:
    return "".join(sorted((set(text) | set(BASE_CHARS)) - set("\n\r\t")))


@lru_cache(maxsize=64)
def _subset_woff(family: str, chars: str) -> bytes | None:
    path = fonts.find_font_file(family)
    if path is None:
        return None
    try:
        from fontTools import subset
        from fontTools.ttLib import TTFont
    except ImportError:  # pragma: no cover - fontTools comes with matplotlib
        return None
    try:
        font = TTFont(str(path), lazy=True)
        opts = subset.Options()
        opts.flavor = "woff"
        opts.name_IDs = [1, 2]  # family and style only: no licence text of kB
        opts.hinting = False
        opts.drop_tables += ["FFTM"]  # FontForge's timestamps
        opts.desubroutinize = True
        # no OpenType layout: the lettering needs no ligatures, and reading GSUB/GPOS
        # took most of the time of a subset
        opts.layout_features = []
        opts.drop_tables += ["GSUB", "GPOS", "GDEF", "kern", "MATH"]
        sub = subset.Subsetter(opts)
        sub.populate(text=chars)
        sub.subset(font)
        buf = io.BytesIO()
        font.flavor = "woff"
        font.recalcTimestamp = False  # keep the font's own date: the same page every run
        font.save(buf)
        font.close()
        return buf.getvalue()
    except Exception:  # a broken font file: leave the family out
        return None


def font_face_css(text: str, families: tuple[str, ...] = fonts.FONT_CHAIN) -> str:
    """``@font-face`` rules embedding ``families`` subset to the characters of ``text``."""
    chars = _chars(text)
    rules = []
    for fam in families:
        data = _subset_woff(fam, chars)
        if data is None:
            continue
        b64 = base64.b64encode(data).decode("ascii")
        rules.append(f"@font-face{{font-family:'{fam}';font-style:normal;font-weight:normal;"
                     f"src:url(data:font/woff;base64,{b64}) format('woff');}}")
    return "\n".join(rules)


__all__ = ["font_face_css"]
