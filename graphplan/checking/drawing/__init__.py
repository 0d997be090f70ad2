"""Checking a student's drawing: a sheet as DXF, SVG or PDF, measured against graphplan.

``graphplan check --drawing SHEET.dxf --variant VARIANT.toml`` reads the drawing
(:mod:`.dxf`, :mod:`.svg`, :mod:`.pdf` → :mod:`.primitives`), reads it as a draftsman
does — where lines end, arrowheads, letters near points (:mod:`.scene`) — finds the
velocity and acceleration plans by their letters, captions and scales (:mod:`.plans`),
lays each against graphplan's construction of its position at the student's scale
(:mod:`.measure`) and judges it with the calculation checker's verdicts and causes
(:mod:`.check`); the schemes of a position (:mod:`.positions`) and the plan of all
positions (:mod:`.position_plan`) are laid against the exact positions; :mod:`.overlay`
draws graphplan's construction over the student's plans. See ``docs/check-format.md``,
"Checking a drawing".

Imports are lazy: ``import graphplan.checking.drawing`` loads nothing heavy.
"""

from __future__ import annotations

_API = {"check_drawing": "check", "read_drawing": "read", "DrawingError": "primitives",
        "drawing_overlay": "overlay"}


def __getattr__(name: str):
    if name in _API:
        import importlib

        return getattr(importlib.import_module(f"{__name__}.{_API[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = sorted(_API)
