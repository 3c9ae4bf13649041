//! The dynamic check of the jamming diagram: a grid of load ratios
//! (F_x/F_z, M/(r F_z)) at fixed depth, one simulation per grid point run in
//! parallel (rayon), each classified inserted / jammed / wedged, and the
//! comparison of the class boundary with the quasi-static parallelogram.
//!
//! The simulator is a closure, so the driver does not depend on a particular
//! dynamic model (the scene plugs in `compliant_peg::simulate_insertion`).

use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;

use super::diagram::{Parallelogram, Ratio};

/// How one simulated insertion ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunClass {
    /// Reached the target depth.
    Inserted,
    /// Stopped, contact forces inside the friction cones balancing the load.
    Jammed,
    /// Stopped in two-point contact with the contact line inside both cones.
    Wedged,
    /// Anything else (left the hole, no contact, unfinished).
    Other,
    /// The integrator could not finish the run (step size underflow,
    /// non-finite values, step budget).
    Failed,
}

impl RunClass {
    /// Name as written in the sweep CSV.
    pub fn name(self) -> &'static str {
        match self {
            RunClass::Inserted => "inserted",
            RunClass::Jammed => "jammed",
            RunClass::Wedged => "wedged",
            RunClass::Other => "other",
            RunClass::Failed => "failed",
        }
    }

    /// Stuck: jammed or wedged.
    pub fn is_stuck(self) -> bool {
        matches!(self, RunClass::Jammed | RunClass::Wedged)
    }
}

/// One axis of the grid: `n ≥ 2` points from `min` to `max`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    /// First value.
    pub min: f64,
    /// Last value.
    pub max: f64,
    /// Number of points (≥ 2).
    pub n: usize,
}

impl Axis {
    /// Grid spacing.
    pub fn step(&self) -> f64 {
        (self.max - self.min) / (self.n.max(2) - 1) as f64
    }
    /// The `i`-th value.
    pub fn at(&self, i: usize) -> f64 {
        self.min + self.step() * i as f64
    }
}

/// A grid over (F_x/F_z, M/(r F_z)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grid {
    /// F_x/F_z values.
    pub x: Axis,
    /// M/(r F_z) values.
    pub y: Axis,
}

impl Grid {
    /// All grid points, x fastest.
    pub fn points(&self) -> Vec<Ratio> {
        (0..self.y.n)
            .flat_map(|j| (0..self.x.n).map(move |i| [self.x.at(i), self.y.at(j)]))
            .collect()
    }
    /// Length of a cell's diagonal: the resolution of the boundary.
    pub fn resolution(&self) -> f64 {
        self.x.step().hypot(self.y.step())
    }
}

/// One classified grid point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepPoint {
    /// The load ratio.
    pub ratio: Ratio,
    /// The class of the simulated run.
    pub class: RunClass,
}

/// Runs `simulate` at every grid point in parallel; `progress(done, total)`
/// is called after each run (from worker threads).
pub fn run<F, P, E>(grid: &Grid, simulate: F, progress: P) -> Result<Vec<SweepPoint>, E>
where
    F: Fn(Ratio) -> Result<RunClass, E> + Sync,
    P: Fn(usize, usize) + Sync,
    E: Send,
{
    let points = grid.points();
    let total = points.len();
    let done = AtomicUsize::new(0);
    points
        .into_par_iter()
        .map(|ratio| {
            let class = simulate(ratio)?;
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
            Ok(SweepPoint { ratio, class })
        })
        .collect()
}

/// The comparison of a sweep with the quasi-static parallelogram.
#[derive(Debug, Clone, PartialEq)]
pub struct BoundaryCheck {
    /// Points farther than `tolerance` from the parallelogram's boundary
    /// whose simulated class contradicts it (inserted outside, stuck inside).
    pub mismatches: Vec<SweepPoint>,
    /// Points farther than `tolerance` from the boundary (the ones judged).
    pub judged: usize,
    /// Points of class [`RunClass::Other`] or [`RunClass::Failed`] (not
    /// judged).
    pub other: usize,
    /// Of [`Self::other`], the points of class [`RunClass::Failed`].
    pub failed: usize,
    /// Distance to the boundary within which any class is accepted.
    pub tolerance: f64,
}

/// Compares the simulated classes with `par`: a point counts only when its
/// distance to the boundary exceeds `tolerance` (normally the grid
/// resolution); then inserted must be inside and jammed/wedged outside.
pub fn check(par: &Parallelogram, points: &[SweepPoint], tolerance: f64) -> BoundaryCheck {
    let mut out = BoundaryCheck {
        mismatches: Vec::new(),
        judged: 0,
        other: 0,
        failed: 0,
        tolerance,
    };
    for p in points {
        if matches!(p.class, RunClass::Other | RunClass::Failed) {
            out.other += 1;
            out.failed += usize::from(p.class == RunClass::Failed);
            continue;
        }
        let margin = par.margin(p.ratio);
        if margin.abs() <= tolerance {
            continue;
        }
        out.judged += 1;
        if (margin > 0.0) == p.class.is_stuck() {
            out.mismatches.push(*p);
        }
    }
    out
}
