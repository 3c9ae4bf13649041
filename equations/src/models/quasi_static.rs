//! The quasi-static contact-force solution of the compliant planar peg, Eqs. 51–54, derived
//! here from the contact geometry (not typed in from the printed result).
//!
//! Paper frame (Fig. 5): x lateral, y along the hole axis into the hole, θ the
//! tilt, positive in the sense of the rotation matrix R(θ) = [[c, s], [−s, c]]
//! (body → world) used by Eqs. 27–30. Body axes at the centre of mass C: x
//! across the peg, y along it towards the tip; C is l_c above the tip face.
//!
//! - A, the hole-mouth edge on the peg side, body point (−r, l_c − l); force
//!   on the peg f_A (n_A − μ a), n_A = R(1, 0) = (c, −s), a = R(0, 1) = (s, c)
//!   the axis towards the tip (friction opposes insertion).
//! - B, the tip corner on the wall x = D, body point (r, l_c); force
//!   f_B ((−1, 0) − μ (0, 1)).
//! - Input force f₁ a + f₂ n_A (f₁ axial, f₂ radial), input moment M about C
//!   in the sense of θ, so J θ̈ = M − Σ τ with τ = Δx F_y − Δy F_x.
//!
//! The force balance m (ẍ, ÿ) = F + f_A u_A + f_B u_B is solved for (f_A, f_B)
//! by Cramer's rule (determinant −k₃ of Eq. 52), then M = J θ̈ + Σ τ. One-point
//! forms (Eqs. 53, 54): the normal force from the balance along the contact
//! normal, then M. `whitney_tip` is the same equilibrium in Whitney's hole
//! frame (mirror image, moment about the tip, quasi-static), the form the
//! jamming diagram uses (`pegdyn::jamming::forces`).
//! Units: N, N·m, m, kg, kg·m², rad, m/s², rad/s².

use crate::GenError;
use crate::builder::{ModelBuilder, Outputs};
use crate::expr::Expr;
use crate::model::Output;

type V2<'g> = (Expr<'g>, Expr<'g>);

fn torque<'g>(at: V2<'g>, f: V2<'g>) -> Expr<'g> {
    at.0 * f.1 - at.1 * f.0
}

/// R(θ) (bx, by) with R = [[c, s], [−s, c]], given s = sin θ, c = cos θ.
fn rot<'g>(s: Expr<'g>, c: Expr<'g>, bx: Expr<'g>, by: Expr<'g>) -> V2<'g> {
    (c * bx + s * by, -s * bx + c * by)
}

/// Solve [u v] (x, y)ᵀ = w by Cramer's rule.
fn cramer<'g>(u: V2<'g>, v: V2<'g>, w: V2<'g>) -> V2<'g> {
    let det = u.0 * v.1 - u.1 * v.0;
    ((w.0 * v.1 - w.1 * v.0) / det, (u.0 * w.1 - u.1 * w.0) / det)
}

