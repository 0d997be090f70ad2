"""PNG preview of a sheet at a chosen resolution, from the sheet's SVG — wheels alone.

The picture is the whole sheet on white, ``round(W·dpi/25.4)`` × ``round(H·dpi/25.4)``
pixels for a W×H mm sheet: A1 at the default 100 dpi is 3311×2339 px (about 4 px per
mm, thin 0.25 mm lines one pixel wide), at 50 dpi 1656×1169.

Two engines draw it: ``resvg`` (the default; the resvg-py wheel, MIT, no system
library), given the bundled font files only — never the system's — so the preview is
the same pixels on every machine; and ``cairo`` (CairoSVG, the ``cairo`` extra and the
cairo C library), whose fonts come from fontconfig. Both letter each text in the first
family of its font list, which :mod:`graphplan.fonts` makes a family that draws the
whole text. Choose with ``engine=`` or ``$GRAPHPLAN_EXPORT_ENGINE``.
"""

from __future__ import annotations

import math
from pathlib import Path

from .. import fonts
from ..drawing import Sheet
from ..errors import InputError
from ..files import write_atomic
from .extra import engine_for, require

DEFAULT_DPI = 100.0  #: resolution of the previews, dots per inch
MAX_SIDE_PX = 20000  #: no side longer than this (A1 at 600 dpi is 19866 px wide)


def check_dpi(dpi: object) -> float:
    """``dpi`` as a float; InputError unless it is a finite number > 0."""
    try:
        value = float(dpi)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise InputError(f"PNG dpi must be a number (got {dpi!r})") from None
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"PNG dpi must be > 0 (got {dpi!r})")
    return value


def svg_to_png_bytes(svg_text: str, dpi: float = DEFAULT_DPI, engine: str | None = None
                     ) -> bytes:
    """PNG bytes of an SVG sheet whose size is given in mm, at ``dpi`` dots per inch.

    ``engine``: ``"resvg"`` (default) or ``"cairo"``; None reads
    ``$GRAPHPLAN_EXPORT_ENGINE``.

    Raises
    ------
    InputError
        If ``dpi`` is not a positive number.
    MissingExtraError
        If the engine's package (or the cairo library) is not installed.
    """
    dpi = check_dpi(dpi)
    if engine_for("png", engine) == "cairo":
        cairosvg = require("cairosvg", "png", extra="cairo")
        return cairosvg.svg2png(bytestring=svg_text.encode("utf-8"), dpi=dpi,
                                background_color="white")
    resvg = require("resvg_py", "png")
    files = [str(p) for p in (fonts.find_font_file(f) for f in fonts.FONT_CHAIN) if p]
    # a character no bundled font draws (a name in Chinese …): a system font draws it
    files += [str(p) for p in fonts.fallback_font_files(fonts.text_of_svg(svg_text))]
    try:
        return bytes(resvg.svg_to_bytes(
            svg_string=svg_text, dpi=dpi, background="white", skip_system_fonts=True,
            font_files=files, font_family=fonts.FONT_CHAIN[0],
            sans_serif_family=fonts.FONT_CHAIN[1], monospace_family=fonts.FONT_CHAIN[2]))
    except ValueError as exc:  # resvg: an SVG it cannot read
        raise InputError(f"PNG: the SVG cannot be drawn ({' '.join(str(exc).split())[:200]})"
                         ) from None


def png_size(sheet: Sheet, dpi: float = DEFAULT_DPI) -> tuple[int, int]:
    """Pixel size of the preview of ``sheet`` at ``dpi`` (width, height)."""
    return (round(sheet.page.width * dpi / 25.4), round(sheet.page.height * dpi / 25.4))


def png_size_check(sheet: Sheet, dpi: float) -> float:
    """``dpi`` checked (:func:`check_dpi`) and the preview's size with it.

    Raises
    ------
    InputError
        If ``dpi`` is not positive or a side would exceed :data:`MAX_SIDE_PX`.
    """
    dpi = check_dpi(dpi)
    w, h = png_size(sheet, dpi)
    if max(w, h) > MAX_SIDE_PX:
        raise InputError(f"PNG dpi {dpi:g} gives {w}×{h} px; at most {MAX_SIDE_PX} px a side")
    return dpi


def png_bytes(sheet: Sheet, dpi: float = DEFAULT_DPI, svg_text: str | None = None, *,
              engine: str | None = None) -> bytes:
    """PNG preview of ``sheet`` (``svg_text``: its SVG if already rendered).

    Raises
    ------
    InputError
        If ``dpi`` is not positive or a side would exceed :data:`MAX_SIDE_PX`.
    """
    dpi = png_size_check(sheet, dpi)
    if svg_text is None:
        from ..render.svg import render_svg

        svg_text = render_svg(sheet)
    return svg_to_png_bytes(svg_text, dpi, engine)


def write_png(sheet: Sheet, path: str | Path, dpi: float = DEFAULT_DPI,
              protect: tuple[Path, ...] = (), *, svg_text: str | None = None,
              engine: str | None = None) -> Path:
    """Write the PNG preview of ``sheet`` to ``path`` atomically; returns the path."""
    return write_atomic(path, png_bytes(sheet, dpi, svg_text, engine=engine), protect=protect)


__all__ = ["DEFAULT_DPI", "MAX_SIDE_PX", "check_dpi", "png_bytes", "png_size", "png_size_check",
           "svg_to_png_bytes", "write_png"]
