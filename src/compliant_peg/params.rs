//! Checked parameters of the compliant peg-in-hole and their translation
//! into the generated models' parameters (`From`, field by field).

use nalgebra::SVector;

use super::geometry::{ContactPair, PegHoleGeometry};
use crate::generated::{compliant_peg as all, compliant_peg_elastic as elastic};
use crate::hertz::{EllipticityMethod, HertzError, Material};

/// Number of model parameters (the fields of
/// [`generated::compliant_peg::Params`](all::Params), which
/// `compliant_peg_lean` shares).
pub const N_PARAMS: usize = all::Params::<f64>::NAMES.len();

/// Number of parameters of the elastic-friction model (the fields of
/// [`generated::compliant_peg_elastic::Params`](elastic::Params): those of
/// [`N_PARAMS`] and `g_star`, `delta_floor`, `tau_t`).
pub const N_PARAMS_ELASTIC: usize = elastic::Params::<f64>::NAMES.len();

/// Penetration floor `δ_0` (m) of the elastic friction law's utilisation
/// rate: below it the rate uses `δ_0` instead of `δ` (out of contact the
/// normal force, and so the friction force, is zero anyway).
pub const DELTA_FLOOR: f64 = 1e-9;

/// The tangential friction law at the contacts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FrictionLaw {
    /// Regularized Coulomb `F = −μ f v/√(v² + v_s²)`: no extra state; a
    /// stuck contact creeps at a speed of the order of `v_s`, and the
    /// viscous branch (slope `μ f / v_s`) is stiff.
    #[default]
    Regularized,
    /// Hertz–Mindlin tangential compliance (`k_t = 8 G* a`) capped by
    /// Coulomb: a stuck contact holds without creep and slides at
    /// `μ f`; one utilisation state per contact, always all four contacts.
    /// See `docs/compliant.md`.
    Elastic,
}

/// Which contacts the model includes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum ContactSet {
    /// All four (either lean, every contact state of the paper's Fig. 4).
    #[default]
    All,
    /// Only the left edge and right wall (the paper's Fig. 5 lean, θ > 0).
    Lean,
}

/// Everything that defines a compliant peg and hole (SI units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompliantSpec {
    /// Peg and hole dimensions and fillets.
    pub geometry: PegHoleGeometry,
    /// Peg material.
    pub peg: Material,
    /// Hole material.
    pub hole: Material,
    /// Peg mass `m` (kg).
    pub mass: f64,
    /// Moment of inertia `J` about the centre of mass (kg·m²).
    pub inertia: f64,
    /// Distance `l_c` from the centre of mass to the bottom face (m).
    pub com_height: f64,
    /// Coulomb friction coefficient `μ ≥ 0`.
    pub friction: f64,
    /// Velocity scale `v_s > 0` of the regularized friction law (m/s).
    pub slip_velocity: f64,
    /// Tilt at which the Hertz stiffness is evaluated (rad).
    pub reference_tilt: f64,
    /// Contacts included.
    pub contacts: ContactSet,
    /// Hunt–Crossley damping coefficient `α ≥ 0` (s/m): the normal force is
    /// `k δ^{3/2} max(0, 1 + α δ̇)`. 0 (the default) gives elastic contacts.
    pub damping: f64,
    /// The tangential friction law (default regularized).
    pub friction_law: FrictionLaw,
    /// Damping time `τ_t ≥ 0` (s) of the elastic law's tangential springs:
    /// damping `η = τ_t k_t` on their stick motion (default
    /// [`TANGENTIAL_DAMPING`]; unused by the regularized law).
    pub tangential_damping: f64,
}

/// Default damping time `τ_t` (s) of the elastic law's tangential springs:
/// about a tenth of critical damping for the reference steel peg
/// (`k_t ≈ 3·10⁶ N/m`, `m ≈ 0.4 kg`: `2√(m/k_t) ≈ 7·10⁻⁴ s`).
pub const TANGENTIAL_DAMPING: f64 = 1e-4;

/// Validated parameters with the Hertz contacts set up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompliantParams {
    /// The specification.
    pub spec: CompliantSpec,
    /// Hertz contacts of edge and wall at the reference tilt.
    pub pair: ContactPair,
}

/// The applied loads in the peg's frame, the paper's (50) (constant in time).
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct Load {
    /// Axial force `f₁` (N), positive pushing the peg into the hole.
    pub axial: f64,
    /// Radial force `f₂` (N), along `e_r` (towards `+x` at θ = 0).
    pub radial: f64,
    /// Torque `M` (N·m) about the centre of mass, positive increasing θ.
    pub torque: f64,
}

