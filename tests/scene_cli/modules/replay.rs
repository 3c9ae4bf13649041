//! The replay of synthetic runs of the compliant 3-D and planar pegs: the
//! contacts drawn where the model puts them, every event kept, enormous
//! runs bounded, bad runs refused.

use nalgebra::{SVector, UnitQuaternion, Vector3};
use pegdyn::compliant_peg_3d::Peg3dParams;
use pegdyn::compliant_peg_3d::insertion::{Insertion, N_STATE};
use pegdyn::compliant_peg_3d::pose_state;
use pegdyn::integrate::{EventHit, Solution, Stats, StopReason};
use pegdyn::replay::peg3d::{Meaning, Run3d};
use pegdyn::replay::*;

/// A 25 mm peg in a bore with a 37.5 µm radial clearance.
fn params() -> Peg3dParams {
    let mut p = Peg3dParams::steel(0.025 - 75e-6, 0.05, 0.025, 3e-4, 5e-4, 0.03);
    p.friction = 0.2;
    p
}

/// The peg upright, its tip `depth` below the top face, its axis shifted
/// by `dx` along x, sliding down at 1 mm/s.
fn state(p: &Peg3dParams, depth: f64, dx: f64) -> SVector<f64, N_STATE> {
    let centre = Vector3::new(dx, 0.0, 0.5 * p.length - depth);
    let ys = pose_state(
        centre,
        UnitQuaternion::identity(),
        Vector3::new(0.0, 0.0, -1e-3),
        Vector3::zeros(),
    );
    let mut y = SVector::<f64, N_STATE>::zeros();
    y.fixed_rows_mut::<15>(0).copy_from(&ys);
    y
}

/// `n` samples of the peg sinking from 5 to 6 mm, pressed 1 µm into the
/// wall at +x (the rim on the wall, the side on the mouth), with one contact transition event
/// in the middle and a seat at the end.
fn pressed_run(p: &Peg3dParams, n: usize) -> Solution<N_STATE> {
    let c = p.bore_radius() - p.peg_radius();
    let y = |k: f64| state(p, 0.005 + 0.001 * k, c + 1e-6);
    let t: Vec<f64> = (0..n).map(|i| i as f64 / n as f64).collect();
    Solution {
        x: t.iter().map(|&s| y(s)).collect(),
        events: vec![
            EventHit {
                index: 0,
                t: 0.5 + 0.1 / n as f64,
                x: y(0.5),
                rising: true,
            },
            EventHit {
                index: 1,
                t: 1.0,
                x: y(1.0),
                rising: true,
            },
        ],
        t,
        stop: StopReason::Event { index: 1, t: 1.0 },
        stats: Stats::default(),
        t_final: 1.0,
        x_final: y(1.0),
        non_finite: None,
        model_error: None,
    }
}

fn meaning(e: &EventHit<N_STATE>) -> Option<Meaning> {
    Some(match e.index {
        0 => Meaning::Transition((1, 1)),
        _ => Meaning::Seated,
    })
}

fn replay_of(sys: &Insertion, sol: &Solution<N_STATE>, budget: Budget) -> Replay {
    let run = Run3d {
        title: "pressed",
        subtitle: "the rim pressed on the wall".into(),
        system: sys,
        solution: sol,
        meaning: &meaning,
    };
    peg3d::replay(&run, budget).expect("a replay")
}

