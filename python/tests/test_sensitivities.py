"""``Result.sensitivities``: the derivatives of a ``[sensitivities]`` table
as numpy arrays, the numbers of ``<name>.sensitivities.csv``; a derivative
agrees with differences of two runs."""

import numpy as np

import pegdyn
from conftest import ROOT

SCENE = ROOT / "scenes" / "insert_compliant_sensitivities.toml"
PLAIN = ROOT / "scenes" / "insert_compliant.toml"


def _table(result):
    """``result.sensitivities``, checked to be a table of equal-length
    numpy arrays with float64 numbers and the rows of the run's own
    ``.sensitivities`` table."""
    s = result.sensitivities
    assert s is not None
    n = len(s["metric"])
    assert n > 0 and all(len(v) == n for v in s.values())
    for k in ("value", "derivative", "elasticity"):
        assert s[k].dtype == np.float64
    table = next(t for k, t in result.tables.items() if k.endswith(".sensitivities"))
    assert list(s["metric"]) == list(table["metric"])
    return s


def test_the_table_comes_as_numpy_arrays():
    s = _table(pegdyn.load(SCENE).run())
    # The field the model does not use: a zero, flagged.
    unused = s["parameter"] == "insert_compliant.tangential_damping"
    assert unused.any()
    assert np.all(s["flag"][unused] == "not used by this model")
    assert np.all(s["derivative"][unused] == 0.0)
    # Unflagged rows: elasticity = q/m dm/dq, here for the friction (q = 0.1).
    mu = (s["parameter"] == "insert_compliant.friction") & (s["flag"] == "")
    assert mu.any()
    np.testing.assert_allclose(
        s["elasticity"][mu], 0.1 / s["value"][mu] * s["derivative"][mu], rtol=1e-12
    )


def test_the_seat_time_derivative_agrees_with_differences_of_two_runs():
    scene = pegdyn.load(SCENE)
    s = scene.run().sensitivities
    row = (s["metric"] == "seat_time_s") & (s["parameter"] == "insert_compliant.axial_force")
    d = s["derivative"][row][0]

    def seat(f1):
        t = scene.with_values({"insert_compliant.axial_force": f1}).run().sensitivities
        return t["value"][t["metric"] == "seat_time_s"][0]

    h = 0.005
    fd = (seat(5.0 + h) - seat(5.0 - h)) / (2 * h)
    assert abs(d - fd) < 1e-4 * abs(fd), (d, fd)


def test_a_scene_without_the_table_has_none():
    scene = pegdyn.load(PLAIN)
    assert scene.with_values({"integrator.t_end": 0.01}).run().sensitivities is None


def test_a_sweep_carries_each_points_derivatives():
    # Two fields named, three points along the axial force: each row holds
    # the derivatives of its own point (the run's table, as Result gives
    # them), and the seat time's derivative at the middle point agrees with
    # the sweep's own differences of the seat time.
    text = SCENE.read_text()
    start = text.index("parameters = [")
    end = text.index("]", start) + 1
    text = (
        text[:start]
        + 'parameters = ["insert_compliant.axial_force", "insert_compliant.tangential_damping"]'
        + text[end:]
    )
    scene = pegdyn.loads(text, name="sweep_sens")
    h = 0.005
    forces = [5.0 - h, 5.0, 5.0 + h]
    rows = pegdyn.sweep(scene, grid={"insert_compliant.axial_force": forces}, threads=2)
    assert all("inserted" in r["stop"] for r in rows)
    assert [r["outcome"] for r in rows] == ["ok"] * 3
    key = "d(seat_time_s)/d(insert_compliant.axial_force)"
    single = scene.with_values({"insert_compliant.axial_force": 5.0}).run().sensitivities
    pick = (single["metric"] == "seat_time_s") & (
        single["parameter"] == "insert_compliant.axial_force"
    )
    assert rows[1][key] == single["derivative"][pick][0]
    # The runs stop at the seat: t_end is the seat time.
    seat = rows["t_end"]
    fd = (seat[2] - seat[0]) / (2 * h)
    assert abs(rows[1][key] - fd) < 1e-4 * abs(fd), (rows[1][key], fd)
    # Elasticity = q/m dm/dq at each point (m from the sensitivity pass,
    # t_end from the scene's own run: equal to the scene's rtol, 1e-8).
    for f, r, t in zip(forces, rows, seat):
        e = r["elasticity(seat_time_s, insert_compliant.axial_force)"]
        assert abs(e - f / t * r[key]) < 1e-7 * abs(e), (e, f / t * r[key])
    # The ranking note comes as its text, not NaN.
    assert rows[1]["elasticities of seat_time_s"].startswith("axial_force -0.49")
    # The unused field: a zero derivative and its flag.
    assert rows[0]["d(seat_time_s)/d(insert_compliant.tangential_damping)"] == 0.0
    assert (
        rows[0]["flag(seat_time_s, insert_compliant.tangential_damping)"]
        == "not used by this model"
    )


