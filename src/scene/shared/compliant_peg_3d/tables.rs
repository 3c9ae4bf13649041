//! The tables shared by the scene kinds of the compliant 3-D peg: `[peg]`
//! (peg, hole, materials, contact law), `[wrist]`, `[robot]` and
//! `[criteria]`, each validated field by field against its declared range
//! ([`super::ranges`]).

use serde::Deserialize;

use crate::compliant_peg_3d::insertion::Held;
use crate::compliant_peg_3d::outcome::Criteria;
use crate::compliant_peg_3d::robot::{Descent, RobotMotion, Spiral};
use crate::compliant_peg_3d::wrist::WristParams;
use crate::compliant_peg_3d::{HertzMode, Peg3dParams};
use crate::hertz::Material;
use crate::scene::shared::material::{MaterialSpec, steel};
use crate::scene::validate::Checker;
use nalgebra::Vector3;

use super::ranges as r;

fn default_slip() -> f64 {
    1e-4
}
fn default_gravity() -> f64 {
    9.81
}

/// The `[peg]` table: the peg, the hole and the contact law (SI units).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PegTable {
    /// Bore diameter `D` (m).
    pub hole_diameter: f64,
    /// Clearance ratio `c = (D − d)/D`.
    pub clearance_ratio: f64,
    /// Peg length `L` (m).
    pub length: f64,
    /// Fillet radius of the peg's bottom rim `ρ_p` (m).
    pub rim_fillet: f64,
    /// Fillet radius of the hole's mouth `ρ_h` (m): the rounded stand-in
    /// for a chamfer of that size.
    pub mouth_fillet: f64,
    /// Bore depth below the top face (m).
    pub bore_depth: f64,
    /// Peg density (kg/m³): a solid cylinder.
    pub density: f64,
    /// Gravitational acceleration (m/s², default 9.81).
    #[serde(default = "default_gravity")]
    pub gravity: f64,
    /// Coulomb friction coefficient `μ`.
    pub friction: f64,
    /// Velocity scale `v_s` of the regularized friction (m/s, default 1e-4).
    #[serde(default = "default_slip")]
    pub slip_velocity: f64,
    /// Hunt–Crossley damping `α` (s/m, default 0).
    #[serde(default)]
    pub contact_damping: f64,
    /// A fixed Hertz stiffness `k` (N/m^1.5) for every contact instead of
    /// the curvature-based one (optional).
    pub contact_stiffness: Option<f64>,
    /// Peg material (default steel).
    #[serde(default = "steel")]
    pub peg_material: MaterialSpec,
    /// Block material (default steel).
    #[serde(default = "steel")]
    pub hole_material: MaterialSpec,
}

impl PegTable {
    /// Validates every field (`peg.*`) and builds the model parameters.
    pub fn build(&self, c: &mut Checker) -> Peg3dParams {
        let d = r::HOLE_DIAMETER.require(c, self.hole_diameter);
        let cr = r::CLEARANCE_RATIO.require(c, self.clearance_ratio);
        let len = r::LENGTH.require(c, self.length);
        let radius = 0.5 * d * (1.0 - cr);
        r::RIM_FILLET
            .within(f64::NAN, 0.5 * radius)
            .require(c, self.rim_fillet);
        r::MOUTH_FILLET
            .within(f64::NAN, 0.25 * d)
            .require(c, self.mouth_fillet);
        r::BORE_DEPTH.require(c, self.bore_depth);
        r::DENSITY.require(c, self.density);
        r::GRAVITY.require(c, self.gravity);
        r::FRICTION.require(c, self.friction);
        r::SLIP_VELOCITY.require(c, self.slip_velocity);
        r::CONTACT_DAMPING.require(c, self.contact_damping);
        if let Some(k) = self.contact_stiffness {
            r::CONTACT_STIFFNESS.require(c, k);
        }
        if len.is_finite() && len <= self.rim_fillet * 2.0 {
            c.push(crate::error::SceneError::invalid(
                r::LENGTH.field,
                len,
                "must exceed twice the rim fillet",
            ));
        }
        for (m, modulus, poisson) in [
            (
                &self.peg_material,
                r::PEG_YOUNGS_MODULUS,
                r::PEG_POISSON_RATIO,
            ),
            (
                &self.hole_material,
                r::HOLE_YOUNGS_MODULUS,
                r::HOLE_POISSON_RATIO,
            ),
        ] {
            modulus.require(c, m.youngs_modulus);
            poisson.require(c, m.poisson_ratio);
        }
        let mut p = Peg3dParams::steel(
            2.0 * radius,
            len,
            d,
            self.rim_fillet,
            self.mouth_fillet,
            self.bore_depth,
        );
        let scale = self.density / 7850.0;
        p.mass *= scale;
        p.inertia_transverse *= scale;
        p.inertia_axial *= scale;
        p.gravity = self.gravity;
        p.friction = self.friction;
        p.slip_scale = self.slip_velocity;
        p.damping = self.contact_damping;
        p.peg_material = Material {
            youngs_modulus: self.peg_material.youngs_modulus,
            poisson_ratio: self.peg_material.poisson_ratio,
        };
        p.hole_material = Material {
            youngs_modulus: self.hole_material.youngs_modulus,
            poisson_ratio: self.hole_material.poisson_ratio,
        };
        p.hertz = match self.contact_stiffness {
            Some(k) => HertzMode::Fixed(k),
            None => HertzMode::Curvature,
        };
        p
    }
}

