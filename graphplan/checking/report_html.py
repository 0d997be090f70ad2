"""The HTML report of a check: self-contained (no external files), printable.

Top: who, which variant, the tolerances and the verdict. Then every finding (where,
stated, graphplan's value, the difference, the kind and why), every figure of every
position with its verdict, every written line with its re-evaluation and the names of
its numbers, and the overlay sheets (graphplan's construction with the wrong figures in
red) inline as SVG.
"""

from __future__ import annotations

from html import escape

from .findings import FigureCheck, Finding, Report
from .words import KIND_WORDS, VERDICT_WORDS, num, pct, qty

WORDS = {
    "en": {"title": "Check of a student's calculation", "student": "Student",
           "variant": "Variant", "file": "File", "tolerances": "Tolerances",
           "summary": "Summary", "findings": "Findings", "figures": "Every figure",
           "lines": "The written lines", "overlay": "graphplan's construction and the "
           "student's figures (red)", "where": "Where", "quantity": "Quantity",
           "stated": "Stated", "expected": "graphplan", "delta": "Δ", "kind": "Kind",
           "verdict": "Verdict", "why": "Why", "position": "Position",
           "general": "whole mechanism", "line": "Line", "re": "Re-evaluated",
           "arith": "Arithmetic", "names": "Numbers named", "ok_all": "Nothing is wrong.",
           "faults": "{p} faults of their own, {n} findings in all (the others follow from "
           "them).", "follows": "follows from", "scale": "scale", "uses": "uses",
           "seg": "segments on paper: ok within {sok} % (or {rd2} mm), tolerance {seg} % "
           "(or {rd} mm); derived values: ok within {dok} %, tolerance {der} %; written "
           "arithmetic: {ar} % or the last written digit",
           "a_ok": "ok", "a_wrong": "wrong", "a_sign": "sign", "a_unread": "unread"},
    "ru": {"title": "Проверка расчёта студента", "student": "Студент", "variant": "Вариант",
           "file": "Файл", "tolerances": "Допуски", "summary": "Итог",
           "findings": "Замечания", "figures": "Все величины", "lines": "Записанные строки",
           "overlay": "Точное построение graphplan и цифры студента (красным)",
           "where": "Где", "quantity": "Величина", "stated": "Записано",
           "expected": "Расчёт", "delta": "Δ", "kind": "Вид", "verdict": "Оценка",
           "why": "Почему", "position": "Положение", "general": "механизм в целом",
           "line": "Строка", "re": "Пересчёт", "arith": "Арифметика",
           "names": "Числа и их обозначения", "ok_all": "Ошибок нет.",
           "faults": "Самостоятельных ошибок: {p}, всего замечаний: {n} (остальные — их "
           "следствия).", "follows": "следует из", "scale": "масштаб", "uses": "записей",
           "seg": "отрезки на чертеже: верно в пределах {sok} % (или {rd2} мм), допуск "
           "{seg} % (или {rd} мм); производные величины: верно в пределах {dok} %, допуск "
           "{der} %; арифметика: {ar} % или последний записанный знак",
           "a_ok": "верно", "a_wrong": "неверно", "a_sign": "знак", "a_unread": "не прочитано"},
}

CSS = """
body { font-family: 'DejaVu Sans', Arial, sans-serif; margin: 2em; color: #111;
       font-size: 10.5pt; }
h1 { font-size: 16pt; margin-bottom: .2em; } h2 { font-size: 13pt; margin-top: 1.6em;
border-bottom: 1px solid #999; } h3 { font-size: 11pt; margin: 1.2em 0 .3em; }
table { border-collapse: collapse; width: 100%; margin: .4em 0 1em; }
th, td { border: 1px solid #bbb; padding: 2px 5px; vertical-align: top; }
th { background: #eee; text-align: left; } td.n { text-align: right; white-space: nowrap; }
td.code, code { font-family: 'DejaVu Sans Mono', monospace; font-size: 8.5pt;
                word-break: break-all; }
table.findings td:first-child { width: 22%; } table.findings td:last-child { width: 34%; }
.ok { color: #176117; } .inaccurate { color: #8a6d00; } .not-compared { color: #555; } .wrong { color: #b00020;
font-weight: bold; } tr.follows td { color: #555; } tr.follows td.wrong { font-weight: normal; }
.banner { padding: .5em 1em; border: 2px solid; display: inline-block; margin: .5em 0; }
.banner.ok { border-color: #176117; } .banner.wrong { border-color: #b00020; }
.notes { color: #444; font-size: 9pt; margin: .2em 0 0 1em; padding: 0; }
.sheet svg { width: 100%; height: auto; border: 1px solid #ccc; margin: .5em 0; }
@media print { body { margin: 0; font-size: 9pt; } h2 { page-break-after: avoid; }
  tr { page-break-inside: avoid; } .sheet { page-break-before: always; } }
"""


