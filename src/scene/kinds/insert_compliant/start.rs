//! The start pose of an `insert_compliant` run, checked before the run
//! (`docs/scenes.md`, "Start poses"): a start that overlaps the hole would
//! begin with a contact force set by the overlap alone; and the run's time
//! scales ([`crate::scene::timescales`]).

use super::{Built, InsertParams};
use crate::compliant_peg::{CompliantParams, CompliantSystem, Load, PegState};
use crate::error::{SceneError, SceneErrors};
use crate::scene::numbers::significant as sig;
use crate::scene::timescales::TimeScale;

/// Refuses a start pose that overlaps the hole (`docs/scenes.md`, "Start
/// poses"): deeper than [`TOUCH_FRACTION`](crate::scene::shared::compliant_peg_3d::start::TOUCH_FRACTION)
/// of the smaller fillet at any of the contacts, named on the field that
/// places the peg (`initial_tilt` for a two-point start, else
/// `initial_depth`).
pub fn overlap(
    params: &CompliantParams,
    load: &Load,
    initial: &PegState,
    p: &InsertParams,
) -> Result<(), SceneErrors> {
    use crate::scene::shared::compliant_peg_3d::start::TOUCH_FRACTION;
    let s = CompliantSystem::new(params, load).sample(&initial.to_vector());
    let g = &params.spec.geometry;
    let tolerance = TOUCH_FRACTION * g.peg_fillet.min(g.hole_fillet);
    let (which, delta, force) = if s.delta_edge >= s.delta_wall {
        ("edge", s.delta_edge, s.f_edge)
    } else {
        ("wall", s.delta_wall, s.f_wall)
    };
    // A NaN penetration is no overlap: the model's own checks name it.
    if delta.is_nan() || delta <= tolerance {
        return Ok(());
    }
    let (field, value) = if p.initial_tilt > 0.0 {
        ("initial_tilt", p.initial_tilt)
    } else {
        ("initial_depth", p.initial_depth)
    };
    Err(SceneErrors::from(SceneError::invalid(
        format!("insert_compliant.{field}"),
        value,
        format!(
            "the start pose overlaps the hole: the {which} contact penetrates {} m (a contact \
             force of {} N at t = 0), so the peg would start inside the block; choose a start \
             that only touches",
            crate::scene::numbers::significant(delta),
            crate::scene::numbers::significant(force)
        ),
    )))
}

/// The time scales of a run: the edge contact's natural period at the
/// applied load, the regularized friction's time constant, the loads'
/// time to move the peg by its radius.
pub fn time_scales(b: &Built, p: &InsertParams) -> Vec<TimeScale> {
    let spec = &b.params.spec;
    let m = spec.mass;
    let r = spec.geometry.peg_radius;
    let load =
        (p.axial_force.abs() + p.radial_force.abs() + p.torque.abs() / r).max(f64::MIN_POSITIVE);
    let k = b.params.pair.edge.stiffness();
    let mut out = vec![TimeScale::new(
        format!(
            "the edge contact's natural period 2 pi sqrt(m/k_eff) at {} N",
            sig(load)
        ),
        format!(
            "k = {} N/m^1.5 from insert_compliant.peg_fillet, hole_fillet and the \
             materials, on a peg of {} kg",
            sig(k),
            sig(m)
        ),
        TimeScale::period_of(m, TimeScale::hertz_stiffness(k, load)),
    )];
    if spec.friction > 0.0 {
        out.push(TimeScale::new(
            "the regularized friction's time constant m v_s / (mu F)",
            format!(
                "insert_compliant.slip_velocity = {} m/s, insert_compliant.friction = {}",
                sig(spec.slip_velocity),
                sig(spec.friction)
            ),
            m * spec.slip_velocity / (spec.friction * load),
        ));
    }
    out.push(TimeScale::new(
        "the loads' time to move the peg by its radius sqrt(m r / F)",
        format!(
            "insert_compliant.axial_force, radial_force, torque: {} N on {} kg",
            sig(load),
            sig(m)
        ),
        (m * r / load).sqrt(),
    ));
    out
}
