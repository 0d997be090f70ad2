"""The lettering font of the sheets (GOST 2.304-81 type B, slanted) and its metrics.

The sheets are lettered in **osifont**, an ISO 3098 CAD font close to GOST type B,
which graphplan ships (``graphplan/data/fonts/osifont.ttf``, Debian's fonts-osifont
0.1.20220224 with → and − added as composites of its own en dash and '>', Ё ё Э э
drawn from Е е С с and the subscript digits ₀ … ₉ from its superscripts, by
``docs/osifont_patch.py``, so that the equations and titles of the
sheets stay in one typeface; with its
licence: GPL-3 with the font exception, which lets documents embed it under any
licence). The symbols osifont lacks come from the DejaVu fonts that matplotlib ships. So
the lettering, its metrics and so every SVG, table and report are the same bytes on every
machine, with or without installed fonts; fonts installed on the system are never used for
the sheets (:func:`find_font_file`). The bundled build of
osifont cannot letter every text of a TMM sheet:

* it has no **∥**, **⟂**, **⊥**, **√** (the upstream build had no **−**, **→** and
  subscript digits **₁ ₂ ₃** either, and its **Ё ё Э э** were blank — one filled
  quadrilateral each, which :func:`glyph_is_blank` still catches in such a build:
  graphplan's draws them).

So every text gets its own font-family list. Its first family is the first font of
:data:`FONT_CHAIN` that really draws every character of the text (checked glyph by
glyph with fontTools), then the rest of the chain, then the generic ``sans-serif``.
The first family matters: CairoSVG (the optional PDF/PNG engine) uses only the first
family of the list and does no glyph fallback, and resvg, Typst and the browsers letter
a text in one family when that family draws all of it. The required symbols come from::

    osifont           А–я, Ё ё, ω ε φ π μ δ Δ Σ ψ τ ° ± × − → ₁ ₂ ₃
    DejaVu Sans       ∥ √ ⊥ (and any text that contains them)
    DejaVu Sans Mono  ⟂ (U+27C2 is in neither osifont nor DejaVu Sans; prefer ⊥ U+22A5)

Should a font file be unreadable (a damaged installation), the choice falls back on the
coverage the bundled build is known to have (:data:`_ASSUMED`), and widths on
:data:`FALLBACK_ADVANCE` per character.

Fonts outside the package (for the renderers' fallback on characters no family of the
chain draws) are found with matplotlib's font manager on every platform, or only in
the folders of ``$GRAPHPLAN_FONT_PATH`` when it is set: pointed at a folder that does
not exist, it hides every system font (:func:`font_dirs`).

The size of a text is its capital height ``h`` in mm (GOST 2.304). SVG's ``font-size``
is the em size, so the renderer writes ``font-size = h / cap_ratio(family)``; for
osifont ``cap_ratio = sCapHeight / unitsPerEm = 1515 / 2048 = 0.740``.

fontTools (a declared dependency) is imported only when a font file is read.
"""

from __future__ import annotations

import contextlib
import math
import os
import unicodedata
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cache, lru_cache
from importlib import resources
from pathlib import Path
from types import MappingProxyType

#: Font families tried in order for every text; the generic family ends the CSS list.
FONT_CHAIN: tuple[str, ...] = ("osifont", "DejaVu Sans", "DejaVu Sans Mono")
GENERIC_FAMILY = "sans-serif"

#: Characters every sheet must be able to letter (tests check the chain covers them).
REQUIRED_CHARS: str = (
    "АБВГДЕЖЗИЙКЛМНОПРСТУФХЦЧШЩЪЫЬЭЮЯабвгдежзийклмнопрстуфхцчшщъыьэюяЁё"
    "ωεφπμδΔΣ°±×−ψτ∥⟂₁₂₃"
)

#: Cap height / em when a font cannot be measured (typical sans-serif value).
FALLBACK_CAP_RATIO = 0.72
#: Advance width per character, in units of the capital height h, when no metrics are
#: known. GOST type B capitals are 6/10 h wide plus 2/10 h spacing (0.8 h); DejaVu Sans,
#: the widest font of the chain, averages 0.84 h on Russian text, so 0.85 h.
FALLBACK_ADVANCE = 0.85
#: The same for spaces, stops and other narrow characters (DejaVu Sans: 0.44 h).
FALLBACK_NARROW = 0.45
_NARROW = frozenset(" .,:;!|'`()[]ijlI1і·")

