"""The replay pages of the shipped scenes in a real browser (headless Chromium
driven by Playwright): each page loads from disk with no console error and
draws; the peg is drawn elsewhere at the end than at t = 0; jumping to an
event puts the cursor at its time; with the network disabled the page
still draws (it fetches nothing); without WebGL it says so and the
timeline still works.

Needs Chromium (`apt-get install chromium`; $PEGDYN_CHROMIUM for another
binary) and `pip install playwright pillow` (Playwright drives the system's
Chromium, it downloads no browser). The tests skip, saying why, only when
$PEGDYN_BROWSER_SKIP names a reason (set by .ci/run when Chromium cannot be
installed) or, outside CI, when Chromium is missing.

Run as a script to write the screenshots of docs/insertion/:

    python python/tests/test_replay_browser.py --shots docs/insertion
"""

import io
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
# The scenes that have a replay page, and the largest page allowed (bytes).
SCENES = ["insert_rcc", "drop_3d", "insert_compliant", "rotation_assist", "design_margins"]
MAX_PAGE = 2_000_000
CHROMIUM = os.environ.get("PEGDYN_CHROMIUM", "/usr/bin/chromium")
# Flags that work headless as root on a closed network: no sandbox, no
# background connections; WebGL from SwiftShader (no GPU).
ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--use-gl=swiftshader",
    "--enable-unsafe-swiftshader",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-quic",
    "--no-first-run",
]
VIEWPORT = {"width": 1200, "height": 800}


def replay_page(stdout: str) -> Path:
    """The replay page among the files a `pegdyn run` reports (its `wrote
    PATH` lines): the one place these tests learn a page's file name."""
    written = [line.split("wrote ", 1)[1] for line in stdout.splitlines() if "wrote " in line]
    pages = [Path(w) for w in written if w.endswith(".html")]
    assert len(pages) == 1, f"one replay page expected among {written}"
    return pages[0]


def make_pages(out: Path) -> dict:
    """Runs every shipped scene with `pegdyn run SCENE --out OUT` (the CLI
    that `cargo test` built, or $PEGDYN_CLI); returns {scene: its page}."""
    from conftest import cli_path

    pages = {}
    for name in SCENES:
        done = subprocess.run(
            [str(cli_path()), "run", str(ROOT / "scenes" / f"{name}.toml"), "--out", str(out), "-q"],
            check=True,
            capture_output=True,
            text=True,
        )
        pages[name] = replay_page(done.stdout)
    return pages


def skip_reason():
    """Why the browser tests cannot run here, or None."""
    if os.environ.get("PEGDYN_BROWSER_SKIP"):
        return "no browser: " + os.environ["PEGDYN_BROWSER_SKIP"]
    if not Path(CHROMIUM).exists():
        if os.environ.get("CI"):
            return None  # CI installs Chromium: a missing one is a failure below
        return f"no Chromium at {CHROMIUM} (apt-get install chromium)"
    return None


@pytest.fixture(scope="module")
def playwright():
    reason = skip_reason()
    if reason:
        print(f"\nSKIPPED browser tests: {reason}", file=sys.stderr)
        pytest.skip(reason)
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        yield p


@pytest.fixture(scope="module")
def browser(playwright):
    b = playwright.chromium.launch(executable_path=CHROMIUM, args=ARGS)
    yield b
    b.close()


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    return make_pages(tmp_path_factory.mktemp("replay"))


class Opened:
    """A page opened from disk, with its console errors and its requests."""

    def __init__(self, browser, path: Path, offline=False):
        self.context = browser.new_context(viewport=VIEWPORT, offline=offline)
        self.requests = []
        self.context.on("request", lambda r: self.requests.append(r.url))
        self.page = self.context.new_page()
        self.errors = []
        self.page.on("console", lambda m: m.type == "error" and self.errors.append(m.text))
        self.page.on("pageerror", lambda e: self.errors.append(str(e)))
        start = time.perf_counter()
        self.page.goto(path.as_uri())
        self.page.wait_for_function("window.pegdynReplay && window.pegdynReplay.ready")
        if self.page.evaluate("pegdynReplay.webgl"):
            self.page.wait_for_function("pegdynReplay.renders > 0")
        self.load_seconds = time.perf_counter() - start

    def state(self, expr):
        return self.page.evaluate(f"pegdynReplay.{expr}")

    def show(self, time_s):
        """Seeks and draws synchronously."""
        self.page.evaluate(f"pegdynReplay.seek({time_s!r}); pegdynReplay.render()")

    def view_pixels(self):
        from PIL import Image

        png = self.page.locator("#view").screenshot()
        return Image.open(io.BytesIO(png)).convert("RGB")

    def close(self):
        self.context.close()


