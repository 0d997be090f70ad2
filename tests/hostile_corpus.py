"""The hostile corpus of issue 20: inputs a hostile or clumsy user gives graphplan.

Generated, never committed: written lines that cannot be read (``1/0``, ``2^1024``,
``9**9**9``, a zero-width space inside a number, ``ln 0``, ``sqrt(-1)``, nesting, length),
student files (nested TOML, 20,000 lines, CPU bombs, FIFOs, links to ``/dev/zero``, names
that are paths or the summary's, escape sequences, spreadsheet formulas, their own
tolerances and variants), variant files (control characters, ``reading_mm = 0``, guides
0.1° from parallel, 48 positions, non-finite numbers, special files) and output paths
(an existing file, links, folders that are not output folders).

The tests (``tests/test_hostile.py``) run parts of it in-process; run as a script it
runs all of it as a user would, every command a new process bounded by a timeout, and
prints the counts published in ``docs/reliability.md``::

    PYTHONPATH=. python tests/hostile_corpus.py [--timeout 120] [--json FILE]

Counted: inputs, tracebacks (a ``Traceback`` on standard error, or an internal error),
hangs (a command killed at the timeout), silent passes (exit 0, or a class row ``ok``, on
an input that holds an unreadable line), summaries missing after a class run, files
written outside the output folder.
"""

from __future__ import annotations

import contextlib
import json
import os
import random
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
PRESS = EXAMPLES / "press.toml"

# --- written lines ---------------------------------------------------------------------------

GOOD_LINE = "G3 = m3∙g = 1250∙9,81 = 12262,5 Н"
"""A line of the answer key; every hostile line replaces its numbers and keeps the right
result, so a checker that skips what it cannot read says "nothing is wrong"."""

BAD_NUMBERS = {
    # division by zero
    "div-zero": "1250∙9,81/0",
    "div-zero-bracket": "1250∙9,81/(1−1)",
    "div-zero-inner": "1250∙9,81∙(1/0)",
    # results and literals that are not finite
    "pow-1024": "1250∙9,81∙2^1024/2^1024",
    "pow-10-400": "1250∙9,81∙10^400/10^400",
    "literal-1e400": "1250∙9,81∙1e400/1e400",
    "literal-1e400-minus": "1250∙9,81 + 1e400 − 1e400",
    "sum-overflow": "1250∙9,81∙(1e308+1e308)/1e308",
    "tower-9": "1250∙9,81∙9^9^9/9^9^9",
    "tower-2": "1250∙9,81∙2^2^2^2^2/2^2^2^2^2",
    "inf-times-zero": "1250∙9,81 + 1e309∙0",
    "power-superscript": "1250∙9,81∙(10^300)²/(10^300)²",
    # Python and other languages
    "python-power": "1250∙9,81∙9**9**9",
    "python-power-1": "1250**1∙9,81",
    "python-call": "1250∙9,81∙__import__('os')",
    "semicolon": "1250∙9,81;1",
    # invisible characters inside a number
    "zero-width-space": "12\u200b50∙9,81",
    "zero-width-decimal": "1250∙9,\u200b81",
    "word-joiner": "1250\u2060∙9,81",
    "bom-inside": "1250\ufeff∙9,81",
    "soft-hyphen": "1250∙9,81\u00ad",
    "zero-width-joiner": "1250∙9\u200d,81",
    # functions outside their domain
    "ln-0": "1250∙9,81 + ln 0",
    "lg-0": "1250∙9,81∙lg 0/lg 0",
    "sqrt-minus-1": "1250∙9,81 + sqrt(-1)",
    "root-minus-4": "1250∙9,81∙√(−4)/√(−4)",
    "arcsin-2": "1250∙9,81∙arcsin 2/arcsin 2",
    "arccos-minus-2": "1250∙9,81 + arccos(−2)",
    "ctg-0": "1250∙9,81 + ctg 0",
    "cube-root-negative": "1250∙9,81∙(−8)^(1/3)/(−8)^(1/3)",
    "zero-to-minus-1": "1250∙9,81∙0^(−1)",
    # bounds of the reader
    "nested-60": "(" * 60 + "1250∙9,81" + ")" * 60,
    "signs-60": "1250∙9,81∙" + "−" * 60 + "1",
    "length-1000": "1250∙9,81" + "+0" * 500,
    # malformed
    "double-times": "1250∙∙9,81",
    "unmatched-close": "1250∙9,81)",
    "unmatched-open": "((1250∙9,81",
    "trailing-times": "1250∙9,81∙",
    "double-comma": "1250,,0∙9,81",
    "dangling-exponent": "1250∙9,81e",
}

