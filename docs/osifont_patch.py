"""How graphplan's bundled osifont was made from Debian's fonts-osifont 0.1.20220224.

The upstream build has no → (U+2192) and no − (U+2212): every equation of sheet 2
(``ΣMB(2): Rτ12·AB − … = 0 → Rτ12 = …``) fell back to DejaVu Sans, another typeface in the
middle of the type-B lettering. This script adds the two as composites of osifont's own
glyphs — the minus is the en dash's outline (the same width and bar), the arrow three en
dashes into the '>' whose tip ends the bar (as long as osifont's ↔) — and redraws the
blank placeholders of Ё ё Э э (one filled quadrilateral each: «Силовой расчёт» fell back
to DejaVu too) as Е е with two full stops and С с mirrored with a bar, and adds the
subscript digits ₀ … ₉ (II₂(2,3)) as its superscripts moved down; it changes nothing
else. The licence (GPL-3 with the font exception, ``osifont.COPYRIGHT``) allows the
modification; the exception is kept.

Run from the repository's root on the upstream file (it refuses a file already patched)::

    python docs/osifont_patch.py UPSTREAM/osifont.ttf \\
        graphplan/data/fonts/osifont.ttf
"""

from __future__ import annotations

import sys

from fontTools.ttLib import TTFont
from fontTools.ttLib.tables._g_l_y_f import Glyph, GlyphComponent

ROUND_XY_TO_GRID = 0x4


def _composite(parts) -> Glyph:
    """A composite of ``(glyph, dx[, dy[, sx]])`` parts: each glyph moved by (dx, dy) font
    units after scaling x by ``sx`` (−1 mirrors it)."""
    g = Glyph()
    g.numberOfContours = -1
    g.components = []
    for name, dx, *rest in parts:
        dy, sx = (list(rest) + [0, 1.0][len(rest):])[:2]
        c = GlyphComponent()
        c.glyphName, c.x, c.y, c.flags = name, dx, dy, ROUND_XY_TO_GRID
        if sx != 1.0:
            c.transform = [[sx, 0.0], [0.0, 1.0]]
        g.components.append(c)
    return g


def patch(src: str, dst: str) -> None:
    f = TTFont(src)
    glyf, hmtx = f["glyf"], f["hmtx"]
    order = list(f.getGlyphOrder())
    if "arrowright" in order or "minus" in order:
        raise SystemExit(f"{src}: already has 'arrowright' or 'minus'")
    new = {
        "arrowright": (_composite([("endash", 0), ("endash", 400), ("endash", 800),
                                   ("greater", 898)]), 1850),
        "minus": (_composite([("endash", 0)]), hmtx["endash"][0]),
    }
    for name, (glyph, advance) in new.items():
        order.append(name)
        glyf.glyphs[name] = glyph
        hmtx[name] = (advance, hmtx["endash"][1])
    f.setGlyphOrder(order)
    glyf.glyphOrder = order
    # the blank placeholders of Ё ё Э э (one filled quadrilateral each) redrawn: Е е with two
    # full stops over them, С с mirrored with a shortened hyphen for the bar
    cmap = f.getBestCmap()
    redrawn = {
        0x0401: [("uni0415", 0), ("period", 173, 1650), ("period", 493, 1650)],   # Ё
        0x0451: [("uni0435", 0), ("period", 93, 1250), ("period", 408, 1250)],    # ё
        0x042D: [("uni0421", 938, 0, -1.0), ("hyphen", 270, 158, 0.6)],           # Э
        0x044D: [("uni0441", 697, 0, -1.0), ("hyphen", 200, -69, 0.5)],           # э
    }
    for cp, parts in redrawn.items():
        glyf.glyphs[cmap[cp]] = _composite(parts)
        new[cmap[cp]] = (glyf.glyphs[cmap[cp]], hmtx[cmap[cp]][0])
    # the subscript digits ₀ … ₉ (II₂(2,3), ω₁): the font's own superscripts ⁰ ¹ ² … ⁹
    # moved down by 1050 units (their baseline 250 under the line's)
    supers = [0x2070, 0xB9, 0xB2, 0xB3, 0x2074, 0x2075, 0x2076, 0x2077, 0x2078, 0x2079]
    for d, sup in enumerate(supers):
        name = f"uni{0x2080 + d:04X}"
        order.append(name)
        glyf.glyphs[name] = _composite([(cmap[sup], 0, -1050)])
        hmtx[name] = hmtx[cmap[sup]]
        new[name] = (glyf.glyphs[name], hmtx[name][0])
    f.setGlyphOrder(order)
    glyf.glyphOrder = order
    for name in new:
        glyf[name].recalcBounds(glyf)
    for table in f["cmap"].tables:
        if table.isUnicode():
            table.cmap[0x2192] = "arrowright"
            table.cmap[0x2212] = "minus"
            for d in range(10):
                table.cmap[0x2080 + d] = f"uni{0x2080 + d:04X}"
    f["maxp"].numGlyphs = len(order)
    f.save(dst)


if __name__ == "__main__":
    patch(sys.argv[1], sys.argv[2])
