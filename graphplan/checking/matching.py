"""Naming the numbers of a written calculation by its formula.

A student writes the formula and then the same formula with numbers::

    Мур = R21∙Кр∙h21∙Кl = 90,47∙200∙37,86∙0,002 = 1370,1 Нм

:func:`match` lays the formula's tree (a template, with names) over the numbers' tree
and returns which number (or which bracket of numbers) each name stands for, here
``R21 → 90,47``, ``Кр → 200``, ``h21 → 37,86``, ``Кl → 0,002``. Sums and products
may be written in another order than the formula (terms and factors are matched as
sets: the assignment of least cost wins, the cost saying how far each number is from
what the name is known to be). A term whose sign differs between the formula and the
numbers (``−Pи3·h3`` against ``+1498,51∙80``) is reported. A name may stand for a
bracket or a product (``m3aВ`` over ``900∙(67∙0.02)`` gives ``aВ → 67∙0.02``). Literal
numbers of the formula (``0,7`` in ``0,7Q0``) must be the same in the numbers.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from itertools import permutations

from .errors import ExpressionError
from .expressions import Bin, Call, Neg, Node, Num, Sym, value

MAX_PERMUTED = 6
"""Sums or products with more parts than this are matched in the written order only."""

SIGN_COST = 1.0
ORDER_COST = 0.25


@dataclass(frozen=True, slots=True)
class Match:
    """Names bound to parts of the numbers, terms whose sign differs, and the cost."""

    bindings: tuple[tuple[str, Node], ...]
    signs: tuple[tuple[Node, Node, int, int], ...]  # (formula term, numbers term, signs)
    cost: float


Cost = Callable[[str, float], float]


def terms(node: Node) -> list[tuple[int, Node]]:
    """The signed terms of a sum (``a − b + c`` → ``[(+1, a), (−1, b), (+1, c)]``)."""
    if isinstance(node, Bin) and node.op in "+-":
        right = terms(node.b)
        if node.op == "-":
            right = [(-s, t) for s, t in right]
        return terms(node.a) + right
    if isinstance(node, Neg):
        return [(-s, t) for s, t in terms(node.x)]
    return [(1, node)]


def factors(node: Node) -> tuple[list[Node], list[Node]]:
    """Numerator and denominator factors of a product (``a·b/c`` → ``([a, b], [c])``)."""
    if isinstance(node, Bin) and node.op == "*":
        an, ad = factors(node.a)
        bn, bd = factors(node.b)
        return an + bn, ad + bd
    if isinstance(node, Bin) and node.op == "/":
        an, ad = factors(node.a)
        bn, bd = factors(node.b)
        return an + bd, ad + bn
    return [node], []


def rebuild_sum(parts: list[tuple[int, Node]]) -> Node:
    """A sum from signed terms (inverse of :func:`terms`)."""
    s0, n0 = parts[0]
    node: Node = n0 if s0 > 0 else Neg(n0)
    for s, n in parts[1:]:
        node = Bin("+" if s > 0 else "-", node, n)
    return node


def _val(n: Node) -> float | None:
    try:
        return value(n)
    except ExpressionError:
        return None


def match(t: Node, n: Node, cost: Cost) -> Match | None:
    """Lay the formula ``t`` over the numbers ``n`` (see the module docstring)."""
    if isinstance(t, Sym):
        v = _val(n)
        if v is None:
            return None
        return Match(((t.name, n),), (), cost(t.name, v))
    tt, nt = terms(t), terms(n)
    if len(tt) == 1 and len(nt) == 1 and tt[0][0] > 0 and nt[0][0] > 0:
        return _match_product(tt[0][1], nt[0][1], cost)
    if len(tt) != len(nt):
        return None
    pairs = [[_match_product(a, b, cost) for _, b in nt] for _, a in tt]

    def sign(i: int, j: int) -> tuple | None:  # a term written with the other sign
        return (tt[i][1], nt[j][1], tt[i][0], nt[j][0]) if tt[i][0] != nt[j][0] else None

    return _best_order(pairs, sign)


def _match_product(t: Node, n: Node, cost: Cost) -> Match | None:
    if isinstance(t, Sym):
        return match(t, n, cost)
    tn, td = factors(t)
    nn, nd = factors(n)
    if len(tn) == 1 and not td and len(nn) == 1 and not nd:
        return _match_atom(tn[0], nn[0], cost)
    if len(tn) != len(nn) or len(td) != len(nd):
        return None
    out = []
    for ts, ns in ((tn, nn), (td, nd)):
        if not ts:
            continue
        m = _assign(ts, ns, cost)
        if m is None:
            return None
        out.append(m)
    return Match(tuple(b for m in out for b in m.bindings),
                 tuple(s for m in out for s in m.signs), sum(m.cost for m in out))


def _assign(ts: list[Node], ns: list[Node], cost: Cost) -> Match | None:
    return _best_order([[match(a, b, cost) for b in ns] for a in ts])


def _best_order(pairs: list[list[Match | None]],
                sign: Callable[[int, int], tuple | None] | None = None) -> Match | None:
    """The cheapest way to pair the formula's parts ``i`` with the numbers' parts ``j``
    one to one (``pairs[i][j]``: the match of the two, None where they do not match): each
    part out of its written order costs :data:`ORDER_COST`, each ``sign(i, j)`` that is not
    None (a term written with the other sign) is noted and costs :data:`SIGN_COST`."""
    n = len(pairs[0]) if pairs else 0
    best: Match | None = None
    orders = permutations(range(n)) if n <= MAX_PERMUTED else [range(n)]
    for order in orders:
        binds: list = []
        signs: list = []
        c = 0.0
        for i, j in enumerate(order):
            m = pairs[i][j]
            if m is None:
                break
            binds += m.bindings
            signs += m.signs
            c += m.cost + ORDER_COST * (i != j)
            flipped = sign(i, j) if sign is not None else None
            if flipped is not None:
                signs.append(flipped)
                c += SIGN_COST
        else:
            if best is None or c < best.cost:
                best = Match(tuple(binds), tuple(signs), c)
    return best


def _match_atom(t: Node, n: Node, cost: Cost) -> Match | None:
    if isinstance(t, Num):
        v = _val(n)
        if v is None or not math.isclose(v, t.value, rel_tol=1e-9, abs_tol=1e-12):
            return None
        return Match((), (), 0.0)
    if isinstance(t, Bin) and t.op == "^" and isinstance(n, Bin) and n.op == "^":
        a = match(t.a, n.a, cost)
        b = match(t.b, n.b, cost)
        if a is None or b is None:
            return None
        return Match(a.bindings + b.bindings, a.signs + b.signs, a.cost + b.cost)
    if isinstance(t, Call) and isinstance(n, Call) and t.fn == n.fn:
        return match(t.arg, n.arg, cost)
    if (isinstance(t, Bin) and t.op in "+-") or isinstance(t, Neg):
        return match(t, n, cost)
    return None


def substitute(t: Node, env: dict[str, float]) -> float:
    """The formula's value with names replaced by ``env`` (raises ExpressionError)."""
    return value(t, env)