/// The `[wrist]` table (SI units; angles in rad).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WristTable {
    /// Height `L_c` of the compliance centre above the tip (m).
    pub centre_height: f64,
    /// Lateral stiffness `K_x` (N/m).
    pub lateral_stiffness: f64,
    /// Lateral stiffness `K_y` (N/m, default `K_x`).
    pub lateral_stiffness_y: Option<f64>,
    /// Axial stiffness `K_z` (N/m).
    pub axial_stiffness: f64,
    /// Angular stiffness `K_θ` (N·m/rad).
    pub angular_stiffness: f64,
    /// Torsional stiffness `K_φ` (N·m/rad).
    pub torsional_stiffness: f64,
    /// Lateral damping (N·s/m).
    pub lateral_damping: f64,
    /// Axial damping (N·s/m).
    pub axial_damping: f64,
    /// Angular and torsional damping (N·m·s/rad).
    pub angular_damping: f64,
}

impl WristTable {
    /// Validates every field (`wrist.*`) and builds the wrist for a peg of
    /// `length`.
    pub fn build(&self, c: &mut Checker, length: f64) -> WristParams {
        let reach = 10.0 * length.abs();
        let lc = r::CENTRE_HEIGHT
            .within(-reach, reach)
            .require(c, self.centre_height);
        let kx = r::LATERAL_STIFFNESS.require(c, self.lateral_stiffness);
        let ky = match self.lateral_stiffness_y {
            Some(v) => r::LATERAL_STIFFNESS_Y.require(c, v),
            None => kx,
        };
        WristParams {
            centre_height: lc,
            lateral: [kx, ky],
            axial: r::AXIAL_STIFFNESS.require(c, self.axial_stiffness),
            angular: r::ANGULAR_STIFFNESS.require(c, self.angular_stiffness),
            torsional: r::TORSIONAL_STIFFNESS.require(c, self.torsional_stiffness),
            lateral_damping: r::LATERAL_DAMPING.require(c, self.lateral_damping),
            axial_damping: r::AXIAL_DAMPING.require(c, self.axial_damping),
            angular_damping: r::ANGULAR_DAMPING.require(c, self.angular_damping),
        }
    }
}

/// The `[robot]` table (SI units; errors and rates as named).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RobotTable {
    /// Lateral error of the tip (m).
    pub lateral_error: f64,
    /// Direction of the lateral error, degrees from `x` (default 0).
    #[serde(default)]
    pub lateral_error_direction_deg: f64,
    /// Angular error of the axis (degrees).
    pub angular_error_deg: f64,
    /// Azimuth of the tilt, degrees from `x` (default 180: the tip leads
    /// towards the hole's centre for a positive lateral error along `x`).
    #[serde(default = "default_azimuth")]
    pub tilt_direction_deg: f64,
    /// Start height of the tip above the top face (m). Negative: the peg
    /// starts in the bore, aligned and centred, the tip that deep; the
    /// wrist then carries the errors as a deflection.
    pub start_height: f64,
    /// Descent speed (m/s); ignored under `axial_force`.
    pub speed: f64,
    /// Constant axial force of a force-controlled descent (N, optional).
    pub axial_force: Option<f64>,
    /// How far below the seat depth the robot frame's target lies (m,
    /// default 1 mm).
    #[serde(default = "default_overtravel")]
    pub overtravel: f64,
    /// Precession rate `ψ̇` of the tilt direction (rad/s, default 0).
    #[serde(default)]
    pub precession_rate: f64,
    /// Spin rate `φ̇` about the peg's axis (rad/s, default 0).
    #[serde(default)]
    pub spin_rate: f64,
    /// Spiral search: radial growth per turn (m, default 0: no spiral).
    #[serde(default)]
    pub spiral_pitch: f64,
    /// Spiral search: angular rate (rad/s).
    #[serde(default)]
    pub spiral_rate: f64,
}

