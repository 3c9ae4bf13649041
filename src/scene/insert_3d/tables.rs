//! The tables shared by the scene kinds of the compliant 3-D peg: `[peg]`
//! (peg, hole, materials, contact law), `[wrist]`, `[robot]` and
//! `[criteria]`, each validated field by field.

use serde::Deserialize;

use crate::compliant_peg_3d::insertion::Held;
use crate::compliant_peg_3d::outcome::Criteria;
use crate::compliant_peg_3d::robot::{Descent, RobotMotion, Spiral};
use crate::compliant_peg_3d::wrist::WristParams;
use crate::compliant_peg_3d::{HertzMode, Peg3dParams};
use crate::hertz::Material;
use crate::scene::insert_compliant::MaterialSpec;
use crate::scene::validate::Checker;
use nalgebra::Vector3;

fn steel() -> MaterialSpec {
    MaterialSpec {
        youngs_modulus: 210e9,
        poisson_ratio: 0.3,
    }
}
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
    /// Validates every field (prefix `t`, e.g. `peg`) and builds the model
    /// parameters.
    pub fn build(&self, t: &str, c: &mut Checker) -> Peg3dParams {
        let f = |k: &str| format!("{t}.{k}");
        // Sizes from a micrometre to a kilometre: the contact search's
        // tolerances and the energies stay far inside f64.
        let d = c.in_range(&f("hole_diameter"), self.hole_diameter, 1e-6, 1e3);
        let cr = c.in_range(&f("clearance_ratio"), self.clearance_ratio, 1e-6, 0.2);
        let len = c.in_range(&f("length"), self.length, 1e-6, 1e3);
        let r = 0.5 * d * (1.0 - cr);
        c.in_range(&f("rim_fillet"), self.rim_fillet, 1e-7, 0.5 * r);
        c.in_range(&f("mouth_fillet"), self.mouth_fillet, 1e-7, 0.25 * d);
        c.in_range(&f("bore_depth"), self.bore_depth, 1e-6, 1e3);
        c.in_range(&f("density"), self.density, 1.0, 1e5);
        c.in_range(&f("gravity"), self.gravity, 0.0, 1e3);
        c.in_range(&f("friction"), self.friction, 0.0, 2.0);
        c.in_range(&f("slip_velocity"), self.slip_velocity, 1e-9, 1.0);
        c.in_range(&f("contact_damping"), self.contact_damping, 0.0, 1e3);
        if let Some(k) = self.contact_stiffness {
            c.in_range(&f("contact_stiffness"), k, 1e3, 1e15);
        }
        if len.is_finite() && len <= self.rim_fillet * 2.0 {
            c.push(crate::error::SceneError::invalid(
                f("length"),
                len,
                "must exceed twice the rim fillet",
            ));
        }
        for (name, m) in [
            ("peg_material", &self.peg_material),
            ("hole_material", &self.hole_material),
        ] {
            c.in_range(
                &f(&format!("{name}.youngs_modulus")),
                m.youngs_modulus,
                1e3,
                1e13,
            );
            c.in_range(
                &f(&format!("{name}.poisson_ratio")),
                m.poisson_ratio,
                -0.99,
                0.499,
            );
        }
        let mut p = Peg3dParams::steel(
            2.0 * r,
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
    /// Validates every field and builds the wrist.
    pub fn build(&self, t: &str, c: &mut Checker, length: f64) -> WristParams {
        let f = |k: &str| format!("{t}.{k}");
        let lc = c.in_range(
            &f("centre_height"),
            self.centre_height,
            -10.0 * length.abs(),
            10.0 * length.abs(),
        );
        let kx = c.in_range(&f("lateral_stiffness"), self.lateral_stiffness, 1.0, 1e9);
        let ky = match self.lateral_stiffness_y {
            Some(v) => c.in_range(&f("lateral_stiffness_y"), v, 1.0, 1e9),
            None => kx,
        };
        WristParams {
            centre_height: lc,
            lateral: [kx, ky],
            axial: c.in_range(&f("axial_stiffness"), self.axial_stiffness, 1.0, 1e10),
            angular: c.in_range(&f("angular_stiffness"), self.angular_stiffness, 1e-3, 1e7),
            torsional: c.in_range(
                &f("torsional_stiffness"),
                self.torsional_stiffness,
                1e-3,
                1e7,
            ),
            lateral_damping: c.in_range(&f("lateral_damping"), self.lateral_damping, 0.0, 1e6),
            axial_damping: c.in_range(&f("axial_damping"), self.axial_damping, 0.0, 1e6),
            angular_damping: c.in_range(&f("angular_damping"), self.angular_damping, 0.0, 1e4),
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
    /// Validates every field and builds the motion for a wrist with
    /// compliance centre `lc` above the tip and seat depth `seat`.
    pub fn build(&self, t: &str, c: &mut Checker, lc: f64, seat: f64, d: f64) -> RobotMotion {
        let f = |k: &str| format!("{t}.{k}");
        let e = c.in_range(&f("lateral_error"), self.lateral_error, -2.0 * d, 2.0 * d);
        let dir = c
            .in_range(
                &f("lateral_error_direction_deg"),
                self.lateral_error_direction_deg,
                -360.0,
                360.0,
            )
            .to_radians();
        let tilt = c
            .in_range(&f("angular_error_deg"), self.angular_error_deg, -30.0, 30.0)
            .to_radians();
        let az = c
            .in_range(
                &f("tilt_direction_deg"),
                self.tilt_direction_deg,
                -360.0,
                360.0,
            )
            .to_radians();
        let h0 = c.in_range(&f("start_height"), self.start_height, -seat, 1.0);
        let speed = c.in_range(&f("speed"), self.speed, 0.0, 10.0);
        c.in_range(&f("overtravel"), self.overtravel, 0.0, 1.0);
        let pr = c.in_range(&f("precession_rate"), self.precession_rate, -1e4, 1e4);
        let sr = c.in_range(&f("spin_rate"), self.spin_rate, -1e4, 1e4);
        c.in_range(&f("spiral_pitch"), self.spiral_pitch, 0.0, d);
        c.in_range(&f("spiral_rate"), self.spiral_rate, -1e4, 1e4);
        let descent = match self.axial_force {
            Some(force) => Descent::Force {
                force: c.in_range(&f("axial_force"), force, 0.0, 1e6),
            },
            None => {
                if speed <= 0.0 {
                    c.push(crate::error::SceneError::invalid(
                        f("speed"),
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
    /// Validates every field against the bore depth `bore`.
    pub fn build(&self, t: &str, c: &mut Checker, bore: f64) -> Criteria {
        let f = |k: &str| format!("{t}.{k}");
        Criteria {
            seat_depth: c.in_range(&f("seat_depth"), self.seat_depth, 1e-6, 0.999 * bore),
            wrist_force_limit: c.in_range(
                &f("wrist_force_limit"),
                self.wrist_force_limit,
                1e-6,
                1e7,
            ),
            contact_force_limit: c.in_range(
                &f("contact_force_limit"),
                self.contact_force_limit,
                1e-6,
                1e8,
            ),
            release_time: c.in_range(&f("release_time"), self.release_time, 1e-5, 1.0),
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
    let p = peg.build("peg", c);
    let w = wrist.build("wrist", c, p.length);
    let cr = criteria.build("criteria", c, p.bore_depth);
    let r = robot.build("robot", c, w.centre_height, cr.seat_depth, p.hole_diameter);
    (p, Held { wrist: w, robot: r }, cr)
}
