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


def scale(v: Vec, s) -> Vec:
    """Multiply each vector of ``v`` by the matching scalar of ``s``."""
    return np.asarray(v, float) * np.asarray(s, float)[..., None]


