"""The teaching pages in a real browser: headless Chromium driven over the DevTools
protocol (``--remote-debugging-pipe``: JSON messages on file descriptors 3 and 4, the
standard library only).

One browser for the module; each page is opened from disk (``file://``). The tests step
through every step with the keyboard, check each step's caption and new lines, take
screenshots of the first and last steps, watch the Network domain for requests, and
play the try-it-yourself mode. They skip without Chromium unless
``GRAPHPLAN_REQUIRE_BROWSER`` is set (CI sets it): then they fail.
"""

from __future__ import annotations

import base64
import contextlib
import fcntl
import io
import json
import os
import re
import select
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np
import pytest

from graphplan.files import bundled_example, examples_dir
from graphplan.model import load
from graphplan.project import analyze
from graphplan.render.browser import ENV_VAR, FLAGS, find_chromium
from graphplan.teaching import lesson, write_lesson
from graphplan.teaching.captions import WORDS, ZERO_MM, localise

WIDTH, HEIGHT = 1280, 800


class Browser:
    """A headless Chromium and one page target, driven over ``--remote-debugging-pipe``."""

    def __init__(self, exe: str, profile: Path):
        r_in, w_in = os.pipe()  # we write commands → Chromium reads fd 3
        r_out, w_out = os.pipe()  # Chromium writes fd 4 → we read

        def child():  # in the child, between fork and exec: the pipe ends become 3 and 4
            a = fcntl.fcntl(r_in, fcntl.F_DUPFD, 10)  # above 4, so neither is clobbered
            b = fcntl.fcntl(w_out, fcntl.F_DUPFD, 10)
            os.dup2(a, 3)  # inheritable; every other descriptor is close-on-exec
            os.dup2(b, 4)

        flags = [f for f in FLAGS if not f.startswith("--virtual-time-budget")]
        self.proc = subprocess.Popen(
            [exe, *flags, "--remote-debugging-pipe", f"--user-data-dir={profile}",
             f"--window-size={WIDTH},{HEIGHT}", "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            close_fds=False, preexec_fn=child, start_new_session=True)
        os.close(r_in)
        os.close(w_out)
        self.w = os.fdopen(w_in, "wb", buffering=0)
        self.r = os.fdopen(r_out, "rb", buffering=0)
        self.buf = b""
        self.next_id = 0
        self.events: list[dict] = []
        target = self.call("Target.createTarget", url="about:blank")["targetId"]
        self.session = self.call("Target.attachToTarget", targetId=target,
                                 flatten=True)["sessionId"]
        for domain in ("Page", "Runtime", "Network"):
            self.call(f"{domain}.enable", session=True)
        self.call("Emulation.setDeviceMetricsOverride", session=True, width=WIDTH,
                  height=HEIGHT, deviceScaleFactor=1, mobile=False)

    def _message(self, timeout: float) -> dict:
        deadline = time.monotonic() + timeout
        while b"\0" not in self.buf:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self.r], [], [], left)[0]:
                raise TimeoutError("Chromium did not answer")
            chunk = self.r.read(65536)
            if not chunk:
                raise RuntimeError("Chromium closed the pipe")
            self.buf += chunk
        msg, self.buf = self.buf.split(b"\0", 1)
        return json.loads(msg)

    def call(self, method: str, session: bool = False, timeout: float = 30, **params):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params}
        if session:
            msg["sessionId"] = self.session
        self.w.write(json.dumps(msg).encode() + b"\0")
        while True:
            m = self._message(timeout)
            if m.get("id") == self.next_id:
                if "error" in m:
                    raise RuntimeError(f"{method}: {m['error']}")
                return m.get("result", {})
            if "method" in m:
                self.events.append(m)

    def wait_event(self, name: str, timeout: float = 30) -> dict:
        for i, e in enumerate(self.events):
            if e["method"] == name:
                return self.events.pop(i)
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            m = self._message(deadline - time.monotonic())
            if m.get("method") == name:
                return m
            if "method" in m:
                self.events.append(m)
        raise TimeoutError(name)

    def open(self, path: Path) -> None:
        self.events.clear()
        self.call("Page.navigate", session=True, url=path.resolve().as_uri())
        self.wait_event("Page.loadEventFired")

    def js(self, expr: str):
        r = self.call("Runtime.evaluate", session=True, expression=expr, returnByValue=True,
                      awaitPromise=True)
        if "exceptionDetails" in r:
            raise RuntimeError(r["exceptionDetails"])
        return r["result"].get("value")

    def key(self, key: str, code: str, vk: int, text: str = "") -> None:
        for typ in ("keyDown", "keyUp"):
            params = {"type": typ, "key": key, "code": code, "windowsVirtualKeyCode": vk}
            if text and typ == "keyDown":
                params["text"] = text
            self.call("Input.dispatchKeyEvent", session=True, **params)

    def type_text(self, text: str) -> None:
        self.call("Input.insertText", session=True, text=text)

    def screenshot(self) -> np.ndarray:
        from matplotlib import image

        data = self.call("Page.captureScreenshot", session=True, format="png")["data"]
        raw = base64.b64decode(data)
        return image.imread(io.BytesIO(raw), format="png")[..., :3], raw

    def requests(self) -> list[str]:
        """URLs the page asked for, from the Network events seen so far."""
        while True:  # drain what is waiting
            try:
                self.events.append(self._message(0.2))
            except TimeoutError:
                break
        return [e["params"]["request"]["url"] for e in self.events
                if e["method"] == "Network.requestWillBeSent"]

    def close(self) -> None:
        with contextlib.suppress(Exception):
            self.call("Browser.close", timeout=5)
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self.w.close()
        self.r.close()


