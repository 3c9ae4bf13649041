//! The stick-capable friction law of the compliant planar peg
//! (Hertz–Mindlin tangential compliance capped by Coulomb, `docs/compliant.md`):
//! a peg under a load inside the friction cone holds without creep, one
//! outside slides at the Coulomb force, the energy balance
//! `T + P + E_t − W + S` closes with `S` never decreasing, and the
//! regularized law approaches it as its velocity scale shrinks.

use nalgebra::SVector;
use pegdyn::compliant_peg::{
    CompliantParams, CompliantSpec, CompliantSystem, ElasticSystem, FrictionLaw, Load, PegState,
};
use pegdyn::integrate::{Method, Options, OutputMode, Solver};
use pegdyn::system::OdeSystem;

fn params(mu: f64, law: FrictionLaw, v_s: f64) -> CompliantParams {
    let mut spec = CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, mu);
    spec.friction_law = law;
    spec.slip_velocity = v_s;
    CompliantParams::try_new(spec).unwrap()
}

/// Upright peg against the right side of the hole (edge and wall contacts
/// slightly loaded), pushed sideways by `f₂` and axially by `f₁`.
fn side_start(p: &CompliantParams) -> PegState {
    let r = p.spec.geometry.peg_radius;
    let mut start = PegState::centred(p, 0.02);
    start.x = 0.025 - r + 2e-7;
    start
}

/// The states at `times` of the run from `y0` (RODAS4, tight tolerances).
fn states_at<const N: usize, S: OdeSystem<N>>(
    sys: &S,
    y0: SVector<f64, N>,
    times: &[f64],
) -> Vec<SVector<f64, N>> {
    let mut options = Options::with_tolerances(1e-8, 1e-13);
    options.output = OutputMode::AtTimes(times.to_vec());
    let sol = Solver::new(Method::Rodas4, options)
        .solve(sys, 0.0, y0, *times.last().unwrap())
        .unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    sol.x
}

/// Depths of the elastic-law run at `times` (RODAS4, tight tolerances).
fn elastic_depths(mu: f64, load: &Load, times: &[f64]) -> (Vec<f64>, Vec<SVector<f64, 12>>) {
    let p = params(mu, FrictionLaw::Elastic, 1e-5);
    let sys = ElasticSystem::new(&p, load);
    let x = states_at(&sys, side_start(&p).to_vector_elastic(), times);
    (x.iter().map(|y| sys.sample(y).depth).collect(), x)
}

fn regularized_depths(mu: f64, v_s: f64, load: &Load, times: &[f64]) -> Vec<f64> {
    let p = params(mu, FrictionLaw::Regularized, v_s);
    let sys = CompliantSystem::new(&p, load);
    let x = states_at(&sys, side_start(&p).to_vector(), times);
    x.iter().map(|y| sys.sample(y).depth).collect()
}

const HOLD: Load = Load {
    axial: 2.0,
    radial: 50.0,
    torque: 0.0,
};

const SLIDE: Load = Load {
    axial: 20.0,
    radial: 50.0,
    torque: 0.0,
};

#[test]
fn elastic_law_holds_a_load_inside_the_cone_without_creep() {
    // After the tip into two-point contact has settled (by 0.1 s), the
    // elastic law holds the depth to rounding for the next 0.2 s; the
    // regularized law (v_s = 1e-5 m/s) creeps meanwhile.
    let times = [0.05, 0.1, 0.3];
    let (d, ys) = elastic_depths(0.1, &HOLD, &times);
    let reg = regularized_depths(0.1, 1e-5, &HOLD, &times);
    let held = d[2] - d[1];
    let crept = reg[2] - reg[1];
    assert!(held.abs() <= 1e-15, "elastic law moved {held:e} m");
    assert!(crept > 1e-8, "regularized creep {crept:e} m");
    // Stuck inside the cone: every loaded contact below full utilisation,
    // speeds at rounding level.
    let y = ys[2];
    assert!(
        y[3].abs() < 1e-12 && y[4].abs() < 1e-12,
        "{:?}",
        y.as_slice()
    );
    let p = params(0.1, FrictionLaw::Elastic, 1e-5);
    let s = ElasticSystem::new(&p, &HOLD).sample(&y);
    assert!(s.f_edge > 1.0 && s.f_wall > 1.0, "{s:?}");
    assert!(s.friction_edge.abs() < 0.1 * s.f_edge, "{s:?}");
    assert!(s.friction_wall.abs() < 0.1 * s.f_wall, "{s:?}");
}

