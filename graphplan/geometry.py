"""Vectorised plane geometry on arrays of 2-vectors.

Conventions, stated once for the whole package: the model frame is the variant's
own frame, x to the right, y up; angles are in radians, measured from +x,
counter-clockwise positive. A vector array has shape ``(..., 2)``. ``k×v``
(:func:`perp`) is the vector ``v`` turned +90°, i.e. the cross product of the
unit normal to the plane with ``v``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

Vec = NDArray[np.float64]


def vec(x, y) -> Vec:
    """Stack x and y components into an array of 2-vectors."""
    return np.stack(np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float)), axis=-1)


def perp(v: Vec) -> Vec:
    """Return ``k×v``: each vector turned by +90° (counter-clockwise)."""
    v = np.asarray(v, float)
    return np.stack((-v[..., 1], v[..., 0]), axis=-1)


def cross(a: Vec, b: Vec) -> NDArray[np.float64]:
    """Scalar cross product ``a_x·b_y − a_y·b_x`` (positive when b is CCW of a)."""
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def dot(a: Vec, b: Vec) -> NDArray[np.float64]:
    """Scalar product of two arrays of vectors."""
    return np.sum(np.asarray(a, float) * np.asarray(b, float), axis=-1)


def norm(v: Vec) -> NDArray[np.float64]:
    """Euclidean length of each vector."""
    return np.hypot(np.asarray(v, float)[..., 0], np.asarray(v, float)[..., 1])


def unit_of_angle(theta) -> Vec:
    """Unit vectors at angles ``theta`` (rad, CCW from +x)."""
    theta = np.asarray(theta, float)
    return np.stack((np.cos(theta), np.sin(theta)), axis=-1)


def angle_of(v: Vec) -> NDArray[np.float64]:
    """Angle of each vector in (−π, π], CCW from +x."""
    v = np.asarray(v, float)
    return np.arctan2(v[..., 1], v[..., 0])


def scale(v: Vec, s) -> Vec:
    """Multiply each vector of ``v`` by the matching scalar of ``s``."""
    return np.asarray(v, float) * np.asarray(s, float)[..., None]


def solve2(c1: Vec, c2: Vec, rhs: Vec) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Solve ``x1·c1 + x2·c2 = rhs`` for each row by Cramer's rule.

    This is the algebra of every vector equation of a plan: two known directions
    ``c1``, ``c2`` and a known closing vector ``rhs`` give the two unknown
    magnitudes. The caller guarantees ``cross(c1, c2) ≠ 0`` (it checks the
    conditioning of each dyad first).
    """
    det = cross(c1, c2)
    return cross(rhs, c2) / det, cross(c1, rhs) / det


def sine_between(a: Vec, b: Vec) -> NDArray[np.float64]:
    """|sin| of the angle between the lines of ``a`` and ``b`` (0 for a zero vector)."""
    na = norm(a)
    nb = norm(b)
    with np.errstate(invalid="ignore", divide="ignore"):
        s = np.abs(cross(a, b)) / (na * nb)
    return np.where((na > 0) & (nb > 0), s, 0.0)


def wrap_deg(angle_deg):
    """Wrap degrees to [0, 360)."""
    w = np.mod(angle_deg, 360.0)
    return np.where(np.isclose(w, 360.0, atol=1e-9), 0.0, w)
