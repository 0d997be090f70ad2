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

from ..i18n import tr

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
                        help="the teacher's variant: student files are checked against it "
                        "(a class summary flags a student whose own variant differs), and "
                        "so are drawings (--drawing)")
    parser.add_argument("--class", dest="class_file", metavar="FILE",
                        help="a class file: [class] variant = ... and [tolerances] (the "
                        "command's options win)")
    parser.add_argument("--timeout", type=float, default=None, metavar="S",
                        help="wall-time limit of one student file in a folder (default 120)")
    parser.add_argument("--memory", type=int, default=None, metavar="MB",
                        help="memory limit of one student file's worker (default 1024)")
    parser.add_argument("--resume", action="store_true",
                        help="a folder: keep the rows of the last run (-o DIR/summary.jsonl) "
                        "whose file has not changed, check the rest")
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
    variant = Path(args.variant) if args.variant else None
    if args.class_file:
        from .batch import class_rules

        cvariant, ctol = class_rules(args.class_file)
        variant = variant or cvariant
        tol = {**ctol, **tol}
    if variant is not None and not variant.is_file():
        raise StudentFileError(f"--variant: variant file {str(variant)!r} not found")
    args.teacher_variant = variant
    paths = [Path(p) for p in args.paths]
    if any(p.is_dir() for p in paths):
        if len(paths) != 1:
            raise StudentFileError("graphplan check: give one folder, or student files")
        return _folder(paths[0], args, tol)
    if len(paths) > 1 and (args.json or args.html or args.svg):
        raise StudentFileError("graphplan check: --json, --html and --svg take one student "
                               "file (use -o DIR for several)")
    from .batch import report_names

    status = 0
    for p, name in zip(paths, report_names(paths), strict=True):
        status = max(status, _file(p, args, tol, multiple=len(paths) > 1, name=name))
    return status


def _file(path: Path, args, tol: dict, multiple: bool, name: str = "") -> int:
    import dataclasses

    from ..files import write_atomic
    from ..safe_text import terminal_text
    from .checks import checker_for, overlays
    from .report_html import html_report
    from .report_text import text_report
    from .student import load_student

    work = load_student(path)
    if work.tolerances:
        print(terminal_text(tr(f"graphplan: note: {path}: the file's own [tolerances] are "
                               "ignored (tolerances are the teacher's: --segment-tolerance, "
                               "--class …)")), file=sys.stderr)
        work = dataclasses.replace(work, tolerances={})
    if args.teacher_variant is not None:
        work = dataclasses.replace(work, variant=args.teacher_variant)
    checker = checker_for(work, tol, tuple(Path(n) for n in args.neighbour), args.lang)
    report = checker.run()
    protect = (path, work.variant)
    sheets = overlays(checker, report) if (args.html or args.svg or args.output) else []
    if work.drawings:  # [work] drawing: the sheets too, and what was written against them
        from .drawing.combine import with_drawings

        report, drawn = with_drawings(report, work, tol, args.lang or work.lang)
        sheets = sheets + drawn if (args.html or args.svg or args.output) else sheets
    if args.json:
        from ..console import json_ascii  # \u escapes on a console lacking a character

        sys.stdout.write(json.dumps(report.to_json(), ensure_ascii=json_ascii(), indent=1,
                                    allow_nan=False) + "\n")
    else:
        sys.stdout.write(terminal_text_lines(text_report(report)))
    if args.html:
        write_atomic(args.html, html_report(report, sheets), protect=protect)
    if args.svg:
        write_atomic(args.svg, sheets[0], protect=protect)
        for i, s in enumerate(sheets[1:], start=2):
            p = Path(args.svg)
            write_atomic(p.with_name(f"{p.stem}-{i}{p.suffix}"), s, protect=protect)
    if args.output:
        root = Path(args.output)
        out = root / (name if multiple else "")
        write_atomic(out / "report.html", html_report(report, sheets), protect=protect,
                     root=root)
        write_atomic(out / "report.json", json.dumps(report.to_json(), ensure_ascii=False,
                                                     indent=1, allow_nan=False) + "\n",
                     protect=protect, root=root)
        for i, s in enumerate(sheets, start=1):
            write_atomic(out / ("overlay.svg" if i == 1 else f"overlay-{i}.svg"), s,
                         protect=protect, root=root)
    return 0 if report.ok else 1


def terminal_text_lines(text: str) -> str:
    """A report for the terminal: every line made safe (:func:`terminal_text`)."""
    from ..safe_text import terminal_text

    return "".join(terminal_text(ln) + "\n" for ln in text.splitlines())


def _folder(folder: Path, args, tol: dict) -> int:
    from ..safe_text import terminal_text
    from .batch import Limits, check_folder

    limits = Limits()
    if args.timeout is not None:
        if not 0 < args.timeout <= 86400:
            raise_bad("--timeout", "a number of seconds in (0, 86400]", args.timeout)
        limits = Limits(args.timeout, limits.memory_mb, limits.max_bytes)
    if args.memory is not None:
        if not 64 <= args.memory <= 1 << 20:
            raise_bad("--memory", "a number of megabytes of at least 64", args.memory)
        limits = Limits(limits.seconds, args.memory, limits.max_bytes)
    if args.resume and not args.output:
        raise_bad("--resume", "-o DIR (the folder of the run to resume)", "no -o")

    def line(r) -> str:
        name = terminal_text(Path(r.file).name)
        if r.status == "error":
            text = f"{name}  error   {terminal_text(r.error)}"
        else:
            text = (f"{name}  {r.status:<6}  {r.figures} figures, {r.wrong} wrong, "
                    f"{r.faults} faults{': ' + r.kinds if r.kinds else ''}"
                    + (f", {r.unreadable} unreadable lines" if r.unreadable else ""))
        return text + (f"  [{terminal_text(r.notes)}]" if r.notes else "")

    batch = check_folder(folder, args.output, jobs=args.jobs, tolerances=tol, lang=args.lang,
                         variant=args.teacher_variant, limits=limits, resume=args.resume,
                         progress=lambda r: print(tr(line(r)), flush=True))
    for name in batch.skipped:
        print(tr(f"{terminal_text(Path(name).name)}: not a student file (no [work] table), "
                 "skipped"), file=sys.stderr)
    n_err = sum(r.status == "error" for r in batch.rows)
    n_ok = sum(r.status == "ok" for r in batch.rows)
    print(tr(f"{len(batch.rows)} files: {n_ok} without faults, "
             f"{len(batch.rows) - n_ok - n_err} with faults, {n_err} not checked"
             + (f"; class variant {terminal_text(batch.class_variant)}"
                if batch.class_variant else "")
             + (f"; summary in {terminal_text(str(Path(args.output) / 'summary.html'))}"
                if args.output else "")))
    return 0 if batch.ok else 1


def raise_bad(option: str, expected: str, got) -> None:
    from .errors import StudentFileError

    raise StudentFileError(f"{option}: expected {expected} (got {got})")


__all__ = ["HELP", "add_arguments", "run"]
