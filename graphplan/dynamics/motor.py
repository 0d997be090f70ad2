"""Choice of the electric motor and of the overall gear ratio (method guide, section B.5).

The catalogues are CSV files in ``graphplan/data`` (``motors_air.csv`` for the AIR series,
``motors_4a.csv`` for the 4A series, ``motors_delphi.csv`` for Motive's Delphi series of
IEC motors), each with a comment header that names its source and what the source does
not give. A cell the source leaves blank is ``None`` here. Only the Delphi catalogue gives
the rotor inertia J_рот, so it is the default series (:data:`DEFAULT_SERIES`); with AIR
or 4A :attr:`MotorChoice.J_reduced` is ``None`` and the rotor is not counted in the
flywheel (the report says so).

The course rule:

* required power ``P = M_c,avg·ω1/η`` (W), the mean power of the resistance over the cycle
  divided by the drive's efficiency (:func:`required_power`);
* the motor is the one of the smallest rated power ``P_ном ≥ P`` at the chosen synchronous
  speed; by default 1500 rpm (4 poles), the usual choice of course projects: cheaper and
  lighter than 1000/750 rpm, with a gear ratio lower than at 3000 rpm (:func:`choose_motor`);
* the overall gear ratio is ``u = n_ном/n1`` and the rotor inertia reduced to the crank shaft
  is ``J_рот·u²``.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from ..errors import GraphplanError, InputError
from ..files import decode_text
from ..model import MOTOR_SERIES, SYNC_SPEEDS

__all__ = [
    "DEFAULT_SERIES",
    "DEFAULT_SYNC_RPM",
    "SYNC_SPEEDS",
    "Motor",
    "MotorChoice",
    "MotorSelectionError",
    "catalogue_path",
    "choose_motor",
    "load_catalogue",
    "required_power",
    "series_names",
]

#: synchronous speed used when none is given: 4 poles, the common choice of course projects
DEFAULT_SYNC_RPM = 1500

_FILES = {"AIR": "motors_air.csv", "4A": "motors_4a.csv", "DELPHI": "motors_delphi.csv"}
#: the series used when the variant names none: the one bundled catalogue that gives the
#: rotor inertia (and both torque ratios), so that J_рот·u² counts in the flywheel
DEFAULT_SERIES = "DELPHI"

_COLUMNS = (
    "type",
    "power_kw",
    "sync_rpm",
    "rated_rpm",
    "slip_pct",
    "start_torque_ratio",
    "max_torque_ratio",
    "inertia_kg_m2",
    "efficiency_pct",
    "cos_phi",
    "mass_kg",
)
_REQUIRED = ("type", "power_kw", "sync_rpm", "rated_rpm")


class MotorSelectionError(GraphplanError, ValueError):
    """No catalogue motor satisfies the request (power too large, unknown speed or series)."""


@dataclass(frozen=True)
class Motor:
    """One catalogue row. Optional values are ``None`` where the source gives none."""

    type: str
    power_kw: float
    sync_rpm: int
    rated_rpm: float
    slip_pct: float | None = None  # as printed by the source
    start_torque_ratio: float | None = None  # M_п/M_ном
    max_torque_ratio: float | None = None  # M_max/M_ном
    inertia_kg_m2: float | None = None  # J_рот
    efficiency_pct: float | None = None
    cos_phi: float | None = None
    mass_kg: float | None = None

    @property
    def power_w(self) -> float:
        return self.power_kw * 1000.0

    @property
    def slip(self) -> float:
        """Rated slip from the speeds, s = 1 − n_ном/n_с (a fraction)."""
        return 1.0 - self.rated_rpm / self.sync_rpm

    @property
    def poles(self) -> int:
        return round(6000 / self.sync_rpm)


@dataclass(frozen=True)
class MotorChoice:
    """The chosen motor and what follows from it for the crank shaft."""

    motor: Motor
    P_required: float  # W
    crank_rpm: float  # n1
    u: float  # overall gear ratio n_ном/n1
    reserve: float  # P_ном/P_required − 1
    J_reduced: float | None  # J_рот·u², kg·m², None when the catalogue has no J_рот
    reason: str  # one line
    series: str = ""  # the catalogue's series (AIR, 4A, …)


def _series_key(series: str) -> str:
    key = MOTOR_SERIES.get(str(series).strip().upper())
    if key is None:
        raise MotorSelectionError(
            f"unknown motor series {series!r}: expected one of AIR (АИР), 4A (4А), "
            "DELPHI (Motive Delphi)"
        )
    return key


def series_names() -> tuple[str, ...]:
    """Every accepted spelling of the bundled series (``dynamics.motor_series``)."""
    return tuple(MOTOR_SERIES)


def catalogue_path(series: str = DEFAULT_SERIES) -> Path:
    """The packaged CSV file of a series."""
    name = _FILES[_series_key(series)]
    return Path(str(resources.files("graphplan") / "data" / name))


def _number(text: str, where: str, column: str, *, positive: bool = True) -> float:
    try:
        value = float(text)
    except ValueError:
        raise InputError(f"{where}, column {column!r}: expected a number, got {text!r}") from None
    if not math.isfinite(value) or (positive and value <= 0):
        raise InputError(f"{where}, column {column!r}: expected a positive number, got {text!r}")
    return value


def _parse_row(row: dict[str, str], where: str) -> Motor:
    for column in _REQUIRED:
        if not (row.get(column) or "").strip():
            raise InputError(f"{where}, column {column!r}: value is missing")
    sync = _number(row["sync_rpm"], where, "sync_rpm")
    if sync not in SYNC_SPEEDS:
        raise InputError(
            f"{where}, column 'sync_rpm': expected one of {', '.join(map(str, SYNC_SPEEDS))},"
            f" got {row['sync_rpm']!r}"
        )
    rated = _number(row["rated_rpm"], where, "rated_rpm")
    if rated >= sync:
        raise InputError(
            f"{where}, column 'rated_rpm': the rated speed {rated:g} must be below the"
            f" synchronous speed {sync:g}"
        )
    optional = {}
    for column in _COLUMNS[4:]:
        text = (row.get(column) or "").strip()
        optional[column] = _number(text, where, column) if text else None
    return Motor(
        type=row["type"].strip(),
        power_kw=_number(row["power_kw"], where, "power_kw"),
        sync_rpm=int(sync),
        rated_rpm=rated,
        **optional,
    )


def load_catalogue(series: str = DEFAULT_SERIES, *,
                   path: str | Path | None = None) -> tuple[Motor, ...]:
    """Read a motor catalogue (the packaged one of ``series``, or the CSV file at ``path``).

    Lines starting with ``#`` are comments; the first other line is the header. A bad row
    raises :class:`InputError` naming the file, the line and the column.
    """
    file = Path(path) if path is not None else catalogue_path(series)
    try:
        text = decode_text(file.read_bytes(), str(file))
    except OSError as exc:
        raise InputError(f"{file}: cannot read the motor catalogue ({exc.strerror})") from None
    lines = [
        (n, line)
        for n, line in enumerate(text.splitlines(), 1)
        if line.strip() and not line.lstrip().startswith("#")
    ]
    if not lines:
        raise InputError(f"{file}: the motor catalogue has no header and no rows")
    header_no, header_line = lines[0]
    header = [h.strip() for h in next(csv.reader([header_line]))]
    missing = [c for c in _REQUIRED if c not in header]
    if missing:
        raise InputError(f"{file}, line {header_no}: header lacks column(s) {', '.join(missing)}")
    unknown = [c for c in header if c not in _COLUMNS]
    if unknown:
        raise InputError(f"{file}, line {header_no}: unknown column(s) {', '.join(unknown)}")
    motors = []
    for n, line in lines[1:]:
        cells = next(csv.reader([line]))
        where = f"{file}, line {n}"
        if len(cells) != len(header):
            raise InputError(f"{where}: expected {len(header)} cells, got {len(cells)}")
        motors.append(_parse_row(dict(zip(header, cells, strict=True)), where))
    if not motors:
        raise InputError(f"{file}: the motor catalogue has no rows")
    return tuple(motors)


def required_power(M_c_avg: float, omega1: float, efficiency: float) -> float:
    """Motor power required, P = |M_c,avg|·ω1/η, in W.

    ``M_c_avg`` is the mean moment of the resistance reduced to the crank (N·m; its sign is
    ignored, as in P_c = |A_c(2π)|·n1/60), ``omega1`` the crank's angular velocity (rad/s),
    ``efficiency`` the overall efficiency of the drive, 0 < η ≤ 1.
    """
    for name, value in (("M_c_avg", M_c_avg), ("omega1", omega1), ("efficiency", efficiency)):
        if not isinstance(value, int | float) or not math.isfinite(value):
            raise InputError(f"required_power: {name} must be a finite number, got {value!r}")
    if omega1 <= 0:
        raise InputError(f"required_power: omega1 must be positive, got {omega1!r}")
    if not 0 < efficiency <= 1:
        raise InputError(f"required_power: efficiency must be in (0, 1], got {efficiency!r}")
    return abs(M_c_avg) * omega1 / efficiency


def choose_motor(
    P_required: float,
    crank_rpm: float,
    *,
    series: str = DEFAULT_SERIES,
    sync_rpm: int | None = None,
    catalogue: tuple[Motor, ...] | None = None,
) -> MotorChoice:
    """The motor of the smallest rated power ≥ ``P_required`` (W) at the synchronous speed.

    ``sync_rpm`` defaults to :data:`DEFAULT_SYNC_RPM` (1500 rpm). ``crank_rpm`` is n1 of the
    crank. ``catalogue`` replaces the packaged catalogue of ``series``.
    """
    if not math.isfinite(P_required) or P_required <= 0:
        raise InputError(
            f"choose_motor: P_required must be a positive power in W, got {P_required!r}"
        )
    if not math.isfinite(crank_rpm) or crank_rpm <= 0:
        raise InputError(f"choose_motor: crank_rpm must be positive, got {crank_rpm!r}")
    sync = DEFAULT_SYNC_RPM if sync_rpm is None else sync_rpm
    if sync not in SYNC_SPEEDS:
        raise MotorSelectionError(
            f"synchronous speed {sync!r} rpm: expected one of {', '.join(map(str, SYNC_SPEEDS))}"
        )
    motors = catalogue if catalogue is not None else load_catalogue(series)
    at_speed = sorted((m for m in motors if m.sync_rpm == sync), key=lambda m: m.power_kw)
    if not at_speed:
        raise MotorSelectionError(f"the catalogue has no motor at {sync} rpm")
    for motor in at_speed:
        if motor.power_w >= P_required:
            break
    else:
        largest = at_speed[-1]
        raise MotorSelectionError(
            f"no motor at {sync} rpm is large enough: {P_required / 1000:.3g} kW required,"
            f" the largest is {largest.type} with {largest.power_kw:g} kW"
        )
    u = motor.rated_rpm / crank_rpm
    reserve = motor.power_w / P_required - 1.0
    J_reduced = None if motor.inertia_kg_m2 is None else motor.inertia_kg_m2 * u * u
    rule = "default 1500 rpm" if sync_rpm is None else f"{sync} rpm asked"
    reason = (
        f"{motor.type}: the smallest motor at {sync} rpm ({rule}) with P_ном = "
        f"{motor.power_kw:g} kW ≥ P = {P_required / 1000:.3g} kW (reserve {reserve:.0%}); "
        f"u = n_ном/n1 = {motor.rated_rpm:g}/{crank_rpm:g} = {u:.2f}"
    )
    return MotorChoice(
        motor=motor,
        P_required=float(P_required),
        crank_rpm=float(crank_rpm),
        u=u,
        reserve=reserve,
        J_reduced=J_reduced,
        reason=reason,
        series="" if catalogue is not None else _series_key(series),
    )
