"""Random and mutated variant files: a clean one-line error or finite results, nothing else.

Every generated document goes through the whole pipeline::

    loads → analyse_structure → analyse_cycle → sweep

and each stage must either raise a :class:`graphplan.GraphplanError` whose message is
one line starting with the source name, or succeed. After ``sweep`` every array of
positions, velocities, accelerations, ω and ε must be finite. Any other exception
(a traceback) fails the test.

Documents come from:

* random TOML-ish documents: the right section names and keys (and some wrong
  ones) with random values of random types;
* plausible mechanisms built from scratch (one dyad of each kind, random frame
  points, lengths, guides, branch, units), sometimes spoiled by one mutation;
* mutations of valid variants (the press example and five written here, which
  between them use every dyad kind): a key deleted, a value replaced by a value
  of another type or by a special number (negative, zero, huge, tiny, nan, inf),
  a number scaled, a point or link renamed, a dyad kind swapped, a branch
  flipped, a count or a list length changed, an unknown key added;
* number-only changes of those variants (scaled lengths, flipped branches), which
  mostly reach the solver;
* text-level damage of the press file (lines dropped, duplicated, cut, swapped),
  arbitrary text, and arbitrary bytes through ``load``.

Numbers range over every float (subnormal, ±1e308, nan, ±inf) and over integers
far beyond 64 bits; keys and values may hold any character, line breaks included.
The bugs these tests found are kept at the end of this file as minimal reproducers:
regressions for those fixed, ``xfail(strict=True)`` for those still open.
"""

from __future__ import annotations

import copy
import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, event, example, given, settings
from hypothesis import strategies as st

import graphplan as g
from graphplan.model import SECTIONS

SRC = "fuzz/variant.toml"
EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
PRESS_TEXT = (EXAMPLES / "press.toml").read_text(encoding="utf-8")

FOURBAR_TEXT = """
[variant]
name = "four-bar"
[frame]
link = "4"
points = { O = [0.0, 0.0], C = [0.3, 0.0] }
[crank]
link = "1"
joints = ["O", "A"]
length = 0.1
rpm = 60
[[dyads]]
kind = "RRR"
links = ["2", "3"]
joints = ["A", "B", "C"]
lengths = [0.35, 0.25]
branch = "+"
[[points]]
name = "S2"
link = "2"
from = "A"
toward = "B"
fraction = 0.5
[[points]]
name = "S3"
link = "3"
from = "C"
toward = "B"
along = 0.1
across = 0.02
[links.2]
mass = 2.0
inertia = 0.01
centre = "S2"
[links.3]
mass = 1.0
centre = "S3"
[output]
link = "3"
working = "+"
[[loads]]
kind = "moment"
link = "3"
max = 10
diagram = [[0.0, 0.2], [0.5, 1.0], [1.0, 0.2]]
[positions]
count = 12
first = "start"
extra = [{ label = "m", stroke = 0.5 }, { label = "e", from = "end", turn = 15 }]
"""

# a shaper: slotted lever (RPR) driving a ram (PRP) whose first guide is on the rocker
SHAPER_TEXT = """
[variant]
length_unit = "mm"
[frame]
link = "4"
points = { O = [0, 0], C = [0, -300] }
[crank]
link = "1"
joints = ["O", "A"]
length = 100
rpm = 40
direction = "cw"
[[dyads]]
kind = "RPR"
links = ["2", "3"]
joints = ["A", "C"]
offset = 0
[[points]]
name = "S3"
link = "3"
from = "C"
along = 250
[[dyads]]
kind = "PRP"
links = ["5", "6"]
joints = ["B"]
guides = [{ link = "3", through = "C", angle = 0 }, { link = "4", through = [0, 500], angle = 0 }]
[links.3]
mass = 20
inertia = 0.4
centre = "S3"
[output]
link = "6"
working = "-"
[[loads]]
kind = "force"
link = "6"
point = "B"
max = 2000
diagram = [[0.0, 0.0], [0.1, 1.0], [0.9, 1.0], [1.0, 0.0]]
[positions]
count = 12
first = "start"
extra = [{ label = "s", stroke = 0.5 }, { label = "p", phi = 100 }]
"""

