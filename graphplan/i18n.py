"""The language of what graphplan says: English or Russian, for every message it prints.

graphplan's messages are written in English where they are raised (an error, a warning, a
progress line, an option's help); the command line translates each finished message just
before printing it, by a **catalogue of templates** (``graphplan/data/messages/ru/*.txt``)::

    en: {}: {}: expected a table (got {})
    ru: {}: {}: ожидалась таблица (получено: {})

An English template is the message's f-string with every replacement field written ``{}``
(in source order); the Russian one takes the same fields as ``{}`` in the same order or as
``{0}``, ``{1}`` … in any order. :func:`tr` matches a message against every template (the
most specific first), translates each field's text in turn (a field may itself be a
message, a type name, a hint) and fills the Russian template. A message that no template
matches whole is split at its first ``": "`` (a file name, a key path) and its tail is
tried again; a message nothing matches is printed as it is (in English).

A new message needs a Russian twin in the catalogue: ``tests/test_messages_ru.py`` reads
every message of the package off its source (AST) and fails on one without; ``python
tests/test_messages_ru.py`` prints the missing templates ready to paste.

The language (:func:`language`): ``--lang ru|en`` anywhere on the command line, else the
environment variable ``GRAPHPLAN_LANG``, else the system locale (``LC_ALL``,
``LC_MESSAGES``, ``LANG``; on Windows the user's interface language) — Russian for a
Russian (Belarusian, Kazakh) locale, English otherwise.
"""

from __future__ import annotations

import functools
import os
import re
import sys
from collections.abc import Mapping, Sequence
from importlib import resources

LANGS = ("en", "ru")
ENV_VAR = "GRAPHPLAN_LANG"
#: Locales whose users read Russian best (a language code's first part).
RUSSIAN_LOCALES = frozenset({"ru", "be", "kk", "ky", "tg"})
#: Windows primary language ids: Russian, Belarusian, Kazakh, Kyrgyz, Tajik.
_WINDOWS_RUSSIAN = {0x19, 0x23, 0x3F, 0x40, 0x28}

_current: str | None = None


def _from_locale_name(name: str | None) -> str | None:
    if not name:
        return None
    code = re.split(r"[_.@\-]", name.strip().lower(), maxsplit=1)[0]
    if code in ("c", "posix", ""):
        return None
    if code in RUSSIAN_LOCALES or code.startswith("russian"):
        return "ru"
    return "en"


def _windows_language() -> str | None:  # pragma: no cover - Windows only
    try:
        import ctypes

        lang_id = ctypes.windll.kernel32.GetUserDefaultUILanguage()  # type: ignore[attr-defined]
    except (AttributeError, OSError):
        return None
    return "ru" if (lang_id & 0x3FF) in _WINDOWS_RUSSIAN else "en"


def system_language(environ: Mapping[str, str] | None = None, platform: str | None = None) -> str:
    """The language of the user's system: ``GRAPHPLAN_LANG``, else the locale; ``en`` when
    nothing says (a ``C``/``POSIX`` locale)."""
    env = os.environ if environ is None else environ
    chosen = env.get(ENV_VAR, "").strip().lower()
    if chosen in LANGS:
        return chosen
    for var in ("LC_ALL", "LC_MESSAGES", "LANG"):
        value = env.get(var)
        if value:  # the first one set decides (POSIX), even "C"
            return _from_locale_name(value) or "en"
    if (platform or sys.platform) == "win32":
        found = _windows_language()
        if found:
            return found
        import locale

        return _from_locale_name(locale.getlocale()[0]) or "en"
    return "en"


def language_from_argv(argv: Sequence[str]) -> str | None:
    """The value of the first ``--lang X`` / ``--lang=X`` of a command line (before ``--``)."""
    for k, arg in enumerate(argv):
        if arg == "--":
            break
        value = None
        if arg == "--lang" and k + 1 < len(argv):
            value = argv[k + 1]
        elif arg.startswith("--lang="):
            value = arg.split("=", 1)[1]
        if value is not None:
            return value if value in LANGS else None
    return None


def set_language(lang: str | None) -> None:
    """Set the language of :func:`tr` (``None``: back to the system's)."""
    global _current
    if lang is not None and lang not in LANGS:
        raise ValueError(f"language {lang!r}: expected one of {', '.join(LANGS)}")
    _current = lang


