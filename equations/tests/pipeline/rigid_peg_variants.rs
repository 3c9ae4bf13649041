//! The derivation of the rigid three-point peg and its variants: the planar
//! specialization makes the ψ Lagrange row and the lateral centre-of-mass
//! row vanish identically (the planar motion solves the 2-DOF equations);
//! every variant's residual is linear in its unknowns, so A = ∂R/∂u and
//! b = −R(0) are exact; the mass matrix is diagonal; the normal forces do
//! no virtual work; the transport-theorem v_C and a_C equal the fixed-frame
//! derivatives rotated by −ψ; and substitution is simultaneous and
//! simplifying.

use pegdyn_equations::models::rigid_peg::variants::{Variant, specialize};
use pegdyn_equations::models::rigid_peg::{self, Derivation};
use pegdyn_equations::{Expr, Graph};

const VARIANTS: [Variant; 4] = [
    Variant::Full,
    Variant::Frictionless,
    Variant::Planar,
    Variant::PlanarFrictionless,
];

#[test]
fn planar_specialization_makes_the_psi_and_lateral_rows_vanish() {
    for v in VARIANTS {
        let g = Graph::new();
        let d = rigid_peg::derive(&g);
        let sp = specialize(&g, &d, v);
        let want = if v.is_planar() { 2 } else { 0 };
        assert_eq!(sp.vanished.len(), want, "{v:?}");
        for r in &sp.vanished {
            assert_eq!(r.as_const(), Some(0.0), "{v:?}: {r}");
        }
        assert_eq!(sp.rows.len(), 5 - want);
    }
}

#[test]
fn residual_rows_are_linear_in_the_unknowns() {
    for v in VARIANTS {
        let g = Graph::new();
        let d = rigid_peg::derive(&g);
        let sp = specialize(&g, &d, v);
        let unknowns: Vec<Expr<'_>> = sp
            .accel
            .iter()
            .chain(&sp.moments)
            .chain(&sp.normal)
            .copied()
            .collect();
        for r in &sp.rows {
            for &u in &unknowns {
                let du = r.diff(u);
                for &w in &unknowns {
                    assert_eq!(du.diff(w).as_const(), Some(0.0), "{v:?}: ∂²R/∂{u}∂{w}");
                }
            }
        }
    }
}

