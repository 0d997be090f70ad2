"""The student file: what it accepts, and one-line errors naming the file and the key."""

import pytest

from graphplan.checking.checks import check_work
from graphplan.checking.errors import StudentFileError
from graphplan.checking.student import load_student, loads_student
from graphplan.errors import GraphplanError, InputError
from graphplan.files import bundled_example

PRESS = str(bundled_example("press"))
GOOD = f"""
[work]
variant = "{PRESS}"
student = "Иванов"

[general]
lines = ["G3 = m3∙g = 1250∙9,81 = 12262,5 Н"]
figures = {{ m2 = 129 }}

[arms]
h3 = {{ force = "G3", about = "A" }}

[[positions]]
label = "(2)"
lines = [
  {{ line = "Кр=420/42=10 кН/мм", symbols = "Q/Q_mm" }},
  {{ line = "0,7Q0 = 0.7∙600000 = 420000 H", quantity = "Q", note = "из диаграммы" }},
]
figures = {{ h21 = "37,39 мм" }}
"""


def test_a_good_file_reads():
    w = loads_student(GOOD, "good.toml")
    assert w.student == "Иванов" and w.lang == "ru"
    assert [ln.text for ln in w.general] == ["m2 = 129.0", "G3 = m3∙g = 1250∙9,81 = 12262,5 Н"]
    (p,) = w.positions
    assert p.label == "(2)" and "h3" in p.arms
    assert p.lines[0].text == "h21 = 37,39 мм"
    assert p.lines[1].symbols == "Q/Q_mm" and p.lines[2].quantity == "Q"
    assert all(ln.file_line for ln in w.lines if ln.key.startswith(("general.lines",
                                                                    "positions[0].lines")))


def test_a_good_file_checks_clean():
    r = check_work(loads_student(GOOD, "good.toml"))
    assert r.ok and not r.findings
    assert {f.quantity for f in r.figures} >= {"G3", "m2", "h21", "Q", "Q_mm", "Кр"}


BAD = [
    ("[work]\n", "positions: missing required key"),
    ("x = 1\n[work]\nvariant='a'\n[[positions]]\nlabel='1'\n",
     "x: unknown key"),
    (f"[work]\nvariant='{PRESS}'\n", "positions: missing required key"),
    ("[work]\nvariant='nowhere.toml'\n[[positions]]\nlabel='1'\n",
     "work.variant: variant file"),
    (f"[work]\nvariant='{PRESS}'\nlang='de'\n[[positions]]\nlabel='1'\n",
     "work.lang: expected one of ru, en"),
    (f"[work]\nvariant='{PRESS}'\n[[positions]]\nlabel='1'\nlines='G3=1'\n",
     "positions[0].lines: expected an array of lines"),
    (f"[work]\nvariant='{PRESS}'\n[[positions]]\nlabel='1'\nlines=[3]\n",
     "positions[0].lines[0]: expected a table"),
    (f"[work]\nvariant='{PRESS}'\n[[positions]]\nlabel='1'\nlines=['']\n",
     "positions[0].lines[0]: empty line"),
    (f"[work]\nvariant='{PRESS}'\n[[positions]]\nlabel='1'\nlines=[{{text='a=1'}}]\n",
     "positions[0].lines[0].text: unknown key"),
    (f"[work]\nvariant='{PRESS}'\n[[positions]]\nlabel='1'\n[[positions]]\nlabel='1'\n",
     "positions[1].label: position '1' appears twice"),
    (f"[work]\nvariant='{PRESS}'\n[[positions]]\nlabel='a@b'\n",
     "positions[0].label: expected a position label"),
    (f"[work]\nvariant='{PRESS}'\n[arms]\nh3={{force='G3'}}\n[[positions]]\nlabel='1'\n",
     "arms.h3.about: missing required key"),
    (f"[work]\nvariant='{PRESS}'\n[tolerances]\nsegment=2\n[[positions]]\nlabel='1'\n",
     "tolerances.segment: must be <= 1"),
    ("[work\n", "not valid TOML"),
]


@pytest.mark.parametrize(("text", "message"), BAD, ids=[b[1][:30] for b in BAD])
def test_bad_files_name_the_key(text, message):
    with pytest.raises(StudentFileError) as info:
        loads_student(text, "class/ivanov.toml")
    msg = str(info.value)
    assert msg.startswith("class/ivanov.toml: ")
    assert message in msg and "\n" not in msg
    assert isinstance(info.value, InputError) and isinstance(info.value, GraphplanError)


def test_unknown_position_is_named(tmp_path):
    w = loads_student(f"[work]\nvariant='{PRESS}'\n[[positions]]\nlabel='42'\n"
                      "lines=['G3 = 12262,5 Н']\n", tmp_path / "s.toml")
    with pytest.raises(StudentFileError, match=r"positions\[0\]\.label: the variant has no "
                                               r"position '42'"):
        check_work(w)


def test_position_given_by_its_angle():
    # a position the variant does not number, at φ = 300°
    w = loads_student(f"[work]\nvariant='{PRESS}'\n[[positions]]\nlabel='x'\nphi=300\n"
                      "lines=['h21 = 79,5 мм']\n[general]\nlines=['Kl = 0,001 м/мм']\n",
                      "s.toml")
    r = check_work(w)
    (h21,) = [f for f in r.figures if f.quantity == "h21"]
    assert h21.expected is not None and h21.position == "x"


def test_missing_and_unreadable_files(tmp_path):
    with pytest.raises(StudentFileError, match="file not found"):
        load_student(tmp_path / "none.toml")
    bad = tmp_path / "bad.toml"
    bad.write_bytes(b"\x80\x81[work]")  # (a BOM of UTF-16 would be read as UTF-16)
    with pytest.raises(StudentFileError, match="not UTF-8"):
        load_student(bad)
