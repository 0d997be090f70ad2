"""PDF of a sheet at its true size, vector, fonts embedded — from wheels alone.

The SVG of a sheet is ``width="841mm" height="594mm"`` (A1), so the one page of its
PDF is 841×594 mm = 2383.9×1683.8 pt (1 pt = 25.4/72 mm): printed at 100 % it is the
sheet at 1:1. Two engines write it:

* ``typst`` (the default; the ``typst`` wheel, Apache-2.0, no system library on Windows,
  macOS or Linux): a one-page Typst document whose page is the sheet's size and whose
  only content is the sheet's SVG, converted by Typst's SVG engine (usvg + svg2pdf):
  lines and fills stay vector paths, the lettering stays text in subsets of the
  bundled fonts (osifont, DejaVu; :func:`graphplan.fonts.find_font_file`), embedded.
  The system's fonts are never consulted, so the PDF is the same bytes everywhere.
* ``cairo`` (``pip install 'graphplan[cairo]'`` and the cairo C library): CairoSVG,
  the first engine; cairo finds fonts through fontconfig only, so it letters in
  osifont only where osifont is installed on the system.

Choose with ``engine=`` or ``$GRAPHPLAN_EXPORT_ENGINE`` (``cairo``). The document
info holds the title (designation and title of the sheet) and **no date**: the same
sheet gives the same bytes. See ``docs/exports.md`` for the measured comparison.
"""

from __future__ import annotations

import re
from html import unescape
from pathlib import Path

from .. import fonts
from ..drawing import Sheet
from ..errors import InputError
from ..files import write_atomic
from .extra import engine_for, require

CREATOR = "graphplan"

#: The Typst document: the page is the SVG's size, the SVG fills it, no margin, no date.
_TYPST_MAIN = b"""#set document(title: sys.inputs.title, author: (), date: none)
#set page(width: float(sys.inputs.width) * 1mm, height: float(sys.inputs.height) * 1mm,
          margin: 0pt)
#image(bytes(sys.inputs.svg), format: "svg", width: 100%, height: 100%)
"""


def _title(svg_text: str) -> str:
    m = re.search(r"<title>(.*?)</title>", svg_text, re.S)
    return unescape(m.group(1)).strip() if m else ""


def svg_size_mm(svg_text: str) -> tuple[float, float]:
    """``(width, height)`` in mm from the root ``width="…mm" height="…mm"`` of a sheet."""
    root = re.search(r"<svg\b[^>]*>", svg_text)
    sizes = []
    for key in ("width", "height"):
        m = re.search(rf'\s{key}="([0-9.]+)mm"', root.group(0)) if root else None
        if m is None:
            raise InputError(f"the SVG has no {key} in mm: not a graphplan sheet")
        sizes.append(float(m.group(1)))
    return sizes[0], sizes[1]


def font_folders(svg_text: str = "") -> list[str]:
    """Folders of the fonts Typst may use for ``svg_text``.

    The folders of the bundled fonts of :data:`graphplan.fonts.FONT_CHAIN`, then — only
    when the SVG has characters none of them draws — the folders of the system fonts
    that do (:func:`graphplan.fonts.fallback_font_files`). Typst takes folders, not files.
    """
    paths = [fonts.find_font_file(f) for f in fonts.FONT_CHAIN]
    folders = list(dict.fromkeys(str(p.parent) for p in paths if p is not None))
    if svg_text:
        extra = fonts.fallback_font_files(fonts.text_of_svg(svg_text))
        folders += [d for d in dict.fromkeys(str(p.parent) for p in extra) if d not in folders]
    return folders


def _typst_pdf(svg_text: str) -> bytes:
    typst = require("typst", "pdf")
    width, height = svg_size_mm(svg_text)
    inputs = {"svg": svg_text, "title": _title(svg_text), "width": repr(width),
              "height": repr(height)}
    return typst.compile(_TYPST_MAIN, sys_inputs=inputs, font_paths=font_folders(svg_text),
                         ignore_system_fonts=True, format="pdf")


def _cairo_pdf(svg_text: str) -> bytes:
    require("cairosvg", "pdf", extra="cairo")
    cairocffi = require("cairocffi", "pdf", extra="cairo")
    from cairosvg.surface import PDFSurface

    title = _title(svg_text)

    class _Surface(PDFSurface):
        # _create_surface is CairoSVG's hook for making the cairo surface: set the
        # document info before anything is drawn
        def _create_surface(self, width, height):
            surface, w, h = super()._create_surface(width, height)
            surface.set_metadata(cairocffi.PDF_METADATA_CREATE_DATE, "")  # no date
            surface.set_metadata(cairocffi.PDF_METADATA_CREATOR, CREATOR)
            if title:
                surface.set_metadata(cairocffi.PDF_METADATA_TITLE, title)
            return surface, w, h

    return _Surface.convert(bytestring=svg_text.encode("utf-8"))


def svg_to_pdf_bytes(svg_text: str, engine: str | None = None) -> bytes:
    """One-page PDF of an SVG sheet, at the size its root ``width``/``height`` give.

    ``engine``: ``"typst"`` (default) or ``"cairo"``; None reads
    ``$GRAPHPLAN_EXPORT_ENGINE``.

    Raises
    ------
    MissingExtraError
        If the engine's package (or the cairo library) is not installed.
    """
    if engine_for("pdf", engine) == "cairo":
        return _cairo_pdf(svg_text)
    return _typst_pdf(svg_text)


def pdf_bytes(sheet: Sheet, svg_text: str | None = None, *, engine: str | None = None) -> bytes:
    """PDF of ``sheet`` (``svg_text``: its SVG if already rendered)."""
    if svg_text is None:
        from ..render.svg import render_svg

        svg_text = render_svg(sheet)
    return svg_to_pdf_bytes(svg_text, engine)


def write_pdf(sheet: Sheet, path: str | Path, protect: tuple[Path, ...] = (), *,
              svg_text: str | None = None, engine: str | None = None) -> Path:
    """Write the PDF of ``sheet`` to ``path`` atomically; returns the path."""
    return write_atomic(path, pdf_bytes(sheet, svg_text, engine=engine), protect=protect)


__all__ = ["pdf_bytes", "svg_size_mm", "svg_to_pdf_bytes", "write_pdf"]
