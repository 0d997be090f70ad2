"""Checking a whole class folder: every student file in its own bounded worker, a summary
that is always written.

:func:`check_folder` checks every student file (``*.toml`` with a ``[work]`` table) of a
folder on ``jobs`` worker processes, writes each student's report
(``<name>/report.html``, ``<name>/report.json``) and the summary (``summary.csv``,
``summary.html``, and the journal ``summary.jsonl``) into the output folder.

Students' files are untrusted, so each is checked in a worker that is bounded
(:class:`Limits`): wall time (the worker is killed and replaced), CPU time and address
space (``resource`` limits where the system has them — not on Windows, where the wall
time still holds), the file's size and TOML nesting. Whatever happens to one file — a
malformed file, a FIFO or a link to ``/dev/zero``, a number that overflows, a worker that
runs out of memory or time or dies — becomes a row of the summary with its reason, and
the others are still checked. Ctrl-C or SIGTERM stops the run: the rows done so far and
the files not checked are written to the summary, then the run exits (130/143). A worker
watches its parent and exits when it is gone (``kill -9`` of the parent leaves no
orphans). ``resume=True`` keeps the rows of ``summary.jsonl`` whose file and settings
have not changed, and checks the rest.

The teacher's rules, not the student's: the tolerances come from the command (or a class
file, :func:`class_rules`), and a student file's own ``[tolerances]`` are ignored (the
row says so); with ``variant`` every file is checked against the teacher's variant. The
summary shows each student's own variant and flags one that differs from the class's
(the teacher's, else the one most of the class uses).

A TOML file without ``[work]`` (the variant itself, kept in the same folder, a class
file, any settings) is not a student file: it is left out (``Batch.skipped``).
"""

from __future__ import annotations

import contextlib
import csv
import dataclasses
import hashlib
import io
import json
import multiprocessing
import os
import re
import sys
import threading
import time
from collections import Counter, deque
from dataclasses import dataclass
from html import escape
from multiprocessing.connection import wait
from pathlib import Path
from urllib.parse import quote

from ..errors import GraphplanError
from ..files import MAX_INPUT_BYTES, decode_text, read_input, write_atomic
from ..safe_text import csv_cell, terminal_text, xml_text

COLUMNS = ("file", "student", "group", "variant", "status", "figures", "ok", "inaccurate",
           "wrong", "unreadable", "findings", "faults", "kinds", "error", "notes", "report")
"""Columns of ``summary.csv``: ``status`` is ``ok`` (nothing wrong), ``faults`` or
``error`` (the file could not be checked: ``error`` says why); ``variant`` is the
student's own variant file; ``unreadable`` counts the written lines that could not be
read as arithmetic (each is a finding); ``faults`` counts the findings that are faults of
their own; ``kinds`` lists them by kind; ``notes`` flags a variant that differs from the
class's and a file's own tolerances that were ignored."""

RESERVED = ("summary.csv", "summary.html", "summary.jsonl")
"""Names of the output folder that are the summary's: a student's report folder never
takes one of them."""


@dataclass(frozen=True, slots=True)
class Limits:
    """Bounds of one student file's check.

    Attributes
    ----------
    seconds : float
        Wall time of one file's check (its worker is killed and replaced beyond it).
    memory_mb : int
        Address space of a worker (``RLIMIT_AS``; where ``resource`` exists).
    max_bytes : int
        Largest student file read.
    """

    seconds: float = 120.0
    memory_mb: int = 1024
    max_bytes: int = MAX_INPUT_BYTES