# a Scotch yoke (RPP) with the crank's mass given in [crank]
YOKE_TEXT = """
[frame]
link = "4"
points = { O = [0, 0] }
[crank]
link = "1"
joints = ["O", "A"]
length = 0.1
rpm = 100
mass = 1.0
centre = "O"
[[dyads]]
kind = "RPP"
links = ["2", "3"]
joints = ["A", "D"]
guide = { link = "4", through = [0.0, 0.0], angle = 0 }
slot_angle = 90
[[points]]
name = "E"
link = "3"
from = "D"
along = 0.2
across = 0.05
[[loads]]
kind = "force"
link = "3"
point = "D"
max = 100
diagram = [[0, 1], [1, 1]]
[positions]
first = "end"
count = 6
"""

# a six-bar: four-bar, then a crank-slider driven from a point of the coupler
SIXBAR_TEXT = """
[frame]
link = "6"
points = { O = [0.0, 0.0], C = [0.3, 0.05] }
[crank]
link = "1"
joints = ["O", "A"]
length = 0.1
rpm = 120
[[dyads]]
kind = "RRR"
links = ["2", "3"]
joints = ["A", "B", "C"]
lengths = [0.35, 0.25]
branch = "-"
[[points]]
name = "E"
link = "2"
from = "A"
toward = "B"
along = 0.1
across = 0.05
[[dyads]]
kind = "RRP"
links = ["4", "5"]
joints = ["E", "F"]
length = 0.4
guide = { link = "6", through = [0.0, -0.2], angle = 180 }
branch = "-"
[output]
link = "5"
[[loads]]
kind = "force"
link = "5"
point = "F"
max = 50
diagram = [[0, 0.5], [1, 1]]
"""

# an inverted slider-crank: RRP whose guide is carried by the crank, anchored on a fixed point
INVERTED_TEXT = """
[frame]
link = "4"
points = { O = [0.0, 0.0], C = [0.25, 0.0] }
[crank]
link = "1"
joints = ["O", "A"]
length = 0.1
rpm = 30
[[dyads]]
kind = "RRR"
links = ["2", "3"]
joints = ["A", "B", "C"]
lengths = [0.2, 0.15]
[[dyads]]
kind = "RPR"
links = ["5", "6"]
joints = ["B", "O"]
offset = 0.01
[output]
link = "6"
[positions]
first = 0
count = 4
"""

BASES = {
    "press": tomllib.loads(PRESS_TEXT),
    "fourbar": tomllib.loads(FOURBAR_TEXT),
    "shaper": tomllib.loads(SHAPER_TEXT),
    "yoke": tomllib.loads(YOKE_TEXT),
    "sixbar": tomllib.loads(SIXBAR_TEXT),
    "inverted": tomllib.loads(INVERTED_TEXT),
}


# -- a minimal TOML writer: every value inline, every key quoted -----------------------------


def toml_string(s: str) -> str:
    out = []
    for ch in s:
        if ch == "\\":
            out.append("\\\\")
        elif ch == '"':
            out.append('\\"')
        elif ord(ch) < 0x20 or ord(ch) == 0x7F:
            out.append(f"\\u{ord(ch):04X}")
        else:
            out.append(ch)
    return '"' + "".join(out) + '"'


def toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return toml_string(v)
    if isinstance(v, list | tuple):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        if not v:
            return "{}"
        return "{ " + ", ".join(f"{toml_string(str(k))} = {toml_value(x)}"
                                for k, x in v.items()) + " }"
    raise TypeError(f"cannot write {type(v).__name__} as TOML")


def dumps(doc: dict) -> str:
    return "".join(f"{toml_string(str(k))} = {toml_value(v)}\n" for k, v in doc.items())


# -- the property -----------------------------------------------------------------------------


def assert_clean(exc: g.GraphplanError, source: str = SRC) -> None:
    msg = str(exc)
    assert len(msg.splitlines()) == 1, f"{type(exc).__name__} is not one line: {msg!r}"
    assert msg.startswith(f"{source}: "), f"{type(exc).__name__} lacks the source: {msg!r}"


def assert_finite(kin: g.Kinematics, cycle: g.Cycle) -> None:
    groups = {
        "pos.points": kin.pos.points,
        "vel.points": kin.vel.points,
        "acc.points": kin.acc.points,
        "vel.omega": kin.vel.omega,
        "acc.epsilon": kin.acc.epsilon,
    }
    for group, arrays in groups.items():
        assert arrays, f"{group} is empty"
        for name, arr in arrays.items():
            arr = np.asarray(arr)
            assert arr.shape[0] == len(cycle.phi), f"{group}[{name!r}] has shape {arr.shape}"
            assert np.isfinite(arr).all(), f"{group}[{name!r}] is not finite: {arr!r}"
    assert np.isfinite(cycle.phi).all(), f"cycle.phi is not finite: {cycle.phi!r}"
    for field in ("stroke", "swing", "q_start", "q_end", "working_turn"):
        assert math.isfinite(getattr(cycle, field)), f"cycle.{field} is not finite"


