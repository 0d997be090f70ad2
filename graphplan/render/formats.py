"""Exports of the sheets for CAD programs and for print: DXF, PDF and PNG beside the SVG.

* ``svg`` — :func:`graphplan.render.svg.render_svg` (always available);
* ``dxf`` — model space in mm at 1:1, one layer per kind of content, GOST line types
  and weights, TEXT in a style naming the GOST-like font, vectors only
  (:mod:`graphplan.render.dxf`, needs ezdxf);
* ``pdf`` — one page at the true sheet size (A1 841×594 mm), vector, fonts embedded
  (:mod:`graphplan.render.pdf`, needs typst);
* ``png`` — a preview at a chosen dpi (:mod:`graphplan.render.png`, needs resvg-py).

ezdxf, typst and resvg-py are the ``export`` extra (``pip install graphplan[export]``),
wheels for Windows, macOS and Linux that need no system library; CairoSVG, the other
PDF/PNG engine, is the ``cairo`` extra (:mod:`graphplan.render.extra`). They
are imported only when their format is asked for, and a missing one raises
:class:`MissingExtraError` with a one-line message naming the extra. Call
:func:`check_formats` before the work starts to fail early.

Files are named after the sheet: ``sheet1.svg``, ``sheet1.dxf``, ``sheet1.pdf``,
``sheet1.png``. Every output is deterministic (no timestamps) and written atomically.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from pathlib import Path

from ..drawing import Sheet
from ..errors import InputError
from ..files import write_atomic
from .extra import EXTRA, PACKAGES, MissingExtraError, require_format
from .png import DEFAULT_DPI, check_dpi
from .workers import PreviewPool, resolve

#: Export formats, in the order their files are listed.
FORMATS: tuple[str, ...] = ("svg", "dxf", "pdf", "png")


def parse_formats(spec: str | Iterable[str]) -> tuple[str, ...]:
    """Formats from ``"svg,dxf,pdf,png"`` (or a list of names), in :data:`FORMATS` order.

    Case and spaces are ignored, repeats dropped; ``"all"`` means every format.

    Raises
    ------
    InputError
        On an unknown format or an empty list (one line naming the known formats).
    """
    items = spec.split(",") if isinstance(spec, str) else list(spec)
    names = {str(s).strip().lower() for s in items} - {""}
    if "all" in names:
        names = (names - {"all"}) | set(FORMATS)
    unknown = sorted(names - set(FORMATS))
    if unknown or not names:
        got = ", ".join(unknown) if unknown else "nothing"
        raise InputError(f"--format: expected some of {', '.join(FORMATS)} separated by "
                         f"commas (got {got})")
    return tuple(f for f in FORMATS if f in names)


def check_formats(formats: Iterable[str], engine: str | None = None) -> None:
    """Import the packages the ``formats`` need; MissingExtraError if one is missing."""
    for fmt in formats:
        if fmt in PACKAGES:
            require_format(fmt, engine)


def sheet_files(sheets: Mapping[str, Sheet], formats: Iterable[str] = ("svg",), *,
                dpi: float = DEFAULT_DPI, engine: str | None = None,
                pool: PreviewPool | None = None) -> dict[str, str | bytes]:
    """File name → content of every sheet in every format (nothing is written here).

    Parameters
    ----------
    sheets : mapping of str to Sheet
        Base name (e.g. ``"sheet1"``) → sheet, in the order the files should be listed.
    formats : iterable of str
        Some of :data:`FORMATS` (e.g. from :func:`parse_formats`).
    dpi : float
        Resolution of the PNG previews.
    engine : str, optional
        Engine of the PDF and PNG: None (``$GRAPHPLAN_EXPORT_ENGINE``, else typst and
        resvg) or ``"cairo"``.
    pool : PreviewPool, optional
        Worker processes for the PNG previews and the DXF files
        (:mod:`graphplan.render.workers`), shared with the caller: those are then left
        *pending* in the result, for the caller to
        :func:`~graphplan.render.workers.resolve` when its other work is done. Without
        one, the previews of several sheets are drawn in workers of their own (where
        there are workers) and the result holds only values.

    Returns
    -------
    dict
        ``"sheet1.svg"`` → SVG text, ``"sheet1.dxf"`` → bytes, ``"sheet1.pdf"`` →
        bytes, ``"sheet1.png"`` → bytes; sheet by sheet, formats in :data:`FORMATS`
        order. SVG is rendered once per sheet and shared by the PDF and the PNG.

    Raises
    ------
    InputError
        Unknown format or bad ``dpi``.
    MissingExtraError
        A package of the ``export`` extra is missing (checked before any work).
    """
    fmts = parse_formats(formats if isinstance(formats, str) else list(formats))
    if "png" in fmts:
        dpi = check_dpi(dpi)
    check_formats(fmts, engine)
    if pool is None:
        with PreviewPool(len(sheets) * len({"png", "dxf"} & set(fmts))) as own:
            return resolve(sheet_files(sheets, fmts, dpi=dpi, engine=engine, pool=own))
    from ..render.svg import render_svg
    from .dxf import dxf_bytes
    from .pdf import svg_to_pdf_bytes
    from .png import png_bytes, png_size_check, svg_to_png_bytes

    out: dict[str, str | bytes] = {}
    for name, sheet in sheets.items():
        svg = render_svg(sheet) if {"svg", "pdf", "png"} & set(fmts) else None
        png = dxf = None
        if "png" in fmts:  # handed to a worker first: it draws while the rest is made
            if pool.workers:
                png_size_check(sheet, dpi)
                png = pool.submit(svg_to_png_bytes, svg, dpi, engine)
            else:
                png = png_bytes(sheet, dpi, svg_text=svg, engine=engine)
        if "dxf" in fmts and pool.workers:  # so is the DXF (ezdxf's Python, ~0.3 s a sheet)
            dxf = pool.submit(dxf_bytes, sheet)
        for fmt in fmts:
            if fmt == "svg":
                out[f"{name}.svg"] = svg  # type: ignore[assignment]
            elif fmt == "dxf":
                out[f"{name}.dxf"] = dxf if dxf is not None else dxf_bytes(sheet)
            elif fmt == "pdf":
                out[f"{name}.pdf"] = svg_to_pdf_bytes(svg, engine)  # type: ignore[arg-type]
            else:
                out[f"{name}.png"] = png  # type: ignore[assignment]
    return out


def write_exports(sheets: Mapping[str, Sheet], out_dir: str | Path,
                  formats: Iterable[str] = ("svg",), *, dpi: float = DEFAULT_DPI,
                  protect: tuple[Path, ...] = (), engine: str | None = None
                  ) -> tuple[Path, ...]:
    """Write every sheet in every format into ``out_dir`` (atomically); the paths written.

    ``protect`` lists input files that must never be overwritten (the variant).
    """
    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise InputError(f"{out}: the output must be a directory")
    files = sheet_files(sheets, formats, dpi=dpi, engine=engine)
    return tuple(write_atomic(out / name, data, protect=protect) for name, data in files.items())


__all__ = ["DEFAULT_DPI", "EXTRA", "FORMATS", "MissingExtraError", "check_formats",
           "parse_formats", "sheet_files", "write_exports"]