BAD_RESULTS = {
    "result-1e400": "1e400 Н",
    "result-zero-width": "12262,\u200b5 Н",
    "result-div-zero": "12262,5/0 Н",
    "result-empty": "",
}


def hostile_lines() -> dict[str, str]:
    """Name → a line computing G3 right that cannot be read."""
    out = {f"line-{k}": f"G3 = m3∙g = {v} = 12262,5 Н" for k, v in BAD_NUMBERS.items()}
    out.update({f"line-{k}": f"G3 = m3∙g = 1250∙9,81 = {v}" for k, v in BAD_RESULTS.items()})
    return out


def answer_key(folder: Path, variant: Path = PRESS) -> str:
    """The answer key of the press (a correct student file) naming ``variant.toml`` in
    ``folder``, where the variant is copied."""
    from graphplan.checking.generate import generate

    (folder / "press.toml").write_text(variant.read_text(encoding="utf-8"), encoding="utf-8")
    text = generate(folder / "press.toml", variant_ref="press.toml").toml()
    assert f'"{GOOD_LINE}"' in text, "the answer key changed its G3 line"
    return text


def with_line(key: str, line: str) -> str:
    """The key with its G3 line replaced (TOML-escaped)."""
    return key.replace(f'"{GOOD_LINE}"', json.dumps(line, ensure_ascii=True), 1)


# --- student files ---------------------------------------------------------------------------


def _bomb(lines: int, terms: int, seed: int = 1) -> str:
    names = ["G3", "h3", "Pи2", "h2", "G2", "hG2", "R43", "h43", "m2", "m3", "Kl", "Kv"]
    rng = random.Random(seed)
    rows = []
    for _ in range(lines):
        t = "+".join(f"{rng.choice(names)}∙{rng.choice(names)}" for _ in range(terms))
        n = "+".join(f"{rng.randint(1, 99)}∙{rng.randint(1, 9)}" for _ in range(terms))
        rows.append(f'  "R43 = {t} = {n} = 1234 Н",')
    return ('[work]\nvariant = "press.toml"\n[[positions]]\nlabel = "(2)"\nlines = [\n'
            + "\n".join(rows) + "\n]\n")