#: Environment variable: the folders searched for fonts other than the bundled ones.
FONT_PATH_ENV = "GRAPHPLAN_FONT_PATH"

#: The DejaVu files of FONT_CHAIN, as matplotlib ships them.
_MATPLOTLIB_FILES: Mapping[str, str] = MappingProxyType(
    {"DejaVu Sans": "DejaVuSans.ttf", "DejaVu Sans Mono": "DejaVuSansMono.ttf"}
)

#: Measured cap ratios of the reference builds, used when the file is absent.
_KNOWN_CAP_RATIO: Mapping[str, float] = MappingProxyType(
    {"osifont": 1515 / 2048, "DejaVu Sans": 1493 / 2048, "DejaVu Sans Mono": 1493 / 2048}
)

_BASIC = [(0x20, 0x7E), (0xA0, 0xFF)]
_GREEK = [(0x391, 0x3A9), (0x3B1, 0x3C9)]
_CYRILLIC = [(0x401, 0x401), (0x410, 0x44F), (0x451, 0x451)]
_MATH = [(0x2070, 0x209F), (0x2200, 0x22FF), (0x2010, 0x2027)]


def _ranges(ranges: list[tuple[int, int]], minus: str = "") -> frozenset[int]:
    cps = {c for lo, hi in ranges for c in range(lo, hi + 1)}
    return frozenset(cps - {ord(ch) for ch in minus})


#: Coverage assumed for a family whose file is not installed: what the Debian bookworm
#: builds (fonts-osifont 0.1.20220224 with graphplan's → and −, fonts-dejavu-core 2.37)
#: were measured to draw.
_ASSUMED: Mapping[str, frozenset[int]] = MappingProxyType(
    {
        "osifont": _ranges(_BASIC + _GREEK + _CYRILLIC
                           + [(0x2080, 0x2089), (0x2192, 0x2192), (0x2212, 0x2212)]),
        "DejaVu Sans": _ranges(_BASIC + _GREEK + _CYRILLIC + _MATH),
        "DejaVu Sans Mono": _ranges(_BASIC + _GREEK + _CYRILLIC + _MATH + [(0x27C2, 0x27C2)],
                                    minus="∥"),
    }
)

#: Code points whose glyphs are drawn and checked for blankness when a font is read
#: (Latin, Greek, Cyrillic, super/subscripts, punctuation, arrows, mathematics); a
#: glyph outside them is taken as drawn. Checking all ~6000 glyphs of DejaVu took 2 s.
_CHECKED = _ranges(_BASIC + _GREEK + _CYRILLIC + _MATH
                   + [(0x300, 0x3FF), (0x400, 0x4FF), (0x2000, 0x206F), (0x2190, 0x21FF),
                      (0x2300, 0x23FF), (0x25A0, 0x25FF), (0x27C0, 0x27EF)])

#: Letters whose true outline is a single contour of at most 4 points (a bar).
_SIMPLE_LETTERS = frozenset("IlıІӀ")


@dataclass(frozen=True, slots=True, eq=False)
class FontInfo:
    """Metrics and glyph coverage of one installed font file.

    ``advances`` maps a code point to its advance width in font units; ``blank`` holds
    the code points the cmap maps to a glyph that draws nothing useful (see
    :func:`glyph_is_blank`); ``covered`` holds the code points drawn for real.
    """

    family: str
    path: Path
    units_per_em: int
    cap_height: float
    advances: Mapping[int, int]
    covered: frozenset[int]
    blank: frozenset[int]

    @property
    def cap_ratio(self) -> float:
        """Capital height / em size: ``font-size = h / cap_ratio`` draws capitals h tall."""
        return self.cap_height / self.units_per_em


def bundled_font_file(family: str) -> Path | None:
    """The file of ``family`` that comes with graphplan or matplotlib (None if not one).

    osifont is in ``graphplan/data/fonts`` (with its licence); DejaVu Sans and DejaVu
    Sans Mono are the files matplotlib ships in ``mpl-data/fonts/ttf`` (DejaVu 2.35:
    the same advance widths and capital height as Debian's 2.37, a dozen fewer glyphs
    outside the lettering's alphabet).
    """
    if family == "osifont":
        return Path(str(resources.files("graphplan") / "data" / "fonts" / "osifont.ttf"))
    name = _MATPLOTLIB_FILES.get(family)
    if name is None:
        return None
    # matplotlib's data folder without importing matplotlib (a third of a second): its
    # get_data_path() is the package's own mpl-data folder
    import importlib.util

    spec = importlib.util.find_spec("matplotlib")
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(next(iter(spec.submodule_search_locations))) / "mpl-data" / "fonts" / "ttf" / name


