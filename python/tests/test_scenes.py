"""Scenes from Python agree with the command line: every shipped scene
loads, validates and runs to the same numbers the CLI writes."""

import math
import subprocess

import numpy as np
import pytest

import pegdyn
from conftest import SCENES

# The jamming scene's dynamic check is 169 compliant insertions; a 3 x 3
# grid exercises the same code at a tenth of the cost. The full-size
# grids (1,008 rotation runs, 1,023 design-margin runs): a few points of
# their axes, the same kind and settings.
SMALLER = {
    "jamming": {"sweep.n": 3},
    "design_margins_grid": {
        "grid.centre_lateral_errors": [-6e-4, 0.0, 6e-4],
        "grid.angular_errors_deg": [0.0],
    },
    # The robot insertion's sensitivities at the shipped 1e-8 cost a
    # debug-built module half a minute; 1e-6 checks the same code.
    "insert_rcc_sensitivities": {"integrator.rtol": 1e-6, "integrator.atol": 1e-10},
    "rotation_assist_grid": {
        "grid.lateral_errors": [0.0, 3e-4],
        "grid.precession_rates": [0.0, 10.0],
        "grid.spin_rates": [0.0],
    },
}


def scene_for(path):
    s = pegdyn.load(path)
    return s.with_values(SMALLER[s.name]) if s.name in SMALLER else s


def test_every_shipped_scene_is_found():
    assert {p.stem for p in SCENES} >= {"pendulum", "fig9", "jamming", "insert_compliant"}


def test_every_scene_kind_has_a_shipped_scene():
    # The package wraps kinds through the runtime's registry: a new kind
    # needs no Python change, only a scene in scenes/ for the comparison
    # with the CLI below to cover it.
    shipped = {pegdyn.load(p).kind for p in SCENES}
    assert shipped == {k for k, _ in pegdyn.kinds()}


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
    # In memory: no "wrote" line, and the same tables as from the files.
    assert "wrote" not in result.text
    assert "pegdyn-memory" not in result.text
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


@pytest.mark.parametrize("stem", ["pendulum", "jamming"])
def test_run_in_memory_equals_run_to_files(stem, tmp_path):
    scene = scene_for(next(p for p in SCENES if p.stem == stem))
    mem, files = scene.run(), scene.run(out=tmp_path)
    # Every file in the directory is an output, but the run's manifest.
    written = sorted(str(p) for p in tmp_path.iterdir() if p.name != f"{stem}.run.toml")
    assert sorted(files.paths) == written
    assert list(mem.tables) == [t for t in mem.tables if t in files.tables]
    assert sorted(mem.tables) == sorted(files.tables)
    for name, table in files.tables.items():
        assert list(mem.tables[name]) == list(table)
        for col, v in table.items():
            if isinstance(v, list):
                assert mem.tables[name][col] == v
            else:
                assert mem.tables[name][col].tobytes() == v.tobytes(), (name, col)
    assert mem.metrics == files.metrics and mem.events == files.events
    assert mem.notes == files.notes


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
    assert a.outcome.t_end == 2.0
    # From 60 degrees at rest, theta rises through zero once in 2 s, three
    # quarters of a period in: a passing (non-terminal) event.
    [ev] = a.events
    t, name, details = ev
    assert name == "theta_zero_rising" and not ev.terminal
    assert details["direction"] == 1.0 and abs(details["x[0]"]) < 1e-9
    assert 0.5 < details["x[1]"] and 1.0 < t < 2.0
    # Exact period 4 sqrt(L/g) K(sin(theta0/2)), K by the arithmetic-geometric mean.
    k = math.sin(math.radians(60.0) / 2)
    x, y = 1.0, math.sqrt(1 - k * k)
    for _ in range(8):
        x, y = (x + y) / 2, math.sqrt(x * y)
    period = 4 * math.sqrt(1.0 / 9.80665) * math.pi / (2 * x)
    assert t == pytest.approx(0.75 * period, rel=1e-7)


