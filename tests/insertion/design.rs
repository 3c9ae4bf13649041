//! The insertion's derivatives in design parameters (the scene fields of
//! `[sensitivities]`): `∂f/∂q` of the right-hand side, in dual numbers
//! through the contact law, the pair functions at their stationary angle,
//! the wrist and the robot frame, against Richardson-extrapolated central
//! differences of the `f64` right-hand side of the scene rebuilt with the
//! field moved, at states of the shipped `insert_rcc` run with the rim on
//! the mouth, the rim on the wall and two-point contact; the start state's
//! derivative against differences of the rebuilt start; `∂f/∂y` at the
//! same states against differences.

use crate::common::differences::richardson;
use crate::common::rcc;
use nalgebra::{SMatrix, SVector};
use pegdyn::compliant_peg_3d::Pair;
use pegdyn::compliant_peg_3d::design::{N_DESIGN, slots};
use pegdyn::compliant_peg_3d::insertion::{Insertion, N_STATE};
use pegdyn::compliant_peg_3d::no_jam::MarginLoad;
use pegdyn::compliant_peg_3d::outcome::counts;
use pegdyn::scene::shared::compliant_peg_3d::design::{FIELDS, design, seeds, slot, values};
use pegdyn::scene::shared::compliant_peg_3d::insertion::RccScene;
use pegdyn::system::OdeSystem;

/// The shipped scene (DOPRI5, as written).
fn shipped() -> String {
    include_str!("../../scenes/insert_rcc.toml").to_string()
}

/// The system of `scene` with field `k` set to `v`.
fn system_with(scene: &RccScene, k: usize, v: f64) -> (Insertion, SVector<f64, N_STATE>) {
    let mut s = scene.clone();
    *slot(&mut s, k) = v;
    let b = s.build().expect("the moved scene is valid");
    let sys = Insertion::new(b.params, Some(b.held), 0.0);
    let y0 = b.start_state(&sys);
    (sys, y0)
}

/// The largest mismatch of two columns, relative to the largest entry of
/// the difference or to `floor`, whichever is larger.
fn mismatch<const R: usize>(exact: &SVector<f64, R>, fd: &SVector<f64, R>, floor: f64) -> f64 {
    (exact - fd).amax() / fd.amax().max(floor).max(1e-300)
}

/// The rounding floor of a difference quotient of `f` with step `h`
/// (relative error 10⁻¹³ of `f`'s largest entry, over `h`).
fn noise<const R: usize>(f: &SVector<f64, R>, h: f64) -> f64 {
    1e-13 * f.amax() / h
}

/// The size of the terms that the right-hand side sums at `(t, y)`: the
/// largest of `f` itself and the accelerations that the contact forces
/// alone would give (`F/m` and `F L/I`). Near a quasi-static balance `f`
/// is a small difference of the contact and wrist forces, and its rounding
/// is set by those forces, not by `f`.
fn term_scale(sys: &Insertion, t: f64, y: &SVector<f64, N_STATE>) -> f64 {
    let f = sys.rhs(t, y).amax();
    let force = sys
        .sample(t, y)
        .expect("the state's contacts set up")
        .total_normal();
    let p = &sys.peg.params;
    f.max(force / p.mass + force * p.length / p.inertia_transverse)
}

/// The column size below which a difference quotient with step `h` cannot
/// show a relative error of `10⁻⁶`: its rounding, about `10⁻¹⁵` of the
/// terms' size `scale` over `h`, is then above `10⁻⁶` of the column. A
/// smaller column is compared in absolute terms, to `10⁻⁶` of this floor.
fn rounding_floor(scale: f64, h: f64) -> f64 {
    1e-15 * scale / h / 1e-6
}

/// The step of [`difference`] along field `k` at `q`: `10⁻⁵ |q|` for the
/// fields that move the contacts' geometry (the clearance and the fillets:
/// a penetration of a micrometre moves by `10⁻⁸` m of its size), `10⁻¹ |q|`
/// for the friction and the contact damping (the right-hand side is linear
/// in them, and their columns are small beside the rounding of the
/// elastic forces), `10⁻³ |q|` for the others; at `q = 0`, `10⁻³` for the
/// precession and spin rates (rad/s) and `10⁻⁸` for the others (the
/// compliance centre at the tip, m).
fn step(k: usize, q: f64) -> f64 {
    let relative = match k {
        4..=6 => 1e-5,
        7 | 8 => 1e-1,
        _ => 1e-3,
    };
    match (k, q == 0.0) {
        // The precession and spin rates (rad/s), zero in the shipped
        // scene: the right-hand side is smooth in them (angles ψ̇ t, φ̇ t).
        (12 | 13, true) => 1e-3,
        (_, true) => 1e-8,
        _ => relative * q.abs(),
    }
}

