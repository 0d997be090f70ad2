"""The note as a DOCX (python-docx, the ``note`` extra), laid out after GOST 2.105.

A4 portrait; the title page without a frame; from the contents on, every page has the frame
with the title block (GOST 2.104 form 2 on the first page of the text, form 2a on the
others) drawn as a picture behind the text in the page header, and the page number (and on
the first page the number of pages) as Word fields in their cells. Times New Roman 14 pt,
1.5 lines, paragraph indent 12.5 mm; numbered headings ("1", "2.1"); formulas centred with
their number "(2.3)" at the right margin; "Таблица N – …" above each table, "Рисунок N – …"
below each picture. The contents are a TOC field Word and LibreOffice fill in on opening.

Styles the checker reads back (:mod:`graphplan.checking.note_reader`): the calculation's
lines are paragraphs of the style ``GP Formula``; a position's lines follow a heading
``Положение N, …`` (``Position N, …``); an arm is declared by a paragraph
``h — плечо силы F относительно точки B, мм``.
"""

from __future__ import annotations

import io
import zipfile
from copy import deepcopy

from ..render import require
from .blocks import Arm, Figure, Formula, Heading, Note, Paragraph, Table
from .figures import svg_png
from .frames import A4, FRAME, HEIGHT, SHEET_CELL, frame_svg

FORMULA_STYLE = "GP Formula"  #: the calculation's lines (read back by the checker)
SHOWN_STYLE = "GP Calculation"  #: lines shown only (the dynamics)
LEFT, RIGHT, TOP = 25.0, 10.0, 15.0  #: text margins, mm: 5 mm inside the frame
BOTTOM = {2: 297.0 - (FRAME[3] - HEIGHT[2]) + 3.0, 3: 297.0 - (FRAME[3] - HEIGHT[3]) + 3.0}
FOOTER_DISTANCE = 7.0  #: mm from the page's bottom edge to the page-number line's bottom
FRAME_DPI = 300.0
_FIXED_TIME = (1980, 1, 1, 0, 0, 0)

WORDS = {
    "ru": {"contents": "Содержание", "table": "Таблица", "figure": "Рисунок",
           "note": "ПОЯСНИТЕЛЬНАЯ ЗАПИСКА",
           "to": "к курсовому проекту по теории механизмов и машин",
           "author": "Выполнил", "checker": "Проверил",
           "toc_hint": "(обновите поле: F9 в Word, Сервис → Обновить в LibreOffice)"},
    "en": {"contents": "Contents", "table": "Table", "figure": "Figure",
           "note": "EXPLANATORY NOTE", "to": "to the course project in the theory of machines "
                                              "and mechanisms",
           "author": "Done by", "checker": "Checked by",
           "toc_hint": "(update the field: F9 in Word, Tools → Update in LibreOffice)"},
}


def _field(paragraph, instr: str, placeholder: str = "1") -> None:
    """A Word field (``PAGE``, ``NUMPAGES``, ``TOC …``) in ``paragraph``."""
    from docx.oxml import OxmlElement
    from docx.oxml.ns import qn

    def run_with(child):
        r = OxmlElement("w:r")
        r.append(child)
        paragraph._p.append(r)

    begin = OxmlElement("w:fldChar")
    begin.set(qn("w:fldCharType"), "begin")
    begin.set(qn("w:dirty"), "true")
    run_with(begin)
    text = OxmlElement("w:instrText")
    text.set(qn("xml:space"), "preserve")
    text.text = f" {instr} "
    run_with(text)
    sep = OxmlElement("w:fldChar")
    sep.set(qn("w:fldCharType"), "separate")
    run_with(sep)
    shown = OxmlElement("w:r")
    for i, line in enumerate(placeholder.split("\n")):
        if i:
            shown.append(OxmlElement("w:br"))
        t = OxmlElement("w:t")
        t.set(qn("xml:space"), "preserve")
        t.text = line
        shown.append(t)
    paragraph._p.append(shown)
    end = OxmlElement("w:fldChar")
    end.set(qn("w:fldCharType"), "end")
    run_with(end)


