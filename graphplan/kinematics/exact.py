"""Exact kinematics of a whole sweep: positions, velocities, accelerations together.

:func:`solve` chains :mod:`~graphplan.kinematics.positions`, :mod:`~graphplan.kinematics.velocities`
and :mod:`~graphplan.kinematics.accelerations`; all are vectorised over the crank angles.
Units: m, m/s, m/s², rad, rad/s, rad/s²; angles CCW positive from +x.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from numpy.typing import NDArray

from ..errors import SingularPoseError
from ..model import Mechanism
from .accelerations import AccelerationState, accelerations_complex
from .accelerations import state_of as acceleration_state
from .positions import PositionState, as_xy, solve_complex, translating_links, where
from .velocities import VelocityState, velocities_complex
from .velocities import state_of as velocity_state

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


def cycle_angle_deg(phi, phi_first: float, sense: float, period: float):
    """A position's angle φ as every table, sheet and report gives it, degrees.

    Over a one-turn cycle (``period`` = 2π) it is the crank's angle, the absolute angle of
    O→A counter-clockwise from +x, in [0°, 360°). Over a four-stroke cycle (4π) it is the
    **cycle angle**, the crank's travel from the first position in the sense of rotation,
    ``(sense·(φ − φ_first)) mod 720°`` in [0°, 720°) — as the engine books count it from the
    ВМТ of intake, where the angle of O→A modulo 720° would read 90 … 690, 0, 30, 60.

    Parameters
    ----------
    phi : float or array_like
        Absolute crank angles, rad (they may run over two turns).
    phi_first : float
        The first position's absolute angle, rad (``positions.number_from``).
    sense : float
        +1 for a counter-clockwise crank, −1 for a clockwise one.
    period : float
        The cycle, rad of crank travel (2π or 4π).
    """
    phi = np.asarray(phi, float)
    if period > 2.0 * math.pi + 1e-9:
        out = np.degrees(sense * (phi - phi_first)) % math.degrees(period)
    else:
        out = np.degrees(phi) % 360.0
    out = np.where(np.isclose(out, math.degrees(period), rtol=0.0, atol=1e-9), 0.0, out)
    return float(out) if out.ndim == 0 else out


def position_angles_deg(mech: Mechanism, kin: Kinematics) -> Array:
    """Each position's φ as the tables, sheets and reports give it (:func:`cycle_angle_deg`),
    degrees; the first position is the one labelled ``positions.number_from``."""
    return np.atleast_1d(cycle_angle_deg(kin.phi, first_position_phi(mech, kin),
                                         mech.crank.sense, mech.positions.period))


def first_position_phi(mech: Mechanism, kin: Kinematics) -> float:
    """The absolute crank angle (rad) of the first position, the one labelled
    ``positions.number_from`` (the first solved position when there is none)."""
    first = str(mech.positions.number_from)
    return float(kin.phi[kin.labels.index(first) if first in kin.labels else 0])


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
    n = phi.shape[0]
    P, theta, G = solve_complex(mech, phi, named)
    U = {key: u for key, (_, u) in G.items()}
    velc = velocities_complex(mech, phi, P, U, named)
    accc = accelerations_complex(mech, n, P, U, velc[1], velc[2])
    pos = PositionState(phi, {k: as_xy(z, n) for k, z in P.items()}, theta,
                        {key: (as_xy(g, n), as_xy(u, n)) for key, (g, u) in G.items()})
    vel = velocity_state(velc, n)
    acc = acceleration_state(accc, n)
    if not _all_finite(mech, P, velc[0], accc[0], velc[1], accc[1]):
        _check_finite(mech, phi, named, pos, vel, acc)
    return Kinematics(phi, named or _numbers(len(phi)), pos, vel, acc)


def _all_finite(mech: Mechanism, P, v, a, omega, eps) -> bool:
    """True when no position, velocity, acceleration, ω or ε is NaN or infinite.

    One pass over the velocities, accelerations, ω and ε: every position enters the
    acceleration of its point (``a = a_O + (P − P_O)·(iε − ω²)``; NaN·0 is NaN), except
    the points of a translating link, whose accelerations are copies of their origin's —
    their positions are added. Constants (the frame's points) are finite.
    """
    still = translating_links(mech)
    arrays = [z.view(np.float64) for t in (v, a) for z in t.values()
              if isinstance(z, np.ndarray)]
    arrays += [P[p.name].view(np.float64) for p in mech.points
               if p.link in still and isinstance(P.get(p.name), np.ndarray)]
    arrays += [x for t in (omega, eps) for x in t.values()]
    return bool(np.isfinite(np.concatenate(arrays)).all())


@lru_cache(maxsize=16)
def _numbers(n: int) -> tuple[str, ...]:
    """Default labels ``"0"``, ``"1"``, … of n positions."""
    return tuple(map(str, range(n)))


def _check_finite(mech: Mechanism, phi, labels, pos, vel, acc) -> None:
    """No NaN or infinity leaves the solver: a non-finite rate marks a singular pose."""
    tables = (("position", pos.points), ("ω", vel.omega), ("ε", acc.epsilon),
              ("v", vel.points), ("a", acc.points))
    for kind, table in tables:
        for name, arr in table.items():
            ok = np.isfinite(arr).reshape(len(phi), -1).all(axis=1)
            if not ok.all():
                k = int(np.argmin(ok))
                raise SingularPoseError(
                    f"{mech.source}: {kind} of {name} is not finite at {where(phi, k, labels)} "
                    "(a singular pose: some link's rate is unbounded there)")
