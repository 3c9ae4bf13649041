//! One file per module of the library, named after its path under
//! `src/`: the module's own items, tested through the crate's paths.

mod output_atomic;
mod output_axes;
mod output_csv;
mod output_legend;
mod output_manifest;
mod output_names;
mod output_plot;
mod output_record;
mod output_sink;
mod output_svg;
mod replay;
mod replay_decimate;
mod replay_json;
mod replay_page;
mod replay_states;
mod scene_document;
mod scene_integrator;
mod scene_limits;
mod scene_progress;
mod scene_ranges;
mod scene_shared_replay;
mod scene_shared_sensitivities;
mod scene_simulate;
mod scene_summary;
mod scene_timescales;
mod scene_translate;
mod scene_validate;
