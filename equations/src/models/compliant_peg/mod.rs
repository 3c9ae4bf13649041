//! The compliant planar peg of "Dynamic analysis for peg-in-hole assembly
//! with contact deformation" ((31)–(51) and (55)–(64)),
//! derived from a potential instead of the paper's constraint Jacobians.
//!
//! Coordinates `q = (x, z, θ)` of the peg's centre of mass and tilt (frame in
//! [`geometry`]); mass matrix `diag(m, m, J)`. Each contact
//! `c` has a penetration `δ_c(q)` and stores the Hertz energy
//! `V_c = (2/5) k_c max(δ_c, 0)^{5/2}` ((62)); its normal force on the peg is
//! `−∂V_c/∂q = −k_c max(δ_c,0)^{3/2} ∂δ_c/∂q` — unilateral, acting only
//! while the bodies overlap, along the contact normal (the gradient of a
//! distance). Coulomb friction acts against the sliding velocity
//! `v_c = J_c(q) q̇` of the peg's material point at the contact:
//! generalized force `−μ f_c φ(v_c) J_cᵀ`, with the regularized sign
//! `φ(v) = v/√(v² + v_s²)` (velocity scale `v_s`). The applied force
//! Optional Hunt–Crossley damping (`α = hc_alpha`, default 0) scales the
//! normal force by `max(0, 1 + α δ̇)`. The applied force
//! `f₁ e_a + f₂ e_r` at the centre of mass and the torque `M` give
//! `(f₁ sin θ + f₂ cos θ, f₁ cos θ − f₂ sin θ, M)`, the right side of (50).
//!
//! The state is `(x, z, θ, ẋ, ż, θ̇, W, S)` with `W` the work of the applied
//! loads and `S ≥ 0` the energy dissipated by friction (`S_μ` of (64)) and
//! contact damping, so
//! that `T + V − W + S` is constant along every solution.
//! Units: SI (kg, kg·m², m, rad, N, N·m, J).

pub mod elastic;
pub mod geometry;
pub mod variants;

use super::hertz::{self, HertzCoefficients, HertzState};
use crate::expr::Expr;
use crate::graph::Graph;
use geometry::{Contact, PegFrame};

/// Names of the state components, in order.
pub const STATE: [&str; 8] = [
    "x",
    "z",
    "theta",
    "xdot",
    "zdot",
    "thetadot",
    "work",
    "dissipation",
];

/// Names of the parameters, in order: mass `m` (kg), inertia `J` about the
/// centre of mass (kg·m²), dimensions `r, l_c, D, ρ_p, ρ_h` (m), friction
/// coefficient `μ`, friction velocity scale `v_s` (m/s), Hertz stiffnesses
/// `k_edge, k_wall` (N/m^{3/2}), loads `f₁, f₂` (N) and `M` (N·m), and the
/// Hertz coefficients of the edge and wall contacts (see
/// [`HertzCoefficients::params`]), and the Hunt–Crossley damping
/// coefficient `α` (s/m; 0 for purely elastic contacts).
pub const PARAMS: [&str; 24] = [
    "m",
    "J",
    "r",
    "l_c",
    "D",
    "rho_p",
    "rho_h",
    "mu",
    "v_s",
    "k_edge",
    "k_wall",
    "f1",
    "f2",
    "M",
    "e_star",
    "edge_sum",
    "edge_ma",
    "edge_mb",
    "edge_dstar",
    "wall_sum",
    "wall_ma",
    "wall_mb",
    "wall_dstar",
    "hc_alpha",
];

/// What each state component of [`STATE`] is, with its unit.
pub const STATE_DOCS: [&str; 8] = [
    "lateral position x of the centre of mass, m",
    "position z of the centre of mass along the hole's axis, into the hole, m",
    "tilt θ of the peg's axis, rad",
    "lateral velocity of the centre of mass, m/s",
    "axial velocity of the centre of mass, m/s",
    "angular velocity of the tilt, rad/s",
    "work W of the applied loads since the start, J",
    "energy S dissipated by friction and contact damping since the start, J",
];

