//! The items of `src/scene/summary.rs`.

use pegdyn::internals::scene::format_metric;
use pegdyn::scene::integrator::Method;
use pegdyn::scene::*;

fn part(steps: usize, t_end: f64, success: bool) -> IntegrationSummary {
    IntegrationSummary {
        method: Method::Named(pegdyn::integrate::MethodKind::Dopri5),
        t_end,
        stop: format!("stop at {t_end}"),
        success,
        steps,
        rejected: 1,
        rhs_calls: 6 * steps,
        events: vec![EventRecord {
            name: "hit".into(),
            t: t_end,
            terminal: !success,
            details: vec![],
        }],
        step_failure: None,
    }
}

#[test]
fn merge_adds_counters_and_keeps_the_last_stop() {
    let mut a = part(10, 1.0, true);
    a.merge(part(5, 2.5, false));
    assert_eq!((a.steps, a.rejected, a.rhs_calls), (15, 2, 90));
    assert_eq!((a.t_end, a.success), (2.5, false));
    let times: Vec<(f64, bool)> = a.events.iter().map(|e| (e.t, e.terminal)).collect();
    assert_eq!(times, [(1.0, false), (2.5, true)]);
}

#[test]
fn display_prints_metrics_readably() {
    let s = RunSummary {
        integration: Some(part(3, 1.0, true)),
        metrics: vec![
            Metric::new("period", 2.0, "s"),
            Metric::new("drift", 1.5e-11, ""),
        ],
        outputs: vec![],
    };
    let text = s.to_string();
    assert!(text.contains("period = 2 s"), "{text}");
    assert_eq!(format_metric(0.0), "0");
    assert_eq!(format_metric(-0.0), "0");
    assert_eq!(format_metric([0.0_f64; 0].iter().sum::<f64>()), "0");
    assert_eq!(format_metric(169.0), "169");
    assert_eq!(format_metric(2.5), "2.500000");
    assert!(text.contains("drift = 1.500e-11\n"), "{text}");
    assert!(
        text.contains("3 steps (1 rejected), 18 rhs calls"),
        "{text}"
    );
    assert!(s.success() && RunSummary::default().success());
}

#[test]
fn a_coded_metric_prints_its_meaning_before_its_code() {
    let s = RunSummary {
        metrics: vec![
            Metric::coded("outcome", 0.0, "seated"),
            Metric::coded("outcome", 4.0, "wrist force limit (2 N)"),
            Metric::new("mean insertion time", -0.0, "s"),
            Metric::note("diagram check", "not made"),
        ],
        ..RunSummary::default()
    };
    let text = s.to_string();
    assert!(text.contains("  outcome = seated (code 0)\n"), "{text}");
    assert!(
        text.contains("  outcome = wrist force limit (2 N) (code 4)\n"),
        "{text}"
    );
    assert!(text.contains("mean insertion time = 0 s"), "{text}");
    assert!(text.contains("  diagram check: not made\n"), "{text}");
    assert!(!text.contains("-0"), "{text}");
}
