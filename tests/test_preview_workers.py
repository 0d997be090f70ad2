"""PNG previews and DXFs made by worker processes are those made in line (issue 21).

graphplan.render.workers hands each sheet's PNG and DXF to a forked worker (Linux, more
than one CPU) while the main process goes on; GRAPHPLAN_JOBS=1 makes them in line. The bytes
must not depend on which did it, a lost worker must not lose a preview, and a worker's
error must reach the caller as the same error.
"""

from __future__ import annotations

import os
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from graphplan.render import workers
from graphplan.render.workers import PreviewPool, resolve, worker_count

linux_multi = pytest.mark.skipif(
    sys.platform != "linux" or len(os.sched_getaffinity(0)) < 2,
    reason="workers are used on Linux with more than one CPU")
no_threads = pytest.mark.skipif(
    threading.active_count() > 1, reason="a process with threads is not forked (pytest-xdist "
    "runs threads: test_previews_same_from_workers checks the workers in new processes)")


def test_worker_count(monkeypatch):
    monkeypatch.delenv(workers.JOBS_ENV, raising=False)
    assert worker_count(0) == 0
    monkeypatch.setenv(workers.JOBS_ENV, "1")
    assert worker_count(3) == 0  # one job: in line
    monkeypatch.setenv(workers.JOBS_ENV, "many")  # not a number: as if unset
    n = worker_count(3)
    assert 0 <= n <= 3


def _square(x):
    return x * x


def _fail(x):
    raise ValueError(f"bad {x}")


PARENT = os.getpid()


def _die(x):
    """Kills the worker it runs in (as if killed or out of memory); in line it returns."""
    if os.getpid() != PARENT:
        os._exit(3)
    return f"in line {x}"


@linux_multi
@no_threads
def test_pool_results_and_errors(monkeypatch):
    monkeypatch.setenv(workers.JOBS_ENV, "2")
    with PreviewPool(2) as pool:
        assert pool.workers == 2
        files = {"a": pool.submit(_square, 3), "b": "text", "c": pool.submit(_square, 4)}
        assert isinstance(files["a"], workers.Pending)
        assert resolve(files) == {"a": 9, "b": "text", "c": 16}
        with pytest.raises(ValueError, match="bad 5"):  # the worker's error, as raised there
            resolve({"x": pool.submit(_fail, 5)})
    with PreviewPool(2) as pool:  # a worker lost: the preview is drawn in line
        assert resolve({"x": pool.submit(_die, 1)}) == {"x": "in line 1"}


def test_pool_in_line(monkeypatch):
    monkeypatch.setenv(workers.JOBS_ENV, "1")
    with PreviewPool(3) as pool:
        assert pool.workers == 0
        assert pool.submit(_square, 5) == 25


@linux_multi
def test_previews_same_from_workers(tmp_path):
    """Every file of `graphplan sheets --format all` (the press: three sheets) is
    the same byte for byte whether its PNGs and DXFs were made by workers or in line (new
    processes, as a user runs it: no threads there)."""
    pytest.importorskip("ezdxf")
    pytest.importorskip("resvg_py")
    pytest.importorskip("typst")
    root = Path(__file__).resolve().parent.parent
    outs = {}
    for jobs in ("1", "2"):
        env = {**os.environ, workers.JOBS_ENV: jobs,
               "PYTHONPATH": os.pathsep.join([str(root), os.environ.get("PYTHONPATH", "")])}
        outs[jobs] = tmp_path / f"jobs{jobs}"
        subprocess.run([sys.executable, "-m", "graphplan", "sheets", "examples/press.toml",
                        "-o", str(outs[jobs]), "--format", "all", "--dpi", "20"],
                       cwd=root, env=env, check=True, capture_output=True, timeout=600)
    names = sorted(p.name for p in outs["1"].iterdir())
    assert names == sorted(p.name for p in outs["2"].iterdir())
    assert [n for n in names if n.endswith(".png")] == ["sheet1.png", "sheet2.png",
                                                         "sheet3.png"]
    for name in names:
        assert (outs["1"] / name).read_bytes() == (outs["2"] / name).read_bytes(), name


def test_no_fork_with_threads(monkeypatch):
    """A process running threads draws its previews in line (forking it is unsafe)."""
    monkeypatch.setenv(workers.JOBS_ENV, "2")
    stop = threading.Event()
    t = threading.Thread(target=stop.wait)
    t.start()
    try:
        with PreviewPool(2) as pool:
            assert pool.submit(_square, 6) == 36
            assert pool.workers == 0
    finally:
        stop.set()
        t.join()


def test_a_refused_hand_over_draws_in_line(monkeypatch):
    """A pool that cannot fork (OSError on the hand-over) draws this preview and every later
    one in line; a preview's own error made in line is raised as it is, not caught or
    chained to the hand-over's."""
    monkeypatch.setenv(workers.JOBS_ENV, "2")
    handed: list = []

    class Refusing:
        def __init__(self, *a, **kw):
            pass

        def submit(self, fn, *args):
            handed.append(fn)
            raise OSError("fork refused")

        def shutdown(self, **kw):
            pass

    monkeypatch.setattr(workers, "ProcessPoolExecutor", Refusing)
    monkeypatch.setattr(workers, "worker_count", lambda tasks: 2)
    monkeypatch.setattr(workers.threading, "active_count", lambda: 1)
    with PreviewPool(3) as pool:
        assert pool.submit(_square, 7) == 49  # refused, drawn here
        assert pool.workers == 0
        with pytest.raises(ValueError, match="bad 8") as err:
            pool.submit(_fail, 8)
        assert err.value.__context__ is None  # not raised while handling the refusal
    assert handed == [_square]  # once refused, never handed over again
