"""The command line: exit codes, one-line errors, the JSON contract."""

import json
import math

import pytest

from graphplan.cli import main

POSITION_KEYS = {"label", "phi_deg", "points", "velocities", "accelerations", "omega", "epsilon"}


def run(capsys, *argv):
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_analyze_defaults_to_the_bundled_press(capsys):
    code, out, err = run(capsys, "analyze")
    assert code == 0 and err == ""
    assert "I(4,1) → II₂(2,3)" in out
    assert "W = 3·n − 2·p5 − p4 = 3·3 − 2·4 − 0 = 1" in out
    assert "stroke H = 160.00 mm" in out


def test_analyze_in_russian(capsys):
    code, out, _ = run(capsys, "analyze", "--lang", "ru")
    assert code == 0
    assert "Структурный анализ" in out and "формула строения" in out


def test_json_contract(capsys):
    code, out, _ = run(capsys, "analyze", "--json")
    assert code == 0
    data = json.loads(out)
    mech = data["mechanism"]
    assert mech["mobility"] == 1
    assert mech["groups"][0]["kind"] == "RRP" and mech["groups"][0]["links"] == ["2", "3"]
    assert mech["links"]["2"] == ["A", "B", "S2"]
    assert mech["stroke_m"] == pytest.approx(0.16)
    assert mech["dead_centres_deg"] == pytest.approx([90.0, 270.0])
    labels = [p["label"] for p in data["positions"]]
    assert labels == ["1", "2", "3", "4", "5", "6", "7", "8", "(2)", "(3)"]
    for p in data["positions"]:
        assert set(p) >= POSITION_KEYS
        assert set(p["omega"]) == {"1", "2", "3"} and set(p["epsilon"]) == {"1", "2", "3"}
        for group in ("points", "velocities", "accelerations"):
            for xy in p[group].values():
                assert len(xy) == 2 and all(math.isfinite(c) for c in xy)
    p2 = data["positions"][labels.index("(2)")]
    assert p2["phi_deg"] == pytest.approx(250.0)
    assert p2["points"]["B"][1] == pytest.approx(-0.2732949, abs=1e-7)
    # the crank turns counter-clockwise at π·55/30 rad/s
    assert p2["omega"]["1"] == pytest.approx(math.pi * 55 / 30)


def test_missing_file_is_one_line(capsys, tmp_path):
    code, out, err = run(capsys, "analyze", str(tmp_path / "nope.toml"))
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "nope.toml: file not found" in err


def test_bad_key_is_one_line_naming_file_and_key(capsys, tmp_path):
    bad = tmp_path / "v.toml"
    src = (pytest.importorskip("graphplan.files").bundled_example("press")).read_text()
    bad.write_text(src.replace("length = 200", "length = -200"), encoding="utf-8")
    code, _, err = run(capsys, "analyze", str(bad))
    assert code == 2
    assert err.strip() == f"graphplan: error: {bad}: dyads[0].length: must be > 0 (got -200)"


def test_output_file_is_written_and_input_protected(capsys, tmp_path):
    out = tmp_path / "report.json"
    code, stdout, _ = run(capsys, "analyze", "--json", "-o", str(out))
    assert code == 0 and stdout == ""
    assert json.loads(out.read_text())["mechanism"]["mobility"] == 1
    variant = tmp_path / "v.toml"
    from graphplan.files import bundled_example

    variant.write_text(bundled_example("press").read_text(), encoding="utf-8")
    before = variant.read_bytes()
    code, _, err = run(capsys, "analyze", str(variant), "-o", str(variant))
    assert code == 2 and "refusing to overwrite an input file" in err
    assert variant.read_bytes() == before


def test_debug_shows_the_traceback(tmp_path):
    from graphplan.errors import InputError

    with pytest.raises(InputError):
        main(["--debug", "analyze", str(tmp_path / "nope.toml")])


