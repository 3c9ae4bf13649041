//! The compliant 3-D peg held by a compliant wrist that a robot moves: the
//! wrist's load ([`super::wrist`]) at the robot frame of
//! [`super::robot::RobotMotion`] is added to the contact wrench of
//! [`Peg3d`] before the generated Newton–Euler right-hand side. An
//! optional follower moment `M = −M₀ (e_z × a)/√(|e_z × a|² + s²)`
//! (`s = 10⁻³`) turns the peg's axis `a` towards the hole's axis whatever
//! the tilt's azimuth (the aligning moment of a precessing peg).
//!
//! State: the peg's 15 components `(p, q, v, ω_body, W, S)` and `W_r`, the
//! work done on the peg by the robot (through the wrist) and by the
//! follower moment. The wrist's dampers add to the dissipation `S`, so
//!
//! ```text
//! E = T + m g z + V_c + V_w − W − W_r + S
//! ```
//!
//! is constant along a solution when the contact stiffness is fixed
//! ([`Insertion::energy_balance`]).

use super::contact::{ContactPoint, Pair};
use super::curvature;
use super::forces::ContactForce;
use super::params::Peg3dParams;
use super::robot::RobotMotion;
use super::system::{Peg3d, pose_state};
use super::wrist::{Kinematics, PegMotion, RobotFrame, WristLoad, WristParams};
use crate::generated::compliant_peg_3d as generated;
use crate::hertz::{EllipticityMethod, HertzContact, HertzError};
use crate::system::{KinematicSplit, ModelError, OdeSystem};
use nalgebra::{Quaternion, SMatrix, SVector, UnitQuaternion, Vector3};

/// State dimension of [`Insertion`].
pub const N_STATE: usize = 16;

/// Names of the components of [`Insertion`]'s state: the peg's
/// (`generated::compliant_peg_3d::Y_NAMES`) and the work done on it by the
/// robot through the wrist and by the follower moment (J).
pub const STATE_NAMES: [&str; N_STATE] = {
    let mut names = [""; N_STATE];
    let mut i = 0;
    while i < generated::Y_NAMES.len() {
        names[i] = generated::Y_NAMES[i];
        i += 1;
    }
    names[N_STATE - 1] = "robot_work";
    names
};

/// A wrist and the robot motion that carries it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Held {
    /// The wrist.
    pub wrist: WristParams,
    /// The robot frame's motion.
    pub robot: RobotMotion,
}

/// The peg, optionally held by a wrist, optionally under a follower
/// aligning moment.
pub struct Insertion {
    /// The peg and its contacts.
    pub peg: Peg3d,
    /// The wrist and robot, if the peg is held.
    pub held: Option<Held>,
    /// Magnitude `M₀` of the follower aligning moment (N·m, 0 for none).
    pub aligning_moment: f64,
}

/// Everything about one state, for output and outcome checks.
#[derive(Clone, Debug)]
pub struct Sample {
    /// Contact forces, pair by pair.
    pub forces: Vec<ContactForce>,
    /// The wrist's load, if held.
    pub wrist: Option<WristLoad>,
    /// The robot frame, if held.
    pub frame: Option<RobotFrame>,
    /// Depth of the tip (centre of the bottom face) below the top face (m).
    pub depth: f64,
    /// Tilt of the axis from the hole's axis (rad).
    pub tilt: f64,
    /// Azimuth of the tilt (rad).
    pub azimuth: f64,
    /// Kinetic energy (J).
    pub kinetic: f64,
    /// `E` of the module documentation (J).
    pub balance: f64,
}

impl Sample {
    /// Sum of the contact normal forces (N).
    pub fn total_normal(&self) -> f64 {
        self.forces.iter().map(|f| f.normal_force).sum()
    }

    /// Largest contact normal force (N).
    pub fn peak_normal(&self) -> f64 {
        self.forces
            .iter()
            .map(|f| f.normal_force)
            .fold(0.0, f64::max)
    }
}

/// The peg's 15-component state inside an [`Insertion`] state.
pub fn peg_state(y: &SVector<f64, N_STATE>) -> SVector<f64, 15> {
    y.fixed_rows::<15>(0).into_owned()
}

/// The peg's pose and velocities (hole frame) of a peg state.
pub fn motion(y: &SVector<f64, 15>) -> PegMotion {
    let q = UnitQuaternion::from_quaternion(Quaternion::new(y[3], y[4], y[5], y[6]));
    PegMotion {
        centre: Vector3::new(y[0], y[1], y[2]),
        orientation: q,
        velocity: Vector3::new(y[7], y[8], y[9]),
        angular_velocity: q * Vector3::new(y[10], y[11], y[12]),
    }
}

