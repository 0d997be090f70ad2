"""Time to write each A1 sheet: build the sheet, render its SVG, write it to disk.

The sheets are listed in :data:`SHEETS`, ``(name, module, function)``; a sheet whose
module does not exist yet is skipped, so a new sheet is one more line here.
"""

from __future__ import annotations

import importlib
import tempfile
from pathlib import Path
from time import perf_counter

from .timing import median

SHEETS: tuple[tuple[str, str, str], ...] = (
    ("sheet1", "graphplan.drawing.sheet1", "kinematics_sheet"),
    ("sheet2", "graphplan.drawing.sheet2", "kinetostatics_sheet"),
    ("sheet3", "graphplan.drawing.sheet3", "dynamics_sheet"),
)
"""The sheets of a project: name, module, and the function ``f(analysis, lang=…) -> Sheet``."""


def sheet_functions() -> dict:
    """The sheets that exist in this graphplan: name → function."""
    out = {}
    for name, module, fn in SHEETS:
        try:
            out[name] = getattr(importlib.import_module(module), fn)
        except (ImportError, AttributeError):
            continue
    return out


def write_sheet(fn, analysis, path: Path, lang: str = "ru") -> None:
    from graphplan.files import write_atomic
    from graphplan.render.svg import render_svg

    write_atomic(path, render_svg(fn(analysis, lang=lang)))


def time_sheets(analysis, reps: int = 3) -> dict:
    """Per sheet: the first write in this process (``first_s``: fonts and caches loaded
    then) and the median of ``reps`` more; and the three in a row, cold and warm."""
    fns = sheet_functions()
    out: dict = {}
    with tempfile.TemporaryDirectory() as tmp:
        t_all = perf_counter()
        for name, fn in fns.items():
            t = perf_counter()
            write_sheet(fn, analysis, Path(tmp) / f"{name}.svg")
            out[name] = {"first_s": perf_counter() - t}
        first_all = perf_counter() - t_all
        warm_all = []
        for _ in range(reps):
            t_all = perf_counter()
            for name, fn in fns.items():
                t = perf_counter()
                write_sheet(fn, analysis, Path(tmp) / f"{name}.svg")
                out[name].setdefault("times", []).append(perf_counter() - t)
            warm_all.append(perf_counter() - t_all)
        size = {name: (Path(tmp) / f"{name}.svg").stat().st_size for name in fns}
    for name in fns:
        ts = out[name].pop("times")
        out[name].update(median_s=median(ts), repetitions=len(ts), bytes=size[name])
    out["all"] = {"first_s": first_all, "median_s": median(warm_all), "sheets": list(fns)}
    return out


__all__ = ["SHEETS", "sheet_functions", "time_sheets", "write_sheet"]
