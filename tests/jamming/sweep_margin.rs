//! The dynamic sweep's margin to its exact parallelogram
//! (`SweepSetup::margin_gradient`, dual numbers through the whole chain:
//! tilt of the requested depth, the start state's Whitney depth, corners,
//! nearest edge) against Richardson-extrapolated central differences of the
//! margin of setups rebuilt with the design moved (`SweepSetup::new` and
//! `Parallelogram::margin`, the code the sweep's CSV reads), over load
//! ratios across the diagram and random designs.

use pegdyn::jamming::PegHole;
use pegdyn::jamming::dynamic::{SweepSetup, SweepSpec};

use crate::common::Rng;

/// The reference sweep's setup at design `(r, c, μ, l)`.
fn setup(x: [f64; 4]) -> SweepSetup {
    SweepSetup::new(SweepSpec {
        peg: PegHole::try_new(x[0], x[1], x[2]).expect("a valid peg"),
        depth: x[3],
        ..SweepSpec::reference()
    })
    .expect("a valid setup")
}

/// Richardson-extrapolated central difference (steps `h`, `h/2`).
fn difference(f: impl Fn(f64) -> f64, x: f64, h: f64) -> f64 {
    let central = |h: f64| (f(x + h) - f(x - h)) / (2.0 * h);
    let (d1, d2) = (central(h), central(0.5 * h));
    (4.0 * d2 - d1) / 3.0
}

#[test]
fn the_sweep_margins_derivatives_match_differences_of_rebuilt_setups() {
    let mut rng = Rng(20_261_202);
    let mut checked = 0;
    let mut worst: f64 = 0.0;
    for _ in 0..12 {
        // r 5–15 mm, c 0.005–0.02, μ 0.1–0.5, l from 1.5 to 3 times the
        // least two-point depth √(D² − d²).
        let (r, c, mu) = (
            rng.uniform(0.005, 0.015),
            rng.uniform(0.005, 0.02),
            rng.uniform(0.1, 0.5),
        );
        let big_d = 2.0 * r / (1.0 - c);
        let least = (big_d * big_d - 4.0 * r * r).sqrt();
        let x = [r, c, mu, least * rng.uniform(1.5, 3.0)];
        let base = setup(x);
        for _ in 0..6 {
            let q = [rng.uniform(-4.0, 4.0), rng.uniform(-8.0, 8.0)];
            let m = base.margin_gradient(q);
            // The value is the sweep's own margin.
            let plain = base.diagram.margin(q);
            assert!(
                (m.value - plain).abs() <= 1e-12 * plain.abs().max(1.0),
                "{x:?}, {q:?}: {} against the diagram's {plain}",
                m.value
            );
            let Some(g) = m.gradient else {
                continue;
            };
            for (k, exact) in g.to_array().into_iter().enumerate() {
                let h = 1e-4 * x[k];
                let fd = difference(
                    |v| {
                        let mut y = x;
                        y[k] = v;
                        setup(y).diagram.margin(q)
                    },
                    x[k],
                    h,
                );
                // Relative to the derivative, or to the margin's size per
                // unit of the input where the derivative is near zero.
                let scale = fd.abs().max(1e-3 * m.value.abs().max(1.0) / x[k]);
                let e = (exact - fd).abs() / scale;
                worst = worst.max(e);
                assert!(
                    e < 1e-7,
                    "{x:?}, q = {q:?}, d m/d x{k}: exact {exact:e}, difference {fd:e}"
                );
                checked += 1;
            }
        }
    }
    eprintln!("{checked} derivatives, worst relative mismatch {worst:.1e}");
    assert!(checked >= 200, "{checked} derivatives checked");
}

#[test]
fn on_a_corners_bisector_the_margin_has_no_derivative() {
    // The origin is equally far from the mirrored pair of edges (the
    // diagram is point-symmetric): the two nearest edges tie.
    let base = setup([0.0125, 0.01, 0.3, 0.01]);
    let m = base.margin_gradient([0.0, 0.0]);
    assert!(m.value > 0.0);
    assert!(m.gradient.is_none(), "{m:?}");
    // Just off it (the two distances 1e-4 apart, far above
    // `sweep_margin::KINK`), one edge is nearer and the derivative is back.
    let off = base.margin_gradient([0.0, 1e-3]);
    assert!(off.gradient.is_some(), "{off:?}");
}
