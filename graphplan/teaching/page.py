"""The self-contained teaching page of a lesson: one HTML file, no network.

Everything is inline: the SVG frames (:mod:`graphplan.teaching.drawing`), the fonts as
``data:`` URLs (:mod:`graphplan.teaching.webfonts`), the style sheet and the script. A
Content-Security-Policy of ``default-src 'none'`` (inline styles and scripts, fonts
from ``data:`` only) lets the browser load nothing else even by mistake.

Each step is a ``<section class="step">`` holding its frame and its caption (the vector
equation, the table of known and unknown parts, what is drawn, the results with their
scale conversion). Without the script every section shows, one after another, which is
also the print view (frames at their true size, 1 mm = 1 mm). The script shows one step
at a time: next/previous buttons, keys ← → (PgUp/PgDn, Space, Home/End), a step
counter; ``T`` switches the try-it-yourself mode, in which every result is hidden until
the student enters a reading in mm and then shows the correct value and the deviation;
``P`` shows all steps (and the print dialog prints them all in any case).
"""

from __future__ import annotations

import html
import json
import re

from .captions import (
    KIND_TITLES,
    UNITS_RU,
    WORDS,
    localise,
    result_text,
    scale_text,
    unit,
)
from .drawing import frame_svg, frame_texts, scheme_svg
from .model import Lesson, LessonStep
from .questions import questions
from .webfonts import font_face_css

CSP = ("default-src 'none'; style-src 'unsafe-inline'; script-src 'unsafe-inline'; "
       "font-src data:; img-src data:; base-uri 'none'; form-action 'none'")

_SUB = re.compile(r"_([0-9A-Za-zА-Яа-яЁё'ʹ]+)")


def math_html(text: str) -> str:
    """Escape ``text`` and write ``x_AB`` as x<sub>AB</sub>."""
    return _SUB.sub(lambda m: f"<sub>{m.group(1)}</sub>", html.escape(text, quote=False))


_UNITS = sorted({*UNITS_RU, *UNITS_RU.values()} - {"°"}, key=len, reverse=True)
_VALUE = re.compile(r"(\d[\d.·^]*) (" + "|".join(re.escape(u) for u in _UNITS) + r")(?![\w/])")


def localise_units(text: str, lang: str) -> str:
    """The units after numbers in ``lang``: ``15.00 mm`` → ``15.00 мм``."""
    return _VALUE.sub(lambda m: f"{m.group(1)} {unit(m.group(2), lang)}", text)


def nowrap_values(text_html: str) -> str:
    """Keep a number and its unit on one line: ``0.4219 м/с`` never breaks."""
    return _VALUE.sub(lambda m: f'<span class="nw">{m.group(1)}\u00a0{m.group(2)}</span>',
                      text_html)


