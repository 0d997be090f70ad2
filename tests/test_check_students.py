"""Issue 19: student lines as students write them (each test carries the line as written),
and the report accounting for every line."""

import subprocess
import sys
from pathlib import Path

import pytest

from graphplan.checking.checks import check_work
from graphplan.checking.student import loads_student
from graphplan.files import bundled_example

EXAMPLES = Path(bundled_example("press")).parent
FOURBAR = (EXAMPLES / "fourbar.toml").as_posix()
SHAPER = (EXAMPLES / "shaper.toml").as_posix()

# fourbar, position 2 (φ = 70,8°), read off the plans at Kl = 0,002, Kv = 0,02, Ka = 0,25:
# vBA = 27,9 mm·0,02 = 0,558 m/s; ω2 = 0,558/0,35 = 1,594 1/s; aⁿBA = 1,594²·0,35 = 0,889
# m/s², drawn as 0,889/0,25 = 3,56 mm (graphplan: 3,563 mm).
FOURBAR_HEAD = f'''[work]
variant = "{FOURBAR}"
student = "Петров"
[general]
lines = [
  "Кl = lOA/OA = 0,1/50 = 0,002 м/мм",
  "ω1 = π∙n1/30 = 3,14∙90/30 = 9,42 рад/с",
  "vA = ω1∙lOA = 9,42∙0,1 = 0,942 м/с",
  "Kv = vA/pa = 0,942/47,1 = 0,02 (м/с)/мм",
  "aA = ω1^2∙lOA = 9,42^2∙0,1 = 8,87 м/с²",
  "Ka = aA/πa = 8,87/35,5 = 0,25 (м/с²)/мм",
]
'''


def _check(text: str, **kw):
    return check_work(loads_student(text, "<student>.toml"), **kw)


def test_a_segment_line_names_the_acceleration_it_draws():
    r = _check(FOURBAR_HEAD + '''[[positions]]
label = "2"
lines = [
  "vBA = ab∙Kv = 27,9∙0,02 = 0,558 м/с",
  "ω2 = vBA/lAB = 0,558/0,35 = 1,594 рад/с",
  "anBA = ω2^2∙lAB = 1,594^2∙0,35 = 0,889 м/с²",
  "n_BA = anBA/Ka = 0,889/0,25 = 3,56 мм",
  "anBC = vB^2/lBC = 0,598^2/0,3 = 1,192 м/с²",
  "n_BC = anBC/Ka = 1,192/0,25 = 4,77 мм",
]
''')
    # before: anBA = 0,889 read as a segment of 0,889 mm, "scale ×0,25" twice
    assert r.wrong == (), [f.explanation_en for f in r.wrong]
    names = {f.quantity: f.verdict for f in r.figures}
    assert names["anBA"] == names["n_BA"] == "ok"


def test_an_unbalanced_bracket_is_a_finding_not_a_silence():
    r = _check(FOURBAR_HEAD + '''[[positions]]
label = "2"
lines = ["vB = pb∙Kv = (29,9∙0,02 = 0,598 м/с"]
''', lang="en")
    (f,) = [f for f in r.wrong if f.kind == "unreadable"]
    assert "cannot be read" in f.explanation
    assert not r.ok and r.counts()["lines_unread"] == 1


def test_a_line_nothing_of_which_is_compared_says_so():
    r = _check(FOURBAR_HEAD + '''[[positions]]
label = "2"
lines = ["ψ = 1,4", "vB = pb∙Kv = 29,9∙0,02 = 0,598 м/с"]
''', lang="en")
    (ln,) = [ln for ln in r.lines if ln.text == "ψ = 1,4"]
    assert "not known" in ln.compared
    assert all(ln.compared == "" for ln in r.lines if ln.text.startswith("vB"))
    # the scales are the student's choice: shown as not compared, never as right
    scales = [f for f in r.figures if f.quantity in ("Кl", "Kv", "Ka")]
    assert {f.verdict for f in scales} == {"not compared"}
    c = r.counts()
    assert c["not_compared"] == 3 and c["lines_not_compared"] == 1
    from graphplan.checking.report_text import text_report

    text = text_report(r)
    assert "not compared" in text and "ψ = 1,4" in text


