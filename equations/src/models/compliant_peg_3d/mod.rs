//! The compliant 3-D peg: a rigid cylinder with a filleted bottom rim in a
//! bore with a filleted mouth, six degrees of freedom, Hertz point contacts
//! found along the edge circles at run time.
//!
//! Coordinates (regular at alignment): the centre of mass `p` (hole frame),
//! the unit quaternion `q` of the peg's orientation, the centre-of-mass
//! velocity `v` (hole frame) and the angular velocity `ω` in the peg's
//! principal (body) axes; Newton–Euler equations
//!
//! ```text
//! ṗ = v,   q̇ = ½ q ⊗ (0, ω),
//! m v̇ = F_c + F_a − m g e_z,
//! J ω̇ = Rᵀ(T_c + M_a) − ω × J ω,     J = diag(J_t, J_t, J_a)
//! ```
//!
//! with the contact wrench `(F_c, T_c)` (hole frame, about the centre of
//! mass) an *input*: the runtime finds the contact points and sums their
//! forces, and any further generalized force (a wrist spring–damper, a
//! prescribed frame's reaction) is added to the same input. `F_a`, `M_a` are
//! constant applied loads (hole frame). The state carries the work `W` of
//! the applied loads and the dissipated energy `S` (its rate is the input's
//! seventh component), so that `T + m g z + V_c − W + S` is constant.
//!
//! Per contact pair ([`geometry::Pair`]) one function gives the gap, its
//! first and second derivatives in the edge angle, its gradient in the pose
//! `(p, q)`, the force direction on the peg and the contact point.
//! Units: SI.

pub mod geometry;
pub mod pair;

use crate::GenError;
use crate::builder::{ModelBuilder, Outputs};
use crate::expr::Expr;
use crate::model::Output;
use geometry::{GEOMETRY, POSE, Pair};

/// The module's name.
pub const NAME: &str = "compliant_peg_3d";

/// The module's documentation.
pub const DOC: &str = "Compliant 3-D peg-in-hole: contact-pair gaps along the edge circles and \
                       Newton-Euler dynamics in centre of mass, unit quaternion and body angular \
                       velocity. Inputs: pose x (see X_NAMES), edge angle a, state y, contact \
                       wrench w, parameters p (see P_NAMES). SI units.";

/// What each parameter is, in the order of [`GEOMETRY`] then [`DYNAMICS`].
const PARAM_DOCS: [&str; 16] = [
    "peg radius r, m",
    "peg length L, m",
    "fillet radius of the peg's bottom rim rho_p, m",
    "bore radius R, m",
    "fillet radius of the hole's mouth edge rho_h, m",
    "bore depth h_b, m",
    "mass m, kg",
    "transverse moment of inertia about the centre of mass, kg m^2",
    "axial moment of inertia, kg m^2",
    "gravitational acceleration along -z, m/s^2",
    "applied force x, N",
    "applied force y, N",
    "applied force z, N",
    "applied moment x, N m",
    "applied moment y, N m",
    "applied moment z, N m",
];

/// Names of the state components, in order.
pub const STATE: [&str; 15] = [
    "px",
    "py",
    "pz",
    "q0",
    "q1",
    "q2",
    "q3",
    "vx",
    "vy",
    "vz",
    "wx",
    "wy",
    "wz",
    "work",
    "dissipation",
];

/// What each state component of [`STATE`] is, with its unit.
const STATE_DOCS: [&str; 15] = [
    "centre of mass x, hole frame, m",
    "centre of mass y, hole frame, m",
    "centre of mass z (up the bore axis, 0 at the top face), m",
    "orientation quaternion, scalar part q0",
    "orientation quaternion q1",
    "orientation quaternion q2",
    "orientation quaternion q3",
    "centre-of-mass velocity x, hole frame, m/s",
    "centre-of-mass velocity y, hole frame, m/s",
    "centre-of-mass velocity z, hole frame, m/s",
    "angular velocity about the body x axis, rad/s",
    "angular velocity about the body y axis, rad/s",
    "angular velocity about the body (peg) axis, rad/s",
    "work W of the applied loads since the start, J",
    "energy S dissipated since the start, J",
];

/// What each component of [`WRENCH`] is, with its unit.
const WRENCH_DOCS: [&str; 7] = [
    "contact force x, hole frame, N",
    "contact force y, hole frame, N",
    "contact force z, hole frame, N",
    "contact moment about the centre of mass x, hole frame, N·m",
    "contact moment about the centre of mass y, hole frame, N·m",
    "contact moment about the centre of mass z, hole frame, N·m",
    "rate of dissipation of the contacts and further generalized forces, W",
];

