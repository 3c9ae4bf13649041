//! The planar compliant peg-in-hole model's expression trees
//! (`equations/src/models/compliant_peg/`), evaluated by the interpreter:
//! the symbolic Jacobian against finite differences, contact states arising
//! from the geometry alone (free, two-point), and the Hertz ellipse trees
//! against `pegdyn::hertz`.

use pegdyn::compliant_peg::{ContactPair, PegHoleGeometry};
use pegdyn::hertz::{EllipticityMethod, HertzContact, Material};
use pegdyn_equations::Graph;
use pegdyn_equations::eval::Tape;
use pegdyn_equations::models::compliant_peg::geometry::Contact;
use pegdyn_equations::models::compliant_peg::{self, PARAMS, STATE};

const D: f64 = 0.05;
const C: f64 = 0.002;
const RHO: f64 = 0.2e-3;
const LC: f64 = 0.05;

fn hertz_params(name: &str, c: &HertzContact) -> Vec<(String, f64)> {
    let co = c.coefficients;
    vec![
        (format!("{name}_sum"), c.sum_curvature),
        (format!("{name}_ma"), co.m_a),
        (format!("{name}_mb"), co.m_b),
        (format!("{name}_dstar"), co.delta_star),
        (format!("k_{name}"), c.stiffness()),
    ]
}

/// Parameter values by name: a steel peg, D = 50 mm, c = 0.002, 0.2 mm fillets.
fn params(mu: f64, loads: [f64; 3]) -> (Vec<(String, f64)>, ContactPair) {
    let r = 0.5 * D * (1.0 - C);
    let geo = PegHoleGeometry::try_new(D, r, RHO, RHO).unwrap();
    let pair = ContactPair::try_new(
        &geo,
        &Material::STEEL,
        &Material::STEEL,
        0.0,
        EllipticityMethod::Exact,
    )
    .unwrap();
    let mut p: Vec<(String, f64)> = [
        ("m", 1.5),
        ("J", 2.0e-3),
        ("r", r),
        ("l_c", LC),
        ("D", D),
        ("rho_p", RHO),
        ("rho_h", RHO),
        ("mu", mu),
        ("v_s", 1e-4),
        ("f1", loads[0]),
        ("f2", loads[1]),
        ("M", loads[2]),
        ("e_star", pair.edge.contact_modulus),
        ("hc_alpha", 0.0),
    ]
    .iter()
    .map(|(n, v)| (n.to_string(), *v))
    .collect();
    p.extend(hertz_params("edge", &pair.edge));
    p.extend(hertz_params("wall", &pair.wall));
    (p, pair)
}

/// The state in two-point contact (left edge, right wall) at tilt `theta`
/// with penetrations `delta_a`, `delta_b` (solving the two linear relations
/// of `compliant_peg::geometry` for x and z).
fn two_point(theta: f64, delta_a: f64, delta_b: f64) -> [f64; 3] {
    let r = 0.5 * D * (1.0 - C);
    let (s, c) = theta.sin_cos();
    let x = 0.5 * D - RHO - (LC - RHO) * s - (r - RHO) * c + delta_b;
    let z = RHO + (delta_a - RHO - r + (0.5 * D + RHO + x) * c) / s;
    [x, z, theta]
}

struct Model {
    g: Graph,
}

impl Model {
    fn values(&self, y: &[f64; 8], p: &[(String, f64)]) -> Vec<f64> {
        let mut v = vec![f64::NAN; self.g.symbols().len()];
        for (name, val) in STATE.iter().zip(y) {
            v[self.g.lookup(name).unwrap().index()] = *val;
        }
        for (name, val) in p {
            v[self.g.lookup(name).unwrap().index()] = *val;
        }
        v
    }
}

#[test]
fn parameter_list_is_complete() {
    let g = Graph::new();
    let _ = compliant_peg::build(&g, &Contact::ALL);
    let (p, _) = params(0.1, [0.0; 3]);
    let mut names: Vec<&str> = p.iter().map(|(n, _)| n.as_str()).collect();
    names.sort_unstable();
    let mut want = PARAMS.to_vec();
    want.sort_unstable();
    assert_eq!(names, want);
    for (s, info) in g.symbols() {
        let known = STATE.contains(&info.name.as_str()) || PARAMS.contains(&info.name.as_str());
        assert!(
            known,
            "symbol {} ({s:?}) is neither state nor parameter",
            info.name
        );
    }
}

