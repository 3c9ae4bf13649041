//! Hand-derived geometry and kinematics of the peg leaning on the hole edge
//! at three points K, B1, B2 (paper eqs. (1)–(17), corrected; see
//! `docs/rigid-peg.md` and `docs/formula-departures.md`).
//!
//! Frames and conventions (all lengths in m, angles in rad):
//! - fixed frame O1xyz, origin at the centre of the hole-edge circle
//!   (radius D/2, plane z = 0), z up along the hole axis;
//! - symmetry-plane direction e_η = (cos ψ, sin ψ, 0), node direction
//!   e_n = e_z × e_η = (−sin ψ, cos ψ, 0); ψ̇ > 0 is counter-clockwise seen
//!   from above;
//! - peg axis (upwards) u = −sin γ e_η + cos γ e_z, in-plane normal
//!   w = cos γ e_η + sin γ e_z;
//! - angular velocity ω = ψ̇ e_z − γ̇ e_n (Euler precession ψ and nutation γ,
//!   spin angle held fixed);
//! - K = −(D/2) e_η; B1 = S1 e_η + b e_n (the contact that leads when
//!   ψ̇ > 0), B2 = S1 e_η − b e_n.
//!
//! Near γ0 = arccos(d/D) the differences d − D cos γ and D/2 − S1 cancel;
//! they are evaluated as 2D sin((γ+γ0)/2) sin((γ−γ0)/2) and
//! (d − D cos γ) cos γ / sin²γ (exact forms, no cancellation).

use nalgebra::{Matrix3, Matrix3x2, Vector2, Vector3};

use crate::rigid_peg::{PegParams, RigidError};

/// Planar (γ-only) geometry of the three-point contact, in the symmetry
/// plane O1ηz (paper eqs. (1)–(5)), with the γ-derivatives of the centre of
/// mass coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Geometry {
    /// γ (rad).
    pub gamma: f64,
    /// c = d − D cos γ (m), evaluated without cancellation.
    pub c: f64,
    /// a1 = OO1 = (d − D cos γ)/(2 sin γ) (m), eq. (1).
    pub a1: f64,
    /// a2 = OO2 = (D − d cos γ)/(2 sin γ) (m), eq. (1).
    pub a2: f64,
    /// S1 = O1B = (a2 − a1 cos γ)/sin γ (m), eq. (2).
    pub s1: f64,
    /// S2 = O2B = (a2 cos γ − a1)/sin γ (m), eq. (2) with the sign corrected.
    pub s2: f64,
    /// b = BB1 = √(D²/4 − S1²) (m).
    pub b: f64,
    /// sin τ = b/(D/2).
    pub sin_tau: f64,
    /// cos τ = S1/(D/2).
    pub cos_tau: f64,
    /// η_C (m), eq. (3).
    pub eta_c: f64,
    /// z_C (m), eq. (3).
    pub z_c: f64,
    /// dη_C/dγ (m).
    pub deta_c: f64,
    /// dz_C/dγ = η_C + S1 (m).
    pub dz_c: f64,
    /// d²η_C/dγ² (m).
    pub d2eta_c: f64,
    /// d²z_C/dγ² (m).
    pub d2z_c: f64,
    /// KL = 2 a1 / sin γ (m), eq. (5).
    pub kl: f64,
    /// BL = 2 √(a1² + S1²) (m), eq. (5).
    pub bl: f64,
}

impl Geometry {
    /// The geometry at nutation angle `gamma`.
    ///
    /// # Errors
    /// [`RigidError::NotThreePoint`] unless γ0 < γ < π/2 (at γ ≤ γ0 the points
    /// B1, B2 do not exist; b would be imaginary).
    pub fn try_new(p: &PegParams, gamma: f64) -> Result<Geometry, RigidError> {
        let gamma0 = p.gamma0();
        if !(gamma > gamma0 && gamma < std::f64::consts::FRAC_PI_2) {
            return Err(RigidError::NotThreePoint { gamma, gamma0 });
        }
        Ok(Geometry::new_unchecked(p, gamma, gamma0))
    }

