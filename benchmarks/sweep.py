"""The N sweep: every method on the press from a course project's 36 positions to 360,000.

At each number of positions N the methods are timed in turns in one process
(:func:`benchmarks.timing.interleaved`: medians, the order rotated every round):

* ``graphplan kinematics`` — :func:`graphplan.kinematics.solve`;
* ``graphplan full cycle`` — kinematics + loads + kinetostatics with the variant's
  settings through :class:`graphplan.forces.FullCycle` (compiled once per mechanism
  before the timing, as the closed form reads its data and pylinkage builds its linkage
  once): every point's position, velocity and acceleration, every link's ω and ε, every
  reaction and Mур — the unit of the speed targets;
* ``graphplan full cycle, general objects`` — the same through :func:`solve`,
  :func:`compute_loads` and :func:`solve_forces` (:func:`benchmarks.methods.full_cycle`),
  which build what the plans, tables and the JSON report read;
* ``closed form: kinematics`` and ``closed form: full cycle`` — the press written out
  by hand in numpy (:mod:`benchmarks.closed_form`), the yardstick of the limit;
* ``pylinkage numba`` — pylinkage's ``step_fast_with_kinematics`` (positions, velocities,
  accelerations only; compiled on a first call that is not timed);
* ``pylinkage default`` — its pure-Python ``step_with_derivatives``, timed after the
  others, for every N after the other methods of every N (it fills the heap with Python
  objects, after which numpy's short calls are slower).

The repetitions at each N are as many as fit a time budget (at least 3, at most 31).
"""

from __future__ import annotations

import gc
import math
import statistics
import time

import numpy as np

from . import methods as M
from . import peers
from .timing import interleaved, paired_ratio

SIZES = (36, 360, 3600, 36000, 360000)
"""Positions per turn of the sweep: a course project's 36 to a fine simulation's 360,000."""

GP_KIN, GP_FULL = "graphplan kinematics", "graphplan full cycle"
GP_GENERAL = "graphplan full cycle, general objects"
CF_KIN, CF_FULL = "closed form: kinematics", "closed form: full cycle"
NUMBA, DEFAULT = "pylinkage numba (kinematics)", "pylinkage default (kinematics)"
METHODS = (GP_KIN, GP_FULL, GP_GENERAL, CF_KIN, CF_FULL, NUMBA, DEFAULT)


def grid(n: int) -> np.ndarray:
    """The angles of the benchmark, half a step off the round ones (see run.grid)."""
    return (np.arange(n) + 0.5) * (2 * math.pi / n)


def _once(fn) -> float:
    t = time.perf_counter()
    fn()
    return time.perf_counter() - t


def _reps(single: float, budget_s: float, lo: int = 3, hi: int = 31) -> int:
    return int(max(lo, min(hi, budget_s // max(single, 1e-9))))


def sweep(name: str = "press", sizes=SIZES, budget_s: float = 2.0, default_budget_s: float = 6.0,
          log=print, with_peers: bool = True) -> dict:
    """Median times (s) of every method at every N (``with_peers=False``: graphplan and
    the closed form only)."""
    import graphplan as g
    from graphplan.forces import FullCycle

    from .closed_form import CrankSlider, check
    from .run import ROOT

    mech = g.load(ROOT / "examples" / f"{name}.toml")
    cycle = g.analyse_cycle(mech)
    cs = CrankSlider(mech)
    lean = FullCycle(mech, cycle)
    out: dict = {"mechanism": name, "sizes": list(sizes), "median_s": {m: [] for m in METHODS},
                 "repetitions": [], "paired": {"numba_over_full": []},
                 "closed_form_agreement": check(mech, cycle, grid(360))}
    have_peer = with_peers and peers.available() is not None
    for n in sizes:
        phi = grid(n)
        fns = {GP_KIN: lambda phi=phi: M.kinematics_only(mech, phi),
               GP_FULL: lambda phi=phi: lean(phi),
               GP_GENERAL: lambda phi=phi: M.full_cycle(mech, cycle, phi),
               CF_KIN: lambda phi=phi: cs.kinematics(phi),
               CF_FULL: lambda phi=phi: cs.full_cycle(phi)}
        pl = None
        if have_peer:  # its default path is timed after every size (below)
            from graphplan.kinematics import solve

            pl = peers.PylinkageModel(mech, solve(mech, phi[:1]), 0, float(phi[0]), n)
            if peers.has_numba():
                pl.sweep_numba()  # compiles on its first call (not timed)
                fns[NUMBA] = pl.sweep_numba
        single = max(_once(f) for f in fns.values())
        reps = _reps(single, budget_s)
        times = interleaved(fns, reps)
        med = {k: statistics.median(v) for k, v in times.items()}
        for m in METHODS:
            out["median_s"][m].append(med.get(m))
        out["repetitions"].append(reps)
        out["paired"]["numba_over_full"].append(
            paired_ratio(times[NUMBA], times[GP_FULL], reps) if NUMBA in times else None)
        log(f"  N = {n}: " + ", ".join(f"{m} {med[m] * 1e3:.3g} ms" for m in METHODS
                                       if m in med))
        del pl
        gc.collect()
    # pylinkage's pure-Python path last, alone: it fills the heap with Python objects, and
    # numpy's many short calls timed after it were measurably slower (graphplan's full
    # cycle at N = 3,600: 2.7 ms alone, 15 ms after the default path of N = 360)
    for k, n in enumerate(sizes if have_peer else ()):
        from graphplan.kinematics import solve

        phi = grid(n)
        pl = peers.PylinkageModel(mech, solve(mech, phi[:1]), 0, float(phi[0]), n)
        # one warm-up call when a call is short, none when it takes seconds (the first
        # call then is a sample like the others)
        first = _once(pl.sweep_default)
        reps_d = _reps(first, default_budget_s, lo=3, hi=11)
        ts = [] if first < 1.0 else [first]
        gc.collect()
        while len(ts) < reps_d:
            ts.append(_once(pl.sweep_default))
        out["median_s"][DEFAULT][k] = statistics.median(ts)
        log(f"  N = {n}: {DEFAULT} {out['median_s'][DEFAULT][k] * 1e3:.3g} ms")
        del pl
    return out


def ratios(sw: dict) -> dict:
    """Per N: full cycle against the peers and the closed form (None where not measured)."""
    med = sw["median_s"]

    def r(a, b):
        return [None if x is None or y is None else x / y for x, y in zip(a, b, strict=True)]

    return {"default_over_full": r(med[DEFAULT], med[GP_FULL]),
            "numba_over_full": r(med[NUMBA], med[GP_FULL]),
            "numba_over_full_paired": sw["paired"]["numba_over_full"],
            "full_over_closed_form": r(med[GP_FULL], med[CF_FULL]),
            "kinematics_over_closed_form": r(med[GP_KIN], med[CF_KIN]),
            "numba_over_kinematics": r(med[NUMBA], med[GP_KIN]),
            "general_over_full": r(med.get(GP_GENERAL, [None] * len(med[GP_FULL])),
                                   med[GP_FULL])}


__all__ = ["METHODS", "SIZES", "grid", "ratios", "sweep"]
