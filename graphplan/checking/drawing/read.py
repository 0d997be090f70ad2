"""One entry point for every drawing format: :func:`read_drawing`."""

from __future__ import annotations

from pathlib import Path

from .primitives import Drawing, DrawingError

FORMATS = (".dxf", ".svg", ".pdf")


def read_drawing(path: str | Path) -> Drawing:
    """Read a DXF, SVG or PDF drawing (by its suffix, else by its first bytes).

    Raises
    ------
    DrawingError
        One line naming the file: not found, not a drawing, damaged, or past a bound.
    """
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in FORMATS:
        try:
            with path.open("rb") as fh:
                head = fh.read(512)
        except FileNotFoundError:
            raise DrawingError(f"{path}: file not found") from None
        except OSError as exc:
            raise DrawingError(f"{path}: cannot read ({exc.strerror})") from None
        if head.startswith(b"%PDF"):
            suffix = ".pdf"
        elif b"<svg" in head or head.lstrip().startswith(b"<?xml"):
            suffix = ".svg"
        elif b"SECTION" in head:
            suffix = ".dxf"
        else:
            raise DrawingError(f"{path}: not a drawing (expected a .dxf, .svg or .pdf file)")
    if suffix == ".dxf":
        from .dxf import read_dxf

        return read_dxf(path)
    if suffix == ".svg":
        from .svg import read_svg

        return read_svg(path)
    from .pdf import read_pdf

    return read_pdf(path)


__all__ = ["FORMATS", "read_drawing"]
