//! The compliant 3-D peg contains the compliant planar peg as a limit:
//! confined to the symmetry plane (symmetric start, no out-of-plane load,
//! no rotation out of the plane) it follows the planar model's trajectory.
//!
//! The two models are made equal by parameters where they differ in a
//! modelling choice: one fixed Hertz stiffness for every contact (the
//! planar model's edge stiffness for both its contacts and for the 3-D
//! model's `HertzMode::Fixed`), no gravity (the planar model has none), and
//! the planar model's loads, which are fixed in the peg's frame, applied to
//! the 3-D peg as a follower wrench through the generated right-hand side's
//! wrench input. The remaining difference is where friction acts: at the
//! peg's undeformed surface in the planar model, midway between the two
//! surfaces (half the penetration further along the normal) in the 3-D
//! model; it vanishes without friction.

use crate::common::peg3d;

use nalgebra::{SVector, UnitQuaternion, Vector3};
use peg3d::{Follower, pair_forces};
use pegdyn::compliant_peg::{CompliantParams, CompliantSpec, Load, PegState};
use pegdyn::compliant_peg_3d::{HertzMode, Peg3d, Peg3dParams, pose_state};
use pegdyn::generated::compliant_peg as planar;
use pegdyn::integrate::{Method, Options, OutputMode, solve};
use pegdyn::system::OdeSystem;

/// The planar model with a parameter vector of our own (equal stiffnesses).
struct Planar {
    p: SVector<f64, 24>,
}

impl OdeSystem<8> for Planar {
    fn rhs(&self, _t: f64, y: &SVector<f64, 8>) -> SVector<f64, 8> {
        planar::rhs(y, &self.p)
    }
    fn time_derivative(&self, _t: f64, _y: &SVector<f64, 8>) -> SVector<f64, 8> {
        SVector::zeros()
    }
}

/// The planar state `(x, z, θ, ẋ, ż, θ̇)` (z into the hole, axis towards
/// the bottom `(sin θ, cos θ)`) as a 3-D state: `p = (x, 0, −z)`, the tilt a
/// rotation by `−θ` about `e_y`, `v = (ẋ, 0, −ż)`, `ω = −θ̇ e_y`.
fn to_3d(y: &SVector<f64, 8>) -> SVector<f64, 15> {
    pose_state(
        Vector3::new(y[0], 0.0, -y[1]),
        UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -y[2]),
        Vector3::new(y[3], 0.0, -y[4]),
        Vector3::new(0.0, -y[5], 0.0),
    )
}

/// Depth of the bottom face's centre, tilt, and the 3-D model's summed
/// normal force per pair `(edge–side, rim–wall)`.
fn sample_3d(peg: &Peg3d, y: &SVector<f64, 15>) -> [f64; 4] {
    let x = Peg3d::pose(y);
    let axis = pegdyn::compliant_peg_3d::axis_of(&x);
    let depth = -(y[2] - 0.5 * peg.params.length * axis.z);
    let theta = (-axis.x).atan2(axis.z);
    let (edge, wall) = pair_forces(peg, y);
    [depth, theta, edge, wall]
}

/// The largest out-of-plane component of a 3-D state: `p_y`, `v_y`,
/// `ω_x`, `ω_z` and the quaternion's `i`, `k`.
fn out_of_plane(y: &SVector<f64, 15>) -> f64 {
    [y[1], y[8], y[10], y[12], y[4], y[6]]
        .iter()
        .fold(0.0_f64, |m, v| m.max(v.abs()))
}

/// Worst differences over the output times: depth of the bottom face (m),
/// tilt (rad), edge and wall normal forces (relative to the largest), the
/// largest out-of-plane component of the 3-D state.
#[derive(Clone, Copy, Debug, Default)]
struct Diff {
    depth: f64,
    tilt: f64,
    force: f64,
    out_of_plane: f64,
}

/// Depth, tilt, edge force, wall force of a planar state.
fn sample_planar(y: &SVector<f64, 8>, p: &SVector<f64, 24>, com_height: f64) -> [f64; 4] {
    let f = planar::contacts(y, p).normal;
    // Only the lean's two contacts (left edge, right wall) ever act.
    assert!(f[2] == 0.0 && f[3] == 0.0);
    [y[1] + com_height * y[2].cos(), y[2], f[0], f[1]]
}

fn worst(a: &[[f64; 4]], b: &[[f64; 4]]) -> Diff {
    let peak = a.iter().fold(0.0_f64, |m, s| m.max(s[2]).max(s[3]));
    let mut d = Diff::default();
    for (x, y) in a.iter().zip(b) {
        d.depth = d.depth.max((x[0] - y[0]).abs());
        d.tilt = d.tilt.max((x[1] - y[1]).abs());
        d.force = d
            .force
            .max((x[2] - y[2]).abs() / peak)
            .max((x[3] - y[3]).abs() / peak);
    }
    d
}

/// What the planar-limit comparison measured: the 3-D run against the
/// planar run at the same tolerance and at a hundredth of it, each model's
/// own integration error (its run against itself at the tighter
/// tolerance), the peak force, the final depth and the 3-D steps.
struct Limit {
    coarse: Diff,
    fine: Diff,
    planar_error: Diff,
    three_d_error: Diff,
    peak: f64,
    depth: f64,
    steps: usize,
}

