"""Checking a drawing (issue 22): the plan of positions with every position drawn at once
— graphplan's own sheet 1, the same with a student's errors typed into its DXF, and the
plan redrawn as a CAD user draws it with one planted error at a time."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

pytest.importorskip("ezdxf")

from graphplan.checking.drawing.check import check_drawing
from graphplan.checking.drawing.position_plan import revolute_joints
from graphplan.checking.drawing.sample_positions import PositionPlant, positions_sheet

ROOT = Path(__file__).resolve().parents[1]
EX = ROOT / "examples"
EXAMPLES = sorted(p.stem for p in EX.glob("*.toml"))


def _sheet1_dxf(ex: str, folder: Path) -> Path:
    from graphplan.checking.checks import reference_for
    from graphplan.drawing import kinematics_sheet
    from graphplan.render import sheet_files

    ref = reference_for(EX / f"{ex}.toml")
    content = sheet_files({"sheet1": kinematics_sheet(ref.analysis, lang="ru")},
                          ("dxf",))["sheet1.dxf"]
    path = folder / "sheet1.dxf"
    path.write_bytes(content) if isinstance(content, bytes) else path.write_text(
        content, encoding="utf-8")
    return path


@pytest.mark.parametrize("fmt", ["dxf", "svg"])
@pytest.mark.parametrize("ex", EXAMPLES)
def test_graphplans_own_plan_of_positions(tmp_path, ex, fmt):
    """graphplan's own sheet 1 of every example (DXF, SVG; the PDF: test_drawing_check_pdf
    compares it with the SVG): the plan of all positions found, every position's numbered
    pin and its joints read, and nothing off, not even inaccurate."""
    from graphplan.checking.checks import reference_for
    from graphplan.drawing import kinematics_sheet
    from graphplan.render import sheet_files

    ref = reference_for(EX / f"{ex}.toml")
    content = sheet_files({"sheet1": kinematics_sheet(ref.analysis, lang="ru")},
                          (fmt,))[f"sheet1.{fmt}"]
    path = tmp_path / f"sheet1.{fmt}"
    path.write_bytes(content) if isinstance(content, bytes) else path.write_text(
        content, encoding="utf-8")
    j = _positions(check_drawing(path, EX / f"{ex}.toml", lang="en"))
    assert set(j.found.pins) == set(ref.labels)
    assert len(j.found.joints) == len(j.found.expected) - len(j.found.pins)
    assert [f.explanation for f in j.findings if f.verdict != "ok"] == []
    # the trajectories the sheet draws (its dash-dot curves: the centres of mass'), each
    # read as the path of its own point and on it
    drawn = {p.point for p in j.found.paths}
    assert all(p.worst <= 0.25 for p in j.found.paths), [
        (p.point, p.worst) for p in j.found.paths]
    text = content.decode() if isinstance(content, bytes) else content
    traced = {n for n in re.findall(r"pp-path-([A-Za-z0-9]+)", text) if n.startswith("S") and
              _curved(j.found.exact_paths[n])}
    assert traced <= drawn, (traced, drawn)


def _curved(path) -> bool:
    """A path that bends: wider than 8 mm, a point of it over 1 mm off the line through
    its two ends farthest apart (a slider's straight path is drawn, not read as a curve)."""
    import numpy as np

    d = np.hypot(path[:, None, 0] - path[None, :, 0], path[:, None, 1] - path[None, :, 1])
    i, k = np.unravel_index(int(d.argmax()), d.shape)
    if d[i, k] < 8.0:
        return False
    u = (path[k] - path[i]) / d[i, k]
    off = np.abs((path[:, 0] - path[i, 0]) * u[1] - (path[:, 1] - path[i, 1]) * u[0])
    return bool(off.max() > 1.0)


def _positions(dc):
    found = [j for j in dc.plans if j.found.kind == "positions"]
    assert len(found) == 1, [j.found.kind for j in dc.plans]
    return found[0]


def _wrong(rep):
    return [(f.position, f.quantity, f.kind) for f in rep.wrong]


@pytest.mark.parametrize("ex", ["press", "fourbar", "engine"])
def test_planted_in_graphplans_own_plan_of_positions(tmp_path, ex):
    """graphplan's sheet 1 (DXF) with a student's errors typed into it: Kl written twice
    the one drawn (a ``scale`` finding, the positions then read at the drawn Kl: nothing
    else wrong), and every number of the main series written one position on (the
    positions numbered from another start: one ``label`` finding)."""
    import ezdxf

    from graphplan.checking.checks import reference_for
    from graphplan.checking.drawing.sample_positions import _equally_spaced

    ref = reference_for(EX / f"{ex}.toml")
    clean = _sheet1_dxf(ex, tmp_path)
    j = _positions(check_drawing(clean, EX / f"{ex}.toml", lang="en"))
    # 1. Kl twice
    doc = ezdxf.readfile(clean)
    cap = next(t for t in doc.modelspace().query("TEXT")
               if t.dxf.text.startswith("План положений"))
    m = re.search(r"= ([\d,]+) м/мм$", cap.dxf.text)
    assert m
    kl = float(m[1].replace(",", "."))
    cap.dxf.text = cap.dxf.text.replace(m[0], f"= {2 * kl:g} м/мм".replace(".", ","))
    doc.saveas(tmp_path / "kl.dxf")
    rep = check_drawing(tmp_path / "kl.dxf", EX / f"{ex}.toml", lang="en").report
    assert [(f.quantity, f.kind) for f in rep.wrong if "plan of positions" in f.where] == [
        ("Kl", "scale")], _wrong(rep)
    # 2. numbered from another start: the text of each number of the series at the pin
    # of the position before it now names the next one
    doc = ezdxf.readfile(clean)
    series = [ref.labels[k] for k in _equally_spaced(
        [float(p) for p in ref.kin.phi], ref.mech.crank.sense, ref.analysis.cycle.period)]
    nxt = dict(zip(series, series[1:] + series[:1], strict=True))
    pins = j.found.pins
    changed = 0
    for t in doc.modelspace().query("TEXT"):
        labs = t.dxf.text.split(", ")  # "0, 12": the twins of a 720° cycle at one pin
        if all(lab in nxt and lab in pins for lab in labs):
            x, y = t.dxf.insert[0], t.dxf.insert[1]
            if math.hypot(x - pins[labs[0]][0], y - pins[labs[0]][1]) < 40:
                t.dxf.text = ", ".join(nxt[lab] for lab in labs)
                changed += len(labs)
    assert changed >= len(series) - 1
    doc.saveas(tmp_path / "num.dxf")
    rep = check_drawing(tmp_path / "num.dxf", EX / f"{ex}.toml", lang="en").report
    kinds = [f.kind for f in rep.wrong if "plan of positions" in f.where and f.primary]
    assert kinds.count("label") == 1, _wrong(rep)


def _plants(v) -> list[PositionPlant]:
    """A joint moved 3 mm (the last revolute joint, at the second position and one half a
    turn on), Kl written twice the drawn, the positions numbered from another start, each
    extreme position drawn with the crank turned on by 8° (and at least 3,2 mm at the
    pin), the first extreme position left out, and each centre of mass' trajectory that
    curves drawn 3 mm off its path (a slider's straight one is its guide)."""
    from graphplan.checking.checks import reference_for

    ref = reference_for(v)
    labels = list(ref.labels)
    r = ref.mech.crank.length / ref.analysis.sheet1.kl.per_mm
    dead = [d % (2 * math.pi) for d in ref.analysis.cycle.dead_centres]
    out = [PositionPlant("scale"), PositionPlant("numbering")]
    out += [PositionPlant("extreme", lab, turn=max(8.0, math.degrees(3.2 / r)))
            for k, lab in enumerate(labels)
            if any(abs((float(ref.kin.phi[k]) - d + math.pi) % (2 * math.pi) - math.pi) < 1e-6
                   for d in dead)]
    if len(out) > 2:
        out.append(PositionPlant("missing", out[2].position))
    joints = [n for n in revolute_joints(ref.mech) if n != ref.mech.crank.pin]
    if joints:
        out += [PositionPlant("moved", lab, joints[-1])
                for lab in (labels[1], labels[len(labels) // 2])]
    from graphplan.checking.drawing.trajectories import sheet_paths

    paths = sheet_paths(ref, (0.0, 0.0), ref.analysis.sheet1.kl.per_mm)
    out += [PositionPlant("path", point=n) for n in sorted(paths)
            if n.startswith("S") and _curved(paths[n])]
    return out


WANT = {"moved": "point", "scale": "scale", "numbering": "label", "extreme": "extreme",
        "missing": "extreme", "path": "point"}


def _detected(dc, p: PositionPlant) -> bool:
    """The planted error found as its own kind. A joint moved where another position's
    joint coincides with it (B2 and B8 of a crank-slider, the 720° cycle's twins, a
    parallel twin's piston C of position 1 where B of position 7 is, its rod from the
    one crank pin circle of both) may be read as that position's: both are drawn at one
    place, from one place, and nothing on the drawing tells them apart."""
    j = _positions(dc)
    at = j.found.expected.get((p.position, p.point))
    for f in dc.report.wrong:
        if not f.primary or "plan of positions" not in f.where or f.kind != WANT[p.kind]:
            continue
        if p.kind == "path":
            # a curve drawn off its path may lie nearer another point's: it is then
            # read as that one's, drawn wrong
            if f.quantity.startswith("⌒"):
                return True
        elif p.kind == "moved":
            if not f.quantity.startswith("•"):
                continue
            e = j.found.expected.get((f.position, f.quantity[1:]))
            if (f.position, f.quantity) == (p.position, f"•{p.point}") or (
                    at and e and math.dist(at, e) < 0.5):
                return True
        elif p.kind in ("extreme", "missing"):
            if f.position == p.position:
                return True
        else:
            return True
    return False


# a few of the variants nobody tuned the reader on (tests/data/variants): a loom's beater
# (a rocker's arc), a loaded coupler point, a rotating slotted link, a rocking shears with
# its dead centres close together, a V compressor, and the twin engines of a 720° cycle
# (each position drawn twice at one place, 1 and 13; a parallel twin's pistons on one
# line, so up to 8 joints of 8 positions at one place: before session 10 a joint moved
# there was read at an exact circle — of circles drawn at one place only the first was
# held taken — and an extreme position turned 8° was read at its twin's pin)
VARIANTS = ROOT / "tests" / "data" / "variants"
UNSEEN = ["loom_beater", "dough_mixer", "slotter_rotating", "shears_rocking",
          "v_two_stage_compressor", "twin_engine", "v_twin_engine", "inline_twin_180"]


@pytest.mark.parametrize("v", [EX / f"{ex}.toml" for ex in EXAMPLES] +
                         [VARIANTS / f"{n}.toml" for n in UNSEEN], ids=lambda p: p.stem)
def test_plan_of_positions_redrawn_with_planted_errors(tmp_path, v):
    """The plan of all positions of every example and of five unseen variants drawn as a
    CAD user draws it (links from hinge to hinge, some split in two, some polylines;
    hinges as INSERTs of a block, centres of mass as filled dots; the crank pin's
    trajectory a CIRCLE, a centre of mass' a SPLINE; numbers in MTEXT, some as ``A3``;
    3 m from the origin; the first in inches): no false alarm, every position's pin and
    joints read, the trajectories read on their paths, and every planted error found
    with its cause (the issue asks recall ≥ 0.95; measured 1.0: 5 to 9 plants each)."""
    from graphplan.checking.checks import reference_for

    ref = reference_for(v)
    for inches, letters in ((True, False), (False, True)):
        dc = check_drawing(positions_sheet(v, tmp_path / "clean.dxf", inches=inches,
                                           letter_numbers=letters), v, lang="en")
        assert not dc.report.wrong, _wrong(dc.report)
        j = _positions(dc)
        assert set(j.found.pins) == set(ref.labels)
        assert len(j.found.joints) == len(j.found.expected) - len(ref.labels)
        assert ref.mech.crank.pin in {p.point for p in j.found.paths}
        assert all(p.worst <= 0.25 for p in j.found.paths)
    total = hit = 0
    missed = []
    for i, p in enumerate(_plants(v)):
        dc = check_drawing(positions_sheet(v, tmp_path / f"p{i}.dxf", plant=p,
                                           letter_numbers=bool(i % 2)), v, lang="en")
        total += 1
        if _detected(dc, p):
            hit += 1
        else:
            missed.append((p, _wrong(dc.report)))
    assert total >= 3 and hit == total, missed


def test_overlay_shows_positions_findings(tmp_path):
    """A joint of one position drawn 3 mm off its place: the overlay lays every position
    exactly from the student's pivot (green, dashed) and draws the joint's error in red
    with its distance, with a close-up of the plan; a position drawn at another crank
    angle gets its crank in red and its angle off; a trajectory drawn off its path, the
    curve in red with its distance."""
    from graphplan.checking.drawing.overlay import RED, drawing_overlay

    v = EX / "fourbar.toml"
    dc = check_drawing(positions_sheet(v, tmp_path / "m.dxf",
                                       plant=PositionPlant("moved", "2", "B")), v, lang="en")
    assert [(f.position, f.quantity) for f in dc.report.wrong] == [("2", "•B")]
    sheets = drawing_overlay(dc, "en")
    assert len(sheets) == 2 and "plan of positions" in sheets[1].split("<title>")[1]
    assert f"stroke='{RED}'" in sheets[0] and "B2: 3 mm" in sheets[0]  # √(2.4² + 1.8²)
    assert "stroke-dasharray" in sheets[0]
    dc = check_drawing(positions_sheet(v, tmp_path / "e.dxf",
                                       plant=PositionPlant("extreme", "1'", turn=10.0)), v,
                       lang="en")
    over = drawing_overlay(dc, "en")
    assert len(over) == 2 and "φ1&#x27;: +10°" in over[0]
    # a centre of mass' trajectory 3 mm off: the curve in red over the exact path, dashed
    dc = check_drawing(positions_sheet(v, tmp_path / "t.dxf",
                                       plant=PositionPlant("path", point="S2")), v, lang="en")
    assert [(f.quantity, f.kind) for f in dc.report.wrong] == [("⌒S2", "point")]
    over = drawing_overlay(dc, "en")
    assert len(over) == 2 and "⌒S2: " in over[0]
    assert "<polyline points=" in over[0] and f"stroke='{RED}' stroke-width='0.45'" in over[0]
    right = drawing_overlay(check_drawing(positions_sheet(v, tmp_path / "s.dxf"), v,
                                          lang="en"), "en")
    assert len(right) == 1 and f"stroke='{RED}'" not in right[0]


ALL_VARIANTS = sorted(p.stem for p in VARIANTS.glob("*.toml"))
# what graphplan's own sheet 1 of a variant draws that a teacher would misread too
# (written to sheet 1's owner in /work/coord/DEFECTS.md)
VARIANT_SHEET_TODO: dict[str, str] = {}


@pytest.fixture(scope="module")
def variant_sheets(tmp_path_factory):
    """graphplan's own sheet 1 of a variant as DXF, SVG and PDF (drawn once)."""
    from graphplan.checking.checks import reference_for
    from graphplan.drawing import kinematics_sheet
    from graphplan.render import sheet_files

    out = tmp_path_factory.mktemp("variants")

    def make(name: str) -> Path:
        folder = out / name
        if not folder.is_dir():
            folder.mkdir()
            ref = reference_for(VARIANTS / f"{name}.toml")
            fmts = ("dxf", "svg", "pdf") if _has("pypdf") and _has("typst") else ("dxf", "svg")
            files = sheet_files({"sheet1": kinematics_sheet(ref.analysis, lang="ru")}, fmts)
            for fn, content in files.items():
                (folder / fn).write_bytes(content.encode("utf-8") if isinstance(content, str)
                                          else content)
        return folder

    return make


def _has(module: str) -> bool:
    import importlib.util

    return importlib.util.find_spec(module) is not None


@pytest.mark.parametrize("name", ALL_VARIANTS)
def test_graphplans_own_sheet1_of_every_variant(request, variant_sheets, name):
    """Sheet 1 of every variant in tests/data/variants (written from the docs alone; the
    reader was not tuned on them) as DXF, SVG and PDF: no wrong finding on any plan, the
    plan of all positions found with every position's pin and every joint, and its
    trajectories read on their paths. Before this session's changes: the plan of
    positions not found on 3 variants (a two-throw crank drawn as one line through the
    pivot), 2 positions unread on 2 (numbers on long leaders), the second throw's joints
    unread (10–22 of 36–72)."""
    if name in VARIANT_SHEET_TODO:
        request.applymarker(pytest.mark.xfail(strict=True, reason=VARIANT_SHEET_TODO[name]))
    from graphplan.checking.checks import reference_for

    ref = reference_for(VARIANTS / f"{name}.toml")
    folder = variant_sheets(name)
    wrong = {}
    for path in sorted(folder.glob("sheet1.*")):
        dc = check_drawing(path, VARIANTS / f"{name}.toml", lang="en")
        wrong[path.suffix] = _wrong(dc.report)
        j = _positions(dc)
        assert set(j.found.pins) == set(ref.labels), path.suffix
        assert len(j.found.joints) == len(j.found.expected) - len(ref.labels), path.suffix
        assert all(p.worst <= 0.25 for p in j.found.paths), path.suffix
    assert len(wrong) >= 2 and not any(wrong.values()), wrong


@pytest.mark.parametrize("v", [EX / "press.toml", VARIANTS / "opposed_compressor.toml"],
                         ids=lambda p: p.stem)
def test_plan_of_positions_at_a_gost_ratio_of_its_own(tmp_path, v):
    """The plan of positions redrawn by a CAD user at a ГОСТ 2.302 scale of their own
    choosing (not graphplan's Kl) and written as a ratio, «План положений М 1:n»: read at
    Kl = n/1000 m/mm with nothing wrong; written «М 1:2n» while drawn at 1:n, one
    ``scale`` finding (Kl) and the positions then read at the Kl drawn. Before: a ratio
    was no scale («μl = 1:2» read Kl = 1 m/mm)."""
    from graphplan.checking.checks import reference_for

    ref = reference_for(v)
    own = ref.analysis.sheet1.kl.per_mm
    n = next(k for k in (2, 5, 4, 2.5) if abs(k / 1000 - own) > 1e-9)
    kl = n / 1000
    dc = check_drawing(positions_sheet(v, tmp_path / "r.dxf", kl=kl,
                                       scale_text=f"М 1:{n:g}".replace(".", ",")), v,
                       lang="en")
    assert not dc.report.wrong, _wrong(dc.report)
    j = _positions(dc)
    assert j.found.kl == pytest.approx(kl) and set(j.found.pins) == set(ref.labels)
    assert j.found.radius == pytest.approx(ref.mech.crank.length / kl, rel=1e-3)
    assert len(j.found.joints) == len(j.found.expected) - len(ref.labels)
    dc = check_drawing(positions_sheet(v, tmp_path / "w.dxf", kl=kl,
                                       scale_text=f"М 1:{2 * n:g}".replace(".", ",")), v,
                       lang="en")
    assert [(f.quantity, f.kind) for f in dc.report.wrong] == [("Kl", "scale")], _wrong(
        dc.report)