CSS = """
:root { --ink:#111; --muted:#666; --line:#d8d8d8; --accent:#1f5fd1; --bg:#fff;
  --good:#1a7f37; --fair:#b26b00; --off:#c0262d; }
* { box-sizing: border-box; }
html { font-family: 'DejaVu Sans', 'DejaVu Sans Mono', sans-serif; color: var(--ink);
  background: var(--bg); }
body { margin: 0; font-size: 16px; line-height: 1.4; }
header { position: sticky; top: 0; z-index: 2; background: #f7f7f5; border-bottom: 1px solid
  var(--line); padding: .5rem 1rem; display: flex; flex-wrap: wrap; gap: .5rem 1.5rem;
  align-items: center; }
header h1 { font-size: 1.15rem; margin: 0; font-weight: normal; flex: 1 1 20rem; }
.controls { display: flex; gap: .5rem; align-items: center; flex-wrap: wrap; }
.controls button, .ask button { font: inherit; padding: .3rem .8rem; border: 1px solid #999;
  border-radius: 4px; background: #fff; cursor: pointer; }
.controls button:disabled { opacity: .4; cursor: default; }
.controls button[aria-pressed="true"] { background: var(--accent); color: #fff;
  border-color: var(--accent); }
#counter { min-width: 5.5rem; text-align: center; font-variant-numeric: tabular-nums; }
main { padding: .5rem 1rem 1rem; }
section.step { display: grid; grid-template-columns: minmax(0, 3fr) minmax(18rem, 2fr);
  gap: 1rem 2rem; padding: 1rem 0; border-bottom: 1px solid var(--line); }
body.js:not(.all) section.step:not(.current) { display: none; }
body.js:not(.all) section.step { border-bottom: 0; }
.fig { min-width: 0; }
.fig svg { display: block; width: 100%; height: auto; max-height: 74vh; }
figure.mech { margin: .8rem 0 0; }
figure.mech svg { display: block; width: 100%; max-width: 22rem; height: auto; max-height: 60vh; }
figure.mech figcaption { color: var(--muted); font-size: .85rem; }
.cap h2 { font-size: 1.1rem; margin: .2rem 0 .6rem; font-weight: normal; color: var(--accent); }
.where { color: var(--muted); margin: 0; font-size: .9rem; }
.eq { font-size: 1.2rem; margin: .4rem 0 .8rem; }
table.terms { border-collapse: collapse; margin: .4rem 0 .8rem; font-size: .95rem; }
table.terms th, table.terms td { border: 1px solid var(--line); padding: .2rem .6rem;
  text-align: left; }
table.terms th { background: #f3f3f3; font-weight: normal; color: var(--muted); }
td.unknown { color: var(--off); font-weight: bold; }
ul.results, ul.notes { padding-left: 1.2rem; margin: .4rem 0; }
li.result { margin: .35rem 0; }
.scale { color: var(--muted); font-size: .9rem; }
.ask { display: none; }
.ask input { font: inherit; width: 7rem; padding: .15rem .3rem; }
.feedback { display: block; font-size: .95rem; }
.feedback.good { color: var(--good); } .feedback.fair { color: var(--fair); }
.feedback.off { color: var(--off); }
body.try .answer { display: none; }
body.try .ask { display: block; }
body.try li.done .answer { display: block; }
body.try section.done .answer { display: revert; }
body.try li.done .ask button { display: none; }
.hint { color: var(--muted); font-size: .85rem; }
.quiz { margin: .5rem 0; } .quiz .prompt { margin: .2rem 0; }
.quiz button.opt { font: inherit; margin: .15rem .3rem .15rem 0; padding: .2rem .6rem;
  border: 1px solid #999; border-radius: 4px; background: #fff; cursor: pointer; }
.quiz button.good { border-color: var(--good); color: var(--good); }
.quiz button.off { border-color: var(--off); color: var(--off); }
.verdict.good { color: var(--good); } .verdict.off { color: var(--off); }
.nw { white-space: nowrap; }
body:not(.try) .try-only { display: none; }
footer { padding: 0 1rem 1rem; color: var(--muted); font-size: .85rem; }
@media (max-width: 900px) { section.step { grid-template-columns: 1fr; } }
@media print {
  header .controls, footer .hint, .ask button { display: none !important; }
  header { position: static; background: none; }
  section.step { display: grid !important; break-inside: avoid; page-break-inside: avoid;
    grid-template-columns: auto minmax(14rem, 1fr); }
  .fig svg { width: auto; height: auto; max-width: 100%; max-height: none; }
  body { font-size: 11pt; }
}
"""