def require_chromium() -> str:
    exe = find_chromium()
    if exe is None:
        reason = f"Chromium not found (install Debian 'chromium' or set {ENV_VAR})"
        if os.environ.get("GRAPHPLAN_REQUIRE_BROWSER", "") not in ("", "0"):
            pytest.fail(f"GRAPHPLAN_REQUIRE_BROWSER is set but {reason}")
        pytest.skip(reason)
    return exe


@pytest.fixture(scope="module")
def browser():
    exe = require_chromium()
    with tempfile.TemporaryDirectory(prefix="graphplan-teach-") as tmp:
        b = Browser(exe, Path(tmp) / "profile")
        try:
            yield b
        finally:
            b.close()


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    """A few pages: the press's velocity plan (ru), its forces at (2), the lever (en),
    the flywheel, and the acceleration plan of the shaper (an RPR group with Coriolis)."""
    d = tmp_path_factory.mktemp("teach pages")  # a space in the URL
    press = analyze(load(bundled_example("press")))
    shaper = analyze(load(examples_dir() / "shaper.toml"))
    out = {}
    for key, a, plan, pos, lang in (("velocity", press, "velocity", "2", "ru"),
                                    ("forces", press, "forces", "(2)", "ru"),
                                    ("lever", press, "zhukovsky", "(3)", "en"),
                                    ("flywheel", press, "flywheel", None, "en"),
                                    ("shaper", shaper, "acceleration", "3", "en")):
        les = lesson(a, plan, pos)
        out[key] = (les, write_lesson(les, d / key, lang=lang)[0], lang)
    return out


NUMBER = re.compile(r"(?<![\w.])[−-]?\d+(?:\.\d+)?(?:·10\^-?\d+)?")


def parse(s: str) -> float:
    s = s.replace("−", "-")
    if "·10^" in s:
        m, e = s.split("·10^")
        return float(m) * 10 ** int(e)
    return float(s)


STATE = """(() => {
  const s = document.querySelector('section.step.current');
  const visible = Array.from(document.querySelectorAll('section.step'))
      .filter(x => getComputedStyle(x).display !== 'none').length;
  return {step: +s.dataset.step, counter: document.getElementById('counter').textContent,
          visible: visible, kind: s.dataset.kind,
          caption: s.querySelector('.cap').innerText,
          results: Array.from(s.querySelectorAll('li.result')).map(li => ({
              mm: +li.dataset.mm, value: +li.dataset.value,
              text: li.querySelector('.answer').innerText,
              shown: getComputedStyle(li.querySelector('.answer')).display !== 'none'})),
          fresh: s.querySelectorAll('svg.frame g.new > *').length,
          freshBox: Array.from(s.querySelectorAll('svg.frame g.new > *')).map(e => {
              const b = e.getBBox(); return b.width + b.height; }),
          old: s.querySelectorAll('svg.frame g.old > *').length,
          eq: (s.querySelector('.eq') || {innerText: ''}).innerText};
})()"""


def step_through(browser, path: Path, les) -> list[dict]:
    browser.open(path)
    states = [browser.js(STATE)]
    for _ in range(len(les.steps) - 1):
        browser.key("ArrowRight", "ArrowRight", 39)
        states.append(browser.js(STATE))
    return states


