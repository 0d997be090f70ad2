"""Read a variant file (TOML) into a validated :class:`~graphplan.model.mechanism.Mechanism`.

Every error is an :class:`~graphplan.errors.InputError` whose one-line message
names the file, the key path and what was expected, e.g.
``examples/press.toml: dyads[0].length: must be > 0 (got -200)``.
Units are converted here, at the edge: lengths by ``variant.length_unit``
(``"m"`` or ``"mm"``), angles from degrees to radians. The key reference is
``docs/variant-format.md``.
"""

from __future__ import annotations

import math
import re
from collections.abc import Set as AbstractSet
from pathlib import Path
from typing import Any

from ..errors import InputError
from ..files import decode_text
from .mechanism import (
    DYAD_KINDS,
    JOINT_COUNT,
    NEW_JOINTS,
    Crank,
    Dyad,
    ExtraPosition,
    Guide,
    LinkProps,
    Mechanism,
    Output,
    PointOnLink,
    Positions,
    Resistance,
)
from .settings import MOTOR_SERIES, SYNC_SPEEDS
from .toml_text import _CONTROL, one_line, parse_toml

LENGTH_UNITS = {"m": 1.0, "mm": 1e-3}
MAX_LENGTH_M = 1000.0
"""No machine of a TMM project is a kilometre across; larger numbers are typos."""
MAX_RPM = 1e5
MAX_LOAD = 1e12
"""No load of a TMM variant reaches 10¹² N or N·m; larger numbers are typos."""
PRESSURE_UNITS = {"Pa": 1.0, "kPa": 1e3, "MPa": 1e6, "bar": 1e5, "atm": 101325.0,
                  "kgf/cm2": 98066.5, "kgf/cm²": 98066.5, "at": 98066.5,
                  "Па": 1.0, "кПа": 1e3, "МПа": 1e6, "бар": 1e5, "атм": 101325.0,
                  "кгс/см2": 98066.5, "кгс/см²": 98066.5, "ат": 98066.5}
"""Units of the pressures of an indicator diagram, in Pa, as the task books write them in
either alphabet: kgf/cm2 (кгс/см², the technical atmosphere at, ат, of the older books)
is 98 066.5 Pa; atm (атм), the physical atmosphere, 101 325 Pa."""
LOAD_KEYS = {"kind", "link", "point", "max", "value", "diagram", "name", "sense", "over",
             "stroke", "strokes", "travel", "angle", "travel_link", "working", "phase",
             "bore", "rod", "p_max", "p_ambient", "pressure_unit", "unit"}
FORCE_UNITS = {"N": 1.0, "kN": 1e3, "MN": 1e6, "Н": 1.0, "кН": 1e3, "МН": 1e6}
"""Units of a force load's ``max`` or ``value``, in N (Russian spellings accepted)."""
MOMENT_UNITS = {"N·m": 1.0, "N*m": 1.0, "Nm": 1.0, "kN·m": 1e3, "kN*m": 1e3, "kNm": 1e3,
                "Н·м": 1.0, "кН·м": 1e3}
"""Units of a couple's ``max`` or ``value``, in N·m."""
STROKE_SETS = ("working", "idle", "both")
NAME_RE = re.compile(r"[A-Za-z][A-Za-z0-9_']*")  # used with fullmatch: no trailing newline
LINK_RE = re.compile(r"[0-9]{1,3}")
Diagram = tuple[tuple[float, float], ...]  #: a load diagram's (abscissa, value) pairs

# Sections and keys each section accepts. Later stages (drawing, kinetostatics,
# dynamics, title block) keep their settings here so that a typo is caught at load.
SECTIONS: dict[str, set[str] | None] = {
    "variant": {"name", "length_unit", "description"},
    "frame": {"link", "points"},
    "crank": {"link", "joints", "length", "rpm", "omega", "direction", "mass", "weight",
              "inertia", "centre"},
    "dyads": None,
    "points": None,
    "links": None,
    "gravity": {"enabled", "g", "angle"},
    "loads": None,
    "positions": {"count", "first", "number_from", "extra", "cycle"},
    "output": {"link", "working"},
    "kinetostatics": {"neglect_below", "inertia", "shift_inertia_force", "positions"},
    "dynamics": {
        "delta",
        "efficiency",
        "crank_inertia",
        "flywheel",
        "grid",
        "intervals",
        "motor_series",
        "motor_speed",
    },
    "drawing": {"format", "Kl", "Kv", "Ka", "Kp", "reading_mm", "language", "positions",
                "accelerations"},
    "title_block": {
        "title",
        "designation",
        "author",
        "checker",
        "teacher",
        "group",
        "school",
        "sheet",
        "sheets",
        "date",
        "litera",
        "mass",
        "scale",
    },
}


class _Reader:
    """Typed access to a TOML table that reports errors with the file and key path."""

    def __init__(self, source: str):
        self.source = source

    def fail(self, path: str, message: str) -> InputError:
        return InputError(one_line(f"{self.source}: {path}: {message}"))

    def table(self, value: Any, path: str) -> dict:
        if not isinstance(value, dict):
            raise self.fail(path, f"expected a table (got {_typename(value)})")
        return value

    def keys(self, table: dict, path: str, allowed: AbstractSet[str] | None,
             required: AbstractSet[str] = frozenset()):
        """Refuse a key not in ``allowed`` (None: any key) and a missing ``required`` one."""
        for k in table:
            if allowed is not None and k not in allowed:
                hint = ", ".join(sorted(allowed))
                raise self.fail(_join(path, k), f"unknown key (expected one of: {hint})")
        for k in sorted(required):
            if k not in table:
                raise self.fail(_join(path, k), "missing required key")

    def number(self, value: Any, path: str, *, positive=False, nonneg=False, lo=None, hi=None):
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise self.fail(path, f"expected a number (got {_typename(value)} {value!r})")
        try:
            x = float(value)
        except OverflowError:
            raise self.fail(path, f"expected a finite number (got an integer of "
                                  f"{len(str(abs(value)))} digits)") from None
        if not math.isfinite(x):
            raise self.fail(path, f"expected a finite number (got {value!r})")
        if positive and not x > 0:
            raise self.fail(path, f"must be > 0 (got {value!r})")
        if nonneg and x < 0:
            raise self.fail(path, f"must be >= 0 (got {value!r})")
        if lo is not None and x < lo:
            raise self.fail(path, f"must be >= {lo} (got {value!r})")
        if hi is not None and x > hi:
            raise self.fail(path, f"must be <= {hi} (got {value!r})")
        return x

    def integer(self, value: Any, path: str, lo: int, hi: int) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(path, f"expected a whole number (got {_typename(value)} {value!r})")
        if not lo <= value <= hi:
            raise self.fail(path, f"must be from {lo} to {hi} (got {value!r})")
        return int(value)

    def string(self, value: Any, path: str, choices=None) -> str:
        if not isinstance(value, str):
            raise self.fail(path, f"expected a string (got {_typename(value)} {value!r})")
        if choices is not None and value not in choices:
            raise self.fail(path, f"expected one of {', '.join(map(repr, choices))} "
                                  f"(got {value!r})")
        return value

    def name(self, value: Any, path: str) -> str:
        s = self.string(value, path)
        if not NAME_RE.fullmatch(s):
            from .mistakes import lookalike_hint

            raise self.fail(path, f"expected a point name like 'A', 'S2', 'O3' (got {s!r})"
                            + lookalike_hint(s))
        return s

    def link(self, value: Any, path: str) -> str:
        if isinstance(value, int) and not isinstance(value, bool):
            value = str(value)
        s = self.string(value, path)
        if not LINK_RE.fullmatch(s):
            raise self.fail(path, f"expected a link number like \"2\" (got {s!r})")
        return s

    def boolean(self, value: Any, path: str) -> bool:
        if not isinstance(value, bool):
            raise self.fail(path, f"expected true or false (got {_typename(value)} {value!r})")
        return value

    def array(self, value: Any, path: str, length: int | None = None, minlen: int = 0) -> list:
        if not isinstance(value, list):
            raise self.fail(path, f"expected an array (got {_typename(value)})")
        if length is not None and len(value) != length:
            raise self.fail(path, f"expected {length} items (got {len(value)})")
        if len(value) < minlen:
            raise self.fail(path, f"expected at least {minlen} items (got {len(value)})")
        return value

    def xy(self, value: Any, path: str, unit: float) -> tuple[float, float]:
        items = self.array(value, path, 2)
        lim = MAX_LENGTH_M / unit
        return (
            self.number(items[0], f"{path}[0]", lo=-lim, hi=lim) * unit,
            self.number(items[1], f"{path}[1]", lo=-lim, hi=lim) * unit,
        )

    def length(self, value: Any, path: str, unit: float, *, signed: bool = False) -> float:
        """A length in the variant's unit, converted to metres, at most 1 km."""
        lim = MAX_LENGTH_M / unit
        if signed:
            return self.number(value, path, lo=-lim, hi=lim) * unit
        return self.number(value, path, positive=True, hi=lim) * unit


