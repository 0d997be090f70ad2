"""The code generator of the lean full cycle (:mod:`graphplan.forces.lean`).

A value of the generated function is an array's name, a constant (folded at generation:
an operation on constants is done then, ``x + 0``, ``x·1``, ``x − x`` are not generated),
or a pending negation (taken by the constant or subtraction that uses it). Expressions
already generated are reused; lines whose value nothing reads are dropped; each array is
deleted after its last use.
"""

from __future__ import annotations

import importlib
import math
import re

import numpy as np

_NAME = re.compile(r"\bt\d+\b")


def _compiled(name: str, public):
    """numpy's C function ``name`` behind a public wrapper (the wrapper's argument checks
    cost 0.1–1 µs a call, which counts at 36 positions); the public one where this numpy
    has it elsewhere."""
    for module in ("numpy._core.multiarray", "numpy.core.multiarray"):
        try:
            return getattr(importlib.import_module(module), name)
        except (ImportError, AttributeError):
            continue
    return public


count_nonzero = _compiled("count_nonzero", np.count_nonzero)
"""``np.count_nonzero`` of a whole array."""
interp_complex = _compiled("interp_complex", np.interp)
"""``np.interp(x, xp, fp, left, right)`` of float ``x``, ``xp`` and complex ``fp``."""


class Value:
    """A value of the generated code: an array's name, a constant, or the negation of
    another value not yet generated (``neg``: a sign is folded into the constant or the
    subtraction that uses it, and generated only where nothing can take it).

    ``kind`` is the array's dtype — ``"c"`` complex, ``"r"`` real, ``"b"`` a mask, None
    unknown — so that a constant is held in the dtype of the array it meets (numpy's
    loops on two operands of one dtype take half the time of a mixed pair at 36
    positions). ``bound`` is an upper bound of ``|x|`` at every finite φ (``inf`` where
    none is known): an output with a finite bound needs no check for NaN or infinity.
    """

    __slots__ = ("bound", "code", "const", "kind", "neg", "parts", "scaled")

    def __init__(self, code: str | None = None, const=None, neg: Value | None = None,
                 kind: str | None = None, bound: float = math.inf):
        self.code, self.const, self.neg = code, const, neg
        self.parts: tuple[Value, Value] | None = None  # (a, b) of a value generated as a + b
        self.scaled: tuple | None = None  # (c, x) of a value made as c·x, c a constant
        if const is not None:
            c = complex(const)
            kind, bound = ("c" if c.imag else "r"), abs(c)
        elif neg is not None:
            kind, bound = neg.kind, neg.bound
        self.kind: str | None = kind
        self.bound: float = bound

    def is_const(self, value=None) -> bool:
        return self.const is not None and (value is None or self.const == value)


def _kind(a: Value, b: Value) -> str | None:
    """The dtype of ``a ∘ b`` for + − × /."""
    if a.kind is None or b.kind is None:
        return None
    return "c" if "c" in (a.kind, b.kind) else "r"


