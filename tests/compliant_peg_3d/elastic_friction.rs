//! The elastic friction law of the compliant 3-D peg (Mindlin's tangential
//! stiffness capped by Coulomb, `src/compliant_peg_3d/mindlin.rs`) against
//! the regularized law, on one contact: a 10 mm steel peg standing upright
//! on the block's top face away from the bore (the ring of its bottom rim
//! on the flat, one tracked slot), pressed down by 10 N and pushed
//! sideways at its centre of mass, with an applied moment that cancels the
//! couple of the push and the friction at the base (no rocking).

use nalgebra::{SVector, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::mindlin::Mindlin;
use pegdyn::compliant_peg_3d::{
    ElasticPeg3d, FrictionLaw, Pair, Peg3d, Peg3dParams, SlotKey, pose_state,
};
use pegdyn::hertz::contact_modulus;
use pegdyn::integrate::{Method, Options, OutputMode, Solution, solve};
use pegdyn::system::OdeSystem;

/// State length of the one-slot elastic system.
const N: usize = 18;

/// Downward push (N).
const PRESS: f64 = 10.0;

/// Friction coefficient.
const MU: f64 = 0.3;

/// The peg (d = 10 mm, L = 20 mm, 0.5 mm fillets) beside a 10.1 mm bore,
/// pressed down by [`PRESS`] and pushed along `x` by `push` (N) at its
/// centre of mass, with the moment `−(L/2) couple e_y` (`couple` the
/// friction force it balances, N).
fn params(law: FrictionLaw, push: f64, couple: f64) -> Peg3dParams {
    let mut prm = Peg3dParams::steel(0.010, 0.020, 0.0101, 5e-4, 5e-4, 0.02);
    prm.friction = MU;
    prm.friction_law = law;
    prm.force = Vector3::new(push, 0.0, -PRESS);
    prm.moment = Vector3::new(0.0, -0.5 * prm.length * couple, 0.0);
    prm
}

/// The normal load `Q = m g + PRESS` (N) of the peg at rest.
fn load(prm: &Peg3dParams) -> f64 {
    prm.mass * prm.gravity + PRESS
}

/// Upright at 20 mm from the bore's axis, at the ring's equilibrium depth
/// `δ₀ = Q/(2 ϱ E*)` (the punch's stiffness `2 ϱ E*`, `ϱ = r − ρ_p`), with
/// velocity `v`.
fn start(prm: &Peg3dParams, v: Vector3<f64>) -> SVector<f64, 15> {
    let e_star = contact_modulus(&prm.peg_material, &prm.hole_material);
    let depth = load(prm) / (2.0 * (prm.peg_radius() - prm.rim_fillet) * e_star);
    pose_state(
        Vector3::new(0.02, 0.0, 0.5 * prm.length - depth),
        UnitQuaternion::identity(),
        v,
        Vector3::zeros(),
    )
}

/// The ring's tangential stiffness `k_t = β 2 ϱ E*` (N/m): Mindlin's ratio
/// `β = 4 G*/E*` times the flat punch's normal stiffness.
fn ring_stiffness(prm: &Peg3dParams) -> f64 {
    let e_star = contact_modulus(&prm.peg_material, &prm.hole_material);
    Mindlin::of(prm).ratio * 2.0 * (prm.peg_radius() - prm.rim_fillet) * e_star
}

/// The elastic system's state of the peg's state `y` with the ring's
/// displacement `xi` (m) along `x`.
fn with_displacement(y: &SVector<f64, 15>, xi: f64) -> SVector<f64, N> {
    let mut out = ElasticPeg3d::<N>::state(y);
    out[15] = xi;
    out
}

fn elastic(prm: Peg3dParams) -> ElasticPeg3d<N> {
    ElasticPeg3d::try_new(prm, &[SlotKey::ring(Pair::RimTop)]).unwrap()
}

fn run<const M: usize, S: OdeSystem<M>>(
    sys: &S,
    y0: SVector<f64, M>,
    t_end: f64,
    rtol: f64,
) -> Solution<M> {
    let sol = solve(
        sys,
        Method::Rodas4,
        (0.0, y0),
        t_end,
        &Options {
            max_steps: 200_000,
            ..Options::with_tolerances(rtol, 1e-13)
        },
    )
    .unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    sol
}

/// The state at time `t` (the first step at or after it).
fn at<const M: usize>(sol: &Solution<M>, t: f64) -> SVector<f64, M> {
    let k = sol.t.iter().position(|&s| s >= t).unwrap();
    sol.x[k]
}

/// The horizontal drift (m) of the peg's centre of mass from time `t0` to
/// the end of `sol`.
fn drift<const M: usize>(sol: &Solution<M>, t0: f64) -> f64 {
    let (a, b) = (at(sol, t0), sol.x.last().unwrap());
    (b[0] - a[0]).hypot(b[1] - a[1])
}

#[test]
fn elastic_law_holds_a_load_inside_the_cone_without_creep() {
    // Half the friction limit, its couple cancelled; the spring starts at
    // its static extension push/k_t.
    let push = 0.5 * MU * load(&params(FrictionLaw::Elastic, 0.0, 0.0));
    let prm = params(FrictionLaw::Elastic, push, push);
    let sys = elastic(prm);
    let y0 = with_displacement(&start(&prm, Vector3::zeros()), push / ring_stiffness(&prm));
    let sol = run(&sys, y0, 0.011, 1e-8);
    let slip = drift(&sol, 0.001);
    let reg = params(FrictionLaw::Regularized, push, push);
    let rsol = run(&Peg3d::new(reg), start(&reg, Vector3::zeros()), 0.011, 1e-8);
    let creep = drift(&rsol, 0.001);
    // Creep of the regularized law: F = μ Q v/√(v² + v_s²) = push at
    // v = v_s (push/μQ)/√(1 − (push/μQ)²) = v_s/√3.
    let expected = 0.01 * reg.slip_scale / 3f64.sqrt();
    eprintln!("slip {slip:e} m, creep {creep:e} m (expected {expected:e} m)");
    assert!(slip <= 1e-9, "elastic law slipped {slip:e} m in 1 s");
    assert!(
        (creep / expected - 1.0).abs() < 1e-3,
        "regularized creep {creep:e} m, expected {expected:e} m"
    );
}

#[test]
fn elastic_law_slides_at_the_coulomb_force() {
    // Pushed at 1.5 μ Q from rest with the spring at its slip limit μQ/k_t;
    // the moment cancels the sliding friction's couple.
    let q = load(&params(FrictionLaw::Elastic, 0.0, 0.0));
    let prm = params(FrictionLaw::Elastic, 1.5 * MU * q, MU * q);
    let sys = elastic(prm);
    let y0 = with_displacement(
        &start(&prm, Vector3::zeros()),
        MU * q / ring_stiffness(&prm),
    );
    let t = 0.001;
    let sol = run(&sys, y0, t, 1e-8);
    let y = sol.x.last().unwrap();
    let s = sys.slot_forces(y).unwrap()[0];
    let f = s.spring.force;
    let ft = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
    let rel = ft / (MU * q) - 1.0;
    // Newton: v = (1.5 μQ − μQ) t / m.
    let v = 0.5 * MU * q * t / prm.mass;
    eprintln!(
        "|F_t| = {ft:e} N, μQ = {:e} N (rel {rel:e}); v_x = {:e} m/s, expected {v:e} m/s; {} steps",
        MU * q,
        y[7],
        sol.stats.steps
    );
    assert!(
        rel.abs() < 1e-6,
        "friction {ft:e} N against μQ {:e} N",
        MU * q
    );
    assert!(f[0] < 0.0 && (f[0].abs() - ft).abs() < 1e-6 * ft);
    assert!((y[7] / v - 1.0).abs() < 1e-6);
}

#[test]
fn energy_balance_closes_with_the_stored_tangential_energy() {
    // Thrown against the push (−x) and sideways (+y) with Hunt–Crossley
    // and tangential damping: the slide stops, reverses along x, the y
    // motion sticks.
    let q = load(&params(FrictionLaw::Elastic, 0.0, 0.0));
    let mut prm = params(FrictionLaw::Elastic, 1.5 * MU * q, MU * q);
    prm.damping = 10.0;
    let sys = elastic(prm);
    let y0 = ElasticPeg3d::<N>::state(&start(&prm, Vector3::new(-0.02, 0.01, 0.0)));
    let e0 = sys.energy_balance(&y0).unwrap();
    let sol = run(&sys, y0, 3e-4, 1e-10);
    let mut worst: f64 = 0.0;
    let mut stored: f64 = 0.0;
    let mut last_s = 0.0;
    for y in &sol.x {
        worst = worst.max((sys.energy_balance(y).unwrap() - e0).abs());
        stored = stored.max(sys.slot_forces(y).unwrap()[0].spring.energy);
        assert!(y[14] >= last_s - 1e-18, "dissipation decreased");
        last_s = y[14];
    }
    let end = sol.x.last().unwrap();
    let kinetic = 0.5 * prm.mass * (0.02f64.powi(2) + 0.01f64.powi(2));
    eprintln!(
        "balance drift {worst:e} J of initial kinetic {kinetic:e} J; S = {:e} J, W = {:e} J, largest E_t {stored:e} J, v = ({:e}, {:e}); {} steps",
        end[14], end[13], end[7], end[8], sol.stats.steps
    );
    assert!(end[7] > 0.0, "the slide along x did not reverse");
    assert!(stored > 0.0);
    assert!(worst <= 1e-6 * kinetic, "drift {worst:e} J");
}

#[test]
fn regularized_law_approaches_the_elastic_one_as_v_s_shrinks() {
    // Both from rest, pushed at 1.5 μ Q, the elastic spring at its slip
    // limit (so that it slides at μ Q from the start, as the regularized
    // law does as v_s → 0): the position after 0.5 ms.
    let q = load(&params(FrictionLaw::Elastic, 0.0, 0.0));
    let prm = params(FrictionLaw::Elastic, 1.5 * MU * q, MU * q);
    let t = 0.0005;
    let sys = elastic(prm);
    let slip_limit = MU * q / ring_stiffness(&prm);
    let y0 = with_displacement(&start(&prm, Vector3::zeros()), slip_limit);
    let x_el = run(&sys, y0, t, 1e-9).x.last().unwrap()[0];
    let mut diffs = Vec::new();
    for vs in [1e-3, 1e-4, 1e-5, 1e-6] {
        let mut reg = params(FrictionLaw::Regularized, 1.5 * MU * q, MU * q);
        reg.slip_scale = vs;
        let x = run(&Peg3d::new(reg), start(&reg, Vector3::zeros()), t, 1e-9)
            .x
            .last()
            .unwrap()[0];
        diffs.push(x - x_el);
    }
    eprintln!(
        "x_el {x_el:e} m; x_reg − x_el at v_s = 1e-3 … 1e-6 m/s: {diffs:?} m; ξ_max {slip_limit:e} m"
    );
    // Linear in v_s: a factor of about 10 per decade, below 1 nm at 1e-6.
    for k in 0..3 {
        assert!(
            diffs[k + 1].abs() * 8.0 < diffs[k].abs(),
            "no convergence: {diffs:?}"
        );
    }
    assert!(diffs[3].abs() < 1e-9, "{diffs:?}");
}

#[test]
fn elastic_system_refuses_what_it_cannot_integrate() {
    use pegdyn::compliant_peg_3d::ElasticError;
    let ring = [SlotKey::ring(Pair::RimTop)];
    let reg = params(FrictionLaw::Regularized, 0.0, 0.0);
    assert!(matches!(
        ElasticPeg3d::<N>::try_new(reg, &ring),
        Err(ElasticError::FrictionLaw)
    ));
    let mut no_friction = params(FrictionLaw::Elastic, 0.0, 0.0);
    no_friction.friction = 0.0;
    assert!(matches!(
        ElasticPeg3d::<N>::try_new(no_friction, &ring),
        Err(ElasticError::Friction(_))
    ));
    let err = ElasticPeg3d::<21>::try_new(params(FrictionLaw::Elastic, 0.0, 0.0), &ring)
        .err()
        .unwrap();
    assert_eq!(
        err,
        ElasticError::Slots {
            slots: 1,
            state: 21
        }
    );
    assert!(err.to_string().contains("18"), "{err}");
}

/// As [`elastic_law_holds_a_load_inside_the_cone_without_creep`] over 1 s
/// (4.2 million steps: run with `--ignored`).
#[test]
#[ignore = "4.2 million RODAS4 steps"]
fn elastic_law_holds_a_load_for_one_second() {
    let push = 0.5 * MU * load(&params(FrictionLaw::Elastic, 0.0, 0.0));
    let prm = params(FrictionLaw::Elastic, push, push);
    let sys = elastic(prm);
    let y0 = with_displacement(&start(&prm, Vector3::zeros()), push / ring_stiffness(&prm));
    let options = Options {
        max_steps: 20_000_000,
        output: OutputMode::AtTimes(vec![0.0, 0.001, 1.0]),
        ..Options::with_tolerances(1e-8, 1e-13)
    };
    let sol = solve(&sys, Method::Rodas4, (0.0, y0), 1.0, &options).unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    let slip = drift(&sol, 0.001);
    eprintln!("slip {slip:e} m in 1 s; {} steps", sol.stats.steps);
    assert!(slip <= 1e-9, "elastic law slipped {slip:e} m in 1 s");
}
