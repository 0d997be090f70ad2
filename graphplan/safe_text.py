"""Safe text in every output: untrusted strings (a student's name, a variant's title, a
file name) made harmless for the terminal, XML/SVG, CSV opened in a spreadsheet and
Markdown.

* :func:`control_character` finds a character no input should hold (C0/C1 controls
  other than tab, the bidirectional overrides that reorder what a reader sees, the
  non-characters U+FFFE/U+FFFF, lone surrogates); the readers of variant and student
  files refuse them with a one-line error naming the key.
* :func:`terminal_text` writes such characters as visible escapes (``\\x1b``): an escape
  sequence in a student's name never reaches the teacher's terminal raw.
* :func:`xml_text` drops what XML 1.0 cannot hold (an SVG with a control character is
  not well-formed, and no viewer opens it).
* :func:`csv_cell` neutralises a cell a spreadsheet would run as a formula (a leading
  ``=``, ``+``, ``-``, ``@``, tab or carriage return gets a leading apostrophe), per the
  OWASP advice on CSV injection; numbers are left as they are.
* :func:`markdown_cell` escapes a table cell: ``|``, backslashes, HTML (``<``, ``>``,
  ``&``) and line breaks.
"""

from __future__ import annotations

import re

_BIDI = "\u061c\u200e\u200f\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069"
_CONTROL = re.compile(f"[\x00-\x08\x0b-\x1f\x7f-\x9f{_BIDI}\ufffe\uffff\ud800-\udfff]")
_CONTROL_NO_NL = re.compile(f"[\x00-\x08\x0a-\x1f\x7f-\x9f{_BIDI}\ufffe\uffff\ud800-\udfff]")
_XML_BAD = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff\ud800-\udfff]")


def control_character(text: str) -> str | None:
    """The first character of ``text`` no input should hold (``None`` if there is none),
    written as ``U+001B``. Tab is allowed; so are line breaks (the callers that want one
    line refuse those themselves)."""
    m = _CONTROL.search(text.replace("\n", "").replace("\r", ""))
    return None if m is None else f"U+{ord(m.group()):04X}"


def terminal_text(text: str) -> str:
    """``text`` with every control character (line breaks too) written as a visible
    escape: ``"a\\x1b[31mb"`` → ``"a\\\\x1b[31mb"``."""
    return _CONTROL_NO_NL.sub(_escape, text.replace("\t", " "))


def _escape(m: re.Match) -> str:
    c = ord(m.group())
    return f"\\x{c:02x}" if c < 0x100 else f"\\u{c:04x}"


def xml_text(text: str) -> str:
    """``text`` without the characters XML 1.0 cannot hold (each becomes U+FFFD)."""
    return _XML_BAD.sub("\ufffd", text)


def csv_cell(value):
    """A CSV cell a spreadsheet shows as text: a string starting with ``= + - @``, tab or
    carriage return gets a leading apostrophe; control characters are escaped. Numbers
    (``int``/``float``) are returned as they are."""
    if not isinstance(value, str):
        return value
    text = terminal_text(value) if _CONTROL_NO_NL.search(value) else value
    if text and text[0] in "=+-@\t\r":
        return "'" + text
    return text


def markdown_cell(text: str) -> str:
    """A Markdown table cell: ``|`` and ``\\`` escaped, HTML written as text, one line."""
    text = terminal_text(" ".join(str(text).split()))
    text = text.replace("\\", "\\\\").replace("|", "\\|")
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


__all__ = ["control_character", "csv_cell", "markdown_cell", "terminal_text", "xml_text"]
