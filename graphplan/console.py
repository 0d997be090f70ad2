"""Text in any console: what graphplan prints never stops on an encoding, and exit codes.

A Windows console with a Russian code page (cp1251, cp866) or an ASCII-only terminal
cannot encode every character graphplan prints (ω, φ, ε, −, ₁, ², ·, Cyrillic on an
ASCII terminal). :func:`prepare_streams` sets the standard streams up once, before a
command runs:

* **output redirected to a file or a pipe** (``graphplan analyze > out.txt``): UTF-8,
  so the file keeps every character — unless ``PYTHONIOENCODING`` names an encoding,
  which is then kept;
* **a console**, and any kept encoding: its own encoding, and a character it cannot
  encode is written in a spelling it can (:func:`console_spelling`: ω → w, φ → phi,
  − → -, ₁ → 1, ² → ^2, Cyrillic → Latin on an ASCII console, anything else → ?), never
  a ``UnicodeEncodeError``. JSON written there escapes such characters instead
  (``\\u03c9``, :func:`json_ascii`): the data stay exact.

Standard error gets the same replacement (its encoding is left as it is).

Exit status of every command (:data:`EXIT_CODES`)::

    0  done, nothing wrong
    1  `graphplan check`: faults found in the student's work
    2  bad input: a variant or student file, an option, a usage error (one line on stderr)
    3  a file could not be read or written (permissions, a full disk; one line on stderr)
    4  an internal error of graphplan — a bug (one line; --debug shows the traceback)
    130 interrupted (Ctrl+C)
    143 terminated (SIGTERM)
"""

from __future__ import annotations

import codecs
import os
import sys
import unicodedata

EXIT_OK = 0
EXIT_FAULTS = 1
EXIT_BAD_INPUT = 2
EXIT_FILE_ERROR = 3
EXIT_INTERNAL = 4
EXIT_INTERRUPTED = 130
EXIT_TERMINATED = 143

#: Exit status → meaning (docs/cli.md and the README list the same).
EXIT_CODES: dict[int, str] = {
    EXIT_OK: "done, nothing wrong",
    EXIT_FAULTS: "graphplan check: faults found in the student's work",
    EXIT_BAD_INPUT: "bad input: a variant or student file, an option, a usage error",
    EXIT_FILE_ERROR: "a file could not be read or written",
    EXIT_INTERNAL: "an internal error of graphplan (a bug)",
    EXIT_INTERRUPTED: "interrupted (Ctrl+C)",
    EXIT_TERMINATED: "terminated (SIGTERM); a class run writes its summary first",
}

ERROR_HANDLER = "graphplan-console"  #: codecs error handler registered by this module

#: Spellings of the method's symbols for consoles that cannot encode them.
SYMBOLS: dict[str, str] = {
    "ω": "w", "Ω": "W", "ε": "eps", "φ": "phi", "Φ": "Phi", "ψ": "psi", "Ψ": "Psi",
    "π": "pi", "μ": "mu", "δ": "delta", "Δ": "Delta", "Σ": "Sum", "τ": "tau", "η": "eta",
    "α": "alpha", "β": "beta", "γ": "gamma", "λ": "lambda", "ρ": "rho", "θ": "theta",
    "−": "-", "–": "-", "—": "--", "·": "*", "×": "x", "±": "+-", "°": " deg", "′": "'",
    "″": "''", "≈": "~", "≤": "<=", "≥": ">=", "≠": "!=", "∥": "||", "⟂": "_|_",
    "⊥": "_|_", "√": "sqrt", "→": "->", "←": "<-", "↻": "(cw)", "…": "...", "«": '"',
    "»": '"', "\u00a0": " ", "\u2009": " ", "\u202f": " ", "✓": "v", "✗": "x",
    "²": "^2", "³": "^3", "¹": "^1", "⁰": "^0", "ⁿ": "^n", "₀": "0", "₁": "1", "₂": "2",
    "₃": "3", "₄": "4", "₅": "5", "₆": "6", "₇": "7", "₈": "8", "₉": "9", "№": "No",
}

#: Russian letters in Latin (GOST 7.79-2000 system B, simplified), for ASCII consoles.
_CYRILLIC = dict(zip(
    "абвгдеёжзийклмнопрстуфхцчшщъыьэюя",
    ["a", "b", "v", "g", "d", "e", "yo", "zh", "z", "i", "j", "k", "l", "m", "n", "o", "p",
     "r", "s", "t", "u", "f", "x", "c", "ch", "sh", "shh", "''", "y'", "'", "e'", "yu", "ya"],
    strict=True))


def console_spelling(ch: str) -> str:
    """How ``ch`` is written where it cannot be encoded (ASCII; ``?`` if unknown)."""
    if ch in SYMBOLS:
        return SYMBOLS[ch]
    low = ch.lower()
    if low in _CYRILLIC:
        latin = _CYRILLIC[low]
        return latin[:1].upper() + latin[1:] if ch != low else latin
    base = unicodedata.normalize("NFKD", ch).encode("ascii", "ignore").decode("ascii")
    return base or "?"


def _handler(err: UnicodeError) -> tuple[str, int]:
    if not isinstance(err, UnicodeEncodeError):
        raise err
    text = "".join(console_spelling(ch) for ch in err.object[err.start:err.end])
    # a spelling the encoding cannot take either (never for ASCII spellings): '?'
    return text, err.end


codecs.register_error(ERROR_HANDLER, _handler)


def _is_utf(encoding: str | None) -> bool:
    return encoding is not None and codecs.lookup(encoding).name == "utf-8"


def json_ascii(stream=None) -> bool:
    """``ensure_ascii`` for JSON written to ``stream`` (default: sys.stdout).

    False on a UTF-8 stream; True on any other, so that JSON on a cp1251, cp866 or ASCII
    console escapes what the console lacks (``\\u03c9``) and stays exactly the data —
    never a spelling that changes a value.
    """
    stream = sys.stdout if stream is None else stream
    encoding = getattr(stream, "encoding", None)
    return encoding is not None and not _is_utf(encoding)


def prepare_streams(stdout=None, stderr=None) -> None:
    """Make ``stdout``/``stderr`` (default: sys's) safe for any text graphplan prints."""
    out = sys.stdout if stdout is None else stdout
    err = sys.stderr if stderr is None else stderr
    for stream, is_out in ((out, True), (err, False)):
        reconfigure = getattr(stream, "reconfigure", None)
        if reconfigure is None or _is_utf(getattr(stream, "encoding", None)):
            continue  # a StringIO, a captured stream or already UTF-8: nothing to fear
        redirected = not _isatty(stream)
        try:
            if is_out and redirected and not os.environ.get("PYTHONIOENCODING"):
                reconfigure(encoding="utf-8", errors="strict")
            else:
                reconfigure(errors=ERROR_HANDLER)
        except (ValueError, OSError):  # pragma: no cover - a stream that cannot change
            continue


def _isatty(stream) -> bool:
    try:
        return bool(stream.isatty())
    except (ValueError, OSError):
        return False


__all__ = [
    "ERROR_HANDLER",
    "EXIT_BAD_INPUT",
    "EXIT_CODES",
    "EXIT_FAULTS",
    "EXIT_FILE_ERROR",
    "EXIT_INTERNAL",
    "EXIT_INTERRUPTED",
    "EXIT_OK",
    "SYMBOLS",
    "console_spelling",
    "json_ascii",
    "prepare_streams",
]