def _behind_text(run, width_mm: float, height_mm: float) -> None:
    """Turn the run's inline picture into one anchored at the page's top-left, behind text."""
    from docx.oxml import parse_xml
    from docx.shared import Mm

    inline = run._r.find(".//{http://schemas.openxmlformats.org/drawingml/2006/"
                         "wordprocessingDrawing}inline")
    graphic = deepcopy(inline.find("{http://schemas.openxmlformats.org/drawingml/2006/main}"
                                   "graphic"))
    doc_pr = inline.find("{http://schemas.openxmlformats.org/drawingml/2006/"
                         "wordprocessingDrawing}docPr")
    cx, cy = int(Mm(width_mm)), int(Mm(height_mm))
    anchor = parse_xml(
        '<wp:anchor xmlns:wp="http://schemas.openxmlformats.org/drawingml/2006/'
        'wordprocessingDrawing" distT="0" distB="0" distL="0" distR="0" simplePos="0" '
        'relativeHeight="0" behindDoc="1" locked="1" layoutInCell="1" allowOverlap="1">'
        '<wp:simplePos x="0" y="0"/>'
        '<wp:positionH relativeFrom="page"><wp:posOffset>0</wp:posOffset></wp:positionH>'
        '<wp:positionV relativeFrom="page"><wp:posOffset>0</wp:posOffset></wp:positionV>'
        f'<wp:extent cx="{cx}" cy="{cy}"/><wp:effectExtent l="0" t="0" r="0" b="0"/>'
        '<wp:wrapNone/></wp:anchor>')
    anchor.append(deepcopy(doc_pr))
    anchor.append(parse_xml(
        '<wp:cNvGraphicFramePr xmlns:wp="http://schemas.openxmlformats.org/drawingml/2006/'
        'wordprocessingDrawing"/>'))
    anchor.append(graphic)
    inline.getparent().replace(inline, anchor)


def _styles(doc) -> None:
    from docx.enum.style import WD_STYLE_TYPE
    from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_TAB_ALIGNMENT
    from docx.shared import Mm, Pt

    normal = doc.styles["Normal"]
    normal.font.name = "Times New Roman"
    normal.font.size = Pt(14)
    pf = normal.paragraph_format
    pf.line_spacing = 1.5
    pf.first_line_indent = Mm(12.5)
    pf.space_after = Pt(0)
    pf.alignment = WD_ALIGN_PARAGRAPH.JUSTIFY
    for level, size in ((1, 16), (2, 14), (3, 14)):
        st = doc.styles[f"Heading {level}"]
        st.font.name = "Times New Roman"
        st.font.size = Pt(size)
        st.font.bold = True
        st.font.italic = False
        st.font.color.rgb = None
        st.paragraph_format.first_line_indent = Mm(12.5)
        st.paragraph_format.space_before = Pt(12)
        st.paragraph_format.space_after = Pt(6)
        st.paragraph_format.keep_with_next = True
    text_width = A4[0] - LEFT - RIGHT
    for name in (FORMULA_STYLE, SHOWN_STYLE):
        st = doc.styles.add_style(name, WD_STYLE_TYPE.PARAGRAPH)
        st.base_style = normal
        st.paragraph_format.first_line_indent = Mm(0)
        st.paragraph_format.alignment = WD_ALIGN_PARAGRAPH.LEFT
        st.paragraph_format.tab_stops.add_tab_stop(Mm(text_width), WD_TAB_ALIGNMENT.RIGHT)
    for name in ("GP Caption", "GP Table"):
        st = doc.styles.add_style(name, WD_STYLE_TYPE.PARAGRAPH)
        st.base_style = normal
        st.paragraph_format.first_line_indent = Mm(0)
        st.paragraph_format.line_spacing = 1.0
    doc.styles["GP Table"].font.size = Pt(10)
    doc.styles["GP Table"].paragraph_format.alignment = WD_ALIGN_PARAGRAPH.LEFT