def test_the_summary_never_contradicts_the_findings():
    # Мур's written numbers give 663,6, the result says 700: the figure cannot stay "ok"
    r = _check(FOURBAR_HEAD + '''[[positions]]
label = "2"
lines = ["vB = pb∙Kv = 29,9∙0,02 = 0,7 м/с"]
''')
    wrong = [f for f in r.wrong if f.primary]
    assert wrong and r.counts()["wrong"] >= 1
    assert {f.quantity for f in r.figures if f.verdict == "wrong"} >= {"vB"}


def test_coriolis_and_relative_velocity_are_compared():
    # shaper, position 2: graphplan's Coriolis aᵏ = 2·ω3·v_rel = 1,148 m/s² (k_A3 = 4,59
    # mm at Ka = 0,25), relative velocity of the block 0,456 m/s (a3a = 11,40 mm at 0,04)
    head = f'''[work]
variant = "{SHAPER}"
[general]
lines = ["Кl = 0,004 м/мм", "Kv = 0,04 (м/с)/мм", "Ka = 0,25 (м/с²)/мм"]
[[positions]]
label = "2"
lines = [
  "vAA3 = a3a∙Kv = 11,4∙0,04 = 0,456 м/с",
  "ω3 = 1,259 рад/с",
  "{{}}",
  "k_A3 = akA3/Ka = {{}}/0,25 = {{}} мм",
]
'''
    right = _check(head.format("akA3 = 2∙ω3∙vAA3 = 2∙1,259∙0,456 = 1,148 м/с²", "1,148",
                               "4,59"))
    assert right.wrong == ()
    compared = {f.quantity: f.verdict for f in right.figures}
    assert compared["akA3"] == compared["vAA3"] == compared["k_A3"] == "ok"


def test_a_folder_skips_a_toml_that_is_not_a_student_file(tmp_path):
    from graphplan.checking.generate import generate

    (tmp_path / "fourbar.toml").write_text(Path(FOURBAR).read_text(encoding="utf-8"),
                                           encoding="utf-8")
    (tmp_path / "settings.toml").write_text("[tool]\nx = 1\n", encoding="utf-8")
    (tmp_path / "key.toml").write_text(generate(tmp_path / "fourbar.toml", positions=("2",),
                                                variant_ref="fourbar.toml").toml(),
                                       encoding="utf-8")
    p = subprocess.run([sys.executable, "-m", "graphplan", "check", str(tmp_path)],
                       capture_output=True, text=True, encoding="utf-8")
    assert p.returncode == 0, p.stdout + p.stderr
    assert "settings.toml: not a student file" in p.stderr
    assert "1 files" in p.stdout


def test_answer_key_names_the_variant_relative_to_the_written_file(tmp_path):
    out = tmp_path / "keys" / "fourbar-key.toml"
    out.parent.mkdir()
    p = subprocess.run([sys.executable, "-m", "graphplan", "check", "--answer-key", FOURBAR,
                        "-o", str(out)], capture_output=True, text=True, encoding="utf-8")
    assert p.returncode == 0, p.stderr
    import tomllib

    variant = tomllib.loads(out.read_text(encoding="utf-8"))["work"]["variant"]
    assert not Path(variant).is_absolute()
    assert (out.parent / variant).resolve() == Path(FOURBAR).resolve()


@pytest.mark.parametrize("written", ["aᵏA3", "akA3", "aкA3"])
def test_the_coriolis_acceleration_has_the_names_students_give_it(written):
    from graphplan.checking.checks import reference_for

    v = reference_for(Path(SHAPER)).vocabulary()
    assert v.lookup(written).key[:2] == ("reading", "k_A3")


def test_a_slip_in_a_scale_line_is_said_once_and_the_drawing_judged_at_the_scale_used():
    # Kv = 0,942/47,1 = 0,02, written 0,2; every line after uses 0,02 (the drawing's)
    head = FOURBAR_HEAD.replace("0,942/47,1 = 0,02 (м/с)/мм", "0,942/47,1 = 0,2 (м/с)/мм")
    r = _check(head + '''[[positions]]
label = "2"
lines = [
  "vB = pb∙Kv = 29,9∙0,02 = 0,598 м/с",
  "vBA = ab∙Kv = 27,9∙0,02 = 0,558 м/с",
  "ps2 = 36,9 мм",
]
''', lang="en")
    (f,) = r.wrong
    assert f.kind == "arithmetic" and f.quantity == "Kv"
    assert {x.quantity: x.verdict for x in r.figures}["ps2"] == "ok"


