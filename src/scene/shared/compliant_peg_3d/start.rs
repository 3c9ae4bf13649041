//! The start pose of a run of the compliant 3-D peg, checked before the
//! run: a start whose surfaces already overlap the block (a tilt, lateral
//! error or wrist sag that puts the rim below the top face or into the
//! mouth) would begin with a contact force set by the overlap alone — a
//! 30 degree tilt 1 mm above the face starts with hundreds of kilonewtons
//! at `t = 0` — so `check` refuses it, naming the fields that place the
//! peg and the start height that clears the block (`docs/scenes.md`,
//! "Start poses"). A start that only touches (the `drop_3d` lean, lowered
//! until the fillets meet) passes.

use nalgebra::SVector;

use crate::compliant_peg_3d::insertion::{Insertion, N_STATE};
use crate::compliant_peg_3d::{HertzMode, Pair, Peg3dParams};
use crate::error::RunError;
use crate::hertz::HertzError;
use crate::scene::numbers::significant;

/// Largest overlap at the start accepted as touching, as a fraction of the
/// smaller fillet radius: far above the `1e-7` of a fillet to which a lean
/// start is bisected, far below any overlap that carries a load.
pub const TOUCH_FRACTION: f64 = 1e-6;

/// How a start-pose refusal begins ([`Overlap::describe`]).
pub const OVERLAP: &str = "the start pose overlaps the block";

/// The deepest overlap of a start pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Overlap {
    /// The contact pair that overlaps most.
    pub pair: Pair,
    /// Its penetration (m).
    pub penetration: f64,
    /// The largest contact normal force at the start (N; NaN when the
    /// contact law cannot be set up there).
    pub force: f64,
    /// The smallest lift along the hole's axis that leaves the peg only
    /// touching (m).
    pub lift: f64,
}

/// The overlap at start state `y` beyond [`TOUCH_FRACTION`] of the smaller
/// fillet, `None` when the peg is free or only touches.
pub fn overlap(sys: &Insertion, y: &SVector<f64, N_STATE>) -> Option<Overlap> {
    let prm = &sys.peg.params;
    let tolerance = TOUCH_FRACTION * prm.rim_fillet.min(prm.mouth_fillet);
    let deepest = |y: &SVector<f64, N_STATE>| {
        sys.contacts(y)
            .into_iter()
            .max_by(|a, b| a.penetration.total_cmp(&b.penetration))
            .filter(|c| c.penetration > tolerance)
    };
    let c = deepest(y)?;
    let force = sys.sample(0.0, y).map_or(f64::NAN, |s| s.peak_normal());
    let lifted = |h: f64| {
        let mut z = *y;
        z[2] += h;
        z
    };
    // Double the lift until free, then bisect to a thousandth of it.
    let mut hi = c.penetration.max(tolerance);
    for _ in 0..80 {
        if deepest(&lifted(hi)).is_none() {
            break;
        }
        hi *= 2.0;
    }
    let mut lo = 0.0;
    for _ in 0..60 {
        if hi - lo <= 1e-3 * hi {
            break;
        }
        let mid = 0.5 * (lo + hi);
        if deepest(&lifted(mid)).is_some() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(Overlap {
        pair: c.pair,
        penetration: c.penetration,
        force,
        lift: hi,
    })
}

impl Overlap {
    /// What overlaps, by how much and with what force, in words.
    pub fn describe(&self) -> String {
        let force = if self.force.is_finite() {
            format!("a contact force of {} N at t = 0", significant(self.force))
        } else {
            "a contact whose Hertz law cannot be set up".to_owned()
        };
        format!(
            "{OVERLAP}: the {} contact penetrates {} m ({force}), so the peg would start \
             inside the block",
            self.pair.name(),
            significant(self.penetration)
        )
    }
}

/// A Hertz refusal during a run at time `t`, named by the `[peg]` fields
/// that set the contact law: the fillets and diameters whose curvatures
/// the curvature law uses, or the fixed stiffness.
pub fn hertz_refusal(p: &Peg3dParams, t: f64, e: HertzError) -> RunError {
    let fields = match p.hertz {
        HertzMode::Curvature => format!(
            "the contact law takes its curvatures from peg.rim_fillet = {} m, \
             peg.mouth_fillet = {} m, peg.hole_diameter = {} m and peg.clearance_ratio (peg \
             diameter {} m): a contact there is no point contact; set \
             peg.contact_stiffness for a fixed Hertz stiffness, or change those fields",
            significant(p.rim_fillet),
            significant(p.mouth_fillet),
            significant(p.hole_diameter),
            significant(p.peg_diameter)
        ),
        HertzMode::Fixed(k) => format!(
            "with peg.contact_stiffness = {} N/m^1.5 the law's setup at the fillets \
             peg.rim_fillet = {} m, peg.mouth_fillet = {} m failed",
            significant(k),
            significant(p.rim_fillet),
            significant(p.mouth_fillet)
        ),
    };
    RunError::HertzAt {
        t,
        fields,
        source: e,
    }
}
