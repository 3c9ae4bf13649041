//! Hard cases of the rigid peg on the hole edge at three points (the
//! hand-derived model `pegdyn::rigid_peg`): γ → γ0 = arccos(d/D) for small
//! clearances, γ up to 1.2 rad, ψ̇ = 0 exactly and 1e-12, and a 10 s
//! frictionless simulation (energy and contact-constraint drift).
//! The generated rigid model (`pegdyn::generated::rigid_peg*`) is measured
//! near γ0 by `pegdyn accuracy` (grid in `src/accuracy/grid.rs`, asserted
//! in `tests/generator/accuracy_report.rs`).

use nalgebra::{SVector, Vector2, Vector4};
use pegdyn::accuracy::ulp;
use pegdyn::integrate::{Method, Options, Solver};
use pegdyn::rigid_peg::dynamics::{
    forward_system, friction_directions, kinetic_energy, potential_energy, regularized_directions,
    solve,
};
use pegdyn::rigid_peg::kinematics::{Geometry, Pose};
use pegdyn::rigid_peg::{Loads, PegParams, RigidError};
use pegdyn::scalar::{Dd, Real};
use pegdyn::system::OdeSystem;

const U: f64 = f64::EPSILON / 2.0;

fn peg(clearance: f64, friction: f64) -> PegParams {
    let mut p = PegParams::fig9();
    p.peg_diameter = p.hole_diameter - clearance;
    p.friction = friction;
    p
}

/// c = d − D cos γ at γ = γ0(1 + ε), ε = 1e-3 … 1e-12, clearances 50 µm to
/// 1 nm at D = 50 mm. The hand form 2D sin((γ+γ0)/2) sin((γ−γ0)/2) carries
/// the rounding of γ0 itself (a few ulps), so its error is bounded by
/// 4 D sin γ · ulp(γ0) + 8u|c| against d − D cos γ in double-double from
/// the same inputs; the naive f64 `d − D cos γ` misses that bound by up to
/// 1/γ0² (asserted to fail it somewhere on the grid).
#[test]
fn gap_near_gamma0_small_clearances() {
    for clearance in [50e-6, 1e-6, 1e-8, 1e-9] {
        let p = peg(clearance, 0.2);
        let gamma0 = p.gamma0();
        let mut naive_fails = false;
        for k in 3..=12 {
            let gamma = gamma0 * (1.0 + 10f64.powi(-k));
            let geo = Geometry::try_new(&p, gamma).expect("three-point");
            let exact =
                Dd::from(p.peg_diameter) - Dd::from(p.hole_diameter) * Dd::from(gamma).cos();
            let bound =
                4.0 * p.hole_diameter * gamma.sin() * ulp(gamma0) + 8.0 * U * exact.hi().abs();
            let err = |v: f64| (Dd::from(v) - exact).hi().abs();
            assert!(
                err(geo.c) <= bound,
                "c={clearance} ε=1e-{k}: {} vs {exact}",
                geo.c
            );
            assert!(geo.b > 0.0 && geo.b.is_finite() && geo.s1.is_finite());
            naive_fails |= err(p.peg_diameter - p.hole_diameter * gamma.cos()) > bound;
        }
        if clearance <= 1e-6 {
            assert!(
                naive_fails,
                "c={clearance}: the naive form met the bound everywhere"
            );
        }
    }
}

/// At γ = γ0, just below it, and at π/2 three-point contact does not exist
/// (B1 and B2 merge, or the peg lies flat): a typed `NotThreePoint`, never
/// a NaN geometry.
#[test]
fn gamma_at_or_below_gamma0_is_refused() {
    let p = peg(1e-9, 0.2);
    let gamma0 = p.gamma0();
    for gamma in [
        gamma0,
        gamma0 * (1.0 - 1e-12),
        std::f64::consts::FRAC_PI_2,
        f64::NAN,
    ] {
        match Geometry::try_new(&p, gamma) {
            Err(RigidError::NotThreePoint { gamma0: g0, .. }) => assert_eq!(g0, gamma0),
            other => panic!("γ = {gamma}: {other:?}"),
        }
    }
}

/// γ from just above γ0 to 1.2 rad: the contacts B1, B2 lie on the hole
/// edge, b² + S1² = (D/2)², to 1e-14 relative, and every quantity is finite.
#[test]
fn gamma_up_to_1_2_rad_keeps_contacts_on_the_edge() {
    let p = peg(50e-6, 0.2);
    let gamma0 = p.gamma0();
    for k in 1..=60 {
        let gamma = gamma0 + (1.2 - gamma0) * f64::from(k) / 60.0;
        let geo = Geometry::try_new(&p, gamma).expect("three-point");
        let r2 = geo.b * geo.b + geo.s1 * geo.s1;
        let half = 0.5 * p.hole_diameter;
        assert!((r2 - half * half).abs() <= 1e-14 * half * half, "γ={gamma}");
        assert!(geo.kl.is_finite() && geo.bl.is_finite() && geo.d2z_c.is_finite());
    }
}