def test_two_force_plans_at_one_position_each_at_its_own_kp():
    # sixbar_press, position 2: group 4-5 at Kp = 10 N/mm, then group 2-3 at 12 N/mm
    # (graphplan draws them so: 1470.77 N of R42 over 122.56 mm, the plans' series 1, 1.2,
    # 1.5, …); the segments after each Kp are read at that Kp: R12 = 1504.3/12 = 125.36 mm
    from graphplan.checking.generate import generate

    gen = generate(EXAMPLES / "sixbar_press.toml", positions=("2",),
                   variant_ref=(EXAMPLES / "sixbar_press.toml").as_posix())
    text = gen.toml()
    assert text.count('"Кр = ') == 2
    text = text.replace('"h21 = ', '"R12_mm = 125,4 мм",\n  "h21 = ')  # a plain segment
    r = _check(text)
    assert r.wrong == (), [f.explanation_en for f in r.wrong]
    assert {f.quantity: f.verdict for f in r.figures}["R12_mm"] == "ok"


MC_LINES = [
    # fourbar, position 2: the resisting moment on the rocker is 171,5 N·m
    ("Мс = 171,5 Нм", None),
    ("Мс = 0,1715 кНм", None),
    ("Мс = 0,1715 Нм", "unit"),  # the number of kN·m with the unit N·m
    ("Мс = 171,5 кНм", "unit"),  # the number of N·m with the unit kN·m
]


@pytest.mark.parametrize(("line", "kind"), MC_LINES)
def test_a_moment_in_kn_m_is_a_unit_slip_in_either_direction_never_a_formula(line, kind):
    r = _check(FOURBAR_HEAD + f'[[positions]]\nlabel = "2"\nlines = ["{line}"]\n')
    assert [f.kind for f in r.wrong] == ([kind] if kind else [])


def test_the_levers_mbal_is_compared_with_the_balancing_moment():
    # Мур from the force plans 41,3 N·m; from Zhukovsky's lever written Мур.ж = 45,5
    r = _check(FOURBAR_HEAD + '''[[positions]]
label = "2"
lines = ["Мур = 41,3 Нм", "Мур.ж = 45,5 Нм"]
''')
    (f,) = r.wrong
    assert f.quantity in ("Мур.ж", "Мур_ж") and f.kind == "consistency"
    assert all(ln.compared == "" for ln in r.lines)


def test_a_reaction_written_as_its_segment_in_mbal_is_named_and_mbal_follows():
    # R12 = 60,02 mm ∙ 2 N/mm = 120,04 N; Мур takes 60,02 (the segment) for R21
    gen_lines = '''[[positions]]
label = "1"
lines = [
  "Кр = 2 Н/мм",
  "R12 = R12_mm∙Кр = 60,02∙2 = 120,04 Н",
  "h21 = 20,93 мм",
  "Мур = R21∙h21∙Кl = 60,02∙20,93∙0,002 = 2,512 Нм",
]
'''
    r = _check(FOURBAR_HEAD + gen_lines, lang="en")
    roots = [f for f in r.wrong if f.primary]
    assert [(f.quantity, f.kind) for f in roots] == [("R21", "scale")], roots
    assert "segment" in roots[0].explanation and "Kp" in roots[0].explanation
    assert [f.quantity for f in r.wrong if not f.primary] == ["Мур"]


def test_a_reading_reused_from_another_position_of_the_same_student():
    # pb is 29,9 mm at position 2; the student writes the same 29,9 at position 3
    # (graphplan there: 44,74 mm) — their own reading, named however far graphplan's
    # value of position 2 is from 29,9 (the old match needed 0,2 mm)
    r = _check(FOURBAR_HEAD + '''[[positions]]
label = "2"
lines = ["vB = pb∙Kv = 30,3∙0,02 = 0,606 м/с"]
[[positions]]
label = "3"
lines = ["vB = pb∙Kv = 30,3∙0,02 = 0,606 м/с"]
''', lang="en")
    roots = [f for f in r.wrong if f.primary]
    assert [(f.position, f.quantity, f.kind) for f in roots] == [("3", "pb", "other-variant")]
    assert "own" in roots[0].explanation
