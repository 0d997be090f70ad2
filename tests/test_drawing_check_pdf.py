"""Checking graphplan's own sheets as a vector PDF (issue 22): the PDF that
``graphplan sheets --format pdf`` writes (Typst: every glyph placed on its own, words
without a space character, subscripts smaller and lower, a slanted font) reads as its SVG
does — the same texts, the same plans, the same verdicts — and errors typed into the
sheet before it is made a PDF are found in it."""

from __future__ import annotations

import html
import math
import re
from collections import Counter
from pathlib import Path

import pytest

pytest.importorskip("pypdf")
pytest.importorskip("typst")

from graphplan.checking.drawing.check import check_drawing
from graphplan.checking.drawing.read import read_drawing

ROOT = Path(__file__).resolve().parents[1]
EX = ROOT / "examples"
EXAMPLES = sorted(p.stem for p in EX.glob("*.toml"))

#: A PDF that still reads otherwise than its SVG, with its named cause (none since session
#: 10: the loads drawn on «Механизм с нагрузками» are not a force plan — PDF and SVG found
#: a different number of such false plans —, and Rn12 is judged by its own direction)
PDF_SVG_TODO: dict[str, str] = {}
#: An error planted in the PDF that is not found, with its named cause (none)
PLANTED_PDF_TODO: dict[str, str] = {}


@pytest.fixture(scope="module")
def own(tmp_path_factory):
    """Sheets 1 and 2 of an example as graphplan writes them, SVG and PDF."""
    from graphplan.checking.checks import reference_for
    from graphplan.drawing import kinematics_sheet, kinetostatics_sheet
    from graphplan.render import sheet_files

    out = tmp_path_factory.mktemp("own")

    def make(ex: str) -> Path:
        folder = out / ex
        if not folder.is_dir():
            folder.mkdir()
            ref = reference_for(EX / f"{ex}.toml")
            files = sheet_files({"sheet1": kinematics_sheet(ref.analysis, lang="ru"),
                                 "sheet2": kinetostatics_sheet(ref.analysis, lang="ru")},
                                ("svg", "pdf"))
            for name, content in files.items():
                data = content.encode("utf-8") if isinstance(content, str) else content
                (folder / name).write_bytes(data)
        return folder

    return make


def _verdicts(rep) -> Counter:
    return Counter((f.position, f.quantity, f.verdict, f.kind) for f in rep.findings)


def test_typst_pdf_texts_are_the_svgs(own):
    """Every text of sheet 2 (``R`` + subscript ``12`` shown as three glyphs, ``Rτ12`` in
    two fonts, «Кривошипный пресс.» with no space character) is read whole, as the SVG
    reader reads it; every text set by its middle (the plans' letters) at its place
    (mm, y up) to 0.3 mm and of its height to 0.05 mm (where a text starts or ends, the
    SVG reader guesses its width)."""
    folder = own("press")
    a = read_drawing(folder / "sheet2.pdf")
    svg = (folder / "sheet2.svg").read_text(encoding="utf-8")
    b = read_drawing(folder / "sheet2.svg")
    assert sorted(t.text for t in a.texts) == sorted(t.text for t in b.texts)
    assert {"Rτ12", "Rn12, R12, R23", "Кривошипный пресс.", "G3, Pи3"} <= {
        t.text for t in a.texts}
    middle = [t for (m, _text), t in zip(_svg_texts(svg), b.texts, strict=True)
              if 'text-anchor="middle"' in m[1] and t.angle == 0]
    assert len(middle) > 100
    for u in middle:
        near = min((t for t in a.texts if t.text == u.text),
                   key=lambda t: math.hypot(t.x - u.x, t.y - u.y))
        assert math.hypot(near.x - u.x, near.y - u.y) < 0.3, u.text
        assert abs(near.height - u.height) < 0.05, u.text


@pytest.mark.parametrize("ex", [pytest.param(e, marks=pytest.mark.xfail(
    strict=True, reason=PDF_SVG_TODO[e])) if e in PDF_SVG_TODO else e for e in EXAMPLES])
