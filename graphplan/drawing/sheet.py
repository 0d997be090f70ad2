"""A drawing sheet: its page, its items and its title block, and the check of its layout.

The items and the paper's conventions (mm from the top-left corner, y down; angles
counter-clockwise as seen on the sheet) are :mod:`graphplan.drawing.items`; the frame and
the title block :mod:`graphplan.drawing.title_block`.
"""


from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import shapely
from shapely.geometry.base import BaseGeometry

from ..errors import InputError
from ..paper import Page
from .items import (
    ITEM_TYPES,
    MARGIN_LAYERS,
    Group,
    Item,
    Leaf,
    Text,
    item_geometry,
    iter_leaves,
    text_box,
)
from .title_block import (
    TitleBlock,
    frame_items,
    title_block_items,
)


@dataclass(frozen=True, slots=True)
class Sheet:
    """One drawing sheet: its page, its items and its title block (None: no block).

    ``lang`` is the language of its lettering: on a Russian sheet (``"ru"``) the
    renderers write numbers with the decimal comma (:func:`graphplan.units.
    decimal_comma`; the title block's designation is left as it is). Every sheet's
    renderers write the indices of the quantities as subscripts (vB, R12, Mур:
    :func:`graphplan.units.subscript_runs`) where the format can (SVG, PDF, PNG).
    """

    page: Page = field(default_factory=Page)
    items: tuple[Item, ...] = ()
    title_block: TitleBlock | None = None
    lang: str | None = None

    def __post_init__(self) -> None:
        items = tuple(self.items)
        for it in items:
            if not isinstance(it, ITEM_TYPES):
                raise InputError(f"sheet items must be drawing items (got {type(it).__name__})")
        object.__setattr__(self, "items", items)

    def all_items(self) -> tuple[Item, ...]:
        """Frame, title block (if any), then the sheet's own items, in drawing order."""
        tb = title_block_items(self.page, self.title_block) if self.title_block else ()
        return frame_items(self.page) + tb + self.items

    def _repr_svg_(self) -> str:
        """Jupyter: the sheet as SVG, as wide as the notebook (the viewBox keeps its mm)."""
        import re

        from ..render.svg import render_svg

        svg = render_svg(self)
        return re.sub(r'<svg([^>]*?) height="[^"]*"([^>]*?) width="[^"]*"',
                      r'<svg\1\2 width="100%"', svg, count=1)


# ----------------------------------------------------------------- layout checks


def _describe(t: Leaf) -> str:
    name = f"{type(t).__name__.lower()}"
    if t.id:
        name += f" {t.id!r}"
    if isinstance(t, Text):
        name += f" {t.text!r} at ({t.pos[0]:.1f}, {t.pos[1]:.1f})"
    return f"{name} [{t.layer}]"


#: Layers that hold the construction lines and the arms of the plans drawn in these layers.
_PLAN_LAYERS = frozenset({"position_plan", "velocity_plan", "acceleration_plan", "force_plan"})


def _same_figure(text_layer: str, item_layer: str) -> bool:
    """A plan's letters may cross its own construction lines and arms (other layers)."""
    return text_layer == item_layer or (text_layer in _PLAN_LAYERS
                                        and item_layer in ("construction", "dimensions"))


def check_layout(sheet: Sheet) -> list[str]:
    """Problems of a sheet's layout, one line each (empty list: nothing found).

    Reported: duplicate element ids; a text outside the inner frame (outside the
    sheet, for the frame and title layers, whose graphs 31–32 sit in the margin); a
    text of another layer over the title block or graph 26; a drawing item leaving
    the inner frame; two texts whose boxes overlap; a text box crossed by a line of
    another layer (a plan's letters may cross its construction lines and arms).
    """
    problems: list[str] = []
    all_items = sheet.all_items()
    seen: dict[str, int] = {}

    def walk(items: Iterable[Item]) -> None:
        for it in items:
            if it.id is not None:
                seen[it.id] = seen.get(it.id, 0) + 1
            if isinstance(it, Group):
                walk(it.items)

    walk(all_items)
    problems += [f"id {k!r} is used {v} times" for k, v in seen.items() if v > 1]

    leaves = list(iter_leaves(all_items))
    page = sheet.page
    frame = page.frame.polygon().buffer(1e-6)
    trim = page.trim.polygon().buffer(1e-6)
    reserved = page.title_block_rect.polygon().union(page.graph26_rect.polygon())
    texts = [t for t in leaves if isinstance(t, Text)]
    boxes = [text_box(t) for t in texts]
    for t, b in zip(texts, boxes, strict=True):
        if t.layer in MARGIN_LAYERS:
            if not trim.contains(b):
                problems.append(f"{_describe(t)} is outside the sheet")
        elif not frame.contains(b):
            problems.append(f"{_describe(t)} is outside the inner frame")
        elif b.intersection(reserved).area > 1e-6:
            problems.append(f"{_describe(t)} is over the title block")

    geoms: list[tuple[Leaf, BaseGeometry]] = []
    for it in leaves:
        g = item_geometry(it) if not isinstance(it, Text) else None
        if g is None or g.is_empty:
            continue
        geoms.append((it, g))
        if it.layer not in MARGIN_LAYERS and not frame.contains(g):
            problems.append(f"{_describe(it)} leaves the inner frame")

    if boxes:
        tree = shapely.STRtree(boxes)
        left, right = tree.query(boxes, predicate="intersects")
        for i, j in zip(left.tolist(), right.tolist(), strict=True):
            if i < j and boxes[i].intersection(boxes[j]).area > 1e-6:
                problems.append(f"{_describe(texts[i])} overlaps {_describe(texts[j])}")
    if boxes and geoms:
        tree = shapely.STRtree([g for _, g in geoms])
        for i, b in enumerate(boxes):
            for j in tree.query(b, predicate="intersects").tolist():
                it, g = geoms[j]
                if not _same_figure(texts[i].layer, it.layer) and not g.touches(b):
                    problems.append(f"{_describe(texts[i])} is crossed by {_describe(it)}")
    return problems
