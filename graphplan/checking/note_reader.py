"""An explanatory note written from graphplan's template (``graphplan note``, a DOCX) read
back as a student file, so that ``graphplan check NOTE.docx`` checks the lines a student
kept or edited in Word.

What is read (the conventions of :mod:`graphplan.note.docx_writer`): the paragraphs of the
style ``GP Formula`` are the calculation's lines, their number ``(2.3)`` after a tab dropped;
a heading ``Положение N, …`` (``Position N, …``) opens position N, any other heading of level
1–2 goes back to the general lines; ``h — плечо силы F относительно точки B`` (``h is the arm
of F about point B``) declares an arm; the document's keywords ``graphplan-variant=PATH``
name the variant (relative to the note), its author the student. Only the standard library
reads the file (a DOCX is a zip of XML), bounded in size.
"""

from __future__ import annotations

import io
import re
import zipfile
from pathlib import Path
from xml.etree import ElementTree as ET

from .errors import StudentFileError

W = "{http://schemas.openxmlformats.org/wordprocessingml/2006/main}"
MAX_XML_BYTES = 64 * 1024 * 1024  #: the largest document.xml read
FORMULA_STYLE = "GP Formula"
_NUMBER = re.compile(r"\t\(\d+(?:\.\d+)*\)\s*$")
_POSITION = re.compile(r"^\s*(?:\d+(?:\.\d+)*\s+)?(?:Положение|Position)\s+(\S+?),")
_ARM = re.compile(r"^\s*(\S+)\s+(?:—|-|–)\s+плечо силы\s+(\S+)\s+относительно точки\s+(\S+?)[,.\s]"
                  r"|^\s*(\S+)\s+is the arm of\s+(\S+)\s+about point\s+(\S+?)[,.\s]")


def _xml(z: zipfile.ZipFile, name: str, source: str) -> ET.Element | None:
    try:
        info = z.getinfo(name)
    except KeyError:
        return None
    if info.file_size > MAX_XML_BYTES:
        raise StudentFileError(f"{source}: {name}: {info.file_size} bytes, at most "
                               f"{MAX_XML_BYTES} are read")
    try:
        return ET.fromstring(z.read(name))
    except ET.ParseError as exc:
        raise StudentFileError(f"{source}: {name}: not valid XML ({exc})") from None


def _text(p: ET.Element) -> str:
    out = []
    for el in p.iter():
        if el.tag == W + "t" and el.text:
            out.append(el.text)
        elif el.tag == W + "tab":
            out.append("\t")
    return "".join(out)


def _q(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def note_student_toml(path: str | Path, data: bytes) -> str:
    """The student file (TOML text, ``docs/check-format.md``) of a DOCX note: ``data`` are
    the file's bytes (read bounded by the caller), ``path`` names it."""
    path = Path(path)
    source = str(path)
    try:
        z = zipfile.ZipFile(io.BytesIO(data))
    except (zipfile.BadZipFile, OSError) as exc:
        raise StudentFileError(f"{source}: not a DOCX file ({exc})") from None
    with z:
        doc = _xml(z, "word/document.xml", source)
        if doc is None:
            raise StudentFileError(f"{source}: not a DOCX file (no word/document.xml)")
        styles = _xml(z, "word/styles.xml", source)
        core = _xml(z, "docProps/core.xml", source)
    names: dict[str, str] = {}
    if styles is not None:
        for st in styles.iter(W + "style"):
            name = st.find(W + "name")
            if name is not None:
                names[st.get(W + "styleId", "")] = name.get(W + "val", "")
    variant, student = "", ""
    if core is not None:
        for el in core:
            tag = el.tag.rsplit("}", 1)[-1]
            if tag == "keywords" and el.text and "graphplan-variant=" in el.text:
                variant = el.text.split("graphplan-variant=", 1)[1].strip()
            elif tag == "creator" and el.text:
                student = el.text.strip()
    if not variant:
        raise StudentFileError(f"{source}: the note names no variant (keywords "
                               "'graphplan-variant=…'): give it with --variant")
    general: list[str] = []
    positions: dict[str, tuple[list[str], dict[str, tuple[str, str]]]] = {}
    current: str | None = None
    body = doc.find(W + "body")
    for p in (body if body is not None else []):
        if p.tag != W + "p":
            continue
        ppr = p.find(W + "pPr")
        sid = ""
        pstyle = ppr.find(W + "pStyle") if ppr is not None else None
        if pstyle is not None:
            sid = pstyle.get(W + "val", "")
        style = names.get(sid, sid)
        text = _text(p)
        if style.lower().startswith("heading"):
            m = _POSITION.match(text)
            level = style[-1:]
            if m:
                current = m.group(1)
                positions.setdefault(current, ([], {}))
            elif level in ("1", "2"):
                current = None
            continue
        arm = _ARM.match(text + " ")
        if arm and current is not None:
            g = [x for x in arm.groups() if x is not None]
            positions[current][1][g[0]] = (g[1], g[2])
            continue
        if style == FORMULA_STYLE and text.strip():
            line = _NUMBER.sub("", text).strip()
            (general if current is None else positions[current][0]).append(line)
    out = ["[work]", f"variant = {_q(variant)}", f"student = {_q(student or path.stem)}",
           'lang = "ru"', f"source = {_q(path.name)}", "", "[general]", "lines = ["]
    out += [f"  {_q(ln)}," for ln in general]
    out.append("]")
    for label, (lines, arms) in positions.items():
        if not lines:
            continue
        out += ["", "[[positions]]", f"label = {_q(label)}"]
        if arms:
            inner = ", ".join(f"{_q(n)} = {{ force = {_q(f)}, about = {_q(a)} }}"
                              for n, (f, a) in arms.items())
            out.append(f"arms = {{ {inner} }}")
        out.append("lines = [")
        out += [f"  {_q(ln)}," for ln in lines]
        out.append("]")
    return "\n".join(out) + "\n"
