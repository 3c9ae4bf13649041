"""Scenes from Python agree with the command line: every shipped scene
loads, validates and runs to the same numbers the CLI writes."""

import math
import subprocess

import numpy as np
import pytest

import pegdyn
from conftest import SCENES

# The jamming scene's dynamic check is 169 compliant insertions; a 3 x 3
# grid exercises the same code at a tenth of the cost.
SMALLER = {"jamming": {"sweep.n": 3}}


def scene_for(path):
    s = pegdyn.load(path)
    return s.with_values(SMALLER[s.name]) if s.name in SMALLER else s


def test_every_shipped_scene_is_found():
    assert {p.stem for p in SCENES} >= {"pendulum", "fig9", "jamming", "insert_compliant"}


def cli_run(cli, scene, tmp_path):
    src = tmp_path / f"{scene.name}.toml"
    src.write_text(scene.text)
    out = tmp_path / "cli"
    p = subprocess.run([str(cli), "run", "-q", str(src), "--out", str(out)], capture_output=True, text=True)
    return p, out


def cells_equal(text_cells, values):
    if isinstance(values, list):
        return text_cells == values
    parsed = np.array([float(c) for c in text_cells])
    same = (parsed == values) | (np.isnan(parsed) & np.isnan(values))
    return bool(same.all()) and parsed.shape == values.shape


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_run_agrees_with_cli_csv(path, cli, tmp_path):
    scene = scene_for(path)
    proc, out = cli_run(cli, scene, tmp_path)
    result = scene.run()
    assert result.paths == []
    cli_csvs = sorted(out.glob("*.csv"))
    assert cli_csvs, proc.stderr
    assert sorted(result.tables) == [c.stem for c in cli_csvs]
    for c in cli_csvs:
        lines = c.read_text().splitlines()
        header = lines[0].split(",")
        table = result.tables[c.stem]
        assert list(table) == header
        rows = [line.split(",") for line in lines[1:]]
        for j, name in enumerate(header):
            col = [r[j] for r in rows]
            assert cells_equal(col, table[name]), f"{c.name}: column {name} differs"
    # Outcome and metrics as the CLI prints them.
    assert result.outcome.success == (proc.returncode == 0)
    printed = [line for line in proc.stdout.splitlines()[1:] if "wrote" not in line]
    ours = [line for line in result.text.splitlines() if "wrote" not in line]
    assert ours == printed


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_check_agrees_with_cli(path, cli):
    s = pegdyn.load(path)
    p = subprocess.run([str(cli), "check", str(path)], capture_output=True, text=True)
    assert p.returncode == 0
    assert p.stdout.strip() == f"{path}: OK ({s.kind}): {s.describe()}"


def test_run_with_out_writes_the_cli_files(cli, tmp_path):
    scene = pegdyn.load(next(p for p in SCENES if p.stem == "pendulum"))
    _, cli_out = cli_run(cli, scene, tmp_path)
    result = scene.run(out=tmp_path / "py")
    assert sorted(p.split("/")[-1] for p in result.paths) == ["pendulum.csv", "pendulum.svg"]
    py_csv = (tmp_path / "py" / "pendulum.csv").read_bytes()
    assert py_csv == (cli_out / "pendulum.csv").read_bytes()


def test_loads_and_from_dict_round_trip():
    base = pegdyn.load(next(p for p in SCENES if p.stem == "pendulum"))
    d = {
        "kind": "pendulum",
        "pendulum": {"length": 1.0, "mass": 1.0, "gravity": 9.80665, "theta0_deg": 60.0, "omega0": 0.0},
        "integrator": {"method": "dopri5", "rtol": 1e-10, "atol": 1e-12, "t_end": 2.0, "output_interval": 0.01},
    }
    a = pegdyn.from_dict(d).run()
    b = pegdyn.loads(base.with_values({"integrator.t_end": 2.0}).text).run()
    assert a.outcome == b.outcome
    for k in a.columns:
        np.testing.assert_array_equal(a.columns[k], b.columns[k])
    # Energy is conserved to the tolerance: a real value, not a shape check.
    e = a.columns["energy_J"]
    assert abs(e[-1] - e[0]) < 1e-8 * abs(e[0])
    assert a.outcome.t_end == 2.0 and a.events == []


def test_scene_pickles_as_its_text():
    import pickle

    s = pegdyn.load(next(p for p in SCENES if p.stem == "fig9"))
    t = pickle.loads(pickle.dumps(s))
    assert t == s and t.kind == "fig9"


def test_terminal_event_is_reported():
    s = pegdyn.load(next(p for p in SCENES if p.stem == "align_forward"))
    r = s.run()
    if r.events:
        ev = r.events[0]
        assert ev.t == pytest.approx(r.outcome.t_end)
        assert ev.name in r.outcome.stop
    else:
        assert "event" not in r.outcome.stop


def test_to_pandas_when_installed():
    pd = pytest.importorskip("pandas")
    r = pegdyn.load(next(p for p in SCENES if p.stem == "fig9")).run()
    df = r.to_pandas()
    assert isinstance(df, pd.DataFrame)
    assert list(df.columns) == list(r.columns)
    assert math.isclose(df["gamma"].iloc[-1], 0.5)


def test_ctrl_c_interrupts_a_long_run():
    import _thread
    import threading

    # About a million steps: still running when the interrupt arrives.
    s = pegdyn.load(next(p for p in SCENES if p.stem == "pendulum")).with_values(
        {"integrator.t_end": 2e4, "integrator.output_interval": 1000.0}
    )
    timer = threading.Timer(0.1, _thread.interrupt_main)
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        s.run()
    timer.join()
    # The package is usable afterwards.
    assert pegdyn.load(next(p for p in SCENES if p.stem == "fig9")).run().outcome.success
