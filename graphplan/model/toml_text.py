"""The one TOML reader of graphplan's input files: a variant, a student's work, a class file.

:func:`parse_toml` turns a file's text into its tables, or raises a one-line error naming
the file, tomllib's reason and, where it sees one, the likely cause (a decimal comma:
:func:`~graphplan.model.mistakes.toml_hint`).
"""

from __future__ import annotations

import re
import tomllib
from typing import Any

from ..errors import GraphplanError, InputError
from .mistakes import toml_hint

_CONTROL = re.compile(r"[\x00-\x1f\x7f\u2028\u2029\x85]")


def one_line(text: str) -> str:
    """Escape control characters (a quoted TOML key may hold a newline) to keep one line."""
    return _CONTROL.sub(lambda m: repr(m.group())[1:-1], text)


def parse_toml(text: str, source: str, error: type[GraphplanError] = InputError
               ) -> dict[str, Any]:
    """The tables of a TOML text.

    Raises
    ------
    error
        ``"<source>: not valid TOML (<reason>)<hint>"`` on one line when the text is not TOML
        (a syntax error, an integer of thousands of digits, tables nested too deeply).
    """
    try:
        return tomllib.loads(text)
    except (tomllib.TOMLDecodeError, ValueError) as exc:  # ValueError: a 5000-digit integer
        reason = " ".join(str(exc).split())
        raise error(one_line(f"{source}: not valid TOML ({reason})"
                             + toml_hint(text, str(exc)))) from None
    except RecursionError:
        raise error(f"{source}: not valid TOML (nested too deeply)") from None


__all__ = ["one_line", "parse_toml"]
