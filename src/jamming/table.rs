//! Tables of the jamming scene: parallelogram corners and wedging angles
//! over lists of clearance ratios, friction coefficients and depths.

use super::diagram::{Ratio, exact_parallelogram, whitney_parallelogram};
use super::error::ParamError;
use super::params::PegHole;
use super::wedging::wedging_angle;

/// Which parallelogram a corner belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DiagramKind {
    /// Whitney's small-angle parallelogram.
    Whitney,
    /// The exact finite-angle parallelogram.
    Exact,
}

impl DiagramKind {
    /// Name as written in `<name>.corners.csv`.
    pub fn name(self) -> &'static str {
        match self {
            DiagramKind::Whitney => "whitney",
            DiagramKind::Exact => "exact",
        }
    }
}

/// One corner of one parallelogram.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CornerRow {
    /// Insertion depth l (m).
    pub l: f64,
    /// Clearance ratio c.
    pub c: f64,
    /// Friction coefficient μ.
    pub mu: f64,
    /// Small-angle or exact.
    pub kind: DiagramKind,
    /// (F_x/F_z, M/(r F_z)), moment about the peg tip.
    pub corner: Ratio,
}

/// Corners for every (c, μ, l), c outermost: four Whitney rows, then four
/// exact rows unless two-point contact is impossible at that depth.
pub fn corner_rows(
    r: f64,
    cs: &[f64],
    mus: &[f64],
    ls: &[f64],
) -> Result<Vec<CornerRow>, ParamError> {
    let mut rows = Vec::new();
    for &c in cs {
        for &mu in mus {
            let p = PegHole::try_new(r, c, mu)?;
            for &l in ls {
                let w = whitney_parallelogram(&p, l)?;
                let e = exact_parallelogram(&p, l)?;
                let both = [(DiagramKind::Whitney, Some(w)), (DiagramKind::Exact, e)];
                for (kind, g) in both {
                    for corner in g.iter().flat_map(|g| g.corners) {
                        rows.push(CornerRow {
                            l,
                            c,
                            mu,
                            kind,
                            corner,
                        });
                    }
                }
            }
        }
    }
    Ok(rows)
}

/// Exact wedging angle for one (c, μ); `None` when wedging is impossible.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WedgingRow {
    /// Clearance ratio c.
    pub c: f64,
    /// Friction coefficient μ.
    pub mu: f64,
    /// θ_c (rad), see [`wedging_angle`].
    pub theta: Option<f64>,
}

/// Wedging angles for every (c, μ), c outermost.
pub fn wedging_rows(r: f64, cs: &[f64], mus: &[f64]) -> Result<Vec<WedgingRow>, ParamError> {
    let mut rows = Vec::new();
    for &c in cs {
        for &mu in mus {
            let p = PegHole::try_new(r, c, mu)?;
            rows.push(WedgingRow {
                c,
                mu,
                theta: wedging_angle(&p),
            });
        }
    }
    Ok(rows)
}
