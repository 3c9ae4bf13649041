//! The held peg's wrench beyond its contacts, written once for any scalar
//! ([`Real`]): the wrist's load at the robot frame of the time
//! ([`super::wrist::WristParams::load_of`]) and the follower moment
//! `M = −M₀ (e_z × a)/√(|e_z × a|² + s²)`, added to the contact wrench,
//! with the power `Ẇ_r` they deliver. [`Insertion`]'s right-hand side
//! evaluates it at `f64`; its exact Jacobian at dual numbers of the
//! state, on top of the contact wrench in the same dual numbers at the
//! contacts the right-hand side just found ([`Peg3d::contact_wrench_dual`]):
//!
//! ```text
//! ẏ = (f(y, w_c(y) + w_h(t, y)), Ẇ_r(t, y))
//! ∂ẏ/∂y = (∂f/∂y + ∂f/∂w · (dw_c/dy + ∂w_h/∂y), ∂Ẇ_r/∂y)
//! ∂ẏ/∂t = (∂f/∂w · ∂w_h/∂t, ∂Ẇ_r/∂t)
//! ```
//!
//! (`w_c` the contact wrench, `w_h` the wrist's and the follower's;
//! neither reads the work integrals `W`, `S`, `W_r`, so their columns are
//! zero). Only the robot frame depends on the time; `∂w_h/∂t` is its
//! central difference with the step `2⁻²⁰ s ≈ 9.5 · 10⁻⁷ s` (the wrist
//! alone, no contact search; relative error about `ε τ/δ + (δ/τ)²`,
//! below 10⁻⁹ for the robot's time scales `τ` of milliseconds and more).

use super::frame::{V3, cross, dot, rotate, scale};
use super::insertion::{Insertion, N_STATE, peg_state};
use super::jacobian;
#[cfg(doc)]
use super::system::Peg3d;
use super::wrist::{FrameTerms, Kinematics, WristOf, load_with};
use crate::generated::compliant_peg_3d as generated;
use crate::hertz::HertzError;
use crate::scalar::Real;
use nalgebra::{SMatrix, SVector};

/// Smoothing `s` of the follower moment's direction near `γ = 0`.
pub const FOLLOWER_SCALE: f64 = 1e-3;

/// Step of the central difference in time of the wrist's load (s).
pub const TIME_STEP: f64 = 1.0 / 1_048_576.0;

/// The partial rate in time `∂g/∂t` of a quantity `g` that the robot
/// frame's motion moves: central differences at [`TIME_STEP`] and half of
/// it, Richardson-extrapolated (a plain central difference's `h² g‴/6` is
/// large where the frame moves across a small load: the norm of a force
/// has `g‴ ~ |F_t|³/|F|²`).
pub fn time_partial(t: f64, g: impl Fn(f64) -> f64) -> f64 {
    let central = |h: f64| {
        let (t1, t0) = (t + h, t - h);
        (g(t1) - g(t0)) / (t1 - t0)
    };
    (4.0 * central(0.5 * TIME_STEP) - central(TIME_STEP)) / 3.0
}

/// The follower moment `−M₀ (e_z × a)/√(|e_z × a|² + s²)` at axis `a`
/// (hole frame, N·m), `m0 = M₀`.
pub fn follower<T: Real>(m0: f64, a: &V3<T>) -> V3<T> {
    let c = T::from_f64;
    let e = cross(&[c(0.0), c(0.0), c(1.0)], a);
    scale(
        &e,
        c(-m0) / (dot(&e, &e) + c(FOLLOWER_SCALE * FOLLOWER_SCALE)).sqrt(),
    )
}

impl Insertion {
    /// Adds the wrist's load at time `t` (if held) and the follower
    /// moment (if any) to the wrench `w = (F, T about the centre of mass,
    /// Ṡ)` of the peg in motion `m`; returns the power `Ẇ_r` they deliver.
    pub fn add_held<T: Real>(&self, t: f64, m: &Kinematics<T>, w: &mut [T; 7]) -> T {
        let held = self
            .held
            .map(|h| (h.wrist.of(), FrameTerms::of(&h.robot.frame(t))));
        let length = T::from_f64(self.peg.params.length);
        self.add_held_with(m, held.as_ref().map(|(wr, f)| (wr, f)), length, w)
    }

    /// [`Insertion::add_held`] with the wrist `held.0` at the robot frame's
    /// terms `held.1` on a peg of length `length`, all at scalar `T` (dual
    /// numbers of design parameters carry their derivative,
    /// [`super::design`]).
    pub fn add_held_with<T: Real>(
        &self,
        m: &Kinematics<T>,
        held: Option<(&WristOf<T>, &FrameTerms<T>)>,
        length: T,
        w: &mut [T; 7],
    ) -> T {
        let c = T::from_f64;
        let mut power = c(0.0);
        if let Some((wrist, frame)) = held {
            let load = load_with(wrist, length, m, frame);
            for k in 0..3 {
                w[k] = w[k] + load.force[k];
                w[3 + k] = w[3 + k] + load.moment[k];
            }
            w[6] = w[6] + load.dissipation_rate;
            power = power + load.robot_power;
        }
        let fm = if self.aligning_moment == 0.0 {
            [c(0.0); 3]
        } else {
            let axis = rotate(&m.orientation, &[c(0.0), c(0.0), c(1.0)]);
            follower(self.aligning_moment, &axis)
        };
        for k in 0..3 {
            w[3 + k] = w[3 + k] + fm[k];
        }
        power + dot(&fm, &m.angular_velocity)
    }

    /// The exact Jacobian `∂ẏ/∂y` (16 × 16) at `(t, y)` of the module
    /// documentation.
    ///
    /// # Errors
    /// As [`Peg3d::setups`] when the contacts of `y` have to be searched.
    pub fn exact_jacobian(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
    ) -> Result<SMatrix<f64, N_STATE, N_STATE>, HertzError> {
        let ys = peg_state(y);
        let mut w = self.peg.contact_wrench_dual(&ys)?;
        let power = self.add_held(t, &Kinematics::of_state(&jacobian::seeded(&ys)), &mut w);
        let (wv, dw) = jacobian::split(&w);
        let peg = jacobian::chain(self.peg.param_vector(), &ys, &wv, &dw);
        let mut out = SMatrix::<f64, N_STATE, N_STATE>::zeros();
        out.fixed_view_mut::<15, 15>(0, 0).copy_from(&peg);
        for (k, d) in power.d.iter().enumerate() {
            out[(15, k)] = *d;
        }
        Ok(out)
    }

    /// `∂ẏ/∂t` at `(t, y)` of the module documentation: zero for a peg
    /// that is not held.
    pub fn time_rate(&self, t: f64, y: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        let mut out = SVector::<f64, N_STATE>::zeros();
        if self.held.is_none() {
            return out;
        }
        let ys = peg_state(y);
        let m = Kinematics::of_state(ys.as_slice());
        let held = |t: f64| {
            let mut w = [0.0; 7];
            let power = self.add_held(t, &m, &mut w);
            (SVector::<f64, 7>::from(w), power)
        };
        let (t1, t0) = (t + TIME_STEP, t - TIME_STEP);
        let ((w1, p1), (w0, p0)) = (held(t1), held(t0));
        let dw = (w1 - w0) / (t1 - t0);
        // ∂f/∂w does not depend on w (the right-hand side is linear in it).
        let partial = generated::rhs_jacobian(&ys, &SVector::zeros(), self.peg.param_vector());
        out.fixed_rows_mut::<15>(0).copy_from(&(partial.dw * dw));
        out[15] = (p1 - p0) / (t1 - t0);
        out
    }
}