_MARKUP = re.compile(r"[<>&|`\\]")  # markup in Markdown, HTML and the CSV tables


def _typename(value: Any) -> str:
    return {dict: "table", list: "array", str: "string", bool: "boolean"}.get(
        type(value), type(value).__name__
    )


def _join(path: str, key: str) -> str:
    return f"{path}.{key}" if path else key


def load(path: str | Path) -> Mechanism:
    """Load and validate a variant file.

    Parameters
    ----------
    path : str or Path
        The TOML file.

    Returns
    -------
    Mechanism
        In SI units (m, kg, N, rad, rad/s).

    Raises
    ------
    InputError
        For any problem with the file, naming the file and the key.
    """
    path = Path(path)
    source = str(path)
    from ..files import read_input

    raw = read_input(path)  # a regular file, bounded in size (no FIFO, no /dev/zero)
    return loads(decode_text(raw, source), source=source)  # BOM, CRLF, "save as UTF-8"


def loads(text: str, source: str = "<string>") -> Mechanism:
    """Validate a variant given as TOML text (see :func:`load`)."""
    data = parse_toml(text, source)
    mech = _build(data, _Reader(source))
    _refuse_control_characters(data, source)
    return mech


def _refuse_control_characters(data, source: str, key: str = "") -> None:
    """Every text of a variant reaches the sheets (XML), the tables and the terminal: a
    control character (an escape sequence, U+0008 …) is refused at load, naming the key."""
    from ..safe_text import control_character

    items = data.items() if isinstance(data, dict) else enumerate(data)
    for k, v in items:
        where = f"{key}.{k}" if isinstance(k, str) and key else (k if isinstance(k, str)
                                                                   else f"{key}[{k}]")
        for text in ((k, v) if isinstance(k, str) else (v,)):
            if isinstance(text, str):
                bad = control_character(text)
                if bad is not None:
                    raise InputError(f"{source}: {where}: a control character ({bad}) in "
                                     "the text: not allowed")
        if isinstance(v, dict | list):
            _refuse_control_characters(v, source, where)


#: Sections and keys a variant may use for a driving link that does not turn fully about a
#: frame pivot: a hydraulic or pneumatic cylinder, a slider pushed along a guide.
DRIVER_SECTIONS = ("driver", "actuator", "cylinder", "slider")
DRIVER_KEYS = ("kind", "type", "guide", "stroke")
TRANSLATING = ("slider", "translating", "linear", "prismatic", "cylinder", "hydraulic",
               "pneumatic", "piston", "ползун", "гидроцилиндр", "цилиндр")


def _translating(table: dict) -> str | None:
    """The key of ``table`` that makes it a translating driver (None: none does)."""
    for k in DRIVER_KEYS:
        if k not in table:
            continue
        v = table[k]
        if k in ("guide", "stroke") or (isinstance(v, str) and v.strip().lower() in TRANSLATING):
            return k
    return None


def _refuse_translating_driver(data: dict, r: _Reader) -> None:
    """A translating driving link is not a crank: one line saying why graphplan needs one."""
    why = ("graphplan's initial mechanism is a crank turning fully about a frame pivot at a "
           "constant speed (rpm or omega): a translating driving link (a hydraulic or "
           "pneumatic cylinder) has no ω1 to reduce Mур, Mпр and Jпр to; give the rotating "
           "link that drives the machine as [crank]")
    for sec in DRIVER_SECTIONS:
        if sec not in data or sec in SECTIONS:
            continue
        table = data[sec] if isinstance(data[sec], dict) else {}
        if sec != "driver" or _translating(table):
            raise r.fail(sec, f"a translating driver is not supported: {why}")
        raise r.fail(sec, "the driving link is described in [crank] (link, joints = [pivot, "
                     "pin], length, rpm or omega, direction)")
    crank = data.get("crank")
    if isinstance(crank, dict):
        k = _translating({x: v for x, v in crank.items() if x not in (SECTIONS["crank"] or ())})
        if k is not None:
            raise r.fail(f"crank.{k}", f"the driving link must turn, not slide: {why}")


def _build(data: dict, r: _Reader) -> Mechanism:
    """The variant's sections read in the order they depend on one another.

    Each section has its own reader below; a later one sees the links and points the
    earlier ones defined (:class:`_Known`), so a key naming a point or a link that comes
    later is refused with the ones known so far.
    """
    _refuse_translating_driver(data, r)
    _check_sections(data, r)
    name, unit_name, unit = _variant(data, r)
    frame_points, known = _frame(data, r, unit)
    crank = _crank(data["crank"], r, known, unit)
    points = _ExtraPoints(data, r, unit)
    points.place(known)
    dyads = _dyads(data, r, known, unit, points)
    points.refuse_unplaced(known)
    g, gravity = _gravity(data, r)
    links = _masses(data, r, known, crank.link, g)
    output = _output(data, r, known, dyads)
    positions = _positions(data, r)
    resistances = _loads(r, data, dict(
        frame_link=known.frame, link_points=known.link_points, link_order=known.order,
        known_points=known.points, dyads=dyads, crank=crank, output=output, unit=unit,
        cycle=positions.cycle))
    settings = {
        sec: data[sec]
        for sec in ("kinetostatics", "dynamics", "drawing", "title_block", "variant")
        if sec in data
    }
    _check_settings(r, settings)
    return Mechanism(
        name=name,
        source=r.source,
        frame_link=known.frame,
        frame_points=frame_points,
        crank=crank,
        dyads=tuple(dyads),
        points=tuple(points.placed),
        links=links,
        gravity=gravity,
        resistances=tuple(resistances),
        positions=positions,
        output=output,
        length_unit=unit_name,
        settings=settings,
    )