    /// The geometry without the range check; `gamma0` must be `p.gamma0()`.
    pub fn new_unchecked(p: &PegParams, gamma: f64, gamma0: f64) -> Geometry {
        let (dh, dp, h) = (p.hole_diameter, p.peg_diameter, p.height);
        let (s, co) = gamma.sin_cos();
        // d − D cos γ = D (cos γ0 − cos γ), as a product (stable near γ0).
        let c = 2.0 * dh * (0.5 * (gamma + gamma0)).sin() * (0.5 * (gamma - gamma0)).sin();
        // D − d cos γ = (D − d) + 2 d sin²(γ/2) (no cancellation).
        let e = (dh - dp) + 2.0 * dp * (0.5 * gamma).sin().powi(2);
        let a1 = c / (2.0 * s);
        let a2 = e / (2.0 * s);
        let s1 = (a2 - a1 * co) / s;
        let s2 = (a2 * co - a1) / s;
        // D/2 − S1 = c cos γ / sin²γ;  b² = (D/2 − S1)(D/2 + S1).
        let gap = c * co / (s * s);
        let b = (gap * (dh - gap)).sqrt();
        let half = 0.5 * dh;
        let lever = 0.5 * h - a2;
        let eta_c = -lever * s;
        let z_c = lever * co + a1;
        // a1' = a2/sin γ, a2' = a1/sin γ.
        let deta_c = a1 - lever * co;
        let dz_c = eta_c + s1;
        let d2eta_c = (a2 + a1 * co) / s + lever * s;
        // S1' = 2(a1 − a2 cos γ)/sin²γ = −2 S2 / sin γ.
        let d2z_c = deta_c - 2.0 * s2 / s;
        Geometry {
            gamma,
            c,
            a1,
            a2,
            s1,
            s2,
            b,
            sin_tau: b / half,
            cos_tau: s1 / half,
            eta_c,
            z_c,
            deta_c,
            dz_c,
            d2eta_c,
            d2z_c,
            kl: 2.0 * a1 / s,
            bl: 2.0 * a1.hypot(s1),
        }
    }

    /// Instantaneous centre L of the planar motion, (η_L, z_L) = (−S1, 2 a1)
    /// (m), eq. (4b).
    pub fn centre_l(&self) -> (f64, f64) {
        (-self.s1, 2.0 * self.a1)
    }
}

/// The orthonormal frame (e_η, e_n, e_z) of the symmetry plane at ψ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// e_η = (cos ψ, sin ψ, 0).
    pub eta: Vector3<f64>,
    /// e_n = e_z × e_η = (−sin ψ, cos ψ, 0).
    pub n: Vector3<f64>,
    /// e_z.
    pub z: Vector3<f64>,
}

impl Frame {
    /// The frame at precession angle `psi`.
    pub fn new(psi: f64) -> Frame {
        let (s, c) = psi.sin_cos();
        Frame {
            eta: Vector3::new(c, s, 0.0),
            n: Vector3::new(-s, c, 0.0),
            z: Vector3::z(),
        }
    }

    /// The fixed-frame vector with components (η, n, z).
    pub fn at(&self, eta: f64, n: f64, z: f64) -> Vector3<f64> {
        self.eta * eta + self.n * n + self.z * z
    }

    /// The rotation R = [e_η | e_n | e_z]: fixed = R · local.
    pub fn matrix(&self) -> Matrix3<f64> {
        Matrix3::from_columns(&[self.eta, self.n, self.z])
    }
}

/// Positions of the peg's points at (γ, ψ) in the fixed frame (eqs. (6)–(9),
/// corrected), and the contact normals (eqs. (14)–(17), corrected).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    /// Planar geometry at γ.
    pub geo: Geometry,
    /// Frame at ψ.
    pub frame: Frame,
    /// Peg axis, unit, upwards.
    pub axis: Vector3<f64>,
    /// Centre of mass C.
    pub c: Vector3<f64>,
    /// Intersection O of the peg and hole axes, (0, 0, a1).
    pub o: Vector3<f64>,
    /// Centre O2 of the peg's bottom face, O − a2 u.
    pub o2: Vector3<f64>,
    /// Contacts `[K, B1, B2]`.
    pub contacts: [Vector3<f64>; 3],
    /// Unit normals of the contact forces on the peg, `[n_K, n_B1, n_B2]`.
    pub normals: [Vector3<f64>; 3],
    /// The same points and normals in frame components (η, n, z), computed
    /// directly (not projected), so that the lateral (e_n) components keep
    /// full relative accuracy when b → 0.
    pub local: LocalPose,
}

/// Centre of mass, contacts and normals in components along (e_η, e_n, e_z).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LocalPose {
    /// C = (η_C, 0, z_C).
    pub c: Vector3<f64>,
    /// `[K, B1, B2]`.
    pub contacts: [Vector3<f64>; 3],
    /// `[n_K, n_B1, n_B2]`.
    pub normals: [Vector3<f64>; 3],
}