@pytest.mark.parametrize("key", ["velocity", "forces", "lever", "flywheel", "shaper"])
def test_stepping_through_with_the_keyboard(browser, pages, key):
    les, path, lang = pages[key]
    states = step_through(browser, path, les)
    n = len(les.steps)
    for i, (st, step) in enumerate(zip(states, les.steps, strict=True)):
        assert st["step"] == i + 1
        assert st["counter"] == f"{i + 1} / {n}"
        assert st["visible"] == 1  # one step at a time
        assert st["kind"] == step.kind
        # the caption says which step it is, what is drawn, and the equation
        w = WORDS[lang]
        assert st["caption"].startswith(f"{w['step']} {i + 1} {w['of']} {n}")
        if step.kind != "read":  # (a reading's sentence is its list of results)
            said = localise(step.text[lang], lang).replace("_", "")
            assert said[:30] in st["caption"].replace("\u00a0", " ")
        if step.equation:
            assert st["eq"].replace(" ", "") == localise(step.equation, lang).replace(
                "_", "").replace(" ", "")
        # the new lines of the step appear, with an extent, over the earlier ones
        drawn = [m for m in step.marks if m.kind != "label" and m.role != "context"
                 and not (m.kind == "vector" and m.points[0] == m.points[-1])]
        if drawn:
            assert st["fresh"] > 0 and max(st["freshBox"]) > 0.5, (i, st)
        # every result is shown with the construction's numbers
        assert len(st["results"]) == len(step.results)
        for r, shown in zip(step.results, st["results"], strict=True):
            assert shown["shown"]
            assert shown["mm"] == pytest.approx(r.mm, abs=1e-9)
            nums = [parse(x) for x in NUMBER.findall(shown["text"])]
            assert any(abs(x - r.mm) <= 0.005 + 1e-12 for x in nums), (shown["text"], r.mm)
            tol = 5e-4 * abs(r.value) + ZERO_MM * r.per_mm + 1e-12
            assert any(abs(x - r.value) <= tol for x in nums), (shown["text"], r.value)
    # earlier steps of the same panel stay, greyed
    for i in range(1, n):
        if les.steps[i].panel == les.steps[i - 1].panel and states[i - 1]["fresh"]:
            assert states[i]["old"] >= states[i - 1]["fresh"]
    # back with the left arrow, Home and End
    browser.key("ArrowLeft", "ArrowLeft", 37)
    assert browser.js(STATE)["step"] == max(1, n - 1)
    browser.key("Home", "Home", 36)
    assert browser.js(STATE)["step"] == 1
    browser.key("End", "End", 35)
    assert browser.js(STATE)["step"] == n


def test_first_and_last_steps_look_different_and_not_blank(browser, pages, tmp_path):
    _, path, _ = pages["velocity"]
    browser.open(path)
    first, png1 = browser.screenshot()
    browser.key("End", "End", 35)
    last, png2 = browser.screenshot()
    (tmp_path / "first.png").write_bytes(png1)
    (tmp_path / "last.png").write_bytes(png2)
    for img in (first, last):
        grey = img.mean(axis=-1)
        assert img.shape[:2] == (HEIGHT, WIDTH)
        assert 0.005 < (grey < 0.5).mean() < 0.3  # ink: text and lines, mostly paper
    # colour: the current step's lines are drawn in colour, not only black and grey
    sat = last.max(axis=-1) - last.min(axis=-1)
    assert (sat > 0.3).sum() > 50
    assert np.abs(first - last).mean() > 0.005  # a different picture


def test_no_network_request(browser, pages):
    _, path, _ = pages["flywheel"]
    browser.open(path)
    browser.key("End", "End", 35)
    urls = browser.requests()
    # the page itself is the only request (fonts and pictures are data: URLs, which
    # Chromium does not report as network requests, or reports as data:)
    assert [u for u in urls if not u.startswith("data:")] == [path.resolve().as_uri()]
    csp = browser.js("document.querySelector('meta[http-equiv=Content-Security-Policy]')"
                     ".content")
    assert "default-src 'none'" in csp
    # the embedded fonts are used: osifont (when installed where the page was made)
    # letters the drawing from its data: URL
    from graphplan.drawing import find_font_file

    if find_font_file("osifont") is not None:
        loaded = browser.js("Array.from(document.fonts).filter(f => f.status === 'loaded')"
                            ".map(f => f.family).join(',')")
        assert loaded.count("osifont") == 1, loaded


