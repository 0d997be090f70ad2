"""The frame of a sheet and its main title block, GOST 2.104 form 1 (and graph 26).

Paper in mm from the sheet's top-left corner, y down (:mod:`graphplan.drawing.items`).
"""


from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass

from .. import fonts
from ..errors import InputError, LayoutError
from ..paper import Page, Rect
from .items import (
    LINE_PITCH,
    MAIN,
    THIN,
    Item,
    Line,
    Polyline,
    S,
    Style,
    Text,
    text_at_centre,
)


def _rect_items(r: Rect, style: Style, layer: str, id: str) -> Polyline:
    return Polyline(((r.x0, r.y0), (r.x1, r.y0), (r.x1, r.y1), (r.x0, r.y1)), style, True,
                    layer=layer, id=id)


def frame_items(page: Page) -> tuple[Item, ...]:
    """Trim border (thin) and inner frame (main line) of ``page``."""
    return (
        _rect_items(page.trim, THIN, "frame", "trim"),
        _rect_items(page.frame, MAIN, "frame", "frame"),
    )


#: Segments of form 1 (GOST 2.104, KiCad WS_Osn1), title-block coordinates (top-left
#: origin, y down): (weight, x0, y0, x1, y1), "S" main line, "t" thin. The bottom and
#: right edges of the block are the frame's own lines.
FORM1_SEGMENTS: tuple[tuple[str, float, float, float, float], ...] = (
    ("S", 0, 0, 185, 0), ("S", 0, 0, 0, 55), ("S", 7, 0, 7, 25), ("S", 17, 0, 17, 55),
    ("S", 40, 0, 40, 55), ("S", 55, 0, 55, 55), ("S", 65, 0, 65, 55), ("S", 65, 15, 185, 15),
    ("S", 65, 40, 185, 40), ("S", 0, 20, 65, 20), ("S", 0, 25, 65, 25), ("S", 135, 20, 185, 20),
    ("S", 135, 35, 185, 35), ("S", 135, 15, 135, 55), ("S", 150, 15, 150, 35),
    ("S", 167, 15, 167, 35), ("S", 155, 35, 155, 40),
    ("t", 0, 5, 65, 5), ("t", 0, 10, 65, 10), ("t", 0, 15, 65, 15), ("t", 0, 30, 65, 30),
    ("t", 0, 35, 65, 35), ("t", 0, 40, 65, 40), ("t", 0, 45, 65, 45), ("t", 0, 50, 65, 50),
    ("t", 140, 20, 140, 35), ("t", 145, 20, 145, 35),
)

#: Printed labels of form 1: (id, text, cell x0, y0, x1, y1, anchor). A label is
#: centred in its cell, or starts 1 mm inside it; the cells put the capitals' centres
#: on KiCad's points, e.g. "Изм." c(3.5, 22.5), "Лист" l(136, 37.5).
FORM1_LABELS: tuple[tuple[str, str, float, float, float, float, str], ...] = (
    ("izm", "Изм.", 0, 20, 7, 25, "middle"), ("list", "Лист", 7, 20, 17, 25, "middle"),
    ("doc", "№ докум.", 17, 20, 40, 25, "middle"), ("podp", "Подп.", 40, 20, 55, 25, "middle"),
    ("data", "Дата", 55, 20, 65, 25, "middle"),
    ("lit", "Лит.", 135, 15, 150, 20, "middle"), ("massa", "Масса", 150, 15, 167, 20, "middle"),
    ("masshtab", "Масштаб", 167, 15, 185, 20, "middle"),
    ("sheet", "Лист", 135, 35, 146, 40, "start"), ("sheets", "Листов", 155, 35, 173, 40, "start"),
)
LABEL_HEIGHTS = (2.5, 1.8)  #: printed labels: 2.5 mm, 1.8 if a font is too wide

#: Signature rows (role, surname, date) of graphs 10, 11 and 13, rows y = 25..55.
DEFAULT_SIGNATURES: tuple[tuple[str, str, str], ...] = (
    ("Разраб.", "", ""), ("Пров.", "", ""), ("Т.контр.", "", ""), ("", "", ""),
    ("Н.контр.", "", ""), ("Утв.", "", ""),
)


def signatures(author: str = "", checker: str = "", *, tech_control: str = "",
               extra: tuple[str, str] = ("", ""), norm_control: str = "", approved: str = "",
               date: str = "") -> tuple[tuple[str, str, str], ...]:
    """The six signature rows of form 1 filled with surnames (one date for the author).

    ``extra`` is (role, surname) of the free fourth row, e.g. ("Консульт.", "Петров").
    """
    return (
        ("Разраб.", author, date), ("Пров.", checker, ""), ("Т.контр.", tech_control, ""),
        (extra[0], extra[1], ""), ("Н.контр.", norm_control, ""), ("Утв.", approved, ""),
    )