/// What each parameter of [`PARAMS`] is, with its unit.
pub const PARAM_DOCS: [&str; 24] = [
    "mass m of the peg, kg",
    "moment of inertia J about the centre of mass, kg·m²",
    "peg radius r, m",
    "distance l_c from the centre of mass to the bottom face, m",
    "hole diameter D, m",
    "fillet radius ρ_p of the peg's bottom corners, m",
    "fillet radius ρ_h of the hole's top edges, m",
    "Coulomb friction coefficient μ, dimensionless",
    "velocity scale v_s of the regularized friction law, m/s",
    "Hertz stiffness of the edge contacts, N/m^1.5",
    "Hertz stiffness of the wall contacts, N/m^1.5",
    "applied axial force f₁ (along e_a, pushing the peg into the hole), N",
    "applied radial force f₂ (along e_r), N",
    "applied torque M about the centre of mass, positive increasing θ, N·m",
    "contact modulus E* of the peg and hole materials, Pa",
    "sum of the principal curvatures Σρ of the edge contacts, 1/m",
    "Hertz ellipse coefficient m_a of the edge contacts (9), dimensionless",
    "Hertz ellipse coefficient m_b of the edge contacts (10), dimensionless",
    "Hertz approach coefficient δ* of the edge contacts (13), dimensionless",
    "sum of the principal curvatures Σρ of the wall contacts, 1/m",
    "Hertz ellipse coefficient m_a of the wall contacts (9), dimensionless",
    "Hertz ellipse coefficient m_b of the wall contacts (10), dimensionless",
    "Hertz approach coefficient δ* of the wall contacts (13), dimensionless",
    "Hunt–Crossley damping coefficient α (0 for elastic contacts), s/m",
];

/// Extra parameters of the elastic friction law (after [`PARAMS`]): the
/// effective shear modulus `G*` (Pa), the penetration floor `δ_0` (m)
/// of the utilisation rate and the tangential damping time `τ_t` (s) (see
/// [`elastic`]).
pub const ELASTIC_PARAMS: [&str; 3] = ["g_star", "delta_floor", "tau_t"];

/// What each parameter of [`ELASTIC_PARAMS`] is, with its unit.
pub const ELASTIC_PARAM_DOCS: [&str; 3] = [
    "effective shear modulus G* of Mindlin's tangential stiffness, Pa",
    "penetration floor δ_0 of the utilisation rate, m",
    "damping time τ_t of the tangential springs, s",
];

/// The friction law of the tangential contact forces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrictionLaw {
    /// Regularized Coulomb `−μ f v/√(v² + v_s²)`: no extra state; a stuck
    /// contact creeps at a speed `∝ v_s`.
    Regularized,
    /// Hertz–Mindlin tangential compliance capped by Coulomb ([`elastic`]):
    /// one utilisation state `u_<contact>` per contact after the 8 states,
    /// parameters [`ELASTIC_PARAMS`] after [`PARAMS`].
    Elastic,
}

/// Everything the generated functions output, as expressions.
pub struct PlanarPeg<'g> {
    /// The state symbols, in [`STATE`] order.
    pub state: Vec<Expr<'g>>,
    /// The parameter symbols, in [`PARAMS`] order.
    pub params: Vec<Expr<'g>>,
    /// The contacts included, in output order.
    pub contacts: Vec<Contact>,
    /// Right-hand side `ẏ = f(y)` of the 8 states (and the utilisations of
    /// the elastic law).
    pub rhs: Vec<Expr<'g>>,
    /// Exact Jacobian `∂f/∂y`, square.
    pub jacobian: Vec<Vec<Expr<'g>>>,
    /// Normal force `f_c = k max(δ,0)^{3/2} max(0, 1 + α δ̇)` per contact (N).
    pub normal: Vec<Expr<'g>>,
    /// Friction force `−μ f_c φ(v_c)` per contact, along its tangent (N).
    pub friction: Vec<Expr<'g>>,
    /// Penetration `δ_c` per contact (m; negative = gap).
    pub delta: Vec<Expr<'g>>,
    /// Sliding velocity `v_c` per contact (m/s).
    pub slip: Vec<Expr<'g>>,
    /// Hertz ellipse and pressure per contact at load `f_c`.
    pub ellipse: Vec<HertzState<'g>>,
    /// Stored tangential energy `Σ E_t` of the elastic law (J; 0 for the
    /// regularized law).
    pub tangential: Expr<'g>,
    /// Kinetic energy `T` (59) (J).
    pub kinetic: Expr<'g>,
    /// Contact potential `P = Σ ∫ f dδ` (63) (J).
    pub potential: Expr<'g>,
    /// Insertion depth `l` of the bottom face's centre (m).
    pub depth: Expr<'g>,
}

/// Builds the model with the given contacts (a scene that only leans one way
/// generates only the two contacts of that lean) and the regularized
/// friction law.
pub fn build<'g>(g: &'g Graph, contacts: &[Contact]) -> PlanarPeg<'g> {
    build_law(g, contacts, FrictionLaw::Regularized)
}

