//! Initial states of the peg: centred and upright, or tilted in two-point
//! contact (the paper's Fig. 5).

use nalgebra::SVector;

use super::params::CompliantParams;
use super::system::N_STATE;
use crate::hertz::HertzError;
use crate::scalar::Real;

/// The peg's coordinates and velocities (m, rad, m/s, rad/s).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct PegState {
    /// Centre of mass across the hole.
    pub x: f64,
    /// Centre of mass along the hole's axis, positive into the hole.
    pub z: f64,
    /// Tilt θ (the axis is `(sin θ, cos θ)`).
    pub theta: f64,
    /// `ẋ`.
    pub xdot: f64,
    /// `ż`.
    pub zdot: f64,
    /// `θ̇`.
    pub thetadot: f64,
}

impl PegState {
    /// The model state with zero work and dissipation.
    pub fn to_vector(&self) -> SVector<f64, N_STATE> {
        SVector::from([
            self.x,
            self.z,
            self.theta,
            self.xdot,
            self.zdot,
            self.thetadot,
            0.0,
            0.0,
        ])
    }

    /// The elastic-friction model's state
    /// ([`super::elastic`]): zero work, dissipation and tangential
    /// utilisations (unloaded tangential springs).
    pub fn to_vector_elastic(&self) -> SVector<f64, { super::elastic::N_STATE_ELASTIC }> {
        let mut y = SVector::<f64, { super::elastic::N_STATE_ELASTIC }>::zeros();
        y.fixed_rows_mut::<8>(0).copy_from(&self.to_vector());
        y
    }

    /// The peg at rest, upright on the hole's axis, its bottom face at
    /// depth `depth` (m).
    pub fn centred(params: &CompliantParams, depth: f64) -> PegState {
        PegState {
            z: depth - params.spec.com_height,
            ..PegState::default()
        }
    }

    /// The peg at rest, tilted by `theta > 0`, touching the hole's left top
    /// edge with its side and the right wall with its bottom edge, both with
    /// penetration `penetration ≥ 0` (m): the two-point state of the paper's
    /// Fig. 5. The depth follows from the geometry (`≈ cD/θ`).
    ///
    /// Refuses (field `tilt`) a tilt that is not positive, reaches 0.8 of the
    /// wall contact's split tilt, or leaves the bottom edge above the edge
    /// fillet (the peg not yet in the hole).
    pub fn two_point(
        params: &CompliantParams,
        theta: f64,
        penetration: f64,
    ) -> Result<PegState, HertzError> {
        let g = &params.spec.geometry;
        let bad = |reason| {
            Err(HertzError::Invalid {
                field: "tilt".to_owned(),
                value: theta,
                reason,
            })
        };
        if !(theta > 0.0 && theta < 0.8 * g.wall_split_tilt()) {
            return bad("must be > 0 and below 0.8 of the wall contact's split tilt");
        }
        let (r, rp, rh, half_d) = (
            g.peg_radius,
            g.peg_fillet,
            g.hole_fillet,
            0.5 * g.hole_diameter,
        );
        let lc = params.spec.com_height;
        let (x, z) = two_point_pose([r, rp, rh, half_d], lc, theta, penetration);
        let (s, c) = theta.sin_cos();
        let state = PegState {
            x,
            z,
            theta,
            ..PegState::default()
        };
        // The wall contact point must lie below the edge fillet.
        let wall_contact_depth = z + (lc - rp) * c - (r - rp) * s;
        if wall_contact_depth <= rh {
            return bad("puts the bottom edge above the hole's edge fillet: choose a smaller tilt");
        }
        Ok(state)
    }

    /// Depth of the bottom face's centre (m).
    pub fn depth(&self, params: &CompliantParams) -> f64 {
        self.z + params.spec.com_height * self.theta.cos()
    }
}

/// The centre of mass `(x, z)` (m) of [`PegState::two_point`] at tilt
/// `theta` (rad) with both contacts `penetration` deep, at any scalar:
/// `[r, ρ_p, ρ_h, D/2]` the peg's radius, its fillet, the hole's fillet
/// and the hole's radius, `lc` the centre of mass's height above the
/// bottom face (m). From the two contacts' approaches,
///
/// ```text
/// wall (right):  δ_B = x + (l_c − ρ_p) sin θ + (r − ρ_p) cos θ + ρ_p − D/2
/// edge (left):   δ_A = ρ_h + r + (−(D/2 + ρ_h) − x) cos θ − (ρ_h − z) sin θ
/// ```
///
/// each set to `penetration`.
pub fn two_point_pose<T: Real>(geometry: [T; 4], lc: T, theta: T, penetration: T) -> (T, T) {
    let [r, rp, rh, half_d] = geometry;
    let (s, c) = theta.sin_cos();
    let x = half_d - rp - (lc - rp) * s - (r - rp) * c + penetration;
    let z = rh + (penetration - rh - r + (half_d + rh + x) * c) / s;
    (x, z)
}
