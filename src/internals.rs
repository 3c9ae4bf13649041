//! Building blocks that the library uses internally and that its tests
//! (`tests/<area>/modules/`) reach: not part of the API, hidden from the
//! documentation, and free to change in any release.
//!
//! Each submodule re-exports items of a module that is private to the
//! crate. A few items of public modules are hidden from the
//! documentation for the same reason and reached at their own paths:
//! `output::svg::segments`, the number formats of `replay::json`
//! (`Digits`, `number`, `string` and the digit constants),
//! `replay::page::SCRIPTS`, `scene::Document::found_at`,
//! `jamming::forces::forces_from_factors`,
//! `scene::kinds::insert_compliant::sensitivities::fields::slot` and the
//! grid rows of `scene::kinds::rotation_assist` (`Point`, `Row`,
//! `rate_pairs`).

/// The implicit integrators' linear algebra: the dense LU with partial
/// pivoting and the reduced solves of the Newton matrix `cI − J`.
pub mod integrate {
    pub use crate::integrate::iteration::{IterationLu, second_order_split};
    pub use crate::integrate::kinematic::{Kinematic, Refused};
    pub use crate::integrate::lu::Lu;
}

/// The plots' axes and legend placement.
#[cfg(feature = "scenes")]
pub mod output {
    pub use crate::output::axes::{bounds, tick};
    pub use crate::output::legend::{
        Mapping, Place, Plan, covers, crosses, legend_size, place, plan,
    };
}

/// The scenes' run loop, progress line, summaries and the translation of
/// TOML errors into plain words.
#[cfg(feature = "scenes")]
pub mod scene {
    pub use crate::scene::progress::{SLOW_AFTER, SLOW_STEPS, eta, slow_notice};
    pub use crate::scene::simulate::{
        describe_stop, describe_stop_at, event_records, integrate, integration_summary,
        solver_config,
    };
    pub use crate::scene::summary::format_metric;
    pub use crate::scene::translate::{
        plain_found, plain_text, plain_type, plain_value, translate,
    };
}

/// The `insert_compliant` scene kind's start pose and model errors.
#[cfg(feature = "scenes")]
pub mod insert_compliant {
    pub use crate::scene::kinds::insert_compliant::model_errors::to_scene_error;
    pub use crate::scene::kinds::insert_compliant::start::{overlap, time_scales};
}

/// The `rotation_assist` scene kind's figure.
#[cfg(feature = "scenes")]
pub mod rotation_assist {
    pub use crate::scene::kinds::rotation_assist::figure::heat_maps;
}

/// The `jamming` scene kind's comparison of the sweep with the diagram.
#[cfg(feature = "scenes")]
pub mod jamming {
    pub use crate::scene::kinds::jamming::comparison::comparison;
}
