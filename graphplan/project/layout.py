"""Where things go on sheet 1 (kinematics): the regions of an A1/A2/A3 page.

The page is cut as a student cuts it:

* a **left column** holding the plan of positions (top) and the kinematic
  diagrams s(φ), v(φ), a(φ) (below it);
* a **grid** to its right with one cell per plan: the velocity plans of all
  positions, then their acceleration plans, in reading order;
* a **bottom strip** under the grid with the table of the plans, and the block of
  scales above the title block.

The cell size fixes the scales Kv and Ka (each plan fills its cell), so the
layout is computed before the plans are drawn, from sizes only. Paper mm, y down.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import LayoutError
from ..paper import GRAPH26_SIZE, TITLE_BLOCK_SIZE, Page, Rect

GAP = 8.0  #: clearance between regions, mm
CAPTION = 7.0  #: caption strip above a plan cell, mm
ROW = 7.0  #: row height of the table (3.5 mm lettering)
SCALES_BLOCK = 27.0  #: height of the block of scales (three lines of 3.5 mm + title)
DIAGRAM_MIN = (200.0, 130.0)  #: smallest useful box of the three diagrams, mm
DIAGRAM_MAX_H = 240.0


def diagram_min(page: Page) -> tuple[float, float]:
    """Smallest box of the diagrams on ``page``: DIAGRAM_MIN on A1, in proportion below."""
    k = min(1.0, page.frame.height / 584.0)
    return DIAGRAM_MIN[0] * k, DIAGRAM_MIN[1] * k


@dataclass(frozen=True, slots=True)
class Sheet1Layout:
    """Regions of sheet 1 (mm on paper, y down).

    ``plan_box`` is where the plan of positions goes (its own size, centred in the
    left column), ``diagrams`` the box of the three diagrams, ``cells`` the plan
    cells in order (velocity plans of positions 0…N−1, then acceleration plans),
    ``table`` the top-left corner and width available for the table of the plans,
    ``scales`` the box of the list of scales.
    """

    page: Page
    plan_box: Rect
    diagrams: Rect
    cells: tuple[Rect, ...]
    table: Rect
    scales: Rect

    @property
    def cell_inner(self) -> tuple[float, float]:
        """Room for one plan in a cell (below its caption, with a margin for letters)."""
        c = self.cells[0]
        return c.width - 2 * 6.0, c.height - CAPTION - 2 * 6.0


def sheet1_layout(page: Page, plan_w: float, plan_h: float, n_positions: int,
                  n_plans: int | None = None) -> Sheet1Layout:
    """Cut ``page`` for a plan of positions of ``plan_w``×``plan_h`` mm and N positions.

    The grid takes the column count that gives the largest square-ish cells for
    2·``n_plans`` plans (default: every position); the table has a row per position.
    Raises LayoutError when the plan of positions leaves no room.
    """
    f = page.frame
    top = f.y0 + GRAPH26_SIZE[1] + 4.0
    dmin_w, dmin_h = diagram_min(page)
    left_w = max(plan_w, dmin_w)
    if plan_h + GAP + dmin_h > f.y1 - top - 4.0 or left_w > f.width * 0.55:
        raise LayoutError(
            f"the plan of positions ({plan_w:.0f}×{plan_h:.0f} mm) does not leave room for the "
            f"plans on {page.format}: choose a smaller Kl (drawing.Kl) or a larger format"
        )
    x0 = f.x0 + 4.0
    plan_box = Rect(x0 + (left_w - plan_w) / 2, top, x0 + (left_w + plan_w) / 2, top + plan_h)
    d_h = min(f.y1 - 4.0 - (plan_box.y1 + GAP), DIAGRAM_MAX_H)
    diagrams = Rect(x0, f.y1 - 4.0 - d_h, x0 + left_w, f.y1 - 4.0)

    gx0, gx1 = x0 + left_w + GAP + 4.0, f.x1 - 4.0
    table_h = ROW * (n_positions + 1) + CAPTION
    tb_w, tb_h = TITLE_BLOCK_SIZE
    strip = max(table_h, tb_h + GAP + SCALES_BLOCK)
    gy0, gy1 = f.y0 + 4.0, f.y1 - strip - GAP
    n_cells = 2 * (n_positions if n_plans is None else n_plans)
    best = None
    for ncol in range(1, n_cells + 1):
        nrow = math.ceil(n_cells / ncol)
        w, h = (gx1 - gx0) / ncol, (gy1 - gy0) / nrow
        room = min(w - 12.0, h - CAPTION - 12.0)
        if best is None or room > best[0]:
            best = (room, ncol, nrow, w, h)
    room, ncol, nrow, w, h = best  # type: ignore[misc]
    if room < 30.0:
        raise LayoutError(
            f"{n_cells} plans leave cells of {room:.0f} mm on {page.format}: choose the "
            "positions to draw (drawing.positions) or a larger format"
        )
    cells = tuple(Rect(gx0 + (i % ncol) * w, gy0 + (i // ncol) * h,
                       gx0 + (i % ncol + 1) * w, gy0 + (i // ncol + 1) * h)
                  for i in range(n_cells))
    tbx = f.x1 - tb_w
    table = Rect(gx0, f.y1 - 4.0 - table_h, tbx - GAP, f.y1 - 4.0)
    scales = Rect(tbx, f.y1 - tb_h - GAP / 2 - SCALES_BLOCK, f.x1 - 4.0, f.y1 - tb_h - GAP / 2)
    return Sheet1Layout(page, plan_box, diagrams, cells, table, scales)


@dataclass(frozen=True, slots=True)
class FittedTable:
    """A table cut to the width it has: the columns kept, their widths, and how many of all."""

    header: list[str]
    rows: list[list[str]]
    widths: list[float]
    shown: int
    total: int


def fit_columns(header, rows, width: float, height: float = 3.5,
                pad: float = 3.0) -> FittedTable:
    """Column widths from the lettering; the leading columns that fit into ``width``.

    A table wider than its place loses its last columns (the full table is in the
    markdown tables); the caller says so in the table's title.
    """
    from ..drawing.sheet import Text, text_width

    widths = []
    for j in range(len(header)):
        cells = [str(header[j])] + [str(row[j]) for row in rows]
        widths.append(max(text_width(Text((0, 0), c, height, layer="tables")) for c in cells
                          if c.strip()) + pad)
    keep, acc = [], 0.0
    for j, wd in enumerate(widths):
        if acc + wd > width:
            break
        keep.append(j)
        acc += wd
    return FittedTable([str(header[j]) for j in keep], [[row[j] for j in keep] for row in rows],
                       [widths[j] for j in keep], len(keep), len(header))


SHEET2_STRIP = 120.0  #: height of sheet 2's bottom strip (Mур(φ) and the table), mm
SHEET2_CELL_MIN = 60.0  #: smallest useful cell of sheet 2, mm
LABEL_ROOM = 12.0  #: room kept around a plan in its cell for letters, mm


def sheet2_cells(page: Page, n_groups: int, n_rows: int) -> tuple[tuple[Rect, ...], ...]:
    """The cells of sheet 2, one row per position: the scheme, the plans of the groups, the
    crank's plan, Zhukovsky's lever (each cell's top CAPTION mm for its caption)."""
    f = page.frame
    x0, y0, x1 = f.x0 + 4.0, f.y0 + GRAPH26_SIZE[1] + 8.0, f.x1 - 4.0
    y1 = f.y1 - SHEET2_STRIP - GAP
    ncol = n_groups + 3
    cw, ch = (x1 - x0) / ncol, (y1 - y0) / n_rows
    if min(cw, ch) < SHEET2_CELL_MIN:
        raise LayoutError(f"sheet 2 leaves cells of {min(cw, ch):.0f} mm on {page.format}: "
                          "choose fewer positions (kinetostatics.positions) or a larger format")
    return tuple(tuple(Rect(x0 + i * cw, y0 + r * ch, x0 + (i + 1) * cw, y0 + (r + 1) * ch)
                       for i in range(ncol)) for r in range(n_rows))


def plan_room(cell: Rect) -> float:
    """The largest extent (diameter) of a plan that fits ``cell`` with its letters, mm."""
    return min(cell.width, cell.height - CAPTION) - 2 * LABEL_ROOM


def titled_table(x0: float, y0: float, width: float, title: str, header, rows, *,
                 ident: str, title_id: str, notes=None) -> list:
    """A table under its title at (x0, y0), cut to ``width`` by :func:`fit_columns`.

    When columns were left out, ``notes(shown, total)`` gives the remarks to append to the
    title, longest first; the first that fits the width at 3.5 or 2.5 mm is used.
    """
    from ..drawing.sheet import Text, table_items, text_width

    fit = fit_columns(header, rows, width)
    text, height = title, 5.0
    if fit.shown < fit.total and notes is not None:
        for note in notes(fit.shown, fit.total):
            for h in (3.5, 2.5):
                if text_width(Text((0, 0), title + note, h, layer="text")) <= width:
                    text, height = title + note, h
                    break
            if height < 5.0:
                break
    items = [Text((x0, y0 + 5.0), text, height, layer="text", id=title_id)]
    items += table_items((x0, y0 + CAPTION), fit.widths, fit.rows, fit.header, 3.5, id=ident)
    return items