@dataclass(frozen=True, slots=True)
class Row:
    """One student file of a batch."""

    file: str
    student: str = ""
    group: str = ""
    variant: str = ""
    status: str = "ok"
    figures: int = 0
    ok: int = 0
    inaccurate: int = 0
    wrong: int = 0
    unreadable: int = 0
    findings: int = 0
    faults: int = 0
    kinds: str = ""
    error: str = ""
    notes: str = ""
    report: str = ""
    found: tuple[tuple[str | None, str, str], ...] = ()  # primary: (position, quantity, kind)
    variant_sha: str = ""

    def values(self) -> list:
        return [getattr(self, c) for c in COLUMNS]

    def to_json(self) -> dict:
        d = {c: getattr(self, c) for c in COLUMNS}
        d["found"] = [list(f) for f in self.found]
        d["variant_sha"] = self.variant_sha
        return d

    @classmethod
    def from_json(cls, d: dict) -> Row:
        kw = {f.name: d[f.name] for f in dataclasses.fields(cls) if f.name in d}
        kw["found"] = tuple(tuple(f) for f in d.get("found", ()))
        return cls(**kw)


@dataclass(frozen=True, slots=True)
class Rules:
    """The teacher's rules of a class run: the variant every file is checked against
    (``None``: each file's own), the tolerances, the language of the explanations."""

    variant: Path | None = None
    tolerances: tuple[tuple[str, float], ...] = ()
    lang: str | None = None
    overlay: bool = True

    def key(self) -> dict:
        sha = ""
        if self.variant is not None:
            try:
                sha = hashlib.sha256(read_input(self.variant)).hexdigest()
            except GraphplanError:
                sha = str(self.variant)
        return {"variant": sha, "tolerances": dict(self.tolerances), "lang": self.lang,
                "overlay": self.overlay}


def class_rules(path: str | Path) -> tuple[Path | None, dict[str, float]]:
    """A teacher's class file: ``[class] variant = "press.toml"`` (relative to the class
    file) and ``[tolerances]`` as in a student file. Returns (variant, tolerances)."""
    from ..model import parse_toml
    from .errors import StudentFileError
    from .student import TOLERANCE_KEYS

    path = Path(path)
    raw = read_input(path, error=StudentFileError)
    data = parse_toml(decode_text(raw, str(path), StudentFileError), str(path),
                      StudentFileError)
    for k in data:
        if k not in ("class", "tolerances"):
            raise StudentFileError(f"{path}: {k}: unknown key (expected class, tolerances)")
    variant = None
    klass = data.get("class", {})
    if not isinstance(klass, dict) or any(k != "variant" for k in klass):
        raise StudentFileError(f"{path}: class: expected a table with a variant")
    if "variant" in klass:
        if not isinstance(klass["variant"], str):
            raise StudentFileError(f"{path}: class.variant: expected a file name")
        variant = path.parent / klass["variant"]
        if not variant.is_file():
            raise StudentFileError(f"{path}: class.variant: variant file {str(variant)!r} "
                                   "not found")
    tol = data.get("tolerances", {})
    if not isinstance(tol, dict):
        raise StudentFileError(f"{path}: tolerances: expected a table")
    out = {}
    for k, v in tol.items():
        hi = 10.0 if k == "reading_mm" else 1.0
        if k not in TOLERANCE_KEYS:
            raise StudentFileError(f"{path}: tolerances.{k}: unknown key (expected one of: "
                                   f"{', '.join(TOLERANCE_KEYS)})")
        if isinstance(v, bool) or not isinstance(v, int | float) or not 0 <= v <= hi:
            raise StudentFileError(f"{path}: tolerances.{k}: expected a number in "
                                   f"[0, {hi:g}] (got {v!r})")
        out[k] = float(v)
    return variant, out


# --- one file (in a worker) ------------------------------------------------------------------


def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split()) or type(exc).__name__
    return terminal_text(text)[:500]


def _toml_kind(path: Path, max_bytes: int) -> str:
    """``"student"``, ``"other"`` (a variant, a class file) — or raises the one-line
    error of a file that cannot be read."""
    from ..model import parse_toml
    from .errors import StudentFileError

    raw = read_input(path, max_bytes, StudentFileError)
    try:
        data = parse_toml(decode_text(raw, str(path), StudentFileError), str(path),
                          StudentFileError)
    except StudentFileError:  # not UTF-8, not TOML: load_student reports it with its reason
        return "student"
    return "student" if "work" in data else "other"  # a variant, a class file, settings