/// Depth of the tip `−(p_z − (L/2) a_z)` (m), tilt `arccos a_z` and
/// azimuth `atan2(a_y, a_x)` of a peg state.
pub fn depth_tilt(prm: &Peg3dParams, y: &SVector<f64, 15>) -> (f64, f64, f64) {
    let m = motion(y);
    let a = m.orientation * Vector3::z();
    let depth = -(m.centre.z - 0.5 * prm.length * a.z);
    (
        depth,
        a.xy().norm().atan2(a.z),
        if a.xy().norm() > 0.0 {
            a.y.atan2(a.x)
        } else {
            0.0
        },
    )
}

impl Insertion {
    /// The system of a peg with parameters `params`, `held` or free, under
    /// the follower moment `aligning_moment` (N·m).
    pub fn new(params: Peg3dParams, held: Option<Held>, aligning_moment: f64) -> Insertion {
        Insertion {
            peg: Peg3d::new(params),
            held,
            aligning_moment,
        }
    }

    /// The robot frame and the wrist's load at time `t`, if held.
    pub fn wrist_load(&self, t: f64, y: &SVector<f64, 15>) -> Option<(RobotFrame, WristLoad)> {
        self.held.map(|h| {
            let frame = h.robot.frame(t);
            let load = h.wrist.load(self.peg.params.length, &motion(y), &frame);
            (frame, load)
        })
    }

    /// The rate of the state: the generated right-hand side with the
    /// contact, wrist and follower wrench.
    ///
    /// # Errors
    /// As [`Peg3d::forces`].
    pub fn rate(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
    ) -> Result<SVector<f64, N_STATE>, HertzError> {
        let ys = peg_state(y);
        let mut w: [f64; 7] = self.peg.contact_wrench(&ys)?.into();
        let power = self.add_held(t, &Kinematics::of_state(ys.as_slice()), &mut w);
        let w = SVector::from(w);
        let d = generated::rhs(&ys, &w, self.peg.param_vector());
        let mut out = SVector::<f64, N_STATE>::zeros();
        out.fixed_rows_mut::<15>(0).copy_from(&d);
        out[15] = power;
        Ok(out)
    }

    /// Everything about state `y` at time `t`.
    ///
    /// # Errors
    /// As [`Peg3d::forces`].
    pub fn sample(&self, t: f64, y: &SVector<f64, N_STATE>) -> Result<Sample, HertzError> {
        let ys = peg_state(y);
        let forces = self.peg.forces(&ys)?;
        let held = self.wrist_load(t, &ys);
        let (depth, tilt, azimuth) = depth_tilt(&self.peg.params, &ys);
        let generated::EnergyOut { kinetic, gravity } =
            generated::energy(&ys, self.peg.param_vector());
        let vc: f64 = forces.iter().map(|f| f.potential).sum();
        let vw = held.map_or(0.0, |(_, l)| l.potential);
        Ok(Sample {
            balance: kinetic + gravity + vc + vw - ys[13] - y[15] + ys[14],
            forces,
            wrist: held.map(|(_, l)| l),
            frame: held.map(|(f, _)| f),
            depth,
            tilt,
            azimuth,
            kinetic,
        })
    }

    /// `E = T + m g z + V_c + V_w − W − W_r + S` at `(t, y)` (J).
    ///
    /// # Errors
    /// As [`Peg3d::forces`].
    pub fn energy_balance(&self, t: f64, y: &SVector<f64, N_STATE>) -> Result<f64, HertzError> {
        Ok(self.sample(t, y)?.balance)
    }

    /// The contact points of state `y`.
    pub fn contacts(&self, y: &SVector<f64, N_STATE>) -> Vec<ContactPoint> {
        self.peg.contacts(&peg_state(y))
    }

    /// The start state of a held peg: the wrist undeflected at `t = 0`
    /// except for the static axial sag `m g / K_z` (speed-controlled
    /// descent), moving with the robot frame.
    pub fn held_start(&self) -> Option<SVector<f64, N_STATE>> {
        let h = self.held?;
        let f = h.robot.frame(0.0);
        let prm = &self.peg.params;
        let axis = f.orientation * Vector3::z();
        let arm = axis * (h.wrist.centre_height - 0.5 * prm.length);
        let sag = match f.axial_force {
            None if h.wrist.axial > 0.0 => prm.mass * prm.gravity / h.wrist.axial,
            _ => 0.0,
        };
        let centre = f.position - arm - Vector3::z() * sag;
        let v = f.velocity + f.angular_velocity.cross(&(centre - f.position));
        let omega_body = f.orientation.inverse() * f.angular_velocity;
        let ys = pose_state(centre, f.orientation, v, omega_body);
        let mut y = SVector::<f64, N_STATE>::zeros();
        y.fixed_rows_mut::<15>(0).copy_from(&ys);
        Some(y)
    }
}

