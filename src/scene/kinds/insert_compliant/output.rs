//! CSV and SVG output of an `insert_compliant` run.
//!
//! CSV columns: `t_s, x_m, z_m, theta_rad, depth_m, f_A_N, f_B_N, p0_A_Pa,
//! p0_B_Pa, delta_A_m, delta_B_m, kinetic_J, potential_J, work_J,
//! dissipation_J, balance_J` (A: the loaded edge contact, B: the loaded
//! wall contact; `balance = T + P + E_t − W + S`, constant along a
//! solution, `E_t` the energy stored in the tangential springs of the
//! elastic friction law, 0 with the regularized law).

use nalgebra::SVector;

use crate::compliant_peg::system::Sample;
use crate::error::RunError;
use crate::integrate::Solution;
use crate::output::names::Part;
use crate::output::plot::{Figure, Panel, Series};
use crate::scene::context::RunContext;
use crate::scene::summary::{Metric, RunSummary};

const HEADER: [&str; 16] = [
    "t_s",
    "x_m",
    "z_m",
    "theta_rad",
    "depth_m",
    "f_A_N",
    "f_B_N",
    "p0_A_Pa",
    "p0_B_Pa",
    "delta_A_m",
    "delta_B_m",
    "kinetic_J",
    "potential_J",
    "work_J",
    "dissipation_J",
    "balance_J",
];

/// Writes `<name>.csv` and `<name>.svg` and adds the run's metrics
/// (energy-balance drift, peak forces and pressures) to `out`.
/// `sample` gives the contact and energy quantities of a state (of either
/// friction law's system); `(f_max, p_max)` are the largest contact force
/// (N) and Hertz pressure (Pa) over the ends of the run's accepted steps,
/// which the peaks over the samples extend.
pub fn write_outputs<const N: usize>(
    ctx: &RunContext,
    sample: impl Fn(&SVector<f64, N>) -> Sample,
    sol: &Solution<N>,
    (f_max, p_max): (f64, f64),
    out: &mut RunSummary,
) -> Result<(), RunError> {
    let mut csv = ctx.table(Part::Main, &HEADER)?;
    let mut cols: Vec<Vec<(f64, f64)>> = vec![Vec::new(); HEADER.len()];
    let (mut drift, mut work_scale, mut f_max, mut p_max) = (0.0_f64, 0.0_f64, f_max, p_max);
    let h0 = sol.x.first().map(|y| sample(y).balance()).unwrap_or(0.0);
    for (&t, y) in sol.t.iter().zip(&sol.x) {
        let s = sample(y);
        let row = [
            t,
            y[0],
            y[1],
            y[2],
            s.depth,
            s.f_edge,
            s.f_wall,
            s.p0_edge,
            s.p0_wall,
            s.delta_edge,
            s.delta_wall,
            s.kinetic,
            s.potential,
            s.work,
            s.dissipation,
            s.balance(),
        ];
        csv.row(&row)?;
        for (k, v) in row.iter().enumerate().skip(1) {
            cols[k].push((t, *v));
        }
        drift = drift.max((s.balance() - h0).abs());
        work_scale = work_scale.max(s.work.abs()).max(s.kinetic);
        f_max = f_max.max(s.f_edge).max(s.f_wall);
        p_max = p_max.max(s.p0_edge).max(s.p0_wall);
    }
    csv.finish()?;
    let series = |k: usize, name: &str| Series::line(name, cols[k].clone());
    let mut fig = Figure::new();
    fig.panels
        .push(Panel::new("Insertion depth", "t [s]", "depth l [m]").with(series(4, "l")));
    fig.panels
        .push(Panel::new("Tilt", "t [s]", "θ [rad]").with(series(3, "θ")));
    fig.panels.push(
        Panel::new("Contact forces (Hertz)", "t [s]", "f [N]")
            .with(series(5, "f_A (edge)"))
            .with(series(6, "f_B (wall)")),
    );
    fig.panels.push(
        Panel::new("Maximum contact pressure", "t [s]", "p₀ [Pa]")
            .with(series(7, "p0_A"))
            .with(series(8, "p0_B")),
    );
    fig.panels.push(
        Panel::new("Energy terms", "t [s]", "[J]")
            .with(series(11, "kinetic T"))
            .with(series(12, "contact P"))
            .with(series(13, "work W"))
            .with(series(14, "friction S"))
            .with(series(15, "T + P − W + S")),
    );
    ctx.figure(Part::Main, &fig)?;
    let drift = drift / work_scale.max(1e-300);
    out.metrics.push(Metric::new(
        "max |T + P - W + S - E0| / max(|W|, T)",
        drift,
        "",
    ));
    out.metrics
        .extend(crate::scene::energy_drift_warning(drift));
    out.metrics
        .push(Metric::new("peak contact force", f_max, "N"));
    out.metrics
        .push(Metric::new("peak Hertz pressure p0", p_max, "Pa"));
    Ok(())
}