impl CompliantSpec {
    /// The reference peg of `scenes/insert_compliant.toml`: a solid steel
    /// cylinder of length `length` (m) in a steel hole of diameter `d` (m)
    /// with clearance ratio `c`, 0.2 mm fillets, centre of mass at
    /// mid-length, friction `mu`, `v_s = 1e-5 m/s`, all four contacts.
    ///
    /// ```
    /// use pegdyn::compliant_peg::{CompliantParams, CompliantSpec};
    /// let spec = CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.1);
    /// assert!((spec.mass - 1.535).abs() < 1e-3);
    /// assert!(CompliantParams::try_new(spec).is_ok());
    /// ```
    pub fn steel_cylinder(d: f64, c: f64, length: f64, mu: f64) -> CompliantSpec {
        let r = 0.5 * d * (1.0 - c);
        let mass = 7850.0 * std::f64::consts::PI * r * r * length;
        CompliantSpec {
            geometry: PegHoleGeometry {
                hole_diameter: d,
                peg_radius: r,
                peg_fillet: super::geometry::DEFAULT_FILLET,
                hole_fillet: super::geometry::DEFAULT_FILLET,
            },
            peg: Material::STEEL,
            hole: Material::STEEL,
            mass,
            inertia: mass * (3.0 * r * r + length * length) / 12.0,
            com_height: 0.5 * length,
            friction: mu,
            slip_velocity: 1e-5,
            reference_tilt: 0.0,
            contacts: ContactSet::All,
            damping: 0.0,
            friction_law: FrictionLaw::Regularized,
            tangential_damping: TANGENTIAL_DAMPING,
        }
    }
}

fn invalid(field: &str, value: f64, reason: &'static str) -> HertzError {
    HertzError::Invalid {
        field: field.to_owned(),
        value,
        reason,
    }
}

impl CompliantParams {
    /// Checks `spec` and sets up the Hertz contacts. Errors name the field:
    /// `mass`, `inertia`, `com_height` (finite, `> 0`, above the fillet),
    /// `friction` (finite, `≥ 0`), `slip_velocity` (finite, `> 0`),
    /// `reference_tilt` (below 0.8 of the wall contact's split tilt),
    /// `peg.*`, `hole.*` for the materials.
    pub fn try_new(spec: CompliantSpec) -> Result<CompliantParams, HertzError> {
        let g = &spec.geometry;
        // Re-check the geometry and materials (their fields are public).
        PegHoleGeometry::try_new(g.hole_diameter, g.peg_radius, g.peg_fillet, g.hole_fillet)?;
        Material::try_new(spec.peg.youngs_modulus, spec.peg.poisson_ratio)
            .map_err(|e| e.with_prefix("peg"))?;
        Material::try_new(spec.hole.youngs_modulus, spec.hole.poisson_ratio)
            .map_err(|e| e.with_prefix("hole"))?;
        for (field, v) in [
            ("mass", spec.mass),
            ("inertia", spec.inertia),
            ("com_height", spec.com_height),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(invalid(field, v, "must be finite and > 0"));
            }
        }
        if spec.com_height <= g.peg_fillet {
            return Err(invalid(
                "com_height",
                spec.com_height,
                "must exceed peg_fillet",
            ));
        }
        if !(spec.friction.is_finite() && spec.friction >= 0.0) {
            return Err(invalid(
                "friction",
                spec.friction,
                "must be finite and >= 0",
            ));
        }
        if spec.friction_law == FrictionLaw::Elastic && spec.friction <= 0.0 {
            return Err(invalid(
                "friction",
                spec.friction,
                "must be > 0 with the elastic friction law (use the regularized law without friction)",
            ));
        }
        if !(spec.tangential_damping.is_finite() && spec.tangential_damping >= 0.0) {
            return Err(invalid(
                "tangential_damping",
                spec.tangential_damping,
                "must be finite and >= 0",
            ));
        }
        if !(spec.damping.is_finite() && spec.damping >= 0.0) {
            return Err(invalid("damping", spec.damping, "must be finite and >= 0"));
        }
        if !(spec.slip_velocity.is_finite() && spec.slip_velocity > 0.0) {
            return Err(invalid(
                "slip_velocity",
                spec.slip_velocity,
                "must be finite and > 0",
            ));
        }
        let tilt_ok = spec.reference_tilt.is_finite()
            && spec.reference_tilt.abs() < 0.8 * g.wall_split_tilt();
        if !tilt_ok {
            return Err(invalid(
                "reference_tilt",
                spec.reference_tilt,
                "must be below 0.8 of the tilt at which the wall contact splits (see docs/contact-geometry.md)",
            ));
        }
        let pair = ContactPair::try_new(
            g,
            &spec.peg,
            &spec.hole,
            spec.reference_tilt.abs(),
            EllipticityMethod::Exact,
        )?;
        Ok(CompliantParams { spec, pair })
    }

    /// The generated model's parameter vector under `load` (the same for
    /// `compliant_peg` and `compliant_peg_lean`, which share their
    /// `Params`).
    pub fn vector(&self, load: &Load) -> SVector<f64, N_PARAMS> {
        all::Params::from((self, load)).into()
    }

    /// Effective shear modulus `G*` (Pa) of Mindlin's tangential stiffness
    /// `k_t = 8 G* a`: `1/G* = (2 − ν₁)/G₁ + (2 − ν₂)/G₂`, `G = E/(2(1 + ν))`.
    pub fn shear_modulus(&self) -> f64 {
        let part = |m: &crate::hertz::Material| {
            let g = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
            (2.0 - m.poisson_ratio) / g
        };
        1.0 / (part(&self.spec.peg) + part(&self.spec.hole))
    }

    /// The elastic-friction model's parameter vector under `load`.
    pub fn vector_elastic(&self, load: &Load) -> SVector<f64, N_PARAMS_ELASTIC> {
        elastic::Params::from((self, load)).into()
    }
}

