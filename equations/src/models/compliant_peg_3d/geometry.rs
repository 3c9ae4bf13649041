//! Geometry of the compliant 3-D peg: the signed distance of each contact
//! pair as a function of the pose and one angle along an edge circle.
//!
//! Frames: the hole frame has `z` up the bore axis, the block's top face in
//! `z = 0`, the bore wall at radius `R = D/2` for `−h_b ≤ z ≤ −ρ_h`, the
//! bore bottom in `z = −h_b`, and the mouth edge rounded by a quarter torus
//! of tube radius `ρ_h` whose tube-centre circle has radius `R + ρ_h` at
//! height `−ρ_h`. The peg (radius `r = d/2`, length `L`) has its centre of
//! mass `p` at mid-length; its body axis `e₃` points from the bottom face to
//! the top; the bottom rim is rounded by a torus of tube radius `ρ_p` whose
//! tube-centre circle has radius `r − ρ_p` at body height `−L/2 + ρ_p`.
//! The orientation is the unit quaternion `q = (q₀, q₁, q₂, q₃)`, rotation
//! matrix `R(q)` (body to hole frame), `a = R e₃` the peg's axis.
//!
//! Every gap is exact for its pair because a torus is the set of points
//! within its tube radius of its tube-centre circle: the distance from the
//! torus to a convex (or, for the bore, concave) surface is the smallest
//! distance from the circle to that surface minus the tube radius, so the
//! gap `g(α)` along the circle's angle `α` is a smooth function whose local
//! minima are the candidate contact points (penetration `δ = −g > 0`).
//!
//! - mouth edge vs peg side: `c(α) = ((R+ρ_h) cos α, (R+ρ_h) sin α, −ρ_h)`,
//!   `u = c − p`, `w = u − (u·a) a`; `g = |w| − r − ρ_h`; the force on the
//!   peg acts along `n = −w/|w|` through `c`.
//! - peg rim vs bore wall: `c(β) = p + R(q) ((r−ρ_p) cos β, (r−ρ_p) sin β,
//!   −L/2+ρ_p)`, `ρ_c = |(c_x, c_y)|`; `g = R − ρ_p − ρ_c`; `n = −(c_x, c_y,
//!   0)/ρ_c`.
//! - peg rim vs a horizontal plane `z = z₀` (the top face `z₀ = 0`, the bore
//!   bottom `z₀ = −h_b`): `g = c_z − ρ_p − z₀`; `n = e_z`.
//! - peg rim vs mouth edge (torus against torus): the distance between the
//!   two tori is the distance between their tube-centre circles minus both
//!   tube radii. Along the rim circle `c(β)`, the closest point of the
//!   mouth circle (radius `R+ρ_h` about `e_z`, height `−ρ_h`) is in closed
//!   form: it lies in the meridian half-plane through `c`, at
//!   `m = (R+ρ_h) ê + (0, 0, −ρ_h)` with `ê = (c_x, c_y, 0)/ρ_c`, so
//!   `|c − m|² = (ρ_c − R − ρ_h)² + (c_z + ρ_h)²` and
//!   `g = |c − m| − ρ_p − ρ_h`; `n = (c − m)/|c − m|`. A local minimum of
//!   `g` in `β` is then a joint stationary point in both circles' angles, so
//!   the envelope theorem gives the pose gradient as for the other pairs.
//!
//! Units: m, rad.

use crate::expr::Expr;
use crate::graph::Graph;

/// A 3-vector of expressions in hole-frame components.
pub type V3<'g> = [Expr<'g>; 3];

/// Names of the pose components, in order: centre of mass `px, py, pz` (m)
/// and the unit quaternion `q0..q3` (scalar first).
pub const POSE: [&str; 7] = ["px", "py", "pz", "q0", "q1", "q2", "q3"];

/// Names of the geometry parameters, in order: peg radius `r`, peg length
/// `L`, rim fillet `rho_p`, bore radius `R`, mouth fillet `rho_h`, bore
/// depth `h_b` (all m).
pub const GEOMETRY: [&str; 6] = ["r", "L", "rho_p", "R", "rho_h", "h_b"];

pub use super::pair::Pair;

fn dot<'g>(a: &V3<'g>, b: &V3<'g>) -> Expr<'g> {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `R(q) v` with the rotation matrix of the quaternion `q` (exact for
/// `|q| = 1`).
pub fn rotate<'g>(q: &[Expr<'g>; 4], v: &V3<'g>) -> V3<'g> {
    let [w, x, y, z] = *q;
    let r = [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - w * z),
            2.0 * (x * z + w * y),
        ],
        [
            2.0 * (x * y + w * z),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - w * x),
        ],
        [
            2.0 * (x * z - w * y),
            2.0 * (y * z + w * x),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ];
    [dot(&r[0], v), dot(&r[1], v), dot(&r[2], v)]
}

