//! The rigid three-point peg's accelerations and reactions (N_K, N_B1,
//! N_B2) differentiated with respect to its parameters
//! (`rigid_peg::reaction_sensitivity`: `∂u/∂p = A⁻¹ forward_p`, plus the
//! term of γ0 = arccos(d/D) for D and d) against Richardson-extrapolated
//! central differences of the runtime's own forward dynamics
//! (`generated_model::forward`) with the field of `PegParams` changed, at
//! states from 1.05 γ0 to 1.5 γ0, with and without precession, to 1e-5
//! relative: with the friction directions held (`forward_sensitivity`)
//! and with them opposing the sliding velocities of the changed design
//! (`sliding_forward_sensitivity`).

use nalgebra::{Vector2, Vector3};
use pegdyn::rigid_peg::PegParams;
use pegdyn::rigid_peg::generated_model::{
    Variant, contact_velocities, forward, friction_directions,
};
use pegdyn::rigid_peg::reaction_sensitivity::{
    ForwardDerivative, ForwardSensitivity, forward_sensitivity, gamma0_gradient,
    sliding_forward_sensitivity,
};

use crate::common::Rng;
use crate::common::rigid::loads;

/// `df/dx` (each of the five unknowns) by central differences at steps
/// `h`, `h/2` and `h/4`, Richardson-extrapolated twice (error O(h⁶)).
fn richardson(f: impl Fn(f64) -> [f64; 5], h: f64) -> [f64; 5] {
    let central = |h: f64| {
        let (a, b) = (f(h), f(-h));
        std::array::from_fn::<f64, 5, _>(|i| (a[i] - b[i]) / (2.0 * h))
    };
    let (d1, d2, d4) = (central(h), central(0.5 * h), central(0.25 * h));
    std::array::from_fn(|i| {
        let (r1, r2) = ((4.0 * d2[i] - d1[i]) / 3.0, (4.0 * d4[i] - d2[i]) / 3.0);
        (16.0 * r2 - r1) / 15.0
    })
}

type Field = (
    &'static str,
    fn(&mut PegParams) -> &mut f64,
    fn(&pegdyn::rigid_peg::reaction_sensitivity::ForwardSensitivity) -> ForwardDerivative,
);

const FIELDS: [Field; 6] = [
    (
        "hole_diameter",
        |p| &mut p.hole_diameter,
        |s| s.hole_diameter,
    ),
    ("peg_diameter", |p| &mut p.peg_diameter, |s| s.peg_diameter),
    ("height", |p| &mut p.height, |s| s.height),
    ("mass", |p| &mut p.mass, |s| s.mass),
    ("gravity", |p| &mut p.gravity, |s| s.gravity),
    ("friction", |p| &mut p.friction, |s| s.friction),
];

const UNKNOWNS: [&str; 5] = ["γ̈", "ψ̈", "N_K", "N_B1", "N_B2"];

/// The friction directions opposing the sliding velocities of design `p`.
fn sliding(p: &PegParams, q: Vector2<f64>, qdot: Vector2<f64>) -> [Vector3<f64>; 3] {
    friction_directions(&contact_velocities(Variant::Full, p, q, qdot).unwrap()).unwrap()
}

#[test]
fn reaction_derivatives_match_richardson_differences_of_the_runtime() {
    reaction_derivatives_match(false);
}

#[test]
fn with_sliding_directions_they_match_differences_that_recompute_the_directions() {
    reaction_derivatives_match(true);
}

/// Exact against differences at 16 random states; `follow`: the friction
/// directions are those of each changed design's sliding velocities (else
/// the base design's, held).
fn reaction_derivatives_match(follow: bool) {
    let base = PegParams::fig9();
    let l = loads();
    let mut rng = Rng(31);
    let mut worst = (0.0f64, String::new(), 0.0f64);
    for point in 0..16 {
        let spin = point % 2 == 1;
        let gamma = base.gamma0() * rng.uniform(1.05, 1.5);
        let q = Vector2::new(gamma, rng.uniform(-1.0, 1.0));
        let qdot = Vector2::new(
            rng.uniform(-1.0, 1.0),
            if spin { rng.uniform(-2.0, 2.0) } else { 0.0 },
        );
        // Friction directions of the base design's contact velocities,
        // held fixed under the change, or recomputed for each design.
        let t = sliding(&base, q, qdot);
        let s: ForwardSensitivity = if follow {
            sliding_forward_sensitivity(&base, &l, q, qdot).unwrap()
        } else {
            forward_sensitivity(&base, &l, q, qdot, &t).unwrap()
        };
        for (name, field, pick) in FIELDS {
            let mut p = base;
            let x = *field(&mut p);
            // D and d: 3e-6 of the value, 1/300 of the clearance (γ0
            // moves by 7e-5 rad, 1/30 of γ − γ0 at the closest state);
            // the others 1e-2 of the value.
            let h = if name.ends_with("diameter") {
                3e-6 * x
            } else {
                1e-2 * x
            };
            let fd = richardson(
                |dx| {
                    let mut p = base;
                    *field(&mut p) = x + dx;
                    let t = if follow { sliding(&p, q, qdot) } else { t };
                    let a = forward(Variant::Full, &p, &l, q, qdot, &t).unwrap();
                    [a.qdd[0], a.qdd[1], a.normal[0], a.normal[1], a.normal[2]]
                },
                h,
            );
            let e = pick(&s).to_array();
            // Relative per unknown; an unknown whose derivative is below
            // 1e-3 of the largest of its kind (accelerations, forces; an
            // exact or near zero, such as ∂ψ̈/∂g without precession, whose
            // differences are rounding) is compared against 1e-3 of that
            // largest.
            for i in 0..5 {
                let group = if i < 2 { 0..2 } else { 2..5 };
                let largest = group.map(|j| e[j].abs()).fold(0.0, f64::max);
                let own = e[i].abs() >= 1e-3 * largest;
                let rel = (e[i] - fd[i]).abs() / e[i].abs().max(1e-3 * largest);
                assert!(
                    rel <= 1e-5,
                    "point {point} (γ/γ0 = {:.3}, ψ̇ = {}): ∂{}/∂{name}: exact {:e}, differences {:e}, relative {rel:e}",
                    gamma / base.gamma0(),
                    qdot[1],
                    UNKNOWNS[i],
                    e[i],
                    fd[i]
                );
                if own && rel > worst.0 {
                    worst.0 = rel;
                    worst.1 = format!("∂{}/∂{name} at point {point}", UNKNOWNS[i]);
                }
                if !own {
                    worst.2 = worst.2.max(rel);
                }
            }
        }
    }
    eprintln!(
        "directions {}: worst relative error {:e} ({}); near-zero entries {:e}",
        if follow { "following" } else { "held" },
        worst.0,
        worst.1,
        worst.2
    );
}