def run_pipeline(text: str, source: str = SRC) -> str:
    """Run the whole pipeline on ``text``; return the stage reached (for statistics).

    A GraphplanError must be one clean line; anything else propagates and fails the test.
    """
    try:
        mech = g.loads(text, source=source)
    except g.GraphplanError as exc:
        assert_clean(exc, source)
        return f"load: {type(exc).__name__}"
    assert isinstance(mech, g.Mechanism)
    try:
        g.analyse_structure(mech)
    except g.GraphplanError as exc:
        assert_clean(exc, source)
        return f"structure: {type(exc).__name__}"
    try:
        cycle = g.analyse_cycle(mech)
    except g.GraphplanError as exc:
        assert_clean(exc, source)
        return f"cycle: {type(exc).__name__}"
    try:
        kin = g.sweep(mech, cycle)
    except g.GraphplanError as exc:
        assert_clean(exc, source)
        return f"sweep: {type(exc).__name__}"
    assert_finite(kin, cycle)
    return "solved"


def check_document(doc: dict) -> None:
    text = dumps(doc)
    event(run_pipeline(text))


@pytest.mark.parametrize("name", sorted(BASES))
def test_bases_solve(name):
    text = dumps(BASES[name])
    assert tomllib.loads(text) == BASES[name]  # the writer round-trips
    assert run_pipeline(text) == "solved"


# -- strategies -------------------------------------------------------------------------------

SPECIAL_NUMBERS = [
    0, 0.0, -0.0, 1, -1, 2, 90, -90, 180, 360, 0.5, -0.5, 1e-3, -1e-3,
    1e-9, -1e-9, 1e-30, 5e-324, -5e-324, 2.2250738585072014e-308,
    999.999, 1000, 1000.001, 1e5, 1e6, -1e6, 1e6 + 1, 1e9, 1e12, 1e30, -1e30,
    1e100, 1e200, -1e200, 1.7976931348623157e308, -1.7976931348623157e308,
    2**31, 2**53 + 1, 2**63 - 1, -(2**63), 2**64, 10**400, -(10**400),
    math.nan, math.inf, -math.inf,
]

numbers = st.one_of(
    st.sampled_from(SPECIAL_NUMBERS),
    st.integers(),
    st.integers(min_value=-(2**70), max_value=2**70),
    st.floats(),
    st.floats(min_value=-1000, max_value=1000),
)

LINE_BREAKS = "\n\r\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029"
key_text = st.one_of(
    st.text(alphabet=st.characters(blacklist_categories=("Cs",)), max_size=6),
    st.tuples(st.sampled_from(["x", "A", "2", "crank", ""]), st.sampled_from(LINE_BREAKS)).map(
        "".join),
)
any_text = st.text(alphabet=st.characters(blacklist_categories=("Cs",)), max_size=8)

NAMES = ["O", "A", "B", "C", "D", "E", "F", "S2", "S3", "O3", "B'", "Z"]
LINKS = ["1", "2", "3", "4", "5", "6", "7", "0", "10", "999"]
WORDS = ["+", "-", "m", "mm", "ccw", "cw", "start", "end", "force", "moment", "A1", "en",
         *g.model.DYAD_KINDS, "", " ", "nan"]
names = st.sampled_from(NAMES)
links = st.one_of(st.sampled_from(LINKS), st.integers(-1, 12))
strings = st.one_of(st.sampled_from(NAMES + LINKS + WORDS), any_text)
scalars = st.one_of(numbers, strings, st.booleans())
any_value = st.recursive(
    scalars,
    lambda kids: st.one_of(st.lists(kids, max_size=4),
                           st.dictionaries(st.one_of(names, key_text), kids, max_size=3)),
    max_leaves=8,
)
xy = st.lists(numbers, min_size=2, max_size=2)
sometimes_wrong = lambda s: st.one_of(s, s, s, any_value)  # noqa: E731

guide = st.fixed_dictionaries(
    {"link": sometimes_wrong(links), "through": sometimes_wrong(st.one_of(names, xy))},
    optional={"angle": sometimes_wrong(numbers), "toward": sometimes_wrong(names)},
)

