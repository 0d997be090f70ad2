"""Checking a drawing (issue 22): graphplan's own sheets, drawings made as students make
them (ezdxf like a CAD user, matplotlib's PDF), planted errors, hostile files, the CLI."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

pytest.importorskip("ezdxf")
pytest.importorskip("pypdf")

from graphplan.checking.drawing.check import check_drawing
from graphplan.checking.drawing.primitives import DrawingError
from graphplan.checking.drawing.read import read_drawing
from graphplan.checking.drawing.sample import Plant, student_sheet
from graphplan.cli import main

ROOT = Path(__file__).resolve().parents[1]
EX = ROOT / "examples"


EXAMPLES = sorted(p.stem for p in EX.glob("*.toml"))


@pytest.fixture(scope="module")
def sheets(tmp_path_factory):
    """graphplan's own sheet 1 of an example as DXF and SVG, drawn by the current code
    (the sheets' layout and scales change: nothing here depends on where plans are)."""
    from graphplan.checking.checks import reference_for
    from graphplan.drawing import kinematics_sheet
    from graphplan.render import sheet_files

    out = tmp_path_factory.mktemp("sheets")

    class Sheets:
        def __truediv__(self, ex: str) -> Path:
            folder = out / ex
            if not folder.is_dir():
                folder.mkdir()
                ref = reference_for(EX / f"{ex}.toml")
                files = sheet_files({"sheet1": kinematics_sheet(ref.analysis, lang="ru")},
                                    ("svg", "dxf"))
                for name, content in files.items():
                    if isinstance(content, str):
                        (folder / name).write_text(content, encoding="utf-8")
                    else:
                        (folder / name).write_bytes(content)
            return folder

    return Sheets()


def _wrong(rep):
    return [(f.where, f.quantity, f.kind) for f in rep.wrong]


# Letters set farther out on leaders and a pole's letter group set below the pole are
# read (test_letters_on_leaders); what is left is a letter the sheet itself sets nearer
# another point than its own (written to sheet 1's owner in /work/coord/DEFECTS.md):
OWN_SHEET_TODO: dict[str, str] = {}


@pytest.mark.parametrize("fmt", ["dxf", "svg"])
@pytest.mark.parametrize("ex", EXAMPLES)
def test_graphplans_own_sheet_is_right(request, sheets, ex, fmt):
    """Sheet 1 of every example — crowded plans (the six-bar press, both shapers: letters
    "b, s3" at one point, short components beside the pole) included: no false alarm,
    every plan found under its caption."""
    if ex in OWN_SHEET_TODO:
        request.applymarker(pytest.mark.xfail(strict=True, reason=OWN_SHEET_TODO[ex]))
    dc = check_drawing(sheets / ex / f"sheet1.{fmt}", EX / f"{ex}.toml", lang="en")
    rep = dc.report
    assert rep.ok, _wrong(rep)  # the plan of all positions too (test_drawing_check_positions)
    # every plan the sheet draws is found, under its caption, and measured
    import re

    kinds = {(j.found.kind, j.position) for j in dc.plans
             if j.found.kind in ("velocity", "acceleration")}
    drawn = set()
    for t in dc.drawing.texts:
        # "пол. 2, 14": a velocity plan of the first turn that the second turn's twin shares
        m = re.fullmatch(r"План (скоростей|ускорений), пол\. ([^,\s]+)(?:, \S+)*", t.text)
        if m:
            drawn.add(({"скоростей": "velocity", "ускорений": "acceleration"}[m[1]], m[2]))
    assert len(drawn) >= 6 and kinds == drawn
    assert len(rep.figures) > 4 * len(drawn)
    assert all(f.verdict != "wrong" for f in rep.figures)


def test_dxf_and_svg_read_alike(sheets):
    a = read_drawing(sheets / "press" / "sheet1.dxf")
    b = read_drawing(sheets / "press" / "sheet1.svg")
    ta = sorted((t.text, t.x, t.y) for t in a.texts)
    tb = sorted((t.text, t.x, t.y) for t in b.texts)
    assert [t[0] for t in ta] == [t[0] for t in tb]
    # the same texts at the same places (mm, y up), to 1 mm
    for text, x, y in (t for t in ta if len(t[0]) <= 8):  # letters (a long text's width is a guess)
        assert any(t == text and abs(x - u) < 1 and abs(y - v) < 1 for t, u, v in tb), text


def test_planted_in_graphplans_export(sheets, tmp_path):
    """graphplan's DXF with the student's errors typed into it: Ka written twice the
    scale the plans are drawn at (every acceleration plan at another scale), two captions
    swapped (the plans of positions 2 and 3 under each other's numbers)."""
    import ezdxf

    doc = ezdxf.readfile(sheets / "press" / "sheet1.dxf")
    accel = set()
    for t in doc.modelspace().query("TEXT"):
        text = t.dxf.text
        if text.startswith("Ka = "):
            ka = float(text.split("=")[-1].split()[0].replace(",", "."))
            t.dxf.text = f"Ka = {2 * ka:g} (м/с²)/мм"
        elif text == "План скоростей, пол. 2":
            t.dxf.text = "План скоростей, пол. 3"
        elif text == "План скоростей, пол. 3":
            t.dxf.text = "План скоростей, пол. 2"
        elif text.startswith("План ускорений, пол. "):
            accel.add(text.rsplit(" ", 1)[1])
    doc.saveas(tmp_path / "planted.dxf")
    rep = check_drawing(tmp_path / "planted.dxf", EX / "press.toml", lang="en").report
    primary = [f for f in rep.wrong if f.primary]
    scale = {f.position for f in primary if f.kind == "scale" and
             "acceleration plan" in f.where}
    assert accel and scale == accel
    other = {f.position for f in primary if f.kind == "other-variant"}
    assert other == {"2", "3"}


@pytest.mark.parametrize("fmt", ["dxf", "pdf"])
@pytest.mark.parametrize("ex", EXAMPLES)
def test_students_drawing_of_every_example_is_right(tmp_path, ex, fmt):
    """Two positions of every example drawn as a CAD user draws and as a vector PDF: no
    false alarm, every plan found under its caption."""
    v = EX / f"{ex}.toml"
    labels = _two_positions(v)
    dc = check_drawing(student_sheet(v, tmp_path / f"s.{fmt}", labels, fmt=fmt), v,
                       lang="en")
    assert dc.report.ok, _wrong(dc.report)
    assert {(j.found.kind, j.position) for j in dc.plans} == {
        (k, lab) for k in ("velocity", "acceleration") for lab in labels}


@pytest.mark.parametrize("fmt,inches", [("dxf", False), ("dxf", True), ("pdf", False)])
def test_students_drawing_is_right(tmp_path, fmt, inches):
    """Drawn as a CAD user draws (pieces, polylines, arrowheads as blocks, MTEXT, far
    from the origin, in inches) and as a vector PDF: nothing wrong."""
    f = student_sheet(EX / "press.toml", tmp_path / f"s.{fmt}", ["2", "(2)", "(3)"], fmt=fmt,
                      inches=inches)
    dc = check_drawing(f, EX / "press.toml", lang="en")
    assert dc.report.ok, _wrong(dc.report)
    assert {(j.found.kind, j.position) for j in dc.plans} == {
        (k, lab) for k in ("velocity", "acceleration") for lab in ("2", "(2)", "(3)")}


@pytest.mark.parametrize("ex", EXAMPLES)
def test_letters_on_leaders(tmp_path, ex):
    """Every letter set 8–18 mm out from its point on a thin leader that stops 1.5 mm short
    of it (nearer other points' lines and leaders than its own point), the pole's letter
    group set under the pole below two direction lines drawn through it: every plan read
    with no false alarm, and a point moved by 3.2 mm still found wrong — the letter names
    the point its leader points at."""
    v = EX / f"{ex}.toml"
    labels = _two_positions(v)
    dc = check_drawing(student_sheet(v, tmp_path / "s.dxf", labels, leaders=8.0), v,
                       lang="en")
    assert dc.report.ok, _wrong(dc.report)
    assert {(j.found.kind, j.position) for j in dc.plans} == {
        (k, lab) for k in ("velocity", "acceleration") for lab in labels}
    for p in (p for p in _plants(v, labels) if p.kind == "moved"):
        f = student_sheet(v, tmp_path / "m.dxf", labels, leaders=8.0, plant=p)
        assert _detected(check_drawing(f, v, lang="en").report, p), p


def _plants(variant, labels):
    import numpy as np

    from graphplan.checking.checks import reference_for
    from graphplan.checking.drawing.measure import construction
    ref = reference_for(variant)
    sc1 = ref.analysis.sheet1
    kl, kv, ka = sc1.kl, sc1.kv, sc1.ka
    sc = {"Kl": kl.per_mm, "Kv": kv.per_mm, "Ka": ka.per_mm}
    out = []
    for lab in labels:
        k = ref.index(lab)
        for kind in ("velocity", "acceleration"):
            plan = construction(ref, kind, k, sc)
            pole = "p" if kind == "velocity" else "π"
            pts = [p for p in plan.points if p != pole and np.hypot(*plan.points[p]) > 5
                   and not p.startswith(("n_", "k_"))]
            if pts:
                out.append(Plant("moved", kind, lab, point=pts[-1]))
            out.append(Plant("scale", kind, lab, factor=2.0))
            others = [x for x in ref.labels if x != lab]
            out.append(Plant("position", kind, lab,
                             other=others[(ref.labels.index(lab) + 2) % len(others)]))
            if kind == "acceleration":
                for e in (e for st in plan.steps for e in st.elements):
                    if e.kind == "segment" and e.role == "normal" and \
                            np.hypot(*np.subtract(e.end, e.start)) >= 2.0:
                        out.append(Plant("omit", kind, lab, point=e.name))
                        break
    return out


WANT = {"moved": None, "scale": "scale", "position": "other-variant", "omit": "missing"}


def _detected(rep, p: Plant) -> bool:
    word = f"{p.plan} plan"
    return any(f.verdict == "wrong" and f.primary and f.position == p.position and
               word in f.where and WANT[p.kind] in (None, f.kind) for f in rep.findings)


def _two_positions(v) -> list[str]:
    """The second position and one half a turn on: no example's choice by hand."""
    from graphplan.checking.checks import reference_for

    labels = list(reference_for(v).labels)
    return [labels[1], labels[len(labels) // 2]]


@pytest.mark.parametrize("ex", EXAMPLES)
def test_planted_errors_recall(tmp_path, ex):
    """Every planted error (a moved point, a wrong scale, a normal component left out, the
    plan of another position) in two positions of every example, drawn as a CAD user
    draws (DXF) and as a vector PDF (every other example): every one found with the
    checker's own causes (the issue asks recall ≥ 0.95), and no false alarm on the
    correct drawing."""
    v = EX / f"{ex}.toml"
    labels = _two_positions(v)
    fmt = "pdf" if EXAMPLES.index(ex) % 2 else "dxf"
    rep = check_drawing(student_sheet(v, tmp_path / f"{ex}.{fmt}", labels, fmt=fmt), v,
                        lang="en").report
    assert rep.ok, _wrong(rep)
    total = hit = 0
    missed = []
    for i, p in enumerate(_plants(v, labels)):
        try:
            f = student_sheet(v, tmp_path / f"{ex}-{i}.{fmt}", labels, fmt=fmt, plant=p)
        except ValueError:
            continue  # a normal component with no tangential one after it: nothing to omit
        total += 1
        if _detected(check_drawing(f, v, lang="en").report, p):
            hit += 1
        else:
            missed.append(p)
    assert total >= 12
    assert hit == total, missed  # 161 of 161 over the twelve examples (the issue asks ≥ 0.95)


def test_no_plan_is_one_line(tmp_path):
    import ezdxf

    doc = ezdxf.new()
    doc.modelspace().add_line((0, 0), (10, 0))
    doc.modelspace().add_text("a").set_placement((10, 1))
    doc.saveas(tmp_path / "empty.dxf")
    with pytest.raises(DrawingError, match=r"no plan found: no text 'p' \(velocity\)"):
        check_drawing(tmp_path / "empty.dxf", EX / "press.toml")


def test_hostile_files(tmp_path, monkeypatch):
    bomb = tmp_path / "bomb.svg"
    bomb.write_text('<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY a "aaaa">'
                    '<!ENTITY b "&a;&a;&a;">]><svg xmlns="http://www.w3.org/2000/svg">'
                    "<text>&b;</text></svg>")
    with pytest.raises(DrawingError, match="entities"):
        read_drawing(bomb)
    deep = tmp_path / "deep.svg"
    deep.write_text('<svg xmlns="http://www.w3.org/2000/svg">' + "<g>" * 40 +
                    '<line x1="0" y1="0" x2="1" y2="1" stroke="black"/>' + "</g>" * 40 +
                    "</svg>")
    with pytest.raises(DrawingError, match="nested"):
        read_drawing(deep)
    junk = tmp_path / "junk.dxf"
    junk.write_bytes(b"\x00\x01 not a dxf at all")
    with pytest.raises(DrawingError) as e:
        read_drawing(junk)
    assert "\n" not in str(e.value) and "junk.dxf" in str(e.value)
    from graphplan.checking.drawing import primitives

    monkeypatch.setattr(primitives, "MAX_ITEMS", 50)
    many = tmp_path / "many.svg"
    many.write_text('<svg xmlns="http://www.w3.org/2000/svg">' +
                    '<line x1="0" y1="0" x2="1" y2="1" stroke="black"/>' * 60 + "</svg>")
    with pytest.raises(DrawingError, match="more than 50 drawn items"):
        read_drawing(many)
    with pytest.raises(DrawingError, match="not a drawing"):
        (tmp_path / "x.txt").write_text("hello")
        read_drawing(tmp_path / "x.txt")


def test_command_line(sheets, tmp_path, capsys):
    sheet = sheets / "press" / "sheet1.dxf"
    assert main(["check", "--drawing", str(sheet), "--variant", str(EX / "press.toml"),
                 "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["summary"]["wrong"] == 0 and data["summary"]["ok"] > 50
    jsonschema = pytest.importorskip("jsonschema")
    schema = json.loads((ROOT / "graphplan" / "data" / "schema" / "check.schema.json"
                         ).read_text(encoding="utf-8"))
    jsonschema.validate(data, schema)  # the calculation checker's JSON, same keys
    out = tmp_path / "out"
    import shutil

    import ezdxf

    cls = tmp_path / "class"
    cls.mkdir()
    shutil.copy(sheet, cls / "sheet1.dxf")
    blank = ezdxf.new()
    blank.modelspace().add_line((0, 0), (10, 0))
    blank.saveas(cls / "blank.dxf")
    assert main(["check", "--drawing", str(cls), "--variant",
                 str(EX / "press.toml"), "-o", str(out)]) == 1  # blank.dxf: no plan
    text = capsys.readouterr().out
    assert "sheet1.dxf" in text and "not checked" in text
    assert (out / "sheet1" / "report.html").read_text(encoding="utf-8").count("<svg") >= 1
    # the class summary as the calculation checker's: HTML with a link to each report,
    # CSV in its columns, JSON with the rows and the class's totals
    page = (out / "summary.html").read_text(encoding="utf-8")
    assert "sheet1/report.html" in page and "blank.dxf" in page
    assert (out / "summary.csv").read_text(encoding="utf-8").startswith("file,student,group")
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    assert summary["totals"] == {"drawings": 2, "ok": 1, "faults": 0, "error": 1,
                                 "faults_by_kind": {}}
    rows = {r["file"]: r for r in summary["drawings"]}
    assert rows["sheet1.dxf"]["status"] == "ok" and rows["sheet1.dxf"]["ok"] > 50
    assert "no plan found" in rows["blank.dxf"]["error"]
    assert main(["check", "--drawing", str(sheet)]) == 2  # no --variant: one line
    assert "--variant" in capsys.readouterr().err


def test_force_plans_and_h21_of_graphplans_sheet2(tmp_path):
    """The force plans of sheet 2 are found by the names along their lines, their positions
    by the forces they fit (their captions name none), their Kp read from the captions;
    the reactions R12 (= R21, R41) and R23 of every position are measured right, and h21 of
    position 2 (on its scheme, at the scheme's Kl)."""
    assert main(["sheets", str(EX / "press.toml"), "--format", "dxf", "-o",
                 str(tmp_path)]) == 0
    rep = check_drawing(tmp_path / "sheet2.dxf", EX / "press.toml", lang="en").report
    figs = {(f.position, f.quantity): f for f in rep.figures if f.verdict != "not compared"}
    for pos in ("2", "(2)", "(3)"):
        for q in ("R12_mm", "R23_mm", "R41_mm"):
            assert figs[(pos, q)].verdict == "ok", (pos, q)
    assert figs[("2", "h21")].verdict == "ok"
    assert figs[("2", "G3_mm")].verdict == "ok" and figs[("2", "Pи3_mm")].verdict == "ok"
    assert sum(f.verdict == "ok" for f in figs.values()) >= 20


def test_student_file_names_its_drawing(tmp_path, capsys):
    """[work] drawing: the sheet is checked with the calculation, and what the student
    wrote (pb = 31,5 мм) against what they drew (graphplan's pb at the sheet's Kv)."""
    student_sheet(EX / "press.toml", tmp_path / "sheet.dxf", ["2", "(2)"])
    (tmp_path / "ivanov.toml").write_text(
        f'[work]\nvariant = "{(EX / "press.toml").as_posix()}"\ndrawing = "sheet.dxf"\n'
        'lang = "en"\n\n[[positions]]\nlabel = "2"\n'
        'figures = { pb = "31,5 мм" }\n', encoding="utf-8")
    assert main(["check", str(tmp_path / "ivanov.toml"), "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    wrong = [f for f in data["findings"] if f["verdict"] == "wrong"]
    assert [(f["quantity"], f["kind"]) for f in wrong] == [("pb", "consistency")]
    drawn = [f for f in data["figures"] if f["where"].startswith("sheet.dxf: ") and
             f["quantity"] == "pb" and f["position"] == "2"]
    assert len(drawn) == 1 and drawn[0]["verdict"] == "ok"
    assert wrong[0]["expected"] == drawn[0]["stated"]  # what is drawn
    (tmp_path / "bad.toml").write_text(
        f'[work]\nvariant = "{(EX / "press.toml").as_posix()}"\ndrawing = "nope.dxf"\n\n'
        '[[positions]]\nlabel = "2"\nfigures = { pb = 1 }\n', encoding="utf-8")
    assert main(["check", str(tmp_path / "bad.toml")]) == 2
    assert "work.drawing: drawing" in capsys.readouterr().err


# Sheet 2's own force plans that still get a false finding (none since session 9: a
# stub a fraction of a millimetre longer than its head carried on to it, a name by a line
# another name owns read at the unnamed arrow of its plan that fits it, h21 never a
# force's own arrow):
FORCE_TODO: dict[str, str] = {
    # session 10 (sheet2's relayout for whole ΣM equations + the loads' table, DEFECTS.md →
    # drawcheck): position 4's plan of group 4–5 (x 745, y 470 mm): Rτ14 read 'scale'
    "compressor": ("issue 22/18: compressor pos. 4 plan 4-5, Rτ14 read 'scale' after sheet 2's "
                   "relayout"),
}


def _sheet2(ex: str, folder: Path, fmt: str = "dxf") -> Path:
    from graphplan.checking.checks import reference_for
    from graphplan.drawing import kinetostatics_sheet
    from graphplan.render import sheet_files

    ref = reference_for(EX / f"{ex}.toml")
    content = sheet_files({"sheet2": kinetostatics_sheet(ref.analysis, lang="ru")},
                          (fmt,))[f"sheet2.{fmt}"]
    path = folder / f"sheet2.{fmt}"
    if isinstance(content, str):
        path.write_text(content, encoding="utf-8")
    else:
        path.write_bytes(content)
    return path


@pytest.mark.parametrize("fmt", ["dxf", "svg"])
@pytest.mark.parametrize("ex", EXAMPLES)
def test_force_plans_of_every_example_are_read(request, tmp_path, ex, fmt):
    """Sheet 2 of every example (drawn by the current code): its force plans are found by
    the names along their lines (short forces crowded out of their middles, names on
    leaders, a vector drawn over a shorter one), each with the Kp of its caption and the
    position its row's scheme names; no false alarm, and most forces read right.
    Measured over the twelve examples' sheet 2 (session 9): force figures ok 249 → 259
    of 268 in each of DXF, SVG and PDF (the rest forces too short to draw at the plan's
    Kp); false findings 6 / 6 / 3 (DXF / SVG / PDF, on the shaper, four-bar and crusher)
    → 0: a stub a fraction of a millimetre longer than its head carried on to it (Pи5 of
    3.6 mm read 3.0), G2, Pи2, G3 drawn over each other on one line each carried to its
    own head, a name set off a cluster by another name's line read at the unnamed arrow
    of its plan that fits it (G5 10 mm under the crusher's cluster), h21 never a force's
    arrow drawn into the pivot, the Rτ/Rn of a rod whose piston's centre is its pin."""
    from graphplan.checking.checks import reference_for

    todo = FORCE_TODO.get(ex) or FORCE_TODO.get(f"{ex}-{fmt}")
    if todo:
        request.applymarker(pytest.mark.xfail(strict=True, reason=todo))
    v = EX / f"{ex}.toml"
    ref = reference_for(v)
    dc = check_drawing(_sheet2(ex, tmp_path, fmt), v, lang="en")
    plans = [j for j in dc.plans if j.found.kind == "force" and j.scale]
    assert plans and all(j.position in ref.labels for j in plans)
    # every force plan the sheet draws is found — as many as its captions with a Kp (the
    # groups' «План сил ВВВ(2-3), Kp = …», the crank's «Кривошип, Kp = …») — and none
    # where it draws none (the loads on «Механизм с нагрузками» start at their points,
    # tail to tail; the force tables' names are in cells, not by lines)
    drawn = [t for t in dc.drawing.texts if "Kp = " in t.text]
    assert len(plans) == len(drawn), ([j.found.where for j in plans], len(drawn))
    assert all(j.scale for j in dc.plans if j.found.kind == "force"), \
        [j.found.where for j in dc.plans if j.found.kind == "force" and not j.scale]
    # h21 on the crank's scheme of every example, at its scheme's Kl and position (a
    # crank drawn large puts its caption far from the arm)
    arms = [f for f in dc.report.figures if f.quantity == "h21"]
    assert arms and all(f.verdict == "ok" and f.position in ref.labels for f in arms)
    assert dc.report.ok, _wrong(dc.report)
    figs = [f for f in dc.report.figures if f.quantity.endswith("_mm")]
    assert sum(f.verdict == "ok" for f in figs) >= 0.7 * len(figs) > 0


@pytest.mark.parametrize("ex", EXAMPLES)
def test_force_plans_planted_errors(tmp_path, ex):
    """Errors planted in sheet 2's DXF of every example, each found in its own plan:
    every force plan's Kp written twice the scale it is drawn at (its forces wrong), and
    two names of one plan swapped (forces of lengths ≥ 30 % and 3 mm apart, written at
    each other's lines: the reader may not take them back to their own lines), and the
    crank scheme's Kl written twice the drawn one (h21 wrong)."""
    import math
    import re

    import ezdxf

    v = EX / f"{ex}.toml"
    clean = _sheet2(ex, tmp_path)
    dc = check_drawing(clean, v, lang="en")
    plans = [j for j in dc.plans if j.found.kind == "force" and j.scale]
    total = hit = 0
    # 1. Kp twice the scale, each plan in turn
    for n, j in enumerate(plans):
        doc = ezdxf.readfile(clean)
        cap = j.found.caption
        same = [t for t in doc.modelspace().query("TEXT")
                if t.dxf.text == getattr(cap, "text", None) and "Kp = " in t.dxf.text]
        if not same:
            continue
        # the rows' captions read alike: the one nearest the plan's caption
        t = min(same, key=lambda t: math.hypot(t.dxf.insert[0] - cap.x,  # type: ignore
                                               t.dxf.insert[1] - cap.y))  # type: ignore
        m = re.search(r"(Kp = )([\d,.]+)", t.dxf.text)
        assert m
        t.dxf.text = t.dxf.text.replace(m[0], f"Kp = {2 * float(m[2].replace(',', '.')):g}")
        doc.saveas(tmp_path / f"kp{n}.dxf")
        total += 1
        rep = check_drawing(tmp_path / f"kp{n}.dxf", v, lang="en").report
        hit += any(f.verdict == "wrong" and j.found.where in f.where and
                   f.quantity.endswith("_mm") for f in rep.findings)
    # 2. the crank scheme's Kl written twice the drawn one: h21 wrong
    doc = ezdxf.readfile(clean)
    crank = [t for t in doc.modelspace().query("TEXT") if t.dxf.text.startswith(
        "Схема звена 1") and "Kl = " in t.dxf.text]
    assert crank
    for t in crank:
        m = re.search(r"(Kl = )([\d,.]+)", t.dxf.text)
        assert m
        t.dxf.text = t.dxf.text.replace(m[0], f"Kl = {2 * float(m[2].replace(',', '.')):g}")
    doc.saveas(tmp_path / "kl.dxf")
    total += 1
    rep = check_drawing(tmp_path / "kl.dxf", v, lang="en").report
    hit += any(f.verdict == "wrong" and f.quantity == "h21" for f in rep.findings)
    # 3. two names swapped in the first plan that has such a pair, each name nearer its own
    # line than the other's and one of them by 2 mm or more (swapped, each then stands at
    # the other's line: names the sheet sets off a cluster, nearer a neighbour's line,
    # would stand by their own again)
    from graphplan.checking.drawing.primitives import Segment
    from graphplan.checking.drawing.scene import point_segment

    def text_of(n: str, f):
        """The text that is the name alone nearest its line (None: the name is written
        in a text with others, ``Rn63, R63``)."""
        mx, my = (f.start[0] + f.end[0]) / 2, (f.start[1] + f.end[1]) / 2
        return min((t for t in dc.drawing.texts if t.text == n),
                   key=lambda t: math.hypot(t.x - mx, t.y - my), default=None)

    def gap(t, f) -> float:
        return point_segment(t.x, t.y, Segment(*f.start, *f.end))

    def nearer(a: str, fa, fb, by: float = 0.0) -> bool:
        """Whether a's name stands nearer its own line than fb's, by ``by`` mm."""
        t = text_of(a, fa)
        return t is not None and gap(t, fa) + by < gap(t, fb)

    swapped = None
    for j in plans:
        single = {n: f for n, f in j.found.forces.items()
                  if sum(g.segments == f.segments for g in j.found.forces.values()) == 1}
        for a in single:
            for b in single:
                fa, fb = single[a], single[b]
                la, lb = fa.length, fb.length
                if a < b and abs(la - lb) >= max(3.0, 0.3 * max(la, lb)) and \
                        nearer(a, fa, fb) and nearer(b, fb, fa) and \
                        (nearer(a, fa, fb, 2.0) or nearer(b, fb, fa, 2.0)):
                    swapped = swapped or (j, a, b)
    assert swapped is not None
    j, a, b = swapped
    doc = ezdxf.readfile(clean)
    names = []
    for n in (a, b):  # the name nearest its line (a load's name is on the scheme too)
        f = j.found.forces[n]
        mx, my = (f.start[0] + f.end[0]) / 2, (f.start[1] + f.end[1]) / 2
        names.append(min((t for t in doc.modelspace().query("TEXT") if t.dxf.text == n),
                         key=lambda t, mx=mx, my=my: math.hypot(t.dxf.insert[0] - mx,
                                                                t.dxf.insert[1] - my)))
    for t in names:
        t.dxf.text = b if t.dxf.text == a else a
    doc.saveas(tmp_path / "swap.dxf")
    total += 1
    rep = check_drawing(tmp_path / "swap.dxf", v, lang="en").report
    hit += any(f.verdict == "wrong" and f.quantity in (f"{a}_mm", f"{b}_mm", f"∠{a}", f"∠{b}")
               for f in rep.findings)
    assert total >= 3 and hit == total, (hit, total)


def test_overlay_shows_force_findings(tmp_path):
    """A force plan's Kp written twice the scale it is drawn at: every force of it is
    wrong, and the overlay draws graphplan's forces from the student's starts (green,
    dashed) and the student's in red, measured ≠ expected, with a close-up of the plan."""
    import re

    import ezdxf

    from graphplan.checking.drawing.overlay import drawing_overlay

    assert main(["sheets", str(EX / "press.toml"), "--format", "dxf", "-o",
                 str(tmp_path)]) == 0
    doc = ezdxf.readfile(tmp_path / "sheet2.dxf")
    done = False
    for t in doc.modelspace().query("TEXT"):
        m = re.match(r"(План сил .*Kp = )(\d+)( Н/мм)", t.dxf.text)
        if m and not done:
            t.dxf.text = f"{m[1]}{2 * int(m[2])}{m[3]}"
            done = True
    assert done
    doc.saveas(tmp_path / "planted.dxf")
    dc = check_drawing(tmp_path / "planted.dxf", EX / "press.toml", lang="en")
    bad = [x for x in dc.report.wrong if x.quantity.endswith("_mm") and "force plan" in x.where]
    assert len(bad) >= 2
    sheets = drawing_overlay(dc, "en")
    svg = "".join(sheets)
    name = bad[0].quantity[:-3]
    assert f"{name}: " in svg and " ≠ " in svg and "stroke-dasharray" in svg
    assert any("force plan" in s.split("<title>")[1] for s in sheets[1:])


def _scheme_dxf(variant, label: str, path: Path, move: str = "") -> Path:
    """The scheme of one position drawn as a CAD user draws it: joints as circles with
    capital letters beside them, links as lines from circle to circle, the caption with
    its position and Kl; ``move``: that joint drawn 3 mm off its place."""
    import itertools

    import ezdxf
    import numpy as np

    from graphplan.checking.checks import reference_for

    ref = reference_for(variant)
    kl = ref.analysis.sheet1.kl.per_mm
    k = ref.index(label)
    P = ref.kin.pos.points
    o = np.asarray(P[ref.mech.crank.pivot][k])
    origin = np.array([1200.0, 700.0])
    at = {n: origin + (np.asarray(P[n][k]) - o) / kl for n in P if not n.startswith("S")}
    if move:
        at[move] = at[move] + np.array([2.4, 1.8])
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 4  # mm
    msp = doc.modelspace()
    for n, xy in at.items():
        msp.add_circle(tuple(xy), 1.0)
        msp.add_text(n, dxfattribs={"height": 3.5}).set_placement(tuple(xy + np.array([2.0, 1.5])))
    mech = ref.mech
    for link in [mech.crank.link, *mech.links]:
        pts = [q for q in mech.points_of(link) if q in at]
        for a, b in itertools.pairwise(pts):
            A, B = at[a], at[b]
            u = (B - A) / np.hypot(*(B - A))
            msp.add_line(tuple(A + u), tuple(B - u))  # from rim to rim
    top = max(xy[1] for xy in at.values()) + 15.0
    msp.add_text(f"План положений, пол. {label}, Kl = {str(kl).replace('.', ',')} м/мм",
                 dxfattribs={"height": 5.0}).set_placement((origin[0] - 40, top))
    doc.saveas(path)
    return path


@pytest.mark.parametrize("ex", ["press", "fourbar", "shaper", "sixbar_press"])
def test_scheme_of_a_position(tmp_path, ex):
    """The plan of positions at one position: its joints against the exact position at
    the student's Kl — right as drawn, and a joint drawn 3 mm off its place found."""
    from graphplan.checking.checks import reference_for

    v = EX / f"{ex}.toml"
    ref = reference_for(v)
    label = ref.labels[2]
    dc = check_drawing(_scheme_dxf(v, label, tmp_path / "s.dxf"), v, lang="en")
    schemes = [j for j in dc.plans if j.found.kind == "scheme"]
    assert len(schemes) == 1 and schemes[0].position == label
    assert len(schemes[0].found.joints) >= 2 and schemes[0].found.links
    assert dc.report.ok, _wrong(dc.report)
    joint = next(n for n in ref.kin.pos.points if n not in ref.mech.frame_points and
                 not n.startswith("S") and n != ref.mech.crank.pin)
    dc = check_drawing(_scheme_dxf(v, label, tmp_path / "m.dxf", move=joint), v, lang="en")
    assert any(f.quantity == f"•{joint}" and f.kind == "point" and f.position == label
               for f in dc.report.wrong), _wrong(dc.report)


def test_overlay_shows_scheme_findings(tmp_path):
    """A scheme with a joint drawn 3 mm off its place: the overlay lays the exact position
    from the student's pivot (green rings, dashed links) and draws the joint's error in
    red, from where it is drawn to the exact place, with its distance; a close-up of the
    scheme. The scheme drawn right gives no red."""
    from graphplan.checking.drawing.overlay import RED, drawing_overlay

    v = EX / "fourbar.toml"
    from graphplan.checking.checks import reference_for

    label = reference_for(v).labels[2]
    dc = check_drawing(_scheme_dxf(v, label, tmp_path / "m.dxf", move="B"), v, lang="en")
    assert any(f.quantity == "•B" for f in dc.report.wrong)
    sheets = drawing_overlay(dc, "en")
    assert len(sheets) == 2 and "scheme" in sheets[1].split("<title>")[1]
    whole = sheets[0]
    assert f"stroke='{RED}'" in whole and "B: 3 mm" in whole  # √(2.4² + 1.8²) = 3
    assert "stroke-dasharray" in whole
    right = drawing_overlay(check_drawing(_scheme_dxf(v, label, tmp_path / "s.dxf"), v,
                                          lang="en"), "en")
    assert len(right) == 1 and f"stroke='{RED}'" not in right[0]
