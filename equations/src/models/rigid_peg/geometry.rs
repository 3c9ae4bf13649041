//! Geometry of the rigid peg leaning on the hole edge at three points K, B1,
//! B2 (the rigid-peg paper's eqs. (1)–(9) and (14)–(17), corrected), as expression trees
//! of the nutation angle γ and the parameters.
//!
//! Frames (as `src/rigid_peg/kinematics.rs`): fixed O1xyz with the hole-edge circle
//! (radius D/2) in z = 0 and z up the hole axis; the rotating components
//! (e_η, e_n, e_z) with e_η = (cos ψ, sin ψ, 0) in the symmetry plane and
//! e_n = e_z × e_η. Every vector here is in rotating components, so none
//! depends on ψ: C = (η_C, 0, z_C), K = (−D/2, 0, 0), B1,2 = (S1, ±b, 0).
//! The peg axis (upwards) is u = (−sin γ, 0, cos γ); w = (cos γ, 0, sin γ)
//! completes the peg's principal axes (u, w, e_n).
//!
//! Near γ0 = arccos(d/D) the differences d − D cos γ and D/2 − S1 cancel
//! catastrophically; they are built in exact product forms instead:
//! d − D cos γ = 2 D sin((γ+γ0)/2) sin((γ−γ0)/2),
//! D − d cos γ = (D − d) + 2 d sin²(γ/2),
//! D/2 − S1 = (d − D cos γ) cos γ / sin²γ, b² = (D/2 − S1)(D/2 + S1).
//!
//! γ0 is a *parameter* (`gamma0`), computed once per scene at run time as
//! 2 asin(√((D − d)/(2D))) (`PegParams::gamma0`, full relative accuracy
//! from D − d), not a derived expression: it depends on the parameters only,
//! so deriving it in every call would add an `asin` and a `sqrt` per call
//! for nothing, and the hand-derived model uses the very same value, which
//! keeps the generated-vs-hand comparison free of a second rounding path.
//! The caller must pass γ0 consistent with D and d.
//! Units: m, rad, kg.

use crate::expr::Expr;
use crate::graph::Graph;

/// A vector in rotating components (e_η, e_n, e_z).
pub type Vec3<'g> = [Expr<'g>; 3];

/// Names of the parameters, in order: hole diameter `D_hole` (m), peg
/// diameter `d_peg` (m), peg height `H` (m), mass `m` (kg), gravity `g`
/// (m/s², along −z), Coulomb friction coefficient `f`, and
/// `gamma0` = arccos(d/D) (rad, see the module doc).
pub const PARAMS: [&str; 7] = ["D_hole", "d_peg", "H", "m", "g", "f", "gamma0"];

/// The parameters as expressions.
#[derive(Clone, Copy)]
pub struct Params<'g> {
    /// Hole diameter D (m).
    pub hole: Expr<'g>,
    /// Peg diameter d (m).
    pub peg: Expr<'g>,
    /// Peg height H (m).
    pub height: Expr<'g>,
    /// Mass m (kg).
    pub mass: Expr<'g>,
    /// Gravitational acceleration g (m/s²).
    pub gravity: Expr<'g>,
    /// Friction coefficient f.
    pub friction: Expr<'g>,
    /// γ0 = arccos(d/D) (rad).
    pub gamma0: Expr<'g>,
}

impl<'g> Params<'g> {
    /// The parameter symbols of `g`, named as [`PARAMS`].
    pub fn new(g: &'g Graph) -> Params<'g> {
        let [hole, peg, height, mass, gravity, friction, gamma0] = PARAMS.map(|n| g.param(n));
        Params {
            hole,
            peg,
            height,
            mass,
            gravity,
            friction,
            gamma0,
        }
    }

    /// All parameters in [`PARAMS`] order.
    pub fn all(&self) -> Vec<Expr<'g>> {
        vec![
            self.hole,
            self.peg,
            self.height,
            self.mass,
            self.gravity,
            self.friction,
            self.gamma0,
        ]
    }
}

