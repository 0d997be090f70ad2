"""Reading a student's lines: members, names of the numbers, figures, scales, verdicts.

:class:`Work` turns a :class:`~graphplan.checking.student.StudentWork` into *occurrences*
— every place a quantity is written: as the result of a line (``R43 = … = 8145,71 H``),
as another name of that result (``R41 = R12 = 424 Н``), or as a number inside an
expression, named by the line's formula (:mod:`graphplan.checking.matching`) — and
groups them into *figures* (one quantity at one position, or of the whole mechanism).

Each figure is compared with graphplan's exact value (:class:`Reference`) at the
student's own scales: a length on paper is compared at the scale the student stated, or
at a scale the student used at that position when the drawing fits it better (the seed
states ``Kl = 0,001`` and measures its arms at 0,002); that choice is reported.

Tolerances (:class:`Tolerances`): a segment measured on a plan is *ok* within
``max(segment_ok·|e|, reading_mm/2)`` and *inaccurate* within
``max(segment·|e|, reading_mm)``; a derived value within ``derived_ok``, ``derived`` of
its size, but not finer than the reading precision at its plan's scale
(``reading_mm·Kp`` for a force); a datum of the variant (a mass, g, a length) within
0.2 % and 1 %; written arithmetic within ``arithmetic`` (relative) or half a unit of the
last written digit, whichever is larger.
"""

from __future__ import annotations

import math
import re
from collections import Counter
from dataclasses import dataclass, field, fields
from itertools import pairwise
from typing import overload

from .errors import ExpressionError, UnreadableError
from .expressions import Node, Sym, decimals, parse, show, split_chain, value
from .matching import Match, match
from .quantities import SCALE_DIMENSIONS, Quantity, Vocabulary
from .reference import Reference
from .student import Line, StudentWork
from .units import Unit, fold, split_unit


@dataclass(frozen=True, slots=True)
class Tolerances:
    """Bands of the verdicts (fractions; ``reading_mm`` in mm). See the module docstring."""

    segment_ok: float = 0.005
    segment: float = 0.02
    derived_ok: float = 0.01
    derived: float = 0.05
    arithmetic: float = 0.005
    reading_mm: float = 0.5
    datum_ok: float = 0.002
    datum: float = 0.01

    @classmethod
    def of(cls, values: dict[str, float] | None) -> Tolerances:
        names = {f.name for f in fields(cls)}
        return cls(**{k: float(v) for k, v in (values or {}).items() if k in names})

    def as_dict(self) -> dict[str, float]:
        return {f.name: getattr(self, f.name) for f in fields(self)}


# --- members and lines -----------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Member:
    """One member of a chain ``a = b = c``.

    ``kind``: ``numeric`` (numbers only, ``value`` set), ``name`` (one known name),
    ``formula`` (names and numbers), ``text`` (not readable as either), ``bad`` (digits
    and signs that do not parse: ``error`` says why).
    """

    text: str
    kind: str
    node: Node | None = None
    unit: Unit | None = None
    value: float | None = None
    error: str = ""


def read_member(text: str, vocab: Vocabulary) -> Member:
    """Classify and parse one member of a written chain. Numbers that parse but have no
    finite value (``1/0``, ``ln 0``, ``1e400``: :class:`UnreadableError`) are ``bad``,
    never a formula."""
    body, unit = split_unit(text)
    try:
        node = parse(body)
        return Member(text, "numeric", node, unit, value(node))
    except UnreadableError as exc:
        return Member(text, "bad", unit=unit, error=str(exc))
    except ExpressionError as exc:
        err = str(exc)
    if not any(c.isalpha() for c in body):
        return Member(text, "bad", unit=unit, error=err)
    try:
        node = parse(text, names=True, resolve=vocab.split)
    except ExpressionError as exc:
        # a name with a dotted index, as written for the lever's moment (Мур.ж), alone
        # or in a formula ((Мур.ж − Мур)/Мур.ж∙100)
        found: Node | None = None
        for t in (text, body):
            undotted = re.sub(r"(?<=[^\W\d_])\.(?=[^\W\d_])", "_", t)
            try:
                found = parse(undotted, names=True, resolve=vocab.split)
                break
            except ExpressionError:
                continue
        if found is None:
            return Member(text, "text", error=str(exc))
        node = found
    if isinstance(node, Sym):
        return Member(text, "name", node)
    unknown = [n for n in _sym_names(node) if vocab.lookup(n) is None]
    # "9,81e": numbers with a stray letter (not a formula naming a length of its own,
    # VA3^2/lO3A)
    unknown = [n for n in unknown if re.search(r"[\d,.]\s*" + re.escape(n), text)]
    if unknown and _has_number(node):
        return Member(text, "text", error=f"{unknown[0]!r} among the numbers is no known "
                      "name")
    return Member(text, "formula", node)