def student_files(key: str) -> dict[str, str | bytes]:
    """Name → content of hostile student files (text, or bytes for a broken encoding).
    Special files (FIFO, links) are made by :func:`make_class`."""
    work = key.replace("[work]\n", "[work]\n", 1)
    faulty = with_line(key, "G3 = m3∙g = 1250∙9,81 = 11000 Н")
    out: dict[str, str | bytes] = {
        "key.toml": key,
        "nested-500.toml": "x = " + "[" * 500 + "]" * 500 + "\n",
        "nested-table-500.toml": "x = " + "{a = " * 500 + "1" + "}" * 500 + "\n",
        "lines-20000.toml": ('[work]\nvariant = "press.toml"\n[[positions]]\nlabel = "(2)"\n'
                             "lines = [\n" + "".join(f'  "G3 = 1250∙9,81 = {i} Н",\n'
                                                      for i in range(20000)) + "]\n"),
        "bomb-100x50.toml": _bomb(100, 50),
        "big-2mb.toml": key + "#" * (2 << 20) + "\n",
        "summary.csv.toml": key,
        "...toml": key,
        ".hidden.toml": key,
        "A.toml": key,
        "a.toml": key,
        "latin1.toml": key.encode("utf-8") + "# Größe\n".encode("latin-1"),
        "empty.toml": "",
        "binary.toml": bytes(range(256)) * 4,
        "name-escape.toml": work.replace('student = "graphplan"',
                                         'student = "\\u001b[2J\\u001b[31mEvil"', 1),
        "name-bidi.toml": work.replace('student = "graphplan"',
                                       'student = "\\u202eevil\\u202c"', 1),
        "group-formula.toml": work.replace('student = "graphplan"',
                                           'student = "=HYPERLINK(\\"http://x\\",\\"y\\")"\n'
                                           'group = "+cmd|\' /C calc\'!A0"', 1),
        "name-html.toml": work.replace('student = "graphplan"',
                                       'student = "<script>alert(1)</script> | **x**"', 1),
        "own-tolerances.toml": faulty + "\n[tolerances]\nsegment = 1\nsegment_ok = 1\n"
                               "derived = 1\nderived_ok = 1\narithmetic = 1\n",
        "other-variant.toml": work.replace('variant = "press.toml"',
                                           'variant = "bundled:fourbar"', 1),
        "variant-dev-zero.toml": work.replace('variant = "press.toml"',
                                              'variant = "/dev/zero"', 1),
        "variant-nested.toml": work.replace('variant = "press.toml"',
                                            'variant = "nested-500.toml"', 1),
        "variant-self.toml": work.replace('variant = "press.toml"',
                                          'variant = "variant-self.toml"', 1),
        "label-escape.toml": key.replace('label = "1"', 'label = "1\\u001b[0m"', 1),
    }
    for name, line in hostile_lines().items():
        out[f"{name}.toml"] = with_line(key, line)
    return out


SILENT_IF_OK = ("line-", "own-tolerances", "other-variant")
"""Files that must never come out "ok": an unreadable line; a fault hidden by the file's
own tolerances; another variant than the class's (flagged, whatever its verdict)."""


def make_class(folder: Path, key: str | None = None) -> dict[str, str | bytes]:
    """Write the hostile class folder (and its special files); returns the regular files."""
    folder.mkdir(parents=True, exist_ok=True)
    key = key or answer_key(folder)
    (folder / "press.toml").write_text(PRESS.read_text(encoding="utf-8"), encoding="utf-8")
    files = student_files(key)
    for name, data in files.items():
        p = folder / name
        if isinstance(data, bytes):
            p.write_bytes(data)
        else:
            p.write_text(data, encoding="utf-8")
    if hasattr(os, "mkfifo"):
        os.mkfifo(folder / "fifo.toml")
    for name, target in (("dev-zero.toml", "/dev/zero"), ("dev-null.toml", "/dev/null"),
                         ("loop.toml", "loop.toml"), ("dangling.toml", "no-such-file"),
                         ("to-folder.toml", "/")):
        with contextlib.suppress(OSError, NotImplementedError):
            os.symlink(target, folder / name)
    (folder / "folder.toml").mkdir()
    return files


# --- variant files ---------------------------------------------------------------------------


def variant_files() -> dict[str, str | bytes]:
    """Name → content of hostile variant files (and two that must work)."""
    press = PRESS.read_text(encoding="utf-8")
    yoke = (EXAMPLES / "scotch_yoke.toml").read_text(encoding="utf-8")

    def sub(text: str, old: str, new: str) -> str:
        assert re.search(old, text, flags=re.M), old
        return re.sub(old, lambda _m: new, text, count=1, flags=re.M)

    return {
        "title-bell.toml": sub(press, r'^title = ".*"', 'title = "Пресс\\u0007\\u001b[31m"'),
        "title-nul.toml": sub(press, r'^title = ".*"', 'title = "a\\u0000b"'),
        "title-markup.toml": sub(press, r'^title = ".*"',
                                 'title = "<svg onload=alert(1)> & ]]> | *x*"'),
        "author-formula.toml": sub(press, r'^author = ".*"', 'author = "=1+2"'),
        "name-markup.toml": sub(press, r'^name = "press"', 'name = "<b>pr|ess</b>"'),
        "label-markup.toml": sub(press, r'label = "\(2\)"', 'label = "<b>|2"'),
        "label-path.toml": sub(press, r'label = "\(2\)"', 'label = "../../../x"'),
        "reading-0.toml": sub(press, r"^reading_mm = .*", "reading_mm = 0"),
        "positions-48.toml": sub(press, r"^count = 8 .*", "count = 48"),
        "guides-0.1deg.toml": sub(yoke, r"^slot_angle = 90 .*", "slot_angle = 0.1"),
        "guides-0.05deg.toml": sub(yoke, r"^slot_angle = 90 .*", "slot_angle = 179.95"),
        "length-1e400.toml": sub(press, r"^length = 80 .*", "length = 1e400"),
        "length-inf.toml": sub(press, r"^length = 80 .*", "length = inf"),
        "length-nan.toml": sub(press, r"^length = 80 .*", "length = nan"),
        "rpm-huge-int.toml": sub(press, r"^rpm = 55 .*", "rpm = " + "9" * 5000),
        "nested-500.toml": "x = " + "[" * 500 + "]" * 500 + "\n",
        "big-2mb.toml": press + "#" * (2 << 20) + "\n",
        "latin1.toml": press.encode("utf-8") + "# Größe\n".encode("latin-1"),
        "empty.toml": "",
        "binary.toml": bytes(range(256)) * 4,
    }


