//! Geometry of the compliant planar peg ((14)–(30),
//! re-derived): penetration and sliding velocity of each of the four
//! possible contacts as expressions of the peg's coordinates.
//!
//! Frame: `x` across the hole, `z` along the hole's axis pointing *into* the
//! hole; the hole's walls are `x = ±D/2` for `z ≥ 0`, its top face `z = 0`.
//! The peg's centre of mass is `C = (x, z)`; its axis, pointing from `C` to
//! the bottom face, is `e_a = (sin θ, cos θ)` and its radial direction
//! `e_r = (cos θ, −sin θ)` (so the applied force `f₁ e_a + f₂ e_r` has the
//! components of the paper's (50)). A point of the peg at axial offset `s`
//! (towards the bottom) and radial offset `u` is `C + s e_a + u e_r`; its
//! velocity is `v_C + θ̇ (s e_r − u e_a)`.
//!
//! Edges are filleted: the hole's top edges are circles (in the plane) of
//! radius `ρ_h` centred at `(±(D/2 + ρ_h), ρ_h)`; the peg's bottom corners
//! are circles of radius `ρ_p` centred at `C + (l_c − ρ_p) e_a ± (r − ρ_p) e_r`.
//! Each penetration is an exact signed distance between a circle and a line
//! (so that its gradient is the contact normal), positive when the bodies
//! overlap.

use crate::expr::Expr;
use crate::graph::Graph;

/// One of the four contacts between the peg and the hole.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Contact {
    /// Peg's left side (`u = −r`) on the hole's left top edge: the paper's A
    /// when the peg leans with `θ > 0`.
    EdgeLeft,
    /// Peg's right bottom corner on the right wall: the paper's B when
    /// `θ > 0`.
    WallRight,
    /// Peg's right side on the hole's right top edge: A of the mirror lean.
    EdgeRight,
    /// Peg's left bottom corner on the left wall: B of the mirror lean.
    WallLeft,
}

impl Contact {
    /// All four contacts, in the order of the generated outputs.
    pub const ALL: [Contact; 4] = [
        Contact::EdgeLeft,
        Contact::WallRight,
        Contact::EdgeRight,
        Contact::WallLeft,
    ];

    /// Whether this is an edge contact (peg side on hole edge) rather than a
    /// wall contact (peg corner on hole wall).
    pub fn is_edge(self) -> bool {
        matches!(self, Contact::EdgeLeft | Contact::EdgeRight)
    }

    /// Short name used in output names: `edge_left`, `wall_right`, ...
    pub fn name(self) -> &'static str {
        match self {
            Contact::EdgeLeft => "edge_left",
            Contact::WallRight => "wall_right",
            Contact::EdgeRight => "edge_right",
            Contact::WallLeft => "wall_left",
        }
    }
}

/// The peg's coordinates, velocities and dimensions as expressions.
#[derive(Clone, Copy, Debug)]
pub struct PegFrame<'g> {
    /// Lateral position `x` of the centre of mass (m).
    pub x: Expr<'g>,
    /// Position `z` of the centre of mass along the hole's axis, into the
    /// hole (m).
    pub z: Expr<'g>,
    /// Tilt `θ` of the peg's axis (rad).
    pub theta: Expr<'g>,
    /// Rate of `x` (m/s).
    pub xdot: Expr<'g>,
    /// Rate of `z` (m/s).
    pub zdot: Expr<'g>,
    /// Rate of `θ` (rad/s).
    pub thetadot: Expr<'g>,
    /// Peg radius `r` (m).
    pub r: Expr<'g>,
    /// Distance `l_c` from the centre of mass to the bottom face (m).
    pub lc: Expr<'g>,
    /// Hole diameter `D` (m).
    pub d: Expr<'g>,
    /// Peg bottom-edge fillet `ρ_p` (m).
    pub rho_p: Expr<'g>,
    /// Hole top-edge fillet `ρ_h` (m).
    pub rho_h: Expr<'g>,
}