@dataclass(frozen=True, slots=True)
class TitleBlock:
    """Contents of the main title block, GOST 2.104 form 1 (graph numbers in brackets).

    designation [2], title [1] (wrapped as needed), material [3], litera [4] (up to
    three characters, one per cell), mass [5], scale [6], sheet [7], sheets [8],
    organisation [9], signatures [10, 11, 13] as up to six (role, surname, date) rows.
    ``margin_labels`` prints "Копировал" and "Формат А1" under the frame (graphs 31, 32).
    """

    designation: str = ""
    title: str = ""
    material: str = ""
    litera: str = ""
    mass: str = ""
    scale: str = ""
    sheet: int | None = None
    sheets: int | None = None
    organisation: str = ""
    signatures: tuple[tuple[str, str, str], ...] = DEFAULT_SIGNATURES
    margin_labels: bool = True

    def __post_init__(self) -> None:
        for name in ("designation", "title", "material", "litera", "mass", "scale",
                     "organisation"):
            v = getattr(self, name)
            if not isinstance(v, str) or "\n" in v:
                raise InputError(f"title block {name} must be a one-line string (got {v!r})")
        if len(self.litera.replace(" ", "")) > 3:
            raise InputError(f"title block litera has 3 cells (got {self.litera!r})")
        for name in ("sheet", "sheets"):
            v = getattr(self, name)
            if v is not None and (not isinstance(v, int) or v < 1):
                raise InputError(f"title block {name} must be a positive integer (got {v!r})")
        rows = tuple(tuple(str(c) for c in row) for row in self.signatures)
        if len(rows) > 6 or any(len(r) != 3 for r in rows):
            raise InputError("title block signatures: up to 6 rows of (role, surname, date)")
        object.__setattr__(self, "signatures", rows)


def _wrap(text: str, height: float, width: float) -> list[str] | None:
    """Word wrap at capital height ``height`` into as few lines as fit ``width``.

    The number of lines is the greedy one; the breaks are then chosen to make the
    longest line as short as possible (balanced lines: "Кафедра ТММ, / гр. МТ-21"
    rather than "Кафедра ТММ, гр. / МТ-21"). None if one word alone is too wide.
    """
    words = text.split()
    lines: list[str] = []
    for word in words:
        trial = f"{lines[-1]} {word}" if lines else word
        if lines and _width(trial, height) <= width:
            lines[-1] = trial
        elif _width(word, height) <= width:
            lines.append(word)
        else:
            return None
    n = len(lines)
    if n < 2 or len(words) > 16:
        return lines
    best, best_key = lines, None
    for cuts in itertools.combinations(range(1, len(words)), n - 1):
        bounds = (0, *cuts, len(words))
        cand = [" ".join(words[a:b]) for a, b in itertools.pairwise(bounds)]
        ws = [_width(c, height) for c in cand]
        if max(ws) > width:
            continue
        key = (round(max(ws), 6), sum(w * w for w in ws))
        if best_key is None or key < best_key:
            best, best_key = cand, key
    return best


def _width(s: str, h: float) -> float:
    return fonts.lettering_width(s, h)


def _fit(text: str, cell: Rect, heights: Sequence[float], what: str, *, wrap: bool = False,
         pad: float = 1.0) -> tuple[float, list[str]]:
    """Largest height of ``heights`` at which ``text`` fits ``cell`` (wrapped if allowed)."""
    w, hmax = cell.width - 2 * pad, cell.height - 1.0  # 0.5 mm clear above and below
    for h in heights:
        lines = _wrap(text, h, w) if wrap else ([text] if _width(text, h) <= w else None)
        if lines and h + (len(lines) - 1) * LINE_PITCH * h + 0.3 * h <= hmax + 1e-9:
            return h, lines
    raise LayoutError(
        f"title block {what}: {text!r} does not fit its {cell.width:g}×{cell.height:g} mm cell "
        f"even at {heights[-1]:g} mm lettering"
    )


def _cell_texts(text: str, cell: Rect, heights: Sequence[float], what: str, id: str,
                *, wrap: bool = False, anchor: str = "middle", pad: float = 1.0,
                rotate_deg: float = 0.0) -> list[Text]:
    """Texts of one cell: largest fitting height, lines centred as a block in the cell."""
    if not text.strip():
        return []
    h, lines = _fit(text.strip(), cell, heights, what, wrap=wrap, pad=pad)
    cy = (cell.y0 + cell.y1) / 2
    cx = {"middle": (cell.x0 + cell.x1) / 2, "start": cell.x0 + pad, "end": cell.x1 - pad}[anchor]
    pitch = LINE_PITCH * h
    out = []
    for i, line in enumerate(lines):
        dy = (i - (len(lines) - 1) / 2) * pitch
        if rotate_deg == 180.0:  # upside down: the first line is lowest on the paper
            dy = -dy
        ident = id if len(lines) == 1 else f"{id}-{i + 1}"
        out.append(text_at_centre((cx, cy + dy), line, h, anchor=anchor, rotate_deg=rotate_deg,
                                  layer="title", id=ident))
    return out