/// Declares the `quasi_static` model: the two-point and one-point
/// contact forces (Eqs. 51–54) of `pose`, `load`, `acc` and the parameters
/// `p`, and Whitney's tip equilibrium of `pose`, `w` and `q = (mu, r)`.
///
/// # Errors
/// Those of [`ModelBuilder`] (none for this fixed model).
pub fn declare(b: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    b.doc(
        "Quasi-static contact forces of the planar peg in two-point and one-point contact \
         (*Dynamic analysis for peg-in-hole assembly with contact deformation*, Eqs. 51-54), derived from the contact geometry. Inputs: pose = (theta rad, \
         l m), load = (f1 axial N, f2 radial N), acc = (xdd, ydd m/s^2, thdd rad/s^2), \
         p = (mu, r m, l_c m, m kg, J kg m^2).",
    );
    b.outputs(Outputs::NONE);
    let g = b.g();
    let theta = b.symbol("theta", "tilt of the peg, rad")?;
    let l = b.symbol("l", "insertion depth, m")?;
    let f1 = b.symbol("f1", "applied force along the peg's axis, N")?;
    let f2 = b.symbol("f2", "applied force across the peg's axis, N")?;
    let xdd = b.symbol("xdd", "lateral acceleration of the centre of mass, m/s²")?;
    let ydd = b.symbol("ydd", "axial acceleration of the centre of mass, m/s²")?;
    let thdd = b.symbol("thdd", "angular acceleration, rad/s²")?;
    let mu = b.parameter("mu", "Coulomb friction coefficient, dimensionless")?;
    let r = b.parameter("r", "peg radius, m")?;
    let l_c = b.parameter("l_c", "distance from the centre of mass to the tip face, m")?;
    let m = b.parameter("m", "mass of the peg, kg")?;
    let j = b.parameter("J", "moment of inertia about the centre of mass, kg·m²")?;
    let (s, c) = (theta.sin(), theta.cos());
    let n_a = (c, -s);
    let axis = (s, c);
    let u_a = (n_a.0 - mu * axis.0, n_a.1 - mu * axis.1);
    let u_b = (-g.constant(1.0), -mu);
    let at_a = rot(s, c, -r, l_c - l);
    let at_b = rot(s, c, r, l_c);
    let force = (f1 * axis.0 + f2 * n_a.0, f1 * axis.1 + f2 * n_a.1);
    let rhs = (m * xdd - force.0, m * ydd - force.1);

    let (fa, fb) = cramer(u_a, u_b, rhs);
    // Lever arms of unit contact forces, expanded: torque(at, f u) =
    // f torque(at, u), and sin² θ + cos² θ folds (torque(at_A, u_A) = μ r − (l_c − l)).
    let arm_a = torque(at_a, u_a).expand();
    let arm_b = torque(at_b, u_b).expand();
    let moment_two = j * thdd + fa * arm_a + fb * arm_b;
    // one-point: normal balance (u_A·n_A = 1, u_B·(−1, 0) = 1)
    // Expanded: f1 s c − f1 c s cancels and f2 (s² + c²) folds to f2.
    let fa_only = (rhs.0 * n_a.0 + rhs.1 * n_a.1).expand();
    let moment_a = j * thdd + fa_only * arm_a;
    let fb_only = -rhs.0;
    let moment_b = j * thdd + fb_only * arm_b;

    // Whitney's frame (hole frame, z into the hole, moment about the tip)
    let fx = b.symbol("fx", "applied lateral force F_x in Whitney's frame, N")?;
    let fz = b.symbol(
        "fz",
        "applied force F_z into the hole in Whitney's frame, N",
    )?;
    let tip_at = (-r * c, -r * s);
    let edge_at = (r * c + l * s, r * s - l * c);
    let u_t = (g.constant(1.0), -mu);
    let u_e = (-c + mu * s, -s - mu * c);
    let (ft, fe) = cramer(u_t, u_e, (-fx, -fz));
    let m_tip = -(ft * torque(tip_at, u_t).expand() + fe * torque(edge_at, u_e).expand());

    let paper_inputs: [(&str, &[Expr<'_>]); 3] = [
        ("pose", &[theta, l]),
        ("load", &[f1, f2]),
        ("acc", &[xdd, ydd, thdd]),
    ];
    const F_A: &str = "normal force f_A at the hole's edge A, N";
    const F_B: &str = "normal force f_B at the peg's tip corner B, N";
    const MOMENT: &str = "input moment about the centre of mass C, N·m";
    b.function(
        "two_point",
        "Eq. 52: edge force f_a (N), tip force f_b (N) and input moment about C (N m) \
         for two-point sliding contact with the given accelerations.",
        &paper_inputs,
        vec![
            ("f_a", F_A, Output::scalar(fa)),
            ("f_b", F_B, Output::scalar(fb)),
            ("moment", MOMENT, Output::scalar(moment_two)),
        ],
    )?;
    b.function(
        "edge_only",
        "Eq. 53 (signs corrected): edge force f_a (N) from the normal balance and \
         input moment about C (N m), one-point contact at the edge A.",
        &paper_inputs,
        vec![
            ("f_a", F_A, Output::scalar(fa_only)),
            ("moment", MOMENT, Output::scalar(moment_a)),
        ],
    )?;
    b.function(
        "tip_only",
        "Eq. 54: tip force f_b (N) from the normal balance and input moment about C \
         (N m), one-point contact at the tip corner B.",
        &paper_inputs,
        vec![
            ("f_b", F_B, Output::scalar(fb_only)),
            ("moment", MOMENT, Output::scalar(moment_b)),
        ],
    )?;
    b.typed_input(
        "q",
        "WhitneyParams",
        "The parameters of Whitney's tip equilibrium ([`whitney_tip`]): friction and radius.",
    )?;
    b.function(
        "whitney_tip",
        "Whitney's frame (x lateral, z into the hole, moment about the tip): tip \
         force f_tip (N), edge force f_edge (N) and the moment M (N m) holding \
         the peg in two-point sliding under applied (F_x, F_z) (N); \
         pose = (theta rad, l m), w = (F_x, F_z), q = (mu, r m).",
        &[("pose", &[theta, l]), ("w", &[fx, fz]), ("q", &[mu, r])],
        vec![
            (
                "f_tip",
                "normal force at the peg's tip, N",
                Output::scalar(ft),
            ),
            (
                "f_edge",
                "normal force at the hole's edge, N",
                Output::scalar(fe),
            ),
            (
                "moment",
                "moment about the tip holding the peg, N·m",
                Output::scalar(m_tip),
            ),
        ],
    )
}
