"""The Russian documentation (issue 23): README.ru.md and a Russian twin of each user
document in docs/, every relative link of them leading to a file that exists, each linked
with its English twin both ways."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
#: Written by their owners (the variant format's and the checker's), in their own time.
OWNED_ELSEWHERE = {"variant-format.md", "check-format.md"}
LINK = re.compile(r"\]\(([^)#\s]+)(#[^)\s]*)?\)")


def _english_docs() -> list[Path]:
    return sorted(p for p in (ROOT / "docs").glob("*.md") if not p.name.endswith(".ru.md"))


def _russian_docs() -> list[Path]:
    return [ROOT / "README.ru.md", *sorted((ROOT / "docs").glob("*.ru.md"))]


@pytest.mark.parametrize("doc", [p.name for p in _english_docs()])
def test_every_user_document_has_a_russian_twin(doc):
    twin = ROOT / "docs" / doc.replace(".md", ".ru.md")
    if doc in OWNED_ELSEWHERE and not twin.exists():
        pytest.skip(f"{doc}: its owner writes the Russian twin")
    assert twin.exists(), f"docs/{doc} has no Russian twin docs/{twin.name}"
    assert f"({doc})" in twin.read_text(encoding="utf-8"), "the twin links to the English"


@pytest.mark.parametrize("doc", [p.relative_to(ROOT).as_posix() for p in _russian_docs()])
def test_russian_documents_link_to_files_that_exist(doc):
    path = ROOT / doc
    text = path.read_text(encoding="utf-8")
    assert re.search(r"[А-Яа-я]{4}", text), f"{doc} is not in Russian"
    for target, _anchor in LINK.findall(text):
        if re.match(r"[a-z]+:", target):
            continue  # https:, mailto:
        assert (path.parent / target).exists(), f"{doc}: a link to {target} leads nowhere"


def test_the_english_readme_links_the_russian_one():
    assert "(README.ru.md)" in (ROOT / "README.md").read_text(encoding="utf-8")
    assert "(README.md)" in (ROOT / "README.ru.md").read_text(encoding="utf-8")