@dataclass(slots=True)
class Occurrence:
    """A quantity written somewhere: its value in the quantity's unit and how it got it."""

    q: Quantity
    scope: str  # "global", a position label, or "general" (a position figure outside one)
    position: str | None  # the position of the line (None: general)
    line: Line
    role: str  # "result" | "alias" | "operand"
    raw: float  # the number as written
    value: float  # in q.unit
    prefix: int  # power of 1000 read into an unlabelled number (kN, kN·m …)
    explicit: str | None  # the unit as written, if any
    text: str  # the number (or the bracket) as written
    name: str  # the name as written
    composite: bool = False
    work: LineWork | None = None

    @property
    def where(self) -> str:
        return self.where_in("en")

    def where_in(self, lang: str) -> str:
        """``"position 2, line 68"`` / ``"положение 2, строка 68"``."""
        return where_text(self.position, self.line, lang)


@dataclass(slots=True)
class LineWork:
    """A line being read: its members, result, arithmetic and the names of its numbers."""

    line: Line
    position: str | None
    vocab: Vocabulary
    members: list[Member]
    result_q: Quantity | None = None
    result_name: str = ""
    result: Member | None = None
    expr: Member | None = None
    arithmetic: str = ""
    evaluated: float | None = None
    bad: tuple[Member, Member] | None = None
    template: Node | None = None
    matched: Match | None = None
    occs: list[Occurrence] = field(default_factory=list)
    unit_problem: str = ""
    note: str = ""


def where_text(position: str | None, line: Line, lang: str = "en") -> str:
    """Where a line is: its position (or the general part) and its line in the file."""
    if lang == "ru":
        pos = "общие данные" if position is None else f"положение {position}"
    else:
        pos = "general" if position is None else f"position {position}"
    return f"{pos}, {line.where_in(lang)}"


def _close(a: float, b: float, rel: float, abs_: float = 0.0) -> bool:
    return abs(a - b) <= max(rel * max(abs(a), abs(b)), abs_)


def _number(m: Member) -> float:
    """The value of a member read as a number (``value`` is set on those)."""
    assert m.value is not None, m.text
    return float(m.value)


def arithmetic_agrees(computed: float, written: Member, rel: float) -> bool:
    """Whether a written number is the computed one, rounded as written."""
    half = 0.5 * 10.0 ** (-decimals(written.text)) * 1.01
    return _close(computed, _number(written), rel, half)


