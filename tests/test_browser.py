"""Sheets rendered in headless Chromium: size, ink, frame position, no network; errors.

The rendering tests skip when Chromium is not installed, unless
``GRAPHPLAN_REQUIRE_BROWSER`` is set (CI sets it): then they fail.
"""

import json
import os

import pytest
from matplotlib import image

from graphplan.drawing import (
    DASHDOT,
    MAIN,
    MEDIUM,
    THIN,
    Arrow,
    Line,
    Page,
    Sheet,
    Text,
    TitleBlock,
    signatures,
)
from graphplan.errors import GraphplanError
from graphplan.render.browser import ENV_VAR, find_chromium, render_svg_png, svg_size_mm
from graphplan.render.svg import write_svg

PX_PER_MM = 2  # 1682 px across 841 mm


def px(mm):
    return round(mm * PX_PER_MM)


def make_sheet():
    tb = TitleBlock(
        designation="ТММ.КП.00.01",
        title="Кривошипный пресс. План скоростей",
        litera="У",
        sheet=1,
        sheets=3,
        organisation="Кафедра ТММ, гр. МТ-21",
        signatures=signatures("Иванов И.И.", "Петров П.П."),
    )
    items = (
        Line((100, 150), (400, 150), MAIN, layer="position_plan", id="link"),
        Line((100, 150), (250, 400), THIN, layer="construction", id="thin"),
        Line((60, 450), (500, 450), DASHDOT, layer="construction", id="axis"),
        Arrow(
            (400, 200),
            (520, 140),
            MEDIUM,
            head_length=5,
            head_width=1.5,
            layer="velocity_plan",
            id="v-a",
        ),
        Text((100, 100), "План скоростей ω ε φ π", 7, layer="text", id="caption"),
    )
    return Sheet(Page("A1"), items, tb)


def require_chromium():
    if find_chromium() is None:
        reason = f"Chromium not found (install Debian 'chromium' or set {ENV_VAR})"
        if os.environ.get("GRAPHPLAN_REQUIRE_BROWSER", "") not in ("", "0"):
            pytest.fail(f"GRAPHPLAN_REQUIRE_BROWSER is set but {reason}")
        pytest.skip(reason)


@pytest.fixture(scope="module")
def shot(tmp_path_factory):
    require_chromium()
    d = tmp_path_factory.mktemp("browser")
    svg = write_svg(make_sheet(), d / "лист 1.svg")  # a space and Cyrillic in the URL
    png = render_svg_png(svg, d / "sheet.png", net_log=d / "net.json")
    grey = image.imread(png)[..., :3].mean(axis=-1)  # 0 black … 1 white
    return grey, json.loads((d / "net.json").read_text(encoding="utf-8"))


def dark(grey):
    return grey < 0.5


def test_picture_has_the_sheets_aspect_ratio(shot):
    grey, _ = shot
    h, w = grey.shape
    assert w == 1682
    assert abs(h - w * 594 / 841) <= 1


def test_picture_is_not_blank(shot):
    grey, _ = shot
    share = dark(grey).mean()
    assert 0.003 < share < 0.2, share
    assert grey[5:-5, 45:-5].mean() > 0.9  # mostly paper


def test_frame_lines_are_at_20_and_5_mm(shot):
    grey, _ = shot
    ink = dark(grey)
    rows, cols = slice(px(10), px(520)), slice(px(25), px(640))
    edges = {
        "left": ink[rows, px(20) - 1 : px(20) + 2].any(axis=1),
        "right": ink[rows, px(836) - 1 : px(836) + 2].any(axis=1),
        "top": ink[px(5) - 1 : px(5) + 2, cols].any(axis=0),
        "bottom": ink[px(589) - 1 : px(589) + 2, cols].any(axis=0),
    }
    for name, line in edges.items():
        assert line.mean() > 0.99, name
    # nothing just inside the left edge (the margin between frame and drawing)
    assert not ink[px(30) : px(120), px(20) + 3 : px(20) + 20].any()
    # the title block's left edge, 185 mm from the frame's right edge
    assert ink[px(540) : px(585), px(651) - 1 : px(651) + 2].any(axis=1).mean() > 0.99


def test_caption_and_plan_lines_have_ink(shot):
    grey, _ = shot
    ink = dark(grey)
    caption = ink[px(91) : px(102), px(100) : px(160)]  # "План скоростей ω ε φ π", h = 7 mm
    assert 0.05 < caption.mean() < 0.6
    assert ink[px(150) - 1 : px(150) + 2, px(110) : px(390)].any(axis=0).all()  # main line


def test_page_made_no_network_request(shot):
    _, log = shot
    types = {v: k for k, v in log["constants"]["logEventTypes"].items()}
    starts = [
        e.get("params", {})
        for e in log["events"]
        if types.get(e["type"]) == "URL_REQUEST_START_JOB"
    ]
    # Chromium's own services ask "not an origin"; the page's requests have its origin
    from_page = [p["url"] for p in starts if p.get("initiator", "not an origin") != "not an origin"]
    assert from_page == []


# ------------------------------------------------------------- without Chromium


