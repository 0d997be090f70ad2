"""Figures of the note cut out of the project's own sheets: the same drawing, at its scale.

A figure is the set of a sheet's items whose ids start with a prefix (``pp-``: the plan of
positions; ``vp3-``/``ap3-``: the velocity/acceleration plan of the fourth position;
``s2p8-``: sheet 2's scheme, force plans and lever of a position; ``s3-``…: sheet 3's
diagrams), drawn alone and cropped to their extent plus a margin.
"""

from __future__ import annotations

import re

from ..drawing import Group, Item, Sheet, item_geometry, iter_leaves

MARGIN_MM = 4.0
DPI = 200.0


def _selected(items: tuple[Item, ...], prefixes: tuple[str, ...]) -> list[Item]:
    out: list[Item] = []
    for it in items:
        ident = getattr(it, "id", None) or ""
        if ident.startswith(prefixes):
            out.append(it)
        elif isinstance(it, Group):
            out += _selected(it.items, prefixes)
    return out


def _bounds(items: list[Item]) -> tuple[float, float, float, float] | None:
    boxes = []
    for leaf in iter_leaves(items):
        g = item_geometry(leaf)
        if g is not None and not g.is_empty:
            boxes.append(g.bounds)
    if not boxes:
        return None
    return (min(b[0] for b in boxes), min(b[1] for b in boxes),
            max(b[2] for b in boxes), max(b[3] for b in boxes))


def sheet_part_svg(sheet: Sheet, *prefixes: str) -> tuple[str, float] | None:
    """The SVG of the items of ``sheet`` whose ids start with one of ``prefixes``, cropped,
    and its width in mm; None when the sheet has no such item."""
    from ..numbers import trimmed as num
    from ..render.svg import render_svg

    items = _selected(sheet.items, prefixes)
    box = _bounds(items)
    if box is None:
        return None
    x0, y0 = box[0] - MARGIN_MM, box[1] - MARGIN_MM
    w, h = box[2] - box[0] + 2 * MARGIN_MM, box[3] - box[1] + 2 * MARGIN_MM
    svg = render_svg(Sheet(page=sheet.page, items=tuple(items), title_block=None))
    root = re.search(r"<svg[^>]*>", svg)
    assert root is not None  # render_svg writes one root element
    head = root.group(0)
    head = re.sub(r'\s(width|height|viewBox)="[^"]*"', "", head)
    head = head[:-1] + (f' width="{num(w)}mm" height="{num(h)}mm" '
                        f'viewBox="{num(x0)} {num(y0)} {num(w)} {num(h)}">')
    return svg[:root.start()] + head + svg[root.end():], w


def svg_png(svg: str, dpi: float = DPI) -> bytes:
    """PNG of an SVG through the export engine (``graphplan[export]``)."""
    from ..render.png import svg_to_png_bytes

    return svg_to_png_bytes(svg, dpi)
