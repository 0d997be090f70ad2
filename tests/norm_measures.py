"""What a norm-controller measures on a sheet (issue 18), shared by the norm-control tests of the
examples (``test_norm_control.py``) and of the variants nobody wrote an example for
(``test_norm_control_variants.py``).

Measured from the sheets themselves — the items of :class:`graphplan.drawing.sheet.Sheet` and the
SVG they render to:

* :func:`drawn_links`: the moving links drawn in each figure (items ``<prefix><k>-link-<n>`` or
  ``<prefix><k>-slider-<n>-…``);
* :func:`plan_longest`: the longest vector of every velocity and acceleration plan, whose
  marks are ``LONGEST_MIN`` (every plan) and ``MEDIAN_MIN`` (their median);
* :func:`empty_share`: the share of 20×20 mm tiles with no ink, mark ``EMPTY_MAX``;
* :func:`overlaps`: every text over another text or crossed by a line.
"""

from __future__ import annotations

import io
import math
import re
import statistics

import numpy as np
import pytest
import shapely

from graphplan.drawing import Arrow, Hatch, Text, item_geometry, iter_leaves, text_box
from graphplan.render.svg import render_svg

TILE = 20.0  #: mm
EMPTY_MAX = 0.40
LONGEST_MIN, MEDIAN_MIN = 40.0, 50.0



def drawn_links(sh, prefix: str) -> dict[str, set[str]]:
    """Drawn links per figure: ``{figure id: {link numbers}}`` from the items' ids
    ``<prefix><k>-link-<n>…`` and ``<prefix><k>-slider-<n>-…``."""
    out: dict[str, set[str]] = {}
    pat = re.compile(rf"^({prefix}\d+)-(?:link|slider)-([^-]+)")
    for it in iter_leaves(sh.items):
        m = pat.match(it.id or "")
        if m:
            out.setdefault(m.group(1), set()).add(m.group(2))
    return out


def plan_longest(sh) -> dict[str, float]:
    """The longest vector (mm) of every velocity (``vp<k>``) and acceleration (``ap<k>``)
    plan on a sheet, from its arrows."""
    out: dict[str, float] = {}
    for it in iter_leaves(sh.items):
        m = re.match(r"^((?:vp|ap)\d+)-", it.id or "")
        if m and isinstance(it, Arrow):
            out[m.group(1)] = max(out.get(m.group(1), 0.0), math.dist(it.p0, it.p1))
    return out


def empty_share(sh) -> float:
    """Share of 20×20 mm tiles inside the frame, title block left out, with no ink
    (the rendered SVG at 2 px/mm, a tile is empty when no pixel is darker than 200/255)."""
    pytest.importorskip("resvg_py")  # the export extra's renderer: no cairo needed
    from PIL import Image

    from graphplan.render.png import svg_to_png_bytes

    png = svg_to_png_bytes(render_svg(sh), 2 * 25.4, engine="resvg")
    im = np.asarray(Image.open(io.BytesIO(png)).convert("L"))
    f, tb = sh.page.frame, sh.page.title_block_rect
    tiles = empty = 0
    y = f.y0 + 1.0
    while y + TILE <= f.y1 - 1.0:
        x = f.x0 + 1.0
        while x + TILE <= f.x1 - 1.0:
            if not (x + TILE > tb.x0 and y + TILE > tb.y0):
                tiles += 1
                tile = im[int(y * 2):int((y + TILE) * 2), int(x * 2):int((x + TILE) * 2)]
                empty += bool((tile > 200).all())
            x += TILE
        y += TILE
    return empty / max(tiles, 1)


def overlaps(sh) -> list[str]:
    """Every text over another text and every text crossed by a line (any layer: a plan's
    letter over its own construction line counts), and any text over an embedded diagram."""
    leaves = list(iter_leaves(sh.all_items()))
    texts = [t for t in leaves if isinstance(t, Text)]
    boxes = [text_box(t) for t in texts]
    out: list[str] = []
    tree = shapely.STRtree(boxes)
    left, right = tree.query(boxes, predicate="intersects")
    for i, j in zip(left.tolist(), right.tolist(), strict=True):
        if i < j and boxes[i].intersection(boxes[j]).area > 0.05:
            out.append(f"text {texts[i].text!r} ({texts[i].id}) over text {texts[j].text!r} "
                       f"({texts[j].id})")
    lines = []
    for it in leaves:
        if isinstance(it, (Text, Hatch)):
            continue
        g = item_geometry(it)
        if g is None or g.is_empty:
            continue
        g = g.boundary if g.geom_type == "Polygon" else g
        lines.append((it, g))
    if lines:
        tree = shapely.STRtree([g for _, g in lines])
        for t, b in zip(texts, boxes, strict=True):
            inner = b.buffer(-0.15)
            for j in tree.query(inner, predicate="intersects").tolist():
                it, g = lines[j]
                out.append(f"text {t.text!r} ({t.id}) crossed by {type(it).__name__} "
                           f"{it.id} [{it.layer}]")
    return out



# ------------------------------------------------- the checks both test files make


def check_links_on_sheet_1(a, sheet) -> None:
    """Every moving link drawn in every position of the plan of positions."""
    moving = set(a.mech.moving_links)
    drawn = drawn_links(sheet, "pp-")
    for k in range(a.kin.n):
        assert moving <= drawn.get(f"pp-{k}", set()), (k, moving - drawn.get(f"pp-{k}", set()))


def check_links_on_sheet_2(a, sheet) -> None:
    """Every moving link drawn in every scheme of sheet 2 (its groups and its crank)."""
    moving = set(a.mech.moving_links)
    drawn = drawn_links(sheet, "s2p")
    assert drawn
    for fig, links in drawn.items():
        assert moving <= links, (fig, moving - links)


def check_plans_readable(sheet) -> None:
    """Each plan's longest vector ≥ LONGEST_MIN and their median ≥ MEDIAN_MIN, in mm."""
    longest = plan_longest(sheet)
    assert longest
    assert min(longest.values()) >= LONGEST_MIN, sorted(longest.items(), key=lambda kv: kv[1])[:3]
    assert statistics.median(longest.values()) >= MEDIAN_MIN