def test_try_it_yourself(browser, pages):
    les, path, _ = pages["velocity"]
    browser.open(path)
    browser.key("t", "KeyT", 84, "t")
    assert browser.js("document.body.classList.contains('try')")
    k = next(i for i, s in enumerate(les.steps) if s.kind == "read")
    for _ in range(k):
        browser.key("ArrowRight", "ArrowRight", 39)
    st = browser.js(STATE)
    assert st["step"] == k + 1
    assert all(not r["shown"] for r in st["results"])  # results hidden
    assert les.steps[k].text["ru"][:10] not in st["caption"]  # the numbers' sentence too
    r0 = les.steps[k].results[0]
    answer = round(r0.mm + 1.25, 2)  # a reading 1.25 mm too long
    browser.js("document.querySelector('section.step.current li.result input').focus()")
    browser.type_text(f"{answer}".replace(".", ","))  # a decimal comma is accepted
    browser.key("Enter", "Enter", 13)
    fb = browser.js("document.querySelector('section.step.current li.result .feedback')"
                    ".innerText")
    nums = [parse(x) for x in NUMBER.findall(fb)]
    # your 43.44 mm · correct 42.19 mm · deviation +1.25 mm (+3.0 %)
    assert nums[0] == pytest.approx(answer)
    assert nums[1] == pytest.approx(round(r0.mm, 2))
    assert nums[2] == pytest.approx(answer - round(r0.mm, 2), abs=0.011)
    assert nums[3] == pytest.approx((answer - r0.mm) / r0.mm * 100, abs=0.051)
    st = browser.js(STATE)
    assert st["results"][0]["shown"] and not st["results"][1]["shown"]
    # arrows inside the field do not change the step; PageDown does
    browser.js("document.querySelectorAll('section.step.current li.result input')[1].focus()")
    browser.key("ArrowRight", "ArrowRight", 39)
    assert browser.js(STATE)["step"] == k + 1
    browser.key("PageDown", "PageDown", 34)
    assert browser.js(STATE)["step"] == k + 2
    # leaving the mode shows every result again
    browser.key("t", "KeyT", 84, "t")
    assert all(r["shown"] for r in browser.js(STATE)["results"])


def test_try_it_asks_where_the_coriolis_acceleration_points(browser, pages):
    """In the try-it mode the shaper's Coriolis step asks where aᵏ points: hidden outside
    the mode, a wrong option is marked wrong, the right one (v_AA3 turned by 90° in the
    sense of ω3) right."""
    from graphplan.teaching.questions import questions

    les, path, lang = pages["shaper"]
    k = next(i for i, s in enumerate(les.steps) if s.equation.startswith("aᵏ"))
    q = next(q for q in questions(les.steps[k], lang) if "Coriolis" in q.prompt)
    browser.open(path)
    for _ in range(k):
        browser.key("ArrowRight", "ArrowRight", 39)
    quiz = "document.querySelector('section.step.current .quiz')"
    assert browser.js(f"getComputedStyle({quiz}).display") == "none"  # not outside the mode
    browser.key("t", "KeyT", 84, "t")
    assert browser.js(f"getComputedStyle({quiz}).display") != "none"
    assert "Coriolis" in browser.js(f"{quiz}.querySelector('.prompt').innerText")
    wrong = (q.correct + 1) % len(q.options)
    browser.js(f"{quiz}.querySelectorAll('button.opt')[{wrong}].click()")
    assert browser.js(f"{quiz}.getAttribute('data-answered')") == "wrong"
    browser.js(f"{quiz}.querySelectorAll('button.opt')[{q.correct}].click()")
    assert browser.js(f"{quiz}.getAttribute('data-answered')") == "right"
    right = browser.js(f"{quiz}.querySelectorAll('button.opt')[{q.correct}].innerText")
    assert "in the sense of ω3" in right and "v" in right


def test_print_view_shows_every_step(browser, pages):
    les, path, _ = pages["forces"]
    browser.open(path)
    browser.key("p", "KeyP", 80, "p")
    assert browser.js(STATE)["visible"] == len(les.steps)
    browser.call("Emulation.setEmulatedMedia", session=True, media="print")
    try:
        browser.key("p", "KeyP", 80, "p")  # back to one step on screen; print shows all
        assert browser.js(STATE)["visible"] == len(les.steps)
        # frames at true size: 1 mm of the plan is 1 mm of paper (96 px per 25.4 mm)
        w = browser.js("(() => { const s = document.querySelector('section.step svg.frame');"
                       " return [s.getBoundingClientRect().width, s.width.baseVal"
                       ".valueInSpecifiedUnits, s.width.baseVal.unitType]; })()")
        if w[0] < 700:  # wider frames are shrunk to the page width
            assert w[2] == 7  # mm
            assert w[0] == pytest.approx(w[1] * 96 / 25.4, rel=0.01)
    finally:
        browser.call("Emulation.setEmulatedMedia", session=True, media="")