def language() -> str:
    """The language messages are printed in now."""
    return _current or system_language()


# -- the catalogue -------------------------------------------------------------------------

_FIELD = re.compile(r"\{\{|\}\}|\{(\d*)\}")


def template_fields(template: str) -> int:
    """How many ``{}`` fields an English template has."""
    return sum(1 for m in _FIELD.finditer(template) if m.group().startswith("{") and
               m.group() != "{{")


def _literals(template: str) -> list[str]:
    """The literal text between the fields (``{{``/``}}`` unescaped)."""
    parts, buf, pos = [], [], 0
    for m in _FIELD.finditer(template):
        buf.append(template[pos:m.start()])
        if m.group() == "{{":
            buf.append("{")
        elif m.group() == "}}":
            buf.append("}")
        else:
            parts.append("".join(buf))
            buf = []
        pos = m.end()
    buf.append(template[pos:])
    parts.append("".join(buf))
    return parts


#: A field whose brackets balance (two levels deep): a field of "(got {})" ends at its own
#: bracket, not at the first ")" of a nested "(at line 1, column 7)".
_BALANCED = r"((?:[^()]|\((?:[^()]|\([^()]*\))*\))*?)"


class _Entry:
    __slots__ = ("anchor", "balanced", "en", "pattern", "ru", "weight")

    def __init__(self, en: str, ru: str):
        self.en, self.ru = en, ru
        lits = _literals(en)
        self.pattern = re.compile("(.*?)".join(re.escape(s) for s in lits), re.DOTALL)
        self.balanced = re.compile(_BALANCED.join(re.escape(s) for s in lits), re.DOTALL)
        self.anchor = max(lits, key=len)
        self.weight = sum(len(s) for s in lits)


