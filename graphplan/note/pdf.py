"""A PDF of the note through LibreOffice (``soffice --headless --convert-to pdf``), where it
is installed: the PDF is the DOCX as a word processor lays it out, fields updated."""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from ..errors import InputError

TIMEOUT_S = 180.0  #: the longest a conversion may take
_WINDOWS = (r"C:\Program Files\LibreOffice\program\soffice.exe",
            r"C:\Program Files (x86)\LibreOffice\program\soffice.exe")


def find_office() -> str | None:
    """The LibreOffice executable: ``$GRAPHPLAN_SOFFICE``, ``soffice``/``libreoffice`` on the
    PATH, or the usual place on Windows; None when there is none."""
    env = os.environ.get("GRAPHPLAN_SOFFICE")
    if env:
        return env if Path(env).is_file() else None
    for name in ("soffice", "libreoffice"):
        found = shutil.which(name)
        if found:
            return found
    return next((p for p in _WINDOWS if Path(p).is_file()), None)


def require_office() -> str:
    """The LibreOffice executable, or a one-line error saying what to do instead."""
    office = find_office()
    if office is None:
        raise InputError("note.pdf needs LibreOffice (soffice) on the PATH or in "
                         "$GRAPHPLAN_SOFFICE; without it, open note.docx in Word or "
                         "LibreOffice and save it as PDF")
    return office


def note_pdf(docx: bytes) -> bytes:
    """The PDF of a note's DOCX bytes (LibreOffice in a private profile, bounded in time)."""
    office = require_office()
    with tempfile.TemporaryDirectory(prefix="graphplan-note-") as tmp:
        src = Path(tmp) / "note.docx"
        src.write_bytes(docx)
        profile = (Path(tmp) / "profile").as_uri()
        try:
            subprocess.run([office, f"-env:UserInstallation={profile}", "--headless",
                            "--convert-to", "pdf", "--outdir", tmp, str(src)],
                           capture_output=True, timeout=TIMEOUT_S, check=False)
        except subprocess.TimeoutExpired:
            raise InputError(f"note.pdf: LibreOffice took more than {TIMEOUT_S:g} s") from None
        pdf = Path(tmp) / "note.pdf"
        if not pdf.is_file():
            raise InputError("note.pdf: LibreOffice wrote no PDF (open note.docx and save "
                             "it as PDF)")
        return pdf.read_bytes()
