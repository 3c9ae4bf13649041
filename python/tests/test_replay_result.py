"""A run's replay page from Python: kept by a run in memory, the same bytes
as the file `pegdyn run` writes, shown inline in Jupyter through a
sandboxed iframe, written by `Result.replay(path)`; a ValueError where the
run has none."""

import html
import re

import pytest

import pegdyn
from conftest import ROOT

# A short run of the compliant planar peg (its page is quick to make).
PLANAR = (ROOT / "scenes" / "insert_compliant.toml").read_text().replace("t_end = 0.3 ", "t_end = 0.02")


def test_a_run_in_memory_keeps_the_page_the_cli_writes(cli, tmp_path):
    import subprocess

    scene_file = tmp_path / "tilt.toml"
    scene_file.write_text(PLANAR)
    done = subprocess.run([str(cli), "run", str(scene_file), "--out", str(tmp_path / "cli"), "-q"],
                          capture_output=True, text=True, check=True)
    written = [l.split("wrote ", 1)[1] for l in done.stdout.splitlines() if "wrote " in l]
    page_file = next(p for p in written if p.endswith(".html"))
    result = pegdyn.load(scene_file).run()
    assert result.has_replay and result.paths == []
    out = result.replay(tmp_path / "again.html")
    assert open(out, "rb").read() == open(page_file, "rb").read()
    # A run into a directory reads the page from its file there.
    on_disk = pegdyn.load(scene_file).run(out=tmp_path / "py")
    assert on_disk.has_replay and on_disk._repr_html_() == result._repr_html_()


def test_the_inline_page_is_a_sandboxed_iframe_of_the_whole_page():
    result = pegdyn.loads(PLANAR, "tilt").run()
    shown = result._repr_html_()
    m = re.fullmatch(r'<iframe sandbox="allow-scripts" style="[^"]*" title="pegdyn replay" srcdoc="([^"]*)"></iframe>', shown, flags=re.S)
    assert m, shown[:300]
    page = html.unescape(m.group(1))
    assert page.startswith("<!DOCTYPE html>") and "pegdynReplay" in page
    assert page.encode() == result._page
    # The repr of the result stays short (the page is not in it).
    assert len(repr(result)) < len(shown) / 2


@pytest.mark.parametrize("scene", ["pendulum", "double_pendulum"])
def test_kinds_without_a_page_say_so(scene, tmp_path):
    result = pegdyn.load(ROOT / "scenes" / f"{scene}.toml").run()
    assert not result.has_replay and result._repr_html_() is None
    with pytest.raises(ValueError, match=f"this {scene} run has no replay page"):
        result.replay(tmp_path / "x.html")
    assert not (tmp_path / "x.html").exists()


def test_a_scene_that_turns_the_page_off_has_none(tmp_path):
    result = pegdyn.loads(PLANAR + "\n[replay]\npage = false\n", "off").run()
    assert not result.has_replay
    with pytest.raises(ValueError, match=r"page = false"):
        result.replay(tmp_path / "x.html")


def test_a_sweep_makes_no_page():
    rows = pegdyn.sweep(pegdyn.loads(PLANAR, "tilt"), {"insert_compliant.friction": [0.1, 0.2]})
    assert rows["outcome"] == ["ok", "ok"]
    assert not hasattr(rows, "replay")