def parse_catalogue(text: str, source: str = "catalogue") -> list[tuple[str, str]]:
    """``(english, russian)`` pairs of a catalogue text: ``en:``/``ru:`` line pairs,
    ``#`` comments and blank lines between them."""
    pairs: list[tuple[str, str]] = []
    en: str | None = None
    for n, line in enumerate(text.splitlines(), 1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        tag, sep, body = line.partition(": ")
        if not sep and line.rstrip() in ("en:", "ru:"):
            tag, body = line.rstrip()[:2], ""
        if tag == "en" and en is None:
            en = body
        elif tag == "ru" and en is not None:
            if template_fields(en) and not _fits(en, body):
                raise ValueError(f"{source}:{n}: the Russian template's fields do not "
                                 f"match the English one's: {en!r}")
            pairs.append((en, body))
            en = None
        else:
            raise ValueError(f"{source}:{n}: expected 'en: …' then 'ru: …' (got {line!r})")
    if en is not None:
        raise ValueError(f"{source}: the last 'en:' line has no 'ru:' line")
    return pairs


def _fits(en: str, ru: str) -> bool:
    n = template_fields(en)
    try:
        ru.format(*range(n))
    except (IndexError, KeyError, ValueError):
        return False
    return True


@functools.cache
def catalogue() -> tuple[_Entry, ...]:
    """The Russian catalogue's entries, the most specific (longest literal text) first."""
    folder = resources.files("graphplan") / "data" / "messages" / "ru"
    entries = []
    for item in sorted(folder.iterdir(), key=lambda p: p.name):
        if item.name.endswith(".txt"):
            for en, ru in parse_catalogue(item.read_text(encoding="utf-8"), item.name):
                entries.append(_Entry(en, ru))
    entries.sort(key=lambda e: -e.weight)
    return tuple(entries)


@functools.cache
def _exact() -> dict[str, str]:
    return {e.en: e.ru for e in catalogue() if not template_fields(e.en)}


def tr(text: str, lang: str | None = None) -> str:
    """``text`` (a finished English message) in ``lang`` (default: :func:`language`)."""
    if (lang or language()) != "ru" or not text:
        return text
    return _translate(text, 0)


_MAX_DEPTH = 4


def _matches(text: str) -> list[tuple[int, object]]:
    """The templates matching ``text`` whole, as (balanced, hit): ``balanced`` is 1 when
    the fields' brackets balance; ``hit`` is the entry, or the Russian text of an exact
    one. Fields are translated by the caller."""
    exact = _exact().get(text)
    if exact is not None:
        return [(1, exact)]
    out: list[tuple[int, object]] = []
    for e in catalogue():
        if e.anchor not in text or not template_fields(e.en):
            continue
        if e.balanced.fullmatch(text):
            out.append((1, e))
        elif e.pattern.fullmatch(text):
            out.append((0, e))
    return out


_LATIN = re.compile(r"[a-z]{2,}")


def _translate(text: str, depth: int) -> str:
    """The Russian of ``text``: of the templates matching the whole text or a tail of it
    after a ``": "`` (the head — a file name, a key path, another message — translated in
    turn), the reading that leaves the fewest English letters; else its parts around
    ``"; "`` or ``" — "``; else ``text``."""
    if depth > _MAX_DEPTH or not re.search(r"[A-Za-z]", text):
        return text
    best: tuple[tuple[int, int, int, int], str] | None = None
    pos = 0
    while True:
        for balanced, hit in _matches(text[pos:]):
            if isinstance(hit, _Entry):
                tail = text[pos:]
                m = (hit.balanced.fullmatch(tail) if balanced else None) or \
                    hit.pattern.fullmatch(tail)
                assert m is not None
                body = hit.ru.format(*(_translate(g, depth + 1) for g in m.groups()))
            else:
                body = str(hit)
            new = body if pos == 0 else _translate(text[:pos - 2], depth + 1) + ": " + body
            score = (sum(len(w) for w in _LATIN.findall(new)), -balanced, pos,
                     -getattr(hit, "weight", len(text)))
            if best is None or score < best[0]:
                best = (score, new)
        nxt = text.find(": ", pos)
        if nxt < 0:
            break
        pos = nxt + 2
    if best is not None:
        return best[1]
    for sep in ("; ", " — "):  # a message and its hint, each of its own template
        head, found_sep, tail = text.partition(sep)
        if found_sep and tail:
            new = _translate(head, depth + 1) + sep + _translate(tail, depth + 1)
            if new != text:
                return new
    return text


# -- argparse's own words --------------------------------------------------------------------

ARGPARSE_RU: dict[str, str] = {
    "usage: ": "вызов: ",
    "positional arguments": "аргументы",
    "options": "параметры",
    "optional arguments": "параметры",
    "show this help message and exit": "показать эту справку и выйти",
    "show program's version number and exit": "показать версию программы и выйти",
    "%(prog)s: error: %(message)s\n": "%(prog)s: ошибка: %(message)s\n",
    "the following arguments are required: %s": "не хватает обязательных аргументов: %s",
    "unrecognized arguments: %s": "непонятные аргументы: %s",
    "invalid choice: %(value)r (choose from %(choices)s)":
        "недопустимое значение: %(value)r (выберите из: %(choices)s)",
    "argument %(argument_name)s: %(message)s": "аргумент %(argument_name)s: %(message)s",
    "expected one argument": "ожидалось одно значение",
    "expected at most one argument": "ожидалось не больше одного значения",
    "expected at least one argument": "ожидалось хотя бы одно значение",
    "expected %s argument": "ожидалось значений: %s",
    "expected %s arguments": "ожидалось значений: %s",
    "invalid %(type)s value: %(value)r": "недопустимое значение (%(type)s): %(value)r",
    "ambiguous option: %(option)s could match %(matches)s":
        "неоднозначный параметр: %(option)s подходит к %(matches)s",
    "not allowed with argument %s": "нельзя вместе с аргументом %s",
    "one of the arguments %s is required": "нужен один из аргументов: %s",
    "ignored explicit argument %r": "лишнее значение %r не учтено",
    "unexpected option string: %s": "неожиданный параметр: %s",
    "%(prog)s: error: %(message)s": "%(prog)s: ошибка: %(message)s",
}


def argparse_gettext(message: str) -> str:
    """argparse's ``_()`` in the current language."""
    return ARGPARSE_RU.get(message, message) if language() == "ru" else message


def argparse_ngettext(singular: str, plural: str, n: int) -> str:
    """argparse's ``ngettext()`` in the current language."""
    return argparse_gettext(singular if n == 1 else plural)


__all__ = [
    "ENV_VAR",
    "LANGS",
    "argparse_gettext",
    "argparse_ngettext",
    "catalogue",
    "language",
    "language_from_argv",
    "parse_catalogue",
    "set_language",
    "system_language",
    "template_fields",
    "tr",
]