/// The directions' term is not negligible: on the Fig. 9 peg with
/// precession, following the sliding velocities changes a geometric
/// derivative by more than a hundred times the agreement tolerance, and
/// leaves the mass, gravity and friction columns (which do not move the
/// velocities) equal to rounding.
#[test]
fn the_sliding_directions_term_matters_for_the_geometry_only() {
    let p = PegParams::fig9();
    let l = loads();
    let q = Vector2::new(1.2 * p.gamma0(), 0.3);
    let qdot = Vector2::new(0.4, 1.5);
    let held = forward_sensitivity(&p, &l, q, qdot, &sliding(&p, q, qdot)).unwrap();
    let follow = sliding_forward_sensitivity(&p, &l, q, qdot).unwrap();
    let rel = |a: ForwardDerivative, b: ForwardDerivative| {
        let (a, b) = (a.to_array(), b.to_array());
        let scale = a[2..].iter().map(|v| v.abs()).fold(0.0, f64::max);
        (2..5)
            .map(|i| (a[i] - b[i]).abs() / scale)
            .fold(0.0, f64::max)
    };
    let geometry = [
        rel(held.hole_diameter, follow.hole_diameter),
        rel(held.peg_diameter, follow.peg_diameter),
        rel(held.height, follow.height),
    ];
    eprintln!(
        "the directions' term, relative to the largest force derivative (D, d, H): {geometry:?}"
    );
    assert!(
        geometry.iter().any(|&r| r > 1e-3),
        "the directions' term changes the geometric derivatives of the forces by {geometry:?}"
    );
    for (name, a, b) in [
        ("mass", held.mass, follow.mass),
        ("gravity", held.gravity, follow.gravity),
        ("friction", held.friction, follow.friction),
    ] {
        assert!(rel(a, b) < 1e-12, "{name}: {}", rel(a, b));
    }
}

/// The γ0 term is what makes D and d agree: without it (the generated
/// columns of D and d alone) the differences disagree by far more than
/// the tolerance, and `gamma0_gradient` is the derivative of the
/// runtime's own γ0.
#[test]
fn the_gamma0_term_is_needed_and_is_the_derivative_of_the_runtime_gamma0() {
    let p = PegParams::fig9();
    let [dg_dh, dg_dp] = gamma0_gradient(&p);
    for (k, exact) in [(0, dg_dh), (1, dg_dp)] {
        let h = 1e-6 * p.hole_diameter;
        let g0 = |dx: f64| {
            let mut q = p;
            if k == 0 {
                q.hole_diameter += dx;
            } else {
                q.peg_diameter += dx;
            }
            q.gamma0()
        };
        let central = |h: f64| (g0(h) - g0(-h)) / (2.0 * h);
        let fd = (4.0 * central(0.5 * h) - central(h)) / 3.0;
        assert!(
            (exact - fd).abs() <= 1e-8 * exact.abs(),
            "{k}: {exact} vs {fd}"
        );
    }
    let q = Vector2::new(1.2 * p.gamma0(), 0.3);
    let qdot = Vector2::new(0.4, 0.7);
    let t = friction_directions(&contact_velocities(Variant::Full, &p, q, qdot).unwrap()).unwrap();
    let s = forward_sensitivity(&p, &loads(), q, qdot, &t).unwrap();
    let without = s.hole_diameter.n_k - s.gamma0.n_k * dg_dh;
    assert!(
        (without - s.hole_diameter.n_k).abs() > 1e-3 * s.hole_diameter.n_k.abs(),
        "the γ0 term is negligible here: {without} vs {}",
        s.hole_diameter.n_k
    );
}
