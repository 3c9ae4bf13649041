//! The held peg's exact Jacobian and time derivative (the contact law,
//! the wrist and the follower moment in dual numbers at the contacts the
//! right-hand side just found) against central differences of the
//! right-hand side, at contact states with a moving robot; the right-hand
//! side written once for any scalar is the nalgebra composition to the
//! last bit; RODAS4 with it follows DOPRI5.

use crate::common::peg3d::orientation;
use nalgebra::{Quaternion, SMatrix, SVector, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::insertion::{Held, Insertion, N_STATE, motion, peg_state};
use pegdyn::compliant_peg_3d::robot::{Descent, RobotMotion, Spiral};
use pegdyn::compliant_peg_3d::wrist::WristParams;
use pegdyn::compliant_peg_3d::{HertzMode, Pair, Peg3dParams, pose_state};
use pegdyn::generated::compliant_peg_3d as generated;
use pegdyn::integrate::{Method, Options, solve};
use pegdyn::system::OdeSystem;

fn peg() -> Peg3dParams {
    let mut p = Peg3dParams::steel(0.02495, 0.05, 0.025, 3e-4, 5e-4, 0.04);
    p.hertz = HertzMode::Fixed(1.5e10);
    p.friction = 0.3;
    p.slip_scale = 1e-3;
    p.damping = 0.5;
    p
}

/// A wrist with every stiffness and damper, the compliance centre 10 mm
/// above the tip, on a robot that descends, precesses, spins and searches
/// on a spiral, starting near the states of [`states`] (the wrist pushes
/// with about 10 N down and 5 N sideways).
fn held() -> Held {
    Held {
        wrist: WristParams {
            centre_height: 0.01,
            lateral: [2e4, 3e4],
            axial: 2e5,
            angular: 20.0,
            torsional: 15.0,
            lateral_damping: 40.0,
            axial_damping: 400.0,
            angular_damping: 0.04,
        },
        robot: RobotMotion {
            start: Vector3::new(2e-4, -1e-4, -0.02705),
            tilt: 0.01,
            tilt_azimuth: 0.4,
            precession_rate: 3.0,
            spin_rate: -2.0,
            descent: Descent::Speed {
                speed: 0.01,
                end: -0.05,
            },
            spiral: Some(Spiral {
                pitch: 2e-4,
                rate: 20.0,
            }),
        },
    }
}

fn with_work(ys: SVector<f64, 15>) -> SVector<f64, N_STATE> {
    let mut y = SVector::<f64, N_STATE>::zeros();
    y.fixed_rows_mut::<15>(0).copy_from(&ys);
    y[13] = 0.3;
    y[14] = 0.1;
    y[15] = -0.2;
    y
}

/// The peg centred 12 mm below the top face, its axis tilted by `gamma`
/// towards azimuth 0.3 rad, moving and spinning.
fn tilted(gamma: f64) -> SVector<f64, N_STATE> {
    with_work(pose_state(
        Vector3::new(0.0, 0.0, -0.012),
        orientation(gamma, 0.3, 0.3),
        Vector3::new(0.003, -0.002, -0.01),
        Vector3::new(0.5, -1.0, 4.0),
    ))
}

/// Contact states of the held peg: two-point contact in the bore (the
/// mouth edge on the side, the rim on the wall; the tilt bisected to the
/// largest penetration 1 µm) and the rim on the mouth's fillet (1 µm),
/// moving and spinning.
fn states(prm: &Peg3dParams) -> Vec<(&'static str, SVector<f64, N_STATE>)> {
    let free = Insertion::new(*prm, None, 0.0);
    let deepest = |y: &SVector<f64, N_STATE>| {
        free.contacts(y)
            .iter()
            .map(|c| c.penetration)
            .fold(0.0, f64::max)
    };
    let (mut lo, mut hi) = (0.0, 0.01);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if deepest(&tilted(mid)) > 1e-6 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let rr = prm.peg_radius() - prm.rim_fillet;
    let (rho_p, rho_h) = (prm.rim_fillet, prm.mouth_fillet);
    let dist = rho_p + rho_h - 1e-6;
    let centre = Vector3::new(
        prm.bore_radius() + rho_h - dist * 0.6_f64.sin(),
        0.0,
        -rho_h + dist * 0.6_f64.cos(),
    );
    let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -0.05);
    let on_mouth = centre - q * Vector3::new(rr, 0.0, rho_p - 0.5 * prm.length);
    vec![
        ("edge_side + rim_wall", tilted(hi)),
        (
            "rim_edge",
            with_work(pose_state(
                on_mouth,
                q,
                Vector3::new(0.003, -0.002, -0.01),
                Vector3::new(0.5, -1.0, 4.0),
            )),
        ),
    ]
}