/// States of the shipped run with the contacts `pairs` (exactly those
/// pairs, one point each), from the middle of each stretch.
fn states(
    sys: &Insertion,
    t: &[f64],
    x: &[SVector<f64, N_STATE>],
    pairs: &[Pair],
) -> Vec<(f64, SVector<f64, N_STATE>)> {
    let want: [usize; Pair::ALL.len()] =
        std::array::from_fn(|k| usize::from(pairs.contains(&Pair::ALL[k])));
    let hits: Vec<usize> = (0..x.len())
        .filter(|&i| counts(&sys.contacts(&x[i])) == want)
        .collect();
    assert!(
        !hits.is_empty(),
        "the shipped run has no state with {pairs:?}"
    );
    let mid = hits[hits.len() / 2];
    vec![(t[mid], x[mid])]
}

#[test]
fn the_parameter_jacobian_matches_differences_of_the_right_hand_side() {
    let (scene, built, run) = rcc::run(&shipped());
    let sys = &run.system;
    let sol = &run.solution;
    let q = values(&scene);
    let mut poses = Vec::new();
    for (name, pairs) in [
        ("rim on the mouth", &[Pair::RimEdge][..]),
        ("rim on the wall", &[Pair::RimWall][..]),
        ("two-point contact", &[Pair::EdgeSide, Pair::RimWall][..]),
    ] {
        for s in states(sys, &sol.t, &sol.x, pairs) {
            poses.push((name, s));
        }
    }
    let mut worst = 0.0_f64;
    for (name, (t, y)) in &poses {
        // Every field, in passes of as many as a run carries.
        let fields: Vec<usize> = (0..FIELDS.len()).collect();
        let mut d = None;
        for pass in fields.chunks(N_DESIGN) {
            let (dp, _) = design(&scene, &built, &seeds(pass));
            let exact: SMatrix<f64, N_STATE, N_DESIGN> = sys
                .parameter_rate(*t, y, &dp)
                .expect("the state's contacts set up");
            for (j, &k) in pass.iter().enumerate() {
                let fd = richardson(q[k], step(k, q[k]), |v| {
                    let (s, _) = system_with(&scene, k, v);
                    s.rate(*t, y).expect("the moved system sets up")
                });
                let floor = rounding_floor(term_scale(sys, *t, y), step(k, q[k]));
                let e = mismatch(&exact.column(j).into_owned(), &fd, floor);
                worst = worst.max(e);
                eprintln!("{name}, {}: {e:.2e}", FIELDS[k]);
                assert!(
                    e < 1e-6,
                    "{name}, d f/d {}: relative mismatch {e:.2e}\nexact {:?}\ndifference {:?}",
                    FIELDS[k],
                    exact.column(j).as_slice(),
                    fd.as_slice()
                );
            }
            d.get_or_insert((dp, exact));
        }
        let (d, exact) = d.expect("a pass");
        // ∂f/∂y at the same state.
        let j = sys.jacobian(*t, y);
        for i in 0..13 {
            let h = 1e-7 * y[i].abs().max(1e-3);
            let (mut up, mut down) = (*y, *y);
            up[i] += h;
            down[i] -= h;
            let fd = (sys.rhs(*t, &up) - sys.rhs(*t, &down)) / (2.0 * h);
            let e = mismatch(&j.column(i).into_owned(), &fd, noise(&sys.rhs(*t, y), h));
            assert!(e < 1e-4, "{name}, d f/d y{i}: relative mismatch {e:.2e}");
        }
        // The sensitivities' rate in one pass (the state seeded with the
        // columns of s): the numbers of J s + ∂f/∂q formed apart.
        #[allow(clippy::cast_precision_loss)] // small integers
        let s = SMatrix::<f64, N_STATE, N_DESIGN>::from_fn(|i, k| {
            ((i * 7 + k * 3) % 11) as f64 / 11.0 - 0.4
        });
        let _ = sys.rhs(*t, y);
        let one_pass = sys
            .sensitivity_rate(*t, y, &s, &d)
            .expect("the state's contacts set up");
        let apart = j * s + exact;
        let e = (one_pass - apart).amax() / apart.amax();
        eprintln!("{name}, one-pass rate against J s + f_q: {e:.1e}");
        assert!(e < 1e-12, "{name}: one-pass rate off by {e:.1e}");
    }
    eprintln!("worst relative mismatch of d f/d q: {worst:.2e}");
}

