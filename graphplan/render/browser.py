"""PNG screenshots of SVG sheets in a real browser: headless Chromium, standard library only.

The SVG is shown as an ``<img>`` filling the viewport of a small HTML page written to a
temporary folder, and Chromium's ``--screenshot`` of a window exactly that size is the
picture: ``width_px`` wide, as high as the SVG's root ``width``/``height`` ask (an A1
sheet, 841 x 594 mm, at 1682 px is 2 px per mm and 1682 x 1188 px). An SVG shown as an
image loads nothing from outside, so the page makes no network request; Chromium's own
services are quietened by flags (the rest of their attempts fail harmlessly when the
network is closed). Each run gets a fresh profile folder, removed afterwards.

Chromium is started with ``--no-sandbox`` (it refuses to start as root otherwise, and
containers often lack the namespaces its sandbox needs): render only trusted SVG files,
such as the sheets graphplan writes.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import struct
import subprocess
import tempfile
import time
import xml.etree.ElementTree as ET
from html import escape
from pathlib import Path

from ..errors import GraphplanError
from ..files import write_atomic

#: Environment variable naming the Chromium executable (a path or a command on PATH).
ENV_VAR = "GRAPHPLAN_CHROMIUM"
#: Commands tried on PATH, in order, when :data:`ENV_VAR` is not set.
CANDIDATES: tuple[str, ...] = ("chromium", "chromium-browser", "google-chrome")

#: Flags of every run: headless, no sandbox, no GPU, and Chromium's services kept quiet.
FLAGS: tuple[str, ...] = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--disable-default-apps",
    "--disable-domain-reliability",
    "--disable-dev-shm-usage",
    "--disable-features=NetworkTimeServiceQuerying,Translate,MediaRouter,OptimizationHints",
    "--no-pings",
    "--force-device-scale-factor=1",
    "--hide-scrollbars",
    "--virtual-time-budget=5000",
)

#: Largest side of a picture, px. Chromium 156 leaves the bottom of larger sheets blank
#: (an A1 sheet from about 9700 px wide); 8192 px across A1 is about 250 dpi.
MAX_SIDE_PX = 8192

_MM_PER_UNIT = {
    "mm": 1.0,
    "cm": 10.0,
    "in": 25.4,
    "pt": 25.4 / 72,
    "pc": 25.4 / 6,
    "px": 25.4 / 96,
    "": 25.4 / 96,
}
_LENGTH = re.compile(r"\s*([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\s*(mm|cm|in|pt|pc|px|)\s*")

_PAGE = """<!DOCTYPE html>
<html><head><meta charset="utf-8">
<style>html, body {{ margin: 0; padding: 0; overflow: hidden; background: #fff; }}
img {{ display: block; width: {w}px; height: {h}px; }}</style></head>
<body><img src="{src}" alt=""></body></html>
"""


def find_chromium() -> str | None:
    """The Chromium executable to use, or None when there is none.

    Returns
    -------
    str or None
        The value of ``GRAPHPLAN_CHROMIUM`` resolved on PATH (or as a path) if that
        variable is set and not empty, otherwise the first of ``chromium``,
        ``chromium-browser``, ``google-chrome`` found on PATH. When the variable is set
        but names nothing executable the result is None: an explicit choice is never
        replaced by another browser.
    """
    chosen = os.environ.get(ENV_VAR, "").strip()
    if chosen:
        return shutil.which(chosen)
    for name in CANDIDATES:
        found = shutil.which(name)
        if found:
            return found
    return None


def svg_size_mm(svg_path: str | Path) -> tuple[float, float]:
    """Width and height of an SVG's root element in mm (``viewBox`` units if it has none).

    Raises
    ------
    GraphplanError
        If the file cannot be read or parsed, or its size is missing or not positive.
    """
    try:
        _, root = next(ET.iterparse(svg_path, events=("start",)))
    except (OSError, ET.ParseError, StopIteration) as exc:
        raise GraphplanError(f"{svg_path}: cannot read the SVG ({exc})") from None
    size: list[float] = []
    for name in ("width", "height"):
        m = _LENGTH.fullmatch(root.get(name) or "")
        if m:
            size.append(float(m[1]) * _MM_PER_UNIT[m[2]])
    if len(size) < 2:
        box = (root.get("viewBox") or "").replace(",", " ").split()
        try:
            size = [float(box[2]), float(box[3])]
        except (IndexError, ValueError):
            raise GraphplanError(
                f"{svg_path}: the root <svg> has no absolute width/height and no viewBox"
            ) from None
    w, h = size
    if not (w > 0 and h > 0):
        raise GraphplanError(f"{svg_path}: the root <svg> size must be positive (got {w} x {h})")
    return w, h


def _why(stderr: str) -> str:
    """The last line of Chromium's stderr that is not launcher or D-Bus noise."""
    for line in reversed(stderr.splitlines()):
        line = line.strip()
        if line and "dbus" not in line and "/usr/bin/chromium:" not in line:
            return line[:300]
    return "no message"


def render_svg_png(
    svg_path: str | Path,
    png_path: str | Path,
    *,
    width_px: int = 1682,
    timeout: float = 60,
    net_log: str | Path | None = None,
) -> Path:
    """Screenshot of a whole SVG sheet in headless Chromium, written to ``png_path``.

    Parameters
    ----------
    svg_path : str or Path
        The SVG file (opened as a ``file://`` URL).
    png_path : str or Path
        Where the PNG goes (written atomically; folders are created).
    width_px : int
        Width of the picture in pixels; the height keeps the SVG's aspect ratio,
        ``round(width_px · height / width)``. No side may exceed :data:`MAX_SIDE_PX`.
    timeout : float
        Seconds Chromium may take before it is killed.
    net_log : str or Path, optional
        If given, Chromium writes its network log (JSON, ``--log-net-log``) there.

    Returns
    -------
    Path
        ``png_path``.

    Raises
    ------
    GraphplanError
        If the SVG has no usable size, the picture would be too large, or Chromium is
        not found, fails, times out or writes no screenshot of the expected size.
    """
    svg = Path(svg_path).resolve()
    if not svg.is_file():
        raise GraphplanError(f"{svg_path}: no such SVG file")
    w_mm, h_mm = svg_size_mm(svg)
    width = int(width_px)
    height = round(width * h_mm / w_mm)
    if not (min(width, height) >= 1 and max(width, height) <= MAX_SIDE_PX):
        raise GraphplanError(
            f"the picture must be 1 to {MAX_SIDE_PX} px on each side (width_px={width_px!r} "
            f"gives {width} x {height})"
        )
    exe = find_chromium()
    if exe is None:
        chosen = os.environ.get(ENV_VAR, "").strip()
        raise GraphplanError(
            f"{ENV_VAR}={chosen!r} is not an executable"
            if chosen
            else "Chromium not found: install the Debian packages 'chromium chromium-driver' "
            f"or set {ENV_VAR}"
        )
    with tempfile.TemporaryDirectory(prefix="graphplan-chromium-") as tmp:
        tmp_dir = Path(tmp)
        page, shot = tmp_dir / "sheet.html", tmp_dir / "sheet.png"
        page.write_text(_PAGE.format(w=width, h=height, src=escape(svg.as_uri())), encoding="utf-8")
        cmd = [
            exe,
            *FLAGS,
            f"--user-data-dir={tmp_dir / 'profile'}",
            f"--window-size={width},{height}",
            f"--screenshot={shot}",
        ]
        if net_log is not None:
            cmd.append(f"--log-net-log={Path(net_log).resolve()}")
        cmd.append(page.as_uri())
        # a session of its own, so that a timeout kills Chromium's helpers too
        proc = subprocess.Popen(
            cmd,
            stdin=subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            errors="replace",
            start_new_session=True,
        )
        started = time.monotonic()
        try:
            _, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
            raise GraphplanError(
                f"Chromium did not render {svg_path} within {timeout:g} s"
            ) from None
        if proc.returncode != 0 or not shot.is_file():
            raise GraphplanError(
                f"Chromium failed to render {svg_path} (exit {proc.returncode} after "
                f"{time.monotonic() - started:.1f} s): {_why(err)}"
            )
        png = shot.read_bytes()
        if png[12:16] != b"IHDR" or struct.unpack(">II", png[16:24]) != (width, height):
            raise GraphplanError(
                f"Chromium's screenshot of {svg_path} is not a {width} x {height} px PNG"
            )
        return write_atomic(png_path, png)


__all__ = ["MAX_SIDE_PX", "find_chromium", "render_svg_png", "svg_size_mm"]