# plausible values for the keys the format knows; any other key gets any value
KEY_VALUES = {
    "link": links,
    "links": st.lists(links, min_size=2, max_size=2),
    "joints": st.lists(names, min_size=1, max_size=3),
    "kind": st.sampled_from([*g.model.DYAD_KINDS, "force", "moment", "RRRR"]),
    "points": st.dictionaries(names, xy, max_size=3),
    "length": numbers,
    "lengths": st.lists(numbers, min_size=2, max_size=2),
    "guide": guide,
    "guides": st.lists(guide, min_size=2, max_size=2),
    "offset": numbers,
    "slot_angle": numbers,
    "branch": st.sampled_from(["+", "-", "0"]),
    "name": st.one_of(names, any_text),
    "from": st.one_of(names, st.sampled_from(["start", "end"])),
    "toward": names,
    "through": st.one_of(names, xy),
    "fraction": numbers,
    "along": numbers,
    "across": numbers,
    "mass": numbers,
    "inertia": numbers,
    "centre": names,
    "rpm": numbers,
    "direction": st.sampled_from(["ccw", "cw"]),
    "length_unit": st.sampled_from(["m", "mm", "cm"]),
    "enabled": st.booleans(),
    "count": st.one_of(st.integers(-1, 40), st.sampled_from([3600, 3601])),
    "first": st.one_of(st.sampled_from(["start", "end"]), numbers),
    "number_from": st.integers(-1, 2),
    "working": st.sampled_from(["+", "-"]),
    "max": numbers,
    "diagram": st.lists(st.lists(numbers, min_size=2, max_size=2), max_size=4),
    "label": strings,
    "phi": numbers,
    "turn": numbers,
    "stroke": numbers,
}

TABLE_KEYS = {
    "dyads": {"kind", "links", "joints", "branch", "lengths", "length", "guide", "guides",
              "offset", "slot_angle"},
    "points": {"name", "link", "from", "toward", "along", "across", "fraction"},
    "loads": {"kind", "link", "point", "max", "diagram"},
    "extra": {"label", "phi", "from", "turn", "stroke"},
    "links.*": {"mass", "inertia", "centre"},
}


def table_of(keys):
    """A table whose keys are mostly the expected ones, with plausible or random values."""
    keys = sorted(keys)
    key = st.one_of(st.sampled_from(keys), st.sampled_from(keys), key_text)
    return st.dictionaries(key, st.just(None), max_size=len(keys) + 1).flatmap(
        lambda d: st.fixed_dictionaries(
            {k: sometimes_wrong(KEY_VALUES.get(k, any_value)) for k in d}
        )
    )


KEY_VALUES["extra"] = st.lists(table_of(TABLE_KEYS["extra"]), max_size=2)


def section(name):
    if name in ("dyads", "points", "loads"):
        return st.lists(table_of(TABLE_KEYS[name]), min_size=0, max_size=3)
    if name == "links":
        return st.dictionaries(links.map(str), table_of(TABLE_KEYS["links.*"]), max_size=3)
    return table_of(SECTIONS[name])


random_documents = st.fixed_dictionaries(
    {},
    optional={
        **{sec: sometimes_wrong(section(sec)) for sec in SECTIONS},
        "frams": any_value,
    },
)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(random_documents)
def test_random_documents(doc):
    check_document(doc)


# plausible mechanisms built from scratch (one dyad of any kind, random dimensions), so that
# many reach the solver, then sometimes spoiled by one of the mutations below
coord = st.floats(min_value=-1, max_value=1)
size = st.floats(min_value=0.01, max_value=1)
angle = st.one_of(st.floats(min_value=-360, max_value=360), st.sampled_from([0, 90, 180, -90]))
plain_guide = st.one_of(
    st.fixed_dictionaries({"link": st.just("4"), "through": st.lists(coord, min_size=2,
                                                                   max_size=2)},
                          optional={"angle": angle}),
    st.fixed_dictionaries({"link": st.just("1"), "through": st.sampled_from(["O", "A"])},
                          optional={"angle": angle}),
    st.fixed_dictionaries({"link": st.just("4"), "through": st.sampled_from(["O", "C"]),
                           "toward": st.sampled_from(["C", "D"])}),
)
DYAD_TEMPLATES = {
    "RRR": {"joints": st.just(["A", "B", "C"]), "lengths": st.lists(size, min_size=2,
                                                                   max_size=2)},
    "RRP": {"joints": st.just(["A", "B"]), "length": size, "guide": plain_guide},
    "RPR": {"joints": st.sampled_from([["A", "C"], ["A", "D"]])},
    "PRP": {"joints": st.just(["B"]), "guides": st.lists(plain_guide, min_size=2, max_size=2)},
    "RPP": {"joints": st.just(["A", "D"]), "guide": plain_guide},
}
DYAD_OPTIONAL = {"RPR": {"offset": st.floats(-0.2, 0.2)}, "RPP": {"slot_angle": angle}}


