//! The time scales of a run of the compliant 3-D peg
//! ([`crate::scene::timescales`]): the contact's natural period at the
//! load the peg carries, the regularized friction's time constant, the
//! wrist's periods and damping times, the aligning moment's and the
//! robot's rates.

use crate::compliant_peg_3d::insertion::Held;
use crate::compliant_peg_3d::robot::Descent;
use crate::compliant_peg_3d::{HertzMode, Peg3dParams};
use crate::hertz::contact_modulus;
use crate::scene::numbers::significant as sig;
use crate::scene::timescales::TimeScale;

/// The peg's own scales under a reference contact load `load` (N; what
/// sets it in words, `load_from`): the contact's natural period and the
/// friction's time constant.
pub fn peg(p: &Peg3dParams, load: f64, load_from: &str) -> Vec<TimeScale> {
    let m = p.mass;
    let (k, fields) = match p.hertz {
        HertzMode::Fixed(k) => (
            k,
            format!(
                "peg.contact_stiffness = {} N/m^1.5 on a peg of {} kg, at {load_from}",
                sig(k),
                sig(m)
            ),
        ),
        HertzMode::Curvature => {
            let r = p.rim_fillet.min(p.mouth_fillet);
            let e = contact_modulus(&p.peg_material, &p.hole_material);
            (
                4.0 / 3.0 * e * r.sqrt(),
                format!(
                    "k = 4/3 E* sqrt(R) of the fillet R = {} m (peg.rim_fillet, \
                     peg.mouth_fillet) and E* = {} Pa, on a peg of {} kg, at {load_from}",
                    sig(r),
                    sig(e),
                    sig(m)
                ),
            )
        }
    };
    let k_eff = TimeScale::hertz_stiffness(k, load);
    let mut out = vec![TimeScale::new(
        format!(
            "the contact's natural period 2 pi sqrt(m/k_eff) at {} N",
            sig(load)
        ),
        fields,
        TimeScale::period_of(m, k_eff),
    )];
    if p.friction > 0.0 {
        out.push(TimeScale::new(
            "the regularized friction's time constant m v_s / (mu F)",
            format!(
                "peg.slip_velocity = {} m/s, peg.friction = {}, on a peg of {} kg at {load_from}",
                sig(p.slip_scale),
                sig(p.friction),
                sig(m)
            ),
            m * p.slip_scale / (p.friction * load),
        ));
    }
    out
}

/// The reference contact load of a peg: its weight, and what pushes it.
pub fn load(p: &Peg3dParams, push: f64) -> f64 {
    (p.mass * p.gravity + push.abs()).max(f64::MIN_POSITIVE)
}

/// The scales of a held peg: the peg's at its weight plus the axial force,
/// the wrist's periods and damping times, the robot's rates.
pub fn held(p: &Peg3dParams, h: &Held) -> Vec<TimeScale> {
    let (push, from) = match h.robot.descent {
        Descent::Force { force } => (force, "the peg's weight plus robot.axial_force"),
        Descent::Speed { .. } => (0.0, "the peg's weight"),
    };
    let mut out = peg(p, load(p, push), from);
    let (m, it, ia) = (p.mass, p.inertia_transverse, p.inertia_axial);
    let w = &h.wrist;
    for (what, field, inertia, k) in [
        (
            "lateral",
            "wrist.lateral_stiffness",
            m,
            w.lateral[0].min(w.lateral[1]),
        ),
        ("axial", "wrist.axial_stiffness", m, w.axial),
        ("angular", "wrist.angular_stiffness", it, w.angular),
        ("torsional", "wrist.torsional_stiffness", ia, w.torsional),
    ] {
        out.push(TimeScale::new(
            format!("the wrist's {what} period 2 pi sqrt(m/K)"),
            format!("{field} = {}", sig(k)),
            TimeScale::period_of(inertia, k),
        ));
    }
    for (what, field, inertia, c) in [
        ("lateral", "wrist.lateral_damping", m, w.lateral_damping),
        ("axial", "wrist.axial_damping", m, w.axial_damping),
        (
            "angular",
            "wrist.angular_damping",
            it.min(ia),
            w.angular_damping,
        ),
    ] {
        if c > 0.0 {
            out.push(TimeScale::new(
                format!("the wrist's {what} damping time m/c"),
                format!("{field} = {}", sig(c)),
                inertia / c,
            ));
        }
    }
    for (what, field, rate) in [
        (
            "precession",
            "robot.precession_rate",
            h.robot.precession_rate,
        ),
        ("spin", "robot.spin_rate", h.robot.spin_rate),
    ] {
        if rate != 0.0 {
            out.push(TimeScale::new(
                format!("the robot's {what} period 2 pi / rate"),
                format!("{field} = {} rad/s", sig(rate)),
                std::f64::consts::TAU / rate.abs(),
            ));
        }
    }
    out
}

/// The scales of the aligning moment `m0` (N·m) on a free peg: the time
/// `sqrt(I / M)` it takes to turn the peg by a radian.
pub fn aligning(p: &Peg3dParams, m0: f64) -> Option<TimeScale> {
    (m0 != 0.0).then(|| {
        TimeScale::new(
            "the aligning moment's turning time sqrt(I/M)",
            format!(
                "drop.aligning_moment = {} N m on a peg of inertia {} kg m^2",
                sig(m0),
                sig(p.inertia_transverse)
            ),
            (p.inertia_transverse / m0.abs()).sqrt(),
        )
    })
}