class _Known:
    """The links and points the sections read so far have defined.

    ``points`` maps a point to its home link, ``link_points`` a link to its points (in the
    order they were defined), ``order`` the links in the order they were defined.
    """

    def __init__(self, r: _Reader, frame: str, frame_points: list[str]):
        self.r = r
        self.frame = frame
        self.points: dict[str, str] = {p: frame for p in frame_points}
        self.link_points: dict[str, list[str]] = {frame: list(frame_points)}
        self.order: list[str] = [frame]

    def point(self, value: Any, path: str, *, known: bool) -> str:
        """A point's name: one defined before (``known``) or a new one."""
        p = self.r.name(value, path)
        if known and p not in self.points:
            have = ", ".join(self.points) or "none"
            raise self.r.fail(path, f"point {p!r} is not defined before this (known: {have})")
        if not known and p in self.points:
            raise self.r.fail(path, f"point {p!r} is already defined; a new joint needs a new "
                              "name")
        return p

    def link(self, value: Any, path: str, *, known: bool) -> str:
        """A link's name (one defined before when ``known``)."""
        ln = self.r.link(value, path)
        if known and ln not in self.link_points:
            have = ", ".join(self.order)
            raise self.r.fail(path, f"link {ln!r} is not defined before this (known: {have})")
        return ln

    def on_link(self, value: Any, path: str, ln: str) -> str:
        """The name of a point of link ``ln``."""
        p = self.r.name(value, path)
        if p not in self.link_points[ln]:
            raise self.r.fail(path, f"point {p!r} is not on link {ln!r} "
                              f"(its points: {', '.join(self.link_points[ln])})")
        return p

    def add(self, point: str, ln: str) -> None:
        """Point ``point`` is now known, on link ``ln``."""
        self.points[point] = ln
        self.link_points[ln].append(point)


def _check_sections(data: dict, r: _Reader) -> None:
    """Only known sections, the required ones present, and only known keys in each."""
    r.keys(data, "", set(SECTIONS), {"frame", "crank", "dyads"})
    for sec, allowed in SECTIONS.items():
        if sec in data and allowed is not None:
            r.keys(r.table(data[sec], sec), sec, allowed)


def _variant(data: dict, r: _Reader) -> tuple[str, str, float]:
    """``[variant]``: the name, the length unit's name and its size in metres."""
    variant = r.table(data.get("variant", {}), "variant")
    unit_name = r.string(variant.get("length_unit", "m"), "variant.length_unit",
                         tuple(LENGTH_UNITS))
    name = r.string(variant.get("name", Path(r.source).stem), "variant.name")
    return name, unit_name, LENGTH_UNITS[unit_name]


def _frame(data: dict, r: _Reader, unit: float) -> tuple[dict[str, tuple[float, float]], _Known]:
    """``[frame]``: the frame link and its fixed points (in metres)."""
    frame = r.table(data["frame"], "frame")
    r.keys(frame, "frame", SECTIONS["frame"], {"link", "points"})
    frame_link = r.link(frame["link"], "frame.link")
    fpts = r.table(frame["points"], "frame.points")
    frame_points: dict[str, tuple[float, float]] = {}
    for k, v in fpts.items():
        r.name(k, f"frame.points.{k}")
        frame_points[k] = r.xy(v, f"frame.points.{k}", unit)
    if not frame_points:
        raise r.fail("frame.points", "expected at least one fixed point (the crank pivot)")
    return frame_points, _Known(r, frame_link, list(frame_points))


def _crank(crank_t: dict, r: _Reader, known: _Known, unit: float) -> Crank:
    """``[crank]``, the driving link: its pivot on the frame, its pin, length and speed."""
    r.keys(crank_t, "crank", SECTIONS["crank"], {"link", "joints", "length"})
    crank_link = r.link(crank_t["link"], "crank.link")
    if crank_link == known.frame:
        raise r.fail("crank.link", f"the crank cannot be the frame link {known.frame!r}")
    cj = r.array(crank_t["joints"], "crank.joints", 2)
    pivot = known.point(cj[0], "crank.joints[0]", known=True)
    if known.points[pivot] != known.frame:
        raise r.fail("crank.joints[0]", f"the crank pivot {pivot!r} must be a frame point")
    pin = known.point(cj[1], "crank.joints[1]", known=False)
    length = r.length(crank_t["length"], "crank.length", unit)
    rpm, omega = _crank_speed(crank_t, r)
    known.points[pin] = crank_link
    known.link_points[crank_link] = [pivot, pin]
    known.order.append(crank_link)
    return Crank(crank_link, pivot, pin, length, rpm, omega)


def _crank_speed(crank_t: dict, r: _Reader) -> tuple[float, float]:
    """The crank's speed: n1 in rpm and the signed ω1 in rad/s (+ counter-clockwise).

    Given as ``rpm`` (n1) or ``omega`` (ω1, rad/s); ω1 = π·n1/30, its sign from
    ``direction``.
    """
    if "rpm" not in crank_t and "omega" not in crank_t:
        raise r.fail("crank.rpm", "missing required key: the crank speed, 'rpm' (n1, rpm) "
                     "or 'omega' (ω1, rad/s)")
    if "rpm" in crank_t and "omega" in crank_t:
        raise r.fail("crank.omega", "give the crank speed once: either 'rpm' (n1, rpm) or "
                     "'omega' (ω1, rad/s), not both")
    if "rpm" in crank_t:
        rpm = r.number(crank_t["rpm"], "crank.rpm", positive=True, hi=MAX_RPM)
    else:  # ω1 in rad/s, as many assignment books give it; n1 = 30·ω1/π
        w1 = r.number(crank_t["omega"], "crank.omega", positive=True,
                      hi=MAX_RPM * math.pi / 30.0)
        rpm = w1 * 30.0 / math.pi
    direction = r.string(crank_t.get("direction", "ccw"), "crank.direction", ("ccw", "cw"))
    omega = math.pi * rpm / 30.0 * (1.0 if direction == "ccw" else -1.0)
    if "omega" in crank_t:
        omega = math.copysign(float(crank_t["omega"]), omega)  # exactly as given
    return rpm, omega


POINT_KEYS = {"name", "link", "from", "toward", "along", "across", "fraction"}


class _ExtraPoints:
    """``[[points]]``: points defined on a link, placed as soon as their link is known."""

    def __init__(self, data: dict, r: _Reader, unit: float):
        self.r = r
        self.unit = unit
        raw_points = data.get("points", [])
        r.array(raw_points, "points")
        self.pending: list[tuple[int, dict]] = []
        for n, pt in enumerate(raw_points):
            path = f"points[{n}]"
            r.table(pt, path)
            r.keys(pt, path, POINT_KEYS, {"name", "link", "from"})
            self.pending.append((n, pt))
        self.placed: list[PointOnLink] = []

    def place(self, known: _Known) -> None:
        """Place every pending point whose link is known (a point may stand on another)."""
        progress = True
        while progress:
            progress = False
            for item in list(self.pending):
                n, pt = item
                ln = self.r.link(pt["link"], f"points[{n}].link")
                if ln not in known.link_points:
                    continue
                self.placed.append(self._point(f"points[{n}]", pt, ln, known))
                self.pending.remove(item)
                progress = True

    def _point(self, path: str, pt: dict, ln: str, known: _Known) -> PointOnLink:
        r = self.r
        nm = known.point(pt["name"], f"{path}.name", known=False)
        origin = known.on_link(pt["from"], f"{path}.from", ln)
        toward = None
        if "toward" in pt:
            toward = known.on_link(pt["toward"], f"{path}.toward", ln)
            if toward == origin:
                raise r.fail(f"{path}.toward", "must differ from 'from'")
        fraction = None
        if "fraction" in pt:
            if toward is None:
                raise r.fail(f"{path}.fraction", "needs 'toward' (fraction of from→toward)")
            if "along" in pt:
                raise r.fail(f"{path}.fraction", "give either 'fraction' or 'along', not both")
            fraction = r.number(pt["fraction"], f"{path}.fraction", lo=-100, hi=100)
        along = r.length(pt.get("along", 0.0), f"{path}.along", self.unit, signed=True)
        across = r.length(pt.get("across", 0.0), f"{path}.across", self.unit, signed=True)
        known.add(nm, ln)
        return PointOnLink(nm, ln, origin, toward, along, across, fraction)

    def refuse_unplaced(self, known: _Known) -> None:
        """A point left pending names a link that no section defined."""
        if self.pending:
            n, pt = self.pending[0]
            raise self.r.fail(f"points[{n}].link", f"link {pt['link']!r} is not a link of this "
                              f"mechanism (links: {', '.join(known.order)})")