impl Insertion {
    /// The largest Hertz pressure `p₀ = 3 Q / (2π a b)` (Pa) over the
    /// contacts of `sample` at state `y`, the ellipse from the curvatures
    /// of both surfaces at each point (whatever the contact law's
    /// stiffness). Contacts whose curvatures give no point contact are
    /// skipped and counted.
    pub fn peak_pressure(&self, y: &SVector<f64, N_STATE>, sample: &Sample) -> (f64, usize) {
        self.pressures(y, &sample.forces, None)
    }

    /// The largest Hertz pressure `p₀` (Pa) of the contact `forces` at
    /// state `y` whose pressure may exceed `floor`: each contact is
    /// screened with the Hamrock–Brewe fits and evaluated exactly (as in
    /// [`Insertion::peak_pressure`]) only where the fitted pressure is at
    /// least half of `floor`, so that a run can take its peak at every
    /// step for little more than its forces; 0 when none may.
    pub fn peak_pressure_above(
        &self,
        y: &SVector<f64, N_STATE>,
        forces: &[ContactForce],
        floor: f64,
    ) -> f64 {
        self.pressures(y, forces, Some(floor)).0
    }

    /// [`Insertion::peak_pressure`], over the contacts that pass the
    /// screen of [`Insertion::peak_pressure_above`] when `floor` is given.
    fn pressures(
        &self,
        y: &SVector<f64, N_STATE>,
        forces: &[ContactForce],
        floor: Option<f64>,
    ) -> (f64, usize) {
        let prm = &self.peg.params;
        let m = motion(&peg_state(y));
        let axis = m.orientation * Vector3::z();
        let (mut p0, mut skipped) = (0.0_f64, 0);
        for f in forces {
            let c = &f.contact;
            let curv = curvature::at(prm, c, &m.centre, &axis);
            let (m1, m2) = match c.pair {
                Pair::EdgeSide => (&prm.hole_material, &prm.peg_material),
                _ => (&prm.peg_material, &prm.hole_material),
            };
            let screened_out = floor.is_some_and(|floor| {
                HertzContact::try_new(&curv, m1, m2, EllipticityMethod::HamrockBrewe)
                    .is_ok_and(|h| h.max_pressure(f.normal_force) < 0.5 * floor)
            });
            if screened_out {
                continue;
            }
            match HertzContact::try_new(&curv, m1, m2, EllipticityMethod::Exact) {
                Ok(h) => p0 = p0.max(h.max_pressure(f.normal_force)),
                Err(_) => skipped += 1,
            }
        }
        (p0, skipped)
    }

    /// The start state of a held peg already in the bore: aligned with the
    /// hole's axis and centred, its tip `depth` (m) below the top face,
    /// moving down with the robot frame's axial velocity; the wrist
    /// carries the robot's lateral and angular errors as a deflection.
    pub fn centred_start(&self, depth: f64) -> Option<SVector<f64, N_STATE>> {
        let h = self.held?;
        let f = h.robot.frame(0.0);
        let prm = &self.peg.params;
        let centre = Vector3::new(0.0, 0.0, 0.5 * prm.length - depth);
        let v = Vector3::new(0.0, 0.0, f.velocity.z);
        let ys = pose_state(centre, UnitQuaternion::identity(), v, Vector3::zeros());
        let mut y = SVector::<f64, N_STATE>::zeros();
        y.fixed_rows_mut::<15>(0).copy_from(&ys);
        Some(y)
    }
}

impl OdeSystem<N_STATE> for Insertion {
    /// [`Insertion::rate`], NaN after a Hertz setup error.
    fn rhs(&self, t: f64, y: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        self.rate(t, y)
            .unwrap_or_else(|_| SVector::repeat(f64::NAN))
    }

    /// [`Insertion::rate`].
    fn try_rhs(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
    ) -> Result<SVector<f64, N_STATE>, ModelError> {
        Ok(self.rate(t, y)?)
    }

    /// [`Insertion::exact_jacobian`], NaN after a Hertz setup error.
    fn jacobian(&self, t: f64, y: &SVector<f64, N_STATE>) -> SMatrix<f64, N_STATE, N_STATE> {
        self.try_jacobian(t, y)
            .unwrap_or_else(|_| SMatrix::repeat(f64::NAN))
    }

