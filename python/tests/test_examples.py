"""The worked design example runs in its small form: the optimizer with
exact gradients lowers the peak contact force of the robot insertion
from the shipped design, and the grid search reports its best point."""

import re
import subprocess
import sys

import pytest

from conftest import ROOT

pytest.importorskip("scipy")

EXAMPLE = ROOT / "python" / "examples" / "design_rcc.py"
LINE = re.compile(
    r"^(?P<label>[^:]+): centre height (?P<h>[-\d.]+) mm, angular stiffness (?P<k>[\d.]+) N m/rad "
    r"-> peak contact force (?P<peak>[\d.]+) N, seat time (?P<seat>[\d.]+) s \((?P<runs>\d+) runs?"
)


def test_the_design_example_lowers_the_peak_contact_force():
    p = subprocess.run([sys.executable, str(EXAMPLE), "--small"], capture_output=True, text=True, timeout=900)
    assert p.returncode == 0, p.stderr
    found = {m["label"]: m for m in map(LINE.match, p.stdout.splitlines()) if m}
    assert set(found) == {"the shipped design", "SLSQP with exact gradients", "grid 2 x 2 (plain runs)"}, p.stdout
    start = found["the shipped design"]
    opt = found["SLSQP with exact gradients"]
    grid = found["grid 2 x 2 (plain runs)"]
    # The shipped design: compliance centre at the tip, 20 N m/rad.
    assert float(start["h"]) == 0.0 and float(start["k"]) == 20.0
    # Two SLSQP iterations along the exact gradient lower the peak
    # within the box (0-20 mm, 5-80 N m/rad), still seating in time.
    assert float(opt["peak"]) < float(start["peak"]), p.stdout
    assert 0.0 <= float(opt["h"]) <= 20.0 and 5.0 <= float(opt["k"]) <= 80.0
    assert float(opt["seat"]) <= 0.95
    # The grid's four plain runs: its best corner, evaluated the same way.
    assert int(grid["runs"]) == 4
    assert float(grid["h"]) in (0.0, 20.0) and float(grid["k"]) in (5.0, 80.0)