#[test]
fn jacobian_matches_central_differences() {
    let model = Model { g: Graph::new() };
    let pp = compliant_peg::build(&model.g, &Contact::ALL);
    let rhs_ids: Vec<_> = pp.rhs.iter().map(|e| e.id()).collect();
    let jac_ids: Vec<_> = pp.jacobian.iter().flatten().map(|e| e.id()).collect();
    let (rhs, jac) = (Tape::new(&model.g, &rhs_ids), Tape::new(&model.g, &jac_ids));
    let (mut p, _) = params(0.1, [20.0, 3.0, 0.1]);
    // Exercise the Hunt–Crossley terms too.
    p.iter_mut()
        .filter(|(n, _)| n == "hc_alpha")
        .for_each(|(_, v)| *v = 0.5);
    let [x, z, th] = two_point(0.01, 2e-7, 3e-7);
    // Velocities chosen so that both contacts slip by a few v_s.
    let y = [x, z, th, 3e-4, -2e-4, 0.02, 0.0, 0.0];
    let j = jac.eval(&model.values(&y, &p));
    for col in 0..8 {
        // Steps small against the penetrations (1e-7 m) and v_s (1e-4 m/s).
        let h = if col < 3 { 1e-11 } else { 1e-8 };
        let (mut yp, mut ym) = (y, y);
        yp[col] += h;
        ym[col] -= h;
        let (fp, fm) = (
            rhs.eval(&model.values(&yp, &p)),
            rhs.eval(&model.values(&ym, &p)),
        );
        for row in 0..8 {
            let fd = (fp[row] - fm[row]) / (2.0 * h);
            let ex = j[row * 8 + col];
            // Truncation (relative) plus rounding (ε |f| / h) error of the difference.
            let rounding = 10.0 * f64::EPSILON * fp[row].abs().max(fm[row].abs()) / h;
            let tol = 1e-5 * ex.abs().max(fd.abs()) + rounding;
            assert!(
                (fd - ex).abs() <= tol,
                "J[{row}][{col}] = {ex} vs finite difference {fd}"
            );
        }
    }
}

#[test]
fn centred_upright_peg_feels_no_contact_force() {
    let model = Model { g: Graph::new() };
    let pp = compliant_peg::build(&model.g, &Contact::ALL);
    let roots: Vec<_> = pp.normal.iter().chain(&pp.rhs).map(|e| e.id()).collect();
    let tape = Tape::new(&model.g, &roots);
    let (p, _) = params(0.1, [30.0, 0.0, 0.0]);
    let out = tape.eval(&model.values(&[0.0, 0.01, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0], &p));
    assert!(out[..4].iter().all(|&f| f == 0.0), "forces {:?}", &out[..4]);
    let acc = &out[4 + 3..4 + 6];
    assert_eq!(acc[0], 0.0);
    assert!((acc[1] - 30.0 / 1.5).abs() < 1e-12);
    assert_eq!(acc[2], 0.0);
}

#[test]
fn tilted_peg_in_two_point_contact_has_both_forces_positive() {
    let model = Model { g: Graph::new() };
    let pp = compliant_peg::build(&model.g, &Contact::ALL);
    let roots: Vec<_> = pp.normal.iter().chain(&pp.delta).map(|e| e.id()).collect();
    let tape = Tape::new(&model.g, &roots);
    let (p, pair) = params(0.1, [0.0; 3]);
    for (theta, da, db) in [(0.005, 1e-7, 2e-7), (0.02, 3e-7, 1e-7)] {
        let [x, z, th] = two_point(theta, da, db);
        let out = tape.eval(&model.values(&[x, z, th, 0.0, 0.0, 0.0, 0.0, 0.0], &p));
        let (f, d) = (&out[..4], &out[4..]);
        // Order: edge_left, wall_right, edge_right, wall_left.
        assert!(
            (d[0] - da).abs() < 1e-12 && (d[1] - db).abs() < 1e-12,
            "δ = {d:?}"
        );
        assert!(f[0] > 0.0 && f[1] > 0.0, "forces {f:?}");
        assert!((f[0] - pair.edge.load(da)).abs() < 1e-9 * f[0]);
        assert!((f[1] - pair.wall.load(db)).abs() < 1e-9 * f[1]);
        assert!(
            f[2] == 0.0 && f[3] == 0.0,
            "mirror contacts must be open: {f:?}"
        );
    }
}

