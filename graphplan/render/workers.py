"""PNG previews and DXF files made in worker processes while the main process goes on.

A PNG of an A1 sheet at 100 dpi is about 0.5–1 s of resvg's rasterising and encoding
(7.7 million pixels), and resvg holds the interpreter's lock all the while, so threads
would not help; a DXF is about 0.3 s of ezdxf's Python. On Linux they are made in forked
worker processes: each sheet's PNG and DXF are handed to a worker as soon as its SVG is
rendered, and the main process goes on with the PDF, the tables and the next sheet; the
bytes are collected at the end. They are the same bytes (the same calls on the same SVG
text and sheet).

Workers are used only where ``fork`` is the safe, cheap way to start them (Linux) and
more than one CPU is available; elsewhere, with ``GRAPHPLAN_JOBS=1``, and in a process
that already runs threads (forking it is unsafe), the previews are drawn one after
another in the main process. The workers are forked when the first PNG is handed over,
before any PDF is compiled (the PDF engine may start threads of its own).
"""

from __future__ import annotations

import os
import sys
import threading
from collections.abc import Mapping
from concurrent.futures import BrokenExecutor, Future, ProcessPoolExecutor

JOBS_ENV = "GRAPHPLAN_JOBS"  #: environment variable: at most this many worker processes


def worker_count(tasks: int) -> int:
    """How many worker processes to make ``tasks`` files with (0: make them here)."""
    if tasks < 1 or sys.platform != "linux":
        return 0
    try:
        cpus = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        cpus = os.cpu_count() or 1
    limit = os.environ.get(JOBS_ENV, "").strip()
    if limit.isdigit():  # anything else: as if unset
        cpus = min(cpus, int(limit))
    return min(tasks, cpus) if cpus > 1 else 0


class PreviewPool:
    """Worker processes for PNG previews (and DXF files), started on the first :meth:`submit`.

    ``submit(fn, *args)`` returns a :class:`Pending` result (or, without workers, the
    value itself); :func:`resolve` turns a dict of both into values. Use as a context
    manager: the workers are shut down on exit.
    """

    def __init__(self, tasks: int):
        self.workers = worker_count(tasks)
        self._pool: ProcessPoolExecutor | None = None

    def submit(self, fn, *args):
        """``fn(*args)`` handed to a worker (a :class:`Pending`), or its value made here when
        there are no workers or the pool cannot take it. Only the hand-over's own errors send
        it in line; ``fn``'s errors are raised as they are, never caught here."""
        pool = self._started()
        if pool is not None:
            try:
                return Pending(pool.submit(fn, *args), fn, args)
            except (OSError, RuntimeError):  # BrokenExecutor is a RuntimeError
                self.workers = 0  # the pool cannot fork or is broken: this and later in line
        return fn(*args)

    def _started(self) -> ProcessPoolExecutor | None:
        """The worker pool, made on the first call; None where previews are made in line."""
        if self.workers and self._pool is None:
            if threading.active_count() > 1:
                self.workers = 0  # a process with threads is not forked (they may hold locks)
                return None
            import multiprocessing

            try:
                self._pool = ProcessPoolExecutor(
                    self.workers, mp_context=multiprocessing.get_context("fork"))
            except (OSError, ValueError, RuntimeError):
                self.workers = 0  # no worker processes here: draw in line
        return self._pool if self.workers else None

    def close(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None

    def __enter__(self) -> PreviewPool:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


class Pending:
    """A preview being drawn by a worker: its future and the call, to draw it in line if
    the worker process was lost (killed, out of memory)."""

    __slots__ = ("args", "fn", "future")

    def __init__(self, future: Future, fn, args: tuple):
        self.future, self.fn, self.args = future, fn, args

    def result(self):
        """The value (the worker's error raised as it was raised there)."""
        try:
            return self.future.result()
        except BrokenExecutor:
            return self.fn(*self.args)


def resolve(files: Mapping[str, object]) -> dict:
    """``files`` with every :class:`Pending` replaced by its result."""
    return {name: (v.result() if isinstance(v, Pending) else v) for name, v in files.items()}


__all__ = ["JOBS_ENV", "Pending", "PreviewPool", "resolve", "worker_count"]
