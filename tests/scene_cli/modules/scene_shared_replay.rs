//! The items of `src/scene/shared/replay.rs`.

use pegdyn::scene::shared::replay::*;

#[test]
fn worst_is_the_first_failure_else_the_slowest_seat() {
    let w = RunChoice::Worst;
    let k = |runs: &[(bool, f64)]| w.pick(runs).map(|p| p.0);
    assert_eq!(k(&[(true, 1.0), (false, 0.5), (false, 2.0)]), Some(1));
    assert_eq!(k(&[(true, 1.0), (true, 3.0), (true, 2.0)]), Some(1));
    assert_eq!(k(&[(true, 1.0), (true, 0.5)]), Some(0));
    assert_eq!(k(&[]), None);
    assert_eq!(RunChoice::Nominal.pick(&[(false, 1.0)]), None);
    assert_eq!(RunChoice::Index(1).pick(&[]).map(|p| p.0), Some(1));
    assert_eq!(RunChoice::Index(2).check(3).ok(), Some(RunChoice::Index(2)));
    let e = RunChoice::Index(3).check(3).unwrap_err().to_string();
    assert!(e.contains("replay.run") && e.contains("0 to 2"), "{e}");
}