def title_block_items(page: Page, tb: TitleBlock) -> tuple[Item, ...]:
    """Lines, printed labels and filled-in values of form 1, plus graph 26.

    Placed in the bottom-right corner of the frame of ``page`` (origin
    ``page.title_block_origin``); all items are on the "title" layer. Values take the
    largest GOST lettering that fits their cell: designation 7/5/3.5 mm, title
    7/5/3.5/2.5 (wrapped), organisation 5/3.5/2.5 (wrapped), surnames 3.5/2.5/1.8,
    labels 2.5. Raises LayoutError if a value does not fit even at the smallest size.
    """
    ox, oy = page.title_block_origin

    def R(x0: float, y0: float, x1: float, y1: float) -> Rect:
        return Rect(ox + x0, oy + y0, ox + x1, oy + y1)

    items: list[Item] = []
    for i, (w, x0, y0, x1, y1) in enumerate(FORM1_SEGMENTS, 1):
        items.append(Line((ox + x0, oy + y0), (ox + x1, oy + y1), MAIN if w == "S" else THIN,
                          layer="title", id=f"tb-line-{i:02d}"))
    for slug, text, x0, y0, x1, y1, anchor in FORM1_LABELS:
        items += _cell_texts(text, R(x0, y0, x1, y1), LABEL_HEIGHTS, f"label {text!r}",
                             f"tb-label-{slug}", anchor=anchor,
                             pad=1.0 if anchor == "start" else S / 2 + 0.1)  # clear of the line
    for i, (role, surname, date) in enumerate(tb.signatures):
        y0 = 25 + 5 * i
        items += _cell_texts(role, R(0, y0, 17, y0 + 5), LABEL_HEIGHTS, f"role row {i + 1}",
                             f"tb-role-{i + 1}", anchor="start", pad=1.0)
        items += _cell_texts(surname, R(17, y0, 40, y0 + 5), (3.5, 2.5, 1.8),
                             f"surname row {i + 1}", f"tb-surname-{i + 1}", anchor="start", pad=0.5)
        items += _cell_texts(date, R(55, y0, 65, y0 + 5), (2.5, 1.8), f"date row {i + 1}",
                             f"tb-date-{i + 1}", pad=0.3)
    items += _cell_texts(tb.designation, R(65, 0, 185, 15), (7.0, 5.0, 3.5),
                         "graph 2 (designation)", "tb-designation", pad=2.0)
    items += _cell_texts(tb.title, R(65, 15, 135, 40), (7.0, 5.0, 3.5, 2.5), "graph 1 (title)",
                         "tb-title", wrap=True, pad=1.5)
    items += _cell_texts(tb.material, R(65, 40, 135, 55), (5.0, 3.5, 2.5), "graph 3 (material)",
                         "tb-material", wrap=True, pad=1.5)
    for i, ch in enumerate(tb.litera.replace(" ", "")):
        items += _cell_texts(ch, R(135 + 5 * i, 20, 140 + 5 * i, 35), (3.5, 2.5),
                             "graph 4 (litera)", f"tb-litera-{i + 1}", pad=0.5)
    items += _cell_texts(tb.mass, R(150, 20, 167, 35), (5.0, 3.5, 2.5), "graph 5 (mass)",
                         "tb-mass")
    items += _cell_texts(tb.scale, R(167, 20, 185, 35), (5.0, 3.5, 2.5), "graph 6 (scale)",
                         "tb-scale")
    if tb.sheet is not None:
        items.append(text_at_centre((ox + 149, oy + 37.5), str(tb.sheet), 2.5, layer="title",
                                    id="tb-sheet"))
    if tb.sheets is not None:
        items.append(text_at_centre((ox + 175, oy + 37.5), str(tb.sheets), 2.5, anchor="start",
                                    layer="title", id="tb-sheets"))
    items += _cell_texts(tb.organisation, R(135, 40, 185, 55), (5.0, 3.5, 2.5),
                         "graph 9 (organisation)", "tb-organisation", wrap=True, pad=1.5)
    if tb.margin_labels:
        fmt = "А" + page.format[1:]  # Cyrillic А, as printed on Russian sheets
        items.append(text_at_centre((ox + 75, oy + 57.5), "Копировал", 2.5, anchor="start",
                                    layer="title", id="tb-label-copied"))
        items.append(text_at_centre((ox + 145, oy + 57.5), "Формат", 2.5, anchor="start",
                                    layer="title", id="tb-label-format"))
        items.append(text_at_centre((ox + 165, oy + 57.5), fmt, 2.5, anchor="start",
                                    layer="title", id="tb-format"))
    # graph 26: the designation turned 180° in a 70×14 box at the frame's top-left
    g = page.graph26_rect
    items.append(Line((g.x1, g.y0), (g.x1, g.y1), MAIN, layer="title", id="tb-g26-right"))
    items.append(Line((g.x0, g.y1), (g.x1, g.y1), MAIN, layer="title", id="tb-g26-bottom"))
    items += _cell_texts(tb.designation, g, (5.0, 3.5, 2.5), "graph 26 (designation)",
                         "tb-g26", pad=2.0, rotate_deg=180.0)
    return tuple(items)
