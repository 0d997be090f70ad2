"""Does the force-plan reader generalise (issue 22)? graphplan's own sheet 2 of every
variant in tests/data/variants — machines nobody tuned the reader on (engines of two and
four cylinders, a rotating кулиса, a dough mixer with a load on a coupler point, a loom
beater, shears, compressors) — read as DXF, SVG and vector PDF: every force plan found
with its caption's Kp and a position of the variant, h21 found and right, and no false
finding. Measured before the session-9 reader (stubs carried to their heads, a name by
another name's line read at the unnamed arrow that fits it, h21 never a force's arrow, the
components Rτ/Rn of a rod whose piston's centre is its pin): 35 false findings on 45
drawings of the 15 variants then (8 variants); after: none, on the 17 now (51 drawings)."""

from __future__ import annotations

from pathlib import Path

import pytest

pytest.importorskip("ezdxf")

from graphplan.checking.drawing.check import check_drawing

ROOT = Path(__file__).resolve().parents[1]
VARIANTS = sorted((ROOT / "tests" / "data" / "variants").glob("*.toml"))

# A variant whose sheet 2 still gets a false finding, with its named cause:
VARIANT_TODO: dict[tuple[str, str], str] = {
    # session 10 (families' new variant): position 9's force plan of group 2-3 names G3 (6.7 mm,
    # the vertical d→e) under the line e→f (R43), 6 mm right of e — a teacher reads G3 there
    # too: the reader finds '∠G3' wrong. Sheet 2's label placement (→ sheet2 in DEFECTS.md).
    **{("inclined_screen", f): "issue 22/18: G3 named under R43's line in position 9's plan 2-3"
       for f in ("dxf", "svg", "pdf")},
}


def _formats() -> list[str]:
    fmts = ["dxf", "svg"]
    try:
        import pypdf  # noqa: F401
        import typst  # noqa: F401
    except ImportError:
        return fmts
    return [*fmts, "pdf"]


@pytest.fixture(scope="module")
def sheet2(tmp_path_factory):
    """Sheet 2 of a variant in every format, drawn once by the current code."""
    from graphplan.checking.checks import reference_for
    from graphplan.drawing import kinetostatics_sheet
    from graphplan.render import sheet_files

    out = tmp_path_factory.mktemp("variants")

    def make(v: Path) -> Path:
        folder = out / v.stem
        if not folder.is_dir():
            folder.mkdir()
            ref = reference_for(v)
            files = sheet_files({"sheet2": kinetostatics_sheet(ref.analysis, lang="ru")},
                                tuple(_formats()))
            for name, content in files.items():
                data = content.encode("utf-8") if isinstance(content, str) else content
                (folder / name).write_bytes(data)
        return folder

    return make


@pytest.mark.parametrize("fmt", _formats())
@pytest.mark.parametrize("v", VARIANTS, ids=lambda p: p.stem)
def test_own_sheet2_of_every_variant_reads_clean(request, sheet2, v, fmt):
    from graphplan.checking.checks import reference_for

    todo = VARIANT_TODO.get((v.stem, fmt))
    if todo:
        request.applymarker(pytest.mark.xfail(strict=True, reason=todo))
    ref = reference_for(v)
    dc = check_drawing(sheet2(v) / f"sheet2.{fmt}", v, lang="en")
    rep = dc.report
    plans = [j for j in dc.plans if j.found.kind == "force" and j.scale]
    # every force plan the sheet draws is found: as many as its captions with a Kp (the
    # groups' «План сил ВВВ(2-3), Kp = …» and the crank's «Кривошип, Kp = …»)
    drawn = [t for t in dc.drawing.texts if "Kp = " in t.text]
    assert plans and len(plans) == len(drawn), ([j.found.where for j in plans], len(drawn))
    # and no force plan where the sheet draws none (the loads on the mechanism's scheme)
    assert all(j.scale for j in dc.plans if j.found.kind == "force"), \
        [j.found.where for j in dc.plans if j.found.kind == "force" and not j.scale]
    assert all(j.position in ref.labels for j in plans)
    arms = [f for f in rep.figures if f.quantity == "h21"]
    assert arms and all(f.verdict == "ok" and f.position in ref.labels for f in arms)
    assert rep.ok, [(f.where, f.quantity, f.kind) for f in rep.wrong]
    figs = [f for f in rep.figures if f.quantity.endswith("_mm")]
    assert sum(f.verdict == "ok" for f in figs) >= 0.8 * len(figs) > 0