/// The planar (γ-only) geometry, paper eqs. (1)–(5), and the contact
/// points and normals in rotating components, eqs. (7)–(9), (14)–(17).
#[derive(Clone, Copy)]
pub struct Geometry<'g> {
    /// d − D cos γ (m), in the product form.
    pub c: Expr<'g>,
    /// D − d cos γ (m), in the sum-of-positives form.
    pub e: Expr<'g>,
    /// a1 = OO1 = (d − D cos γ)/(2 sin γ) (m), eq. (1).
    pub a1: Expr<'g>,
    /// a2 = OO2 = (D − d cos γ)/(2 sin γ) (m), eq. (1).
    pub a2: Expr<'g>,
    /// S1 = O1B = (a2 − a1 cos γ)/sin γ (m), eq. (2).
    pub s1: Expr<'g>,
    /// S2 = O2B = (a2 cos γ − a1)/sin γ (m), eq. (2) with the sign corrected.
    pub s2: Expr<'g>,
    /// D/2 − S1 = (d − D cos γ) cos γ / sin²γ (m).
    pub gap: Expr<'g>,
    /// b = BB1 = √(gap (D − gap)) (m).
    pub b: Expr<'g>,
    /// sin τ = b/(D/2).
    pub sin_tau: Expr<'g>,
    /// cos τ = S1/(D/2).
    pub cos_tau: Expr<'g>,
    /// η_C = −(H/2 − a2) sin γ (m), eq. (3).
    pub eta_c: Expr<'g>,
    /// z_C = (H/2 − a2) cos γ + a1 (m), eq. (3).
    pub z_c: Expr<'g>,
    /// (η_L, z_L) = (−S1, 2 a1) (m), eq. (4b).
    pub centre_l: [Expr<'g>; 2],
    /// KL = 2 a1 / sin γ (m), eq. (5).
    pub kl: Expr<'g>,
    /// BL = 2 √(a1² + S1²) (m), eq. (5).
    pub bl: Expr<'g>,
    /// |OB| = √(D²/4 + a1²) (m): distance from the axes' intersection O to
    /// B1 and B2.
    pub ob: Expr<'g>,
    /// Centre of mass C = (η_C, 0, z_C).
    pub centre: Vec3<'g>,
    /// Peg axis u = (−sin γ, 0, cos γ) (upwards).
    pub axis: Vec3<'g>,
    /// In-plane transverse axis w = (cos γ, 0, sin γ).
    pub transverse: Vec3<'g>,
    /// Contacts `[K, B1, B2]`: K = (−D/2, 0, 0), B1,2 = (S1, ±b, 0).
    pub contacts: [Vec3<'g>; 3],
    /// Unit normals of the contact forces on the peg `[n_K, n_B1, n_B2]`:
    /// n_K = w (the side's normal in the symmetry plane), n_B1,2 =
    /// (−S1, ∓b, a1)/|OB| (along B→O, the common perpendicular of the two
    /// edges' tangents).
    pub normals: [Vec3<'g>; 3],
}

impl<'g> Geometry<'g> {
    /// The geometry at nutation angle `gamma` (a symbol or any expression).
    pub fn new(g: &'g Graph, p: &Params<'g>, gamma: Expr<'g>) -> Geometry<'g> {
        let (dh, dp, h) = (p.hole, p.peg, p.height);
        let (s, co) = (gamma.sin(), gamma.cos());
        // Names for the generated code (the values are unchanged).
        (0.5 * p.gamma0).named("half_gamma0");
        let half_gamma = (0.5 * gamma).named("half_gamma");
        let c = 2.0
            * dh
            * (0.5 * (gamma + p.gamma0)).sin().named("sin_sum")
            * (0.5 * (gamma - p.gamma0)).sin();
        // sin(½(γ − γ0)) is stored as −sin(½(γ0 − γ)).
        (0.5 * (p.gamma0 - gamma)).sin().named("sin_diff");
        let c = c.named("delta");
        let e = ((dh - dp) + 2.0 * dp * half_gamma.sin().square()).named("e");
        let a1 = (c / (2.0 * s)).named("a1");
        let a2 = (e / (2.0 * s)).named("a2");
        let s1 = ((a2 - a1 * co) / s).named("s1");
        let s2 = ((a2 * co - a1) / s).named("s2");
        let gap = (c * co / s.square()).named("gap");
        let b = (gap * (dh - gap)).sqrt().named("bb1");
        let half = (0.5 * dh).named("half_d");
        let lever = (0.5 * h - a2).named("lever");
        let eta_c = -lever * s;
        let z_c = lever * co + a1;
        let zero = g.constant(0.0);
        let ob = half.hypot(a1).named("ob");
        let normal_b = |sign: f64| [-s1 / ob, sign * b / ob, a1 / ob];
        Geometry {
            c,
            e,
            a1,
            a2,
            s1,
            s2,
            gap,
            b,
            sin_tau: b / half,
            cos_tau: s1 / half,
            eta_c,
            z_c,
            centre_l: [-s1, 2.0 * a1],
            kl: 2.0 * a1 / s,
            bl: 2.0 * a1.hypot(s1),
            ob,
            centre: [eta_c, zero, z_c],
            axis: [-s, zero, co],
            transverse: [co, zero, s],
            contacts: [[-half, zero, zero], [s1, b, zero], [s1, -b, zero]],
            normals: [[co, zero, s], normal_b(-1.0), normal_b(1.0)],
        }
    }
}

/// a + b.
pub fn add<'g>(a: &Vec3<'g>, b: &Vec3<'g>) -> Vec3<'g> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// a − b.
pub fn sub<'g>(a: &Vec3<'g>, b: &Vec3<'g>) -> Vec3<'g> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// a × b.
pub fn cross<'g>(a: &Vec3<'g>, b: &Vec3<'g>) -> Vec3<'g> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// a · b.
pub fn dot<'g>(g: &'g Graph, a: &Vec3<'g>, b: &Vec3<'g>) -> Expr<'g> {
    g.sum((0..3).map(|k| a[k] * b[k]))
}
