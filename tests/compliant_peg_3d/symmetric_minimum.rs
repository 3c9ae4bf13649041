//! A pose symmetric about the tilt plane puts a pair's minimum exactly on
//! an angle where the search's start arcs meet (`0` or `π`), so the zero
//! of the profile's slope lies on the end of the arc that brackets it. The
//! safeguarded Newton iteration must stop there within a few steps: a
//! strict bracket test rejects every Newton step (the step rounds to the
//! end itself) and bisects towards the end for about 50 steps.

use crate::insertion_split::insertion_peg;
use nalgebra::SVector;
use pegdyn::compliant_peg_3d::{Pair, Search};

/// The peg's centre at `(x, 0, z)` (m), its axis tilted by `gamma` (rad)
/// about the hole frame's y axis: symmetric about the x–z plane.
fn tilted(x: f64, z: f64, gamma: f64) -> SVector<f64, 7> {
    let (s, c) = (0.5 * gamma).sin_cos();
    SVector::from([x, 0.0, z, c, 0.0, s, 0.0])
}

#[test]
fn a_minimum_on_the_plane_of_symmetry_takes_a_few_newton_steps() {
    let prm = insertion_peg();
    let pv = prm.vector();
    let half = 0.5 * prm.length;
    let mut searched = 0;
    // Tip at 2 to 6 mm in the bore, leaning on the side wall and the mouth
    // (lateral offsets along ±x, tilts of both signs).
    for depth in [2e-3, 4e-3, 6e-3] {
        for x in [-2e-4, 0.0, 1e-4, 3e-4] {
            for gamma in [-0.02_f64, -0.005, 0.005, 0.01, 0.02] {
                let pose = tilted(x, half * gamma.cos() - depth, gamma);
                for pair in [Pair::EdgeSide, Pair::RimWall, Pair::RimEdge] {
                    let mut s = Search::default();
                    let found = s.minima(pair, &pose, &pv, 1e-4);
                    if found.is_empty() {
                        continue;
                    }
                    searched += 1;
                    // Two end slopes per convex arc, a few Newton steps
                    // per minimum: about 50 per minimum before.
                    let bound = 2 * s.work.arcs + 8 * found.len();
                    assert!(
                        s.work.points <= bound,
                        "{pair:?} at depth {depth}, x {x}, gamma {gamma}: {} points \
                         for {} minima over {} arcs ({:?})",
                        s.work.points,
                        found.len(),
                        s.work.arcs,
                        found
                    );
                    // The minima lie on the plane of symmetry.
                    for a in &found {
                        let off = a.sin().abs();
                        assert!(off < 1e-12, "{pair:?}: minimum at {a} rad");
                    }
                }
            }
        }
    }
    assert!(searched >= 60, "only {searched} searches found a minimum");
}
