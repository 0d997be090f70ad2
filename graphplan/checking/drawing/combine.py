"""A student's calculation and drawing checked together (``[work] drawing = "sheet1.dxf"``).

The drawing is checked as with ``--drawing`` (:func:`~.check.check_drawing`); its findings
and figures join the calculation's report, and every length the student *wrote* in the
calculation (a segment of a plan, a force's segment, h21, in mm) is compared with the
same length *drawn* on the sheet: a difference beyond the segment tolerance is a
``consistency`` finding ("pb = 42,2 мм written, 40,1 мм drawn") — the student read the
plan wrong, or drew another plan than the one calculated.
"""

from __future__ import annotations

from dataclasses import replace

from ..engine import Tolerances
from ..findings import Finding, Report
from ..units import fold
from ..words import num


def with_drawings(report: Report, work, tolerances: dict | None, lang: str
                  ) -> tuple[Report, list[str]]:
    """The calculation's report with the drawings' findings, figures and the written
    against drawn comparisons; and the drawings' overlay sheets."""
    from .check import check_drawing
    from .overlay import drawing_overlay

    tol = Tolerances.of(tolerances)
    findings = list(report.findings)
    figures = list(report.figures)
    notes = list(report.notes)
    sheets: list[str] = []
    for path in work.drawings:
        dc = check_drawing(path, work.variant, tolerances, lang, work.student, work.group)
        name = path.name
        findings += [replace(f, where=f"{name}: {f.where}") for f in dc.report.findings]
        figures += [replace(f, where=f"{name}: {f.where}") for f in dc.report.figures]
        notes += [f"{name}: {n}" for n in dc.report.notes]
        sheets += drawing_overlay(dc, lang)
        drawn = {(f.position, fold(f.quantity)): f for f in dc.report.figures
                 if f.unit == "mm" and f.verdict != "not compared"}
        for f in report.figures:
            if f.unit != "mm":
                continue
            d = drawn.get((f.position, fold(f.quantity)))
            if d is None:
                continue
            diff = abs(f.stated - d.stated)
            band = max(tol.segment * abs(d.stated), tol.reading_mm)
            if diff <= band:
                continue
            en = (f"{f.quantity} = {num(f.stated)} mm is written in the calculation, but "
                  f"{num(d.stated)} mm is drawn on {name} ({d.where}).")
            ru = (f"{f.quantity} = {num(f.stated, 'ru')} мм записано в расчёте, а на "
                  f"чертеже {name} — {num(d.stated, 'ru')} мм ({d.where}).")
            findings.append(Finding(
                where=f.where, quantity=f.quantity, stated=f.stated, expected=d.stated,
                unit="mm", kind="consistency", verdict="wrong",
                explanation=ru if lang == "ru" else en, position=f.position, line=f.line,
                notes=(f"{name}: {d.where}",), explanation_en=en, explanation_ru=ru))
    return replace(report, findings=tuple(findings), figures=tuple(figures),
                   notes=tuple(notes)), sheets


__all__ = ["with_drawings"]
