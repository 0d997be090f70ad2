"""``graphplan check``: exit status, the JSON for scripts, the files it writes, its reports."""

import json
import random
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from graphplan.checking.generate import generate, inject
from graphplan.cli import main
from graphplan.files import bundled_example

SEED = Path(__file__).resolve().parent.parent / "examples" / "seed-check" / "seed.toml"
KEYS = {"where", "quantity", "stated", "expected", "kind", "verdict", "explanation"}


@pytest.fixture(scope="module")
def answer_key(tmp_path_factory):
    d = tmp_path_factory.mktemp("key")
    path = d / "key.toml"
    assert main(["check", "--answer-key", str(bundled_example("press")), "-o", str(path)]) == 0
    return path


def test_seed_json_for_scripts(capsys):
    assert main(["check", str(SEED), "--json", "--lang", "en"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert data["findings"] and all(set(f) >= KEYS for f in data["findings"])
    assert {f["verdict"] for f in data["findings"]} <= {"ok", "inaccurate", "wrong"}
    kinds = {f["kind"] for f in data["findings"]}
    assert {"arithmetic", "unit", "scale", "sign", "lever-arm", "consistency"} <= kinds
    assert data["summary"]["wrong"] > 0 and data["figures"]


def test_answer_key_passes_and_exits_0(answer_key, capsys):
    assert main(["check", str(answer_key)]) == 0
    assert "ошибок нет" in capsys.readouterr().out


def test_terminal_summary_of_the_seed(capsys):
    assert main(["check", str(SEED), "--lang", "en"]) == 1
    out = capsys.readouterr().out
    assert "position 2" in out and "arithmetic" in out and "follows from R43 (2)" in out
    assert "✗" in out and "↳" in out


def test_outputs_are_written(tmp_path, capsys):
    out = tmp_path / "out"
    html, svg = tmp_path / "r.html", tmp_path / "o.svg"
    assert main(["check", str(SEED), "-o", str(out), "--html", str(html), "--svg",
                 str(svg)]) == 1
    capsys.readouterr()
    for p in (out / "report.html", out / "report.json", out / "overlay.svg", html, svg):
        assert p.is_file() and p.stat().st_size > 1000, p
    text = html.read_text(encoding="utf-8")
    # self-contained: no stylesheet, script or picture from elsewhere
    assert "<link" not in text and "<script" not in text and "src=" not in text
    assert text.count("<svg") == len(list(out.glob("overlay*.svg")))
    assert "R43" in text and "8145" in text


def test_overlay_marks_the_wrong_lengths(tmp_path, capsys):
    svg = tmp_path / "o.svg"
    main(["check", str(SEED), "--svg", str(svg), "--json"])
    data = json.loads(capsys.readouterr().out)
    root = ET.parse(svg).getroot()
    assert root.get("width") == "841mm" and root.get("viewBox") == "0 0 841 594"
    # a text may carry subscripts as tspans (R₁₂): read all of it
    texts = ["".join(el.itertext()) for el in root.iter("{http://www.w3.org/2000/svg}text")
             if el.get("id", "").endswith("-mark")]
    # the first sheet holds positions (2), (3), 2, 3: their wrong lengths on paper
    wrong_mm = {(f["position"], f["quantity"].replace("_mm", "")) for f in data["figures"]
                if f["verdict"] == "wrong" and f["unit"] == "mm" and f["position"] in
                ("2", "3")}
    marked = {t.split(":")[0] for t in texts}
    assert {q for _, q in wrong_mm} >= marked and len(texts) >= 6
    assert any(t.startswith("R12: 90,47") for t in texts)


def test_folder_mode(tmp_path, answer_key, capsys):
    key = generate(bundled_example("press"))
    for i, kinds in enumerate(((), ("unit",), ("sign", "scale"))):
        work, _ = inject(key, kinds, random.Random(i))
        (tmp_path / f"s{i}.toml").write_text(work.toml(), encoding="utf-8")
    assert main(["check", str(tmp_path), "-o", str(tmp_path / "out"), "--jobs", "1"]) == 1
    out = capsys.readouterr().out
    assert "3 files: 1 without faults, 2 with faults, 0 not checked" in out
    assert (tmp_path / "out" / "summary.html").is_file()


def test_errors_exit_2(tmp_path, capsys):
    assert main(["check", str(tmp_path / "none.toml")]) == 2
    assert "file not found" in capsys.readouterr().err
    assert main(["check"]) == 2
    assert "expected a student file or a folder" in capsys.readouterr().err
    assert main(["check", str(SEED), "--segment-tolerance", "3"]) == 2
    err = capsys.readouterr().err
    assert "--segment-tolerance: expected a number in (0, 1]" in err and err.count("\n") == 1


def test_inputs_are_never_overwritten(tmp_path, capsys):
    assert main(["check", str(SEED), "--html", str(SEED)]) == 2
    assert "refusing to overwrite an input file" in capsys.readouterr().err


def test_the_command_module_is_light():
    # `graphplan --help` builds every parser: the check command must not pull in the
    # rendering libraries (matplotlib, svgwrite, shapely) just by being imported
    import subprocess
    import sys

    code = ("import sys, graphplan.checking.command, graphplan.checking;"
            "print(','.join(m for m in ('svgwrite', 'matplotlib', 'shapely', 'numpy.linalg')"
            " if m in sys.modules and m != 'numpy.linalg'))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == ""
