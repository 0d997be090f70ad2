"""`graphplan sheets --format … --dpi …`: the exports from the command line.

The formats themselves are proven in tests/test_exports.py; here: the command writes
every sheet of the press in every asked format beside the tables, the SVG it writes is
the one of a plain run, a missing extra or a bad option is one line and nothing is
written.
"""

from __future__ import annotations

import io
import sys

import pytest

ezdxf = pytest.importorskip("ezdxf")
pypdf = pytest.importorskip("pypdf")
pytest.importorskip("typst")
pytest.importorskip("resvg_py")

from graphplan.cli import main  # noqa: E402
from graphplan.files import bundled_example  # noqa: E402

TABLES = ["plans.ru.md", "plans.en.md", "plans.csv", "forces.ru.md", "forces.en.md",
          "forces.csv", "dynamics.ru.md", "dynamics.en.md", "dynamics.csv", "analysis.json"]


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """The press written plainly and with every format at 20 dpi."""
    base = tmp_path_factory.mktemp("exports")
    assert main(["sheets", "-o", str(base / "plain")]) == 0
    assert main(["sheets", "-o", str(base / "all"), "--format", "svg,dxf,pdf,png",
                 "--dpi", "20"]) == 0
    return base


def test_every_sheet_in_every_format_beside_the_tables(runs):
    names = {p.name for p in (runs / "all").iterdir()}
    sheets = {f"sheet{n}.{ext}" for n in (1, 2, 3) for ext in ("svg", "dxf", "pdf", "png")}
    assert names == sheets | set(TABLES)
    plain = {p.name for p in (runs / "plain").iterdir()}
    assert plain == {f"sheet{n}.svg" for n in (1, 2, 3)} | set(TABLES)


def test_the_svg_and_tables_are_those_of_a_plain_run(runs):
    for name in ["sheet1.svg", "sheet2.svg", "sheet3.svg", *TABLES]:
        assert (runs / "all" / name).read_bytes() == (runs / "plain" / name).read_bytes(), name


def test_the_exports_have_the_a1_size(runs):
    from PIL import Image

    for n in (1, 2, 3):
        doc = ezdxf.readfile(runs / "all" / f"sheet{n}.dxf")
        assert not doc.audit().has_errors
        pdf = pypdf.PdfReader(runs / "all" / f"sheet{n}.pdf")
        box = pdf.pages[0].mediabox  # points: 841 mm = 841/25.4·72 = 2383.9 pt
        assert len(pdf.pages) == 1
        assert float(box.width) == pytest.approx(841 / 25.4 * 72, abs=0.5)
        assert float(box.height) == pytest.approx(594 / 25.4 * 72, abs=0.5)
        with Image.open(runs / "all" / f"sheet{n}.png") as im:
            # 841 mm at 20 dpi: 841·20/25.4 = 662.2 → 662 px; 594·20/25.4 = 467.7 → 468 px
            assert im.size == (662, 468)


def test_format_alone_replaces_the_svg(tmp_path):
    assert main(["sheets", "-o", str(tmp_path), "--format", "pdf"]) == 0
    names = {p.name for p in tmp_path.iterdir()}
    assert names == {"sheet1.pdf", "sheet2.pdf", "sheet3.pdf"} | set(TABLES)


def _fails(argv, capsys) -> str:
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("graphplan: error: ")
    return err


def test_a_bad_format_or_dpi_is_one_line_and_writes_nothing(tmp_path, capsys):
    out = tmp_path / "out"
    assert "svg, dxf, pdf, png" in _fails(["sheets", "-o", str(out), "--format", "svg,jpg"],
                                          capsys)
    assert "dpi" in _fails(["sheets", "-o", str(out), "--format", "png", "--dpi", "0"], capsys)
    assert not out.exists()


def test_a_missing_extra_names_it_before_any_work(tmp_path, capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "ezdxf", None)  # `import ezdxf` now fails
    out = tmp_path / "out"
    err = _fails(["sheets", str(bundled_example("press")), "-o", str(out), "--format",
                  "svg,dxf"], capsys)
    assert "pip install 'graphplan[export]'" in err and "'ezdxf'" in err
    assert not out.exists()


def test_the_help_lists_the_formats():
    stdout = sys.stdout
    sys.stdout = buf = io.StringIO()
    try:
        with pytest.raises(SystemExit):
            main(["sheets", "--help"])
    finally:
        sys.stdout = stdout
    text = " ".join(buf.getvalue().split())
    assert "--format FORMATS" in text and "svg, dxf" in text and "--dpi DPI" in text
