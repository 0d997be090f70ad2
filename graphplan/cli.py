"""Command line.

``graphplan analyze [VARIANT.toml] [--json] [--lang ru|en] [-o FILE]`` — structure and
exact kinematics; ``graphplan sheets [VARIANT.toml ...] -o DIR [--format svg,dxf,pdf,png]``
— the sheets, the tables and the JSON report of each variant (see
:mod:`graphplan.outputs`, :mod:`graphplan.render.formats`); ``graphplan check STUDENT.toml`` —
a student's calculation checked figure by figure (:mod:`graphplan.checking`);
``graphplan teach VARIANT.toml --position N --plan PLAN -o DIR`` — step-by-step teaching
pages (:mod:`graphplan.teaching`).

A thin layer over the library: every error becomes one line on standard error (a
traceback only with ``--debug``) and an exit status of its own (2 bad input, 3 a file
could not be read or written, 4 an internal error, 130 interrupted, 143 terminated); the
exit codes and the console encodings are :mod:`graphplan.console`'s.
With no variant file, the bundled press example is used.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import sys
from pathlib import Path

from . import __version__
from .checking import command as check_command
from .errors import GraphplanError
from .i18n import tr
from .teaching import command as teach_command


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="graphplan",
        description="The graphical method of TMM for a class-II linkage described in a "
        "variant file: structure, plans of positions, velocities and accelerations, force "
        "plans, Zhukovsky's lever, flywheel and motor, drawn on ESKD sheets; students' "
        "calculations checked; step-by-step teaching pages.",
    )
    p.add_argument("--version", action="version", version=f"graphplan {__version__}",
                   help="show graphplan's version and exit")
    p.add_argument("--debug", action="store_true", help="show tracebacks of errors")
    p.add_argument("--lang", choices=("en", "ru"), default=None, dest="ui_lang",
                   help="language of the messages, the help and the reports (default: the "
                   "GRAPHPLAN_LANG environment variable, else the system's language); "
                   "also given after a command")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")
    a = sub.add_parser("analyze", help="structure and exact kinematics of every position")
    a.add_argument("variant", nargs="?", help="variant file (default: the bundled press example)")
    a.add_argument("--json", action="store_true", help="print one JSON object for scripts")
    a.add_argument("--lang", choices=("en", "ru"), default=None,
                   help="language of the tables (default: the language of the messages)")
    a.add_argument("-o", "--output", help="write the report to this file (atomically)")
    a.add_argument("--picture", metavar="FILE",
                   help="also draw the mechanism at its first position with the paths of the "
                   "output link's points, to see a wrong branch or direction before the sheets "
                   "(.svg or .png)")
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
    s.add_argument("--note", action="store_true",
                   help="also write the explanatory note (note.docx; pip install "
                   "'graphplan[note]')")
    n = sub.add_parser("note", help="write the explanatory note (пояснительная записка) as DOCX")
    n.add_argument("variant", nargs="?", help="variant file (default: the bundled press example)")
    n.add_argument("-o", "--output", required=True, metavar="DIR",
                   help="output folder: note.docx (and note.pdf with --pdf)")
    n.add_argument("--lang", choices=("en", "ru"), default="ru", help="language of the note")
    n.add_argument("--pdf", action="store_true",
                   help="also a PDF of the note, through LibreOffice where it is installed")
    w = sub.add_parser("new", help="start a variant file from a family (press, engine, "
                       "compressor, pump, shaper, slotter, crusher, fourbar, …), every key "
                       "explained")
    w.add_argument("family", help="the family: a bundled example's name or its Russian name "
                   "(двигатель, компрессор, насос, строгальный, долбёжный, дробилка, …)")
    w.add_argument("-o", "--output", required=True, metavar="FILE",
                   help="the new variant file (never overwrites a file)")
    w.add_argument("--lang", choices=("ru", "en"), default="ru",
                   help="language of the explanations (default: ru)")
    for name, command in (("check", check_command), ("teach", teach_command)):
        command.add_arguments(sub.add_parser(name, help=command.HELP))
    _translate_help(p)
    return p


def _translate_help(parser: argparse.ArgumentParser) -> None:
    """Every help text and description of ``parser`` and its commands in the messages'
    language (:func:`graphplan.i18n.tr`; argparse's own words through its gettext)."""
    if parser.description:
        parser.description = tr(parser.description)
    for action in parser._actions:
        if action.help and action.help != argparse.SUPPRESS:
            action.help = tr(action.help)
        if isinstance(action, argparse._SubParsersAction):
            for choice in action._choices_actions:
                if choice.help:
                    choice.help = tr(choice.help)
            for sub in dict.fromkeys(action.choices.values()):
                _translate_help(sub)


def _variant_path(arg: str | None) -> Path:
    from .files import bundled_example

    return Path(arg) if arg else bundled_example("press")


def _analyze(args) -> int:
    from .model import load
    from .project import analyze
    from .reports import analysis_text

    path = _variant_path(args.variant)
    result = analyze(load(path))
    for w in result.warnings:
        print(tr(f"graphplan: warning: {w}"), file=sys.stderr)
    if args.picture:
        _picture(result, Path(args.picture), args.lang, path)
    if args.json:  # escaped (\u03c9) only on a console that cannot encode the text
        from .console import json_ascii

        text = json.dumps(result.to_json(), ensure_ascii=json_ascii() and not args.output,
                          indent=1, allow_nan=False) + "\n"
    else:
        from .i18n import language

        text = analysis_text(result, args.lang or language())
    if args.output:
        from .files import write_atomic

        write_atomic(args.output, text, protect=(path,))
    else:
        sys.stdout.write(text)
    return 0


def _picture(result, out: Path, lang: str | None, variant: Path) -> None:
    """``analyze --picture FILE``: the mechanism at a glance (SVG, or PNG by the suffix)."""
    from .errors import InputError
    from .files import write_atomic
    from .i18n import language
    from .teaching.scheme import mechanism_picture

    suffix = out.suffix.lower()
    if suffix not in (".svg", ".png"):
        raise InputError(f"--picture: expected a file name ending in .svg or .png (got {out})")
    svg = mechanism_picture(result, lang or language())
    if suffix == ".png":
        from .render.png import svg_to_png_bytes

        write_atomic(out, svg_to_png_bytes(svg, 150), protect=(variant,))
    else:
        write_atomic(out, svg, protect=(variant,))
    print(tr(f"graphplan: the mechanism's picture: {out}"), file=sys.stderr)


def _sheets(args) -> int:
    from .errors import InputError
    from .outputs import write_project
    from .safe_text import terminal_text

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
            print(tr(f"graphplan: warning: {w}"), file=sys.stderr)
        files = [str(f) for f in done.files]
        if args.note:
            files += [str(f) for f in _write_note(v, target, args.lang or "ru", pdf=False)]
        print(terminal_text(f"{v}: " + ", ".join(files)))
    return 0


def _write_note(variant: Path, out: Path, lang: str, *, pdf: bool) -> list[Path]:
    from .files import write_atomic
    from .note import build_note, note_docx, note_pdf

    note = build_note(variant, lang=lang, out_dir=out)
    docx = note_docx(note)
    written = [write_atomic(out / "note.docx", docx, protect=(variant,))]
    if pdf:
        written.append(write_atomic(out / "note.pdf", note_pdf(docx), protect=(variant,)))
    return written


def _note(args) -> int:
    from .note.pdf import require_office

    if args.pdf:
        require_office()  # before any work: nothing is written without it
    variant = _variant_path(args.variant)
    files = _write_note(variant, Path(args.output), args.lang, pdf=args.pdf)
    from .safe_text import terminal_text

    print(terminal_text(f"{variant}: " + ", ".join(str(f) for f in files)))
    return 0


def _new(args) -> int:
    from .errors import InputError
    from .files import write_atomic
    from .model.template import variant_template
    from .safe_text import terminal_text

    out = Path(args.output)
    if out.exists() or out.is_symlink():
        raise InputError(f"{out}: the file exists; a new variant never overwrites a file "
                         "(choose another name)")
    text = variant_template(args.family, lang=args.lang, name=out.name)
    write_atomic(out, text)
    print(terminal_text(tr(f"{out}: a new variant; check it: graphplan analyze {out}",
                           args.lang)))
    return 0


COMMANDS = {"new": _new, "analyze": _analyze, "sheets": _sheets, "note": _note,
            "check": check_command.run, "teach": teach_command.run}


class Terminated(KeyboardInterrupt):
    """SIGTERM, handled like Ctrl-C: the work done so far is kept (a class run writes
    its summary), then the command exits with 143."""


def _on_sigterm(signum, frame):  # pragma: no cover - exercised in a subprocess test
    raise Terminated()


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit status (:data:`graphplan.console.EXIT_CODES`).

    0 done, 1 faults found by ``check``, 2 bad input, 3 a file could not be read or
    written (read-only, full disk, a link or a file in the way), 4 an internal error (a
    bug), 130 interrupted (Ctrl-C), 143 terminated (SIGTERM; a class run writes its
    summary first).
    """
    import signal

    from . import console, i18n
    from .files import os_error_text
    from .safe_text import terminal_text

    console.prepare_streams()  # never a UnicodeEncodeError on a cp1251/cp866/ASCII console
    i18n.set_language(i18n.language_from_argv(sys.argv[1:] if argv is None else argv))
    saved = argparse._, argparse.ngettext  # type: ignore[attr-defined]
    argparse._ = i18n.argparse_gettext  # type: ignore[attr-defined]
    argparse.ngettext = i18n.argparse_ngettext  # type: ignore[attr-defined]
    try:
        args = _parser().parse_args(argv)
    finally:
        argparse._, argparse.ngettext = saved  # type: ignore[attr-defined]
    previous = None
    with contextlib.suppress(ValueError, AttributeError):  # not the main thread / Windows
        previous = signal.signal(signal.SIGTERM, _on_sigterm)
    if args.ui_lang and getattr(args, "lang", "") is None:
        args.lang = args.ui_lang  # `graphplan --lang ru check …`: the reports too
    try:
        return COMMANDS[args.command](args)
    except BrokenPipeError:  # pragma: no cover - `graphplan analyze | head`
        return console.EXIT_OK
    except OSError as exc:  # also graphplan's OutputError (a GraphplanError)
        if args.debug:
            raise
        msg = str(exc) if isinstance(exc, GraphplanError) else os_error_text(exc)
        print(tr(f"graphplan: error: {terminal_text(msg)}"), file=sys.stderr)
        return console.EXIT_FILE_ERROR
    except GraphplanError as exc:
        if args.debug:
            raise
        print(tr(f"graphplan: error: {terminal_text(str(exc))}"), file=sys.stderr)
        return console.EXIT_BAD_INPUT
    except Terminated:
        print(tr("graphplan: terminated"), file=sys.stderr)
        return console.EXIT_TERMINATED
    except KeyboardInterrupt:
        print(tr("graphplan: interrupted"), file=sys.stderr)
        return console.EXIT_INTERRUPTED
    except (RecursionError, MemoryError) as exc:
        if args.debug:
            raise
        print(tr(f"graphplan: error: the input is too large or too deeply nested "
                 f"({type(exc).__name__})"), file=sys.stderr)
        return console.EXIT_BAD_INPUT
    except Exception as exc:
        if args.debug:
            raise
        reason = terminal_text(" ".join(f"{type(exc).__name__}: {exc}".split()))[:300]
        print(tr(f"graphplan: internal error (a bug, please report it; --debug shows "
                 f"where): {reason}"), file=sys.stderr)
        return console.EXIT_INTERNAL
    finally:
        i18n.set_language(None)
        if previous is not None:
            with contextlib.suppress(ValueError):
                signal.signal(signal.SIGTERM, previous)
