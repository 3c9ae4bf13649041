//! The generated derivatives of the quasi-static design quantities
//! (`pegdyn::jamming::sensitivities`, the chamfer's
//! `Capture::sensitivities`) against Richardson-extrapolated central
//! differences of the runtime functions that compute those quantities
//! (`diagram::whitney_parallelogram`, `diagram::exact_parallelogram`,
//! `wedging::*`, `Capture::width` …), at random designs, to 1e-8 relative.

use pegdyn::jamming::PegHole;
use pegdyn::jamming::diagram::{Parallelogram, exact_parallelogram, whitney_parallelogram};
use pegdyn::jamming::geometry::min_two_point_depth;
use pegdyn::jamming::sensitivities::{Gradient, ParallelogramSensitivity, sensitivities};
use pegdyn::jamming::wedging::{wedging_angle, wedging_angle_series, wedging_angle_whitney};
use pegdyn::scene::kinds::design_margins::chamfer::Capture;
use pegdyn::scene::kinds::design_margins::chamfer_sensitivity::CaptureGradient;

use crate::common::Rng;

/// `df/dx` by central differences at steps `h`, `h/2` and `h/4`,
/// Richardson-extrapolated twice (error O(h⁶)), so that a step large
/// enough to keep f64 rounding of the differenced quantities (several of
/// which cancel, as Q = −P₁ᵧ + 2 s P₁ₓ) far below 1e-8 still leaves the
/// truncation there.
fn richardson(f: impl Fn(f64) -> f64, x: f64, h: f64) -> f64 {
    let central = |h: f64| (f(x + h) - f(x - h)) / (2.0 * h);
    let (d1, d2, d4) = (central(h), central(0.5 * h), central(0.25 * h));
    let (r1, r2) = ((4.0 * d2 - d1) / 3.0, (4.0 * d4 - d2) / 3.0);
    (16.0 * r2 - r1) / 15.0
}

/// A design: (r, c, μ, l).
#[derive(Clone, Copy, Debug)]
struct Design([f64; 4]);

impl Design {
    fn peg(&self) -> PegHole {
        PegHole::try_new(self.0[0], self.0[1], self.0[2]).unwrap()
    }
    /// The design with input `k` moved by `dx`.
    fn moved(&self, k: usize, dx: f64) -> Design {
        let mut v = self.0;
        v[k] += dx;
        Design(v)
    }
    /// The difference step of input `k`: 2e-2 of its value (of its
    /// distance to 1 for c, whichever is smaller).
    fn step(&self, k: usize) -> f64 {
        let v = self.0[k];
        if k == 1 {
            2e-2 * v.min(1.0 - v)
        } else {
            2e-2 * v
        }
    }
}

/// The largest relative error seen of an entry compared with itself, with
/// what it was, and of a near-zero entry (against the largest share).
#[derive(Default)]
struct Worst(f64, String, f64);

/// `exact` against differences of `q` (a quantity of the design), input by
/// input: each entry to 1e-8 of itself, or, for an entry whose share
/// `|∂q/∂x_k| x_k` is below 1e-3 of the largest share (an exact or near
/// zero, whose differences are rounding), its share to 1e-11 of that
/// largest share (of the quantity when every derivative is zero).
fn check(exact: &Gradient, q: impl Fn(&Design) -> f64, at: &Design, what: &str, worst: &mut Worst) {
    let e = exact.to_array();
    let fd: [f64; 4] =
        std::array::from_fn(|k| richardson(|dx| q(&at.moved(k, dx)), 0.0, at.step(k)));
    // The largest share, or (every derivative zero) the quantity itself.
    let largest = (0..4).map(|k| (e[k] * at.0[k]).abs()).fold(0.0, f64::max);
    let share = if largest > 0.0 { largest } else { q(at).abs() };
    for k in 0..4 {
        let err = (e[k] - fd[k]).abs();
        let rel = err * at.0[k]
            / (e[k] * at.0[k])
                .abs()
                .max(1e-3 * share)
                .max(f64::MIN_POSITIVE);
        assert!(
            rel <= 1e-8,
            "{what} at {at:?}: ∂/∂{}: exact {:e}, differences {:e} (relative {rel:e})",
            Gradient::NAMES[k],
            e[k],
            fd[k]
        );
        let own = (e[k] * at.0[k]).abs() >= 1e-3 * share;
        if own && rel > worst.0 {
            worst.0 = rel;
            worst.1 = format!("{what} ∂/∂{}", Gradient::NAMES[k]);
        }
        if !own && rel > worst.2 {
            worst.2 = rel;
        }
    }
}

