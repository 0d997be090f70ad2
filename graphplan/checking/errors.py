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


class UnreadableError(ExpressionError):
    """Arithmetic that is written well but has no value a calculation can have: a literal
    or a result that is not a finite real number (``1e400``, ``2^1024``), a division by
    zero (``1/0``), a function outside its domain (``ln 0``, ``sqrt(-1)``), or work
    beyond the reader's bounds.

    The checker reports such a line as a finding of its own (kind ``unreadable``): it is
    never taken for a formula, and never "nothing is wrong".
    """