class Work:
    """The student's work read against one variant (see the module docstring).

    Attributes
    ----------
    work : StudentWork
    ref : Reference
    tol : Tolerances
    lines : list[LineWork]
    occs : list[Occurrence]
    figures : dict[tuple[str, tuple], list[Occurrence]]
        By (scope, key): the occurrences of one figure, the stated one first.
    """

    def __init__(self, work: StudentWork, ref: Reference, tol: Tolerances):
        self.work = work
        self.ref = ref
        self.tol = tol
        self.vocab_general = ref.vocabulary(work.arms)
        self.vocab = {p.label: ref.vocabulary(p.arms) for p in work.positions}
        self.lines: list[LineWork] = []
        self.occs: list[Occurrence] = []
        self._formulas: dict[tuple, Node | None] = {}  # the last formula written alone, by its name
        self.figures: dict[tuple[str, tuple], list[Occurrence]] = {}  # filled at the end
        # by (scope, key), in reading order; and the stated scales found so far: looked up
        # for every number of every line, so kept linear in the file's size
        self._occ_index: dict[tuple[str, tuple], list[Occurrence]] = {}
        self._scale_memo: dict[tuple[str, str], float | None] = {}
        self._scale_state: dict[tuple[str, tuple], list] = {}
        for ln in work.general:
            self.lines.append(self._read(ln, None, self.vocab_general))
        for p in work.positions:
            for ln in p.lines:
                self.lines.append(self._read(ln, p.label, self.vocab[p.label]))
        self.stated_first: dict[tuple[str, tuple], float] = {}
        for lw in self.lines:
            self._result(lw)
        for lw in self.lines:
            self._bind(lw)
        for o in self.occs:
            self.figures.setdefault((o.scope, o.q.key), []).append(o)
        order = {"result": 0, "alias": 1, "operand": 2}
        index = {id(o): i for i, o in enumerate(self.occs)}
        for occs in self.figures.values():
            occs.sort(key=lambda o: (order[o.role], index[id(o)]))
        self._scale_memo.clear()

    # --- reading ----------------------------------------------------------------------

    def _read(self, line: Line, position: str | None, vocab: Vocabulary) -> LineWork:
        members = [read_member(m, vocab) for m in split_chain(line.text)]
        lw = LineWork(line, position, vocab, members)
        nums = [m for m in members if m.kind == "numeric"]
        bad = [m for m in members if m.kind == "bad"]
        if bad:
            lw.arithmetic = "unread"
            lw.note = bad[0].error
        if nums:
            lw.result = nums[-1]
        if len(nums) >= 2:
            lw.expr = nums[0]
            lw.evaluated = nums[0].value
            lw.arithmetic = lw.arithmetic or "ok"
            for a, b in pairwise(nums):
                if not self._same(a, b):
                    flipped = Member(b.text, b.kind, b.node, b.unit, -float(b.value))  # type: ignore[arg-type]
                    lw.arithmetic = "sign" if b.value and self._same(a, flipped) else "wrong"
                    lw.bad = (a, b)
                    break
        # the quantity the line computes
        name = line.quantity
        if name is None and members and members[0].kind == "name":
            name = members[0].node.name  # type: ignore[union-attr]
        if name is not None:
            lw.result_name = name
            lw.result_q = vocab.lookup(name)
            if lw.result_q is None and line.quantity is not None:
                lw.note = lw.note or f"unknown quantity {name!r}"
        # the formula the numbers are named by
        if line.symbols:
            try:
                lw.template = parse(line.symbols, names=True, resolve=vocab.split)
            except ExpressionError as exc:
                lw.note = f"symbols: {exc}"
        else:
            first_num = members.index(nums[0]) if nums else len(members)
            forms = [m for m in members[:first_num] if m.kind == "formula"]
            names = [m for m in members[1:first_num] if m.kind == "name"]
            if forms:
                lw.template = forms[-1].node
            elif names and len(nums) >= 2:
                lw.template = names[-1].node
            elif nums and lw.result_name:
                # "R43 = (Pи2h2 + G3h3 …)/h43", then "R43 = (299,7∙37,13 + …)/191,3 = …"
                lw.template = self._formulas.get((position, fold(lw.result_name)))
            if forms and not nums and lw.result_name:
                self._formulas[(position, fold(lw.result_name))] = forms[-1].node
        return lw

    def _same(self, a: Member, b: Member) -> bool:
        """Two written members agree (converted when both carry units of one dimension)."""
        va, vb = float(a.value), float(b.value)  # type: ignore[arg-type]
        if a.unit and b.unit and a.unit.dimension == b.unit.dimension:
            va, vb = va * a.unit.factor, vb * b.unit.factor
            return _close(va, vb, self.tol.arithmetic) or arithmetic_agrees(
                va / b.unit.factor, b, self.tol.arithmetic)
        return arithmetic_agrees(va, b, self.tol.arithmetic)

    # --- occurrences ------------------------------------------------------------------

    def scope_of(self, q: Quantity, position: str | None) -> str:
        if q.scope == "global":
            return "global"
        return position if position is not None else "general"

    def _result(self, lw: LineWork) -> None:
        """The line's result (and its other names) as occurrences."""
        q, m = lw.result_q, lw.result
        if m is None:
            return
        aliases = [x for x in lw.members[1:] if x.kind == "name"]
        targets: list[tuple[Quantity, str, str]] = []
        if q is not None:
            targets.append((q, lw.result_name, "result"))
        for a in aliases:
            aq = lw.vocab.lookup(a.node.name)  # type: ignore[union-attr]
            if aq is not None and (q is None or aq.key != q.key):
                targets.append((aq, a.node.name, "alias"))  # type: ignore[union-attr]
        for q0, name, role in targets:
            tq = self._by_unit(lw, q0, m.unit)
            if tq is None:
                continue
            o = self._occurrence(lw, tq, name, role, float(m.value), m.unit, m.text)  # type: ignore[arg-type]
            if o is not None and m.unit is not None:
                self.stated_first.setdefault((o.scope, tq.key), o.value)

    def _by_unit(self, lw: LineWork, q: Quantity, unit: Unit | None) -> Quantity | None:
        """A force (velocity …) written in mm is its segment; a unit of another dimension
        is a unit problem (reported, the number then read without it)."""
        if unit is None or unit.dimension == q.dimension:
            return q
        if unit.dimension == "m" and not q.on_paper:
            seg = lw.vocab.segment_of(q)
            if seg is not None:
                return seg
        if unit.dimension == "1":
            return q
        lw.unit_problem = unit.text
        return q

    def _occurrence(self, lw: LineWork, q: Quantity, name: str, role: str, raw: float,
                    unit: Unit | None, text: str, composite: bool = False
                    ) -> Occurrence | None:
        position = lw.position
        ref_pos = name.split("@", 1)[1] if "@" in name else None
        if ref_pos is not None:
            ref_pos = ref_pos.strip("()") if ref_pos not in self.ref.labels else ref_pos
            if ref_pos not in self.ref.labels and f"({ref_pos})" in self.ref.labels:
                ref_pos = f"({ref_pos})"
            position = ref_pos
        scope = self.scope_of(q, position)
        if unit is not None and unit.dimension == q.dimension and not lw.unit_problem:
            val, prefix, explicit = raw * unit.factor / q.factor, 0, unit.text
        else:
            prefix = self._prefix(q, raw, scope, position)
            val, explicit = raw * 1000.0 ** prefix, None
        o = Occurrence(q, scope, position, lw.line, role, raw, val, prefix, explicit, text,
                       name, composite, lw)
        lw.occs.append(o)
        self.occs.append(o)
        self._occ_index.setdefault((scope, q.key), []).append(o)
        if q.key[0] == "scale":  # what _find_stated_scale needs, kept as the lines are read
            st = self._scale_state.setdefault((scope, q.key), [None, None, Counter()])
            if role == "result" and st[0] is None:
                st[0] = o.value
            elif role == "alias" and st[1] is None:
                st[1] = o.value
            st[2][o.value] += 1
            self._scale_memo.clear()
        return o

    def reference_value(self, q: Quantity, scope: str, position: str | None,
                        line: Line | None = None) -> float | None:
        """What a name is known to be: graphplan's value, else the student's stated one
        (a scale; a Kp: the one in force on ``line``)."""
        where = position if position in self.ref.labels or position == "max" else 0
        try:
            v = self.ref.expected(q, where, self.stated_scales(position, line))
        except (KeyError, ValueError, IndexError):
            v = None
        if v is not None and v != 0:
            return v
        first = self.stated_first.get((scope, q.key), v)
        if q.key == ("scale", "Kp") and line is not None:
            return self.kp_at(scope, line, first)
        return first

    def _prefix(self, q: Quantity, raw: float, scope: str, position: str | None) -> int:
        if len(q.prefixes) == 1:
            return q.prefixes[0]
        ref = self.reference_value(q, scope, position)
        if ref is None or ref == 0 or raw == 0:
            return 0
        return min(q.prefixes, key=lambda k: abs(math.log(abs(raw) * 1000.0 ** k / abs(ref))))

    def _bind(self, lw: LineWork) -> None:
        """Name the numbers of the line's expression by its formula."""
        target = lw.expr or (lw.result if lw.template is not None and
                             not isinstance(lw.template, Sym) else None)
        if lw.template is None or target is None or target.node is None:
            return
        if isinstance(lw.template, Sym) and lw.expr is None:
            return

        all_names = set(_sym_names(lw.template))

        def cost(name: str, v: float) -> float:
            q = lw.vocab.lookup(name)
            if q is None:
                return 0.5
            q = self._in_product(lw, q, name, all_names)
            pos = name.split("@", 1)[1] if "@" in name else lw.position
            ref = self.reference_value(q, self.scope_of(q, pos), pos,
                                       lw.line if pos == lw.position else None)
            if pos == lw.position and "@" not in name:
                # the student's own value written before in this position names the
                # number better than graphplan's (Мур and Мур.ж, both ≈ graphplan's Мур)
                prior = next((o for o in self._occ_index.get((self.scope_of(q, pos), q.key), ())
                              if o.role == "result" and o.line is not lw.line), None)
                if prior is not None and prior.value:
                    ref = prior.value
            if ref is None:
                return 0.5
            if ref == 0 or v == 0:
                return 0.0 if ref == v else 3.0
            return min(3.0, min(abs(math.log(abs(v) * 1000.0 ** k / abs(ref)))
                                for k in q.prefixes))

        memo: dict[tuple[str, float], float] = {}

        def cost_once(name: str, v: float) -> float:  # a pair is tried once per term pair
            if (name, v) not in memo:
                memo[(name, v)] = cost(name, v)
            return memo[(name, v)]

        m = match(lw.template, target.node, cost_once)
        lw.matched = m
        if m is None:
            lw.note = lw.note or ("the formula and the numbers differ in form: the numbers "
                                  "are not named")
            return
        names = {n for n, _ in m.bindings}
        powers = _product_powers(lw.template)
        for name, node in m.bindings:
            q = lw.vocab.lookup(name)
            if q is None:
                continue
            q = self._in_product(lw, q, name, names, powers)
            composite = not _is_number(node)
            self._occurrence(lw, q, name, "operand", value(node), None, show(node), composite)

    def _in_product(self, lw: LineWork, q: Quantity, name: str, names: set[str],
                    powers: list[dict[str, int]] | None = None) -> Quantity:
        """A force multiplied by Kp stands for its segment (``R21∙Кр∙h21∙Кl``); divided
        by it, it is the force itself (``n_BA = anBA/Ka``: anBA is an acceleration)."""
        if q.on_paper or q.kind == "scale":
            return q
        scale = {"N": "Kp", "m/s": "Kv", "m/s²": "Ka"}.get(q.dimension)
        if scale is None:
            return q
        for other in names:
            oq = lw.vocab.lookup(other)
            if oq is not None and oq.kind == "scale" and oq.name == scale:
                if powers is not None and not any(
                        t.get(name, 0) * t.get(other, 0) > 0 for t in powers):
                    continue
                seg = lw.vocab.segment_of(q)
                return seg if seg is not None else q
        return q

    # --- scales -----------------------------------------------------------------------

    def stated_scales(self, position: str | None, line: Line | None = None
                      ) -> dict[str, float]:
        """The scales the student states (Kl, Kv, Ka for the whole work, Kp per position).

        A position may have a force plan per group, each at its own Kp: a Kp stated on a
        line holds for the lines after it, up to the next Kp stated (``line`` says where;
        before the first, the first holds).
        """
        out: dict[str, float] = {}
        for sym in SCALE_DIMENSIONS:
            scope = "global" if sym != "Kp" else (position or "general")
            v = self._stated_scale(sym, scope)
            if sym == "Kp" and line is not None:
                v = self.kp_at(scope, line, v)
            if v is not None:
                out[sym] = v
        return out

    def _occs_of(self, scope: str, key: tuple) -> list[Occurrence]:
        return self.figures.get((scope, key)) or [o for o in self.occs if o.scope == scope
                                                   and o.q.key == key]

    def kp_stated(self, scope: str) -> list[tuple[int, float]]:
        """The Kp stated at a position, in the order of the lines: (file line, value)."""
        out: list[tuple[int, float]] = []
        for o in sorted(self._occs_of(scope, ("scale", "Kp")),
                        key=lambda x: x.line.file_line or 0):
            if o.role in ("result", "alias"):
                v = self._effective(o)
                if not out or not _close(out[-1][1], v, 1e-9):
                    out.append((o.line.file_line or 0, v))
        return out

    @overload
    def kp_at(self, scope: str, line: Line, default: float) -> float: ...
    @overload
    def kp_at(self, scope: str, line: Line, default: float | None) -> float | None: ...

    def kp_at(self, scope: str, line: Line, default: float | None) -> float | None:
        """The Kp in force on a line (see :meth:`stated_scales`)."""
        stated = self.kp_stated(scope)
        if len(stated) < 2 or line.file_line is None:
            return default
        before = [v for n, v in stated if n <= line.file_line]
        return before[-1] if before else stated[0][1]

    def _effective(self, o: Occurrence) -> float:
        """A scale as the student really uses it: a scale line whose result is an
        arithmetic slip (``Kv = 0,942/47,1 = 0,2``) holds with the value its numbers give
        when the student uses that value elsewhere (the slip is reported once, on its
        line)."""
        lw = o.work
        if lw is None or lw.arithmetic != "wrong" or lw.bad is None or o.role == "operand":
            return o.value
        computed = _number(lw.bad[0]) * (o.value / o.raw if o.raw else 1.0)
        used = [x.value for x in self._occs_of(o.scope, o.q.key)
                if x.role == "operand" and x.work is not lw]
        if any(_close(u, computed, 0.005) for u in used):
            return computed
        return o.value

    def _stated_scale(self, sym: str, scope: str) -> float | None:
        if (sym, scope) not in self._scale_memo:
            self._scale_memo[(sym, scope)] = self._find_stated_scale(sym, scope)
        return self._scale_memo[(sym, scope)]

    def _find_stated_scale(self, sym: str, scope: str) -> float | None:
        key = ("scale", sym)
        if not self.figures:  # while the lines are read: the state kept by _occurrence
            st = self._scale_state.get((scope, key))
            if st is None:
                return None
            first = st[0] if st[0] is not None else st[1]
            return first if first is not None else st[2].most_common(1)[0][0]
        occs = self.figures.get((scope, key), [])
        res = [o for o in occs if o.role == "result"] or [o for o in occs if o.role == "alias"]
        if res:
            return self._effective(res[0])
        if occs:
            return Counter(o.value for o in occs).most_common(1)[0][0]
        return None

    def used_scales(self, position: str | None, sym: str) -> list[float]:
        """The values of a scale used in the expressions of one position's lines."""
        return [o.value for o in self.occs if o.q.key == ("scale", sym) and o.role == "operand"
                and o.position == position]

    def scale_candidates(self, q: Quantity, position: str | None,
                         occs: list[Occurrence] | None = None) -> list[float]:
        """Scales a length on paper may be drawn at: the stated one first, then others the
        student used in the lines where the figure is written (``occs``; default: in any
        line of the position)."""
        if not q.scale:
            return []
        at = occs[0].line if occs else None
        stated = self.stated_scales(position, at).get(q.scale)
        out = [stated] if stated else []
        if occs is None:
            used = self.used_scales(position, q.scale)
        else:
            lines = {id(o.work) for o in occs}
            used = [o.value for o in self.occs if o.q.key == ("scale", q.scale) and
                    o.role == "operand" and id(o.work) in lines]
        for v in used:
            if v and all(not _close(v, w, 1e-9) for w in out):
                out.append(v)
        return out

    # --- figures ----------------------------------------------------------------------

    def where_index(self, scope: str, o: Occurrence) -> str | int | None:
        """The position a figure's expected value is taken at."""
        if scope == "global":
            return o.position if o.position in self.ref.labels else 0
        if scope == "general":
            return None
        if scope == "max" or scope in self.ref.labels:
            return scope
        return None

    def expected(self, q: Quantity, scope: str, o: Occurrence, model: str = "rule",
                 scales: dict[str, float] | None = None) -> float | None:
        """graphplan's value of a figure (``None`` if there is none to compare with)."""
        where = self.where_index(scope, o)
        scales = scales if scales is not None else self.stated_scales(o.position, o.line)
        if where is None:  # a position's figure outside a position: only if it is constant
            vals = [self.ref.expected(q, k, scales, model) for k in range(len(self.ref.labels))]
            if not vals or any(v is None for v in vals):
                return None
            v0 = vals[0]
            if all(_close(v, v0, 1e-6, 1e-12) for v in vals):  # type: ignore[arg-type]
                return v0
            return None
        return self.ref.expected(q, where, scales, model)


