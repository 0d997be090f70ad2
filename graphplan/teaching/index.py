"""The index page of a variant's lessons: ``teach-index.html`` beside the lesson pages.

Every lesson page in the folder (``teach-*.html``, this run's and earlier runs') is listed by
plan in the textbook's order — velocities, accelerations, force plans, Zhukovsky's lever, the
flywheel — and within a plan by position, each with its title, so that a student opens one
file and finds every lesson of the variant. Self-contained like the lessons (no network, the
fonts inline), deterministic.
"""

from __future__ import annotations

import html
import re
from pathlib import Path

from .page import CSP
from .webfonts import font_face_css

INDEX_NAME = "teach-index.html"
MAX_HEAD_BYTES = 64 * 1024  #: how much of a page is read for its title
ORDER = ("velocity", "acceleration", "forces", "zhukovsky", "flywheel")
_TITLE = re.compile(r"<title>(.*?)</title>", re.S)

WORDS = {
    "ru": {"title": "Уроки графического метода", "intro": "Каждый урок строит план шаг за "
           "шагом: откройте урок, листайте шаги клавишами ← →, режим «Проверь себя» — T.",
           "velocity": "Планы скоростей", "acceleration": "Планы ускорений",
           "forces": "Планы сил", "zhukovsky": "Рычаг Жуковского", "flywheel": "Маховик",
           "other": "Другие уроки", "variant": "Вариант"},
    "en": {"title": "Lessons of the graphical method", "intro": "Each lesson builds a plan "
           "step by step: open a lesson, turn the steps with ← →, try-it-yourself with T.",
           "velocity": "Velocity plans", "acceleration": "Acceleration plans",
           "forces": "Force plans", "zhukovsky": "Zhukovsky's lever", "flywheel": "Flywheel",
           "other": "Other lessons", "variant": "Variant"},
}

CSS = """body{font-family:osifont,'DejaVu Sans',sans-serif;max-width:60em;margin:2em auto;
padding:0 1em;line-height:1.5}h1{font-style:italic}h2{margin-top:1.5em}
li{margin:.3em 0}a{text-decoration:none}a:hover{text-decoration:underline}
.hint{color:#555}"""


def _title(path: Path) -> str:
    with path.open("rb") as f:
        head = f.read(MAX_HEAD_BYTES).decode("utf-8", "replace")
    m = _TITLE.search(head)
    return html.unescape(m.group(1)).strip() if m else path.stem


def _plan_of(name: str) -> str:
    stem = name.removeprefix("teach-").removesuffix(".html")
    return next((p for p in ORDER if stem == p or stem.startswith(p + "-")), "other")


def index_page(out_dir: str | Path, *, variant: str, labels: tuple[str, ...] = (),
               lang: str = "ru") -> str:
    """The HTML of the index of the lesson pages in ``out_dir`` (module docstring).

    ``labels`` are the variant's positions in their order (a page of a position sorts by
    it); ``variant`` names the variant on the page.
    """
    from . import page_name

    w = WORDS[lang]
    out = Path(out_dir)
    pages = sorted(p for p in out.glob("teach-*.html")
                   if p.name != INDEX_NAME and p.is_file() and not p.is_symlink())
    rank = {}
    for i, lab in enumerate(labels):
        for plan in ORDER:
            rank[page_name(plan, lab)] = i
    groups: dict[str, list[tuple[int, str, str]]] = {}
    for p in pages:
        groups.setdefault(_plan_of(p.name), []).append(
            (rank.get(p.name, len(labels)), p.name, _title(p)))
    parts = []
    for plan in (*ORDER, "other"):
        if plan not in groups:
            continue
        items = "".join(f'<li><a href="{html.escape(name, quote=True)}">{html.escape(t)}</a>'
                        "</li>" for _, name, t in sorted(groups[plan]))
        parts.append(f"<h2>{html.escape(w[plan])}</h2><ul>{items}</ul>")
    title = f"{w['title']} — {variant}"
    body = (f"<h1>{html.escape(title)}</h1><p class=\"hint\">{html.escape(w['intro'])}</p>"
            + "".join(parts))
    css = font_face_css(body) + "\n" + CSS
    return (f"<!DOCTYPE html>\n<html lang=\"{lang}\"><head><meta charset=\"utf-8\">\n"
            f"<meta http-equiv=\"Content-Security-Policy\" content=\"{CSP}\">\n"
            f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            f"<meta name=\"generator\" content=\"graphplan teach\">\n"
            f"<title>{html.escape(title)}</title>\n<style>{css}</style>\n</head>\n"
            f"<body>\n{body}\n</body></html>\n")
