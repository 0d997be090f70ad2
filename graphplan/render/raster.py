"""PNG previews of SVG sheets (the engine of :mod:`graphplan.render.png`).

resvg (a wheel, no system library) letters each text in the first family of its
font-family list from the bundled fonts; :mod:`graphplan.fonts` puts a family that
draws the whole text first.
"""

from __future__ import annotations

from pathlib import Path

from ..files import write_atomic


def svg_to_png_bytes(svg_text: str, dpi: float = 50) -> bytes:
    """PNG bytes of an SVG whose size is given in mm, at ``dpi`` dots per inch."""
    from .png import svg_to_png_bytes as to_png

    return to_png(svg_text, dpi)


def svg_to_png(svg_text: str, path: str | Path, dpi: float = 50,
               protect: tuple[Path, ...] = ()) -> Path:
    """Render ``svg_text`` to a PNG file at ``path`` (atomically); returns the path.

    At the default 50 dpi an A1 sheet is 1656×1169 pixels.
    """
    return write_atomic(path, svg_to_png_bytes(svg_text, dpi), protect=protect)