@st.composite
def random_mechanisms(draw):
    kind = draw(st.sampled_from(sorted(DYAD_TEMPLATES)))
    dyad = draw(st.fixed_dictionaries(
        {"kind": st.just(kind), "links": st.just(["2", "3"]), **DYAD_TEMPLATES[kind]},
        optional={"branch": st.sampled_from(["+", "-"]), **DYAD_OPTIONAL.get(kind, {})}))
    doc = {
        "variant": {"length_unit": draw(st.sampled_from(["m", "mm"]))},
        "frame": {"link": "4", "points": {
            "O": [0.0, 0.0],
            "C": draw(st.lists(coord, min_size=2, max_size=2)),
            "D": draw(st.lists(coord, min_size=2, max_size=2)),
        }},
        "crank": {"link": "1", "joints": ["O", "A"], "length": draw(size),
                  "rpm": draw(st.floats(min_value=1, max_value=3000)),
                  "direction": draw(st.sampled_from(["ccw", "cw"]))},
        "dyads": [dyad],
        "positions": {"count": draw(st.integers(1, 24)),
                      "first": draw(st.one_of(st.sampled_from(["start", "end"]), angle))},
    }
    doc = copy.deepcopy(doc)  # st.just() hands out the same lists: never mutate those
    if doc["variant"]["length_unit"] == "mm":  # the same mechanism, written in millimetres
        doc = _scale_lengths(doc, 1000.0)
    if draw(st.booleans()):
        draw(st.sampled_from(OPS))(draw, doc)
    return doc


def _scale_lengths(doc, k):
    doc = copy.deepcopy(doc)
    pts = doc["frame"]["points"]
    for name in pts:
        pts[name] = [c * k for c in pts[name]]
    doc["crank"]["length"] *= k
    d = doc["dyads"][0]
    if "lengths" in d:
        d["lengths"] = [x * k for x in d["lengths"]]
    for key in ("length", "offset"):
        if key in d:
            d[key] *= k
    for gd in d.get("guides", [d.get("guide")]):
        if gd and isinstance(gd.get("through"), list):
            gd["through"] = [c * k for c in gd["through"]]
    return doc


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(random_mechanisms())
def test_random_mechanisms(doc):
    check_document(doc)


# -- mutations of valid variants --------------------------------------------------------------


def all_paths(node, prefix=()):
    out = []
    if isinstance(node, dict):
        items = node.items()
    elif isinstance(node, list):
        items = enumerate(node)
    else:
        return out
    for k, v in items:
        out.append((*prefix, k))
        out.extend(all_paths(v, (*prefix, k)))
    return out


def get(doc, path):
    for k in path:
        doc = doc[k]
    return doc


def put(doc, path, value):
    get(doc, path[:-1])[path[-1]] = value


NAME_RE = re.compile(r"^[A-Za-z][A-Za-z0-9_']*$")


def _pick(draw, doc, where):
    paths = [p for p in all_paths(doc) if where(p, get(doc, p))]
    if not paths:
        return None
    return draw(st.sampled_from(paths))


def op_delete(draw, doc):
    p = _pick(draw, doc, lambda p, v: True)
    if p:
        del get(doc, p[:-1])[p[-1]]


def op_replace_any(draw, doc):
    p = _pick(draw, doc, lambda p, v: True)
    if p:
        put(doc, p, draw(any_value))


def op_replace_number(draw, doc):
    p = _pick(draw, doc, lambda p, v: isinstance(v, int | float) and not isinstance(v, bool))
    if p:
        put(doc, p, draw(numbers))


def op_scale_number(draw, doc):
    p = _pick(draw, doc, lambda p, v: isinstance(v, int | float) and not isinstance(v, bool))
    if p:
        f = draw(st.sampled_from([-1, 0, 0.5, 0.9, 0.99, 1.01, 1.1, 1.5, 2, 10, 1e-6, 1e6]))
        v = get(doc, p)
        if isinstance(v, int) and abs(v) > 2**1000:  # too big for a float: scale exactly
            f = int(f) or -1
        put(doc, p, v * f)


def op_retype(draw, doc):
    """Replace a leaf by the same content in another type: "80" for 80, 80 for "80", [x]…"""
    p = _pick(draw, doc, lambda p, v: not isinstance(v, dict | list))
    if p:
        v = get(doc, p)
        put(doc, p, draw(st.sampled_from([str(v), [v], {"value": v}, bool(v), 1, 1.0, "1"])))


