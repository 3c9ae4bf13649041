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
pub(super) fn overlap(
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
pub(super) fn time_scales(b: &Built, p: &InsertParams) -> Vec<TimeScale> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::kinds::insert_compliant::InsertCompliantScene;

    fn shipped() -> (InsertCompliantScene, Built) {
        let text = include_str!("../../../../scenes/insert_compliant.toml");
        let doc = crate::scene::Document::parse(text).unwrap_or_else(|e| panic!("{e}"));
        let s: InsertCompliantScene = doc.body().unwrap_or_else(|e| panic!("{e}"));
        let b = s.build().unwrap_or_else(|e| panic!("{e}"));
        (s, b)
    }

    #[test]
    fn a_two_point_start_pressed_into_the_hole_is_refused_on_the_tilt() {
        let (s, b) = shipped();
        let p = &s.insert_compliant;
        for (tilt, penetration) in [(0.01, 1e-5), (0.02, 1e-6), (0.005, 1e-7)] {
            let start = PegState::two_point(&b.params, tilt, penetration).unwrap();
            let e = overlap(&b.params, &b.load, &start, p)
                .expect_err("an overlapping start")
                .to_string();
            assert!(
                e.contains("`insert_compliant.initial_tilt`") && e.contains("overlaps the hole"),
                "{e}"
            );
            // Touching exactly, the same tilt runs.
            let touching = PegState::two_point(&b.params, tilt, 0.0).unwrap();
            assert!(overlap(&b.params, &b.load, &touching, p).is_ok(), "{tilt}");
        }
    }

    #[test]
    fn the_edge_contact_period_follows_the_hertz_law() {
        let (s, b) = shipped();
        let scales = time_scales(&b, &s.insert_compliant);
        let contact = &scales[0];
        let k = b.params.pair.edge.stiffness();
        let load = 5.0 + 0.002 / b.params.spec.geometry.peg_radius;
        let k_eff = 1.5 * k.powf(2.0 / 3.0) * load.cbrt();
        let expected = std::f64::consts::TAU * (b.params.spec.mass / k_eff).sqrt();
        assert!(
            (contact.period / expected - 1.0).abs() < 1e-12,
            "{contact:?}"
        );
        assert!(contact.fields.contains("peg_fillet"), "{contact:?}");
    }
}
