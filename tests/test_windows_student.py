"""A Windows student's first run: Russian and ASCII consoles, Notepad's files, exit codes.

The commands run as a user runs them (``python -m graphplan`` in a subprocess) with the
standard streams in the console's code page (``PYTHONIOENCODING``, or redirected to a
file under a legacy locale encoding), and the variant and student files written as
Windows programs write them: UTF-8 with a BOM, CRLF line ends, cp1251 ("ANSI").
"""

from __future__ import annotations

import io
import os
import subprocess
import sys
from pathlib import Path

import pytest

from graphplan import console
from graphplan.checking.student import load_student
from graphplan.errors import InputError
from graphplan.files import bundled_example, decode_text
from graphplan.model import load

ROOT = Path(__file__).resolve().parent.parent
PRESS = bundled_example("press")
SEED = ROOT / "examples" / "seed-check" / "seed.toml"


def graphplan(args: list[str], encoding: str | None, stdout=subprocess.PIPE):
    """Run the command with its streams in ``encoding`` (None: UTF-8 from a redirect)."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        p for p in (str(ROOT), os.environ.get("PYTHONPATH")) if p))
    env.pop("PYTHONIOENCODING", None)
    env.pop("PYTHONUTF8", None)
    if encoding is not None:
        env["PYTHONIOENCODING"] = encoding
    return subprocess.run([sys.executable, "-m", "graphplan", *args], env=env, cwd=ROOT,
                          stdout=stdout, stderr=subprocess.PIPE, timeout=600, check=False)


@pytest.mark.parametrize("encoding", ["cp1251", "cp866", "ascii"])
def test_analyze_on_a_legacy_console_never_crashes(encoding):
    proc = graphplan(["analyze", "--lang", "ru"], encoding)
    err = proc.stderr.decode(encoding, "replace")
    assert proc.returncode == 0, err
    assert "Traceback" not in err and "UnicodeEncodeError" not in err
    out = proc.stdout.decode(encoding)  # strictly in the console's code page
    # ω is not in cp1251, cp866 or ASCII: written as w
    assert "ω" not in out and "w1" in out.replace(" ", "").replace("_", "")
    if encoding == "ascii":
        assert out.isascii()
    else:
        assert any("а" <= ch <= "я" for ch in out)  # Russian stays Russian


@pytest.mark.parametrize("encoding", ["cp1251", "cp866", "ascii"])
def test_check_on_a_legacy_console_reports_faults_with_exit_1(encoding, tmp_path):
    report = tmp_path / "report.txt"
    with report.open("wb") as f:
        proc = graphplan(["check", str(SEED)], encoding, stdout=f)
    assert proc.returncode == console.EXIT_FAULTS, proc.stderr.decode(encoding, "replace")
    assert b"Traceback" not in proc.stderr
    text = report.read_bytes().decode(encoding)
    assert len(text.splitlines()) > 10


def test_redirected_output_is_utf8_with_every_character(tmp_path):
    out = tmp_path / "out.txt"
    with out.open("wb") as f:  # no PYTHONIOENCODING: a redirect is written in UTF-8
        proc = graphplan(["analyze"], None, stdout=f)
    assert proc.returncode == 0
    assert "ω" in out.read_bytes().decode("utf-8")


def test_the_streams_are_prepared_once_for_any_console():
    raw = io.BytesIO()
    stream = io.TextIOWrapper(raw, encoding="cp866", errors="strict")
    console.prepare_streams(stream, stream)  # not a tty: becomes UTF-8
    stream.write("ω₁ = 12,57 рад/с\n")
    stream.flush()
    assert raw.getvalue().decode("utf-8") == "ω₁ = 12,57 рад/с\n"


def test_spellings_for_consoles_that_lack_a_character():
    assert "ω₁ − φ² · 3°".encode("cp1251", console.ERROR_HANDLER).decode("cp1251") == \
        "w1 - phi^2 · 3°"  # · and ° are in cp1251, kept
    assert "ω₁ − φ² · 3°".encode("ascii", console.ERROR_HANDLER) == b"w1 - phi^2 * 3 deg"
    assert "Ёмкость Щ".encode("ascii", console.ERROR_HANDLER) == b"Yomkost' Shh"
    assert "ω рад".encode("cp866", console.ERROR_HANDLER).decode("cp866") == "w рад"
    assert console.console_spelling("☃") == "?"


def test_exit_codes_are_distinct_and_documented():
    codes = [console.EXIT_OK, console.EXIT_FAULTS, console.EXIT_BAD_INPUT,
             console.EXIT_FILE_ERROR, console.EXIT_INTERNAL, console.EXIT_INTERRUPTED,
             console.EXIT_TERMINATED]
    assert codes == [0, 1, 2, 3, 4, 130, 143] and set(console.EXIT_CODES) == set(codes)
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    for code in codes:
        assert f"| {code} |" in readme, code


def test_exit_code_2_for_bad_input_and_3_for_a_file_that_cannot_be_written(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[crank\n", encoding="utf-8")
    proc = graphplan(["analyze", str(bad)], "cp1251")
    assert proc.returncode == console.EXIT_BAD_INPUT
    assert len(proc.stderr.decode("cp1251").strip().splitlines()) == 1
    blocker = tmp_path / "file"
    blocker.write_text("x", encoding="utf-8")
    proc = graphplan(["analyze", "-o", str(blocker / "out.txt")], "cp1251")
    assert proc.returncode in (console.EXIT_BAD_INPUT, console.EXIT_FILE_ERROR)
    assert b"Traceback" not in proc.stderr
    assert len(proc.stderr.decode("cp1251").strip().splitlines()) == 1


def test_an_internal_error_is_one_line_with_exit_4(monkeypatch, capsys):
    from graphplan import cli

    def boom(args):
        raise ZeroDivisionError("division by zero")

    monkeypatch.setitem(cli.COMMANDS, "analyze", boom)
    assert cli.main(["analyze"]) == console.EXIT_INTERNAL
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "internal error" in err and "ZeroDivisionError" in err


# ------------------------------------------------------------- input files

def _variants(tmp_path: Path) -> dict[str, Path]:
    text = PRESS.read_text(encoding="utf-8")
    files = {
        "bom": b"\xef\xbb\xbf" + text.encode("utf-8"),
        "crlf": text.replace("\n", "\r\n").encode("utf-8"),
        "bom-crlf": b"\xef\xbb\xbf" + text.replace("\n", "\r\n").encode("utf-8"),
        "utf16": text.replace("\n", "\r\n").encode("utf-16"),  # Notepad's "Unicode"
    }
    out = {}
    for name, data in files.items():
        out[name] = tmp_path / f"{name}.toml"
        out[name].write_bytes(data)
    return out


def test_variants_as_notepad_saves_them_load_as_the_original(tmp_path):
    reference = load(PRESS)
    for name, path in _variants(tmp_path).items():
        mech = load(path)
        assert mech.crank == reference.crank, name
        assert mech.dyads == reference.dyads, name


def test_a_cp1251_variant_asks_to_be_saved_as_utf8(tmp_path):
    path = tmp_path / "press.toml"
    text = PRESS.read_text(encoding="utf-8").replace("\n", "\r\n")
    path.write_bytes(("# Вариант 12, кривошипный пресс\r\n" + text).encode("cp1251",
                                                                            "replace"))
    with pytest.raises(InputError) as err:
        load(path)
    msg = str(err.value)
    assert "\n" not in msg and msg.startswith(f"{path}: line 1:")
    assert "cp1251" in msg and "save the file as UTF-8" in msg
    proc = graphplan(["analyze", str(path)], "cp1251")
    assert proc.returncode == console.EXIT_BAD_INPUT
    assert "save the file as UTF-8" in proc.stderr.decode("cp1251")


def test_student_files_as_notepad_saves_them(tmp_path):
    text = SEED.read_text(encoding="utf-8")
    reference = load_student(SEED)
    for name, data in {"bom": b"\xef\xbb\xbf" + text.encode("utf-8"),
                       "crlf": text.replace("\n", "\r\n").encode("utf-8")}.items():
        path = SEED.parent / f".tmp-{name}-{os.getpid()}.toml"  # beside it: its variant path
        try:
            path.write_bytes(data)
            work = load_student(path)
        finally:
            path.unlink(missing_ok=True)
        assert (work.general, work.positions) == (reference.general, reference.positions), name
    path = tmp_path / "student.toml"
    path.write_bytes(text.encode("cp1251", "replace"))
    from graphplan.checking.errors import StudentFileError

    with pytest.raises(StudentFileError, match="save the file as UTF-8"):
        load_student(path)


def test_decode_text_names_the_line_and_the_code_page():
    assert decode_text(b"\xef\xbb\xbfa = 1\r\nb = 2\r", "x") == "a = 1\nb = 2\n"
    with pytest.raises(InputError, match=r"^x: line 2: .*cp866"):
        decode_text("a = 1\n# Привет мир\n".encode("cp866"), "x")
    with pytest.raises(InputError, match=r"^x: line 1: not UTF-8 text: save"):
        decode_text(b"\xff\x00\x80", "x")


@pytest.mark.parametrize("encoding", ["cp1251", "ascii"])
def test_json_on_a_legacy_console_is_escaped_not_altered(encoding):
    import json

    proc = graphplan(["analyze", "--json"], encoding)
    assert proc.returncode == 0
    text = proc.stdout.decode(encoding)
    data = json.loads(text)
    assert data["positions"][0]["forces"]["loads"]["forces"]["Pи2"]["kind"] == "inertia"
    assert text.isascii()  # every non-ASCII character escaped: the data are exact


def test_the_verdicts_of_the_check_schema_are_the_checkers():
    import json
    from importlib import resources

    from graphplan.checking.findings import VERDICTS

    schema = json.loads((resources.files("graphplan") / "data" / "schema" /
                         "check.schema.json").read_text(encoding="utf-8"))
    enum = schema["properties"]["figures"]["items"]["properties"]["verdict"]["enum"]
    assert tuple(enum) == VERDICTS
