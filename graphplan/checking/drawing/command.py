"""``graphplan check --drawing SHEET --variant VARIANT``: the command line of a drawing.

    graphplan check --drawing sheet1.dxf --variant press.toml [--json] [--html F] [-o DIR]
    graphplan check --drawing class/ --variant press.toml -o out/

A folder: every ``*.dxf``, ``*.svg`` and ``*.pdf`` in it is checked (one line each; with
``-o`` each drawing's ``report.html``/``report.json``/``overlay*.svg`` go to
``OUT/<name>/`` and ``OUT/summary.csv`` lists them); a drawing that cannot be read or has
no plan is a line with its error, the others are still checked.
"""

from __future__ import annotations

import csv
import io
import json
import sys
from pathlib import Path

from ...i18n import tr
from .read import FORMATS


def run_drawings(args, tol: dict) -> int:
    """Check the drawings of ``--drawing``; 0 when nothing is wrong, 1 when something is."""
    from ..errors import StudentFileError

    if not args.variant:
        raise StudentFileError("graphplan check --drawing: give the variant the drawing is "
                               "of (--variant VARIANT.toml)")
    variant = Path(args.variant)
    if not variant.is_file():
        raise StudentFileError(f"{variant}: variant file not found (--variant)")
    files: list[Path] = []
    folder = False
    for d in args.drawing:
        p = Path(d)
        if p.is_dir():
            folder = True
            files += sorted(q for q in p.iterdir() if q.suffix.lower() in FORMATS)
        else:
            files.append(p)
    if not files:
        raise StudentFileError(f"{', '.join(args.drawing)}: no drawing (.dxf, .svg, .pdf)")
    lang = args.lang or "ru"
    if len(files) == 1 and not folder:
        return _one(files[0], variant, args, tol, lang)
    if args.json or args.html or args.svg:
        raise StudentFileError("graphplan check --drawing: --json, --html and --svg take one "
                               "drawing (use -o DIR for several)")
    return _many(files, variant, args, tol, lang)


def _outputs(dc, lang: str):
    from ..report_html import html_report
    from .overlay import drawing_overlay

    sheets = drawing_overlay(dc, lang)
    return sheets, html_report(dc.report, sheets, lang)


def _one(path: Path, variant: Path, args, tol: dict, lang: str) -> int:
    from ...files import write_atomic
    from ..report_text import text_report
    from .check import check_drawing

    dc = check_drawing(path, variant, tol, lang)
    rep = dc.report
    protect = (path, variant)
    if args.json:
        sys.stdout.write(json.dumps(rep.to_json(), ensure_ascii=False, indent=1,
                                    allow_nan=False) + "\n")
    else:
        sys.stdout.write(text_report(rep))
    if args.html or args.svg or args.output:
        sheets, page = _outputs(dc, lang)
        if args.html:
            write_atomic(args.html, page, protect=protect)
        if args.svg:
            write_atomic(args.svg, sheets[0], protect=protect)
        if args.output:
            out = Path(args.output)
            write_atomic(out / "report.html", page, protect=protect)
            write_atomic(out / "report.json", json.dumps(rep.to_json(), ensure_ascii=False,
                                                         indent=1, allow_nan=False) + "\n",
                         protect=protect)
            for i, s in enumerate(sheets, start=1):
                write_atomic(out / ("overlay.svg" if i == 1 else f"overlay-{i}.svg"), s,
                             protect=protect)
    return 0 if rep.ok else 1


def _many(files: list[Path], variant: Path, args, tol: dict, lang: str) -> int:
    from ...errors import GraphplanError
    from ...files import write_atomic
    from .check import check_drawing

    rows = []
    status = 0
    width = max(len(f.name) for f in files)
    for f in files:
        try:
            dc = check_drawing(f, variant, tol, lang)
        except (GraphplanError, ValueError) as exc:
            msg = " ".join(str(exc).split())
            print(tr(f"{f.name.ljust(width)}  error   {msg}"))
            rows.append((f.name, "error", "", "", "", msg))
            status = 1
            continue
        rep = dc.report
        c = rep.counts()
        st = "ok" if rep.ok else "faults"
        kinds = ", ".join(sorted({x.kind for x in rep.wrong if x.primary}))
        print(tr(f"{f.name.ljust(width)}  {st:<6}  {len(rep.figures)} figures, {c['wrong']} "
                 f"wrong, {c['primary']} faults{': ' + kinds if kinds else ''}"))
        rows.append((f.name, st, len(rep.figures), c["wrong"], c["primary"], kinds))
        status = max(status, 0 if rep.ok else 1)
        if args.output:
            sheets, page = _outputs(dc, lang)
            out = Path(args.output) / f.stem
            write_atomic(out / "report.html", page, protect=(f, variant))
            write_atomic(out / "report.json", json.dumps(rep.to_json(), ensure_ascii=False,
                                                         indent=1, allow_nan=False) + "\n",
                         protect=(f, variant))
            for i, s in enumerate(sheets, start=1):
                write_atomic(out / ("overlay.svg" if i == 1 else f"overlay-{i}.svg"), s,
                             protect=(f, variant))
    if args.output:
        buf = io.StringIO()
        w = csv.writer(buf)
        w.writerow(["file", "status", "figures", "wrong", "faults", "kinds_or_error"])
        w.writerows(rows)
        write_atomic(Path(args.output) / "summary.csv", buf.getvalue(), protect=(variant,))
    n_ok = sum(r[1] == "ok" for r in rows)
    n_err = sum(r[1] == "error" for r in rows)
    print(tr(f"{len(rows)} drawings: {n_ok} without faults, {len(rows) - n_ok - n_err} "
             f"with faults, {n_err} not checked"))
    return status


__all__ = ["run_drawings"]