def test_graphplans_own_pdf_checks_as_its_svg(own, ex):
    """Sheets 1 and 2 of every example as PDF: the same plans found and every finding the
    same as the SVG's (so no false alarm where the SVG has none); sheet 2's force plans
    found with their Kp. Before this reader the sheet-2 PDF gave no force plan at all.
    Measured: PDF = SVG on both sheets of eleven examples; on the crusher's sheet 2 the
    PDF reads G5 right where the SVG (and DXF) misread it."""
    folder = own(ex)
    v = EX / f"{ex}.toml"
    for sheet in ("sheet1", "sheet2"):
        svg = check_drawing(folder / f"{sheet}.svg", v, lang="en")
        pdf = check_drawing(folder / f"{sheet}.pdf", v, lang="en")
        assert Counter((j.found.kind, j.position) for j in pdf.plans) == Counter(
            (j.found.kind, j.position) for j in svg.plans), sheet
        a, b = _verdicts(pdf.report), _verdicts(svg.report)
        if svg.report.ok:
            assert a == b, (sheet, a - b, b - a)
        else:
            # where the SVG's reading of a crowded plan errs (FORCE_TODO of
            # test_drawing_check), the PDF's glyph-exact places may tip it right: no
            # wrong finding the SVG has not, and as many figures right
            wrong = Counter(k for k in b.elements() if k[2] == "wrong")
            assert not Counter(k for k in a.elements() if k[2] == "wrong") - wrong, sheet
            ok = [sum(f.verdict == "ok" for f in r.report.figures) for r in (pdf, svg)]
            assert ok[0] >= ok[1], sheet
        if sheet == "sheet2":
            assert [j for j in pdf.plans if j.found.kind == "force" and j.scale]
            assert any(f.quantity == "h21" and f.verdict == "ok" for f in pdf.report.figures)
        else:
            assert sum(j.found.kind in ("velocity", "acceleration") for j in pdf.plans) >= 6


_TEXT = re.compile(r"(<text\b[^>]*>)(.*?)(</text>)", re.S)


def _svg_texts(svg: str):
    """The ``<text>`` elements of a sheet's SVG in order, each as (match, its text)."""
    out = []
    for m in _TEXT.finditer(svg):
        text = " ".join(html.unescape(re.sub(r"<[^>]+>", "", m[2])).split())
        if text:
            out.append((m, text))
    return out


def _placed(svg: str, path: Path):
    """Each text element of the SVG with where the SVG reader puts it (mm, y up)."""
    path.write_text(svg, encoding="utf-8")
    read = read_drawing(path).texts
    els = _svg_texts(svg)
    assert [t for _m, t in els] == [t.text for t in read]
    return [(m, t, (r.x, r.y)) for (m, t), r in zip(els, read, strict=True)]


def _edit(svg: str, edits: dict) -> str:
    """The SVG with some text elements' content replaced: {match: new inner XML}."""
    out, last = [], 0
    for m in sorted(edits, key=lambda m: m.start()):
        out += [svg[last:m.start(2)], edits[m]]
        last = m.end(2)
    return "".join(out) + svg[last:]


def _scaled(m, key: str, factor: float = 2.0) -> str:
    """The element's content with the number after ``key = `` times ``factor``."""
    sub = r"(?:</tspan><tspan[^>]*>)?"  # the scale's subscript, a tspan of its own
    num = re.search(rf"({key[0]}{sub}{key[1:]}{sub} = )([\d,.]+)", m[2])
    assert num, m[2]
    x = float(num[2].replace(",", ".")) * factor
    return m[2].replace(num[0], num[1] + f"{x:g}".replace(".", ","), 1)


def _last_number(text: str) -> float:
    """The last number written after an equals sign: the value of a scale."""
    return float(re.findall(r"= ([\d,.]+)", text)[-1].replace(",", "."))


def _pdf(svg: str, path: Path) -> Path:
    from graphplan.render import svg_to_pdf_bytes

    path.write_bytes(svg_to_pdf_bytes(svg))
    return path


def _near(placed, text: str, xy):
    return min((p for p in placed if p[1] == text),
               key=lambda p: math.hypot(p[2][0] - xy[0], p[2][1] - xy[1]))


@pytest.mark.parametrize("ex", [pytest.param(e, marks=pytest.mark.xfail(
    strict=True, reason=PLANTED_PDF_TODO[e])) if e in PLANTED_PDF_TODO else e for e in EXAMPLES])
