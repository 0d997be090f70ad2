"""Every error path of the loader, and the analysis errors a bad variant runs into.

The requirement: bad input gets ONE clear line that names the file, the key and
what was expected (no traceback). Each case below breaks one thing in a valid
variant (the press example or a four-bar) and checks

* the exception type (:class:`graphplan.InputError` for the loader),
* that ``str(exc)`` is a single line,
* that it starts with the source name and then the key path
  (``v.toml: dyads[0].length: ...``),
* that it says what was expected.

The variants are edited as dicts and written back with the small TOML writer
below (``tomllib`` has no writer), so every case is one targeted change.
"""

from __future__ import annotations

import copy
import math
import re
import tomllib
from pathlib import Path

import pytest

import graphplan as g

SRC = "v.toml"
EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
PRESS_TEXT = (EXAMPLES / "press.toml").read_text(encoding="utf-8")
PRESS = tomllib.loads(PRESS_TEXT)

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

[links.2]
mass = 2.0
centre = "S2"

[output]
link = "3"
"""
FOURBAR = tomllib.loads(FOURBAR_TEXT)


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


# -- edits addressed by key path ---------------------------------------------------------------

_TOKEN = re.compile(r"\[(\d+)\]|([^.\[\]]+)")


def _tokens(path: str) -> list:
    return [int(i) if i else k for i, k in _TOKEN.findall(path)]


def _parent(doc, path: str):
    toks = _tokens(path)
    node = doc
    for t in toks[:-1]:
        node = node[t]
    return node, toks[-1]


def set_(path: str, value):
    def edit(doc):
        node, last = _parent(doc, path)
        if isinstance(node, list) and last == len(node):
            node.append(value)
        else:
            node[last] = value
    return edit


def drop(path: str):
    def edit(doc):
        node, last = _parent(doc, path)
        assert last in node or isinstance(node, list), f"{path} is not in the base variant"
        del node[last]
    return edit


def build(base: dict, *edits) -> str:
    doc = copy.deepcopy(base)
    for e in edits:
        e(doc)
    return dumps(doc)


def assert_one_line(msg: str, source: str = SRC) -> None:
    assert len(msg.splitlines()) == 1, f"message is not one line: {msg!r}"
    assert msg.startswith(f"{source}: "), f"message does not start with the source: {msg!r}"


def input_error(text: str) -> str:
    with pytest.raises(g.InputError) as ei:
        g.loads(text, source=SRC)
    msg = str(ei.value)
    assert_one_line(msg)
    return msg


# -- sanity: the bases are valid and the writer round-trips -------------------------------------


@pytest.mark.parametrize("base", [PRESS, FOURBAR], ids=["press", "fourbar"])
def test_writer_round_trips_and_bases_load(base):
    text = dumps(base)
    assert tomllib.loads(text) == base
    m = g.loads(text, source=SRC)
    assert isinstance(m, g.Mechanism)
    assert g.analyse_structure(m).mobility == 1


# -- reading the file ---------------------------------------------------------------------------


def test_file_not_found(tmp_path):
    path = tmp_path / "nope.toml"
    with pytest.raises(g.InputError) as ei:
        g.load(path)
    msg = str(ei.value)
    assert_one_line(msg, str(path))
    assert msg == f"{path}: file not found"


def test_not_utf8(tmp_path):
    path = tmp_path / "latin1.toml"
    path.write_bytes(PRESS_TEXT.encode("utf-8") + "# Größe\n".encode("latin-1"))
    with pytest.raises(g.InputError) as ei:
        g.load(path)
    msg = str(ei.value)
    assert_one_line(msg, str(path))
    # the last line of the file: "# Größe" in latin-1
    line = PRESS_TEXT.count("\n") + 1
    assert f": line {line}: not UTF-8 text" in msg and "save the file as UTF-8" in msg


def test_cannot_read_a_directory(tmp_path):
    with pytest.raises(g.InputError) as ei:
        g.load(tmp_path)
    msg = str(ei.value)
    assert_one_line(msg, str(tmp_path))
    assert "cannot read" in msg


def test_load_uses_the_path_as_source(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(build(PRESS, set_("crank.length", -80)), encoding="utf-8")
    with pytest.raises(g.InputError) as ei:
        g.load(path)
    msg = str(ei.value)
    assert_one_line(msg, str(path))
    assert msg == f"{path}: crank.length: must be > 0 (got -80)"


@pytest.mark.parametrize(
    "text",
    [
        "[frame\nlink = 4\n",
        "frame = \n",
        "a = 1\na = 2\n",
        'x = "unterminated\n',
        "[frame]\npoints = { O = [0, 0], }\n",
        PRESS_TEXT.replace("[crank]", "[frame]", 1),
    ],
    ids=["open-bracket", "no-value", "duplicate-key", "open-string", "trailing-comma",
         "table-twice"],
)
def test_invalid_toml(text):
    msg = input_error(text)
    assert msg.startswith(f"{SRC}: not valid TOML (")
    assert re.search(r"line \d+, column \d+", msg)


def test_empty_document_names_the_first_missing_section():
    msg = input_error("")
    assert msg == f"{SRC}: crank: missing required key"


# -- the loader, one case per r.fail(...) -------------------------------------------------------
# (id, base, edits, key path the message names, fragment saying what was expected)

P, F = PRESS, FOURBAR
CASES = [
    # top level and sections
    ("unknown-section", P, [set_("frames", {"link": "4"})],
     "frames", "unknown key (expected one of: crank, drawing, dyads, dynamics, frame,"),
    ("missing-frame", P, [drop("frame")], "frame", "missing required key"),
    ("missing-crank", P, [drop("crank")], "crank", "missing required key"),
    ("missing-dyads", P, [drop("dyads")], "dyads", "missing required key"),
    ("section-not-table", P, [set_("variant", 3)], "variant", "expected a table (got int)"),
    ("unknown-key-in-section", P, [set_("crank.lenght", 80)],
     "crank.lenght", "unknown key (expected one of: centre, direction, inertia, joints,"),
    ("unknown-key-in-settings", P, [set_("dynamics.flywheels", 1)],
     "dynamics.flywheels", "unknown key"),
    # variant
    ("length-unit-choice", P, [set_("variant.length_unit", "cm")],
     "variant.length_unit", "expected one of 'm', 'mm' (got 'cm')"),
    ("variant-name-number", P, [set_("variant.name", 7)],
     "variant.name", "expected a string (got int 7)"),
    ("variant-description-bool", P, [set_("variant.description", True)],
     "variant.description", "expected a string (got boolean True)"),
    # frame
    ("frame-missing-link", P, [drop("frame.link")], "frame.link", "missing required key"),
    ("frame-missing-points", P, [drop("frame.points")], "frame.points", "missing required key"),
    ("frame-link-word", P, [set_("frame.link", "frame")],
     "frame.link", 'expected a link number like "2"'),
    ("frame-link-bool", P, [set_("frame.link", True)],
     "frame.link", "expected a string (got boolean True)"),
    ("frame-points-array", P, [set_("frame.points", [[0, 0]])],
     "frame.points", "expected a table (got array)"),
    ("frame-points-empty", P, [set_("frame.points", {})],
     "frame.points", "expected at least one fixed point"),
    ("frame-point-bad-name", P, [set_("frame.points.1O", [1, 1])],
     "frame.points.1O", "expected a point name like 'A', 'S2', 'O3' (got '1O')"),
    ("frame-point-3-coords", P, [set_("frame.points.O", [0, 0, 0])],
     "frame.points.O", "expected 2 items (got 3)"),
    ("frame-point-not-array", P, [set_("frame.points.O", 0)],
     "frame.points.O", "expected an array (got int)"),
    ("frame-point-string-coord", P, [set_("frame.points.O", ["0", 0])],
     "frame.points.O[0]", "expected a number (got string '0')"),
    ("frame-point-inf", P, [set_("frame.points.O", [0, math.inf])],
     "frame.points.O[1]", "expected a finite number (got inf)"),
    ("frame-point-beyond-1-km", P, [set_("frame.points.O", [0, 2e6])],
     "frame.points.O[1]", "must be <= 1000000.0 (got 2000000.0)"),  # mm: 1 km = 1e6 mm
    ("frame-point-huge-integer", P, [set_("frame.points.O", [-(10**400), 0])],
     "frame.points.O[0]", "expected a finite number (got an integer of 401 digits)"),
    # crank
    ("crank-missing-length", P, [drop("crank.length")], "crank.length", "missing required key"),
    ("crank-missing-rpm", P, [drop("crank.rpm")], "crank.rpm", "missing required key"),
    ("crank-missing-joints", P, [drop("crank.joints")], "crank.joints", "missing required key"),
    ("crank-is-frame", P, [set_("crank.link", "4")],
     "crank.link", "the crank cannot be the frame link '4'"),
    ("crank-link-number-ok-but-negative", P, [set_("crank.link", -1)],
     "crank.link", "expected a link number like \"2\" (got '-1')"),
    ("crank-joints-three", P, [set_("crank.joints", ["O", "A", "B"])],
     "crank.joints", "expected 2 items (got 3)"),
    ("crank-joints-string", P, [set_("crank.joints", "OA")],
     "crank.joints", "expected an array (got string)"),
    ("crank-pivot-unknown", P, [set_("crank.joints", ["Q", "A"])],
     "crank.joints[0]", "point 'Q' is not defined before this (known: O)"),
    ("crank-pin-redefines-pivot", P, [set_("crank.joints", ["O", "O"])],
     "crank.joints[1]", "point 'O' is already defined; a new joint needs a new name"),
    ("crank-pin-bad-name", P, [set_("crank.joints", ["O", "A-1"])],
     "crank.joints[1]", "expected a point name"),
    ("crank-length-negative", P, [set_("crank.length", -80)],
     "crank.length", "must be > 0 (got -80)"),
    ("crank-length-zero", P, [set_("crank.length", 0)], "crank.length", "must be > 0 (got 0)"),
    ("crank-length-negative-zero", P, [set_("crank.length", -0.0)],
     "crank.length", "must be > 0 (got -0.0)"),
    ("crank-length-string", P, [set_("crank.length", "80")],
     "crank.length", "expected a number (got string '80')"),
    ("crank-length-bool", P, [set_("crank.length", True)],
     "crank.length", "expected a number (got boolean True)"),
    ("crank-length-array", P, [set_("crank.length", [80])],
     "crank.length", "expected a number (got array [80])"),
    ("crank-length-nan", P, [set_("crank.length", math.nan)],
     "crank.length", "expected a finite number (got nan)"),
    ("crank-length-inf", P, [set_("crank.length", math.inf)],
     "crank.length", "expected a finite number (got inf)"),
    ("crank-length-minus-inf", P, [set_("crank.length", -math.inf)],
     "crank.length", "expected a finite number (got -inf)"),
    ("crank-rpm-zero", P, [set_("crank.rpm", 0)], "crank.rpm", "must be > 0 (got 0)"),
    ("crank-rpm-negative", P, [set_("crank.rpm", -55.5)],
     "crank.rpm", "must be > 0 (got -55.5)"),
    ("crank-rpm-above-limit", P, [set_("crank.rpm", 1e200)],
     "crank.rpm", "must be <= 100000.0 (got 1e+200)"),
    ("crank-length-beyond-1-km", P, [set_("crank.length", 1e6 + 1)],
     "crank.length", "must be <= 1000000.0 (got 1000001.0)"),
    ("crank-direction", P, [set_("crank.direction", "clockwise")],
     "crank.direction", "expected one of 'ccw', 'cw' (got 'clockwise')"),
    ("crank-direction-number", P, [set_("crank.direction", 1)],
     "crank.direction", "expected a string (got int 1)"),
    # points
    ("points-not-array", P, [set_("points", 3)], "points", "expected an array (got int)"),
    ("points-a-table", P, [set_("points", {"name": "S2"})],
     "points", "expected an array (got table)"),
    ("point-not-table", P, [set_("points[0]", "S2")],
     "points[0]", "expected a table (got string)"),
    ("point-unknown-key", P, [set_("points[1].alng", 1.0)],
     "points[1].alng", "unknown key (expected one of: across, along, fraction, from,"),
    ("point-missing-name", P, [drop("points[1].name")], "points[1].name", "missing required key"),
    ("point-missing-link", P, [drop("points[1].link")], "points[1].link", "missing required key"),
    ("point-missing-from", P, [drop("points[1].from")], "points[1].from", "missing required key"),
    ("point-link-word", P, [set_("points[1].link", "slider")],
     "points[1].link", 'expected a link number like "2"'),
    ("point-redefined-joint", P, [set_("points[1].name", "A")],
     "points[1].name", "point 'A' is already defined"),
    ("point-redefined-point", P, [set_("points[1].name", "S2")],
     "points[1].name", "point 'S2' is already defined"),
    ("point-from-not-on-link", P, [set_("points[1].from", "A")],
     "points[1].from", "point 'A' is not on link '3' (its points: B)"),
    ("point-toward-not-on-link", P, [set_("points[0].toward", "O")],
     "points[0].toward", "point 'O' is not on link '2' (its points: A, B)"),
    ("point-toward-is-from", P, [set_("points[0].toward", "A")],
     "points[0].toward", "must differ from 'from'"),
    ("point-fraction-without-toward", P, [set_("points[1].fraction", 0.5)],
     "points[1].fraction", "needs 'toward'"),
    ("point-fraction-and-along", P, [set_("points[0].along", 10)],
     "points[0].fraction", "give either 'fraction' or 'along', not both"),
    ("point-fraction-string", P, [set_("points[0].fraction", "35%")],
     "points[0].fraction", "expected a number (got string '35%')"),
    ("point-along-nan", P, [set_("points[1].along", math.nan)],
     "points[1].along", "expected a finite number (got nan)"),
    ("point-across-bool", P, [set_("points[1].across", False)],
     "points[1].across", "expected a number (got boolean False)"),
    ("point-along-beyond-1-km", P, [set_("points[1].along", -2e6)],
     "points[1].along", "must be >= -1000000.0 (got -2000000.0)"),
    ("point-fraction-above-100", P, [set_("points[0].fraction", 101)],
     "points[0].fraction", "must be <= 100 (got 101)"),
    ("point-on-unknown-link", P, [set_("points[1].link", "9")],
     "points[1].link", "link '9' is not a link of this mechanism (links: 4, 1, 2, 3)"),
    # dyads
    ("dyads-table", P, [set_("dyads", {"kind": "RRP"})],
     "dyads", "expected an array (got table)"),
    ("dyads-empty", P, [set_("dyads", [])], "dyads", "expected at least 1 items (got 0)"),
    ("dyad-not-table", P, [set_("dyads[0]", "RRP")],
     "dyads[0]", "expected a table (got string)"),
    ("dyad-missing-kind", P, [drop("dyads[0].kind")], "dyads[0].kind", "missing required key"),
    ("dyad-kind-unknown", P, [set_("dyads[0].kind", "RRX")],
     "dyads[0].kind", "expected one of 'RRR', 'RRP', 'RPR', 'PRP', 'RPP' (got 'RRX')"),
    ("dyad-kind-lowercase", P, [set_("dyads[0].kind", "rrp")], "dyads[0].kind", "(got 'rrp')"),
    ("dyad-unknown-key", P, [set_("dyads[0].lengths", [200, 100])],
     "dyads[0].lengths", "unknown key (expected one of: branch, guide, joints, kind, length,"),
    ("dyad-key-of-other-kind", F, [set_("dyads[0].guide", {"link": "4", "through": [0, 0]})],
     "dyads[0].guide", "unknown key"),
    ("dyad-missing-links", P, [drop("dyads[0].links")], "dyads[0].links", "missing required key"),
    ("dyad-missing-joints", P, [drop("dyads[0].joints")],
     "dyads[0].joints", "missing required key"),
    ("rrp-missing-length", P, [drop("dyads[0].length")],
     "dyads[0].length", "missing required key"),
    ("rrp-missing-guide", P, [drop("dyads[0].guide")], "dyads[0].guide", "missing required key"),
    ("rrr-missing-lengths", F, [drop("dyads[0].lengths")],
     "dyads[0].lengths", "missing required key"),
    ("prp-missing-guides", P,
     [set_("dyads[0]", {"kind": "PRP", "links": ["2", "3"], "joints": ["B"]})],
     "dyads[0].guides", "missing required key"),
    ("rpp-missing-guide", P,
     [set_("dyads[0]", {"kind": "RPP", "links": ["2", "3"], "joints": ["A", "B"]})],
     "dyads[0].guide", "missing required key"),
    ("dyad-links-three", P, [set_("dyads[0].links", ["2", "3", "5"])],
     "dyads[0].links", "expected 2 items (got 3)"),
    ("dyad-link-word", P, [set_("dyads[0].links", ["2", "ram"])],
     "dyads[0].links[1]", "expected a link number like \"2\" (got 'ram')"),
    ("dyad-link-float", P, [set_("dyads[0].links", [2.0, 3])],
     "dyads[0].links[0]", "expected a string (got float 2.0)"),
    ("rrp-joints-three", P, [set_("dyads[0].joints", ["A", "B", "C"])],
     "dyads[0].joints", "expected 2 items (got 3)"),
    ("rrr-joints-two", F, [set_("dyads[0].joints", ["A", "B"])],
     "dyads[0].joints", "expected 3 items (got 2)"),
    ("dyad-anchor-unknown", P, [set_("dyads[0].joints", ["X", "B"])],
     "dyads[0].joints[0]", "point 'X' is not defined before this (known: O, A)"),
    ("dyad-new-joint-redefined", P, [set_("dyads[0].joints", ["A", "O"])],
     "dyads[0].joints[1]", "point 'O' is already defined; a new joint needs a new name"),
    ("rrr-new-joint-redefined", F, [set_("dyads[0].joints", ["A", "C", "O"])],
     "dyads[0].joints[1]", "point 'C' is already defined"),
    ("rrr-joints-not-distinct", F, [set_("dyads[0].joints", ["A", "B", "A"])],
     "dyads[0].joints", "joints must be distinct (got ['A', 'B', 'A'])"),
    ("dyad-joint-number", P, [set_("dyads[0].joints", ["A", 2])],
     "dyads[0].joints[1]", "expected a string (got int 2)"),
    ("dyad-branch-word", P, [set_("dyads[0].branch", "up")],
     "dyads[0].branch", "expected one of '+', '-' (got 'up')"),
    ("dyad-branch-number", P, [set_("dyads[0].branch", 1)],
     "dyads[0].branch", "expected a string (got int 1)"),
    ("rrr-lengths-one", F, [set_("dyads[0].lengths", [0.35])],
     "dyads[0].lengths", "expected 2 items (got 1)"),
    ("rrr-length-negative", F, [set_("dyads[0].lengths", [0.35, -0.25])],
     "dyads[0].lengths[1]", "must be > 0 (got -0.25)"),
    ("rrr-length-zero", F, [set_("dyads[0].lengths", [0, 0.25])],
     "dyads[0].lengths[0]", "must be > 0 (got 0)"),
    ("rrr-length-string", F, [set_("dyads[0].lengths", ["0.35", 0.25])],
     "dyads[0].lengths[0]", "expected a number (got string '0.35')"),
    ("rrp-length-negative", P, [set_("dyads[0].length", -200)],
     "dyads[0].length", "must be > 0 (got -200)"),
    ("rrp-length-zero", P, [set_("dyads[0].length", 0.0)],
     "dyads[0].length", "must be > 0 (got 0.0)"),
    ("rrp-length-nan", P, [set_("dyads[0].length", math.nan)],
     "dyads[0].length", "expected a finite number (got nan)"),
    ("rrp-length-bool", P, [set_("dyads[0].length", False)],
     "dyads[0].length", "expected a number (got boolean False)"),
    ("rpr-offset-string", P,
     [set_("dyads[0]", {"kind": "RPR", "links": ["2", "3"], "joints": ["A", "O"],
                        "offset": "10"})],
     "dyads[0].offset", "expected a number (got string '10')"),
    ("rpr-offset-beyond-1-km", F,
     [set_("dyads[0]", {"kind": "RPR", "links": ["2", "3"], "joints": ["A", "C"],
                        "offset": -1001})],
     "dyads[0].offset", "must be >= -1000.0 (got -1001)"),  # the four-bar is in metres
    ("rrr-length-beyond-1-km", F, [set_("dyads[0].lengths", [0.35, 1e200])],
     "dyads[0].lengths[1]", "must be <= 1000.0 (got 1e+200)"),
    # guides
    ("guide-not-table", P, [set_("dyads[0].guide", "4")],
     "dyads[0].guide", "expected a table (got string)"),
    ("guide-unknown-key", P, [set_("dyads[0].guide.angel", 90)],
     "dyads[0].guide.angel", "unknown key (expected one of: angle, link, through, toward)"),
    ("guide-missing-through", P, [drop("dyads[0].guide.through")],
     "dyads[0].guide.through", "missing required key"),
    ("guide-missing-link", P, [drop("dyads[0].guide.link")],
     "dyads[0].guide.link", "missing required key"),
    ("guide-on-own-slider", P, [set_("dyads[0].guide.link", "3")],
     "dyads[0].guide.link", "link '3' is not defined before this dyad (known: 4, 1)"),
    ("guide-coords-on-moving-link", P, [set_("dyads[0].guide.link", "1")],
     "dyads[0].guide.through", "coordinates are allowed for a frame guide only"),
    ("guide-point-not-on-link", P, [set_("dyads[0].guide", {"link": "1", "through": "B"})],
     "dyads[0].guide.through", "point 'B' is not on link '1' (its points: O, A)"),
    ("guide-through-number", P, [set_("dyads[0].guide.through", 0)],
     "dyads[0].guide.through", "expected a string (got int 0)"),
    ("guide-through-3-coords", P, [set_("dyads[0].guide.through", [0, 0, 0])],
     "dyads[0].guide.through", "expected 2 items (got 3)"),
    ("guide-angle-and-toward", P, [set_("dyads[0].guide.toward", "O")],
     "dyads[0].guide", "give either 'angle' or 'toward', not both"),
    ("guide-toward-not-on-link", P,
     [set_("dyads[0].guide", {"link": "1", "through": "O", "toward": "B"})],
     "dyads[0].guide.toward", "expected another point of link '1' (its points: O, A)"),
    ("guide-toward-is-through", P,
     [set_("dyads[0].guide", {"link": "1", "through": "O", "toward": "O"})],
     "dyads[0].guide.toward", "expected another point of link '1'"),
    ("guide-angle-string", P, [set_("dyads[0].guide.angle", "-90")],
     "dyads[0].guide.angle", "expected a number (got string '-90')"),
    ("guide-angle-inf", P, [set_("dyads[0].guide.angle", -math.inf)],
     "dyads[0].guide.angle", "expected a finite number (got -inf)"),
    ("prp-guides-one", P,
     [set_("dyads[0]", {"kind": "PRP", "links": ["2", "3"], "joints": ["B"],
                        "guides": [{"link": "1", "through": "A", "angle": 90}]})],
     "dyads[0].guides", "expected 2 items (got 1)"),
    ("prp-second-guide-not-table", P,
     [set_("dyads[0]", {"kind": "PRP", "links": ["2", "3"], "joints": ["B"],
                        "guides": [{"link": "1", "through": "A", "angle": 90}, 0]})],
     "dyads[0].guides[1]", "expected a table (got int)"),
    ("rpp-slot-parallel", P,
     [set_("dyads[0]", {"kind": "RPP", "links": ["2", "3"], "joints": ["A", "D"],
                        "guide": {"link": "4", "through": [0, 0]}, "slot_angle": 180})],
     "dyads[0].slot_angle", "the slot must not be parallel to the guide (got 180°)"),
    ("rpp-slot-zero", P,
     [set_("dyads[0]", {"kind": "RPP", "links": ["2", "3"], "joints": ["A", "D"],
                        "guide": {"link": "4", "through": [0, 0]}, "slot_angle": 0})],
     "dyads[0].slot_angle", "must not be parallel"),
    # links (masses)
    ("links-not-table", P, [set_("links", [1])], "links", "expected a table (got array)"),
    ("links-frame", P, [set_("links.4", {"mass": 1.0, "centre": "O"})],
     "links.4", "not a moving link of this mechanism (moving links: 1, 2, 3)"),
    ("links-unknown", P, [set_("links.9", {"mass": 1.0})],
     "links.9", "not a moving link of this mechanism"),
    ("links-word", P, [set_("links.rod", {"mass": 1.0})],
     "links.rod", 'expected a link number like "2"'),
    ("links-props-not-table", P, [set_("links.2", 129)],
     "links.2", "expected a table (got int)"),
    ("links-unknown-key", P, [set_("links.2.masse", 1)],
     "links.2.masse", "unknown key (expected one of: centre, inertia, mass, weight)"),
    ("mass-negative", P, [set_("links.3.mass", -1250)],
     "links.3.mass", "must be >= 0 (got -1250)"),
    ("mass-string", P, [set_("links.3.mass", "1250 kg")],
     "links.3.mass", "expected a number (got string '1250 kg')"),
    ("inertia-negative", P, [set_("links.2.inertia", -0.5)],
     "links.2.inertia", "must be >= 0 (got -0.5)"),
    ("mass-above-limit", P, [set_("links.3.mass", 2e9)],
     "links.3.mass", "must be <= 1000000000.0 (got 2000000000.0)"),
    ("inertia-above-limit", P, [set_("links.2.inertia", 1e13)],
     "links.2.inertia", "must be <= 1000000000000.0 (got 10000000000000.0)"),
    ("mass-without-centre", P, [drop("links.3.centre")],
     "links.3.centre", "a link with mass needs its centre of mass point"),
    ("centre-not-on-link", P, [set_("links.3.centre", "S2")],
     "links.3.centre", "point 'S2' is not on link '3' (its points: B, S3)"),
    ("crank-mass-twice", P, [set_("crank.mass", 10), set_("crank.centre", "O"),
                             set_("links.1", {"mass": 10, "centre": "O"})],
     "links.1", "crank mass given twice (in [crank] and [links])"),
    ("crank-mass-without-centre", P, [set_("crank.mass", 10)],
     "links.1.centre", "a link with mass needs its centre of mass point"),
    # gravity
    ("gravity-enabled-string", P, [set_("gravity.enabled", "yes")],
     "gravity.enabled", "expected true or false (got string 'yes')"),
    ("gravity-enabled-int", P, [set_("gravity.enabled", 1)],
     "gravity.enabled", "expected true or false (got int 1)"),
    ("gravity-g-negative", P, [set_("gravity.g", -9.81)], "gravity.g", "must be >= 0 (got -9.81)"),
    ("gravity-g-above-limit", P, [set_("gravity.g", 1e4)],
     "gravity.g", "must be <= 1000.0 (got 10000.0)"),
    ("gravity-angle-nan", P, [set_("gravity.angle", math.nan)],
     "gravity.angle", "expected a finite number (got nan)"),
    # output
    ("output-not-table", P, [set_("output", "3")], "output", "expected a table (got string)"),
    ("output-link-unknown", P, [set_("output.link", "9")],
     "output.link", "link '9' is not defined before this (known: 4, 1, 2, 3)"),
    ("output-link-frame", P, [set_("output.link", "4")],
     "output.link", "the output cannot be the frame"),
    ("output-working", P, [set_("output.working", "down")],
     "output.working", "expected one of '+', '-' (got 'down')"),
    # loads
    ("loads-table", P, [set_("loads", {"kind": "force"})],
     "loads", "expected an array (got table)"),
    ("load-not-table", P, [set_("loads[0]", 600000)], "loads[0]", "expected a table (got int)"),
    ("load-unknown-key", P, [set_("loads[0].maximum", 1)],
     "loads[0].maximum", "unknown key (expected one of: angle, bore, diagram, kind, link, max, "
     "name, over, p_ambient, p_max, phase, point, pressure_unit, rod, sense, stroke, strokes, "
     "travel, travel_link, unit, value, working)"),
    ("load-missing-max", P, [drop("loads[0].max")], "loads[0].max", "missing required key"),
    ("load-missing-diagram", P, [drop("loads[0].diagram")],
     "loads[0].diagram", "missing required key: 'diagram'"),
    ("load-kind", P, [set_("loads[0].kind", "torque")],
     "loads[0].kind", "expected one of 'force', 'moment' (got 'torque')"),
    ("load-link-unknown", P, [set_("loads[0].link", "7")],
     "loads[0].link", "link '7' is not a link of this mechanism (moving links: 1, 2, 3)"),
    ("load-on-frame", P, [set_("loads[0].link", "4")],
     "loads[0].link", "a load acts on a moving link, not the frame"),
    ("force-without-point", P, [drop("loads[0].point")],
     "loads[0].point", "missing required key (the point the force acts at)"),
    ("force-point-not-on-link", P, [set_("loads[0].point", "A")],
     "loads[0].point", "point 'A' is not on link '3' (its points: B, S3)"),
    # loads act on any link now (issue 17); what is still refused:
    ("force-on-rod-no-direction", P,
     [set_("loads[0].link", "2"), set_("loads[0].point", "S2"), set_("loads[0].sense", "diagram")],
     "loads[0].angle", "missing: the direction of the force (degrees) — link '2' does not "
                       "slide on a frame guide to give one"),
    ("moment-with-point", P, [set_("loads[0].kind", "moment")],
     "loads[0].point", "a moment load has no point"),
    ("moment-on-slider", P, [set_("loads[0].kind", "moment"), drop("loads[0].point")],
     "loads[0].link", "a couple on link '3', which only translates on a frame guide, does "
                      "no work"),
    ("load-sense", P, [set_("loads[0].sense", "helps")],
     "loads[0].sense", "expected one of 'resists', 'drives', 'diagram' (got 'helps')"),
    ("load-diagram-short-of-stroke", P, [set_("loads[0].diagram", [[0.0, 0.0], [0.9, 1.0]])],
     "loads[0].diagram", "the diagram does not cover the stroke (travel 0 … 1): it runs from "
                         "0 to 0.9"),
    ("load-diagram-late-start", P, [set_("loads[0].diagram", [[0.1, 0.0], [1.0, 1.0]])],
     "loads[0].diagram", "the diagram does not cover the stroke (travel 0 … 1): it runs from "
                         "0.1 to 1"),
    ("load-crank-diagram-short", P,
     [set_("loads[0].over", "crank"), set_("loads[0].diagram", [[0, 1.0], [300, 1.0]])],
     "loads[0].diagram", "the diagram does not cover the cycle (crank angle 0 … 360°): it "
                         "runs from 0 to 300"),
    ("load-strokes-count", P,
     [drop("loads[0].diagram"), set_("loads[0].strokes", [[[0, 1], [1, 1]]] * 4)],
     "loads[0].strokes", "expected 2 diagrams, one per stroke of the 360° cycle (got 4) "
                         "(4 strokes: a four-stroke cycle needs positions.cycle = 720)"),
    ("cycle-720-without-process", P, [set_("positions.cycle", 720)],
     "positions.cycle", "a 720° cycle needs a process over two turns"),
    ("cycle-540", P, [set_("positions.cycle", 540)],
     "positions.cycle", "expected 360 (one turn) or 720"),
    ("load-diagram-and-strokes", P, [set_("loads[0].strokes", [[[0, 1], [1, 1]], []])],
     "loads[0].diagram", "give either 'diagram'"),
    ("load-value-and-max", P, [set_("loads[0].value", 10)],
     "loads[0].max", "a constant load is given by 'value' alone"),
    ("gas-on-rod", P, [set_("loads", [{"link": "2", "point": "S2", "bore": 80,
                                        "diagram": [[0, 1], [1, 1]]}])],
     "loads[0].link", "a gas force (bore) acts on a piston sliding in a frame guide"),
    ("gas-with-max", P, [set_("loads[0].bore", 80)],
     "loads[0].max", "a gas force is p·πD²/4"),
    ("pressure-unit", P, [drop("loads[0].max"), set_("loads[0].bore", 80),
                          set_("loads[0].pressure_unit", "psi")],
     "loads[0].pressure_unit", "expected one of 'Pa', 'kPa', 'MPa', 'bar', 'atm', 'kgf/cm2'"),
    ("load-angle-resisting", P, [set_("loads[0].angle", 90)],
     "loads[0].angle", "the direction 'angle' goes with a force of sense = \"diagram\""),
    ("load-name-twice", P, [set_("loads[0].name", "Q"),
                            set_("loads[1]", {"name": "Q", "kind": "moment", "link": "2",
                                              "value": 1.0})],
     "loads[1].name", "name 'Q' is already used by another load"),
    ("weight-and-mass", P, [set_("links.2.weight", 100)],
     "links.2.weight", "give either 'mass' (kg) or 'weight' (N), not both"),
    ("crank-rpm-and-omega", P, [set_("crank.omega", 10)],
     "crank.omega", "give the crank speed once"),
    ("load-max-negative", P, [set_("loads[0].max", -600000)],
     "loads[0].max", "must be >= 0 (got -600000)"),
    ("load-max-above-limit", P, [set_("loads[0].max", 1e13)],
     "loads[0].max", "must be <= 1000000000000.0 (got 10000000000000.0)"),
    ("load-diagram-one-pair", P, [set_("loads[0].diagram", [[0.0, 1.0]])],
     "loads[0].diagram", "expected at least 2 items (got 1)"),
    ("load-diagram-not-pair", P, [set_("loads[0].diagram[1]", [0.5])],
     "loads[0].diagram[1]", "expected 2 items (got 1)"),
    ("load-diagram-travel-above-1", P, [set_("loads[0].diagram[1]", [1.5, 0.0])],
     "loads[0].diagram[1][0]", "must be <= 1.0 (got 1.5)"),
    ("load-diagram-force-negative", P, [set_("loads[0].diagram[1]", [0.5, -0.1])],
     "loads[0].diagram[1][1]", "must be >= 0.0 (got -0.1)"),
    ("load-diagram-decreasing", P, [set_("loads[0].diagram[2]", [0.5, 1.0])],
     "loads[0].diagram[2][0]", "the abscissae must not decrease (got 0.5 after 0.88513)"),
    # positions
    ("positions-not-table", P, [set_("positions", 8)], "positions", "expected a table (got int)"),
    ("count-zero", P, [set_("positions.count", 0)],
     "positions.count", "must be from 1 to 3600 (got 0)"),
    ("count-too-many", P, [set_("positions.count", 3601)],
     "positions.count", "must be from 1 to 3600 (got 3601)"),
    ("count-float", P, [set_("positions.count", 8.0)],
     "positions.count", "expected a whole number (got float 8.0)"),
    ("count-bool", P, [set_("positions.count", True)],
     "positions.count", "expected a whole number (got boolean True)"),
    ("first-word", P, [set_("positions.first", "middle")],
     "positions.first", "expected one of 'start', 'end' (got 'middle')"),
    ("first-array", P, [set_("positions.first", [0])],
     "positions.first", "expected a number (got array [0])"),
    ("first-inf", P, [set_("positions.first", math.inf)],
     "positions.first", "expected a finite number (got inf)"),
    ("number-from-2", P, [set_("positions.number_from", 2)],
     "positions.number_from", "must be from 0 to 1 (got 2)"),
    ("extra-not-array", P, [set_("positions.extra", {"label": "x"})],
     "positions.extra", "expected an array (got table)"),
    ("extra-not-table", P, [set_("positions.extra[0]", "(2)")],
     "positions.extra[0]", "expected a table (got string)"),
    ("extra-unknown-key", P, [set_("positions.extra[0].angle", 10)],
     "positions.extra[0].angle", "unknown key (expected one of: from, label, phi, stroke, turn)"),
    ("extra-missing-label", P, [drop("positions.extra[1].label")],
     "positions.extra[1].label", "missing required key"),
    ("extra-label-number", P, [set_("positions.extra[0].label", 2)],
     "positions.extra[0].label", "expected a string (got int 2)"),
    ("extra-label-blank", P, [set_("positions.extra[0].label", "  ")],
     "positions.extra[0].label", "must not be empty"),
    ("extra-label-two-lines", P, [set_("positions.extra[0].label", "(2)\nbis")],
     "positions.extra[0].label", "expected a one-line label (got '(2)\\nbis')"),
    ("extra-label-duplicates-numbered", P, [set_("positions.extra[0].label", "8")],
     "positions.extra[0].label", "label '8' is already used"),
    ("extra-label-duplicates-extra", P, [set_("positions.extra[1].label", "(2)")],
     "positions.extra[1].label", "label '(2)' is already used"),
    ("extra-two-ways", P, [set_("positions.extra[0].phi", 30)],
     "positions.extra[0]", "give exactly one of 'phi' (crank angle, °), 'from' (dead centre "
                           "with 'turn'), 'stroke' (travel fraction of the working stroke)"),
    ("extra-three-ways", P, [set_("positions.extra[0].phi", 30),
                             set_("positions.extra[0].stroke", 0.5)],
     "positions.extra[0]", "give exactly one of"),
    ("extra-no-way", P, [set_("positions.extra[0]", {"label": "x"})],
     "positions.extra[0]", "give exactly one of"),
    ("extra-turn-without-from", P,
     [set_("positions.extra[0]", {"label": "x", "phi": 10, "turn": 5})],
     "positions.extra[0].turn", "goes with 'from'"),
    ("extra-phi-string", P, [set_("positions.extra[0]", {"label": "x", "phi": "10"})],
     "positions.extra[0].phi", "expected a number (got string '10')"),
    ("extra-from-word", P, [set_("positions.extra[0].from", "bottom")],
     "positions.extra[0].from", "expected one of 'start', 'end' (got 'bottom')"),
    ("extra-turn-too-big", P, [set_("positions.extra[0].turn", -400)],
     "positions.extra[0].turn", "must be >= -360 (got -400)"),
    ("extra-stroke-negative", P, [set_("positions.extra[0]", {"label": "x", "stroke": -0.5})],
     "positions.extra[0].stroke", "must be >= 0.0 (got -0.5)"),
    ("extra-stroke-above-1", P, [set_("positions.extra[0]", {"label": "x", "stroke": 2})],
     "positions.extra[0].stroke", "must be <= 1.0 (got 2)"),
    # settings of later stages
    ("neglect-below-above-1", P, [set_("kinetostatics.neglect_below", 10)],
     "kinetostatics.neglect_below", "must be <= 1.0 (got 10)"),
    ("kin-inertia-string", P, [set_("kinetostatics.inertia", "true")],
     "kinetostatics.inertia", "expected true or false (got string 'true')"),
    ("kin-shift-int", P, [set_("kinetostatics.shift_inertia_force", 0)],
     "kinetostatics.shift_inertia_force", "expected true or false (got int 0)"),
    ("delta-zero", P, [set_("dynamics.delta", 0)], "dynamics.delta", "must be > 0 (got 0)"),
    ("delta-above-1", P, [set_("dynamics.delta", 1.5)],
     "dynamics.delta", "must be <= 1.0 (got 1.5)"),
    ("efficiency-negative", P, [set_("dynamics.efficiency", -0.85)],
     "dynamics.efficiency", "must be > 0 (got -0.85)"),
    ("crank-inertia-negative", P, [set_("dynamics.crank_inertia", -1)],
     "dynamics.crank_inertia", "must be >= 0 (got -1)"),
    ("grid-too-small", P, [set_("dynamics.grid", 6)],
     "dynamics.grid", "must be from 12 to 100000 (got 6)"),
    ("kl-zero", P, [set_("drawing", {"Kl": 0})], "drawing.Kl", "must be > 0 (got 0)"),
    ("ka-string", P, [set_("drawing", {"Ka": "0.02"})],
     "drawing.Ka", "expected a number (got string '0.02')"),
    ("reading-mm-too-big", P, [set_("drawing", {"reading_mm": 6})],
     "drawing.reading_mm", "must be <= 5.0 (got 6)"),
    ("drawing-format", P, [set_("drawing", {"format": "A4"})],
     "drawing.format", "expected one of 'A1', 'A2', 'A3' (got 'A4')"),
    ("drawing-language", P, [set_("drawing", {"language": "de"})],
     "drawing.language", "expected one of 'ru', 'en' (got 'de')"),
    ("title-sheets-zero", P, [set_("title_block.sheets", 0)],
     "title_block.sheets", "must be from 1 to 99 (got 0)"),
    ("title-author-number", P, [set_("title_block.author", 5)],
     "title_block.author", "expected a string (got int 5)"),
]


@pytest.mark.parametrize(
    ("base", "edits", "path", "expected"),
    [c[1:] for c in CASES],
    ids=[c[0] for c in CASES],
)
def test_loader_error(base, edits, path, expected):
    msg = input_error(build(base, *edits))
    assert msg.startswith(f"{SRC}: {path}: "), msg
    assert expected in msg, msg


def test_case_ids_are_unique():
    ids = [c[0] for c in CASES]
    assert len(ids) == len(set(ids))


def test_unit_mm_is_applied_before_checks_and_reported_as_given():
    # the message shows the value as written in the file, not the converted one
    msg = input_error(build(PRESS, set_("dyads[0].length", -0.5)))
    assert msg == f"{SRC}: dyads[0].length: must be > 0 (got -0.5)"


def test_nan_written_in_toml_text():
    text = PRESS_TEXT.replace("length = 200 ", "length = nan ", 1)
    assert text != PRESS_TEXT
    msg = input_error(text)
    assert msg == f"{SRC}: dyads[0].length: expected a finite number (got nan)"


def test_inf_written_in_toml_text():
    text = PRESS_TEXT.replace("rpm = 55 ", "rpm = +inf ", 1)
    assert text != PRESS_TEXT
    msg = input_error(text)
    assert msg == f"{SRC}: crank.rpm: expected a finite number (got inf)"


def test_unknown_key_lists_the_allowed_keys_on_the_same_line():
    msg = input_error(build(PRESS, set_("gravity.on", True)))
    assert msg == f"{SRC}: gravity.on: unknown key (expected one of: angle, enabled, g)"


def test_string_values_with_newlines_stay_on_one_line():
    # a value is shown with repr(), so a newline in it is escaped
    msg = input_error(build(PRESS, set_("crank.direction", "c\ncw")))
    assert msg == f"{SRC}: crank.direction: expected one of 'ccw', 'cw' (got 'c\\ncw')"


# -- analysis errors: structure, assembly, lock-up ------------------------------------------


def analysis_error(text: str, exc_type):
    """Load (must succeed), then run structure and cycle; return the one-line message."""
    m = g.loads(text, source=SRC)
    with pytest.raises(exc_type) as ei:
        g.analyse_structure(m)
        g.analyse_cycle(m)
    msg = str(ei.value)
    assert_one_line(msg)
    return msg, ei.value


SECOND_DYAD = {
    "kind": "RRP", "links": ["3", "5"], "joints": ["B", "D"], "length": 0.3,
    "guide": {"link": "4", "through": [0.0, 0.0], "angle": 0},
}


def test_dyad_reusing_a_link_has_mobility_not_1():
    msg, _ = analysis_error(build(FOURBAR, set_("dyads[1]", SECOND_DYAD)), g.StructureError)
    assert "W = 3·n − 2·p5 − p4 = 3·4 − 2·7 − 0 = -2" in msg
    assert "needs W = 1" in msg


def test_dyad_reusing_the_rod_of_the_press():
    # a second RRP hung on the rod's centre S2 whose slider is the rod itself
    dyad = {**SECOND_DYAD, "links": ["5", "2"], "joints": ["S2", "D"]}
    msg, _ = analysis_error(build(PRESS, set_("dyads[1]", dyad)), g.StructureError)
    assert "W =" in msg and "= -2" in msg


@pytest.mark.parametrize(
    ("links", "pair"),
    [(["1", "3"], "R A (1-1)"), (["2", "4"], "R C (4-4)"), (["2", "2"], "R B (2-2)")],
    ids=["crank-as-link-i", "frame-as-link-j", "same-link-twice"],
)
def test_dyad_link_joined_to_itself(links, pair):
    msg, _ = analysis_error(build(FOURBAR, set_("dyads[0].links", links),
                                  set_("points", []), set_("links", {}), drop("output")),
                            g.StructureError)
    assert f"pair {pair}" in msg and "to itself" in msg


def test_cycle_analysis_checks_the_structure_first():
    m = g.loads(build(FOURBAR, set_("dyads[1]", SECOND_DYAD)), source=SRC)
    with pytest.raises(g.StructureError) as ei:
        g.analyse_cycle(m)
    assert_one_line(str(ei.value))
    assert "W =" in str(ei.value)


def test_structure_error_is_not_an_input_error_but_a_graphplan_error():
    m = g.loads(build(FOURBAR, set_("dyads[1]", SECOND_DYAD)), source=SRC)
    with pytest.raises(g.GraphplanError) as ei:
        g.analyse_structure(m)
    assert type(ei.value) is g.StructureError


CRANK_SLIDER = {
    "variant": {"length_unit": "mm"},
    "frame": {"link": "4", "points": {"O": [0, 0]}},
    "crank": {"link": "1", "joints": ["O", "A"], "length": 80, "rpm": 60},
    "dyads": [{"kind": "RRP", "links": ["2", "3"], "joints": ["A", "B"], "length": 100,
               "guide": {"link": "4", "through": [30, 0], "angle": -90}}],
}


def test_crank_slider_rod_shorter_than_crank_plus_offset():
    # crank 80 + offset 30 = 110 > rod 100: A leaves the rod's reach on the far side of the
    # guide; the message names the first crank angle of the turn where it does
    msg, exc = analysis_error(dumps(CRANK_SLIDER), g.AssemblyError)
    assert not isinstance(exc, g.SingularPoseError)
    m = re.fullmatch(re.escape(f"{SRC}: dyad RRP(2-3) cannot be assembled at φ = ")
                     + r"([0-9.]+)°: the distance from A to the guide, ([0-9.]+) m, "
                     + re.escape("exceeds lAB = 0.1 m")
                     + r"; the crank cannot make a full turn: the chain closes only for φ "
                     + r"in ([0-9.]+)°…([0-9.]+)° \(([0-9.]+)°\), so link 1 can only rock "
                     + r"within that range — shorten crank.length or "
                     + r"lengthen the dyad's links", msg)
    assert m, msg
    # the reach, said with the likely fix: it closes where 30 − 80·cos φ ≤ 100, i.e.
    # cos φ ≥ −7/8: from 360° − 151.04° = 208.96° through 0° to 151.04°
    lo, hi = float(m.group(3)), float(m.group(4))
    assert lo == pytest.approx(360 - math.degrees(math.acos(-70 / 80)), abs=0.01)
    assert hi == pytest.approx(math.degrees(math.acos(-70 / 80)), abs=0.01)
    phi, dist = float(m.group(1)), float(m.group(2))
    assert 90 < phi < 180  # the crank turns ccw from 0°: it first fails before 180°
    assert 0.1 < dist <= 0.11
    # the crank angle named is where it fails: 30 − 80·cos φ = 100
    assert phi == pytest.approx(math.degrees(math.acos(-70 / 80)), abs=0.1)


def test_crank_slider_rod_shorter_than_crank():
    doc = build(CRANK_SLIDER, set_("dyads[0].guide.through", [0, 0]),
                set_("dyads[0].length", 50))
    msg, _ = analysis_error(doc, g.AssemblyError)
    assert msg.startswith(f"{SRC}: dyad RRP(2-3) cannot be assembled at φ = 0.00°: ")
    assert "the distance from A to the guide, 0.08 m, exceeds lAB = 0.05 m" in msg


def test_crank_slider_just_long_enough_assembles():
    doc = build(CRANK_SLIDER, set_("dyads[0].length", 111))
    m = g.loads(doc, source=SRC)
    cyc = g.analyse_cycle(m)
    assert cyc.stroke > 0


def test_four_bar_not_grashof_crank_cannot_turn():
    # |AC| runs over [0.2, 0.4] m but the dyad closes only for [0.15, 0.35] m
    doc = build(FOURBAR, set_("dyads[0].lengths", [0.25, 0.1]))
    msg, exc = analysis_error(doc, g.AssemblyError)
    assert not isinstance(exc, g.SingularPoseError)
    assert msg.startswith(f"{SRC}: dyad RRR(2-3) cannot be assembled at φ = ")
    assert "|AC| = " in msg
    assert "is outside [|lAB − lCB|, lAB + lCB] = [0.15, 0.35] m" in msg
    phi = float(re.search(r"φ = ([0-9.]+)°", msg).group(1))
    assert 90 < phi < 270  # on the far side from C


def test_four_bar_rocker_too_short_for_the_near_side():
    # l_AB − l_CB = 0.3 > min |AC| = 0.2: fails around φ = 0°
    doc = build(FOURBAR, set_("dyads[0].lengths", [0.5, 0.2]))
    msg, _ = analysis_error(doc, g.AssemblyError)
    assert "RRR(2-3)" in msg and "= [0.3, 0.7] m" in msg


def test_prp_with_guides_parallel_at_one_angle():
    doc = build(PRESS, set_("dyads[0]", {
        "kind": "PRP", "links": ["2", "3"], "joints": ["B"],
        "guides": [{"link": "1", "through": "A", "angle": 0},
                   {"link": "4", "through": [0, 50], "angle": 0}]}),
        set_("points", []), set_("links", {}), set_("loads", []))
    msg, _exc = analysis_error(doc, g.AssemblyError)
    assert msg == (f"{SRC}: dyad PRP(2-3) cannot be assembled at φ = 0.00°: "
                   "its two guides are parallel")


def test_prp_with_guides_always_parallel():
    doc = build(PRESS, set_("dyads[0]", {
        "kind": "PRP", "links": ["2", "3"], "joints": ["B"],
        "guides": [{"link": "4", "through": [0, 0], "angle": 30},
                   {"link": "4", "through": [0, 50], "angle": 210}]}),
        set_("points", []), set_("links", {}), set_("loads", []))
    msg, _ = analysis_error(doc, g.AssemblyError)
    assert "PRP(2-3)" in msg and "its two guides are parallel" in msg


CHANGE_POINT = {
    "frame": {"link": "4", "points": {"O": [0.0, 0.0], "C": [0.75, 0.0]}},
    "crank": {"link": "1", "joints": ["O", "A"], "length": 0.25, "rpm": 60},
    "dyads": [{"kind": "RRR", "links": ["2", "3"], "joints": ["A", "B", "C"],
               "lengths": [0.5, 0.5]}],
}


def test_lock_up_of_a_change_point_four_bar():
    # l_crank + l_frame = 0.25 + 0.75 = l_coupler + l_rocker = 0.5 + 0.5: at φ = 180° the
    # coupler and rocker are collinear, the velocity equation has parallel lines.
    msg, _ = analysis_error(dumps(CHANGE_POINT), g.SingularPoseError)
    assert msg == (f"{SRC}: dyad RRR(2-3) passes through a lock-up at φ = 180.00° "
                   "(the two lines of its vector equation are parallel)")


def test_lock_up_between_the_check_grid_points_is_found():
    # the same linkage turned so that the change point falls at φ = 123.45°, off the grid
    turn = math.radians(123.45 - 180.0)
    c = [0.75 * math.cos(turn), 0.75 * math.sin(turn)]
    doc = build(CHANGE_POINT, set_("frame.points.C", c))
    msg, _ = analysis_error(doc, g.SingularPoseError)
    assert msg.startswith(f"{SRC}: dyad RRR(2-3) passes through a lock-up at φ = "), msg
    phi = float(re.search(r"φ = ([0-9.]+)°", msg).group(1))
    assert phi == pytest.approx(123.45, abs=0.011)


def test_lock_up_is_an_assembly_error():
    assert issubclass(g.SingularPoseError, g.AssemblyError)
    assert issubclass(g.AssemblyError, g.GraphplanError)


def test_positions_from_dead_centre_of_an_output_without_one():
    # the crank as output turns fully: there are no dead centres to start from
    doc = build(FOURBAR, set_("output.link", "1"))
    msg, _ = analysis_error(doc, g.InputError)
    assert msg == (f"{SRC}: positions.first: the output link '1' has no dead centres; "
                   "give a crank angle instead")


def test_stroke_position_of_an_output_without_dead_centres():
    doc = build(FOURBAR, set_("output.link", "1"), set_("positions", {
        "first": 0, "extra": [{"label": "x", "stroke": 0.5}]}))
    msg, _ = analysis_error(doc, g.InputError)
    assert msg.startswith(f"{SRC}: positions.extra[0].stroke: the output link '1' has no dead")


# -- bugs found by these tests and fixed since: kept as regressions -----------------------------


def test_integer_too_big_for_a_float():
    # was: OverflowError from float(10**400) in _Reader.number
    msg = input_error(build(PRESS, set_("crank.length", 10**400)))
    assert msg == f"{SRC}: crank.length: expected a finite number (got an integer of 401 digits)"


def test_integer_with_too_many_digits():
    # was: ValueError (int max str digits) escaping tomllib.loads
    text = PRESS_TEXT.replace("rpm = 55 ", "rpm = 1" + "0" * 5000 + " ", 1)
    assert text != PRESS_TEXT
    msg = input_error(text)
    assert msg.startswith(f"{SRC}: not valid TOML (Exceeds the limit (4300 digits)")


@pytest.mark.parametrize(
    ("edit", "expected"),
    [
        (set_("frame.points.X\nY", [1, 1]),
         "frame.points.X\\nY: expected a point name like 'A', 'S2', 'O3' (got 'X\\nY')"),
        (set_("crank.x\ny", 1), "crank.x\\ny: unknown key"),
        (set_("crank.x\u2028y", 1), "crank.x\\u2028y: unknown key"),
        (set_("links.2\r", {}), "links.2\\r: "),
        (set_("new\nsection", 1), "new\\nsection: unknown key"),
    ],
    ids=["frame-point-name", "unknown-key", "line-separator", "links-key", "top-level-key"],
)
def test_key_with_a_line_break_is_escaped_on_one_line(edit, expected):
    # was: the raw key went into the key path and the message spanned two lines
    msg = input_error(build(PRESS, edit))
    assert msg.startswith(f"{SRC}: {expected}"), msg


@pytest.mark.parametrize(
    ("edits", "path", "got"),
    [
        ([set_("dyads[0].links", ["2\n", "3"])], "dyads[0].links[0]", "'2\\n'"),
        ([set_("crank.joints", ["O", "A\n"]), set_("dyads[0].joints", ["A\n", "B"])],
         "crank.joints[1]", "'A\\n'"),
        ([set_("frame.points.O\n", [1, 1])], "frame.points.O\\n", "'O\\n'"),
    ],
    ids=["link-2-newline", "point-A-newline", "frame-point-O-newline"],
)
def test_name_ending_in_a_newline_is_refused(edits, path, got):
    # was: NAME_RE/LINK_RE ended in '$' (matches before a final newline): the names were
    # accepted and the AssemblyError of this too-short crank-slider printed them over two lines
    msg = input_error(build(CRANK_SLIDER, *edits))
    assert msg.startswith(f"{SRC}: {path}: expected a "), msg
    assert f"(got {got})" in msg, msg


def test_guide_toward_a_point_at_its_own_through():
    # was: AssemblyError("guide of link 4: None and G coincide, ..."): no source, no dyad
    m = g.loads(build(PRESS, set_("frame.points.G", [0, 0]),
                      set_("dyads[0].guide", {"link": "4", "through": [0, 0], "toward": "G"})),
                source=SRC)
    with pytest.raises(g.AssemblyError) as ei:
        g.analyse_cycle(m)
    msg = str(ei.value)
    assert_one_line(msg)
    assert msg.startswith(f"{SRC}: dyad RRP(2-3): "), msg
    assert "toward G is undefined" in msg and "None" not in msg, msg


def test_a_group_attached_to_the_frame_only_is_refused():
    """Found by the loader's fuzz test: an RPR whose outer joints are both frame points
    crashed the kinematics with a bare ValueError (it cannot move: a truss, not a group)."""
    import graphplan as g

    doc = """
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
joints = ["C", "O"]
offset = 0.01
[output]
link = "6"
"""
    with pytest.raises(g.InputError, match=r"x\.toml: dyads\[1\]\.joints: the group is "
                                         r"attached to the frame only \(joints C, O"):
        g.loads(doc, source="x.toml")