def check_one(path: str, out_dir: str | None = None, tolerances: dict | None = None,
              lang: str | None = None, overlay: bool = True, *, report_name: str | None = None,
              variant: str | None = None, max_bytes: int = MAX_INPUT_BYTES,
              folder: str | None = None) -> Row | None:
    """Check one file for a batch; every error becomes the row's ``error``. ``None`` for
    a TOML file that is not a student file (a variant)."""
    p = Path(path)
    known: dict = {}  # what is known of the file when something fails: still in its row

    def failed(error: str) -> Row:
        return Row(str(p), known.get("student", ""), known.get("group", ""),
                   known.get("variant", ""), "error", error=error,
                   notes=known.get("notes", ""), variant_sha=known.get("sha", ""))

    try:
        from .checks import checker_for, overlays
        from .report_html import html_report
        from .student import load_student

        if _toml_kind(p, max_bytes) != "student":
            return None
        work = load_student(p)
        try:
            vsha = hashlib.sha256(read_input(work.variant)).hexdigest()
        except GraphplanError:
            vsha = ""
        notes = []
        if work.tolerances:
            notes.append("the file's own [tolerances] ignored (the teacher's apply)")
        known.update(student=work.student, group=work.group, sha=vsha, notes="; ".join(notes),
                     variant=_variant_name(work.variant, folder or str(p.parent)))
        work = dataclasses.replace(work, tolerances={})
        if variant is not None:
            work = dataclasses.replace(work, variant=Path(variant))
        checker = checker_for(work, tolerances, lang=lang)
        report = checker.run()
        link = ""
        if out_dir is not None:
            name = report_name or p.stem
            target = Path(out_dir) / name
            sheets = overlays(checker, report) if overlay else []
            write_atomic(target / "report.html", html_report(report, sheets), protect=(p,),
                         root=out_dir)
            write_atomic(target / "report.json",
                         json.dumps(report.to_json(), ensure_ascii=False, indent=1,
                                    allow_nan=False) + "\n", protect=(p,), root=out_dir)
            link = f"{name}/report.html"
        c = report.counts()
        prim = [f for f in report.findings if f.verdict == "wrong" and f.primary]
        kinds = Counter(f.kind for f in prim)
        unread = sum(f.kind == "unreadable" for f in report.findings)
        return Row(str(p), report.student, report.group, known["variant"],
                   "ok" if report.ok else "faults", c["ok"] + c["inaccurate"] + c["wrong"],
                   c["ok"], c["inaccurate"], c["wrong"], unread, c["findings"], len(prim),
                   "; ".join(f"{k}: {n}" for k, n in sorted(kinds.items())), "",
                   known["notes"], link,
                   tuple((f.position, f.quantity, f.kind) for f in prim), vsha)
    except MemoryError:
        return failed("not checked: memory limit exceeded")
    except RecursionError:
        return failed("not checked: nested too deeply")
    except (GraphplanError, OSError) as exc:
        return failed(_one_line(exc))
    except Exception as exc:  # a bug of the checker must not stop the class
        return failed(f"internal error of the checker ({type(exc).__name__}: "
                      f"{_one_line(exc)[:200]}); please report it with this file")


def _variant_name(variant: Path, folder: str) -> str:
    try:
        return os.path.relpath(variant, folder) if not str(variant).startswith(
            str(Path(__file__).resolve().parents[2])) else f"bundled:{variant.stem}"
    except ValueError:  # another drive (Windows)
        return str(variant)


# --- workers ---------------------------------------------------------------------------------


def _limit(limits: Limits) -> None:
    """Bound this process (where the system can): address space, file size."""
    try:
        import resource
    except ImportError:  # Windows: the parent's wall-time limit still holds
        return
    mem = limits.memory_mb * 1024 * 1024
    for res, val in ((resource.RLIMIT_AS, mem), (resource.RLIMIT_FSIZE, 256 << 20)):
        try:
            _soft, hard = resource.getrlimit(res)
            resource.setrlimit(res, (val if hard == resource.RLIM_INFINITY else
                                     min(val, hard), hard))
        except (ValueError, OSError):
            pass
    import signal

    if hasattr(signal, "SIGXFSZ"):  # a too-large report is an OSError, not a kill
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)