JS = r"""
(function () {
  'use strict';
  var body = document.body;
  body.classList.add('js');
  var steps = Array.prototype.slice.call(document.querySelectorAll('section.step'));
  var counter = document.getElementById('counter');
  var prev = document.getElementById('prev'), next = document.getElementById('next');
  var tryBtn = document.getElementById('try'), allBtn = document.getElementById('all');
  var W = JSON.parse(document.getElementById('words').textContent);
  var cur = 0;
  function show(i) {
    cur = Math.max(0, Math.min(steps.length - 1, i));
    steps.forEach(function (s, j) { s.classList.toggle('current', j === cur); });
    counter.textContent = (cur + 1) + ' / ' + steps.length;
    prev.disabled = cur === 0;
    next.disabled = cur === steps.length - 1;
    if (body.classList.contains('all')) { steps[cur].scrollIntoView({block: 'start'}); }
  }
  function setTry(on) {
    body.classList.toggle('try', on);
    tryBtn.setAttribute('aria-pressed', on ? 'true' : 'false');
  }
  function setAll(on) {
    body.classList.toggle('all', on);
    allBtn.setAttribute('aria-pressed', on ? 'true' : 'false');
  }
  function fixed(x, d) { var s = x.toFixed(d); return s === '-0.00' ? '0.00' : s; }
  function check(li) {
    var input = li.querySelector('input');
    var fb = li.querySelector('.feedback');
    var v = parseFloat(String(input.value).replace(',', '.'));
    if (!isFinite(v)) { fb.textContent = W.enter; fb.className = 'feedback off'; return; }
    var ok = parseFloat(li.getAttribute('data-mm'));
    var dev = v - ok;
    var pct = ok !== 0 ? ' (' + (dev >= 0 ? '+' : '−') + fixed(Math.abs(dev / ok * 100), 1)
        + ' %)' : '';
    fb.textContent = W.yours + ' ' + fixed(v, 2) + ' ' + W.mm + ' · ' + W.correct + ' '
        + fixed(ok, 2) + ' ' + W.mm + ' · ' + W.deviation + ' ' + (dev >= 0 ? '+' : '−')
        + fixed(Math.abs(dev), 2) + ' ' + W.mm + pct;
    var a = Math.abs(dev);
    fb.className = 'feedback ' + (a <= 0.5 ? 'good' : a <= 2 ? 'fair' : 'off');
    li.classList.add('done');
    li.setAttribute('data-answer', String(v));
    var sec = li.closest('section.step');
    if (!sec.querySelector('li.result:not(.done)')) { sec.classList.add('done'); }
  }
  prev.addEventListener('click', function () { show(cur - 1); });
  next.addEventListener('click', function () { show(cur + 1); });
  tryBtn.addEventListener('click', function () { setTry(!body.classList.contains('try')); });
  allBtn.addEventListener('click', function () { setAll(!body.classList.contains('all')); });
  document.querySelectorAll('.quiz').forEach(function (qz) {
    var right = parseInt(qz.getAttribute('data-correct'), 10);
    var verdict = qz.querySelector('.verdict');
    qz.querySelectorAll('button.opt').forEach(function (btn) {
      btn.addEventListener('click', function () {
        var ok = parseInt(btn.getAttribute('data-i'), 10) === right;
        btn.classList.add(ok ? 'good' : 'off');
        verdict.textContent = ok ? W.right : W.wrong;
        verdict.className = 'verdict ' + (ok ? 'good' : 'off');
        qz.setAttribute('data-answered', ok ? 'right' : 'wrong');
      });
    });
  });
  document.querySelectorAll('li.result').forEach(function (li) {
    li.querySelector('button.check').addEventListener('click', function () { check(li); });
  });
  document.addEventListener('keydown', function (e) {
    if (e.altKey || e.ctrlKey || e.metaKey) { return; }
    var t = e.target;
    if (t && t.tagName === 'INPUT') {
      if (e.key === 'Enter') { e.preventDefault(); check(t.closest('li.result')); }
      else if (e.key === 'Escape') { t.blur(); }
      else if (e.key === 'PageDown') { e.preventDefault(); t.blur(); show(cur + 1); }
      else if (e.key === 'PageUp') { e.preventDefault(); t.blur(); show(cur - 1); }
      return;
    }
    var k = e.key;
    if (k === 'ArrowRight' || k === 'ArrowDown' || k === 'PageDown' || k === ' ') {
      e.preventDefault(); show(cur + 1);
    } else if (k === 'ArrowLeft' || k === 'ArrowUp' || k === 'PageUp') {
      e.preventDefault(); show(cur - 1);
    } else if (k === 'Home') { e.preventDefault(); show(0); }
    else if (k === 'End') { e.preventDefault(); show(steps.length - 1); }
    else if (k.length === 1 && 'tTеЕ'.indexOf(k) >= 0) { setTry(!body.classList.contains('try')); }
    else if (k.length === 1 && 'pPзЗ'.indexOf(k) >= 0) { setAll(!body.classList.contains('all')); }
  });
  var m = /^#step-(\d+)$/.exec(location.hash);
  show(m ? parseInt(m[1], 10) - 1 : 0);
}());
"""