def font_dirs() -> tuple[Path, ...] | None:
    """Folders searched for fonts outside the package, or None for the system's own.

    ``$GRAPHPLAN_FONT_PATH`` (folders separated by ``os.pathsep``) replaces the
    system's font folders; pointed at a folder that does not exist it hides every
    system font (the tests and CI do that to prove the output does not depend on
    them). Unset, matplotlib's font manager looks where the platform keeps fonts
    (fontconfig, the X11 and macOS folders, the Windows registry and the per-user
    folder ``%LOCALAPPDATA%\\Microsoft\\Windows\\Fonts``).
    """
    spec = os.environ.get(FONT_PATH_ENV)
    if spec is None:
        return None
    return tuple(Path(p) for p in spec.split(os.pathsep) if p)


def system_fonts_hidden() -> bool:
    """True when ``$GRAPHPLAN_FONT_PATH`` names no existing folder (no system font seen)."""
    dirs = font_dirs()
    return dirs is not None and not any(d.is_dir() for d in dirs)


def system_font_files() -> tuple[Path, ...]:
    """Font files outside the package (``$GRAPHPLAN_FONT_PATH``'s or the system's)."""
    from matplotlib import font_manager

    dirs = font_dirs()
    if dirs is None:
        return tuple(sorted(Path(f) for f in font_manager.findSystemFonts()))
    found = font_manager.findSystemFonts(fontpaths=[str(d) for d in dirs if d.is_dir()])
    return tuple(sorted(Path(f) for f in found))


@cache
def find_system_font(family: str) -> Path | None:
    """A regular font file of ``family`` outside the package, or None.

    In ``$GRAPHPLAN_FONT_PATH``'s folders when it is set, else through matplotlib's
    font manager (every platform's system and per-user font folders).
    """
    from matplotlib import font_manager

    if font_dirs() is None:
        prop = font_manager.FontProperties(family=family, style="normal", weight="normal")
        try:
            return Path(font_manager.fontManager.findfont(prop, fallback_to_default=False,
                                                          rebuild_if_missing=False))
        except ValueError:
            return None
    best = None
    for path in system_font_files():
        try:
            entry = font_manager.ttfFontProperty(font_manager.get_font(str(path)))
        except Exception:  # not a font matplotlib can read
            continue
        regular = (entry.style, entry.weight) == ("normal", 400)
        if entry.name == family and (best is None or regular):
            best = path
    return best


@cache
def find_font_file(family: str) -> Path | None:
    """Path of the font file of ``family``, or None.

    The families of :data:`FONT_CHAIN` always come with the package (osifont) or with
    matplotlib (DejaVu): the sheets are lettered, measured and embedded in the same
    fonts on every machine, whatever it has installed. Any other family is looked up
    with :func:`find_system_font`.
    """
    path = bundled_font_file(family)
    if path is not None and path.is_file():
        return path
    return find_system_font(family)


def glyph_is_blank(glyph_set, glyph_name: str, char: str) -> bool:
    """True if the glyph of ``char`` draws nothing that could be the character.

    A glyph is blank if it has no contour (for a non-space character), or if ``char``
    is a letter and its whole outline is one contour of at most 4 points: the
    placeholder quadrilaterals of osifont's Ё ё Э э. Letters that really are a bar
    (I, l, ı, І, Ӏ) are exempt; digits and symbols are judged by "no contour" only,
    since a hyphen or a minus may well be a 4-point rectangle.
    """
    from fontTools.pens.recordingPen import DecomposingRecordingPen

    pen = DecomposingRecordingPen(glyph_set)
    glyph_set[glyph_name].draw(pen)
    contours = sum(1 for op, _ in pen.value if op in ("closePath", "endPath"))
    points = sum(len(args) for op, args in pen.value if op not in ("closePath", "endPath"))
    if char.isspace():
        return False
    if contours == 0:
        return True
    return char.isalpha() and char not in _SIMPLE_LETTERS and contours == 1 and points <= 4


