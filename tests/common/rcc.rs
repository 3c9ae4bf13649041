//! Shared by the insertion tests (`tests/insertion/outcomes.rs`,
//! `tests/insertion/quasi_static.rs`): an
//! `insert_rcc` scene text built and run in-process with its own
//! integrator (RODAS4, the kind's default, when it names none).

#![allow(dead_code)]

use pegdyn::scene::Progress;
use pegdyn::scene::shared::compliant_peg_3d::insertion::{Built, RccScene, Run, run_one};

/// Parses `text` as an `insert_rcc` scene, builds it and runs it.
pub fn run(text: &str) -> (RccScene, Built, Run) {
    let mut doc: toml::Table = toml::from_str(text).expect("the test scene is TOML");
    doc.remove("kind");
    doc.remove("description");
    let scene: RccScene = doc
        .try_into()
        .expect("the test scene is an insert_rcc scene");
    let built = scene.build().expect("the test scene is valid");
    let (spec, _) = scene
        .integrator
        .resolved(pegdyn::scene::integrator::DefaultMethod::STIFF_CONTACT);
    let run = run_one(&built, &spec, false, &mut Progress::silent()).expect("the run starts");
    (scene, built, run)
}