#: Keys of a dyad beyond kind, links, joints and branch: (allowed, required) by kind.
DYAD_KEYS = {
    "RRR": ({"lengths"}, {"lengths"}),
    "RRP": ({"length", "guide"}, {"length", "guide"}),
    "RPR": ({"offset"}, set()),
    "PRP": ({"guides"}, {"guides"}),
    "RPP": ({"guide", "slot_angle"}, {"guide"}),
}


def _dyads(data: dict, r: _Reader, known: _Known, unit: float,
           points: _ExtraPoints) -> list[Dyad]:
    """``[[dyads]]``: the Assur groups in the order they are attached."""
    dyads: list[Dyad] = []
    for n, dt in enumerate(r.array(data["dyads"], "dyads", minlen=1)):
        dyad = _dyad(dt, f"dyads[{n}]", r, known, unit)
        dyads.append(dyad)
        li, lj = dyad.links
        for p in dyad.new_points:
            known.points[p] = li if dyad.kind != "RPP" else lj
        for ln in (li, lj):
            if ln not in known.link_points:
                known.link_points[ln] = []
                known.order.append(ln)
        for ln, ps in zip((li, lj), dyad.points_on_links, strict=True):
            for p in ps:
                if p not in known.link_points[ln]:
                    known.link_points[ln].append(p)
        points.place(known)
    return dyads


def _dyad(dt: Any, path: str, r: _Reader, known: _Known, unit: float) -> Dyad:
    """One dyad: its kind, two new links, joints, branch and the geometry its kind needs."""
    r.table(dt, path)
    kind = r.string(dt.get("kind"), f"{path}.kind", DYAD_KINDS) if "kind" in dt else None
    if kind is None:
        raise r.fail(f"{path}.kind", "missing required key")
    allowed, required = DYAD_KEYS[kind]
    r.keys(dt, path, {"kind", "links", "joints", "branch"} | allowed,
           {"kind", "links", "joints"} | required)
    lk = r.array(dt["links"], f"{path}.links", 2)
    li = known.link(lk[0], f"{path}.links[0]", known=False)
    lj = known.link(lk[1], f"{path}.links[1]", known=False)
    jt = r.array(dt["joints"], f"{path}.joints", JOINT_COUNT[kind])
    new_idx = NEW_JOINTS[kind]
    joints = tuple(
        known.point(v, f"{path}.joints[{m}]", known=m not in new_idx) for m, v in enumerate(jt)
    )
    if len(set(joints)) != len(joints):
        raise r.fail(f"{path}.joints", f"joints must be distinct (got {list(joints)})")
    branch_s = r.string(dt.get("branch", "+"), f"{path}.branch", ("+", "-"))
    branch = 1 if branch_s == "+" else -1
    lengths, guides, offset, slot_angle = _dyad_geometry(kind, dt, path, r, known, unit)
    outer = [joints[m] for m in range(len(joints)) if m not in new_idx]
    if (outer and all(known.points.get(p) == known.frame for p in outer)
            and all(g.link == known.frame for g in guides)):
        raise r.fail(f"{path}.joints", "the group is attached to the frame only (joints "
                     f"{', '.join(outer)} are frame points): it cannot move — attach it "
                     "to a moving link's point")
    return Dyad(kind, (li, lj), joints, lengths, guides, offset, slot_angle, branch)


def _dyad_geometry(kind: str, dt: dict, path: str, r: _Reader, known: _Known, unit: float
                   ) -> tuple[tuple[float, ...], tuple[Guide, ...], float, float]:
    """A dyad's lengths, guides, offset and slot angle (radians), as its kind has them."""
    lengths: tuple[float, ...] = ()
    guides: tuple[Guide, ...] = ()
    offset = 0.0
    slot_angle = 0.0
    if kind == "RRR":
        ls = r.array(dt["lengths"], f"{path}.lengths", 2)
        lengths = tuple(r.length(v, f"{path}.lengths[{m}]", unit) for m, v in enumerate(ls))
    elif kind == "RRP":
        lengths = (r.length(dt["length"], f"{path}.length", unit),)
        guides = (_guide(r, dt["guide"], f"{path}.guide", known.link_points, known.frame,
                         unit),)
    elif kind == "RPR":
        offset = r.length(dt.get("offset", 0.0), f"{path}.offset", unit, signed=True)
    elif kind == "PRP":
        gs = r.array(dt["guides"], f"{path}.guides", 2)
        guides = tuple(
            _guide(r, g, f"{path}.guides[{m}]", known.link_points, known.frame, unit)
            for m, g in enumerate(gs)
        )
    elif kind == "RPP":
        guides = (_guide(r, dt["guide"], f"{path}.guide", known.link_points, known.frame,
                         unit),)
        slot_angle = math.radians(r.number(dt.get("slot_angle", 90.0), f"{path}.slot_angle"))
        if abs(math.sin(slot_angle)) < 1e-6:
            raise r.fail(f"{path}.slot_angle",
                         "the slot must not be parallel to the guide (got "
                         f"{dt.get('slot_angle', 90.0)!r}°)")
    return lengths, guides, offset, slot_angle


def _gravity(data: dict, r: _Reader) -> tuple[float, tuple[float, float]]:
    """``[gravity]``: g (it also turns weights G into masses m = G/g) and its vector."""
    grav = r.table(data.get("gravity", {}), "gravity")
    g_on = r.boolean(grav.get("enabled", True), "gravity.enabled")
    g = r.number(grav.get("g", 9.81), "gravity.g", nonneg=True, hi=1e3)
    g_ang = math.radians(r.number(grav.get("angle", -90.0), "gravity.angle"))
    gravity = (g * math.cos(g_ang), g * math.sin(g_ang)) if g_on else (0.0, 0.0)
    gx, gy = (0.0 if abs(c) < 1e-12 * max(g, 1.0) else c for c in gravity)
    return g, (gx, gy)


def _masses(data: dict, r: _Reader, known: _Known, crank_link: str, g: float
            ) -> dict[str, LinkProps]:
    """``[links]`` (and the crank's own mass keys): each moving link's mass and inertia."""
    crank_t = data["crank"]
    raw_links = r.table(data.get("links", {}), "links")
    crank_props = {k: crank_t[k] for k in ("mass", "weight", "inertia", "centre")
                   if k in crank_t}
    if crank_props:
        raw_links = {**raw_links}
        if crank_link in raw_links:
            raise r.fail(f"links.{crank_link}", "crank mass given twice (in [crank] and [links])")
        raw_links[crank_link] = crank_props
    links: dict[str, LinkProps] = {}
    for ln, props in raw_links.items():
        path = f"links.{ln}"
        r.link(ln, path)
        if ln not in known.link_points or ln == known.frame:
            raise r.fail(path, f"not a moving link of this mechanism (moving links: "
                         f"{', '.join(x for x in known.order if x != known.frame)})")
        links[ln] = _link_props(props, path, ln, r, known, g)
    return links


