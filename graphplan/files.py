"""Files in and out: the bundled examples, and atomic writes that never touch an input."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from .errors import InputError

_HERE = Path(__file__).resolve().parent


def examples_dir() -> Path:
    """Folder of the bundled example variants (installed copy, or the source tree's)."""
    for candidate in (_HERE / "examples", _HERE.parent / "examples"):
        if (candidate / "press.toml").is_file():
            return candidate
    raise InputError("the bundled examples are not installed (examples/press.toml not found)")


def bundled_example(name: str = "press") -> Path:
    """Path of a bundled example variant, e.g. ``bundled_example("press")``."""
    path = examples_dir() / f"{name}.toml"
    if not path.is_file():
        raise InputError(f"{path}: no such bundled example")
    return path


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def write_atomic(path: str | Path, data: str | bytes, protect: tuple[Path, ...] = ()) -> Path:
    """Write ``data`` to ``path`` through a temporary file and a rename.

    A reader never sees a half-written file, and a failure leaves the old file
    as it was. ``protect`` lists input files that must never be overwritten.
    """
    path = Path(path)
    target = path.resolve()
    for p in protect:
        if Path(p).resolve() == target:
            raise InputError(f"{path}: refusing to overwrite an input file")
    target.parent.mkdir(parents=True, exist_ok=True)
    raw = data.encode("utf-8") if isinstance(data, str) else data
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    try:
        # mkstemp makes the file private (0600); give it the mode a plain open() would
        # (or keep the mode of the file it replaces)
        mode = target.stat().st_mode & 0o7777 if target.exists() else 0o666 & ~_umask()
        os.chmod(tmp, mode)
        with os.fdopen(fd, "wb") as fh:
            fh.write(raw)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


#: Notepad's byte order marks: UTF-8 ("UTF-8 with BOM") and UTF-16 ("Unicode").
_BOMS = ((b"\xef\xbb\xbf", "utf-8"), (b"\xff\xfe", "utf-16-le"), (b"\xfe\xff", "utf-16-be"))


def decode_text(raw: bytes, source: str, error: type[Exception] = InputError) -> str:
    """The text of a file as Windows programs write it: UTF-8, with or without a BOM.

    A byte order mark (UTF-8's, or UTF-16's from Notepad's "Unicode") is honoured and
    dropped; Windows (CRLF) and old Mac (CR) line ends become ``\\n``, so line numbers
    in messages are the editor's. Text that is not UTF-8 raises ``error`` with one line
    naming the file and the line, and saying what to do — "save the file as UTF-8";
    a file in the Windows Cyrillic code page (cp1251, Notepad's "ANSI" on a Russian
    Windows) or in DOS's cp866 is named as such.
    """
    encoding = "utf-8"
    for bom, enc in _BOMS:
        if raw.startswith(bom):
            raw, encoding = raw[len(bom):], enc
            break
    try:
        text = raw.decode(encoding)
    except UnicodeDecodeError as exc:
        line = raw[:exc.start].count(b"\n") + 1
        raise error(f"{source}: line {line}: not UTF-8 text{_legacy_code_page(raw)}: "
                    f"save the file as UTF-8 (Notepad: File → Save as → Encoding: UTF-8)"
                    ) from None
    return text.replace("\r\n", "\n").replace("\r", "\n")


def _legacy_code_page(raw: bytes) -> str:
    """`` (it looks like cp1251 …)`` when the bytes read as Russian text in a code page."""
    high = [b for b in raw if b >= 0x80]
    if not high:
        return ""
    # cp1251: а–я are 0xE0–0xFF, А–Я 0xC0–0xDF; cp866: А–п 0x80–0xAF, р–я 0xE0–0xEF
    cp1251 = sum(b >= 0xC0 for b in high) / len(high)
    cp866 = sum(0x80 <= b <= 0xAF or 0xE0 <= b <= 0xEF for b in high) / len(high)
    if cp1251 >= 0.9 and cp1251 >= cp866:
        return " (it looks like the Windows Cyrillic code page cp1251, Notepad's 'ANSI')"
    if cp866 >= 0.9:
        return " (it looks like the DOS Cyrillic code page cp866)"
    return ""
