"""What a newcomer meets following the README: the exception classes show
as `pegdyn.SceneError` / `pegdyn.RunError` and pickle (a Dask worker hands
them back), the README's SceneError example shows the error it means to
show, its Dask block runs as a script, and `with_values` works on every
scene `loads` accepts."""

import pickle
import re
import subprocess
import sys
from pathlib import Path

import pytest

import pegdyn
from conftest import ROOT, SCENES

README = (ROOT / "README.md").read_text(encoding="utf-8")


def python_blocks():
    return re.findall(r"```python\n(.*?)```", README, flags=re.S)


@pytest.mark.parametrize("cls", [pegdyn.SceneError, pegdyn.RunError])
def test_the_exception_classes_are_named_as_imported(cls):
    assert cls.__module__ == "pegdyn"
    assert f"{cls.__module__}.{cls.__qualname__}" == f"pegdyn.{cls.__name__}"
    assert getattr(pegdyn, cls.__name__) is cls
    assert repr(cls) == f"<class 'pegdyn.{cls.__name__}'>"


def test_a_scene_error_pickles_with_its_fields():
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.loads('kind = "pendulum"\n[pendulum]\nlength = -1.0\nmass = 1.0\ntheta0_deg = 3.0\n'
                     '[integrator]\nt_end = 1.0\n')
    back = pickle.loads(pickle.dumps(e.value))
    assert type(back) is pegdyn.SceneError
    assert (back.field, back.value, str(back)) == (e.value.field, e.value.value, str(e.value))
    assert back.errors == e.value.errors


def test_the_readme_scene_error_example_shows_the_negative_length(capsys):
    block = next(b for b in python_blocks() if "except pegdyn.SceneError" in b)
    lines = block.splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("try:"))
    end = next(i for i, l in enumerate(lines) if "print(e.field" in l)
    exec("\n".join(lines[start : end + 1]), {"pegdyn": pegdyn})
    out = capsys.readouterr().out
    assert out.startswith("pendulum.length -1.0 "), out
    # What the README says it prints is what it prints.
    assert out.strip() == lines[end].split("#", 1)[1].strip()


def test_the_readme_dask_block_runs_as_a_script(tmp_path):
    block = next(b for b in python_blocks() if "LocalCluster" in b)
    guard = block.index('if __name__ == "__main__":')
    assert guard < block.index("Client(LocalCluster())")
    # The same script with a small cluster and fewer points (the guard is
    # what is tested: the worker processes import the script).
    script = (
        block.replace("Client(LocalCluster())", "Client(LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None))")
        .replace("10_000", "24")
        .replace("print(rows.to_pandas().describe())", "print(len(rows), rows['outcome'].count('ok'))")
    )
    path = tmp_path / "readme_dask.py"
    path.write_text(script)
    done = subprocess.run([sys.executable, str(path)], capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]
    assert done.stdout.split()[-2:] == ["24", "24"], done.stdout
    assert "bootstrapping phase" not in done.stderr


TEXTS = {
    "byte order mark": "\ufeff" + (ROOT / "scenes" / "pendulum.toml").read_text(),
    "CRLF lines": (ROOT / "scenes" / "pendulum.toml").read_text().replace("\n", "\r\n"),
    "dotted keys": 'kind = "pendulum"\npendulum.length = 1.0\npendulum.mass = 1.0\npendulum.theta0_deg = 30.0\n'
    "integrator.t_end = 0.5\n",
    "inline tables": 'kind = "pendulum"\npendulum = { length = 1.0, mass = 1.0, theta0_deg = 30.0 }\n'
    "integrator = { t_end = 0.5 }\n",
    "the largest limit": (ROOT / "scenes" / "pendulum.toml").read_text() + "\n[limits]\nmax_steps = 9223372036854775807\n",
}


@pytest.mark.parametrize("what", sorted(TEXTS))
def test_with_values_takes_every_scene_loads_takes(what):
    scene = pegdyn.loads(TEXTS[what], "p")
    changed = scene.with_values({"pendulum.mass": 2.0})
    assert changed.kind == "pendulum" and "mass = 2.0" in changed.text
    rows = pegdyn.sweep(scene, {"pendulum.mass": [2.0]})
    assert rows["outcome"] == ["ok"], rows[0]["error"]


@pytest.mark.parametrize("big", ["10000000000000000000", "18446744073709551615", "-9223372036854775809"])
def test_an_integer_past_64_bits_is_refused_by_loads_naming_it(big):
    # Every TOML reader refuses it (TOML integers are 64-bit signed); loads
    # said OK once, and with_values then failed as "not TOML".
    text = (ROOT / "scenes" / "pendulum.toml").read_text() + f"\n[limits]\nmax_steps = {big}\n"
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.loads(text)
    assert (e.value.field, e.value.value) == ("limits.max_steps", big)
    assert "9223372036854775807" in e.value.reason


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_with_values_of_every_shipped_scene(path):
    scene = pegdyn.load(path)
    assert scene.with_values({}).text  # the text survives a round trip
    assert pegdyn.Scene(scene.with_values({}).text, scene.name).kind == scene.kind