def _terms_html(step: LessonStep, lang: str) -> str:
    if not step.terms:
        return ""
    w = WORDS[lang]
    rows = [f"<tr><th>{w['vector']}</th><th>{w['direction']}</th><th>{w['magnitude']}</th></tr>"]
    for t in step.terms:
        cells = []
        for v in (t.direction, t.magnitude):
            if v is None:
                cells.append('<td class="unknown">?</td>')
            else:
                cells.append(f"<td>{math_html(v)}</td>")
        rows.append(f"<tr><td>{math_html(t.name)}</td>{''.join(cells)}</tr>")
    rows = [localise_units(localise(r, lang), lang) for r in rows]
    return f'<table class="terms">{"".join(rows)}</table>'


def _results_html(step: LessonStep, lang: str) -> str:
    if not step.results:
        return ""
    w = WORDS[lang]
    u = "мм" if lang == "ru" else "mm"
    items = []
    for r in step.results:
        attrs = (f'data-mm="{r.mm!r}" data-value="{r.value!r}" data-per-mm="{r.per_mm!r}" '
                 f'data-segment="{html.escape(r.segment)}" '
                 f'data-quantity="{html.escape(r.quantity)}" data-laid="{int(r.laid)}"')
        what = math_html(f"{r.segment} = {r.quantity}/{r.factor}" if r.laid else r.segment)
        items.append(
            f'<li class="result" {attrs}><span class="ask"><label>{what} = <input type="text" '
            f'inputmode="decimal" autocomplete="off" aria-label="{html.escape(r.segment)}, {u}">'
            f' {u}</label> <button type="button" class="check">{w["check"]}</button></span>'
            f'<span class="feedback" aria-live="polite"></span><span class="answer">'
            f'{nowrap_values(math_html(result_text(r, lang)))}</span></li>')
    return f'<ul class="results">{"".join(items)}</ul>'


def _questions_html(step: LessonStep, lang: str) -> str:
    """The step's direction and sense questions (try-it mode only)."""
    items = []
    for n, q in enumerate(questions(step, lang), start=1):
        opts = "".join(f'<button type="button" class="opt" data-i="{i}">{math_html(o)}</button>'
                       for i, o in enumerate(q.options))
        items.append(f'<div class="quiz try-only" data-correct="{q.correct}" data-q="{n}">'
                     f'<p class="prompt">{math_html(q.prompt)}</p>{opts}'
                     f'<span class="verdict" aria-live="polite"></span></div>')
    return "".join(items)


def _step_html(lesson: Lesson, step: LessonStep, lang: str, svg: str) -> str:
    w = WORDS[lang]
    n = len(lesson.steps)
    panel = lesson.panels[step.panel]
    parts = [f'<p class="where"><span class="stepno">{w["step"]} {step.number} {w["of"]} {n}'
             f'</span> · <span class="panel">{html.escape(panel.title[lang])}</span></p>',
             f'<h2 class="kind">{html.escape(KIND_TITLES[lang].get(step.kind, step.kind))}</h2>']
    if step.equation:
        parts.append(f'<p class="eq">{math_html(localise(step.equation, lang))}</p>')
    parts.append(_terms_html(step, lang))
    if step.kind != "read":  # a reading's sentence is its results, written below
        hide = " answer" if step.results or step.notes else ""
        what = localise_units(localise(step.text[lang], lang), lang)
        parts.append(f'<p class="what{hide}">{nowrap_values(math_html(what))}</p>')
    if step.results:
        parts.append(f'<p class="scale">{math_html(scale_text(panel.scale, lang))}</p>')
    parts.append(_results_html(step, lang))
    parts.append(_questions_html(step, lang))
    if step.notes:
        notes = "".join(f"<li>{nowrap_values(math_html(nt[lang]))}</li>"
                        for nt in step.notes)
        parts.append(f'<ul class="notes answer">{notes}</ul>')
    scheme = scheme_svg(lesson, step.number)
    if scheme:
        links = ", ".join(step.links)
        many = len(step.links) > 1
        said = ((f"звенья {links} выделены" if many else f"звено {links} выделено")
                if lang == "ru" else f"{'links' if many else 'link'} {links} in colour")
        head = (f"Механизм в положении {lesson.position}" if lang == "ru"
                else f"The mechanism in position {lesson.position}")
        scheme = (f'<figure class="mech">{scheme}<figcaption>{html.escape(head)}'
                  f'{"; " + html.escape(said) if step.links else ""}</figcaption></figure>')
    return (f'<section class="step" id="step-{step.number}" data-step="{step.number}" '
            f'data-panel="{step.panel}" data-kind="{step.kind}" '
            f'data-results="{len(step.results)}">'
            f'<div class="fig">{svg}</div><div class="cap">{"".join(parts)}{scheme}</div>'
            f'</section>')


