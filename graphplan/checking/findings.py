"""What the checker reports: figures, findings, the report of one student file.

Verdicts (stated once):

``ok``
    the figure agrees with graphplan's exact value within the *ok band* (drafting
    reading accuracy);
``inaccurate``
    off by more than that but within the method's tolerance (by default 2 % for a
    segment measured on a plan, 5 % for a value derived from measurements);
``wrong``
    off by more than the tolerance, or a calculation that does not give its result;
``not compared``
    written, but there is nothing of graphplan's to compare it with (a scale, the
    student's own choice, is checked only for its arithmetic and its use; a name the
    variant does not know; a figure graphplan does not compute): ``explanation`` says
    why. Never counted as right.

Kinds of findings: ``arithmetic`` (the written numbers do not give the written result),
``consistency`` (one quantity with different values in different places), ``unit``
(a unit mix-up: a ratio of 1000, 10⁶ or g), ``scale`` (a segment measured, or a value
computed, at another scale than the stated one), ``sign``, ``other-variant`` (the value
of another position or of a neighbouring variant), ``lever-arm`` (the arm of another
force or about another point), ``geometry`` (an arm the mechanism cannot have),
``formula`` (the formula itself is wrong), ``label`` (a right number under a wrong name),
``propagated`` (right working from a wrong figure before it), ``model`` (differs from
graphplan with no simpler explanation), ``coriolis`` (the Coriolis acceleration without
its factor 2, or left out of the vector equation), ``unreadable`` (a line that cannot be
read: a finding, never a silence).

Values are in the figure's unit: SI (N, N·m, m/s …) or mm for lengths on paper.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..numbers import finite

VERDICTS = ("ok", "inaccurate", "wrong", "not compared")
KINDS = ("arithmetic", "consistency", "unit", "scale", "sign", "other-variant", "lever-arm",
         "geometry", "formula", "label", "propagated", "model", "coriolis", "unreadable",
         "direction", "missing", "closure", "point")  # the last four: a drawing's
#                                                       (checking/drawing, docs/drawing-check.md)


@dataclass(frozen=True, slots=True)
class Finding:
    """One thing found, with where it is, what was stated and what was expected.

    Attributes
    ----------
    where : str
        ``"position 2, line 41"`` (a line of the student file) or ``"general, line 12"``.
    quantity : str
        The figure's name as the student wrote it (``"R43"``), or a term (``"Pи3·h3"``).
    stated, expected : float | None
        In ``unit``; ``expected`` is graphplan's exact value (or the re-evaluated result
        of the written numbers for an arithmetic slip without a model value).
    unit : str
    kind : str
        One of :data:`KINDS`.
    verdict : str
        One of :data:`VERDICTS`.
    explanation : str
        One or two sentences, in the report's language.
    position : str | None
        The position's label (``None`` for the whole mechanism).
    line : str
        The line as written.
    file_line : int | None
    follows_from : tuple[str, ...]
        Figures this one follows from (``propagated``): not a fault of its own.
    notes : tuple[str, ...]
        Further observations (other places the same value is used, other explanations).
    explanation_en, explanation_ru : str
        The explanation in both languages.
    """

    where: str
    quantity: str
    stated: float | None
    expected: float | None
    unit: str
    kind: str
    verdict: str
    explanation: str
    position: str | None = None
    line: str = ""
    file_line: int | None = None
    follows_from: tuple[str, ...] = ()
    notes: tuple[str, ...] = ()
    explanation_en: str = ""
    explanation_ru: str = ""

    @property
    def primary(self) -> bool:
        """A fault of its own (not only the consequence of another figure)."""
        return not self.follows_from

    @property
    def relative(self) -> float | None:
        """(stated − expected)/|expected|, ``None`` where it is undefined."""
        if self.stated is None or self.expected is None or self.expected == 0:
            return None
        return (self.stated - self.expected) / abs(self.expected)

    def to_json(self) -> dict:
        rel = self.relative
        return {"where": self.where, "quantity": self.quantity, "stated": _num(self.stated),
                "expected": _num(self.expected), "kind": self.kind, "verdict": self.verdict,
                "explanation": self.explanation, "unit": self.unit,
                "position": self.position, "line": self.line, "file_line": self.file_line,
                "relative_error": _num(rel), "primary": self.primary,
                "follows_from": list(self.follows_from), "notes": list(self.notes),
                "explanation_en": self.explanation_en, "explanation_ru": self.explanation_ru}


@dataclass(frozen=True, slots=True)
class FigureCheck:
    """One figure of the student's work beside graphplan's value (every figure, ok or not).

    ``scale_used`` names the scale a length on paper was compared at when it is not the
    stated one (``"Kl = 0.002"``).
    """

    position: str | None
    quantity: str
    unit: str
    stated: float
    expected: float | None
    verdict: str
    where: str
    line: str
    kind: str = ""
    explanation: str = ""
    scale_used: str = ""
    uses: int = 1

    @property
    def relative(self) -> float | None:
        if self.expected is None or self.expected == 0:
            return None
        return (self.stated - self.expected) / abs(self.expected)

    def to_json(self) -> dict:
        return {"position": self.position, "quantity": self.quantity, "unit": self.unit,
                "stated": _num(self.stated), "expected": _num(self.expected),
                "relative_error": _num(self.relative), "verdict": self.verdict,
                "where": self.where, "line": self.line, "kind": self.kind,
                "explanation": self.explanation, "scale_used": self.scale_used,
                "uses": self.uses}


@dataclass(frozen=True, slots=True)
class LineCheck:
    """One written line: its members, the re-evaluated result and what its numbers are.

    ``evaluated`` is the value of its numeric expression, ``stated`` the written result
    (``None`` when the line holds no arithmetic); ``names`` maps the names of its formula
    to the numbers they stand for.
    """

    where: str
    position: str | None
    text: str
    quantity: str | None
    evaluated: float | None
    stated: float | None
    arithmetic: str  # "ok" | "wrong" | "" (nothing to re-evaluate) | "unread"
    names: tuple[tuple[str, str], ...] = ()
    note: str = ""
    compared: str = ""  # "" when a figure of the line was compared, else why not

    def to_json(self) -> dict:
        return {"where": self.where, "position": self.position, "text": self.text,
                "quantity": self.quantity, "evaluated": _num(self.evaluated),
                "stated": _num(self.stated), "arithmetic": self.arithmetic,
                "names": dict(self.names), "note": self.note,
                "compared": not self.compared, "not_compared_why": self.compared}


@dataclass(frozen=True, slots=True)
class Report:
    """The check of one student file."""

    source: str
    variant: str
    student: str
    title: str
    lang: str
    tolerances: dict[str, float]
    findings: tuple[Finding, ...]
    figures: tuple[FigureCheck, ...]
    lines: tuple[LineCheck, ...]
    positions: tuple[tuple[str, float], ...] = ()  # label, φ (degrees)
    group: str = ""
    notes: tuple[str, ...] = field(default_factory=tuple)

    @property
    def wrong(self) -> tuple[Finding, ...]:
        return tuple(f for f in self.findings if f.verdict == "wrong")

    @property
    def ok(self) -> bool:
        """Nothing is wrong (inaccurate figures are allowed)."""
        return not self.wrong

    def _repr_html_(self) -> str:
        """Jupyter: the HTML report, in a frame of its own (its styles stay inside)."""
        import html

        from .report_html import html_report

        return (f'<iframe srcdoc="{html.escape(html_report(self), quote=True)}" sandbox="" '
                'style="width:100%;height:640px;border:1px solid #ddd"></iframe>')

    def counts(self) -> dict[str, int]:
        """Figures by verdict, and the number of findings and of primary ones."""
        out = {v: 0 for v in VERDICTS}
        for f in self.figures:
            out[f.verdict] += 1
        out["not_compared"] = out.pop("not compared")
        out["findings"] = len(self.findings)
        out["primary"] = sum(1 for f in self.wrong if f.primary)
        out["lines"] = len(self.lines)
        out["lines_wrong"] = sum(1 for ln in self.lines if ln.arithmetic in ("wrong", "sign"))
        out["lines_unread"] = sum(1 for ln in self.lines if ln.arithmetic == "unread")
        out["lines_not_compared"] = sum(1 for ln in self.lines if ln.compared)
        return out

    def to_json(self) -> dict:
        return {"source": self.source, "variant": self.variant, "student": self.student,
                "group": self.group, "title": self.title, "lang": self.lang,
                "tolerances": dict(self.tolerances), "summary": self.counts(),
                "positions": [{"label": lab, "phi_deg": _num(phi)} for lab, phi in
                              self.positions],
                "findings": [f.to_json() for f in self.findings],
                "figures": [f.to_json() for f in self.figures],
                "lines": [ln.to_json() for ln in self.lines],
                "notes": list(self.notes)}


def _num(x: float | None) -> float | None:
    if x is None:
        return None
    return finite(x, "a report") + 0.0


__all__ = ["KINDS", "VERDICTS", "FigureCheck", "Finding", "LineCheck", "Report"]