def _link_props(props: Any, path: str, ln: str, r: _Reader, known: _Known, g: float
                ) -> LinkProps:
    """One link's mass (kg, or a weight G in N: m = G/g), inertia and centre of mass."""
    r.table(props, path)
    r.keys(props, path, {"mass", "weight", "inertia", "centre"})
    if "weight" in props:  # G in N, as assignment books often give it: m = G/g
        if "mass" in props:
            raise r.fail(f"{path}.weight", "give either 'mass' (kg) or 'weight' (N), not both")
        if g <= 0:
            raise r.fail(f"{path}.weight", "a weight needs gravity.g > 0 to give the mass")
        mass = r.number(props["weight"], f"{path}.weight", nonneg=True, hi=1e10) / g
    else:
        mass = r.number(props.get("mass", 0.0), f"{path}.mass", nonneg=True, hi=1e9)
    inertia = r.number(props.get("inertia", 0.0), f"{path}.inertia", nonneg=True, hi=1e12)
    centre = None
    if "centre" in props:
        centre = known.on_link(props["centre"], f"{path}.centre", ln)
    elif mass > 0:
        raise r.fail(f"{path}.centre", "a link with mass needs its centre of mass point")
    return LinkProps(mass, inertia, centre)


def _output(data: dict, r: _Reader, known: _Known, dyads: list[Dyad]) -> Output:
    """``[output]``: the output link (the last dyad's second by default), its working sense."""
    out_t = r.table(data.get("output", {}), "output")
    out_link = dyads[-1].links[1]
    if "link" in out_t:
        out_link = known.link(out_t["link"], "output.link", known=True)
        if out_link == known.frame:
            raise r.fail("output.link", "the output cannot be the frame")
    working = 1 if r.string(out_t.get("working", "+"), "output.working", ("+", "-")) == "+" else -1
    return Output(out_link, working)


def _positions(data: dict, r: _Reader) -> Positions:
    """``[positions]``: how many plans, where they start, extra positions, the cycle."""
    pos_t = r.table(data.get("positions", {}), "positions")
    count = r.integer(pos_t.get("count", 8), "positions.count", 1, 3600)
    first_raw = pos_t.get("first", "start")
    if isinstance(first_raw, str):
        first: str | float = r.string(first_raw, "positions.first", ("start", "end"))
    else:
        first = math.radians(r.number(first_raw, "positions.first"))
    number_from = r.integer(pos_t.get("number_from", 1), "positions.number_from", 0, 1)
    labels = {str(number_from + k) for k in range(count)}
    extras = [_extra_position(et, f"positions.extra[{n}]", r, labels)
              for n, et in enumerate(r.array(pos_t.get("extra", []), "positions.extra"))]
    cycle_deg = r.integer(pos_t.get("cycle", 360), "positions.cycle", 360, 720)
    if cycle_deg not in (360, 720):
        raise r.fail("positions.cycle", f"expected 360 (one turn) or 720 (two turns: a "
                     f"four-stroke process) (got {cycle_deg})")
    return Positions(count, first, number_from, tuple(extras), cycle_deg)


def _extra_position(et: Any, path: str, r: _Reader, labels: set[str]) -> ExtraPosition:
    """One ``[[positions.extra]]``: a labelled position by angle, dead centre or stroke."""
    r.table(et, path)
    r.keys(et, path, {"label", "phi", "from", "turn", "stroke"}, {"label"})
    label = r.string(et["label"], f"{path}.label")
    if not label.strip():
        raise r.fail(f"{path}.label", "must not be empty")
    if _CONTROL.search(label):
        raise r.fail(f"{path}.label", f"expected a one-line label (got {label!r})")
    if _MARKUP.search(label) or "/" in label:  # a label is a cell, a heading, a file name
        raise r.fail(f"{path}.label", f"expected a label without < > & | ` / \\ "
                     f"(got {label!r})")
    if label in labels:
        raise r.fail(f"{path}.label", f"label {label!r} is already used")
    labels.add(label)
    ways = [k for k in ("phi", "from", "stroke") if k in et]
    if len(ways) != 1:
        raise r.fail(path, "give exactly one of 'phi' (crank angle, °), 'from' (dead centre "
                     "with 'turn'), 'stroke' (travel fraction of the working stroke)")
    if "turn" in et and "from" not in et:
        raise r.fail(f"{path}.turn", "goes with 'from'")
    if "phi" in et:
        return ExtraPosition(label, phi=math.radians(r.number(et["phi"], f"{path}.phi")))
    if "from" in et:
        return ExtraPosition(
            label,
            from_dead_centre=r.string(et["from"], f"{path}.from", ("start", "end")),
            turn=math.radians(r.number(et.get("turn", 0.0), f"{path}.turn", lo=-360, hi=360)),
        )
    return ExtraPosition(label, stroke=r.number(et["stroke"], f"{path}.stroke", lo=0.0, hi=1.0))


def _guide(r: _Reader, value: Any, path: str, link_points, frame_link: str, unit: float) -> Guide:
    g = r.table(value, path)
    r.keys(g, path, {"link", "through", "angle", "toward"}, {"link", "through"})
    ln = r.link(g["link"], f"{path}.link")
    if ln not in link_points:
        raise r.fail(f"{path}.link", f"link {ln!r} is not defined before this dyad "
                     f"(known: {', '.join(link_points)})")
    through = None
    xy = None
    if isinstance(g["through"], list):
        if ln != frame_link:
            raise r.fail(f"{path}.through", "coordinates are allowed for a frame guide only; "
                         "on a moving link name a point of it")
        xy = r.xy(g["through"], f"{path}.through", unit)
    else:
        through = r.name(g["through"], f"{path}.through")
        if through not in link_points[ln]:
            raise r.fail(f"{path}.through", f"point {through!r} is not on link {ln!r} "
                         f"(its points: {', '.join(link_points[ln])})")
    if "angle" in g and "toward" in g:
        raise r.fail(path, "give either 'angle' or 'toward', not both")
    toward = None
    if "toward" in g:
        toward = r.name(g["toward"], f"{path}.toward")
        if toward not in link_points[ln] or toward == through:
            raise r.fail(f"{path}.toward", f"expected another point of link {ln!r} "
                         f"(its points: {', '.join(link_points[ln])})")
    angle = math.radians(r.number(g.get("angle", 0.0), f"{path}.angle"))
    return Guide(ln, through, xy, angle, toward)


def _translates_on_frame(link: str, dyads: list[Dyad], frame_link: str) -> bool:
    for d in dyads:
        if d.kind in ("RRP", "RPP") and d.links[1] == link:
            return d.guides[0].link == frame_link
        if d.kind == "PRP" and link in d.links:
            return d.guides[d.links.index(link)].link == frame_link
    return False


def _rotates_about_frame(link, dyads, crank, known_points, frame_link) -> bool:
    if link == crank.link:
        return True
    for d in dyads:
        if d.kind in ("RRR", "RPR") and d.links[1] == link:
            pivot = d.joints[-1]
            return known_points.get(pivot) == frame_link
    return False


