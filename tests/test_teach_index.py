"""Lessons (issue 23): one file name per position label, whatever its letters, and an index
page linking every lesson of the variant."""

from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path

from graphplan.cli import main
from graphplan.teaching import page_name
from graphplan.teaching.index import INDEX_NAME

ROOT = Path(__file__).resolve().parent.parent
PRESS = ROOT / "examples" / "press.toml"


def test_every_label_has_its_own_file_name():
    labels = ["2", "(2)", "(р)", "(х)", "(x)", "(p)", "A", "a", "1'", "1′", "(2) ", "(2)_"]
    names = [page_name("velocity", lab) for lab in labels]
    # distinct even where the folder ignores case (Windows, macOS)
    assert len({n.lower() for n in names}) == len(labels)
    # the names of plain labels do not change (the committed pages, students' bookmarks)
    assert page_name("velocity", "2") == "teach-velocity-2.html"
    assert page_name("forces", "(2)") == "teach-forces-(2).html"
    assert page_name("flywheel", None) == "teach-flywheel.html"
    assert all(re.fullmatch(r"[0-9A-Za-z()_.\-]+", n) for n in names)


class _Links(HTMLParser):
    def __init__(self):
        super().__init__()
        self.links: list[str] = []

    def handle_starttag(self, tag, attrs):
        if tag == "a":
            self.links.append(dict(attrs)["href"])


def _links(path: Path) -> list[str]:
    p = _Links()
    p.feed(path.read_text(encoding="utf-8"))
    return p.links


def test_the_index_links_every_lesson_of_the_folder(tmp_path, capsys):
    assert main(["teach", str(PRESS), "--position", "2", "(2)", "--plan", "velocity",
                 "forces", "-o", str(tmp_path)]) == 0
    index = tmp_path / INDEX_NAME
    links = _links(index)
    pages = sorted(p.name for p in tmp_path.glob("teach-*.html") if p.name != INDEX_NAME)
    assert sorted(links) == pages and len(pages) == 4
    # the textbook's order: velocities before forces, positions in the variant's order
    assert links == ["teach-velocity-2.html", "teach-velocity-(2).html",
                     "teach-forces-2.html", "teach-forces-(2).html"]
    # a later run adds its lessons to the same index
    assert main(["teach", str(PRESS), "--plan", "flywheel", "-o", str(tmp_path)]) == 0
    assert _links(index)[-1] == "teach-flywheel.html" and len(_links(index)) == 5
    text = index.read_text(encoding="utf-8")
    assert "http" not in text.replace("http-equiv", "")  # nothing from the network
    assert "Планы скоростей" in text and "Маховик" in text
    assert "teach-index.html" in capsys.readouterr().out
