"""Checking a whole class folder in parallel, with a summary per student.

:func:`check_folder` checks every student file (``*.toml`` with a ``[work]`` table) of a
folder on all cores (:class:`concurrent.futures.ProcessPoolExecutor`), writes each
student's report (``<name>/report.html``, ``<name>/report.json``) and the summary table
(``summary.csv``, ``summary.html``) into the output folder, and keeps going past a file
that cannot be read or checked: its row says why. A TOML file without ``[work]`` (the
variant itself, kept in the same folder) is not a student file and is left out.
"""

from __future__ import annotations

import csv
import io
import json
import os
import tomllib
from collections import Counter
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from html import escape
from pathlib import Path

from ..errors import GraphplanError, InputError
from ..files import decode_text, write_atomic

COLUMNS = ("file", "student", "group", "status", "figures", "ok", "inaccurate", "wrong",
           "findings", "faults", "kinds", "error", "report")
"""Columns of ``summary.csv``: ``status`` is ``ok`` (nothing wrong), ``faults`` or
``error`` (the file could not be checked: ``error`` says why); ``faults`` counts the
findings that are faults of their own; ``kinds`` lists them by kind."""


@dataclass(frozen=True, slots=True)
class Row:
    """One student file of a batch."""

    file: str
    student: str = ""
    group: str = ""
    status: str = "ok"
    figures: int = 0
    ok: int = 0
    inaccurate: int = 0
    wrong: int = 0
    findings: int = 0
    faults: int = 0
    kinds: str = ""
    error: str = ""
    report: str = ""
    found: tuple[tuple[str | None, str, str], ...] = ()  # primary: (position, quantity, kind)

    def values(self) -> list:
        return [getattr(self, c) for c in COLUMNS]


def is_student_file(path: Path) -> bool:
    """A TOML file with a ``[work]`` table (a file that is not TOML counts: it is
    reported as broken; a TOML without ``[work]`` — a variant, a class file, any other
    settings — is not a student's and is skipped with a note)."""
    try:
        data = tomllib.loads(decode_text(path.read_bytes(), str(path)))
    except (tomllib.TOMLDecodeError, InputError, ValueError):
        return True
    except OSError:
        return True
    return "work" in data


def check_one(path: str, out_dir: str | None = None, tolerances: dict | None = None,
              lang: str | None = None, overlay: bool = True) -> Row:
    """Check one file for a batch; every error becomes the row's ``error``."""
    from .checks import checker_for, overlays
    from .report_html import html_report
    from .student import load_student

    p = Path(path)
    try:
        work = load_student(p)
        checker = checker_for(work, tolerances, lang=lang)
        report = checker.run()
        link = ""
        if out_dir is not None:
            target = Path(out_dir) / p.stem
            sheets = overlays(checker, report) if overlay else []
            write_atomic(target / "report.html", html_report(report, sheets), protect=(p,))
            write_atomic(target / "report.json",
                         json.dumps(report.to_json(), ensure_ascii=False, indent=1,
                                    allow_nan=False) + "\n", protect=(p,))
            link = f"{p.stem}/report.html"
        c = report.counts()
        prim = [f for f in report.findings if f.verdict == "wrong" and f.primary]
        kinds = Counter(f.kind for f in prim)
        return Row(str(p), report.student, report.group,
                   "ok" if report.ok else "faults", c["ok"] + c["inaccurate"] + c["wrong"],
                   c["ok"], c["inaccurate"], c["wrong"], c["findings"], len(prim),
                   "; ".join(f"{k}: {n}" for k, n in sorted(kinds.items())), "", link,
                   tuple((f.position, f.quantity, f.kind) for f in prim))
    except (GraphplanError, OSError) as exc:
        return Row(str(p), status="error", error=" ".join(str(exc).split()))


