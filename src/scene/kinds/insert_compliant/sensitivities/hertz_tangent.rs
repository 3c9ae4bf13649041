//! The change of a Hertz contact's load-independent numbers (curvature sum,
//! `m_a`, `m_b`, `δ*`, stiffness `k`) for a change of its two directional
//! curvature sums and of its contact modulus, by hand.
//!
//! With the relative curvatures `(A, B)`, `A ≤ B`, the ratio `ρ = B/A`
//! fixes `m = e² = 1 − 1/κ²` through (Johnson, *Contact Mechanics*, 4.39–4.41)
//!
//! ```text
//! ρ(m) = (E/(1 − m) − K) / (K − E),
//! dK/dm = (E − (1 − m) K) / (2 m (1 − m)),   dE/dm = (E − K) / (2m),
//! ```
//!
//! so `dm = dρ / ρ'(m)`, `dκ = ½ (1 − m)^{−3/2} dm`, and
//!
//! ```text
//! d ln m_a = (2 d ln κ + d ln E)/3,   d ln m_b = (d ln E − d ln κ)/3,
//! d ln δ* = d ln K − d ln m_a,
//! d ln k  = d ln E* − (3/2) d ln δ* − ½ d ln Σρ,   Σρ = 2(A + B).
//! ```

use crate::hertz::HertzContact;

/// The change of a contact's numbers (the model parameters
/// `<contact>_sum, _ma, _mb, _dstar` and `k_<contact>`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HertzTangent {
    /// `dΣρ`.
    pub sum: f64,
    /// `dm_a`.
    pub m_a: f64,
    /// `dm_b`.
    pub m_b: f64,
    /// `dδ*`.
    pub delta_star: f64,
    /// `dk`.
    pub stiffness: f64,
}

/// The change of `contact` for changes of its two directional half-sums of
/// curvature, each given as `(value, change)`: `plane` in the plane of
/// tilt, `around` around the hole (the relative curvatures before sorting,
/// `A` the smaller), and `de_star` of its modulus.
pub fn contact_tangent(
    contact: &HertzContact,
    plane: (f64, f64),
    around: (f64, f64),
    de_star: f64,
) -> HertzTangent {
    let (a, b) = contact.relative;
    let (da, db) = if around.0 <= plane.0 {
        (around.1, plane.1)
    } else {
        (plane.1, around.1)
    };
    let sum = contact.sum_curvature;
    let dsum = 2.0 * (da + db);
    let el = &contact.ellipticity;
    let co = &contact.coefficients;
    let ratio = b / a;
    let dratio = (db * a - b * da) / (a * a);
    let (dkappa, dk_int, de_int) = if ratio > 1.0 {
        let mc = 1.0 / (el.kappa * el.kappa);
        let m = 1.0 - mc;
        let (k, e) = (el.k, el.e);
        let dk_dm = (e - mc * k) / (2.0 * m * mc);
        let de_dm = (e - k) / (2.0 * m);
        let num = e / mc - k;
        let den = k - e;
        let dnum = de_dm / mc + e / (mc * mc) - dk_dm;
        let dden = dk_dm - de_dm;
        let dratio_dm = (dnum * den - num * dden) / (den * den);
        let dm = dratio / dratio_dm;
        (0.5 * mc.powf(-1.5) * dm, dk_dm * dm, de_dm * dm)
    } else {
        (0.0, 0.0, 0.0)
    };
    let dln_kappa = dkappa / el.kappa;
    let dln_e = de_int / el.e;
    let dln_ma = (2.0 * dln_kappa + dln_e) / 3.0;
    let dln_mb = (dln_e - dln_kappa) / 3.0;
    let dln_dstar = dk_int / el.k - dln_ma;
    let dln_k = de_star / contact.contact_modulus - 1.5 * dln_dstar - 0.5 * dsum / sum;
    HertzTangent {
        sum: dsum,
        m_a: co.m_a * dln_ma,
        m_b: co.m_b * dln_mb,
        delta_star: co.delta_star * dln_dstar,
        stiffness: contact.stiffness() * dln_k,
    }
}
