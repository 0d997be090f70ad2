"""The explanatory note (пояснительная записка) of a course project: the calculation as a document.

:func:`build_note` lays out the project's calculation in the textbook's order — structural
analysis, kinematics, force analysis, dynamics, conclusions — as a sequence of
:mod:`blocks <graphplan.note.blocks>`, every formula written as the seed writes it
(formula, numbers, result with its unit) from the same solved figures as the sheets and the
tables; :func:`note_docx` writes them as a DOCX laid out after GOST 2.105 (frames with the
title blocks of GOST 2.104 forms 2 and 2a, numbered sections, formulas, figures and tables).
"""

from .blocks import Figure, Formula, Heading, Note, Paragraph, Table
from .content import build_note
from .docx_writer import note_docx
from .pdf import find_office, note_pdf

__all__ = ["Figure", "Formula", "Heading", "Note", "Paragraph", "Table", "build_note",
           "find_office", "note_docx", "note_pdf"]