def _cpu_budget(seconds: float) -> None:
    """Allow this process ``seconds`` more CPU time (``RLIMIT_CPU``: SIGXCPU beyond)."""
    try:
        import resource
    except ImportError:
        return
    used = resource.getrusage(resource.RUSAGE_SELF)
    total = int(used.ru_utime + used.ru_stime + seconds) + 1
    try:
        _soft, hard = resource.getrlimit(resource.RLIMIT_CPU)
        resource.setrlimit(resource.RLIMIT_CPU, (total if hard == resource.RLIM_INFINITY
                                                 else min(total, hard), hard))
    except (ValueError, OSError):
        pass


def _watch_parent(parent: int) -> None:
    """Exit this worker when its parent is gone (``kill -9`` of the parent)."""
    def run():
        if os.name == "posix":
            while os.getppid() == parent:
                time.sleep(0.5)
        else:  # pragma: no cover - Windows
            proc = multiprocessing.parent_process()
            if proc is None:
                return
            wait([proc.sentinel])
        os._exit(3)

    threading.Thread(target=run, daemon=True, name="watch-parent").start()


def _worker_main(conn, parent: int, limits: Limits) -> None:  # pragma: no cover - subprocess
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    if hasattr(signal, "SIGTERM"):
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
    _watch_parent(parent)
    _limit(limits)
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 1000))
    while True:
        try:
            task = conn.recv()
        except (EOFError, OSError):
            break
        if task is None:
            break
        index, args, kw = task
        _cpu_budget(limits.seconds * 1.5 + 5)
        try:
            row = check_one(*args, **kw)
        except MemoryError:
            row = Row(str(args[0]), status="error", error="not checked: memory limit "
                      f"exceeded ({limits.memory_mb} MB)")
        except BaseException as exc:  # anything at all is a row
            row = Row(str(args[0]), status="error", error=f"not checked: "
                      f"{type(exc).__name__}: {_one_line(exc)[:200]}")
        try:
            conn.send((index, row))
        except (OSError, ValueError):
            break
    os._exit(0)


class _Worker:
    def __init__(self, ctx, limits: Limits):
        self.conn, child = ctx.Pipe()
        self.proc = ctx.Process(target=_worker_main, args=(child, os.getpid(), limits),
                                daemon=True, name="graphplan-check")
        self.proc.start()
        child.close()
        self.task: tuple | None = None
        self.deadline = 0.0

    def give(self, task: tuple, seconds: float) -> None:
        self.task = task
        self.deadline = time.monotonic() + seconds
        self.conn.send(task)

    def stop(self) -> None:
        if self.proc.is_alive():
            self.proc.kill()
        self.proc.join(5)
        self.conn.close()


def _death(proc) -> str:
    code = proc.exitcode
    if code is None:
        return "its worker stopped answering"
    if code < 0:
        import signal

        try:
            name = signal.Signals(-code).name
        except ValueError:
            name = f"signal {-code}"
        why = {"SIGXCPU": " (CPU time limit)", "SIGKILL": " (killed: out of memory?)",
               "SIGSEGV": " (crashed)"}.get(name, "")
        return f"its worker died of {name}{why}"
    return f"its worker exited with status {code}"


