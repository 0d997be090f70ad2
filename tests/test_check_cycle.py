"""K (the coefficient of change of the output's average speed) and δ (the discrepancy of
the balancing moments of the force plans and of Zhukovsky's lever) are compared
(issue 19): K with the cycle's, δ with what the student's own two moments give by the
formula they wrote — each with its cause.

The shaper of examples/shaper.toml: its working stroke takes 216° of the crank, the idle
one 144°, so θ = 36° and K = 216/144 = (180 + 36)/(180 − 36) = 1,5.
"""

from graphplan.checking.checks import check_work
from graphplan.checking.student import loads_student
from graphplan.files import bundled_example

SHAPER = bundled_example("shaper")


def _check(general: list[str], position: list[str], label: str = "2"):
    lines = ",\n  ".join(f'"{x}"' for x in general)
    pos = ",\n  ".join(f'"{x}"' for x in position)
    text = (f'[work]\nvariant = "{SHAPER}"\n\n[general]\nlines = [\n  {lines}\n]\n\n'
            f'[[positions]]\nlabel = "{label}"\nlines = [\n  {pos}\n]\n')
    return check_work(loads_student(text, "<kd>.toml"))


def _fig(report, name):
    return next(f for f in report.figures if f.quantity == name)


# position 2: graphplan's Мур = 663,55 Нм; the student's 663,5 and, from the lever, 675,2:
# δ = (675,2 − 663,5)/675,2·100 = 1,733 %
MOMENTS = ["Мур = 663,5 Нм", "Мур.ж = 675,2 Нм"]
K_RIGHT = ["θ = 36°", "K = (180+θ)/(180-θ) = (180+36)/(180-36) = 1,5"]


def test_right_k_theta_and_delta_are_compared_and_come_out_clean():
    r = _check(K_RIGHT, [*MOMENTS, "δ = (Мур.ж - Мур)/Мур.ж∙100% = (675,2-663,5)/675,2∙100 "
                                   "= 1,73 %"])
    assert not [f for f in r.findings if f.verdict == "wrong"], r.findings
    for name in ("K", "θ", "δ"):
        assert _fig(r, name).verdict == "ok", _fig(r, name)
    assert abs(_fig(r, "K").expected - 1.5) < 1e-4
    assert abs(_fig(r, "δ").expected - 1.7328) < 1e-3  # from the student's own moments
    assert not [x for x in r.lines if x.compared]  # every line is compared


def test_k_written_the_other_way_up_is_a_formula_fault():
    r = _check(["θ = 36°", "K = (180-θ)/(180+θ) = (180-36)/(180+36) = 0,6667"], MOMENTS)
    [f] = [f for f in r.findings if f.verdict == "wrong"]
    assert (f.quantity, f.kind) == ("K", "formula")
    assert "inverse" in f.explanation_en


def test_k_from_a_misread_theta_follows_from_theta():
    # θ read as 30° (graphplan 36°): K = 210/150 = 1,4 follows from it
    r = _check(["θ = 30°", "K = (180+θ)/(180-θ) = (180+30)/(180-30) = 1,4"], MOMENTS)
    roots = [f for f in r.findings if f.verdict == "wrong" and f.primary]
    assert [f.quantity for f in roots] == ["θ"]
    k = next(f for f in r.findings if f.quantity == "K")
    assert k.kind == "propagated" and k.follows_from


def test_delta_with_wrong_arithmetic():
    r = _check(K_RIGHT, [*MOMENTS, "δ = (Мур.ж - Мур)/Мур.ж∙100% = (675,2-663,5)/675,2∙100 "
                                   "= 17,3 %"])
    [f] = [f for f in r.findings if f.verdict == "wrong"]
    assert (f.quantity, f.kind) == ("δ", "arithmetic")


def test_delta_written_as_a_fraction_is_a_unit_slip():
    r = _check(K_RIGHT, [*MOMENTS, "δ = (Мур.ж - Мур)/Мур.ж = (675,2-663,5)/675,2 = 0,0173"])
    [f] = [f for f in r.findings if f.verdict == "wrong"]
    assert (f.quantity, f.kind) == ("δ", "unit")


def test_delta_not_from_the_students_own_moments():
    # no formula: 2,5 % does not come from 663,5 and 675,2 (1,73 %)
    r = _check(K_RIGHT, [*MOMENTS, "δ = 2,5 %"])
    [f] = [f for f in r.findings if f.verdict == "wrong"]
    assert (f.quantity, f.kind) == ("δ", "consistency")
    assert "663,5" in f.explanation_ru and "675,2" in f.explanation_ru


def test_delta_by_a_formula_of_its_own():
    # the sum in the denominator: 11,7/1338,7·100 = 0,874 %, not a discrepancy
    r = _check(K_RIGHT, [*MOMENTS, "δ = (Мур.ж - Мур)/(Мур.ж + Мур)∙100 = "
                                   "(675,2-663,5)/(675,2+663,5)∙100 = 0,874 %"])
    [f] = [f for f in r.findings if f.verdict == "wrong"]
    assert (f.quantity, f.kind) == ("δ", "formula")


def test_delta_without_the_levers_moment_is_not_compared_and_says_why():
    r = _check(K_RIGHT, ["Мур = 663,5 Нм", "δ = 1,7 %"])
    assert not [f for f in r.findings if f.verdict == "wrong"]
    d = _fig(r, "δ")
    assert d.verdict == "not compared" and "Мур.ж" in d.explanation


def test_the_levers_moment_is_its_own_figure_and_compared_with_graphplans():
    # Мур.ж 2 % off the force plans' Мур is no "one quantity, two values"
    r = _check(K_RIGHT, ["Мур = 663,5 Нм", "Мур.ж = 676,8 Нм"])
    assert not [f for f in r.findings if f.verdict == "wrong"]
    assert _fig(r, "Мур_ж").verdict == "inaccurate"
    r = _check(K_RIGHT, ["Мур = 663,5 Нм", "Мур.ж = -663,5 Нм"])
    [f] = [f for f in r.findings if f.verdict == "wrong"]
    assert f.kind == "sign"


def test_delta_in_the_general_lines_is_the_coefficient_of_speed_fluctuation():
    # the engine's variant: dynamics.delta = 0.0125 (1/80)
    from graphplan.files import bundled_example as ex

    def run(line):
        text = (f'[work]\nvariant = "{ex("engine")}"\n[general]\nlines = ["{line}"]\n'
                '[[positions]]\nlabel = "1"\nlines = ["vB = pb∙Kv = 63,79∙0,15 = 9,5685 м/с"]\n')
        return check_work(loads_student(text, "<fluctuation>.toml"))

    for right in ("δ = 1/80 = 0,0125", "δ = 1,25 %"):
        r = run(right)
        assert _fig(r, "δ").verdict == "ok", _fig(r, "δ")
    r = run("δ = 1/50 = 0,02")
    [f] = [f for f in r.findings if f.verdict == "wrong"]
    assert f.quantity == "δ" and "1/80" in f.explanation_en