# --- running (script) ------------------------------------------------------------------------


class Tally:
    """Counts of one kind of run."""

    def __init__(self):
        self.inputs = self.tracebacks = self.hangs = self.silent = self.outside = 0
        self.no_summary = 0
        self.cases: list[dict] = []

    def add(self, name: str, p, *, silent: bool = False, outside: bool = False) -> None:
        self.inputs += 1
        hung = p is None
        err = "" if hung else p.stderr
        tb = (not hung) and ("Traceback" in err or "internal error" in err)
        self.tracebacks += tb
        self.hangs += hung
        self.silent += silent
        self.outside += outside
        self.cases.append({"name": name, "code": None if hung else p.returncode,
                           "traceback": tb, "hang": hung, "silent": silent,
                           "outside": outside,
                           "stderr": "" if hung else err.strip().splitlines()[-1:]})

    def counts(self) -> dict:
        return {"inputs": self.inputs, "tracebacks": self.tracebacks, "hangs": self.hangs,
                "silent": self.silent, "no_summary": self.no_summary,
                "outside": self.outside}


def _run(argv: list[str], timeout: float, cwd: Path) -> subprocess.CompletedProcess | None:
    cmd = [sys.executable, "-m", "graphplan", *argv]
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, encoding="utf-8", errors="replace",
                            start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return None
    return subprocess.CompletedProcess(cmd, proc.returncode, out, err)


def _tree(path: Path) -> set[str]:
    return {str(p.relative_to(path)) for p in path.rglob("*")} if path.exists() else set()


