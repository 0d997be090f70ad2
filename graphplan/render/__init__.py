"""Backends of the sheets (SVG, DXF, PDF, PNG, the browser); each imports its library lazily."""

from .browser import CANDIDATES, ENV_VAR, FLAGS, find_chromium, render_svg_png
from .dxf import (
    APPID,
    DEFAULT_TEXT_STYLE,
    GOST_LINETYPES,
    LAYER_DESCRIPTIONS,
    TEXT_STYLES,
    dxf_bytes,
    dxf_document,
    dxf_text,
    lineweight,
    write_dxf,
)
from .extra import (
    ENGINE_ENV,
    ENGINES,
    EXTRA,
    PACKAGES,
    MissingExtraError,
    engine_for,
    package_for,
    require,
    require_format,
)
from .formats import FORMATS, check_formats, parse_formats, sheet_files, write_exports
from .pdf import CREATOR, font_folders, pdf_bytes, svg_to_pdf_bytes, write_pdf
from .png import DEFAULT_DPI, check_dpi, png_bytes, png_size, write_png
from .raster import svg_to_png
from .workers import JOBS_ENV, PreviewPool, resolve

__all__ = [
    "APPID",
    "CANDIDATES",
    "CREATOR",
    "DEFAULT_DPI",
    "DEFAULT_TEXT_STYLE",
    "ENGINES",
    "ENGINE_ENV",
    "ENV_VAR",
    "EXTRA",
    "FLAGS",
    "FORMATS",
    "GOST_LINETYPES",
    "JOBS_ENV",
    "LAYER_DESCRIPTIONS",
    "PACKAGES",
    "TEXT_STYLES",
    "MissingExtraError",
    "PreviewPool",
    "check_dpi",
    "check_formats",
    "dxf_bytes",
    "dxf_document",
    "dxf_text",
    "engine_for",
    "find_chromium",
    "font_folders",
    "lineweight",
    "package_for",
    "parse_formats",
    "pdf_bytes",
    "png_bytes",
    "png_size",
    "render_svg_png",
    "require",
    "require_format",
    "resolve",
    "sheet_files",
    "svg_to_pdf_bytes",
    "svg_to_png",
    "write_dxf",
    "write_exports",
    "write_pdf",
    "write_png",
]
