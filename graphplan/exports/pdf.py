"""PDF of a sheet at its true size, vector, fonts embedded: CairoSVG from the sheet's SVG.

The SVG of a sheet is ``width="841mm" height="594mm"`` (A1), so the one page of its
PDF is 841×594 mm = 2383.9×1683.8 pt (1 pt = 25.4/72 mm): printed at 100 % it is the
sheet at 1:1. cairo writes lines and fills as vector paths and the lettering as text in
subsets of the sheet's fonts (osifont, DejaVu), embedded in the file; the kinematic
diagrams (nested matplotlib SVG) stay vector too.

The document info holds the title (designation and title of the sheet) and
"graphplan" as creator, and **no creation date**: the same sheet gives the same bytes.
"""

from __future__ import annotations

import re
from html import unescape
from pathlib import Path

from ..files import write_atomic
from ..sheet import Sheet
from .extra import require

CREATOR = "graphplan"


def _title(svg_text: str) -> str:
    m = re.search(r"<title>(.*?)</title>", svg_text, re.S)
    return unescape(m.group(1)).strip() if m else ""


def svg_to_pdf_bytes(svg_text: str) -> bytes:
    """One-page PDF of an SVG sheet, at the size its root ``width``/``height`` give.

    Raises
    ------
    MissingExtraError
        If cairosvg (or the cairo library) is not installed.
    """
    require("cairosvg", "pdf")
    require("cairocffi", "pdf")
    import cairocffi
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


def pdf_bytes(sheet: Sheet, svg_text: str | None = None) -> bytes:
    """PDF of ``sheet`` (``svg_text``: its SVG if already rendered)."""
    if svg_text is None:
        from ..render.svg import render_svg

        svg_text = render_svg(sheet)
    return svg_to_pdf_bytes(svg_text)


def write_pdf(sheet: Sheet, path: str | Path, protect: tuple[Path, ...] = (), *,
              svg_text: str | None = None) -> Path:
    """Write the PDF of ``sheet`` to ``path`` atomically; returns the path."""
    return write_atomic(path, pdf_bytes(sheet, svg_text), protect=protect)


__all__ = ["pdf_bytes", "svg_to_pdf_bytes", "write_pdf"]
