//! Cost of the curvature stiffness's term `−(2/5) δ^{5/2} ∂k/∂(pose)` of
//! the compliant 3-D peg: the right-hand side with the stiffness from the
//! curvatures, the Hertz setup of its contacts alone and with the term
//! (`stiffness::gradient`), and the right-hand side with a fixed
//! stiffness, at a rim on the top
//! face, a rim on the mouth fillet and a peg clear of every surface. Run
//! with `cargo run --release -p pegdyn-benches --bin curvature_stiffness_cost` and state
//! the machine's load beside the figures.

use nalgebra::{SVector, Unit, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::ContactForce;
use pegdyn::compliant_peg_3d::{HertzMode, Peg3d, Peg3dParams, pose_state, stiffness};
use pegdyn::system::OdeSystem;
use std::hint::black_box;
use std::time::Instant;

fn per_call(n: usize, mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    for _ in 0..n {
        f();
    }
    start.elapsed().as_secs_f64() / n as f64 * 1e6
}

fn main() {
    let prm = Peg3dParams::steel(0.04995, 0.070, 0.050, 1e-3, 1e-3, 0.1);
    let rr = prm.peg_radius() - prm.rim_fillet;
    let h = prm.rim_fillet - 0.5 * prm.length;
    // Rim on the top face, tilt 0.05 rad, 5 µm deep.
    let tilt = Unit::new_normalize(Vector3::new(-0.7f64.sin(), 0.7f64.cos(), 0.0));
    let q = UnitQuaternion::from_axis_angle(&tilt, 0.05);
    let a = q * Vector3::z();
    let (ex, ey) = (q * Vector3::x(), q * Vector3::y());
    let lowest = h * a.z - rr * ex.z.hypot(ey.z);
    let top = pose_state(
        Vector3::new(0.08, -0.01, prm.rim_fillet - 5e-6 - lowest),
        q,
        Vector3::zeros(),
        Vector3::zeros(),
    );
    // Rim on the mouth fillet, tilt 0.02 rad about y, 8 µm deep.
    let dist = 2e-3 - 8e-6;
    let centre = Vector3::new(
        prm.bore_radius() + 1e-3 - dist * 0.5f64.sin(),
        0.0,
        -1e-3 + dist * 0.5f64.cos(),
    );
    let qm = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -0.02);
    let pm = centre - qm * Vector3::new(rr, 0.0, 1e-3 - 0.5 * prm.length);
    let mouth = pose_state(pm, qm, Vector3::zeros(), Vector3::zeros());
    let clear = pose_state(
        Vector3::new(0.0, 0.0, 0.1),
        q,
        Vector3::zeros(),
        Vector3::zeros(),
    );
    let n = 20_000;
    for (what, y) in [
        ("rim on the top face", top),
        ("rim on the mouth fillet", mouth),
        ("clear", clear),
    ] {
        let curv = Peg3d::new(prm);
        let mut fixed_prm = prm;
        let forces = curv.forces(&y).unwrap_or_default();
        fixed_prm.hertz = HertzMode::Fixed(forces.first().map_or(2e10, |f| f.stiffness));
        let fixed = Peg3d::new(fixed_prm);
        let t_curv = per_call(n, || {
            black_box(curv.rhs(0.0, black_box(&y)));
        });
        let t_fixed = per_call(n, || {
            black_box(fixed.rhs(0.0, black_box(&y)));
        });
        let x: SVector<f64, 7> = Peg3d::pose(&y);
        let hertz = |f: &ContactForce| stiffness::hertz_at(&prm, &f.contact, &x);
        let t_term = per_call(n, || {
            for f in &forces {
                if let Ok(hz) = hertz(f) {
                    let c = &f.contact;
                    let g = stiffness::gradient(
                        &prm,
                        curv.param_vector(),
                        c.pair,
                        c.angle,
                        black_box(&x),
                        &hz,
                    );
                    black_box(g).ok();
                }
            }
        });
        let t_k = per_call(n, || {
            for f in &forces {
                black_box(hertz(black_box(f))).ok();
            }
        });
        println!(
            "{what}: {} contacts; rhs {t_curv:.2} µs with the curvature stiffness; its Hertz setup {t_k:.2} µs, with the stiffness term {t_term:.2} µs (the term {:.2} µs); rhs {t_fixed:.2} µs with a fixed stiffness",
            forces.len(),
            t_term - t_k
        );
    }
}
