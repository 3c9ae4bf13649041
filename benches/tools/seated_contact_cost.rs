//! Cost of one contact search of the compliant 3-D peg near the flats:
//! the aligned peg seated on the bore bottom (the ring alone), tilted
//! 2 mrad (ring and point in the hand-over), tilted 5 mrad (the point
//! alone), and a peg 20 mm above the bore bottom at 5 mrad (the ring's
//! test rejects it at once). Run with `cargo run --release -p pegdyn-benches
//! --bin seated_contact_cost` and state the machine's load beside the figures.

use nalgebra::{Unit, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::{Peg3d, Peg3dParams, pose_state};
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let prm = Peg3dParams::steel(0.04995, 0.070, 0.050, 1e-3, 1e-3, 0.1);
    let rr = prm.peg_radius() - prm.rim_fillet;
    let h = prm.rim_fillet - 0.5 * prm.length;
    let z0 = -prm.bore_depth;
    let cases = [
        ("aligned on the bore bottom (ring)", 0.0, 1e-7),
        ("2 mrad on the bore bottom (hand-over)", 2e-3, 1e-7),
        ("5 mrad on the bore bottom (point)", 5e-3, 1e-7),
        ("5 mrad, 20 mm above the bottom", 5e-3, -0.02),
    ];
    let n = 20_000;
    for (what, gamma, depth) in cases {
        let axis = Unit::new_normalize(Vector3::new(-0.3f64.sin(), 0.3f64.cos(), 0.0));
        let q = UnitQuaternion::from_axis_angle(&axis, gamma);
        let a = q * Vector3::z();
        let p = Vector3::new(
            -h * a.x,
            -h * a.y,
            z0 - depth + prm.rim_fillet - h * a.z + rr * a.xy().norm(),
        );
        let y = pose_state(p, q, Vector3::zeros(), Vector3::zeros());
        let sys = Peg3d::new(prm);
        let found = sys.contacts(&y).len();
        let start = Instant::now();
        // `search`, not `contacts`: the system keeps the contacts of the
        // last pose, so asking again at `y` would not search.
        let mut out = pegdyn::compliant_peg_3d::Contacts::new();
        for _ in 0..n {
            sys.search(black_box(&y), &mut out);
            black_box(&out);
        }
        let per = start.elapsed().as_secs_f64() / n as f64;
        println!("{what}: {found} contacts, {:.2} µs per search", per * 1e6);
    }
}
