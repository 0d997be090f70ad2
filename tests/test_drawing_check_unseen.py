"""Checking a drawing (issue 22, item 5): drawings made as nobody here makes them — a
КОМПАС-like DXF (R12: POLYLINE, TEXT of width factor 0,8 and oblique 15°, arrowheads as
INSERTs of SOLID blocks, no units header; and the same in centimetres by ``$INSUNITS``),
a matplotlib PDF turned on its page by ``/Rotate`` — and damaged or oversized files, each
one clear line; a class folder with a broken drawing goes on with the others."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

pytest.importorskip("ezdxf")

from graphplan.checking.drawing.check import check_drawing
from graphplan.checking.drawing.primitives import DrawingError
from graphplan.checking.drawing.read import read_drawing
from graphplan.checking.drawing.sample import Plant, kompas_like, student_sheet

ROOT = Path(__file__).resolve().parents[1]
EX = ROOT / "examples"
PRESS = EX / "press.toml"
LABELS = ["2", "(2)"]


def _found(dc):
    return sorted((j.found.kind, j.position) for j in dc.plans)


def _wrong(rep):
    return [(f.position, f.quantity, f.kind) for f in rep.wrong if f.primary]


@pytest.mark.parametrize("units", ["mm", "cm"])
def test_kompas_like_dxf(tmp_path, units):
    """The press's plans redrawn as КОМПАС writes a DXF: R12 with no units header (read as
    mm, said in the notes), or R2000 in cm: every plan found, nothing wrong; a point moved
    3 mm found at its place (the press's s3 is drawn at b: both named)."""
    import ezdxf

    src = student_sheet(PRESS, tmp_path / "s.dxf", LABELS)
    out = kompas_like(src, tmp_path / f"k_{units}.dxf", units)
    doc = ezdxf.readfile(out)
    kinds = {e.dxftype() for e in doc.modelspace()}
    assert kinds == {"INSERT", "LINE", "POLYLINE", "TEXT"}
    assert all(t.dxf.width == 0.8 and t.dxf.oblique == 15.0 for t in doc.modelspace()
               .query("TEXT"))
    dc = check_drawing(out, PRESS, lang="en")
    assert dc.report.ok, _wrong(dc.report)
    assert _found(dc) == sorted((k, lab) for k in ("velocity", "acceleration")
                                for lab in LABELS)
    assert any("no units" in n for n in dc.drawing.notes) == (units == "mm")
    moved = student_sheet(PRESS, tmp_path / "m.dxf", LABELS,
                          plant=Plant("moved", "velocity", "2", point="b"))
    dc = check_drawing(kompas_like(moved, tmp_path / f"km_{units}.dxf", units), PRESS,
                       lang="en")
    assert ("2", "•b", "point") in _wrong(dc.report)


@pytest.mark.parametrize("turn", [90, 180, 270])
def test_pdf_turned_on_its_page(tmp_path, turn):
    """A matplotlib PDF whose content is turned on a page of the turned size and shown
    upright by ``/Rotate`` (a landscape sheet plotted on a portrait page): read as shown —
    every text at the place of the upright PDF's to 0,01 mm — and checked alike. Without
    ``/Rotate`` applied, every text was read 90° or 180° away."""
    pypdf = pytest.importorskip("pypdf")
    pytest.importorskip("matplotlib")
    from pypdf.generic import NameObject, NumberObject

    src = student_sheet(PRESS, tmp_path / "s.pdf", LABELS, fmt="pdf")
    w = pypdf.PdfWriter(clone_from=src)
    page = w.pages[0]
    W, H = float(page.mediabox.width), float(page.mediabox.height)
    page.add_transformation(pypdf.Transformation().rotate(turn).translate(
        *{90: (H, 0), 180: (W, H), 270: (0, W)}[turn]))
    if turn != 180:
        page.mediabox.upper_right = (H, W)
    page[NameObject("/Rotate")] = NumberObject(turn)
    out = tmp_path / f"turned{turn}.pdf"
    w.write(out)
    a, b = read_drawing(src), read_drawing(out)
    assert len(a.texts) == len(b.texts) > 20
    for s, t in zip(sorted(a.texts, key=lambda t: (t.text, t.x, t.y)),
                    sorted(b.texts, key=lambda t: (t.text, t.x, t.y)), strict=True):
        assert s.text == t.text and abs(s.x - t.x) < 0.01 and abs(s.y - t.y) < 0.01
    assert a.size == pytest.approx(b.size)
    dc = check_drawing(out, PRESS, lang="en")
    assert dc.report.ok, _wrong(dc.report)
    assert _found(dc) == _found(check_drawing(src, PRESS, lang="en"))


def test_damaged_and_oversized_drawings_are_one_line(tmp_path, monkeypatch):
    """A PDF cut in half, a PDF that is only its header, a DXF whose sections are garbage,
    a PDF past the bound of drawing operations and a DXF past the bound of bytes: each one
    line naming the file (never a hang or a traceback)."""
    pytest.importorskip("pypdf")
    pytest.importorskip("matplotlib")
    from graphplan.checking.drawing import pdf, primitives

    good = student_sheet(PRESS, tmp_path / "s.pdf", LABELS, fmt="pdf")
    data = good.read_bytes()
    cases = {
        "half.pdf": data[: len(data) // 2],
        "head.pdf": b"%PDF-1.7\n%\xe2\xe3\xcf\xd3\n",
        "garbage.dxf": b"  0\nSECTION\n  2\nENTITIES\n" + b"\x00\xff garbage \x01" * 500,
    }
    for name, content in cases.items():
        (tmp_path / name).write_bytes(content)
        with pytest.raises(DrawingError) as e:
            check_drawing(tmp_path / name, PRESS)
        msg = str(e.value)
        assert "\n" not in msg and name in msg, msg
    monkeypatch.setattr(pdf, "MAX_OPERATIONS", 100)
    with pytest.raises(DrawingError, match=r"more than 100 drawing"):
        read_drawing(good)
    dxf = student_sheet(PRESS, tmp_path / "s.dxf", LABELS)
    monkeypatch.setattr(primitives, "MAX_BYTES", 1000)
    with pytest.raises(DrawingError, match=r"larger than"):
        read_drawing(dxf)


def test_a_class_folder_goes_on_past_a_broken_drawing(tmp_path, capsys):
    """A folder of three drawings, one of them a damaged PDF: the other two are checked
    (each its report with the overlay), the damaged one is a row with its one-line
    error; one drawing checked alone writes the HTML report with its overlay."""
    pytest.importorskip("matplotlib")
    from graphplan.cli import main

    cls = tmp_path / "class"
    cls.mkdir()
    student_sheet(PRESS, cls / "ivanov.dxf", LABELS)
    student_sheet(PRESS, cls / "petrov.pdf", LABELS, fmt="pdf",
                  plant=Plant("scale", "velocity", "2"))
    (cls / "sidorov.pdf").write_bytes(b"%PDF-1.7\nnot really\n")
    out = tmp_path / "out"
    assert main(["check", "--drawing", str(cls), "--variant", str(PRESS), "-o",
                 str(out)]) == 1
    capsys.readouterr()
    rows = {r["file"]: r for r in json.loads((out / "summary.json").read_text(
        encoding="utf-8"))["drawings"]}
    assert rows["ivanov.dxf"]["status"] == "ok"
    assert rows["petrov.pdf"]["status"] == "faults"
    assert rows["sidorov.pdf"]["status"] == "error" and "sidorov.pdf" in rows[
        "sidorov.pdf"]["error"]
    for name in ("ivanov", "petrov"):
        assert "<svg" in (out / name / "report.html").read_text(encoding="utf-8")
    page = tmp_path / "one.html"
    assert main(["check", "--drawing", str(cls / "petrov.pdf"), "--variant", str(PRESS),
                 "--html", str(page)]) == 1
    from graphplan.checking.drawing.overlay import RED

    text = page.read_text(encoding="utf-8")
    assert "<svg" in text and RED in text  # the plan drawn at another scale, in red


def test_pdf_with_its_text_as_outlines_is_one_clear_line(tmp_path, capsys):
    """A PDF printed from a viewer that turns text into curves (the plans drawn by
    matplotlib, its letters as glyph paths, printed to PDF by cairosvg): no letter can be
    read, and the check says so in one line naming the file and why, in English and in
    Russian — not "no plan found"; the same sheet with its text kept is checked clean."""
    pytest.importorskip("matplotlib")
    pytest.importorskip("cairosvg")
    from graphplan.cli import main

    out = student_sheet(PRESS, tmp_path / "outlines.pdf", LABELS, fmt="pdf", outlines=True)
    d = read_drawing(out)
    assert not d.texts and len(d.fills) > 100 and d.segments  # glyphs are filled shapes
    with pytest.raises(DrawingError) as e:
        check_drawing(out, PRESS)
    msg = str(e.value)
    assert "\n" not in msg and "outlines.pdf" in msg and "no letters can be read" in msg
    assert "outlines" in msg.split("outlines.pdf", 1)[1]
    assert main(["check", "--drawing", str(out), "--variant", str(PRESS), "--lang", "ru"]) != 0
    err = capsys.readouterr().err
    assert "буквы не прочитать" in err and "контурами" in err, err
    kept = student_sheet(PRESS, tmp_path / "text.pdf", LABELS, fmt="pdf")
    dc = check_drawing(kept, PRESS, lang="en")
    assert dc.report.ok and _found(dc) == sorted(
        (k, lab) for k in ("velocity", "acceleration") for lab in LABELS)


@pytest.mark.parametrize(("v", "scales"), [(PRESS, 2.0), (ROOT / "tests" / "data" / "variants" /
                                                      "loom_beater.toml", 0.5)],
                         ids=["press", "loom_beater"])
def test_plans_at_a_cad_users_own_scales(tmp_path, v, scales):
    """Sheet 1's plans redrawn by a CAD user at scales of their own (twice or half
    graphplan's Kv and Ka), the scales written with the unit as «μv = 0,02 м/(с·мм)»,
    «μa = … м/(с²·мм)»: every plan found and read at the scale written, nothing wrong;
    the same drawing with one scale written wrong is a ``scale`` finding."""
    from graphplan.checking.checks import reference_for

    ref = reference_for(v)
    labels = [ref.labels[2], ref.labels[4]]
    out = student_sheet(v, tmp_path / "own.dxf", labels, scales=scales, units="м/(с·мм)")
    texts = [t.dxf.text for t in __import__("ezdxf").readfile(out).modelspace().query("TEXT")]
    assert any("м/(с·мм)" in t for t in texts) and any("м/(с²·мм)" in t for t in texts)
    dc = check_drawing(out, v, lang="en")
    assert dc.report.ok, _wrong(dc.report)
    assert _found(dc) == sorted((k, lab) for k in ("velocity", "acceleration")
                                for lab in labels)
    for j in dc.plans:
        own = ref.sheet1.kv if j.found.kind == "velocity" else ref.sheet1.ka
        assert j.scale == pytest.approx(own.per_mm * scales, rel=1e-3), (j.found.kind, j.scale)
    bad = student_sheet(v, tmp_path / "bad.dxf", labels, scales=scales, units="м/(с·мм)",
                        plant=Plant("scale", "velocity", labels[0]))
    rep = check_drawing(bad, v, lang="en").report
    assert (labels[0], "Kv", "scale") in _wrong(rep), _wrong(rep)
