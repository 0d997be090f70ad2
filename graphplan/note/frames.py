"""The frames of a text document's pages with the title blocks of GOST 2.104:
form 2 (185×40 mm, the first page of the text) and form 2a (185×15 mm, the others).

A4 portrait, the frame 20 mm from the left edge and 5 mm from the others (GOST 2.301), drawn
with the sheets' own items and lettering (type B); the page numbers are not drawn here —
the document writes them as fields into the cells :data:`SHEET_CELL` and :data:`SHEETS_CELL`.
"""

from __future__ import annotations

import svgwrite

from ..drawing import Line, Style, Text

A4 = (210.0, 297.0)
FRAME = (20.0, 5.0, 205.0, 292.0)  #: x0, y0, x1, y1, mm from the page's top-left corner
THICK = Style(0.7)
THIN = Style(0.35)
LEFT_COLUMNS = (7.0, 10.0, 23.0, 15.0, 10.0)  #: Изм., Лист, № докум., Подп., Дата
HEIGHT = {2: 40.0, 3: 15.0}  #: form 2 and form 2a ("3" in the code: the later pages)
#: where the page number goes: (x centre, y centre) of the "Лист" value cell, per form
SHEET_CELL = {2: (177.5, 274.5), 3: (200.0, 288.0)}
SHEETS_CELL = (195.0, 274.5)  #: the "Листов" value cell of form 2


def _line(a, b, style: Style = THICK) -> Line:
    return Line(a, b, style, layer="title")


def _text(x: float, y: float, s: str, h: float = 2.5, anchor: str = "middle") -> Text:
    return Text((x, y), s, h, anchor=anchor, layer="title")


def _fitted(x: float, y: float, s: str, width: float, heights=(3.5, 2.5)) -> list[Text]:
    """``s`` centred at (x, y) in a cell ``width`` wide: the largest height that fits, else
    two lines (split at the space nearest the middle) at the smallest."""
    from ..drawing.items import text_width

    for h in heights:
        t = _text(x, y, s, h)
        if text_width(t) <= width:
            return [t]
    h = heights[-1]
    spaces = [i for i, c in enumerate(s) if c == " "]
    if not spaces:
        return [_text(x, y, s, h)]
    cut = min(spaces, key=lambda i: abs(i - len(s) / 2))
    return [_text(x, y - 0.8 * h, s[:cut], h), _text(x, y + 0.8 * h, s[cut + 1:], h)]


def frame_items(form: int, *, designation: str, title: str, author: str, checker: str,
                organisation: str) -> list:
    """The frame and the title block of a page (``form`` 2: first page, 3: form 2a)."""
    x0, y0, x1, y1 = FRAME
    h = HEIGHT[form]
    top = y1 - h
    items: list = [_line((x0, y0), (x1, y0), THICK), _line((x1, y0), (x1, y1), THICK),
                   _line((x1, y1), (x0, y1), THICK), _line((x0, y1), (x0, y0), THICK),
                   _line((x0, top), (x1, top), THICK)]
    xs = [x0]
    for wdt in LEFT_COLUMNS:
        xs.append(xs[-1] + wdt)
    left_end = xs[-1]  # 85 mm
    rows = int(h // 5)
    for i in range(1, rows):  # the left part's rows, 5 mm each
        y = top + 5.0 * i
        items.append(_line((x0, y), (left_end, y), THICK if i == 2 else THIN))
    for x in xs[1:]:
        y_end = y1 if x == left_end else top + (15.0 if form == 2 else h)
        items.append(_line((x, top), (x, y_end), THICK))
    labels = ("Изм.", "Лист", "№ докум.", "Подп.", "Дата")
    label_y = top + 14.0
    for i, s in enumerate(labels):
        items.append(_text((xs[i] + xs[i + 1]) / 2, label_y, s, 1.8))
    if form == 2:
        for i, s in enumerate(("Разраб.", "Пров.", "", "Н.контр.", "Утв.")):
            y = top + 15.0 + 5.0 * i + 3.8
            if s:
                items.append(_text(xs[0] + 1.0, y, s, 1.8, "start"))
        for i, name in enumerate((author, checker)):
            if name:
                items.append(_text(xs[2] + 1.0, top + 18.8 + 5.0 * i, name, 2.5, "start"))
        for x in (xs[2], xs[3], xs[4]):
            items.append(_line((x, top + 15.0), (x, y1), THICK))
        items.append(_line((left_end, top + 15.0), (x1, top + 15.0), THICK))
        items.append(_text((left_end + x1) / 2, top + 10.0, designation, 5.0))
        name_x1 = left_end + 70.0
        items.append(_line((name_x1, top + 15.0), (name_x1, y1), THICK))
        items += _fitted((left_end + name_x1) / 2, top + 24.0, title, 66.0)
        items.append(_text((left_end + name_x1) / 2, top + 33.0, "Пояснительная записка", 3.5))
        r = name_x1
        items += [_line((r, top + 20.0), (x1, top + 20.0), THICK),
                  _line((r, top + 25.0), (x1, top + 25.0), THICK),
                  _line((r + 15.0, top + 15.0), (r + 15.0, top + 25.0), THICK),
                  _line((r + 30.0, top + 15.0), (r + 30.0, top + 25.0), THICK),
                  _line((r + 5.0, top + 20.0), (r + 5.0, top + 25.0), THIN),
                  _line((r + 10.0, top + 20.0), (r + 10.0, top + 25.0), THIN),
                  _text(r + 7.5, top + 18.8, "Лит.", 1.8),
                  _text(r + 22.5, top + 18.8, "Лист", 1.8),
                  _text(r + 40.0, top + 18.8, "Листов", 1.8),
                  _text(r + 2.5, top + 23.8, "У", 2.5),
                  *_fitted((r + x1) / 2, top + 33.5, organisation, 47.0)]
    else:
        sheet_x0 = x1 - 10.0
        items += [_line((sheet_x0, top), (sheet_x0, y1), THICK),
                  _line((sheet_x0, top + 7.0), (x1, top + 7.0), THIN),
                  _text((sheet_x0 + x1) / 2, top + 4.8, "Лист", 1.8),
                  _text((left_end + sheet_x0) / 2, top + 10.0, designation, 5.0)]
    return items


def frame_svg(form: int, **data: str) -> str:
    """The whole A4 page's frame and title block as SVG (white elsewhere)."""
    from ..render import svg as svg_render

    dwg = svgwrite.Drawing(size=(f"{A4[0]:g}mm", f"{A4[1]:g}mm"),
                           viewBox=f"0 0 {A4[0]:g} {A4[1]:g}", profile="full", debug=False)
    for item in frame_items(form, **data):
        if isinstance(item, Text) and not item.text:
            continue
        dwg.add(svg_render._element(dwg, item))
    return dwg.tostring()
