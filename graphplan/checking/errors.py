"""Errors of the checker: one-line messages naming the file, the key and what was expected.

Both subclass :class:`graphplan.errors.InputError` (so also ``ValueError``): the command
line turns them into one line on standard error and exit status 2.
"""

from __future__ import annotations

from ..errors import InputError


class StudentFileError(InputError):
    """A student file is malformed: not TOML, a missing or unknown key, a wrong value."""


class ExpressionError(InputError):
    """A written calculation cannot be read as arithmetic.

    ``column`` is the 1-based position in the text where reading stopped (0 if unknown).
    """

    def __init__(self, message: str, column: int = 0):
        super().__init__(message)
        self.column = column