def test_errors_planted_in_graphplans_own_pdf(own, ex, tmp_path):
    """Errors typed into the sheets before they are made PDFs, each found in the PDF
    where it was planted: on sheet 2, each force plan's Kp written twice the scale it is
    drawn at (its forces wrong), two names of one plan swapped at their lines, and the
    crank scheme's Kl doubled (h21 wrong); on sheet 1, Ka written twice (every
    acceleration plan at another scale) and two velocity plans' captions swapped (each
    the plan of another position)."""
    folder = own(ex)
    v = EX / f"{ex}.toml"
    found, missed = 0, []

    def hit(ok: bool, what: str) -> None:
        nonlocal found
        found += ok
        if not ok:
            missed.append(what)

    # sheet 2
    svg = (folder / "sheet2.svg").read_text(encoding="utf-8")
    placed = _placed(svg, tmp_path / "s2.svg")
    clean = check_drawing(folder / "sheet2.pdf", v, lang="en")
    plans = [j for j in clean.plans if j.found.kind == "force" and j.scale]
    # every plan's Kp doubled in one sheet (the plans are checked each on its own)
    kp = {_near(placed, j.found.caption.text, (j.found.caption.x, j.found.caption.y))[0]
          for j in plans}
    rep = check_drawing(_pdf(_edit(svg, {m: _scaled(m, "Kp") for m in kp}),
                             tmp_path / "kp.pdf"), v, lang="en").report
    for j in plans:
        hit(any(f.verdict == "wrong" and j.found.where in f.where and
                f.quantity.endswith("_mm") for f in rep.findings), f"Kp of {j.found.where}")
    crank = {p[0]: _scaled(p[0], "Kl") for p in placed
             if p[1].startswith("Схема звена 1") and "Kl = " in p[1]}
    assert crank
    rep = check_drawing(_pdf(_edit(svg, crank), tmp_path / "kl.pdf"), v, lang="en").report
    hit(any(f.verdict == "wrong" and f.quantity == "h21" for f in rep.findings), "Kl")
    # two names swapped: forces of lengths ≥ 30 % and 3 mm apart, each name nearer its
    # own line than the other's and one of them by 2 mm or more (as in test_drawing_check:
    # a name the sheet sets off a cluster, nearer a neighbour's line, swapped would stand
    # by its own line again — the drawing then reads right, no error to find)
    from graphplan.checking.drawing.primitives import Segment
    from graphplan.checking.drawing.scene import point_segment

    def text_of(name: str, f):
        """The text that is the name alone nearest its line (None: the name is written
        in a text with others, ``Rn63, R63``)."""
        mid = ((f.start[0] + f.end[0]) / 2, (f.start[1] + f.end[1]) / 2)
        return _near(placed, name, mid) if any(p[1] == name for p in placed) else None

    def nearer(a: str, fa, fb, by: float = 0.0) -> bool:
        """Whether a's name stands nearer its own line than fb's, by ``by`` mm."""
        p = text_of(a, fa)
        return p is not None and point_segment(*p[2], Segment(*fa.start, *fa.end)) + by < \
            point_segment(*p[2], Segment(*fb.start, *fb.end))

    swapped = None
    for j in plans:
        single = {n: f for n, f in j.found.forces.items()
                  if sum(g.segments == f.segments for g in j.found.forces.values()) == 1}
        for a in sorted(single):
            for b in sorted(single):
                fa, fb = single[a], single[b]
                la, lb = fa.length, fb.length
                if a < b and abs(la - lb) >= max(3.0, 0.3 * max(la, lb)) and \
                        nearer(a, fa, fb) and nearer(b, fb, fa) and \
                        (nearer(a, fa, fb, 2.0) or nearer(b, fb, fa, 2.0)):
                    swapped = swapped or (j, a, b)
    assert swapped is not None
    j, a, b = swapped
    ms = [text_of(name, j.found.forces[name])[0] for name in (a, b)]
    rep = check_drawing(_pdf(_edit(svg, {ms[0]: ms[1][2], ms[1]: ms[0][2]}),
                             tmp_path / "swap.pdf"), v, lang="en").report
    hit(any(f.verdict == "wrong" and f.quantity in (f"{a}_mm", f"{b}_mm", f"∠{a}", f"∠{b}")
            for f in rep.findings), f"{a} ⇄ {b}")
    # sheet 1
    svg = (folder / "sheet1.svg").read_text(encoding="utf-8")
    placed = _placed(svg, tmp_path / "s1.svg")
    # "Ka = aA/πa = 445,37/89,073 = 5 (м/с²)/мм" → "Ka = 10 (м/с²)/мм", as a student
    # writes a scale without its arithmetic
    ka = {p[0]: f"Ka = {2 * _last_number(p[1]):g} (м/с²)/мм".replace(".", ",")
          for p in placed if p[1].startswith("Ka = ")}
    caps = {}
    for p in placed:
        c = re.fullmatch(r"План скоростей, пол\. (\S+)", p[1])
        if c:
            caps.setdefault(c[1], p[0])
    assert ka and len(caps) >= 2
    # two plans far apart in the cycle (neighbouring positions may read alike)
    items = list(caps.items())
    (l1, m1), (l2, m2) = items[0], items[len(items) // 2]
    edits = dict(ka)
    edits[m1], edits[m2] = m2[2], m1[2]
    rep = check_drawing(_pdf(_edit(svg, edits), tmp_path / "s1.pdf"), v, lang="en").report
    primary = [f for f in rep.wrong if f.primary]
    accel = {f.position for f in primary if f.kind == "scale" and "acceleration plan" in f.where}
    other = {f.position for f in primary if f.kind == "other-variant" and
             "velocity plan" in f.where}  # the plan of positions is read from PDF too
    hit(bool(accel), "Ka")
    hit(other == {l1, l2}, f"captions {l1} ⇄ {l2}")
    total = len(plans) + 4
    # the issue asks recall ≥ 0.95 over all: measured 106 of 106 over the twelve examples
    # (the crusher's swapped captions, missed last session, are found since)
    assert found == total, missed
