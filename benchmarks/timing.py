"""Timing and memory: medians of repetitions, the methods interleaved in one process."""

from __future__ import annotations

import gc
import statistics
import tracemalloc
from time import perf_counter

ROUNDS = 10
"""Turns of every method in :func:`interleaved` (3 timed calls each of 31 repetitions)."""


def interleaved(fns: dict, reps: int, rounds: int | None = None) -> dict[str, list[float]]:
    """Time every function ``reps`` times in all, seconds per call.

    The methods take turns in ``rounds`` rounds (default :data:`ROUNDS`; the order
    rotated each round), each turn a block of consecutive calls after one untimed
    call, with the garbage collector off as :mod:`timeit` has it. Taking turns spreads a
    shared machine's load over all the methods; the blocks keep a method from being timed
    in the wake of another (a pure-Python sweep leaves the caches cold and garbage
    behind, which would bill the next method for it).
    """
    names = list(fns)
    times: dict[str, list[float]] = {n: [] for n in names}
    rounds = max(1, min(rounds or ROUNDS, reps))
    per = [reps // rounds + (1 if r < reps % rounds else 0) for r in range(rounds)]
    for r in range(rounds):
        order = names[r % len(names):] + names[:r % len(names)]
        for n in order:
            fn = fns[n]
            gc.collect()
            fn()  # warm-up: imports, caches, first allocations
            was = gc.isenabled()
            gc.disable()
            try:
                for _ in range(per[r]):
                    t = perf_counter()
                    fn()
                    times[n].append(perf_counter() - t)
            finally:
                if was:
                    gc.enable()
    return times


def rounds_of(ts: list[float], reps: int, rounds: int | None = None) -> list[list[float]]:
    """Split the times of one method (from :func:`interleaved`) into its turns."""
    rounds = max(1, min(rounds or ROUNDS, reps))
    per = [reps // rounds + (1 if r < reps % rounds else 0) for r in range(rounds)]
    out, k = [], 0
    for p in per:
        out.append(ts[k:k + p])
        k += p
    return out


def paired_ratio(a: list[float], b: list[float], reps: int, rounds: int | None = None) -> float:
    """Median over the rounds of (median of a's turn)/(median of b's turn).

    Two methods timed in the same round ran seconds apart: on a shared machine whose load
    comes and goes, the ratio of their turns is steadier than the ratio of the medians.
    """
    ra, rb = rounds_of(a, reps, rounds), rounds_of(b, reps, rounds)
    return float(statistics.median(median(x) / median(y) for x, y in zip(ra, rb, strict=True)))


def median(ts) -> float:
    return float(statistics.median(ts))


def summary(ts) -> dict:
    """Median, and the spread (min, max) of the repetitions, in seconds."""
    return {"median_s": median(ts), "min_s": float(min(ts)), "max_s": float(max(ts)),
            "repetitions": len(ts)}


def peak_memory(fn) -> int:
    """Peak of the memory traced (bytes) while ``fn`` runs (numpy allocations included)."""
    gc.collect()
    tracemalloc.start()
    tracemalloc.reset_peak()
    try:
        fn()
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    return int(peak)


__all__ = ["interleaved", "median", "paired_ratio", "peak_memory", "rounds_of", "summary"]