fn default_azimuth() -> f64 {
    180.0
}
fn default_overtravel() -> f64 {
    1e-3
}

impl RobotTable {
    /// Validates every field (`robot.*`) and builds the motion for a wrist
    /// with compliance centre `lc` above the tip, seat depth `seat` and
    /// bore diameter `d`.
    pub fn build(&self, c: &mut Checker, lc: f64, seat: f64, d: f64) -> RobotMotion {
        let e = r::LATERAL_ERROR
            .within(-2.0 * d, 2.0 * d)
            .require(c, self.lateral_error);
        let dir = r::LATERAL_ERROR_DIRECTION
            .require(c, self.lateral_error_direction_deg)
            .to_radians();
        let tilt = r::ANGULAR_ERROR
            .require(c, self.angular_error_deg)
            .to_radians();
        let az = r::TILT_DIRECTION
            .require(c, self.tilt_direction_deg)
            .to_radians();
        let h0 = r::START_HEIGHT
            .within(-seat, f64::NAN)
            .require(c, self.start_height);
        let speed = r::SPEED.require(c, self.speed);
        r::OVERTRAVEL.require(c, self.overtravel);
        let pr = r::PRECESSION_RATE.require(c, self.precession_rate);
        let sr = r::SPIN_RATE.require(c, self.spin_rate);
        r::SPIRAL_PITCH
            .within(f64::NAN, d)
            .require(c, self.spiral_pitch);
        r::SPIRAL_RATE.require(c, self.spiral_rate);
        let descent = match self.axial_force {
            Some(force) => Descent::Force {
                force: r::AXIAL_FORCE.require(c, force),
            },
            None => {
                if speed <= 0.0 {
                    c.push(crate::error::SceneError::invalid(
                        r::SPEED.field,
                        speed,
                        "must be positive without axial_force",
                    ));
                }
                Descent::Speed {
                    speed,
                    end: -(seat + self.overtravel) + lc * tilt.cos(),
                }
            }
        };
        let axis = Vector3::new(tilt.sin() * az.cos(), tilt.sin() * az.sin(), tilt.cos());
        let tip = Vector3::new(e * dir.cos(), e * dir.sin(), h0);
        RobotMotion {
            start: tip + axis * lc,
            tilt,
            tilt_azimuth: az,
            precession_rate: pr,
            spin_rate: sr,
            descent,
            spiral: (self.spiral_pitch > 0.0).then_some(Spiral {
                pitch: self.spiral_pitch,
                rate: self.spiral_rate,
            }),
        }
    }
}

/// The `[criteria]` table: when a run ends (SI units).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CriteriaTable {
    /// Tip depth that counts as seated (m).
    pub seat_depth: f64,
    /// Largest wrist force (N).
    pub wrist_force_limit: f64,
    /// Largest contact normal force (N).
    pub contact_force_limit: f64,
    /// Duration of the release test that tells a wedge from a jam (s,
    /// default 0.02).
    #[serde(default = "default_release")]
    pub release_time: f64,
}

fn default_release() -> f64 {
    0.02
}

impl CriteriaTable {
    /// Validates every field (`criteria.*`) against the bore depth `bore`.
    pub fn build(&self, c: &mut Checker, bore: f64) -> Criteria {
        Criteria {
            seat_depth: r::SEAT_DEPTH
                .within(f64::NAN, 0.999 * bore)
                .require(c, self.seat_depth),
            wrist_force_limit: r::WRIST_FORCE_LIMIT.require(c, self.wrist_force_limit),
            contact_force_limit: r::CONTACT_FORCE_LIMIT.require(c, self.contact_force_limit),
            release_time: r::RELEASE_TIME.require(c, self.release_time),
        }
    }
}

/// The held peg of the `[peg]`, `[wrist]`, `[robot]` and `[criteria]`
/// tables.
pub fn held(
    peg: &PegTable,
    wrist: &WristTable,
    robot: &RobotTable,
    criteria: &CriteriaTable,
    c: &mut Checker,
) -> (Peg3dParams, Held, Criteria) {
    let p = peg.build(c);
    let w = wrist.build(c, p.length);
    let cr = criteria.build(c, p.bore_depth);
    let motion = robot.build(c, w.centre_height, cr.seat_depth, p.hole_diameter);
    (
        p,
        Held {
            wrist: w,
            robot: motion,
        },
        cr,
    )
}