def op_rename_point(draw, doc):
    p = _pick(draw, doc, lambda p, v: isinstance(v, str) and bool(NAME_RE.match(v))
              and p[0] not in ("variant", "title_block", "drawing"))
    if p:
        known = sorted({v for q in all_paths(doc) if isinstance(v := get(doc, q), str)
                        and NAME_RE.match(v)} | set(NAMES))
        put(doc, p, draw(st.sampled_from(known)))


def op_rename_key(draw, doc):
    p = _pick(draw, doc, lambda p, v: isinstance(p[-1], str) and len(p) > 1)
    if p:
        parent = get(doc, p[:-1])
        new = draw(st.one_of(st.sampled_from(NAMES + LINKS), key_text))
        parent[new] = parent.pop(p[-1])


def op_relink(draw, doc):
    p = _pick(draw, doc, lambda p, v: isinstance(v, str) and v.isdigit())
    if p:
        put(doc, p, draw(st.sampled_from(LINKS)))


def op_swap_kind(draw, doc):
    dyads = doc.get("dyads")
    if isinstance(dyads, list) and dyads and isinstance(dyads[0], dict):
        d = draw(st.sampled_from([d for d in dyads if isinstance(d, dict)]))
        d["kind"] = draw(st.sampled_from(g.model.DYAD_KINDS))


def op_branch(draw, doc):
    dyads = doc.get("dyads")
    if isinstance(dyads, list) and dyads and isinstance(dyads[0], dict):
        d = draw(st.sampled_from([d for d in dyads if isinstance(d, dict)]))
        d["branch"] = draw(st.sampled_from(["+", "-", "-" if d.get("branch") == "+" else "+",
                                            "0", 1, -1]))


def op_count(draw, doc):
    pos = doc.setdefault("positions", {})
    if isinstance(pos, dict):
        pos["count"] = draw(st.one_of(st.integers(-2, 50), st.sampled_from([1, 3600, 3601])))


def op_list_length(draw, doc):
    p = _pick(draw, doc, lambda p, v: isinstance(v, list) and v)
    if p:
        lst = get(doc, p)
        how = draw(st.sampled_from(["dup", "pop", "reverse", "clear"]))
        if how == "dup":
            lst.append(copy.deepcopy(draw(st.sampled_from(lst))))
        elif how == "pop":
            lst.pop(draw(st.integers(0, len(lst) - 1)))
        elif how == "reverse":
            lst.reverse()
        else:
            lst.clear()


def op_add_key(draw, doc):
    p = _pick(draw, doc, lambda p, v: isinstance(v, dict))
    target = get(doc, p) if p else doc
    key = draw(st.one_of(st.sampled_from(sorted(KEY_VALUES)), key_text))
    target[key] = draw(KEY_VALUES.get(key, any_value))


def op_drop_section(draw, doc):
    if doc:
        del doc[draw(st.sampled_from(sorted(doc)))]


OPS = [op_delete, op_replace_any, op_replace_number, op_replace_number, op_scale_number,
       op_scale_number, op_retype, op_rename_point, op_rename_key, op_relink, op_swap_kind,
       op_branch, op_count, op_list_length, op_add_key, op_drop_section]


BASE_NAMES = tuple(sorted(BASES))


@st.composite
def mutated(draw, base_names=BASE_NAMES):
    name = draw(st.sampled_from(base_names))
    doc = copy.deepcopy(BASES[name])
    for _ in range(draw(st.integers(1, 3))):
        op = draw(st.sampled_from(OPS))
        op(draw, doc)
    return doc


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated())
def test_mutated_variants(doc):
    check_document(doc)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated(("press", "fourbar")))
def test_mutated_press_and_four_bar(doc):
    check_document(doc)


@st.composite
def geometry_changes(draw):
    """Only numbers change, by plausible factors: these mostly reach the solver."""
    name = draw(st.sampled_from(sorted(BASES)))
    doc = copy.deepcopy(BASES[name])
    for _ in range(draw(st.integers(1, 4))):
        op_scale_number(draw, doc) if draw(st.booleans()) else op_branch(draw, doc)
    return doc


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(geometry_changes())
def test_geometry_changes(doc):
    check_document(doc)


# -- text-level damage ------------------------------------------------------------------------


