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