#[test]
fn the_rim_on_the_wall_is_drawn_on_the_wall_with_its_force() {
    let p = params();
    let sys = Insertion::new(p, None, 0.0);
    let r = replay_of(&sys, &pressed_run(&p, 50), Budget::default());
    // 50 samples, the event between two samples, the seat at t = 1 (which
    // is also the final state): 52 frames, none left out.
    assert_eq!((r.frames.len(), r.states, r.events), (52, 52, 2));
    assert!(r.note().is_none());
    assert_eq!(r.pairs[1], "rim_wall");
    for f in &r.frames {
        let c = f
            .contacts
            .iter()
            .find(|c| r.pairs[c.pair] == "rim_wall")
            .expect("the rim on the wall");
        let radial = c.point.xy().norm();
        assert!(
            (radial - p.bore_radius()).abs() < 2e-6,
            "point {radial} m from the axis, the wall at {}",
            p.bore_radius()
        );
        assert!(c.normal.x < -0.99, "pushes the peg off the wall");
        assert!(c.normal_force > 0.0);
        // Sliding down: friction acts upwards on the peg, at most μ N.
        assert!(c.friction.z > 0.0 && c.friction.norm() <= 0.2 * c.normal_force * (1.0 + 1e-9));
        // Upright and off the axis by more than the clearance, the peg's
        // side also presses on the mouth's round where it meets the wall.
        assert_eq!(f.state, "edge_side + rim_wall");
        let side = f.contacts.iter().find(|c| r.pairs[c.pair] == "edge_side");
        let side = side.expect("the side on the mouth");
        assert!((side.point.xy().norm() - p.bore_radius()).abs() < 2e-6);
        assert!(side.point.z < 0.0 && side.point.z > -p.mouth_fillet - 1e-6);
        let sum: f64 = f.contacts.iter().map(|c| c.normal_force).sum();
        assert!((f.values[0] - sum).abs() <= 1e-12 * sum);
        assert!(f.values[2] >= 5.0 && f.values[2] <= 6.0, "depth in mm");
    }
    let labels: Vec<(&str, f64)> = r.marks.iter().map(|m| (m.label.as_str(), m.t)).collect();
    assert_eq!(labels, [("rim_wall 0 → 1", 0.502), ("seated", 1.0)]);
    assert!(
        r.frames.iter().any(|f| f.t == 0.502),
        "the event's own state"
    );
    assert_eq!(r.exaggeration, 10.0);
}

#[test]
fn an_enormous_run_is_decimated_to_a_bounded_page_that_says_so() {
    let p = params();
    let sys = Insertion::new(p, None, 0.0);
    let r = replay_of(&sys, &pressed_run(&p, 300_000), Budget::default());
    assert!(r.frames.len() <= Budget::default().max_frames);
    assert!(r.frames.iter().any(|f| f.t == 0.5 + 0.1 / 300_000.0));
    let note = r.note().expect("a note");
    assert!(
        note.contains(&format!("of {} states", r.states)) && note.contains("every event kept"),
        "{note}"
    );
    let page = html(&r).expect("a page");
    assert!(page.len() < 2_000_000, "{} bytes", page.len());
    assert_eq!(r.states, 300_002);
    assert!(page.contains(&format!("showing {} of 300002 states", r.frames.len())));
}

#[test]
fn runs_without_samples_or_with_non_finite_states_are_refused() {
    let p = params();
    let sys = Insertion::new(p, None, 0.0);
    let mut empty = pressed_run(&p, 0);
    empty.events.clear();
    let run = Run3d {
        title: "empty",
        subtitle: String::new(),
        system: &sys,
        solution: &empty,
        meaning: &meaning,
    };
    assert_eq!(
        peg3d::replay(&run, Budget::default()),
        Err(ReplayError::NoFrames)
    );
    let mut nan = pressed_run(&p, 20);
    nan.x[7][2] = f64::NAN;
    let run = Run3d {
        solution: &nan,
        ..run
    };
    assert_eq!(
        peg3d::replay(&run, Budget::default()),
        Err(ReplayError::NonFinite {
            quantity: "state",
            t: 7.0 / 20.0
        })
    );
    // A record whose numbers went bad after the run: refused by the writer.
    let mut r = replay_of(&sys, &pressed_run(&p, 5), Budget::default());
    r.frames[3].contacts[0].normal_force = f64::INFINITY;
    assert!(matches!(
        html(&r),
        Err(ReplayError::NonFinite {
            quantity: "contact normal force",
            ..
        })
    ));
}

