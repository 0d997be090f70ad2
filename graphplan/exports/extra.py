"""The optional packages of the exports, imported when a format is asked for.

ezdxf (DXF) and cairosvg (PDF, PNG) come with the ``export`` extra; a missing one is a
:class:`MissingExtraError` whose one-line message names the extra to install.
"""

from __future__ import annotations

import importlib
from types import ModuleType

from ..errors import GraphplanError

EXTRA = "graphplan[export]"  #: what to install for the exports

#: Format → the package that writes it.
PACKAGES: dict[str, str] = {"dxf": "ezdxf", "pdf": "cairosvg", "png": "cairosvg"}


class MissingExtraError(GraphplanError, ImportError):
    """An export needs an optional package (or the C library under it) that is missing."""


def require(package: str, fmt: str) -> ModuleType:
    """Import ``package`` for the ``fmt`` export, or raise MissingExtraError.

    cairosvg also needs the cairo C library: when that is missing, its import fails
    with OSError, which is reported the same way.
    """
    try:
        return importlib.import_module(package)
    except ImportError:
        raise MissingExtraError(
            f"{fmt.upper()} export needs the Python package '{package}': "
            f"pip install '{EXTRA}'"
        ) from None
    except OSError as exc:  # cairocffi: "no library called cairo was found"
        reason = " ".join(str(exc).split())[:200]
        raise MissingExtraError(
            f"{fmt.upper()} export needs the cairo library under '{package}' ({reason}): "
            f"install cairo (Debian: apt install libcairo2) and pip install '{EXTRA}'"
        ) from None


__all__ = ["EXTRA", "PACKAGES", "MissingExtraError", "require"]
