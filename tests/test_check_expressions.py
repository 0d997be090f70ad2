"""The reader of written calculations: the notations students use, and nothing else."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphplan.checking.errors import ExpressionError
from graphplan.checking.expressions import evaluate, parse, show, split_chain, value
from graphplan.checking.units import fold, split_unit
from graphplan.errors import GraphplanError, InputError

# (as written, value, unit as written or None); each value worked by hand
NOTATIONS = [
    ("0.7∙600000", 420000.0, None),                      # 0.7·600000
    ("42,4∙10", 424.0, None),                            # decimal comma, U+2219
    ("424·37,39·0,001", 15.85336, None),                 # U+00B7: 424·37.39 = 15853.36
    ("129*9.81", 1265.49, None),
    ("2×3", 6.0, None),
    ("8145,71/40,79", 8145.71 / 40.79, None),
    ("1:4", 0.25, None),                                 # the school's division sign
    ("1250∙(74,08∙0.02654)", 2457.604, None),            # 74.08·0.02654 = 1.9660832
    ("[2+3]·4", 20.0, None),
    ("5,76²∙0,08", 2.654208, None),                      # 33.1776·0.08
    ("2^10", 1024.0, None),
    ("10^-3", 0.001, None),
    ("2^3^2", 512.0, None),                              # right-associative: 2^9
    ("−2^2", -4.0, None),                                # the power binds first
    ("12262,5 − 1498,51", 10763.99, None),               # U+2212 minus
    ("7 – 2", 5.0, None),                                # en dash
    ("2·−3", -6.0, None),
    ("2(3+4)", 14.0, None),                              # implicit product before a bracket
    ("(1+1)(2+2)", 8.0, None),
    ("600 000", 600000.0, None),                         # thousands in groups of three
    ("12 262,5", 12262.5, None),
    ("1,5e3", 1500.0, None),
    ("√(200²−56,57²)", math.sqrt(200**2 - 56.57**2), None),
    ("sqrt(16)", 4.0, None),
    ("sin45°∙80", 80 * math.sqrt(0.5), None),            # degrees, as written
    ("cos 60", 0.5, None),
    ("tg45", 1.0, None),
    ("arcsin(0,5)", 30.0, None),
    ("π∙55/30", math.pi * 55 / 30, None),
    ("8145,71 H", 8145.71, "H"),                         # Latin H for newtons
    ("2457,604H", 2457.604, "H"),
    ("424 кН", 424.0, "кН"),
    ("15,85кНм", 15.85, "кНм"),
    ("1370,1Нм", 1370.1, "Нм"),
    ("0.001м/мм", 0.001, "м/мм"),
    ("10 кН/мм", 10.0, "кН/мм"),
    ("200 Н/мм", 200.0, "Н/мм"),
    ("90,47мм", 90.47, "мм"),
    ("5,76 рад/с", 5.76, "рад/с"),
    ("1,92 м/с²", 1.92, "м/с²"),
    ("0,01 (м/с)/мм", 0.01, "(м/с)/мм"),
    ("-643,7Нм", -643.7, "Нм"),
    ("3 Н·м", 3.0, "Н·м"),
    ("1,2 kN", 1.2, "kN"),
]


@pytest.mark.parametrize(("text", "expected", "unit"), NOTATIONS, ids=[n[0] for n in NOTATIONS])
def test_notations_students_use(text, expected, unit):
    v = evaluate(text)
    assert v.number == pytest.approx(expected, rel=1e-12, abs=1e-15)
    assert (v.unit.text if v.unit else None) == unit


def test_units_convert_to_si():
    # 15,85 кНм = 15 850 Н·м; 90,47 мм = 0,09047 м; 10 кН/мм = 10 000 Н/мм
    assert evaluate("15,85кНм").si == pytest.approx(15850.0)
    assert evaluate("90,47мм").si == pytest.approx(0.09047)
    assert evaluate("10 кН/мм").si == pytest.approx(10000.0)
    assert evaluate("12 %").si == pytest.approx(0.12)
    assert evaluate("80").si is None


def test_look_alike_letters_fold():
    # Cyrillic К, р, Н, М, у fold onto Latin K, p, H, M, y
    assert fold("Кр") == "Kp"
    assert fold("Мур") == fold("Mур")
    assert split_unit("420000 H")[1].dimension == split_unit("420000 Н")[1].dimension == "N"


def test_a_name_ending_in_unit_letters_is_not_cut():
    assert split_unit("G3h3") == ("G3h3", None)
    assert split_unit("h43")[1] is None


REFUSED = [
    ("", "empty expression"),
    ("G3h3", "a name ('G3h3') where a number is expected"),
    ("0,7Q0", "a name ('Q0') where an operator is expected"),
    ("1 2", "two numbers in a row"),
    ("(1+2", "expected ')'"),
    ("1+2)", "unmatched ')'"),
    ("1/0", "division by zero"),
    ("10^400", "not a finite real number"),
    ("√(-1)", "is not defined"),
    ("1 ∙∙ 2", "unexpected '∙'"),
    ("1 = 2", "unexpected '='"),
    ("2 $ 3", "unexpected character '$'"),
    ("__import__('os')", "unexpected character '_'"),
    ("(" * 60 + "1" + ")" * 60, "nested deeper than"),
    ("1" + "+1" * 400, "at most"),
]


@pytest.mark.parametrize(("text", "message"), REFUSED, ids=[r[0][:20] or "empty" for r in REFUSED])
def test_everything_else_is_refused_with_a_clear_message(text, message):
    with pytest.raises(ExpressionError) as info:
        evaluate(text)
    msg = str(info.value)
    assert message in msg
    assert "\n" not in msg
    assert isinstance(info.value, InputError) and isinstance(info.value, GraphplanError)


def test_refusal_names_the_column():
    with pytest.raises(ExpressionError) as info:
        evaluate("12,5∙∙3")
    assert info.value.column == 6 and "column 6" in str(info.value)


def test_templates_read_names_and_split_juxtaposed_ones():
    known = {"Pи2", "h2", "G3", "h3", "h43", "m3", "aB"}

    def resolve(name):
        if name in known:
            return (name,)
        for i in range(1, len(name)):
            if name[:i] in known and name[i:] in known:
                return (name[:i], name[i:])
        return None

    node = parse("(Pи2h2+G3h3)/h43", names=True, resolve=resolve)
    assert show(node) == "(Pи2·h2+G3·h3)/h43"
    env = {"Pи2": 2.0, "h2": 3.0, "G3": 4.0, "h3": 5.0, "h43": 2.0}
    assert value(node, env) == pytest.approx((2 * 3 + 4 * 5) / 2)  # 13
    assert show(parse("0,7Q0", names=True)) == "0,7·Q0"
    assert show(parse("-Mур@4", names=True)) == "−Mур@4"


def test_chains_split_at_equals_signs():
    assert split_chain("R43=(299,7414∙37,13)/191,3=8145,71 H") == [
        "R43", "(299,7414∙37,13)/191,3", "8145,71 H"]
    assert split_chain("a ≈ 2") == ["a", "2"]


# --- fuzzing ---------------------------------------------------------------------------------


@settings(max_examples=400, deadline=None)
@given(st.text(alphabet=st.sampled_from(list("0123456789,.+-−*/∙·×^()[]²³°√ π=eEНкмHmсрадsin_$@ab"
                                            "Q\t")), max_size=40))
def test_any_text_gives_a_value_or_a_clear_refusal(text):
    try:
        v = evaluate(text)
    except ExpressionError as exc:
        assert str(exc) and "\n" not in str(exc)
    else:
        assert math.isfinite(v.number)


def _numbers():
    return st.one_of(st.integers(0, 99999).map(float),
                     st.decimals(min_value=0, max_value=9999, places=3, allow_nan=False)
                     .map(float))


@st.composite
def expressions(draw, depth=0):
    """(text as a student writes it, value computed by Python) pairs."""
    if depth > 3 or draw(st.booleans()):
        x = draw(_numbers())
        text = repr(x).rstrip("0").rstrip(".") if "e" not in repr(x) else f"{x:.3f}"
        if draw(st.booleans()):
            text = text.replace(".", ",")
        return text, x
    a_text, a = draw(expressions(depth + 1))
    b_text, b = draw(expressions(depth + 1))
    op = draw(st.sampled_from(["+", "−", "∙", "·", "*", "/"]))
    if op == "/" and b == 0:
        op = "+"
    value_ = {"+": a + b, "−": a - b, "/": a / b if b else 0.0}.get(op, a * b)
    return f"({a_text}{op}{b_text})", value_


@settings(max_examples=300, deadline=None)
@given(expressions())
def test_random_written_arithmetic_equals_python(pair):
    text, expected = pair
    assert evaluate(text).number == pytest.approx(expected, rel=1e-9, abs=1e-9)