@cache
def load_font(family: str) -> FontInfo | None:
    """Read the metrics and the real glyph coverage of ``family``; None if not installed.

    Reading a font and drawing its glyphs to find the blank ones takes a tenth of a
    second or more per file, so the result is kept in the user's cache folder
    (:func:`graphplan.files.user_cache_dir`), keyed by the SHA-256 of the file's bytes
    and of the rules that judge a glyph (:func:`_metrics_key`): another file, or a file
    changed in place, or a new rule, is read again, never given another's metrics. A
    cache entry that cannot be read or does not check out is ignored; a cache folder
    that cannot be written is left alone (the metrics are then computed every run).
    """
    path = find_font_file(family)
    if path is None:
        return None
    try:
        raw = path.read_bytes()
    except OSError:
        return None
    key = _metrics_key(raw)
    cached = _read_cached_metrics(key)
    if cached is not None:
        upem, cap, advances, covered, blank = cached
    else:
        measured = _measure_font(path)
        if measured is None:
            return None
        upem, cap, advances, covered, blank = measured
        _write_cached_metrics(key, measured)
    return FontInfo(
        family=family, path=path, units_per_em=upem, cap_height=cap,
        advances=MappingProxyType(advances), covered=frozenset(covered), blank=frozenset(blank),
    )


_METRICS_FORMAT = 1
"""Version of the cached metrics' layout (and of :func:`glyph_is_blank`'s rule): bumped
when either changes, so an old entry is never read as a new one."""


def _metrics_key(raw: bytes) -> str:
    """SHA-256 of a font file's bytes and of what the measurement depends on."""
    import hashlib

    h = hashlib.sha256()
    h.update(f"graphplan font metrics {_METRICS_FORMAT}\n".encode())
    h.update(",".join(map(str, sorted(_CHECKED))).encode())
    h.update(("|" + "".join(sorted(_SIMPLE_LETTERS)) + f"|{FALLBACK_CAP_RATIO!r}|").encode())
    h.update(raw)
    return h.hexdigest()


def _metrics_path(key: str) -> Path | None:
    from .files import user_cache_dir

    folder = user_cache_dir()
    return None if folder is None else folder / "font-metrics" / f"{key}.json"


_Metrics = tuple[int, float, dict[int, int], set[int], set[int]]


def _read_cached_metrics(key: str) -> _Metrics | None:
    """The metrics stored under ``key``, or None (absent, unreadable, or not as written)."""
    import json

    path = _metrics_path(key)
    if path is None:
        return None
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        if data.get("format") != _METRICS_FORMAT or data.get("key") != key:
            return None
        upem, cap = data["units_per_em"], data["cap_height"]
        adv, covered, blank = data["advances"], data["covered"], data["blank"]
        ok = (type(upem) is int and upem > 0 and type(cap) is float and cap > 0
              and isinstance(adv, list) and isinstance(covered, list)
              and isinstance(blank, list)
              and all(isinstance(a, list) and len(a) == 2 and type(a[0]) is int
                      and type(a[1]) is int for a in adv)
              and all(type(c) is int for c in covered) and all(type(c) is int for c in blank))
        if not ok:
            return None
        advances = {cp: w for cp, w in adv}
        cov, bl = set(covered), set(blank)
        if len(advances) != len(adv) or cov & bl or (cov | bl) != advances.keys():
            return None
        return upem, cap, advances, cov, bl
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return None


def _write_cached_metrics(key: str, metrics: _Metrics) -> None:
    """Store the metrics under ``key`` (atomically); silently nothing if it cannot."""
    import json

    from .errors import GraphplanError
    from .files import write_atomic

    path = _metrics_path(key)
    if path is None:
        return
    upem, cap, advances, covered, blank = metrics
    text = json.dumps({"format": _METRICS_FORMAT, "key": key, "units_per_em": upem,
                       "cap_height": float(cap),
                       "advances": sorted([cp, w] for cp, w in advances.items()),
                       "covered": sorted(covered), "blank": sorted(blank)},
                      separators=(",", ":"))
    # a read-only home, a full disk: the metrics are computed again next time
    with contextlib.suppress(OSError, GraphplanError):
        write_atomic(path, text)


