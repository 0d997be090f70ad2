"""Tables on a sheet: a table under its title, cut to its place or split into parts.

The columns' widths come from the lettering (:func:`graphplan.project.fit_columns`,
:func:`graphplan.project.table_parts`: the sheets' layouts size the tables before they are
drawn); here they become drawing items (:func:`table_items`).
"""

from __future__ import annotations

from collections.abc import Sequence

from .. import fonts
from ..errors import InputError, LayoutError
from ..project import (
    CAPTION,
    ROW,
    TABLE_PAD,
    TABLE_PART_GAP,
    FittedTable,
    fit_columns,
    table_parts,
)
from .items import (
    MAIN,
    THIN,
    Item,
    Line,
    Pt,
    Text,
    _positive,
    _pt,
    text_at_centre,
    text_width,
)


def table_items(origin: Pt, column_widths: Sequence[float], rows: Sequence[Sequence[object]],
                header: Sequence[object] | None = None, text_height: float = 3.5, *,
                row_height: float | None = None, align: Sequence[str] | None = None,
                layer: str = "tables", id: str | None = None) -> tuple[Item, ...]:
    """A ruled table: border and header rule in main line, inner rules thin, texts centred.

    ``origin`` is the top-left corner. Every row is ``row_height`` tall (default
    2·text_height, e.g. 7 mm for 3.5 mm lettering); the table is
    ``sum(column_widths)`` wide and ``row_height·(len(rows) + (header is not None))``
    tall. ``align`` gives "start"/"middle"/"end" per column (default "middle"); cell
    values are formatted with ``str``. Ids: ``{id}-r{i}c{j}`` (header row 0).
    Raises LayoutError if a value is wider than its cell.
    """
    ox, oy = _pt(origin, "table origin")
    widths = [_positive(w, "table column width") for w in column_widths]
    if not widths:
        raise InputError("a table needs at least one column")
    rh = _positive(row_height if row_height is not None else 2 * text_height, "table row height")
    al = list(align) if align is not None else ["middle"] * len(widths)
    if len(al) != len(widths):
        raise InputError(f"table align has {len(al)} entries for {len(widths)} columns")
    body = [list(r) for r in rows]
    all_rows = ([list(header)] if header is not None else []) + body
    for i, r in enumerate(all_rows):
        if len(r) != len(widths):
            raise InputError(f"table row {i}: {len(r)} cells for {len(widths)} columns")
    xs = [ox]
    for w in widths:
        xs.append(xs[-1] + w)
    n = len(all_rows)
    ys = [oy + rh * i for i in range(n + 1)]
    pre = f"{id}-" if id else ""
    items: list[Item] = []
    for i, y in enumerate(ys):
        main = i in (0, n) or (header is not None and i == 1)
        items.append(Line((xs[0], y), (xs[-1], y), MAIN if main else THIN, layer=layer,
                          id=f"{pre}h{i}" if id else None))
    for j, x in enumerate(xs):
        main = j in (0, len(widths))
        items.append(Line((x, ys[0]), (x, ys[-1]), MAIN if main else THIN, layer=layer,
                          id=f"{pre}v{j}" if id else None))
    pad = 1.0
    for i, r in enumerate(all_rows):
        row_no = i if header is not None else i + 1
        for j, value in enumerate(r):
            s = str(value).strip()
            if not s:
                continue
            if fonts.lettering_width(s, text_height) > widths[j] - 2 * pad:
                raise LayoutError(
                    f"table {id or ''} row {row_no} column {j + 1}: {s!r} is wider than "
                    f"{widths[j]:g} mm at {text_height:g} mm lettering"
                )
            x = {"start": xs[j] + pad, "middle": (xs[j] + xs[j + 1]) / 2,
                 "end": xs[j + 1] - pad}[al[j]]
            items.append(text_at_centre((x, (ys[i] + ys[i + 1]) / 2), s, text_height, anchor=al[j],
                                        layer=layer, id=f"{pre}r{row_no}c{j + 1}" if id else None))
    return tuple(items)


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


__all__ = ["split_table", "table_items", "titled_table"]