def _margins(section, form: int) -> None:
    from docx.shared import Mm

    section.page_width, section.page_height = Mm(A4[0]), Mm(A4[1])
    section.left_margin, section.right_margin = Mm(LEFT), Mm(RIGHT)
    section.top_margin, section.bottom_margin = Mm(TOP), Mm(BOTTOM[form])
    section.header_distance = Mm(0)
    section.footer_distance = Mm(FOOTER_DISTANCE)


def _frame_header(header, png: bytes) -> None:
    from docx.shared import Mm

    p = header.paragraphs[0]
    p.paragraph_format.first_line_indent = Mm(0)
    run = p.add_run()
    run.add_picture(io.BytesIO(png), width=Mm(A4[0]), height=Mm(A4[1]))
    _behind_text(run, A4[0], A4[1])


def _no_cell_margins(table) -> None:
    """Cells without inner margins: a page number "123" fits the 10 mm "Лист" cell."""
    from docx.oxml import OxmlElement
    from docx.oxml.ns import qn

    mar = OxmlElement("w:tblCellMar")
    for side in ("top", "left", "bottom", "right"):
        el = OxmlElement(f"w:{side}")
        el.set(qn("w:w"), "0")
        el.set(qn("w:type"), "dxa")
        mar.append(el)
    table._tbl.tblPr.append(mar)


def _number_footer(footer, form: int) -> None:
    """The page number in the "Лист" cell (and on form 2 the count in "Листов"): a
    borderless one-row table whose cells stand over the title block's cells."""
    from docx.enum.table import WD_ROW_HEIGHT_RULE
    from docx.enum.text import WD_ALIGN_PARAGRAPH
    from docx.shared import Mm, Pt

    x, y = SHEET_CELL[form]
    half = 7.5 if form == 2 else 5.0
    cells = [(x - half, x + half, "PAGE")]
    if form == 2:
        cells.append((x + half, FRAME[2], "NUMPAGES"))
    widths = [cells[0][0] - LEFT] + [b - a for a, b, _ in cells]
    table = footer.add_table(rows=1, cols=len(widths), width=Mm(sum(widths)))
    table.autofit = False
    _no_cell_margins(table)
    row = table.rows[0]
    row.height = Mm(5.0)
    row.height_rule = WD_ROW_HEIGHT_RULE.EXACTLY
    for j, wdt in enumerate(widths):
        table.columns[j].width = Mm(wdt)
        cell = table.cell(0, j)
        cell.width = Mm(wdt)
        p = cell.paragraphs[0]
        p.paragraph_format.first_line_indent = Mm(0)
        p.paragraph_format.line_spacing = 1.0
        p.paragraph_format.alignment = WD_ALIGN_PARAGRAPH.CENTER
        if j:
            _field(p, cells[j - 1][2])
            for r in p.runs:
                r.font.size = Pt(11)
    # the row's bottom at the cell's bottom: an empty paragraph below fills the rest
    below = (A4[1] - FOOTER_DISTANCE) - (y + 2.5)
    first = footer.paragraphs[0]
    first.paragraph_format.line_spacing = Pt(1)
    first.paragraph_format.first_line_indent = Mm(0)
    tail = footer.add_paragraph()
    tail.paragraph_format.first_line_indent = Mm(0)
    tail.paragraph_format.line_spacing = Mm(max(below, 1.0))
    tail.paragraph_format.space_before = Mm(0)
    tail.paragraph_format.space_after = Mm(0)
    # keep the body text above the title block: the footer reaches up to the block's top
    top_gap = (y - 2.5) - (FRAME[3] - HEIGHT[form]) + 1.0
    first.paragraph_format.space_before = Mm(max(top_gap, 0.0))