/// Names of the wrench input: contact force `Fx, Fy, Fz` (N) and moment
/// about the centre of mass `Tx, Ty, Tz` (N·m), hole frame, and the rate of
/// dissipation `Sdot` (W).
pub const WRENCH: [&str; 7] = ["Fx", "Fy", "Fz", "Tx", "Ty", "Tz", "Sdot"];

/// Names of the dynamics parameters, after [`GEOMETRY`]: mass `m` (kg),
/// transverse and axial moments of inertia `J_t`, `J_a` about the centre of
/// mass (kg·m²), gravity `g` (m/s²), applied force `fa_x, fa_y, fa_z` (N)
/// and moment `ma_x, ma_y, ma_z` (N·m), hole frame.
pub const DYNAMICS: [&str; 10] = [
    "m", "J_t", "J_a", "g", "fa_x", "fa_y", "fa_z", "ma_x", "ma_y", "ma_z",
];

fn cross<'g>(a: &[Expr<'g>; 3], b: &[Expr<'g>; 3]) -> [Expr<'g>; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn pair_function<'g>(
    m: &mut ModelBuilder<'g>,
    which: Pair,
    pose: &[Expr<'g>],
    angle: Expr<'g>,
) -> Result<(), GenError> {
    let g = m.g();
    let p = [pose[0], pose[1], pose[2]];
    let q = [pose[3], pose[4], pose[5], pose[6]];
    let geo = geometry::pair(g, which, &p, &q, angle);
    let d1 = geo.gap.diff(angle);
    let d2 = d1.diff(angle);
    let grad: Vec<Expr<'g>> = pose.iter().map(|&x| geo.gap.diff(x)).collect();
    let what = match which {
        Pair::EdgeSide => {
            "the mouth-edge torus against the peg's side, angle along the mouth-edge circle"
        }
        Pair::RimWall => {
            "the peg's rim torus against the bore wall, angle along the rim circle (body)"
        }
        Pair::RimTop => {
            "the peg's rim torus against the block's top face z = 0, angle along the rim circle"
        }
        Pair::RimBottom => {
            "the peg's rim torus against the bore bottom z = -h_b, angle along the rim circle"
        }
        Pair::RimEdge => {
            "the peg's rim torus against the mouth-edge torus, angle along the rim circle (body), \
             closest mouth-circle point in closed form"
        }
    };
    m.function(
        which.name(),
        &format!(
            "Contact pair: {what}. Gap g (m, negative = penetration), dg/dangle and d2g/dangle2 (m/rad, \
             m/rad^2), gradient dg/d(px, py, pz, q0..q3), unit force direction on the peg, contact \
             point (m) and its axial coordinate along the peg from the centre of mass (m)."
        ),
        &[("x", pose), ("a", &[angle])],
        vec![
            ("gap", "gap g along the pair's normal (negative: penetration), m", Output::scalar(geo.gap)),
            ("d1", "first derivative dg/dangle of the gap, m/rad", Output::scalar(d1)),
            ("d2", "second derivative d²g/dangle² of the gap, m/rad²", Output::scalar(d2)),
            ("grad", "gradient dg/d(px, py, pz, q0, q1, q2, q3) of the gap in the pose, m per unit", Output::vector(&grad)),
            ("normal", "unit direction of the contact force on the peg, hole frame", Output::vector(&geo.normal)),
            ("point", "contact point, hole frame, m", Output::vector(&geo.point)),
            ("axial", "axial coordinate of the contact point along the peg from the centre of mass, m", Output::scalar(geo.axial)),
        ],
    )
}

fn dynamics_functions<'g>(
    mb: &mut ModelBuilder<'g>,
    y: &[Expr<'g>],
    w: &[Expr<'g>],
) -> Result<(), GenError> {
    let g = mb.g();
    let par = |n: &str| g.param(n);
    let (m, jt, ja, grav) = (par("m"), par("J_t"), par("J_a"), par("g"));
    let q = [y[3], y[4], y[5], y[6]];
    let v = [y[7], y[8], y[9]];
    let om = [y[10], y[11], y[12]];
    let fa = [par("fa_x"), par("fa_y"), par("fa_z")];
    let ma = [par("ma_x"), par("ma_y"), par("ma_z")];
    let conj = [q[0], -q[1], -q[2], -q[3]];
    let torque_world = [w[3] + ma[0], w[4] + ma[1], w[5] + ma[2]];
    let tb = geometry::rotate(&conj, &torque_world);
    let jom = [jt * om[0], jt * om[1], ja * om[2]];
    let gyro = cross(&om, &jom);
    let om_world = geometry::rotate(&q, &om);
    let mut rhs = vec![v[0], v[1], v[2]];
    rhs.push(-0.5 * (q[1] * om[0] + q[2] * om[1] + q[3] * om[2]));
    rhs.push(0.5 * (q[0] * om[0] + q[2] * om[2] - q[3] * om[1]));
    rhs.push(0.5 * (q[0] * om[1] + q[3] * om[0] - q[1] * om[2]));
    rhs.push(0.5 * (q[0] * om[2] + q[1] * om[1] - q[2] * om[0]));
    rhs.push((w[0] + fa[0]) / m);
    rhs.push((w[1] + fa[1]) / m);
    rhs.push((w[2] + fa[2]) / m - grav);
    rhs.push((tb[0] - gyro[0]) / jt);
    rhs.push((tb[1] - gyro[1]) / jt);
    rhs.push((tb[2] - gyro[2]) / ja);
    rhs.push(
        fa[0] * v[0]
            + fa[1] * v[1]
            + fa[2] * v[2]
            + ma[0] * om_world[0]
            + ma[1] * om_world[1]
            + ma[2] * om_world[2],
    );
    rhs.push(w[6]);
    let jac = |wrt: &[Expr<'g>]| -> Vec<Vec<Expr<'g>>> {
        rhs.iter()
            .map(|f| wrt.iter().map(|&x| f.diff(x)).collect())
            .collect()
    };
    let kinetic = 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
        + 0.5 * (jt * (om[0] * om[0] + om[1] * om[1]) + ja * om[2] * om[2]);
    mb.function(
        "rhs",
        "Newton-Euler right-hand side of y = (p, q, v, omega_body, work, dissipation) under the \
             contact wrench w = (F, T about the centre of mass, hole frame; dissipation rate), the \
             applied loads and gravity along -z. SI units.",
        &[("y", y), ("w", w)],
        vec![(
            "ydot",
            "the state's rate dy/dt, SI units per s",
            Output::vector(&rhs),
        )],
    )?;
    mb.function(
        "rhs_jacobian",
        "Exact partial derivatives of `rhs`: dy = d(ydot)/dy (15 x 15) at a fixed wrench and \
             dw = d(ydot)/dw (15 x 7); the runtime adds dw times the wrench's own derivative in y.",
        &[("y", y), ("w", w)],
        vec![
            (
                "dy",
                "d(ydot)/dy at a fixed wrench (15 x 15)",
                Output::matrix(&jac(y)),
            ),
            ("dw", "d(ydot)/dw (15 x 7)", Output::matrix(&jac(w))),
        ],
    )?;
    mb.function(
        "energy",
        "Kinetic energy (J) and gravitational potential m g p_z (J).",
        &[("y", y)],
        vec![
            (
                "kinetic",
                "kinetic energy of translation and rotation, J",
                Output::scalar(kinetic),
            ),
            (
                "gravity",
                "gravitational potential m g p_z, J",
                Output::scalar(m * grav * y[2]),
            ),
        ],
    )
}

/// Declares the compliant 3-D peg through the public builder: parameters
/// with their meaning, the pose, angle, state and wrench symbols, one
/// function per contact pair, the Newton–Euler right-hand side with the
/// wrench as an input, its exact partial derivatives and the energy (no
/// adapter: the runtime sums the contact wrench). A downstream build script
/// can declare the same model with
/// `generator.model(NAME, DOC, compliant_peg_3d::declare)`.
///
/// # Errors
/// Those of [`ModelBuilder`] (a name declared twice).
pub fn declare(m: &mut ModelBuilder<'_>) -> Result<(), GenError> {
    // Symbols are declared where the expressions first use them (pose,
    // angle, parameters, the pair functions; then the rest of the state and
    // the wrench), which fixes the order of terms in the emitted code.
    m.doc(DOC);
    m.outputs(Outputs::NONE);
    let mut y = Vec::with_capacity(STATE.len());
    for (name, doc) in STATE[..POSE.len()].iter().zip(STATE_DOCS) {
        y.push(m.symbol(name, doc)?);
    }
    let angle = m.symbol("angle", "angle along the pair's edge circle, rad")?;
    for (name, doc) in GEOMETRY.iter().chain(DYNAMICS.iter()).zip(PARAM_DOCS) {
        m.parameter(name, doc)?;
    }
    let pose = y.clone();
    for pair in Pair::ALL {
        pair_function(m, pair, &pose, angle)?;
    }
    m.shared_output(
        "PairGeometry",
        "One contact pair at one angle along its edge circle: the gap with its first and second \
         derivatives in the angle, its gradient in the pose, the force direction on the peg and \
         the contact point.",
        &Pair::ALL.map(Pair::name),
    )?;
    for (name, doc) in STATE[POSE.len()..].iter().zip(&STATE_DOCS[POSE.len()..]) {
        y.push(m.symbol(name, doc)?);
    }
    let mut w = Vec::with_capacity(WRENCH.len());
    for (name, doc) in WRENCH.into_iter().zip(WRENCH_DOCS) {
        w.push(m.symbol(name, doc)?);
    }
    dynamics_functions(m, &y, &w)
}