/// The mass matrix entries ∂²T/∂q̇_i∂q̇_j of the 2-DOF derivation.
fn mass<'g>(d: &Derivation<'g>) -> [[Expr<'g>; 2]; 2] {
    let [_, _, gd, pd] = d.state;
    let rates = [gd, pd];
    rates.map(|a| rates.map(|b| d.kinetic.diff(a).diff(b)))
}

#[test]
fn mass_matrix_is_diagonal_and_independent_of_psi() {
    let g = Graph::new();
    let d = rigid_peg::derive(&g);
    let m = mass(&d);
    assert_eq!(m[0][1].as_const(), Some(0.0), "M_γψ = {}", m[0][1]);
    assert_eq!(m[1][0].as_const(), Some(0.0));
    let psi = d.state[1];
    assert_eq!(d.kinetic.diff(psi).as_const(), Some(0.0), "T depends on ψ");
}

#[test]
fn normal_forces_do_no_virtual_work() {
    // Each contact's normal is perpendicular to both columns of its
    // velocity Jacobian: checked numerically with the interpreter, because
    // the cancellation needs trigonometric identities.
    let g = Graph::new();
    let d = rigid_peg::derive(&g);
    let [_, _, gd, pd] = d.state;
    let names: Vec<String> = g.symbols().iter().map(|(_, i)| i.name.clone()).collect();
    let mut vals = vec![1.0; names.len()];
    let set = |vals: &mut Vec<f64>, n: &str, v: f64| {
        let k = names.iter().position(|x| x == n).expect(n);
        vals[k] = v;
    };
    for (n, v) in [("D_hole", 0.05), ("d_peg", 0.04995), ("H", 0.07)] {
        set(&mut vals, n, v);
    }
    set(&mut vals, "gamma0", 2.0 * (0.00005f64 / 0.1).sqrt().asin());
    for gv in [0.05, 0.3, 1.0] {
        set(&mut vals, "gamma", gv);
        for (i, v) in d.contact_velocities.iter().enumerate() {
            for rate in [gd, pd] {
                let dot = g.sum((0..3).map(|k| v[k].diff(rate) * d.geo.normals[i][k]));
                let scale = g.sum((0..3).map(|k| v[k].diff(rate).square())).sqrt();
                let (x, s) = (eval_at(&g, dot, &vals), eval_at(&g, scale, &vals));
                assert!(x.abs() < 1e-14 * s, "contact {i} at γ = {gv}: J·n = {x}");
            }
        }
    }
}

fn eval_at(g: &Graph, e: Expr<'_>, vals: &[f64]) -> f64 {
    pegdyn_equations::eval::eval(g, e.id(), |s| vals[s.index()])
}

#[test]
fn substitution_is_simultaneous_and_simplifies() {
    let g = Graph::new();
    let (x, y, z) = (g.var("x"), g.var("y"), g.var("z"));
    let e = x - 2.0 * y;
    assert_eq!(e.subs(&[(x, y), (y, x)]), y - 2.0 * x);
    assert_eq!((x * z + y * z).subs(&[(y, -x)]), g.constant(0.0));
    assert_eq!((x.cos() * z).subs(&[(x, g.constant(0.0))]), z);
    assert_eq!(e.subs(&[(z, x)]), e, "untouched expressions keep their id");
}

#[test]
fn transport_theorem_equals_the_fixed_frame_derivatives() {
    // C in fixed components, differentiated twice by the generator, then
    // rotated by −ψ with numbers: the transport-theorem v_C and a_C.
    let g = Graph::new();
    let d = rigid_peg::derive(&g);
    let [gamma, psi, gd, pd] = d.state;
    let [gdd, pdd] = d.accel;
    let (eta, z) = (d.geo.eta_c, d.geo.z_c);
    let fixed = [eta * psi.cos(), eta * psi.sin(), z];
    let pairs = [(gamma, gd), (psi, pd), (gd, gdd), (pd, pdd)];
    let v = fixed.map(|c| c.dt(&pairs[..2]));
    let a = v.map(|c| c.dt(&pairs));
    let names: Vec<String> = g.symbols().iter().map(|(_, i)| i.name.clone()).collect();
    let index = |n: &str| names.iter().position(|x| x == n).expect(n);
    let mut vals = vec![0.0; names.len()];
    for (n, x) in [("D_hole", 0.05), ("d_peg", 0.04995), ("H", 0.07)] {
        vals[index(n)] = x;
    }
    vals[index("gamma0")] = 2.0 * (0.00005f64 / 0.1).sqrt().asin();
    let states = [
        [0.05, 0.3, -2.0, 10.0, 1.0, -3.0],
        [0.4, -2.0, 1.5, -3.0, -20.0, 4.0],
        [1.2, 2.5, -0.3, 0.7, 0.5, 0.5],
    ];
    for st in states {
        for (n, x) in ["gamma", "psi", "gammadot", "psidot", "gammaddot", "psiddot"]
            .iter()
            .zip(st)
        {
            vals[index(n)] = x;
        }
        let (s, c) = st[1].sin_cos();
        let local = |w: [Expr<'_>; 3]| {
            let w = w.map(|e| eval_at(&g, e, &vals));
            [c * w[0] + s * w[1], -s * w[0] + c * w[1], w[2]]
        };
        for (fixed, rotating) in [(v, d.com_velocity), (a, d.com_acceleration)] {
            let want = local(fixed);
            let got = rotating.map(|e| eval_at(&g, e, &vals));
            let scale = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            for k in 0..3 {
                assert!(
                    (got[k] - want[k]).abs() < 1e-13 * scale,
                    "component {k} at {st:?}: {} vs {}",
                    got[k],
                    want[k]
                );
            }
        }
    }
}
