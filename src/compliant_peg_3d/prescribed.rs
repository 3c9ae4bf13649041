//! The compliant 3-D peg with a prescribed orientation and a free
//! translation: the compliant counterpart of the rigid three-point peg's
//! prescribed motion (nutation γ(t), precession ψ(t), spin held).
//!
//! Orientation (the rigid three-point peg's Euler angles; `e_η`, `e_n` the
//! symmetry-plane frame at ψ):
//!
//! ```text
//! R(t) = R_z(ψ) R_y(−γ),   axis a = R e_z = −sin γ e_η + cos γ e_z
//! ω    = ψ̇ e_z − γ̇ e_n     (hole frame),   ω_body = Rᵀ ω
//! γ(t) = γ_s + γ̇ t,   ψ(t) = ψ_s + ψ̇ t
//! ```
//!
//! The state is `y = (p, v, S)` (centre of mass in m, its velocity in m/s,
//! dissipated energy in J); the moment that drives the orientation is
//! whatever it has to be, and the translation obeys
//!
//! ```text
//! ṗ = v,   m v̇ = Σ (Q n + F_t) + F_a − m g e_z,   Ṡ = Σ ((Q − Q_e) δ̇ − F_t·v_t)
//! ```
//!
//! with the contact forces of [`Peg3d::forces`] (its pairs mouth edge vs
//! peg side, rim vs bore wall, top face and bore bottom; any further pair of
//! [`Peg3d`] is left out, so that it is never counted twice) plus one pair of
//! this module: the peg's bottom-rim torus against the hole's mouth-edge
//! torus ([`rim_mouth`]), where the rigid three-point peg's bottom edge rests
//! on the hole edge at B1 and B2. Its gap is exact: the distance between the
//! two tori is the distance between their tube-centre circles minus both
//! tube radii, and the distance from a point `c` to the mouth's circle
//! (radius `R + ρ_h` at height `−ρ_h`) is
//! `√((|c_xy| − R − ρ_h)² + (c_z + ρ_h)²)`, so the gap is a function of the
//! rim angle `β` alone; its local minima are found by a scan and golden
//! section. Its normal force uses the stiffness `k` of
//! [`HertzMode::Fixed`] and the same damping and
//! friction law as the other pairs (see [`super::system`]).

use super::params::{HertzMode, Peg3dParams};
use super::search::Pair;
use super::system::{Peg3d, pose_state};
use crate::hertz::HertzError;
use crate::system::OdeSystem;
use nalgebra::{SVector, UnitQuaternion, Vector3};
use std::f64::consts::TAU;

/// Steady rates of nutation and precession from a start orientation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// γ at `t = 0` (rad).
    pub gamma: f64,
    /// γ̇ (1/s); negative aligns the peg.
    pub gammadot: f64,
    /// ψ at `t = 0` (rad).
    pub psi: f64,
    /// ψ̇ (1/s); positive is counter-clockwise seen from above.
    pub psidot: f64,
}

impl Motion {
    /// `(γ(t), ψ(t))` (rad).
    pub fn angles(&self, t: f64) -> (f64, f64) {
        (self.gamma + self.gammadot * t, self.psi + self.psidot * t)
    }

    /// `R(t) = R_z(ψ) R_y(−γ)`: the axis tilts by γ towards `−e_η`.
    pub fn orientation(&self, t: f64) -> UnitQuaternion<f64> {
        let (gamma, psi) = self.angles(t);
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), psi)
            * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -gamma)
    }

    /// `ω_body = Rᵀ (ψ̇ e_z − γ̇ e_n)` (1/s), `e_n = (−sin ψ, cos ψ, 0)`.
    pub fn omega_body(&self, t: f64) -> Vector3<f64> {
        let (_, psi) = self.angles(t);
        let e_n = Vector3::new(-psi.sin(), psi.cos(), 0.0);
        let omega = Vector3::z() * self.psidot - e_n * self.gammadot;
        self.orientation(t).inverse() * omega
    }
}

