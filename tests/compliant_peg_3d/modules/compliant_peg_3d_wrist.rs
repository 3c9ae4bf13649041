//! The items of `src/compliant_peg_3d/wrist.rs`.

use nalgebra::Quaternion;
use nalgebra::{Matrix3, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::wrist::*;

/// The load in nalgebra's types: the formulas of the module
/// documentation as written before they were made generic, the
/// reference of [`WristParams::load`] to the last bit.
fn reference(w: &WristParams, length: f64, m: &PegMotion, r: &RobotFrame) -> WristLoad {
    let axis = m.orientation * Vector3::z();
    let arm = axis * (w.centre_height - 0.5 * length);
    let cp = m.centre + arm;
    let rr = r.orientation.to_rotation_matrix();
    let rt = rr.transpose();
    let omega_rb = rt * r.angular_velocity;
    let d = rt * (cp - r.position);
    let kz = if r.axial_force.is_some() {
        0.0
    } else {
        w.axial
    };
    let kt = Matrix3::from_diagonal(&Vector3::new(w.lateral[0], w.lateral[1], kz));
    let mut g = kt * d;
    let mut potential = 0.5 * d.dot(&g);
    if let Some(f) = r.axial_force {
        g.z = f;
        potential += f * d.z;
    }
    let v_cp = m.velocity + m.angular_velocity.cross(&arm);
    let d_robot = -(rt * r.velocity) - omega_rb.cross(&d);
    let d_dot = rt * v_cp + d_robot;
    let ct = Vector3::new(w.lateral_damping, w.lateral_damping, w.axial_damping);
    let damp_t = ct.component_mul(&d_dot);
    let force_robot = -(g + damp_t);
    let rel = r.orientation.inverse() * m.orientation;
    let (qw, u) = (rel.w, Vector3::new(rel.i, rel.j, rel.k));
    let kr = Vector3::new(w.angular, w.angular, w.torsional);
    let ku = kr.component_mul(&u);
    let h = (ku * qw + ku.cross(&u)) * 2.0;
    let omega_rel = rt * (m.angular_velocity - r.angular_velocity);
    let damp_r = omega_rel * w.angular_damping;
    let spring_moment = m.orientation * (-h);
    let pure = spring_moment - rr * damp_r;
    let moment_robot = rt * pure;
    let potential = potential + 2.0 * u.dot(&ku);
    let force = rr * force_robot;
    let moment = pure + arm.cross(&force);
    WristLoad {
        force,
        moment,
        force_robot,
        moment_robot,
        deflection: d,
        rotation: 2.0 * u.norm().atan2(qw.abs()),
        potential,
        dissipation_rate: d_dot.dot(&damp_t) + omega_rel.dot(&damp_r),
        robot_power: (g + damp_t).dot(&d_robot)
            - 2.0 * omega_rb.dot(&(ku * qw + u.cross(&ku)))
            - damp_r.dot(&omega_rb),
    }
}

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

fn bits(v: &Vector3<f64>) -> [u64; 3] {
    [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()]
}

#[test]
fn the_generic_load_is_the_nalgebra_form_to_the_last_bit() {
    let mut r = stream(0x2545_f491_4f6c_dd1d);
    let mut v3 = |s: f64| Vector3::new(r() * s, r() * s, r() * s);
    for k in 0..20_000 {
        let wrist = WristParams {
            centre_height: 0.03 * (1.0 + v3(1.0).x),
            lateral: [2e4 * (1.5 + v3(1.0).x), 2e4 * (1.5 + v3(1.0).y)],
            axial: 2e5 * (1.5 + v3(1.0).z),
            angular: 20.0 * (1.5 + v3(1.0).x),
            torsional: 20.0 * (1.5 + v3(1.0).y),
            lateral_damping: 40.0 * (1.5 + v3(1.0).z),
            axial_damping: 400.0 * (1.5 + v3(1.0).x),
            angular_damping: 0.04 * (1.5 + v3(1.0).y),
        };
        let q4 = v3(1.0);
        let q = UnitQuaternion::from_quaternion(Quaternion::new(v3(1.0).x, q4.x, q4.y, q4.z));
        let m = PegMotion {
            centre: v3(0.03),
            orientation: q,
            velocity: v3(0.1),
            angular_velocity: v3(10.0),
        };
        let rq = UnitQuaternion::from_scaled_axis(v3(0.05));
        let frame = RobotFrame {
            position: v3(0.03),
            orientation: rq,
            velocity: v3(0.02),
            angular_velocity: v3(5.0),
            axial_force: (k % 3 == 0).then(|| 20.0 * (1.5 + v3(1.0).x)),
        };
        let a = wrist.load(0.05, &m, &frame);
        let b = reference(&wrist, 0.05, &m, &frame);
        assert_eq!(bits(&a.force), bits(&b.force), "{k}");
        assert_eq!(bits(&a.moment), bits(&b.moment), "{k}");
        assert_eq!(bits(&a.force_robot), bits(&b.force_robot), "{k}");
        assert_eq!(bits(&a.moment_robot), bits(&b.moment_robot), "{k}");
        assert_eq!(bits(&a.deflection), bits(&b.deflection), "{k}");
        for (x, y) in [
            (a.rotation, b.rotation),
            (a.potential, b.potential),
            (a.dissipation_rate, b.dissipation_rate),
            (a.robot_power, b.robot_power),
        ] {
            assert_eq!(x.to_bits(), y.to_bits(), "{k}: {x} {y}");
        }
    }
}