#[test]
fn elastic_law_slides_at_the_coulomb_force() {
    // From rest in two-point contact under f₁ = 2 N, f₂ = 50 N (held), the
    // axial force rises to 20 N: the peg slides in. Where a loaded contact slides (|v| > 1 mm/s) its spring is
    // saturated and the friction force is μ f against the slip (to 1 %:
    // the contact vibrates along its normal as it slides), except
    // within the presliding displacement 2 ξ_max after a slip reversal
    // (rocking reverses the slip at the edge contact a few times).
    use pegdyn::generated::compliant_peg_elastic as model;
    let p = params(0.1, FrictionLaw::Elastic, 1e-5);
    let sys = ElasticSystem::new(&p, &SLIDE);
    let pv = p.vector_elastic(&SLIDE);
    // Start from the held two-point state of the inside-the-cone load.
    let held = elastic_depths(0.1, &HOLD, &[0.1]).1[0];
    let (mut sliding, mut at_coulomb) = (0usize, 0usize);
    let mut options = Options::with_tolerances(1e-8, 1e-13);
    options.store = false;
    let sol = Solver::new(Method::Rodas4, options)
        .with_observer(|_t, y: &SVector<f64, 12>| {
            let model::ContactsOut {
                normal: f,
                friction: ft,
                slip: v,
                ..
            } = model::contacts(y, &pv);
            for c in 0..4 {
                if f[c] > 1.0 && v[c].abs() > 1e-3 {
                    sliding += 1;
                    if (-ft[c] * v[c].signum() / (0.1 * f[c]) - 1.0).abs() < 1e-2 {
                        at_coulomb += 1;
                    }
                }
            }
        })
        .solve(&sys, 0.0, held, 0.01)
        .unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    let advanced = sys.sample(&sol.x_final).depth - sys.sample(&held).depth;
    assert!(advanced > 2e-5, "not sliding: {advanced:e} m");
    assert!(sliding > 100, "{sliding} sliding samples");
    eprintln!("{at_coulomb} of {sliding}");
    assert!(
        at_coulomb as f64 > 0.9 * sliding as f64,
        "{at_coulomb} of {sliding} sliding samples at the Coulomb force"
    );
}

#[test]
fn energy_balance_closes_with_the_stored_tangential_energy() {
    // The rocking two-point start of tests/compliant_peg/energy.rs.
    let p = params(0.3, FrictionLaw::Elastic, 1e-5);
    let load = Load {
        axial: 20.0,
        radial: 2.0,
        torque: -0.3,
    };
    let sys = ElasticSystem::new(&p, &load);
    let y0 = PegState::two_point(&p, 0.01, 0.0)
        .unwrap()
        .to_vector_elastic();
    let h0 = sys.sample(&y0).balance();
    let (mut drift, mut scale, mut stored, mut min_step, mut last_s) =
        (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64, 0.0);
    let mut options = Options::with_tolerances(1e-10, 1e-14);
    options.store = false;
    let sol = Solver::new(Method::Rodas4, options)
        .with_observer(|_t, y: &SVector<f64, 12>| {
            let s = sys.sample(y);
            drift = drift.max((s.balance() - h0).abs());
            scale = scale.max(s.work.abs()).max(s.kinetic);
            stored = stored.max(s.tangential);
            min_step = min_step.min(s.dissipation - last_s);
            last_s = s.dissipation;
        })
        .solve(&sys, 0.0, y0, 0.03)
        .unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    eprintln!(
        "drift {drift:e} scale {scale:e} stored {stored:e} min_step {min_step:e} S {last_s:e}"
    );
    assert!(last_s > 1e-3 * scale, "S = {last_s:e}, scale {scale:e}");
    assert!(stored > 0.0);
    assert!(min_step >= -1e-12 * scale, "S decreased by {min_step:e}");
    assert!(
        drift < 1e-6 * scale,
        "balance drift {drift:e}, scale {scale:e}"
    );
}

