"""Every message graphplan can print, read off the package's source (an AST walk).

Used by ``tests/test_messages_ru.py`` (each message has a Russian twin in
``graphplan/data/messages/ru/``) and run as a script to print the templates still missing::

    python tests/message_scan.py            # missing templates, as catalogue stubs by file

A message is a string expression (a literal, an f-string, a ``+`` of them, a conditional)
given to

* an exception's constructor (a call of a name ending in ``Error``, but not Python's own
  ``ValueError`` … raised for a bug and printed as an internal error), or a function that
  builds one (``fail``, ``_fail``, ``raise_bad``) — every string argument;
* ``print`` — its first argument;
* an option's ``help=`` or a parser's ``description=``, and a module's ``HELP = …``;
* a value given to a name that holds a message or a part of one (``hint``, ``what``,
  ``msg``, ``message``, ``reason``, ``extra``);
* a ``yield``, a ``return`` or an ``.append`` inside a function whose name says it makes
  warnings or hints (``*warning*``, ``*hint*``), or names a position (``where``);
* a ``lambda`` that makes one of these on demand.

Its template is the English text with each replacement field written ``{}``; a template
needs a Russian twin when its literal text has a lowercase English word and a space (a key path
such as ``loads[{}].working`` does not).
"""

from __future__ import annotations

import ast
import re
import sys
from collections.abc import Iterator
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent / "graphplan"
BUILDERS = {"fail", "_fail", "raise_bad", "failed"}
#: Python's own exceptions: raised for a bug of graphplan, printed as an internal error.
BUILTIN = {"ValueError", "TypeError", "AttributeError", "RuntimeError", "AssertionError",
           "KeyError", "IndexError", "NotImplementedError", "LookupError"}
#: Names a message or a part of one is kept in before it is raised or printed.
PARTS = {"HELP", "hint", "what", "msg", "message", "reason", "extra"}
MAKERS = re.compile(r"warning|hint|^where$", re.I)
WORD = re.compile(r"[a-z]{2,}")


def _esc(s: str) -> str:
    return s.replace("{", "{{").replace("}", "}}")


def templates(node: ast.AST) -> list[str]:
    """The templates of a string expression (none when it is not one)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return [_esc(node.value)]
    if isinstance(node, ast.JoinedStr):
        out = []
        for v in node.values:
            if isinstance(v, ast.Constant):
                out.append(_esc(str(v.value)))
            else:
                out.append("{}")
        return ["".join(out)]
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left, right = templates(node.left), templates(node.right)
        if not left and not right:
            return []
        return [a + b for a in (left or ["{}"]) for b in (right or ["{}"])]
    if isinstance(node, ast.Lambda):  # a message made on demand: _fail(bad, lambda k: f"…")
        return templates(node.body)
    if isinstance(node, ast.IfExp):
        return templates(node.body) + templates(node.orelse)
    if isinstance(node, ast.Call) and node.args and _name(node.func) in (
            "terminal_text", "one_line", "str", "tr"):
        return templates(node.args[0])
    return []


def _name(func: ast.AST) -> str:
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute):
        return func.attr
    return ""


def needs_russian(template: str) -> bool:
    """A template with an English word and a space in its literal text."""
    literal = re.sub(r"\{\}", "", template)
    return bool(WORD.search(literal)) and " " in literal.strip()


def _message_nodes(tree: ast.AST) -> Iterator[ast.AST]:
    makers: list[ast.AST] = [f for f in ast.walk(tree)
                             if isinstance(f, ast.FunctionDef | ast.AsyncFunctionDef)
                             and MAKERS.search(f.name)]
    for node in ast.walk(tree):
        if (isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call) and node.exc.args
                and _name(node.exc.func) not in BUILTIN):
            yield node.exc.args[0]  # raise error(f"…"): an exception class given as a value
        if isinstance(node, ast.Call):
            name = _name(node.func)
            if (name.endswith("Error") and name not in BUILTIN) or name in BUILDERS:
                yield from (node.args if name in BUILDERS else node.args[:1])
            elif name == "print" and node.args:
                yield node.args[0]
            for kw in node.keywords:
                if kw.arg in ("help", "description"):
                    yield kw.value
        elif isinstance(node, ast.Assign) and any(
                isinstance(t, ast.Name) and t.id in PARTS for t in node.targets):
            yield node.value
    for f in makers:
        for node in ast.walk(f):
            if isinstance(node, ast.Yield | ast.Return) and node.value is not None:
                yield node.value
            elif isinstance(node, ast.Call) and _name(node.func) == "append" and node.args:
                yield node.args[0]


def package_messages(root: Path = ROOT) -> dict[str, list[str]]:
    """Template → where it is (``path:line``), for every template that needs Russian."""
    out: dict[str, list[str]] = {}
    for path in sorted(root.rglob("*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in _message_nodes(tree):
            for t in templates(node):
                if needs_russian(t):
                    where = f"{path.relative_to(root.parent)}:{getattr(node, 'lineno', 0)}"
                    out.setdefault(t, []).append(where)
    return out


def missing(root: Path = ROOT) -> dict[str, list[str]]:
    """The templates with no Russian twin in the catalogue."""
    from graphplan.i18n import catalogue

    have = {e.en for e in catalogue()}
    return {t: w for t, w in package_messages(root).items() if t not in have}


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT.parent))
    todo = missing()
    by_file: dict[str, list[str]] = {}
    for t, where in todo.items():
        by_file.setdefault(where[0].split(":")[0], []).append(t)
    for f, ts in sorted(by_file.items()):
        print(f"# {f}")
        for t in ts:
            print(f"en: {t}\nru: \n")
    print(f"# {len(todo)} templates without Russian", file=sys.stderr)