def _e(x) -> str:
    return escape(str(x), quote=True)


def _finding_row(f: Finding, lang: str) -> str:
    w = WORDS[lang]
    cls = "follows" if not f.primary else ""
    why = _e(f.explanation)
    if f.notes:
        why += "<ul class='notes'>" + "".join(f"<li>{_e(n)}</li>" for n in f.notes) + "</ul>"
    line = f"<br><code>{_e(f.line)}</code>" if f.line else ""
    kind = KIND_WORDS[lang].get(f.kind, f.kind)
    if not f.primary:
        kind += f" ({w['follows']} {_e(', '.join(f.follows_from))})"
    stated = qty(f.stated, f.unit, lang) if f.stated is not None else "—"
    expected = qty(f.expected, f.unit, lang) if f.expected is not None else "—"
    return (f"<tr class='{cls}'><td>{_e(f.where)}{line}</td><td>{_e(f.quantity)}</td>"
            f"<td class='n'>{_e(stated)}</td><td class='n'>{_e(expected)}"
            f"</td><td class='n'>{_e(pct(f.relative, lang)) if f.unit else '—'}</td>"
            f"<td>{_e(kind)}</td><td class='{f.verdict}'>"
            f"{_e(VERDICT_WORDS[lang][f.verdict])}</td><td>{why}</td></tr>")


def _figure_row(f: FigureCheck, lang: str) -> str:
    exp = qty(f.expected, f.unit, lang) if f.expected is not None else "—"
    sc = f" ({f.scale_used})" if f.scale_used else ""
    return (f"<tr><td>{_e(f.quantity)}</td><td class='n'>{_e(qty(f.stated, f.unit, lang))}"
            f"</td><td class='n'>{_e(exp)}{_e(sc)}</td><td class='n'>"
            f"{_e(pct(f.relative, lang)) if f.expected is not None else '—'}</td>"
            f"<td class='{f.verdict.replace(' ', '-')}'>{_e(VERDICT_WORDS[lang][f.verdict])}"
            f"</td><td>{_e(KIND_WORDS[lang].get(f.kind, f.kind)) if f.kind else ''}"
            f"{'<br>' + _e(f.explanation) if f.verdict == 'not compared' else ''}</td>"
            f"<td class='code'>{_e(f.where)}</td></tr>")


