"""The student file: a student's figures and written calculations, as TOML.

See ``docs/check-format.md`` for the format. In short::

    [work]
    variant = "../press.toml"        # the variant, relative to this file
    student = "Иванов И. И."
    lang = "ru"

    [general]                        # figures of the whole mechanism
    lines = ["Кl = lOA/OA = 0.08/80 = 0.001 м/мм", "G3 = m3∙g = 1250∙9.81 = 12262.5 H"]

    [arms]                           # arms named in the calculation
    h3 = { force = "G3", about = "A" }

    [[positions]]
    label = "(2)"
    lines = [
      "R12 = 42,4∙10 = 424 кН",
      { line = "Кр = 420/42 = 10 кН/мм", symbols = "Q/Q_mm" },
    ]

:func:`load_student` reads and validates it; every problem is a
:class:`~graphplan.checking.errors.StudentFileError` naming the file and the key.
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Set as AbstractSet
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..files import decode_text
from ..model import parse_toml
from ..safe_text import control_character
from .errors import StudentFileError
from .quantities import ArmSpec

TOLERANCE_KEYS = ("segment", "segment_ok", "derived", "derived_ok", "arithmetic", "reading_mm")
MAX_LINES = 2000


@dataclass(frozen=True, slots=True)
class Line:
    """One written calculation (or one figure) of the student file.

    Attributes
    ----------
    text : str
        As written: ``"R12=42,4∙10=424 кН"``.
    scope : str
        ``"general"`` or the position's label.
    key : str
        Where it is in the file (``"positions[1].lines[3]"``).
    file_line : int | None
        Line number of the text in the file (1-based), when it can be found.
    quantity : str | None
        The name of the figure the line computes, when its left side is not a plain name
        (``"0,7Q0 = 0.7∙600000 = 420000 H"`` computes Q).
    symbols : str | None
        The names of the numbers of its expression, written like the expression
        (``"R12_mm∙Kp"`` for ``42,4∙10``).
    note : str
        A remark of the transcriber, shown in the report.
    """

    text: str
    scope: str
    key: str
    file_line: int | None = None
    quantity: str | None = None
    symbols: str | None = None
    note: str = ""

    @property
    def where(self) -> str:
        """``"line 14"`` (of the file) or the key."""
        return self.where_in("en")

    def where_in(self, lang: str) -> str:
        """``"line 14"`` / ``"строка 14"`` (of the file), or the key."""
        if not self.file_line:
            return self.key
        return f"{'строка' if lang == 'ru' else 'line'} {self.file_line}"


@dataclass(frozen=True, slots=True)
class StudentPosition:
    """The figures of one position: its label (as the variant numbers it), optional crank
    angle (degrees, for a position the variant lacks), title and lines."""

    label: str
    lines: tuple[Line, ...]
    phi_deg: float | None = None
    title: str = ""
    arms: dict[str, ArmSpec] = field(default_factory=dict)


@dataclass(frozen=True, slots=True)
class StudentWork:
    """A student's work as read from the student file."""

    source: Path
    variant: Path
    general: tuple[Line, ...]
    positions: tuple[StudentPosition, ...]
    student: str = ""
    group: str = ""
    title: str = ""
    lang: str = "ru"
    neighbours: tuple[Path, ...] = ()
    tolerances: dict[str, float] = field(default_factory=dict)
    arms: dict[str, ArmSpec] = field(default_factory=dict)
    text: str = ""
    drawings: tuple[Path, ...] = ()  # [work] drawing: the sheets (checking/drawing)

    @property
    def lines(self) -> tuple[Line, ...]:
        """Every line, general ones first."""
        return self.general + tuple(ln for p in self.positions for ln in p.lines)


class _Read:
    def __init__(self, source: str, text: str):
        self.source = source
        self.text = text
        self.rows = text.splitlines()
        self.cursor = 0  # lines are found in file order
        self.starts: list[int] | None = None  # offset of each row in the joined text
        self.joined = ""

    def fail(self, key: str, msg: str) -> StudentFileError:
        return StudentFileError(f"{self.source}: {key}: {msg}")

    def table(self, v: Any, key: str) -> dict:
        if not isinstance(v, dict):
            raise self.fail(key, f"expected a table (got {_typename(v)})")
        return v

    def keys(self, t: dict, key: str, allowed: AbstractSet[str],
             required: AbstractSet[str] = frozenset()):
        for k in t:
            if k not in allowed:
                raise self.fail(f"{key}.{k}" if key else k,
                                f"unknown key (expected one of: {', '.join(sorted(allowed))})")
        for k in sorted(required):
            if k not in t:
                raise self.fail(f"{key}.{k}" if key else k, "missing required key")

    def string(self, v: Any, key: str, choices=None) -> str:
        if not isinstance(v, str):
            raise self.fail(key, f"expected a string (got {_typename(v)})")
        if choices and v not in choices:
            raise self.fail(key, f"expected one of {', '.join(choices)} (got {v!r})")
        if "\n" in v or "\r" in v:
            raise self.fail(key, "expected one line of text (got a line break)")
        bad = control_character(v)
        if bad is not None:
            raise self.fail(key, f"a control character ({bad}) in the text: not allowed")
        return v

    def number(self, v: Any, key: str, lo: float | None = None, hi: float | None = None):
        if isinstance(v, bool) or not isinstance(v, int | float):
            raise self.fail(key, f"expected a number (got {_typename(v)} {v!r})")
        try:
            x = float(v)
        except OverflowError:
            raise self.fail(key, "expected a finite number (got a huge integer)") from None
        if not math.isfinite(x):
            raise self.fail(key, f"expected a finite number (got {v!r})")
        if lo is not None and x < lo:
            raise self.fail(key, f"must be >= {lo:g} (got {v!r})")
        if hi is not None and x > hi:
            raise self.fail(key, f"must be <= {hi:g} (got {v!r})")
        return x

    def find_line(self, text: str) -> int | None:
        probe = text.strip()[:40]
        if not probe:
            return None
        if self.starts is None:
            self.starts = [0]
            for row in self.rows:
                self.starts.append(self.starts[-1] + len(row) + 1)
            self.joined = "\n".join(self.rows)
        at = self.joined.find(probe, self.starts[self.cursor])
        if at >= 0:
            self.cursor = bisect.bisect_right(self.starts, at) - 1
            return self.cursor + 1
        at = self.joined.find(probe)
        return None if at < 0 else bisect.bisect_right(self.starts, at)