#[test]
fn the_page_embeds_its_data_and_renderer_and_fetches_nothing() {
    let p = params();
    let sys = Insertion::new(p, None, 0.0);
    let page = html(&replay_of(&sys, &pressed_run(&p, 10), Budget::default())).unwrap();
    assert!(page.contains(
        "\"pairs\":[\"edge_side\",\"rim_wall\",\"rim_top\",\"rim_bottom\",\"rim_edge\"]"
    ));
    assert!(page.contains("\"geometry\":{\"peg_radius\":0.0124625,\"peg_length\":0.05,"));
    assert!(page.contains("var PegdynThree="));
    // No address the page could fetch: no external script, style or link.
    for needle in ["src=\"http", "href=\"http", "@import", "url(http", "<link"] {
        assert!(!page.contains(needle), "the page refers out: {needle}");
    }
}

#[test]
fn the_planar_peg_in_two_point_contact_touches_the_left_edge_and_the_right_wall() {
    use pegdyn::compliant_peg::{CompliantParams, CompliantSpec, CompliantSystem, Load, PegState};
    let spec = CompliantSpec::steel_cylinder(0.05, 0.002, 0.1, 0.1);
    let params = CompliantParams::try_new(spec).unwrap();
    let load = Load {
        axial: 5.0,
        radial: 0.0,
        torque: 0.0,
    };
    let sys = CompliantSystem::new(&params, &load);
    let y0 = PegState::two_point(&params, 0.01, 1e-7)
        .unwrap()
        .to_vector();
    let sol = Solution {
        t: vec![0.0],
        x: vec![y0],
        events: Vec::new(),
        stop: StopReason::ReachedEnd,
        stats: Stats::default(),
        t_final: 0.0,
        x_final: y0,
        non_finite: None,
        model_error: None,
    };
    let run = planar::Run2d {
        title: "two-point",
        subtitle: String::new(),
        params: &params,
        peg_length: 0.1,
        wall_depth: 0.05,
        solution: &sol,
        sample: &|y| sys.sample(y),
        mark: &|_| None,
    };
    let r = planar::replay(&run, Budget::default()).unwrap();
    let f = &r.frames[0];
    assert_eq!(f.state, "edge_left + wall_right");
    let g = &params.spec.geometry;
    let half = 0.5 * g.hole_diameter;
    for c in &f.contacts {
        assert_eq!(c.point.y, 0.0);
        match planar::PAIRS[c.pair] {
            // On the left edge fillet, pushing the peg to the right.
            "edge_left" => {
                let centre = Vector3::new(-(half + g.hole_fillet), 0.0, -g.hole_fillet);
                assert!(((c.point - centre).norm() - g.hole_fillet).abs() < 1e-12);
                assert!(c.normal.x > 0.99);
            }
            // On the right wall, below the top face, pushing to the left.
            "wall_right" => {
                assert!((c.point.x - half).abs() < 1e-6, "{}", c.point.x);
                assert!(c.point.z < -g.hole_fillet);
                assert_eq!(c.normal, Vector3::new(-1.0, 0.0, 0.0));
            }
            other => panic!("contact {other}"),
        }
    }
    assert_eq!(r.view, View::Section);
    assert!(!r.geometry.bore_bottom);
}

#[test]
fn the_replay_uses_the_models_not_the_scenes_or_the_output_writers() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/replay");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .collect();
    files.sort();
    assert!(files.len() >= 8);
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        for line in text.lines().map(|l| l.split("//").next().unwrap_or("")) {
            for upper in ["scene", "output", "cli"] {
                for root in ["crate::", "pegdyn::", "super::super::"] {
                    let path = format!("{root}{upper}");
                    let hit = line.match_indices(&path).any(|(i, _)| {
                        !line[i + path.len()..]
                            .starts_with(|c: char| c.is_alphanumeric() || c == '_')
                    });
                    assert!(!hit, "{}: {line}", f.display());
                }
            }
        }
    }
}
