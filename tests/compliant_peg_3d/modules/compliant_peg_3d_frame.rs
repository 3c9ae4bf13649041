//! The items of `src/compliant_peg_3d/frame.rs`.

use nalgebra::{Quaternion, SVector, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::frame::*;

/// A reproducible stream of numbers in (−1, 1) (xorshift).
fn stream(seed: u64) -> impl FnMut() -> f64 {
    let mut s = seed;
    move || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

#[test]
fn the_frame_is_nalgebras_to_the_last_bit() {
    let mut r = stream(0x9e37_79b9_7f4a_7c15);
    for _ in 0..20_000 {
        let y: SVector<f64, 15> = SVector::from_fn(|_, _| r() * 3.0);
        let ys: [f64; 15] = y.into();
        // Reference: the nalgebra form of the right-hand side.
        let qn = y.fixed_rows::<4>(3).norm();
        let mut x = SVector::<f64, 7>::zeros();
        x.fixed_rows_mut::<3>(0).copy_from(&y.fixed_rows::<3>(0));
        for k in 0..4 {
            x[3 + k] = y[3 + k] / qn;
        }
        let q = UnitQuaternion::from_quaternion(Quaternion::new(x[3], x[4], x[5], x[6]));
        let om = q * Vector3::new(y[10], y[11], y[12]);
        let m = Motion::of_state(&ys);
        let xs: [f64; 7] = x.into();
        assert_eq!(m.pose.map(f64::to_bits), xs.map(f64::to_bits));
        let oms: [f64; 3] = om.into();
        assert_eq!(m.omega.map(f64::to_bits), oms.map(f64::to_bits));
        let (a, b) = (
            Vector3::new(r(), r(), r()),
            Vector3::new(r() * 1e-3, r(), r() * 1e3),
        );
        let (aa, ba): ([f64; 3], [f64; 3]) = (a.into(), b.into());
        assert_eq!(dot(&aa, &ba).to_bits(), a.dot(&b).to_bits());
        assert_eq!(dot(&aa, &aa).to_bits(), a.norm_squared().to_bits());
        let c: [f64; 3] = a.cross(&b).into();
        assert_eq!(cross(&aa, &ba).map(f64::to_bits), c.map(f64::to_bits));
        let vc: [f64; 3] = (Vector3::new(y[7], y[8], y[9])
            + om.cross(&(b - Vector3::new(y[0], y[1], y[2]))))
        .into();
        assert_eq!(
            m.point_velocity(&ba).map(f64::to_bits),
            vc.map(f64::to_bits)
        );
    }
}
