"""The font metrics cache: the same metrics from the cache as from the file, never another's.

:func:`graphplan.fonts.load_font` keeps each font file's metrics in the user's
cache folder keyed by the SHA-256 of the file (and of the glyph rules); these tests point
``$GRAPHPLAN_CACHE_DIR`` at a temporary folder.
"""

from __future__ import annotations

import json

import pytest

from graphplan import fonts
from graphplan.files import CACHE_ENV, user_cache_dir


@pytest.fixture
def cache(tmp_path, monkeypatch):
    folder = tmp_path / "cache"
    monkeypatch.setenv(CACHE_ENV, str(folder))
    fonts.load_font.cache_clear()
    yield folder
    fonts.load_font.cache_clear()


def _measured(family):
    upem, cap, adv, cov, blank = fonts._measure_font(fonts.find_font_file(family))
    return upem, cap, adv, frozenset(cov), frozenset(blank)


def _as_tuple(info):
    return (info.units_per_em, info.cap_height, dict(info.advances), info.covered, info.blank)


def _entries(folder):
    return sorted((folder / "font-metrics").glob("*.json"))


@pytest.mark.parametrize("family", ["osifont", "DejaVu Sans"])
def test_cached_metrics_equal_the_measured(cache, family):
    first = fonts.load_font(family)
    assert len(_entries(cache)) == 1  # written on the first read
    fonts.load_font.cache_clear()
    second = fonts.load_font(family)  # read back from the cache
    assert _as_tuple(first) == _as_tuple(second) == _measured(family)
    # graphplan's osifont draws Ё ё Э э, − and → (the upstream build's blank placeholders
    # of Ё ё Э э redrawn, docs/osifont_patch.py): covered, not blank, in the cache too
    if family == "osifont":
        assert {ord(c) for c in "ЁёЭэ−→"} <= second.covered - second.blank


def test_a_damaged_entry_is_measured_again_and_rewritten(cache):
    fonts.load_font("osifont")
    (entry,) = _entries(cache)
    for bad in ("{not json", json.dumps({"format": 1}), "[]", ""):
        entry.write_text(bad, encoding="utf-8")
        fonts.load_font.cache_clear()
        assert _as_tuple(fonts.load_font("osifont")) == _measured("osifont")
        assert json.loads(entry.read_text(encoding="utf-8"))["units_per_em"] == 2048


def test_an_entry_that_does_not_check_out_is_not_used(cache):
    """A well-formed entry whose key or contents do not match (another font's metrics
    copied under this name, a covered point also blank) is ignored: never a wrong metric."""
    fonts.load_font("osifont")
    (entry,) = _entries(cache)
    data = json.loads(entry.read_text(encoding="utf-8"))
    wrong = dict(data, key="0" * 64)
    entry.write_text(json.dumps(wrong), encoding="utf-8")
    fonts.load_font.cache_clear()
    assert fonts.load_font("osifont").units_per_em == 2048
    both = dict(data, blank=data["blank"] + data["covered"][:1])
    entry.write_text(json.dumps(both), encoding="utf-8")
    fonts.load_font.cache_clear()
    assert _as_tuple(fonts.load_font("osifont")) == _measured("osifont")


def test_the_key_follows_the_bytes():
    raw = fonts.find_font_file("osifont").read_bytes()
    assert fonts._metrics_key(raw) == fonts._metrics_key(bytes(raw))
    changed = raw[:-1] + bytes([raw[-1] ^ 1])
    assert fonts._metrics_key(changed) != fonts._metrics_key(raw)


def test_an_unwritable_cache_folder_only_costs_time(tmp_path, monkeypatch):
    blocker = tmp_path / "file"
    blocker.write_text("a file where the cache folder should be", encoding="utf-8")
    monkeypatch.setenv(CACHE_ENV, str(blocker / "sub"))
    fonts.load_font.cache_clear()
    try:
        assert _as_tuple(fonts.load_font("osifont")) == _measured("osifont")
    finally:
        fonts.load_font.cache_clear()


def test_an_empty_setting_turns_the_cache_off(tmp_path, monkeypatch):
    monkeypatch.setenv(CACHE_ENV, "")
    assert user_cache_dir() is None
    fonts.load_font.cache_clear()
    try:
        assert fonts.load_font("osifont").units_per_em == 2048
    finally:
        fonts.load_font.cache_clear()


def test_the_default_folder_is_per_user(monkeypatch, tmp_path):
    monkeypatch.delenv(CACHE_ENV, raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    folder = user_cache_dir()
    assert folder is not None and folder.name == "graphplan"