def _check_settings(r: _Reader, settings: dict) -> None:
    """Validate the values of the settings that later stages read."""
    _check_kinetostatics(r, settings.get("kinetostatics", {}))
    dyn = settings.get("dynamics", {})
    _check_dynamics(r, dyn)
    if "flywheel" in dyn:
        _check_flywheel(r, dyn["flywheel"])
    drw = settings.get("drawing", {})
    _check_drawing(r, drw)
    for sec, table in (("kinetostatics", settings.get("kinetostatics", {})), ("drawing", drw)):
        for key in ("positions", "accelerations"):
            if key in table:
                _check_position_labels(r, table[key], f"{sec}.{key}")
    for key, value in settings.get("title_block", {}).items():
        if key in ("sheet", "sheets"):
            r.integer(value, f"title_block.{key}", 1, 99)
        else:
            r.string(value, f"title_block.{key}")
    var = settings.get("variant", {})
    if "description" in var:
        r.string(var["description"], "variant.description")


def _check_kinetostatics(r: _Reader, kin: dict) -> None:
    """``[kinetostatics]``: the neglect rule's share and the two switches."""
    if "neglect_below" in kin:
        r.number(kin["neglect_below"], "kinetostatics.neglect_below", lo=0.0, hi=1.0)
    for key in ("inertia", "shift_inertia_force"):
        if key in kin:
            r.boolean(kin[key], f"kinetostatics.{key}")


def _check_dynamics(r: _Reader, dyn: dict) -> None:
    """``[dynamics]``: δ, η, the crank's inertia, the grids and the motor's choice."""
    for key in ("delta", "efficiency"):
        if key in dyn:
            r.number(dyn[key], f"dynamics.{key}", positive=True, hi=1.0)
    if "crank_inertia" in dyn:
        r.number(dyn["crank_inertia"], "dynamics.crank_inertia", nonneg=True)
    for key, lo, hi in (("grid", 12, 100000), ("intervals", 4, 720)):
        if key in dyn:
            r.integer(dyn[key], f"dynamics.{key}", lo, hi)
    if "motor_series" in dyn:
        s = r.string(dyn["motor_series"], "dynamics.motor_series")
        if s.strip().upper() not in MOTOR_SERIES:
            raise r.fail("dynamics.motor_series", "expected a bundled motor series, one of "
                         f"{', '.join(MOTOR_SERIES)} (got {s!r})")
    if "motor_speed" in dyn:
        speed = r.integer(dyn["motor_speed"], "dynamics.motor_speed", 1, 100000)
        if speed not in SYNC_SPEEDS:
            raise r.fail("dynamics.motor_speed", "expected a synchronous speed at 50 Hz, one "
                         f"of {', '.join(map(str, SYNC_SPEEDS))} rpm (got {speed})")


def _check_flywheel(r: _Reader, value: Any) -> None:
    """``[dynamics.flywheel]``: its shape, shaft and proportions."""
    fw = r.table(value, "dynamics.flywheel")
    r.keys(fw, "dynamics.flywheel", {"shape", "shaft", "b_ratio", "h_ratio", "density"})
    for key, choices in (("shape", ("rim", "disc")), ("shaft", ("crank", "motor"))):
        if key in fw:
            r.string(fw[key], f"dynamics.flywheel.{key}", choices)
    for key, hi in (("b_ratio", 1.0), ("h_ratio", 0.5), ("density", 30000.0)):
        if key in fw:
            r.number(fw[key], f"dynamics.flywheel.{key}", positive=True, hi=hi)


def _check_drawing(r: _Reader, drw: dict) -> None:
    """``[drawing]``: the scales, the reading step, the sheet format and language."""
    for key in ("Kl", "Kv", "Ka", "Kp"):
        if key in drw:
            r.number(drw[key], f"drawing.{key}", positive=True)
    if "reading_mm" in drw:
        r.number(drw["reading_mm"], "drawing.reading_mm", nonneg=True, hi=5.0)
    for key, choices in (("format", ("A1", "A2", "A3")), ("language", ("ru", "en"))):
        if key in drw:
            r.string(drw[key], f"drawing.{key}", choices)


def _check_position_labels(r: _Reader, value: Any, path: str) -> None:
    """A list of position labels, each given once."""
    labels = r.array(value, path, minlen=1)
    for i, lab in enumerate(labels):
        r.string(lab, f"{path}[{i}]")
    if len(set(labels)) != len(labels):
        raise r.fail(path, "expected each position label once")


def _loads(r: _Reader, data: dict, ctx: dict) -> list[Resistance]:
    """The ``[[loads]]``: forces and couples on any moving link (docs/variant-format.md §6.2).

    Each load's diagram is stored per stroke of the cycle (``Resistance.strokes``) or over
    the crank's travel in radians; a bare ``diagram`` keeps the classical meaning: the
    output's working stroke, resisting.
    """
    names: set[str] = set()
    read = [_load(r, lt, f"loads[{n}]", ctx, names)
            for n, lt in enumerate(r.array(data.get("loads", []), "loads"))]
    if ctx["cycle"] == 720 and not any(two for _, two in read):
        raise r.fail("positions.cycle", "a 720° cycle needs a process over two turns — a load "
                     "with 4 different strokes (a four-stroke indicator diagram) or a diagram "
                     "over the crank angle to 720°; no load has one (use 360)")
    return [load for load, _ in read]


def _load(r: _Reader, lt: Any, path: str, ctx: dict, names: set[str]
          ) -> tuple[Resistance, bool]:
    """One ``[[loads]]`` table, and whether its process takes two turns of the crank (a
    720° cycle's diagram over the crank angle, or strokes that differ between the turns).
    The keys are read in the order of the errors a student meets first: what and where
    the load is, its sense, its abscissa, its scale, its diagram."""
    r.table(lt, path)
    r.keys(lt, path, LOAD_KEYS, {"link"})
    gas = "bore" in lt
    kind = _load_kind(r, lt, path, gas)
    ln = _load_link(r, lt, path, ctx)
    name = _load_name(r, lt, path, names)
    point = _load_point(r, lt, path, kind, ln, gas, ctx)
    slider, sense, angle = _load_sense(r, lt, path, kind, ln, gas, ctx)
    over = r.string(lt.get("over", "stroke"), f"{path}.over", ("stroke", "crank"))
    tl = _travel_link(r, lt, path, ln, slider, ctx)
    working = ctx["output"].working
    if "working" in lt:
        working = 1 if r.string(lt["working"], f"{path}.working", ("+", "-")) == "+" else -1
    phase = math.radians(r.number(lt.get("phase", 0.0), f"{path}.phase", lo=0.0,
                                  hi=float(ctx["cycle"])))
    if gas:
        maximum, offset, const = *_gas_scale(r, lt, path, ctx["unit"]), 0.0
    else:
        (maximum, const), offset = _value_scale(r, lt, path, kind, sense), 0.0
    strokes, over, two_turns = _load_strokes(r, lt, path, over, sense == "diagram", const,
                                             ctx["cycle"])
    first = next((d for d in strokes if d is not None), ())
    return Resistance(kind, ln, point, maximum, tuple(first), name, sense, over, strokes,
                      angle, tl, working, phase, offset, gas), two_turns


def _load_kind(r: _Reader, lt: dict, path: str, gas: bool) -> str:
    """``kind``: a force or a moment (a gas force, given by its bore, is a force)."""
    if "kind" in lt:
        return r.string(lt["kind"], f"{path}.kind", ("force", "moment"))
    if gas:
        return "force"
    raise r.fail(f"{path}.kind", "missing required key ('force' or 'moment')")


