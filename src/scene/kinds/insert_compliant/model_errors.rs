//! The compliant model's refusals of an `insert_compliant` scene, named by
//! the scene field (and its value as written) that the model's field comes
//! from.

use super::InsertParams;
use crate::compliant_peg::CompliantParams;
use crate::error::{SceneError, SceneErrors};
use crate::hertz::HertzError;
use crate::scene::numbers::significant;

/// The scene field a model-level field comes from, with its value as the
/// scene wrote it (the model's peg radius from the clearance ratio, its
/// mass and inertia from the density, the default centre-of-mass height
/// from the peg length). `None` for a field no scene field sets alone.
fn written(field: &str, p: &InsertParams) -> Option<(String, f64)> {
    let (name, value) = match field {
        "hole_diameter" => ("hole_diameter", p.hole_diameter),
        "peg_radius" => ("clearance_ratio", p.clearance_ratio),
        "mass" | "inertia" => ("density", p.density),
        "com_height" => match p.com_height {
            Some(h) => ("com_height", h),
            None => ("peg_length", p.peg_length),
        },
        "peg_fillet" => ("peg_fillet", p.peg_fillet),
        "hole_fillet" => ("hole_fillet", p.hole_fillet),
        "friction" => ("friction", p.friction),
        "slip_velocity" => ("slip_velocity", p.slip_velocity),
        "tangential_damping" => ("tangential_damping", p.tangential_damping),
        "damping" => ("contact_damping", p.contact_damping),
        "tilt" => ("initial_tilt", p.initial_tilt),
        "peg.youngs_modulus" => ("peg_material.youngs_modulus", p.peg_material.youngs_modulus),
        "peg.poisson_ratio" => ("peg_material.poisson_ratio", p.peg_material.poisson_ratio),
        "hole.youngs_modulus" => (
            "hole_material.youngs_modulus",
            p.hole_material.youngs_modulus,
        ),
        "hole.poisson_ratio" => ("hole_material.poisson_ratio", p.hole_material.poisson_ratio),
        _ => return None,
    };
    Some((format!("insert_compliant.{name}"), value))
}

/// The scene field a model-level field corresponds to (the geometry's
/// clearance ratio for a field no scene field sets alone, such as a
/// contact curvature).
pub fn scene_field(field: &str, p: &InsertParams) -> String {
    written(field, p).map_or_else(|| "insert_compliant.clearance_ratio".to_owned(), |w| w.0)
}

/// A refusal the geometry as a whole leads to (a contact that is no point
/// contact, a curvature ratio beyond Hertz's solution, a curvature that is
/// not finite): named on the clearance ratio, which sets the curvature
/// around the hole, with the other dimensions that set the curvatures.
fn geometry_error(p: &InsertParams, what: &str) -> SceneErrors {
    SceneErrors::from(SceneError::invalid(
        "insert_compliant.clearance_ratio",
        p.clearance_ratio,
        format!(
            "with hole_diameter = {}, peg_fillet = {} and hole_fillet = {} the contact \
             curvatures leave Hertz's point contact: {what}",
            significant(p.hole_diameter),
            significant(p.peg_fillet),
            significant(p.hole_fillet)
        ),
    ))
}

/// A model-level refusal of the compliant planar peg's parameters as the
/// scene field it comes from.
pub fn to_scene_error(e: HertzError, p: &InsertParams) -> SceneErrors {
    match e {
        HertzError::Invalid {
            field,
            value,
            reason,
        } => match written(&field, p) {
            // A field set directly: its value as written.
            Some((name, own)) if own == value || own.is_nan() && value.is_nan() => {
                SceneErrors::from(SceneError::invalid(name, own, reason))
            }
            // A field derived from the scene's (peg radius, mass, inertia,
            // the default centre-of-mass height): the scene's value, and
            // the derived one with the reason.
            Some((name, own)) => SceneErrors::from(SceneError::invalid(
                name,
                own,
                format!("gives {field} = {value:e}, which {reason}"),
            )),
            None => geometry_error(p, &format!("`{field}` = {value}: {reason}")),
        },
        other => geometry_error(p, &other.to_string()),
    }
}

/// A refused two-point tilt, with the bound it must stay below when that
/// is what refused it (the model's reason names the bound, not its value).
pub fn tilt_error(e: HertzError, params: &CompliantParams, p: &InsertParams) -> SceneErrors {
    match e {
        HertzError::Invalid { field, reason, .. }
            if field == "tilt" && reason.contains("split tilt") =>
        {
            let split = params.spec.geometry.wall_split_tilt();
            SceneErrors::from(SceneError::invalid(
                scene_field(&field, p),
                p.initial_tilt,
                format!(
                    "must be > 0 and below {} rad, 0.8 of the wall contact's split tilt \
                     acos((r - rho_p)/(D/2 - rho_p)) = {} rad (about sqrt(2 c), from \
                     insert_compliant.clearance_ratio and peg_fillet): beyond it the wall \
                     contact is no point contact",
                    significant(0.8 * split),
                    significant(split)
                ),
            ))
        }
        e => to_scene_error(e, p),
    }
}
