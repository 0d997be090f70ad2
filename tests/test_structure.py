"""Mobility by Chebyshev's formula and the decomposition into Assur groups."""

import pytest

import graphplan as g

FRAME = """
[frame]
link = "0"
points = { O = [0, 0], C = [0.3, 0], O3 = [0, 0.5] }
[crank]
link = "1"
joints = ["O", "A"]
length = 0.1
rpm = 60
"""

SHAPER = FRAME + """
[[dyads]]
kind = "RPR"
links = ["2", "3"]
joints = ["A", "O3"]
[[points]]
name = "B"
link = "3"
from = "O3"
along = -0.7
[[dyads]]
kind = "RRP"
links = ["4", "5"]
joints = ["B", "D"]
length = 0.25
guide = { link = "0", through = [0, -0.25], angle = 0 }
"""


def test_shaper_formula_and_mobility():
    m = g.loads(SHAPER, source="shaper.toml")
    st = g.analyse_structure(m)
    # n = 5 moving links, p5 = 7 lower pairs: W = 3·5 − 2·7 = 15 − 14 = 1
    assert (st.n_moving, st.p5, st.mobility) == (5, 7, 1)
    assert st.mobility_equation == "W = 3·n − 2·p5 − p4 = 3·5 − 2·7 − 0 = 1"
    assert [(gr.kind, gr.links) for gr in st.groups] == [("RPR", ("2", "3")), ("RRP", ("4", "5"))]
    assert st.formula == "I(0,1) → II₃(2,3) → II₂(4,5)"
    assert [gr.kind_number for gr in st.groups] == [3, 2]


def test_groups_are_found_on_the_pair_graph_not_copied():
    m = g.loads(SHAPER, source="shaper.toml")
    st = g.analyse_structure(m)
    # the second group's outer pair is the revolute B between rod 4 and rocker 3
    outer = st.groups[1].pairs[0]
    assert (outer.kind, set(outer.links), outer.joint) == ("R", {"3", "4"}, "B")
    kinds = sorted(p.kind for p in st.pairs)
    assert kinds == ["P", "P", "R", "R", "R", "R", "R"]


@pytest.mark.parametrize(
    ("kind", "body", "expected"),
    [
        ("RRR", 'joints = ["A", "B", "C"]\nlengths = [0.3, 0.25]', "II₁(2,3)"),
        ("RRP", 'joints = ["A", "B"]\nlength = 0.3\n'
                'guide = { link = "0", through = [0, 0], angle = 0 }',
         "II₂(2,3)"),
        ("RPR", 'joints = ["A", "C"]', "II₃(2,3)"),
        ("RPP", 'joints = ["A", "D"]\nguide = { link = "0", through = [0, 0], angle = 0 }',
         "II₅(2,3)"),
    ],
)
def test_each_kind_is_recognised(kind, body, expected):
    text = FRAME + f'[[dyads]]\nkind = "{kind}"\nlinks = ["2", "3"]\n{body}\n'
    st = g.analyse_structure(g.loads(text, source="k.toml"))
    assert st.groups[0].formula == expected
    assert st.groups[0].kind == kind


def test_prp_is_recognised_from_its_pairs():
    text = FRAME + """
[[dyads]]
kind = "RPR"
links = ["2", "3"]
joints = ["A", "O3"]
[[dyads]]
kind = "PRP"
links = ["4", "5"]
joints = ["E"]
guides = [{ link = "3", through = "O3", angle = 0 }, { link = "0", through = [0, -0.3], angle = 0 }]
"""
    st = g.analyse_structure(g.loads(text, source="prp.toml"))
    assert [gr.kind for gr in st.groups] == ["RPR", "PRP"]
    assert st.formula == "I(0,1) → II₃(2,3) → II₄(4,5)"


def test_reused_link_number_breaks_mobility():
    # links 2 and 1 for the dyad: link 1 (the crank) appears again, so n = 2 and
    # p5 = 4 lower pairs: W = 3·2 − 2·4 = −2
    text = FRAME + ('[[dyads]]\nkind = "RRR"\nlinks = ["2", "1"]\njoints = ["A", "B", "C"]\n'
                    'lengths = [0.3, 0.25]\n')
    m = g.loads(text, source="bad.toml")
    with pytest.raises(g.StructureError) as exc:
        g.analyse_structure(m)
    msg = str(exc.value)
    assert msg.startswith("bad.toml: mobility W = 3·n − 2·p5 − p4 = 3·2 − 2·4 − 0 = -2")
    assert "\n" not in msg


def test_cycle_refuses_a_frame_link_reused_by_a_dyad():
    # an RRR with links ["2", "0"] would turn the frame: the cycle must not run
    text = FRAME + ('[[dyads]]\nkind = "RRR"\nlinks = ["2", "0"]\njoints = ["A", "B", "C"]\n'
                    'lengths = [0.3, 0.25]\n')
    m = g.loads(text, source="bad.toml")
    with pytest.raises(g.StructureError):
        g.analyse_cycle(m)


def test_russian_reports_name_the_dyad_kinds_as_russian_textbooks_do():
    """В — вращательная пара, П — поступательная (issue 23): RRP is ВВП, RPR is ВПВ."""
    from graphplan.files import bundled_example
    from graphplan.project import solve_project
    from graphplan.reports.tables import structure_text

    p = solve_project(g.load(bundled_example("shaper")))
    assert [grp.kind_ru for grp in p.structure.groups] == ["ВПВ", "ВВП"]
    ru, en = structure_text(p, "ru"), structure_text(p, "en")
    assert "вид ВПВ (3)" in ru and "вид ВВП (2)" in ru and "RPR" not in ru
    assert "kind RPR (3)" in en and "ВПВ" not in en


def test_russian_reports_letter_the_pairs_and_their_class_as_russian_textbooks_do():
    """Issue 23: under --lang ru the pairs are В (вращательная) and П (поступательная), the
    lower pairs p5 of class V and the higher p4 of class IV; no R/P, no Latin dyad kind
    anywhere in the structure and cycle sections (the slotter: 5 revolute, 2 prismatic)."""
    import re

    from graphplan.files import bundled_example
    from graphplan.project import solve_project
    from graphplan.reports.tables import cycle_text, structure_text

    p = solve_project(g.load(bundled_example("slotter")))
    ru = structure_text(p, "ru") + "\n" + cycle_text(p, "ru")
    en = structure_text(p, "en") + "\n" + cycle_text(p, "en")
    pairs_ru = [ln.strip() for ln in ru.splitlines() if re.match(r"  [ВП] ", ln)]
    pairs_en = [ln.strip() for ln in en.splitlines() if re.match(r"  [RP] ", ln)]
    assert len(pairs_ru) == len(pairs_en) == p.structure.p5 == 7
    assert sum(ln.startswith("В ") for ln in pairs_ru) == 5  # O1, A, O3, B, C
    assert sum(ln.startswith("П ") for ln in pairs_ru) == 2  # block in slot 2-3, ram 5-6
    assert "В O1 (6-1) — вращательная" in pairs_ru and "П (2-3) — поступательная" in pairs_ru
    assert "p5 = 7 низших пар V класса" in ru and "p4 = 0 высших пар IV класса" in ru
    assert "группа Ассура II класса 2-го порядка" in ru
    assert "ВПВ(2-3)" in ru and "ВВП(4-5)" in ru  # the conditioning lines too
    assert not re.search(r"\b[RP] |\b[RP]{3}\b", ru), ru
    assert "R O1 (6-1) — revolute" in pairs_en and "RPR(2-3)" in en and "В " not in en
