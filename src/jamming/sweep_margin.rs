//! The dynamic sweep's margin to its exact parallelogram, with its
//! derivatives along the design: the peg radius `r`, the clearance ratio
//! `c`, the friction coefficient `μ` and the requested depth `l` (as in
//! [`mod@super::sensitivities`]; the fillets and the peg's length held).
//!
//! The sweep's diagram ([`super::dynamic::SweepSetup`]) is not the exact
//! parallelogram of the requested depth: it is built at the requested
//! depth's two-point tilt and at the Whitney depth of the start state, which
//! the fillets move. So the margin of a load ratio `q` goes through the whole
//! chain, each link differentiated at once in dual numbers of `(r, c, μ, l)`:
//!
//! ```text
//! d = 2r,  D = d/(1 − c),  θ = atan2(l, d) − atan2(√(l² + d² − D²), D)
//! (x, z) = the start state's centre of mass at θ (both contacts touching,
//!          compliant_peg::initial::two_point_pose)
//! l_W = (z + l_c cos θ + r sin θ)/cos θ          (Whitney depth of the start,
//!                                                dynamic::whitney_depth)
//! corners = [−P₁, Q, P₁, −Q] of (μ, r, l_W, θ)  (jamming::diagram)
//! m(q) = signed distance from q to the nearest edge
//! ```
//!
//! The margin is the least of four smooth edge distances: where the two
//! nearest edges are equally near (a corner's bisector) it has no
//! derivative, and none is given.

use super::diagram::{Ratio, edge_distances, exact_corners, nearest};
use super::dynamic::{SweepSetup, whitney_depth};
use super::geometry::tilt_of;
use super::sensitivities::Gradient;
use crate::compliant_peg::initial::two_point_pose;
use crate::scalar::{Dual, Real};

/// Two edge distances closer than this (relative to the larger of 1 and
/// the distances' size) leave the margin without a derivative.
pub const KINK: f64 = 1e-9;

/// The margin of a load ratio and, away from the parallelogram's
/// bisectors, its derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MarginGradient {
    /// The signed distance to the nearest edge (positive inside).
    pub value: f64,
    /// The nearest edge (`i` from corner `i` to corner `i + 1`).
    pub edge: usize,
    /// `(∂m/∂r, ∂m/∂c, ∂m/∂μ, ∂m/∂l)`; `None` where two edges are equally
    /// near ([`KINK`]).
    pub gradient: Option<Gradient>,
}

type D4 = Dual<4>;

impl SweepSetup {
    /// The margin of `q` to the sweep's exact parallelogram
    /// ([`SweepSetup::diagram`]) with its derivatives along `(r, c, μ, l)`
    /// (the module's chain).
    pub fn margin_gradient(&self, q: Ratio) -> MarginGradient {
        let p = &self.spec.peg;
        let r = D4::variable(p.r(), 0);
        let c = D4::variable(p.c(), 1);
        let mu = D4::variable(p.mu(), 2);
        let l = D4::variable(self.spec.depth, 3);
        let k = D4::from_f64;
        let g = &self.params.spec.geometry;
        let lc = k(self.params.spec.com_height);
        let d = k(2.0) * r;
        let big_d = d / (k(1.0) - c);
        let theta = tilt_of(d, big_d, l);
        let geometry = [r, k(g.peg_fillet), k(g.hole_fillet), k(0.5) * big_d];
        let (_, z) = two_point_pose(geometry, lc, theta, k(0.0));
        let corners = exact_corners(mu, r, whitney_depth(z, lc, r, theta), theta);
        let distances = edge_distances(&corners, [k(q[0]), k(q[1])]);
        let edge = nearest(&distances);
        let m = distances[edge];
        // The next nearest edge: a tie leaves no derivative.
        let next = (0..4)
            .filter(|&i| i != edge)
            .map(|i| distances[i].v)
            .fold(f64::INFINITY, f64::min);
        let scale = 1.0_f64.max(m.v.abs()).max(next.abs());
        let gradient = (next - m.v > KINK * scale).then(|| Gradient {
            r: m.d[0],
            c: m.d[1],
            mu: m.d[2],
            l: m.d[3],
        });
        MarginGradient {
            value: m.v,
            edge,
            gradient,
        }
    }
}
