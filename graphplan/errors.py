"""Exceptions of graphplan: one root, leaves that also subclass the natural builtin.

Every message is one line that names where the problem is (file, key or group,
position) and what was expected, so the command line can print it without a
traceback.
"""

from __future__ import annotations


class GraphplanError(Exception):
    """Root of every error graphplan raises on purpose."""


class InputError(GraphplanError, ValueError):
    """A variant file is malformed: a missing or unknown key, a wrong type or value."""


class StructureError(GraphplanError):
    """The mechanism's mobility is not 1, or it does not split into class-II groups."""


class AssemblyError(GraphplanError):
    """A dyad cannot be assembled at some crank angle (its closing lengths do not meet)."""


class SingularPoseError(AssemblyError):
    """A dyad passes through a lock-up: the two lines of its vector equation are parallel."""


class LayoutError(GraphplanError):
    """Plans or diagrams do not fit their place on the sheet at any standard scale."""
