"""The terminal summary of a check: what is wrong, position by position, and why."""

from __future__ import annotations

from .findings import Finding, Report
from .words import KIND_WORDS, VERDICT_WORDS, pct, qty

WORDS = {
    "en": {"check": "check", "student": "student", "variant": "variant",
           "figures": "{n} figures: {ok} ok, {inaccurate} inaccurate, {wrong} wrong, "
           "{not_compared} not compared",
           "lines": "{n} written lines re-evaluated: {lines_wrong} with wrong arithmetic, "
           "{lines_unread} unreadable, {lines_not_compared} with nothing compared",
           "uncompared": "not compared",
           "faults": "{n} findings, {p} of them faults of their own (the rest follow from them)",
           "clean": "nothing is wrong", "general": "whole mechanism",
           "position": "position", "follows": "follows from", "stated": "stated",
           "expected": "graphplan", "tol": "tolerances: segments {seg} % (ok {sok} %), derived "
           "{der} % (ok {dok} %), reading {rd} mm"},
    "ru": {"check": "проверка", "student": "студент", "variant": "вариант",
           "figures": "величин: {n}; верно {ok}, неточно {inaccurate}, неверно {wrong}, "
           "не сравнено {not_compared}",
           "lines": "пересчитано строк: {n}; с арифметической ошибкой {lines_wrong}, "
           "не прочитано {lines_unread}, без сравнения {lines_not_compared}",
           "uncompared": "не сравнено",
           "faults": "замечаний: {n}, из них самостоятельных ошибок: {p} (остальные — их "
           "следствия)",
           "clean": "ошибок нет", "general": "механизм в целом",
           "position": "положение", "follows": "следует из", "stated": "записано",
           "expected": "расчёт", "tol": "допуски: отрезки {seg} % (верно {sok} %), "
           "производные {der} % (верно {dok} %), отсчёт {rd} мм"},
}

MARKS = {"wrong": "✗", "inaccurate": "~", "ok": "✓"}


def _line(f: Finding, lang: str) -> list[str]:
    w = WORDS[lang]
    mark = MARKS[f.verdict] if f.primary else "↳"
    kind = KIND_WORDS[lang].get(f.kind, f.kind)
    head = f"  {mark} {f.where}  {f.quantity}"
    if f.stated is not None:
        head += f" = {qty(f.stated, f.unit, lang)}"
    if f.expected is not None:
        head += f"  ({w['expected']}: {qty(f.expected, f.unit, lang)}"
        rel = f.relative
        head += f", {pct(rel, lang)})" if rel is not None and f.unit else ")"
    head += f"  [{VERDICT_WORDS[lang][f.verdict]}, {kind}]"
    out = [head, f"      {f.explanation}"]
    out += [f"      · {n}" for n in f.notes]
    return out


def text_report(report: Report, lang: str | None = None) -> str:
    """A readable summary for the terminal (every finding, grouped by position)."""
    lang = lang or report.lang
    w = WORDS[lang]
    t = report.tolerances
    c = report.counts()
    out = [f"graphplan {w['check']}: {report.source}"]
    if report.student:
        out.append(f"  {w['student']}: {report.student}" + (f", {report.group}"
                                                              if report.group else ""))
    out.append(f"  {w['variant']}: {report.variant}")
    tol = w["tol"].format(seg=f"{t['segment'] * 100:g}", sok=f"{t['segment_ok'] * 100:g}",
                          der=f"{t['derived'] * 100:g}", dok=f"{t['derived_ok'] * 100:g}",
                          rd=f"{t['reading_mm']:g}")
    out.append("  " + (tol.replace(".", ",") if lang == "ru" else tol))
    out.append("  " + w["figures"].format(n=len(report.figures), **c))
    out.append("  " + w["lines"].format(n=c["lines"], **{k: v for k, v in c.items()
                                                          if k != "lines"}))
    uncompared = [ln for ln in report.lines if ln.compared]
    if not report.findings:
        out += ["", f"  {w['clean']}."]
        out += _uncompared(uncompared, lang)
        return "\n".join(out) + "\n"
    out.append("  " + w["faults"].format(n=c["findings"], p=c["primary"]))
    groups: dict[str | None, list[Finding]] = {}
    for f in report.findings:
        groups.setdefault(f.position, []).append(f)
    order = [None, *(lab for lab, _ in report.positions)]
    for pos in sorted(groups, key=lambda p: order.index(p) if p in order else len(order)):
        title = w["general"] if pos is None else f"{w['position']} {pos}"
        phi = dict(report.positions).get(pos) if pos is not None else None
        if phi is not None:
            title += f" (φ = {phi:.1f}°)".replace(".", "," if lang == "ru" else ".")
        out += ["", f"{title}:"]
        for f in groups[pos]:
            out += _line(f, lang)
    out += _uncompared(uncompared, lang)
    return "\n".join(out) + "\n"


def _uncompared(lines, lang: str) -> list[str]:
    """The lines nothing of which was compared, and why (never shown as right)."""
    if not lines:
        return []
    out = ["", f"{WORDS[lang]['uncompared']}:"]
    out += [f"  · {ln.where}  {ln.text}  — {ln.compared}" for ln in lines]
    return out


__all__ = ["text_report"]
