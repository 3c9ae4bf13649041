//! The scene fields a `[sensitivities]` table may name, and the chain rule
//! from each to the compliant planar peg's model parameters `p` and its
//! initial state `y₀`, written out by hand (forward mode: a unit change of
//! one field is carried through the scene's own translation).
//!
//! The translation being differentiated (`InsertCompliantScene::build`):
//!
//! ```text
//! r = D (1 − c)/2
//! m = ρ π r² L,   J = m (3r² + L²)/12,   l_c = com_height or L/2
//! E* = 1/((1 − ν₁²)/E₁ + (1 − ν₂²)/E₂)
//! edge curvatures: peg [0, 1/r], hole [1/ρ_h, −2/D]
//! wall curvatures: peg [1/ρ_p, 1/r], hole [0, −2/D]
//! (A, B) = sorted (½ Σ plane of tilt, ½ Σ around the hole),  Σρ = 2(A + B)
//! B/A fixes the ellipse (hertz_tangent), k = (2E*/3) √(8/(δ*³ Σρ))
//! two-point start: x = D/2 − ρ_p − (l_c − ρ_p) sin θ − (r − ρ_p) cos θ,
//!                  z = ρ_h + (−ρ_h − r + (D/2 + ρ_h + x) cos θ)/sin θ
//! centred start:   z = initial_depth − l_c
//! ```

use nalgebra::{SMatrix, SVector};

use super::hertz_tangent::{HertzTangent, contact_tangent};
use crate::compliant_peg::params::N_PARAMS;
use crate::compliant_peg::system::N_STATE;
use crate::generated::compliant_peg as all;
use crate::scene::kinds::insert_compliant::{Built, InsertParams};

/// Number of fields a `[sensitivities]` table may name.
pub const N_FIELDS: usize = 21;

/// The fields, by their names in the scene (`[sensitivities] parameters`).
pub const FIELDS: [&str; N_FIELDS] = [
    "insert_compliant.hole_diameter",
    "insert_compliant.clearance_ratio",
    "insert_compliant.peg_length",
    "insert_compliant.density",
    "insert_compliant.com_height",
    "insert_compliant.peg_fillet",
    "insert_compliant.hole_fillet",
    "insert_compliant.friction",
    "insert_compliant.slip_velocity",
    "insert_compliant.contact_damping",
    "insert_compliant.tangential_damping",
    "insert_compliant.axial_force",
    "insert_compliant.radial_force",
    "insert_compliant.torque",
    "insert_compliant.initial_tilt",
    "insert_compliant.initial_depth",
    "insert_compliant.target_depth",
    "insert_compliant.peg_material.youngs_modulus",
    "insert_compliant.peg_material.poisson_ratio",
    "insert_compliant.hole_material.youngs_modulus",
    "insert_compliant.hole_material.poisson_ratio",
];

/// The index of `insert_compliant.target_depth` in [`FIELDS`] (it enters
/// no model parameter, only the seating event).
pub const TARGET_DEPTH: usize = 16;

/// The field at index `k` of [`FIELDS`] in `p`: one place that ties the
/// names' order to the scene's fields (`com_height` is written as its
/// default `L/2` when it was not).
#[doc(hidden)]
pub fn slot(p: &mut InsertParams, k: usize) -> &mut f64 {
    let half_length = 0.5 * p.peg_length;
    match k {
        0 => &mut p.hole_diameter,
        1 => &mut p.clearance_ratio,
        2 => &mut p.peg_length,
        3 => &mut p.density,
        4 => p.com_height.get_or_insert(half_length),
        5 => &mut p.peg_fillet,
        6 => &mut p.hole_fillet,
        7 => &mut p.friction,
        8 => &mut p.slip_velocity,
        9 => &mut p.contact_damping,
        10 => &mut p.tangential_damping,
        11 => &mut p.axial_force,
        12 => &mut p.radial_force,
        13 => &mut p.torque,
        14 => &mut p.initial_tilt,
        15 => &mut p.initial_depth,
        16 => &mut p.target_depth,
        17 => &mut p.peg_material.youngs_modulus,
        18 => &mut p.peg_material.poisson_ratio,
        19 => &mut p.hole_material.youngs_modulus,
        _ => &mut p.hole_material.poisson_ratio,
    }
}

/// The fields' values in a scene (`com_height` its default `L/2` when not
/// written).
pub fn values(p: &InsertParams) -> SVector<f64, N_FIELDS> {
    let mut written = p.clone();
    SVector::from_fn(|k, _| *slot(&mut written, k))
}

/// A change of every field (`d` of each, in [`FIELDS`] order).
type FieldTangent = SVector<f64, N_FIELDS>;

