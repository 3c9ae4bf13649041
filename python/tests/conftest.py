"""Shared fixtures: the repository root, the shipped scenes, the CLI binary."""

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCENES = sorted((ROOT / "scenes").glob("*.toml"))


def cli_path() -> Path:
    """The `pegdyn` binary from cargo's target directory (built if missing):
    $PEGDYN_CLI, else $CARGO_TARGET_DIR/debug/pegdyn, else target/debug/pegdyn."""
    if os.environ.get("PEGDYN_CLI"):
        return Path(os.environ["PEGDYN_CLI"])
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    exe = target / "debug" / "pegdyn"
    if not exe.exists():
        subprocess.run(["cargo", "build", "--locked", "--bin", "pegdyn"], cwd=ROOT, check=True)
    return exe


@pytest.fixture(scope="session")
def cli():
    return cli_path()