impl Pose {
    /// The pose at (γ, ψ).
    ///
    /// # Errors
    /// As [`Geometry::try_new`].
    pub fn try_new(p: &PegParams, gamma: f64, psi: f64) -> Result<Pose, RigidError> {
        Ok(Pose::from_geometry(p, Geometry::try_new(p, gamma)?, psi))
    }

    /// The pose from an already computed geometry.
    pub fn from_geometry(p: &PegParams, geo: Geometry, psi: f64) -> Pose {
        let fr = Frame::new(psi);
        let rot = fr.matrix();
        let (s, co) = geo.gamma.sin_cos();
        let half = 0.5 * p.hole_diameter;
        let axis = fr.at(-s, 0.0, co);
        let o = fr.at(0.0, 0.0, geo.a1);
        let k = Vector3::new(-half, 0.0, 0.0);
        let b1 = Vector3::new(geo.s1, geo.b, 0.0);
        let b2 = Vector3::new(geo.s1, -geo.b, 0.0);
        // K: normal of the peg side in the symmetry plane, w = (cos γ, 0, sin γ).
        let n_k = Vector3::new(co, 0.0, s);
        // B1, B2: along B→O (common perpendicular of the two edge tangents),
        // |OB| = √(D²/4 + a1²).
        let ob = half.hypot(geo.a1);
        let n_b1 = Vector3::new(-geo.s1, -geo.b, geo.a1) / ob;
        let n_b2 = Vector3::new(-geo.s1, geo.b, geo.a1) / ob;
        let local = LocalPose {
            c: Vector3::new(geo.eta_c, 0.0, geo.z_c),
            contacts: [k, b1, b2],
            normals: [n_k, n_b1, n_b2],
        };
        Pose {
            geo,
            frame: fr,
            axis,
            c: rot * local.c,
            o,
            o2: o - axis * geo.a2,
            contacts: local.contacts.map(|v| rot * v),
            normals: local.normals.map(|v| rot * v),
            local,
        }
    }
}

/// Velocities at (γ, ψ, γ̇, ψ̇): centre of mass and the material velocity of
/// the peg at each contact (eqs. (10)–(13), corrected).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kinematics {
    /// Angular velocity ω = ψ̇ e_z − γ̇ e_n (1/s).
    pub omega: Vector3<f64>,
    /// Velocity of C (m/s).
    pub v_c: Vector3<f64>,
    /// Material velocity of the peg at `[K, B1, B2]` (m/s).
    pub v_contacts: [Vector3<f64>; 3],
    /// The same velocities in frame components (η, n, z).
    pub v_contacts_local: [Vector3<f64>; 3],
}

/// Velocity Jacobians: columns ∂v/∂γ̇, ∂v/∂ψ̇ of the centre of mass and of
/// the peg's material point at each contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jacobians {
    /// ∂v_C/∂q̇.
    pub c: Matrix3x2<f64>,
    /// ∂v_P/∂q̇ for P = K, B1, B2.
    pub contacts: [Matrix3x2<f64>; 3],
}

impl Pose {
    /// Jacobians in frame components (η, n, z): v_P = J_P q̇ with
    /// q̇ = (γ̇, ψ̇); ∂ω/∂γ̇ = −e_n, ∂ω/∂ψ̇ = e_z.
    pub fn jacobians_local(&self) -> Jacobians {
        let g = &self.geo;
        let (e_n, e_z) = (Vector3::y(), Vector3::z());
        let jc = Matrix3x2::new(g.deta_c, 0.0, 0.0, g.eta_c, g.dz_c, 0.0);
        let col = |p: &Vector3<f64>| {
            let r = p - self.local.c;
            Matrix3x2::from_columns(&[jc.column(0) - e_n.cross(&r), jc.column(1) + e_z.cross(&r)])
        };
        Jacobians {
            c: jc,
            contacts: self.local.contacts.map(|p| col(&p)),
        }
    }

    /// Jacobians in the fixed frame.
    pub fn jacobians(&self) -> Jacobians {
        let (rot, j) = (self.frame.matrix(), self.jacobians_local());
        Jacobians {
            c: rot * j.c,
            contacts: j.contacts.map(|m| rot * m),
        }
    }

    /// Velocities at this pose for generalized velocities `qdot = (γ̇, ψ̇)`.
    pub fn kinematics(&self, qdot: Vector2<f64>) -> Kinematics {
        let (rot, j) = (self.frame.matrix(), self.jacobians_local());
        let local = j.contacts.map(|m| m * qdot);
        Kinematics {
            omega: self.frame.z * qdot[1] - self.frame.n * qdot[0],
            v_c: rot * (j.c * qdot),
            v_contacts: local.map(|v| rot * v),
            v_contacts_local: local,
        }
    }
}
