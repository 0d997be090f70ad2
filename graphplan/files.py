"""Files in and out: the bundled examples, bounded reading of untrusted inputs, atomic
writes that never touch an input nor follow a link, and sets of files replaced as a set.

Reading (:func:`read_input`): only a regular file is read (a FIFO, a device, a socket or a
link to one is refused without opening it for a blocking read), and at most
:data:`MAX_INPUT_BYTES` of it — a variant or a student file is a few kilobytes, a link to
``/dev/zero`` must not read gigabytes.

Writing (:func:`write_atomic`): through a temporary file in the same folder and a rename,
so a reader sees the old file or the new one, never half of one; an input is never
overwritten; a symbolic link in the way is refused (its target is never written); with
``root`` the file must lie inside that folder, with no link on the way down.

Sets (:func:`write_set`): the files of one output folder (a variant's sheets, tables and
report) are written into a sibling staging folder and swapped in at once — after a crash
or a ``kill -9`` the folder holds the old set or the new one, never a mix, and no
temporary file is left in it. Files of the folder graphplan did not write (teaching pages
beside the sheets) are carried over.
"""

from __future__ import annotations

import contextlib
import ctypes
import ctypes.util
import errno
import os
import secrets
import shutil
import stat
import sys
import tempfile
from pathlib import Path

from .errors import GraphplanError, InputError

_HERE = Path(__file__).resolve().parent

MAX_INPUT_BYTES = 1 << 20
"""Largest input file read (1 MiB): a variant or a student file is a few kilobytes."""


class OutputError(GraphplanError, OSError):
    """An output cannot be written where it was asked: outside the output folder, through
    a symbolic link, onto an input, onto another output, or the file system refused
    (read-only, full, not a folder). The command line exits with status 3."""


def examples_dir() -> Path:
    """Folder of the bundled example variants (installed copy, or the source tree's)."""
    for candidate in (_HERE / "examples", _HERE.parent / "examples"):
        if (candidate / "press.toml").is_file():
            return candidate
    raise InputError("the bundled examples are not installed (examples/press.toml not found)")


def bundled_example(name: str = "press") -> Path:
    """Path of a bundled example variant, e.g. ``bundled_example("press")``."""
    if not name or "/" in name or "\\" in name or name.startswith("."):
        raise InputError(f"{name!r}: no such bundled example")
    path = examples_dir() / f"{name}.toml"
    if not path.is_file():
        raise InputError(f"{path}: no such bundled example")
    return path


# --- reading ---------------------------------------------------------------------------------


def _kind(mode: int) -> str:
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    if stat.S_ISDIR(mode):
        return "a folder"
    return "not a regular file"  # pragma: no cover - door (Solaris) and the like


def read_input(path: str | Path, max_bytes: int = MAX_INPUT_BYTES,
               error: type[InputError] = InputError) -> bytes:
    """The bytes of an input file: a regular file of at most ``max_bytes``.

    A FIFO, a device, a socket or a folder (also behind a symbolic link) is refused
    before it is read; so is a file larger than ``max_bytes``. Every refusal is one line
    (``error``, an :class:`InputError`) naming the file.
    """
    source = str(path)
    try:
        st = os.stat(path)
    except FileNotFoundError:
        raise error(f"{source}: file not found") from None
    except OSError as exc:
        raise error(f"{source}: cannot read ({exc.strerror or exc})") from None
    if not stat.S_ISREG(st.st_mode):
        what = _kind(st.st_mode)
        raise error(f"{source}: cannot read: it is {what} (expected a file)")
    if st.st_size > max_bytes:
        raise error(f"{source}: {st.st_size} bytes; at most {max_bytes} are read "
                    "(is this really a variant or a student file?)")
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    try:
        fd = os.open(path, flags)
    except OSError as exc:
        raise error(f"{source}: cannot read ({exc.strerror or exc})") from None
    try:
        st = os.fstat(fd)  # the file swapped for a FIFO between stat and open
        if not stat.S_ISREG(st.st_mode):
            raise error(f"{source}: cannot read: it is {_kind(st.st_mode)} (expected a file)")
        chunks, total = [], 0
        while total <= max_bytes:
            b = os.read(fd, min(1 << 16, max_bytes + 1 - total))
            if not b:
                break
            chunks.append(b)
            total += len(b)
    except OSError as exc:
        raise error(f"{source}: cannot read ({exc.strerror or exc})") from None
    finally:
        os.close(fd)
    if total > max_bytes:
        raise error(f"{source}: larger than {max_bytes} bytes; not read")
    return b"".join(chunks)


# --- writing ---------------------------------------------------------------------------------


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def os_error_text(exc: OSError) -> str:
    """One line for an error of the file system: the file and the reason."""
    reason = exc.strerror or str(exc) or type(exc).__name__
    if exc.errno == errno.ENOSPC:
        reason = "no space left on the disk"
    elif exc.errno == errno.EROFS:
        reason = "read-only file system"
    elif exc.errno in (errno.EACCES, errno.EPERM):
        reason = "permission denied"
    name = exc.filename if exc.filename is not None else ""
    return f"{name}: {reason}" if name else reason