def _run_pool(tasks: list[tuple], jobs: int, limits: Limits, done) -> None:
    """Run ``tasks`` ((index, args, kw)) on ``jobs`` bounded workers; ``done(index, row)``
    for each, in the order they finish."""
    ctx = multiprocessing.get_context()
    pending = deque(tasks)
    workers: list[_Worker] = []
    try:
        workers = [_Worker(ctx, limits) for _ in range(min(jobs, len(tasks)))]
        while pending or any(w.task for w in workers):
            for w in workers:
                if w.task is None and pending:
                    w.give(pending.popleft(), limits.seconds)
            busy = [w for w in workers if w.task is not None]
            timeout = max(0.0, min(w.deadline for w in busy) - time.monotonic())
            ready = wait([w.conn for w in busy] + [w.proc.sentinel for w in busy],
                         timeout=timeout + 0.05)
            now = time.monotonic()
            for i, w in enumerate(workers):
                if w.task is None:
                    continue
                index, args, _kw = w.task
                if w.conn in ready:
                    try:
                        got, row = w.conn.recv()
                    except (EOFError, OSError, ValueError, TypeError):
                        got, row = None, None
                    if got == index:
                        w.task = None
                        done(index, row)
                        continue
                if w.conn in ready or w.proc.sentinel in ready or now > w.deadline:
                    timed_out = now > w.deadline and w.proc.is_alive()
                    w.stop()
                    why = (f"not checked: it took longer than {limits.seconds:g} s (limit)"
                           if timed_out else f"not checked: {_death(w.proc)}")
                    done(index, Row(str(args[0]), status="error", error=why))
                    workers[i] = _Worker(ctx, limits)
    finally:
        for w in workers:
            if w.task is None and w.proc.is_alive():
                with contextlib.suppress(OSError, ValueError):
                    w.conn.send(None)
        for w in workers:
            if w.task is not None:
                w.stop()
            else:
                w.proc.join(2)
                w.stop()


# --- the batch -------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Batch:
    """The rows of a batch, in file order; ``interrupted`` when the run was stopped."""

    rows: tuple[Row, ...]
    interrupted: bool = False
    class_variant: str = ""
    skipped: tuple[str, ...] = ()  # TOML files without [work]: not students'

    @property
    def ok(self) -> bool:
        return not self.interrupted and all(r.status == "ok" for r in self.rows)

    def csv(self) -> str:
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(COLUMNS)
        for r in self.rows:
            w.writerow([csv_cell(v) for v in r.values()])
        return buf.getvalue()

    def html(self, title: str = "") -> str:
        def esc(v) -> str:
            return escape(xml_text(terminal_text(str(v))))

        head = "".join(f"<th>{esc(c)}</th>" for c in COLUMNS)
        rows = []
        for r in self.rows:
            cells = []
            for c, v in zip(COLUMNS, r.values(), strict=True):
                if c == "report" and v:
                    cells.append(f"<td><a href='{escape(quote(v))}'>{esc(v)}</a></td>")
                elif c == "status":
                    cls = {"ok": "ok", "faults": "wrong", "error": "error"}.get(v, "error")
                    cells.append(f"<td class='{cls}'>{esc(v)}</td>")
                elif c == "notes" and v:
                    cells.append(f"<td class='wrong'>{esc(v)}</td>")
                else:
                    cells.append(f"<td>{esc(v)}</td>")
            rows.append("<tr>" + "".join(cells) + "</tr>")
        n_ok = sum(r.status == "ok" for r in self.rows)
        n_err = sum(r.status == "error" for r in self.rows)
        stop = (" <b>The run was interrupted: the files marked so were not checked.</b>"
                if self.interrupted else "")
        cls = (f" Class variant: {esc(self.class_variant)}." if self.class_variant else "")
        return ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>"
                f"{esc(title or 'graphplan check')}</title><style>"
                "body{font-family:'DejaVu Sans',Arial,sans-serif;margin:2em;font-size:10pt}"
                "table{border-collapse:collapse}th,td{border:1px solid #bbb;padding:2px 6px}"
                "th{background:#eee}.ok{color:#176117}.wrong{color:#b00020;font-weight:bold}"
                ".error{color:#fff;background:#b00020}</style></head><body>"
                f"<h1>{esc(title or 'graphplan check')}</h1>"
                f"<p>{len(self.rows)} files: {n_ok} without faults, "
                f"{len(self.rows) - n_ok - n_err} with faults, {n_err} not checked.{cls}"
                f"{stop}</p><table><tr>{head}</tr>{''.join(rows)}</table></body></html>\n")


