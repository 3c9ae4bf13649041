//! Summaries computed from the run, not from its output samples: an
//! insertion stopped by a force-limit event reports that limit as its peak
//! (the stop falls between two samples), its time series ends with the
//! stop, and a grid's per-run peaks do the same; a rotation pair with no
//! seated run reports no mean insertion time; `drop_3d` says when its list
//! of transitions is cut. Each on several inputs.

use crate::common::scene_text::{shipped, with};
use std::path::Path;

use crate::common::cli::{fresh_dir, metric, run_scene};

/// The CSV at `path`: header and rows of numbers (non-numeric cells NaN).
fn csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).expect("the CSV reads");
    let mut lines = text.lines();
    let header = lines
        .next()
        .unwrap_or_default()
        .split(',')
        .map(str::to_string)
        .collect();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|c| c.parse().unwrap_or(f64::NAN))
                .collect()
        })
        .collect();
    (header, rows)
}

fn column(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name}"))
}

#[test]
fn a_wrist_force_limit_stop_reports_the_limit_as_its_peak_and_ends_the_csv() {
    for limit in [2.0, 3.0, 5.0] {
        let text = with(
            &shipped("insert_rcc"),
            "wrist_force_limit",
            &format!("{limit}"),
        );
        let dir = fresh_dir("summaries", &format!("wrist-{limit}"));
        let s = run_scene(&text, "rcc", &dir);
        let i = s.integration.as_ref().expect("an integration");
        assert!(i.stop.contains("wrist force limit"), "{limit}: {}", i.stop);
        let peak = metric(&s, "peak wrist force");
        assert!(
            (peak / limit - 1.0).abs() < 1e-6,
            "limit {limit}: reported peak {peak}"
        );
        // The time series ends with the stop, where the force is the limit.
        let (h, rows) = csv(&dir.join("rcc.csv"));
        let last = rows.last().expect("rows");
        assert_eq!(last[0], i.t_end, "limit {limit}: last row at {}", last[0]);
        let f: f64 = ["wrist_Fx_N", "wrist_Fy_N", "wrist_Fz_N"]
            .iter()
            .map(|c| last[column(&h, c)].powi(2))
            .sum::<f64>()
            .sqrt();
        assert!(
            (f / limit - 1.0).abs() < 1e-6,
            "limit {limit}: CSV ends at {f} N"
        );
        // Every earlier sample is below the limit: the peak is the stop's.
        let before = rows[..rows.len() - 1]
            .iter()
            .map(|r| {
                ["wrist_Fx_N", "wrist_Fy_N", "wrist_Fz_N"]
                    .iter()
                    .map(|c| r[column(&h, c)].powi(2))
                    .sum::<f64>()
                    .sqrt()
            })
            .fold(0.0, f64::max);
        assert!(before < limit, "limit {limit}: a sample at {before} N");
    }
}

#[test]
fn a_contact_force_limit_stop_reports_at_least_the_limit() {
    for limit in [4.0, 8.0] {
        let text = with(
            &shipped("insert_rcc"),
            "contact_force_limit",
            &format!("{limit}"),
        );
        let dir = fresh_dir("summaries", &format!("contact-{limit}"));
        let s = run_scene(&text, "rcc", &dir);
        let i = s.integration.as_ref().expect("an integration");
        assert!(
            i.stop.contains("contact force limit"),
            "{limit}: {}",
            i.stop
        );
        let peak = metric(&s, "peak contact normal force");
        assert!(peak >= limit * (1.0 - 1e-6), "limit {limit}: peak {peak}");
        let (_, rows) = csv(&dir.join("rcc.csv"));
        assert_eq!(rows.last().map(|r| r[0]), Some(i.t_end), "limit {limit}");
    }
}

#[test]
fn a_grid_reports_each_runs_limit_as_its_peak() {
    let mut text = with(&shipped("rotation_assist"), "wrist_force_limit", "2.0");
    text = with(&text, "lateral_errors", "[3e-4, 5e-4]");
    text = with(&text, "angular_errors_deg", "[1.0, 1.5]");
    text = with(&text, "precession_rates", "[0.0]");
    text = with(&text, "spin_rates", "[0.0, 20.0]");
    text = with(&text, "start_height", "1e-3");
    let dir = fresh_dir("summaries", "grid-limit");
    let s = run_scene(&text, "grid", &dir);
    let (h, rows) = csv(&dir.join("grid.csv"));
    let (code, peak) = (column(&h, "outcome_code"), column(&h, "peak_wrist_force_N"));
    let limited: Vec<f64> = rows
        .iter()
        .filter(|r| r[code] == 4.0)
        .map(|r| r[peak])
        .collect();
    assert!(limited.len() >= 2, "{rows:?}");
    for p in limited {
        assert!((p / 2.0 - 1.0).abs() < 1e-6, "peak {p}");
    }
    // No rotation pair seated: no mean insertion time, no "-0".
    assert_eq!(metric(&s, "seated"), 0.0);
    assert!(
        !s.metrics
            .iter()
            .any(|m| m.name.contains("mean insertion time")),
        "{:?}",
        s.metrics
    );
    let shown = s.to_string();
    assert!(
        !shown.contains("= -0 ") && !shown.contains("= -0\n"),
        "{shown}"
    );
}

