//! A wedged peg with no wrist holds with the elastic friction law and
//! creeps with the regularized one.
//!
//! The insertion scene's peg (d = 24.925 mm in a 25 mm bore, L = 50 mm,
//! fillets 0.3 and 0.5 mm), tilted in the `xz` plane with its bottom face
//! 3 mm below the mouth and pressed into two-point contact (the rim on the
//! bore wall, the mouth edge on the side, each penetrating [`PRELOAD`]),
//! then released at rest under gravity alone, `μ = 0.3`. The contacts lie
//! 2.27 mm (wall) and 0.48 mm (mouth) below the mouth's plane, 25.0 mm
//! apart: the line between them is 4.1° from the normal at the wall and
//! 6.1° from the normal at the mouth (tilted by the peg's 2°), inside the
//! friction cone (`atan 0.3 ≈ 16.7°`): the wedge of Whitney's two-point
//! statics, held by its own contact forces (about 260 N each). Normal and
//! tangential damping settle the release's vibration within a few
//! milliseconds; the test then measures how far the centre of mass moves.

use crate::insertion_split::insertion_peg;
use nalgebra::{SVector, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::{
    Contacts, ElasticPeg3d, FrictionLaw, Pair, Peg3d, Peg3dParams, Search, SlotKey, pose_state,
};
use pegdyn::integrate::{Method, Options, OutputMode, Solution, solve};
use pegdyn::system::OdeSystem;

/// State length with two slots (the two contacts).
const N: usize = 21;

/// Friction coefficient.
const MU: f64 = 0.3;

/// Depth of the bottom face below the mouth's plane (m).
const DEPTH: f64 = 0.003;

/// Penetration of each contact at the start (m).
const PRELOAD: f64 = 2e-6;

/// The insertion scene's peg with friction [`MU`], Hunt–Crossley damping
/// `α = 30 s/m` and tangential damping `τ_t = 10 µs`.
fn params(law: FrictionLaw) -> Peg3dParams {
    let mut prm = insertion_peg();
    prm.friction = MU;
    prm.friction_law = law;
    prm.damping = 30.0;
    prm.tangential_damping = 1e-5;
    prm
}

/// The pose tilted by `theta` about `y` (top towards `+x`) with the
/// bottom face's centre at `(bx, 0, −DEPTH)`.
fn pose(prm: &Peg3dParams, theta: f64, bx: f64) -> SVector<f64, 7> {
    let q = UnitQuaternion::from_axis_angle(&Vector3::y_axis(), theta);
    let a = q * Vector3::z();
    let p = Vector3::new(bx, 0.0, -DEPTH) + a * (0.5 * prm.length);
    SVector::from([p.x, p.y, p.z, q.w, q.i, q.j, q.k])
}

/// The deepest penetration of `pair` at pose `x` (m; 0 when apart), by a
/// fresh search.
fn penetration(prm: &Peg3dParams, pair: Pair, x: &SVector<f64, 7>) -> f64 {
    let mut out = Contacts::new();
    Search::default().find(pair, prm, x, &prm.vector(), &mut out);
    out.iter().map(|c| c.penetration).fold(0.0, f64::max)
}

/// The root of the increasing `f` on `[lo, hi]` by bisection.
fn bisect(mut lo: f64, mut hi: f64, f: impl Fn(f64) -> f64) -> f64 {
    assert!(f(lo) < 0.0 && f(hi) > 0.0, "no bracket");
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        if f(m) < 0.0 {
            lo = m;
        } else {
            hi = m;
        }
    }
    0.5 * (lo + hi)
}

/// The bottom face's `x` at tilt `theta` where the rim penetrates the wall
/// (at `−x`) by [`PRELOAD`].
fn against_wall(prm: &Peg3dParams, theta: f64) -> f64 {
    let c = prm.bore_radius() - prm.peg_radius();
    // Moving towards −x pushes the rim into the wall.
    -bisect(-c, 4.0 * c, |s| {
        penetration(prm, Pair::RimWall, &pose(prm, theta, -s)) - PRELOAD
    })
}