#[test]
fn the_start_states_derivative_matches_differences_of_the_rebuilt_start() {
    let text = shipped();
    let (scene, built, _) = rcc::run(&text.replace("t_end = 1.2 ", "t_end = 1e-3 "));
    let q = values(&scene);
    for k in 0..FIELDS.len() {
        let (_, y0) = design(&scene, &built, &seeds(&[k]));
        let exact = SVector::<f64, N_STATE>::from_fn(|i, _| slots(&y0[i])[0]);
        let fd = richardson(q[k], step(k, q[k]), |v| system_with(&scene, k, v).1);
        let e = (exact - fd).amax();
        assert!(
            e <= 1e-7 * fd.amax() + 1e-8,
            "d y0/d {}: exact {:?}, difference {:?}",
            FIELDS[k],
            exact.as_slice(),
            fd.as_slice()
        );
    }
    // The values are the start's.
    let sys = Insertion::new(built.params, Some(built.held), 0.0);
    let start = built.start_state(&sys);
    let (_, y0) = design(&scene, &built, &seeds(&[]));
    for i in 0..N_STATE {
        assert!((y0[i].v - start[i]).abs() <= 1e-15 * (1.0 + start[i].abs()));
    }
}

#[test]
fn the_no_jam_margins_gradients_match_differences() {
    // The no-jam margin of the applied load and of the contacts' resultant
    // at states of the shipped run on the wall and in two-point contact:
    // `∂m/∂y` against central differences in each state component, `∂m/∂q`
    // along every field against Richardson-extrapolated differences of the
    // rebuilt system, the applied load's `∂m/∂t` against differences in
    // time.
    let (scene, built, run) = rcc::run(&shipped());
    let sys = &run.system;
    let sol = &run.solution;
    let q = values(&scene);
    let mut checked = 0;
    for (name, pairs) in [
        ("rim on the wall", &[Pair::RimWall][..]),
        ("two-point contact", &[Pair::EdgeSide, Pair::RimWall][..]),
    ] {
        for (t, y) in states(sys, &sol.t, &sol.x, pairs) {
            for load in [MarginLoad::Applied, MarginLoad::Contacts] {
                let value = |s: &Insertion, t: f64, y: &SVector<f64, N_STATE>| {
                    s.no_jam_margin(t, y, load)
                        .expect("sets up")
                        .expect("a plane")
                        .value
                };
                let m = value(sys, t, &y);
                let fields: Vec<usize> = (0..FIELDS.len()).collect();
                for pass in fields.chunks(N_DESIGN) {
                    let (dp, _) = design(&scene, &built, &seeds(pass));
                    let (v, g_y, g_q, rate) = sys
                        .no_jam_margin_gradient(t, &y, &dp, load)
                        .expect("sets up")
                        .expect("a plane");
                    assert!(
                        (v - m).abs() <= 1e-12 * m.abs(),
                        "{name}, {load:?}: the value {v:e} against {m:e}"
                    );
                    let fd = SVector::<f64, 13>::from_fn(|i, _| {
                        richardson(y[i], 1e-6 * y[i].abs().max(1e-3), |v| {
                            let mut moved = y;
                            moved[i] = v;
                            value(sys, t, &moved)
                        })
                    });
                    let exact = SVector::<f64, 13>::from_fn(|i, _| g_y[i]);
                    let e = mismatch(&exact, &fd, 0.0);
                    assert!(
                        e < 1e-6,
                        "{name}, {load:?}, dm/dy: {e:.1e}\n{exact:?}\n{fd:?}"
                    );
                    for (j, &k) in pass.iter().enumerate() {
                        // The margin is far from linear in the fields (the
                        // corners go as 1/μ; F_X/F_Z on the wall moves by
                        // 5 % over 10⁻⁴ of the robot's speed): 10⁻⁵ |q|, at q = 0
                        // 10⁻⁶ (the compliance centre's height, m; the rates, rad/s).
                        let h = if q[k] == 0.0 { 1e-6 } else { 1e-5 * q[k].abs() };
                        let fd = richardson(q[k], h, |v| {
                            let (s, _) = system_with(&scene, k, v);
                            value(&s, t, &y)
                        });
                        // Relative, below an elasticity of 10⁻² or the
                        // differences' rounding (10⁻¹² of the margin over
                        // the step) absolute.
                        let floor =
                            1e-2 * m.abs() / q[k].abs().max(1e-3) + 1e-6 * m.abs().max(1e-2) / h;
                        let e = (g_q[j] - fd).abs() / (fd.abs() + floor);
                        eprintln!(
                            "{name}, {load:?}, dm/d {}: {:.8e} against {fd:.8e}",
                            FIELDS[k], g_q[j]
                        );
                        assert!(
                            e < 1e-6,
                            "{name}, {load:?}, dm/d {}: {} against {fd}",
                            FIELDS[k],
                            g_q[j]
                        );
                        checked += 1;
                    }
                    let fd = richardson(t, 1e-6, |s| value(sys, s, &y));
                    let e = (rate - fd).abs() / fd.abs().max(1e-2);
                    assert!(e < 1e-5, "{name}, {load:?}, dm/dt: {rate} against {fd}");
                }
            }
        }
    }
    assert_eq!(checked, 4 * FIELDS.len());
}