/// One penetrating local minimum of the rim–mouth gap.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RimMouthPoint {
    /// Angle along the rim's tube-centre circle, body frame (rad).
    pub angle: f64,
    /// Penetration `δ = −g > 0` (m).
    pub penetration: f64,
    /// Unit direction of the contact force on the peg, hole frame.
    pub normal: Vector3<f64>,
    /// Contact point, midway between the two surfaces (m).
    pub point: Vector3<f64>,
}

/// Gap `g(β)` of the rim torus against the mouth torus, the force
/// direction on the peg (from the mouth's circle to the rim's) and the
/// closest points `(c, m)` of the rim's and the mouth's tube-centre circles.
fn rim_mouth_gap(
    prm: &Peg3dParams,
    centre: &Vector3<f64>,
    q: &UnitQuaternion<f64>,
    beta: f64,
) -> (f64, Vector3<f64>, Vector3<f64>, Vector3<f64>) {
    let rr = prm.peg_radius() - prm.rim_fillet;
    let c = centre
        + q * Vector3::new(
            rr * beta.cos(),
            rr * beta.sin(),
            prm.rim_fillet - 0.5 * prm.length,
        );
    let rho = c.xy().norm();
    let rc = prm.bore_radius() + prm.mouth_fillet;
    let m = Vector3::new(rc * c.x / rho, rc * c.y / rho, -prm.mouth_fillet);
    let u = c - m;
    let dist = u.norm();
    (dist - prm.rim_fillet - prm.mouth_fillet, u / dist, c, m)
}

/// One local minimum of the rim–mouth gap (penetrating or not).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RimMouthMinimum {
    /// Angle along the rim's tube-centre circle, body frame (rad).
    pub angle: f64,
    /// Gap `g` (m), negative when the tori overlap.
    pub gap: f64,
    /// Unit direction of the contact force on the peg, hole frame.
    pub normal: Vector3<f64>,
    /// Midway point between the two surfaces (m).
    pub point: Vector3<f64>,
    /// Whether the closest points lie on the quarters of both tori that
    /// exist: the mouth fillet's upper inner quarter (force direction `n`
    /// with `n_z ≥ 0`, pointing towards the hole's axis) and the rim
    /// fillet's lower outer quarter (`n·a ≥ 0`, pointing towards the peg's
    /// axis).
    pub valid: bool,
}

/// Samples of the scan along the rim.
const RIM_SAMPLES: usize = 256;

/// Every local minimum of the rim–mouth gap at pose `(centre, q)` below
/// `margin` (m): a scan at 256 angles, each discrete local
/// minimum refined by golden section in the bracket of its neighbours to
/// `10⁻¹⁰` rad; minima closer than `10⁻⁹` rad are one.
pub fn rim_mouth_minima(
    prm: &Peg3dParams,
    centre: &Vector3<f64>,
    q: &UnitQuaternion<f64>,
    margin: f64,
) -> Vec<RimMouthMinimum> {
    let step = TAU / RIM_SAMPLES as f64;
    let gap = |b: f64| rim_mouth_gap(prm, centre, q, b).0;
    let samples: Vec<f64> = (0..RIM_SAMPLES).map(|k| gap(k as f64 * step)).collect();
    let axis = q * Vector3::z();
    let mut out: Vec<RimMouthMinimum> = Vec::new();
    for k in 0..RIM_SAMPLES {
        let g = samples[k];
        let prev = samples[(k + RIM_SAMPLES - 1) % RIM_SAMPLES];
        let next = samples[(k + 1) % RIM_SAMPLES];
        if !(g < margin && g <= prev && g < next) {
            continue;
        }
        let beta = golden(&gap, (k as f64 - 1.0) * step, (k as f64 + 1.0) * step).rem_euclid(TAU);
        if out.iter().any(|o| {
            let d = (o.angle - beta).rem_euclid(TAU);
            d.min(TAU - d) <= 1e-9
        }) {
            continue;
        }
        let (g, n, c, m) = rim_mouth_gap(prm, centre, q, beta);
        let radial_mouth = Vector3::new(m.x, m.y, 0.0);
        let radial_peg = {
            let rel = c - centre;
            rel - axis * rel.dot(&axis)
        };
        let valid = n.z >= 0.0
            && n.dot(&radial_mouth) <= 0.0
            && n.dot(&axis) >= 0.0
            && n.dot(&radial_peg) <= 0.0;
        let surface_mouth = m + n * prm.mouth_fillet;
        let surface_rim = c - n * prm.rim_fillet;
        out.push(RimMouthMinimum {
            angle: beta,
            gap: g,
            normal: n,
            point: 0.5 * (surface_mouth + surface_rim),
            valid,
        });
    }
    out
}