#[test]
fn ellipse_trees_agree_with_runtime_hertz() {
    let model = Model { g: Graph::new() };
    let pp = compliant_peg::build(&model.g, &[Contact::EdgeLeft, Contact::WallRight]);
    let roots: Vec<_> = pp
        .ellipse
        .iter()
        .flat_map(|e| [e.a, e.b, e.p0, e.delta])
        .chain(pp.normal.iter().copied())
        .chain(pp.delta.iter().copied())
        .map(|e| e.id())
        .collect();
    let tape = Tape::new(&model.g, &roots);
    let (p, pair) = params(0.0, [0.0; 3]);
    let [x, z, th] = two_point(0.01, 4e-7, 1e-7);
    let out = tape.eval(&model.values(&[x, z, th, 0.0, 0.0, 0.0, 0.0, 0.0], &p));
    for (k, hc) in [pair.edge, pair.wall].iter().enumerate() {
        let q = out[8 + k];
        let s = hc.state(q);
        let got = &out[4 * k..4 * k + 4];
        for (name, g, w) in [
            ("a", got[0], s.a),
            ("b", got[1], s.b),
            ("p0", got[2], s.p0),
            ("delta", got[3], s.delta),
        ] {
            assert!(
                (g - w).abs() <= 1e-12 * w.abs(),
                "contact {k} {name}: tree {g} vs runtime {w}"
            );
        }
        // The approach at the contact force is the penetration.
        let penetration = out[10 + k];
        assert!(
            (got[3] - penetration).abs() < 1e-12 * penetration,
            "{} vs {penetration}",
            got[3]
        );
    }
}

/// The generated code (`pegdyn::generated::compliant_peg`) computes what the
/// interpreter computes at a physical two-point state (the generic
/// `generated_vs_interpreter` test uses random, unphysical inputs).
#[test]
fn generated_functions_match_the_interpreter_at_a_physical_state() {
    use nalgebra::SVector;
    use pegdyn::generated::compliant_peg as cp;
    let model = Model { g: Graph::new() };
    let pp = compliant_peg::build(&model.g, &Contact::ALL);
    let roots: Vec<_> = pp
        .rhs
        .iter()
        .chain(pp.jacobian.iter().flatten())
        .map(|e| e.id())
        .collect();
    let tape = Tape::new(&model.g, &roots);
    let (p, _) = params(0.1, [20.0, 3.0, 0.1]);
    let [x, z, th] = two_point(0.01, 2e-7, 3e-7);
    let y = [x, z, th, 3e-4, -2e-4, 0.02, 0.0, 0.0];
    let want = tape.eval(&model.values(&y, &p));
    let pv: Vec<f64> = cp::P_NAMES
        .iter()
        .map(|n| p.iter().find(|(m, _)| m == n).map(|(_, v)| *v).unwrap())
        .collect();
    let (yv, pv) = (
        SVector::<f64, 8>::from_column_slice(&y),
        SVector::<f64, 24>::from_column_slice(&pv),
    );
    let (f, j) = (cp::rhs(&yv, &pv), cp::jacobian(&yv, &pv));
    let got: Vec<f64> = f
        .iter()
        .copied()
        .chain(j.transpose().iter().copied())
        .collect();
    for (k, (g, w)) in got.iter().zip(&want).enumerate() {
        assert!(
            (g - w).abs() <= 1e-12 * w.abs().max(1.0),
            "entry {k}: generated {g}, interpreted {w}"
        );
    }
}
