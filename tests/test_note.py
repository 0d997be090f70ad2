"""The explanatory note (issue 24): a DOCX laid out after GOST 2.105 whose lines are the
project's own calculation, read back by the checker with no finding and a planted slip found."""

from __future__ import annotations

import io
import json
import re
import zipfile
from pathlib import Path

import numpy as np
import pytest

docx = pytest.importorskip("docx", reason="the note extra (python-docx) is not installed")

from graphplan.checking.generate import generate  # noqa: E402
from graphplan.cli import main  # noqa: E402
from graphplan.note import build_note, find_office, note_docx  # noqa: E402
from graphplan.note.blocks import Formula, Heading  # noqa: E402
from graphplan.note.docx_writer import FORMULA_STYLE  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted(p.stem for p in (ROOT / "examples").glob("*.toml"))
W = "{http://schemas.openxmlformats.org/wordprocessingml/2006/main}"


@pytest.fixture(scope="module")
def press(tmp_path_factory):
    out = tmp_path_factory.mktemp("note")
    note = build_note(ROOT / "examples" / "press.toml", out_dir=out)
    data = note_docx(note)
    (out / "note.docx").write_bytes(data)
    return note, out / "note.docx"


def _check_json(path: Path, capsys) -> dict:
    code = main(["check", str(path), "--json"])
    out = capsys.readouterr().out
    assert code in (0, 1), out
    return json.loads(out)


def test_the_sections_in_the_textbooks_order(press):
    _, path = press
    d = docx.Document(str(path))
    heads = [p.text for p in d.paragraphs if p.style.name.startswith("Heading")]
    order = ["Содержание", "Введение", "1 Структурный анализ механизма",
             "2 Кинематический анализ механизма", "2.1 План положений механизма",
             "2.2 Планы скоростей и ускорений", "3 Силовой анализ механизма",
             "4 Динамический анализ машинного агрегата", "Заключение",
             "Список использованных источников"]
    at = [heads.index(h) for h in order]
    assert at == sorted(at)
    # every position of the variant has its kinematics (2.2.k) and its force analysis (3.2.k)
    positions = [h for h in heads if re.match(r"\d+\.\d+\.\d+ Положение ", h)]
    assert sum(h.startswith("2.2.") for h in positions) == 10
    assert sum(h.startswith("3.2.") for h in positions) == 10


def test_frames_with_the_title_blocks_and_the_page_numbers(press):
    _, path = press
    d = docx.Document(str(path))
    assert len(d.sections) == 2  # the title page without a frame, then the text
    text = d.sections[1]
    assert text.different_first_page_header_footer
    for header in (text.first_page_header, text.header):
        anchors = header._element.findall(
            ".//{http://schemas.openxmlformats.org/drawingml/2006/wordprocessingDrawing}anchor")
        assert len(anchors) == 1 and anchors[0].get("behindDoc") == "1"
    first = "".join(t.text or "" for t in text.first_page_footer._element.iter(W + "instrText"))
    other = "".join(t.text or "" for t in text.footer._element.iter(W + "instrText"))
    assert "PAGE" in first and "NUMPAGES" in first  # form 2: Лист and Листов
    assert "PAGE" in other and "NUMPAGES" not in other  # form 2a: Лист
    # A4, the text 5 mm inside the frame (20 mm left, 5 mm right) and clear of form 2a
    assert round(text.page_width.mm) == 210 and round(text.page_height.mm) == 297
    assert round(text.left_margin.mm) == 25 and round(text.right_margin.mm) == 10
    assert text.bottom_margin.mm > 15 + 5


def test_formulas_numbered_within_their_section(press):
    _, path = press
    d = docx.Document(str(path))
    section, seen = 0, 0
    numbered = 0
    for p in d.paragraphs:
        if p.style.name == "Heading 1" and re.match(r"\d+ ", p.text):
            section, seen = int(p.text.split()[0]), 0
        if p.style.name in (FORMULA_STYLE, "GP Calculation"):
            m = re.search(r"\t\((\d+)\.(\d+)\)$", p.text)
            assert m, p.text
            seen += 1
            assert (int(m.group(1)), int(m.group(2))) == (section, seen), p.text
            numbered += 1
    assert numbered > 150