/// The planar limit of `scenes/insert_compliant.toml` over `[0, t_end]`:
/// the 3-D model against the planar model, both Dormand–Prince 5(4) at
/// `rtol` and at `rtol/100`.
fn compare_with_planar(friction: f64, t_end: f64, rtol: f64) -> Limit {
    // scenes/insert_compliant.toml: D = 50 mm, c = 0.002, L = 0.1 m,
    // 0.2 mm fillets, v_s = 1e-5 m/s, f1 = 5 N, M = −0.002 N·m, two-point
    // start at θ = 0.01 rad, Dormand–Prince 5(4).
    let spec = CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, friction);
    let params = CompliantParams::try_new(spec).unwrap();
    let load = Load {
        axial: 5.0,
        radial: 0.0,
        torque: -0.002,
    };
    let mut pv = params.vector(&load);
    let k = params.pair.edge.stiffness();
    let idx = |n: &str| planar::P_NAMES.iter().position(|&m| m == n).unwrap();
    pv[idx("k_wall")] = k;
    let planar_sys = Planar { p: pv };
    let y0 = PegState::two_point(&params, 0.01, 0.0).unwrap().to_vector();

    let g = &spec.geometry;
    let mut prm = Peg3dParams::steel(
        2.0 * g.peg_radius,
        0.1,
        g.hole_diameter,
        g.peg_fillet,
        g.hole_fillet,
        0.1,
    );
    prm.gravity = 0.0;
    prm.friction = friction;
    prm.slip_scale = spec.slip_velocity;
    prm.hertz = HertzMode::Fixed(k);
    assert!((prm.mass - spec.mass).abs() < 1e-15);
    assert!((prm.inertia_transverse - spec.inertia).abs() < 1e-18);
    let sys3 = Follower {
        peg: Peg3d::new(prm),
        load,
    };

    let n = 100;
    let times: Vec<f64> = (0..=n).map(|i| t_end * i as f64 / n as f64).collect();
    let run_planar = |rtol: f64| {
        let mut opts = Options::with_tolerances(rtol, 1e-16);
        opts.output = OutputMode::AtTimes(times.clone());
        let sol = solve(&planar_sys, Method::Dopri5, (0.0, y0), t_end, &opts).unwrap();
        assert!(sol.stop.is_success());
        sol.x
            .iter()
            .map(|y| sample_planar(y, &pv, spec.com_height))
            .collect::<Vec<_>>()
    };
    let (coarse, fine) = (run_planar(rtol), run_planar(rtol * 1e-2));
    let run_3d = |rtol: f64| {
        let mut opts = Options::with_tolerances(rtol, 1e-16);
        opts.output = OutputMode::AtTimes(times.clone());
        let sol = solve(&sys3, Method::Dopri5, (0.0, to_3d(&y0)), t_end, &opts).unwrap();
        assert!(sol.stop.is_success());
        let out_of_plane = sol.x.iter().map(out_of_plane).fold(0.0, f64::max);
        let samples: Vec<[f64; 4]> = sol.x.iter().map(|y| sample_3d(&sys3.peg, y)).collect();
        (samples, out_of_plane, sol.stats.steps)
    };
    let (three, out, steps) = run_3d(rtol);
    let (three_fine, out_fine, _) = run_3d(rtol * 1e-2);
    let mut d = worst(&three, &coarse);
    d.out_of_plane = out.max(out_fine);
    Limit {
        coarse: d,
        fine: worst(&three_fine, &fine),
        planar_error: worst(&coarse, &fine),
        three_d_error: worst(&three, &three_fine),
        peak: coarse.iter().fold(0.0_f64, |m, s| m.max(s[2]).max(s[3])),
        depth: coarse.last().unwrap()[0],
        steps,
    }
}

fn check_planar_limit(friction: f64) {
    let l = compare_with_planar(friction, 0.1, 1e-9);
    let (d, own) = (l.fine, l.planar_error);
    eprintln!(
        "planar limit, mu = {friction}: 3-D vs planar at rtol 1e-11: depth {:.2e} m, tilt {:.2e} rad, forces {:.2e} (of {:.3} N), out of plane {:.1e}; planar's own error at rtol 1e-9: depth {:.2e} m, tilt {:.2e} rad, forces {:.2e}; at rtol 1e-9 3-D vs planar: depth {:.2e} m, tilt {:.2e} rad, forces {:.2e}, the 3-D model's own error: depth {:.2e} m, tilt {:.2e} rad, forces {:.2e}; {} steps, final depth {:.5} m",
        d.depth,
        d.tilt,
        d.force,
        l.peak,
        l.coarse.out_of_plane,
        own.depth,
        own.tilt,
        own.force,
        l.coarse.depth,
        l.coarse.tilt,
        l.coarse.force,
        l.three_d_error.depth,
        l.three_d_error.tilt,
        l.three_d_error.force,
        l.steps,
        l.depth
    );
    assert!(l.depth > 0.025, "the peg went only to {} m", l.depth);
    assert!(
        l.coarse.out_of_plane < 1e-14,
        "out of plane {}",
        l.coarse.out_of_plane
    );
    // Within twice the planar model's own integration error (the runs at
    // the tighter tolerance, whose own errors are a hundred times smaller:
    // at the same tolerance the two runs' errors add up, and how much they
    // cancel depends on their step sequences).
    assert!(d.depth < 2.0 * own.depth, "depth {d:?} vs {own:?}");
    assert!(d.tilt < 2.0 * own.tilt, "tilt {d:?} vs {own:?}");
    assert!(d.force < 2.0 * own.force, "force {d:?} vs {own:?}");
}

#[test]
fn planar_limit_frictionless_follows_the_planar_peg_within_its_integration_error() {
    check_planar_limit(0.0);
}

#[test]
fn planar_limit_with_friction_follows_the_planar_peg_within_its_integration_error() {
    check_planar_limit(0.1);
}
