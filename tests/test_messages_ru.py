"""Russian as a language of graphplan's messages (graphplan/i18n.py, issue 23).

* every message the package can print has a Russian twin in the catalogue (read off the
  source by :mod:`message_scan`);
* :func:`graphplan.i18n.tr` fills a Russian template from an English message, its fields
  translated in turn, and peels a file name or a key path off a message;
* the language comes from ``--lang``, then ``GRAPHPLAN_LANG``, then the locale;
* commands run under ``--lang ru`` on bad inputs print no English, and under ``--lang en``
  no Cyrillic.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

from graphplan import i18n
from graphplan.cli import main

sys.path.insert(0, str(Path(__file__).resolve().parent))
import message_scan  # noqa: E402

#: English words that never appear in a Russian message (outside file names and keys).
ENGLISH = re.compile(r"\b(the|expected|got|must|should|not|found|missing|unknown|with|"
                     r"from|for|and|of|is|are|has|have|needs?|error|warning|file|folder|"
                     r"cannot|could|no|one|a|an|at|or|to|in|on|be|by)\b")
CYRILLIC = re.compile(r"[А-Яа-яЁё]")


def english_words(text: str) -> list[str]:
    """English words of ``text`` outside quotes, paths, options and key paths."""
    text = re.sub(r"'[^']*'|\"[^\"]*\"|«[^»]*»", " ", text)
    text = re.sub(r"\S*[/\\]\S*|--?[\w-]+|\b\w+\.(toml|svg|dxf|pdf|png|html|csv|json|"
                  r"docx|txt)\b|\b\w*[._\[\]]\w*\b", " ", text)
    return ENGLISH.findall(text)


def test_tr_fills_the_russian_template_and_translates_fields():
    # en: {}: {}: expected a table (got {}) — the type name is itself a message ('table')
    msg = "press.toml: links.AB: expected a table (got array)"
    ru = i18n.tr(msg, "ru")
    assert ru.startswith("press.toml: links.AB: ")
    assert not english_words(ru), ru
    assert i18n.tr(msg, "en") == msg


def test_fields_may_change_order():
    entries = i18n.parse_catalogue("en: {} of {}\nru: {1} — {0}\n")
    assert entries == [("{} of {}", "{1} — {0}")]
    with pytest.raises(ValueError, match="fields"):
        i18n.parse_catalogue("en: {} of {}\nru: {2}\n")
    with pytest.raises(ValueError, match="'ru: …'"):
        i18n.parse_catalogue("ru: без пары\n")


def test_an_unknown_message_is_kept_and_a_known_tail_is_translated():
    assert i18n.tr("zzz qqq", "ru") == "zzz qqq"
    assert i18n.tr("a.toml: b.c: missing required key", "ru") == \
        "a.toml: b.c: " + i18n.tr("missing required key", "ru")
    assert i18n.tr("missing required key", "ru") != "missing required key"


@pytest.mark.parametrize(("env", "lang"), [
    ({"LANG": "ru_RU.UTF-8"}, "ru"),
    ({"LANG": "en_US.UTF-8"}, "en"),
    ({"LC_ALL": "C", "LANG": "ru_RU.UTF-8"}, "en"),  # LC_ALL decides, even C
    ({"LC_MESSAGES": "be_BY.UTF-8", "LANG": "en_GB"}, "ru"),
    ({"GRAPHPLAN_LANG": "en", "LANG": "ru_RU.UTF-8"}, "en"),
    ({"GRAPHPLAN_LANG": "ru", "LC_ALL": "C"}, "ru"),
    ({"LANG": "Russian_Russia.1251"}, "ru"),  # a Windows locale name
    ({}, "en"),
])
def test_the_language_of_the_system(env, lang):
    assert i18n.system_language(env, platform="linux") == lang


def test_lang_on_the_command_line():
    assert i18n.language_from_argv(["analyze", "--lang", "ru", "x.toml"]) == "ru"
    assert i18n.language_from_argv(["--lang=en", "check"]) == "en"
    assert i18n.language_from_argv(["analyze", "--", "--lang", "ru"]) is None
    assert i18n.language_from_argv(["analyze"]) is None


def test_help_in_russian_by_the_locale(monkeypatch, capsys):
    monkeypatch.setenv("LANG", "ru_RU.UTF-8")
    monkeypatch.delenv("LC_ALL", raising=False)
    monkeypatch.delenv("LC_MESSAGES", raising=False)
    monkeypatch.delenv("GRAPHPLAN_LANG", raising=False)
    with pytest.raises(SystemExit):
        main(["--help"])
    out = capsys.readouterr().out
    assert "вызов:" in out and "структура и точная кинематика" in out
    monkeypatch.setenv("GRAPHPLAN_LANG", "en")
    with pytest.raises(SystemExit):
        main(["--help"])
    assert not CYRILLIC.search(capsys.readouterr().out.replace("пояснительная записка", ""))