/// The penetrating, valid minima of [`rim_mouth_minima`] with the margin
/// `r (2π/256)` (how far the gap can dip between two samples: where the two
/// tube circles nearly cross, the gap is V-shaped in `β` on a scale far
/// below the sample spacing, with slopes up to `r`): the contacts of the
/// rim torus on the mouth torus.
pub fn rim_mouth(
    prm: &Peg3dParams,
    centre: &Vector3<f64>,
    q: &UnitQuaternion<f64>,
) -> Vec<RimMouthPoint> {
    let step = TAU / RIM_SAMPLES as f64;
    rim_mouth_minima(prm, centre, q, prm.peg_radius() * step)
        .into_iter()
        .filter(|m| m.valid && m.gap < 0.0)
        .map(|m| RimMouthPoint {
            angle: m.angle,
            penetration: -m.gap,
            normal: m.normal,
            point: m.point,
        })
        .collect()
}

/// The minimum of `f` in `[lo, hi]` by golden section, to `10⁻¹⁰`.
fn golden(f: &dyn Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let inv_phi = 0.5 * (5.0_f64.sqrt() - 1.0);
    let mut a = hi - inv_phi * (hi - lo);
    let mut b = lo + inv_phi * (hi - lo);
    let (mut fa, mut fb) = (f(a), f(b));
    while hi - lo > 1e-10 {
        if fa <= fb {
            hi = b;
            b = a;
            fb = fa;
            a = hi - inv_phi * (hi - lo);
            fa = f(a);
        } else {
            lo = a;
            a = b;
            fa = fb;
            b = lo + inv_phi * (hi - lo);
            fb = f(b);
        }
    }
    0.5 * (lo + hi)
}

/// Which pair a contact of the prescribed peg belongs to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Site {
    /// A pair of [`Peg3d`].
    Pair(Pair),
    /// The rim torus against the mouth torus ([`rim_mouth`]).
    RimMouth,
}

/// One contact's force on the peg.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SiteForce {
    /// The pair.
    pub site: Site,
    /// Contact point, hole frame (m).
    pub point: Vector3<f64>,
    /// Unit direction of the normal force on the peg.
    pub normal: Vector3<f64>,
    /// Penetration (m).
    pub penetration: f64,
    /// Normal force `Q` (N).
    pub normal_force: f64,
    /// Friction force on the peg (N).
    pub friction: Vector3<f64>,
    /// Dissipation rate `(Q − Q_e) δ̇ − F_t·v_t` (W).
    pub dissipation: f64,
}

/// The refusal of [`HertzMode::Curvature`] (field `hertz`).
fn curvature_mode() -> HertzError {
    HertzError::Invalid {
        field: "hertz".to_owned(),
        value: 0.0,
        reason: "the prescribed-orientation peg needs a fixed stiffness (HertzMode::Fixed)",
    }
}

/// The compliant 3-D peg whose orientation follows [`Motion`].
pub struct PrescribedPeg {
    /// The peg; its `hertz` must be [`HertzMode::Fixed`].
    pub peg: Peg3d,
    /// The prescribed orientation.
    pub motion: Motion,
}

impl PrescribedPeg {
    /// The system of `params` (fixed Hertz stiffness) driven along `motion`.
    ///
    /// # Errors
    /// [`HertzError::Invalid`] (field `hertz`) unless the stiffness is
    /// [`HertzMode::Fixed`] with a finite positive `k`: the rim–mouth pair
    /// has no curvature-based stiffness.
    pub fn try_new(params: Peg3dParams, motion: Motion) -> Result<PrescribedPeg, HertzError> {
        match params.hertz {
            HertzMode::Fixed(k) if k.is_finite() && k > 0.0 => Ok(PrescribedPeg {
                peg: Peg3d::new(params),
                motion,
            }),
            HertzMode::Fixed(k) => Err(HertzError::Invalid {
                field: "hertz".to_owned(),
                value: k,
                reason: "the fixed stiffness must be finite and > 0",
            }),
            HertzMode::Curvature => Err(curvature_mode()),
        }
    }

