"""Bad scenes raise SceneError naming the field, with `pegdyn check`'s message."""

import subprocess

import pytest

import pegdyn
from conftest import SCENES

PENDULUM = """kind = "pendulum"
[pendulum]
length = {length}
mass = 1.0
theta0_deg = 30.0
[integrator]
method = "dopri5"
t_end = 1.0
"""


def test_invalid_value_names_field_value_reason():
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.loads(PENDULUM.format(length="-1.0"))
    assert e.value.field == "pendulum.length"
    assert e.value.value == "-1.0"
    assert "positive" in e.value.reason
    assert isinstance(e.value, ValueError)


def test_wrong_type_and_unknown_field():
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.loads(PENDULUM.format(length='"long"'))
    assert e.value.field == "pendulum.length"
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.from_dict({"kind": "pendulum", "pendulum": {"lenght": 1.0}})
    fields = [f for f, _, _ in e.value.errors]
    assert "pendulum.lenght" in fields or "pendulum.length" in fields


def test_unknown_kind():
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.from_dict({"kind": "teapot"})
    assert e.value.field == "kind"
    assert "teapot" in str(e.value)


def test_message_is_the_cli_check_message(cli, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(PENDULUM.format(length="-1.0").replace("mass = 1.0", "mass = -2.0"))
    p = subprocess.run([str(cli), "check", str(bad)], capture_output=True, text=True)
    assert p.returncode == 1
    with pytest.raises(pegdyn.SceneError) as e:
        pegdyn.load(bad)
    assert str(e.value) == p.stderr.strip()
    assert [f for f, _, _ in e.value.errors] == ["pendulum.length", "pendulum.mass"]


def test_sweep_point_that_does_not_validate_is_a_row():
    s = pegdyn.load(next(p for p in SCENES if p.stem == "pendulum")).with_values({"integrator.t_end": 0.1})
    r = pegdyn.sweep(s, {"pendulum.mass": [1.0, -1.0]})
    assert [row["outcome"] for row in r] == ["ok", "invalid"]
    assert "pendulum.mass" in r[1]["error"]
