//! Static-friction holding of a peg in two-point contact, exactly: an
//! applied wrench is held when it is minus a non-negative combination of the
//! contacts' friction-cone edge wrenches. An independent route to the
//! jamming verdict of [`super::diagram`], and a quasi-static stand-in for a
//! simulator in [`super::sweep`] tests.

use nalgebra::{Matrix3, Vector3};

use super::diagram::Ratio;
use super::forces::Wrench;
use super::params::PegHole;
use super::sweep::RunClass;

/// The four cone-edge wrenches (F_x, F_z, M about the tip) that the contacts
/// of the reference tilt can *resist*: minus the contact wrench for unit
/// normal force with friction ratio ±μ at the tip and at the edge.
pub fn resisted_generators(p: &PegHole, l: f64, theta: f64) -> [Vector3<f64>; 4] {
    let (mu, r) = (p.mu(), p.r());
    let (s, c) = theta.sin_cos();
    let tip = |t: f64| -Vector3::new(1.0, -t, r * (c * t + s));
    let edge = |t: f64| -Vector3::new(-c + t * s, -s - t * c, -(l + t * r));
    [tip(mu), tip(-mu), edge(mu), edge(-mu)]
}

/// Whether the contacts of the reference tilt at depth `l` (m) and tilt
/// `theta` (rad) can hold the applied wrench `w` with every contact force
/// inside its friction cone (Carathéodory: some three generators suffice).
pub fn holds(p: &PegHole, l: f64, theta: f64, w: &Wrench) -> bool {
    let g = resisted_generators(p, l, theta);
    let target = Vector3::new(w.fx, w.fz, w.m);
    let scale = target.norm().max(f64::MIN_POSITIVE);
    [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]
        .iter()
        .any(|idx| {
            let m = Matrix3::from_columns(&[g[idx[0]], g[idx[1]], g[idx[2]]]);
            m.lu()
                .solve(&target)
                .is_some_and(|a| a.iter().all(|&v| v >= -1e-12 * scale))
        })
}

/// Quasi-static verdict at load ratio `q` = (F_x/F_z, M/(r F_z)): stuck
/// ([`RunClass::Jammed`]) when either tilt's two contacts hold the load, or
/// the force lies inside one contact's friction cone (one-point contact at
/// the same tilt); else [`RunClass::Inserted`].
pub fn quasi_static_class(p: &PegHole, l: f64, theta: f64, q: Ratio) -> RunClass {
    let w = Wrench {
        fx: q[0],
        fz: 1.0,
        m: q[1] * p.r(),
    };
    let mirrored = Wrench {
        fx: -w.fx,
        fz: w.fz,
        m: -w.m,
    };
    let (k1, k2, _) = super::forces::k_factors(p.mu(), theta);
    let edge_cone = q[0].abs() >= k1 / k2;
    let tip_cone = q[0].abs() >= 1.0 / p.mu();
    if holds(p, l, theta, &w) || holds(p, l, theta, &mirrored) || edge_cone || tip_cone {
        RunClass::Jammed
    } else {
        RunClass::Inserted
    }
}
