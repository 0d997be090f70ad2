"""PNG previews of SVG sheets through CairoSVG (imported only when called).

CairoSVG letters each text in the first family of its font-family list and does no
glyph fallback; :mod:`graphplan.fonts` puts a family that draws the whole text first.
"""

from __future__ import annotations

from pathlib import Path

from ..errors import GraphplanError
from ..files import write_atomic


def svg_to_png_bytes(svg_text: str, dpi: float = 50) -> bytes:
    """PNG bytes of an SVG whose size is given in mm, at ``dpi`` dots per inch."""
    try:
        import cairosvg
    except ImportError as exc:  # also raised when the cairo C library is missing
        raise GraphplanError(
            f"PNG output needs the Python package 'cairosvg' (and the cairo library): {exc}"
        ) from None
    if not dpi > 0:
        raise GraphplanError(f"dpi must be > 0 (got {dpi!r})")
    return cairosvg.svg2png(bytestring=svg_text.encode("utf-8"), dpi=float(dpi),
                            background_color="white")


def svg_to_png(svg_text: str, path: str | Path, dpi: float = 50,
               protect: tuple[Path, ...] = ()) -> Path:
    """Render ``svg_text`` to a PNG file at ``path`` (atomically); returns the path.

    At the default 50 dpi an A1 sheet is 1656×1169 pixels.
    """
    return write_atomic(path, svg_to_png_bytes(svg_text, dpi), protect=protect)