@pytest.fixture(scope="module")
def opened(browser, pages):
    """Each scene's page, opened once for the tests of this module."""
    made = {}

    def open_(name, **kw):
        key = (name, tuple(sorted(kw.items())))
        if key not in made:
            made[key] = Opened(browser, pages[name], **kw)
        return made[key]

    yield open_
    for o in made.values():
        o.close()


def differing(a, b, box, view_box) -> float:
    """The fraction of pixels inside `box` (page CSS pixels) that differ
    between images a and b of the element at `view_box`."""
    left = max(0, int(box["left"] - view_box["x"]))
    top = max(0, int(box["top"] - view_box["y"]))
    right = min(a.width, int(box["right"] - view_box["x"]) + 1)
    bottom = min(a.height, int(box["bottom"] - view_box["y"]) + 1)
    assert right > left and bottom > top, f"the peg is off the view: {box}"
    import numpy as np

    ca = np.asarray(a.crop((left, top, right, bottom)), dtype=np.int16)
    cb = np.asarray(b.crop((left, top, right, bottom)), dtype=np.int16)
    changed = np.abs(ca - cb).max(axis=2) > 24
    return float(changed.mean())


def union(a, b):
    return {
        "left": min(a["left"], b["left"]),
        "top": min(a["top"], b["top"]),
        "right": max(a["right"], b["right"]),
        "bottom": max(a["bottom"], b["bottom"]),
    }


@pytest.mark.parametrize("name", SCENES)
def test_the_page_is_small_loads_without_error_and_draws(opened, pages, name):
    size = pages[name].stat().st_size
    assert size <= MAX_PAGE, f"{pages[name].name} is {size} bytes"
    o = opened(name)
    assert o.state("webgl"), "WebGL did not start under SwiftShader"
    assert o.errors == [], o.errors
    frames = o.state("frames")
    print(f"{pages[name].name}: {size} bytes, {frames} frames, loaded and drawn in {o.load_seconds:.2f} s")
    assert frames >= 100
    assert o.page.locator("#nogl").is_hidden()


@pytest.mark.parametrize("name", SCENES)
def test_the_peg_is_drawn_where_it_moved(opened, name):
    o = opened(name)
    marks = o.state("marks")
    o.show(0.0)
    start, box0 = o.view_pixels(), o.state("pegBox()")
    o.show(marks[-1]["t"])
    o.show(0.0)
    again = o.view_pixels()
    o.show(marks[-1]["t"])
    end, box1 = o.view_pixels(), o.state("pegBox()")
    assert box0 != box1, "the peg's box did not move"
    view_box = o.page.locator("#view").bounding_box()
    changed = differing(start, end, union(box0, box1), view_box)
    # The same instant drawn twice (after a visit to the end) is the same picture.
    same = differing(start, again, union(box0, box1), view_box)
    print(f"{name}: {changed:.1%} of the peg's region changed ({same:.2%} when redrawn)")
    assert same < 0.002, f"{same:.2%} of the peg's region changed without a move"
    assert changed > 0.03, f"only {changed:.1%} of the peg's region changed"
    assert o.errors == [], o.errors