def _check_path(path: Path, root: Path | None) -> Path:
    """The absolute path to write (its folder resolved, the name kept), checked: inside
    ``root`` with no link on the way, and not a link itself."""
    name = path.name
    if name in ("", ".", ".."):
        raise OutputError(f"{path}: not a file name")
    folder = Path(os.path.abspath(path.parent))
    if root is not None:
        top = Path(os.path.abspath(root))
        try:
            rel = folder.relative_to(top)
        except ValueError:
            raise OutputError(f"{path}: outside the output folder {root}") from None
        if ".." in rel.parts:
            raise OutputError(f"{path}: outside the output folder {root}")
        cur = top
        for part in rel.parts:
            cur = cur / part
            if cur.is_symlink():
                raise OutputError(f"{cur}: a symbolic link inside the output folder; "
                                  "graphplan does not write through links")
    target = folder / name
    if target.is_symlink():
        raise OutputError(f"{target}: a symbolic link; graphplan does not write through "
                          "links (remove it, or choose another output)")
    if target.is_dir():
        raise OutputError(f"{target}: is a folder (expected a file name)")
    return target


def write_atomic(path: str | Path, data: str | bytes, protect: tuple[Path, ...] = (),
                 root: str | Path | None = None) -> Path:
    """Write ``data`` to ``path`` through a temporary file and a rename.

    A reader never sees a half-written file, and a failure leaves the old file as it was
    (and no temporary file). ``protect`` lists input files that must never be
    overwritten; ``root``, the output folder the file must lie in. A symbolic link at
    ``path`` (or, with ``root``, on the way to it) is refused: its target is never
    written.

    Raises
    ------
    InputError
        ``path`` is one of ``protect``.
    OutputError
        A link in the way, a path outside ``root``, or the file system refused (with
        the file and the reason: read-only, full, permission).
    """
    path = Path(path)
    target = _check_path(path, None if root is None else Path(root))
    real = Path(os.path.realpath(target))
    for p in protect:
        try:
            same = os.path.realpath(p) == str(real) or (real.exists() and
                                                        os.path.samefile(p, real))
        except (OSError, RuntimeError, ValueError):  # a link loop, a missing input
            same = False
        if same:
            raise InputError(f"{path}: refusing to overwrite an input file")
    raw = data.encode("utf-8") if isinstance(data, str) else data
    tmp = None
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp",
                                   dir=target.parent)
        # mkstemp makes the file private (0600); give it the mode a plain open() would
        # (or keep the mode of the file it replaces)
        mode = target.stat().st_mode & 0o7777 if target.exists() else 0o666 & ~_umask()
        os.chmod(tmp, mode)
        with os.fdopen(fd, "wb") as fh:
            fh.write(raw)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, target)
        tmp = None
    except OSError as exc:
        if isinstance(exc, GraphplanError):
            raise
        if exc.filename is None:
            exc.filename = str(path)
        raise OutputError(f"{path}: cannot write ({os_error_text(exc)})") from exc
    finally:
        if tmp is not None:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
    return path


CACHE_ENV = "GRAPHPLAN_CACHE_DIR"
"""Environment variable: the folder of graphplan's cache (empty: no cache at all)."""


def user_cache_dir() -> Path | None:
    """The folder where graphplan keeps what it can compute again (font metrics), or None.

    ``$GRAPHPLAN_CACHE_DIR`` when set (set empty, no cache is used); else the platform's
    per-user cache folder: ``%LOCALAPPDATA%\\graphplan\\Cache`` on Windows,
    ``~/Library/Caches/graphplan`` on macOS, ``$XDG_CACHE_HOME/graphplan`` (default
    ``~/.cache/graphplan``) elsewhere. The folder may not exist yet nor be writable: a
    cache is only ever an optimisation, and its users fall back on computing.
    """
    spec = os.environ.get(CACHE_ENV)
    if spec is not None:
        return Path(spec) if spec else None
    try:
        if sys.platform == "win32":
            base = os.environ.get("LOCALAPPDATA")
            return Path(base) / "graphplan" / "Cache" if base else None
        home = Path.home()
    except (OSError, RuntimeError):  # no home folder (a service account)
        return None
    if sys.platform == "darwin":
        return home / "Library" / "Caches" / "graphplan"
    xdg = os.environ.get("XDG_CACHE_HOME")
    return (Path(xdg) if xdg and os.path.isabs(xdg) else home / ".cache") / "graphplan"


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


# --- sets of files ---------------------------------------------------------------------------

_STAGE = ".graphplan-new-"
_OLD = ".graphplan-old-"