def test_design_margins_gives_the_capture_widths_derivatives_as_numpy_arrays():
    # The capture widths' derivatives need no run: a one-point grid and a
    # short nominal run keep the scene cheap.
    scene = pegdyn.load(ROOT / "scenes" / "design_margins.toml").with_values(
        {
            "grid.centre_lateral_errors": [0.0],
            "grid.angular_errors_deg": [0.0],
            "integrator.t_end": 0.02,
        }
    )
    s = scene.run().sensitivities
    assert s is not None
    assert set(s["metric"]) == {
        "capture_width_m",
        "frictionless_capture_width_m",
        "aligned_tip_error_m",
    }
    row = (s["metric"] == "capture_width_m") & (s["parameter"] == "peg.hole_diameter")
    # W_mu = D/2 + rho_h - (rho_h + rho_p) mu/sqrt(1 + mu^2)
    assert s["derivative"][row][0] == 0.5
    mu = (s["metric"] == "capture_width_m") & (s["parameter"] == "peg.friction")
    np.testing.assert_allclose(s["derivative"][mu][0], -(8e-4) / 1.04**1.5, rtol=1e-12)
    unused = s["parameter"] == "wrist.centre_height"
    assert np.all(s["flag"][unused] == "not used by this model")
    assert np.all(s["derivative"][unused] == 0.0)


RCC = ROOT / "scenes" / "insert_rcc_sensitivities.toml"


def _short_rcc():
    """The shipped robot insertion's sensitivity scene, started 1 mm in the
    bore and seated at 2 mm (a short run for the tests)."""
    return pegdyn.load(RCC).with_values(
        {
            "robot.start_height": -1e-3,
            "criteria.seat_depth": 0.002,
            "integrator.t_end": 0.3,
            "integrator.rtol": 1e-8,
        }
    )


def test_the_robot_insertion_gives_its_metrics_derivatives_as_numpy_arrays():
    s = _table(_short_rcc().run())
    # Every field the scene names, for the seat time.
    seat = s["metric"] == "seat_time_s"
    named = set(s["parameter"][seat])
    assert {"wrist.lateral_stiffness", "robot.speed", "peg.friction"} <= named
    # Unflagged rows carry finite numbers, elasticity = q/m dm/dq.
    ok = s["flag"] == ""
    assert ok.any()
    assert np.all(np.isfinite(s["derivative"][ok]))
    # Along the robot's speed v: the seat time of a peg already in the bore
    # is dominated by the descent, t = (distance)/v, so its elasticity is
    # near -1.
    speed = seat & (s["parameter"] == "robot.speed") & ok
    assert speed.any()
    el = s["elasticity"][speed][0]
    np.testing.assert_allclose(
        el, 0.01 / s["value"][speed][0] * s["derivative"][speed][0], rtol=1e-12
    )
    assert -1.1 < el < -0.9, el


def test_the_robot_insertion_seat_time_derivative_agrees_with_two_runs():
    scene = _short_rcc()
    s = scene.run().sensitivities
    row = (s["metric"] == "seat_time_s") & (s["parameter"] == "peg.friction")
    assert s["flag"][row][0] == ""
    d = s["derivative"][row][0]

    def seat(mu):
        t = scene.with_values({"peg.friction": mu}).run().sensitivities
        return t["value"][t["metric"] == "seat_time_s"][0]

    h = 2e-4
    fd = (seat(0.2 + h) - seat(0.2 - h)) / (2 * h)
    assert abs(d - fd) < 1e-4 * abs(fd), (d, fd)


def test_a_rotation_grid_gives_each_points_derivatives_with_its_coordinates():
    # The shipped rotation_assist grid cut to two points, started in the
    # bore (a short run): the rows carry their grid point, and each point
    # has every metric along every field named.
    lines = []
    for line in (ROOT / "scenes" / "rotation_assist.toml").read_text().splitlines():
        for key, value in (
            ("angular_errors_deg", "[1.0]"),
            ("precession_rates", "[10.0]"),
            ("spin_rates", "[20.0]"),
        ):
            if line.startswith(key + " "):
                line = f"{key} = {value}"
        lines.append(line)
    text = "\n".join(lines) + '\n[sensitivities]\nparameters = ["robot.spin_rate", "peg.friction"]\n'
    grid = pegdyn.loads(text, "grid").with_values(
        {
            "robot.start_height": -1e-3,
            "criteria.seat_depth": 0.002,
            "integrator.t_end": 0.3,
        }
    )
    s = _table(grid.run())
    assert s["lateral_error_m"].dtype == np.float64
    points = sorted(set(zip(s["lateral_error_m"].tolist(), s["spin_rate"].tolist())))
    assert points == [(1e-4, 20.0), (3e-4, 20.0)]
    for lateral, _ in points:
        at = s["lateral_error_m"] == lateral
        seat = at & (s["metric"] == "seat_time_s")
        assert set(s["parameter"][seat]) == {"robot.spin_rate", "peg.friction"}
        assert np.all(np.isfinite(s["derivative"][seat]))