/// Central differences of the right-hand side: steps 1e-8 in the pose,
/// 1e-7 in the velocities and the work integrals.
fn central(sys: &Insertion, t: f64, y: &SVector<f64, N_STATE>) -> SMatrix<f64, N_STATE, N_STATE> {
    let mut j = SMatrix::<f64, N_STATE, N_STATE>::zeros();
    for c in 0..N_STATE {
        let h = if c < 7 { 1e-8 } else { 1e-7 };
        let (mut a, mut b) = (*y, *y);
        a[c] += h;
        b[c] -= h;
        j.set_column(c, &((sys.rhs(t, &a) - sys.rhs(t, &b)) / (2.0 * h)));
    }
    j
}

#[test]
fn the_held_peg_s_exact_jacobian_matches_central_differences() {
    let prm = peg();
    for (aligning, label) in [(0.0, "held"), (0.05, "held, follower moment")] {
        let sys = Insertion::new(prm, Some(held()), aligning);
        for (what, y) in states(&prm) {
            let t = 0.37;
            let pairs: Vec<Pair> = sys.contacts(&y).iter().map(|c| c.pair).collect();
            assert!(!pairs.is_empty(), "{what}: no contact");
            let _ = sys.rhs(t, &y);
            let exact = sys.jacobian(t, &y);
            let fd = central(&sys, t, &y);
            let big = (0..N_STATE)
                .map(|c| exact.column(c).norm())
                .fold(0.0, f64::max);
            for c in 0..N_STATE {
                let (e, f) = (exact.column(c), fd.column(c));
                let err = (e - f).norm() / (e.norm() + 1e-2 * big);
                assert!(
                    err < 1e-5,
                    "{label}, {what} {pairs:?}: column {c}: {err:.2e}\n{e}\n{f}"
                );
            }
            // The robot's work: its row is the power's derivative.
            let row_err = (exact.row(15) - fd.row(15)).norm() / fd.row(15).norm();
            assert!(
                row_err < 1e-5,
                "{label}, {what}: robot work row {row_err:.2e}"
            );
            // The work integrals are read by nothing.
            for c in 13..N_STATE {
                assert!(exact.column(c).iter().all(|&v| v == 0.0), "column {c}");
            }
        }
    }
}

#[test]
fn the_held_peg_s_time_derivative_matches_central_differences() {
    let prm = peg();
    let sys = Insertion::new(prm, Some(held()), 0.05);
    for (what, y) in states(&prm) {
        for t in [0.0, 0.37, 1.2] {
            let dt = 1e-5;
            let fd = (sys.rhs(t + dt, &y) - sys.rhs(t - dt, &y)) / (2.0 * dt);
            let exact = sys.time_derivative(t, &y);
            let err = (exact - fd).norm() / fd.norm();
            assert!(err < 1e-6, "{what} at t = {t}: {err:.2e}\n{exact}\n{fd}");
        }
    }
    // A free peg is autonomous.
    let free = Insertion::new(prm, None, 0.05);
    assert_eq!(
        free.time_derivative(0.3, &states(&prm)[0].1),
        SVector::<f64, N_STATE>::zeros()
    );
}