def _product_powers(node: Node) -> list[dict[str, int]]:
    """For each term of a sum, the names of its product and their powers' signs
    (``R21∙Kp∙h21`` → ``{R21: 1, Kp: 1, h21: 1}``; ``anBA/Ka`` → ``{anBA: 1, Ka: -1}``);
    a name inside a bracket of a sum gets the bracket's place."""
    from .expressions import Bin, Call, Neg

    def prod(n: Node, sign: int, out: dict[str, int]) -> None:
        if isinstance(n, Sym):
            out[n.name] = out.get(n.name, 0) + sign
        elif isinstance(n, Neg):
            prod(n.x, sign, out)
        elif isinstance(n, Bin) and n.op == "*":
            prod(n.a, sign, out)
            prod(n.b, sign, out)
        elif isinstance(n, Bin) and n.op == "/":
            prod(n.a, sign, out)
            prod(n.b, -sign, out)
        elif isinstance(n, Bin) and n.op == "^":
            prod(n.a, sign, out)
        elif isinstance(n, Bin):  # a sum inside a product
            for t in (n.a, n.b):
                prod(t, sign, out)
        elif isinstance(n, Call):
            prod(n.arg, sign, out)

    terms: list[Node] = []

    def split(n: Node) -> None:
        if isinstance(n, Bin) and n.op in "+-":
            split(n.a)
            split(n.b)
        elif isinstance(n, Neg):
            split(n.x)
        else:
            terms.append(n)

    split(node)
    out = []
    for t in terms:
        d: dict[str, int] = {}
        prod(t, 1, d)
        out.append(d)
    return out


def _sym_names(node: Node) -> list[str]:
    from .expressions import Bin, Call, Neg

    if isinstance(node, Sym):
        return [node.name]
    if isinstance(node, Neg):
        return _sym_names(node.x)
    if isinstance(node, Bin):
        return _sym_names(node.a) + _sym_names(node.b)
    if isinstance(node, Call):
        return _sym_names(node.arg)
    return []


def _has_number(node: Node) -> bool:
    """A number written in the tree (names such as G3 hold digits, not numbers)."""
    from .expressions import Bin, Call, Neg, Num

    if isinstance(node, Num):
        return node.text != "π"
    if isinstance(node, Neg):
        return _has_number(node.x)
    if isinstance(node, Call):
        return _has_number(node.arg)
    if isinstance(node, Bin):
        return _has_number(node.a) or _has_number(node.b)
    return False


def _is_number(node: Node) -> bool:
    from .expressions import Neg, Num

    return isinstance(node, Num) or (isinstance(node, Neg) and isinstance(node.x, Num))


__all__ = ["LineWork", "Member", "Occurrence", "Tolerances", "Work", "arithmetic_agrees",
           "read_member"]