/// The model parameters' and initial state's change for one change `dq`
/// of the fields.
fn tangent(
    p: &InsertParams,
    b: &Built,
    dq: &FieldTangent,
) -> (SVector<f64, N_PARAMS>, SVector<f64, N_STATE>) {
    let q = values(p);
    let (d, c, len, rho) = (q[0], q[1], q[2], q[3]);
    let (dd, dc, dlen, drho) = (dq[0], dq[1], dq[2], dq[3]);
    let r = 0.5 * d * (1.0 - c);
    let dr = 0.5 * (dd * (1.0 - c) - d * dc);
    let m = b.params.spec.mass;
    let dm = m * (drho / rho + 2.0 * dr / r + dlen / len);
    let shape = (3.0 * r * r + len * len) / 12.0;
    let dj = dm * shape + m * (6.0 * r * dr + 2.0 * len * dlen) / 12.0;
    let dlc = if p.com_height.is_some() {
        dq[4]
    } else {
        dq[4] + 0.5 * dlen
    };
    let (rp, rh, drp, drh) = (q[5], q[6], dq[5], dq[6]);
    // E* = 1/(c₁ + c₂), c = (1 − ν²)/E.
    let compliance = |e: f64, nu: f64, de: f64, dnu: f64| {
        (
            (1.0 - nu * nu) / e,
            -2.0 * nu * dnu / e - (1.0 - nu * nu) * de / (e * e),
        )
    };
    let (c1, dc1) = compliance(q[17], q[18], dq[17], dq[18]);
    let (c2, dc2) = compliance(q[19], q[20], dq[19], dq[20]);
    let e_star = 1.0 / (c1 + c2);
    let de_star = -e_star * e_star * (dc1 + dc2);
    // Curvatures around the hole: 1/r − 2/D (both contacts).
    let around = (
        0.5 * (1.0 / r - 2.0 / d),
        0.5 * (-dr / (r * r) + 2.0 * dd / (d * d)),
    );
    let pair = &b.params.pair;
    let edge: HertzTangent = contact_tangent(
        &pair.edge,
        (0.5 / rh, -0.5 * drh / (rh * rh)),
        around,
        de_star,
    );
    let wall: HertzTangent = contact_tangent(
        &pair.wall,
        (0.5 / rp, -0.5 * drp / (rp * rp)),
        around,
        de_star,
    );
    let dp: SVector<f64, N_PARAMS> = all::Params {
        m: dm,
        J: dj,
        r: dr,
        l_c: dlc,
        D: dd,
        rho_p: drp,
        rho_h: drh,
        mu: dq[7],
        v_s: dq[8],
        k_edge: edge.stiffness,
        k_wall: wall.stiffness,
        f1: dq[11],
        f2: dq[12],
        M: dq[13],
        e_star: de_star,
        edge_sum: edge.sum,
        edge_ma: edge.m_a,
        edge_mb: edge.m_b,
        edge_dstar: edge.delta_star,
        wall_sum: wall.sum,
        wall_ma: wall.m_a,
        wall_mb: wall.m_b,
        wall_dstar: wall.delta_star,
        hc_alpha: dq[9],
    }
    .into();
    let mut dy0 = SVector::<f64, N_STATE>::zeros();
    let lc = b.params.spec.com_height;
    if p.initial_tilt > 0.0 {
        let (th, dth) = (p.initial_tilt, dq[14]);
        let (s, co) = th.sin_cos();
        let x = 0.5 * d - rp - (lc - rp) * s - (r - rp) * co;
        let dx = 0.5 * dd - drp - (dlc - drp) * s - (lc - rp) * co * dth - (dr - drp) * co
            + (r - rp) * s * dth;
        let u = -rh - r + (0.5 * d + rh + x) * co;
        let du = -drh - dr + (0.5 * dd + drh + dx) * co - (0.5 * d + rh + x) * s * dth;
        let dz = drh + du / s - u * co * dth / (s * s);
        dy0[0] = dx;
        dy0[1] = dz;
        dy0[2] = dth;
    } else {
        dy0[1] = dq[15] - dlc;
    }
    (dp, dy0)
}

/// `∂p/∂q` (24 × [`N_FIELDS`]) and `∂y₀/∂q` (8 × [`N_FIELDS`]) of the
/// scene's translation at its values.
pub fn jacobians(
    p: &InsertParams,
    b: &Built,
) -> (
    SMatrix<f64, N_PARAMS, N_FIELDS>,
    SMatrix<f64, N_STATE, N_FIELDS>,
) {
    let mut dp = SMatrix::<f64, N_PARAMS, N_FIELDS>::zeros();
    let mut dy0 = SMatrix::<f64, N_STATE, N_FIELDS>::zeros();
    for k in 0..N_FIELDS {
        let mut e = FieldTangent::zeros();
        e[k] = 1.0;
        let (a, y) = tangent(p, b, &e);
        dp.set_column(k, &a);
        dy0.set_column(k, &y);
    }
    (dp, dy0)
}

/// Whether field `k` moves nothing the run depends on (no model parameter,
/// not the start, not the target).
pub fn unused(
    k: usize,
    dp: &SMatrix<f64, N_PARAMS, N_FIELDS>,
    dy0: &SMatrix<f64, N_STATE, N_FIELDS>,
) -> bool {
    k != TARGET_DEPTH
        && dp
            .column(k)
            .iter()
            .chain(dy0.column(k).iter())
            .all(|v| *v == 0.0)
}
