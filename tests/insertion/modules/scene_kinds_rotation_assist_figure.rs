//! The items of `src/scene/kinds/rotation_assist/figure.rs`.

use pegdyn::internals::rotation_assist::*;
use pegdyn::scene::kinds::rotation_assist::Point;
use pegdyn::scene::kinds::rotation_assist::Row;

fn row(lateral: f64, angular_deg: f64, spin: f64, code: f64, peak: f64) -> Row {
    Row {
        point: Point {
            lateral,
            angular_deg,
            precession: 0.0,
            spin,
        },
        outcome: String::new(),
        code,
        end: 0.5,
        seated: code == 0.0,
        peak_contact: peak,
        peak_pressure: 0.0,
        peak_moment: 0.0,
        peak_wrist: 0.0,
    }
}

#[test]
fn a_colour_means_one_thing_in_every_panel() {
    // Two rotation pairs, outcomes 0 to 3 and forces in every quartile.
    let mut rows = Vec::new();
    for (k, spin) in [0.0, 20.0].into_iter().enumerate() {
        for i in 0..4 {
            for j in 0..2 {
                let code = ((i + j + k) % 4) as f64;
                let peak = 10.0 * (1 + i + 4 * j + 8 * k) as f64;
                rows.push(row(1e-4 * i as f64, 0.5 + j as f64, spin, code, peak));
            }
        }
    }
    let fig = heat_maps(&rows);
    assert_eq!(fig.panels.len(), 4);
    // name -> (palette colour, shade) over every panel.
    type Colour = (Option<usize>, Option<(usize, usize)>);
    let mut meaning: Vec<(String, Colour)> = Vec::new();
    for s in fig.panels.iter().flat_map(|p| &p.series) {
        assert!(s.color.is_some() || s.shade.is_some(), "{}", s.name);
        match meaning.iter().find(|m| m.0 == s.name) {
            Some(m) => assert_eq!(m.1, (s.color, s.shade), "{}", s.name),
            None => meaning.push((s.name.clone(), (s.color, s.shade))),
        }
    }
    // ... and a colour names one thing.
    for (i, a) in meaning.iter().enumerate() {
        for b in &meaning[i + 1..] {
            assert!(a.1 != b.1, "{} and {} share a colour", a.0, b.0);
        }
    }
    // Every outcome is in the palette, every force band a shade.
    let outcomes: Vec<&str> = pegdyn::compliant_peg_3d::outcome::CODE_LEGEND
        .iter()
        .map(|(_, n)| *n)
        .collect();
    for (name, (colour, shade)) in &meaning {
        if outcomes.contains(&name.as_str()) {
            assert!(colour.is_some() && shade.is_none(), "{name}");
        } else {
            assert!(shade.is_some(), "{name}");
        }
    }
}