def test_scene_pickles_as_its_text():
    import pickle

    s = pegdyn.load(next(p for p in SCENES if p.stem == "fig9"))
    t = pickle.loads(pickle.dumps(s))
    assert t == s and t.kind == "fig9"


def test_every_event_is_reported_and_a_terminal_one_last():
    s = pegdyn.load(next(p for p in SCENES if p.stem == "pendulum"))
    r = s.run()
    period = r.metrics["period (measured)"]
    times = [e.t for e in r.events]
    assert len(times) >= 2 and all(e.name == "theta_zero_rising" for e in r.events)
    assert not any(e.terminal for e in r.events)
    # Upward zero crossings one period apart.
    np.testing.assert_allclose(np.diff(times), period, rtol=1e-6)
    assert all(e.details["direction"] == 1.0 for e in r.events)
    # The inserted peg's scene ends on its terminal event, reported last.
    ins = pegdyn.load(next(p for p in SCENES if p.stem == "insert_compliant")).run()
    stop = ins.outcome.stop
    if "event" in stop:
        last = ins.events[-1]
        assert last.terminal and last.name in stop and last.t == ins.outcome.t_end
    assert sum(e.terminal for e in ins.events) == (1 if "event" in stop else 0)


def test_the_robot_insertions_events_are_named_by_what_they_are():
    # Contact transitions are named by their pair and point count, the
    # seating by its name, and only the seating is terminal: the same
    # list as the events table.
    r = pegdyn.load(next(p for p in SCENES if p.stem == "insert_rcc")).run()
    assert "seated" in r.outcome.stop
    *transitions, last = r.events
    assert last.name == "seated" and last.terminal and last.t == r.outcome.t_end
    table = next(t for k, t in r.tables.items() if k.endswith(".events"))
    assert len(transitions) == len(table["t_s"]) > 0
    np.testing.assert_array_equal([e.t for e in transitions], table["t_s"])
    for e, row in zip(transitions, table["transition"]):
        # "rim_wall 0 -> 1" in the table is the event "rim_wall 1".
        pair, before, _, after = row.split(" ")
        assert not e.terminal and e.name == f"{pair} {max(int(before), int(after))}", (e.name, row)


def test_to_pandas_when_installed():
    pd = pytest.importorskip("pandas")
    r = pegdyn.load(next(p for p in SCENES if p.stem == "fig9")).run()
    df = r.to_pandas()
    assert isinstance(df, pd.DataFrame)
    assert list(df.columns) == list(r.columns)
    assert math.isclose(df["gamma"].iloc[-1], 0.5)


def test_ctrl_c_interrupts_a_long_run():
    import _thread
    import signal
    import threading

    # About a million steps: still running when the interrupt arrives.
    s = pegdyn.load(next(p for p in SCENES if p.stem == "pendulum")).with_values(
        {"integrator.t_end": 2e4, "integrator.output_interval": 1000.0}
    )
    # A process started in the background inherits SIGINT ignored, and
    # interrupt_main does nothing then: Python's own handler for the test.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        timer = threading.Timer(0.1, _thread.interrupt_main)
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            s.run()
        timer.join()
    finally:
        signal.signal(signal.SIGINT, previous)
    # The package is usable afterwards.
    assert pegdyn.load(next(p for p in SCENES if p.stem == "fig9")).run().outcome.success


def test_results_in_words_are_notes_not_nan_metrics():
    # The reduced jamming sweep judges no grid point: its diagram check is
    # a note with the reason, not a NaN among the numbers.
    jam = scene_for(next(p for p in SCENES if p.stem == "jamming")).run()
    assert "diagram check" not in jam.metrics
    assert jam.notes["diagram check"].startswith("NOT MADE")
    assert all(v == v for v in jam.metrics.values()), jam.metrics
    assert set(jam.units) == set(jam.metrics)
