"""A class folder: 100 generated student files with injected faults, checked in parallel;
every fault is found, a broken file is reported and the rest are still checked."""

import csv
import random
from pathlib import Path

import pytest

from graphplan.checking.batch import check_folder
from graphplan.checking.checks import reference_for
from graphplan.checking.generate import FAULT_KINDS, generate, inject
from graphplan.files import bundled_example

STUDENTS = 100


@pytest.fixture(scope="module")
def klass(tmp_path_factory):
    folder = tmp_path_factory.mktemp("class")
    variant = Path(bundled_example("press"))
    (folder / "press.toml").write_text(variant.read_text(encoding="utf-8"), encoding="utf-8")
    key = generate(folder / "press.toml", variant_ref="press.toml")
    ref = reference_for(folder / "press.toml")
    rng = random.Random(20240601)
    expected = {}
    for n in range(STUDENTS):
        kinds = tuple(rng.sample(FAULT_KINDS[:6], rng.randint(0, 3)))  # the kinds of 2024
        work, faults = inject(key, kinds, rng, ref)
        name = f"student{n:03d}.toml"
        (folder / name).write_text(work.toml(), encoding="utf-8")
        expected[name] = {(f.position, f.quantity, f.finding_kind) for f in faults}
    (folder / "broken.toml").write_text("[work]\nvariant = 'press.toml'\n[[positions]\n",
                                        encoding="utf-8")
    return folder, expected


def test_every_fault_of_the_class_is_found(klass, tmp_path):
    folder, expected = klass
    out = tmp_path / "out"
    batch = check_folder(folder, out, jobs=2, overlay=False)
    rows = {Path(r.file).name: r for r in batch.rows}
    assert "press.toml" not in rows  # the variant in the same folder is not a student
    assert len(rows) == STUDENTS + 1
    broken = rows.pop("broken.toml")
    assert broken.status == "error" and "broken.toml" in broken.error
    assert "not valid TOML" in broken.error
    for name, row in rows.items():
        assert set(row.found) == expected[name], name
        assert row.status == ("faults" if expected[name] else "ok"), name
    assert sum(bool(e) for e in expected.values()) > 50
    assert not batch.ok
    # the summary, as a teacher opens it
    with open(out / "summary.csv", encoding="utf-8") as fh:
        table = list(csv.DictReader(fh))
    assert len(table) == STUDENTS + 1
    assert {r["status"] for r in table} == {"ok", "faults", "error"}
    html = (out / "summary.html").read_text(encoding="utf-8")
    assert html.count("<tr>") == STUDENTS + 2 and "student000/report.html" in html
    assert (out / "student000" / "report.json").is_file()
