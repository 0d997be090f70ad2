"""Command line: ``graphplan analyze [VARIANT.toml] [--json] [--lang ru|en] [-o FILE]``.

A thin layer over the library: every :class:`GraphplanError` becomes one line
on standard error and exit status 2 (a traceback only with ``--debug``).
With no variant file, the bundled press example is used.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from . import __version__
from .errors import GraphplanError


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="graphplan",
        description="The graphical method of TMM: structure, kinematics and plans of a "
        "class-II linkage described in a variant file.",
    )
    p.add_argument("--version", action="version", version=f"graphplan {__version__}")
    p.add_argument("--debug", action="store_true", help="show tracebacks of errors")
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")
    a = sub.add_parser("analyze", help="structure and exact kinematics of every position")
    a.add_argument("variant", nargs="?", help="variant file (default: the bundled press example)")
    a.add_argument("--json", action="store_true", help="print one JSON object for scripts")
    a.add_argument("--lang", choices=("en", "ru"), default="en", help="language of the tables")
    a.add_argument("-o", "--output", help="write the report to this file (atomically)")
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
    if args.json:
        text = json.dumps(result.to_json(), ensure_ascii=False, indent=1, allow_nan=False) + "\n"
    else:
        text = analysis_text(result, args.lang)
    if args.output:
        from .files import write_atomic

        write_atomic(args.output, text, protect=(path,))
    else:
        sys.stdout.write(text)
    return 0


COMMANDS = {"analyze": _analyze}


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit status (0 ok, 2 on a graphplan error)."""
    args = _parser().parse_args(argv)
    try:
        return COMMANDS[args.command](args)
    except GraphplanError as exc:
        if args.debug:
            raise
        print(f"graphplan: error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # pragma: no cover - `graphplan analyze | head`
        return 0
