//! One file per module of the library, named after its path under
//! `src/`: the module's own items, tested through the crate's paths.

mod scene_kinds_insert_compliant_model_errors;
mod scene_kinds_insert_compliant_ranges;
mod scene_kinds_insert_compliant_sensitivities_fields;
mod scene_kinds_insert_compliant_start;