@st.composite
def damaged_text(draw):
    lines = PRESS_TEXT.splitlines(keepends=True)
    for _ in range(draw(st.integers(1, 4))):
        how = draw(st.sampled_from(["drop", "dup", "cut", "insert", "swap"]))
        k = draw(st.integers(0, len(lines) - 1))
        if how == "drop" and len(lines) > 1:
            del lines[k]
        elif how == "dup":
            lines.insert(k, lines[k])
        elif how == "cut":
            line = lines[k]
            lines[k] = line[: draw(st.integers(0, len(line)))] + "\n"
        elif how == "insert":
            lines.insert(k, draw(any_text) + "\n")
        else:
            j = draw(st.integers(0, len(lines) - 1))
            lines[k], lines[j] = lines[j], lines[k]
    return "".join(lines)


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_text())
def test_damaged_press_text(text):
    event(run_pipeline(text))


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=200))
def test_arbitrary_text(text):
    event(run_pipeline(text))


@settings(max_examples=100, deadline=None)
@given(st.binary(max_size=200))
def test_arbitrary_bytes_through_load(tmp_path_factory, data):
    path = tmp_path_factory.mktemp("fuzz") / "variant.toml"
    path.write_bytes(data)
    try:
        g.load(path)
    except g.GraphplanError as exc:
        assert_clean(exc, str(path))


# -- bugs found by fuzzing and fixed since: kept as regressions ------------------------------


def press(**changes) -> dict:
    doc = copy.deepcopy(BASES["press"])
    for path, value in changes.items():
        put(doc, path.split("__"), value)
    return doc


def first_error(text: str) -> g.GraphplanError | None:
    try:
        m = g.loads(text, source=SRC)
        g.analyse_structure(m)
        g.sweep(m, g.analyse_cycle(m))
    except g.GraphplanError as exc:
        return exc
    return None


def test_huge_rpm_is_refused():
    # was: rpm = 1e200 gave ω1² = inf and inf/nan accelerations, returned without an error
    exc = first_error(dumps(press(crank__rpm=1e200)))
    assert isinstance(exc, g.InputError)
    assert str(exc) == f"{SRC}: crank.rpm: must be <= 100000.0 (got 1e+200)"


def test_rpm_at_its_limit_gives_finite_results():
    assert run_pipeline(dumps(press(crank__rpm=1e5))) == "solved"


@pytest.mark.parametrize(("doc", "path"), [
    pytest.param(press(dyads=[{**BASES["press"]["dyads"][0], "length": 1e200}]),
                 "dyads[0].length", id="RRP-rod"),
    pytest.param({**copy.deepcopy(BASES["fourbar"]),
                  "dyads": [{**BASES["fourbar"]["dyads"][0], "lengths": [1e200, 1e200]}]},
                 "dyads[0].lengths[0]", id="RRR-lengths"),
])
def test_huge_dyad_length_is_refused(doc, path):
    # was: OverflowError from l1**2 (a Python float) in positions.py
    exc = first_error(dumps(doc))
    assert isinstance(exc, g.InputError)
    assert str(exc).startswith(f"{SRC}: {path}: must be <= ")


def test_point_toward_a_coincident_point():
    # was: NaN coordinates of Q (0/0 direction), returned without an error
    doc = press()
    doc["frame"]["points"] = {"O": [0, 0], "P": [0, 0]}
    doc["points"].append({"name": "Q", "link": "4", "from": "O", "toward": "P",
                          "fraction": 0.5})
    exc = first_error(dumps(doc))
    assert isinstance(exc, g.AssemblyError)
    assert str(exc) == (f"{SRC}: point Q: the direction from O toward P is undefined at "
                        "φ = 0.00° (the two points coincide)")


def test_guide_toward_a_coincident_point():
    # was: AssemblyError('guide of link 4: None and G coincide, ...'): no source, no dyad
    doc = press()
    doc["frame"]["points"]["G"] = [0, 0]
    doc["dyads"][0]["guide"] = {"link": "4", "through": [0, 0], "toward": "G"}
    exc = first_error(dumps(doc))
    assert isinstance(exc, g.AssemblyError)
    assert_clean(exc)
    msg = str(exc)
    assert "RRP(2-3)" in msg and "None" not in msg, msg


@example(("link", "2", "\n"))
@example(("point", "A", "\n"))
@settings(max_examples=30, deadline=None)
@given(st.tuples(st.sampled_from(["link", "point"]), st.sampled_from(["2", "A"]),
                 st.sampled_from(["\n", "\r\n", "\n\n", "\r", "\u2028"])))