def report_names(paths: list[Path]) -> list[str]:
    """The name of each file's report folder: its stem made safe (no ``..``, no leading
    dot, no separator, none of :data:`RESERVED`) and unique (case-insensitively: two
    inputs never share an output)."""
    out, seen = [], set()
    for p in paths:
        stem = p.name[:-5] if p.name.lower().endswith(".toml") else p.name
        name = re.sub(r"[^\w\-. ]", "_", stem).strip(" .") or "student"
        if name.lower() in RESERVED or name.startswith("."):
            name = "_" + name
        base, k = name[:100], 1
        name = base
        while name.lower() in seen:
            k += 1
            name = f"{base}-{k}"
        seen.add(name.lower())
        out.append(name)
    return out


def skipped_files(folder: str | Path) -> list[Path]:
    """The ``*.toml`` of a folder that are TOML but not student files (no ``[work]``);
    read bounded (a FIFO or a huge file is not skipped: it is a row of the summary)."""
    out = []
    for p in student_files(folder):
        try:
            if _toml_kind(p, MAX_INPUT_BYTES) == "other":
                out.append(p)
        except GraphplanError:
            pass
    return out


def student_files(folder: str | Path) -> list[Path]:
    """The ``*.toml`` files of a folder, sorted (which are student files is decided in
    the workers: reading an untrusted file is theirs to bound)."""
    folder = Path(folder)
    return sorted(folder / e.name for e in os.scandir(folder)
                  if e.name.lower().endswith(".toml"))


def _journal_rows(path: Path, settings: dict) -> dict[str, tuple[str, Row]]:
    """The rows a previous run of the same settings wrote to its journal."""
    out: dict[str, tuple[str, Row]] = {}
    try:
        lines = read_input(path, 64 << 20).decode("utf-8", "replace").splitlines()
    except GraphplanError:
        return out
    if not lines:
        return out
    try:
        head = json.loads(lines[0])
    except ValueError:
        return out
    if head.get("settings") != settings:
        return out
    for ln in lines[1:]:
        try:
            d = json.loads(ln)
            row = Row.from_json(d["row"])
        except (ValueError, KeyError, TypeError):
            continue  # a torn last line of a killed run
        out[d["name"]] = (d["sha256"], row)
    return out


