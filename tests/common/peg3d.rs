//! Fixtures of the compliant 3-D peg tests (`tests/compliant_peg_3d/`): the
//! Fig. 9 peg, orientations by tilt, precession and spin, the rim on the
//! mouth fillet, the peg under a load fixed in its frame, its two-point
//! contact forces, and the tight DOPRI5 run the energy tests integrate
//! with.

#![allow(dead_code)]

use nalgebra::{SVector, Unit, UnitQuaternion, Vector3};
use pegdyn::compliant_peg::Load;
use pegdyn::compliant_peg_3d::{Pair, Peg3d, Peg3dParams, pose_state};
use pegdyn::generated::compliant_peg_3d as gen3d;
use pegdyn::integrate::{Method, Options, Solution, solve};
use pegdyn::system::OdeSystem;

/// The Fig. 9 peg (D = 50 mm, d = 49.95 mm, L = 70 mm) with 1 mm fillets
/// and a 100 mm bore, steel on steel, stiffness from the curvatures.
pub fn fig9() -> Peg3dParams {
    Peg3dParams::steel(0.04995, 0.070, 0.050, 1e-3, 1e-3, 0.1)
}

/// Tilt `gamma` of the axis towards azimuth `psi`, after a spin `phi` about
/// the peg's own axis.
pub fn orientation(gamma: f64, psi: f64, phi: f64) -> UnitQuaternion<f64> {
    let tilt_axis = Unit::new_normalize(Vector3::new(-psi.sin(), psi.cos(), 0.0));
    UnitQuaternion::from_axis_angle(&tilt_axis, gamma)
        * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi)
}

/// The family of poses where the rim's two points on the mouth fillet
/// (B1, B2) merge: tilt `gamma` about `y` with the rim point at body angle
/// 0 highest and outermost, its tube centre held `s` inside and `h` above
/// the mouth's tube-centre circle at angle 0 (`√(s² + h²) = ρ_p + ρ_h − δ`).
pub fn rim_on_mouth(prm: &Peg3dParams, gamma: f64, depth: f64) -> SVector<f64, 15> {
    let (rho_p, rho_h) = (prm.rim_fillet, prm.mouth_fillet);
    let rr = prm.peg_radius() - rho_p;
    let dist = rho_p + rho_h - depth;
    let (s, h) = (dist * 0.5_f64.sin(), dist * 0.5_f64.cos());
    let centre = Vector3::new(prm.bore_radius() + rho_h - s, 0.0, -rho_h + h);
    let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), -gamma);
    let p = centre - q * Vector3::new(rr, 0.0, rho_p - 0.5 * prm.length);
    pose_state(p, q, Vector3::zeros(), Vector3::zeros())
}

/// The 3-D peg under a load fixed in the peg's frame: force
/// `f₁ e_a + f₂ e_r` at the centre of mass (`e_a = −R e_z` towards the
/// bottom face, `e_r = R e_x`) and moment `−M e_y` (the planar torque `M`
/// increases the tilt θ, a rotation about `−e_y`).
pub struct Follower {
    pub peg: Peg3d,
    pub load: Load,
}

impl OdeSystem<15> for Follower {
    fn rhs(&self, _t: f64, y: &SVector<f64, 15>) -> SVector<f64, 15> {
        let Ok(forces) = self.peg.forces(y) else {
            return SVector::repeat(f64::NAN);
        };
        let mut w = Peg3d::wrench(y, &forces);
        let x = Peg3d::pose(y);
        let q = UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(x[3], x[4], x[5], x[6]));
        let f = q * Vector3::new(self.load.radial, 0.0, -self.load.axial);
        for k in 0..3 {
            w[k] += f[k];
        }
        w[4] -= self.load.torque;
        gen3d::rhs(y, &w, self.peg.param_vector())
    }
    fn time_derivative(&self, _t: f64, _y: &SVector<f64, 15>) -> SVector<f64, 15> {
        SVector::zeros()
    }
}

/// Summed normal forces `(edge–side, rim–wall)` (N) of a peg leaning in
/// two-point contact; any other contact fails the test.
pub fn pair_forces(peg: &Peg3d, y: &SVector<f64, 15>) -> (f64, f64) {
    let (mut edge, mut wall) = (0.0, 0.0);
    for f in peg.forces(y).unwrap() {
        match f.contact.pair {
            Pair::EdgeSide => edge += f.normal_force,
            Pair::RimWall => wall += f.normal_force,
            other => panic!("unexpected contact {other:?}"),
        }
    }
    (edge, wall)
}

/// DOPRI5 at rtol 1e-11 and the given `atol` from `y0` at t = 0 to
/// `t_end`, every step stored; the run must end at `t_end`.
pub fn tight_dopri5<S: OdeSystem<15>>(
    sys: &S,
    y0: SVector<f64, 15>,
    t_end: f64,
    atol: f64,
) -> Solution<15> {
    let sol = solve(
        sys,
        Method::Dopri5,
        (0.0, y0),
        t_end,
        &Options::with_tolerances(1e-11, atol),
    )
    .unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    sol
}