/// Penetration and sliding of one contact.
#[derive(Clone, Copy, Debug)]
pub struct ContactKinematics<'g> {
    /// Penetration `δ` (m), positive when the bodies overlap (the paper's
    /// (14), (15)).
    pub delta: Expr<'g>,
    /// Sliding velocity `v_t` (m/s) of the peg's material point at the
    /// contact, along the contact tangent; linear in the velocities.
    pub slip: Expr<'g>,
}

impl<'g> PegFrame<'g> {
    /// Coordinates `x, z, theta`, velocities `xdot, zdot, thetadot` and the
    /// dimension parameters `r, l_c, D, rho_p, rho_h` of graph `g`.
    pub fn new(g: &'g Graph) -> PegFrame<'g> {
        PegFrame {
            x: g.var("x"),
            z: g.var("z"),
            theta: g.var("theta"),
            xdot: g.var("xdot"),
            zdot: g.var("zdot"),
            thetadot: g.var("thetadot"),
            r: g.param("r"),
            lc: g.param("l_c"),
            d: g.param("D"),
            rho_p: g.param("rho_p"),
            rho_h: g.param("rho_h"),
        }
    }

    /// `(e_a, e_r)`: unit vectors along the axis (towards the bottom) and radial.
    pub fn axes(&self) -> ([Expr<'g>; 2], [Expr<'g>; 2]) {
        let (s, c) = (self.theta.sin(), self.theta.cos());
        ([s, c], [c, -s])
    }

    /// Velocity of the peg's material point at axial offset `s`, radial offset `u`.
    fn point_velocity(&self, s: Expr<'g>, u: Expr<'g>) -> [Expr<'g>; 2] {
        let (ea, er) = self.axes();
        [
            self.xdot + self.thetadot * (s * er[0] - u * ea[0]),
            self.zdot + self.thetadot * (s * er[1] - u * ea[1]),
        ]
    }

    /// Insertion depth `l = z + l_c cos θ` of the centre of the bottom face (m).
    pub fn depth(&self) -> Expr<'g> {
        self.z + self.lc * self.theta.cos()
    }

    /// Penetration and sliding velocity of `contact`.
    pub fn contact(&self, contact: Contact) -> ContactKinematics<'g> {
        let (ea, er) = self.axes();
        let half_d = 0.5 * self.d;
        match contact {
            Contact::EdgeLeft | Contact::EdgeRight => {
                // Side u = ∓r against the edge circle centred at E = (∓(D/2+ρ_h), ρ_h).
                let sign = if contact == Contact::EdgeLeft {
                    -1.0
                } else {
                    1.0
                };
                let ex = sign * (half_d + self.rho_h) - self.x;
                let ez = self.rho_h - self.z;
                // Signed distance of E outside the side line, minus ρ_h.
                let radial = ex * er[0] + ez * er[1];
                let delta = self.rho_h + self.r - sign * radial;
                let s = ex * ea[0] + ez * ea[1];
                let v = self.point_velocity(s, sign * self.r);
                ContactKinematics {
                    delta,
                    slip: v[0] * ea[0] + v[1] * ea[1],
                }
            }
            Contact::WallRight | Contact::WallLeft => {
                // Corner circle centred at F = C + (l_c−ρ_p) e_a ± (r−ρ_p) e_r against x = ±D/2.
                let sign = if contact == Contact::WallRight {
                    1.0
                } else {
                    -1.0
                };
                let s0 = self.lc - self.rho_p;
                let u0 = sign * (self.r - self.rho_p);
                let fx = self.x + s0 * ea[0] + u0 * er[0];
                let delta = sign * fx + self.rho_p - half_d;
                // Contact point F + ρ_p (±1, 0), i.e. ±ρ_p (cos θ e_r + sin θ e_a).
                let s = s0 + sign * self.rho_p * ea[0];
                let u = u0 + sign * self.rho_p * er[0];
                let v = self.point_velocity(s, u);
                ContactKinematics { delta, slip: v[1] }
            }
        }
    }
}