def _table(doc, t: Table) -> None:
    from docx.shared import Pt

    table = doc.add_table(rows=1 + len(t.rows), cols=len(t.header))
    table.style = doc.styles["Table Grid"]
    # a wide table in a smaller type, so that its numbers stay on one line
    size = Pt(10 if len(t.header) <= 6 else 8)
    for j, h in enumerate(t.header):
        cell = table.cell(0, j)
        cell.text = h
        cell.paragraphs[0].style = doc.styles["GP Table"]
        for r in cell.paragraphs[0].runs:
            r.font.bold = True
            r.font.size = size
    for i, row in enumerate(t.rows, 1):
        for j in range(len(t.header)):
            cell = table.cell(i, j)
            cell.text = row[j] if j < len(row) else ""
            cell.paragraphs[0].style = doc.styles["GP Table"]
            for r in cell.paragraphs[0].runs:
                r.font.size = size
    header_row = table.rows[0]._tr
    from docx.oxml import OxmlElement
    from docx.oxml.ns import qn

    tr_pr = header_row.get_or_add_trPr()
    repeat = OxmlElement("w:tblHeader")
    repeat.set(qn("w:val"), "true")
    tr_pr.append(repeat)
    doc.add_paragraph().paragraph_format.space_after = Pt(6)


def _deterministic(data: bytes) -> bytes:
    """The same bytes for the same note: every zip entry dated 1980-01-01."""
    src = zipfile.ZipFile(io.BytesIO(data))
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as dst:
        for info in src.infolist():
            fixed = zipfile.ZipInfo(info.filename, date_time=_FIXED_TIME)
            fixed.compress_type = zipfile.ZIP_DEFLATED
            dst.writestr(fixed, src.read(info.filename))
    return out.getvalue()


def _contents(note: Note) -> list[str]:
    """The headings of levels 1–2 as numbered in the text (the contents' first filling,
    until Word or LibreOffice updates the field with the page numbers)."""
    out, numbers = [], [0, 0, 0]
    for b in note.blocks:
        if not isinstance(b, Heading) or b.level > 2:
            continue
        if b.numbered:
            numbers[b.level - 1] += 1
            numbers[b.level:] = [0] * (3 - b.level)
            out.append(".".join(str(n) for n in numbers[:b.level]) + " " + b.text)
        else:
            out.append(b.text)
    return out


