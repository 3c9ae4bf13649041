"""A run into a directory from Python keeps the run manifest as `pegdyn run`
does: only its own files, never replacing a user's file of that name."""

import pytest

import pegdyn
from conftest import ROOT

tomllib = pytest.importorskip("tomllib")


def _pendulum():
    return pegdyn.load(ROOT / "scenes" / "pendulum.toml").with_values({"integrator.t_end": 0.2})


def test_a_run_into_a_directory_records_its_files(tmp_path):
    r = _pendulum().run(out=tmp_path)
    m = tomllib.loads((tmp_path / "pendulum.run.toml").read_text())
    assert m["status"] == "ok" and m["pegdyn_manifest"] == 1
    assert m["files"] == sorted(p.split("/")[-1] for p in r.paths)
    assert m["stale"] == []


@pytest.mark.parametrize("user", ["my notes\n", "[tool]\nx = 1\n", ""])
def test_a_users_file_with_the_manifests_name_is_kept(tmp_path, user):
    (tmp_path / "pendulum.run.toml").write_text(user)
    with pytest.raises(pegdyn.RunError, match="not a pegdyn run manifest"):
        _pendulum().run(out=tmp_path)
    assert (tmp_path / "pendulum.run.toml").read_text() == user
    assert not (tmp_path / "pendulum.csv").exists()