def flip_term(t: Node, index: int) -> Node | None:
    """The formula with the sign of one term of its (numerator's) sum reversed.

    ``(a + b − c)/d`` with index 1 gives ``(a − b − c)/d``; ``None`` when the formula
    has no such term.
    """
    parts = terms(t)
    if len(parts) > 1:
        if index >= len(parts):
            return None
        s, n = parts[index]
        parts[index] = (-s, n)
        return rebuild_sum(parts)
    num, den = factors(t)
    for i, f in enumerate(num):
        inner = terms(f)
        if len(inner) > 1:
            flipped = flip_term(f, index)
            if flipped is None:
                return None
            node: Node = flipped
            for g in num[:i] + num[i + 1:]:
                node = Bin("*", node, g)
            for g in den:
                node = Bin("/", node, g)
            return node
    return None


def sum_terms(t: Node) -> list[tuple[int, Node]]:
    """The terms of the formula's sum, or of the sum in its numerator (see
    :func:`flip_term`)."""
    parts = terms(t)
    if len(parts) > 1:
        return parts
    num, _ = factors(t)
    for f in num:
        inner = terms(f)
        if len(inner) > 1:
            return inner
    return []


__all__ = ["Match", "factors", "flip_term", "match", "rebuild_sum", "substitute", "sum_terms",
           "terms"]
