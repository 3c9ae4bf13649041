//! The design parameters of an `insert_rcc` scene by their scene names
//! ([`FIELDS`]), and the scene's translation into the held peg's model
//! ([`RccScene::build`]) written once more in dual numbers of them: the
//! model's quantities ([`Design`]) and the start state with their
//! derivatives in the fields, for the insertion's forward sensitivities
//! ([`crate::compliant_peg_3d::design`]).
//!
//! The translation (`super::tables`):
//!
//! ```text
//! r = D (1 − c)/2,   m = ρ π r² L,   J_t = m (3r² + L²)/12,   J_a = m r²/2
//! θ₀ = angular_error_deg · π/180,   a₀ = (sin θ₀ cos ψ₀, sin θ₀ sin ψ₀, cos θ₀)
//! c_R(0) = (e cos β, e sin β, h₀) + L_c a₀,   z_end = −(seat + overtravel) + L_c cos θ₀
//! held start: p = c_R(0) − (L_c − L/2) a₀ − (m g/K_z) e_z,  v = ċ_R + Ω_R × (p − c_R),
//!             q = q_R(0),  ω_body = R_Rᵀ Ω_R
//! start in the bore: p = (0, 0, L/2 − depth),  v = (0, 0, ż_R),  q = 1
//! ```
//!
//! (`e`, `β` the lateral error and its direction, `ψ₀` the tilt's azimuth,
//! `h₀` the start height; `K_y = K_x` unless `wrist.lateral_stiffness_y`
//! is written).

use nalgebra::SVector;

use super::insertion::{Built, RccScene};
use crate::compliant_peg_3d::design::{Design, N_DESIGN, Q};
use crate::compliant_peg_3d::frame::{V3, add, cross, scale, sub};
use crate::compliant_peg_3d::insertion::N_STATE;
use crate::compliant_peg_3d::law::LawParams;
use crate::compliant_peg_3d::robot::{MotionOf, RobotMotion};
use crate::compliant_peg_3d::wrist::WristOf;
use crate::compliant_peg_3d::{HertzMode, Peg3dParams};
use crate::generated::compliant_peg_3d as generated;
use crate::scalar::Real;

/// How many fields [`FIELDS`] lists.
pub const N_FIELDS: usize = 14;

/// The fields a `[sensitivities]` table of an `insert_rcc` scene may name,
/// in field order. A sensitivity run carries at most [`N_DESIGN`] of them
/// (its slots); more are run in several passes.
pub const FIELDS: [&str; N_FIELDS] = [
    "wrist.lateral_stiffness",
    "wrist.angular_stiffness",
    "wrist.centre_height",
    "wrist.axial_stiffness",
    "peg.clearance_ratio",
    "peg.mouth_fillet",
    "peg.rim_fillet",
    "peg.friction",
    "peg.contact_damping",
    "robot.speed",
    "robot.lateral_error",
    "robot.angular_error_deg",
    "robot.precession_rate",
    "robot.spin_rate",
];

/// The field at index `k` of [`FIELDS`] in `s`: one place that ties the
/// names' order to the scene's fields.
pub fn slot(s: &mut RccScene, k: usize) -> &mut f64 {
    match k {
        0 => &mut s.wrist.lateral_stiffness,
        1 => &mut s.wrist.angular_stiffness,
        2 => &mut s.wrist.centre_height,
        3 => &mut s.wrist.axial_stiffness,
        4 => &mut s.peg.clearance_ratio,
        5 => &mut s.peg.mouth_fillet,
        6 => &mut s.peg.rim_fillet,
        7 => &mut s.peg.friction,
        8 => &mut s.peg.contact_damping,
        9 => &mut s.robot.speed,
        10 => &mut s.robot.lateral_error,
        11 => &mut s.robot.angular_error_deg,
        12 => &mut s.robot.precession_rate,
        _ => &mut s.robot.spin_rate,
    }
}

/// The fields' values in a scene, in field order.
pub fn values(s: &RccScene) -> SVector<f64, N_FIELDS> {
    let mut written = s.clone();
    SVector::from_fn(|k, _| *slot(&mut written, k))
}

/// Which field each of a sensitivity run's [`N_DESIGN`] slots carries
/// (an index into [`FIELDS`]; `None`: the slot is empty).
pub type Seeds = [Option<usize>; N_DESIGN];

/// The seeds of `fields` (indices into [`FIELDS`], at most [`N_DESIGN`]) in
/// slot order.
///
/// # Panics
/// More than [`N_DESIGN`] fields (a caller's error: a scene's table is run
/// in passes of at most that many).
pub fn seeds(fields: &[usize]) -> Seeds {
    assert!(
        fields.len() <= N_DESIGN,
        "at most {N_DESIGN} fields per pass"
    );
    std::array::from_fn(|j| fields.get(j).copied())
}

/// The values of the seeded fields, slot by slot (0 in an empty slot).
pub fn slot_values(s: &RccScene, seeds: &Seeds) -> SVector<f64, N_DESIGN> {
    let all = values(s);
    SVector::from_fn(|j, _| seeds[j].map_or(0.0, |k| all[k]))
}

