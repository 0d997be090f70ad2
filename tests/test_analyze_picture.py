"""graphplan analyze --picture (issue 23): the mechanism at a glance before the sheets, so that
a wrong assembly branch or direction is seen — the mechanism at its first position, the paths
of the output link's points over the cycle, the crank's sense and K, in the user's language."""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import pytest

from graphplan.cli import main
from graphplan.files import bundled_example

SVG = "{http://www.w3.org/2000/svg}"


def _texts(root) -> list[str]:
    return ["".join(t.itertext()) for t in root.iter(SVG + "text")]


@pytest.mark.parametrize("family", ["slotter", "shaper", "sixbar_press", "press"])
def test_the_picture_shows_the_mechanism_its_output_paths_and_senses(family, tmp_path,
                                                                     capsys, solved):
    p = solved(family)
    out = tmp_path / "m.svg"
    assert main(["analyze", str(bundled_example(family)), "--lang", "ru",
                 "--picture", str(out)]) == 0
    assert "рисунок механизма" in capsys.readouterr().err
    root = ET.fromstring(out.read_text(encoding="utf-8"))
    texts = _texts(root)
    letters = {t.strip() for line in texts for t in line.split(",")}
    assert set(p.kin.pos.points) <= letters  # every point lettered
    sense = "против часовой стрелки" if p.mech.crank.sense > 0 else "по часовой стрелке"
    assert any(t.startswith(f"ω1 {sense}") for t in texts), texts
    if p.cycle.dead_centres:
        k_line = next(t for t in texts if "K = " in t)
        assert float(k_line.split("K = ")[1]) == pytest.approx(p.cycle.time_ratio, rel=1e-3)
        assert any("начало рабочего хода" in t for t in texts)
    # the dashed path of each output point spans its travel at the scheme's scale: the
    # slider's path is as long as the stroke H (to the scheme's scale, read off the crank)
    paths = {e.get("id"): e for e in root.iter() if (e.get("id") or "").startswith("path-")}
    assert paths and all(re.search("[а-я]", t) or not re.search("[a-z]{4}", t)
                         for t in texts)
    circles = {e.get("id")[len("scheme-joint-"):]: (float(e.get("cx")), float(e.get("cy")))
               for e in root.iter(SVG + "circle") if (e.get("id") or "").startswith(
                   "scheme-joint-")}
    o, a = p.mech.crank.pivot, p.mech.crank.pin
    if o in circles and a in circles and p.cycle.output_kind == "slider":
        scale = math.dist(circles[o], circles[a]) / p.mech.crank.length  # mm per m
        out_joint = next(q for q in p.mech.points_of(p.mech.output.link)
                         if f"path-{q}" in paths)
        pts = [tuple(map(float, xy.split(","))) for xy in
               paths[f"path-{out_joint}"].get("points").split()]
        span = max(math.dist(u, v) for u in pts for v in pts)
        assert span == pytest.approx(p.cycle.stroke * scale, rel=1e-6)


def test_a_png_picture_and_a_wrong_suffix(tmp_path, capsys):
    png = tmp_path / "m.png"
    assert main(["analyze", str(bundled_example("press")), "--picture", str(png),
                 "--lang", "en"]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "the mechanism's picture" in capsys.readouterr().err
    assert main(["--lang", "ru", "analyze", str(bundled_example("press")), "--picture",
                 str(tmp_path / "m.jpg")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "ожидалось имя файла с окончанием .svg или .png" in err
    assert not (tmp_path / "m.jpg").exists()