def test_names_with_a_final_line_break(case):
    """A point name or link number ending in a line break is refused on one line.

    Was: NAME_RE/LINK_RE ended in '$', which matches before a final newline, so 'A\\n'
    and '2\\n' were accepted and AssemblyError printed them raw, over two lines.
    """
    what, _, brk = case
    doc = copy.deepcopy(BASES["press"])
    doc["dyads"][0]["length"] = 50  # too short: an AssemblyError would name dyad and joints
    doc["points"], doc["links"], doc["loads"] = [], {}, []
    if what == "link":
        doc["dyads"][0]["links"] = ["2" + brk, "3"]
    else:
        doc["crank"]["joints"] = ["O", "A" + brk]
        doc["dyads"][0]["joints"] = ["A" + brk, "B"]
    exc = first_error(dumps(doc))
    assert isinstance(exc, g.InputError), exc
    assert_clean(exc)


def rpr_through_pivot(c_xy, extra_phi=None) -> dict:
    """Crank 0.5 m about O; the slotted rocker pivots at C on (or by) the crank circle."""
    doc = {"frame": {"link": "4", "points": {"O": [0.0, 0.0], "C": c_xy}},
           "crank": {"link": "1", "joints": ["O", "A"], "length": 0.5, "rpm": 60},
           "dyads": [{"kind": "RPR", "links": ["2", "3"], "joints": ["A", "C"]}],
           "positions": {"first": 0, "count": 1}}
    if extra_phi is not None:
        doc["positions"]["extra"] = [{"label": "x", "phi": extra_phi}]
    return doc


@pytest.mark.parametrize("offset", [1e-200, 1e-100, 0.0])
def test_rpr_pin_through_its_pivot(offset):
    # was (1e-200): the pin passed the pivot at φ = 0, ε came out NaN without an error
    exc = first_error(dumps(rpr_through_pivot([0.5, offset])))
    assert isinstance(exc, g.AssemblyError), exc
    assert_clean(exc)
    assert "RPR(2-3)" in str(exc) and "φ = 0.00°" in str(exc), str(exc)


@pytest.mark.parametrize("label", ["x\ny", "x\r", "\u2028x", "x\ty"])
def test_position_label_with_a_control_character(label):
    # was: the label was printed raw by positions.where(), so the AssemblyError at that
    # position (this RPR's pin runs through its pivot at 33.33°) spanned two lines
    a = math.radians(33.33)
    doc = rpr_through_pivot([0.5 * math.cos(a), 0.5 * math.sin(a)], 33.33)
    doc["positions"]["extra"][0]["label"] = label
    exc = first_error(dumps(doc))
    assert isinstance(exc, g.InputError), exc
    assert_clean(exc)
    assert str(exc).startswith(f"{SRC}: positions.extra[0].label: expected a one-line label")


# -- bugs found by the fuzzing, now fixed: regressions ----------------------------------------


def test_rpr_pivot_on_the_crank_circle_is_caught_by_the_cycle_check():
    """The pivot C on the crank circle at 33.33°, between two check-grid angles (0.1° apart)."""
    a = math.radians(33.33)
    mech = g.loads(dumps(rpr_through_pivot([0.5 * math.cos(a), 0.5 * math.sin(a)], 33.33)),
                   source=SRC)
    try:
        g.analyse_cycle(mech)
    except g.AssemblyError as exc:
        assert_clean(exc)
        assert "RPR(2-3)" in str(exc)
        assert "φ = 33.33°" in str(exc)
        return
    raise AssertionError("analyse_cycle passed a turn in which A runs through C")


def test_guide_toward_a_coincident_point_names_the_crank_angle():
    doc = press()
    doc["frame"]["points"]["G"] = [0, 0]
    doc["dyads"][0]["guide"] = {"link": "4", "through": [0, 0], "toward": "G"}
    exc = first_error(dumps(doc))
    assert isinstance(exc, g.AssemblyError)
    assert "φ = " in str(exc), str(exc)


def test_guide_toward_a_point_a_subnormal_distance_away_is_coincident():
    # found by test_random_mechanisms (session 10): C 2.2e-313 m from O, a guide from O toward
    # C: the direction's reciprocal distance overflowed (a RuntimeWarning, not a clean error)
    doc = press()
    doc["frame"]["points"]["C"] = [0.0, 2.2250738585e-313]
    doc["dyads"][0]["guide"] = {"link": "4", "through": "O", "toward": "C"}
    exc = first_error(dumps(doc))
    assert isinstance(exc, g.AssemblyError), exc
    assert_clean(exc)
    assert "the two points coincide" in str(exc)