def _measure_font(path: Path) -> _Metrics | None:
    """Units per em, cap height, advances, covered and blank code points of a font file."""
    try:
        from fontTools.pens.boundsPen import BoundsPen
        from fontTools.ttLib import TTFont
    except ImportError:  # fontTools comes with matplotlib; without it use the fallbacks
        return None
    try:
        font = TTFont(str(path), lazy=True)
        cmap = font.getBestCmap() or {}
        glyph_set = font.getGlyphSet()
        hmtx = font["hmtx"]
        upem = int(font["head"].unitsPerEm)
        os2 = font.get("OS/2")
        cap = float(getattr(os2, "sCapHeight", 0) or 0) if os2 is not None else 0.0
        if cap <= 0 and ord("H") in cmap:
            pen = BoundsPen(glyph_set)
            glyph_set[cmap[ord("H")]].draw(pen)
            cap = float(pen.bounds[3]) if pen.bounds else 0.0
        if cap <= 0:
            cap = FALLBACK_CAP_RATIO * upem
        advances: dict[int, int] = {}
        covered: set[int] = set()
        blank: set[int] = set()
        for cp, name in cmap.items():
            if name == ".notdef" or name not in glyph_set:
                continue
            advances[cp] = int(hmtx[name][0])
            if cp in _CHECKED and glyph_is_blank(glyph_set, name, chr(cp)):
                blank.add(cp)
            else:
                covered.add(cp)
    except Exception:  # a broken or unreadable file counts as not installed
        return None
    finally:
        if "font" in locals():
            font.close()  # a lazy TTFont keeps its file open until closed
    if upem <= 0:
        return None
    return upem, float(cap), advances, covered, blank


def _coverage(family: str) -> frozenset[int]:
    info = load_font(family)
    if info is not None:
        return info.covered
    return _ASSUMED.get(family, frozenset())


def _needed(text: str) -> list[str]:
    # Whitespace and combining/format characters never need a glyph of their own.
    return [ch for ch in text if not ch.isspace() and unicodedata.category(ch)[0] not in "CM"]


def missing_chars(family: str, text: str) -> str:
    """Characters of ``text`` that ``family`` does not draw (missing or blank glyphs).

    Uses the installed file when there is one, else the coverage assumed for the
    reference build of the family.
    """
    cov = _coverage(family)
    return "".join(dict.fromkeys(ch for ch in _needed(text) if ord(ch) not in cov))


def is_installed(family: str) -> bool:
    """True if a readable font file of ``family`` was found."""
    return load_font(family) is not None


def blank_chars(family: str, text: str) -> str:
    """Characters of ``text`` whose glyph exists in the installed font but is blank."""
    info = load_font(family)
    if info is None:
        return ""
    return "".join(dict.fromkeys(ch for ch in text if ord(ch) in info.blank))


MINUS, EN_DASH = "\u2212", "\u2013"


def drawable_minus(text: str) -> str:
    """``text`` with its minus signs (U+2212) written as osifont's en dash, when that lets
    osifont letter the whole text; else ``text`` unchanged (it is then lettered in the
    fallback family, slanted all the same). graphplan's osifont draws U+2212 as the en
    dash's outline, but the upstream build CAD programs letter the DXF's texts in has no
    U+2212: the dash reads the same on the sheet and in CAD."""
    if MINUS not in text:
        return text
    swapped = text.replace(MINUS, EN_DASH)
    return swapped if not missing_chars("osifont", swapped) else text


@lru_cache(maxsize=4096)
def choose_family(text: str) -> str:
    """The family that letters ``text``: the first of FONT_CHAIN drawing all of it.

    If none draws every character, the family missing the fewest (earliest on ties);
    if none draws any, the generic family.
    """
    best, best_missing = GENERIC_FAMILY, None
    for family in FONT_CHAIN:
        n = len(missing_chars(family, text))
        if n == 0:
            return family
        if best_missing is None or n < best_missing:
            best, best_missing = family, n
    if best_missing is not None and best_missing == len(set(_needed(text))):
        return GENERIC_FAMILY
    return best


def font_family(text: str) -> str:
    """CSS font-family list for ``text``: the chosen family first, then the chain.

    >>> font_family("Масштаб")          # doctest: +SKIP
    "'osifont', 'DejaVu Sans', 'DejaVu Sans Mono', sans-serif"
    """
    first = choose_family(text)
    names = [first] + [f for f in FONT_CHAIN if f != first]
    return ", ".join(GENERIC_FAMILY if n == GENERIC_FAMILY else f"'{n}'" for n in names
                     ) + ("" if first == GENERIC_FAMILY else f", {GENERIC_FAMILY}")