def check_folder(folder: str | Path, out_dir: str | Path | None = None, *,
                 jobs: int | None = None, tolerances: dict | None = None,
                 lang: str | None = None, overlay: bool = True,
                 variant: str | Path | None = None, limits: Limits | None = None,
                 resume: bool = False, progress=None) -> Batch:
    """Check every student file of ``folder`` on ``jobs`` bounded workers (default: all
    cores), see the module docstring.

    With ``out_dir``, each student's report goes to ``out_dir/<name>/`` (the file's stem,
    made safe and unique: :func:`report_names`) and the summary to ``out_dir/summary.csv``,
    ``summary.html`` and ``summary.jsonl`` (written row by row, read by ``resume``).
    ``progress(row)`` is called as each file is done. On Ctrl-C (``KeyboardInterrupt``)
    the summary is written with the files not checked, then the interrupt goes on.
    """
    from .errors import StudentFileError

    folder = Path(folder)
    if not folder.is_dir():
        raise StudentFileError(f"{folder}: not a folder")
    limits = limits or Limits()
    files = student_files(folder)
    if not files:
        raise StudentFileError(f"{folder}: no student files (*.toml with a [work] table)")
    names = report_names(files)
    rules = Rules(None if variant is None else Path(variant),
                  tuple(sorted((tolerances or {}).items())), lang, overlay)
    settings = rules.key()
    out = None if out_dir is None else Path(out_dir)
    if out is not None:
        if out.is_symlink():
            raise StudentFileError(f"{out}: a symbolic link; give the output folder itself")
        if out.exists() and not out.is_dir():
            raise StudentFileError(f"{out}: exists and is not a folder")
        try:
            if out.resolve() == folder.resolve():
                raise StudentFileError(f"{out}: the output folder is the class folder; "
                                       "give another one")
        except OSError:
            pass
        out.mkdir(parents=True, exist_ok=True)
    journal = None if out is None else out / "summary.jsonl"
    previous = _journal_rows(journal, settings) if (resume and journal) else {}

    rows: dict[int, Row | None] = {}
    shas: dict[int, str] = {}
    tasks = []
    for i, (p, name) in enumerate(zip(files, names, strict=True)):
        try:
            sha = hashlib.sha256(read_input(p, limits.max_bytes, StudentFileError)
                                 ).hexdigest()
        except GraphplanError as exc:
            rows[i] = Row(str(p), status="error", error=_one_line(exc))
            continue
        shas[i] = sha
        if name in previous and previous[name][0] == sha and not \
                previous[name][1].error.startswith("not checked: the run was interrupted"):
            rows[i] = previous[name][1]
            continue
        kw = {"report_name": name, "variant": None if variant is None else str(variant),
              "max_bytes": limits.max_bytes, "folder": str(folder)}
        tasks.append((i, (str(p), None if out is None else str(out), tolerances, lang,
                          overlay), kw))

    fh = None
    if journal is not None:
        write_atomic(journal, json.dumps({"graphplan_check": 1, "settings": settings}) + "\n",
                     root=out)
        fh = open(journal, "a", encoding="utf-8")  # noqa: SIM115 - closed below

    def record(i: int, row: Row | None) -> None:
        rows[i] = row
        if fh is not None and i in shas:
            fh.write(json.dumps({"name": names[i], "sha256": shas[i],
                                 "row": None if row is None else row.to_json()},
                                ensure_ascii=False) + "\n")
            fh.flush()
        if progress is not None and row is not None:
            progress(row)

    interrupted = False
    try:
        for i, r in sorted(rows.items()):
            if fh is not None and i in shas and r is not None:
                fh.write(json.dumps({"name": names[i], "sha256": shas[i],
                                     "row": r.to_json()}, ensure_ascii=False) + "\n")
        jobs = max(1, jobs or os.cpu_count() or 1)
        if tasks:
            _run_pool(tasks, jobs, limits, record)
    except KeyboardInterrupt:
        interrupted = True
        raise
    finally:
        if fh is not None:
            fh.close()
        batch = _finish(files, rows, rules, interrupted)
        if out is not None:
            protect = tuple(files)
            write_atomic(out / "summary.csv", batch.csv(), protect=protect, root=out)
            write_atomic(out / "summary.html", batch.html(f"graphplan check: {folder}"),
                         protect=protect, root=out)
    return batch


def _finish(files: list[Path], rows: dict[int, Row | None], rules: Rules,
            interrupted: bool) -> Batch:
    """The rows in file order, the files not checked marked, the variants flagged."""
    out = []
    for i, p in enumerate(files):
        if i not in rows:
            out.append(Row(str(p), status="error",
                           error="not checked: the run was interrupted (run again with "
                           "--resume to check the rest)"))
        elif (row := rows[i]) is not None:
            out.append(row)
    shas = Counter(r.variant_sha for r in out if r.variant_sha)
    class_sha, class_name = "", ""
    if rules.variant is not None:
        try:
            class_sha = hashlib.sha256(read_input(rules.variant)).hexdigest()
        except GraphplanError:
            class_sha = ""
        class_name = str(rules.variant)
    elif shas:
        class_sha = shas.most_common(1)[0][0]
        class_name = next(r.variant for r in out if r.variant_sha == class_sha)
    skipped = tuple(str(p) for i, p in enumerate(files) if i in rows and rows[i] is None)
    flagged = []
    for r in out:
        if r.variant_sha and class_sha and r.variant_sha != class_sha:
            note = f"variant {r.variant} differs from the class's ({class_name})"
            r = dataclasses.replace(r, notes="; ".join(x for x in (note, r.notes) if x))
        flagged.append(r)
    return Batch(tuple(flagged), interrupted, class_name, skipped)


__all__ = ["COLUMNS", "RESERVED", "Batch", "Limits", "Row", "Rules", "check_folder",
           "check_one", "class_rules", "report_names", "skipped_files", "student_files"]