def _load_link(r: _Reader, lt: dict, path: str, ctx: dict) -> str:
    """``link``: a moving link of the mechanism."""
    frame_link, link_points = ctx["frame_link"], ctx["link_points"]
    ln = r.link(lt["link"], f"{path}.link")
    if ln == frame_link:
        raise r.fail(f"{path}.link", "a load acts on a moving link, not the frame")
    if ln not in link_points:
        moving = [x for x in ctx["link_order"] if x != frame_link]
        raise r.fail(f"{path}.link", f"link {ln!r} is not a link of this mechanism "
                     f"(moving links: {', '.join(moving)})")
    return ln


def _load_name(r: _Reader, lt: dict, path: str, names: set[str]) -> str | None:
    """``name``: a short one-line name, each load's its own (None: named by its kind)."""
    if "name" not in lt:
        return None
    name = r.string(lt["name"], f"{path}.name").strip()
    if not name or _CONTROL.search(name) or _MARKUP.search(name) or len(name) > 12:
        raise r.fail(f"{path}.name", f"expected a short one-line name like 'Fг' "
                     f"(got {lt['name']!r})")
    if name in names:
        raise r.fail(f"{path}.name", f"name {name!r} is already used by another load")
    names.add(name)
    return name


def _load_point(r: _Reader, lt: dict, path: str, kind: str, ln: str, gas: bool, ctx: dict
                ) -> str | None:
    """``point``: where a force acts, on its link; a couple has none and must do work."""
    frame_link, dyads = ctx["frame_link"], ctx["dyads"]
    point = None
    if kind == "force":
        if "point" not in lt:
            raise r.fail(f"{path}.point", "missing required key (the point the force acts at)")
        point = r.name(lt["point"], f"{path}.point")
        if point not in ctx["link_points"][ln]:
            raise r.fail(f"{path}.point", f"point {point!r} is not on link {ln!r} "
                         f"(its points: {', '.join(ctx['link_points'][ln])})")
    elif "point" in lt:
        raise r.fail(f"{path}.point", "a moment load has no point")
    elif _translates_on_frame(ln, dyads, frame_link):
        raise r.fail(f"{path}.link", f"a couple on link {ln!r}, which only translates on a "
                     "frame guide, does no work (put a force on it)")
    if gas and kind != "force":
        raise r.fail(f"{path}.bore", "a pressure (bore) gives a force on a piston, "
                     "not a moment")
    return point


def _load_sense(r: _Reader, lt: dict, path: str, kind: str, ln: str, gas: bool, ctx: dict
                ) -> tuple[bool, str, float | None]:
    """``sense`` and ``angle``: whether the load resists, drives or follows its diagram's
    sign, and a diagram force's direction (rad) where no frame guide gives one. Returns
    (the link slides on a frame guide, sense, angle)."""
    slider = _translates_on_frame(ln, ctx["dyads"], ctx["frame_link"])
    if gas and not slider:
        raise r.fail(f"{path}.link", f"a gas force (bore) acts on a piston sliding in a "
                     f"frame guide (cylinder); link {ln!r} is not one")
    sense = r.string(lt.get("sense", "diagram" if gas else "resists"), f"{path}.sense",
                     ("resists", "drives", "diagram"))
    angle = None
    if "angle" in lt:
        if kind != "force" or sense != "diagram":
            raise r.fail(f"{path}.angle", "the direction 'angle' goes with a force of "
                         "sense = \"diagram\"; a resisting or driving load follows the motion")
        angle = math.radians(r.number(lt["angle"], f"{path}.angle"))
    elif kind == "force" and sense == "diagram" and not slider:
        raise r.fail(f"{path}.angle", f"missing: the direction of the force (degrees) — "
                     f"link {ln!r} does not slide on a frame guide to give one")
    return slider, sense, angle


def _travel_link(r: _Reader, lt: dict, path: str, ln: str, slider: bool, ctx: dict) -> str:
    """``travel_link``: the link whose travel is the diagram's abscissa (by default the
    loaded link where it slides on or turns about the frame, else the output)."""
    frame_link, link_points = ctx["frame_link"], ctx["link_points"]
    if "travel_link" in lt:
        tl = r.link(lt["travel_link"], f"{path}.travel_link")
        if tl not in link_points or tl == frame_link:
            moving = [x for x in ctx["link_order"] if x != frame_link]
            raise r.fail(f"{path}.travel_link", f"link {tl!r} is not a moving link of this "
                         f"mechanism (moving links: {', '.join(moving)})")
        return tl
    crank = ctx["crank"]
    rocker = _rotates_about_frame(ln, ctx["dyads"], crank, ctx["known_points"], frame_link)
    return ln if (slider or (rocker and ln != crank.link)) else ctx["output"].link


def _gas_scale(r: _Reader, lt: dict, path: str, unit: float) -> tuple[float, float]:
    """A gas force's scale p_max·A and the ambient pressure's force p_ambient·A, N, signed
    along the piston's x (away from the head): A = πD²/4 on the head's side; on the rod's
    side of a double-acting cylinder (``rod`` = d) A = π(D² − d²)/4 and both are negative,
    the pressure pushing the piston toward the head."""
    if "unit" in lt:
        raise r.fail(f"{path}.unit", "a gas force is p·πD²/4: its unit is "
                     "pressure_unit (MPa, bar …), with the bore in the length unit")
    for k in ("max", "value"):
        if k in lt:
            raise r.fail(f"{path}.{k}", "a gas force is p·πD²/4: give the pressures "
                         "(diagram/strokes, p_max) and the bore, not the force")
    D = r.length(lt["bore"], f"{path}.bore", unit)
    area, side = math.pi * D * D / 4.0, 1.0
    if "rod" in lt:  # the rod's side of a double-acting cylinder: the annulus, toward the head
        d = r.length(lt["rod"], f"{path}.rod", unit)
        if d >= D:
            raise r.fail(f"{path}.rod", f"the piston rod's diameter must be less than the "
                         f"bore ({d * 1000:g} mm ≥ {D * 1000:g} mm)")
        area, side = math.pi * (D * D - d * d) / 4.0, -1.0
    pu = r.string(lt.get("pressure_unit", "MPa"), f"{path}.pressure_unit",
                  tuple(PRESSURE_UNITS))
    pmax = r.number(lt.get("p_max", 1.0), f"{path}.p_max", positive=True, hi=1e9)
    pamb = r.number(lt.get("p_ambient", 0.0), f"{path}.p_ambient", nonneg=True, hi=1e9)
    maximum = pmax * PRESSURE_UNITS[pu] * area
    if maximum > MAX_LOAD:
        raise r.fail(f"{path}.p_max", f"p_max·πD²/4 = {maximum:.3g} N is beyond "
                     f"{MAX_LOAD:g} N (check pressure_unit and bore)")
    return side * maximum, side * pamb * PRESSURE_UNITS[pu] * area