def test_json_plans_per_position(capsys):
    _code, out, _ = run(capsys, "analyze", "--json")
    data = json.loads(out)
    assert data["mechanism"]["scales"]["Kl"]["basis"] == "Kl = lOA/OA = 0.08/80 = 0.001 m/mm"
    for p in data["positions"]:
        plans = p["plans"]
        assert plans["Kl"] == 0.001 and plans["Kv"] > 0 and plans["Ka"] > 0
        seg = plans["segments_mm"]
        # read back at the scales, the plans give the exact velocities and accelerations
        vb = math.hypot(*p["velocities"]["B"])
        ab = math.hypot(*p["accelerations"]["B"])
        assert seg["pb"] * plans["Kv"] == pytest.approx(vb, rel=1e-6, abs=1e-12)
        assert seg["πb"] * plans["Ka"] == pytest.approx(ab, rel=1e-6, abs=1e-12)
        # the normal component of the rod: n_BA = ω2²·l_AB / Ka
        assert seg["n_BA"] * plans["Ka"] == pytest.approx(p["omega"]["2"] ** 2 * 0.2, rel=1e-6,
                                                          abs=1e-12)


def test_sheets_writes_the_sheet_tables_and_report(capsys, tmp_path):
    code, _out, err = run(capsys, "sheets", "-o", str(tmp_path / "press"))
    assert code == 0 and err == ""
    names = sorted(p.name for p in (tmp_path / "press").iterdir())
    assert names == ["analysis.json", "dynamics.csv", "dynamics.en.md", "dynamics.ru.md",
                     "forces.csv", "forces.en.md", "forces.ru.md", "plans.csv",
                     "plans.en.md", "plans.ru.md", "sheet1.svg", "sheet2.svg", "sheet3.svg"]
    svg = (tmp_path / "press" / "sheet1.svg").read_text(encoding="utf-8")
    assert 'width="841mm"' in svg and "План скоростей" in svg
    report = json.loads((tmp_path / "press" / "analysis.json").read_text(encoding="utf-8"))
    # the JSON's scales are the sheet's: Kl as the seed fixes it, Kv and Ka as printed
    assert report["positions"][0]["plans"]["Kl"] == 0.001
    kv = report["positions"][0]["plans"]["Kv"]
    assert _ends_a_text(svg, f"= {kv:g} (м/с)/мм".replace(".", ","))  # decimal comma
    assert not any(p.name.endswith(".tmp") for p in (tmp_path / "press").iterdir())


def test_sheets_of_several_variants_go_into_subfolders(capsys, tmp_path):
    from graphplan.files import bundled_example

    code, _, _ = run(capsys, "sheets", str(bundled_example("fourbar")),
                     str(bundled_example("scotch_yoke")), "-o", str(tmp_path))
    assert code == 0
    assert (tmp_path / "fourbar" / "sheet1.svg").is_file()
    assert (tmp_path / "scotch_yoke" / "plans.csv").is_file()


@pytest.mark.parametrize("argv, expected", [
    (["--precision", "-1"], "--precision: expected a reading precision of 0 … 5 mm (got -1)"),
    (["--precision", "nan"], "--precision: expected a reading precision"),
])
def test_sheets_bad_options_are_one_line_errors(capsys, tmp_path, argv, expected):
    code, out, err = run(capsys, "sheets", "-o", str(tmp_path), *argv)
    assert code == 2 and out == ""
    assert err.startswith("graphplan: error: " + expected) and err.count("\n") == 1


def test_sheets_refuses_a_file_as_output_folder(capsys, tmp_path):
    f = tmp_path / "taken"
    f.write_text("x")
    code, _, err = run(capsys, "sheets", "-o", str(f))
    assert code == 3 and "the output must be a folder" in err  # 3: an output error
    assert f.read_text() == "x"


def test_written_files_get_the_usual_permissions(tmp_path):
    """mkstemp's private 0600 must not leak into the outputs: a plain file's mode."""
    import os

    from graphplan.files import write_atomic

    mask = os.umask(0o022)
    try:
        p = write_atomic(tmp_path / "a.txt", "x")
        assert p.stat().st_mode & 0o777 == 0o644  # 0666 & ~0022
        p.chmod(0o600)
        write_atomic(p, "y")  # replacing a file keeps its mode
        assert p.stat().st_mode & 0o777 == 0o600
    finally:
        os.umask(mask)