#[test]
fn regularized_law_approaches_the_elastic_one_as_v_s_shrinks() {
    // Depth 1 ms into the sliding start: the regularized law converges
    // linearly in v_s (each tenfold smaller v_s shrinks the change tenfold)
    // to a limit within the elastic law's presliding displacement
    // (ξ_max = μ k δ / C_t ≈ 7e-8 m here) of the elastic law's depth.
    let times = [0.001];
    let (el, _) = elastic_depths(0.1, &SLIDE, &times);
    let diffs: Vec<f64> = [1e-3, 1e-4, 1e-5, 1e-6]
        .iter()
        .map(|&v_s| (regularized_depths(0.1, v_s, &SLIDE, &times)[0] - el[0]).abs())
        .collect();
    for w in diffs.windows(2) {
        assert!(w[1] < w[0], "{diffs:?}");
    }
    for w in diffs.windows(3) {
        let ratio = (w[0] - w[1]) / (w[1] - w[2]);
        assert!(ratio > 5.0, "not converging ~ v_s: {diffs:?}");
    }
    assert!(diffs[3] < 2e-7, "{diffs:?}");
}

#[test]
fn elastic_sweep_classes_match_the_regularized_ones_away_from_the_boundary() {
    use pegdyn::jamming::dynamic::{self, SweepSetup, SweepSpec};
    // The shipped sweep of scenes/jamming.toml on a 3 x 3 grid (corners and
    // centre of its load range: every point far from the parallelogram's
    // boundary).
    let setup = SweepSetup::new(SweepSpec {
        early_stop: true,
        ..SweepSpec::reference()
    })
    .unwrap();
    let classes = |s: &SweepSetup| -> Vec<_> {
        dynamic::run(s, 4.5, 6.0, 3, |_, _| {})
            .unwrap()
            .1
            .iter()
            .map(|p| p.point.class)
            .collect()
    };
    let regularized = classes(&setup);
    let elastic = classes(
        &setup
            .clone()
            .with_friction_law(FrictionLaw::Elastic)
            .unwrap(),
    );
    assert_eq!(elastic, regularized);
    let stuck = elastic.iter().filter(|c| c.is_stuck()).count();
    assert!(stuck > 0 && stuck < elastic.len(), "{elastic:?}");
}

#[test]
fn insert_compliant_scene_takes_the_elastic_law() {
    use pegdyn::scene::document::Document;
    use pegdyn::scene::kinds::insert_compliant::InsertCompliantScene;
    let text = include_str!("../../scenes/insert_compliant.toml").replace(
        "[insert_compliant]",
        "[insert_compliant]\nfriction_law = \"elastic\"\ntangential_damping = 2e-4",
    );
    let scene: InsertCompliantScene = Document::parse(&text).and_then(|d| d.body()).unwrap();
    let built = scene.build().unwrap();
    assert_eq!(built.params.spec.friction_law, FrictionLaw::Elastic);
    assert_eq!(built.params.spec.tangential_damping, 2e-4);
    let bad = text.replace("tangential_damping = 2e-4", "tangential_damping = -1.0");
    let scene: InsertCompliantScene = Document::parse(&bad).and_then(|d| d.body()).unwrap();
    let err = scene.build().unwrap_err().to_string();
    assert!(err.contains("insert_compliant.tangential_damping"), "{err}");
}
