"""The optional packages of the exports, imported when a format is asked for.

The ``export`` extra holds wheels only — ezdxf (DXF), typst (PDF) and resvg-py (PNG) —
so ``pip install 'graphplan[export]'`` works on Windows, macOS and Linux with no
system library. The ``cairo`` extra adds CairoSVG, the first PDF/PNG engine, which
needs the cairo C library. A missing package is a :class:`MissingExtraError` whose
one-line message names the extra to install.

The engine of PDF and PNG is ``typst``/``resvg`` unless ``engine="cairo"`` is asked
for or ``$GRAPHPLAN_EXPORT_ENGINE`` is ``cairo``.
"""

from __future__ import annotations

import importlib
import os
from types import ModuleType

from ..errors import GraphplanError, InputError

EXTRA = "graphplan[export]"  #: what to install for the exports
ENGINE_ENV = "GRAPHPLAN_EXPORT_ENGINE"  #: environment variable choosing the engine
#: Format → engines (the first is the default).
ENGINES: dict[str, tuple[str, ...]] = {"pdf": ("typst", "cairo"), "png": ("resvg", "cairo")}
#: (format, engine) → the package that writes it, and its extra.
_PACKAGES: dict[tuple[str, str], tuple[str, str]] = {
    ("dxf", ""): ("ezdxf", "export"),
    ("pdf", "typst"): ("typst", "export"),
    ("png", "resvg"): ("resvg_py", "export"),
    ("pdf", "cairo"): ("cairosvg", "cairo"),
    ("png", "cairo"): ("cairosvg", "cairo"),
}


class MissingExtraError(GraphplanError, ImportError):
    """An export needs an optional package (or the C library under it) that is missing."""


def engine_for(fmt: str, engine: str | None = None) -> str:
    """The engine that writes ``fmt`` ("" for DXF): ``engine``, else the environment's.

    Raises
    ------
    InputError
        On an engine that does not write ``fmt``.
    """
    if fmt not in ENGINES:
        return ""
    name = (engine if engine is not None else os.environ.get(ENGINE_ENV, "")).strip().lower()
    if name in ("", "default", "wheels"):
        return ENGINES[fmt][0]
    if name == "cairo" or name in ENGINES[fmt]:
        return name
    known = ", ".join(sorted({e for es in ENGINES.values() for e in es}))
    raise InputError(f"export engine: expected one of {known} (got {name!r})")


def package_for(fmt: str, engine: str | None = None) -> str:
    """The Python package that writes ``fmt`` with ``engine``."""
    return _PACKAGES[(fmt, engine_for(fmt, engine))][0]


def require(package: str, fmt: str, *, extra: str | None = None) -> ModuleType:
    """Import ``package`` for the ``fmt`` export, or raise MissingExtraError.

    cairosvg also needs the cairo C library: when that is missing, its import fails
    with OSError, which is reported the same way.
    """
    wanted = f"graphplan[{extra}]" if extra else EXTRA
    try:
        return importlib.import_module(package)
    except ImportError:
        raise MissingExtraError(
            f"{fmt.upper()} export needs the Python package '{package}': "
            f"pip install '{wanted}'"
        ) from None
    except OSError as exc:  # cairocffi: "no library called cairo was found"
        reason = " ".join(str(exc).split())[:200]
        raise MissingExtraError(
            f"{fmt.upper()} export with the cairo engine needs the cairo library under "
            f"'{package}' ({reason}); the default engine needs none: unset {ENGINE_ENV} "
            f"and pip install '{EXTRA}'"
        ) from None


def require_format(fmt: str, engine: str | None = None) -> ModuleType:
    """Import the package writing ``fmt`` with ``engine`` (MissingExtraError if missing)."""
    package, extra = _PACKAGES[(fmt, engine_for(fmt, engine))]
    return require(package, fmt, extra=extra)


#: Format → the package that writes it with the default engine.
PACKAGES: dict[str, str] = {"dxf": "ezdxf", "pdf": "typst", "png": "resvg_py"}

__all__ = ["ENGINES", "ENGINE_ENV", "EXTRA", "PACKAGES", "MissingExtraError", "engine_for",
           "package_for", "require", "require_format"]
