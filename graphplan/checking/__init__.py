"""Checking students' work: every figure of a calculation beside graphplan's construction.

A teacher transcribes a student's calculation into a *student file*
(``docs/check-format.md``); :func:`check_file` reads it, re-evaluates every written line,
compares every figure with graphplan's exact results at the student's own scales and
says, figure by figure, what is ok, inaccurate or wrong — and why (an arithmetic slip, a
wrong scale, a value of another position or variant, a unit mix-up, a wrong sign, a wrong
lever arm). ``graphplan check`` is the command line (:mod:`graphplan.checking.command`).

Modules: :mod:`~.expressions` (a safe reader of written arithmetic), :mod:`~.units`,
:mod:`~.quantities` (the names of figures), :mod:`~.student` (the file format),
:mod:`~.reference` (graphplan's values), :mod:`~.matching` (naming the numbers of a line),
:mod:`~.engine` (occurrences and figures), :mod:`~.checks` and :mod:`~.diagnosis` (the
checks and the why), :mod:`~.findings`, :mod:`~.report_text`, :mod:`~.report_html`,
:mod:`~.overlay`, :mod:`~.batch`, :mod:`~.generate` (correct files and faults).

Imports are lazy: ``import graphplan.checking`` loads nothing heavy.
"""

from __future__ import annotations

_API = {
    "check_file": "checks", "check_work": "checks", "load_student": "student",
    "loads_student": "student", "evaluate": "expressions", "Report": "findings",
    "Finding": "findings", "Tolerances": "engine", "check_folder": "batch",
    "generate": "generate", "inject": "generate", "text_report": "report_text",
    "html_report": "report_html",
}


def __getattr__(name: str):
    if name in _API:
        import importlib

        return getattr(importlib.import_module(f"{__name__}.{_API[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = sorted(_API)