def fake_chromium(tmp_path, body):
    exe = tmp_path / "fake-chromium"
    exe.write_text(f"#!/bin/sh\n{body}\n", encoding="utf-8")
    exe.chmod(0o755)
    return exe


@pytest.fixture
def svg(tmp_path):
    return write_svg(Sheet(Page("A3")), tmp_path / "a3.svg")


def test_svg_size_in_mm(svg, tmp_path):
    assert svg_size_mm(svg) == (420.0, 297.0)
    p = tmp_path / "px.svg"
    p.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="96" height="48px"/>')
    assert svg_size_mm(p) == pytest.approx((25.4, 12.7))
    p.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 30 20"/>')
    assert svg_size_mm(p) == (30.0, 20.0)
    p.write_text('<svg xmlns="http://www.w3.org/2000/svg" width="100%"/>')
    with pytest.raises(GraphplanError, match="no absolute width/height"):
        svg_size_mm(p)


def test_find_chromium_prefers_the_environment(tmp_path, monkeypatch):
    exe = fake_chromium(tmp_path, "exit 0")
    monkeypatch.setenv(ENV_VAR, str(exe))
    assert find_chromium() == str(exe)
    monkeypatch.setenv(ENV_VAR, str(tmp_path / "missing"))
    assert find_chromium() is None


def test_missing_chromium_is_a_one_line_error(svg, tmp_path, monkeypatch):
    monkeypatch.setenv(ENV_VAR, str(tmp_path / "missing"))
    with pytest.raises(GraphplanError, match=ENV_VAR) as err:
        render_svg_png(svg, tmp_path / "out.png")
    assert "\n" not in str(err.value)


def test_failing_chromium_is_a_one_line_error(svg, tmp_path, monkeypatch):
    monkeypatch.setenv(ENV_VAR, str(fake_chromium(tmp_path, "echo 'it broke' >&2; exit 3")))
    with pytest.raises(GraphplanError, match=r"exit 3 .*it broke") as err:
        render_svg_png(svg, tmp_path / "out.png")
    assert "\n" not in str(err.value)
    assert not (tmp_path / "out.png").exists()


def test_hanging_chromium_is_killed(svg, tmp_path, monkeypatch):
    monkeypatch.setenv(ENV_VAR, str(fake_chromium(tmp_path, "exec sleep 30")))
    with pytest.raises(GraphplanError, match=r"within 0\.5 s"):
        render_svg_png(svg, tmp_path / "out.png", timeout=0.5)


def test_sizes_follow_the_svg(svg, tmp_path, monkeypatch):
    # the fake records its arguments instead of drawing
    args = tmp_path / "args"
    monkeypatch.setenv(ENV_VAR, str(fake_chromium(tmp_path, f'echo "$@" > "{args}"; exit 1')))
    with pytest.raises(GraphplanError):
        render_svg_png(svg, tmp_path / "out.png", width_px=840)
    assert "--window-size=840,594" in args.read_text().split()
    with pytest.raises(GraphplanError, match="8192 px on each side"):
        render_svg_png(svg, tmp_path / "out.png", width_px=9000)


def test_a_screenshot_of_the_wrong_size_is_an_error(svg, tmp_path, monkeypatch):
    # writes a 1 x 1 PNG wherever --screenshot= points
    body = 'for a; do case $a in --screenshot=*) printf "%b" "$PNG" > "${a#*=}";; esac; done'
    monkeypatch.setenv(ENV_VAR, str(fake_chromium(tmp_path, body)))
    ihdr = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x01\0\0\0\x01"
    monkeypatch.setenv("PNG", "".join(f"\\{b:03o}" for b in ihdr))
    with pytest.raises(GraphplanError, match="is not a 840 x 594 px PNG"):
        render_svg_png(svg, tmp_path / "out.png", width_px=840)


def test_sheet1_of_the_press_renders_in_the_browser(tmp_path):
    """The real sheet 1 (plans, embedded matplotlib diagrams, table) in Chromium.

    The diagrams' box is drawn (ink inside it, lower-left of the sheet) and the
    plans' grid has ink in every cell's middle band: nothing is lost in the browser.
    """
    require_chromium()
    from graphplan.drawing import kinematics_sheet
    from graphplan.files import bundled_example
    from graphplan.model import load
    from graphplan.project import analyze, sheet_scales

    a = analyze(load(bundled_example("press")))
    svg = write_svg(kinematics_sheet(a), tmp_path / "sheet1.svg")
    png = render_svg_png(svg, tmp_path / "sheet1.png")
    grey = image.imread(png)[..., :3].mean(axis=-1)
    h, w = grey.shape
    assert w == 1682 and abs(h - w * 594 / 841) <= 1
    assert 0.005 < dark(grey).mean() < 0.25
    lay = sheet_scales(a.mech, a.kin).layout
    d = lay.diagrams
    box = grey[int(px(d.y0)):int(px(d.y1)), int(px(d.x0)):int(px(d.x1))]
    assert dark(box).mean() > 0.005  # the curves, axes and pole rays
    for c in lay.cells:
        cell = grey[int(px(c.y0 + 10)):int(px(c.y1)), int(px(c.x0)):int(px(c.x1))]
        assert dark(cell).sum() > 50, c
