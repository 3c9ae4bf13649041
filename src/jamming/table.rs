//! Tables of the jamming scene: parallelogram corners, wedging angles and
//! their derivatives over lists of clearance ratios, friction coefficients
//! and depths.

use super::diagram::{Parallelogram, Ratio, exact_parallelogram, whitney_parallelogram};
use super::error::ParamError;
use super::params::PegHole;
use super::sensitivities::{Gradient, ParallelogramSensitivity, sensitivities};
use super::wedging::{wedging_angle, wedging_angle_series, wedging_angle_whitney};

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

/// One derivative row of `<name>.sensitivities.csv`: a design quantity and
/// its derivatives with respect to r, c, μ and l
/// ([`super::sensitivities`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SensitivityRow {
    /// Insertion depth l (m); `None` for the wedging angles (independent of l).
    pub l: Option<f64>,
    /// Clearance ratio c.
    pub c: f64,
    /// Friction coefficient μ.
    pub mu: f64,
    /// `whitney`, `exact` or `wedging`.
    pub kind: &'static str,
    /// The quantity's name (see [`QUANTITIES`]).
    pub quantity: &'static str,
    /// Its value.
    pub value: f64,
    /// Its derivatives.
    pub gradient: Gradient,
}

/// The quantities of a parallelogram in the sensitivity table, in order:
/// the corners P₁ and Q (F_x/F_z and M/(r F_z)), the two-point line's slope
/// and intercept, and the tilt.
pub const QUANTITIES: [&str; 7] = [
    "p1_fx_over_fz",
    "p1_m_over_rfz",
    "q_fx_over_fz",
    "q_m_over_rfz",
    "slope",
    "intercept",
    "tilt_rad",
];

/// The values and gradients of [`QUANTITIES`] of `g`.
fn parallelogram_quantities(
    g: &Parallelogram,
    s: &ParallelogramSensitivity,
) -> [(f64, Gradient); 7] {
    let [_, q, p1, _] = g.corners;
    let (slope, intercept) = g.two_point_line();
    [
        (p1[0], s.edge_corner.force_ratio),
        (p1[1], s.edge_corner.moment_ratio),
        (q[0], s.mirrored_corner.force_ratio),
        (q[1], s.mirrored_corner.moment_ratio),
        (slope, s.slope),
        (intercept, s.intercept),
        (g.theta, s.tilt),
    ]
}

/// Derivative rows for every (c, μ), c outermost: for each depth seven
/// Whitney rows and (where two-point contact exists) seven exact rows, then
/// the wedging angles: `theta_exact_rad` (where it exists),
/// `theta_series_rad`, `theta_whitney_rad`.
pub fn sensitivity_rows(
    r: f64,
    cs: &[f64],
    mus: &[f64],
    ls: &[f64],
) -> Result<Vec<SensitivityRow>, ParamError> {
    let mut rows = Vec::new();
    for &c in cs {
        for &mu in mus {
            let p = PegHole::try_new(r, c, mu)?;
            let mut push = |l, kind, quantity, (value, gradient): (f64, Gradient)| {
                rows.push(SensitivityRow {
                    l,
                    c,
                    mu,
                    kind,
                    quantity,
                    value,
                    gradient,
                });
            };
            let mut wedging = None;
            for &l in ls {
                let s = sensitivities(&p, l)?;
                let w = whitney_parallelogram(&p, l)?;
                for (q, v) in QUANTITIES
                    .iter()
                    .zip(parallelogram_quantities(&w, &s.whitney))
                {
                    push(Some(l), "whitney", q, v);
                }
                if let (Some(e), Some(se)) = (exact_parallelogram(&p, l)?, s.exact) {
                    for (q, v) in QUANTITIES.iter().zip(parallelogram_quantities(&e, &se)) {
                        push(Some(l), "exact", q, v);
                    }
                }
                wedging = Some(s.wedging);
            }
            let Some(wd) = wedging else { continue };
            if let (Some(theta), Some(g)) = (wedging_angle(&p), wd.exact) {
                push(None, "wedging", "theta_exact_rad", (theta, g));
            }
            push(
                None,
                "wedging",
                "theta_series_rad",
                (wedging_angle_series(&p), wd.series),
            );
            push(
                None,
                "wedging",
                "theta_whitney_rad",
                (wedging_angle_whitney(&p), wd.whitney),
            );
        }
    }
    Ok(rows)
}