/// Builds the model with the given contacts and friction law.
pub fn build_law<'g>(g: &'g Graph, contacts: &[Contact], law: FrictionLaw) -> PlanarPeg<'g> {
    let f = PegFrame::new(g);
    let elastic_law = law == FrictionLaw::Elastic;
    let mut state: Vec<Expr<'g>> = STATE.iter().map(|n| g.var(n)).collect();
    let mut params: Vec<Expr<'g>> = PARAMS.iter().map(|n| g.param(n)).collect();
    if elastic_law {
        state.extend(contacts.iter().map(|c| g.var(&format!("u_{}", c.name()))));
        params.extend(ELASTIC_PARAMS.iter().map(|n| g.param(n)));
    }
    let mut rates = vec![];
    let mut stored = vec![];
    let p = |n: &str| g.param(n);
    let (m, j, mu, vs, alpha) = (p("m"), p("J"), p("mu"), p("v_s"), p("hc_alpha"));
    let q = [f.x, f.z, f.theta];
    let qd = [f.xdot, f.zdot, f.thetadot];
    let pairs = [(f.x, f.xdot), (f.z, f.zdot), (f.theta, f.thetadot)];
    let (ea, er) = f.axes();
    let (f1, f2, torque) = (p("f1"), p("f2"), p("M"));
    let applied = [f1 * ea[0] + f2 * er[0], f1 * ea[1] + f2 * er[1], torque];

    let mut gen_force = applied;
    let (mut normal, mut friction, mut delta, mut slip, mut ellipse) =
        (vec![], vec![], vec![], vec![], vec![]);
    let mut potentials = vec![];
    let mut dissipation_rate = vec![];
    let edge = HertzCoefficients::params(g, "edge");
    let wall = HertzCoefficients::params(g, "wall");
    for &c in contacts {
        let kin = f.contact(c);
        let (k, coeffs) = if c.is_edge() {
            (p("k_edge"), &edge)
        } else {
            (p("k_wall"), &wall)
        };
        let tag = c.name();
        kin.delta.named(&format!("delta_{tag}"));
        kin.delta.max0().named(&format!("pen_{tag}"));
        kin.slip.named(&format!("slip_{tag}"));
        let v = hertz::potential(k, kin.delta);
        let elastic = hertz::load(k, kin.delta);
        // Hunt–Crossley: f = k δ^{3/2} max(0, 1 + α δ̇); the damping part
        // f − k δ^{3/2} never makes the contact pull.
        let ddelta = kin.delta.dt(&pairs);
        let fn_ = (elastic.named(&format!("elastic_{tag}"))
            * (1.0 + alpha * ddelta.named(&format!("delta_rate_{tag}"))).max0())
        .named(&format!("normal_{tag}"));
        let damping = fn_ - elastic;
        let ft = if elastic_law {
            let floor = p("delta_floor");
            let floored = kin.delta.hypot(floor);
            let t = elastic::tangential(&elastic::TangentialInputs {
                kin: &kin,
                floor_rate: floored.dt(&pairs),
                floored,
                u: g.var(&format!("u_{tag}")),
                k,
                normal: elastic,
                coeffs,
                mu,
                g_star: p("g_star"),
                tau: p("tau_t"),
            });
            for i in 0..3 {
                gen_force[i] = gen_force[i]
                    - v.diff(q[i])
                    - damping * kin.delta.diff(q[i])
                    - t.normal_extra * kin.delta.diff(q[i])
                    + t.force * kin.slip.diff(qd[i]);
            }
            dissipation_rate.push(t.dissipation + damping * ddelta);
            rates.push(t.rate);
            stored.push(t.energy);
            t.force
        } else {
            // Regularized Coulomb friction along the tangent, against the slip.
            let ft = -mu * fn_ * kin.slip / kin.slip.hypot(vs);
            for i in 0..3 {
                gen_force[i] = gen_force[i] - v.diff(q[i]) - damping * kin.delta.diff(q[i])
                    + ft * kin.slip.diff(qd[i]);
            }
            dissipation_rate.push(-ft * kin.slip + damping * ddelta);
            ft
        };
        potentials.push(v);
        ellipse.push(hertz::state(fn_, coeffs));
        normal.push(fn_);
        friction.push(ft);
        delta.push(kin.delta);
        slip.push(kin.slip);
    }
    let power = g.sum((0..3).map(|i| applied[i] * qd[i]));
    let mut rhs = vec![
        f.xdot,
        f.zdot,
        f.thetadot,
        gen_force[0] / m,
        gen_force[1] / m,
        gen_force[2] / j,
        power,
        g.sum(dissipation_rate),
    ];
    rhs.extend(rates);
    let jacobian = rhs
        .iter()
        .map(|fi| state.iter().map(|&y| fi.diff(y)).collect())
        .collect();
    let kinetic = 0.5 * m * (f.xdot.square() + f.zdot.square()) + 0.5 * j * f.thetadot.square();
    PlanarPeg {
        state,
        params,
        contacts: contacts.to_vec(),
        rhs,
        jacobian,
        normal,
        friction,
        delta,
        slip,
        ellipse,
        tangential: g.sum(stored),
        kinetic,
        potential: g.sum(potentials),
        depth: f.depth(),
    }
}