impl From<(&CompliantParams, &Load)> for all::Params<f64> {
    /// The compliant planar peg's parameters under `load`: the spec's
    /// dimensions, mass and friction, the Hertz stiffnesses and
    /// coefficients of the edge and wall contacts, and the load.
    fn from((c, load): (&CompliantParams, &Load)) -> Self {
        let (s, g) = (&c.spec, &c.spec.geometry);
        let (edge, wall) = (&c.pair.edge, &c.pair.wall);
        all::Params {
            m: s.mass,
            J: s.inertia,
            r: g.peg_radius,
            l_c: s.com_height,
            D: g.hole_diameter,
            rho_p: g.peg_fillet,
            rho_h: g.hole_fillet,
            mu: s.friction,
            v_s: s.slip_velocity,
            k_edge: edge.stiffness(),
            k_wall: wall.stiffness(),
            f1: load.axial,
            f2: load.radial,
            M: load.torque,
            e_star: edge.contact_modulus,
            edge_sum: edge.sum_curvature,
            edge_ma: edge.coefficients.m_a,
            edge_mb: edge.coefficients.m_b,
            edge_dstar: edge.coefficients.delta_star,
            wall_sum: wall.sum_curvature,
            wall_ma: wall.coefficients.m_a,
            wall_mb: wall.coefficients.m_b,
            wall_dstar: wall.coefficients.delta_star,
            hc_alpha: s.damping,
        }
    }
}

impl From<(&CompliantParams, &Load)> for elastic::Params<f64> {
    /// The elastic-friction model's parameters under `load`: those of the
    /// regularized model, the effective shear modulus, the penetration
    /// floor [`DELTA_FLOOR`] and the tangential damping time.
    fn from((c, load): (&CompliantParams, &Load)) -> Self {
        let b = all::Params::from((c, load));
        elastic::Params {
            m: b.m,
            J: b.J,
            r: b.r,
            l_c: b.l_c,
            D: b.D,
            rho_p: b.rho_p,
            rho_h: b.rho_h,
            mu: b.mu,
            v_s: b.v_s,
            k_edge: b.k_edge,
            k_wall: b.k_wall,
            f1: b.f1,
            f2: b.f2,
            M: b.M,
            e_star: b.e_star,
            edge_sum: b.edge_sum,
            edge_ma: b.edge_ma,
            edge_mb: b.edge_mb,
            edge_dstar: b.edge_dstar,
            wall_sum: b.wall_sum,
            wall_ma: b.wall_ma,
            wall_mb: b.wall_mb,
            wall_dstar: b.wall_dstar,
            hc_alpha: b.hc_alpha,
            g_star: c.shear_modulus(),
            delta_floor: DELTA_FLOOR,
            tau_t: c.spec.tangential_damping,
        }
    }
}