/// One pair's gap, force direction on the peg and contact point (midway
/// between the two surfaces along the normal), and the axial coordinate of
/// the contact along the peg's axis measured from the centre of mass.
pub struct PairGeometry<'g> {
    /// Signed distance `g` (m): positive apart, negative overlapping.
    pub gap: Expr<'g>,
    /// Unit normal along which the contact pushes the peg.
    pub normal: V3<'g>,
    /// Contact point (m), hole frame.
    pub point: V3<'g>,
    /// `(x − p)·a` of the contact point (m).
    pub axial: Expr<'g>,
}

/// The geometry of `pair` at pose `(p, q)` and angle `t`.
pub fn pair<'g>(
    g: &'g Graph,
    which: Pair,
    p: &V3<'g>,
    q: &[Expr<'g>; 4],
    t: Expr<'g>,
) -> PairGeometry<'g> {
    let r = g.param("r");
    let len = g.param("L");
    let rho_p = g.param("rho_p");
    let bore = g.param("R");
    let rho_h = g.param("rho_h");
    let depth = g.param("h_b");
    let zero = g.constant(0.0);
    let one = g.constant(1.0);
    let axis = rotate(q, &[zero, zero, one]);
    let (s, c) = (t.sin(), t.cos());
    match which {
        Pair::EdgeSide => {
            let rc = bore + rho_h;
            let centre = [rc * c, rc * s, -rho_h];
            let u = [centre[0] - p[0], centre[1] - p[1], centre[2] - p[2]];
            let along = dot(&u, &axis);
            let w = [
                u[0] - along * axis[0],
                u[1] - along * axis[1],
                u[2] - along * axis[2],
            ];
            let dist = dot(&w, &w).sqrt();
            let gap = dist - r - rho_h;
            let normal = [-w[0] / dist, -w[1] / dist, -w[2] / dist];
            let half = 0.5 * (rho_h + dist - r);
            let point = [
                centre[0] + half * normal[0],
                centre[1] + half * normal[1],
                centre[2] + half * normal[2],
            ];
            let axial = dot(&[point[0] - p[0], point[1] - p[1], point[2] - p[2]], &axis);
            PairGeometry {
                gap,
                normal,
                point,
                axial,
            }
        }
        Pair::RimWall | Pair::RimTop | Pair::RimBottom | Pair::RimEdge => {
            let rr = r - rho_p;
            let body = [rr * c, rr * s, rho_p - 0.5 * len];
            let off = rotate(q, &body);
            let centre = [p[0] + off[0], p[1] + off[1], p[2] + off[2]];
            let (gap, normal, point) = match which {
                Pair::RimWall => {
                    let rad = (centre[0] * centre[0] + centre[1] * centre[1]).sqrt();
                    let gap = bore - rho_p - rad;
                    let normal = [-centre[0] / rad, -centre[1] / rad, zero];
                    let mid = 0.5 * (bore + rad + rho_p);
                    let point = [-mid * normal[0], -mid * normal[1], centre[2]];
                    (gap, normal, point)
                }
                Pair::RimEdge => {
                    let rad = (centre[0] * centre[0] + centre[1] * centre[1]).sqrt();
                    let rm = bore + rho_h;
                    let dr = rad - rm;
                    let dz = centre[2] + rho_h;
                    let dist = (dr * dr + dz * dz).sqrt();
                    let gap = dist - rho_p - rho_h;
                    let radial = [centre[0] / rad, centre[1] / rad];
                    let normal = [dr * radial[0] / dist, dr * radial[1] / dist, dz / dist];
                    // Midway between the mouth surface (m + ρ_h n) and the
                    // rim surface (c − ρ_p n).
                    let half = 0.5 * (rho_h + dist - rho_p);
                    let point = [
                        rm * radial[0] + half * normal[0],
                        rm * radial[1] + half * normal[1],
                        -rho_h + half * normal[2],
                    ];
                    (gap, normal, point)
                }
                _ => {
                    let plane = if which == Pair::RimTop { zero } else { -depth };
                    let gap = centre[2] - rho_p - plane;
                    let point = [centre[0], centre[1], 0.5 * (centre[2] - rho_p + plane)];
                    (gap, [zero, zero, one], point)
                }
            };
            let axial = dot(&[point[0] - p[0], point[1] - p[1], point[2] - p[2]], &axis);
            PairGeometry {
                gap,
                normal,
                point,
                axial,
            }
        }
    }
}
