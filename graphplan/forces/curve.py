"""The curve of the balancing moment Mур(φ) over one turn of the crank (sheet 2, the seed).

Exact, on a fine grid of crank angles with the positions' own angles merged in: the
kinematics of the grid, the loads and the kinetostatics of :mod:`graphplan.forces`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..kinematics import Cycle, Kinematics, solve
from ..model import Mechanism
from .kinetostatics import solve_forces
from .loads import compute_loads

CURVE_POINTS = 360
"""Points of :func:`moment_curve`'s uniform grid over one turn of the crank."""


@dataclass(frozen=True, slots=True)
class MomentCurve:
    """Exact Mур over one turn of the crank, and at the positions.

    Unpacks as ``travel_deg, M = moment_curve(mech, kin, cycle)`` (a project's ``curve``).

    Attributes
    ----------
    travel_deg : ndarray (N,)
        Crank travel from the first position in the direction of rotation, degrees,
        increasing in [0, 360) — [0, 720) for a four-stroke cycle: the uniform grid
        with the positions' travels merged in.
    phi_deg : ndarray (N,)
        The absolute crank angle φ of each point, degrees in [0, 360).
    M : ndarray (N,)
        Mур, N·m, counter-clockwise positive (``Mс = −Mур`` is the moment of the resisting
        forces reduced to the crank).
    labels : tuple[str, ...]
        The positions' labels, in the order of ``kin``.
    position_travel_deg, position_phi_deg, M_positions : ndarray
        The travel, φ and Mур of each position (the same values as in ``M`` at
        ``index``).
    index : ndarray of int
        Index of each position in the grid.
    """

    travel_deg: np.ndarray
    phi_deg: np.ndarray
    M: np.ndarray
    labels: tuple[str, ...]
    position_travel_deg: np.ndarray
    position_phi_deg: np.ndarray
    M_positions: np.ndarray
    index: np.ndarray

    def __iter__(self):
        return iter((self.travel_deg, self.M))


def moment_curve(mech: Mechanism, kin: Kinematics, cycle: Cycle,
                 points: int = CURVE_POINTS, *, neglect_below: float | None = None
                 ) -> MomentCurve:
    """Exact Mур(φ) on a fine grid over one turn, vectorised (one kinetostatics sweep).

    The kinematics of ``points`` equally spaced crank angles from the first position
    (:func:`graphplan.kinematics.exact.solve`), with the positions' own angles merged in, the
    loads of :func:`graphplan.forces.loads.compute_loads` (the variant's rules unless
    ``neglect_below`` is given) and :func:`graphplan.forces.kinetostatics.solve_forces`.

    Sign: Mур is the balancing moment on the crank, CCW positive; the seed plots it as
    the curve of the moments of the resisting forces (their reduced moment is −Mур).
    Where the neglect rule switches a load on or off the curve jumps (at the press, where
    Q grows past ten times G3 the weight and inertia of the ram are dropped).

    Returns
    -------
    MomentCurve
    """
    if points < 2:
        raise ValueError("moment_curve needs at least 2 points")
    sense = mech.crank.sense
    phi0 = float(kin.phi[0])
    period = math.degrees(cycle.period)  # 360°, or 720° for a four-stroke process
    turns = round(period / 360.0)
    pos_travel = np.degrees(sense * (kin.phi - phi0)) % period
    grid = np.linspace(0.0, period, points * turns, endpoint=False)
    keep = np.all(np.abs(grid[:, None] - pos_travel[None, :]) > 1e-9, axis=1)
    travel = np.concatenate([grid[keep], pos_travel])
    order = np.argsort(travel, kind="stable")
    travel = travel[order]
    index = np.argsort(order)[len(travel) - len(pos_travel):]
    phi = phi0 + sense * np.radians(travel)
    phi[index] = kin.phi  # the positions at exactly their own angles
    fine = solve(mech, phi)
    loads = compute_loads(mech, fine, cycle, neglect_below=neglect_below)
    M = solve_forces(mech, fine, loads).M_bal
    return MomentCurve(travel, np.degrees(phi) % 360.0, M, kin.labels, pos_travel,
                       np.degrees(kin.phi) % 360.0, M[index].copy(), index)
