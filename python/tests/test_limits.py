"""Work is bounded from Python as from the command line: from_dict, loads,
with_values and run under the scene's [limits] with the same overrides
(`limits=`, as `--limit`), grids refused before they are built, sweeps
refused before their first run; scene names that cannot name outputs."""

import pickle

import pytest

import pegdyn
from conftest import ROOT

tomllib = pytest.importorskip("tomllib")


def _rotation(n: int) -> dict:
    """The shipped rotation_assist scene as a dict with n^4 grid points."""
    d = tomllib.loads((ROOT / "scenes" / "rotation_assist.toml").read_text())
    step = [1e-6, 1e-3, 1e-2, 1e-2]
    for key, s in zip(["lateral_errors", "angular_errors_deg", "precession_rates", "spin_rates"], step):
        d["grid"][key] = [1e-5 + k * s for k in range(n)]
    return d


@pytest.mark.parametrize("n", [8, 30, 178])
def test_grids_are_refused_before_they_are_built(n):
    # 8^4 = 4096, 30^4 = 810 000 and 178^4 ≈ 1e9 points, each over max_runs.
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.from_dict(_rotation(n), "grid")
    assert e.value.field == "grid"
    assert "max_runs" in e.value.reason
    text = pegdyn._pegdyn.to_toml(_rotation(n))
    with pytest.raises(pegdyn.SceneError, match="max_runs"):
        pegdyn.loads(text, "grid")


def test_raised_limits_past_the_machine_are_a_typed_error():
    huge = {"max_runs": 10**12, "max_memory_mb": 10**12}
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.from_dict(_rotation(178), "grid", limits=huge)
    assert "cannot reserve memory" in str(e.value) and "max_runs" in str(e.value)


def test_limits_take_the_cli_keys_and_refuse_the_rest():
    scene = pegdyn.from_dict(_rotation(8), "grid", limits={"runs": 5000.0})
    assert scene.limits == ("runs=5000",)
    same = pegdyn.from_dict(_rotation(8), "grid", limits=["max_runs=5e3"])
    assert same.kind == "rotation_assist"
    for bad in [{"max_run": 5}, ["runs=0"], ["runs"], {"runs": -1}]:
        with pytest.raises(ValueError, match="limit"):
            pegdyn.from_dict(_rotation(2), "grid", limits=bad)
    with pytest.raises(TypeError):
        pegdyn.from_dict(_rotation(2), "grid", limits="runs=5")


def test_limits_travel_with_the_scene():
    scene = pegdyn.from_dict(_rotation(8), "grid", limits={"max_runs": 5000})
    back = pickle.loads(pickle.dumps(scene))
    assert back == scene and back.limits == scene.limits
    # with_values keeps them: the copy is validated under the same limits.
    copy = scene.with_values({"grid.yield_pressure": 2e9})
    assert copy.limits == scene.limits
    with pytest.raises(pegdyn.SceneError, match="max_runs"):
        pegdyn.Scene(scene.text, "grid")


def test_a_sweep_is_refused_before_its_first_run():
    pend = pegdyn.load(ROOT / "scenes" / "pendulum.toml")
    # 3000 points of one run each: over max_runs = 2500; nothing runs
    # (a point that ran would take seconds each at this t_end).
    long = pend.with_values({"integrator.t_end": 1e3, "integrator.output_interval": 1e-2})
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.sweep(long, {"pendulum.theta0_deg": list(range(3000))})
    assert e.value.field == "sweep" and "max_runs" in e.value.reason
    # A grid scene's points count its runs: 700 points x 16 runs.
    grid = pegdyn.from_dict(_rotation(2), "grid")
    with pytest.raises(pegdyn.SceneError, match="max_runs"):
        pegdyn.sweep(grid, {"grid.yield_pressure": [1e9 + k for k in range(700)]})
    # Raised, a small sweep runs; the limits reach every point.
    rows = pegdyn.sweep(
        pend.with_values({"integrator.t_end": 0.2}),
        {"pendulum.theta0_deg": [10, 20]},
        limits={"max_runs": 3000},
    )
    assert [r["outcome"] for r in rows] == ["ok", "ok"]
    tight = pegdyn.sweep(
        pend.with_values({"integrator.t_end": 0.2}),
        {"integrator.output_interval": [0.1, 1e-7]},
        limits={"max_output_samples": 100},
    )
    assert [r["outcome"] for r in tight] == ["ok", "invalid"]
    assert "max_output_samples" in tight[1]["error"]


@pytest.mark.parametrize("name", ["v1.2", "x.run", ".hidden", "a/b", ""])
def test_names_that_cannot_name_outputs_are_refused(name):
    text = (ROOT / "scenes" / "pendulum.toml").read_text()
    with pytest.raises(pegdyn.SceneError):
        pegdyn.loads(text, name)


def test_part_files_are_named_after_the_scene_with_a_dot(tmp_path):
    scene = pegdyn.load(ROOT / "scenes" / "jamming.toml").with_values({"sweep.n": 3})
    r = scene.run(out=tmp_path)
    names = sorted(p.split("/")[-1] for p in r.paths)
    assert names == [
        "jamming.corners.csv",
        "jamming.sensitivities.csv",
        "jamming.svg",
        "jamming.sweep.csv",
        "jamming.sweep.svg",
        "jamming.wedging.csv",
    ]
    assert sorted(r.tables) == [
        "jamming.corners",
        "jamming.sensitivities",
        "jamming.sweep",
        "jamming.wedging",
    ]
