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
pub(super) fn scene_field(field: &str, p: &InsertParams) -> String {
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

pub(super) fn to_scene_error(e: HertzError, p: &InsertParams) -> SceneErrors {
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
pub(super) fn tilt_error(e: HertzError, params: &CompliantParams, p: &InsertParams) -> SceneErrors {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::kinds::insert_compliant::InsertCompliantScene;

    fn shipped() -> InsertParams {
        let text = include_str!("../../../../scenes/insert_compliant.toml");
        let doc = crate::scene::Document::parse(text).unwrap_or_else(|e| panic!("{e}"));
        let s: InsertCompliantScene = doc.body().unwrap_or_else(|e| panic!("{e}"));
        s.insert_compliant
    }

    fn first(e: SceneErrors) -> (String, String) {
        let e = &e.errors[0].error;
        (e.field().unwrap_or_default().to_owned(), e.to_string())
    }

    #[test]
    fn every_model_refusal_names_a_scene_field_with_its_written_value() {
        let p = shipped();
        // Refusals of the geometry as a whole: named on the clearance ratio
        // as written, with the dimensions that set the curvatures.
        for e in [
            HertzError::NotPointContact { a: -1.0, b: 5.0 },
            HertzError::LineContact {
                ratio: 2e12,
                limit: 1e12,
            },
            HertzError::NoConvergence {
                kernel: "ellipticity solve",
                iterations: 100,
                input: 3e11,
            },
            HertzError::Invalid {
                field: "curvature".into(),
                value: f64::NAN,
                reason: "must be finite",
            },
        ] {
            let what = e.to_string();
            let (field, text) = first(to_scene_error(e, &p));
            assert_eq!(field, "insert_compliant.clearance_ratio", "{text}");
            assert!(
                text.contains("= 0.002")
                    && text.contains("hole_diameter = 0.05, peg_fillet = 2e-4")
                    && !text.contains("NaN =")
                    && text.contains(what.split(':').next().unwrap_or_default()),
                "{text}"
            );
        }
        // A field set directly: its own name and value.
        let (field, text) = first(to_scene_error(
            HertzError::Invalid {
                field: "damping".into(),
                value: p.contact_damping,
                reason: "must be finite and >= 0",
            },
            &p,
        ));
        assert_eq!(field, "insert_compliant.contact_damping", "{text}");
        // A derived field: the scene's value, and the derived one in the reason.
        let (field, text) = first(to_scene_error(
            HertzError::Invalid {
                field: "com_height".into(),
                value: 1e-5,
                reason: "must exceed peg_fillet",
            },
            &p,
        ));
        assert_eq!(field, "insert_compliant.peg_length", "{text}");
        assert!(text.contains("gives com_height = 1e-5"), "{text}");
        let (field, _) = first(to_scene_error(
            HertzError::Invalid {
                field: "hole.poisson_ratio".into(),
                value: p.hole_material.poisson_ratio,
                reason: "must lie in (-1, 0.5)",
            },
            &p,
        ));
        assert_eq!(field, "insert_compliant.hole_material.poisson_ratio");
    }
}