/// The wedged pose: both contacts at [`PRELOAD`].
fn wedged(prm: &Peg3dParams) -> SVector<f64, 7> {
    let theta = bisect(0.0, 0.1, |t| {
        penetration(prm, Pair::EdgeSide, &pose(prm, t, against_wall(prm, t))) - PRELOAD
    });
    pose(prm, theta, against_wall(prm, theta))
}

fn run<const M: usize, S: OdeSystem<M>>(
    sys: &S,
    y0: SVector<f64, M>,
    times: Vec<f64>,
) -> Solution<M> {
    let t_end = *times.last().unwrap();
    let options = Options {
        max_steps: 2_000_000,
        output: OutputMode::AtTimes(times),
        ..Options::with_tolerances(1e-8, 1e-13)
    };
    let sol = solve(sys, Method::Rodas4, (0.0, y0), t_end, &options).unwrap();
    assert!(sol.stop.is_success(), "{:?}", sol.stop);
    sol
}

/// How far (m) the centre of mass moves from output `from` to the last.
fn moved<const M: usize>(sol: &Solution<M>, from: usize) -> f64 {
    let (a, b) = (sol.x[from], sol.x.last().unwrap());
    ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2) + (b[2] - a[2]).powi(2)).sqrt()
}

/// The wedged peg released at rest, its elastic system (two slots: the
/// rim on the wall, the mouth edge on the side) and its 15 states.
fn release() -> (ElasticPeg3d<N>, SVector<f64, 15>) {
    let prm = params(FrictionLaw::Elastic);
    let x = wedged(&prm);
    let y = pose_state(
        Vector3::new(x[0], x[1], x[2]),
        UnitQuaternion::new_normalize(nalgebra::Quaternion::new(x[3], x[4], x[5], x[6])),
        Vector3::zeros(),
        Vector3::zeros(),
    );
    let slots = [
        SlotKey::point(Pair::RimWall, 0),
        SlotKey::point(Pair::EdgeSide, 0),
    ];
    (ElasticPeg3d::<N>::try_new(prm, &slots).unwrap(), y)
}

/// Both slots touch and hold their friction force inside the cone (stuck,
/// not sliding at `μ Q`), at the end of `sol`.
fn assert_stuck(sys: &ElasticPeg3d<N>, sol: &Solution<N>) {
    for f in sys.slot_forces(sol.x.last().unwrap()).unwrap() {
        let v = f.spring.force;
        let ft = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        eprintln!(
            "{:?}: Q = {:.3} N, |F_t| = {ft:.3} N = {:.3} μQ",
            f.key.pair,
            f.normal_force,
            ft / (MU * f.normal_force)
        );
        assert!(f.touching, "{:?} let go", f.key);
        assert!(ft > 0.05 * MU * f.normal_force && ft < 0.5 * MU * f.normal_force);
    }
}

#[test]
fn a_wedged_peg_holds_for_a_second_with_the_elastic_law_and_creeps_with_the_regularized() {
    let (sys, y) = release();
    let sol = run(&sys, ElasticPeg3d::<N>::state(&y), vec![0.0, 0.005, 1.0]);
    assert_stuck(&sys, &sol);
    let slip = moved(&sol, 1);
    // The regularized law (v_s = 1e-4 m/s) over 4 ms only: it creeps at
    // a speed of the order of v_s, and its steps stay short while it does.
    let rsol = run(
        &Peg3d::new(params(FrictionLaw::Regularized)),
        y,
        vec![0.0, 0.002, 0.004],
    );
    let creep = moved(&rsol, 1);
    eprintln!(
        "elastic: {slip:e} m from 5 ms to 1 s ({} steps); regularized: {creep:e} m from 2 to 4 ms ({} steps)",
        sol.stats.steps, rsol.stats.steps
    );
    assert!(slip <= 1e-9, "elastic law slipped {slip:e} m in 1 s");
    assert!(
        creep > 5e-8,
        "regularized law crept only {creep:e} m in 2 ms"
    );
}
