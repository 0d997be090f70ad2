"""The same sheets on every machine: the lettering comes with the package.

osifont is bundled (``graphplan/data/fonts``, with its licence), DejaVu is matplotlib's;
the fonts a machine has installed never reach a sheet, a table, a report or a teaching
page. Proven by running the commands of ``drawings/README.md`` on a simulated bare
machine — ``$GRAPHPLAN_FONT_PATH`` pointing at a folder that does not exist, matplotlib
told to ignore the system's fonts and given a fresh cache — and comparing every file
byte for byte with the committed ``drawings/``.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import matplotlib

from graphplan import fonts

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
TEACH = ["teach", "examples/press.toml", "--position", "2", "(2)", "(3)", "--plan", "velocity",
         "acceleration", "forces", "zhukovsky", "flywheel"]
FIGURE = re.compile(r'(<svg class="figure"[^>]*>).*?(</svg>\s*</g>|</svg>(?=\s*<))', re.S)
MPL_VERSION = re.compile(r"Matplotlib v([0-9][^,\s<]*)")


def bare_env(tmp_path: Path) -> dict[str, str]:
    """The environment of a machine with no fonts installed (and a fresh matplotlib)."""
    env = dict(os.environ)
    env[fonts.FONT_PATH_ENV] = str(tmp_path / "no-such-folder")
    env["MPL_IGNORE_SYSTEM_FONTS"] = "1"
    env["MPLCONFIGDIR"] = str(tmp_path / "mplconfig")
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(ROOT), env.get("PYTHONPATH")) if p)
    return env


def run(args: list[str], env: dict[str, str]) -> None:
    proc = subprocess.run([sys.executable, "-m", "graphplan", *args], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=600, check=False)
    assert proc.returncode == 0, proc.stderr[-2000:]


def _masked(text: str) -> str:
    return FIGURE.sub(lambda m: m.group(1) + "…" + m.group(2), text)


def assert_same_bytes(fresh: Path, committed: Path) -> None:
    new, old = fresh.read_bytes(), committed.read_bytes()
    if new == old:
        return
    where = (f"{committed.relative_to(ROOT)} differs from a run without system fonts: if the "
             f"output changed on purpose, regenerate drawings/ with the commands of "
             f"drawings/README.md (the sheets AND the press's teaching pages)")
    if fresh.suffix == ".svg":
        # matplotlib's own path output may change between its releases: when the
        # committed figures come from another matplotlib, compare the rest byte for byte
        found = MPL_VERSION.search(old.decode("utf-8"))
        if found and found.group(1) != matplotlib.__version__:
            assert _masked(new.decode("utf-8")) == _masked(old.decode("utf-8")), where
            return
    raise AssertionError(where)


def test_the_chain_is_bundled_whatever_the_machine_has(tmp_path, monkeypatch):
    # a decoy "osifont.ttf" (really DejaVu Serif) in the only folder searched
    decoy = tmp_path / "fonts"
    decoy.mkdir()
    shutil.copy(Path(matplotlib.get_data_path()) / "fonts/ttf/DejaVuSerif.ttf",
                decoy / "osifont.ttf")
    monkeypatch.setenv(fonts.FONT_PATH_ENV, str(decoy))
    fonts.find_font_file.cache_clear()
    fonts.find_system_font.cache_clear()
    try:
        osi = fonts.find_font_file("osifont")
        assert osi == ROOT / "graphplan" / "data" / "fonts" / "osifont.ttf"
        mpl = Path(matplotlib.get_data_path()) / "fonts" / "ttf"
        assert fonts.find_font_file("DejaVu Sans") == mpl / "DejaVuSans.ttf"
        assert fonts.find_font_file("DejaVu Sans Mono") == mpl / "DejaVuSansMono.ttf"
        # other families are found in the folders of $GRAPHPLAN_FONT_PATH only
        assert fonts.system_font_files() == (decoy / "osifont.ttf",)
        assert fonts.find_system_font("DejaVu Serif") == decoy / "osifont.ttf"
        assert fonts.find_font_file("Liberation Sans") is None
    finally:
        fonts.find_font_file.cache_clear()
        fonts.find_system_font.cache_clear()


def test_a_font_path_that_points_nowhere_hides_every_system_font(tmp_path, monkeypatch):
    monkeypatch.setenv(fonts.FONT_PATH_ENV, str(tmp_path / "nowhere"))
    fonts.find_system_font.cache_clear()
    try:
        assert fonts.system_fonts_hidden()
        assert fonts.system_font_files() == ()
        assert fonts.find_system_font("DejaVu Serif") is None
        assert fonts.find_font_file("osifont").is_file()  # the bundled one stays
    finally:
        fonts.find_system_font.cache_clear()
    monkeypatch.delenv(fonts.FONT_PATH_ENV)
    assert fonts.font_dirs() is None and not fonts.system_fonts_hidden()


def test_the_bundled_font_carries_its_licence():
    folder = ROOT / "graphplan" / "data" / "fonts"
    copyright_text = (folder / "osifont.COPYRIGHT").read_text(encoding="utf-8")
    assert "GPL-3-only+FE" in copyright_text and "special exception" in copyright_text
    assert "GNU GENERAL PUBLIC LICENSE" in (folder / "osifont.GPL-3.txt").read_text("utf-8")
    from fontTools.ttLib import TTFont

    with TTFont(folder / "osifont.ttf") as font:
        assert font["name"].getDebugName(1) == "osifont"


def test_sheets_and_pages_without_system_fonts_are_the_committed_bytes(tmp_path):
    env = bare_env(tmp_path)
    out = tmp_path / "drawings"
    run(["sheets", *(str(p.relative_to(ROOT)) for p in EXAMPLES), "-o", str(out)], env)
    run([*TEACH, "-o", str(out / "press")], env)
    written = sorted(p for p in out.rglob("*") if p.is_file())
    assert len(written) >= 12 * len(EXAMPLES)
    for fresh in written:
        committed = ROOT / "drawings" / fresh.relative_to(out)
        assert committed.is_file(), f"{committed} is missing"
        assert_same_bytes(fresh, committed)
    # and nothing committed is left without a fresh twin
    committed_files = {p.relative_to(ROOT / "drawings") for p in (ROOT / "drawings").rglob("*")
                       if p.is_file() and p.name != "README.md"}
    assert committed_files == {p.relative_to(out) for p in written}


def test_other_fonts_come_from_matplotlibs_font_manager(monkeypatch, tmp_path):
    # unset $GRAPHPLAN_FONT_PATH: the system's fonts are matplotlib's findSystemFonts(),
    # which on Windows reads the registry of the machine and of the user (the per-user
    # folder %LOCALAPPDATA%\Microsoft\Windows\Fonts of Windows 10+), fontconfig elsewhere
    from matplotlib import font_manager

    user_font = tmp_path / "AppData/Local/Microsoft/Windows/Fonts/STIXGeneral.ttf"
    user_font.parent.mkdir(parents=True)
    shutil.copy(Path(matplotlib.get_data_path()) / "fonts/ttf/STIXGeneral.ttf", user_font)
    seen = []

    def find_system_fonts(fontpaths=None, fontext="ttf"):
        seen.append(fontpaths)
        return [str(user_font)]

    monkeypatch.delenv(fonts.FONT_PATH_ENV, raising=False)
    monkeypatch.setattr(font_manager, "findSystemFonts", find_system_fonts)
    assert fonts.system_font_files() == (user_font,)
    assert seen == [None]  # the platform's own search, not a folder list of ours
    assert fonts.fallback_font_files("⌢") == (user_font,)
    assert fonts.fallback_font_files("Масштаб 1:2 ω₁") == ()  # the bundled fonts draw it