def note_docx(note: Note) -> bytes:
    """The DOCX of ``note`` (see the module docstring)."""
    require("docx", "docx", extra="note")
    from docx import Document
    from docx.enum.section import WD_SECTION
    from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_BREAK
    from docx.shared import Mm, Pt

    w = WORDS[note.lang]
    doc = Document()
    _styles(doc)
    props = doc.core_properties
    props.title = note.title
    props.author = note.author
    props.subject = note.designation
    props.keywords = f"graphplan-variant={note.variant}"
    props.comments = "graphplan explanatory note"

    # the title page: no frame
    first = doc.sections[0]
    _margins(first, 3)
    first.top_margin = Mm(20)
    first.bottom_margin = Mm(20)

    def centred(text: str, size: int = 14, bold: bool = False, before: float = 0.0):
        p = doc.add_paragraph()
        p.alignment = WD_ALIGN_PARAGRAPH.CENTER
        p.paragraph_format.first_line_indent = Mm(0)
        p.paragraph_format.space_before = Mm(before)
        r = p.add_run(text)
        r.font.size = Pt(size)
        r.font.bold = bold
        return p

    centred(note.organisation or " ")
    centred(w["note"], 20, True, before=70)
    centred(w["to"], 14)
    centred(note.title, 16, True, before=10)
    centred(f"{note.designation} ПЗ" if note.designation else "", 14, before=5)
    for word, name in ((w["author"], note.author), (w["checker"], note.checker)):
        p = doc.add_paragraph()
        p.alignment = WD_ALIGN_PARAGRAPH.RIGHT
        p.paragraph_format.space_before = Mm(25 if word == w["author"] else 2)
        p.add_run(f"{word}: {name}")

    # the text: frames from here on
    sec = doc.add_section(WD_SECTION.NEW_PAGE)
    _margins(sec, 3)
    sec.different_first_page_header_footer = True
    for hdr in (sec.header, sec.first_page_header, sec.footer, sec.first_page_footer):
        hdr.is_linked_to_previous = False
    data = {"designation": f"{note.designation} ПЗ".strip(), "title": note.title,
            "author": note.author, "checker": note.checker,
            "organisation": note.organisation}
    _frame_header(sec.first_page_header, svg_png(frame_svg(2, **data), FRAME_DPI))
    _frame_header(sec.header, svg_png(frame_svg(3, **data), FRAME_DPI))
    _number_footer(sec.first_page_footer, 2)
    _number_footer(sec.footer, 3)

    h = doc.add_paragraph(w["contents"], style="Heading 1")
    h.alignment = WD_ALIGN_PARAGRAPH.CENTER
    toc = doc.add_paragraph()
    toc.alignment = WD_ALIGN_PARAGRAPH.LEFT
    toc.paragraph_format.first_line_indent = Mm(0)
    _field(toc, 'TOC \\o "1-2" \\h \\z \\u', "\n".join(_contents(note)) or w["toc_hint"])
    doc.add_paragraph().add_run().add_break(WD_BREAK.PAGE)

    numbers = [0, 0, 0]
    formula_no = table_no = figure_no = 0
    for b in note.blocks:
        if isinstance(b, Heading):
            if b.numbered:
                numbers[b.level - 1] += 1
                for j in range(b.level, 3):
                    numbers[j] = 0
                if b.level == 1:
                    formula_no = 0
                num = ".".join(str(n) for n in numbers[:b.level])
                text = f"{num} {b.text}"
            else:
                text = b.text
            p = doc.add_paragraph(text, style=f"Heading {b.level}")
            if not b.numbered:
                p.alignment = WD_ALIGN_PARAGRAPH.CENTER
                p.paragraph_format.first_line_indent = Mm(0)
        elif isinstance(b, Formula):
            formula_no += 1
            style = FORMULA_STYLE if b.checkable else SHOWN_STYLE
            doc.add_paragraph(f"{b.text}\t({numbers[0]}.{formula_no})", style=style)
        elif isinstance(b, Arm):
            words = ("{name} — плечо силы {force} относительно точки {about}, мм"
                     if note.lang == "ru" else "{name} is the arm of {force} about point "
                                                "{about}, mm")
            doc.add_paragraph(words.format(name=b.name, force=b.force, about=b.about))
        elif isinstance(b, Paragraph):
            doc.add_paragraph(b.text)
        elif isinstance(b, Table):
            table_no += 1
            cap = doc.add_paragraph(f"{w['table']} {table_no} – {b.caption}", style="GP Caption")
            cap.paragraph_format.keep_with_next = True
            _table(doc, b)
        elif isinstance(b, Figure):
            figure_no += 1
            p = doc.add_paragraph(style="GP Caption")
            p.alignment = WD_ALIGN_PARAGRAPH.CENTER
            p.paragraph_format.keep_with_next = True
            p.add_run().add_picture(io.BytesIO(b.png), width=Mm(b.width_mm))
            cap = doc.add_paragraph(f"{w['figure']} {figure_no} – {b.caption}",
                                    style="GP Caption")
            cap.alignment = WD_ALIGN_PARAGRAPH.CENTER
    # Word updates the fields (contents, page count) when the document is opened
    from docx.oxml import OxmlElement
    from docx.oxml.ns import qn

    upd = OxmlElement("w:updateFields")
    upd.set(qn("w:val"), "true")
    doc.settings.element.append(upd)
    buf = io.BytesIO()
    doc.save(buf)
    return _deterministic(buf.getvalue())
