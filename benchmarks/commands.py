"""Whole commands timed cold: a new process each time, as a user runs them.

Each command is run as ``python -m graphplan …`` in a fresh process (with this checkout
first on ``PYTHONPATH``, so the code measured is the code of the checkout): Python's
start, the imports, the analysis and writing every file all count. The first run uses an
empty cache folder (``$GRAPHPLAN_CACHE_DIR``: the font metrics are measured then, as on a
user's first run ever) and is reported apart (``first_run_s``); the figure judged is the
median of the next runs, which find the cache as a user's later runs do.

The package's modules are compiled to bytecode before the timing (not timed), as
``pip install`` does: an environment with ``PYTHONDONTWRITEBYTECODE`` set would otherwise
compile every module of the checkout again in every timed run (0.1–0.2 s).

The class of students is generated before the timing (not timed): works written by
:func:`graphplan.checking.generate.generate` over the examples, read with drafting
noise, most with faults planted (:func:`graphplan.checking.generate.inject`).
"""

from __future__ import annotations

import os
import random
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: name → arguments of ``graphplan`` ({out} the output folder, {class} the class folder)
COMMANDS: dict[str, list[str]] = {
    "sheets press": ["sheets", "examples/press.toml", "-o", "{out}"],
    "sheets six-bar": ["sheets", "examples/sixbar_press.toml", "-o", "{out}"],
    "sheets press --format all": ["sheets", "examples/press.toml", "-o", "{out}",
                                  "--format", "all"],
    "check a class": ["check", "{class}", "-o", "{out}", "--jobs", "2"],
}

#: the examples a generated class is drawn from (each a different machine)
CLASS_VARIANTS = ("press", "fourbar", "shaper", "offset_slider", "sixbar_press", "engine",
                  "slotter", "scotch_yoke")


def write_class(folder: Path, size: int, seed: int = 0) -> list[Path]:
    """``size`` student files in ``folder``: round-robin over :data:`CLASS_VARIANTS`, read
    with ±0.5 mm drafting noise, one in six correct, the others with 1–3 planted faults."""
    from graphplan.checking.generate import FAULT_KINDS, Drafting, generate, inject
    from graphplan.checking.reference import Reference

    folder.mkdir(parents=True, exist_ok=True)
    rng = random.Random(seed)
    refs: dict[str, Reference] = {}
    labels: dict[str, list[str]] = {}
    out = []
    for k in range(size):
        name = CLASS_VARIANTS[k % len(CLASS_VARIANTS)]
        variant = ROOT / "examples" / f"{name}.toml"
        if name not in refs:
            refs[name] = Reference.of(str(variant))
            labels[name] = [p.label for p in generate(variant, ref=refs[name]).positions]
        ref, labs = refs[name], labels[name]
        pos = tuple(sorted(rng.sample(labs, min(3, len(labs))), key=labs.index))
        gen = generate(variant, positions=pos, variant_ref=str(variant.resolve()), ref=ref,
                       drafting=Drafting(0.5, random.Random(seed * 7919 + k)),
                       student=f"student {k}")
        if k % 6:
            kinds = tuple(rng.sample(FAULT_KINDS, rng.choice((1, 2, 3))))
            fits: list[str] = []
            for kind in kinds:
                try:
                    inject(gen, (*fits, kind), random.Random(k), ref)
                    fits.append(kind)
                except ValueError:
                    continue
            if fits:
                gen, _ = inject(gen, tuple(fits), random.Random(k), ref)
        path = folder / f"{k:03d}-{name}.toml"
        path.write_text(gen.toml(), encoding="utf-8")
        out.append(path)
    return out


def _run(args: list[str], env: dict) -> float:
    t = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "graphplan", *args], cwd=ROOT, env=env,
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          timeout=1800)
    dt = time.perf_counter() - t
    # `check` exits 1 when it finds faults in the students' work: that is its answer
    if done.returncode not in (0, 1):
        raise RuntimeError(f"graphplan {' '.join(args)} failed ({done.returncode}): "
                           f"{done.stderr.strip()[-500:]}")
    return dt


def compile_package() -> None:
    """Byte-compile the checkout's ``graphplan`` (as ``pip install`` does for a user)."""
    import compileall

    compileall.compile_dir(str(ROOT / "graphplan"), quiet=1, workers=1)


def time_commands(runs: int = 5, class_size: int = 100, names=None, log=print) -> dict:
    """Cold timings of :data:`COMMANDS` (seconds): first run, median and spread of ``runs``."""
    names = list(names or COMMANDS)
    out: dict = {}
    compile_package()
    with tempfile.TemporaryDirectory(prefix="graphplan-bench-") as tmp:
        tmp_path = Path(tmp)
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join([str(ROOT), *filter(None, [env.get("PYTHONPATH")])])
        env["GRAPHPLAN_CACHE_DIR"] = str(tmp_path / "cache")
        klass = tmp_path / "class"
        if "check a class" in names:
            t = time.perf_counter()
            write_class(klass, class_size)
            log(f"  a class of {class_size} students written in {time.perf_counter() - t:.0f} s")
        for name in names:
            args = [a.replace("{class}", str(klass)) for a in COMMANDS[name]]
            shutil.rmtree(tmp_path / "cache", ignore_errors=True)  # the first run ever
            times = []
            for k in range(runs + 1):
                dest = tmp_path / f"out-{k}"
                times.append(_run([a.replace("{out}", str(dest)) for a in args], env))
                shutil.rmtree(dest, ignore_errors=True)
            timed = times[1:]
            shown = " ".join(COMMANDS[name]).format(out="OUT", **{"class": "CLASS"})
            entry = {"command": f"graphplan {shown}",
                     "first_run_s": times[0], "median_s": statistics.median(timed),
                     "min_s": min(timed), "max_s": max(timed), "runs": len(timed)}
            if name == "check a class":
                entry["students"] = class_size
            out[name] = entry
            log(f"  {name}: {entry['median_s']:.2f} s (first run {times[0]:.2f} s)")
    return out


__all__ = ["CLASS_VARIANTS", "COMMANDS", "time_commands", "write_class"]