@dataclass(frozen=True, slots=True)
class Batch:
    """The rows of a batch, in file order."""

    rows: tuple[Row, ...]

    @property
    def ok(self) -> bool:
        return all(r.status == "ok" for r in self.rows)

    def csv(self) -> str:
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(COLUMNS)
        for r in self.rows:
            w.writerow(r.values())
        return buf.getvalue()

    def html(self, title: str = "") -> str:
        head = "".join(f"<th>{escape(c)}</th>" for c in COLUMNS)
        rows = []
        for r in self.rows:
            cells = []
            for c, v in zip(COLUMNS, r.values(), strict=True):
                if c == "report" and v:
                    cells.append(f"<td><a href='{escape(v)}'>{escape(v)}</a></td>")
                elif c == "status":
                    cls = {"ok": "ok", "faults": "wrong", "error": "error"}[v]
                    cells.append(f"<td class='{cls}'>{escape(v)}</td>")
                else:
                    cells.append(f"<td>{escape(str(v))}</td>")
            rows.append("<tr>" + "".join(cells) + "</tr>")
        n_ok = sum(r.status == "ok" for r in self.rows)
        n_err = sum(r.status == "error" for r in self.rows)
        return ("<!DOCTYPE html><html><head><meta charset='utf-8'><title>"
                f"{escape(title or 'graphplan check')}</title><style>"
                "body{font-family:'DejaVu Sans',Arial,sans-serif;margin:2em;font-size:10pt}"
                "table{border-collapse:collapse}th,td{border:1px solid #bbb;padding:2px 6px}"
                "th{background:#eee}.ok{color:#176117}.wrong{color:#b00020;font-weight:bold}"
                ".error{color:#fff;background:#b00020}</style></head><body>"
                f"<h1>{escape(title or 'graphplan check')}</h1>"
                f"<p>{len(self.rows)} files: {n_ok} without faults, "
                f"{len(self.rows) - n_ok - n_err} with faults, {n_err} not checked.</p>"
                f"<table><tr>{head}</tr>{''.join(rows)}</table></body></html>\n")


def student_files(folder: str | Path) -> list[Path]:
    """The student files of a folder (``*.toml`` with ``[work]``), sorted."""
    return [p for p in sorted(Path(folder).glob("*.toml")) if is_student_file(p)]


def skipped_files(folder: str | Path) -> list[Path]:
    """The ``*.toml`` of a folder that are TOML but not student files (no ``[work]``)."""
    return [p for p in sorted(Path(folder).glob("*.toml")) if not is_student_file(p)]


def check_folder(folder: str | Path, out_dir: str | Path | None = None, *,
                 jobs: int | None = None, tolerances: dict | None = None,
                 lang: str | None = None, overlay: bool = True) -> Batch:
    """Check every student file of ``folder`` on ``jobs`` processes (default: all cores).

    With ``out_dir``, each student's report goes to ``out_dir/<file stem>/`` and the
    summary to ``out_dir/summary.csv`` and ``out_dir/summary.html``.
    """
    from .errors import StudentFileError

    folder = Path(folder)
    if not folder.is_dir():
        raise StudentFileError(f"{folder}: not a folder")
    files = student_files(folder)
    if not files:
        raise StudentFileError(f"{folder}: no student files (*.toml with a [work] table)")
    jobs = max(1, min(jobs or os.cpu_count() or 1, len(files)))
    out = None if out_dir is None else str(out_dir)
    args = [(str(p), out, tolerances, lang, overlay) for p in files]
    if jobs == 1:
        rows = [check_one(*a) for a in args]
    else:
        with ProcessPoolExecutor(max_workers=jobs) as ex:
            rows = list(ex.map(check_one, *zip(*args, strict=True),
                               chunksize=max(1, len(args) // (4 * jobs))))
    batch = Batch(tuple(rows))
    if out_dir is not None:
        protect = tuple(files)
        write_atomic(Path(out_dir) / "summary.csv", batch.csv(), protect=protect)
        write_atomic(Path(out_dir) / "summary.html", batch.html(f"graphplan check: {folder}"),
                     protect=protect)
    return batch


__all__ = ["COLUMNS", "Batch", "Row", "check_folder", "check_one", "is_student_file",
           "skipped_files", "student_files"]