/// The follower moment in nalgebra's types, as the right-hand side
/// wrote it before the held wrench was made generic.
fn follower(m0: f64, a: &Vector3<f64>) -> Vector3<f64> {
    if m0 == 0.0 {
        return Vector3::zeros();
    }
    let c = Vector3::z().cross(a);
    c * (-m0 / (c.norm_squared() + 1e-6).sqrt())
}

#[test]
fn the_held_right_hand_side_is_the_nalgebra_composition_to_the_last_bit() {
    let prm = peg();
    let mut s = 0x9e37_79b9_7f4a_7c15_u64;
    let mut r = move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    };
    for aligning in [0.0, 0.05] {
        for k in 0..400 {
            let t = 0.5 * (1.0 + r());
            let mut y = states(&prm)[k % 2].1;
            for i in 0..7 {
                y[i] += 1e-6 * r();
            }
            for i in 7..N_STATE {
                y[i] += 0.1 * r();
            }
            let ys = peg_state(&y);
            // Each side searches cold, so that both find the same contacts
            // to the last bit.
            let sys = Insertion::new(prm, Some(held()), aligning);
            let rate = sys.rhs(t, &y);
            let sys = Insertion::new(prm, Some(held()), aligning);
            let mut w = sys.peg.contact_wrench(&ys).unwrap();
            let mut power = 0.0;
            if let Some((_, load)) = sys.wrist_load(t, &ys) {
                for k in 0..3 {
                    w[k] += load.force[k];
                    w[3 + k] += load.moment[k];
                }
                w[6] += load.dissipation_rate;
                power += load.robot_power;
            }
            let m = motion(&ys);
            let fm = follower(aligning, &(m.orientation * Vector3::z()));
            for k in 0..3 {
                w[3 + k] += fm[k];
            }
            power += fm.dot(&m.angular_velocity);
            let d = generated::rhs(&ys, &w, sys.peg.param_vector());
            for i in 0..15 {
                assert_eq!(rate[i].to_bits(), d[i].to_bits(), "{k}: component {i}");
            }
            assert_eq!(rate[15].to_bits(), power.to_bits(), "{k}: power");
            // The wrist reads the quaternion normalized once, as nalgebra does.
            let q = UnitQuaternion::from_quaternion(Quaternion::new(y[3], y[4], y[5], y[6]));
            assert_eq!(m.orientation.coords, q.coords);
        }
    }
}

#[test]
fn rodas4_with_the_exact_jacobian_inserts_like_dopri5() {
    // The held peg in two-point contact, pushed down and sideways by the
    // robot for 2 ms (it bounces between the mouth and the wall): RODAS4
    // (exact Jacobian, the velocity-block solve) and DOPRI5 end within
    // their tolerance of each other.
    let prm = peg();
    let sys = Insertion::new(prm, Some(held()), 0.0);
    let y0 = states(&prm)[0].1;
    // Each bounce amplifies the integration error (at rtol 1e-8 to 1e-10 the
    // two methods end 1e-7 to 5e-7 apart, not monotonically), so both run
    // tight enough that their difference is the methods', not the bounces'.
    let opts = Options::with_tolerances(1e-11, 1e-15);
    let end = 2e-3;
    let r4 = solve(&sys, Method::Rodas4, (0.0, y0), end, &opts).unwrap();
    let dp = solve(&sys, Method::Dopri5, (0.0, y0), end, &opts).unwrap();
    assert!(r4.stop.is_success() && dp.stop.is_success());
    let (a, b) = (
        r4.x_final.fixed_rows::<13>(0),
        dp.x_final.fixed_rows::<13>(0),
    );
    eprintln!(
        "RODAS4 {} steps, DOPRI5 {} steps, end-state difference {:.2e}",
        r4.stats.steps,
        dp.stats.steps,
        (a - b).amax()
    );
    assert!((a - b).amax() < 1e-8, "{a} vs {b}");
    let touching = r4.x.iter().filter(|y| !sys.contacts(y).is_empty()).count();
    assert!(
        touching > r4.x.len() / 2,
        "{touching} of {} in contact",
        r4.x.len()
    );
}
