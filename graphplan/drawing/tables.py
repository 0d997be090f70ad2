"""Tables on a sheet: a table under its title, cut to its place or split into parts.

The columns' widths come from the lettering (:func:`graphplan.project.fit_columns`,
:func:`graphplan.project.table_parts`: the sheets' layouts size the tables before they are
drawn); here they become drawing items (:func:`graphplan.drawing.sheet.table_items`).
"""

from __future__ import annotations

from ..project import (
    CAPTION,
    ROW,
    TABLE_PAD,
    TABLE_PART_GAP,
    FittedTable,
    fit_columns,
    table_parts,
)
from .sheet import Text, table_items, text_width


def titled_table(x0: float, y0: float, width: float, title: str, header, rows, *,
                 ident: str, title_id: str, notes=None,
                 lettering: tuple[float, ...] = (3.5,)) -> list:
    """A table under its title at (x0, y0), cut to ``width`` by :func:`fit_columns`.

    ``lettering``: the heights of the table's lettering to try, largest first (GOST 2.304's
    3.5 and 2.5 mm): the first at which every column fits is used, its rows kept ROW tall and
    (a smaller one) its columns widened alike to span ``width``; when none fits, the last,
    cut. When columns were left out, ``notes(shown, total)`` gives the remarks to append to
    the title, longest first; the first that fits the width at 3.5 or 2.5 mm is used.
    """
    for lh in lettering:
        fit = fit_columns(header, rows, width, lh, TABLE_PAD * lh)
        if fit.shown == fit.total:
            break
    if lh < lettering[0] and fit.shown == fit.total:
        # smaller lettering to keep every column: the table still spans its place
        k = width / sum(fit.widths)
        fit = FittedTable(fit.header, fit.rows, [w * k for w in fit.widths], fit.shown, fit.total)
    text, height = title, 5.0
    if fit.shown < fit.total and notes is not None:
        for note in notes(fit.shown, fit.total):
            for h in (3.5, 2.5):
                if text_width(Text((0, 0), title + note, h, layer="text")) <= width:
                    text, height = title + note, h
                    break
            if height < 5.0:
                break
    items: list[object] = [Text((x0, y0 + 5.0), text, height, layer="text", id=title_id)]
    items += table_items((x0, y0 + CAPTION), fit.widths, fit.rows, fit.header, lh,
                         row_height=ROW, id=ident)
    return items


def split_table(x0: float, y0: float, width: float, title: str, header, rows, *, ident: str,
                title_id: str, continued: str, key: int = 1) -> list:
    """A table under its title at (x0, y0); wider than ``width``, in parts one under the
    other (:func:`table_parts`), each after the first under ``continued`` («Продолжение
    таблицы …») with the key columns and its own header. Ids: the first part
    ``{ident}-r{i}c{j}``, the n-th ``{ident}-{n}-r{i}c{j}``."""
    items: list = []
    y = y0
    for n, part in enumerate(table_parts(header, rows, width, key), 1):
        items.append(Text((x0, y + 5.0), title if n == 1 else continued, 5.0 if n == 1 else 3.5,
                          layer="text", id=title_id if n == 1 else f"{title_id}-{n}"))
        items += table_items((x0, y + CAPTION), part.widths, part.rows, part.header, 3.5,
                             id=ident if n == 1 else f"{ident}-{n}")
        y += CAPTION + ROW * (len(rows) + 1) + TABLE_PART_GAP
    return items


__all__ = ["split_table", "titled_table"]
