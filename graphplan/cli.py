"""Command line.

``graphplan analyze [VARIANT.toml] [--json] [--lang ru|en] [-o FILE]`` — structure and
exact kinematics; ``graphplan sheets [VARIANT.toml ...] -o DIR [--format svg,dxf,pdf,png]``
— the sheets, the tables and the JSON report of each variant (see
:mod:`graphplan.project`, :mod:`graphplan.exports`); ``graphplan check STUDENT.toml`` —
a student's calculation checked figure by figure (:mod:`graphplan.checking`);
``graphplan teach VARIANT.toml --position N --plan PLAN -o DIR`` — step-by-step teaching
pages (:mod:`graphplan.teaching`).

A thin layer over the library: every :class:`GraphplanError` becomes one line
on standard error and exit status 2 (a traceback only with ``--debug``); the exit
codes and the console encodings are :mod:`graphplan.console`'s.
With no variant file, the bundled press example is used.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from . import __version__
from .checking import command as check_command
from .errors import GraphplanError
from .teaching import command as teach_command


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="graphplan",
        description="The graphical method of TMM for a class-II linkage described in a "
        "variant file: structure, plans of positions, velocities and accelerations, force "
        "plans, Zhukovsky's lever, flywheel and motor, drawn on ESKD sheets; students' "
        "calculations checked; step-by-step teaching pages.",
    )
    p.add_argument("--version", action="version", version=f"graphplan {__version__}")
    p.add_argument("--debug", action="store_true", help="show tracebacks of errors")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")
    a = sub.add_parser("analyze", help="structure and exact kinematics of every position")
    a.add_argument("variant", nargs="?", help="variant file (default: the bundled press example)")
    a.add_argument("--json", action="store_true", help="print one JSON object for scripts")
    a.add_argument("--lang", choices=("en", "ru"), default="en", help="language of the tables")
    a.add_argument("-o", "--output", help="write the report to this file (atomically)")
    s = sub.add_parser("sheets", help="draw the sheets and write the tables and the JSON report")
    s.add_argument("variants", nargs="*", metavar="VARIANT",
                   help="variant files (default: the bundled press example)")
    s.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="output folder (with several variants: one sub-folder per variant)")
    s.add_argument("--lang", choices=("en", "ru"), default=None,
                   help="lettering of the sheets (default: the variant's drawing.language, ru)")
    s.add_argument("--page", choices=("A1", "A2", "A3"), default=None,
                   help="sheet format (default: the variant's drawing.format, A1)")
    s.add_argument("--precision", type=float, default=None, metavar="MM",
                   help="reading precision of the drafting tables, mm (default: the "
                   "variant's drawing.reading_mm, 0.5)")
    s.add_argument("--format", default="svg", metavar="FORMATS",
                   help="formats of the sheets, separated by commas: svg, dxf (CAD, with "
                   "layers), pdf (true size), png (preview), or all (default: svg); dxf, "
                   "pdf and png need pip install 'graphplan[export]'")
    s.add_argument("--dpi", type=float, default=None, metavar="DPI",
                   help="resolution of the PNG previews (default: 100)")
    for name, command in (("check", check_command), ("teach", teach_command)):
        command.add_arguments(sub.add_parser(name, help=command.HELP))
    return p


def _variant_path(arg: str | None) -> Path:
    from .files import bundled_example

    return Path(arg) if arg else bundled_example("press")


def _analyze(args) -> int:
    from .analysis import analyze
    from .loader import load
    from .render.tables import analysis_text

    path = _variant_path(args.variant)
    result = analyze(load(path))
    for w in result.warnings:
        print(f"graphplan: warning: {w}", file=sys.stderr)
    if args.json:  # escaped (\u03c9) only on a console that cannot encode the text
        from .console import json_ascii

        text = json.dumps(result.to_json(), ensure_ascii=json_ascii() and not args.output,
                          indent=1, allow_nan=False) + "\n"
    else:
        text = analysis_text(result, args.lang)
    if args.output:
        from .files import write_atomic

        write_atomic(args.output, text, protect=(path,))
    else:
        sys.stdout.write(text)
    return 0


def _sheets(args) -> int:
    from .errors import InputError
    from .project import write_project

    if args.precision is not None and not (0 <= args.precision <= 5):
        raise InputError(f"--precision: expected a reading precision of 0 … 5 mm "
                         f"(got {args.precision:g})")
    variants = [Path(v) for v in args.variants] or [_variant_path(None)]
    out = Path(args.output)
    for v in variants:
        target = out / v.stem if len(variants) > 1 else out
        done = write_project(v, target, lang=args.lang, precision=args.precision,
                             page=args.page, formats=args.format, dpi=args.dpi)
        for w in done.warnings:
            print(f"graphplan: warning: {w}", file=sys.stderr)
        print(f"{v}: " + ", ".join(str(f) for f in done.files))
    return 0


COMMANDS = {"analyze": _analyze, "sheets": _sheets, "check": check_command.run,
            "teach": teach_command.run}


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit status (:data:`graphplan.console.EXIT_CODES`).

    0 done, 1 faults found by ``check``, 2 bad input, 3 a file could not be read or
    written, 4 an internal error (a bug), 130 interrupted.
    """
    from . import console

    console.prepare_streams()  # never a UnicodeEncodeError on a cp1251/cp866/ASCII console
    args = _parser().parse_args(argv)
    try:
        return COMMANDS[args.command](args)
    except GraphplanError as exc:
        if args.debug:
            raise
        print(f"graphplan: error: {exc}", file=sys.stderr)
        return console.EXIT_BAD_INPUT
    except BrokenPipeError:  # pragma: no cover - `graphplan analyze | head`
        return console.EXIT_OK
    except OSError as exc:
        if args.debug:
            raise
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"graphplan: error: {where}{exc.strerror or exc}", file=sys.stderr)
        return console.EXIT_FILE_ERROR
    except KeyboardInterrupt:
        print("graphplan: interrupted", file=sys.stderr)
        return console.EXIT_INTERRUPTED
    except Exception as exc:
        if args.debug:
            raise
        reason = " ".join(f"{type(exc).__name__}: {exc}".split())[:300]
        print(f"graphplan: internal error (a bug, please report it; --debug shows where): "
              f"{reason}", file=sys.stderr)
        return console.EXIT_INTERNAL