/// Every corner, the line and the tilt of a parallelogram.
fn check_parallelogram(
    s: &ParallelogramSensitivity,
    diagram: impl Fn(&Design) -> Parallelogram,
    at: &Design,
    name: &str,
    worst: &mut Worst,
) {
    let d = &diagram;
    let corner = |c: usize, i: usize| move |x: &Design| d(x).corners[c][i];
    let p1 = &s.edge_corner;
    let q = &s.mirrored_corner;
    check(
        &p1.force_ratio,
        corner(2, 0),
        at,
        &format!("{name} P₁ₓ"),
        worst,
    );
    check(
        &p1.moment_ratio,
        corner(2, 1),
        at,
        &format!("{name} P₁ᵧ"),
        worst,
    );
    check(
        &q.force_ratio,
        corner(1, 0),
        at,
        &format!("{name} Qₓ"),
        worst,
    );
    check(
        &q.moment_ratio,
        corner(1, 1),
        at,
        &format!("{name} Qᵧ"),
        worst,
    );
    check(
        &s.slope,
        |x| d(x).two_point_line().0,
        at,
        &format!("{name} slope"),
        worst,
    );
    check(
        &s.intercept,
        |x| d(x).two_point_line().1,
        at,
        &format!("{name} intercept"),
        worst,
    );
    check(&s.tilt, |x| d(x).theta, at, &format!("{name} tilt"), worst);
}

#[test]
fn design_quantities_derivatives_match_richardson_differences_of_the_runtime() {
    let mut rng = Rng(2026);
    let mut worst = Worst::default();
    let (mut exact_checked, mut wedging_checked) = (0, 0);
    for _ in 0..12 {
        let (r, c, mu) = (
            rng.uniform(0.004, 0.02),
            rng.uniform(1e-3, 0.03),
            rng.uniform(0.1, 0.8),
        );
        let peg = PegHole::try_new(r, c, mu).unwrap();
        let l = min_two_point_depth(&peg) * rng.uniform(1.5, 12.0);
        let at = Design([r, c, mu, l]);
        let s = sensitivities(&peg, l).unwrap();
        check_parallelogram(
            &s.whitney,
            |x| whitney_parallelogram(&x.peg(), x.0[3]).unwrap(),
            &at,
            "Whitney",
            &mut worst,
        );
        let exact = s.exact.expect("two-point contact at l > l_min");
        check_parallelogram(
            &exact,
            |x| exact_parallelogram(&x.peg(), x.0[3]).unwrap().unwrap(),
            &at,
            "exact",
            &mut worst,
        );
        exact_checked += 1;
        check(
            &s.wedging.series,
            |x| wedging_angle_series(&x.peg()),
            &at,
            "θ_c series",
            &mut worst,
        );
        check(
            &s.wedging.whitney,
            |x| wedging_angle_whitney(&x.peg()),
            &at,
            "θ_c Whitney",
            &mut worst,
        );
        match (wedging_angle(&peg), s.wedging.exact) {
            (Some(_), Some(g)) => {
                check(
                    &g,
                    |x| wedging_angle(&x.peg()).unwrap(),
                    &at,
                    "θ_c",
                    &mut worst,
                );
                wedging_checked += 1;
            }
            (None, None) => {}
            (value, gradient) => panic!("θ_c {value:?} but its gradient {gradient:?}"),
        }
    }
    assert!(
        exact_checked == 12 && wedging_checked >= 4,
        "{wedging_checked}"
    );
    eprintln!(
        "worst relative error {:e} ({}); near-zero entries {:e}",
        worst.0, worst.1, worst.2
    );
}