def _typename(v: Any) -> str:
    return {dict: "table", list: "array", str: "string", bool: "boolean"}.get(
        type(v), type(v).__name__)


def _arms(r: _Read, v: Any, key: str) -> dict[str, ArmSpec]:
    out = {}
    for name, spec in r.table(v, key).items():
        k = f"{key}.{name}"
        if not name or not (name[0].isalpha()) or not all(c.isalnum() or c == "_" for c in name):
            raise r.fail(k, "an arm's name must be a name such as h3 or hG2")
        spec = r.table(spec, k)
        r.keys(spec, k, {"force", "about"}, {"force", "about"})
        out[name] = ArmSpec(name, r.string(spec["force"], f"{k}.force"),
                            r.string(spec["about"], f"{k}.about"))
    return out


def _lines(r: _Read, v: Any, key: str, scope: str) -> list[Line]:
    if not isinstance(v, list):
        raise r.fail(key, f"expected an array of lines (got {_typename(v)})")
    out = []
    for i, item in enumerate(v):
        k = f"{key}[{i}]"
        if isinstance(item, str):
            text, quantity, symbols, note = item, None, None, ""
        else:
            t = r.table(item, k)
            r.keys(t, k, {"line", "quantity", "symbols", "note"}, {"line"})
            text = r.string(t["line"], f"{k}.line")
            quantity = r.string(t["quantity"], f"{k}.quantity") if "quantity" in t else None
            symbols = r.string(t["symbols"], f"{k}.symbols") if "symbols" in t else None
            note = r.string(t["note"], f"{k}.note") if "note" in t else ""
        text = r.string(text, k).strip()
        if not text:
            raise r.fail(k, "empty line (expected a calculation such as 'G3 = m3∙g = 12262,5 Н')")
        out.append(Line(text, scope, k, r.find_line(text), quantity, symbols, note))
    return out


def _figures(r: _Read, v: Any, key: str, scope: str) -> list[Line]:
    """``figures = { h21 = "37,39 мм", m3 = 1250 }`` as lines ``h21 = 37,39 мм``."""
    out = []
    for name, val in r.table(v, key).items():
        k = f"{key}.{name}"
        if isinstance(val, str):
            text = f"{name} = {r.string(val, k)}"
        else:
            x = r.number(val, k)
            text = f"{name} = {x!r}"
        out.append(Line(text, scope, k, r.find_line(f"{name} =") or r.find_line(name)))
    return out


def _count_lines(data: dict) -> int:
    """Lines and figures of a student file, as written (whatever their types)."""
    def size(v) -> int:
        return len(v) if isinstance(v, list | dict) else 0

    tables = [data.get("general")]
    if isinstance(data.get("positions"), list):
        tables += data["positions"]
    return sum(size(t.get("lines")) + size(t.get("figures")) for t in tables
               if isinstance(t, dict))


def load_student(path: str | Path) -> StudentWork:
    """Read and validate a student file (``docs/check-format.md``).

    Raises
    ------
    StudentFileError
        For any problem, naming the file and the key.
    """
    path = Path(path)
    source = str(path)
    from ..files import read_input

    if path.suffix.lower() == ".docx":  # an explanatory note written by `graphplan note`
        from .note_reader import note_student_toml

        raw = read_input(path, error=StudentFileError)
        return loads_student(note_student_toml(path, raw), path)

    raw = read_input(path, error=StudentFileError)  # a regular file, bounded in size
    # a BOM, CRLF line ends; cp1251 and other non-UTF-8 text: "save the file as UTF-8"
    return loads_student(decode_text(raw, source, StudentFileError), path)


