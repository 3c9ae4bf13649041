//! Parameters of the compliant 3-D peg and the generated functions'
//! parameter vector (from `pegdyn::generated::compliant_peg_3d::Params`).

use crate::hertz::Material;
use nalgebra::{SVector, Vector3};

/// How each contact's Hertz stiffness `k` of `Q = k δ^{3/2}` is obtained.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HertzMode {
    /// From the principal curvatures of both surfaces at the contact point
    /// (Hertz's elliptical contact, recomputed at every evaluation).
    Curvature,
    /// One constant stiffness `k` (N/m^{3/2}) for every contact: the
    /// contact potential `(2/5) k δ^{5/2}` is then exact, which the energy
    /// tests use.
    Fixed(f64),
}

/// The peg, the hole, the materials, the loads and the contact laws. SI
/// units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peg3dParams {
    /// Peg diameter `d` (m).
    pub peg_diameter: f64,
    /// Peg length `L` (m).
    pub length: f64,
    /// Fillet radius of the peg's bottom rim `ρ_p` (m).
    pub rim_fillet: f64,
    /// Bore diameter `D` (m).
    pub hole_diameter: f64,
    /// Fillet radius of the hole's mouth edge `ρ_h` (m).
    pub mouth_fillet: f64,
    /// Bore depth `h_b` below the top face (m).
    pub bore_depth: f64,
    /// Mass `m` (kg).
    pub mass: f64,
    /// Transverse moment of inertia `J_t` about the centre of mass (kg·m²).
    pub inertia_transverse: f64,
    /// Axial moment of inertia `J_a` (kg·m²).
    pub inertia_axial: f64,
    /// Gravitational acceleration along `−z` (m/s²).
    pub gravity: f64,
    /// Constant applied force at the centre of mass, hole frame (N).
    pub force: Vector3<f64>,
    /// Constant applied moment, hole frame (N·m).
    pub moment: Vector3<f64>,
    /// Peg material.
    pub peg_material: Material,
    /// Block material.
    pub hole_material: Material,
    /// Coulomb friction coefficient `μ`.
    pub friction: f64,
    /// Velocity scale `v_s` of the regularized sign `v/√(v² + v_s²)` (m/s).
    pub slip_scale: f64,
    /// Hunt–Crossley damping `α` (s/m): normal force `k δ^{3/2} (1 + α δ̇)`.
    pub damping: f64,
    /// How the Hertz stiffness is obtained.
    pub hertz: HertzMode,
    /// The tangential friction law at the contacts. [`super::Peg3d`] (15
    /// states) applies the regularized law whatever this says; the elastic
    /// law needs the tangential displacements of
    /// [`super::elastic::ElasticPeg3d`], which requires
    /// [`FrictionLaw::Elastic`].
    pub friction_law: FrictionLaw,
    /// Damping time `τ_t ≥ 0` (s) of the elastic law's tangential springs:
    /// a damper `τ_t k_t` on their stick motion ([`super::mindlin`]).
    pub tangential_damping: f64,
}

/// The tangential friction law at the compliant 3-D peg's contacts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FrictionLaw {
    /// Regularized Coulomb `F_t = −μ Q v_t/√(|v_t|² + v_s²)`: no extra
    /// state; a stuck contact creeps at a speed of the order of `v_s`.
    #[default]
    Regularized,
    /// Mindlin's tangential compliance capped by Coulomb
    /// ([`super::mindlin`]): a tangential displacement per tracked contact
    /// in the state ([`super::elastic`]); a stuck contact holds without
    /// creep and a sliding one carries `μ Q`.
    Elastic,
}

/// Default damping time `τ_t` (s) of the elastic law's tangential springs:
/// none. A 3-D contact's tangential spring is stiff (`8 G* ϱ ≈ 8.5e8 N/m`
/// for a 10 mm steel peg seated on its ring, critical damping at
/// `τ_t ≈ 8 µs`); the planar peg's 1e-4 s would be an overdamped viscous
/// grip beyond the Coulomb force.
pub const TANGENTIAL_DAMPING: f64 = 0.0;

impl Peg3dParams {
    /// A solid steel cylinder of diameter `d` and length `l` in a steel
    /// block with bore `big_d`, fillets `rho_p`, `rho_h`, bore depth `depth`,
    /// density 7850 kg/m³, gravity 9.81 m/s², no applied loads, no friction,
    /// no damping, curvature-based Hertz stiffness, the regularized friction
    /// law.
    pub fn steel(d: f64, l: f64, big_d: f64, rho_p: f64, rho_h: f64, depth: f64) -> Peg3dParams {
        let r = 0.5 * d;
        let mass = 7850.0 * std::f64::consts::PI * r * r * l;
        Peg3dParams {
            peg_diameter: d,
            length: l,
            rim_fillet: rho_p,
            hole_diameter: big_d,
            mouth_fillet: rho_h,
            bore_depth: depth,
            mass,
            inertia_transverse: mass * (3.0 * r * r + l * l) / 12.0,
            inertia_axial: 0.5 * mass * r * r,
            gravity: 9.81,
            force: Vector3::zeros(),
            moment: Vector3::zeros(),
            peg_material: Material::STEEL,
            hole_material: Material::STEEL,
            friction: 0.0,
            slip_scale: 1e-4,
            damping: 0.0,
            hertz: HertzMode::Curvature,
            friction_law: FrictionLaw::Regularized,
            tangential_damping: TANGENTIAL_DAMPING,
        }
    }

    /// Peg radius `r = d/2` (m).
    pub fn peg_radius(&self) -> f64 {
        0.5 * self.peg_diameter
    }

    /// Bore radius `R = D/2` (m).
    pub fn bore_radius(&self) -> f64 {
        0.5 * self.hole_diameter
    }

    /// The generated functions' parameter vector, field by field
    /// ([`crate::generated::compliant_peg_3d::Params`]).
    pub fn vector(&self) -> SVector<f64, 16> {
        crate::generated::compliant_peg_3d::Params {
            r: self.peg_radius(),
            L: self.length,
            rho_p: self.rim_fillet,
            R: self.bore_radius(),
            rho_h: self.mouth_fillet,
            h_b: self.bore_depth,
            m: self.mass,
            J_t: self.inertia_transverse,
            J_a: self.inertia_axial,
            g: self.gravity,
            fa_x: self.force.x,
            fa_y: self.force.y,
            fa_z: self.force.z,
            ma_x: self.moment.x,
            ma_y: self.moment.y,
            ma_z: self.moment.z,
        }
        .into()
    }
}