class Code:
    """Straight-line numpy code with constants folded (see the module docstring)."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.ns: dict = {"np": np, "sqrt": np.sqrt, "exp": np.exp, "arctan2": np.arctan2,
                         "maximum": np.maximum, "isfinite": np.isfinite,
                         "concatenate": np.concatenate,
                   "count_nonzero": count_nonzero}
        self._n = 0
        self._seen: dict[str, Value] = {}
        self._consts: dict = {}
        self._low: dict[str, float] = {}  # |x| > low, checked (by code)

    # values
    def K(self, value) -> Value:
        return Value(None, value)

    def ref(self, v: Value, like: str | None = None) -> str:
        """The name of ``v`` in the generated code; a constant as a 0-d array (numpy's
        fast path for a scalar), complex where it or the array it meets (``like``) is."""
        if v.neg is not None and v.code is None:  # a negation nothing could take: from
            # here on an array of its own (its negation is pending again, not v.neg)
            v.code = self.tmp(f"-{self.ref(v.neg)}", v.neg.kind, v.neg.bound).code
            v.neg = None
        if v.const is None:
            assert v.code is not None
            return v.code
        c = complex(v.const)
        dtype = np.complex128 if (c.imag or like == "c") else np.float64
        key = (dtype, c)
        if key not in self._consts:
            name = self._consts[key] = f"k{self._n}"
            self._n += 1
            self.ns[name] = np.array(c if dtype is np.complex128 else c.real, dtype)
        return self._consts[key]

    @staticmethod
    def unit(angle: float) -> complex:
        """``e^{iα}``, an axis' direction exactly (cos 90° is 6e-17 in floating point:
        ``u = i`` exactly lets the products by it fold)."""
        c, s = math.cos(angle), math.sin(angle)
        if abs(c) < 1e-15:
            c, s = 0.0, math.copysign(1.0, s)
        elif abs(s) < 1e-15:
            c, s = math.copysign(1.0, c), 0.0
        return complex(c, s)

    def lit(self, value: float) -> str:
        """A real constant's name in a comparison (a 0-d array: a Python float literal
        costs numpy a conversion on every call)."""
        return self.ref(self.K(float(value)), "r")

    def tmp(self, expr: str, kind: str | None = None, bound: float = math.inf) -> Value:
        """A new array ``expr`` of dtype ``kind`` and ``|x| ≤ bound`` (an expression
        already generated is reused: the values are never changed once made)."""
        if expr in self._seen:
            return self._seen[expr]
        name = f"t{self._n}"
        self._n += 1
        self.lines.append(f"{name} = {expr}")
        # (the bound of the exact value, plus the operation's round-off: a few ulp)
        self._seen[expr] = v = Value(name, kind=kind, bound=bound * (1 + 1e-12))
        return v

    def _bin(self, a: Value, op: str, b: Value, bound: float) -> Value:
        """``a op b`` of two values, at least one an array."""
        return self.tmp(f"{self.ref(a, b.kind)} {op} {self.ref(b, a.kind)}", _kind(a, b), bound)

    @staticmethod
    def within(v: Value, bound: float) -> Value:
        """``v`` with ``|v| ≤ bound`` known from the geometry (a unit vector, a point at a
        link's length from another), tighter than the arithmetic's bound."""
        x: Value | None = v
        while x is not None and x.const is None:
            x.bound = min(x.bound, bound)
            x = x.neg
        return v

    def check_min(self, x: Value, lo: float, absolute: bool = True) -> None:
        """Return None unless ``|x| > lo`` everywhere (``absolute=False``: ``x > lo``, of
        an ``x`` ≥ 0); ``x`` then divides with ``|1/x| < 1/lo``."""
        self.refuse(f"{self.ref(self.abs(x) if absolute else x)} <= {self.lit(lo)}")
        self.set_low(x, lo)

    def set_low(self, x: Value, lo: float) -> None:
        """Record ``|x| > lo`` (checked, or following from a check)."""
        while x.neg is not None and x.code is None:
            x = x.neg
        if x.code is not None and lo > 0:
            self._low[x.code] = max(lo, self._low.get(x.code, 0.0))

    def low(self, x: Value) -> float:
        """The recorded lower bound of ``|x|`` (0 where none is known)."""
        while x.neg is not None and x.code is None:
            x = x.neg
        if x.const is not None:
            return abs(complex(x.const))
        return self._low.get(x.code, 0.0) if x.code is not None else 0.0

    def finite_check(self, arrays: list[Value]) -> str:
        """The condition that the outputs are finite, φ being finite: every array whose
        bound is not known is (``isfinite`` of their concatenation; past 4,096 positions
        of each one's sum, not a copy of all); "" where every bound is known."""
        open_ = list(dict.fromkeys(self.ref(v) for v in arrays if not v.bound < 1e300))
        if not open_:
            return ""
        listed = f"({', '.join(open_)},)"
        return (f"isfinite(concatenate({listed})).all() if phi.shape[0] <= 4096 "
                f"else isfinite(sum([x.sum() for x in {listed}]))")

    def bind(self, name: str, value) -> str:
        self.ns[name] = value
        return name

    def check(self, condition: str) -> None:
        """Return None (the general path decides) where ``condition`` is not true."""
        self.lines.append(f"if not ({condition}): return None")

    def refuse(self, bad: str) -> None:
        """Return None where the mask ``bad`` is true at any position (``count_nonzero``:
        a fifth of the time of a ``min``/``max`` or ``any`` at 36 positions; φ is checked
        finite first, so no NaN reaches a mask)."""
        self.lines.append(f"if count_nonzero({bad}): return None")

    # arithmetic, folded
    def add(self, a: Value, b: Value) -> Value:
        if a.const is not None and b.const is not None:
            return self.K(a.const + b.const)
        if a.is_const(0):
            return b
        if b.is_const(0):
            return a
        if b.neg is not None:
            return self.sub(a, b.neg)
        if a.neg is not None:
            return self.sub(b, a.neg)
        v = self._bin(a, "+", b, a.bound + b.bound)
        v.parts = (a, b)
        return v

    def sub(self, a: Value, b: Value) -> Value:
        if a.const is not None and b.const is not None:
            return self.K(a.const - b.const)
        if b.is_const(0):
            return a
        if a.is_const(0):
            return self.neg(b)
        if a is b or (a.code is not None and a.code == b.code):
            return self.K(0.0)
        if b.neg is not None:
            return self.add(a, b.neg)
        if a.neg is not None:
            return self.neg(self.add(a.neg, b))
        if a.parts is not None and b in a.parts:  # (x + y) − x = y
            return a.parts[1] if a.parts[0] is b else a.parts[0]
        rev = f"{self.ref(b, a.kind)} - {self.ref(a, b.kind)}"
        if rev in self._seen:  # a − b = −(b − a), already made
            return self.neg(self._seen[rev])
        return self._bin(a, "-", b, a.bound + b.bound)

    def mul(self, a: Value, b: Value) -> Value:
        if a.const is not None and b.const is not None:
            return self.K(a.const * b.const)
        if a.is_const(0) or b.is_const(0):
            return self.K(0.0)
        if b.const is not None and a.const is None:
            a, b = b, a  # the constant first
        if b.neg is not None:
            if a.const is not None:
                return self.mul(self.K(-a.const), b.neg)
            return self.neg(self.mul(a, b.neg))
        if a.neg is not None:
            return self.neg(self.mul(a.neg, b))
        if a.is_const(1):
            return b
        if a.is_const(-1):
            return self.neg(b)
        if a.const is not None and b.scaled is not None:  # c·(d·x) = (c·d)·x
            return self.mul(self.K(a.const * b.scaled[0]), b.scaled[1])
        v = self._bin(a, "*", b, a.bound * b.bound)
        if a.const is not None:
            v.scaled = (a.const, b)
        return v

    def div(self, a: Value, b: Value) -> Value:
        if b.const is not None:
            return self.mul(a, self.K(1.0 / b.const))
        if a.is_const(0):
            return self.K(0.0)
        if a.neg is not None:
            return self.neg(self.div(a.neg, b))
        if b.neg is not None:
            return self.neg(self.div(a, b.neg))
        low = self.low(b)
        return self._bin(a, "/", b, a.bound / low if low > 0 else math.inf)

    def neg(self, a: Value) -> Value:
        if a.const is not None:
            return self.K(-a.const)
        if a.neg is not None:
            return a.neg
        return Value(neg=a)

    def conj(self, a: Value) -> Value:
        if a.const is not None:
            return self.K(complex(a.const).conjugate())
        if a.neg is not None:
            return self.neg(self.conj(a.neg))
        return self.tmp(f"{self.ref(a)}.conjugate()", a.kind, a.bound)

    def re(self, a: Value) -> Value:
        if a.const is not None:
            return self.K(complex(a.const).real)
        if a.neg is not None:
            return self.neg(self.re(a.neg))
        return Value(f"{self.ref(a)}.real", kind="r", bound=a.bound)

    def im(self, a: Value) -> Value:
        if a.const is not None:
            return self.K(complex(a.const).imag)
        if a.neg is not None:
            return self.neg(self.im(a.neg))
        return Value(f"{self.ref(a)}.imag", kind="r", bound=a.bound)

    def cross(self, a: Value, b: Value) -> Value:
        """``a×b = Im(conj(a)·b)``; with a constant one product: ``−Im(a·conj(b))``."""
        if b.const is not None:
            return self.neg(self.im(self.mul(a, self.K(complex(b.const).conjugate()))))
        return self.im(self.mul(self.conj(a), b))

    def dot(self, a: Value, b: Value) -> Value:
        """``a·b = Re(conj(a)·b) = Re(a·conj(b))``."""
        if b.const is not None:
            return self.re(self.mul(a, self.K(complex(b.const).conjugate())))
        return self.re(self.mul(self.conj(a), b))

    def fn(self, name: str, *args: Value, fold=None, kind: str | None = "r",
           bound: float = math.inf) -> Value:
        """``name(*args)``: a real array (``kind``) with ``|x| ≤ bound``."""
        if fold is not None and all(a.const is not None for a in args):
            return self.K(fold(*(a.const for a in args)))
        like = "c" if any(a.kind == "c" for a in args) else "r"
        return self.tmp(f"{name}({', '.join(self.ref(a, like) for a in args)})", kind, bound)

    def abs(self, a: Value) -> Value:
        if a.neg is not None:
            return self.abs(a.neg)
        return self.fn("abs", a, fold=abs, bound=a.bound)

    def sqrt(self, a: Value) -> Value:
        """√a of a value checked ≥ 0."""
        return self.fn("sqrt", a, fold=math.sqrt, bound=math.sqrt(a.bound))

    def maximum(self, a: Value, b: Value) -> Value:
        return self.fn("maximum", a, b, fold=max, bound=max(a.bound, b.bound))

    def arg(self, a: Value) -> Value:
        if a.const is not None:
            z = complex(a.const)
            return self.K(math.atan2(z.imag, z.real))
        return self.fn("arctan2", self.im(a), self.re(a), bound=math.pi)

    def source(self, name: str, args: str, outputs: list[str], free: bool = False) -> str:
        """The function's text; with ``free``, each array is deleted after its last use:
        the next array of its size reuses its memory (numpy's cache of small blocks at 36
        positions, the allocator's free memory at 3,600) instead of all of them being
        held to the end and fresh pages faulted in on every call — faster at every N
        (press: 54 → 50 µs at 36 positions, 1.56 → 0.42 ms at 3,600)."""
        # φ finite first (φ − φ is 0 exactly where it is): every bound and check below
        # assumes it
        lines = ["if count_nonzero(phi - phi): return None", *live_lines(self.lines, outputs)]
        if free:
            keep = {m for o in outputs for m in _NAME.findall(o)}
            last: dict[str, int] = {}
            for k, ln in enumerate(lines):
                for m in _NAME.findall(ln.split(" = ", 1)[1] if " = " in ln[:8] else ln):
                    last[m] = k
            dead: dict[int, list[str]] = {}
            for m, k in last.items():
                if m not in keep:
                    dead.setdefault(k, []).append(m)
            # (after a check on a line of its own: ``if …: return None; del x`` never dels)
            lines = [ln + (("\n    del " if ln.startswith("if ") else "; del ")
                           + ", ".join(sorted(dead[k])) if k in dead else "")
                     for k, ln in enumerate(lines)]
        body = "\n".join("    " + ln for ln in lines)
        return f"def {name}({args}):\n{body}\n    return ({', '.join(outputs)},)\n"


class NotCompiled(Exception):
    """A variant's setting the lean path does not compile (the general path solves it)."""


def live_lines(lines: list[str], outputs: list[str]) -> list[str]:
    """The lines whose values are used: by a later line kept, a check, or the outputs."""
    needed = {m for o in outputs for m in _NAME.findall(o)}
    kept = []
    for ln in reversed(lines):
        target, _, expr = ln.partition(" = ")
        if _NAME.fullmatch(target) and not ln.startswith("if "):
            if target not in needed:
                continue
            needed.update(_NAME.findall(expr))
        else:
            needed.update(_NAME.findall(ln))
        kept.append(ln)
    return kept[::-1]


def py_number(c):
    """A folded constant as a Python number (for the generated code's literals)."""
    c = complex(c)
    return c if c.imag else c.real


__all__ = ["Code", "NotCompiled", "Value", "count_nonzero", "interp_complex", "live_lines",
           "py_number"]