def cap_ratio(family: str) -> float:
    """Capital height / em size of ``family`` (measured, known, or FALLBACK_CAP_RATIO)."""
    info = load_font(family)
    if info is not None:
        return info.cap_ratio
    return _KNOWN_CAP_RATIO.get(family, FALLBACK_CAP_RATIO)


def font_size(height: float, text: str) -> float:
    """SVG font-size (mm) that makes the capitals of ``text`` exactly ``height`` mm tall."""
    return height / cap_ratio(choose_family(text))


def text_width(text: str, height: float) -> float:
    """Advance width (mm) of ``text`` lettered upright at capital height ``height``.

    Uses the advance widths of the family chosen for the text; characters without
    metrics count FALLBACK_ADVANCE·h each (FALLBACK_NARROW·h for
    spaces, stops and the like). The slant of italic lettering is not
    included (see :func:`graphplan.drawing.items.text_box`).
    """
    family = choose_family(text)
    info = load_font(family)
    advances = info.advances if info is not None else {}
    size = height / info.cap_ratio if info is not None else 0.0
    total = 0.0
    for ch in text:
        adv = advances.get(ord(ch))
        if adv is None:
            total += (FALLBACK_NARROW if ch in _NARROW else FALLBACK_ADVANCE) * height
        else:
            total += adv / info.units_per_em * size  # type: ignore[union-attr]
    return total


#: GOST 2.304 type B slant: the letters lean at 75° to the baseline, 15° from upright.
SLANT_DEG = 15.0


def lettering_width(text: str, height: float, italic: bool = True) -> float:
    """Width (mm) of a line of lettering at capital height ``height``: the advance widths
    (:func:`text_width`) plus, when slanted (type B), the lean of its capitals,
    w = Σ advance + h·tan 15°."""
    lean = height * math.tan(math.radians(SLANT_DEG)) if italic else 0.0
    return text_width(text, height) + lean


def text_of_svg(svg_text: str) -> str:
    """The characters of the texts of an SVG (its text nodes; markup left out)."""
    import html
    import re

    return html.unescape("".join(re.findall(r">([^<]+)<", svg_text)))


@lru_cache(maxsize=1024)
def _file_coverage(path: Path) -> frozenset[int]:
    """Code points a font file maps to a glyph (the first font of a collection)."""
    try:
        from fontTools.ttLib import TTFont

        with TTFont(str(path), lazy=True, fontNumber=0) as font:
            return frozenset((font.getBestCmap() or {}).keys())
    except Exception:  # not a font fontTools reads: it covers nothing
        return frozenset()


def uncovered_chars(text: str) -> str:
    """Characters of ``text`` that no family of :data:`FONT_CHAIN` draws."""
    return "".join(dict.fromkeys(
        ch for ch in _needed(text)
        if not any(ord(ch) in _coverage(f) for f in FONT_CHAIN)))


def fallback_font_files(text: str) -> tuple[Path, ...]:
    """System font files that draw the characters of ``text`` the bundled fonts lack.

    For the PDF and PNG renderers: a title or a student's name in a script the lettering
    fonts do not have (Chinese, Georgian, Arabic …) is drawn in a font of the machine,
    found with :func:`system_font_files` (matplotlib's font manager, or
    ``$GRAPHPLAN_FONT_PATH``), the first that draws each character. Empty — and so the
    output independent of the machine — when the bundled fonts draw everything, as for
    every sheet of Russian or English text.
    """
    need = set(uncovered_chars(text))
    if not need:
        return ()
    chosen: list[Path] = []
    for path in system_font_files():
        drawn = {ch for ch in need if ord(ch) in _file_coverage(path)}
        if drawn:
            chosen.append(path)
            need -= drawn
            if not need:
                break
    return tuple(chosen)


def coverage_report(chars: str = REQUIRED_CHARS) -> dict[str, str]:
    """For each character, the family that letters it alone (GENERIC_FAMILY if none)."""
    return {ch: choose_family(ch) for ch in dict.fromkeys(chars) if not ch.isspace()}
