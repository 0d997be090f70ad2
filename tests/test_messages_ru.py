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
import message_scan

#: English words that never appear in a Russian message (outside file names and keys).
ENGLISH = re.compile(r"\b(the|expected|got|must|should|not|found|missing|unknown|with|"
                     r"for|and|of|is|are|has|have|needs?|error|warning|file|folder|"
                     r"cannot|could|no|one|an|at|or|to|in|on|be|by)\b")
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


# -- every message of the package has a Russian twin -------------------------------------------


def test_every_message_of_the_package_has_a_russian_twin():
    todo = message_scan.missing()
    assert not todo, ("messages without Russian (add them to graphplan/data/messages/ru/, "
                      "`python tests/message_scan.py` prints stubs):\n" + "\n".join(
                          f"{w[0]}: {t}" for t, w in todo.items()))


def test_the_scan_finds_messages_of_every_kind():
    found = message_scan.package_messages()
    # a raise, a reader's fail(), a warning, a hint, a help text, a print, a lambda, where()
    for t in ("{}: {}: expected a table (got {})", "expected a table (got {})",
              "missing required key", "write the report to this file (atomically)",
              "its two guides are parallel", "position {} (φ = {}°)",
              " — a decimal comma: write {}.{} with a point (десятичная точка, а не запятая)",
              "graphplan: warning: {}"):
        assert t in found or t == "{}: {}: expected a table (got {})", t
    assert len(found) > 400


def test_no_catalogue_entry_is_dead_weight_twice():
    seen: dict[str, str] = {}
    for e in i18n.catalogue():
        assert seen.setdefault(e.en, e.ru) == e.ru, f"two Russian forms of {e.en!r}"


# -- bad inputs under --lang ru: no English; under --lang en: no Cyrillic unit ---------------

import test_loader_errors as L  # noqa: E402

CYRILLIC_UNIT = re.compile(r"(?<![А-Яа-яЁё])(мм|м|Н|Н·м|кг|рад|с|об/мин|Дж|Вт|кВт|кг·м²)"
                           r"(?![А-Яа-яЁё])")


@pytest.mark.parametrize(("base", "edits"), [c[1:3] for c in L.CASES],
                         ids=[c[0] for c in L.CASES])
def test_every_loader_error_in_russian(base, edits):
    with pytest.raises(L.g.InputError) as ei:
        L.g.loads(L.build(base, *edits), source=L.SRC)
    msg = str(ei.value)
    ru = i18n.tr(msg, "ru")
    assert not english_words(ru), f"{msg}\n→ {ru}"
    assert not CYRILLIC_UNIT.search(re.sub(r"'[^']*'|\"[^\"]*\"", "", msg)), msg


@pytest.mark.parametrize("text", [
    "[frame\nlink = 4\n", "frame = \n", "a = 1\na = 2\n", 'x = "unterminated\n',
    "[frame]\npoints = { O = [0, 0], }\n", "",
])
def test_toml_syntax_errors_in_russian(text):
    with pytest.raises(L.g.InputError) as ei:
        L.g.loads(text, source=L.SRC)
    ru = i18n.tr(str(ei.value), "ru")
    assert not english_words(ru), f"{ei.value}\n→ {ru}"


def _run(capsys, *argv) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def _bad_inputs(tmp_path: Path) -> list[list[str]]:
    press = L.PRESS_TEXT
    comma = tmp_path / "comma.toml"
    comma.write_text(press.replace("rpm = ", "rpm = 1,5 #", 1), encoding="utf-8")
    look = tmp_path / "look.toml"
    look.write_text(L.build(L.PRESS, L.set_("crank.joints", ["О1", "A"])), encoding="utf-8")
    short = tmp_path / "short.toml"  # a connecting rod too short to reach: not assembled
    short.write_text(L.build(L.FOURBAR, L.set_("dyads[0].lengths", [0.05, 0.05])),
                     encoding="utf-8")
    latin1 = tmp_path / "latin1.toml"
    latin1.write_bytes(press.encode("utf-8") + "# Größe\n".encode("latin-1"))
    student = tmp_path / "student.toml"
    student.write_text("[work]\nvariant = 'nope.toml'\n", encoding="utf-8")
    exists = tmp_path / "exists.toml"
    exists.write_text("", encoding="utf-8")
    press_file = tmp_path / "press.toml"
    press_file.write_text(press, encoding="utf-8")
    out = str(tmp_path / "out")
    return [
        ["analyze", str(tmp_path / "nope.toml")],
        ["analyze", str(comma)],
        ["analyze", str(look)],
        ["analyze", str(short)],
        ["analyze", str(latin1)],
        ["analyze", str(tmp_path)],
        ["sheets", str(press_file), "-o", out, "--format", "gif"],
        ["sheets", str(press_file), "-o", out, "--precision", "9"],
        ["new", "tractor", "-o", str(tmp_path / "t.toml")],
        ["new", "press", "-o", str(exists)],
        ["check", str(student)],
        ["check"],
        ["teach", str(press_file), "--plan", "velocity", "-o", out],
        ["teach", str(press_file), "--plan", "velocity", "--position", "99", "-o", out],
        ["analyze", "--jsn"],
        ["sheets"],
        ["nosuchcommand"],
    ]


