//! The compliant wrist and the robot frame without contacts: linearized
//! frequencies, the energy balance with a moving robot, and the remote
//! centre compliance's decoupling of lateral force and tilt.

use nalgebra::{SVector, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::insertion::{Held, Insertion, N_STATE, depth_tilt, peg_state};
use pegdyn::compliant_peg_3d::robot::{Descent, RobotMotion, Spiral};
use pegdyn::compliant_peg_3d::wrist::WristParams;
use pegdyn::compliant_peg_3d::{HertzMode, Peg3dParams, pose_state};
use pegdyn::integrate::{Method, Options, OutputMode, Solver};

fn peg() -> Peg3dParams {
    let mut p = Peg3dParams::steel(0.02495, 0.05, 0.025, 3e-4, 5e-4, 0.04);
    p.hertz = HertzMode::Fixed(2e10);
    p
}

fn wrist(centre_height: f64) -> WristParams {
    WristParams {
        centre_height,
        lateral: [2e4, 3e4],
        axial: 1e5,
        angular: 20.0,
        torsional: 15.0,
        lateral_damping: 0.0,
        axial_damping: 0.0,
        angular_damping: 0.0,
    }
}

fn still(z: f64) -> RobotMotion {
    RobotMotion {
        start: Vector3::new(0.0, 0.0, z),
        tilt: 0.0,
        tilt_azimuth: 0.0,
        precession_rate: 0.0,
        spin_rate: 0.0,
        descent: Descent::Speed { speed: 0.0, end: z },
        spiral: None,
    }
}

fn solve(
    sys: &Insertion,
    y0: SVector<f64, N_STATE>,
    t_end: f64,
    dt: f64,
) -> (Vec<f64>, Vec<SVector<f64, N_STATE>>) {
    let mut o = Options::with_tolerances(1e-11, 1e-14);
    o.max_steps = 1_000_000;
    let n = (t_end / dt).floor() as usize;
    o.output = OutputMode::AtTimes((0..=n).map(|k| k as f64 * dt).collect());
    let t_end = n as f64 * dt;
    let sol = Solver::new(Method::Dopri5, o)
        .solve(sys, 0.0, y0, t_end)
        .unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    (sol.t, sol.x)
}

/// Mean period from the upward zero crossings of `s` (linear interpolation).
fn frequency(t: &[f64], s: &[f64]) -> f64 {
    let mut ups = Vec::new();
    for k in 1..s.len() {
        if s[k - 1] < 0.0 && s[k] >= 0.0 {
            ups.push(t[k - 1] + (t[k] - t[k - 1]) * (-s[k - 1]) / (s[k] - s[k - 1]));
        }
    }
    assert!(ups.len() >= 4, "{} crossings", ups.len());
    std::f64::consts::TAU * (ups.len() - 1) as f64 / (ups[ups.len() - 1] - ups[0])
}

#[test]
fn wrist_alone_oscillates_at_the_linearized_frequencies() {
    let mut prm = peg();
    prm.gravity = 0.0;
    let w = wrist(0.012);
    let sys = Insertion::new(
        prm,
        Some(Held {
            wrist: w,
            robot: still(0.1),
        }),
        0.0,
    );
    let y0 = sys.held_start().unwrap();
    let freq = w.linear_frequencies(
        prm.mass,
        prm.inertia_transverse,
        prm.inertia_axial,
        prm.length,
    );
    // Axial: 10 µm down.
    let mut y = y0;
    y[2] -= 1e-5;
    let w_ax = freq[0];
    let (t, x) = solve(&sys, y, 12.0 * std::f64::consts::TAU / w_ax, 0.02 / w_ax);
    let z0 = y0[2];
    let f = frequency(&t, &x.iter().map(|y| y[2] - z0).collect::<Vec<_>>());
    assert!((f / w_ax - 1.0).abs() < 2e-3, "axial {f} vs {w_ax}");
    // Lateral x (K_y about... the x translation couples with tilt about y):
    // start on each eigenvector of the coupled pair.
    let e = w.centre_height - 0.5 * prm.length;
    let k = w.lateral[0];
    for &om in &freq[2..4] {
        let theta = 1e-4;
        let xoff = -k * e * theta / (k - om * om * prm.mass);
        let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), theta);
        let p = Vector3::new(y0[0] + xoff, y0[1], y0[2]);
        let ys = pose_state(p, q, Vector3::zeros(), Vector3::zeros());
        let mut y = SVector::<f64, N_STATE>::zeros();
        y.fixed_rows_mut::<15>(0).copy_from(&ys);
        let (t, x) = solve(&sys, y, 12.0 * std::f64::consts::TAU / om, 0.02 / om);
        let tilt: Vec<f64> = x
            .iter()
            .map(|y| {
                let a = pegdyn::compliant_peg_3d::insertion::motion(&peg_state(y)).orientation
                    * Vector3::z();
                a.x
            })
            .collect();
        let f = frequency(&t, &tilt);
        assert!((f / om - 1.0).abs() < 2e-3, "lateral-tilt mode {f} vs {om}");
    }
}

