//! Design margins of an insertion, the quasi-static theory drawn over the
//! simulation (see `docs/insertion.md` for the derivations):
//!
//! - **No-jam condition.** At every sample in contact, the load on the peg
//!   (wrist force and moment plus gravity) reduced to the tip, in the tilt
//!   plane (`X` the horizontal direction of the axis's lean, `Z` into the
//!   hole): the ratio `q = (F_X/F_Z, M/(r F_Z))` and its signed distance to
//!   the edges of Whitney's parallelogram at the current depth `l`
//!   (`pegdyn::jamming::diagram::whitney_parallelogram`; positive inside:
//!   the peg slides in).
//! - **Wedging depth.** Two-point contact entered at `l < μ d` can wedge
//!   (the line between the contacts lies inside both friction cones).
//! - **Two-point depth.** With tilt `θ` the peg enters two-point contact
//!   where `l θ ≈ D − d`, `l` the axial distance between the mouth's
//!   innermost circle (depth `ρ_h`) and the rim's outermost circle (`ρ_p`
//!   above the tip): tip depth `ρ_h + ρ_p + (D − d)/θ`.
//! - **Chamfer acceptance.** An aligned peg's rounded rim lands on the
//!   rounded mouth, and is guided in, while its lateral error is below
//!   `e_max = (R − r) + ρ_h + ρ_p`.

use nalgebra::Vector3;

use super::output::Samples;
use crate::compliant_peg_3d::Peg3dParams;
use crate::compliant_peg_3d::insertion::{motion, peg_state};
use crate::compliant_peg_3d::no_jam::load_ratio;
use crate::compliant_peg_3d::outcome::two_point;
use crate::jamming::PegHole;
use crate::jamming::diagram::whitney_parallelogram;
use crate::output::plot::{Panel, Series, Style};
use crate::scene::summary::Metric;

/// The load ratio of each sample in two-point contact in the bore (the
/// mouth edge on the side and the rim on the wall,
/// [`two_point`]), pushed in
/// (`F_Z > 0`): `(t, (F_X/F_Z, M/(r F_Z)), tip depth)`
/// ([`load_ratio`] of the wrist's load plus gravity).
pub fn ratio(prm: &Peg3dParams, s: &super::output::Samples) -> Vec<(f64, [f64; 2], f64)> {
    let mut out = Vec::new();
    for (t, y, smp) in &s.rows {
        let Some(w) = &smp.wrist else { continue };
        if !two_point(smp.forces.iter().map(|f| f.contact.pair)) || smp.depth <= prm.mouth_fillet {
            continue;
        }
        let m = motion(&peg_state(y));
        let a = m.orientation * Vector3::z();
        let force = w.force + Vector3::z() * (-prm.mass * prm.gravity);
        let Some(q) = load_ratio(
            &a.into(),
            0.5 * prm.length,
            &force.into(),
            &w.moment.into(),
            prm.peg_radius(),
        ) else {
            continue;
        };
        out.push((*t, q, smp.depth));
    }
    out
}

/// The margins' metrics and the panel of the load-ratio path over the
/// no-jam parallelogram at the deepest sample (without series when the run
/// has no two-point contact in the bore).
pub fn margins(
    prm: &Peg3dParams,
    clearance_ratio: f64,
    angular_error: f64,
    s: &Samples,
) -> (Vec<Metric>, Panel) {
    let mut metrics = Vec::new();
    let d = prm.peg_diameter;
    metrics.push(Metric::new(
        "wedging possible for two-point contact above depth l = mu d",
        prm.friction * d,
        "m",
    ));
    if angular_error > 0.0 {
        metrics.push(Metric::new(
            "two-point depth rho_h + rho_p + (D - d)/theta0 at the angular error",
            prm.mouth_fillet + prm.rim_fillet + (prm.hole_diameter - d) / angular_error,
            "m",
        ));
    }
    metrics.push(Metric::new(
        "chamfer accepts lateral errors below (R - r) + rho_h + rho_p",
        prm.bore_radius() - prm.peg_radius() + prm.mouth_fillet + prm.rim_fillet,
        "m",
    ));
    let mut panel = Panel::new(
        "Load ratio against Whitney's no-jam parallelogram",
        "F_x / F_z",
        "M / (r F_z)",
    );
    let Ok(hole) = PegHole::try_new(prm.peg_radius(), clearance_ratio, prm.friction.max(1e-6))
    else {
        return (metrics, panel);
    };
    let path = ratio(prm, s);
    let mut worst = f64::INFINITY;
    let mut deepest = 0.0_f64;
    for (_, q, l) in &path {
        if let Ok(g) = whitney_parallelogram(&hole, *l) {
            worst = worst.min(g.margin(*q));
        }
        deepest = deepest.max(*l);
    }
    if worst.is_finite() {
        metrics.push(Metric::new(
            "smallest no-jam margin in two-point contact (negative: outside)",
            worst,
            "",
        ));
    }
    if path.is_empty() {
        return (metrics, panel);
    }
    panel = panel.with(
        Series::line(
            "simulated load ratio",
            path.iter().map(|(_, q, _)| (q[0], q[1])).collect(),
        )
        .styled(Style::LineMarkers),
    );
    for (k, l) in [0.25 * deepest, deepest].iter().enumerate() {
        if let Ok(g) = whitney_parallelogram(&hole, *l) {
            let mut pts: Vec<(f64, f64)> = g.corners.iter().map(|c| (c[0], c[1])).collect();
            pts.push(pts[0]);
            panel = panel.with(
                Series::line(format!("no-jam region at l = {:.2} mm", l * 1e3), pts)
                    .styled(Style::Dashed)
                    .colored(k + 2),
            );
        }
    }
    (metrics, panel)
}