def test_tables_and_figures_captioned_and_numbered(press):
    _, path = press
    d = docx.Document(str(path))
    tables = [p.text for p in d.paragraphs if p.text.startswith("Таблица ")]
    figures = [p.text for p in d.paragraphs if p.text.startswith("Рисунок ")]
    assert [int(t.split()[1]) for t in tables] == list(range(1, len(tables) + 1))
    assert [int(f.split()[1]) for f in figures] == list(range(1, len(figures) + 1))
    assert len(d.tables) >= len(tables) >= 30
    pictures = d.inline_shapes
    assert len(pictures) == len(figures) >= 6  # positions, v and a plans, diagrams, sheet 2, 3
    assert all(s.width.mm <= 170.5 for s in pictures)


def test_the_lines_are_the_projects_own_calculation(press):
    note, _ = press
    key = generate(ROOT / "examples" / "press.toml")
    expected = [ln.text() for ln in key.general] + [
        ln.text() for p in key.positions for ln in p.lines]
    written = [b.text for b in note.blocks if isinstance(b, Formula) and b.checkable]
    assert sorted(written) == sorted(expected)
    # the dynamics of sheet 3 with its decimal comma: the flywheel's J and the motor's power
    from graphplan.dynamics import machine_unit
    from graphplan.model import load
    from graphplan.numbers import fmt
    from graphplan.project import analyze

    unit = machine_unit(analyze(load(ROOT / "examples" / "press.toml")))
    shown = " ".join(b.text for b in note.blocks if isinstance(b, Formula))
    assert fmt(unit.flywheel.J_I, 6).replace(".", ",") in shown
    assert fmt(unit.power_W, 6).replace(".", ",") in shown


def test_the_checker_reads_the_note_back_with_no_finding(press, capsys):
    _, path = press
    report = _check_json(path, capsys)
    s = report["summary"]
    assert s["findings"] == 0 and s["wrong"] == 0 and s["lines_unread"] == 0
    key = generate(ROOT / "examples" / "press.toml")
    # every line of the calculation was read: as many as the answer key writes
    assert s["lines"] == len(key.general) + sum(len(p.lines) for p in key.positions)


def _edit(path: Path, out: Path, old: str, new: str) -> None:
    src = zipfile.ZipFile(path)
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as dst:
        for info in src.infolist():
            data = src.read(info.filename)
            if info.filename == "word/document.xml":
                text = data.decode("utf-8")
                assert text.count(old) == 1, old
                data = text.replace(old, new).encode("utf-8")
            dst.writestr(info, data)
    out.write_bytes(buf.getvalue())


def test_a_slip_planted_in_the_note_is_found(press, capsys, tmp_path):
    note, path = press
    # position (2)'s Mур: R21 read off its force plan (141,31 mm at Kp = 3000 Н/мм = 423930 Н),
    # 423930∙37,39∙0,001 = 15850,7 ≈ 15851 Нм; the student writes its digits 8 and 5 swapped
    line = next(b.text for b in note.blocks if isinstance(b, Formula)
                and b.text.startswith("Мур = R21∙h21∙Кl = ") and "∙37,39∙" in b.text)
    result = re.search(r"= (\d+) Нм$", line)
    assert result is not None, line
    right = result.group(1)
    wrong = right[0] + right[2] + right[1] + right[3:]
    assert wrong != right and abs(int(wrong) - int(right)) > 0.01 * int(right)
    slipped = line[:result.start(1)] + wrong + line[result.end(1):]
    _edit(path, path.parent / "slip.docx", line, slipped)
    (tmp_path / "slip.docx").write_bytes((path.parent / "slip.docx").read_bytes())
    report = _check_json(path.parent / "slip.docx", capsys)
    assert report["summary"]["findings"] >= 1
    hit = [f for f in report["findings"] if wrong in f.get("line", "") or
           f.get("stated") == int(wrong)]
    assert hit, report["findings"]


@pytest.mark.parametrize("example", EXAMPLES)
def test_every_examples_note_is_read_back_clean(example, tmp_path, capsys):
    note = build_note(ROOT / "examples" / f"{example}.toml", out_dir=tmp_path, figures=False)
    (tmp_path / "note.docx").write_bytes(note_docx(note))
    s = _check_json(tmp_path / "note.docx", capsys)["summary"]
    assert s["findings"] == 0 and s["wrong"] == 0 and s["lines_unread"] == 0, s
    assert s["lines"] == len(note.formulas) - sum(not f.checkable for f in note.formulas)