def _exchange(a: Path, b: Path) -> bool:
    """Swap two paths in one step (Linux ``renameat2(RENAME_EXCHANGE)``); ``False`` where
    the system cannot."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
        fn = libc.renameat2
    except (OSError, AttributeError):
        return False
    fn.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p,
                   ctypes.c_uint]
    at_fdcwd, rename_exchange = -100, 2
    if fn(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange) == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.ENOSYS, errno.EINVAL, errno.ENOTSUP if hasattr(errno, "ENOTSUP")
               else errno.EINVAL):
        return False
    raise OSError(err, os.strerror(err), str(b))


def recover_set(out_dir: str | Path) -> None:
    """Finish or undo a swap a crash interrupted, and remove staging folders left by a
    killed run (their set was never swapped in)."""
    out = Path(os.path.abspath(out_dir))
    parent = out.parent
    if not parent.is_dir():
        return
    stage, old = f"{_STAGE}{out.name}.", f"{_OLD}{out.name}."
    for entry in parent.iterdir():
        if entry.name.startswith(old) and entry.is_dir() and not entry.is_symlink():
            if not out.exists():  # killed between the two renames: the old set returns
                os.rename(entry, out)
            else:
                shutil.rmtree(entry, ignore_errors=True)
        elif entry.name.startswith(stage) and entry.is_dir() and not entry.is_symlink():
            shutil.rmtree(entry, ignore_errors=True)


def write_set(out_dir: str | Path, files: dict[str, str | bytes],
              protect: tuple[Path, ...] = ()) -> tuple[Path, ...]:
    """Replace the files of ``out_dir`` as a set.

    The new files are written into a sibling staging folder (``.graphplan-new-<name>.*``),
    the files of ``out_dir`` that are not part of the set are carried over (hard links,
    or copies), and the staging folder is swapped with ``out_dir`` in one step where the
    system can (Linux), else by two renames that :func:`recover_set` completes after a
    crash. A reader, or a crash, sees the old set or the new one.

    ``files`` maps a plain file name to its content. ``out_dir`` must be a folder of
    files (a folder holding sub-folders is refused: it is not an output folder).

    Raises
    ------
    InputError
        A file of the set would overwrite one of ``protect``.
    OutputError
        ``out_dir`` is a file, a link, holds folders, or the file system refused.
    """
    out = Path(os.path.abspath(out_dir))
    for name in files:
        if not name or name in (".", "..") or "/" in name or "\\" in name:
            raise OutputError(f"{out}: {name!r} is not a plain file name")
    if out.is_symlink():
        raise OutputError(f"{out_dir}: a symbolic link; graphplan does not write through "
                          "links (give the folder itself)")
    try:
        recover_set(out)
        if out.exists() and not out.is_dir():
            raise OutputError(f"{out_dir}: exists and is not a folder (the output must be "
                              "a folder)")
        keep: list[Path] = []
        if out.is_dir():
            for entry in out.iterdir():
                if entry.name in files:
                    for p in protect:
                        with contextlib.suppress(OSError):
                            if os.path.samefile(p, entry):
                                raise InputError(f"{entry}: refusing to overwrite an "
                                                 "input file")
                    continue
                if entry.is_symlink() or not entry.is_file():
                    raise OutputError(
                        f"{out_dir}: holds {entry.name!r}, which is not a file graphplan "
                        "writes; give an empty or new output folder")
                keep.append(entry)
        out.parent.mkdir(parents=True, exist_ok=True)
        stage = Path(tempfile.mkdtemp(prefix=f"{_STAGE}{out.name}.", dir=out.parent))
        moved = False  # the stage became the output (or was cleared)
        try:
            os.chmod(stage, 0o777 & ~_umask())
            for entry in keep:
                try:
                    os.link(entry, stage / entry.name)
                except OSError:
                    shutil.copy2(entry, stage / entry.name)
            for name, data in files.items():
                raw = data.encode("utf-8") if isinstance(data, str) else data
                with open(stage / name, "wb") as fh:
                    fh.write(raw)
                    fh.flush()
                    os.fsync(fh.fileno())
            if not out.exists():
                os.rename(stage, out)
            elif not _exchange(stage, out):
                old = out.parent / f"{_OLD}{out.name}.{secrets.token_hex(4)}"
                os.rename(out, old)
                os.rename(stage, out)
                shutil.rmtree(old, ignore_errors=True)
            else:
                shutil.rmtree(stage, ignore_errors=True)  # now holds the old set
            moved = True
        finally:
            if not moved:
                shutil.rmtree(stage, ignore_errors=True)
    except OSError as exc:
        if isinstance(exc, GraphplanError):
            raise
        raise OutputError(f"{out_dir}: cannot write ({os_error_text(exc)})") from exc
    return tuple(Path(out_dir) / name for name in files)


__all__ = ["CACHE_ENV", "MAX_INPUT_BYTES", "OutputError", "bundled_example", "decode_text",
           "examples_dir", "os_error_text", "read_input", "recover_set", "user_cache_dir",
           "write_atomic", "write_set"]