def _command(lesson: Lesson, lang: str) -> str:
    """The command that writes this page again."""
    pos = "" if lesson.position is None else f" --position '{lesson.position}'"
    return f"graphplan teach {lesson.source}{pos} --plan {lesson.plan} --lang {lang} -o DIR"


def teaching_page(lesson: Lesson, lang: str = "ru") -> str:
    """The HTML text of the lesson's page (module docstring); deterministic."""
    if lang not in ("ru", "en"):
        raise ValueError(f"lang must be 'ru' or 'en' (got {lang!r})")
    w = WORDS[lang]
    frames = [frame_svg(lesson, s.number, lang=lang) for s in lesson.steps]
    sections = "\n".join(_step_html(lesson, s, lang, f) for s, f in zip(lesson.steps, frames,
                                                                         strict=True))
    title = lesson.title[lang]
    scales = "".join(f"<li>{math_html(scale_text(s, lang))}</li>" for s in lesson.scales)
    words = {"yours": w["yours"], "correct": w["correct"], "deviation": w["deviation"],
             "mm": "мм" if lang == "ru" else "mm", "enter": w["enter"],
             "right": "верно" if lang == "ru" else "right",
             "wrong": "неверно, подумайте ещё" if lang == "ru" else "wrong, think again"}
    body = f"""<header><h1>{html.escape(title)}</h1>
<div class="controls" role="toolbar">
<button type="button" id="prev" accesskey="b">← {w['prev']}</button>
<span id="counter" aria-live="polite">{len(lesson.steps)}</span>
<button type="button" id="next" accesskey="n">{w['next']} →</button>
<button type="button" id="try" aria-pressed="false">{w['try']}</button>
<button type="button" id="all" aria-pressed="false">{w['print']}</button>
</div></header>
<main>
<p class="hint try-only">{html.escape(w['try_hint'])}</p>
{sections}
</main>
<footer><p>{w['scales']}:</p><ul>{scales}</ul>
<p class="hint">{html.escape(w['keys'])}. {html.escape(w['units'])}</p>
<p class="hint">graphplan · {html.escape(_command(lesson, lang))}</p>
<noscript><p>{html.escape(w['no_script'])}</p></noscript></footer>"""
    text = body + frame_texts(lesson, lang) + json.dumps(words, ensure_ascii=False)
    css = font_face_css(text) + "\n" + CSS
    return (f"<!DOCTYPE html>\n<html lang=\"{lang}\"><head><meta charset=\"utf-8\">\n"
            f"<meta http-equiv=\"Content-Security-Policy\" content=\"{CSP}\">\n"
            f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            f"<meta name=\"generator\" content=\"graphplan teach\">\n"
            f"<title>{html.escape(title)}</title>\n<style>{css}</style>\n"
            f"<script type=\"application/json\" id=\"words\">"
            f"{json.dumps(words, ensure_ascii=False)}</script>\n</head>\n<body>\n{body}\n"
            f"<script>{JS}</script>\n</body></html>\n")


def notebook_html(lesson: Lesson, lang: str = "ru", height_px: int = 720) -> str:
    """The page in a sandboxed ``<iframe srcdoc>`` for Jupyter (scripts, keys stay inside)."""
    page = teaching_page(lesson, lang)
    return (f'<iframe srcdoc="{html.escape(page, quote=True)}" sandbox="allow-scripts" '
            f'style="width:100%;height:{int(height_px)}px;border:1px solid #ddd" '
            f'title="{html.escape(lesson.title[lang])}"></iframe>')


__all__ = ["CSP", "math_html", "notebook_html", "teaching_page"]
