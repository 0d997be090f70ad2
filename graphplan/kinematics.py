"""Exact kinematics of a whole sweep: positions, velocities, accelerations together.

:func:`solve` chains :mod:`~graphplan.positions`, :mod:`~graphplan.velocities`
and :mod:`~graphplan.accelerations`; all are vectorised over the crank angles.
Units: m, m/s, m/s², rad, rad/s, rad/s²; angles CCW positive from +x.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from .accelerations import AccelerationState, solve_accelerations
from .errors import SingularPoseError
from .model import Mechanism
from .positions import PositionState, solve_positions, where
from .velocities import VelocityState, solve_velocities

Array = NDArray[np.float64]


@dataclass(frozen=True, slots=True)
class Kinematics:
    """Kinematics of N positions: the three solved states and the labels."""

    phi: Array
    labels: tuple[str, ...]
    pos: PositionState
    vel: VelocityState
    acc: AccelerationState

    @property
    def n(self) -> int:
        """Number of positions."""
        return int(self.phi.shape[0])

    def point_names(self) -> list[str]:
        """All point names, in the order they were placed."""
        return list(self.pos.points)

    def as_json(self, k: int, links: tuple[str, ...]) -> dict:
        """Position k as the JSON object of ``graphplan analyze --json``."""

        def pt(d):
            return {name: [float(d[name][k, 0]), float(d[name][k, 1])] for name in d}

        return {
            "label": self.labels[k],
            "phi_deg": float(np.degrees(self.phi[k]) % 360.0),
            "points": pt(self.pos.points),
            "velocities": pt(self.vel.points),
            "accelerations": pt(self.acc.points),
            "omega": {ln: float(self.vel.omega[ln][k]) for ln in links},
            "epsilon": {ln: float(self.acc.epsilon[ln][k]) for ln in links},
            "theta_deg": {ln: float(np.degrees(self.pos.theta[ln][k])) for ln in links},
            "sliding": {
                key: {
                    "velocity": float(self.vel.sliding[key][k]),
                    "acceleration": float(self.acc.sliding[key][k]),
                    "coriolis": [float(c) for c in self.acc.coriolis[key][k]],
                }
                for key in self.vel.sliding
            },
            "conditioning": {
                name: float(s[k]) for name, s in self.vel.conditioning.items()
            },
        }


def solve(mech: Mechanism, phi, labels=None) -> Kinematics:
    """Solve positions, velocities and accelerations at the crank angles ``phi`` (rad).

    Parameters
    ----------
    mech : Mechanism
    phi : array_like
        Absolute crank angles of O→A, rad, CCW from +x.
    labels : sequence of str, optional
        Position labels (default ``"0"``, ``"1"``, …), used in errors and output.

    Returns
    -------
    Kinematics

    Raises
    ------
    AssemblyError, SingularPoseError
        Naming the dyad and the position where it fails.
    """
    phi = np.atleast_1d(np.asarray(phi, float))
    named = tuple(labels) if labels is not None else None  # unnamed angles: errors say φ only
    pos = solve_positions(mech, phi, named)
    vel = solve_velocities(mech, pos, named)
    acc = solve_accelerations(mech, pos, vel)
    _check_finite(mech, phi, named, pos, vel, acc)
    return Kinematics(phi, named or tuple(str(k) for k in range(len(phi))), pos, vel, acc)


def _check_finite(mech: Mechanism, phi, labels, pos, vel, acc) -> None:
    """No NaN or infinity leaves the solver: a non-finite rate marks a singular pose."""
    for kind, table in (("position", pos.points), ("ω", vel.omega), ("ε", acc.epsilon),
                        ("v", vel.points), ("a", acc.points)):
        for name, arr in table.items():
            ok = np.isfinite(arr).reshape(len(phi), -1).all(axis=1)
            if not ok.all():
                k = int(np.argmin(ok))
                raise SingularPoseError(
                    f"{mech.source}: {kind} of {name} is not finite at {where(phi, k, labels)} "
                    "(a singular pose: some link's rate is unbounded there)")