def html_report(report: Report, overlays: list[str] | None = None,
                lang: str | None = None) -> str:
    """The report as one HTML document (see the module docstring)."""
    lang = lang or report.lang
    w = WORDS[lang]
    c = report.counts()
    t = report.tolerances
    title = f"{w['title']}: {report.student or report.source}"
    out = [f"<!DOCTYPE html><html lang='{lang}'><head><meta charset='utf-8'>",
           f"<title>{_e(title)}</title><style>{CSS}</style></head><body>",
           f"<h1>{_e(title)}</h1>"]
    meta = [(w["file"], report.source), (w["variant"], report.variant)]
    if report.title:
        meta.insert(0, ("", report.title))
    if report.group:
        meta.append((w["student"], f"{report.student}, {report.group}"))
    out.append("<p>" + "<br>".join(f"{_e(k) + ': ' if k else ''}{_e(v)}" for k, v in meta)
               + "</p>")
    out.append(f"<p><b>{_e(w['tolerances'])}</b>: " + _e(w["seg"].format(
        sok=f"{t['segment_ok'] * 100:g}", rd2=f"{t['reading_mm'] / 2:g}",
        seg=f"{t['segment'] * 100:g}", rd=f"{t['reading_mm']:g}",
        dok=f"{t['derived_ok'] * 100:g}", der=f"{t['derived'] * 100:g}",
        ar=f"{t['arithmetic'] * 100:g}")) + "</p>")
    ok = report.ok
    banner = w["ok_all"] if ok else w["faults"].format(p=c["primary"], n=c["findings"])
    out.append(f"<h2>{_e(w['summary'])}</h2><div class='banner {'ok' if ok else 'wrong'}'>"
               f"{_e(banner)}</div>")
    out.append("<p>" + " · ".join(f"<span class='{v}'>{_e(VERDICT_WORDS[lang][v])}: {c[v]}"
                                  "</span>" for v in ("ok", "inaccurate", "wrong")) +
               f" · {_e(VERDICT_WORDS[lang]['not compared'])}: {c['not_compared']}</p>")
    if report.findings:
        out.append(f"<h2>{_e(w['findings'])}</h2><table class='findings'><tr>" + "".join(
            f"<th>{_e(w[k])}</th>" for k in ("where", "quantity", "stated", "expected",
                                             "delta", "kind", "verdict", "why")) + "</tr>")
        out += [_finding_row(f, lang) for f in report.findings]
        out.append("</table>")
    out.append(f"<h2>{_e(w['figures'])}</h2>")
    groups: dict[str | None, list[FigureCheck]] = {}
    for f in report.figures:
        groups.setdefault(f.position, []).append(f)
    phis = dict(report.positions)
    for pos, figs in groups.items():
        head = w["general"] if pos is None else f"{w['position']} {pos}"
        phi = phis.get(pos) if pos is not None else None
        if phi is not None:
            head += f", φ = {num(phi, lang, 4)}°"
        out.append(f"<h3>{_e(head)}</h3><table><tr>" + "".join(
            f"<th>{_e(w[k])}</th>" for k in ("quantity", "stated", "expected", "delta",
                                             "verdict", "kind", "where")) + "</tr>")
        out += [_figure_row(f, lang) for f in figs]
        out.append("</table>")
    out.append(f"<h2>{_e(w['lines'])}</h2><table><tr>" + "".join(
        f"<th>{_e(w[k])}</th>" for k in ("where", "line", "re", "arith", "names")) + "</tr>")
    for ln in report.lines:
        names = ", ".join(f"{n} = {v}" for n, v in ln.names)
        ar = w.get(f"a_{ln.arithmetic}", "") if ln.arithmetic else ""
        cls = {"ok": "ok", "wrong": "wrong", "sign": "wrong"}.get(ln.arithmetic, "")
        note = f"<br><span class='notes'>{_e(ln.note)}</span>" if ln.note else ""
        if ln.compared:
            note += (f"<br><span class='notes'>{_e(VERDICT_WORDS[lang]['not compared'])}: "
                     f"{_e(ln.compared)}</span>")
        re_ = num(ln.evaluated, lang, 6) if ln.evaluated is not None else ""
        out.append(f"<tr><td>{_e(ln.where)}</td><td class='code'>{_e(ln.text)}{note}</td>"
                   f"<td class='n'>{_e(re_)}"
                   f"</td><td class='{cls}'>{_e(ar)}</td><td class='code'>{_e(names)}</td></tr>")
    out.append("</table>")
    if overlays:
        out.append(f"<h2>{_e(w['overlay'])}</h2>")
        for svg in overlays:
            body = svg[svg.find("<svg"):]
            out.append(f"<div class='sheet'>{body}</div>")
    if report.notes:
        out.append("<ul class='notes'>" + "".join(f"<li>{_e(n)}</li>" for n in report.notes)
                   + "</ul>")
    out.append("</body></html>\n")
    return "\n".join(out)


__all__ = ["html_report"]
