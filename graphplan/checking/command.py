"""``graphplan check``: check a student's calculation (a file) or a class (a folder).

    graphplan check STUDENT.toml [--json] [--html FILE] [--svg FILE] [-o DIR]
    graphplan check FOLDER/ [-o DIR] [--jobs N]
    graphplan check --answer-key VARIANT.toml [-o FILE]
    graphplan check --drawing SHEET.dxf|.svg|.pdf|FOLDER --variant VARIANT.toml [...]

Exit status: 0 when nothing is wrong, 1 when something is (a wrong figure, or in a
folder a student with faults or a file that could not be checked), 2 on an error of the
command itself (reported by :func:`graphplan.cli.main`).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

HELP = "check a student's calculation (a student file, or a folder of them) against graphplan"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The options of ``graphplan check``."""
    parser.add_argument("paths", nargs="*", metavar="PATH",
                        help="student files (docs/check-format.md) or a folder of them")
    parser.add_argument("--json", action="store_true",
                        help="print the findings as one JSON object (a file only)")
    parser.add_argument("--html", metavar="FILE", help="write the HTML report (a file only)")
    parser.add_argument("--svg", metavar="FILE",
                        help="write the overlay sheet: graphplan's construction with the "
                        "wrong figures in red (a file only)")
    parser.add_argument("-o", "--output", metavar="DIR",
                        help="write report.html, report.json and overlay*.svg (a file), or "
                        "each student's reports and summary.csv/.html (a folder)")
    parser.add_argument("--lang", choices=("en", "ru"), default=None,
                        help="language of the explanations (default: the file's work.lang)")
    parser.add_argument("--jobs", type=int, default=None, metavar="N",
                        help="processes for a folder (default: all cores)")
    parser.add_argument("--neighbour", action="append", default=[], metavar="VARIANT",
                        help="a neighbouring variant a value may have been copied from "
                        "(repeatable)")
    for name, what in (("segment", "segments measured on a plan (fraction, default 0.02)"),
                       ("derived", "values derived from measurements (default 0.05)"),
                       ("arithmetic", "written arithmetic (default 0.005)")):
        parser.add_argument(f"--{name}-tolerance", type=float, default=None, metavar="F",
                            help=f"tolerance of {what}")
    parser.add_argument("--reading", type=float, default=None, metavar="MM",
                        help="drafting reading precision, mm (default 0.5)")
    parser.add_argument("--drawing", action="append", default=[], metavar="SHEET",
                        help="check a drawing (.dxf, .svg, .pdf) or a folder of them "
                        "against the variant's constructions (with --variant; repeatable)")
    parser.add_argument("--variant", metavar="VARIANT",
                        help="the variant file a drawing is checked against (--drawing)")
    parser.add_argument("--answer-key", metavar="VARIANT",
                        help="write the calculation graphplan itself would hand in for a "
                        "variant, as a student file (to -o FILE, or to standard output)")


def _tolerances(args) -> dict[str, float]:
    from .errors import StudentFileError

    out = {}
    for key, opt, val in (("segment", "--segment-tolerance", args.segment_tolerance),
                          ("derived", "--derived-tolerance", args.derived_tolerance),
                          ("arithmetic", "--arithmetic-tolerance", args.arithmetic_tolerance),
                          ("reading_mm", "--reading", args.reading)):
        if val is None:
            continue
        hi = 10.0 if key == "reading_mm" else 1.0
        if not (0 < val <= hi):
            raise StudentFileError(f"{opt}: expected a number in (0, {hi:g}] (got {val:g})")
        out[key] = val
    return out


