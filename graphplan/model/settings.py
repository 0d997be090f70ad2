"""The variant's ``[drawing]``, ``[kinetostatics]``, ``[title_block]`` and ``[variant]``
tables, typed, with every default written once, here.

The loader checks each key's type and range (:mod:`graphplan.model.loader`); every later
stage reads them through :attr:`Mechanism.drawing <graphplan.model.Mechanism.drawing>`,
``.kinetostatics``, ``.title_block`` and ``.description`` (``[dynamics]`` is read through
:class:`graphplan.dynamics.DynamicsSettings`, beside the dynamics it configures).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, fields
from typing import Any

FORMATS = ("A1", "A2", "A3")  #: sheet formats, GOST 2.301
LANGUAGES = ("ru", "en")  #: the sheets' lettering

#: ``[dynamics] motor_speed``: synchronous speeds at 50 Hz, rpm (2, 4, 6, 8 poles)
SYNC_SPEEDS = (3000, 1500, 1000, 750)
#: ``[dynamics] motor_series``: the spellings accepted for the bundled motor catalogues
#: (Latin and Cyrillic, any case) and the series each names (:mod:`graphplan.dynamics.motor`)
MOTOR_SERIES = {"AIR": "AIR", "АИР": "AIR", "4A": "4A", "4А": "4A", "DELPHI": "DELPHI",
                "MOTIVE": "DELPHI", "MOTIVE DELPHI": "DELPHI"}


def _labels(value: Any) -> tuple[str, ...] | None:
    return None if value is None else tuple(str(v) for v in value)


def _number(value: Any) -> float | None:
    return None if value is None else float(value)


@dataclass(frozen=True, slots=True)
class DrawingSettings:
    """``[drawing]``: the sheets' format and language, the draftsman's reading step and the
    scales or positions the variant fixes.

    ``Kl``, ``Kv``, ``Ka``, ``Kp`` None: chosen to fill the sheet (:mod:`graphplan.project.
    scales`); ``positions`` None: the velocity plans of every position; ``accelerations``
    None: the acceleration plans of the working and the idle positions the sheet chooses.
    """

    format: str = "A1"
    language: str = "ru"
    reading_mm: float = 0.5  #: mm, the step a length is read to on paper
    Kl: float | None = None  #: m/mm
    Kv: float | None = None  #: (m/s)/mm
    Ka: float | None = None  #: (m/s²)/mm
    Kp: float | None = None  #: N/mm
    positions: tuple[str, ...] | None = None  #: labels of the positions sheet 1 draws
    accelerations: tuple[str, ...] | None = None  #: labels of its acceleration plans

    @classmethod
    def of(cls, settings: Mapping[str, Any]) -> DrawingSettings:
        """The ``[drawing]`` table of a variant's settings, defaults filled in."""
        t = settings.get("drawing", {})
        d = cls()
        return cls(format=str(t.get("format", d.format)),
                   language=str(t.get("language", d.language)),
                   reading_mm=float(t.get("reading_mm", d.reading_mm)),
                   Kl=_number(t.get("Kl")), Kv=_number(t.get("Kv")), Ka=_number(t.get("Ka")),
                   Kp=_number(t.get("Kp")), positions=_labels(t.get("positions")),
                   accelerations=_labels(t.get("accelerations")))

    def table(self) -> dict[str, Any]:
        """The TOML table of these settings: every key that is not None."""
        out: dict[str, Any] = {}
        for f in fields(self):
            v = getattr(self, f.name)
            if v is not None:
                out[f.name] = list(v) if isinstance(v, tuple) else v
        return out


@dataclass(frozen=True, slots=True)
class KinetostaticsSettings:
    """``[kinetostatics]``: which loads the force analysis takes.

    ``neglect_below`` a share of the largest load below which a load is left out of a
    position's force plans (0: none is); ``inertia`` False: a static analysis;
    ``shift_inertia_force``: Φ and MΦ drawn as one force shifted by h = MΦ/Φ;
    ``positions`` None: the positions sheet 2 chooses.
    """

    neglect_below: float = 0.0
    inertia: bool = True
    shift_inertia_force: bool = False
    positions: tuple[str, ...] | None = None

    @classmethod
    def of(cls, settings: Mapping[str, Any]) -> KinetostaticsSettings:
        """The ``[kinetostatics]`` table of a variant's settings, defaults filled in."""
        t = settings.get("kinetostatics", {})
        d = cls()
        return cls(neglect_below=float(t.get("neglect_below", d.neglect_below)),
                   inertia=bool(t.get("inertia", d.inertia)),
                   shift_inertia_force=bool(t.get("shift_inertia_force", d.shift_inertia_force)),
                   positions=_labels(t.get("positions")))


@dataclass(frozen=True, slots=True)
class TitleBlockSettings:
    """``[title_block]``: what form 1 of GOST 2.104 is filled with ("" where not given;
    ``title`` "" means the mechanism's name, ``sheet`` None the sheet's own number)."""

    title: str = ""
    designation: str = ""
    author: str = ""
    checker: str = ""
    teacher: str = ""
    group: str = ""
    school: str = ""
    date: str = ""
    litera: str = "У"  #: «учебный»
    mass: str = ""
    scale: str = ""
    sheet: int | None = None
    sheets: int | None = None

    @classmethod
    def of(cls, settings: Mapping[str, Any]) -> TitleBlockSettings:
        """The ``[title_block]`` table of a variant's settings, defaults filled in."""
        t = settings.get("title_block", {})
        d = cls()
        text = {f.name: str(t.get(f.name, getattr(d, f.name))) for f in fields(cls)
                if f.name not in ("sheet", "sheets")}
        return cls(**text,
                   sheet=None if t.get("sheet") is None else int(t["sheet"]),
                   sheets=None if t.get("sheets") is None else int(t["sheets"]))


def description_of(settings: Mapping[str, Any]) -> str | None:
    """``[variant] description``: where the variant comes from (None: not given)."""
    value = settings.get("variant", {}).get("description")
    return None if value is None else str(value)


__all__ = ["FORMATS", "LANGUAGES", "MOTOR_SERIES", "SYNC_SPEEDS", "DrawingSettings",
           "KinetostaticsSettings", "TitleBlockSettings", "description_of"]
