"""The variant's ``[dynamics]`` table, typed, with every default in one place.

The loader checks each key's type and range (``model/loader.py``); the dynamics read them
only through :meth:`DynamicsSettings.of`, so a default is written once, here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from ..model import Mechanism
from .motor import DEFAULT_SERIES

GRID = 720  #: intervals of the crank's turn the reduced moment and inertia are found on
STEEL = 7800.0  #: density of the flywheel (kg/m³) unless the variant gives one


@dataclass(frozen=True, slots=True)
class FlywheelSettings:
    """``[dynamics.flywheel]``: the flywheel's shape, shaft and proportions."""

    shape: str = "rim"  #: "rim" or "disc"
    shaft: str = "crank"  #: where it is mounted: "crank" or "motor"
    b_ratio: float = 0.2  #: rim width b over the mean diameter D
    h_ratio: float = 0.1  #: rim height h over D
    density: float = STEEL  #: kg/m³


@dataclass(frozen=True, slots=True)
class DynamicsSettings:
    """``[dynamics]``: what sheet 3 needs beyond the mechanism.

    ``delta`` None: not given (sheet 3 cannot be drawn without it); ``efficiency`` None:
    not given (η = 1 where a value is needed, :attr:`eta`); ``intervals`` None: 24 a turn
    of the crank (:meth:`intervals_for`); ``motor_speed`` None: the series' default.
    """

    delta: float | None = None
    efficiency: float | None = None
    crank_inertia: float = 0.0  #: kg·m², on the crank's shaft (a gear, a pulley)
    grid: Any = GRID  #: an int ≥ 12 (checked where used: settings may come from a script)
    intervals: int | None = None
    motor_series: str = DEFAULT_SERIES
    motor_speed: int | None = None
    flywheel: FlywheelSettings = field(default_factory=FlywheelSettings)

    @classmethod
    def of(cls, mech: Mechanism) -> DynamicsSettings:
        """The settings of ``mech`` (its ``[dynamics]`` table), defaults filled in."""
        dyn = mech.settings.get("dynamics", {})
        fw = dyn.get("flywheel", {})
        d = cls()
        f = d.flywheel
        return cls(
            delta=None if dyn.get("delta") is None else float(dyn["delta"]),
            efficiency=None if dyn.get("efficiency") is None else float(dyn["efficiency"]),
            crank_inertia=float(dyn.get("crank_inertia", d.crank_inertia)),
            grid=dyn.get("grid", d.grid),
            intervals=None if dyn.get("intervals") is None else int(dyn["intervals"]),
            motor_series=str(dyn.get("motor_series", d.motor_series)),
            motor_speed=dyn.get("motor_speed"),
            flywheel=FlywheelSettings(
                shape=str(fw.get("shape", f.shape)), shaft=str(fw.get("shaft", f.shaft)),
                b_ratio=float(fw.get("b_ratio", f.b_ratio)),
                h_ratio=float(fw.get("h_ratio", f.h_ratio)),
                density=float(fw.get("density", f.density))))

    @property
    def eta(self) -> float:
        """The efficiency η of the machine (1 when not given)."""
        return 1.0 if self.efficiency is None else self.efficiency

    def intervals_for(self, period: float) -> int:
        """The intervals of the graphical integration over a cycle of ``period`` rad."""
        if self.intervals is not None:
            return self.intervals
        return 24 * round(period / (2 * math.pi))


__all__ = ["GRID", "STEEL", "DynamicsSettings", "FlywheelSettings"]