@pytest.mark.parametrize("name", SCENES)
def test_jumping_to_an_event_moves_the_cursor_to_its_time(opened, name):
    o = opened(name)
    marks = o.state("marks")
    assert marks, "no event to jump to"
    picks = sorted({0, len(marks) // 2, len(marks) - 1})
    for k in picks:
        o.show(0.0)
        o.page.locator(f'#events button[data-index="{k}"]').click()
        m = marks[k]
        assert o.state("time") == m["t"], (k, m)
        assert o.state("frame") == m["frame"], (k, m)
        assert o.state("cursor") == m["t"]
        assert abs(o.state("scrubber") - m["t"]) <= 1e-9 * max(1.0, abs(m["t"]))
    # The markers on the timeline jump the same way.
    k = len(marks) - 1
    o.show(0.0)
    o.page.locator(f'#markers button[data-index="{k}"]').dispatch_event("click")
    assert o.state("time") == marks[k]["t"]
    assert o.errors == [], o.errors


def test_with_the_network_disabled_the_page_still_draws(opened):
    o = opened("insert_rcc", offline=True)
    assert o.state("webgl") and o.state("renders") > 0
    assert [u for u in o.requests if not u.startswith(("file:", "data:", "blob:"))] == []
    img = o.view_pixels()
    import numpy as np

    colours = len(np.unique(np.asarray(img).reshape(-1, 3), axis=0))
    assert colours > 100, f"a blank view ({colours} colours)"
    assert o.errors == [], o.errors


def test_without_webgl_the_page_says_so_and_the_timeline_works(playwright, pages):
    b = playwright.chromium.launch(
        executable_path=CHROMIUM, args=ARGS + ["--disable-webgl", "--disable-3d-apis"]
    )
    try:
        o = Opened(b, pages["insert_rcc"])
        assert not o.state("webgl")
        message = o.page.locator("#nogl")
        assert message.is_visible() and "WebGL" in message.inner_text()
        marks = o.state("marks")
        o.page.locator('#events button[data-index="1"]').click()
        assert o.state("time") == marks[1]["t"]
        assert o.errors == [], o.errors
    finally:
        b.close()


def test_the_notebook_iframe_runs_the_page(browser, tmp_path):
    """`Result._repr_html_()` as Jupyter shows it: the page in a sandboxed
    iframe (scripts allowed, no same-origin) loads, draws and jumps."""
    import pegdyn

    text = (ROOT / "scenes" / "insert_compliant.toml").read_text().replace("t_end = 0.3 ", "t_end = 0.05")
    shown = pegdyn.loads(text, "notebook").run()._repr_html_()
    cell = tmp_path / "cell.html"
    cell.write_text(f"<!DOCTYPE html><html><body><h1>a notebook cell</h1>{shown}</body></html>")
    context = browser.new_context(viewport=VIEWPORT)
    errors = []
    page = context.new_page()
    page.on("console", lambda m: m.type == "error" and errors.append(m.text))
    try:
        page.goto(cell.as_uri())
        frame = page.frame_locator("iframe")
        inner = next(f for f in page.frames if f != page.main_frame)
        inner.wait_for_function("window.pegdynReplay && window.pegdynReplay.ready")
        assert inner.evaluate("pegdynReplay.webgl")
        inner.wait_for_function("pegdynReplay.renders > 0")
        marks = inner.evaluate("pegdynReplay.marks")
        frame.locator(f'#events button[data-index="{len(marks) - 1}"]').click()
        assert inner.evaluate("pegdynReplay.time") == marks[-1]["t"]
        assert errors == [], errors
    finally:
        context.close()


def write_shots(out: Path):
    """Screenshots of the shipped insert_rcc, close up: the whole page at the
    two-point contact, and the view one frame after each pair's first
    contact (the new point then carries load) and at the seat."""
    import tempfile

    from playwright.sync_api import sync_playwright

    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        page_file = make_pages(Path(tmp))["insert_rcc"]
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        o = Opened(b, page_file)
        marks = o.state("marks")
        shots = {}
        for k, m in enumerate(marks):
            rising = m["label"].endswith("0 → 1")
            if rising or m["kind"] == "seat":
                shots.setdefault(m["label"], k)
        two_point = next(k for k, m in enumerate(marks) if m["label"].startswith("edge_side 0"))
        o.page.locator("#close").click()
        o.page.evaluate(f"pegdynReplay.jump({two_point}); pegdynReplay.render()")
        o.page.screenshot(path=str(out / "replay_insert_rcc.png"))
        frames = o.state("frames")
        for label, k in shots.items():
            frame = min(frames - 1, marks[k]["frame"] + (0 if marks[k]["kind"] == "seat" else 1))
            o.page.evaluate(
                f"pegdynReplay.seek(pegdynReplay.marks[{k}].t); pegdynReplay.step({frame}); "
                "pegdynReplay.render()"
            )
            slug = label.replace(" → ", "-").replace(" ", "_")
            path = out / f"replay_insert_rcc_{k:02d}_{slug}.png"
            o.page.locator("#view").screenshot(path=str(path))
            state = o.page.locator("#readout dd").first.inner_text()
            print(path.name, f"t = {o.state('time')} s", label, "->", state)
        o.close()
        b.close()


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--shots":
        write_shots(ROOT / sys.argv[2])
    else:
        sys.exit(__doc__)
