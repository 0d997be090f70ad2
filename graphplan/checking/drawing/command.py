"""``graphplan check --drawing SHEET --variant VARIANT``: the command line of a drawing.

    graphplan check --drawing sheet1.dxf --variant press.toml [--json] [--html F] [-o DIR]
    graphplan check --drawing class/ --variant press.toml -o out/

A folder: every ``*.dxf``, ``*.svg`` and ``*.pdf`` in it is checked (one line each; with
``-o`` each drawing's ``report.html``/``report.json``/``overlay*.svg`` go to
``OUT/<name>/`` and ``OUT/summary.html``, ``summary.csv`` and ``summary.json`` list them
in the calculation checker's class columns); a drawing that cannot be read or has
no plan is a line with its error, the others are still checked.
"""

from __future__ import annotations

import json
import sys
from collections import Counter
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
    """A class folder: one line each, and with ``-o`` each drawing's report and the class
    summary (``summary.html``, ``summary.csv``, ``summary.json``) in the calculation
    checker's columns (:data:`graphplan.checking.batch.COLUMNS`)."""
    from ...errors import GraphplanError
    from ...files import write_atomic
    from ..batch import Batch, Row, report_names
    from .check import check_drawing

    rows: list[Row] = []
    width = max(len(f.name) for f in files)
    stems = Counter(f.stem.lower() for f in files)
    names = report_names([Path(f.stem if stems[f.stem.lower()] == 1 else f.name)
                          for f in files])
    for f, name in zip(files, names, strict=True):
        try:
            dc = check_drawing(f, variant, tol, lang)
        except (GraphplanError, ValueError, OSError) as exc:
            msg = " ".join(str(exc).split())
            print(tr(f"{f.name.ljust(width)}  error   {msg}"))
            rows.append(Row(f.name, variant=str(variant), status="error", error=msg))
            continue
        rep = dc.report
        c = rep.counts()
        st = "ok" if rep.ok else "faults"
        prim = [x for x in rep.wrong if x.primary]
        kinds = ", ".join(sorted({x.kind for x in prim}))
        print(tr(f"{f.name.ljust(width)}  {st:<6}  {len(rep.figures)} figures, {c['wrong']} "
                 f"wrong, {c['primary']} faults{': ' + kinds if kinds else ''}"))
        link = ""
        if args.output:
            sheets, page = _outputs(dc, lang)
            out = Path(args.output) / name
            write_atomic(out / "report.html", page, protect=(f, variant))
            write_atomic(out / "report.json", json.dumps(rep.to_json(), ensure_ascii=False,
                                                         indent=1, allow_nan=False) + "\n",
                         protect=(f, variant))
            for i, s in enumerate(sheets, start=1):
                write_atomic(out / ("overlay.svg" if i == 1 else f"overlay-{i}.svg"), s,
                             protect=(f, variant))
            link = f"{name}/report.html"
        by_kind = Counter(x.kind for x in prim)
        rows.append(Row(f.name, rep.student, rep.group, str(variant), st,
                        c["ok"] + c["inaccurate"] + c["wrong"], c["ok"], c["inaccurate"],
                        c["wrong"], 0, c["findings"], len(prim),
                        "; ".join(f"{k}: {n}" for k, n in sorted(by_kind.items())), "",
                        "; ".join(rep.notes), link,
                        tuple((x.position, x.quantity, x.kind) for x in prim)))
    batch = Batch(tuple(rows), class_variant=str(variant))
    if args.output:
        out = Path(args.output)
        protect = (variant, *files)
        write_atomic(out / "summary.csv", batch.csv(), protect=protect)
        write_atomic(out / "summary.html", batch.html(f"graphplan check --drawing: "
                                                      f"{', '.join(args.drawing)}"),
                     protect=protect)
        summary = {"variant": str(variant), "drawings": [r.to_json() for r in rows],
                   "totals": _totals(rows)}
        write_atomic(out / "summary.json", json.dumps(summary, ensure_ascii=False, indent=1,
                                                      allow_nan=False) + "\n",
                     protect=protect)
    n_ok = sum(r.status == "ok" for r in rows)
    n_err = sum(r.status == "error" for r in rows)
    print(tr(f"{len(rows)} drawings: {n_ok} without faults, {len(rows) - n_ok - n_err} "
             f"with faults, {n_err} not checked"))
    return 0 if batch.ok else 1


def _totals(rows) -> dict:
    """The class's counts: drawings by status, and the faults by kind."""
    kinds: Counter = Counter()
    for r in rows:
        for _pos, _q, kind in r.found:
            kinds[kind] += 1
    return {"drawings": len(rows), "ok": sum(r.status == "ok" for r in rows),
            "faults": sum(r.status == "faults" for r in rows),
            "error": sum(r.status == "error" for r in rows),
            "faults_by_kind": dict(sorted(kinds.items()))}


__all__ = ["run_drawings"]