    /// [`Insertion::exact_jacobian`]: at the contacts the right-hand side
    /// just found at `y`.
    fn try_jacobian(
        &self,
        t: f64,
        y: &SVector<f64, N_STATE>,
    ) -> Result<SMatrix<f64, N_STATE, N_STATE>, ModelError> {
        Ok(self.exact_jacobian(t, y)?)
    }

    /// [`Insertion::time_rate`].
    fn time_derivative(&self, t: f64, y: &SVector<f64, N_STATE>) -> SVector<f64, N_STATE> {
        self.time_rate(t, y)
    }

    /// Positions `(p, q)` with the kinematic map `ṗ = v`,
    /// `q̇ = ½ q ⊗ (0, ω)`, velocities `(v, ω)`, then the work integrals.
    fn kinematic_split(&self) -> Option<KinematicSplit> {
        Some(KinematicSplit {
            positions: 7,
            velocities: 6,
        })
    }

    fn state_names(&self) -> &'static [&'static str] {
        &STATE_NAMES
    }
}

/// Why [`lean_pose`] found no pose.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LeanError {
    /// The rigid three-point configuration does not exist at this tilt.
    #[error("no three-point lean at gamma = {gamma} rad: {reason}")]
    NoLean {
        /// The tilt asked for (rad).
        gamma: f64,
        /// The rigid model's reason.
        reason: String,
    },
    /// The peg lowered 10 % of its length met no contact.
    #[error("no contact within {0} m below the sharp-edged lean")]
    NoContact(f64),
}

/// A peg leaning on the mouth at tilt `gamma` (rad) with the tilt's
/// azimuth `psi` (rad): the rigid three-point configuration of the
/// sharp-edged peg and hole (`crate::rigid_peg::kinematics::Pose`: peg
/// side on the edge at K, bottom rim on the edge at B1, B2), lowered along
/// the hole's axis until the filleted surfaces first touch (bisection to
/// 1e-10 m, or 1e-7 of the smaller fillet when that is finer). Returns the centre of mass and the orientation (axis
/// `−sin γ e_η + cos γ e_z`, no twist).
///
/// # Errors
/// [`LeanError`] when the rigid lean does not exist (`γ ≤ γ0`) or no
/// contact is met.
pub fn lean_pose(
    prm: &Peg3dParams,
    gamma: f64,
    psi: f64,
) -> Result<(Vector3<f64>, UnitQuaternion<f64>), LeanError> {
    let rigid = crate::rigid_peg::PegParams {
        hole_diameter: prm.hole_diameter,
        peg_diameter: prm.peg_diameter,
        height: prm.length,
        mass: prm.mass,
        gravity: prm.gravity,
        friction: prm.friction,
    };
    let pose = crate::rigid_peg::kinematics::Pose::try_new(&rigid, gamma, psi).map_err(|e| {
        LeanError::NoLean {
            gamma,
            reason: e.to_string(),
        }
    })?;
    let axis = pose.axis;
    let q = UnitQuaternion::rotation_between(&Vector3::z(), &axis)
        .unwrap_or_else(UnitQuaternion::identity);
    let centre = pose.o2 + axis * (0.5 * prm.length);
    let peg = Peg3d::new(*prm);
    let touches = |s: f64| {
        let y = pose_state(
            centre - Vector3::z() * s,
            q,
            Vector3::zeros(),
            Vector3::zeros(),
        );
        !peg.contacts(&y).is_empty()
    };
    let (mut lo, mut hi) = (0.0, 0.1 * prm.length);
    if touches(lo) {
        // Already overlapping: lift until free.
        let mut up = 1e-6;
        while touches(-up) && up < 0.1 * prm.length {
            up *= 2.0;
        }
        lo = -up;
        hi = -0.5 * up;
        if !touches(hi) {
            hi = 0.0;
        }
    } else if !touches(hi) {
        return Err(LeanError::NoContact(hi));
    }
    // Bisection to 0.1 nm, or 1e-7 of the smaller fillet when that is
    // finer (a micrometre peg touches within 1e-14 m, not within 0.1 nm,
    // which would press its fillets far into the block), at most 200
    // halvings (a peg of any size).
    let tolerance = 1e-10_f64.min(1e-7 * prm.rim_fillet.min(prm.mouth_fillet));
    for _ in 0..200 {
        if hi - lo <= tolerance {
            break;
        }
        let mid = 0.5 * (lo + hi);
        if touches(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Ok((centre - Vector3::z() * hi, q))
}