def test_the_note_is_the_same_bytes_every_time(tmp_path):
    a = note_docx(build_note(ROOT / "examples" / "fourbar.toml", out_dir=tmp_path,
                             figures=False))
    b = note_docx(build_note(ROOT / "examples" / "fourbar.toml", out_dir=tmp_path,
                             figures=False))
    assert a == b


def test_an_english_note(tmp_path):
    note = build_note(ROOT / "examples" / "fourbar.toml", lang="en", out_dir=tmp_path,
                      figures=False)
    d = docx.Document(io.BytesIO(note_docx(note)))
    heads = [p.text for p in d.paragraphs if p.style.name.startswith("Heading")]
    assert "1 Structural analysis of the mechanism" in heads
    # symbols keep their letters (Mс, Pи); no Russian word is left in an English heading
    assert not [h for h in heads if re.search("[а-яА-ЯёЁ]{2,}", h)]


def test_the_command_writes_the_note_and_refuses_a_pdf_without_libreoffice(
        tmp_path, monkeypatch, capsys):
    out = tmp_path / "out"
    monkeypatch.setenv("GRAPHPLAN_SOFFICE", str(tmp_path / "no-office"))
    assert main(["note", str(ROOT / "examples" / "fourbar.toml"), "-o", str(out),
                 "--pdf"]) == 2
    assert "LibreOffice" in capsys.readouterr().err
    assert not out.exists()  # checked before any work: nothing written


@pytest.mark.skipif(find_office() is None, reason="LibreOffice is not installed: the note "
                    "is not rendered (install libreoffice-writer to render it)")
def test_the_note_renders_in_libreoffice(press):
    from pypdf import PdfReader

    from graphplan.note import note_pdf

    _, path = press
    pdf = PdfReader(io.BytesIO(note_pdf(path.read_bytes())))
    assert len(pdf.pages) > 20
    box = pdf.pages[1].mediabox
    assert round(float(box.width) * 25.4 / 72) == 210
    assert round(float(box.height) * 25.4 / 72) == 297
    text = pdf.pages[1].extract_text()
    assert "Содержание" in text


def _number(text: str) -> float:
    return float(text.replace(" ", "").replace(",", "."))


def test_every_figure_of_the_json_report_stands_in_the_note_with_its_value(press):
    """Per position: the speeds and accelerations of the points, the reactions and Mур of
    analysis.json are the results the note writes (to the note's written digits: 5
    significant figures; readings at 0,01 mm where a figure is read off a plan)."""
    from graphplan.model import load
    from graphplan.project import analyze

    note, _ = press
    report = analyze(load(ROOT / "examples" / "press.toml")).to_json()
    results: dict[tuple[str, str], float] = {}
    label = None
    for b in note.blocks:
        if isinstance(b, Heading) and b.position is not None:
            label = b.position
        if isinstance(b, Formula) and b.checkable and label is not None:
            name = b.text.split("=", 1)[0].strip()
            m = re.search(r"=\s*(-?[\d ]+(?:,\d+)?)\s*\S*$", b.text)
            if m:
                results[(label, name)] = _number(m.group(1))
    compared = 0
    for pos in report["positions"]:
        lab = pos["label"]
        pairs = [(f"v{p}", float(np.hypot(*v))) for p, v in pos["velocities"].items()]
        pairs += [(f"a{p}", float(np.hypot(*a))) for p, a in pos["accelerations"].items()]
        pairs += [(n, r["magnitude"]) for n, r in pos["forces"]["reactions"].items()]
        pairs.append(("Мур", pos["forces"]["M_bal"]))
        for name, exact in pairs:
            if (lab, name) not in results:
                continue
            written = results[(lab, name)]
            big = max(abs(exact), 1.0 if name[0] in "va" else 50.0)
            # read off a plan at 0,01 mm on a 50–120 mm vector: within 0,05 % of the largest
            assert abs(written - exact) <= 5e-4 * big + 5e-4 * abs(exact), (lab, name)
            compared += 1
    assert compared >= 60  # v and a of every point, R12, R23, R43 and Мур of every position