def _value_scale(r: _Reader, lt: dict, path: str, kind: str, sense: str
                 ) -> tuple[float, float]:
    """A load's scale in SI (``max`` in its ``unit``; 1 for a constant), and the constant
    ``value`` in SI (0 for a diagram)."""
    for k in ("p_max", "p_ambient", "pressure_unit", "rod"):
        if k in lt:
            raise r.fail(f"{path}.{k}", "goes with 'bore' (a gas force on a piston)")
    units = FORCE_UNITS if kind == "force" else MOMENT_UNITS
    factor = units[r.string(lt.get("unit", "N" if kind == "force" else "N·m"),
                            f"{path}.unit", tuple(units))]
    top = MAX_LOAD / factor
    if "value" in lt:
        for k in ("max", "diagram", "strokes", "travel"):
            if k in lt:
                raise r.fail(f"{path}.{k}", "a constant load is given by 'value' alone")
        lo = -top if sense == "diagram" else 0.0
        return 1.0, r.number(lt["value"], f"{path}.value", lo=lo, hi=top) * factor
    if "max" not in lt:
        raise r.fail(f"{path}.max", "missing required key (the scale of the diagram, "
                     "N or N·m; or give 'value' for a constant load)")
    return r.number(lt["max"], f"{path}.max", nonneg=True, hi=top) * factor, 0.0


def _load_strokes(r: _Reader, lt: dict, path: str, over: str, signed: bool, const: float,
                  cycle: int) -> tuple[tuple, str, bool]:
    """The load's diagram per stroke of the cycle, or over the crank angle (radians): a
    constant over the whole cycle or the strokes named, a diagram over the crank angle,
    one stroke's diagram or one per stroke. Returns (strokes, over, two turns)."""
    n_strokes = 2 * cycle // 360
    if "value" in lt:  # constant: the whole cycle, or the strokes named
        if "stroke" in lt:
            which = r.string(lt["stroke"], f"{path}.stroke", STROKE_SETS)
            d: Diagram = ((0.0, const), (1.0, const))
            return _stroke_set(which, d, n_strokes), over, False
        return (((0.0, const), (math.radians(cycle), const)),), "crank", False
    if over == "crank":
        for k in ("stroke", "strokes", "travel"):
            if k in lt:
                raise r.fail(f"{path}.{k}", "a diagram over the crank angle has no strokes")
        if "diagram" not in lt:
            raise r.fail(f"{path}.diagram", "missing required key (pairs [φ°, value])")
        d = _pairs(r, lt["diagram"], f"{path}.diagram", signed, hi_x=float(cycle))
        _covers(r, d, f"{path}.diagram", float(cycle), "the cycle (crank angle 0 … "
                f"{cycle}°)")
        return (tuple((math.radians(x), v) for x, v in d),), over, cycle == 720
    if "diagram" not in lt and "strokes" not in lt:
        raise r.fail(f"{path}.diagram", "missing required key: 'diagram' (one "
                     "stroke's diagram) or 'strokes' (one diagram per stroke)")
    if "diagram" in lt and "strokes" in lt:
        raise r.fail(f"{path}.diagram", "give either 'diagram' (one stroke's diagram) "
                     "or 'strokes' (one diagram per stroke of the cycle), not both")
    travel = _travel_column(r, lt, path)
    if "diagram" in lt:
        d = _pairs(r, lt["diagram"], f"{path}.diagram", signed, hi_x=1.0)
        _covers(r, d, f"{path}.diagram", 1.0, "the stroke (travel 0 … 1)")
        which = r.string(lt.get("stroke", "working"), f"{path}.stroke", STROKE_SETS)
        return _stroke_set(which, d, n_strokes), over, False
    strokes = _stroke_table(r, lt, path, signed, travel, cycle)
    return strokes, over, cycle == 720 and strokes[:2] != strokes[2:]


def _travel_column(r: _Reader, lt: dict, path: str) -> list[float] | None:
    """``travel``: the travel fractions (0 … 1, not decreasing) of a ``strokes`` table."""
    if "travel" not in lt:
        return None
    if "strokes" not in lt:
        raise r.fail(f"{path}.travel", "goes with 'strokes' (a table: the travel "
                     "column and one column of values per stroke)")
    tv = r.array(lt["travel"], f"{path}.travel", minlen=2)
    travel = [r.number(x, f"{path}.travel[{m}]", lo=0.0, hi=1.0) for m, x in enumerate(tv)]
    for m in range(1, len(travel)):
        if travel[m] < travel[m - 1]:
            raise r.fail(f"{path}.travel[{m}]", "travel fractions must not "
                         f"decrease (got {travel[m]} after {travel[m - 1]})")
    return travel


def _stroke_table(r: _Reader, lt: dict, path: str, signed: bool,
                  travel: list[float] | None, cycle: int) -> tuple:
    """``strokes``: one diagram per stroke of the cycle (an empty one: no load on that
    stroke), as pairs or as a column of values at the ``travel`` fractions."""
    n_strokes = 2 * cycle // 360
    if "stroke" in lt:
        raise r.fail(f"{path}.stroke", "goes with 'diagram'; 'strokes' lists "
                     "every stroke")
    ss = r.array(lt["strokes"], f"{path}.strokes", minlen=1)
    if len(ss) != n_strokes:
        hint = (" (4 strokes: a four-stroke cycle needs positions.cycle = 720)"
                if len(ss) == 4 and cycle == 360 else "")
        raise r.fail(f"{path}.strokes", f"expected {n_strokes} diagrams, one per "
                     f"stroke of the {cycle}° cycle (got {len(ss)}){hint}")
    items: list[Diagram | None] = []
    for m, sd in enumerate(ss):
        sp = f"{path}.strokes[{m}]"
        sd = r.array(sd, sp)
        if not sd:
            items.append(None)
            continue
        if travel is not None:
            if len(sd) != len(travel):
                raise r.fail(sp, f"expected {len(travel)} values, one per 'travel' "
                             f"(got {len(sd)})")
            lo = -MAX_LOAD if signed else 0.0
            vals = [r.number(v, f"{sp}[{k}]", lo=lo, hi=MAX_LOAD) for k, v in enumerate(sd)]
            d: Diagram = tuple(zip(travel, vals, strict=True))
        else:
            d = _pairs(r, sd, sp, signed, hi_x=1.0)
        _covers(r, d, sp, 1.0, "the stroke (travel 0 … 1)")
        items.append(d)
    if all(x is None for x in items):
        raise r.fail(f"{path}.strokes", "every stroke is empty: no load")
    return tuple(items)


def _stroke_set(which: str, d, n_strokes: int) -> tuple:
    """The diagram on the working (0→1), idle (1→0) or both strokes of every turn."""
    return tuple(d if (which == "both" or (k % 2 == 0) == (which == "working")) else None
                 for k in range(n_strokes))


def _pairs(r: _Reader, value: Any, path: str, signed: bool, hi_x: float) -> Diagram:
    """Pairs ``[x, value]`` with x not decreasing in [0, hi_x]; values ≥ 0 unless signed."""
    diag = r.array(value, path, minlen=2)
    pairs: list[tuple[float, float]] = []
    for m, pr in enumerate(diag):
        pp = r.array(pr, f"{path}[{m}]", 2)
        x = r.number(pp[0], f"{path}[{m}][0]", lo=0.0, hi=hi_x)
        v = r.number(pp[1], f"{path}[{m}][1]", lo=-MAX_LOAD if signed else 0.0, hi=MAX_LOAD)
        if pairs and x < pairs[-1][0]:
            raise r.fail(f"{path}[{m}][0]",
                         f"the abscissae must not decrease (got {x} after {pairs[-1][0]})")
        pairs.append((x, v))
    return tuple(pairs)


def _covers(r: _Reader, d, path: str, end: float, what: str) -> None:
    if d[0][0] != 0.0 or abs(d[-1][0] - end) > 1e-12 * max(end, 1.0):
        raise r.fail(path, f"the diagram does not cover {what}: it runs from {d[0][0]:g} to "
                     f"{d[-1][0]:g}")