/// The model's quantities of scene `s` (validated into `built`) and its
/// start state, in dual numbers whose slot `j` carries the derivative in
/// the field `seeds[j]` (the fields no slot carries are constants).
pub fn design(s: &RccScene, built: &Built, seeds: &Seeds) -> (Design, [Q; N_STATE]) {
    let params = &built.params;
    let written = values(s);
    let q: [Q; N_FIELDS] =
        std::array::from_fn(|k| match seeds.iter().position(|f| *f == Some(k)) {
            Some(j) => Q::variable(written[k], j),
            None => Q::constant(written[k]),
        });
    // The fields by name, in the order of `FIELDS`.
    let [
        kx,
        angular,
        lc,
        axial,
        clearance,
        mouth_fillet,
        rim_fillet,
        friction,
        damping,
        speed,
        lateral_error,
        angular_error_deg,
        precession_rate,
        spin_rate,
    ] = q;
    let c = Q::from_f64;
    let peg = &s.peg;
    let (d, len) = (c(peg.hole_diameter), c(peg.length));
    let r = c(0.5) * d * (c(1.0) - clearance);
    let mass = c(peg.density * std::f64::consts::PI) * r * r * len;
    let mut p = generated::Params::from(params.vector().map(Q::constant));
    p.r = r;
    p.rho_p = rim_fillet;
    p.rho_h = mouth_fillet;
    p.m = mass;
    p.J_t = mass * (c(3.0) * r * r + len * len) / c(12.0);
    p.J_a = c(0.5) * mass * r * r;
    let law = LawParams {
        friction,
        slip_scale: c(params.slip_scale),
        damping,
    };
    let w = &s.wrist;
    let wrist = WristOf {
        centre_height: lc,
        lateral: [kx, w.lateral_stiffness_y.map_or(kx, c)],
        axial,
        angular,
        torsional: c(w.torsional_stiffness),
        lateral_damping: c(w.lateral_damping),
        axial_damping: c(w.axial_damping),
        angular_damping: c(w.angular_damping),
    };
    let rb = &s.robot;
    let tilt = angular_error_deg * c(std::f64::consts::PI / 180.0);
    let (sa, ca) = tilt.sin_cos();
    let (sz, cz) = rb.tilt_direction_deg.to_radians().sin_cos();
    let (sb, cb) = rb.lateral_error_direction_deg.to_radians().sin_cos();
    let a0 = [sa * c(cz), sa * c(sz), ca];
    let tip = [
        lateral_error * c(cb),
        lateral_error * c(sb),
        c(rb.start_height),
    ];
    let forced = rb.axial_force.is_some();
    let robot = MotionOf {
        start: add(&tip, &scale(&a0, lc)),
        tilt,
        speed: if forced { c(0.0) } else { speed },
        end: if forced {
            c(0.0)
        } else {
            -c(s.criteria.seat_depth + rb.overtravel) + lc * ca
        },
        precession_rate,
        spin_rate,
    };
    let design = Design {
        p: p.into(),
        law,
        wrist,
        robot,
    };
    (design, start(s, &built.held.robot, &design))
}

/// The start state of [`RccScene`]'s run in dual numbers of the fields
/// (the module documentation's held start, or the start in the bore).
fn start(s: &RccScene, motion: &RobotMotion, d: &Design) -> [Q; N_STATE] {
    let c = Q::from_f64;
    let mut y = [c(0.0); N_STATE];
    let f = motion.terms_of(0.0, &d.robot);
    // ċ_R = −R_R (−R_Rᵀ ċ_R).
    let times = |m: &[V3<Q>; 3], v: &V3<Q>| -> V3<Q> {
        std::array::from_fn(|r| m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2])
    };
    let velocity = times(&f.rotation, &f.robot_velocity).map(|v| -v);
    let half = c(0.5) * d.params().L;
    if s.robot.start_height < 0.0 {
        y[2] = half + c(s.robot.start_height);
        y[3] = c(1.0);
        y[9] = velocity[2];
        return y;
    }
    let axis = [f.rotation[0][2], f.rotation[1][2], f.rotation[2][2]];
    let arm = scale(&axis, d.wrist.centre_height - half);
    let sag = if s.robot.axial_force.is_some() {
        c(0.0)
    } else {
        d.params().m * d.params().g / d.wrist.axial
    };
    let mut centre = sub(&f.position, &arm);
    centre[2] = centre[2] - sag;
    let v = add(
        &velocity,
        &cross(&f.angular_velocity, &sub(&centre, &f.position)),
    );
    let [i, j, k, w] = f.inverse;
    let quaternion = [w, -i, -j, -k];
    y[..3].copy_from_slice(&centre);
    y[3..7].copy_from_slice(&quaternion);
    y[7..10].copy_from_slice(&v);
    y[10..13].copy_from_slice(&f.omega_robot);
    y
}

/// Whether the scene's contacts have a fixed Hertz stiffness (the
/// curvature stiffness's variation with the geometry is not carried).
pub fn fixed_stiffness(params: &Peg3dParams) -> bool {
    matches!(params.hertz, HertzMode::Fixed(_))
}