#[test]
fn exact_diagram_sensitivity_is_refused_where_two_point_contact_is_not() {
    let peg = PegHole::try_new(0.0125, 0.01, 0.3).unwrap();
    let l_min = min_two_point_depth(&peg);
    assert!(sensitivities(&peg, 0.9 * l_min).unwrap().exact.is_none());
    assert!(sensitivities(&peg, 1.01 * l_min).unwrap().exact.is_some());
    assert_eq!(sensitivities(&peg, -1.0).unwrap_err().field, "l");
    // μ = 0.1, c = 0.05: (1 − c)² (1 + μ²) < 1, no wedging angle.
    let no_wedge = PegHole::try_new(0.0125, 0.05, 0.1).unwrap();
    assert!(wedging_angle(&no_wedge).is_none());
    assert!(
        sensitivities(&no_wedge, 0.01)
            .unwrap()
            .wedging
            .exact
            .is_none()
    );
}

#[test]
fn capture_width_derivatives_match_richardson_differences_of_the_runtime() {
    let mut rng = Rng(99);
    for _ in 0..8 {
        let cap = Capture {
            peg_radius: rng.uniform(0.004, 0.02),
            bore_radius: 0.0,
            rim_fillet: rng.uniform(1e-4, 1e-3),
            mouth_fillet: rng.uniform(1e-4, 2e-3),
            friction: rng.uniform(0.05, 0.8),
            centre_height: rng.uniform(0.01, 0.05),
        };
        let cap = Capture {
            bore_radius: cap.peg_radius * (1.0 + rng.uniform(1e-3, 0.02)),
            ..cap
        };
        let s = cap.sensitivities();
        type Field = (
            &'static str,
            fn(&mut Capture) -> &mut f64,
            fn(&CaptureGradient) -> f64,
        );
        let fields: [Field; 5] = [
            ("peg_radius", |c| &mut c.peg_radius, |g| g.peg_radius),
            ("bore_radius", |c| &mut c.bore_radius, |g| g.bore_radius),
            ("rim_fillet", |c| &mut c.rim_fillet, |g| g.rim_fillet),
            ("mouth_fillet", |c| &mut c.mouth_fillet, |g| g.mouth_fillet),
            ("friction", |c| &mut c.friction, |g| g.friction),
        ];
        type Width = (&'static str, fn(&Capture) -> f64, CaptureGradient);
        let widths: [Width; 3] = [
            ("W_0", Capture::frictionless_width, s.frictionless_width),
            ("W_mu", Capture::width, s.width),
            (
                "aligned tip error",
                Capture::aligned_tip_error,
                s.aligned_tip_error,
            ),
        ];
        for (wname, w, grad) in widths {
            for (fname, field, entry) in fields {
                let mut base = cap;
                let x = *field(&mut base);
                let h = 1e-3 * x;
                let fd = richardson(
                    |dx| {
                        let mut c = cap;
                        *field(&mut c) = x + dx;
                        w(&c)
                    },
                    0.0,
                    h,
                );
                let e = entry(&grad);
                // A zero derivative (the field does not enter) must be
                // zero by differences to rounding: 1e-8 of the width per
                // the field's value.
                let tol = if e == 0.0 {
                    1e-8 * w(&cap) / x
                } else {
                    1e-8 * e.abs()
                };
                assert!(
                    (e - fd).abs() <= tol,
                    "{wname} ∂/∂{fname}: exact {e:e}, differences {fd:e}"
                );
            }
        }
    }
}