def run(args) -> int:
    """Run ``graphplan check``; 0 when nothing is wrong, 1 when something is."""
    from ..files import write_atomic
    from .errors import StudentFileError

    if args.answer_key:
        from .generate import generate

        ref = Path(args.answer_key)
        if args.output:  # the variant as seen from the written file (a movable pair)
            base = Path(args.output).resolve().parent
            ref = Path(os.path.relpath(ref.resolve(), base))
        text = generate(args.answer_key, variant_ref=ref.as_posix()).toml()
        if args.output:
            write_atomic(args.output, text, protect=(Path(args.answer_key),))
        else:
            sys.stdout.write(text)
        return 0
    if args.drawing:
        from .drawing.command import run_drawings

        return run_drawings(args, _tolerances(args))
    if not args.paths:
        raise StudentFileError("graphplan check: expected a student file or a folder "
                               "(or --answer-key VARIANT)")
    tol = _tolerances(args)
    paths = [Path(p) for p in args.paths]
    if any(p.is_dir() for p in paths):
        if len(paths) != 1:
            raise StudentFileError("graphplan check: give one folder, or student files")
        return _folder(paths[0], args, tol)
    if len(paths) > 1 and (args.json or args.html or args.svg):
        raise StudentFileError("graphplan check: --json, --html and --svg take one student "
                               "file (use -o DIR for several)")
    status = 0
    for p in paths:
        status = max(status, _file(p, args, tol, multiple=len(paths) > 1))
    return status


def _file(path: Path, args, tol: dict, multiple: bool) -> int:
    from ..files import write_atomic
    from .checks import checker_for, overlays
    from .report_html import html_report
    from .report_text import text_report
    from .student import load_student

    work = load_student(path)
    checker = checker_for(work, tol, tuple(Path(n) for n in args.neighbour), args.lang)
    report = checker.run()
    protect = (path, work.variant)
    sheets = overlays(checker, report) if (args.html or args.svg or args.output) else []
    if args.json:
        from ..console import json_ascii  # \u escapes on a console lacking a character

        sys.stdout.write(json.dumps(report.to_json(), ensure_ascii=json_ascii(), indent=1,
                                    allow_nan=False) + "\n")
    else:
        sys.stdout.write(text_report(report))
    if args.html:
        write_atomic(args.html, html_report(report, sheets), protect=protect)
    if args.svg:
        write_atomic(args.svg, sheets[0], protect=protect)
        for i, s in enumerate(sheets[1:], start=2):
            p = Path(args.svg)
            write_atomic(p.with_name(f"{p.stem}-{i}{p.suffix}"), s, protect=protect)
    if args.output:
        out = Path(args.output) / (path.stem if multiple else "")
        write_atomic(out / "report.html", html_report(report, sheets), protect=protect)
        write_atomic(out / "report.json", json.dumps(report.to_json(), ensure_ascii=False,
                                                     indent=1, allow_nan=False) + "\n",
                     protect=protect)
        for i, s in enumerate(sheets, start=1):
            write_atomic(out / ("overlay.svg" if i == 1 else f"overlay-{i}.svg"), s,
                         protect=protect)
    return 0 if report.ok else 1


def _folder(folder: Path, args, tol: dict) -> int:
    from .batch import check_folder

    from .batch import skipped_files

    for p in skipped_files(folder):
        print(f"{p.name}: not a student file (no [work] table), skipped", file=sys.stderr)
    batch = check_folder(folder, args.output, jobs=args.jobs, tolerances=tol, lang=args.lang)
    width = max(len(Path(r.file).name) for r in batch.rows)
    for r in batch.rows:
        name = Path(r.file).name.ljust(width)
        if r.status == "error":
            print(f"{name}  error   {r.error}")
        else:
            print(f"{name}  {r.status:<6}  {r.figures} figures, {r.wrong} wrong, {r.faults} "
                  f"faults{': ' + r.kinds if r.kinds else ''}")
    n_err = sum(r.status == "error" for r in batch.rows)
    n_ok = sum(r.status == "ok" for r in batch.rows)
    print(f"{len(batch.rows)} files: {n_ok} without faults, {len(batch.rows) - n_ok - n_err} "
          f"with faults, {n_err} not checked"
          + (f"; summary in {Path(args.output) / 'summary.html'}" if args.output else ""))
    return 0 if batch.ok else 1


__all__ = ["HELP", "add_arguments", "run"]