    /// The 15-state `(p, q(t), v, ω_body(t), 0, S)` of the full model.
    pub fn full_state(&self, t: f64, y: &SVector<f64, 7>) -> SVector<f64, 15> {
        let mut full = pose_state(
            Vector3::new(y[0], y[1], y[2]),
            self.motion.orientation(t),
            Vector3::new(y[3], y[4], y[5]),
            self.motion.omega_body(t),
        );
        full[14] = y[6];
        full
    }

    /// Every contact force at time `t`, state `y`.
    ///
    /// # Errors
    /// As [`Peg3d::forces`]; [`HertzError::Invalid`] (field `hertz`) when
    /// the parameters were changed to [`HertzMode::Curvature`].
    pub fn forces(&self, t: f64, y: &SVector<f64, 7>) -> Result<Vec<SiteForce>, HertzError> {
        let full = self.full_state(t, y);
        let prm = &self.peg.params;
        let x = Peg3d::pose(&full);
        let centre = Vector3::new(x[0], x[1], x[2]);
        let v = Vector3::new(y[3], y[4], y[5]);
        let q = self.motion.orientation(t);
        let omega = q * self.motion.omega_body(t);
        let mut out = Vec::new();
        let known = |p: Pair| {
            matches!(
                p,
                Pair::EdgeSide | Pair::RimWall | Pair::RimTop | Pair::RimBottom
            )
        };
        for f in self.peg.forces(&full)? {
            if !known(f.contact.pair) {
                continue;
            }
            let one = [f];
            let w = Peg3d::wrench(&full, &one);
            out.push(SiteForce {
                site: Site::Pair(f.contact.pair),
                point: f.contact.point,
                normal: f.contact.normal,
                penetration: f.contact.penetration,
                normal_force: f.normal_force,
                friction: f.friction,
                dissipation: w[6],
            });
        }
        let HertzMode::Fixed(k) = prm.hertz else {
            return Err(curvature_mode());
        };
        for c in rim_mouth(prm, &centre, &q) {
            let d = c.penetration;
            let qe = k * d * d.sqrt();
            let vc = v + omega.cross(&(c.point - centre));
            let vn = c.normal.dot(&vc);
            let qn = (qe * (1.0 - prm.damping * vn)).max(0.0);
            let vt = vc - c.normal * vn;
            let ft = vt
                * (-prm.friction * qn
                    / (vt.norm_squared() + prm.slip_scale * prm.slip_scale).sqrt());
            out.push(SiteForce {
                site: Site::RimMouth,
                point: c.point,
                normal: c.normal,
                penetration: d,
                normal_force: qn,
                friction: ft,
                dissipation: -(qn - qe) * vn - ft.dot(&vt),
            });
        }
        Ok(out)
    }
}

impl OdeSystem<7> for PrescribedPeg {
    /// `(v, (Σ F_contact + F_a)/m − g e_z, Ṡ)`; NaN (which stops the
    /// integrators) when [`PrescribedPeg::forces`] fails.
    fn rhs(&self, t: f64, y: &SVector<f64, 7>) -> SVector<f64, 7> {
        let Ok(forces) = self.forces(t, y) else {
            return SVector::repeat(f64::NAN);
        };
        let prm = &self.peg.params;
        let mut f = prm.force - Vector3::z() * (prm.mass * prm.gravity);
        let mut s = 0.0;
        for c in &forces {
            f += c.normal * c.normal_force + c.friction;
            s += c.dissipation;
        }
        let a = f / prm.mass;
        SVector::<f64, 7>::from_column_slice(&[y[3], y[4], y[5], a.x, a.y, a.z, s])
    }
}