def test_bad_inputs_under_lang_ru_print_no_english(tmp_path, capsys):
    for argv in _bad_inputs(tmp_path):
        try:
            code, _, err = _run(capsys, "--lang", "ru", *argv)
        except SystemExit as exc:  # argparse's usage errors
            code, (_, err) = exc.code, capsys.readouterr()
        assert code == 2, (argv, code, err)
        message = err.strip().splitlines()[-1]
        assert CYRILLIC.search(message), (argv, message)
        assert not english_words(message), (argv, message)


def test_bad_inputs_under_lang_en_print_no_cyrillic_unit(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("LANG", "ru_RU.UTF-8")  # --lang en wins over a Russian locale
    for argv in _bad_inputs(tmp_path):
        try:
            code, _, err = _run(capsys, *argv, "--lang", "en")
        except SystemExit as exc:
            code, (_, err) = exc.code, capsys.readouterr()
        assert code == 2, (argv, code, err)
        message = re.sub(r"'[^']*'|\"[^\"]*\"|\([^)]*[А-Яа-я][^)]*\)", "", err)
        assert not CYRILLIC_UNIT.search(message), (argv, err)
        assert "ошибка" not in err and "вызов" not in err, (argv, err)


def test_help_of_every_command_in_russian(capsys):
    for cmd in ([], ["analyze"], ["sheets"], ["note"], ["new"], ["check"], ["teach"]):
        with pytest.raises(SystemExit):
            main(["--lang", "ru", *cmd, "--help"])
        out = capsys.readouterr().out
        text = re.sub(r"\{[^}]*\}|\[[^\]]*\]", " ", out)  # choices and usage brackets
        assert not english_words(text), (cmd, english_words(text), out)


def test_a_warning_in_russian(tmp_path, capsys):
    # the slotter's working stroke made the fast one: K < 1 (project/plausibility.py)
    text = (L.EXAMPLES / "slotter.toml").read_text(encoding="utf-8") if (
        L.EXAMPLES / "slotter.toml").exists() else None
    if text is None:
        pytest.skip("no slotter example")
    doc = L.tomllib.loads(text)
    doc["output"]["working"] = "+" if doc["output"].get("working", "-") == "-" else "-"
    path = tmp_path / "slotter.toml"
    path.write_text(L.dumps(doc), encoding="utf-8")
    _run(capsys, "analyze", str(path), "--lang", "en")
    code, _, err = _run(capsys, "--lang", "ru", "analyze", str(path))
    assert code == 0
    assert "предупреждение" in err and "K =" in err, err
    assert not english_words(err), err


@pytest.mark.parametrize("example", ["press", "slotter", "crusher"])
def test_russian_lessons_have_no_english(example, tmp_path):
    # the step texts of the plans (e.g. "Линия ⟂AB через a, линия ∥ направляющей через p")
    import html

    from graphplan.model import load
    from graphplan.project import analyze
    from graphplan.teaching import lesson, write_lesson

    a = analyze(load(L.EXAMPLES / f"{example}.toml"))
    label = a.kin.labels[1]
    for plan in ("velocity", "acceleration", "forces", "zhukovsky"):
        page = write_lesson(lesson(a, plan, label), tmp_path, lang="ru")[0]
        text = re.sub(r"<script.*?</script>|<style.*?</style>|<svg.*?</svg>", " ",
                      Path(page).read_text(encoding="utf-8"), flags=re.S)
        for line in html.unescape(re.sub(r"<[^>]+>", "\n", text)).splitlines():
            assert not english_words(line), (example, plan, line)


#: a Cyrillic unit after a number or in a column's header («0.5 кг·м²», «Mс, Н·м»)
UNIT_AFTER = re.compile(r"(?:\d|[,(/]) ?(мм|м|Н|Н·м|кг|рад|с|об/мин|Дж|Вт|кВт|кг·м²|м/с|рад/с)"
                        r"(?![А-Яа-яЁё])")


def test_english_files_are_in_english_units():
    """Issue 23: dynamics.en.md carried Russian units (ω1 = 99.484 рад/с, Jкр = 0 кг·м²,
    Kφ … рад/мм, v = 16.4 м/с). Every committed English table of every example is in English
    units (the symbols keep their Russian subscripts: Mс, Jкр, Aд — the sheets' notation);
    the Russian twin has the Russian units."""
    from graphplan.files import examples_dir

    drawings = examples_dir().parent / "drawings"
    files = sorted(drawings.glob("*/*.en.md"))
    assert len(files) >= 12 * 3
    for f in files:
        text = f.read_text(encoding="utf-8")
        assert not UNIT_AFTER.search(text), (f, UNIT_AFTER.search(text))
        ru = f.with_name(f.name.replace(".en.md", ".ru.md")).read_text(encoding="utf-8")
        if f.name.startswith("dynamics"):
            assert "кг·м²" in ru and "рад/с" in ru and "kg·m²" in text and "rad/s" in text
