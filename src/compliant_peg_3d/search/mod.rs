//! The contact search: for each pair, every local minimum of the gap
//! `g(α)` along its circle that lies below zero (every contact), found
//! with certainty.
//!
//! Each pair's gap is an increasing function of a simpler profile `h`
//! ([`profile`]): a trigonometric polynomial of degree two for the mouth
//! edge on the peg's side and the rim on the bore wall (squared distances
//! to a line and to the hole's axis), a sinusoid for the rim on a plane,
//! and for the rim on the mouth edge the squared distance between the two
//! tube-centre circles, `(√F − R_m)² + Z²`. The plane pairs have their one
//! minimum in closed form. The others are searched by branch and bound
//! over arcs ([`certified`]): an arc is dropped only when an enclosure of
//! `h`, `h′` or `h″` over it ([`trig`], [`interval`]) proves that it holds
//! no minimum below the level, and the minimum of a convex arc is found by
//! safeguarded Newton. A minimum is never missed by sampling between
//! points; the search needs no warm start, so it is the same at a start,
//! after an impact, along a sweep and along a smooth run.
//!
//! Only penetrating minima (`g < 0`) on the part of each surface that
//! exists (see [`Pair::valid`]) become contacts; minima closer than
//! `10⁻⁹` rad are one.

pub mod certified;
pub mod interval;
pub mod profile;
pub mod trig;

use super::contact::{ContactPoint, Contacts, Pair, axis_of};
use super::merge;
use super::params::Peg3dParams;
use nalgebra::SVector;

pub use certified::{Angles, MAX_MINIMA, Work};
use profile::Problem;

/// The minimum at `a` (from the profile) as a root of the generated
/// function's own `g′`: one Newton step on the generated derivatives, kept
/// when it is short (`10⁻⁹` rad) and lowers `|g′|`. The two agree to
/// rounding; the step makes a contact of a symmetric pose lie exactly on
/// the plane of symmetry, as the generated derivative says. Returns the
/// angle and the generated outputs there.
fn polish(
    pair: Pair,
    x: &SVector<f64, 7>,
    p: &SVector<f64, 16>,
    a: f64,
) -> (f64, super::contact::PairOut<f64>) {
    let e = pair.eval(x, a, p);
    if e.d1 != 0.0 && e.d2 > 0.0 {
        let next = a - e.d1 / e.d2;
        if (next - a).abs() < 1e-9 {
            let en = pair.eval(x, next, p);
            if en.d1.abs() < e.d1.abs() {
                return (next.rem_euclid(std::f64::consts::TAU), en);
            }
        }
    }
    (a, e)
}

/// The contact search of the pairs, with the work its last call did.
#[derive(Clone, Debug, Default)]
pub struct Search {
    /// What the last search did (arcs visited, points evaluated).
    pub work: Work,
}

impl Search {
    /// Every local minimum of `pair`'s gap below `below` (m) at pose `x`
    /// (unit quaternion), `p` the generated functions' parameter vector
    /// ([`Peg3dParams::vector`]): angles in `[0, 2π)`. The result may hold
    /// further local minima of the gap (at or above `below`), never a point
    /// that is not one.
    pub fn minima(
        &mut self,
        pair: Pair,
        x: &SVector<f64, 7>,
        p: &SVector<f64, 16>,
        below: f64,
    ) -> Angles {
        let mut out = Angles::new();
        self.work = Work::default();
        match Problem::of(pair, x, p, below) {
            Problem::Nothing | Problem::Closed(None) => {}
            Problem::Closed(Some(a)) => {
                certified::push(&mut out, a);
            }
            Problem::Search { h, level } => {
                self.work = certified::minima(&h, level, &mut out);
            }
        }
        out
    }

    /// The penetrating, valid local minima of `pair`'s gap at pose `x`
    /// (unit quaternion), appended to `out` with the cols of
    /// [`merge::assign`].
    pub fn find(
        &mut self,
        pair: Pair,
        prm: &Peg3dParams,
        x: &SVector<f64, 7>,
        p: &SVector<f64, 16>,
        out: &mut Contacts,
    ) {
        let minima = self.minima(pair, x, p, 0.0);
        let axis = axis_of(x);
        let first = out.len();
        for &a in &minima {
            let (a, e) = polish(pair, x, p, a);
            if e.gap < 0.0
                && pair.valid(prm, &axis, &e.normal, &e.point, e.axial)
                && pair.rim_faces_out(x, &e.normal, &e.point)
            {
                let point = ContactPoint {
                    pair,
                    angle: a,
                    penetration: -e.gap,
                    gradient: e.grad,
                    normal: e.normal,
                    point: e.point,
                    saddle: None,
                    ring: false,
                };
                if out.try_push(point).is_err() {
                    self.work.unresolved += 1;
                }
            }
        }
        merge::assign(pair, x, p, &mut out[first..]);
    }
}