def run_all(work: Path, timeout: float = 120.0) -> dict:
    """Run the whole corpus as a user would (see the module docstring)."""
    work.mkdir(parents=True, exist_ok=True)
    res = {k: Tally() for k in ("check", "class", "analyze", "sheets", "outputs")}
    klass = work / "class"
    files = make_class(klass)
    before = _tree(work)
    # each student file alone, then the folder
    for name in [*sorted(files), "fifo.toml", "dev-zero.toml"]:
        p = _run(["check", str(klass / name)], timeout, work)
        silent = p is not None and p.returncode == 0 and name.startswith(SILENT_IF_OK)
        res["check"].add(name, p, silent=silent)
    out = work / "class-out"
    p = _run(["check", str(klass), "-o", str(out)], max(600.0, timeout * 5), work)
    t = res["class"]
    t.add("class folder", p)
    t.inputs = len([n for n in os.listdir(klass) if n.lower().endswith(".toml")])
    if not (out / "summary.csv").is_file():
        t.no_summary += 1
    else:
        import csv

        with open(out / "summary.csv", encoding="utf-8") as fh:
            for row in csv.DictReader(fh):
                name = Path(row["file"]).name
                if name.startswith(SILENT_IF_OK) and row["status"] == "ok" and not row.get(
                        "notes"):
                    t.silent += 1
                    t.cases.append({"name": name, "silent": True})
    # variants through analyze, analyze --json, sheets
    vdir = work / "variants"
    vdir.mkdir()
    for name, data in variant_files().items():
        (vdir / name).write_bytes(data if isinstance(data, bytes) else data.encode("utf-8"))
    if hasattr(os, "mkfifo"):
        os.mkfifo(vdir / "fifo.toml")
    os.symlink("/dev/zero", vdir / "dev-zero.toml")
    for name in sorted(os.listdir(vdir)):
        for argv in (["analyze", str(vdir / name)], ["analyze", "--json", str(vdir / name)]):
            res["analyze"].add(f"{' '.join(argv[:-1])} {name}", _run(argv, timeout, work))
        sout = work / "sheets" / name
        p = _run(["sheets", str(vdir / name), "-o", str(sout)], timeout, work)
        bad_xml = False
        if p is not None and p.returncode == 0:
            from xml.dom import minidom

            for svg in sout.glob("*.svg"):
                try:
                    minidom.parse(str(svg))
                except Exception:
                    bad_xml = True
        res["sheets"].add(name, p, silent=bad_xml)
    # output paths
    o = work / "outputs"
    o.mkdir()
    (o / "a-file").write_text("x")
    (o / "real").mkdir()
    os.symlink(o / "real", o / "link-folder")
    (o / "holds-folder").mkdir()
    (o / "holds-folder" / "sub").mkdir()
    victim = o / "victim.txt"
    victim.write_text("keep")
    (o / "with-link").mkdir()
    os.symlink(victim, o / "with-link" / "sheet1.svg")
    os.symlink(victim, o / "with-link" / "notes.txt")
    other = work / "other-class"
    other.mkdir()
    (other / "press.toml").write_text(PRESS.read_text(encoding="utf-8"), encoding="utf-8")
    (other / "key.toml").write_bytes((klass / "key.toml").read_bytes())
    for name, argv in (
            ("-o a file", ["sheets", str(PRESS), "-o", str(o / "a-file")]),
            ("-o a link", ["sheets", str(PRESS), "-o", str(o / "link-folder")]),
            ("-o a folder of folders", ["sheets", str(PRESS), "-o", str(o / "holds-folder")]),
            ("-o a folder with links", ["sheets", str(PRESS), "-o", str(o / "with-link")]),
            ("check -o a file", ["check", str(klass / "key.toml"), "-o", str(o / "a-file")]),
            ("two inputs, one name", ["check", str(klass / "key.toml"),
                                      str(other / "key.toml"), "-o", str(o / "two")]),
            ("analyze -o a link", ["analyze", str(PRESS), "-o", str(o / "with-link" /
                                                                    "sheet1.svg")])):
        p = _run(argv, timeout, work)
        res["outputs"].add(name, p, outside=victim.read_text() != "keep")
        victim.write_text("keep")
    twos = list((o / "two").glob("*/report.json")) if (o / "two").exists() else []
    if len(twos) < 2:  # two inputs written onto one output
        res["outputs"].silent += 1
        res["outputs"].cases.append({"name": "two inputs, one name", "silent": True})
    after = _tree(work)
    allowed = ("class-out", "sheets", "outputs", "variants", "class", "other-class")
    stray = {f for f in after - before if not f.startswith(allowed)}
    res["outputs"].outside += len(stray)
    return {k: {**v.counts(), "cases": v.cases} for k, v in res.items()}


def main(argv: list[str] | None = None) -> int:
    import argparse
    import tempfile

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--json", metavar="FILE")
    ap.add_argument("--work", metavar="DIR")
    a = ap.parse_args(argv)
    work = Path(a.work) if a.work else Path(tempfile.mkdtemp(prefix="hostile-"))
    t0 = time.perf_counter()
    res = run_all(work, a.timeout)
    res["seconds"] = round(time.perf_counter() - t0, 1)
    for k, v in res.items():
        if isinstance(v, dict):
            print(f"{k:8s}", {c: n for c, n in v.items() if c != "cases"})
            for c in v["cases"]:
                if c.get("traceback") or c.get("hang") or c.get("silent") or c.get("outside"):
                    print("   ", c)
    print("seconds", res["seconds"], "work", work)
    if a.json:
        Path(a.json).write_text(json.dumps(res, ensure_ascii=False, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