#[test]
fn a_wrist_force_limit_the_start_already_passes_is_refused() {
    // The held peg hangs on the wrist with its weight, 1.88 N: a limit at
    // or below it is passed before the run and the limit's event (a rise
    // through it) would never fire.
    for limit in ["0.5", "1.0", "1.8"] {
        let text = with(&shipped("insert_rcc"), "wrist_force_limit", limit);
        let e = pegdyn::scene::parse_named(&text, "rcc").expect_err(limit);
        let shown = e.to_string();
        assert!(
            shown.contains(&format!("`criteria.wrist_force_limit` = {limit}"))
                && shown.contains("already carries 1.87"),
            "{shown}"
        );
    }
    assert!(
        pegdyn::scene::parse_named(
            &with(&shipped("insert_rcc"), "wrist_force_limit", "1.9"),
            "rcc"
        )
        .is_ok()
    );
}

#[test]
fn drop_3d_says_when_its_list_of_transitions_is_cut() {
    for (t_end, cut) in [("0.003", false), ("0.02", true)] {
        let text = with(&shipped("drop_3d"), "t_end", t_end);
        let dir = fresh_dir("summaries", &format!("drop-{t_end}"));
        let s = run_scene(&text, "drop", &dir);
        let n = metric(&s, "contact transitions") as usize;
        let listed = s.metrics.iter().filter(|m| m.name.contains(" -> ")).count();
        assert_eq!(listed, n.min(12), "{:?}", s.metrics);
        let note = s
            .metrics
            .iter()
            .find(|m| m.name.starts_with("transitions listed below"));
        assert_eq!(note.is_some(), cut, "t_end {t_end}: {n} transitions");
        if let Some(m) = note {
            assert!(
                m.name.contains(&format!("the first 12 of {n}"))
                    && m.name.contains("drop.events.csv"),
                "{}",
                m.name
            );
        }
        let (_, rows) = csv(&dir.join("drop.csv"));
        let t_end = s.integration.as_ref().map(|i| i.t_end);
        assert_eq!(rows.last().map(|r| r[0]), t_end);
    }
}

#[test]
fn an_energy_balance_drift_above_its_limit_is_a_warning_in_the_summary() {
    use pegdyn::scene::shared::compliant_peg_3d::insertion::RunPeaks;
    use pegdyn::scene::shared::compliant_peg_3d::output::{Peaks, metrics};
    use pegdyn::scene::{ENERGY_DRIFT_WARNING, RunSummary};
    let summary = |drift: f64, scale: f64| {
        RunSummary {
            metrics: metrics(&Peaks {
                forces: RunPeaks {
                    contact: 5.0,
                    pressure: 1e8,
                    wrist_force: 1.0,
                    wrist_moment: 0.01,
                },
                drift,
                scale,
            }),
            ..RunSummary::default()
        }
        .to_string()
    };
    // A drift of 182 (relative) and one just above the limit warn; a
    // conservative run's 4e-12 and one at the limit do not.
    for (drift, scale, warns) in [
        (364.0, 2.0, true),
        (2.0 * ENERGY_DRIFT_WARNING * 1.001, 2.0, true),
        (8e-12, 2.0, false),
        (2.0 * ENERGY_DRIFT_WARNING, 2.0, false),
    ] {
        let text = summary(drift, scale);
        assert_eq!(
            text.contains("  WARNING: the energy balance drifted by"),
            warns,
            "{text}"
        );
    }
    assert!(summary(364.0, 2.0).contains("drifted by 182 (relative)"));
}

#[test]
fn an_impact_between_output_samples_sets_the_peak_contact_force() {
    // Started 2 mm in the bore with the errors held as a wrist deflection,
    // the peg strikes the wall within the first millisecond: at 1 ms
    // output the samples miss the strike, and the summary's peak (over
    // every accepted step) is several times their largest force; sampled
    // every microsecond, the samples resolve the strike and agree with it.
    let largest_sampled = |dir: &Path| {
        let (h, rows) = csv(&dir.join("rcc.csv"));
        let normal: Vec<usize> = h
            .iter()
            .enumerate()
            .filter(|(_, n)| n.ends_with("_N_N"))
            .map(|(k, _)| k)
            .collect();
        rows.iter()
            .flat_map(|r| normal.iter().map(move |&k| r[k]))
            .filter(|v| v.is_finite())
            .fold(0.0, f64::max)
    };
    let base = with(&shipped("insert_rcc"), "start_height", "-2e-3");
    let base = with(&base, "t_end", "0.01");
    for (interval, name) in [("1e-3", "coarse"), ("1e-6", "fine")] {
        let text = with(&base, "output_interval", interval);
        let dir = fresh_dir("summaries", &format!("impact-{name}"));
        let s = run_scene(&text, "rcc", &dir);
        let peak = metric(&s, "peak contact normal force");
        let sampled = largest_sampled(&dir);
        assert!(
            peak >= sampled,
            "{name}: {peak} below the samples' {sampled}"
        );
        if name == "coarse" {
            assert!(peak > 3.0 * sampled, "coarse: {peak} against {sampled}");
        } else {
            assert!(peak < 1.01 * sampled, "fine: {peak} against {sampled}");
        }
    }
}
