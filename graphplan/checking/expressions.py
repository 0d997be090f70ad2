"""A safe reader of written calculations: a small tokenizer and a recursive-descent parser.

Students write ``R43=(299,7414∙37,13+12262,5∙56,57)/191,3=8145,71 H``: decimal commas
(or points), ``∙`` ``·`` ``*`` ``×`` for multiplication, ``/`` or ``:`` for division,
``^`` ``²`` ``³`` for powers, brackets, ``−`` (or ``-``, ``–``) for minus, thousands
groups separated by spaces (``600 000``), and a unit after the result (``кН``, ``Нм``,
``мм``, ``рад/с`` …, see :mod:`graphplan.checking.units`). A line is a chain of members
joined by ``=`` (or ``≈``).

Grammar (``numeric`` mode reads only numbers; ``template`` mode also reads names)::

    member  := expr [unit]
    expr    := term (("+" | "-") term)*
    term    := signed (("·" | "/" | implicit) signed)*
    signed  := ("-" | "+") signed | power
    power   := postfix ("^" signed)?            (right-associative)
    postfix := atom ("²" | "³" | "°")*
    atom    := number | "(" expr ")" | "[" expr "]" | function power | "√" power
             | "π" | name                        (name: template mode only)

Functions: ``sin cos tg tan ctg cot`` take degrees (as written: ``sin 45°``),
``arcsin arccos arctg arctan`` give degrees, ``sqrt`` (or ``√``), ``ln``, ``lg``.
``°`` only marks degrees. Implicit multiplication: a number or a closing bracket
before ``(``, ``√``, a function or ``π`` (``2(3+4)``); in template mode also before a
name (``0,7Q0``). Two numbers in a row are refused.

Nothing is ever passed to ``eval``: the parser builds a tree of frozen nodes and
:func:`value` walks it. Every refusal is an :class:`ExpressionError` naming the
expression, the column and what was expected.

Two kinds of refusal (the interface the checker counts on):

* :class:`ExpressionError` — the text is not arithmetic as written (a name where a number
  is expected, an unknown character, two numbers in a row): it may still be a formula or
  words;
* :class:`UnreadableError` (a subclass) — the text *is* arithmetic, but it has no finite
  real value: a literal that overflows (``1e400``), a result that does (``2^1024``), a
  division by zero, a function outside its domain (``ln 0``, ``sqrt(-1)``). A line with
  such a member is a finding of kind ``unreadable``, never a formula.

Work is bounded linearly in the text: at most :data:`MAX_LENGTH` characters, nesting at
most :data:`MAX_DEPTH`, and every operation on floats (a power is ``math.pow``, never an
integer power that grows without bound).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass

from ..numbers import general
from .errors import ExpressionError, UnreadableError
from .units import Unit, fold, split_unit

MAX_LENGTH = 600
"""Longest expression read (characters)."""

MAX_DEPTH = 40
"""Deepest nesting of brackets, signs and powers."""

# --- nodes -----------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Num:
    """A number as written (``text``) and its value."""

    value: float
    text: str


@dataclass(frozen=True, slots=True)
class Sym:
    """A name of a template (``G3``, ``h43``, ``Kl``, ``Mур@4``)."""

    name: str


@dataclass(frozen=True, slots=True)
class Neg:
    """Unary minus."""

    x: Node


@dataclass(frozen=True, slots=True)
class Bin:
    """A binary operation: ``op`` is one of ``+ - * / ^``."""

    op: str
    a: Node
    b: Node


@dataclass(frozen=True, slots=True)
class Call:
    """A function applied to its argument (trigonometry in degrees)."""

    fn: str
    arg: Node


Node = Num | Sym | Neg | Bin | Call

# --- functions -------------------------------------------------------------------------------


def _deg(f):
    return lambda x: f(math.radians(x))


def _inv_deg(f):
    return lambda x: math.degrees(f(x))


FUNCTIONS: dict[str, Callable[[float], float]] = {
    "sin": _deg(math.sin), "cos": _deg(math.cos), "tg": _deg(math.tan), "tan": _deg(math.tan),
    "ctg": _deg(lambda x: 1.0 / math.tan(x)), "cot": _deg(lambda x: 1.0 / math.tan(x)),
    "arcsin": _inv_deg(math.asin), "arccos": _inv_deg(math.acos),
    "arctg": _inv_deg(math.atan), "arctan": _inv_deg(math.atan),
    "sqrt": math.sqrt, "√": math.sqrt, "ln": math.log, "lg": math.log10,
}
_FUNC_NAMES = sorted((f for f in FUNCTIONS if f != "√"), key=len, reverse=True)

# --- tokens ----------------------------------------------------------------------------------

_SPACE = " \t\u00a0\u202f\u2009"
_NUMBER = re.compile(
    r"\d{1,3}(?:[ \u00a0\u202f\u2009]\d{3})+(?![\d.,])"  # 600 000 (thousands groups)
    r"|\d{1,3}(?:[ \u00a0\u202f\u2009]\d{3})+[.,]\d+"       # 12 262,5
    r"|\d+(?:[.,]\d+)?(?:[eEеЕ][+\-−]?\d+(?![\w]))?"         # 1,5 · 2.5e3
    r"|[.,]\d+"                                             # ,5
)
_OPS = {
    "+": "+", "-": "-", "−": "-", "–": "-", "—": "-",
    "*": "*", "·": "*", "∙": "*", "⋅": "*", "×": "*",
    "/": "/", ":": "/", "÷": "/", "^": "^",
    "(": "(", ")": ")", "[": "(", "]": ")", "²": "²", "³": "³", "°": "°", "√": "√",
}


@dataclass(frozen=True, slots=True)
class Token:
    kind: str  # "num" | "name" | "func" | "op" | "end"
    text: str  # normalised: "*" for every multiplication sign, "-" for every minus
    col: int  # 1-based
    value: float = 0.0
    raw: str = ""  # as written


def _number_value(text: str) -> float:
    t = text
    for sp in _SPACE:
        t = t.replace(sp, "")
    t = t.replace(",", ".").replace("е", "e").replace("Е", "e").replace("−", "-")
    if t.startswith("."):
        t = "0" + t
    x = float(t)
    if not math.isfinite(x):
        raise UnreadableError(f"the number {text!r} is too large to be a finite number")
    return x


def _is_name_start(ch: str) -> bool:
    return ch.isalpha() and ch not in "²³°√"


def _is_name_char(ch: str) -> bool:
    return (ch.isalnum() or ch in "_'") and ch not in "²³°√"


def tokenize(text: str) -> list[Token]:
    """Tokens of an expression (numbers, names, functions, operators), then ``end``."""
    out: list[Token] = []
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch in _SPACE:
            i += 1
            continue
        m = _NUMBER.match(text, i)
        if m and (ch.isdigit() or ch in ".,"):
            num = m.group()
            try:
                val = _number_value(num)
            except UnreadableError as exc:
                raise UnreadableError(f"{exc} at column {i + 1}", i + 1) from None
            out.append(Token("num", num, i + 1, val))
            i = m.end()
            continue
        if _is_name_start(ch):
            j = i + 1
            while j < n and _is_name_char(text[j]):
                j += 1
            if j < n and text[j] == "@":  # a reference to another position: Mур@4, Mур@(2)
                k = j + 1
                if k < n and text[k] == "(":
                    close = text.find(")", k)
                    k = close + 1 if close > 0 else n + 1
                else:
                    while k < n and _is_name_char(text[k]):
                        k += 1
                if k > n or k == j + 1:
                    raise ExpressionError(f"a position label must follow '@' at column {j + 1}",
                                          j + 1)
                j = k
            name = text[i:j]
            low = fold(name).lower()
            fn = next((f for f in _FUNC_NAMES if low == f or (low.startswith(f) and
                                                              low[len(f):].isdigit())), None)
            if fn is not None:
                out.append(Token("func", fn, i + 1))
                i += len(fn)
                continue
            if name == "π":
                out.append(Token("num", "π", i + 1, math.pi))
            else:
                out.append(Token("name", name, i + 1))
            i = j
            continue
        if ch in _OPS:
            out.append(Token("op", _OPS[ch], i + 1, raw=ch))
            i += 1
            continue
        if ch == "=" or ch == "≈":
            raise ExpressionError(f"unexpected {ch!r} at column {i + 1} (a member of a chain "
                                  "holds one expression)", i + 1)
        raise ExpressionError(f"unexpected character {ch!r} at column {i + 1} (expected a "
                              "number, an operator + − · / ^ or a bracket)", i + 1)
    out.append(Token("end", "", n + 1))
    return out


# --- parser ----------------------------------------------------------------------------------

Resolver = Callable[[str], tuple[str, ...] | None]
"""Template mode: a name as written → the known names it is made of (``"Pи2h2"`` →
``("Pи2", "h2")``), or ``None`` if it is not known."""


class _Parser:
    def __init__(self, text: str, names: bool, resolve: Resolver | None):
        self.text = text
        self.names = names
        self.resolve = resolve
        self.toks = tokenize(text)
        self.i = 0
        self.depth = 0

    def fail(self, msg: str, tok: Token | None = None) -> ExpressionError:
        tok = tok or self.peek()
        where = "at the end" if tok.kind == "end" else f"at column {tok.col}"
        return ExpressionError(f"expression {self.text.strip()!r}: {msg} {where}", tok.col)

    def peek(self) -> Token:
        return self.toks[self.i]

    def take(self) -> Token:
        t = self.toks[self.i]
        self.i += 1
        return t

    def is_op(self, *ops: str) -> bool:
        t = self.peek()
        return t.kind == "op" and t.text in ops

    def enter(self) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            err = self.fail(f"nested deeper than {MAX_DEPTH} levels")
            raise UnreadableError(str(err), err.column)

    def leave(self) -> None:
        self.depth -= 1

    def parse(self) -> Node:
        if self.peek().kind == "end":
            raise self.fail("empty expression: expected a number")
        node = self.expr()
        t = self.peek()
        if t.kind != "end":
            if t.kind == "op" and t.text == ")":
                raise self.fail("unmatched ')'", t)
            if t.kind == "name" and not self.names:
                raise self.fail(f"a name ({t.text!r}) where an operator is expected", t)
            raise self.fail(f"unexpected {t.raw or t.text!r} (expected an operator)", t)
        return node

    def expr(self) -> Node:
        node = self.term()
        while self.is_op("+", "-"):
            op = self.take().text
            node = Bin(op, node, self.term())
        return node

    def _starts_factor(self, prev: Node) -> bool:
        t = self.peek()
        if t.kind == "func" or (t.kind == "op" and t.text in ("(", "√")):
            return True
        if t.kind == "num" and t.text == "π":
            return True
        if t.kind == "name":
            return self.names
        if t.kind == "num":  # ")2" is accepted, "2 3" is not
            return False
        return False

    def term(self) -> Node:
        node = self.signed()
        while True:
            if self.is_op("*", "/"):
                op = self.take().text
                node = Bin(op, node, self.signed())
            elif self._starts_factor(node):
                node = Bin("*", node, self.signed())
            elif self.peek().kind == "num":
                raise self.fail("two numbers in a row (a missing operator?)")
            else:
                return node

    def signed(self) -> Node:
        if self.is_op("+", "-"):
            op = self.take().text
            self.enter()
            x = self.signed()
            self.leave()
            return Neg(x) if op == "-" else x
        return self.power()

    def power(self) -> Node:
        base = self.postfix()
        if self.is_op("^"):
            self.take()
            self.enter()
            exp = self.signed()
            self.leave()
            return Bin("^", base, exp)
        return base

    def postfix(self) -> Node:
        node = self.atom()
        while self.is_op("²", "³", "°"):
            t = self.take().text
            if t == "²":
                node = Bin("^", node, Num(2.0, "2"))
            elif t == "³":
                node = Bin("^", node, Num(3.0, "3"))
        return node

    def atom(self) -> Node:
        t = self.peek()
        if t.kind == "num":
            self.take()
            return Num(t.value, t.text)
        if t.kind == "op" and t.text == "(":
            self.take()
            self.enter()
            node = self.expr()
            self.leave()
            if not self.is_op(")"):
                raise self.fail("expected ')'")
            self.take()
            return node
        if t.kind == "func" or (t.kind == "op" and t.text == "√"):
            self.take()
            self.enter()
            arg = self.power_arg()
            self.leave()
            return Call(t.text, arg)
        if t.kind == "name":
            if not self.names:
                raise self.fail(f"a name ({t.text!r}) where a number is expected", t)
            self.take()
            parts = self.resolve(t.text) if self.resolve else None
            if not parts:
                return Sym(t.text)
            node = Sym(parts[0])
            for p in parts[1:]:
                node = Bin("*", node, Sym(p))
            return node
        if t.kind == "end":
            raise self.fail("expected a number or '('", t)
        raise self.fail(f"unexpected {t.raw or t.text!r} (expected a number or '(')", t)

    def power_arg(self) -> Node:
        if self.is_op("+", "-"):
            op = self.take().text
            x = self.power_arg()
            return Neg(x) if op == "-" else x
        return self.power()


def parse(text: str, *, names: bool = False, resolve: Resolver | None = None) -> Node:
    """Parse one expression (no ``=``, no unit) into a tree.

    Parameters
    ----------
    text : str
        The expression as written.
    names : bool
        Template mode: accept names (``G3∙h3``), as :class:`Sym` nodes.
    resolve : callable, optional
        Template mode: splits a name written without a sign between its parts
        (``Pи2h2`` → ``Pи2·h2``), see :data:`Resolver`.

    Raises
    ------
    ExpressionError
        Naming the expression, the column and what was expected.
    """
    if not isinstance(text, str):
        raise ExpressionError(f"expected an expression as text (got {type(text).__name__})")
    if len(text) > MAX_LENGTH:
        raise UnreadableError(f"expression of {len(text)} characters: at most {MAX_LENGTH} "
                              "are read")
    return _Parser(text, names, resolve).parse()


# --- values ----------------------------------------------------------------------------------


def value(node: Node, env: dict[str, float] | None = None) -> float:
    """The value of a tree; names are looked up in ``env``.

    Raises
    ------
    UnreadableError
        Division by zero, a function outside its domain, a result that is not a finite
        real number.
    ExpressionError
        An unknown name.
    """
    if isinstance(node, Num):
        return node.value
    if isinstance(node, Sym):
        if env is None or node.name not in env:
            raise ExpressionError(f"no value for the name {node.name!r}")
        return float(env[node.name])
    if isinstance(node, Neg):
        return -value(node.x, env)
    if isinstance(node, Call):
        x = value(node.arg, env)
        try:
            out = FUNCTIONS[node.fn](x)
        except (ValueError, ZeroDivisionError, OverflowError):
            raise UnreadableError(f"{node.fn}({general(x)}) is not defined") from None
        return _finite(out, node.fn)
    a, b = value(node.a, env), value(node.b, env)
    op = node.op
    if op == "+":
        return _finite(a + b, "a sum")
    if op == "-":
        return _finite(a - b, "a difference")
    if op == "*":
        return _finite(a * b, "a product")
    if op == "/":
        if b == 0:
            raise UnreadableError(f"division by zero ({general(a)}/0)")
        return _finite(a / b, "a quotient")
    try:  # "^"
        out = math.pow(a, b)
    except (ValueError, OverflowError, ZeroDivisionError):
        raise UnreadableError(f"{general(a)}^{general(b)} is not a finite real number") from None
    return _finite(out, "a power")


def _finite(x: float, what: str) -> float:
    if not math.isfinite(x):
        raise UnreadableError(f"{what} is not a finite number")
    return x


@dataclass(frozen=True, slots=True)
class Value:
    """A number read from a written result, and its unit (``None`` when none is written)."""

    number: float
    unit: Unit | None
    text: str

    @property
    def si(self) -> float | None:
        """The value in SI units (``None`` without a unit)."""
        return None if self.unit is None else self.number * self.unit.factor


def evaluate(text: str) -> Value:
    """Evaluate one written member, e.g. ``"1250∙(74,08∙0.02654)"`` or ``"15,85кНм"``.

    Only numbers, operators, brackets, the functions above and one trailing unit are
    accepted; anything else (a name, two numbers in a row, an unknown character) is
    refused with an :class:`ExpressionError`.
    """
    if not isinstance(text, str):
        raise ExpressionError(f"expected an expression as text (got {type(text).__name__})")
    body, unit = split_unit(text)
    node = parse(body)
    try:
        return Value(value(node), unit, text)
    except UnreadableError as exc:
        raise UnreadableError(f"expression {text.strip()!r}: {exc}") from None
    except ExpressionError as exc:
        raise ExpressionError(f"expression {text.strip()!r}: {exc}") from None


def split_chain(line: str) -> list[str]:
    """The members of a written line, split at ``=`` and ``≈`` (``"a=b=c"`` → 3)."""
    return [m.strip() for m in re.split(r"[=≈]", line)]


def decimals(text: str) -> int:
    """Digits written after the decimal sign of the last number in ``text`` (0 if none)."""
    nums = _NUMBER.findall(text)
    if not nums:
        return 0
    last = nums[-1]
    m = re.search(r"[.,](\d+)$", last.replace(" ", ""))
    return len(m.group(1)) if m else 0


def show(node: Node) -> str:
    """A tree written back as text (``·`` for products, minimal brackets)."""
    return _show(node, 0)


_PREC = {"+": 1, "-": 1, "*": 2, "/": 2, "^": 4}


def _show(node: Node, outer: int) -> str:
    if isinstance(node, Num):
        return node.text if node.text else general(node.value)
    if isinstance(node, Sym):
        return node.name
    if isinstance(node, Neg):
        s = "−" + _show(node.x, 3)
        return f"({s})" if outer > 1 else s
    if isinstance(node, Call):
        return f"{node.fn}({_show(node.arg, 0)})"
    p = _PREC[node.op]
    sym = {"*": "·", "-": "−"}.get(node.op, node.op)
    right = p + 1 if node.op in "-/" else p
    s = f"{_show(node.a, p)}{sym}{_show(node.b, right)}"
    return f"({s})" if p < outer else s


__all__ = ["FUNCTIONS", "MAX_DEPTH", "MAX_LENGTH", "Bin", "Call", "ExpressionError", "Neg",
           "Node", "Num", "Sym", "Token", "UnreadableError", "Value", "decimals", "evaluate",
           "parse", "show", "split_chain", "tokenize", "value"]
