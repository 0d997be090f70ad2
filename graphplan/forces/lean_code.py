"""The code generator of the lean full cycle (:mod:`graphplan.forces.lean`).

A value of the generated function is an array's name, a constant (folded at generation:
an operation on constants is done then, ``x + 0``, ``x·1``, ``x − x`` are not generated),
or a pending negation (taken by the constant or subtraction that uses it). Expressions
already generated are reused; lines whose value nothing reads are dropped; each array is
deleted after its last use.
"""

from __future__ import annotations

import math
import re

import numpy as np

_NAME = re.compile(r"\bt\d+\b")


class Value:
    """A value of the generated code: an array's name, a constant, or the negation of
    another value not yet generated (``neg``: a sign is folded into the constant or the
    subtraction that uses it, and generated only where nothing can take it)."""

    __slots__ = ("code", "const", "neg", "parts")

    def __init__(self, code: str | None = None, const=None, neg: Value | None = None):
        self.code, self.const, self.neg = code, const, neg
        self.parts: tuple[Value, Value] | None = None  # (a, b) of a value generated as a + b

    def is_const(self, value=None) -> bool:
        return self.const is not None and (value is None or self.const == value)


class Code:
    """Straight-line numpy code with constants folded (see the module docstring)."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.ns: dict = {"np": np, "sqrt": np.sqrt, "exp": np.exp, "arctan2": np.arctan2,
                         "maximum": np.maximum, "isfinite": np.isfinite,
                         "concatenate": np.concatenate}
        self._n = 0
        self._seen: dict[str, Value] = {}
        self._consts: dict = {}

    # values
    def K(self, value) -> Value:
        return Value(None, value)

    def ref(self, v: Value) -> str:
        if v.neg is not None and v.code is None:  # a negation nothing could take
            v.code = self.tmp(f"-{self.ref(v.neg)}").code
        if v.const is None:
            assert v.code is not None
            return v.code
        key = (type(v.const), v.const)
        if key not in self._consts:
            name = self._consts[key] = f"k{self._n}"
            self._n += 1
            self.ns[name] = np.array(v.const)  # a 0-d array: numpy's fast path for a scalar
        return self._consts[key]

    def tmp(self, expr: str) -> Value:
        """A new array ``expr`` (an expression already generated is reused: the values
        are never changed once made)."""
        if expr in self._seen:
            return self._seen[expr]
        name = f"t{self._n}"
        self._n += 1
        self.lines.append(f"{name} = {expr}")
        self._seen[expr] = v = Value(name)
        return v

    def bind(self, name: str, value) -> str:
        self.ns[name] = value
        return name

    def check(self, condition: str) -> None:
        """Return None (the general path decides) where ``condition`` is not true."""
        self.lines.append(f"if not ({condition}): return None")

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
        v = self.tmp(f"{self.ref(a)} + {self.ref(b)}")
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
        return self.tmp(f"{self.ref(a)} - {self.ref(b)}")

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
        return self.tmp(f"{self.ref(a)} * {self.ref(b)}")

    def div(self, a: Value, b: Value) -> Value:
        if b.const is not None:
            return self.mul(a, self.K(1.0 / b.const))
        if a.is_const(0):
            return self.K(0.0)
        if a.neg is not None:
            return self.neg(self.div(a.neg, b))
        if b.neg is not None:
            return self.neg(self.div(a, b.neg))
        return self.tmp(f"{self.ref(a)} / {self.ref(b)}")

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
        return self.tmp(f"{self.ref(a)}.conjugate()")

    def re(self, a: Value) -> Value:
        if a.const is not None:
            return self.K(complex(a.const).real)
        if a.neg is not None:
            return self.neg(self.re(a.neg))
        return Value(f"{self.ref(a)}.real")

    def im(self, a: Value) -> Value:
        if a.const is not None:
            return self.K(complex(a.const).imag)
        if a.neg is not None:
            return self.neg(self.im(a.neg))
        return Value(f"{self.ref(a)}.imag")

    def cross(self, a: Value, b: Value) -> Value:
        """``a×b = Im(conj(a)·b)``."""
        return self.im(self.mul(self.conj(a), b))

    def dot(self, a: Value, b: Value) -> Value:
        """``a·b = Re(conj(a)·b)``."""
        return self.re(self.mul(self.conj(a), b))

    def fn(self, name: str, *args: Value, fold=None) -> Value:
        if fold is not None and all(a.const is not None for a in args):
            return self.K(fold(*(a.const for a in args)))
        return self.tmp(f"{name}({', '.join(self.ref(a) for a in args)})")

    def abs(self, a: Value) -> Value:
        if a.neg is not None:
            return self.abs(a.neg)
        return self.fn("abs", a, fold=abs)

    def sqrt(self, a: Value) -> Value:
        return self.fn("sqrt", a, fold=math.sqrt)

    def maximum(self, a: Value, b: Value) -> Value:
        return self.fn("maximum", a, b, fold=max)

    def arg(self, a: Value) -> Value:
        if a.const is not None:
            z = complex(a.const)
            return self.K(math.atan2(z.imag, z.real))
        return self.fn("arctan2", self.im(a), self.re(a))

    def source(self, name: str, args: str, outputs: list[str], free: bool = False) -> str:
        """The function's text; with ``free``, each array is deleted after its last use:
        the next array of its size reuses its memory (numpy's cache of small blocks at 36
        positions, the allocator's free memory at 3,600) instead of all of them being
        held to the end and fresh pages faulted in on every call — faster at every N
        (press: 54 → 50 µs at 36 positions, 1.56 → 0.42 ms at 3,600)."""
        lines = live_lines(self.lines, outputs)
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
            lines = [ln + (f"; del {', '.join(sorted(dead[k]))}" if k in dead else "")
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


__all__ = ["Code", "NotCompiled", "Value", "live_lines", "py_number"]