def test_sheets_on_a2(capsys, tmp_path):
    from graphplan.files import bundled_example

    code, _, err = run(capsys, "sheets", str(bundled_example("fourbar")), "--page", "A2",
                       "-o", str(tmp_path))
    assert code == 0, err
    svg = (tmp_path / "sheet1.svg").read_text(encoding="utf-8")
    assert 'width="594mm"' in svg and 'height="420mm"' in svg
    # the report's scales are the A2 sheet's, not the A1 default's
    kv = json.loads((tmp_path / "analysis.json").read_text(encoding="utf-8"))[
        "mechanism"]["scales"]["Kv"]["value"]
    assert _ends_a_text(svg, f"= {kv:g} (м/с)/мм".replace(".", ","))  # decimal comma


def test_sheets_that_do_not_fit_say_what_to_change(capsys, tmp_path):
    """The press on A3 (issue 18): its own Kl is not forced on A3, sheet 2 draws as many
    positions as fit; a variant whose sheet 1 does not fit A3 yet says so in one line."""
    code, out, err = run(capsys, "sheets", "--page", "A3", "-o", str(tmp_path))
    assert code == 0 and err == ""
    assert (tmp_path / "sheet1.svg").exists() and (tmp_path / "sheet2.svg").exists()
    from graphplan.files import bundled_example

    # a press drawn on A3 at the seed's Kl written for A3 (a plan of positions 1:1 does not
    # leave the plans room there): one line saying what to change, nothing written
    text = bundled_example("press").read_text(encoding="utf-8").replace(
        "[drawing]\n", '[drawing]\nformat = "A3"\n')
    (tmp_path / "press_a3.toml").write_text(text, encoding="utf-8")
    code, out, err = run(capsys, "sheets", str(tmp_path / "press_a3.toml"),
                         "-o", str(tmp_path / "big"))
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "Kl" in err
    assert not (tmp_path / "big" / "sheet1.svg").exists()


def test_json_carries_reactions_and_balancing_moments(capsys):
    """The seed's working position (2): R12 = 424 kN, h21 = 37.39 mm, Mур = 15.85 kN·m
    (the seed: Kp = 10 kN/mm, R12 = 42.4 mm · 10 = 424 kN, Mур = 424·37.39·0.001)."""
    code, out, _ = run(capsys, "analyze", "--json")
    assert code == 0
    pos = {p["label"]: p for p in json.loads(out)["positions"]}
    f2 = pos["(2)"]["forces"]
    assert f2["reactions"]["R12"]["magnitude"] == pytest.approx(424.0e3, rel=2e-3)
    assert f2["crank_arms_m"]["R21"] == pytest.approx(0.03739, rel=2e-3)
    assert f2["M_bal"] == pytest.approx(15.85e3, rel=2e-3)
    assert set(f2["loads"]["neglected"]) >= {"G3", "Pи3"}  # the seed's 10 % rule
    # with nothing neglected the moment differs (weights and inertia count again)
    assert pos["(2)"]["M_bal_full"] != pytest.approx(f2["M_bal"], rel=1e-3)


def test_json_carries_force_plans_and_the_lever(capsys):
    """(2): the polygon of group 2-3 at Kp = 4000 N/mm, R12 = ca·Kp = 105.98·4000 = 423.9 kN;
    the crank's plan gives Mур, and Zhukovsky's lever agrees exactly (exact mode)."""
    code, out, _ = run(capsys, "analyze", "--json")
    assert code == 0
    p2 = next(p for p in json.loads(out)["positions"] if p["label"] == "(2)")
    group, crank = p2["force_plans"]
    assert group["group"] == "RRP(2-3)" and group["Kp"] == 4000.0
    assert group["segments_mm"]["ca"] * group["Kp"] == pytest.approx(group["values"]["R12"])
    assert group["values"]["R12"] == pytest.approx(p2["forces"]["reactions"]["R12"]["magnitude"],
                                                   rel=1e-9)
    assert crank["M_bal"] == pytest.approx(p2["forces"]["M_bal"], rel=1e-9)
    assert p2["zhukovsky"]["M_bal"] == pytest.approx(p2["forces"]["M_bal"], rel=1e-9)
    assert p2["zhukovsky"]["discrepancy_pct"] < 1e-6


def _ends_a_text(svg: str, tail: str) -> bool:
    """A ``<text>`` of the SVG, its runs (subscripts) joined, ends with ``tail``."""
    import xml.etree.ElementTree as ET

    root = ET.fromstring(svg.encode("utf-8"))
    return any("".join(t.itertext()).endswith(tail)
               for t in root.iter("{http://www.w3.org/2000/svg}text"))
