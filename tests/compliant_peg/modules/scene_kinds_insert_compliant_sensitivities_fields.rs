//! The items of `src/scene/kinds/insert_compliant/sensitivities/fields.rs`.

use nalgebra::SVector;
use pegdyn::compliant_peg::CompliantParams;
use pegdyn::compliant_peg::params::N_PARAMS;
use pegdyn::compliant_peg::system::N_STATE;
use pegdyn::generated::compliant_peg as all;
use pegdyn::scene::kinds::insert_compliant::InsertCompliantScene;
use pegdyn::scene::kinds::insert_compliant::sensitivities::fields::*;

fn shipped() -> InsertCompliantScene {
    let text = include_str!(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenes/insert_compliant.toml"
    ));
    let doc = pegdyn::scene::Document::parse(text).unwrap_or_else(|e| panic!("{e}"));
    doc.body().unwrap_or_else(|e| panic!("{e}"))
}

/// The scene with field `k` set to `v`.
fn with(s: &InsertCompliantScene, k: usize, v: f64) -> InsertCompliantScene {
    let mut s = s.clone();
    *slot(&mut s.insert_compliant, k) = v;
    s
}

fn translate(s: &InsertCompliantScene) -> (SVector<f64, N_PARAMS>, SVector<f64, N_STATE>) {
    let b = s.build().unwrap_or_else(|e| panic!("{e}"));
    (
        CompliantParams::vector(&b.params, &b.load),
        b.initial.to_vector(),
    )
}

/// Richardson-extrapolated central difference of the translation.
fn difference(
    s: &InsertCompliantScene,
    k: usize,
    q: f64,
) -> (SVector<f64, N_PARAMS>, SVector<f64, N_STATE>) {
    let h = 1e-4 * if q != 0.0 { q.abs() } else { 1.0 };
    let central = |h: f64| {
        let (pu, yu) = translate(&with(s, k, q + h));
        let (pd, yd) = translate(&with(s, k, q - h));
        ((pu - pd) / (2.0 * h), (yu - yd) / (2.0 * h))
    };
    let (p1, y1) = central(h);
    let (p2, y2) = central(0.5 * h);
    ((4.0 * p2 - p1) / 3.0, (4.0 * y2 - y1) / 3.0)
}

#[test]
fn the_chain_rule_matches_differences_of_the_translation() {
    let mut s = shipped();
    // Exercise the radial load, the contact damping, a written
    // com_height and a centred start too.
    s.insert_compliant.radial_force = 0.3;
    s.insert_compliant.contact_damping = 0.5;
    s.insert_compliant.initial_depth = 0.005;
    let centred = with(&s, 14, 0.0);
    for scene in [s.clone(), with(&s, 4, 0.045), centred] {
        let b = scene.build().unwrap_or_else(|e| panic!("{e}"));
        let (dp, dy0) = jacobians(&scene.insert_compliant, &b);
        let q = values(&scene.insert_compliant);
        for k in 0..N_FIELDS {
            if q[k] == 0.0 {
                continue; // the centred start's tilt: no smaller one
            }
            let (fp, fy) = difference(&scene, k, q[k]);
            for i in 0..N_PARAMS {
                let (a, e) = (dp[(i, k)], fp[i]);
                let scale = b.params.vector(&b.load)[i].abs() / q[k].abs().max(1e-300);
                assert!(
                    (a - e).abs() <= 1e-6 * e.abs().max(1e-6 * scale),
                    "d{}/d{}: chain rule {a:e}, difference {e:e}",
                    all::P_NAMES[i],
                    FIELDS[k]
                );
            }
            for i in 0..N_STATE {
                let (a, e) = (dy0[(i, k)], fy[i]);
                assert!(
                    (a - e).abs() <= 1e-6 * e.abs().max(1e-9),
                    "d{}0/d{}: chain rule {a:e}, difference {e:e}",
                    all::Y_NAMES[i],
                    FIELDS[k]
                );
            }
        }
    }
}

#[test]
fn fields_that_move_nothing_are_found() {
    let s = shipped();
    let b = s.build().unwrap_or_else(|e| panic!("{e}"));
    let (dp, dy0) = jacobians(&s.insert_compliant, &b);
    let unused: Vec<&str> = (0..N_FIELDS)
        .filter(|&k| unused(k, &dp, &dy0))
        .map(|k| FIELDS[k])
        .collect();
    // A two-point start ignores initial_depth; the regularized law has
    // no tangential springs.
    assert_eq!(
        unused,
        [
            "insert_compliant.tangential_damping",
            "insert_compliant.initial_depth"
        ]
    );
}