/// ψ̇ = 0 and γ̇ = 0 exactly with friction: no contact slides, Coulomb's
/// direction is undefined and `friction_directions` says so with the typed
/// `NoSliding`; the regularized law (v_s = 1e-6 m/s) gives finite
/// accelerations and reactions, and ψ̇ = 1e-12 rad/s changes them by less
/// than 1e-5 relative (continuous, no NaN).
#[test]
fn psidot_zero_exactly_and_tiny() {
    let p = peg(50e-6, 0.2);
    let gamma = 0.5 * (p.gamma0() + 0.3);
    let pose = Pose::try_new(&p, gamma, 0.4).expect("pose");
    let loads = Loads {
        m_gamma: 0.0,
        m_psi: 0.0,
        force: [0.0; 3],
    };
    let still = pose.kinematics(Vector2::zeros());
    assert!(matches!(
        friction_directions(&still),
        Err(RigidError::NoSliding { .. })
    ));
    let accel = |psidot: f64| {
        let qd = Vector2::new(0.0, psidot);
        let t = regularized_directions(&pose.kinematics(qd), 1e-6);
        let (a, rhs) = forward_system(&p, &loads, &pose, qd, &t);
        solve(&a, &rhs, gamma).expect("regular system")
    };
    let (x0, x1) = (accel(0.0), accel(1e-12));
    assert!(x0.iter().all(|v| v.is_finite()), "{x0}");
    for i in 0..5 {
        assert!(
            (x1[i] - x0[i]).abs() <= 1e-5 * x0.amax().max(1e-300),
            "{i}: {x0} {x1}"
        );
    }
}

/// The frictionless rigid peg on the edge, γ̈ and ψ̈ from the hand model,
/// held by a torsion spring about the nodal axis (a compliant wrist): the
/// nutation moment is `M_γ = m0 + k (γ_eq − γ)`, conservative with
/// potential `½ k (γ − γ_eq)² − m0 γ`.
struct Frictionless {
    p: PegParams,
    m0: f64,
    k: f64,
    gamma_eq: f64,
}

impl Frictionless {
    fn accel(&self, x: &Vector4<f64>) -> Result<Vector2<f64>, RigidError> {
        let pose = Pose::try_new(&self.p, x[0], x[1])?;
        let qd = Vector2::new(x[2], x[3]);
        let t = regularized_directions(&pose.kinematics(qd), 1e-6);
        let loads = Loads {
            m_gamma: self.m0 + self.k * (self.gamma_eq - x[0]),
            m_psi: 0.0,
            force: [0.0; 3],
        };
        let (a, rhs) = forward_system(&self.p, &loads, &pose, qd, &t);
        let s = solve(&a, &rhs, x[0])?;
        Ok(Vector2::new(s[0], s[1]))
    }

    /// T + V + ½ k (γ − γ_eq)² − m0 γ (J).
    fn energy(&self, x: &Vector4<f64>) -> f64 {
        let pose = Pose::try_new(&self.p, x[0], x[1]).expect("pose");
        let kin = pose.kinematics(Vector2::new(x[2], x[3]));
        kinetic_energy(&self.p, &pose, &kin)
            + potential_energy(&self.p, &pose)
            + 0.5 * self.k * (x[0] - self.gamma_eq).powi(2)
            - self.m0 * x[0]
    }
}

impl OdeSystem<4> for Frictionless {
    fn rhs(&self, _t: f64, x: &SVector<f64, 4>) -> SVector<f64, 4> {
        // Outside three-point contact the state is invalid: NaN makes the
        // solver stop with its typed `NonFinite`, which the test rejects.
        let a = self.accel(x).unwrap_or(Vector2::repeat(f64::NAN));
        Vector4::new(x[2], x[3], a[0], a[1])
    }
}

/// 10 s of the frictionless peg (f = 0) on the edge under gravity, held
/// near γ_eq = 0.3 rad by a torsion spring (k = 2 N·m/rad, the moment m0
/// that balances gravity at γ_eq), started at γ = 0.25 rad precessing at
/// ψ̇ = 2 rad/s: about 70 nutation periods. The energy drifts by less than
/// 1e-7 of the energy exchanged (DOPRI5, rtol 1e-11), and the contact
/// points K, B1, B2 stay on the hole-edge circle (radius D/2, z = 0) to a
/// few ulps — the constraints hold by construction of the minimal
/// coordinates, so they cannot drift.
#[test]
fn ten_second_frictionless_energy_and_constraint_drift() {
    let p = peg(50e-6, 0.0);
    let geq = Geometry::try_new(&p, 0.3).expect("three-point");
    let sys = Frictionless {
        p,
        m0: p.mass * p.gravity * geq.dz_c,
        k: 2.0,
        gamma_eq: 0.3,
    };
    let x0 = Vector4::new(0.25, 0.0, 0.0, 2.0);
    let e0 = sys.energy(&x0);
    let swing = (sys.energy(&Vector4::new(0.3, 0.0, 0.0, 2.0)) - e0).abs();
    let (mut drift, mut edge_err, mut lo, mut hi) = (0.0f64, 0.0f64, f64::INFINITY, 0.0f64);
    let mut options = Options::with_tolerances(1e-11, 1e-13);
    options.store = false;
    let sol = Solver::new(Method::Dopri5, options)
        .with_observer(|_t, x: &SVector<f64, 4>| {
            drift = drift.max((sys.energy(x) - e0).abs());
            (lo, hi) = (lo.min(x[0]), hi.max(x[0]));
            let pose = Pose::try_new(&sys.p, x[0], x[1]).expect("pose");
            for c in pose.contacts {
                let r = c.x.hypot(c.y);
                edge_err = edge_err
                    .max((r - 0.5 * sys.p.hole_diameter).abs())
                    .max(c.z.abs());
            }
        })
        .solve(&sys, 0.0, x0, 10.0)
        .expect("valid options");
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    assert!(
        lo < 0.26 && hi > 0.33,
        "the peg must rock: γ in [{lo}, {hi}]"
    );
    assert!(
        drift <= 1e-7 * swing,
        "energy drift {drift} J over a swing of {swing} J"
    );
    assert!(
        edge_err <= 8.0 * U * 0.5 * sys.p.hole_diameter,
        "contact off the edge by {edge_err} m"
    );
}