def loads_student(text: str, path: str | Path = "<string>") -> StudentWork:
    """Validate a student file given as text (see :func:`load_student`)."""
    path = Path(path)
    source = str(path)
    data = parse_toml(text, source, StudentFileError)
    r = _Read(source, text)
    r.keys(data, "", {"work", "general", "arms", "tolerances", "positions"},
           {"work", "positions"})
    total = _count_lines(data)  # before any line is read: the work stays linear
    if total > MAX_LINES:
        raise r.fail("positions", f"{total} lines: at most {MAX_LINES} are checked")
    work = r.table(data["work"], "work")
    r.keys(work, "work", {"variant", "student", "group", "title", "source", "lang",
                          "neighbours", "drawing"}, {"variant"})
    variant = r.string(work["variant"], "work.variant")
    if variant.startswith("bundled:"):
        from ..files import bundled_example

        try:
            vpath = bundled_example(variant.split(":", 1)[1])
        except Exception:
            raise r.fail("work.variant", f"no bundled example {variant!r}") from None
    else:
        vpath = (path.parent / variant) if not Path(variant).is_absolute() else Path(variant)
        if not vpath.is_file():
            raise r.fail("work.variant", f"variant file {str(vpath)!r} not found (a path "
                         "relative to the student file, or 'bundled:press')")
    neighbours = []
    if "neighbours" in work:
        nb = work["neighbours"]
        if not isinstance(nb, list):
            raise r.fail("work.neighbours", f"expected an array of variant files (got "
                         f"{_typename(nb)})")
        for i, n in enumerate(nb):
            fp = path.parent / r.string(n, f"work.neighbours[{i}]")
            if not fp.is_file():
                raise r.fail(f"work.neighbours[{i}]", f"variant file {str(fp)!r} not found")
            neighbours.append(fp)
    drawings = []
    if "drawing" in work:  # the student's sheets, checked with the calculation
        dw = work["drawing"]
        for i, d in enumerate(dw if isinstance(dw, list) else [dw]):
            key = f"work.drawing[{i}]" if isinstance(dw, list) else "work.drawing"
            fp = path.parent / r.string(d, key)
            if not fp.is_file():
                raise r.fail(key, f"drawing {str(fp)!r} not found (a .dxf, .svg or .pdf "
                             "relative to the student file)")
            drawings.append(fp)
    tolerances = {}
    if "tolerances" in data:
        t = r.table(data["tolerances"], "tolerances")
        r.keys(t, "tolerances", set(TOLERANCE_KEYS))
        for k, v in t.items():
            tolerances[k] = r.number(v, f"tolerances.{k}", lo=0.0, hi=10.0 if k ==
                                     "reading_mm" else 1.0)
    arms = _arms(r, data["arms"], "arms") if "arms" in data else {}
    general: list[Line] = []
    if "general" in data:
        g = r.table(data["general"], "general")
        r.keys(g, "general", {"lines", "figures"})
        if "figures" in g:
            general += _figures(r, g["figures"], "general.figures", "general")
        if "lines" in g:
            general += _lines(r, g["lines"], "general.lines", "general")
    positions = []
    pos = data["positions"]
    if not isinstance(pos, list) or not pos:
        raise r.fail("positions", "expected an array of tables [[positions]] (at least one)")
    seen = set()
    for i, p in enumerate(pos):
        k = f"positions[{i}]"
        p = r.table(p, k)
        r.keys(p, k, {"label", "phi", "title", "lines", "figures", "arms"}, {"label"})
        label = p["label"]
        if isinstance(label, int) and not isinstance(label, bool):
            label = str(label)
        label = r.string(label, f"{k}.label")
        if not label.strip() or any(c in label for c in "=@"):
            raise r.fail(f"{k}.label", f"expected a position label such as 2 or (2) (got "
                         f"{label!r})")
        if label in seen:
            raise r.fail(f"{k}.label", f"position {label!r} appears twice")
        seen.add(label)
        phi = r.number(p["phi"], f"{k}.phi", -360.0, 720.0) if "phi" in p else None
        title = r.string(p["title"], f"{k}.title") if "title" in p else ""
        lines: list[Line] = []
        if "figures" in p:
            lines += _figures(r, p["figures"], f"{k}.figures", label)
        if "lines" in p:
            lines += _lines(r, p["lines"], f"{k}.lines", label)
        parms = {**arms, **(_arms(r, p["arms"], f"{k}.arms") if "arms" in p else {})}
        positions.append(StudentPosition(label, tuple(lines), phi, title, parms))
    total = len(general) + sum(len(p.lines) for p in positions)
    if total > MAX_LINES:
        raise r.fail("positions", f"{total} lines: at most {MAX_LINES} are checked")
    lang = r.string(work["lang"], "work.lang", ("ru", "en")) if "lang" in work else "ru"
    return StudentWork(
        source=path, variant=vpath, general=tuple(general), positions=tuple(positions),
        student=r.string(work.get("student", ""), "work.student"),
        group=r.string(work.get("group", ""), "work.group"),
        title=r.string(work.get("title", ""), "work.title"),
        lang=lang, neighbours=tuple(neighbours), tolerances=tolerances, arms=arms, text=text,
        drawings=tuple(drawings))


__all__ = ["TOLERANCE_KEYS", "Line", "StudentPosition", "StudentWork", "load_student",
           "loads_student"]