#[test]
fn moving_robot_closes_the_energy_balance() {
    let prm = peg();
    let mut w = wrist(0.01);
    w.lateral_damping = 5.0;
    w.axial_damping = 20.0;
    w.angular_damping = 0.002;
    let robot = RobotMotion {
        start: Vector3::new(3e-4, -1e-4, 0.1),
        tilt: 0.02,
        tilt_azimuth: 0.3,
        precession_rate: 6.0,
        spin_rate: 4.0,
        descent: Descent::Speed {
            speed: 0.01,
            end: 0.09,
        },
        spiral: Some(Spiral {
            pitch: 1e-3,
            rate: 30.0,
        }),
    };
    let sys = Insertion::new(prm, Some(Held { wrist: w, robot }), 0.01);
    let y0 = sys.held_start().unwrap();
    let (t, x) = solve(&sys, y0, 0.2, 0.01);
    let e0 = sys.energy_balance(0.0, &y0).unwrap();
    let mut drift: f64 = 0.0;
    let (mut work, mut diss): (f64, f64) = (0.0, 0.0);
    for (ti, y) in t.iter().zip(&x) {
        drift = drift.max((sys.energy_balance(*ti, y).unwrap() - e0).abs());
        work = work.max(y[15].abs());
        diss = diss.max(y[14]);
    }
    assert!(
        work > 1e-3 && diss > 1e-6,
        "work {work}, dissipation {diss}"
    );
    assert!(drift < 1e-9, "drift {drift} J against work {work} J");
}

#[test]
fn compliance_centre_at_the_tip_absorbs_a_lateral_error_without_tilting() {
    // An aligned peg 10 mm deep in the bore, the robot frame 0.2 mm to the
    // side: the rim presses on the bore wall near the tip. With the
    // compliance centre at the tip the peg translates; with it at the top
    // it tilts.
    let mut prm = peg();
    prm.gravity = 0.0;
    let tilt_at = |lc: f64| {
        let mut w = wrist(lc);
        w.lateral_damping = 30.0;
        w.axial_damping = 100.0;
        w.angular_damping = 0.05;
        let z = -0.01 + lc;
        let mut robot = still(z);
        robot.start.x = 2e-4;
        let sys = Insertion::new(prm, Some(Held { wrist: w, robot }), 0.0);
        // Start aligned and centred (the wrist deflected by the error).
        let p = Vector3::new(0.0, 0.0, -0.01 + 0.5 * prm.length);
        let ys = pose_state(
            p,
            UnitQuaternion::identity(),
            Vector3::zeros(),
            Vector3::zeros(),
        );
        let mut y = SVector::<f64, N_STATE>::zeros();
        y.fixed_rows_mut::<15>(0).copy_from(&ys);
        let (_, x) = solve(&sys, y, 0.1, 0.01);
        let yl = x.last().unwrap();
        let s = sys.sample(0.1, yl).unwrap();
        assert!(s.total_normal() > 1.0, "no wall contact: {:?}", s.forces);
        depth_tilt(&prm, &peg_state(yl)).1
    };
    let at_tip = tilt_at(0.0);
    let at_top = tilt_at(prm.length);
    assert!(at_top > 1e-3, "top {at_top}");
    assert!(at_tip < 0.02 * at_top, "tip {at_tip} vs top {at_top}");
}
