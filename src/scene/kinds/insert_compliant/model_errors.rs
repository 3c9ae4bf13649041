//! The compliant model's refusals of an `insert_compliant` scene, named by
//! the scene field (and its value as written) that the model's field comes
//! from.

use super::InsertParams;
use crate::compliant_peg::CompliantParams;
use crate::error::{SceneError, SceneErrors};
use crate::hertz::HertzError;

/// The scene field a model-level field corresponds to.
pub(super) fn scene_field(field: &str) -> String {
    let t = "insert_compliant";
    let mapped = match field {
        "peg_radius" => "clearance_ratio".to_owned(),
        "mass" | "inertia" => "density".to_owned(),
        "tilt" => "initial_tilt".to_owned(),
        "damping" => "contact_damping".to_owned(),
        f => f
            .replace("peg.", "peg_material.")
            .replace("hole.", "hole_material."),
    };
    format!("{t}.{mapped}")
}

pub(super) fn to_scene_error(e: HertzError, p: &InsertParams) -> SceneErrors {
    match e {
        // The model's peg radius and mass are derived from the scene's
        // clearance ratio and density: say so rather than print the derived
        // value as if it were the scene's.
        HertzError::Invalid {
            field,
            value,
            reason,
        } if matches!(field.as_str(), "peg_radius" | "mass" | "inertia") => {
            let own = if field == "peg_radius" {
                p.clearance_ratio
            } else {
                p.density
            };
            SceneErrors::from(SceneError::invalid(
                scene_field(&field),
                own,
                format!("gives {field} = {value:e}, which {reason}"),
            ))
        }
        HertzError::Invalid {
            field,
            value,
            reason,
        } => SceneErrors::from(SceneError::invalid(scene_field(&field), value, reason)),
        other => SceneErrors::from(SceneError::invalid(
            "insert_compliant",
            f64::NAN,
            other.to_string(),
        )),
    }
}

/// A refused two-point tilt, with the bound it must stay below when that
/// is what refused it (the model's reason names the bound, not its value).
pub(super) fn tilt_error(e: HertzError, params: &CompliantParams, p: &InsertParams) -> SceneErrors {
    match e {
        HertzError::Invalid { field, reason, .. }
            if field == "tilt" && reason.contains("split tilt") =>
        {
            let split = params.spec.geometry.wall_split_tilt();
            SceneErrors::from(SceneError::invalid(
                scene_field(&field),
                p.initial_tilt,
                format!(
                    "must be > 0 and below {} rad, 0.8 of the wall contact's split tilt \
                     acos((r - rho_p)/(D/2 - rho_p)) = {} rad (about sqrt(2 c), from \
                     insert_compliant.clearance_ratio and peg_fillet): beyond it the wall \
                     contact is no point contact",
                    crate::scene::numbers::significant(0.8 * split),
                    crate::scene::numbers::significant(split)
                ),
            ))
        }
        e => to_scene_error(e, p),
    }
}
